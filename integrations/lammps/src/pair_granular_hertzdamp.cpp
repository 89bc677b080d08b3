/* pair_style granular/hertzdamp: see pair_granular_hertzdamp.h and README.md. */
#include "pair_granular_hertzdamp.h"

#include "fix_hertzdamp_history.h"

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

PairGranularHertzdamp::PairGranularHertzdamp(LAMMPS *lmp) : Pair(lmp)
{
  single_enable = 0;
  no_virial_fdotr_compute = 1;    // forces tallied pair by pair (ev_tally)
  fix_id = "HERTZDAMP_HISTORY_" + std::to_string(instance_me);
}

PairGranularHertzdamp::~PairGranularHertzdamp()
{
  if (copymode) return;
  if (modify && modify->find_fix(fix_id) >= 0) modify->delete_fix(fix_id);
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
    memory->destroy(e_ij);
    memory->destroy(estar_ij);
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
  memory->create(y_i, n + 1, "pair:y_i");
  memory->create(nu_i, n + 1, "pair:nu_i");
  memory->create(maxrad, n + 1, "pair:maxrad");
  for (int i = 0; i <= n; i++) {
    y_i[i] = nu_i[i] = maxrad[i] = 0.0;
    for (int j = 0; j <= n; j++) {
      setflag[i][j] = 0;
      e_ij[i][j] = estar_ij[i][j] = 0.0;
    }
  }
}

/* ----------------------------------------------------------------------
   pair_style granular/hertzdamp (steps N | tc T | fixed K D) [end overlap|force]
                                 [vmin V] [log FILE]
------------------------------------------------------------------------- */

void PairGranularHertzdamp::settings(int narg, char **arg)
{
  RuleSettings rs;
  const char *cmd = "pair_style granular/hertzdamp";
  for (int iarg = 0; iarg < narg;) {
    const std::string key = arg[iarg];
    const int used = rs.parse(lmp, cmd, narg, arg, iarg);
    if (used == 0) fail_all(lmp, __FILE__, __LINE__, std::string(cmd) + ": unknown keyword '" + key + "'");
    iarg += used;
  }
  rs.check(lmp, cmd);
  rule = rs;
  book.reset();
  book.open_log(lmp, rule.logfile, "# hertzdamp pair_style granular/hertzdamp " + rule.describe());

  // the fix that carries contacts across neighbor-list builds and processors
  if (modify->find_fix(fix_id) < 0) modify->add_fix(fix_id + " all HERTZDAMP/HISTORY");
  fix_history = dynamic_cast<FixHertzdampHistory *>(modify->fix[modify->find_fix(fix_id)]);
  if (!fix_history) fail_all(lmp, __FILE__, __LINE__, "granular/hertzdamp: internal history fix missing");
  fix_history->pair = this;
}

/* ----------------------------------------------------------------------
   pair_coeff I J e E [youngs Y poisson NU]
------------------------------------------------------------------------- */

