/* -*- c++ -*-
 * fix hertzdamp/wall: a flat wall with the same per-contact rule as
 * pair_style granular/hertzdamp (effective mass = particle mass, R* = R), and the
 * same friction sub-models (contact_models.h).
 *
 * fix ID group hertzdamp/wall (steps N | tc T | fixed K D) e E [end overlap|force]
 *     [host lammps|none] [vmin V] [phase yes|no] [youngs Y poisson NU [wall_youngs YW wall_poisson NUW]]
 *     [tangential ...] [rolling ...] [twisting ...] [log FILE]
 *     (xplane|yplane|zplane) LO HI         (one wall per fix; LO or HI may be NULL)
 */
#ifndef HERTZDAMP_FIX_HERTZDAMP_WALL_H
#define HERTZDAMP_FIX_HERTZDAMP_WALL_H

#include "contact_models.h"
#include "fix.h"
#include "hertzdamp_lammps.h"

#include <vector>

namespace HertzdampLammps {

class FixHertzdampWall : public LAMMPS_NS::Fix {
 public:
  FixHertzdampWall(LAMMPS *lmp, int narg, char **arg);
  ~FixHertzdampWall() override;
  int setmask() override;
  void init() override;
  void setup(int vflag) override;
  void post_force(int vflag) override;
  void post_run() override;
  void end_of_step() override;
  double compute_vector(int n) override;
  // wall contacts of local atom i at the end of the last step (they move with the atom)
  double active_contacts(int i) const { return (wst[i][0] == ACTIVE ? 1.0 : 0.0) + (wst[i][SLOT] == ACTIVE ? 1.0 : 0.0); }
  // per side: 0 no contact, ACTIVE, ENDED (at the last step, its closing correction kept)
  enum { ACTIVE = 1, ENDED = 2 };

  void grow_arrays(int nmax) override;
  void copy_arrays(int i, int j, int delflag) override;
  void set_arrays(int i) override;
  int pack_exchange(int i, double *buf) override;
  int unpack_exchange(int nlocal, double *buf) override;
  int pack_restart(int i, double *buf) override;
  void unpack_restart(int nlocal, int nth) override;
  int size_restart(int i) override { return 1 + NCOL; }
  int maxsize_restart() override { return 1 + NCOL; }
  double memory_usage() override;

  ContactBook book;

 private:
  enum { SLOT = 1 + NPAYLOAD, NCOL = 2 * SLOT };    // per side: active flag + payload
  void contact(int i, int side, double ov, int setup);
  RuleSettings rule;
  PairConstants pc;    // the rule's constants at this run's N (init)
  FrictionModel fm;
  double e = 0.0, estar = 0.0, gstar = 0.0;
  int axis = -1;
  int has_lo = 0, has_hi = 0;
  double lo = 0.0, hi = 0.0;
  double **wst = nullptr;
  double cache[ContactBook::NSTATS + NHOSTSTATS + ContactBook::NEXTRA];
  LAMMPS_NS::bigint cache_step = -1;
};

}    // namespace HertzdampLammps

#endif
