/*
 * capi_fuzz.c: random and adversarial doubles (NaN, +-inf, zero, subnormals,
 * 1e+-300, DBL_MAX, random bit patterns, ordinary values) and random integers for
 * `end` and `law` into every hertzdamp_c_* function of include/hertzdamp.h.
 * Built by test/capi_fuzz.sh against an installed prefix, with
 * -fsanitize=address,undefined.  Asserts the header's contract:
 *
 *   - the status is a known code and hertzdamp_c_strerror gives a non-empty,
 *     printable message for it;
 *   - status 0: every output finite (k > 0, d >= 0; 0 <= e <= 1, tc > 0;
 *     alpha >= 0, tau_c > 0), and the bounded inverse never exceeds k_phys;
 *   - failure: *k = *d = 0 (inverse), *alpha = *tau_c = 0 (pair), *e = *tc = 0
 *     (forward), except no-rebound: *e = 0, *tc = DBL_MAX;
 *   - a NULL result pointer gives HERTZDAMP_BAD_ARGUMENT;
 *   - hertzdamp_c_invert_n gives, element by element, the bits of
 *     hertzdamp_c_invert and returns the first non-zero status;
 *   - the wrappers agree with the _law forms (law 0), bit for bit;
 *   - a successful inverse fed back to the forward problem gives e and tc back
 *     (1e-9 relative for ordinary magnitudes).
 *
 * Usage: capi_fuzz [N]  (N random rounds, default 200000; fixed seed).
 * Prints `capi_fuzz: P passed, F failed` and exits non-zero on failure.
 */
#define _POSIX_C_SOURCE 200809L
#include <fcntl.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include <hertzdamp.h>

static long passed, failed;
static int reported;

static void check(int ok, const char *what)
{
    if (ok) {
        passed++;
    } else {
        failed++;
        if (reported < 40) { printf("FAIL capi_fuzz: %s\n", what); reported++; }
    }
}

/* one counted check per property, however many calls: failures listed with inputs */
typedef struct { const char *name; long bad; } prop;
static void bad(prop *p, double a, double b, double c, double x, double y, int i, int j, int st, double o1,
                double o2)
{
    if (p->bad++ < 5)
        printf("  %s: args %.17g %.17g %.17g %.17g %.17g ints %d %d -> status %d, out %.17g %.17g\n",
               p->name, a, b, c, x, y, i, j, st, o1, o2);
}

static uint64_t rng_state = 0x2026112217ULL;
static uint64_t next64(void)  /* xorshift64* */
{
    rng_state ^= rng_state >> 12; rng_state ^= rng_state << 25; rng_state ^= rng_state >> 27;
    return rng_state * 2685821657736338717ULL;
}
static double unif(void) { return (double)(next64() >> 11) * 0x1.0p-53; }

static double adversarial(double typical_lo, double typical_hi)
{
    uint64_t bits;
    double x;
    switch (next64() % 16) {
    case 0: return NAN;
    case 1: return INFINITY;
    case 2: return -INFINITY;
    case 3: return 0.0;
    case 4: return -0.0;
    case 5: return DBL_MIN * unif();                        /* subnormal */
    case 6: return DBL_MAX * unif();
    case 7: return (next64() & 1 ? 1e300 : 1e-300) * (1 + unif());
    case 8: return pow(10.0, 640 * unif() - 320);           /* 1e-320 .. 1e320 */
    case 9: return -pow(10.0, 60 * unif() - 30);
    case 10: bits = next64(); memcpy(&x, &bits, sizeof x); return x;   /* any bits */
    default: return typical_lo * pow(typical_hi / typical_lo, unif());  /* log-uniform */
    }
}
static double rand_e(void)
{
    switch (next64() % 6) {
    case 0: return adversarial(1e-4, 1.0);
    case 1: return 1.0;
    case 2: return nextafter(1.0, 2.0);
    case 3: return 1e-4 * pow(1e4, unif());
    default: return unif();
    }
}
static int rand_int(int lo, int hi)  /* mostly lo..hi, sometimes anything */
{
    uint64_t r = next64();
    if (r % 10 == 0) return (int)(int32_t)(r >> 20);
    return lo + (int)((r >> 8) % (uint64_t)(hi - lo + 1));
}

/* hertzdamp_c_invert_n(1, ...) with the array `which` NULL, in a child process (it
   may crash): 1 when the child exited normally with HERTZDAMP_BAD_ARGUMENT */
