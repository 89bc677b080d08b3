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
check "series beyond its radius: outside-validity named" grep -q 'alpha = 1.05 is outside the range of --method series' "$ERR"
expect_fail 2 "series with the force end" table --method series --end force
expect_fail 2 "--order without series" table --order 3
expect_fail 2 "iterative is not a forward method" table --method iterative
expect_fail 2 "list and range together beyond 10000 rows" table --alpha 0.5 --alpha-range 0:1:10000
run table --alpha "$(printf 'x%.0s' {1..100})"; check "long malformed value: exit 2" test "$RC" -eq 2
run "table$(printf ' %.0s' {1..70})junk"; check "command name is read whole (exit 2)" test "$RC" -eq 2
if [ -w /dev/full ]; then
  for args in "table" "--help" "invert --help" "--version" "constants"; do
    "$BIN" $args >/dev/full 2>"$ERR"; RC=$?
    check "$args > /dev/full: exit 4 (got $RC)" test "$RC" -eq 4
    check "$args > /dev/full: one line on stderr" test "$(wc -l <"$ERR")" -eq 1
  done
fi

# lists and ranges: values, linear and logarithmic ranges, mixed
run table --format csv --method fit --alpha 0.01:1:log3,0.5,0:1:3
check "table mixed list: exit 0" test "$RC" -eq 0
check "table mixed list: 0.01 0.1 1 0.5 0 0.5 1" python3 -c '
import sys
a = [float(l.split(",")[0]) for l in open(sys.argv[1]).read().splitlines()[1:]]
want = [0.01, 0.1, 1, 0.5, 0, 0.5, 1]
assert len(a) == len(want) and all(abs(x - w) <= 1e-15 * w for x, w in zip(a, want)), a' "$OUT"
expect_fail 2 "log range needs positive ends" table --alpha 0:1:log3
expect_fail 2 "range count malformed" table --alpha 0:1:logx
# compact gives no z_max, tau_max: absent, never 0
run table --method compact --alpha 0.1 --format csv
check "compact: z_max, tau_max empty in CSV" grep -Eq '^1\.0+E-001,[^,]+,[^,]+,,,ok$' "$OUT"
run table --method compact --alpha 0.1 --format json
check "compact: z_max, tau_max null in JSON" python3 -c 'import json,sys; r=json.load(open(sys.argv[1]))["rows"][0]; assert r["z_max"] is None and r["tau_max"] is None and r["e"] > 0' "$OUT"
run table --method compact --alpha 0.1
check "compact: z_max, tau_max '-' in text, never 0" python3 -c '
import sys, hertzdamp_text
row = hertzdamp_text.rows(open(sys.argv[1]).read())[0]
assert row["z_max"] == "-" and row["tau_max"] == "-" and row["status"] == "ok", row' "$OUT"
# the fit gives z_max, tau_max up to alpha = 1.3 only (overlap): absent beyond
run table --method fit --alpha 2 --format csv
check "fit at alpha = 2: no-rebound, z_max absent" grep -Eq '^2\.0+E\+000,0\.0+E\+000,inf,,,no-rebound$' "$OUT"
# the accuracy guard: series at alpha = 0.99 is inaccurate (was 1.4 % off with status ok)
run table --method series --alpha 0.99,0.1 --format csv
check "series 0.99: exit 3 with partial output (got $RC)" test "$RC" -eq 3
check "series 0.99: inaccurate row, ok row" python3 -c '
import sys
rows = [l.split(",") for l in open(sys.argv[1]).read().splitlines()[1:]]
assert rows[0][1:] == ["", "", "", "", "inaccurate"] and rows[1][-1] == "ok"' "$OUT"
check "series 0.99: one line on stderr naming --accuracy" test "$(wc -l <"$ERR")" -eq 1 -a -n "$(grep -- '--accuracy 1e-10' "$ERR")"
run table --method series --alpha 0.99 --accuracy 0.1 --format csv
check "series 0.99 with --accuracy 0.1: ok" grep -q ',ok$' "$OUT"
run table --method pade --alpha 0.5,0.9 --format csv
check "pade beyond 0.8: outside-validity row (exit $RC)" test "$RC" -eq 3 -a "$(tail -n 1 "$OUT" | cut -d, -f6)" = "outside-validity"
check "pade beyond 0.8: message says what pade accepts and suggests fit or rk45" \
  grep -q 'outside the range of --method pade (0 <= alpha <= 0.8.*use --method fit or rk45' "$ERR"
expect_fail 2 "--accuracy with rk45" table --accuracy 1e-6
expect_fail 2 "--accuracy out of range" table --method series --accuracy 0
expect_fail 2 "--order beyond the stored series" table --method series --order 25

# JSON
run table --format json --alpha 0.3,1.5
check "json exit 0" test "$RC" -eq 0
check "json parses" python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); assert len(d["rows"])==2 and d["rows"][1]["tau_c"] is None and d["rows"][1]["status"]=="no-rebound"' "$OUT"

