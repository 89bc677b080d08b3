/* hertzdamp LAMMPS plugin: rule settings, the per-contact rule, statistics and log. */
#include "hertzdamp_lammps.h"

#include "comm.h"
#include "error.h"
#include "universe.h"
#include "update.h"
#include "utils.h"

#include <cerrno>
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

double parse_double(LAMMPS *lmp, const char *what, const char *str)
{
  char *end = nullptr;
  errno = 0;
  double x = strtod(str, &end);
  if (end == str || *end != '\0' || errno == ERANGE || !std::isfinite(x))
    fail_all(lmp, __FILE__, __LINE__,
             std::string("hertzdamp: malformed value of ") + what + ": '" + str + "'");
  return x;
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
    nsteps = parse_double(lmp, "steps", arg[iarg + 1]);
    if (!(nsteps > 0.0)) fail_all(lmp, __FILE__, __LINE__, std::string(cmd) + ": steps must be > 0");
    return 2;
  }
  if (key == "tc") {
    need(1);
    tcmode = TC_TIME;
    tc = parse_double(lmp, "tc", arg[iarg + 1]);
    if (!(tc > 0.0)) fail_all(lmp, __FILE__, __LINE__, std::string(cmd) + ": tc must be > 0");
    return 2;
  }
  if (key == "fixed") {
    need(2);
    tcmode = TC_FIXED;
    kfix = parse_double(lmp, "fixed K", arg[iarg + 1]);
    dfix = parse_double(lmp, "fixed D", arg[iarg + 2]);
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
    vmin = parse_double(lmp, "vmin", arg[iarg + 1]);
    if (!(vmin >= 0.0)) fail_all(lmp, __FILE__, __LINE__, std::string(cmd) + ": vmin must be >= 0");
    return 2;
  }
  if (key == "phase") {
    need(1);
    const std::string v = arg[iarg + 1];
    if (v == "yes")
      phase = 1;
    else if (v == "no")
      phase = 0;
    else
      fail_all(lmp, __FILE__, __LINE__, std::string(cmd) + ": phase must be yes or no");
    return 2;
  }
  if (key == "log") {
    need(1);
    logfile = arg[iarg + 1];
    return 2;
  }
  return 0;
}

void RuleSettings::check(LAMMPS *lmp, const char *cmd) const
{
  if (ntimes == 0)
    fail_all(lmp, __FILE__, __LINE__, std::string(cmd) + ": one of steps N, tc T or fixed K D is required");
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
  s += std::string(", phase correction ") + (phase ? "yes" : "no");
  return s;
}

/* ---------------------------------------------------------------------- */

Onset contact_rule(LAMMPS *lmp, const RuleSettings &rs, double e, double kphys, double m,
                   double u_raw, double dt)
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
  int st;
  if (kphys > 0.0) {
    st = hertzdamp_c_invert_bounded(e, tc, m, o.u_used, kphys, rs.end, &o.k, &o.d);
    o.bounded = (st == HERTZDAMP_OK && o.k == kphys) ? 1 : 0;
  } else {
    st = hertzdamp_c_invert(e, tc, m, o.u_used, rs.end, &o.k, &o.d);
  }
  if (st != HERTZDAMP_OK)
    fail_one(lmp, __FILE__, __LINE__,
             std::string("hertzdamp: the rule failed at a contact onset (e ") + fmt_g(e) + ", tc " +
                 fmt_g(tc) + ", m " + fmt_g(m) + ", u " + fmt_g(o.u_used) +
                 "): " + hertzdamp_c_strerror(st));
  return o;
}

/* ---------------------------------------------------------------------- */

const char *ContactBook::stat_name(int i)
{
  static const char *names[NSTATS] = {"contacts", "u_min", "u_max", "k_min", "k_max",
                                      "d_min",    "d_max", "bounded", "ended", "e_min",
                                      "e_max",    "log_rows", "carried"};
  return (i >= 0 && i < NSTATS) ? names[i] : "?";
}

void ContactBook::reset()
{
  n_onset = n_bounded = n_end = carried = 0;
  umin = kmin = dmin = emin = 1e300;
  umax = kmax = dmax = emax = -1e300;
  logbuf.clear();
}

void ContactBook::finish(const double *p, double tag_a, double tag_b, double tend_steps,
                         double u_out, double dt)
{
  n_end += 1;
  const double e = p[P_UIN] > 0.0 ? u_out / p[P_UIN] : 0.0;
  lo_hi(emin, emax, e);
  if (logfile.empty()) return;
  const double row[LOG_NCOL] = {p[P_TON], tag_a,  tag_b,  p[P_M], p[P_UIN], p[P_UUSED], p[P_K],
                                p[P_D],   static_cast<double>(static_cast<int>(p[P_FLAGS]) & 1),
                                (tend_steps - p[P_TON]) * dt, u_out, e, tend_steps};
  logbuf.insert(logbuf.end(), row, row + LOG_NCOL);
}

