/* pair_style granular/hertzdamp: see pair_granular_hertzdamp.h and README.md. */
#include "pair_granular_hertzdamp.h"

#include "fix_hertzdamp_history.h"
#include "fix_hertzdamp_wall.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "update.h"
#include "utils.h"

#include <cmath>
#include <cstring>
#include <mpi.h>

using namespace LAMMPS_NS;

namespace HertzdampLammps {

#if HERTZDAMP_LAMMPS_NUM < 20220000
#define HD_FORWARD_COMM_PAIR(p) comm->forward_comm_pair(p)
#define HD_REVERSE_COMM_PAIR(p) comm->reverse_comm_pair(p)
#else
#define HD_FORWARD_COMM_PAIR(p) comm->forward_comm(p)
#define HD_REVERSE_COMM_PAIR(p) comm->reverse_comm(p)
#endif

namespace {
const char *CMD = "pair_style granular/hertzdamp";

// What the oblique normal correction needs of a pair contact at its onset: the two spheres,
// the friction model (frictionless: mindlin with mu 0) and the centres' relative tangential
// speed (del = x_i - x_j, rinv = 1/|del|, approach = -(v_i - v_j) . del/|del|).
ObliqueOnset oblique_onset(const FrictionModel &fo, double kt_phys, double mi, double ri, double mj, double rj,
                           const double *vi, const double *vj, const double *del, double rinv, double approach)
{
  ObliqueOnset ob;
  ob.m1 = mi, ob.r1 = ri, ob.m2 = mj, ob.r2 = rj;
  double tt = 0.0;
  for (int k = 0; k < 3; k++) {
    const double t = vi[k] - vj[k] + approach * del[k] * rinv;    // w - (w . n) n
    tt += t * t;
  }
  ob.vt = std::sqrt(tt);
  ob.tangential = fo.tangential == TANG_LINEAR_HISTORY ? HERTZDAMP_TANGENTIAL_LINEAR_HISTORY
                                                       : HERTZDAMP_TANGENTIAL_MINDLIN;
  ob.kt_phys = fo.any() ? kt_phys : 1.0;
  ob.xgammat = fo.any() ? fo.xt : 0.0;
  ob.mu = fo.any() ? fo.mut : 0.0;
  return ob;
}
const char *COEFF = "pair_coeff granular/hertzdamp";
}    // namespace

PairGranularHertzdamp::PairGranularHertzdamp(LAMMPS *lmp) : Pair(lmp)
{
  single_enable = 0;
  restartinfo = 1;
  no_virial_fdotr_compute = 1;    // forces tallied pair by pair (ev_tally)
  comm_forward = 2;               // contacts and stock wall contacts per atom (isolation)
  comm_reverse = 1;
}

PairGranularHertzdamp::~PairGranularHertzdamp()
{
  if (copymode) return;
  if (modify && modify->find_fix(history_id()) >= 0) modify->delete_fix(history_id());
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
    memory->destroy(e_ij);
    memory->destroy(estar_ij);
    memory->destroy(gstar_ij);
    memory->destroy(y_i);
    memory->destroy(nu_i);
    memory->destroy(maxrad);
  }
}

void PairGranularHertzdamp::allocate()
{
  allocated = 1;
  const int n = atom->ntypes;
  memory->create(setflag, n + 1, n + 1, "pair:setflag");
  memory->create(cutsq, n + 1, n + 1, "pair:cutsq");
  memory->create(e_ij, n + 1, n + 1, "pair:e_ij");
  memory->create(estar_ij, n + 1, n + 1, "pair:estar_ij");
  memory->create(gstar_ij, n + 1, n + 1, "pair:gstar_ij");
  memory->create(y_i, n + 1, "pair:y_i");
  memory->create(nu_i, n + 1, "pair:nu_i");
  memory->create(maxrad, n + 1, "pair:maxrad");
  fm.assign(static_cast<size_t>(n + 1) * (n + 1), FrictionModel());
  pcs.assign(static_cast<size_t>(n + 1) * (n + 1), PairConstants());
  cns.assign(static_cast<size_t>(n + 1) * (n + 1), CorrectionNodes());
  for (int i = 0; i <= n; i++) {
    y_i[i] = nu_i[i] = maxrad[i] = 0.0;
    for (int j = 0; j <= n; j++) {
      setflag[i][j] = 0;
      e_ij[i][j] = estar_ij[i][j] = gstar_ij[i][j] = 0.0;
    }
  }
}

// The internal fix that carries contacts across neighbor-list builds, processors and
// restart files.  Created with the pair style, so that it comes before fixes that insert
// atoms (fix pour, fix deposit) in the pre_exchange order.
void PairGranularHertzdamp::create_history_fix()
{
  if (modify->find_fix(history_id()) < 0) modify->add_fix(std::string(history_id()) + " all HERTZDAMP/HISTORY");
  fix_history = dynamic_cast<FixHertzdampHistory *>(modify->fix[modify->find_fix(history_id())]);
  if (!fix_history) fail_all(lmp, __FILE__, __LINE__, "granular/hertzdamp: internal history fix missing");
  fix_history->pair = this;
}

/* ----------------------------------------------------------------------
   pair_style granular/hertzdamp (steps N | tc T | fixed K D) [end overlap|force]
                                 [host lammps|none] [vmin V] [phase yes|no] [log FILE]
------------------------------------------------------------------------- */