# forward (SI)
run forward --k 1e9 --d 10 --mass 1e-3 --velocity 1 --format csv
check "forward exit 0" test "$RC" -eq 0
check "forward header" test "$(head -n 1 "$OUT")" = "k,d,velocity,mass,radius_eff,k_phys,alpha,t_star,e,t_c,zeta_max,status"
# t* = (m/(k u^0.5))^0.4 = (1e-12)^0.4 = 1.584893192461114e-05, alpha = d t*/m
check "forward t_star and alpha" python3 -c '
import sys
k,d,u,m,r,kp,a,ts,e,tc,zm,st = open(sys.argv[1]).read().splitlines()[1].split(",")
t = (1e-3/1e9)**0.4
assert r == "" and kp == ""  # no materials: no effective radius, no k_phys
assert abs(float(ts)/t-1) < 1e-14 and abs(float(a)/(10*t/1e-3)-1) < 1e-14 and st == "ok"
assert 0 < float(e) < 1 and float(tc) > 3.2*t' "$OUT"
run forward --k 1e9 --d 1e3 --mass 1e-3 --velocity 1 --format csv
check "forward no rebound: exit 0, status no-rebound" grep -q ',inf,.*no-rebound$' "$OUT"
# valid physical input is never bad usage: a damping far beyond every method is no rebound
# (overlap end), with alpha = d t*/m computed without overflow
run forward --k 1e10 --d 1e300 --mass 1 --velocity 1 --format csv
check "forward d = 1e300, overlap: exit 0 (got $RC)" test "$RC" -eq 0
check "forward d = 1e300: no-rebound, alpha = 1e296, zeta_max absent" python3 -c '
import sys
k,d,u,m,r,kp,a,ts,e,tc,zm,st = open(sys.argv[1]).read().splitlines()[1].split(",")
assert st == "no-rebound" and tc == "inf" and zm == "" and float(e) == 0
assert abs(float(a) / 1e296 - 1) < 1e-13 and abs(float(ts) / 1e-4 - 1) < 1e-13' "$OUT"
expect_fail 3 "forward d = 1e300, force end: outside-validity (no method takes alpha > 1e100)" \
  forward --k 1e10 --d 1e300 --mass 1 --velocity 1 --end force
check "forward d = 1e300, force: the message gives alpha" grep -q 'alpha = 1e296' "$ERR"
# lists: one row per combination, in the order k, d, velocity
run forward --k 1e8,1e9 --d 0:1:3 --velocity 0.1:10:log3 --mass 1e-3 --method fit --format csv
check "forward lists: exit 0" test "$RC" -eq 0
check "forward lists: 2 x 3 x 3 rows in order" python3 -c '
import sys, math
rows = [l.split(",") for l in open(sys.argv[1]).read().splitlines()[1:]]
assert len(rows) == 18
want = [(k, d, u) for k in (1e8, 1e9) for d in (0, 0.5, 1) for u in (0.1, 1, 10)]
for r, (k, d, u) in zip(rows, want):
    assert float(r[0]) == k and float(r[1]) == d and abs(float(r[2]) / u - 1) < 1e-15, (r, k, d, u)
    assert r[-1] == "ok"
    # alpha = d m^(-3/5) k^(-2/5) u^(-1/5)
    assert abs(float(r[6]) - d * 1e-3**-0.6 * k**-0.4 * u**-0.2) <= 1e-14 * max(float(r[6]), 1e-300)
# d = 0: elastic, e = 1' "$OUT"
# a bad value in a list: its row is bad-input, the others print; exit 3, one line on stderr
run forward --k 1e9 --d 0.5 --mass 1e-3 --velocity 1,-1,2 --format csv
check "forward bad velocity in a list: exit 3 (got $RC)" test "$RC" -eq 3
check "forward bad velocity in a list: 3 rows, the bad one empty" python3 -c '
import sys
rows = [l.split(",") for l in open(sys.argv[1]).read().splitlines()[1:]]
assert [r[-1] for r in rows] == ["ok", "bad-input", "ok"]
assert all(x == "" for x in rows[1][6:11]) and rows[1][2] == "-1.000000000000000E+000"' "$OUT"
check "forward bad velocity: one line on stderr naming --velocity" \
  test "$(wc -l <"$ERR")" -eq 1 -a -n "$(grep -- '1 of 3 rows have no result (1 bad-input).*--velocity -1' "$ERR")"
expect_fail 2 "forward negative velocity alone: bad usage naming --velocity" \
  forward --k 1e9 --d 0.5 --mass 1e-3 --velocity -1
check "forward negative velocity: the message names --velocity, not e" grep -q -- '--velocity -1: invalid impact velocity' "$ERR"

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
expect_fail 2 "alpha out of range (bad input)" table --alpha -50
check "alpha out of range: says what rk45 accepts" grep -q -- '-10 <= alpha <= 1e100' "$ERR"
expect_fail 2 "forward missing --d" forward --k 1 --mass 1 --velocity 1
expect_fail 2 "forward negative mass" forward --k 1 --d 0 --mass -1 --velocity 1
expect_fail 2 "forward zero velocity" forward --k 1 --d 0 --mass 1 --velocity 0
expect_fail 2 "constants positional" constants extra
expect_fail 2 "huge range rejected" table --alpha-range 0:1:10001
expect_fail 2 "huge list rejected" table --alpha "$(python3 -c 'print(",".join(["0"]*20000))')"
run table --alpha "$(python3 -c 'print(",".join(["0.1"]*2000))')" --format csv
check "long list accepted (2000 rows)" test "$(wc -l <"$OUT")" -eq 2001
finish
