#!/usr/bin/env bash
# LAMMPS plugin test (integrations/lammps/tests/test_restart.py), on both LAMMPS versions:
# a restart file at every step of an oblique friction contact, each continued run bit for
# bit as the uninterrupted one.
source "$(dirname "$0")/lammps_common.bash"
run_lammps_test restart
