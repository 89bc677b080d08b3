# Shared helpers for the CLI test scripts (sourced, not run): counted checks and
# a `run` wrapper that captures stdout, stderr and the exit code of the CLI.
set -u
BIN=${HERTZDAMP_BIN:?HERTZDAMP_BIN must point to the hertzdamp executable}
# the Python with the modules the tests import (make test: .venv's, see the Makefile)
PYTHON=${HERTZDAMP_PYTHON:-python3}
PASSED=0; FAILED=0
# hertzdamp_text.py (beside this file) reads the text output back: `import hertzdamp_text`
export PYTHONPATH="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)${PYTHONPATH:+:$PYTHONPATH}"
OUT=$(mktemp); ERR=$(mktemp)
trap 'rm -f "$OUT" "$ERR"' EXIT

check() {  # label, command...
  local label=$1; shift
  if "$@"; then PASSED=$((PASSED + 1)); else FAILED=$((FAILED + 1)); echo "FAIL $SUITE: $label"; fi
}
run() { "$BIN" "$@" >"$OUT" 2>"$ERR"; RC=$?; }
# a failing command: given exit code, empty stdout, exactly one line on stderr
expect_fail() {  # code, label, args...
  local code=$1 label=$2; shift 2
  run "$@"
  check "$label: exit $code (got $RC)" test "$RC" -eq "$code"
  check "$label: stdout empty" test ! -s "$OUT"
  check "$label: one line on stderr" test "$(wc -l <"$ERR")" -eq 1
}
finish() { echo "$SUITE: $PASSED passed, $FAILED failed"; [ "$FAILED" -eq 0 ]; }
