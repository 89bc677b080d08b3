/* fix hertzdamp/wall: see fix_hertzdamp_wall.h and README.md. */
#include "fix_hertzdamp_wall.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "pair.h"
#include "update.h"

#include <cmath>
#include <cstring>

#include "pair_granular_hertzdamp.h"

using namespace LAMMPS_NS;
using namespace LAMMPS_NS::FixConst;

namespace HertzdampLammps {

namespace {
const char *CMD = "fix hertzdamp/wall";
}

FixHertzdampWall::FixHertzdampWall(LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg)
{
  bool have_e = false;
  double y = 0.0, nu = 0.0, yw = 0.0, nuw = 0.0;
  bool have_y = false, have_nu = false, have_yw = false, have_nuw = false;
  int iarg = 3;
  while (iarg < narg) {
    const std::string key = arg[iarg];
    int used = rule.parse(lmp, CMD, narg, arg, iarg);
    if (!used) used = fm.parse(lmp, CMD, narg, arg, iarg);
    if (used) {
      iarg += used;
      continue;
    }
    auto value = [&]() {
      if (iarg + 1 >= narg) fail_all(lmp, __FILE__, __LINE__, std::string(CMD) + ": " + key + " needs a value");
      return parse_number(lmp, CMD, key.c_str(), arg[iarg + 1]);
    };
    if (key == "e") {
      e = value(), have_e = true, iarg += 2;
    } else if (key == "youngs") {
      y = value(), have_y = true, iarg += 2;
    } else if (key == "poisson") {
      nu = value(), have_nu = true, iarg += 2;
      check_poisson(lmp, CMD, "poisson", nu);
    } else if (key == "wall_youngs") {
      yw = value(), have_yw = true, iarg += 2;
    } else if (key == "wall_poisson") {
      nuw = value(), have_nuw = true, iarg += 2;
      check_poisson(lmp, CMD, "wall_poisson", nuw);
    } else if (key == "xplane" || key == "yplane" || key == "zplane") {
      if (axis >= 0)
        fail_all(lmp, __FILE__, __LINE__,
                 std::string(CMD) + ": one wall per fix (" + "xyz"[axis] + "plane and " + key +
                     "): define a second fix for the second wall");
      if (iarg + 2 >= narg) fail_all(lmp, __FILE__, __LINE__, std::string(CMD) + ": " + key + " needs LO HI");
      axis = key[0] - 'x';
      if (strcmp(arg[iarg + 1], "NULL") != 0) has_lo = 1, lo = parse_number(lmp, CMD, (key + " LO").c_str(), arg[iarg + 1]);
      if (strcmp(arg[iarg + 2], "NULL") != 0) has_hi = 1, hi = parse_number(lmp, CMD, (key + " HI").c_str(), arg[iarg + 2]);
      iarg += 3;
    } else {
      fail_all(lmp, __FILE__, __LINE__, std::string(CMD) + ": unknown keyword '" + key + "'");
    }
  }
  rule.check(lmp, CMD);
  if (!have_e || !(e > 0.0 && e <= 1.0)) fail_all(lmp, __FILE__, __LINE__, std::string(CMD) + ": e E with 0 < E <= 1 is required");
  if (axis < 0 || (!has_lo && !has_hi)) fail_all(lmp, __FILE__, __LINE__, std::string(CMD) + ": a wall (xplane|yplane|zplane LO HI) is required");
  if (has_lo && has_hi && !(lo < hi)) fail_all(lmp, __FILE__, __LINE__, std::string(CMD) + ": need LO < HI");
  if (have_y != have_nu || have_yw != have_nuw || (have_yw && !have_y))
    fail_all(lmp, __FILE__, __LINE__, std::string(CMD) + ": give youngs Y poisson NU (and optionally wall_youngs YW wall_poisson NUW)");
  if (have_y) {
    if (!have_yw) yw = y, nuw = nu;
    if (!(y > 0.0 && yw > 0.0)) fail_all(lmp, __FILE__, __LINE__, std::string(CMD) + ": youngs and wall_youngs must be > 0");
    estar = effective_modulus(y, nu, yw, nuw);
    gstar = effective_shear_modulus(y, nu, yw, nuw);
  }
  fm.check(lmp, CMD, have_y);
  if (rule.tcmode != TC_FIXED) {
    double alpha, tau;
    const int st = hertzdamp_c_pair(e, rule.end, &alpha, &tau);
    if (st != HERTZDAMP_OK) fail_all(lmp, __FILE__, __LINE__, std::string(CMD) + ": e " + fmt_g(e) + ": " + hertzdamp_c_strerror(st));
  }

  vector_flag = 1;
  size_vector = ContactBook::NSTATS + NHOSTSTATS + ContactBook::NEXTRA;
  global_freq = 1;
  extvector = 0;
  maxexchange = NCOL;
  restart_peratom = 1;     // the wall contacts go into restart files
  create_attribute = 1;    // atoms inserted during a run (fix pour) start without contacts

  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
  for (int i = 0; i < atom->nlocal; i++) set_arrays(i);
  book.open_log(lmp, rule.logfile, "# hertzdamp fix hertzdamp/wall " + rule.describe());
}

FixHertzdampWall::~FixHertzdampWall()
{
  if (atom) {
    atom->delete_callback(id, Atom::GROW);
    atom->delete_callback(id, Atom::RESTART);
  }
  memory->destroy(wst);
}

int FixHertzdampWall::setmask()
{
  return POST_FORCE | POST_RUN | (rule.logfile.empty() ? 0 : END_OF_STEP);
}

// the per-contact log, streamed: the rows of all ranks written every LOG_FLUSH_EVERY steps
void FixHertzdampWall::end_of_step()
{
  book.flush_log_every(lmp, update->ntimestep);
}

void FixHertzdampWall::init()
{
  if (!atom->radius_flag || !atom->rmass_flag) fail_all(lmp, __FILE__, __LINE__, "fix hertzdamp/wall requires atom_style sphere");
  if (fm.any() && (!atom->omega_flag || !atom->torque_flag))
    fail_all(lmp, __FILE__, __LINE__, "fix hertzdamp/wall with friction requires atom_style sphere (omega, torque)");
  pair_constants(lmp, rule, e, update->dt, std::string(CMD) + " " + id, pc);
  logmesg(lmp, std::string("fix hertzdamp/wall ") + id + ": " + rule.describe() + ", " + fm.describe() +
                   (rule.tcmode != TC_FIXED ? "; " + describe_constants(rule, pc) : std::string()) + "\n");
}

void FixHertzdampWall::setup(int vflag)
{
  post_force(vflag);
}

void FixHertzdampWall::post_force(int /*vflag*/)
{
  // the pair contacts per atom of this step, whichever of the history fix and this fix
  // comes first in the fix list
  if (auto *pr = dynamic_cast<PairGranularHertzdamp *>(force->pair)) pr->mark_isolation();
  const double *radius = atom->radius;
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  double **x = atom->x;
  const int setup = update->setupflag;

  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    for (int side = 0; side < 2; side++) {
      if (side == 0 ? !has_lo : !has_hi) continue;
      const double dist = side == 0 ? x[i][axis] - lo : hi - x[i][axis];
      contact(i, side, radius[i] - dist, setup);
    }
  }
}

