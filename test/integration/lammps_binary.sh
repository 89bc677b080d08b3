#!/usr/bin/env bash
# LAMMPS plugin test (integrations/lammps/tests/test_binary.py), on both LAMMPS versions:
# head-on collisions and a wall: e, T_c, k and d against the C API.
source "$(dirname "$0")/lammps_common.bash"
run_lammps_test binary
