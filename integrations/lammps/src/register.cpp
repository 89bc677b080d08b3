/*
 * Registration of the hertzdamp styles with a running LAMMPS.
 *
 *  - hertzdamp_lammps_register(lmp): for Debian's stock lmp, which has no
 *    `plugin` command.  build/lammps/load.lmp calls it through LAMMPS's `python`
 *    command (ctypes), with the LAMMPS pointer.  It inserts the creators into the
 *    public style maps Force::pair_map and Modify::fix_map / compute_map.
 *  - lammpsplugin_init(lmp, handle, regfunc): the entry point of LAMMPS's
 *    `plugin load` (LAMMPS built with the PLUGIN package).  The record layout
 *    below follows the documented lammpsplugin_t of LAMMPS 2021 (version, style,
 *    name, info, author, creator, handle).
 *
 * The styles are compiled against the headers of one LAMMPS version; both entry
 * points refuse to register into a different version.
 */
#include "compute_hertzdamp_stats.h"
#include "fix_hertzdamp_history.h"
#include "fix_hertzdamp_wall.h"
#include "pair_granular_hertzdamp.h"

#include "comm.h"
#include "force.h"
#include "modify.h"

#include <cstring>
#include <string>

#ifndef HERTZDAMP_LAMMPS_VERSION
#error "HERTZDAMP_LAMMPS_VERSION (the version string of the LAMMPS headers) must be defined"
#endif

using namespace LAMMPS_NS;
using namespace HertzdampLammps;

namespace {

Pair *make_pair(LAMMPS *lmp)
{
  return new PairGranularHertzdamp(lmp);
}
template <class T> Fix *make_fix(LAMMPS *lmp, int narg, char **arg)
{
  return new T(lmp, narg, arg);
}
Compute *make_stats(LAMMPS *lmp, int narg, char **arg)
{
  return new ComputeHertzdampStats(lmp, narg, arg);
}

bool version_ok(LAMMPS *lmp)
{
  return lmp->version && strcmp(lmp->version, HERTZDAMP_LAMMPS_VERSION) == 0;
}

// plugin record (same layout as LAMMPS's lammpsplugin_t)
typedef void *(*creator_any)();
struct PluginRecord {
  const char *version;
  const char *style;
  const char *name;
  const char *info;
  const char *author;
  void *creator;
  void *handle;
};
typedef void (*register_fn)(PluginRecord *, void *);

}    // namespace

extern "C" {

/* Returns 0 on success, 1 if the LAMMPS version differs from the headers used. */
__attribute__((visibility("default"))) int hertzdamp_lammps_register(void *ptr)
{
  auto *lmp = static_cast<LAMMPS *>(ptr);
  if (!version_ok(lmp)) {
    if (lmp->comm->me == 0)
      fprintf(stderr, "hertzdamp: plugin built for LAMMPS %s, not %s: not registered\n",
              HERTZDAMP_LAMMPS_VERSION, lmp->version);
    return 1;
  }
  (*lmp->force->pair_map)["granular/hertzdamp"] = &make_pair;
  (*lmp->modify->fix_map)["hertzdamp/wall"] = &make_fix<FixHertzdampWall>;
  (*lmp->modify->fix_map)["HERTZDAMP/HISTORY"] = &make_fix<FixHertzdampHistory>;
  (*lmp->modify->compute_map)["hertzdamp/stats"] = &make_stats;
  logmesg(lmp, "hertzdamp: registered pair_style granular/hertzdamp, fix hertzdamp/wall, "
               "compute hertzdamp/stats\n");
  return 0;
}

__attribute__((visibility("default"))) void lammpsplugin_init(void *ptr, void *handle, void *regfunc)
{
  auto *lmp = static_cast<LAMMPS *>(ptr);
  if (!version_ok(lmp)) {
    if (lmp->comm->me == 0)
      fprintf(stderr, "hertzdamp: plugin built for LAMMPS %s, not %s: not loaded\n",
              HERTZDAMP_LAMMPS_VERSION, lmp->version);
    return;
  }
  auto reg = reinterpret_cast<register_fn>(regfunc);
  PluginRecord r;
  r.version = HERTZDAMP_LAMMPS_VERSION;
  r.author = "hertzdamp";
  r.handle = handle;

  r.style = "pair";
  r.name = "granular/hertzdamp";
  r.info = "Hertz contact with per-contact k and d from the hertzdamp rule";
  r.creator = reinterpret_cast<void *>(&make_pair);
  reg(&r, ptr);

  r.style = "fix";
  r.name = "hertzdamp/wall";
  r.info = "flat walls with per-contact k and d from the hertzdamp rule";
  r.creator = reinterpret_cast<void *>(&make_fix<FixHertzdampWall>);
  reg(&r, ptr);

  r.name = "HERTZDAMP/HISTORY";
  r.info = "contact history of pair granular/hertzdamp (internal)";
  r.creator = reinterpret_cast<void *>(&make_fix<FixHertzdampHistory>);
  reg(&r, ptr);

  r.style = "compute";
  r.name = "hertzdamp/stats";
  r.info = "per-contact statistics of pair granular/hertzdamp";
  r.creator = reinterpret_cast<void *>(&make_stats);
  reg(&r, ptr);
}

}    // extern "C"
