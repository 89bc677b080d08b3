/*
 * dem.c: the call sequence of the legacy DEM example (example/legacy_dem) from C.
 *
 *   ./dem_c                  a particle dropped on a wall under gravity; at every
 *                            contact onset k and d come from hertzdamp_c_invert
 *                            (target e, T_c = N dt, the mass and impact speed of
 *                            that contact); prints u_in, k, d and the achieved
 *                            ratio of rebound to impact speed per contact.
 *   ./dem_c e tc m u [end]   one inversion: prints k d and the e tc that
 *                            hertzdamp_c_forward returns for them (%.17g).
 *
 * Build:  make PREFIX=/path/to/prefix   (cc ... -lhertzdamp -lgfortran -lm)
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "hertzdamp.h"

static int one_inversion(int argc, char **argv)
{
    double e = strtod(argv[1], NULL), tc = strtod(argv[2], NULL);
    double m = strtod(argv[3], NULL), u = strtod(argv[4], NULL);
    int end = argc > 5 ? atoi(argv[5]) : HERTZDAMP_END_OVERLAP;
    double k, d, e_out, tc_out;
    int status = hertzdamp_c_invert(e, tc, m, u, end, &k, &d);
    if (status != HERTZDAMP_OK) {
        fprintf(stderr, "hertzdamp_c_invert: %s\n", hertzdamp_c_strerror(status));
        return 1;
    }
    status = hertzdamp_c_forward(k, d, m, u, end, &e_out, &tc_out);
    if (status != HERTZDAMP_OK) {
        fprintf(stderr, "hertzdamp_c_forward: %s\n", hertzdamp_c_strerror(status));
        return 1;
    }
    printf("%.17g %.17g %.17g %.17g\n", k, d, e_out, tc_out);
    return 0;
}

int main(int argc, char **argv)
{
    const double m = 1.0e-3, g = 9.81, dt = 1.0e-5, e_target = 0.8, h0 = 0.1;
    const int n_steps = 10, max_contacts = 5, end = HERTZDAMP_END_OVERLAP;
    const double tc = n_steps * dt;
    double x = h0, v = 0.0, vh, a = -g, f, t = 0.0, t_on = 0.0;
    double k = 0.0, d = 0.0, u_in = 0.0, e_pred = 0.0, tc_pred = 0.0;
    int contacts = 0, in_contact = 0, status;
    long step;

    if (argc >= 5)
        return one_inversion(argc, argv);

    /* a contact without rebound: status HERTZDAMP_NO_REBOUND, e = 0, tc = DBL_MAX */
    status = hertzdamp_c_forward(1.0, 2.0, 1.0, 1.0, HERTZDAMP_END_OVERLAP, &e_pred, &tc_pred);
    printf("# k = 1, d = 2, m = 1, u = 1: status %d (%s), e = %g\n", status,
           hertzdamp_c_strerror(status), e_pred);

    printf("# C DEM: contact, u_in [m/s], k [N/m^1.5], d [kg/s], achieved v_out/u_in, "
           "steps in contact, predicted e, predicted T_c [s]\n");
    for (step = 1; step <= 10000000L; ++step) {
        vh = v + 0.5 * dt * a;        /* velocity Verlet: half kick, drift */
        x += dt * vh;
        t += dt;
        if (!in_contact && x < 0.0) { /* contact onset: parameters for this contact */
            in_contact = 1;
            ++contacts;
            t_on = t;
            u_in = -vh;
            status = hertzdamp_c_invert(e_target, tc, m, u_in, end, &k, &d);
            if (status != HERTZDAMP_OK) {
                fprintf(stderr, "hertzdamp_c_invert: %s\n", hertzdamp_c_strerror(status));
                return 1;
            }
            status = hertzdamp_c_forward(k, d, m, u_in, end, &e_pred, &tc_pred);
            if (status != HERTZDAMP_OK) {
                fprintf(stderr, "hertzdamp_c_forward: %s\n", hertzdamp_c_strerror(status));
                return 1;
            }
        }
        f = -m * g;                   /* force from the new position, half-step velocity */
        if (x < 0.0)
            f += k * pow(-x, 1.5) - d * vh;
        a = f / m;
        v = vh + 0.5 * dt * a;
        if (in_contact && x >= 0.0) { /* contact end: the overlap is back to zero */
            in_contact = 0;
            printf("contact %3d %.17g %.17g %.17g %.8f %5ld %.17g %.17g\n", contacts, u_in, k, d,
                   v / u_in, lround((t - t_on) / dt), e_pred, tc_pred);
            if (contacts >= max_contacts)
                break;
        }
    }
    return 0;
}
