#!/usr/bin/env bash
# The generated Fortran module must be exactly what gen/fit_csv_to_f90.py makes
# of data/fit_coefficients.csv (no hand edits, no stale copy).
cd "$(dirname "$0")/../.."
p=0; f=0
tmp=$(mktemp); trap 'rm -f "$tmp"' EXIT
if python3 gen/fit_csv_to_f90.py data/fit_coefficients.csv "$tmp" && diff -q "$tmp" src/hertzdamp_fit_data.f90 >/dev/null; then
  p=$((p + 1))
else
  echo "FAIL sync_fit: src/hertzdamp_fit_data.f90 differs from the CSV (run make fit-source)"; f=$((f + 1))
fi
# deterministic: a second conversion gives the same bytes
if python3 gen/fit_csv_to_f90.py data/fit_coefficients.csv - | cmp -s - "$tmp"; then p=$((p + 1)); else
  echo "FAIL sync_fit: converter not deterministic"; f=$((f + 1)); fi
# header of the CSV names the generator and the reference tolerance
if grep -q '^# .*gen/fit/gen_fit.f90' data/fit_coefficients.csv && grep -q 'tolerance 1.000E-15' data/fit_coefficients.csv; then
  p=$((p + 1)); else echo "FAIL sync_fit: CSV header"; f=$((f + 1)); fi
if grep -q 'do not edit' src/hertzdamp_fit_data.f90; then p=$((p + 1)); else echo "FAIL sync_fit: no do-not-edit note"; f=$((f + 1)); fi
# the constants table of doc/compact.md is what gen/compact_table.py prints from the CSV
if [ "$(python3 gen/compact_table.py data/fit_coefficients.csv | grep -cxFf - doc/compact.md)" -eq 10 ]; then
  p=$((p + 1)); else echo "FAIL sync_fit: doc/compact.md constants differ from the CSV"; f=$((f + 1)); fi
echo "sync_fit: $p passed, $f failed"
[ "$f" -eq 0 ]
