/* The per-contact call of a C host against the bare formula it replaces (issue 26):
 * tools/pair_kd_speed.sh builds this against the core library (release flags) and runs it.
 * Over n contacts (T_c, m, u log-uniform over [1e-7, 1e-3] s, [1e-9, 1] kg,
 * [1e-3, 10] m/s, as the entry table of `hertzdamp bench`), one material pair (linear
 * law, overlap end, e = 0.5, host none), in turns R times:
 *   bare:    k = m r^(5/2) u^(-1/2), d = alpha m r, r = tau_c / T_c, written in the loop
 *            as a host writes it (one contact per iteration, not vectorised);
 *   pair_kd: hertzdamp_c_pair_kd(&p, tc, m, u, 0, &k, &d), one call per contact.
 * Prints the median and the shortest time of each (ns per contact) and the median of the
 * turns' ratios pair_kd / bare.  Exits non-zero when a call fails or k, d differ from
 * the bare formula by more than 1e-14 relative (it is not the same rounding). */
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

static int cmp(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int main(int argc, char **argv) {
    int n = 100000, turns = argc > 1 ? atoi(argv[1]) : 101;
    double *tc = malloc(8 * n), *m = malloc(8 * n), *u = malloc(8 * n);
    double *k = malloc(8 * n), *d = malloc(8 * n), *kb = malloc(8 * n), *db = malloc(8 * n);
    double *tb = malloc(8 * turns), *tl = malloc(8 * turns), *r = malloc(8 * turns);
    int *s = malloc(4 * n), bad = 0;
    unsigned long long x = 20261122ULL;
    for (int i = 0; i < n; i++) {
        double q[3];
        for (int j = 0; j < 3; j++) { x = x * 6364136223846793005ULL + 1442695040888963407ULL; q[j] = (x >> 11) * 0x1p-53; }
        tc[i] = pow(10.0, -7.0 + 4.0 * q[0]);
        m[i] = pow(10.0, -9.0 + 9.0 * q[1]);
        u[i] = pow(10.0, -3.0 + 4.0 * q[2]);
    }
    hertzdamp_pair_t p;
    if (hertzdamp_c_pair_init(0.5, HERTZDAMP_DAMPING_LINEAR, HERTZDAMP_END_OVERLAP, HERTZDAMP_HOST_NONE, 0.0, &p) != 0) {
        fprintf(stderr, "pair_kd_speed: hertzdamp_c_pair_init failed\n");
        return 1;
    }
    double alpha = p.v[0], tau = p.v[1];   /* the first two fields: alpha, tau_c (hertzdamp.h) */
    for (int j = 0; j < turns; j++) {
        double t0 = now();
        bare(n, alpha, tau, tc, m, u, kb, db);
        double t1 = now();
        lib(n, &p, tc, m, u, k, d, s);
        double t2 = now();
        tb[j] = t1 - t0;
        tl[j] = t2 - t1;
        r[j] = tl[j] / tb[j];
    }
    for (int i = 0; i < n; i++)
        if (s[i] != 0 || fabs(k[i] / kb[i] - 1.0) > 1e-14 || fabs(d[i] / db[i] - 1.0) > 1e-14) bad++;
    qsort(tb, turns, 8, cmp);
    qsort(tl, turns, 8, cmp);
    qsort(r, turns, 8, cmp);
    printf("bare %.2f ns (shortest %.2f), hertzdamp_c_pair_kd %.2f ns (shortest %.2f) per contact; "
           "ratio: median of %d turns %.3f, of the shortest %.3f; %d contacts differ\n",
           1e9 * tb[turns / 2] / n, 1e9 * tb[0] / n, 1e9 * tl[turns / 2] / n, 1e9 * tl[0] / n, turns, r[turns / 2],
           tl[0] / tb[0], bad);
    return bad != 0;
}
