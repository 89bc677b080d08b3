#!/usr/bin/env bash
# Runs every test program (test/unit/, built by fpm) and every script of test/cli/,
# test/docs/ and test/integration/, adds up their `name: P passed, F failed` lines and
# ends with the total.
# A program that crashes or exits non-zero without a summary counts as one failure.
set -u
fpm=$1; test_flags=$2; release_flags=$3; test_link=${4:-}
cd "$(dirname "$0")/.."
export HERTZDAMP_FPM=$fpm HERTZDAMP_RELEASE_FLAGS=$release_flags   # for scripts that build
export HERTZDAMP_BIN=$("$fpm" run hertzdamp --flag "$release_flags" --runner echo 2>/dev/null | tail -n 1)
passed=0; failed=0
log=$(mktemp); trap 'rm -f "$log"' EXIT

run_one() {  # name, command...
  local name=$1; shift
  local start=$SECONDS
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
    passed=$((passed + p)); failed=$((failed + f))
    printf '%-28s %5d passed, %3d failed  (%ds)\n' "$name" "$p" "$f" $((SECONDS - start))
  else
    failed=$((failed + 1))
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
for exe in "${exes[@]}"; do
  if [ ! -x "$exe" ]; then echo "run_tests: $exe missing"; failed=$((failed + 1)); continue; fi
  run_one "$(basename "$exe")" "$exe"
done
for dir in test/cli test/docs test/integration; do
  scripts=("$dir"/*.sh)
  echo "run_tests: $dir: ${#scripts[@]} scripts"
  for script in "${scripts[@]}"; do
    [ -f "$script" ] || continue
    run_one "$(basename "$script" .sh)" bash "$script"
  done
done
# a script left directly in test/ (besides this one) would never run
for script in test/*.sh; do
  [ "$(basename "$script")" = run_tests.sh ] && continue
  echo "run_tests: $script is outside test/{cli,docs,integration}/"; failed=$((failed + 1))
done
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