// One atom against one side of the wall, overlap ov.
void FixHertzdampWall::contact(int i, int side, double ov, int setup)
{
  double **v = atom->v, **f = atom->f;
  const double *radius = atom->radius, *rmass = atom->rmass;
  const double dt = update->dt;
  const double step = static_cast<double>(update->ntimestep);
  const bool force_end = rule.end == HERTZDAMP_END_FORCE;
  const double sgn = side == 0 ? 1.0 : -1.0;    // normal from the wall into the atom
  const double approach = -sgn * v[i][axis];
  double *s = &wst[i][side * SLOT];
  double *p = s + 1;
  if (ov <= 0.0) {
    if (s[0] == 0.0) return;
    if (s[0] == ENDED) {
      // ended at step P_TPREV with the closing correction P_FN: the set-up of a run
      // recomputing that step (after read_restart, run N pre no) applies it again
      if (setup && p[P_TPREV] == step)
        f[i][axis] += sgn * p[P_FN];
      else
        s[0] = 0.0;
      return;
    }
    const ContactEnd ce = payload_end(p, ov, -approach, step, force_end, rule.phase_force());
    const double fc = ce.f_end;
    book.finish(p, static_cast<double>(atom->tag[i]), side == 0 ? -1.0 : -2.0, ce.tend,
                -approach + fc * dt / p[P_M], dt);
    f[i][axis] += sgn * fc;
    // kept until the next step with the correction it applied (restart files)
    s[0] = fc != 0.0 ? static_cast<double>(ENDED) : 0.0;
    p[P_FN] = fc;
    p[P_TPREV] = step;
    return;
  }
  if (s[0] == ENDED) s[0] = 0.0;    // touching again after a contact ended: a new contact
  double f_phase = 0.0;
  bool replay = false;
  if (s[0] == 0.0) {
    // onset: first step with overlap > 0 for an atom without wall history
    const double m = rmass[i];
    const double kphys = estar > 0.0 ? 4.0 / 3.0 * estar * sqrt(radius[i]) : 0.0;
    // a wall's normal does not turn: no oblique normal correction
    const Onset o = contact_rule(lmp, rule, pc, kphys, m, approach, dt, ov);
    s[0] = static_cast<double>(ACTIVE);
    f_phase = payload_onset(p, o, approach, m, ov, step, dt, rule.phase_force());
    p[P_KT] = fm.any() ? contact_kt(rule, fm.tangential, fm.kt < 0.0 ? 8.0 * gstar : fm.kt, o.k, kphys) : 0.0;
    // the wall's normal is the same at the touch point: the impact angle from |v|
    p[P_VTOUCH] = std::sqrt(v[i][0] * v[i][0] + v[i][1] * v[i][1] + v[i][2] * v[i][2]);
    book.onset(o, approach);
  } else {
    replay = setup && p[P_TPREV] == step;    // set-up of a run recomputing a stored step
  }
  // not isolated: the other side of the wall, or pair contacts in this step
  const auto *pair = dynamic_cast<PairGranularHertzdamp *>(force->pair);
  if (wst[i][(1 - side) * SLOT] == ACTIVE || (pair && pair->contacts_of(i) > 0.0))
    p[P_FLAGS] = static_cast<double>(static_cast<int>(p[P_FLAGS]) | FLAG_NOT_ISOLATED);
  if (pair && pair->stock_wall_contacts_of(i) > 0.0)
    p[P_FLAGS] = static_cast<double>(static_cast<int>(p[P_FLAGS]) | FLAG_NOT_ISOLATED | FLAG_STOCK_WALL);
  const double fn = replay ? p[P_FN] : payload_force(p, ov, approach, step, force_end, f_phase);
  p[P_FN] = fn;
  if (!fm.any()) {
    f[i][axis] += sgn * fn;
    return;
  }
  double **omega = atom->omega, **torque = atom->torque;
  ContactState cs;
  cs.nx[0] = cs.nx[1] = cs.nx[2] = 0.0;
  cs.nx[axis] = sgn;
  double *fs = p + P_FS, *fr = p + P_FR;
  const double *n = cs.nx;
  const double radi = radius[i];
  if (!replay) {
    const double vnnr = v[i][axis] * sgn;
    const double wr[3] = {radi * omega[i][0], radi * omega[i][1], radi * omega[i][2]};
    cs.vtr[0] = v[i][0] - vnnr * n[0] - (wr[1] * n[2] - wr[2] * n[1]);
    cs.vtr[1] = v[i][1] - vnnr * n[1] - (wr[2] * n[0] - wr[0] * n[2]);
    cs.vtr[2] = v[i][2] - vnnr * n[2] - (wr[0] * n[1] - wr[1] * n[0]);
    for (int k = 0; k < 3; k++) cs.relrot[k] = omega[i][k];
    cs.delta = ov;
    cs.reff = radi;
    cs.fncrit = std::fabs(fn - f_phase);
    cs.damp_n = p[P_D];
    cs.dt = dt;
    cs.history_update = setup ? 0 : 1;
    friction_forces(fm, p[P_KT], cs, p + P_HIST, fs, fr, p[P_MT]);
  }
  for (int k = 0; k < 3; k++) f[i][k] += fn * n[k] + fs[k];
  const double tor[3] = {n[1] * fs[2] - n[2] * fs[1], n[2] * fs[0] - n[0] * fs[2], n[0] * fs[1] - n[1] * fs[0]};
  const double troll[3] = {radi * (n[1] * fr[2] - n[2] * fr[1]), radi * (n[2] * fr[0] - n[0] * fr[2]),
                           radi * (n[0] * fr[1] - n[1] * fr[0])};
  // lever arm of the tangential force: the radius (as fix wall/gran)
  const double arm = radi;
  for (int k = 0; k < 3; k++) torque[i][k] += -arm * tor[k] + troll[k] + p[P_MT] * n[k];
}

