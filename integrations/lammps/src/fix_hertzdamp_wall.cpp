/* fix hertzdamp/wall: see fix_hertzdamp_wall.h and README.md. */
#include "fix_hertzdamp_wall.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "memory.h"
#include "update.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace LAMMPS_NS::FixConst;

namespace HertzdampLammps {

FixHertzdampWall::FixHertzdampWall(LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg)
{
  const char *cmd = "fix hertzdamp/wall";
  bool have_e = false;
  double y = 0.0, nu = 0.0, yw = 0.0, nuw = 0.0;
  bool have_y = false, have_nu = false, have_yw = false, have_nuw = false;
  int iarg = 3;
  while (iarg < narg) {
    const std::string key = arg[iarg];
    const int used = rule.parse(lmp, cmd, narg, arg, iarg);
    if (used) {
      iarg += used;
      continue;
    }
    auto value = [&](const char *what) {
      if (iarg + 1 >= narg) fail_all(lmp, __FILE__, __LINE__, std::string(cmd) + ": " + what + " needs a value");
      return parse_double(lmp, what, arg[iarg + 1]);
    };
    if (key == "e") {
      e = value("e");
      have_e = true;
      iarg += 2;
    } else if (key == "youngs") {
      y = value("youngs"), have_y = true, iarg += 2;
    } else if (key == "poisson") {
      nu = value("poisson"), have_nu = true, iarg += 2;
    } else if (key == "wall_youngs") {
      yw = value("wall_youngs"), have_yw = true, iarg += 2;
    } else if (key == "wall_poisson") {
      nuw = value("wall_poisson"), have_nuw = true, iarg += 2;
    } else if (key == "xplane" || key == "yplane" || key == "zplane") {
      if (iarg + 2 >= narg) fail_all(lmp, __FILE__, __LINE__, std::string(cmd) + ": " + key + " needs LO HI");
      axis = key[0] - 'x';
      if (strcmp(arg[iarg + 1], "NULL") != 0) has_lo = 1, lo = parse_double(lmp, "wall lo", arg[iarg + 1]);
      if (strcmp(arg[iarg + 2], "NULL") != 0) has_hi = 1, hi = parse_double(lmp, "wall hi", arg[iarg + 2]);
      iarg += 3;
    } else {
      fail_all(lmp, __FILE__, __LINE__, std::string(cmd) + ": unknown keyword '" + key + "'");
    }
  }
  rule.check(lmp, cmd);
  if (!have_e || !(e > 0.0 && e <= 1.0)) fail_all(lmp, __FILE__, __LINE__, std::string(cmd) + ": e E with 0 < E <= 1 is required");
  if (axis < 0 || (!has_lo && !has_hi)) fail_all(lmp, __FILE__, __LINE__, std::string(cmd) + ": a wall (xplane|yplane|zplane LO HI) is required");
  if (has_lo && has_hi && !(lo < hi)) fail_all(lmp, __FILE__, __LINE__, std::string(cmd) + ": need LO < HI");
  if (have_y != have_nu || have_yw != have_nuw || (have_yw && !have_y))
    fail_all(lmp, __FILE__, __LINE__, std::string(cmd) + ": give youngs Y poisson NU (and optionally wall_youngs YW wall_poisson NUW)");
  if (have_y) {
    if (!have_yw) yw = y, nuw = nu;
    if (!(y > 0.0 && yw > 0.0 && nu > -1.0 && nu < 0.5 && nuw > -1.0 && nuw < 0.5))
      fail_all(lmp, __FILE__, __LINE__, std::string(cmd) + ": need youngs > 0 and -1 < poisson < 0.5");
    estar = effective_modulus(y, nu, yw, nuw);
  }
  if (rule.tcmode != TC_FIXED) {
    double alpha, tau;
    const int st = hertzdamp_c_pair(e, rule.end, &alpha, &tau);
    if (st != HERTZDAMP_OK) fail_all(lmp, __FILE__, __LINE__, std::string(cmd) + ": e " + fmt_g(e) + ": " + hertzdamp_c_strerror(st));
  }

  vector_flag = 1;
  size_vector = ContactBook::NSTATS;
  global_freq = 1;
  extvector = 0;
  maxexchange = NCOL;

  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  for (int i = 0; i < atom->nlocal; i++) set_arrays(i);
  book.open_log(lmp, rule.logfile, "# hertzdamp fix hertzdamp/wall " + rule.describe());
}

FixHertzdampWall::~FixHertzdampWall()
{
  if (atom) atom->delete_callback(id, Atom::GROW);
  memory->destroy(wst);
}

int FixHertzdampWall::setmask()
{
  return POST_FORCE | POST_RUN;
}

void FixHertzdampWall::init()
{
  if (!atom->radius_flag || !atom->rmass_flag) fail_all(lmp, __FILE__, __LINE__, "fix hertzdamp/wall requires atom_style sphere");
  logmesg(lmp, std::string("fix hertzdamp/wall ") + id + ": " + rule.describe() + "\n");
}

void FixHertzdampWall::post_force(int /*vflag*/)
{
  double **x = atom->x, **v = atom->v, **f = atom->f;
  const double *radius = atom->radius, *rmass = atom->rmass;
  const int *mask = atom->mask;
  const tagint *tag = atom->tag;
  const int nlocal = atom->nlocal;
  const double dt = update->dt;
  const double step = static_cast<double>(update->ntimestep);
  const bool force_end = rule.end == HERTZDAMP_END_FORCE;

  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    for (int side = 0; side < 2; side++) {
      if (side == 0 ? !has_lo : !has_hi) continue;
      const double dist = side == 0 ? x[i][axis] - lo : hi - x[i][axis];
      const double ov = radius[i] - dist;
      const double approach = side == 0 ? -v[i][axis] : v[i][axis];
      double *s = &wst[i][side * SLOT];
      double *p = s + 1;
      if (ov <= 0.0) {
        if (s[0] == 0.0) continue;
        const ContactEnd ce = payload_end(p, ov, -approach, step, force_end, rule.phase);
        const double fc = ce.f_end;
        book.finish(p, static_cast<double>(tag[i]), side == 0 ? -1.0 : -2.0, ce.tend, -approach + fc * dt / p[P_M], dt);
        f[i][axis] += side == 0 ? fc : -fc;
        s[0] = 0.0;
        continue;
      }
      double f_phase = 0.0;
      if (s[0] == 0.0) {
        // onset: first step with overlap > 0 for an atom without wall history
        const double m = rmass[i];
        const double kphys = estar > 0.0 ? 4.0 / 3.0 * estar * sqrt(radius[i]) : 0.0;
        const Onset o = contact_rule(lmp, rule, e, kphys, m, approach, dt);
        s[0] = 1.0;
        f_phase = payload_onset(p, o, approach, m, ov, step, dt, rule.phase);
        book.onset(o, approach);
      }
      const double fn = payload_force(p, ov, approach, step, force_end, f_phase);
      f[i][axis] += side == 0 ? fn : -fn;
    }
  }
}

