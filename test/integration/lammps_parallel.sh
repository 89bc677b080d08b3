#!/usr/bin/env bash
# LAMMPS plugin test (integrations/lammps/tests/test_parallel.py), on both LAMMPS versions:
# the gas under mpirun -np 1 and 2, contacts that migrate between processors.
source "$(dirname "$0")/lammps_common.bash"
run_lammps_test parallel