void PairGranularHertzdamp::settings(int narg, char **arg)
{
  RuleSettings rs;
  for (int iarg = 0; iarg < narg;) {
    const std::string key = arg[iarg];
    const int used = rs.parse(lmp, CMD, narg, arg, iarg);
    if (used == 0) fail_all(lmp, __FILE__, __LINE__, std::string(CMD) + ": unknown keyword '" + key + "'");
    iarg += used;
  }
  rs.check(lmp, CMD);
  rule = rs;
  book.reset();
  book.open_log(lmp, rule.logfile, "# hertzdamp pair_style granular/hertzdamp " + rule.describe());
  create_history_fix();
}

/* ----------------------------------------------------------------------
   pair_coeff I J e E [youngs Y poisson NU] [tangential ...] [rolling ...] [twisting ...]
------------------------------------------------------------------------- */

void PairGranularHertzdamp::coeff(int narg, char **arg)
{
  if (narg < 4)
    fail_all(lmp, __FILE__, __LINE__,
             std::string(COEFF) + ": I J e E [youngs Y poisson NU] [tangential ...] [rolling ...] [twisting ...]");
  if (!allocated) allocate();
  int ilo, ihi, jlo, jhi;
  utils::bounds(__FILE__, __LINE__, std::string(arg[0]), 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(__FILE__, __LINE__, std::string(arg[1]), 1, atom->ntypes, jlo, jhi, error);
  if (strcmp(arg[2], "e") != 0) fail_all(lmp, __FILE__, __LINE__, std::string(COEFF) + ": expected 'e E' after I J");
  const double e = parse_number(lmp, COEFF, "e", arg[3]);
  if (!(e > 0.0 && e <= 1.0)) fail_all(lmp, __FILE__, __LINE__, std::string(COEFF) + ": e must be in (0, 1]");
  double y = 0.0, nu = 0.0;
  bool have_y = false, have_nu = false;
  FrictionModel f;
  for (int iarg = 4; iarg < narg;) {
    const int used = f.parse(lmp, COEFF, narg, arg, iarg);
    if (used) {
      iarg += used;
      continue;
    }
    const std::string key = arg[iarg];
    if (key != "youngs" && key != "poisson")
      fail_all(lmp, __FILE__, __LINE__, std::string(COEFF) + ": unknown keyword '" + key + "'");
    if (iarg + 1 >= narg) fail_all(lmp, __FILE__, __LINE__, std::string(COEFF) + ": " + key + " needs a value");
    const double x = parse_number(lmp, COEFF, key.c_str(), arg[iarg + 1]);
    if (key == "youngs") {
      if (!(x > 0.0)) fail_all(lmp, __FILE__, __LINE__, std::string(COEFF) + ": youngs must be > 0");
      y = x, have_y = true;
    } else {
      check_poisson(lmp, COEFF, "poisson", x);
      nu = x, have_nu = true;
    }
    iarg += 2;
  }
  if (have_y != have_nu) fail_all(lmp, __FILE__, __LINE__, std::string(COEFF) + ": give youngs Y and poisson NU together");
  f.check(lmp, COEFF, have_y);
  int count = 0;
  for (int i = ilo; i <= ihi; i++) {
    for (int j = (jlo > i ? jlo : i); j <= jhi; j++) {
      e_ij[i][j] = e;
      // both bodies of the pair made of the given material
      estar_ij[i][j] = have_y ? effective_modulus(y, nu, y, nu) : 0.0;
      gstar_ij[i][j] = have_y ? effective_shear_modulus(y, nu, y, nu) : 0.0;
      fm[static_cast<size_t>(i) * (atom->ntypes + 1) + j] = f;
      if (i == j) {
        y_i[i] = y;
        nu_i[i] = nu;
      }
      setflag[i][j] = 1;
      count++;
    }
  }
  if (count == 0) fail_all(lmp, __FILE__, __LINE__, "Incorrect args for pair coefficients");
}

void PairGranularHertzdamp::init_style()
{
  if (!atom->radius_flag || !atom->rmass_flag)
    fail_all(lmp, __FILE__, __LINE__, "pair granular/hertzdamp requires atom_style sphere");
  if (comm->ghost_velocity == 0)
    fail_all(lmp, __FILE__, __LINE__, "pair granular/hertzdamp requires ghost atoms store velocity (comm_modify vel yes)");
  // the first init re-creates the history fix in its place in the fix list: this is
  // where Modify hands it the contacts of a restart file (which it keeps until then)
  if (!history_initialized) {
    modify->add_fix(std::string(history_id()) + " all HERTZDAMP/HISTORY");
    history_initialized = true;
  }
  create_history_fix();

  friction = false;
  for (const FrictionModel &f : fm) friction = friction || f.any();
  if (friction && (!atom->omega_flag || !atom->torque_flag))
    fail_all(lmp, __FILE__, __LINE__, "pair granular/hertzdamp with friction requires atom_style sphere (omega, torque)");

  Pair::init_style();    // a standard half neighbor list (newton as set)

  // cutoff: the largest radius of each type among the atoms and the atoms that fix pour
  // and fix deposit will insert (as pair_style granular does)
  const int n = atom->ntypes;
  std::vector<double> local(n + 1, 0.0), global(n + 1, 0.0);
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->radius[i] > local[atom->type[i]]) local[atom->type[i]] = atom->radius[i];
  MPI_Allreduce(local.data(), global.data(), n + 1, MPI_DOUBLE, MPI_MAX, world);
  for (int k = 0; k < modify->nfix; k++) {
    const std::string style = modify->fix[k]->style;
    if (style.compare(0, 4, "pour") != 0 && style.compare(0, 7, "deposit") != 0) continue;
    for (int t = 1; t <= n; t++) {
      int itype = t;
      const double *r = static_cast<const double *>(modify->fix[k]->extract("radius", itype));
      if (!r)
        fail_all(lmp, __FILE__, __LINE__,
                 std::string("granular/hertzdamp: fix ") + modify->fix[k]->id + " (" + style +
                     ") does not tell the radii it inserts; the cutoff would miss them");
      if (*r > global[t]) global[t] = *r;
    }
  }
  for (int i = 1; i <= n; i++) maxrad[i] = global[i];

  find_stock_walls();
  logmesg(lmp, "granular/hertzdamp: " + rule.describe() + "\n");
}