void FixHertzdampWall::post_run()
{
  book.flush_log(lmp);
  book.summary(lmp, (std::string("fix hertzdamp/wall ") + id).c_str());
}

double FixHertzdampWall::compute_vector(int n)
{
  if (cache_step != update->ntimestep) {
    book.vector(lmp, cache);
    cache_step = update->ntimestep;
  }
  return cache[n];
}

void FixHertzdampWall::grow_arrays(int nmax)
{
  memory->grow(wst, nmax, NCOL, "hertzdamp/wall:wst");
}

void FixHertzdampWall::copy_arrays(int i, int j, int /*delflag*/)
{
  std::memcpy(wst[j], wst[i], sizeof(double) * NCOL);
}

void FixHertzdampWall::set_arrays(int i)
{
  for (int k = 0; k < NCOL; k++) wst[i][k] = 0.0;
}

int FixHertzdampWall::pack_exchange(int i, double *buf)
{
  std::memcpy(buf, wst[i], sizeof(double) * NCOL);
  return NCOL;
}

int FixHertzdampWall::unpack_exchange(int nlocal, double *buf)
{
  std::memcpy(wst[nlocal], buf, sizeof(double) * NCOL);
  return NCOL;
}

double FixHertzdampWall::memory_usage()
{
  return static_cast<double>(atom->nmax) * NCOL * sizeof(double);
}

}    // namespace HertzdampLammps
