#!/usr/bin/env bash
# LAMMPS plugin test (integrations/lammps/tests/test_friction.py), on both LAMMPS versions:
# friction against stock pair_style granular, rolling, spin, restart.
source "$(dirname "$0")/lammps_common.bash"
run_lammps_test friction
