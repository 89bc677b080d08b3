#!/usr/bin/env bash
# LAMMPS plugin test (integrations/lammps/tests/test_oblique.py), on both LAMMPS versions:
# oblique pair impacts at 0-75 degrees, N = 20, e = 0.2, 0.5, 0.9, frictionless and with
# friction: e_n within 2e-3 of the target with the normal correction; the gap without it.
source "$(dirname "$0")/lammps_common.bash"
run_lammps_test oblique
