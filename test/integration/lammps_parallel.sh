#!/usr/bin/env bash
# LAMMPS plugin test (integrations/lammps/tests/test_parallel.py): builds what it needs
# with `make lammps` (Debian lammps/openmpi if missing, the core, the plugin).
set -u
cd "$(dirname "$0")/../.."
if ! make --no-print-directory -s lammps >/tmp/hertzdamp_lammps_build.$$ 2>&1; then
  tail -n 30 /tmp/hertzdamp_lammps_build.$$; rm -f /tmp/hertzdamp_lammps_build.$$
  echo "lammps_parallel: 0 passed, 1 failed"; exit 1
fi
rm -f /tmp/hertzdamp_lammps_build.$$
exec python3 integrations/lammps/tests/test_parallel.py
