#!/usr/bin/env bash
# LAMMPS plugin test (integrations/lammps/tests/test_pour.py), on both LAMMPS versions:
# LAMMPS's granular pour examples with the style swapped in, -np 1 and 2.
source "$(dirname "$0")/lammps_common.bash"
run_lammps_test pour
