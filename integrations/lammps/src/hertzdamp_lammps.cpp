/* hertzdamp LAMMPS plugin: rule settings, the per-contact rule, statistics and log. */
#include "hertzdamp_lammps.h"

#include "contact_models.h"

#include "comm.h"
#include "error.h"
#include "universe.h"
#include "update.h"
#include "utils.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mpi.h>

namespace HertzdampLammps {

void fail_all(LAMMPS *lmp, const char *file, int line, const std::string &msg)
{
  lmp->error->all(std::string(file), line, msg);
}

void fail_one(LAMMPS *lmp, const char *file, int line, const std::string &msg)
{
  lmp->error->one(std::string(file), line, msg);
}

void warn(LAMMPS *lmp, const char *file, int line, const std::string &msg)
{
  lmp->error->warning(std::string(file), line, msg);
}

void logmesg(LAMMPS *lmp, const std::string &msg)
{
  if (lmp->comm->me == 0) LAMMPS_NS::utils::logmesg(lmp, msg);
}

std::string fmt_g(double x)
{
  char buf[40];
  snprintf(buf, sizeof(buf), "%.17g", x);
  return buf;
}

double parse_number(LAMMPS *lmp, const std::string &cmd, const char *keyword, const char *str)
{
  if (!LAMMPS_NS::utils::is_double(str))
    fail_all(lmp, __FILE__, __LINE__,
             cmd + ": " + keyword + " needs a number, not '" + str + "'");
  const double x = LAMMPS_NS::utils::numeric(__FILE__, __LINE__, str, false, lmp);
  if (!std::isfinite(x))
    fail_all(lmp, __FILE__, __LINE__, cmd + ": " + keyword + " must be finite, not '" + str + "'");
  return x;
}

void check_poisson(LAMMPS *lmp, const std::string &cmd, const char *keyword, double nu)
{
  if (!(nu > -1.0 && nu <= 0.5))
    fail_all(lmp, __FILE__, __LINE__, cmd + ": " + keyword + " must be in (-1, 0.5], not " + fmt_g(nu));
}

/* ---------------------------------------------------------------------- */

int RuleSettings::parse(LAMMPS *lmp, const char *cmd, int narg, char **arg, int iarg)
{
  const std::string key = arg[iarg];
  auto need = [&](int n) {
    if (iarg + n >= narg)
      fail_all(lmp, __FILE__, __LINE__,
               std::string(cmd) + ": keyword '" + key + "' needs " + std::to_string(n) +
                   " value(s)");
  };
  if (key == "steps" || key == "tc" || key == "fixed") {
    if (++ntimes > 1)
      fail_all(lmp, __FILE__, __LINE__, std::string(cmd) + ": give only one of steps N, tc T, fixed K D");
  }
  if (key == "steps") {
    need(1);
    tcmode = TC_STEPS;
    const char *v = arg[iarg + 1];
    // any number utils::numeric() reads (20, 1e5, 100.0) whose value is whole
    nsteps = parse_number(lmp, cmd, "steps", v);
    if (std::floor(nsteps) != nsteps)
      fail_all(lmp, __FILE__, __LINE__,
               std::string(cmd) + ": steps N must be a whole number of time steps, not " + v);
    // the fewest N that reach e depend on e (pair_coeff) and the scheme: checked at the
    // run's start (pair_constants)
    if (!(nsteps >= 1.0)) fail_all(lmp, __FILE__, __LINE__, std::string(cmd) + ": steps must be >= 1, not " + v);
    return 2;
  }
  if (key == "tc") {
    need(1);
    tcmode = TC_TIME;
    tc = parse_number(lmp, cmd, "tc", arg[iarg + 1]);
    if (!(tc > 0.0)) fail_all(lmp, __FILE__, __LINE__, std::string(cmd) + ": tc must be > 0");
    return 2;
  }
  if (key == "fixed") {
    need(2);
    tcmode = TC_FIXED;
    kfix = parse_number(lmp, cmd, "fixed K", arg[iarg + 1]);
    dfix = parse_number(lmp, cmd, "fixed D", arg[iarg + 2]);
    if (!(kfix > 0.0) || !(dfix >= 0.0))
      fail_all(lmp, __FILE__, __LINE__, std::string(cmd) + ": fixed needs K > 0 and D >= 0");
    return 3;
  }
  if (key == "end") {
    need(1);
    const std::string v = arg[iarg + 1];
    if (v == "overlap")
      end = HERTZDAMP_END_OVERLAP;
    else if (v == "force")
      end = HERTZDAMP_END_FORCE;
    else
      fail_all(lmp, __FILE__, __LINE__, std::string(cmd) + ": end must be overlap or force");
    return 2;
  }
  if (key == "vmin") {
    need(1);
    vmin = parse_number(lmp, cmd, "vmin", arg[iarg + 1]);
    if (!(vmin >= 0.0)) fail_all(lmp, __FILE__, __LINE__, std::string(cmd) + ": vmin must be >= 0");
    return 2;
  }
  if (key == "phase") {
    need(1);
    const std::string v = arg[iarg + 1];
    if (v == "yes")
      phase = PHASE_YES;
    else if (v == "no")
      phase = PHASE_NO;
    else if (v == "exact")
      phase = PHASE_EXACT;
    else
      fail_all(lmp, __FILE__, __LINE__, std::string(cmd) + ": phase must be yes, no or exact");
    return 2;
  }
  if (key == "tangential_stiffness") {
    need(1);
    const std::string v = arg[iarg + 1];
    if (v == "adapted")
      kt_adapted = 1;
    else if (v == "physical")
      kt_adapted = 0;
    else
      fail_all(lmp, __FILE__, __LINE__, std::string(cmd) + ": tangential_stiffness must be adapted or physical");
    return 2;
  }
  if (key == "normal_correction") {
    need(1);
    const std::string v = arg[iarg + 1];
    if (v == "yes")
      normal_correction = 1;
    else if (v == "no")
      normal_correction = 0;
    else
      fail_all(lmp, __FILE__, __LINE__, std::string(cmd) + ": normal_correction must be yes or no");
    return 2;
  }
  if (key == "host") {
    need(1);
    const std::string v = arg[iarg + 1];
    if (v == "lammps")
      host = HOST_LAMMPS_MODE;
    else if (v == "none")
      host = HOST_NONE_MODE;
    else
      fail_all(lmp, __FILE__, __LINE__, std::string(cmd) + ": host must be lammps or none, not '" + v + "'");
    return 2;
  }
  if (key == "log") {
    need(1);
    logfile = arg[iarg + 1];
    if (logfile == "none") logfile.clear();    // log none: no per-contact log (the default)
    return 2;
  }
  return 0;
}

void RuleSettings::check(LAMMPS *lmp, const char *cmd) const
{
  if (ntimes == 0)
    fail_all(lmp, __FILE__, __LINE__, std::string(cmd) + ": one of steps N, tc T or fixed K D is required");
  if (phase == PHASE_EXACT && host == HOST_NONE_MODE)
    fail_all(lmp, __FILE__, __LINE__,
             std::string(cmd) + ": phase exact makes each contact exact in LAMMPS's integrator: it needs host lammps");
}

std::string RuleSettings::describe() const
{
  std::string s;
  if (tcmode == TC_STEPS)
    s = "contact time " + fmt_g(nsteps) + " steps";
  else if (tcmode == TC_TIME)
    s = "contact time " + fmt_g(tc);
  else
    s = "fixed k " + fmt_g(kfix) + " d " + fmt_g(dfix) + " (no rule)";
  s += std::string(", end ") + (end == HERTZDAMP_END_FORCE ? "force" : "overlap");
  s += ", vmin " + fmt_g(vmin);
  s += std::string(", phase ") + (phase == PHASE_YES ? "yes (onset/release force correction)"
                                  : phase == PHASE_EXACT ? "exact (per-contact constants from the onset phase)" : "no");
  if (tcmode != TC_FIXED) {
    s += std::string(", constants for host ") + scheme_name(pair_scheme());
    s += std::string(", tangential_stiffness ") + (kt_adapted ? "adapted" : "physical");
    s += std::string(", normal_correction ") + (normal_correction ? "yes" : "no");
  }
  return s;
}

/* ---------------------------------------------------------------------- */

const char *scheme_name(int scheme)
{
  switch (scheme) {
    case HERTZDAMP_HOST_NONE: return "none (the continuous model)";
    case HERTZDAMP_HOST_LAMMPS: return "lammps";
    case HERTZDAMP_HOST_LAMMPS_PHASE: return "lammps-phase";
    default: return "?";
  }
}

namespace {
std::string fmt_short(double x)
{
  char buf[40];
  snprintf(buf, sizeof(buf), "%.6g", x);
  return buf;
}
}    // namespace

bool pair_constants(LAMMPS *lmp, const RuleSettings &rs, double e, double dt, const std::string &who,
                    PairConstants &pc)
{
  if (rs.tcmode == TC_FIXED) return false;
  const double n = rs.steps_per_contact(dt);
  const int scheme = rs.pair_scheme();
  const int table = rs.phase_exact() ? 1 : 0;
  if (pc.valid && pc.e == e && pc.steps == n && pc.end == rs.end && pc.scheme == scheme && pc.table == table)
    return false;
  pc.valid = false;
  const std::string key = rs.tcmode == TC_STEPS
      ? "steps " + fmt_short(n)
      : "tc " + fmt_g(rs.tc) + " (" + fmt_short(n) + " time steps of " + fmt_g(dt) + ")";
  // below the fewest N of LAMMPS's scheme no constants reach e; with host none the
  // continuous constants would run anyway, so the same bound applies to them
  // phase exact: every onset phase must be reachable (hertzdamp_c_phase_min_steps)
  int st = table ? hertzdamp_c_pair_init_phase(e, HERTZDAMP_DAMPING_LINEAR, rs.end, scheme, n, &pc.pair)
                 : hertzdamp_c_pair_init(e, HERTZDAMP_DAMPING_LINEAR, rs.end, scheme, n, &pc.pair);
  bool too_few = st == HERTZDAMP_HOST_UNREACHABLE || st == HERTZDAMP_PHASE_UNREACHABLE ||
      (st == HERTZDAMP_BAD_STEPS && n < 2.0);
  int nmin = 0;
  const int st_min = (too_few || (st == HERTZDAMP_OK && scheme == HERTZDAMP_HOST_NONE))
      ? (table ? hertzdamp_c_phase_min_steps(e, HERTZDAMP_DAMPING_LINEAR, rs.end, scheme, &nmin)
               : hertzdamp_c_host_min_steps(e, HERTZDAMP_DAMPING_LINEAR, rs.end, rs.run_scheme(), &nmin))
      : HERTZDAMP_OK;
  if (st_min == HERTZDAMP_OK && nmin > 0 && n < nmin) too_few = true;
  if (too_few) {
    std::string msg = who + ": " + key + ": N = " + fmt_short(n) + " steps cannot reach e = " + fmt_short(e) +
        " with " + scheme_name(rs.run_scheme()) + (table ? " at every onset phase (phase exact): " +
        std::string(hertzdamp_c_strerror(st == HERTZDAMP_OK ? HERTZDAMP_PHASE_UNREACHABLE : st)) : "");
    msg += st_min == HERTZDAMP_OK ? "; N >= " + std::to_string(nmin) + " can"
                                  : std::string(" (") + hertzdamp_c_strerror(st_min) + ")";
    fail_all(lmp, __FILE__, __LINE__, msg);
  }
  if (st != HERTZDAMP_OK)
    fail_all(lmp, __FILE__, __LINE__,
             who + ": e " + fmt_short(e) + ", " + key + ", host " + scheme_name(scheme) + ": " +
                 hertzdamp_c_strerror(st) +
                 (st == HERTZDAMP_BAD_STEPS ? " (host none takes any N; LAMMPS's own error is then below 1/N)" : ""));
  // what LAMMPS achieves with them (zero when the library cannot tell, e.g. N > 1e5)
  if (hertzdamp_c_pair_stats(&pc.pair, rs.run_scheme(), pc.stats) != HERTZDAMP_OK)
    for (double &x : pc.stats) x = 0.0;
  if (table && pc.stats[0] > 0.0) {
    // phase exact: each contact has its own constants, whose e and T_c the library's init
    // checked within 1e-4 at every phase (doc/host-schemes.md section 6): the statistics are
    // those of the targets (the mean-exact constants' stats above are not what runs)
    const double st8[8] = {e, 0.0, e, e, 1.0, 0.0, 1.0, 1.0};
    for (int k = 0; k < 8; k++) pc.stats[k] = st8[k];
  }
  pc.table = table;
  pc.e = e;
  pc.steps = n;
  pc.end = rs.end;
  pc.scheme = scheme;
  pc.valid = true;
  // host none: say when LAMMPS's own error is beyond 1 % (the default host lammps removes it)
  if (scheme == HERTZDAMP_HOST_NONE && pc.stats[0] > 0.0 && std::fabs(pc.stats[0] / e - 1.0) > 0.01 &&
      lmp->comm->me == 0)
    warn(lmp, __FILE__, __LINE__,
         who + ": host none: with the continuous constants LAMMPS's integrator achieves e " +
             fmt_short(pc.stats[0]) + " on average for e = " + fmt_short(e) + " at N = " + fmt_short(n) +
             " (host lammps makes it exact)");
  return true;
}

void constants_stats(const PairConstants &pc, double *out)
{
  const double *s = pc.stats;
  const bool ok = pc.valid && s[0] > 0.0 && s[4] > 0.0;
  out[0] = ok ? s[0] : 0.0;
  out[1] = ok ? s[1] / s[0] : 0.0;
  out[2] = ok ? s[4] : 0.0;
  out[3] = ok ? s[5] / s[4] : 0.0;
}

std::string describe_constants(const RuleSettings &rs, const PairConstants &pc)
{
  if (!pc.valid) return "";
  const double *s = pc.stats;
  std::string t = "e " + fmt_short(pc.e) + ", host " + scheme_name(pc.scheme) + " at N = " + fmt_short(pc.steps);
  if (s[0] <= 0.0) return t + " (achieved e not known at this N)";
  if (pc.table == 1)
    return t + ": phase exact: per-contact constants from the onset phase (the library's table: each contact's e "
               "and T_c within 1e-4 of the targets at every phase)";
  auto pct = [](double x) { return fmt_short(100.0 * x) + " %"; };
  t += std::string(": ") + scheme_name(rs.run_scheme()) + " achieves e mean " + fmt_short(s[0]) + " (" +
       pct(s[0] / pc.e - 1.0) + "), spread " + pct(s[1] / s[0]) + " (" + fmt_short(s[2]) + " .. " +
       fmt_short(s[3]) + "), T_c mean " + fmt_short(s[4]) + " N dt, spread " + pct(s[5] / s[4]) +
       " over the onset phase";
  return t;
}

/* ---------------------------------------------------------------------- */

namespace {
// k and d of one pair's constants at the onset phase phi (0: the mean-exact constants)
int pair_kd_at(const PairConstants &pc, double tc, double m, double u, double kphys, double phi, double *k,
               double *d)
{
  return phi > 0.0 ? hertzdamp_c_pair_kd_phase(&pc.pair, tc, m, u, kphys, phi, k, d)
                   : hertzdamp_c_pair_kd(&pc.pair, tc, m, u, kphys, k, d);
}

// The node j of the correction (host constants at e' = j H), made on first use; false
// when it cannot be made (e' unreachable at this N).
bool correction_node(const RuleSettings &rs, double steps, CorrectionNodes &cn, int j)
{
  if (cn.made_for_steps != steps || cn.made_for_modes != static_cast<int>(rs.pack_modes()) ||
      cn.made_for_end != rs.end || cn.node.empty()) {
    cn.node.assign(CorrectionNodes::NODES + 1, PairConstants());
    cn.state.assign(CorrectionNodes::NODES + 1, 0);
    cn.made_for_steps = steps;
    cn.made_for_modes = static_cast<int>(rs.pack_modes());
    cn.made_for_end = rs.end;
  }
  if (j < 1 || j > CorrectionNodes::NODES) return false;
  if (cn.state[j] == 0) {
    const double ej = j == CorrectionNodes::NODES ? 1.0 : j * CorrectionNodes::H;
    PairConstants &pc = cn.node[j];
    const int scheme = rs.pair_scheme();
    const int st = rs.phase_exact()
        ? hertzdamp_c_pair_init_phase(ej, HERTZDAMP_DAMPING_LINEAR, rs.end, scheme, steps, &pc.pair)
        : hertzdamp_c_pair_init(ej, HERTZDAMP_DAMPING_LINEAR, rs.end, scheme, steps, &pc.pair);
    cn.state[j] = st == HERTZDAMP_OK ? 1 : -1;
    pc.valid = st == HERTZDAMP_OK;
    pc.e = ej;
  }
  return cn.state[j] == 1;
}

// k, d at target x from the linear interpolant between the nodes around x
bool interpolated_kd(const RuleSettings &rs, double steps, CorrectionNodes &cn, double x, double tc, double m,
                     double u, double kphys, double phi, double *k, double *d)
{
  const double t = x / CorrectionNodes::H;
  int j = static_cast<int>(std::floor(t));
  if (j >= CorrectionNodes::NODES) j = CorrectionNodes::NODES - 1;
  const double w = t - j;
  double k0, d0, k1, d1;
  if (!(w >= 0.0 && w <= 1.0) || !correction_node(rs, steps, cn, j) || !correction_node(rs, steps, cn, j + 1) ||
      pair_kd_at(cn.node[j], tc, m, u, kphys, phi, &k0, &d0) != HERTZDAMP_OK ||
      pair_kd_at(cn.node[j + 1], tc, m, u, kphys, phi, &k1, &d1) != HERTZDAMP_OK)
    return false;
  *k = k0 + w * (k1 - k0);
  *d = d0 + w * (d1 - d0);
  return true;
}
}    // namespace

double contact_kt(const RuleSettings &rs, int tang_model, double kt_phys, double k, double kphys)
{
  if (!rs.kt_adapted || rs.tcmode == TC_FIXED || !(kphys > 0.0) || !(kt_phys > 0.0)) return kt_phys;
  double kt = kt_phys;
  const int model = tang_model == TANG_LINEAR_HISTORY ? HERTZDAMP_TANGENTIAL_LINEAR_HISTORY : HERTZDAMP_TANGENTIAL_MINDLIN;
  if (hertzdamp_c_tangential_kt(model, kt_phys, k, kphys, &kt) != HERTZDAMP_OK) return kt_phys;
  return kt;
}

Onset contact_rule(LAMMPS *lmp, const RuleSettings &rs, const PairConstants &pc, double kphys, double m,
                   double u_raw, double dt, double ov, const ObliqueOnset *ob, CorrectionNodes *cn)
{
  Onset o;
  o.bounded = 0;
  o.u_used = u_raw > rs.vmin ? u_raw : rs.vmin;
  if (rs.tcmode == TC_FIXED) {
    o.k = rs.kfix;
    o.d = rs.dfix;
    return o;
  }
  if (!(o.u_used > 0.0))
    fail_one(lmp, __FILE__, __LINE__,
             "hertzdamp: contact onset with approach speed " + fmt_g(u_raw) +
                 " <= 0 (overlapping at creation, or grazing); set a speed floor with vmin V");
  const double tc = rs.contact_time(dt);
  if (rs.phase_exact()) {
    // the onset phase from the first overlap and the approach speed (a contact whose
    // approach speed was raised to vmin, or detected late, gets phi = 1)
    const int sp = u_raw > 0.0 ? hertzdamp_c_onset_phase(ov, u_raw, dt, &o.phi) : HERTZDAMP_BAD_VELOCITY;
    if (sp != HERTZDAMP_OK || o.u_used != u_raw) o.phi = 1.0;
  }
  int st = pair_kd_at(pc, tc, m, o.u_used, kphys, o.phi, &o.k, &o.d);
  if (st != HERTZDAMP_OK)
    fail_one(lmp, __FILE__, __LINE__,
             std::string("hertzdamp: the rule failed at a contact onset (e ") + fmt_g(pc.e) + ", tc " +
                 fmt_g(tc) + ", m " + fmt_g(m) + ", u " + fmt_g(o.u_used) +
                 (rs.phase_exact() ? ", onset phase " + fmt_g(o.phi) : std::string()) +
                 "): " + hertzdamp_c_strerror(st));
  // (not for a contact whose approach speed was raised to vmin: no free binary collision)
  if (ob && cn && rs.normal_correction && ob->vt > 0.0 && o.u_used == u_raw) {
    // the oblique normal correction: lambda = v_t^2 T_c / (u_n (R_1 + R_2)); the shift it
    // corrects is c lambda with c below 0.4 (about 0.4 (1 - e), doc/oblique.md): below
    // LAMBDA_MIN it is under 1e-4 and not solved for (the solve costs about 0.2 ms); above
    // 1 (grazing, resting contacts) the binary-collision model does not describe the contact
    constexpr double LAMBDA_MIN = 2.5e-4;
    const double lambda = ob->vt * ob->vt * tc / (o.u_used * (ob->r1 + ob->r2));
    if (lambda > LAMBDA_MIN && lambda <= 1.0) {
      const double speed = std::sqrt(o.u_used * o.u_used + ob->vt * ob->vt);
      const double angle = std::atan2(ob->vt, o.u_used) * 57.295779513082321;
      // the library's model scales k_t with its k: give it the k_t that yields, at the
      // uncorrected k, the one this contact uses (where no k_phys is known, a bound far
      // above k that never acts)
      const int model = ob->tangential;
      const double pw = model == HERTZDAMP_TANGENTIAL_LINEAR_HISTORY ? 0.8 : 1.0;
      const double kref = kphys > 0.0 ? kphys : o.k * 1e12;
      const int tmodel = model == HERTZDAMP_TANGENTIAL_LINEAR_HISTORY ? TANG_LINEAR_HISTORY : TANG_MINDLIN;
      const double kt_use = ob->mu > 0.0 ? contact_kt(rs, tmodel, ob->kt_phys, o.k, kphys) : 1.0;
      const double kt_arg = kt_use * std::pow(kref / o.k, pw);
      double out[4];
      const int sc = hertzdamp_c_oblique_correct(ob->m1, ob->r1, ob->m2, ob->r2, kref, HERTZDAMP_DAMPING_LINEAR,
                                                 rs.end, model, kt_arg, ob->xgammat, ob->mu,
                                                 HERTZDAMP_LEVER_CONTACT, pc.e, tc, speed, angle, out);
      o.corrected = -1;
      const double ep = out[3];
      // the host constants at e' from the nodes around it, as a difference to those at e
      // (k(e') = k(e) + k_lin(e') - k_lin(e), k_lin the linear interpolant between the
      // nodes): exact where e' = e, and the interpolation errors at e and e' cancel to first order
      double ka, da, kb, db;
      if (sc == HERTZDAMP_OK && ep > 0.0 && ep <= 1.0 && interpolated_kd(rs, pc.steps, *cn, ep, tc, m, o.u_used, kphys, o.phi, &ka, &da) &&
          interpolated_kd(rs, pc.steps, *cn, pc.e, tc, m, o.u_used, kphys, o.phi, &kb, &db)) {
        o.k += ka - kb;
        o.d += da - db;
        o.e_target = ep;
        o.corrected = 1;
      }
    }
  }
  o.bounded = (kphys > 0.0 && o.k == kphys) ? 1 : 0;
  return o;
}

/* ---------------------------------------------------------------------- */

const char *ContactBook::stat_name(int i)
{
  static const char *names[NSTATS + NEXTRA] = {"contacts", "u_min",   "u_max",   "k_min",    "k_max",
                                      "d_min",    "d_max",   "bounded", "ended",    "e_min",
                                      "e_max",    "log_rows", "carried", "isolated", "e_mean",
                                      "e_spread", "not_isolated", "e_median", "headon",
                                      "e_headon", "stock_wall"};
  return (i >= 0 && i < NSTATS + NEXTRA) ? names[i] : "?";
}

void ContactBook::reset()
{
  n_onset = n_bounded = n_end = n_iso = e_sum = e_sumsq = carried = 0;
  n_headon = e_headon = n_stockwall = 0;
  n_corrected = n_uncorrected = 0;
  ehist.assign(ENBIN, 0.0);
  umin = kmin = dmin = emin = 1e300;
  umax = kmax = dmax = emax = -1e300;
  logbuf.clear();
}

namespace {
// one row of the per-contact log: the doubles in their shortest form that reads back to
// the same value (std::to_chars; printf's %.17g cost the pour deck 25 % of its run time)
void write_row(FILE *fp, const double *row)
{
  char buf[LOG_NCOL * 32];
  char *p = buf, *end = buf + sizeof(buf);
  for (int c = 0; c < LOG_NCOL; c++) {
    if (c > 0) *p++ = ' ';
    const bool whole = c == 1 || c == 2 || c == LOG_NCOL - 1;    // atom IDs, isolated flag
    p = whole ? std::to_chars(p, end, static_cast<long long>(row[c])).ptr : std::to_chars(p, end, row[c]).ptr;
  }
  *p++ = '\n';
  fwrite(buf, 1, static_cast<size_t>(p - buf), fp);
}
}    // namespace

void ContactBook::finish(const double *p, double tag_a, double tag_b, double tend_steps,
                         double u_out, double dt)
{
  n_end += 1;
  // e from the normal speeds at the touch and release points
  const double e = p[P_UTOUCH] > 0.0 ? u_out / p[P_UTOUCH] : 0.0;
  const int flags = static_cast<int>(p[P_FLAGS]);
  if (flags & FLAG_STOCK_WALL) n_stockwall += 1;
  // a collision of its own: no other contact meanwhile, and an impact speed the rule saw
  // (not raised to vmin: a resting or grazing contact has no restitution coefficient)
  const bool isolated = !(flags & FLAG_NOT_ISOLATED) && std::isfinite(e) && p[P_UIN] > 0.0 &&
      p[P_UIN] >= p[P_UUSED];
  if (isolated) {
    n_iso += 1;
    e_sum += e;
    e_sumsq += e * e;
    lo_hi(emin, emax, e);
    if (ehist.size() != ENBIN) ehist.assign(ENBIN, 0.0);
    const double b = e / EBIN;
    ehist[b <= 0.0 ? 0 : b >= ENBIN - 1 ? ENBIN - 1 : static_cast<int>(b)] += 1.0;
    if (p[P_UTOUCH] >= COS_HEADON * p[P_VTOUCH]) {
      n_headon += 1;
      e_headon += e;
    }
  }
  if (logfile.empty()) return;
  const double row[LOG_NCOL] = {p[P_TON], tag_a,  tag_b,  p[P_M], p[P_UTOUCH], p[P_UUSED], p[P_K],
                                p[P_D],   static_cast<double>(flags & FLAG_BOUNDED),
                                (tend_steps - p[P_TON]) * dt, u_out, e, tend_steps,
                                isolated ? 1.0 : 0.0};
  if (rank0 && logfp) {
    write_row(logfp, row);    // streamed: errors are seen at the next flush
    rows_written += 1;
  } else {
    logbuf.insert(logbuf.end(), row, row + LOG_NCOL);
  }
}

void ContactBook::vector(LAMMPS *lmp, double *out) const
{
  enum { NSUM = 8, NEXT = 4 };
  double sums[NSUM] = {n_onset, n_bounded, n_end, static_cast<double>(logbuf.size() / LOG_NCOL) + rows_written,
                       carried, n_iso,     e_sum, e_sumsq};
  double mins[NEXT] = {umin, kmin, dmin, emin};
  double maxs[NEXT] = {umax, kmax, dmax, emax};
  double gs[NSUM], gmin[NEXT], gmax[NEXT];
  MPI_Allreduce(sums, gs, NSUM, MPI_DOUBLE, MPI_SUM, lmp->world);
  MPI_Allreduce(mins, gmin, NEXT, MPI_DOUBLE, MPI_MIN, lmp->world);
  MPI_Allreduce(maxs, gmax, NEXT, MPI_DOUBLE, MPI_MAX, lmp->world);
  const bool none = gs[0] == 0.0;
  const double niso = gs[5];
  out[0] = gs[0];
  out[1] = none ? 0.0 : gmin[0];
  out[2] = none ? 0.0 : gmax[0];
  out[3] = none ? 0.0 : gmin[1];
  out[4] = none ? 0.0 : gmax[1];
  out[5] = none ? 0.0 : gmin[2];
  out[6] = none ? 0.0 : gmax[2];
  out[7] = gs[1];
  out[8] = gs[2];
  out[9] = niso > 0 ? gmin[3] : 0.0;
  out[10] = niso > 0 ? gmax[3] : 0.0;
  out[11] = gs[3];
  out[12] = gs[4];
  out[13] = niso;
  const double mean = niso > 0 ? gs[6] / niso : 0.0;
  const double var = niso > 1 ? (gs[7] - niso * mean * mean) / (niso - 1) : 0.0;
  out[14] = mean;
  out[15] = var > 0.0 ? std::sqrt(var) : 0.0;
  out[16] = gs[2] - niso;
  // median e (from the histogram, to EBIN), near-head-on collisions and their mean e,
  // contacts left out because a bead touched a stock wall
  double ex[3] = {n_headon, e_headon, n_stockwall}, gx[3];
  MPI_Allreduce(ex, gx, 3, MPI_DOUBLE, MPI_SUM, lmp->world);
  std::vector<double> h(ENBIN, 0.0);
  if (ehist.size() == ENBIN) h = ehist;
  std::vector<double> gh(ENBIN, 0.0);
  MPI_Allreduce(h.data(), gh.data(), ENBIN, MPI_DOUBLE, MPI_SUM, lmp->world);
  double median = 0.0;
  if (niso > 0) {
    double below = 0.0;
    for (int b = 0; b < ENBIN; b++) {
      if (below + gh[b] >= 0.5 * niso) {
        median = (b + (0.5 * niso - below) / gh[b]) * EBIN;
        break;
      }
      below += gh[b];
    }
  }
  out[17] = median;
  out[18] = gx[0];
  out[19] = gx[0] > 0 ? gx[1] / gx[0] : 0.0;
  out[20] = gx[2];
}

namespace {
// Rank 0's I/O outcome on every rank: a failed log write stops the run everywhere.
void log_io_status(LAMMPS *lmp, int ok, const std::string &what, const std::string &file)
{
  const int err = errno;
  MPI_Bcast(&ok, 1, MPI_INT, 0, lmp->world);
  if (!ok)
    fail_all(lmp, __FILE__, __LINE__, "hertzdamp: log " + file + ": cannot " + what + " (" +
                 (lmp->comm->me == 0 ? std::string(strerror(err)) : std::string("see rank 0")) + ")");
}
}    // namespace

void ContactBook::close_log()
{
  if (logfp) fclose(logfp);
  logfp = nullptr;
}

void ContactBook::open_log(LAMMPS *lmp, const std::string &file, const std::string &header, bool append)
{
  close_log();
  logfile = file;
  logbuf.clear();
  rows_written = 0;
  rank0 = lmp->comm->me == 0;
  if (file.empty()) return;
  int ok = 1;
  if (rank0) {
    errno = 0;
    logfp = fopen(file.c_str(), append ? "a" : "w");
    if (!logfp) {
      ok = 0;
    } else {
      fprintf(logfp, "%s\n", header.c_str());
      fprintf(logfp, "# t_on_step tag_i tag_j m u_in u_used k d bounded tc u_out e t_end_step isolated\n");
      if (fflush(logfp) != 0 || ferror(logfp)) ok = 0;
    }
  }
  log_io_status(lmp, ok, "write", file);
}

void ContactBook::flush_log(LAMMPS *lmp)
{
  if (logfile.empty()) return;
  const int me = lmp->comm->me, nprocs = lmp->comm->nprocs;
  std::vector<double> all;
  int total = 0;
  if (nprocs > 1) {
    // the rows of the other ranks (rank 0 wrote its own as they came)
    int n = static_cast<int>(logbuf.size());
    std::vector<int> counts(nprocs), displs(nprocs);
    MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, lmp->world);
    if (me == 0) {
      for (int p = 0; p < nprocs; p++) {
        displs[p] = total;
        total += counts[p];
      }
      all.resize(total > 0 ? total : 1);
    }
    MPI_Gatherv(logbuf.data(), n, MPI_DOUBLE, all.data(), counts.data(), displs.data(), MPI_DOUBLE,
                0, lmp->world);
    logbuf.clear();
    logbuf.shrink_to_fit();
  }
  int ok = 1;
  if (me == 0) {
    errno = 0;
    if (!logfp) {
      ok = 0;
    } else {
      for (int r = 0; r < total; r += LOG_NCOL) write_row(logfp, &all[r]);
      if (fflush(logfp) != 0 || ferror(logfp)) ok = 0;
    }
    rows_written = 0;
  }
  log_io_status(lmp, ok, "append to", logfile);
}

