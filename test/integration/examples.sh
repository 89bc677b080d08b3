#!/usr/bin/env bash
# The fpm examples (every [[example]] of fpm.toml) build and run (exit 0, non-empty
# output); the plain-Makefile examples (example/legacy_dem/, example/c/) are built and
# run against an installed prefix by test/integration/install_consumers.sh.
cd "$(dirname "$0")/../.."
fpm=${HERTZDAMP_FPM:-.venv/bin/fpm}
p=0; f=0
mapfile -t examples < <(sed -n '/^\[\[example\]\]/,/^main/s/^name = "\(.*\)"/\1/p' fpm.toml)
if [ "${#examples[@]}" -ge 3 ]; then p=$((p + 1)); else f=$((f + 1)); echo "FAIL examples: fpm.toml lists ${#examples[@]} examples"; fi
for ex in "${examples[@]}"; do
  out=$("$fpm" run --example "$ex" --flag "${HERTZDAMP_RELEASE_FLAGS:-}" 2>/dev/null)
  if [ $? -eq 0 ] && [ -n "$out" ]; then p=$((p + 1)); else f=$((f + 1)); echo "FAIL examples: $ex"; fi
done
# the series accuracy table has the seven method rows of README.md
n=$("$fpm" run --example series_accuracy --flag "${HERTZDAMP_RELEASE_FLAGS:-}" 2>/dev/null | grep -c '^| \(series\|Padé\)')
if [ "$n" -eq 7 ]; then p=$((p + 1)); else f=$((f + 1)); echo "FAIL examples: series_accuracy rows ($n)"; fi
# the script named above builds and runs both plain-Makefile examples
for d in legacy_dem c; do
  if grep -q "example/$d\b" test/integration/install_consumers.sh && [ -f "example/$d/Makefile" ]; then
    p=$((p + 1)); else f=$((f + 1)); echo "FAIL examples: example/$d is not built by install_consumers.sh"; fi
done
echo "examples: $p passed, $f failed"
[ "$f" -eq 0 ]
