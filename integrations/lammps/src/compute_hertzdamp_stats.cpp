/* compute hertzdamp/stats: see compute_hertzdamp_stats.h. */
#include "compute_hertzdamp_stats.h"

#include "pair_granular_hertzdamp.h"

#include "force.h"
#include "update.h"

using namespace LAMMPS_NS;

namespace HertzdampLammps {

ComputeHertzdampStats::ComputeHertzdampStats(LAMMPS *lmp, int narg, char **arg) : Compute(lmp, narg, arg)
{
  if (narg != 3) fail_all(lmp, __FILE__, __LINE__, "compute hertzdamp/stats takes no arguments");
  vector_flag = 1;
  size_vector = ContactBook::NSTATS;
  extvector = 0;
  vector = new double[ContactBook::NSTATS]();
}

ComputeHertzdampStats::~ComputeHertzdampStats()
{
  delete[] vector;
}

void ComputeHertzdampStats::compute_vector()
{
  invoked_vector = update->ntimestep;
  auto *pair = dynamic_cast<PairGranularHertzdamp *>(force->pair);
  if (!pair) fail_all(lmp, __FILE__, __LINE__, "compute hertzdamp/stats needs pair_style granular/hertzdamp");
  pair->book.vector(lmp, vector);
}

}    // namespace HertzdampLammps