double PairGranularHertzdamp::init_one(int i, int j)
{
  const size_t nt = static_cast<size_t>(atom->ntypes + 1);
  if (!setflag[i][j]) {
    const std::string ij = std::to_string(i) + " " + std::to_string(j);
    if (e_ij[i][i] != e_ij[j][j])
      fail_all(lmp, __FILE__, __LINE__,
               "granular/hertzdamp: types " + ij + " have different e: give pair_coeff " + ij + " explicitly");
    e_ij[i][j] = e_ij[i][i];
    if (y_i[i] > 0.0 && y_i[j] > 0.0) {
      estar_ij[i][j] = effective_modulus(y_i[i], nu_i[i], y_i[j], nu_i[j]);
      gstar_ij[i][j] = effective_shear_modulus(y_i[i], nu_i[i], y_i[j], nu_i[j]);
    } else if (y_i[i] > 0.0 || y_i[j] > 0.0) {
      fail_all(lmp, __FILE__, __LINE__,
               "granular/hertzdamp: youngs/poisson given for only one of types " + ij +
                   ": give pair_coeff " + ij + " explicitly");
    } else {
      estar_ij[i][j] = gstar_ij[i][j] = 0.0;
    }
    const FrictionModel &fi = fm[i * nt + i], &fj = fm[j * nt + j];
    if (!fi.same_models(fj))
      fail_all(lmp, __FILE__, __LINE__,
               "granular/hertzdamp: types " + ij + " have different friction models: give pair_coeff " +
                   ij + " explicitly");
    fm[i * nt + j] = FrictionModel::mix(fi, fj);
  }
  e_ij[j][i] = e_ij[i][j];
  estar_ij[j][i] = estar_ij[i][j];
  gstar_ij[j][i] = gstar_ij[i][j];
  fm[j * nt + i] = fm[i * nt + j];
  if (rule.tcmode != TC_FIXED) {
    // the pair's constants at this run's N (once per type pair; again when e, N or the
    // settings change: a new time step with tc T, read_restart)
    const std::string ij = std::to_string(i) + " " + std::to_string(j);
    PairConstants &pc = pcs[i * nt + j];
    pair_constants(lmp, rule, e_ij[i][j], update->dt, std::string(CMD) + " (types " + ij + ")", pc);
    pcs[j * nt + i] = pc;
    logmesg(lmp, "granular/hertzdamp: types " + ij + ": " + describe_constants(rule, pc) +
                     (estar_ij[i][j] > 0 ? ", E* " + fmt_g(estar_ij[i][j]) : "") + ", " +
                     fm[i * nt + j].describe() + "\n");
  }
  return maxrad[i] + maxrad[j];
}

const PairConstants &PairGranularHertzdamp::constants(int i, int j) const
{
  static const PairConstants none = PairConstants();
  const size_t k = static_cast<size_t>(i) * (atom->ntypes + 1) + j;
  return k < pcs.size() ? pcs[k] : none;
}

/* ---------------------------------------------------------------------- */

int PairGranularHertzdamp::new_contact()
{
  if (!freelist.empty()) {
    const int c = freelist.back();
    freelist.pop_back();
    return c;
  }
  pool.resize(pool.size() + NPAYLOAD);
  return static_cast<int>(pool.size() / NPAYLOAD) - 1;
}

void PairGranularHertzdamp::free_contact(int c)
{
  freelist.push_back(c);
}

void PairGranularHertzdamp::clear_contacts()
{
  pool.clear();
  freelist.clear();
}

/* ---------------------------------------------------------------------- */