void ContactBook::summary(LAMMPS *lmp, const char *who)
{
  double v[NSTATS + NEXTRA];
  vector(lmp, v);
  std::string s = std::string(who) + ": " + fmt_g(v[0]) + " contacts (" + fmt_g(v[8]) +
                  " ended, " + fmt_g(v[7]) + " with k = k_phys)";
  if (v[0] > 0)
    s += ", u_in " + fmt_g(v[1]) + " .. " + fmt_g(v[2]) + ", k " + fmt_g(v[3]) + " .. " +
         fmt_g(v[4]) + ", d " + fmt_g(v[5]) + " .. " + fmt_g(v[6]);
  if (v[8] > 0) {
    s += "; e over the " + fmt_g(v[13]) + " isolated binary collisions";
    if (v[13] > 0)
      s += ": mean " + fmt_g(v[14]) + ", spread " + fmt_g(v[15]) + ", " + fmt_g(v[9]) + " .. " +
           fmt_g(v[10]);
    if (v[13] > 0)
      s += ", median " + fmt_g(v[17]) + ", near head-on (< 15 degrees) " + fmt_g(v[18]) + " with mean " +
           fmt_g(v[19]);
    s += " (" + fmt_g(v[16]) + " contacts left out: other contacts at the same time (" + fmt_g(v[20]) +
         " of them with a stock wall), or impact speed below vmin)";
  }
  // the oblique normal correction: contacts it corrected, and those where the library's
  // solve failed (they keep the uncorrected constants)
  double nc[2] = {n_corrected, n_uncorrected}, ncall[2];
  MPI_Allreduce(nc, ncall, 2, MPI_DOUBLE, MPI_SUM, lmp->world);
  if (ncall[0] + ncall[1] > 0)
    s += "; oblique normal correction: " + fmt_g(ncall[0]) + " contacts corrected, " + fmt_g(ncall[1]) +
         " not (the library's solve failed: uncorrected constants)";
  logmesg(lmp, s + "\n");
}

}    // namespace HertzdampLammps
