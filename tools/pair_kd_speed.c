/* The per-contact call of a C host against the bare formula it replaces (issue 26):
 * tools/pair_kd_speed.sh builds this against the core library (release flags) and runs it.
 * Over n contacts (T_c, m, u log-uniform over [1e-7, 1e-3] s, [1e-9, 1] kg,
 * [1e-3, 10] m/s, as the entry table of `hertzdamp bench`), one material pair (linear
 * law, overlap end, e = 0.5, host none), in turns R times:
 *   bare:    k = m r^(5/2) u^(-1/2), d = alpha m r, r = tau_c / T_c, written in the loop
 *            as a host writes it (one contact per iteration, not vectorised);
 *   pair_kd: hertzdamp_c_pair_kd(&p, tc, m, u, 0, &k, &d), one call per contact;
 *   phase:   hertzdamp_c_pair_kd_phase(&pp, tc, m, u, 0, phi, &k, &d), one call per contact,
 *            with a pair's onset-phase table (mfix-euler, N = 10, e = 0.5, linear law, overlap
 *            end; issue 32) and phases spread over (0, 1] by golden-ratio steps.
 * Prints the median and the shortest time of each (ns per contact) and the medians of the
 * turns' ratios pair_kd / bare and phase / bare.  Exits non-zero when a call fails or k, d
 * of pair_kd differ from the bare formula by more than 1e-14 relative (it is not the same
 * rounding). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include "hertzdamp.h"

static double now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

__attribute__((noinline, optimize("no-tree-vectorize"))) static void bare(int n, double alpha, double tau,
        const double *tc, const double *m, const double *u, double *k, double *d) {
    for (int i = 0; i < n; i++) {
        double r = tau / tc[i];
        k[i] = m[i] * r * r * sqrt(r / u[i]);
        d[i] = alpha * m[i] * r;
    }
}

__attribute__((noinline)) static void lib(int n, const hertzdamp_pair_t *p, const double *tc, const double *m,
        const double *u, double *k, double *d, int *s) {
    for (int i = 0; i < n; i++) s[i] = hertzdamp_c_pair_kd(p, tc[i], m[i], u[i], 0.0, &k[i], &d[i]);
}

__attribute__((noinline)) static void lib_phase(int n, const hertzdamp_pair_t *p, const double *tc, const double *m,
        const double *u, const double *phi, double *k, double *d, int *s) {
    for (int i = 0; i < n; i++) s[i] = hertzdamp_c_pair_kd_phase(p, tc[i], m[i], u[i], 0.0, phi[i], &k[i], &d[i]);
}

static int cmp(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int main(int argc, char **argv) {
    int n = 100000, turns = argc > 1 ? atoi(argv[1]) : 101;
    double *tc = malloc(8 * n), *m = malloc(8 * n), *u = malloc(8 * n);
    double *k = malloc(8 * n), *d = malloc(8 * n), *kb = malloc(8 * n), *db = malloc(8 * n);
    double *tb = malloc(8 * turns), *tl = malloc(8 * turns), *r = malloc(8 * turns);
    double *phi = malloc(8 * n), *tp = malloc(8 * turns), *rp = malloc(8 * turns), *kp = malloc(8 * n), *dp = malloc(8 * n);
    int *s = malloc(8 * n), bad = 0;
    unsigned long long x = 20261122ULL;
    for (int i = 0; i < n; i++) {
        double q[3];
        for (int j = 0; j < 3; j++) { x = x * 6364136223846793005ULL + 1442695040888963407ULL; q[j] = (x >> 11) * 0x1p-53; }
        tc[i] = pow(10.0, -7.0 + 4.0 * q[0]);
        m[i] = pow(10.0, -9.0 + 9.0 * q[1]);
        u[i] = pow(10.0, -3.0 + 4.0 * q[2]);
        phi[i] = 1.0 - fmod((i + 1) * 0.6180339887498949, 1.0);
    }
    hertzdamp_pair_t p;
    if (hertzdamp_c_pair_init(0.5, HERTZDAMP_DAMPING_LINEAR, HERTZDAMP_END_OVERLAP, HERTZDAMP_HOST_NONE, 0.0, &p) != 0) {
        fprintf(stderr, "pair_kd_speed: hertzdamp_c_pair_init failed\n");
        return 1;
    }
    hertzdamp_pair_t pp;
    if (hertzdamp_c_pair_init_phase(0.5, HERTZDAMP_DAMPING_LINEAR, HERTZDAMP_END_OVERLAP, HERTZDAMP_HOST_MFIX_EULER, 10.0,
                                    &pp) != 0) {
        fprintf(stderr, "pair_kd_speed: hertzdamp_c_pair_init_phase failed\n");
        return 1;
    }
    double alpha = p.v[0], tau = p.v[1];   /* the first two fields: alpha, tau_c (hertzdamp.h) */
    for (int j = 0; j < turns; j++) {
        double t0 = now();
        bare(n, alpha, tau, tc, m, u, kb, db);
        double t1 = now();
        lib(n, &p, tc, m, u, k, d, s);
        double t2 = now();
        lib_phase(n, &pp, tc, m, u, phi, kp, dp, s + n);
        double t3 = now();
        tb[j] = t1 - t0;
        tl[j] = t2 - t1;
        tp[j] = t3 - t2;
        r[j] = tl[j] / tb[j];
        rp[j] = tp[j] / tb[j];
    }
    for (int i = 0; i < n; i++)
        if (s[i] != 0 || s[n + i] != 0 || fabs(k[i] / kb[i] - 1.0) > 1e-14 || fabs(d[i] / db[i] - 1.0) > 1e-14) bad++;
    qsort(tb, turns, 8, cmp);
    qsort(tl, turns, 8, cmp);
    qsort(r, turns, 8, cmp);
    qsort(tp, turns, 8, cmp);
    qsort(rp, turns, 8, cmp);
    printf("bare %.2f ns (shortest %.2f), hertzdamp_c_pair_kd %.2f ns (shortest %.2f) per contact; "
           "ratio: median of %d turns %.3f, of the shortest %.3f; %d contacts differ\n",
           1e9 * tb[turns / 2] / n, 1e9 * tb[0] / n, 1e9 * tl[turns / 2] / n, 1e9 * tl[0] / n, turns, r[turns / 2],
           tl[0] / tb[0], bad);
    printf("hertzdamp_c_pair_kd_phase %.2f ns (shortest %.2f) per contact; ratio to bare: median of %d turns %.3f, "
           "of the shortest %.3f\n", 1e9 * tp[turns / 2] / n, 1e9 * tp[0] / n, turns, rp[turns / 2], tp[0] / tb[0]);
    return bad != 0;
}