void PairGranularHertzdamp::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);

  double **x = atom->x, **v = atom->v, **f = atom->f;
  double **omega = atom->omega, **torque = atom->torque;
  const double *radius = atom->radius, *rmass = atom->rmass;
  const int *type = atom->type;
  const tagint *tag = atom->tag;
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  const int newton_pair = force->newton_pair;
  const double dt = update->dt;
  const double step = static_cast<double>(update->ntimestep);
  const bool force_end = rule.end == HERTZDAMP_END_FORCE;
  const int setup = update->setupflag;
  const size_t nt = static_cast<size_t>(atom->ntypes + 1);

  const int inum = list->inum;
  const int *ilist = list->ilist, *numneigh = list->numneigh;
  int **firstneigh = list->firstneigh;
  if (inum != cached_inum)
    fail_one(lmp, __FILE__, __LINE__,
             "granular/hertzdamp: neighbor list rebuilt without the history fix (internal error)");
  ncontact.assign(nall, 0.0);
  touching.clear();
  records_fresh = false;

  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    const double xi = x[i][0], yi = x[i][1], zi = x[i][2], radi = radius[i];
    const int *jlist = firstneigh[i];
    const int jnum = numneigh[i];
    int *ci = &cidx[offset[ii]];

    for (int jj = 0; jj < jnum; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      const double delx = xi - x[j][0], dely = yi - x[j][1], delz = zi - x[j][2];
      const double rsq = delx * delx + dely * dely + delz * delz;
      const double radsum = radi + radius[j];
      int c = ci[jj];

      if (rsq >= radsum * radsum) {
        if (c < 0) continue;
        double *p = &pool[static_cast<size_t>(c) * NPAYLOAD];
        const double r = sqrt(rsq), rinv = 1.0 / r, ov = radsum - r;
        if (static_cast<int>(p[P_FLAGS]) & FLAG_ENDED) {
          // a contact that ended at step P_TPREV with a closing correction: the set-up of
          // a run recomputing that step (after read_restart, run N pre no) applies it again
          if (setup && p[P_TPREV] == step) {
            add_central(i, j, p[P_FN] * rinv, delx, dely, delz);
          } else {
            free_contact(c);
            ci[jj] = -1;
          }
          continue;
        }
        // contact over: the overlap has returned to zero
        const double u_out = ((v[i][0] - v[j][0]) * delx + (v[i][1] - v[j][1]) * dely +
                              (v[i][2] - v[j][2]) * delz) * rinv;
        const ContactEnd ce = payload_end(p, ov, u_out, step, force_end, rule.phase_force());
        const double f_end = ce.f_end;
        if (newton_pair || j < nlocal || tag[i] < tag[j]) {
          const double ta = tag[i] < tag[j] ? tag[i] : tag[j], tb = tag[i] < tag[j] ? tag[j] : tag[i];
          // separation speed at the release point on the last step's path, once the kick
          // f_end (applied now, along this step's normal) is complete
          const double rr[3] = {delx, dely, delz}, w[3] = {v[i][0] - v[j][0], v[i][1] - v[j][1], v[i][2] - v[j][2]};
          double nr[3];
          double u_rel = u_out + f_end * dt / p[P_M];
          if (contact_point_normal(rr, w, radsum, dt, false, nr)) {
            const double kick = f_end * dt / p[P_M] * rinv;
            u_rel = (w[0] + kick * delx) * nr[0] + (w[1] + kick * dely) * nr[1] + (w[2] + kick * delz) * nr[2];
          }
          book.finish(p, ta, tb, ce.tend, u_rel, dt);
        }
        if (f_end != 0.0) {
          add_central(i, j, f_end * rinv, delx, dely, delz);
          // kept until the next step with the correction it applied (restart files)
          p[P_FLAGS] = static_cast<double>(static_cast<int>(p[P_FLAGS]) | FLAG_ENDED);
          p[P_FN] = f_end;
          p[P_TPREV] = step;
        } else {
          free_contact(c);
          ci[jj] = -1;
        }
        continue;
      }

      const double r = sqrt(rsq), rinv = 1.0 / r, ov = radsum - r;
      // rate of overlap growth = relative normal approach speed
      const double approach = -((v[i][0] - v[j][0]) * delx + (v[i][1] - v[j][1]) * dely +
                                (v[i][2] - v[j][2]) * delz) * rinv;
      const int ti = type[i], tj = type[j];
      double *p;
      double f_phase = 0.0;
      bool replay = false;
      if (c >= 0 && (static_cast<int>(pool[static_cast<size_t>(c) * NPAYLOAD + P_FLAGS]) & FLAG_ENDED)) {
        // the pair overlaps again after its contact ended: a new contact
        free_contact(c);
        ci[jj] = c = -1;
      }
      if (c < 0) {
        // contact onset: first step with overlap > 0 for a pair without history
        const double mi = rmass[i], mj = rmass[j];
        const double m = mi * mj / (mi + mj);
        double kphys = 0.0;
        if (estar_ij[ti][tj] > 0.0) kphys = 4.0 / 3.0 * estar_ij[ti][tj] * sqrt(radi * radius[j] / radsum);
        const FrictionModel &fo = fm[ti * nt + tj];
        const double kt_phys = fo.kt < 0.0 ? 8.0 * gstar_ij[ti][tj] : fo.kt;
        const double del[3] = {delx, dely, delz};
        const ObliqueOnset ob = oblique_onset(fo, kt_phys, mi, radi, mj, radius[j], v[i], v[j], del, rinv, approach);
        CorrectionNodes &cn = cns[(ti < tj ? ti : tj) * nt + (ti < tj ? tj : ti)];
        const Onset o = contact_rule(lmp, rule, pcs[ti * nt + tj], kphys, m, approach, dt, ov, &ob, &cn);
        c = new_contact();
        ci[jj] = c;
        p = &pool[static_cast<size_t>(c) * NPAYLOAD];
        f_phase = payload_onset(p, o, approach, m, ov, step, dt, rule.phase_force());
        p[P_KT] = fo.any() ? contact_kt(rule, fo.tangential, kt_phys, o.k, kphys) : 0.0;
        {
          // normal speed and angle at the touch point, on the last step's free-flight path
          const double rr[3] = {delx, dely, delz}, w[3] = {v[i][0] - v[j][0], v[i][1] - v[j][1], v[i][2] - v[j][2]};
          double nt[3];
          if (contact_point_normal(rr, w, radsum, dt, true, nt)) p[P_UTOUCH] = -(w[0] * nt[0] + w[1] * nt[1] + w[2] * nt[2]);
          p[P_VTOUCH] = sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
        }
        if (newton_pair || j < nlocal || tag[i] < tag[j]) book.onset(o, approach);
      } else {
        p = &pool[static_cast<size_t>(c) * NPAYLOAD];
        // the set-up of a run recomputes the step whose forces are stored: replay them
        replay = setup && p[P_TPREV] == step;
      }
      ncontact[i] += 1.0;
      ncontact[j] += 1.0;
      touching.push_back(c);
      touching.push_back(i);
      touching.push_back(j);

      const double fn = replay ? p[P_FN] : payload_force(p, ov, approach, step, force_end, f_phase);
      p[P_FN] = fn;
      const FrictionModel &fmij = fm[ti * nt + tj];
      if (!fmij.any()) {
        add_central(i, j, fn * rinv, delx, dely, delz);
        continue;
      }

      // friction: tangential, rolling and twisting sub-models (contact_models.cpp)
      ContactState cs;
      cs.nx[0] = delx * rinv;
      cs.nx[1] = dely * rinv;
      cs.nx[2] = delz * rinv;
      double *fs = p + P_FS, *fr = p + P_FR;
      if (!replay) {
        const double vr[3] = {v[i][0] - v[j][0], v[i][1] - v[j][1], v[i][2] - v[j][2]};
        const double vnnr = vr[0] * cs.nx[0] + vr[1] * cs.nx[1] + vr[2] * cs.nx[2];
        const double radj = radius[j];
        const double wr[3] = {radi * omega[i][0] + radj * omega[j][0], radi * omega[i][1] + radj * omega[j][1],
                              radi * omega[i][2] + radj * omega[j][2]};
        const double *n = cs.nx;
        cs.vtr[0] = vr[0] - vnnr * n[0] - (wr[1] * n[2] - wr[2] * n[1]);
        cs.vtr[1] = vr[1] - vnnr * n[1] - (wr[2] * n[0] - wr[0] * n[2]);
        cs.vtr[2] = vr[2] - vnnr * n[2] - (wr[0] * n[1] - wr[1] * n[0]);
        for (int k = 0; k < 3; k++) cs.relrot[k] = omega[i][k] - omega[j][k];
        cs.delta = ov;
        cs.reff = radi * radj / radsum;
        // the normal force without the phase correction (clipped at zero with end force)
        const double fn_phys = fn - f_phase;
        cs.fncrit = std::fabs(fn_phys);
        cs.damp_n = p[P_D];
        cs.dt = dt;
        cs.history_update = setup ? 0 : 1;
        friction_forces(fmij, p[P_KT], cs, p + P_HIST, fs, fr, p[P_MT]);
      }
      const double *n = cs.nx;
      const double fx = fn * n[0] + fs[0], fy = fn * n[1] + fs[1], fz = fn * n[2] + fs[2];
      // torques: tangential force at the contact point, rolling and twisting torques
      const double tor[3] = {n[1] * fs[2] - n[2] * fs[1], n[2] * fs[0] - n[0] * fs[2], n[0] * fs[1] - n[1] * fs[0]};
      const double reff = radi * radius[j] / radsum;
      const double troll[3] = {reff * (n[1] * fr[2] - n[2] * fr[1]), reff * (n[2] * fr[0] - n[0] * fr[2]),
                               reff * (n[0] * fr[1] - n[1] * fr[0])};
      const double mt = p[P_MT];
      const double di = radi - 0.5 * ov, dj = radius[j] - 0.5 * ov;
      f[i][0] += fx;
      f[i][1] += fy;
      f[i][2] += fz;
      for (int k = 0; k < 3; k++) torque[i][k] += -di * tor[k] + troll[k] + mt * n[k];
      if (newton_pair || j < nlocal) {
        f[j][0] -= fx;
        f[j][1] -= fy;
        f[j][2] -= fz;
        for (int k = 0; k < 3; k++) torque[j][k] += -dj * tor[k] - troll[k] - mt * n[k];
      }
      if (evflag) ev_tally_xyz(i, j, nlocal, newton_pair, 0.0, 0.0, fx, fy, fz, delx, dely, delz);
    }
  }
  // the isolation of this step's contacts (two communications) is marked after the force
  // computation, by the history fix (post_force, before the wall fixes' post_force)
  isolation_pending = true;
}

