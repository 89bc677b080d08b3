#!/usr/bin/env bash
# LAMMPS plugin test (integrations/lammps/tests/test_phases.py), on both LAMMPS versions:
# host-exact constants: mean e and T_c over the onset phase at N = 20, pair and wall;
# host none's error; the reported statistics; N too small.
source "$(dirname "$0")/lammps_common.bash"
run_lammps_test phases
