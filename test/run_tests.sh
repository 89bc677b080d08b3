#!/usr/bin/env bash
# Runs every test program (fpm's test/ directory) and every other test/*.sh script,
# adds up their `name: P passed, F failed` lines and ends with the total.
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
# every test program in test/ must have been built and listed
want=$(grep -l '^ *program ' test/*.f90 | wc -l)
if [ "${#exes[@]}" -ne "$want" ]; then
  echo "run_tests: ${#exes[@]} test programs listed by fpm, $want in test/"; failed=$((failed + 1))
fi
for exe in "${exes[@]}"; do
  if [ ! -x "$exe" ]; then echo "run_tests: $exe missing"; failed=$((failed + 1)); continue; fi
  run_one "$(basename "$exe")" "$exe"
done
for script in test/*.sh; do
  [ -f "$script" ] || continue
  [ "$(basename "$script")" = run_tests.sh ] && continue
  run_one "$(basename "$script" .sh)" bash "$script"
done
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
