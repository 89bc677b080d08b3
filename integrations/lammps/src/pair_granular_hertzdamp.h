/* -*- c++ -*-
 * pair_style granular/hertzdamp: Hertz contact with linear damping whose k and d
 * are set per contact, at its onset, by the adaptive collision time rule of the
 * hertzdamp core library (per-pair C API; by default with the constants that make
 * LAMMPS's own integration of the contact exact on average: host lammps); optional friction (tangential, rolling, twisting
 * sub-models of pair_style granular, contact_models.h) with torques.
 */
#ifndef HERTZDAMP_PAIR_GRANULAR_HERTZDAMP_H
#define HERTZDAMP_PAIR_GRANULAR_HERTZDAMP_H

#include "contact_models.h"
#include "hertzdamp_lammps.h"
#include "fix.h"
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
  void write_restart(FILE *fp) override;
  void read_restart(FILE *fp) override;
  void write_restart_settings(FILE *fp) override;
  void read_restart_settings(FILE *fp) override;
  int pack_forward_comm(int n, int *list, double *buf, int pbc_flag, int *pbc) override;
  void unpack_forward_comm(int n, int first, double *buf) override;
  int pack_reverse_comm(int n, int first, double *buf) override;
  void unpack_reverse_comm(int n, int *list, double *buf) override;

  // called by the history fix
  void history_to_atoms(FixHertzdampHistory *fix, bool keep);    // keep: leave the contacts in place
  void history_from_atoms(FixHertzdampHistory *fix);             // after the list is rebuilt (post_neighbor)
  void end_of_run(FixHertzdampHistory *fix);
  // marks this step's contacts that are not isolated collisions (after compute(): the
  // history fix's post_force; communicates the contacts per atom)
  void mark_isolation();

  // constants of type pair i j (valid after the run's init)
  const PairConstants &constants(int i, int j) const;

  // pair contacts of local atom i in this step's force computation (isolation flag of walls)
  double contacts_of(int i) const { return i < static_cast<int>(npair.size()) ? npair[i] : 0.0; }
  // stock wall contacts (fix wall/gran, wall/gran/region with `contacts`) of local atom i
  // at the step before
  double stock_wall_contacts_of(int i) const { return i < static_cast<int>(nstock.size()) ? nstock[i] : 0.0; }

  ContactBook book;
  RuleSettings rule;
  int active_contacts() const { return static_cast<int>(pool.size() / NPAYLOAD - freelist.size()); }
  static const char *history_id() { return "HERTZDAMP_HISTORY"; }

 private:
  void allocate();
  void create_history_fix();
  int new_contact();
  void free_contact(int c);
  void clear_contacts();
  void find_stock_walls();
  void add_central(int i, int j, double fpair, double delx, double dely, double delz);

  // per type pair
  double **e_ij = nullptr;        // target restitution
  double **estar_ij = nullptr;    // E* (0: no physical bound)
  double **gstar_ij = nullptr;    // G* (0: no materials)
  double *y_i = nullptr, *nu_i = nullptr;    // material given with pair_coeff I I (0: none)
  double *maxrad = nullptr;       // largest radius of each type (for the cutoff)
  std::vector<FrictionModel> fm;  // (ntypes+1)^2 friction sub-models
  std::vector<PairConstants> pcs; // (ntypes+1)^2 constants of the rule (hertzdamp_c_pair_init)
  std::vector<CorrectionNodes> cns;    // (ntypes+1)^2, used at [min(I,J)][max(I,J)]: the oblique correction
  bool friction = false;          // any type pair with a tangential model

  // contacts: payload pool, indexed per neighbor-list entry
  std::vector<double> pool;       // NPAYLOAD doubles per contact
  std::vector<int> freelist;
  std::vector<int> cidx;          // contact index per list entry, -1 = none
  std::vector<int> offset;        // first list entry of each ii
  int cached_inum = -1;
  bool records_valid = false;
  bool records_fresh = false;     // records made by end_of_run, no force computation since

  // isolation of contacts: contacts per atom (local + ghost) and this step's contacts
  std::vector<double> ncontact;
  std::vector<double> npair;      // pair contacts of the local atoms
  std::vector<int> touching;      // (contact, i, j) triples of this step
  std::vector<double> nstock;     // stock wall contacts per atom (local + ghost)
  std::vector<LAMMPS_NS::Fix *> stock_walls;    // stock wall fixes with per-atom contacts (init)
  int stock_walls_blind = 0;      // stock wall fixes without `contacts`: not seen

  FixHertzdampHistory *fix_history = nullptr;
  bool history_initialized = false;
  bool isolation_pending = false;  // compute() ran, mark_isolation() not yet
  int lost_contacts = 0;          // contacts lost in transfers this run (reported at its end)
};

}    // namespace HertzdampLammps

#endif
