#!/usr/bin/env bash
# LAMMPS plugin test (integrations/lammps/tests/test_input.py), on both LAMMPS versions:
# bad input stops LAMMPS with an error naming the keyword.
source "$(dirname "$0")/lammps_common.bash"
run_lammps_test input