// A central force fpair (x_i - x_j) on i and its opposite on j (when j is local or
// newton_pair is on), with its virial.
void PairGranularHertzdamp::add_central(int i, int j, double fpair, double delx, double dely, double delz)
{
  double **f = atom->f;
  const int nlocal = atom->nlocal, newton_pair = force->newton_pair;
  f[i][0] += delx * fpair;
  f[i][1] += dely * fpair;
  f[i][2] += delz * fpair;
  if (newton_pair || j < nlocal) {
    f[j][0] -= delx * fpair;
    f[j][1] -= dely * fpair;
    f[j][2] -= delz * fpair;
  }
  if (evflag) ev_tally(i, j, nlocal, newton_pair, 0.0, 0.0, fpair, delx, dely, delz);
}

/* ----------------------------------------------------------------------
   isolation of contacts: a contact is not an isolated binary collision if at any step
   one of its atoms has another contact (pair contacts of this step, wall contacts of
   the step before)
------------------------------------------------------------------------- */

void PairGranularHertzdamp::mark_isolation()
{
  if (!isolation_pending) return;
  isolation_pending = false;
  if (force->newton_pair) HD_REVERSE_COMM_PAIR(this);
  // pair contacts of the local atoms (for the walls), then with the wall contacts
  // (fix hertzdamp/wall, and stock walls through their per-atom `contacts` output) of
  // the step before, to every ghost atom
  const int nlocal = atom->nlocal;
  nstock.assign(ncontact.size(), 0.0);
  for (LAMMPS_NS::Fix *w : stock_walls) {
    double **a = w->array_atom;
    if (!a) continue;
    for (int i = 0; i < nlocal; i++)
      if (a[i][0] != 0.0) nstock[i] += 1.0;
  }
  npair.assign(ncontact.begin(), ncontact.begin() + nlocal);
  for (int i = 0; i < nlocal; i++) ncontact[i] += nstock[i];
  for (int k = 0; k < modify->nfix; k++) {
    const auto *wall = dynamic_cast<const FixHertzdampWall *>(modify->fix[k]);
    if (!wall) continue;
    for (int i = 0; i < nlocal; i++) ncontact[i] += wall->active_contacts(i);
  }
  HD_FORWARD_COMM_PAIR(this);
  for (size_t t = 0; t < touching.size(); t += 3) {
    const int i = touching[t + 1], j = touching[t + 2];
    if (ncontact[i] > 1.0 || ncontact[j] > 1.0) {
      double &flags = pool[static_cast<size_t>(touching[t]) * NPAYLOAD + P_FLAGS];
      const int stock = (nstock[i] > 0.0 || nstock[j] > 0.0) ? FLAG_STOCK_WALL : 0;
      flags = static_cast<double>(static_cast<int>(flags) | FLAG_NOT_ISOLATED | stock);
    }
  }
}

