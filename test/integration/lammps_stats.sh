#!/usr/bin/env bash
# LAMMPS plugin test (integrations/lammps/tests/test_stats.py), on both LAMMPS versions:
# e at the touch and release points of oblique impacts; contacts with stock walls.
source "$(dirname "$0")/lammps_common.bash"
run_lammps_test stats
