#!/usr/bin/env bash
# `invert --fixed`: the best single fixed (k, d) over a range of impact speeds (issue
# 25 item 7), through the command line.  The brute-force search it is tested against
# is test/unit/test_fixed.f90; here: one k and d in every row, the worst error equal
# and opposite at the slowest and fastest impact and the largest of all rows, the
# shortest contact = --dt x --steps, every row reproduced by `forward --method rk45`
# with that k and d, a pair nudged either way does worse, tsuji exact, the bound, and
# the options that do not apply.
SUITE=cli_fixed
source "$(dirname "$0")/cli_common.bash"
cd "$(dirname "$0")/../.."
T=$(mktemp -d); trap 'rm -rf "$T" "$OUT" "$ERR"' EXIT
GLASS="--radius 1e-3 --density 2500 --youngs-modulus 63e9 --poisson-ratio 0.24"

run invert --fixed $GLASS --e 0.9 --dt 1e-6 --steps 10 --velocity 0.01,0.03,0.1,0.3,1,3,5 --format csv
cp "$OUT" "$T/fixed.csv"
check "glass, e 0.9: exit 0" test "$RC" -eq 0
check "glass: the columns" test "$(head -n 1 "$OUT")" = \
  "e,tc,velocity,mass,radius_eff,k_phys,k,d,bound_active,alpha,e_fixed,e_error,tc_fixed,worst_e_error,status"
check "glass: one pair, worst error at the ends, equal and opposite, the shortest contact 10 x 1e-6 s" python3 - "$OUT" <<'PYEOF'
import csv, sys
r = list(csv.DictReader(open(sys.argv[1])))
assert len(r) == 7 and all(x["status"] == "ok" for x in r)
assert len({(x["k"], x["d"], x["worst_e_error"]) for x in r}) == 1
w = float(r[0]["worst_e_error"])
err = [float(x["e_error"]) for x in r]
assert abs(err[0] + w) < 1e-9 and abs(err[-1] - w) < 1e-9, (err, w)
assert all(abs(x) <= w + 1e-12 for x in err)
assert 0.05 < w < 0.07, w                       # 6 % over 0.01-5 m/s at e = 0.9
tc = [float(x["tc_fixed"]) for x in r]
assert abs(min(tc) / 1e-5 - 1) < 1e-9 and min(tc) == tc[-1], tc
assert all(abs(float(x["e_fixed"]) / 0.9 - 1 - float(x["e_error"])) < 1e-15 for x in r)
PYEOF
K=$(python3 -c 'import csv,sys; print(next(csv.DictReader(open(sys.argv[1])))["k"])' "$T/fixed.csv")
D=$(python3 -c 'import csv,sys; print(next(csv.DictReader(open(sys.argv[1])))["d"])' "$T/fixed.csv")
run forward --k "$K" --d "$D" $GLASS --velocity 0.01,0.03,0.1,0.3,1,3,5 --method rk45 --format csv
check "forward --method rk45 with that k and d gives e_fixed and tc_fixed at every speed" python3 - "$T/fixed.csv" "$OUT" <<'PYEOF'
import csv, sys
a = list(csv.DictReader(open(sys.argv[1]))); b = list(csv.DictReader(open(sys.argv[2])))
assert len(a) == len(b)
for x, y in zip(a, b):
    assert abs(float(y["e"]) / float(x["e_fixed"]) - 1) < 1e-10, (x["e_fixed"], y["e"])
    assert abs(float(y["t_c"]) / float(x["tc_fixed"]) - 1) < 1e-10, (x["tc_fixed"], y["t_c"])