// The stock wall fixes (fix wall/gran, wall/gran/region): with their `contacts` keyword
// their per-atom output tells the beads that touch them (column 1); without it their
// contacts are not seen, and a warning says that the isolation test is unsound.
void PairGranularHertzdamp::find_stock_walls()
{
  stock_walls.clear();
  stock_walls_blind = 0;
  for (int k = 0; k < modify->nfix; k++) {
    LAMMPS_NS::Fix *f = modify->fix[k];
    if (std::string(f->style).compare(0, 9, "wall/gran") != 0) continue;
    if (f->peratom_flag && f->size_peratom_cols >= 1) {
      stock_walls.push_back(f);
    } else {
      stock_walls_blind++;
      if (comm->me == 0)
        warn(lmp, __FILE__, __LINE__,
             std::string("granular/hertzdamp: fix ") + f->id + " (" + f->style +
                 ") without its contacts keyword: contacts with it are not seen, so the e statistics "
                 "count beads touching it as isolated collisions (unsound); add `contacts`");
    }
  }
}

int PairGranularHertzdamp::pack_forward_comm(int n, int *list, double *buf, int, int *)
{
  for (int k = 0; k < n; k++) {
    buf[2 * k] = ncontact[list[k]];
    buf[2 * k + 1] = nstock[list[k]];
  }
  return 2 * n;
}

void PairGranularHertzdamp::unpack_forward_comm(int n, int first, double *buf)
{
  for (int k = 0; k < n; k++) {
    ncontact[first + k] = buf[2 * k];
    nstock[first + k] = buf[2 * k + 1];
  }
}

int PairGranularHertzdamp::pack_reverse_comm(int n, int first, double *buf)
{
  for (int k = 0; k < n; k++) buf[k] = ncontact[first + k];
  return n;
}

void PairGranularHertzdamp::unpack_reverse_comm(int n, int *list, double *buf)
{
  for (int k = 0; k < n; k++) ncontact[list[k]] += buf[k];
}

/* ----------------------------------------------------------------------
   restart: the rule's settings and the coefficients of every type pair
------------------------------------------------------------------------- */

void PairGranularHertzdamp::write_restart_settings(FILE *fp)
{
  // phase, host, tangential_stiffness and normal_correction in one number
  // (RuleSettings::pack_modes)
  const double d[7] = {static_cast<double>(rule.tcmode), rule.nsteps, rule.tc, rule.kfix, rule.dfix,
                       rule.vmin, rule.pack_modes()};
  const int end = rule.end, nlog = static_cast<int>(rule.logfile.size());
  fwrite(d, sizeof(double), 7, fp);
  fwrite(&end, sizeof(int), 1, fp);
  fwrite(&nlog, sizeof(int), 1, fp);
  if (nlog) fwrite(rule.logfile.data(), 1, nlog, fp);
}

