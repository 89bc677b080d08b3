/*
 * hertzdamp.h: C interface of hertzdamp, the damped Hertzian normal collision.
 *
 *     m z'' = -d z' - k z^{3/2},  z(0) = 0,  z'(0) = u   (overlap z; doc/theory.md)
 *
 * Link (shared):  cc prog.c -I<prefix>/include -L<prefix>/lib -Wl,-rpath,<prefix>/lib -lhertzdamp
 * Link (static):  cc prog.c -I<prefix>/include <prefix>/lib/libhertzdamp.a -lgfortran -lm
 *   or pkg-config: $(pkg-config --cflags --libs hertzdamp), $(pkg-config --cflags --libs hertzdamp-static)
 *   or CMake:      find_package(hertzdamp CONFIG REQUIRED), target hertzdamp::hertzdamp
 *
 * Every function returns a status: 0 (HERTZDAMP_OK) on success, otherwise one of
 * the codes below; hertzdamp_c_strerror() explains it.  Results are written
 * through the pointers, which must not be NULL (NULL gives HERTZDAMP_BAD_ARGUMENT).
 * The functions keep no state and may be called from any number of threads at
 * once.  Units: SI (kg, m, s); k in N m^-3/2, d in kg/s.
 *
 * Aliasing (the _n calls): a result array may overlap an input array, in place (k
 * over e or m, d over tc or u, each element over the same element) or shifted (a
 * result array starting inside an input array at another element): the overlap is
 * detected and the inputs are copied first, so that the results are those of
 * separate arrays, bit for bit.  The result arrays must not overlap each other.
 * test/integration/capi_fuzz.sh and install_consumers.sh (alias.c) check both.
 *
 * Every C name starts with hertzdamp_c_ (macros with HERTZDAMP_): the legacy
 * Fortran externals (HERTZDAMP_INVERT ... -> hertzdamp_invert_) never collide
 * with them, not even under -fno-underscoring.
 */
#ifndef HERTZDAMP_H
#define HERTZDAMP_H