static int invert_n_null(int which)
{
    pid_t pid = fork();
    int ws;
    if (pid < 0) return 0;
    if (pid == 0) {
        double e = 0.5, tc = 1e-5, m = 1e-3, u = 1, k, d;
        int st, r, null = open("/dev/null", O_WRONLY);
        if (null >= 0) dup2(null, 2);  /* the sanitizer's report of the crash: not wanted here */
        r = hertzdamp_c_invert_n(1, which == 0 ? NULL : &e, &tc, &m, &u, 0, which == 1 ? NULL : &k,
                                 which == 2 ? NULL : &d, which == 3 ? NULL : &st);
        _exit(r == HERTZDAMP_BAD_ARGUMENT ? 0 : 1);
    }
    if (waitpid(pid, &ws, 0) != pid) return 0;
    return WIFEXITED(ws) && WEXITSTATUS(ws) == 0;
}

static int is_finite(double x) { return isfinite(x); }
static int same(double a, double b) { return memcmp(&a, &b, sizeof a) == 0; }

static prop p_status = {"status outside 0..25", 0};
static prop p_msg = {"strerror empty or not printable", 0};
static prop p_inv_ok = {"invert: status 0 with a non-finite or out-of-range k, d", 0};
static prop p_inv_fail = {"invert: failure with k or d not 0", 0};
static prop p_bnd_ok = {"invert_bounded: status 0 with a non-finite or out-of-range k, d", 0};
static prop p_bound = {"invert_bounded, invert_law: k above k_phys (the bound gives k = k_phys)", 0};
static prop p_bnd_fail = {"invert_bounded: failure with k or d not 0", 0};
static prop p_law_ok = {"invert_law: status 0 with a non-finite or out-of-range k, d", 0};
static prop p_law_fail = {"invert_law: failure with k or d not 0", 0};
static prop p_law_same = {"invert_law(law 0, k_phys 0) differs from invert", 0};
static prop p_pair_ok = {"pair(_law): status 0 with bad alpha, tau_c", 0};
static prop p_pair_fail = {"pair(_law): failure with alpha or tau_c not 0", 0};
static prop p_pair_same = {"pair differs from pair_law(law 0)", 0};
static prop p_fwd_ok = {"forward(_law): status 0 with bad e, tc", 0};
static prop p_fwd_fail = {"forward(_law): failure with e, tc not (0, 0) or (0, DBL_MAX) for no-rebound", 0};
static prop p_fwd_same = {"forward differs from forward_law(law 0)", 0};
static prop p_n_same = {"invert_n differs from invert element by element", 0};
static prop p_n_first = {"invert_n does not return the first non-zero status", 0};
static prop p_round = {"invert_law -> forward_law fails or does not give e and tc back (1e-9)", 0};

static void status_ok(int st)
{
    const char *m;
    if (st < 0 || st > 25) bad(&p_status, 0, 0, 0, 0, 0, 0, 0, st, 0, 0);
    m = hertzdamp_c_strerror(st);
    if (m == NULL || m[0] == '\0') { bad(&p_msg, 0, 0, 0, 0, 0, 0, 0, st, 0, 0); return; }
    for (const unsigned char *c = (const unsigned char *)m; *c; c++)
        if (*c < 32 || *c > 126) { bad(&p_msg, 0, 0, 0, 0, 0, 0, 0, st, 0, 0); return; }
}

