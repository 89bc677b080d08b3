#!/usr/bin/env bash
# Lint: fortitude (settings in fortitude.toml) finds nothing in the Fortran sources.
cd "$(dirname "$0")/../.."
dirs=$(for d in src app packages test gen example; do [ -d $d ] && echo $d; done)
if .venv/bin/fortitude check $dirs --output-format concise >/tmp/hertzdamp-lint.$$ 2>&1; then
  echo "lint: 1 passed, 0 failed"; rm -f /tmp/hertzdamp-lint.$$
else
  grep -E '^[^ ]+:[0-9]+:[0-9]+: ' /tmp/hertzdamp-lint.$$ | head -n 30 | sed 's/^/FAIL lint: /'; rm -f /tmp/hertzdamp-lint.$$
  echo "lint: 0 passed, 1 failed"; exit 1
fi
