#!/usr/bin/env bash
# Runs every test program (test/unit/, built by fpm) and every script of test/cli/,
# test/docs/ and test/integration/, adds up their `name: P passed, F failed` lines and
# ends with the total.
# A program that crashes or exits non-zero without a summary counts as one failure.
#
# Two lanes when the machine has two cores or more (HERTZDAMP_TEST_LANES=1: one): the
# LAMMPS tests (*lammps*.sh: about half of the time, and they share the working
# directory LAMMPS writes into) run one after the other beside everything else, which
# runs in order as before (the scripts that build with make, CMake or fpm among them,
# so that no two builds share a build directory).  The LAMMPS lane's lines follow.
set -u
fpm=$1; test_flags=$2; release_flags=$3; test_link=${4:-}
cd "$(dirname "$0")/.."
export HERTZDAMP_FPM=$fpm HERTZDAMP_RELEASE_FLAGS=$release_flags   # for scripts that build
export HERTZDAMP_BIN=$("$fpm" run hertzdamp --flag "$release_flags" --runner echo 2>/dev/null | tail -n 1)
failed=0
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
lanes=${HERTZDAMP_TEST_LANES:-$(( $(nproc 2>/dev/null || echo 1) >= 2 ? 2 : 1 ))}

run_one() {  # lane, name, command...: one line per test; "P F" appended to the lane's tally
  local lane=$1 name=$2; shift 2
  local start=$SECONDS log=$work/$lane.log
  timeout 600 "$@" >"$log" 2>&1
  local rc=$?
  local line
  line=$(grep -E '^[A-Za-z0-9_./-]+: [0-9]+ passed, [0-9]+ failed$' "$log" | tail -n 1)
  grep -E '^FAIL|^ +got' "$log" | head -n 40
  if [ -n "$line" ]; then
    local p f
    p=$(sed -E 's/.*: ([0-9]+) passed, ([0-9]+) failed/\1/' <<<"$line")
    f=$(sed -E 's/.*: ([0-9]+) passed, ([0-9]+) failed/\2/' <<<"$line")
    if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then f=1; fi
    echo "$p $f" >>"$work/$lane.tally"
    printf '%-28s %5d passed, %3d failed  (%ds)\n' "$name" "$p" "$f" $((SECONDS - start))
  else
    echo "0 1" >>"$work/$lane.tally"
    printf '%-28s crashed or gave no summary (exit %d)\n' "$name" "$rc"
    tail -n 20 "$log"
  fi
}

mapfile -t exes < <("$fpm" test --flag "$test_flags" --link-flag "$test_link" --runner echo 2>/dev/null | grep -v '^\[' )
# every test program of test/unit/ must have been built and listed, and no Fortran
# source may sit anywhere else under test/ (fpm would build it as a test)
want=$(grep -l '^ *program ' test/unit/*.f90 | wc -l)
stray=$(find test -name '*.f90' ! -path 'test/unit/*' | head -n 3)
echo "run_tests: test/unit: $want programs"
if [ "${#exes[@]}" -ne "$want" ]; then
  echo "run_tests: ${#exes[@]} test programs listed by fpm, $want in test/unit/"; failed=$((failed + 1))
fi
if [ -n "$stray" ]; then echo "run_tests: Fortran sources outside test/unit/: $stray"; failed=$((failed + 1)); fi
scripts=(); lammps=()
for dir in test/cli test/docs test/integration; do
  n=0
  for script in "$dir"/*.sh; do
    [ -f "$script" ] || continue
    n=$((n + 1))
    case $(basename "$script") in *lammps*) lammps+=("$script") ;; *) scripts+=("$script") ;; esac
  done
  echo "run_tests: $dir: $n scripts"
done
# a script left directly in test/ (besides this one) would never run
for script in test/*.sh; do
  [ "$(basename "$script")" = run_tests.sh ] && continue
  echo "run_tests: $script is outside test/{cli,docs,integration}/"; failed=$((failed + 1))
done
run_lammps() { local s; for s in "${lammps[@]}"; do run_one lammps "$(basename "$s" .sh)" bash "$s"; done; }
if [ "$lanes" -ge 2 ]; then run_lammps >"$work/lammps.out" 2>&1 & fi
for exe in "${exes[@]}"; do
  if [ ! -x "$exe" ]; then echo "run_tests: $exe missing"; failed=$((failed + 1)); continue; fi
  run_one main "$(basename "$exe")" "$exe"
done
for script in "${scripts[@]}"; do
  run_one main "$(basename "$script" .sh)" bash "$script"
done
if [ "$lanes" -ge 2 ]; then wait; cat "$work/lammps.out"; else run_lammps; fi
read -r passed f < <(cat "$work"/*.tally 2>/dev/null | awk '{ p += $1; f += $2 } END { print p + 0, f + 0 }')
failed=$((failed + f))
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
