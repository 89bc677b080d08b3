#!/usr/bin/env bash
# LAMMPS plugin test (integrations/lammps/tests/test_pour.py): poured beads (LAMMPS granular examples)
# flatwall and drum, -np 1 and 2, on both LAMMPS versions.  Builds what it
# needs with `make lammps`.
set -u
cd "$(dirname "$0")/.."
if ! make --no-print-directory -s lammps >/tmp/hertzdamp_lammps_build.$$ 2>&1; then
  tail -n 30 /tmp/hertzdamp_lammps_build.$$; rm -f /tmp/hertzdamp_lammps_build.$$
  echo "lammps_pour: 0 passed, 1 failed"; exit 1
fi
rm -f /tmp/hertzdamp_lammps_build.$$
exec python3 integrations/lammps/tests/test_pour.py