void ContactBook::vector(LAMMPS *lmp, double *out) const
{
  double sums[5] = {n_onset, n_bounded, n_end, static_cast<double>(logbuf.size() / LOG_NCOL), carried};
  double mins[5] = {umin, kmin, dmin, emin, 0.0};
  double maxs[5] = {umax, kmax, dmax, emax, 0.0};
  double gs[5], gmin[5], gmax[5];
  MPI_Allreduce(sums, gs, 5, MPI_DOUBLE, MPI_SUM, lmp->world);
  MPI_Allreduce(mins, gmin, 5, MPI_DOUBLE, MPI_MIN, lmp->world);
  MPI_Allreduce(maxs, gmax, 5, MPI_DOUBLE, MPI_MAX, lmp->world);
  const bool none = gs[0] == 0.0;
  const bool none_ended = gs[2] == 0.0;
  out[0] = gs[0];
  out[1] = none ? 0.0 : gmin[0];
  out[2] = none ? 0.0 : gmax[0];
  out[3] = none ? 0.0 : gmin[1];
  out[4] = none ? 0.0 : gmax[1];
  out[5] = none ? 0.0 : gmin[2];
  out[6] = none ? 0.0 : gmax[2];
  out[7] = gs[1];
  out[8] = gs[2];
  out[9] = none_ended ? 0.0 : gmin[3];
  out[10] = none_ended ? 0.0 : gmax[3];
  out[11] = gs[3];
  out[12] = gs[4];
}

void ContactBook::open_log(LAMMPS *lmp, const std::string &file, const std::string &header)
{
  logfile = file;
  logbuf.clear();
  if (file.empty()) return;
  if (lmp->comm->me == 0) {
    FILE *fp = fopen(file.c_str(), "w");
    if (!fp) fail_one(lmp, __FILE__, __LINE__, "hertzdamp: cannot open log file " + file);
    fprintf(fp, "%s\n", header.c_str());
    fprintf(fp, "# t_on_step tag_i tag_j m u_in u_used k d bounded tc u_out e t_end_step\n");
    fclose(fp);
  }
}

void ContactBook::flush_log(LAMMPS *lmp)
{
  if (logfile.empty()) return;
  const int me = lmp->comm->me, nprocs = lmp->comm->nprocs;
  int n = static_cast<int>(logbuf.size());
  std::vector<int> counts(nprocs), displs(nprocs);
  MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, lmp->world);
  std::vector<double> all;
  if (me == 0) {
    int total = 0;
    for (int p = 0; p < nprocs; p++) {
      displs[p] = total;
      total += counts[p];
    }
    all.resize(total > 0 ? total : 1);
  }
  MPI_Gatherv(logbuf.data(), n, MPI_DOUBLE, all.data(), counts.data(), displs.data(), MPI_DOUBLE,
              0, lmp->world);
  logbuf.clear();
  if (me != 0) return;
  int total = displs[nprocs - 1] + counts[nprocs - 1];
  if (total == 0) return;
  FILE *fp = fopen(logfile.c_str(), "a");
  if (!fp) fail_one(lmp, __FILE__, __LINE__, "hertzdamp: cannot append to log file " + logfile);
  for (int r = 0; r < total; r += LOG_NCOL) {
    const double *row = &all[r];
    fprintf(fp, "%.17g %.0f %.0f", row[0], row[1], row[2]);
    for (int c = 3; c < LOG_NCOL; c++) fprintf(fp, " %.17g", row[c]);
    fprintf(fp, "\n");
  }
  fclose(fp);
}

void ContactBook::summary(LAMMPS *lmp, const char *who)
{
  double v[NSTATS];
  vector(lmp, v);
  std::string s = std::string(who) + ": " + fmt_g(v[0]) + " contacts (" + fmt_g(v[8]) +
                  " ended, " + fmt_g(v[7]) + " with k = k_phys)";
  if (v[0] > 0)
    s += ", u_in " + fmt_g(v[1]) + " .. " + fmt_g(v[2]) + ", k " + fmt_g(v[3]) + " .. " +
         fmt_g(v[4]) + ", d " + fmt_g(v[5]) + " .. " + fmt_g(v[6]);
  if (v[8] > 0) s += ", e " + fmt_g(v[9]) + " .. " + fmt_g(v[10]);
  logmesg(lmp, s + "\n");
}

}    // namespace HertzdampLammps