void PairGranularHertzdamp::read_restart_settings(FILE *fp)
{
  double d[7];
  int end = 0, nlog = 0;
  const int me = comm->me;
  if (me == 0) {
    utils::sfread(__FILE__, __LINE__, d, sizeof(double), 7, fp, nullptr, error);
    utils::sfread(__FILE__, __LINE__, &end, sizeof(int), 1, fp, nullptr, error);
    utils::sfread(__FILE__, __LINE__, &nlog, sizeof(int), 1, fp, nullptr, error);
  }
  MPI_Bcast(d, 7, MPI_DOUBLE, 0, world);
  MPI_Bcast(&end, 1, MPI_INT, 0, world);
  MPI_Bcast(&nlog, 1, MPI_INT, 0, world);
  std::string logfile(nlog, ' ');
  if (nlog > 0) {
    if (me == 0) utils::sfread(__FILE__, __LINE__, &logfile[0], 1, nlog, fp, nullptr, error);
    MPI_Bcast(&logfile[0], nlog, MPI_CHAR, 0, world);
  }
  rule = RuleSettings();
  rule.tcmode = static_cast<int>(d[0]);
  rule.nsteps = d[1];
  rule.tc = d[2];
  rule.kfix = d[3];
  rule.dfix = d[4];
  rule.vmin = d[5];
  rule.unpack_modes(d[6]);
  rule.end = end;
  rule.ntimes = 1;
  // the log goes on in the same file (appended, with a header line of its own)
  rule.logfile = logfile;
  book.reset();
  book.open_log(lmp, logfile, "# hertzdamp pair_style granular/hertzdamp (read_restart) " + rule.describe(), true);
  create_history_fix();
}

void PairGranularHertzdamp::write_restart(FILE *fp)
{
  write_restart_settings(fp);
  const int n = atom->ntypes;
  fwrite(y_i + 1, sizeof(double), n, fp);
  fwrite(nu_i + 1, sizeof(double), n, fp);
  for (int i = 1; i <= n; i++) {
    for (int j = i; j <= n; j++) {
      fwrite(&setflag[i][j], sizeof(int), 1, fp);
      if (!setflag[i][j]) continue;
      const FrictionModel &f = fm[static_cast<size_t>(i) * (n + 1) + j];
      const int models[3] = {f.tangential, f.rolling, f.twisting};
      const double c[13] = {e_ij[i][j], estar_ij[i][j], gstar_ij[i][j], f.kt, f.xt, f.mut, f.kr,
                            f.gr, f.mur, f.ktw, f.gtw, f.mutw, 0.0};
      fwrite(models, sizeof(int), 3, fp);
      fwrite(c, sizeof(double), 13, fp);
    }
  }
}

void PairGranularHertzdamp::read_restart(FILE *fp)
{
  read_restart_settings(fp);
  allocate();
  const int n = atom->ntypes, me = comm->me;
  if (me == 0) {
    utils::sfread(__FILE__, __LINE__, y_i + 1, sizeof(double), n, fp, nullptr, error);
    utils::sfread(__FILE__, __LINE__, nu_i + 1, sizeof(double), n, fp, nullptr, error);
  }
  MPI_Bcast(y_i + 1, n, MPI_DOUBLE, 0, world);
  MPI_Bcast(nu_i + 1, n, MPI_DOUBLE, 0, world);
  for (int i = 1; i <= n; i++) {
    for (int j = i; j <= n; j++) {
      if (me == 0) utils::sfread(__FILE__, __LINE__, &setflag[i][j], sizeof(int), 1, fp, nullptr, error);
      MPI_Bcast(&setflag[i][j], 1, MPI_INT, 0, world);
      if (!setflag[i][j]) continue;
      int models[3];
      double c[13];
      if (me == 0) {
        utils::sfread(__FILE__, __LINE__, models, sizeof(int), 3, fp, nullptr, error);
        utils::sfread(__FILE__, __LINE__, c, sizeof(double), 13, fp, nullptr, error);
      }
      MPI_Bcast(models, 3, MPI_INT, 0, world);
      MPI_Bcast(c, 13, MPI_DOUBLE, 0, world);
      e_ij[i][j] = c[0];
      estar_ij[i][j] = c[1];
      gstar_ij[i][j] = c[2];
      FrictionModel &f = fm[static_cast<size_t>(i) * (n + 1) + j];
      f.tangential = models[0];
      f.rolling = models[1];
      f.twisting = models[2];
      f.kt = c[3], f.xt = c[4], f.mut = c[5];
      f.kr = c[6], f.gr = c[7], f.mur = c[8];
      f.ktw = c[9], f.gtw = c[10], f.mutw = c[11];
    }
  }
}

/* ----------------------------------------------------------------------
   contacts -> per-atom records (before atoms migrate)
------------------------------------------------------------------------- */

