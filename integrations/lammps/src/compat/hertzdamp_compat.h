/*
 * TEMPORARY shim: the C API names of the core library before the rename
 * (hertzdamp_invert/forward/strerror, HD_* macros) mapped onto the final names
 * that the plugin is written against (hertzdamp_c_*, HERTZDAMP_*).  Included only
 * when <hertzdamp.h> does not define HERTZDAMP_END_FORCE.  Delete this file once
 * main's header has the hertzdamp_c_* functions.
 */
#ifndef HERTZDAMP_LAMMPS_COMPAT_H
#define HERTZDAMP_LAMMPS_COMPAT_H

#include <cmath>

#define HERTZDAMP_OK HD_OK
#define HERTZDAMP_NO_REBOUND HD_NO_REBOUND
#define HERTZDAMP_END_OVERLAP HD_END_OVERLAP
#define HERTZDAMP_END_FORCE HD_END_FORCE

static inline int hertzdamp_c_invert(double e, double tc, double m, double u, int end, double *k,
                                     double *d)
{
  return hertzdamp_invert(e, tc, m, u, end, k, d);
}

/* k_phys bound (THEORY.md section 6): if k_phys <= k, k = k_phys and
   d = alpha m^{3/5} k_phys^{2/5} u^{1/5}, i.e. d scales with (k_phys/k)^{2/5}. */
static inline int hertzdamp_c_invert_bounded(double e, double tc, double m, double u,
                                             double k_phys, int end, double *k, double *d)
{
  if (!(k_phys > 0.0) || !std::isfinite(k_phys)) {
    *k = *d = 0.0;
    return HD_BAD_KPHYS;
  }
  int st = hertzdamp_invert(e, tc, m, u, end, k, d);
  if (st != HD_OK) return st;
  if (k_phys <= *k) {
    *d = *d * std::pow(k_phys / *k, 0.4);
    *k = k_phys;
  }
  return st;
}

/* alpha(e) and tau_c(alpha): with m = u = tc = 1, t* = 1/tau_c, k = tau_c^{5/2}, d = alpha tau_c. */
static inline int hertzdamp_c_pair(double e, int end, double *alpha, double *tau_c)
{
  double k, d;
  int st = hertzdamp_invert(e, 1.0, 1.0, 1.0, end, &k, &d);
  if (st != HD_OK) {
    *alpha = *tau_c = 0.0;
    return st;
  }
  *tau_c = std::pow(k, 0.4);
  *alpha = d / *tau_c;
  return st;
}

static inline int hertzdamp_c_forward(double k, double d, double m, double u, int end, double *e,
                                      double *tc)
{
  return hertzdamp_forward(k, d, m, u, end, e, tc);
}

static inline const char *hertzdamp_c_strerror(int status)
{
  return hertzdamp_strerror(status);
}

#endif
