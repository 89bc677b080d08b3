/*
 * hertzdamp.h: C interface of hertzdamp, the damped Hertzian normal collision.
 *
 *     m z'' = -d z' - k z^{3/2},  z(0) = 0,  z'(0) = u   (overlap z, THEORY.md)
 *
 * Link:  cc prog.c -I<prefix>/include -L<prefix>/lib -lhertzdamp -lgfortran -lm
 *   (or: cc prog.c $(pkg-config --cflags --libs --static hertzdamp))
 *
 * Every function returns a status: 0 (HD_OK) on success, otherwise one of the
 * codes below; hertzdamp_strerror() explains it.  Results are written through the
 * pointers, which must not be NULL (NULL gives HD_BAD_ARGUMENT).  The functions
 * keep no state and may be called from any number of threads at once.
 * Units: SI (kg, m, s); k in N m^-3/2, d in kg/s.
 */
#ifndef HERTZDAMP_H
#define HERTZDAMP_H

#ifdef __cplusplus
extern "C" {
#endif

/* Status codes (the values of the Fortran module hertzdamp_status; stable). */
#define HD_OK               0  /* success */
#define HD_NO_REBOUND       1  /* overlap end, alpha >= alpha_c: e = 0, contact time infinite */
#define HD_MAX_STEPS        2  /* integrator reached its step limit */
#define HD_STEP_UNDERFLOW   3  /* step size collapsed below round-off */
#define HD_BAD_ALPHA        4  /* alpha not finite or outside the supported range */
#define HD_BAD_END          5  /* contact-end definition not 0 (overlap) or 1 (force) */
#define HD_BAD_TOL          6  /* tolerance not in [1e-15, 1e-2] */
#define HD_BAD_MASS         7  /* mass not finite and positive */
#define HD_BAD_VELOCITY     8  /* impact velocity not finite and positive */
#define HD_BAD_STIFFNESS    9  /* stiffness not finite and positive */
#define HD_BAD_DAMPING     10  /* damping not finite and non-negative */
#define HD_BAD_TIME        11  /* contact time not finite and positive */
#define HD_BAD_RESTITUTION 12  /* restitution outside the supported range */
#define HD_OUT_OF_RANGE    13  /* a result overflows or underflows double precision */
#define HD_NOT_SUPPORTED   14  /* method does not support this contact-end definition */
#define HD_NO_CONVERGENCE  15  /* an iteration did not converge */
#define HD_BAD_ORDER       16  /* series order outside the stored range */
#define HD_BAD_KPHYS       17  /* physical stiffness bound not finite and positive */
#define HD_BAD_ARGUMENT    18  /* any other invalid argument (e.g. a NULL pointer) */
#define HD_OUTSIDE_VALIDITY 19 /* alpha outside the validity range of the method (series, pade, fit, compact) */

/* Contact-end definitions (argument `end`). */
#define HD_END_OVERLAP 0  /* contact ends when the overlap returns to zero */
#define HD_END_FORCE   1  /* contact ends when the total contact force returns to zero */

/*
 * Inverse problem (adaptive collision time): the Hertz stiffness *k [N m^-3/2] and
 * linear damping *d [kg/s] that give restitution coefficient e (1e-3 <= e <= 1 for the
 * overlap end, 1e-4 <= e <= 1 for the force end) and
 * contact time tc [s] to a contact of effective mass m [kg] hit at speed u [m/s],
 * with contact end `end` (HD_END_OVERLAP or HD_END_FORCE).
 * On failure *k = *d = 0.
 */
int hertzdamp_invert(double e, double tc, double m, double u, int end,
                     double *k, double *d);

/*
 * Forward problem: restitution coefficient *e and contact time *tc [s] of a contact
 * with stiffness k, damping d, effective mass m hit at speed u.
 * Without rebound (overlap end, too much damping): *e = 0, *tc = DBL_MAX and the
 * status is HD_NO_REBOUND.  On other failures *e = *tc = 0.
 */
int hertzdamp_forward(double k, double d, double m, double u, int end,
                      double *e, double *tc);

/*
 * A static, NUL-terminated English message for a status code (never NULL; do not
 * free it).  Unknown codes give "unknown status code".
 */
const char *hertzdamp_strerror(int status);

#ifdef __cplusplus
}
#endif

#endif /* HERTZDAMP_H */