void PairGranularHertzdamp::history_to_atoms(FixHertzdampHistory *fix, bool keep)
{
  // no contacts indexed by a neighbor list since the records were made (a second
  // transfer after post_run, or the records read from a restart file): keep them
  if (cached_inum < 0 && active_contacts() == 0) {
    records_valid = true;
    return;
  }
  // records made at the end of the last run, nothing computed since: they are current
  if (records_fresh && !keep) {
    records_fresh = false;
    clear_contacts();
    cidx.clear();
    cached_inum = -1;
    records_valid = true;
    return;
  }
  const int nlocal = atom->nlocal, nall = atom->nlocal + atom->nghost;
  const tagint *tag = atom->tag;
  const int newton_pair = force->newton_pair;
  for (int i = 0; i < nall && i < static_cast<int>(fix->rec.size()); i++) fix->rec[i].clear();

  int lost = 0;
  if (list && cached_inum >= 0 && cached_inum == list->inum) {
    const int *ilist = list->ilist, *numneigh = list->numneigh;
    int **firstneigh = list->firstneigh;
    for (int ii = 0; ii < cached_inum; ii++) {
      const int i = ilist[ii];
      const int *ci = &cidx[offset[ii]];
      for (int jj = 0; jj < numneigh[i]; jj++) {
        const int c = ci[jj];
        if (c < 0) continue;
        const int j = firstneigh[i][jj] & NEIGHMASK;
        if (i >= nlocal || j >= nall) {
          lost++;
          continue;
        }
        const double *p = &pool[static_cast<size_t>(c) * NPAYLOAD];
        fix->add_record(i, static_cast<double>(tag[j]), p);
        if (newton_pair || j < nlocal) {
          // j's copy seen from j: the friction history and the tangential force change
          // sign, as pair_style granular transfers its history (also the rolling and
          // twisting history, though their rates do not change sign with the order)
          double q[NPAYLOAD];
          std::memcpy(q, p, sizeof(q));
          for (int k = P_HIST; k < P_HIST + 7; k++) q[k] = -q[k];
          for (int k = P_FS; k < P_FS + 3; k++) q[k] = -q[k];
          fix->add_record(j, static_cast<double>(tag[i]), q);
        }
      }
    }
  } else if (active_contacts() > 0) {
    lost = active_contacts();
  }
  // counted here, reported at the end of the run (no collective at every neighbor-list build)
  lost_contacts += lost;

  if (newton_pair) {
#if HERTZDAMP_LAMMPS_NUM < 20220000
    comm->reverse_comm_fix_variable(fix);
#else
    comm->reverse_comm_variable(fix);
#endif
    for (int i = nlocal; i < nall && i < static_cast<int>(fix->rec.size()); i++) fix->rec[i].clear();
  }
  fix->update_maxexchange();
  if (keep) return;
  clear_contacts();
  cidx.clear();
  cached_inum = -1;
  records_valid = true;
}

/* ----------------------------------------------------------------------
   per-atom records -> contacts of the new neighbor list
------------------------------------------------------------------------- */

void PairGranularHertzdamp::history_from_atoms(FixHertzdampHistory *fix)
{
  const int inum = list->inum;
  const int *ilist = list->ilist, *numneigh = list->numneigh;
  int **firstneigh = list->firstneigh;
  const tagint *tag = atom->tag;

  offset.resize(inum + 1);
  int total = 0;
  for (int ii = 0; ii < inum; ii++) {
    offset[ii] = total;
    total += numneigh[ilist[ii]];
  }
  offset[inum] = total;
  cidx.assign(total, -1);

  if (!records_valid && active_contacts() > 0)
    warn(lmp, __FILE__, __LINE__, "granular/hertzdamp: neighbor list rebuilt without a transfer of contacts");
  clear_contacts();

  if (records_valid) {
    for (int ii = 0; ii < inum; ii++) {
      const int i = ilist[ii];
      if (fix->rec[i].empty()) continue;
      const int *jlist = firstneigh[i];
      for (int jj = 0; jj < numneigh[i]; jj++) {
        const int j = jlist[jj] & NEIGHMASK;
        const double *r = fix->find_record(i, static_cast<double>(tag[j]));
        if (!r) continue;
        const int c = new_contact();
        std::memcpy(&pool[static_cast<size_t>(c) * NPAYLOAD], r, sizeof(double) * NPAYLOAD);
        cidx[offset[ii] + jj] = c;
        fix->transferred++;
        if (!(static_cast<int>(r[P_FLAGS]) & FLAG_ENDED)) book.carried += 1;
      }
    }
  }
  const int nall = atom->nlocal + atom->nghost;
  for (int i = 0; i < nall && i < static_cast<int>(fix->rec.size()); i++) fix->rec[i].clear();
  records_valid = false;
  cached_inum = inum;

  // every atom within the cutoff: no radius above the largest one known at the run's start
  // (checked by each process for its atoms: no collective at every neighbor-list build)
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->radius[i] > maxrad[atom->type[i]])
      fail_one(lmp, __FILE__, __LINE__,
               "granular/hertzdamp: an atom of radius " + fmt_g(atom->radius[i]) +
                   " is larger than the radii known at the start of the run (atoms, fix pour, fix deposit), "
                   "which set the cutoff: its contacts would be missed");
}

void PairGranularHertzdamp::end_of_run(FixHertzdampHistory *fix)
{
  // contacts to the atoms' records, for write_restart and for changes between runs;
  // the contacts stay indexed by the neighbor list for a following `run N pre no`
  history_to_atoms(fix, true);
  records_fresh = true;
  int lost_all = 0;
  MPI_Allreduce(&lost_contacts, &lost_all, 1, MPI_INT, MPI_SUM, world);
  lost_contacts = 0;
  if (lost_all > 0)
    warn(lmp, __FILE__, __LINE__,
         "granular/hertzdamp: " + std::to_string(lost_all) +
             " contacts lost (atoms changed between runs); they restarted as new contacts");
  book.flush_log(lmp);
  book.summary(lmp, "granular/hertzdamp");
}

double PairGranularHertzdamp::memory_usage()
{
  double bytes = Pair::memory_usage();
  bytes += pool.capacity() * sizeof(double) + cidx.capacity() * sizeof(int) +
           offset.capacity() * sizeof(int) + freelist.capacity() * sizeof(int);
  return bytes;
}

}    // namespace HertzdampLammps
