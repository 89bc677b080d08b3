#!/usr/bin/env bash
# CLI: table, forward, constants — columns, formats, exit codes, bad arguments.
SUITE=cli_basic
source "$(dirname "$0")/cli_common.bash"

# default table
run table
check "table exits 0" test "$RC" -eq 0
check "table has a header" grep -q 'alpha .*e .*tau_c .*z_max .*tau_max .*status' "$OUT"
check "table shows a no-rebound row" grep -q 'no-rebound' "$OUT"
check "stderr empty on success" test ! -s "$ERR"

# CSV: header, columns, 16 significant digits, inf for no rebound
run table --format csv --alpha 0,0.5,1.2
check "csv exit 0" test "$RC" -eq 0
check "csv header" test "$(head -n 1 "$OUT")" = "alpha,e,tau_c,z_max,tau_max,status"
check "csv 3 rows" test "$(wc -l <"$OUT")" -eq 4
check "csv 6 fields per row" test "$(awk -F, 'NF!=6' "$OUT" | wc -l)" -eq 0
check "csv 16 significant digits" grep -Eq '^0\.000000000000000E\+000,[0-9]\.[0-9]{15}E[-+][0-9]{3},' "$OUT"
check "csv no-rebound row: e=0, tau_c=inf" grep -Eq '^1\.2.*,0\.000000000000000E\+000,inf,.*,no-rebound$' "$OUT"
# alpha = 0 reproduces the elastic closed form tau_c(0) = 3.2180654597190431 to 1e-12
check "csv tau_c(0) closed form" awk -F, 'NR==2 { d = $3 - 3.2180654597190431; exit !(d < 4e-12 && d > -4e-12) }' "$OUT"

# alpha-range and force end
run table --format csv --alpha-range 0:50:6 --end force
check "range+force exit 0" test "$RC" -eq 0
check "range gives 6 rows" test "$(wc -l <"$OUT")" -eq 7
check "force rows all ok" test "$(grep -c ',ok$' "$OUT")" -eq 6

# every forward method through the same dispatch agrees with rk45 where it is valid
run table --format csv --alpha 0.1,0.2
cp "$OUT" "$OUT.ref"
for m in series pade fit compact; do
  run table --format csv --alpha 0.1,0.2 --method $m
  check "table --method $m exit 0" test "$RC" -eq 0
  tolm=1e-11; [ $m = compact ] && tolm=1e-4
  check "table --method $m agrees with rk45 to $tolm" python3 -c '
import sys
a = [l.split(",") for l in open(sys.argv[1]).read().splitlines()[1:]]
b = [l.split(",") for l in open(sys.argv[2]).read().splitlines()[1:]]
tol = float(sys.argv[3])
assert len(a) == len(b) == 2
for x, y in zip(a, b):
    assert x[5] == y[5] == "ok"
    for j in (1, 2):
        assert abs(float(x[j]) / float(y[j]) - 1) < tol, (x, y)' "$OUT" "$OUT.ref" "$tolm"
done
rm -f "$OUT.ref"
run table --format csv --method series --order 20 --alpha 0.3
check "series --order 20 exit 0" test "$RC" -eq 0
expect_fail 3 "series beyond its radius (no solution)" table --method series --alpha 1.05
expect_fail 2 "series with the force end" table --method series --end force
expect_fail 2 "--order without series" table --order 3
expect_fail 2 "iterative is not a forward method" table --method iterative
expect_fail 2 "list and range together beyond 10000 rows" table --alpha 0.5 --alpha-range 0:1:10000
run table --alpha "$(printf 'x%.0s' {1..100})"; check "long malformed value: exit 2" test "$RC" -eq 2
run "table$(printf ' %.0s' {1..70})junk"; check "command name is read whole (exit 2)" test "$RC" -eq 2
if [ -w /dev/full ]; then
  "$BIN" table >/dev/full 2>"$ERR"; RC=$?
  check "stdout write error: exit 4 (got $RC)" test "$RC" -eq 4
  check "stdout write error: one line on stderr" test "$(wc -l <"$ERR")" -eq 1
fi