static void one_round(void)
{
    double e = rand_e();
    double tc = adversarial(1e-9, 1e-1);
    double m = adversarial(1e-15, 1e3);
    double u = adversarial(1e-4, 1e2);
    double kp = next64() % 3 ? adversarial(1e3, 1e12) : 0.0;
    int end = rand_int(0, 1), law = rand_int(0, 2);
    double k = -1, d = -1, k2 = -1, d2 = -1, a = -1, t = -1, a2 = -1, t2 = -1, ee = -1, tt = -1, ee2 = -1, tt2 = -1;
    int st, st2;

    /* inverse */
    st = hertzdamp_c_invert(e, tc, m, u, end, &k, &d);
    status_ok(st);
    if (st == 0) {
        if (!(is_finite(k) && is_finite(d) && k > 0 && d >= 0)) bad(&p_inv_ok, e, tc, m, u, 0, end, 0, st, k, d);
    } else if (!(k == 0 && d == 0)) {
        bad(&p_inv_fail, e, tc, m, u, 0, end, 0, st, k, d);
    }
    st2 = hertzdamp_c_invert_law(e, tc, m, u, 0.0, 0, end, &k2, &d2);
    if (st2 != st || !same(k, k2) || !same(d, d2)) bad(&p_law_same, e, tc, m, u, 0, end, 0, st2, k2, d2);

    /* round trip of every law, over the magnitudes of README's robustness table */
    {
        double m2 = 1e-20 * pow(1e26, unif()), u2 = 1e-8 * pow(1e12, unif()), tc2 = 1e-12 * pow(1e12, unif());
        double e2 = 1e-3 * pow(1e3, unif());
        int law2 = (int)(next64() % 3), end2 = (int)(next64() % 2);
        st = hertzdamp_c_invert_law(e2, tc2, m2, u2, 0.0, law2, end2, &k2, &d2);
        if (st == 0) {
            st2 = hertzdamp_c_forward_law(k2, d2, m2, u2, law2, end2, &ee, &tt);
            if (st2 != 0 || fabs(ee - e2) > 1e-9 * e2 || fabs(tt - tc2) > 1e-9 * tc2)
                bad(&p_round, e2, tc2, m2, u2, 0, end2, law2, st2, ee, tt);
        } else {
            bad(&p_round, e2, tc2, m2, u2, 0, end2, law2, st, k2, d2);
        }
    }

    /* bounded */
    k = d = -1;
    st = hertzdamp_c_invert_bounded(e, tc, m, u, kp, end, &k, &d);
    status_ok(st);
    if (st == 0) {
        if (!(is_finite(k) && is_finite(d) && k > 0 && d >= 0)) bad(&p_bnd_ok, e, tc, m, u, kp, end, 0, st, k, d);
        if (k > kp) bad(&p_bound, e, tc, m, u, kp, end, 0, st, k, d);
    } else if (!(k == 0 && d == 0)) {
        bad(&p_bnd_fail, e, tc, m, u, kp, end, 0, st, k, d);
    }

    /* law */
    k = d = -1;
    st = hertzdamp_c_invert_law(e, tc, m, u, kp, law, end, &k, &d);
    status_ok(st);
    if (st == 0) {
        if (!(is_finite(k) && is_finite(d) && k > 0 && d >= 0)) bad(&p_law_ok, e, tc, m, u, kp, end, law, st, k, d);
        if (kp > 0 && k > kp) bad(&p_bound, e, tc, m, u, kp, end, law, st, k, d);
    } else if (!(k == 0 && d == 0)) {
        bad(&p_law_fail, e, tc, m, u, kp, end, law, st, k, d);
    }

    /* pair */
    st = hertzdamp_c_pair_law(e, law, end, &a, &t);
    status_ok(st);
    if (st == 0) {
        if (!(is_finite(a) && is_finite(t) && a >= 0 && t > 0)) bad(&p_pair_ok, e, 0, 0, 0, 0, end, law, st, a, t);
    } else if (!(a == 0 && t == 0)) {
        bad(&p_pair_fail, e, 0, 0, 0, 0, end, law, st, a, t);
    }
    st = hertzdamp_c_pair(e, end, &a, &t);
    st2 = hertzdamp_c_pair_law(e, 0, end, &a2, &t2);
    if (st != st2 || !same(a, a2) || !same(t, t2)) bad(&p_pair_same, e, 0, 0, 0, 0, end, 0, st, a, t);

    /* forward */
    {
        double kk = adversarial(1e3, 1e12), dd = next64() % 5 ? adversarial(1e-6, 1e3) : 0.0;
        st = hertzdamp_c_forward_law(kk, dd, m, u, law, end, &ee, &tt);
        status_ok(st);
        if (st == 0) {
            if (!(is_finite(ee) && is_finite(tt) && ee >= 0 && ee <= 1 && tt > 0))
                bad(&p_fwd_ok, kk, dd, m, u, 0, end, law, st, ee, tt);
        } else if (!((st == HERTZDAMP_NO_REBOUND && ee == 0 && tt == DBL_MAX) ||
                     (st != HERTZDAMP_NO_REBOUND && ee == 0 && tt == 0))) {
            bad(&p_fwd_fail, kk, dd, m, u, 0, end, law, st, ee, tt);
        }
        st = hertzdamp_c_forward(kk, dd, m, u, end, &ee, &tt);
        st2 = hertzdamp_c_forward_law(kk, dd, m, u, 0, end, &ee2, &tt2);
        if (st != st2 || !same(ee, ee2) || !same(tt, tt2)) bad(&p_fwd_same, kk, dd, m, u, 0, end, 0, st, ee, tt);
    }
}

