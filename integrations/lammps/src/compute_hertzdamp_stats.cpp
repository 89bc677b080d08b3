/* compute hertzdamp/stats: see compute_hertzdamp_stats.h. */
#include "compute_hertzdamp_stats.h"

#include "pair_granular_hertzdamp.h"

#include "atom.h"
#include "force.h"
#include "memory.h"
#include "update.h"

using namespace LAMMPS_NS;

namespace HertzdampLammps {

ComputeHertzdampStats::ComputeHertzdampStats(LAMMPS *lmp, int narg, char **arg) : Compute(lmp, narg, arg)
{
  if (narg != 3) fail_all(lmp, __FILE__, __LINE__, "compute hertzdamp/stats takes no arguments");
  vector_flag = 1;
  size_vector = ContactBook::NSTATS + ContactBook::NEXTRA;
  extvector = 0;
  vector = new double[ContactBook::NSTATS + ContactBook::NEXTRA]();
  array_flag = 1;
  extarray = 0;
  size_array_cols = 3 + NHOSTSTATS;
  size_array_rows = atom->ntypes * (atom->ntypes + 1) / 2;
  memory->create(array, size_array_rows, size_array_cols, "hertzdamp/stats:array");
  for (int r = 0; r < size_array_rows; r++)
    for (int c = 0; c < size_array_cols; c++) array[r][c] = 0.0;
}

ComputeHertzdampStats::~ComputeHertzdampStats()
{
  delete[] vector;
  memory->destroy(array);
}

void ComputeHertzdampStats::compute_vector()
{
  invoked_vector = update->ntimestep;
  auto *pair = dynamic_cast<PairGranularHertzdamp *>(force->pair);
  if (!pair) fail_all(lmp, __FILE__, __LINE__, "compute hertzdamp/stats needs pair_style granular/hertzdamp");
  pair->book.vector(lmp, vector);
}

void ComputeHertzdampStats::compute_array()
{
  invoked_array = update->ntimestep;
  auto *pair = dynamic_cast<PairGranularHertzdamp *>(force->pair);
  if (!pair) fail_all(lmp, __FILE__, __LINE__, "compute hertzdamp/stats needs pair_style granular/hertzdamp");
  const int n = atom->ntypes;
  int r = 0;
  for (int i = 1; i <= n && r < size_array_rows; i++)
    for (int j = i; j <= n && r < size_array_rows; j++, r++) {
      const PairConstants &pc = pair->constants(i, j);
      array[r][0] = i;
      array[r][1] = j;
      array[r][2] = pc.valid ? pc.e : 0.0;
      constants_stats(pc, array[r] + 3);
    }
}

}    // namespace HertzdampLammps