void FixHertzdampWall::post_run()
{
  book.flush_log(lmp);
  book.summary(lmp, (std::string("fix hertzdamp/wall ") + id).c_str());
}

double FixHertzdampWall::compute_vector(int n)
{
  if (cache_step != update->ntimestep) {
    // 1-17 the book's, 18-21 the constants', 22-25 the book's extras
    double v[ContactBook::NSTATS + ContactBook::NEXTRA];
    book.vector(lmp, v);
    for (int k = 0; k < ContactBook::NSTATS; k++) cache[k] = v[k];
    constants_stats(pc, cache + ContactBook::NSTATS);
    for (int k = 0; k < ContactBook::NEXTRA; k++) cache[ContactBook::NSTATS + NHOSTSTATS + k] = v[ContactBook::NSTATS + k];
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

int FixHertzdampWall::pack_restart(int i, double *buf)
{
  buf[0] = 1 + NCOL;
  std::memcpy(buf + 1, wst[i], sizeof(double) * NCOL);
  return 1 + NCOL;
}

void FixHertzdampWall::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int k = 0; k < nth; k++) m += static_cast<int>(extra[nlocal][m]);
  if (static_cast<int>(extra[nlocal][m]) != 1 + NCOL)
    fail_one(lmp, __FILE__, __LINE__, "fix hertzdamp/wall: restart file has wall contacts of another layout");
  std::memcpy(wst[nlocal], &extra[nlocal][m + 1], sizeof(double) * NCOL);
}

double FixHertzdampWall::memory_usage()
{
  return static_cast<double>(atom->nmax) * NCOL * sizeof(double);
}

}    // namespace HertzdampLammps
