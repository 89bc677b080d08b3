#!/usr/bin/env bash
# The series tables are reproducible and in sync:
#  1. rerunning the generator reproduces data/series_coefficients.csv and
#     data/pade_coefficients.csv within the accuracy stated in their *_err columns;
#  2. the Fortran sources are exactly what gen/csv_to_f90.py makes of the CSVs.
SUITE=sync_series
cd "$(dirname "$0")/../.."
PASSED=0; FAILED=0
check() { local l=$1; shift; if "$@"; then PASSED=$((PASSED+1)); else FAILED=$((FAILED+1)); echo "FAIL $SUITE: $l"; fi; }
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fpm=${HERTZDAMP_FPM:-.venv/bin/fpm}
"$fpm" run hertzdamp-gen-series --flag "${HERTZDAMP_RELEASE_FLAGS:-}" -- "$tmp" >"$tmp/log" 2>&1
check "generator runs" test $? -eq 0
check "series CSV regenerated within stated accuracy" python3 - "$tmp/series_coefficients.csv" data/series_coefficients.csv <<'PY'
import csv, sys
def load(p):
    rows = [r for r in csv.reader(l for l in open(p) if not l.startswith('#'))]
    return rows[0], rows[1:]
h1, a = load(sys.argv[1]); h2, b = load(sys.argv[2])
assert h1 == h2 and len(a) == len(b) and len(a) >= 21, "shape"
for ra, rb in zip(a, b):
    for j, name in enumerate(h1):
        if name == 'n' or name.endswith('_err'):
            continue
        k = h1.index(name + '_err')
        x, y = float(ra[j]), float(rb[j])
        tol = float(ra[k]) + float(rb[k])
        assert abs(x - y) <= tol, f"{name}_{ra[0]}: {x} vs {y} (tol {tol})"
PY
check "pade CSV regenerated within round-off" python3 - "$tmp/pade_coefficients.csv" data/pade_coefficients.csv <<'PY'
import sys
def load(p):
    return [l.strip().split(',') for l in open(p) if not l.startswith('#') and l.strip()]
a, b = load(sys.argv[1]), load(sys.argv[2])
assert a[0] == b[0] and len(a) == len(b)
for ra, rb in zip(a[1:], b[1:]):
    for x, y in zip(ra, rb):
        try:
            fx, fy = float(x), float(y)
        except ValueError:
            assert x == y; continue
        assert abs(fx - fy) <= 1e-13 * max(1.0, abs(fy)), (x, y)
PY
# run the converter exactly as `make series-source` does, in a copy of the tree
mkdir -p "$tmp/tree/src" "$tmp/tree/gen" "$tmp/tree/data"
cp gen/csv_to_f90.py "$tmp/tree/gen/"; cp data/series_coefficients.csv data/pade_coefficients.csv "$tmp/tree/data/"
(cd "$tmp/tree" && make -s -f "$OLDPWD/Makefile" series-source >/dev/null)
check "src/hertzdamp_series_data.f90 is generated from the CSV" diff -q "$tmp/tree/src/hertzdamp_series_data.f90" src/hertzdamp_series_data.f90
check "src/hertzdamp_pade_data.f90 is generated from the CSV" diff -q "$tmp/tree/src/hertzdamp_pade_data.f90" src/hertzdamp_pade_data.f90
echo "$SUITE: $PASSED passed, $FAILED failed"
[ "$FAILED" -eq 0 ]
