#!/usr/bin/env bash
# Figures copied into README.md are what the programs print today: the series accuracy
# table (example/series_accuracy.f90) and the `invert` example.
cd "$(dirname "$0")/.."
fpm=${HERTZDAMP_FPM:-.venv/bin/fpm}
p=0; f=0
check() { local l=$1; shift; if "$@"; then p=$((p + 1)); else f=$((f + 1)); echo "FAIL readme_sync: $l"; fi; }
rows=$("$fpm" run --example series_accuracy --flag "${HERTZDAMP_RELEASE_FLAGS:-}" 2>/dev/null | grep '^|')
check "series accuracy table printed" test "$(wc -l <<<"$rows")" -eq 9
while IFS= read -r row; do
  check "README has the row: ${row:0:40}" grep -qxF -- "$row" README.md
done <<<"$rows"
if [ -n "${HERTZDAMP_BIN:-}" ]; then
  line=$("$HERTZDAMP_BIN" invert --e 0.5 --dt 1e-6 --steps 10 --mass 1e-3 --velocity 1 --format csv | sed -n 2p)
  check "README invert example matches the CLI" grep -qxF -- "    $line" README.md
fi
echo "readme_sync: $p passed, $f failed"
[ "$f" -eq 0 ]
