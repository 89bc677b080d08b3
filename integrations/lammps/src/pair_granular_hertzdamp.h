/* -*- c++ -*-
 * pair_style granular/hertzdamp: Hertz contact with linear damping whose k and d
 * are set per contact, at its onset, by the adaptive collision time rule of the
 * hertzdamp core library (C API).  Normal force only (no tangential force, no
 * friction, no torque).
 */
#ifndef HERTZDAMP_PAIR_GRANULAR_HERTZDAMP_H
#define HERTZDAMP_PAIR_GRANULAR_HERTZDAMP_H

#include "hertzdamp_lammps.h"
#include "pair.h"

#include <vector>

namespace HertzdampLammps {

class FixHertzdampHistory;

class PairGranularHertzdamp : public LAMMPS_NS::Pair {
 public:
  explicit PairGranularHertzdamp(LAMMPS *lmp);
  ~PairGranularHertzdamp() override;

  void compute(int eflag, int vflag) override;
  void settings(int narg, char **arg) override;
  void coeff(int narg, char **arg) override;
  void init_style() override;
  double init_one(int i, int j) override;
  double memory_usage() override;

  // called by the history fix
  void history_to_atoms(FixHertzdampHistory *fix);      // before atoms migrate (pre_exchange)
  void history_from_atoms(FixHertzdampHistory *fix);    // after the list is rebuilt (post_neighbor)
  void end_of_run();

  ContactBook book;
  RuleSettings rule;
  int active_contacts() const { return static_cast<int>(pool.size() / NPAYLOAD - freelist.size()); }

 private:
  void allocate();
  int new_contact();
  void free_contact(int c);
  void clear_contacts();

  // per type pair
  double **e_ij = nullptr;        // target restitution
  double **estar_ij = nullptr;    // E* (0: no physical bound)
  double *y_i = nullptr, *nu_i = nullptr;    // material given with pair_coeff I I (0: none)
  double *maxrad = nullptr;       // largest radius of each type (for the cutoff)

  // contacts: payload pool, indexed per neighbor-list entry
  std::vector<double> pool;       // NPAYLOAD doubles per contact
  std::vector<int> freelist;
  std::vector<int> cidx;          // contact index per list entry, -1 = none
  std::vector<int> offset;        // first list entry of each ii
  int cached_inum = -1;
  bool records_valid = false;

  FixHertzdampHistory *fix_history = nullptr;
  std::string fix_id;
};

}    // namespace HertzdampLammps

#endif
