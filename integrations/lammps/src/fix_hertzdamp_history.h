/* -*- c++ -*-
 * Internal fix HERTZDAMP/HISTORY, created by pair_style granular/hertzdamp.
 *
 * Between neighbor-list builds the contacts live in the pair style, indexed by
 * neighbor-list entry.  Before atoms migrate (pre_exchange) the pair style writes
 * every active contact into per-atom records of BOTH atoms (partner ID + payload);
 * with newton_pair on, records of ghost atoms are sent to their owners by a
 * reverse communication.  The records travel with the atoms (pack_exchange) and
 * survive sorting (copy_arrays).  After the new list is built (post_neighbor) the
 * pair style looks every listed pair up in the records of its local atom.
 */
#ifndef HERTZDAMP_FIX_HERTZDAMP_HISTORY_H
#define HERTZDAMP_FIX_HERTZDAMP_HISTORY_H

#include "fix.h"
#include "hertzdamp_lammps.h"

#include <vector>

namespace HertzdampLammps {

class PairGranularHertzdamp;

class FixHertzdampHistory : public LAMMPS_NS::Fix {
 public:
  FixHertzdampHistory(LAMMPS *lmp, int narg, char **arg);
  ~FixHertzdampHistory() override;
  int setmask() override;
  void init() override;
  void setup_pre_exchange() override { pre_exchange(); }
  void pre_exchange() override;
  void min_pre_exchange() override { pre_exchange(); }
  void setup_post_neighbor() override { post_neighbor(); }
  // the isolation of the step's contacts, after the force computation (before the wall
  // fixes, which read the pair contacts per atom)
  void setup(int) override { post_force(0); }
  void post_force(int) override;
  void post_neighbor() override;
  void min_post_neighbor() override { post_neighbor(); }
  void post_run() override;
  void end_of_step() override;

  int pack_restart(int i, double *buf) override;
  void unpack_restart(int nlocal, int nth) override;
  int size_restart(int i) override;
  int maxsize_restart() override;

  void grow_arrays(int nmax) override;
  void copy_arrays(int i, int j, int delflag) override;
  void set_arrays(int i) override;
  int pack_exchange(int i, double *buf) override;
  int unpack_exchange(int nlocal, double *buf) override;
  int pack_reverse_comm_size(int n, int first) override;
  int pack_reverse_comm(int n, int first, double *buf) override;
  void unpack_reverse_comm(int n, int *list, double *buf) override;
  double memory_usage() override;

  enum { RECSIZE = 1 + NPAYLOAD };    // partner ID + payload
  // records of atom i: RECSIZE doubles per contact
  std::vector<std::vector<double>> rec;
  void add_record(int i, double partner, const double *payload);
  const double *find_record(int i, double partner) const;
  void update_maxexchange();

  PairGranularHertzdamp *pair = nullptr;
  long transferred = 0;    // contacts carried through records (all builds, this proc)
};

}    // namespace HertzdampLammps

#endif
