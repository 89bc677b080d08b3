/* -*- c++ -*-
 * compute ID all hertzdamp/stats: global vector of per-contact statistics of
 * pair_style granular/hertzdamp, summed / reduced over all processors:
 *   1 contacts   2 u_min  3 u_max  4 k_min  5 k_max  6 d_min  7 d_max
 *   8 contacts with k = k_phys  9 contacts ended  10 e_min  11 e_max
 *   12 log rows not yet written  13 contacts carried through neighbor-list
 *   rebuilds (per rebuild and processor; not a count of contacts)
 *   14 isolated binary collisions  15 their mean e  16 the spread (standard
 *   deviation) of their e  17 ended contacts left out of 10, 11, 15, 16
 * u = relative normal approach speed at onset (before the vmin floor); e = speed
 * of separation / u, measured when the overlap ends, over isolated binary collisions
 * only (no other contact of either bead meanwhile, impact speed not raised to vmin).
 * Counts since pair_style (or read_restart).
 *
 * Global array, one row per type pair I <= J (row (I-1) n - (I-1)(I-2)/2 + J - I + 1 of
 * n types): what the rule's constants achieve in LAMMPS's integrator, from the library
 * (hertzdamp_c_pair_stats, over the onset phase of a head-on collision):
 *   1 I  2 J  3 target e  4 mean e  5 e spread (standard deviation / mean)
 *   6 mean T_c / (N dt)  7 T_c spread (sd / mean)
 * (zeros for fixed K D, or before the first run).  host lammps: 4 = 3 and 6 = 1.
 */
#ifndef HERTZDAMP_COMPUTE_HERTZDAMP_STATS_H
#define HERTZDAMP_COMPUTE_HERTZDAMP_STATS_H

#include "compute.h"
#include "hertzdamp_lammps.h"

namespace HertzdampLammps {

class ComputeHertzdampStats : public LAMMPS_NS::Compute {
 public:
  ComputeHertzdampStats(LAMMPS *lmp, int narg, char **arg);
  ~ComputeHertzdampStats() override;
  void init() override {}
  void compute_vector() override;
  void compute_array() override;
};

}    // namespace HertzdampLammps

#endif
