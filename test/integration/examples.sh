#!/usr/bin/env bash
# The fpm examples build and run (exit 0, non-empty output); the plain-Makefile
# examples (legacy_dem/, c/) run in cli_install.sh against an installed prefix.
cd "$(dirname "$0")/.."
fpm=${HERTZDAMP_FPM:-.venv/bin/fpm}
p=0; f=0
for ex in example_invert series_accuracy; do
  out=$("$fpm" run --example "$ex" --flag "${HERTZDAMP_RELEASE_FLAGS:-}" 2>/dev/null)
  if [ $? -eq 0 ] && [ -n "$out" ]; then p=$((p + 1)); else f=$((f + 1)); echo "FAIL examples: $ex"; fi
done
# the series accuracy table has the seven method rows of README.md
n=$("$fpm" run --example series_accuracy --flag "${HERTZDAMP_RELEASE_FLAGS:-}" 2>/dev/null | grep -c '^| \(series\|Padé\)')
if [ "$n" -eq 7 ]; then p=$((p + 1)); else f=$((f + 1)); echo "FAIL examples: series_accuracy rows ($n)"; fi
echo "examples: $p passed, $f failed"
[ "$f" -eq 0 ]