PYEOF
# a pair nudged either way (d 1 % more, 1 % less: alpha scales with d) is worse somewhere
worst_of() {  # d -> worst |e/0.9 - 1| over the speeds, rk45
  "$BIN" forward --k "$K" --d "$1" $GLASS --velocity 0.01,0.03,0.1,0.3,1,3,5 --method rk45 --format csv |
    python3 -c 'import csv,sys; print(max(abs(float(x["e"]) / 0.9 - 1) for x in csv.DictReader(sys.stdin)))'
}
W=$(python3 -c 'import csv,sys; print(next(csv.DictReader(open(sys.argv[1])))["worst_e_error"])' "$T/fixed.csv")
for f in 1.01 0.99; do
  Wn=$(worst_of "$(python3 -c "print($D * $f)")")
  check "d x $f: worse ($Wn > $W)" python3 -c "import sys; sys.exit(0 if $Wn > $W else 1)"
done

# tsuji: e does not depend on the speed, one pair is exact
run invert --fixed $GLASS --e 0.5 --tc 1e-5 --velocity 0.01:5:log4 --damping tsuji --format csv
check "tsuji: no error anywhere" python3 -c '
import csv, sys
r = list(csv.DictReader(open(sys.argv[1])))
assert all(abs(float(x["e_error"])) < 1e-13 and float(x["worst_e_error"]) < 1e-13 for x in r)' "$OUT"
# kuwabara-kono, force end: the worst error at the ends, equal and opposite
run invert --fixed --mass 1e-4 --e 0.6 --tc 2e-5 --velocity 0.1:10:log9 --damping kuwabara-kono --end force --format csv
check "kuwabara-kono, force end: worst at the ends, opposite signs (e rises... falls with speed)" python3 -c '
import csv, sys
r = list(csv.DictReader(open(sys.argv[1])))
w = float(r[0]["worst_e_error"]); e = [float(x["e_error"]) for x in r]
assert abs(e[0] - w) < 1e-9 and abs(e[-1] + w) < 1e-9 and all(abs(x) <= w + 1e-12 for x in e), (e, w)' "$OUT"

# the bound: a k_phys below the k for 10 steps: k = k_phys, the contacts longer
run invert --fixed --mass 5.235988e-6 --k-phys 1e8 --e 0.9 --dt 1e-6 --steps 10 --velocity 0.01:5:log5 --format csv
check "bound: k = k_phys, bound_active, the shortest contact longer than 1e-5 s" python3 -c '
import csv, sys
r = list(csv.DictReader(open(sys.argv[1])))
assert all(x["bound_active"] == "true" and float(x["k"]) == 1e8 for x in r)
assert min(float(x["tc_fixed"]) for x in r) > 1e-5' "$OUT"

# text: the pair and the worst error once, above the table of speeds
run invert --fixed $GLASS --e 0.9 --dt 1e-6 --steps 10 --velocity 0.01:5:log5
check "text: k, d and the worst error above the table" \
  test -n "$(grep -E '^# k \[N m\^-3/2\] += [0-9.e+-]+$' "$OUT")" -a -n "$(grep -E '^# worst_e_error += 0\.0595' "$OUT")"

# rows without a pair; options that do not apply
run invert --fixed --mass 1e-3 --e 0.9,0.0005 --tc 1e-5 --velocity 0.1,1 --format csv
check "e outside the fit: its rows without result, exit 3, the others ok" \
  test "$RC" -eq 3 -a "$(grep -c ',ok$' "$OUT")" -eq 2 -a "$(grep -c ',outside-validity$' "$OUT")" -eq 2
check "e outside the fit: the message names --e and the range" grep -q -- '--e 0.0005: --method fit accepts' "$ERR"
expect_fail 2 "a negative speed: every row bad-input" invert --fixed --mass 1e-3 --e 0.9 --tc 1e-5 --velocity -1,1
check "a negative speed: the message names --velocity" grep -q -- '--velocity -1: ' "$ERR"
expect_fail 2 "--fixed with --method" invert --fixed --mass 1e-3 --e 0.9 --tc 1e-5 --velocity 1 --method iterative
check "--fixed with --method: says why" grep -q -- '--method, --tol and --accuracy do not apply' "$ERR"
finish