# JSON
run table --format json --alpha 0.3,1.5
check "json exit 0" test "$RC" -eq 0
check "json parses" python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); assert len(d["rows"])==2 and d["rows"][1]["tau_c"] is None and d["rows"][1]["status"]=="no-rebound"' "$OUT"

# forward (SI)
run forward --k 1e9 --d 10 --mass 1e-3 --velocity 1 --format csv
check "forward exit 0" test "$RC" -eq 0
check "forward header" test "$(head -n 1 "$OUT")" = "alpha,t_star,e,t_c,zeta_max,status"
# t* = (m/(k u^0.5))^0.4 = (1e-12)^0.4 = 1.584893192461114e-05, alpha = d t*/m
check "forward t_star and alpha" python3 -c '
import sys
a,ts,e,tc,zm,st = open(sys.argv[1]).read().splitlines()[1].split(",")
t = (1e-3/1e9)**0.4
assert abs(float(ts)/t-1) < 1e-14 and abs(float(a)/(10*t/1e-3)-1) < 1e-14 and st == "ok"
assert 0 < float(e) < 1 and float(tc) > 3.2*t' "$OUT"
run forward --k 1e9 --d 1e3 --mass 1e-3 --velocity 1 --format csv
check "forward no rebound: exit 0, status no-rebound" grep -q ',inf,.*no-rebound$' "$OUT"

# constants
run constants --format csv
check "constants exit 0" test "$RC" -eq 0
check "constants header" test "$(head -n 1 "$OUT")" = "name,value"
check "alpha_c to 8 digits" python3 -c '
import sys
d = dict(l.split(",") for l in open(sys.argv[1]).read().splitlines()[1:])
assert abs(float(d["alpha_c"]) - 1.12799) < 1e-5
assert abs(float(d["tau_c0"]) - 3.2180654597190431) < 1e-14 and abs(float(d["e1"]) - 1.7878141442883573) < 1e-14
assert abs(float(d["z_max0"]) - 1.0933620739432780) < 1e-14' "$OUT"

# help
run --help; check "--help exit 0" test "$RC" -eq 0
run table --help; check "table --help mentions units" grep -q 'units of t\*' "$OUT"
run forward --help; check "forward --help mentions N m^-3/2" grep -q 'N m^-3/2' "$OUT"

# bad usage: exit 2, one line on stderr, nothing on stdout
expect_fail 2 "unknown command" frobnicate
expect_fail 2 "unknown option" table --frob 1
expect_fail 2 "missing value" table --alpha
expect_fail 2 "repeated option" table --alpha 1 --alpha 2
expect_fail 2 "malformed 1e" table --alpha 1e
expect_fail 2 "malformed abc" table --alpha abc
expect_fail 2 "malformed empty" table --alpha ""
expect_fail 2 "malformed 1,,2" table --alpha 1,,2
expect_fail 2 "malformed 0x10" table --alpha 0x10
expect_fail 2 "malformed nan" table --alpha nan
expect_fail 2 "range N=0" table --alpha-range 0:1:0
expect_fail 2 "range N<0" table --alpha-range 0:1:-3
expect_fail 2 "range malformed" table --alpha-range 0:1
expect_fail 2 "bad end" table --end sometimes
expect_fail 2 "bad format" table --format xml
expect_fail 2 "bad tol" table --tol 1
expect_fail 2 "alpha out of range" table --alpha -50
expect_fail 2 "forward missing --d" forward --k 1 --mass 1 --velocity 1
expect_fail 2 "forward negative mass" forward --k 1 --d 0 --mass -1 --velocity 1
expect_fail 2 "forward zero velocity" forward --k 1 --d 0 --mass 1 --velocity 0
expect_fail 2 "constants positional" constants extra
expect_fail 2 "huge range rejected" table --alpha-range 0:1:10001
expect_fail 2 "huge list rejected" table --alpha "$(python3 -c 'print(",".join(["0"]*20000))')"
run table --alpha "$(python3 -c 'print(",".join(["0.1"]*2000))')" --format csv
check "long list accepted (2000 rows)" test "$(wc -l <"$OUT")" -eq 2001
finish
