#!/usr/bin/env bash
# The Python package (python/hertzdamp, doc/python.md): its tests (python/tests, pytest) run
# with .venv's python against the core library that `make lammps` installs into
# build/lammps/core (this checkout's src/), the program (HERTZDAMP_BIN, for the CLI
# comparisons) and the LAMMPS plugin (build/lammps/load.lmp, for the LAMMPS example).
# Every test must run: a skip (a missing program, plugin or module), an error, or
# pytest's "no tests ran" counts as a failure.  Ends with `python: P passed, F failed`.
cd "$(dirname "$0")/../.."
py=${HERTZDAMP_PYTHON:-.venv/bin/python}
lib=$PWD/build/lammps/core/lib/libhertzdamp.so
load=$PWD/build/lammps/load.lmp
p=0; f=0
missing=""
[ -f "$lib" ] || missing="$missing $lib (make lammps)"
[ -f "$load" ] || missing="$missing $load (make lammps)"
[ -n "${HERTZDAMP_BIN:-}" ] || missing="$missing HERTZDAMP_BIN (test/run_tests.sh sets it)"
if [ -n "$missing" ]; then
  echo "FAIL python: missing:$missing"
  echo "python: 0 passed, 1 failed"; exit 1
fi
out=$(mktemp); trap 'rm -f "$out"' EXIT
HERTZDAMP_LIBRARY=$lib HERTZDAMP_LAMMPS_LOAD=$load PYTHONPATH=$PWD/python PYTHONDONTWRITEBYTECODE=1 \
  "$py" -m pytest -p no:cacheprovider -q -rfEs python/tests >"$out" 2>&1
rc=$?
tail -n 40 "$out" | grep -E '^(FAILED|ERROR|SKIPPED)' | sed 's/^/FAIL python: /'
last=$(grep -E '^(=+ )?[0-9]+ (passed|failed|skipped|error)|no tests ran' "$out" | tail -n 1)
echo "pytest: $last"
count() { grep -oE "[0-9]+ $1" <<<"$last" | grep -oE '^[0-9]+' || echo 0; }
p=$(count passed)
f=$(( $(count failed) + $(count skipped) + $(count errors) + $(count error) ))
if [ "$p" -eq 0 ]; then echo "FAIL python: no test ran"; f=$((f + 1)); fi
if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then echo "FAIL python: pytest exited $rc"; tail -n 20 "$out"; f=1; fi
echo "python: $p passed, $f failed"
[ "$f" -eq 0 ]