void PairGranularHertzdamp::coeff(int narg, char **arg)
{
  if (narg != 4 && narg != 8)
    fail_all(lmp, __FILE__, __LINE__,
             "pair_coeff for granular/hertzdamp: I J e E [youngs Y poisson NU]");
  if (!allocated) allocate();
  int ilo, ihi, jlo, jhi;
  utils::bounds(__FILE__, __LINE__, std::string(arg[0]), 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(__FILE__, __LINE__, std::string(arg[1]), 1, atom->ntypes, jlo, jhi, error);
  if (strcmp(arg[2], "e") != 0)
    fail_all(lmp, __FILE__, __LINE__, "pair_coeff for granular/hertzdamp: expected 'e E' after I J");
  const double e = parse_double(lmp, "e", arg[3]);
  if (!(e > 0.0 && e <= 1.0))
    fail_all(lmp, __FILE__, __LINE__, "pair_coeff for granular/hertzdamp: e must be in (0, 1]");
  double y = 0.0, nu = 0.0;
  if (narg == 8) {
    if (strcmp(arg[4], "youngs") != 0 || strcmp(arg[6], "poisson") != 0)
      fail_all(lmp, __FILE__, __LINE__,
               "pair_coeff for granular/hertzdamp: expected 'youngs Y poisson NU'");
    y = parse_double(lmp, "youngs", arg[5]);
    nu = parse_double(lmp, "poisson", arg[7]);
    if (!(y > 0.0) || !(nu > -1.0 && nu < 0.5))
      fail_all(lmp, __FILE__, __LINE__,
               "pair_coeff for granular/hertzdamp: need youngs > 0 and -1 < poisson < 0.5");
  }
  int count = 0;
  for (int i = ilo; i <= ihi; i++) {
    for (int j = (jlo > i ? jlo : i); j <= jhi; j++) {
      e_ij[i][j] = e;
      // both bodies of the pair made of the given material: E* = Y / (2 (1 - nu^2))
      estar_ij[i][j] = narg == 8 ? effective_modulus(y, nu, y, nu) : 0.0;
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
  const int ifix = modify->find_fix(fix_id);
  if (ifix < 0) fail_all(lmp, __FILE__, __LINE__, "granular/hertzdamp: internal history fix was deleted");
  fix_history = dynamic_cast<FixHertzdampHistory *>(modify->fix[ifix]);
  fix_history->pair = this;

  Pair::init_style();    // a standard half neighbor list (newton as set)

  // cutoff from the largest radius of each type at the start of the run
  const int n = atom->ntypes;
  std::vector<double> local(n + 1, 0.0), global(n + 1, 0.0);
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->radius[i] > local[atom->type[i]]) local[atom->type[i]] = atom->radius[i];
  MPI_Allreduce(local.data(), global.data(), n + 1, MPI_DOUBLE, MPI_MAX, world);
  for (int i = 1; i <= n; i++) maxrad[i] = global[i];

  logmesg(lmp, "granular/hertzdamp: " + rule.describe() + "\n");
}

double PairGranularHertzdamp::init_one(int i, int j)
{
  if (!setflag[i][j]) {
    if (e_ij[i][i] != e_ij[j][j])
      fail_all(lmp, __FILE__, __LINE__,
               "granular/hertzdamp: types " + std::to_string(i) + " and " + std::to_string(j) +
                   " have different e: give pair_coeff " + std::to_string(i) + " " +
                   std::to_string(j) + " explicitly");
    e_ij[i][j] = e_ij[i][i];
    if (y_i[i] > 0.0 && y_i[j] > 0.0)
      estar_ij[i][j] = effective_modulus(y_i[i], nu_i[i], y_i[j], nu_i[j]);
    else if (y_i[i] > 0.0 || y_i[j] > 0.0)
      fail_all(lmp, __FILE__, __LINE__,
               "granular/hertzdamp: youngs/poisson given for only one of types " +
                   std::to_string(i) + ", " + std::to_string(j) + ": give pair_coeff " +
                   std::to_string(i) + " " + std::to_string(j) + " explicitly");
    else
      estar_ij[i][j] = 0.0;
  }
  e_ij[j][i] = e_ij[i][j];
  estar_ij[j][i] = estar_ij[i][j];
  if (rule.tcmode != TC_FIXED) {
    double alpha, tau;
    const int st = hertzdamp_c_pair(e_ij[i][j], rule.end, &alpha, &tau);
    if (st != HERTZDAMP_OK)
      fail_all(lmp, __FILE__, __LINE__,
               "granular/hertzdamp: e " + fmt_g(e_ij[i][j]) + " for types " + std::to_string(i) +
                   " " + std::to_string(j) + ": " + hertzdamp_c_strerror(st));
    if (i == j || !setflag[i][j])
      logmesg(lmp, "granular/hertzdamp: types " + std::to_string(i) + " " + std::to_string(j) +
                       ": e " + fmt_g(e_ij[i][j]) + ", alpha " + fmt_g(alpha) + ", tau_c " +
                       fmt_g(tau) + (estar_ij[i][j] > 0 ? ", E* " + fmt_g(estar_ij[i][j]) : "") +
                       "\n");
  }
  return maxrad[i] + maxrad[j];
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
  const double *radius = atom->radius, *rmass = atom->rmass;
  const int *type = atom->type;
  const tagint *tag = atom->tag;
  const int nlocal = atom->nlocal;
  const int newton_pair = force->newton_pair;
  const double dt = update->dt;
  const double step = static_cast<double>(update->ntimestep);
  const bool force_end = rule.end == HERTZDAMP_END_FORCE;

  const int inum = list->inum;
  const int *ilist = list->ilist, *numneigh = list->numneigh;
  int **firstneigh = list->firstneigh;
  if (inum != cached_inum)
    fail_one(lmp, __FILE__, __LINE__,
             "granular/hertzdamp: neighbor list rebuilt without the history fix (internal error)");

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
        // contact over: the overlap has returned to zero
        double *p = &pool[static_cast<size_t>(c) * NPAYLOAD];
        const double r = sqrt(rsq), rinv = 1.0 / r, ov = radsum - r;
        const double u_out = ((v[i][0] - v[j][0]) * delx + (v[i][1] - v[j][1]) * dely +
                              (v[i][2] - v[j][2]) * delz) * rinv;
        const ContactEnd ce = payload_end(p, ov, u_out, step, force_end, rule.phase);
        const double f_end = ce.f_end;
        if (newton_pair || j < nlocal || tag[i] < tag[j]) {
          const double ta = tag[i] < tag[j] ? tag[i] : tag[j], tb = tag[i] < tag[j] ? tag[j] : tag[i];
          // separation speed once the kick f_end (applied now) is complete
          book.finish(p, ta, tb, ce.tend, u_out + f_end * dt / p[P_M], dt);
        }
        if (f_end != 0.0) {
          const double fpair = f_end * rinv;
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
        free_contact(c);
        ci[jj] = -1;
        continue;
      }

      const double r = sqrt(rsq), rinv = 1.0 / r, ov = radsum - r;
      // rate of overlap growth = relative normal approach speed
      const double approach = -((v[i][0] - v[j][0]) * delx + (v[i][1] - v[j][1]) * dely +
                                (v[i][2] - v[j][2]) * delz) * rinv;
      double *p;
      double f_phase = 0.0;
      if (c < 0) {
        // contact onset: first step with overlap > 0 for a pair without history
        const double mi = rmass[i], mj = rmass[j];
        const double m = mi * mj / (mi + mj);
        const int ti = type[i], tj = type[j];
        double kphys = 0.0;
        if (estar_ij[ti][tj] > 0.0) kphys = 4.0 / 3.0 * estar_ij[ti][tj] * sqrt(radi * radius[j] / radsum);
        const Onset o = contact_rule(lmp, rule, e_ij[ti][tj], kphys, m, approach, dt);
        c = new_contact();
        ci[jj] = c;
        p = &pool[static_cast<size_t>(c) * NPAYLOAD];
        f_phase = payload_onset(p, o, approach, m, ov, step, dt, rule.phase);
        if (newton_pair || j < nlocal || tag[i] < tag[j]) book.onset(o, approach);
      } else {
        p = &pool[static_cast<size_t>(c) * NPAYLOAD];
      }

      const double fn = payload_force(p, ov, approach, step, force_end, f_phase);

      const double fpair = fn * rinv;
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
  }
}

/* ----------------------------------------------------------------------
   contacts -> per-atom records (before atoms migrate)
------------------------------------------------------------------------- */

void PairGranularHertzdamp::history_to_atoms(FixHertzdampHistory *fix)
{
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
        if (newton_pair || j < nlocal) fix->add_record(j, static_cast<double>(tag[i]), p);
      }
    }
  } else if (active_contacts() > 0) {
    lost = active_contacts();
  }
  int lost_all = 0;
  MPI_Allreduce(&lost, &lost_all, 1, MPI_INT, MPI_SUM, world);
  if (lost_all > 0)
    warn(lmp, __FILE__, __LINE__,
         "granular/hertzdamp: " + std::to_string(lost_all) +
             " contacts lost (atoms changed between runs); they restart as new contacts");

  if (newton_pair) {
#if HERTZDAMP_LAMMPS_NUM < 20220000
    comm->reverse_comm_fix_variable(fix);
#else
    comm->reverse_comm_variable(fix);
#endif
    for (int i = nlocal; i < nall && i < static_cast<int>(fix->rec.size()); i++) fix->rec[i].clear();
  }
  clear_contacts();
  cidx.clear();
  cached_inum = -1;
  records_valid = true;
  fix->update_maxexchange();
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
        book.carried += 1;
      }
    }
  }
  const int nall = atom->nlocal + atom->nghost;
  for (int i = 0; i < nall && i < static_cast<int>(fix->rec.size()); i++) fix->rec[i].clear();
  records_valid = false;
  cached_inum = inum;
}

void PairGranularHertzdamp::end_of_run()
{
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
