/* Internal fix HERTZDAMP/HISTORY: see fix_hertzdamp_history.h. */
#include "fix_hertzdamp_history.h"

#include "pair_granular_hertzdamp.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "output.h"
#include "update.h"


#include <cstring>

using namespace LAMMPS_NS;
using namespace LAMMPS_NS::FixConst;

namespace HertzdampLammps {

FixHertzdampHistory::FixHertzdampHistory(LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg)
{
  if (narg != 3) fail_all(lmp, __FILE__, __LINE__, "fix HERTZDAMP/HISTORY is internal to pair granular/hertzdamp");
  maxexchange_dynamic = 1;
  maxexchange = 1;
  restart_peratom = 1;     // every contact's payload goes into restart files
  create_attribute = 1;    // atoms inserted during a run start without records
  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
}

FixHertzdampHistory::~FixHertzdampHistory()
{
  if (atom) {
    atom->delete_callback(id, Atom::GROW);
    atom->delete_callback(id, Atom::RESTART);
  }
}

int FixHertzdampHistory::setmask()
{
  return PRE_EXCHANGE | POST_NEIGHBOR | POST_FORCE | POST_RUN | END_OF_STEP | MIN_PRE_EXCHANGE | MIN_POST_NEIGHBOR;
}

void FixHertzdampHistory::init()
{
  if (!pair || force->pair != pair)
    fail_all(lmp, __FILE__, __LINE__,
             "fix HERTZDAMP/HISTORY without pair_style granular/hertzdamp (hybrid styles are not supported)");
}

void FixHertzdampHistory::pre_exchange()
{
  if (pair) pair->history_to_atoms(this, false);
}

void FixHertzdampHistory::post_neighbor()
{
  if (pair) pair->history_from_atoms(this);
}

void FixHertzdampHistory::post_force(int)
{
  if (pair) pair->mark_isolation();
}

void FixHertzdampHistory::post_run()
{
  if (pair) pair->end_of_run(this);
}

// a restart file written at the end of this step (restart N ...): the contacts go to the
// atoms' records first, where pack_restart finds them; the contacts stay in place
void FixHertzdampHistory::end_of_step()
{
  if (pair && output->restart_flag && output->next_restart == update->ntimestep)
    pair->history_to_atoms(this, true);
  // the per-contact log, streamed: the rows of all ranks written every LOG_FLUSH_EVERY steps
  if (pair) pair->book.flush_log_every(lmp, update->ntimestep);
}

/* restart files: each atom's records (count, then partner ID + payload per contact) */

int FixHertzdampHistory::pack_restart(int i, double *buf)
{
  const std::vector<double> &r = rec[i];
  buf[0] = static_cast<double>(r.size() + 2);
  buf[1] = static_cast<double>(r.size());
  if (!r.empty()) std::memcpy(buf + 2, r.data(), r.size() * sizeof(double));
  return 2 + static_cast<int>(r.size());
}

void FixHertzdampHistory::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int k = 0; k < nth; k++) m += static_cast<int>(extra[nlocal][m]);
  const int n = static_cast<int>(extra[nlocal][m + 1]);
  if (n % RECSIZE != 0)
    fail_one(lmp, __FILE__, __LINE__, "granular/hertzdamp: restart file has contact records of another layout");
  rec[nlocal].assign(&extra[nlocal][m + 2], &extra[nlocal][m + 2] + n);
}

int FixHertzdampHistory::size_restart(int i)
{
  return 2 + static_cast<int>(rec[i].size());
}

int FixHertzdampHistory::maxsize_restart()
{
  size_t most = 0;
  for (int i = 0; i < atom->nlocal; i++)
    if (rec[i].size() > most) most = rec[i].size();
  return 2 + static_cast<int>(most);
}

/* ---------------------------------------------------------------------- */

void FixHertzdampHistory::add_record(int i, double partner, const double *payload)
{
  if (find_record(i, partner)) return;
  std::vector<double> &r = rec[i];
  r.push_back(partner);
  r.insert(r.end(), payload, payload + NPAYLOAD);
}

const double *FixHertzdampHistory::find_record(int i, double partner) const
{
  const std::vector<double> &r = rec[i];
  for (size_t k = 0; k < r.size(); k += RECSIZE)
    if (r[k] == partner) return &r[k + 1];
  return nullptr;
}

void FixHertzdampHistory::update_maxexchange()
{
  size_t most = 0;
  for (int i = 0; i < atom->nlocal; i++)
    if (rec[i].size() > most) most = rec[i].size();
  maxexchange = 1 + static_cast<int>(most);
}

/* ---------------------------------------------------------------------- */

void FixHertzdampHistory::grow_arrays(int nmax)
{
  if (static_cast<int>(rec.size()) < nmax) rec.resize(nmax);
}

void FixHertzdampHistory::copy_arrays(int i, int j, int /*delflag*/)
{
  rec[j] = rec[i];
}

void FixHertzdampHistory::set_arrays(int i)
{
  rec[i].clear();
}

int FixHertzdampHistory::pack_exchange(int i, double *buf)
{
  const std::vector<double> &r = rec[i];
  buf[0] = static_cast<double>(r.size());
  if (!r.empty()) std::memcpy(buf + 1, r.data(), r.size() * sizeof(double));
  return 1 + static_cast<int>(r.size());
}

int FixHertzdampHistory::unpack_exchange(int nlocal, double *buf)
{
  const int n = static_cast<int>(buf[0]);
  rec[nlocal].assign(buf + 1, buf + 1 + n);
  return 1 + n;
}

/* reverse communication: records of ghost atoms go to their owners */

int FixHertzdampHistory::pack_reverse_comm_size(int n, int first)
{
  int m = 0;
  for (int i = first; i < first + n; i++) m += 1 + static_cast<int>(rec[i].size());
  return m;
}

int FixHertzdampHistory::pack_reverse_comm(int n, int first, double *buf)
{
  int m = 0;
  for (int i = first; i < first + n; i++) {
    const std::vector<double> &r = rec[i];
    buf[m++] = static_cast<double>(r.size());
    for (double x : r) buf[m++] = x;
  }
  return m;
}

void FixHertzdampHistory::unpack_reverse_comm(int n, int *list, double *buf)
{
  int m = 0;
  for (int k = 0; k < n; k++) {
    const int i = list[k];
    const int len = static_cast<int>(buf[m++]);
    for (int q = 0; q < len; q += RECSIZE) add_record(i, buf[m + q], &buf[m + q + 1]);
    m += len;
  }
}

double FixHertzdampHistory::memory_usage()
{
  double bytes = static_cast<double>(rec.capacity() * sizeof(std::vector<double>));
  for (const auto &r : rec) bytes += static_cast<double>(r.capacity() * sizeof(double));
  return bytes;
}

}    // namespace HertzdampLammps