static void vector_rounds(int rounds)
{
    enum { N = 37 };
    double e[N], tc[N], m[N], u[N], k[N], d[N];
    int st[N];
    for (int r = 0; r < rounds; r++) {
        int end = rand_int(0, 1), n = (int)(next64() % N) + 1, first = 0, ret;
        for (int i = 0; i < n; i++) {
            e[i] = rand_e(); tc[i] = adversarial(1e-9, 1e-1);
            m[i] = adversarial(1e-15, 1e3); u[i] = adversarial(1e-4, 1e2);
        }
        ret = hertzdamp_c_invert_n(n, e, tc, m, u, end, k, d, st);
        for (int i = 0; i < n; i++) {
            double k1, d1;
            int s1 = hertzdamp_c_invert(e[i], tc[i], m[i], u[i], end, &k1, &d1);
            if (s1 != st[i] || !same(k1, k[i]) || !same(d1, d[i]))
                bad(&p_n_same, e[i], tc[i], m[i], u[i], 0, end, i, st[i], k[i], d[i]);
            if (first == 0) first = st[i];
        }
        if (ret != first) bad(&p_n_first, 0, 0, 0, 0, 0, end, n, ret, first, 0);
    }
}

int main(int argc, char **argv)
{
    long rounds = argc > 1 ? atol(argv[1]) : 200000;
    prop *props[] = {&p_status, &p_msg, &p_inv_ok, &p_inv_fail, &p_bnd_ok, &p_bnd_fail, &p_law_ok, &p_law_fail, &p_bound,
                     &p_law_same, &p_pair_ok, &p_pair_fail, &p_pair_same, &p_fwd_ok, &p_fwd_fail, &p_fwd_same,
                     &p_n_same, &p_n_first, &p_round};
    double k, d, e, t;

    for (long r = 0; r < rounds; r++) one_round();
    vector_rounds((int)(rounds / 20));
    for (size_t i = 0; i < sizeof props / sizeof props[0]; i++) {
        char label[200];
        snprintf(label, sizeof label, "%s (%ld calls)", props[i]->name, props[i]->bad);
        check(props[i]->bad == 0, label);
    }

    /* NULL result pointers: HERTZDAMP_BAD_ARGUMENT, nothing written */
    k = d = 7;
    check(hertzdamp_c_invert(0.5, 1e-5, 1e-3, 1, 0, NULL, &d) == HERTZDAMP_BAD_ARGUMENT, "invert, k NULL");
    check(hertzdamp_c_invert(0.5, 1e-5, 1e-3, 1, 0, &k, NULL) == HERTZDAMP_BAD_ARGUMENT, "invert, d NULL");
    check(hertzdamp_c_invert_bounded(0.5, 1e-5, 1e-3, 1, 1e9, 0, NULL, NULL) == HERTZDAMP_BAD_ARGUMENT,
          "invert_bounded, NULL");
    check(hertzdamp_c_invert_law(0.5, 1e-5, 1e-3, 1, 0, 1, 0, &k, NULL) == HERTZDAMP_BAD_ARGUMENT,
          "invert_law, d NULL");
    check(hertzdamp_c_pair(0.5, 0, NULL, &t) == HERTZDAMP_BAD_ARGUMENT, "pair, alpha NULL");
    check(hertzdamp_c_pair_law(0.5, 2, 1, &e, NULL) == HERTZDAMP_BAD_ARGUMENT, "pair_law, tau_c NULL");
    check(hertzdamp_c_forward(1e9, 0.5, 1e-3, 1, 0, NULL, &t) == HERTZDAMP_BAD_ARGUMENT, "forward, e NULL");
    check(hertzdamp_c_forward_law(1e9, 0.5, 1e-3, 1, 1, 0, &e, NULL) == HERTZDAMP_BAD_ARGUMENT,
          "forward_law, tc NULL");
    check(k == 7 && d == 7, "nothing written through the other pointer");
    check(hertzdamp_c_invert_n(0, NULL, NULL, NULL, NULL, 0, NULL, NULL, NULL) == 0, "invert_n, n = 0, NULL arrays");
    check(hertzdamp_c_invert_n(-5, NULL, NULL, NULL, NULL, 0, NULL, NULL, NULL) == 0, "invert_n, n < 0, NULL arrays");
    /* the header: "Results are written through the pointers, which must not be NULL
       (NULL gives HERTZDAMP_BAD_ARGUMENT)" -- invert_n too, not a crash */
    check(invert_n_null(0), "invert_n, n = 1, e NULL: HERTZDAMP_BAD_ARGUMENT, no crash");
    check(invert_n_null(1), "invert_n, n = 1, k NULL: HERTZDAMP_BAD_ARGUMENT, no crash");
    check(invert_n_null(3), "invert_n, n = 1, status NULL: HERTZDAMP_BAD_ARGUMENT, no crash");
    check(hertzdamp_c_strerror(-1) != NULL && hertzdamp_c_strerror(1000) != NULL &&
          hertzdamp_c_strerror(-2147483647 - 1) != NULL, "strerror of unknown codes not NULL");

    printf("capi_fuzz: %ld passed, %ld failed\n", passed, failed);
    return failed ? 1 : 0;
}