#ifdef __cplusplus
extern "C" {
#endif

/* BEGIN codes (gen/registry.py) */
/* GENERATED from data/registry.toml by gen/registry.py: edit the table, run `make registry`. */

/* The size of hertzdamp_pair_t in doubles (hertzdamp_c_pair_size() at run time). */
#define HERTZDAMP_PAIR_SIZE 256

/* Status codes (0: success; hertzdamp_c_strerror explains each; stable across versions). */
#define HERTZDAMP_OK                  0  /* success */
#define HERTZDAMP_NO_REBOUND          1  /* overlap end with alpha >= alpha_c: e = 0, tau_c = +inf */
#define HERTZDAMP_MAX_STEPS           2  /* integrator reached its step limit */
#define HERTZDAMP_STEP_UNDERFLOW      3  /* step size collapsed below round-off */
#define HERTZDAMP_BAD_ALPHA           4  /* alpha not finite or outside the supported range */
#define HERTZDAMP_BAD_END             5  /* contact-end definition not one of the end codes */
#define HERTZDAMP_BAD_TOL             6  /* tolerance not in [1e-15, 1e-2] */
#define HERTZDAMP_BAD_MASS            7  /* mass not finite and positive */
#define HERTZDAMP_BAD_VELOCITY        8  /* impact velocity not finite and positive */
#define HERTZDAMP_BAD_STIFFNESS       9  /* stiffness not finite and positive */
#define HERTZDAMP_BAD_DAMPING        10  /* damping not finite and non-negative */
#define HERTZDAMP_BAD_TIME           11  /* contact time not finite and positive */
#define HERTZDAMP_BAD_RESTITUTION    12  /* restitution outside the supported range */
#define HERTZDAMP_OUT_OF_RANGE       13  /* a result overflows or underflows double precision */
#define HERTZDAMP_NOT_SUPPORTED      14  /* method does not support this contact-end definition */
#define HERTZDAMP_NO_CONVERGENCE     15  /* an iteration did not converge */
#define HERTZDAMP_BAD_ORDER          16  /* series order outside the stored range */
#define HERTZDAMP_BAD_KPHYS          17  /* physical stiffness bound not finite and positive */
#define HERTZDAMP_BAD_ARGUMENT       18  /* any other invalid argument */
#define HERTZDAMP_OUTSIDE_VALIDITY   19  /* alpha outside the range where the method is valid */
#define HERTZDAMP_INACCURATE         20  /* the method's error estimate exceeds the accuracy asked */
#define HERTZDAMP_BAD_RADIUS         21  /* sphere radius not finite and positive */
#define HERTZDAMP_BAD_DENSITY        22  /* density not finite and positive */
#define HERTZDAMP_BAD_MODULUS        23  /* Young's modulus not finite and positive */
#define HERTZDAMP_BAD_POISSON        24  /* Poisson's ratio outside (-1, 0.5] */
#define HERTZDAMP_BAD_LAW            25  /* damping law not one of the law codes */
#define HERTZDAMP_BAD_HOST           26  /* host scheme not one of the host codes */
#define HERTZDAMP_BAD_STEPS          27  /* steps per contact (or step h) not finite or outside the allowed range */
#define HERTZDAMP_HOST_UNREACHABLE   28  /* no alpha reaches this e with the host at so few steps per contact */
#define HERTZDAMP_BAD_PAIR           29  /* pair not set by the pair init (or its failure), or changed since */
#define HERTZDAMP_PHASE_UNREACHABLE  30  /* some onset phase cannot reach e and T_c at so few steps */
#define HERTZDAMP_BAD_PHASE          31  /* onset phase not finite or outside (0, 1] */
#define HERTZDAMP_NO_PHASE_TABLE     32  /* the pair was initialised without its onset-phase table */
#define HERTZDAMP_BAD_TANGENTIAL     33  /* tangential model or its parameters invalid (model, k_t, x_gammat, friction, lever arm) */
#define HERTZDAMP_BAD_OBLIQUE        34  /* oblique-contact argument invalid (angle, radii, masses, tangential speed) */

/* Contact-end definitions (argument `end`). */
#define HERTZDAMP_END_OVERLAP 0  /* overlap: contact ends when the overlap returns to zero (the default) */
#define HERTZDAMP_END_FORCE   1  /* force: contact ends when the total contact force returns to zero */

/* Damping laws (argument `law`; doc/damping-laws.md): damping force d zeta^q zeta', d in kg s^-1 m^-q. */
#define HERTZDAMP_DAMPING_LINEAR        0  /* linear: q = 0: constant damping (the default) */
#define HERTZDAMP_DAMPING_TSUJI         1  /* tsuji: q = 1/4: Tsuji et al. 1992; d = gamma sqrt(m k) gives alpha = gamma */
#define HERTZDAMP_DAMPING_KUWABARA_KONO 2  /* kuwabara-kono: q = 1/2: Kuwabara and Kono 1987 (LAMMPS viscoelastic) */

/* Host time integrators (argument `host`; doc/host-schemes.md). */
#define HERTZDAMP_HOST_NONE         0  /* none: the continuous model: k, d exact for it */
#define HERTZDAMP_HOST_LAMMPS       1  /* lammps: LAMMPS / LIGGGHTS fix nve/sphere (velocity Verlet, damping from the half-step velocity) */
#define HERTZDAMP_HOST_MFIX_EULER   2  /* mfix-euler: MFiX DES_INTG_METHOD = 'EULER' (the same recurrence as lammps) */
#define HERTZDAMP_HOST_MFIX_AB2     3  /* mfix-ab2: MFiX DES_INTG_METHOD = 'ADAMS_BASHFORTH' */
#define HERTZDAMP_HOST_VERLET       4  /* verlet: the scene engine of this repository (velocity Verlet with onset/release corrections) */
#define HERTZDAMP_HOST_LAMMPS_PHASE 5  /* lammps-phase: lammps with the hertzdamp plugin's onset/release phase correction (phase yes) */

/* Tangential force models (argument `tangential`; doc/oblique.md). */
#define HERTZDAMP_TANGENTIAL_LINEAR_HISTORY 0  /* linear_history: F_t = -k_t xi - eta_t v_t, Coulomb-limited (LAMMPS tangential linear_history) */
#define HERTZDAMP_TANGENTIAL_MINDLIN        1  /* mindlin: F_t = -k_t a xi - eta_t v_t, a = sqrt(R* delta) (LAMMPS tangential mindlin) */

/* Torque lever arms of an oblique contact (argument `lever`; doc/oblique.md). */
#define HERTZDAMP_LEVER_RADIUS  0  /* radius: lever arm R (LAMMPS's wall code) */
#define HERTZDAMP_LEVER_CONTACT 1  /* contact: lever arm R - delta/2 (LAMMPS's pair styles) */
/* END codes */

/*
 * The constants of a material pair (set by hertzdamp_c_pair_init, read by the per-contact
 * calls): HERTZDAMP_PAIR_SIZE doubles, the same memory as the Fortran type
 * hertzdamp_pair_t and the legacy REAL(8) PAIR(HERTZDAMP_PAIR_SIZE) (hertzdamp.fi).  Treat it
 * as opaque: a pair that was not set by hertzdamp_c_pair_init, whose init failed, or of which
 * a part that a call reads was changed since, is refused (HERTZDAMP_BAD_PAIR).  Copying it
 * is fine.  hertzdamp_c_pair_size() gives the size at run time.
 */
typedef struct {
    double v[HERTZDAMP_PAIR_SIZE];
} hertzdamp_pair_t;

/* The size of hertzdamp_pair_t in doubles, as the library was built (HERTZDAMP_PAIR_SIZE). */
int hertzdamp_c_pair_size(void);

/*
 * Per-pair API (the fast path of a DEM host): once per material pair,
 * hertzdamp_c_pair_init with the target restitution e, the damping law, the contact
 * end, the host's time integrator (HERTZDAMP_HOST_*) and the steps per contact N
 * (T_c = N dt; not used by HERTZDAMP_HOST_NONE).  With a host scheme the constants are
 * those that make the phase-averaged e and contact time of the host's own N-step
 * collision exact; when no constants reach e at so few steps the status is
 * HERTZDAMP_HOST_UNREACHABLE (a larger N can).  On failure *p is invalid.
 * The host-exact constants hold only when every hertzdamp_c_pair_kd gets tc = N dt with
 * the dt the host integrates that contact with: a host that changes dt during a run
 * initialises the pair again (or keeps tc/dt = N).  An Adams-Bashforth host
 * (HERTZDAMP_HOST_MFIX_AB2) reads e one step after the first step without overlap.
 */
int hertzdamp_c_pair_init(double e, int law, int end, int host, double steps, hertzdamp_pair_t *p);

/*
 * Then at each contact onset: *k [N m^-3/2] and *d [kg s^-1 m^-q] for target contact
 * time tc = N dt [s], effective mass m [kg] and impact speed u [m/s] > 0, with the
 * physical-stiffness bound when k_phys > 0 (k_phys <= 0: no bound): where
 * k_phys <= k the contact keeps *k = k_phys (it then lasts longer than tc).  The same
 * numbers as hertzdamp_c_invert_law for HERTZDAMP_HOST_NONE, bit for bit.  On failure
 * *k = *d = 0.
 */
int hertzdamp_c_pair_kd(const hertzdamp_pair_t *p, double tc, double m, double u, double k_phys,
                        double *k, double *d);

/*
 * What a pair's constants achieve in the host scheme `host` (HERTZDAMP_HOST_*, not
 * necessarily the pair's own) at the pair's N steps per contact, over the onset phase:
 * stats[0..3] = mean, standard deviation, min and max of e; stats[4..7] = the same of
 * the contact time in units of the target T_c = N dt (HERTZDAMP_HOST_NONE: the
 * continuous model, no spread).  A host-exact pair run by its own scheme gives
 * stats[0] = e and stats[4] = 1; a
 * HERTZDAMP_HOST_NONE pair run by a scheme shows that scheme's error.  Costs about one
 * hertzdamp_c_pair_init: call it once per pair, not per contact.  On failure stats = 0.
 */
int hertzdamp_c_pair_stats(const hertzdamp_pair_t *p, int host, double stats[8]);

/*
 * The fewest whole steps per contact N for which hertzdamp_c_pair_init succeeds with
 * this (e, law, end, host) (HERTZDAMP_HOST_NONE: 2), for a message such as "N = 3 steps
 * cannot reach e = 0.5 with lammps; N >= 6 can".  HERTZDAMP_HOST_UNREACHABLE when no N up
 * to 1024 can; bad input as hertzdamp_c_pair_init.  On failure *n_min = 0.
 */
int hertzdamp_c_host_min_steps(double e, int law, int end, int host, int *n_min);

/*
 * Per-contact constants from the onset phase (issue 32; doc/host-schemes.md section 6).
 * hertzdamp_c_pair_init_phase: hertzdamp_c_pair_init plus the pair's onset-phase table
 * (in the same HERTZDAMP_PAIR_SIZE doubles), per-contact constants that make each
 * contact's own e exact in the host scheme, not only their mean over the phase, and its
 * contact time N dt to within 2.5e-5/N relative (every release is kept 1e-5 of a step or
 * more off a step boundary: doc/host-schemes.md 6.1, the tie); HERTZDAMP_PHASE_UNREACHABLE when some onset phase has none at this N
 * (hertzdamp_c_phase_min_steps gives the fewest N that works).  The header keeps the
 * mean-exact constants: hertzdamp_c_pair_kd gives the same bits with or without the table.
 */
int hertzdamp_c_pair_init_phase(double e, int law, int end, int host, double steps, hertzdamp_pair_t *p);

/*
 * At each contact onset: the onset phase phi = delta1 / (u dt) from the first positive
 * overlap delta1 [m], the approach speed u [m/s] and the time step dt [s]; a contact
 * detected late (phi > 1) gets phi = 1.  HERTZDAMP_BAD_PHASE for delta1 not finite and
 * positive.  On failure *phi = 0.
 */
int hertzdamp_c_onset_phase(double delta1, double u, double dt, double *phi);

/*
 * Then *k and *d of that contact as hertzdamp_c_pair_kd, with the constants of its onset
 * phase phi in (0, 1] (HERTZDAMP_BAD_PHASE otherwise; HERTZDAMP_NO_PHASE_TABLE for a pair
 * initialised without the table).  k_phys <= 0: no bound; where k_phys <= k the contact
 * keeps *k = k_phys and lasts longer than N steps.  On failure *k = *d = 0.
 */
int hertzdamp_c_pair_kd_phase(const hertzdamp_pair_t *p, double tc, double m, double u, double k_phys,
                              double phi, double *k, double *d);

/* The fewest whole N for which hertzdamp_c_pair_init_phase succeeds (every onset phase
   reachable); HERTZDAMP_PHASE_UNREACHABLE when none up to 1024 does; on failure *n_min = 0. */
int hertzdamp_c_phase_min_steps(double e, int law, int end, int host, int *n_min);

/*
 * Inverse problem (adaptive collision time): the Hertz stiffness *k [N m^-3/2] and
 * linear damping *d [kg/s] that give restitution coefficient e (1e-3 <= e <= 1 for
 * the overlap end, 1e-4 <= e <= 1 for the force end) and contact time tc [s] to a
 * contact of effective mass m [kg] hit at relative normal speed u [m/s] > 0, with
 * contact end `end`.  On failure *k = *d = 0.
 */
int hertzdamp_c_invert(double e, double tc, double m, double u, int end,
                       double *k, double *d);

/*
 * hertzdamp_c_invert with the physical-stiffness bound k_phys = (4/3) E* sqrt(R*):
 * where k_phys <= k the contact keeps *k = k_phys and
 * *d = alpha m^{3/5} k_phys^{2/5} u^{1/5} (it is then longer than tc).
 */
int hertzdamp_c_invert_bounded(double e, double tc, double m, double u, double k_phys,
                               int end, double *k, double *d);

/*
 * hertzdamp_c_invert for n contacts: status[i] is the status of contact i.  Returns
 * HERTZDAMP_OK when all succeeded, else the first non-zero status.  Aliasing: see
 * the top of this file.  (The same for hertzdamp_c_invert_law_n.)
 */
int hertzdamp_c_invert_n(int n, const double *e, const double *tc, const double *m,
                         const double *u, int end, double *k, double *d, int *status);

/*
 * The constants of a material pair: *alpha = alpha(e) and *tau_c = tau_c(alpha(e)),
 * which depend only on e and the contact end.  Per contact (mass m, speed u,
 * contact time T_c):  k = m (tau_c/T_c)^{5/2} u^{-1/2},  d = alpha m tau_c/T_c.
 */
int hertzdamp_c_pair(double e, int end, double *alpha, double *tau_c);

/*
 * Forward problem: restitution coefficient *e and contact time *tc [s] of a contact
 * with stiffness k, damping d, effective mass m hit at speed u.
 * Without rebound (overlap end, too much damping): *e = 0, *tc = DBL_MAX and the
 * status is HERTZDAMP_NO_REBOUND.  On other failures *e = *tc = 0.
 */
int hertzdamp_c_forward(double k, double d, double m, double u, int end,
                        double *e, double *tc);

/*
 * The damping laws (HERTZDAMP_DAMPING_*; doc/damping-laws.md): the same calls for the
 * damping force d zeta^q zeta', q = 0 (linear), 1/4 (tsuji), 1/2 (kuwabara-kono),
 * d in kg s^-1 m^-q.  The restitution range of the inverse is [1e-4, 1] for tsuji and
 * kuwabara-kono (both ends).
 *
 * Inverse with the law, and the physical-stiffness bound when k_phys > 0 (k_phys = 0:
 * no bound): with the bound active *k = k_phys and
 * *d = alpha m^{(3-2q)/5} k_phys^{(2+2q)/5} u^{(1-4q)/5} (tsuji: alpha sqrt(m k_phys)).
 */
int hertzdamp_c_invert_law(double e, double tc, double m, double u, double k_phys,
                           int law, int end, double *k, double *d);

/*
 * hertzdamp_c_invert_law without the bound (k_phys = 0) for n contacts, vectorised:
 * status[i] is the status of contact i, the results those of n calls, bit for bit.
 * Returns HERTZDAMP_OK when all succeeded, else the first non-zero status.
 */
int hertzdamp_c_invert_law_n(int n, const double *e, const double *tc, const double *m,
                             const double *u, int law, int end, double *k, double *d,
                             int *status);

/*
 * Material-pair constants of the law: per contact t* = T_c / tau_c,
 * k = m t*^{-5/2} u^{-1/2},  d = alpha m t*^{-1} (u t*)^{-q}.
 */
int hertzdamp_c_pair_law(double e, int law, int end, double *alpha, double *tau_c);

/*
 * Forward problem of the law (d in kg s^-1 m^-q); no rebound as hertzdamp_c_forward.
 */
int hertzdamp_c_forward_law(double k, double d, double m, double u, int law, int end,
                            double *e, double *tc);

/*
 * A static, NUL-terminated English message for a status code (never NULL; do not
 * free it).  Unknown codes give "unknown status code".
 */
const char *hertzdamp_c_strerror(int status);

/* ==================================================================== the oblique contact (doc/oblique.md) */

/* The tangential stiffness of a softened contact (normal stiffness k instead of k_phys)
 * whose outcome is a time-stretched copy of the physical one: mindlin
 * kt_phys k/k_phys, linear_history kt_phys (k/k_phys)^(4/5) (exact on a wall with the
 * lever arm R).  eta_t = x_gammat d needs no change.  NULL kt: HERTZDAMP_BAD_ARGUMENT.
 */
int hertzdamp_c_tangential_kt(int tangential, double kt_phys, double k, double k_phys, double *kt);

/*
 * The oblique impact of sphere 1 (m1, r1) on sphere 2 at rest (m2 = r2 = 0: a wall) at
 * speed [m/s] and angle [degrees from the normal]: out = e_n, e_t (contact point),
 * vt_ratio (centres), rebound angle [degrees], omega1, omega2 [rad/s], sliding fraction,
 * contact time [s]; 0 on failure.  tangential HERTZDAMP_TANGENTIAL_*, lever
 * HERTZDAMP_LEVER_*.
 */
int hertzdamp_c_oblique_impact(double m1, double r1, double m2, double r2, double k, double d,
                               int law, int end, int tangential, double kt, double xgammat, double mu,
                               int lever, double speed, double angle, double out[8]);

/*
 * The oblique normal correction of one contact: the k, d (at contact time tc, with the
 * bound k_phys) of the corrected target e' for which the oblique e_n equals e, and the
 * k_t scaled to that k; out = k, d, k_t, e' (0 on failure).  On a wall or head-on:
 * e' = e with no oblique solve (exact).  Two spheres: a secant solve over fast solves of
 * the oblique contact (a few per call): e_n within 2e-5 of e, e' within 4e-5 of the full
 * solve (doc/oblique.md section 4).
 */
int hertzdamp_c_oblique_correct(double m1, double r1, double m2, double r2, double k_phys,
                                int law, int end, int tangential, double kt_phys, double xgammat,
                                double mu, int lever, double e, double tc, double speed, double angle,
                                double out[4]);

/* ==================================================================== for bindings (issue 35)
 * (ptrdiff_t: <stddef.h>, included here to keep this block in one place)
 * The Python package's entry points; a binding reads every code and size from the
 * library through them rather than from the #defines above.
 *
 * Registries: the names of an enumeration in the order of their codes.  kind is one of
 * "law", "end", "host" (the HERTZDAMP_DAMPING_, _END_, _HOST_ codes), "method" (the
 * forward methods of hertzdamp_c_forward_array: fit, rk45, ...), "tangential", "lever"
 * (the HERTZDAMP_TANGENTIAL_, _LEVER_ codes), "status" (the status
 * codes, lower case with dashes: "ok", "no-rebound", "bad-mass", ...), "stats" (the
 * fields of hertzdamp_c_pair_stats, codes their index) and "size" ("pair": the doubles
 * of hertzdamp_pair_t; "stats": those of hertzdamp_c_pair_stats).  An unknown kind or
 * name, NULL, or a buffer too short gives HERTZDAMP_BAD_ARGUMENT (*code = -1, buf = "").
 */
#include <stddef.h>
int hertzdamp_c_code(const char *kind, const char *name, int *code);
int hertzdamp_c_names(const char *kind, char *buf, int len);   /* "linear tsuji kuwabara-kono" */

/*
 * Array entry points with strides.  An input x with stride s (in elements, s >= 0) gives
 * contact i (from 0) the value x[i*s]: s = 1 one value per contact, s = 0 one value for
 * all (a broadcast without a copy).  The results are contiguous arrays of n and must
 * not overlap an input.  Each returns HERTZDAMP_OK when every contact succeeded, else
 * the first non-zero status (status[i] is contact i's); n <= 0 does nothing; a NULL
 * array that is required, or a negative stride, gives HERTZDAMP_BAD_ARGUMENT and
 * touches nothing.  The results are those of the scalar calls named, bit for bit.
 */

/* hertzdamp_c_invert_law for n contacts by the fit.  k_phys NULL: no bound (else each
   finite and positive).  steps NULL: the continuous constants (host must be
   HERTZDAMP_HOST_NONE); else those of hertzdamp_c_pair_init(e, law, end, host, steps),
   one init per run of equal e and steps, then hertzdamp_c_pair_kd (a failed init gives
   its status to its contacts).  On failure k = d = 0. */
int hertzdamp_c_invert_array(ptrdiff_t n, const double *e, ptrdiff_t se, const double *tc, ptrdiff_t stc,
                             const double *m, ptrdiff_t sm, const double *u, ptrdiff_t su,
                             const double *k_phys, ptrdiff_t skp, const double *steps, ptrdiff_t ss,
                             int law, int end, int host, double *k, double *d, int *status);

/* hertzdamp_c_forward_law for n contacts by the method of code `method` (the "method"
   registry; the fit is hertzdamp_c_forward_law's).  tol (rk45), order (series) and
   accuracy (series, pade): 0 for the library's default.  No rebound: e = 0,
   tc = DBL_MAX, HERTZDAMP_NO_REBOUND; other failures e = tc = 0. */
int hertzdamp_c_forward_array(ptrdiff_t n, const double *k, ptrdiff_t sk, const double *d, ptrdiff_t sd,
                              const double *m, ptrdiff_t sm, const double *u, ptrdiff_t su,
                              int law, int end, int method, double tol, int order, double accuracy,
                              double *e, double *tc, int *status);

/* hertzdamp_c_pair_kd of one pair for n contacts (k_phys NULL: no bound, else each
   finite and positive). */
int hertzdamp_c_pair_kd_array(ptrdiff_t n, const hertzdamp_pair_t *p, const double *tc, ptrdiff_t stc,
                              const double *m, ptrdiff_t sm, const double *u, ptrdiff_t su,
                              const double *k_phys, ptrdiff_t skp, double *k, double *d, int *status);

/* The alpha and tau_c of a pair's k, d formulas (a host: alpha_N, tau_N);
   HERTZDAMP_BAD_PAIR (and 0) for a pair not set by hertzdamp_c_pair_init. */
int hertzdamp_c_pair_constants(const hertzdamp_pair_t *p, double *alpha, double *tau_c);

/* The contact of two spheres (wall = 0) or of a sphere and a wall (wall != 0: radius2,
   density2 not read, may be NULL; youngs2, poisson2 the wall's) from material data, as
   the program's contact options: effective mass [kg], effective radius [m],
   k_phys = (4/3) E* sqrt(R*), and the shorter Rayleigh time of the spheres with its time
   step (hertzdamp_rayleigh_fraction of it; 0 where not representable; both may be NULL).
   On failure m_eff = r_eff = k_phys = 0. */
int hertzdamp_c_contact_array(ptrdiff_t n, const double *radius, ptrdiff_t sr, const double *density, ptrdiff_t srho,
                              const double *youngs, ptrdiff_t sy, const double *poisson, ptrdiff_t snu,
                              const double *radius2, ptrdiff_t sr2, const double *density2, ptrdiff_t srho2,
                              const double *youngs2, ptrdiff_t sy2, const double *poisson2, ptrdiff_t snu2,
                              int wall, double *m_eff, double *r_eff, double *k_phys, double *t_rayleigh,
                              double *dt_rayleigh, int *status);

/* The physical contact (k = k_phys, d from e) as the program's `timestep` computes it:
   alpha and tau_c of e (steps NULL: the continuous constants by the fit; else those of
   hertzdamp_c_pair_init with the host at steps N), the damped contact time
   t*(k_phys, m, u) tau_c and the elastic Hertz time [s]; the time steps are these / N.
   On failure every result is 0. */
int hertzdamp_c_timestep_array(ptrdiff_t n, const double *e, ptrdiff_t se, const double *steps, ptrdiff_t ss,
                               const double *m, ptrdiff_t sm, const double *k_phys, ptrdiff_t skp,
                               const double *u, ptrdiff_t su, int law, int end, int host,
                               double *alpha, double *tau_c, double *tc_damped, double *tc_elastic, int *status);
/* ==================================================================== end of the bindings block */

#ifdef __cplusplus
}
#endif

#endif /* HERTZDAMP_H */
