#!/usr/bin/env bash
# CLI checks of `hertzdamp invert` and `hertzdamp timestep`: columns, lists, material
# input (the glass beads of issue 12), the physical bound and tc_actual, per-row
# statuses, messages that name the option, exit codes.
SUITE=cli_invert
source "$(dirname "$0")/cli_common.bash"
HEAD="e,tc,velocity,mass,radius_eff,k_phys,alpha,tau_c,t_star,k,d,bound_active,tc_actual,status"
GLASS="--radius 1e-3 --density 2500 --youngs-modulus 63e9 --poisson-ratio 0.24"

run invert --e 0.5,0.9 --tc 1e-4 --mass 1e-3 --velocity 1 --format csv
check "csv exit $RC" test "$RC" -eq 0
check "csv header" test "$(head -n 1 "$OUT")" = "$HEAD"
check "csv rows" test "$(wc -l <"$OUT")" -eq 3
check "csv 16 digits" grep -q '^5.000000000000000E-001,1.000000000000000E-004,1.000000000000000E+000,1.000000000000000E-003,,,' "$OUT"
check "bound/tc_actual/status columns" test "$(sed -n 2p "$OUT" | cut -d, -f12,13,14)" = "false,1.000000000000000E-004,ok"
# --dt --steps equals --tc
a=$("$BIN" invert --e 0.5 --tc 1e-4 --mass 1e-3 --velocity 1 --format csv | tail -n 1)
b=$("$BIN" invert --e 0.5 --dt 1e-5 --steps 10 --mass 1e-3 --velocity 1 --format csv | tail -n 1)
check "--dt --steps vs --tc" test -n "$a" -a "$a" = "$b"
# methods agree (fit vs iterative to ~1e-10, compact to ~1e-5)
kf=$(echo "$a" | cut -d, -f10)
ki=$("$BIN" invert --e 0.5 --tc 1e-4 --mass 1e-3 --velocity 1 --method iterative --format csv | tail -n 1 | cut -d, -f10)
kc=$("$BIN" invert --e 0.5 --tc 1e-4 --mass 1e-3 --velocity 1 --method compact --format csv | tail -n 1 | cut -d, -f10)
check "methods agree ($kf $ki $kc)" python3 -c "import sys; a,b,c=map(float,sys.argv[1:]); sys.exit(0 if abs(a/b-1)<1e-9 and abs(a/c-1)<3e-5 else 1)" "$kf" "$ki" "$kc"
# k-phys bound: k = k_phys, and tc_actual is the contact those k, d really give (rk45 forward)
run invert --e 0.5 --tc 1e-4 --mass 1e-3 --velocity 1 --k-phys 1e6 --format csv
check "k-phys bound" test "$RC" -eq 0 -a "$(tail -n 1 "$OUT" | cut -d, -f10,12)" = "1.000000000000000E+006,true"
row=$(tail -n 1 "$OUT")
k=$(cut -d, -f10 <<<"$row"); d=$(cut -d, -f11 <<<"$row"); tca=$(cut -d, -f13 <<<"$row")
fwd=$("$BIN" forward --k "$k" --d "$d" --mass 1e-3 --velocity 1 --format csv | tail -n 1)
check "tc_actual = rk45 contact time of the returned k, d ($tca)" python3 -c '
import sys
tca, fwd = float(sys.argv[1]), sys.argv[2].split(",")
assert abs(float(fwd[9]) / tca - 1) < 1e-11 and tca > 1.0001e-4 and abs(float(fwd[8]) - 0.5) < 1e-11' "$tca" "$fwd"
# json: numbers, booleans, null
run invert --e 0.5,5e-4 --tc 1e-4 --mass 1e-3 --velocity 1 --format json
check "json: exit 3 with the good row" test "$RC" -eq 3
check "json: booleans and nulls" python3 -c '
import json, sys
r = json.load(open(sys.argv[1]))["rows"]
assert r[0]["bound_active"] is False and r[0]["status"] == "ok" and r[0]["radius_eff"] is None
assert r[1]["k"] is None and r[1]["bound_active"] is None and r[1]["status"] == "outside-validity"' "$OUT"
run invert --e 0.5 --tc 1e-4 --mass 1e-3 --velocity 1 --end force
check "text, force" test "$RC" -eq 0 -a -n "$(grep '^# end: force' "$OUT")"

# ------------------------------------------------------------ materials (issue 12)
# two equal 2 mm glass beads: m = rho 4/3 pi R^3 = 1.0472e-5 kg, m* = m/2 = 5.236e-6 kg,
# R* = R/2, E* = E/(2(1 - nu^2)), k_phys = (4/3) E* sqrt(R*) = 9.965e8 N m^-3/2
run invert $GLASS --e 0.9 --dt 1e-6 --steps 10 --velocity 0.01,1 --format csv
check "glass pair: exit 0" test "$RC" -eq 0
check "glass pair: m* = 5.236e-6 kg, R* = 5e-4 m, k_phys = 9.965e8" python3 -c '
import sys
r = open(sys.argv[1]).read().splitlines()[1].split(",")
assert abs(float(r[3]) - 5.236e-6) < 0.0005e-6 and float(r[4]) == 5e-4
assert abs(float(r[5]) - 9.965e8) < 0.0005e8' "$OUT"
check "glass pair: the bound is active at 0.01 m/s (tc_actual 1.59e-5 s), not at 1 m/s" python3 -c '
import sys
r1, r2 = [l.split(",") for l in open(sys.argv[1]).read().splitlines()[1:]]
assert r1[11] == "true" and float(r1[9]) == float(r1[5]) and abs(float(r1[12]) - 1.59e-5) < 0.005e-5
assert r2[11] == "false" and abs(float(r2[12]) / 1e-5 - 1) < 1e-14' "$OUT"
run invert $GLASS --wall --e 0.9 --tc 1e-5 --velocity 1 --format csv
check "glass on a wall of glass: m* = m = 1.0472e-5, R* = R, E* = E/(2(1-nu^2))" python3 -c '
import sys, math
r = open(sys.argv[1]).read().splitlines()[1].split(",")
m = 2500 * 4 / 3 * math.pi * 1e-9
es = 63e9 / (2 * (1 - 0.24**2))
assert abs(float(r[3]) / m - 1) < 1e-15 and float(r[4]) == 1e-3
assert abs(float(r[5]) / (4 / 3 * es * math.sqrt(1e-3)) - 1) < 1e-15' "$OUT"
run invert $GLASS --wall --youngs-modulus2 2.1e11 --poisson-ratio2 0.3 --e 0.9 --tc 1e-5 --velocity 1 --format csv
check "glass on a steel wall: E* from both" python3 -c '
import sys, math
r = open(sys.argv[1]).read().splitlines()[1].split(",")
es = 1 / ((1 - 0.24**2) / 63e9 + (1 - 0.3**2) / 2.1e11)
assert abs(float(r[5]) / (4 / 3 * es * math.sqrt(1e-3)) - 1) < 1e-15' "$OUT"
run invert $GLASS --radius2 2e-3 --density2 7800 --e 0.9 --tc 1e-5 --velocity 1 --format csv
check "glass and a steel-density sphere: m* = m1 m2/(m1+m2), R* = R1 R2/(R1+R2)" python3 -c '
import sys, math
r = open(sys.argv[1]).read().splitlines()[1].split(",")
m1 = 2500 * 4 / 3 * math.pi * 1e-9; m2 = 7800 * 4 / 3 * math.pi * 8e-9
assert abs(float(r[3]) / (m1 * m2 / (m1 + m2)) - 1) < 1e-15 and abs(float(r[4]) / (2e-3 / 3) - 1) < 1e-15' "$OUT"
expect_fail 2 "radius 1e200: refused, not Inf" invert --radius 1e200 --density 2500 --e 0.5 --tc 1 --velocity 1
check "radius 1e200: names --radius" grep -q -- '--radius 1e200 with --density 2500' "$ERR"
expect_fail 2 "radius 2.2e-308: refused" invert --radius 2.2e-308 --density 2500 --e 0.5 --tc 1 --velocity 1
expect_fail 2 "--mass with --density" invert --mass 1 $GLASS --e 0.5 --tc 1 --velocity 1
expect_fail 2 "--k-phys with --youngs-modulus" invert --k-phys 1e9 $GLASS --e 0.5 --tc 1 --velocity 1
expect_fail 2 "--youngs-modulus without --poisson-ratio" invert --radius 1e-3 --density 1 --youngs-modulus 1e9 --e 0.5 --tc 1 --velocity 1
expect_fail 2 "--youngs-modulus without --radius" invert --mass 1 --youngs-modulus 1e9 --poisson-ratio 0.3 --e 0.5 --tc 1 --velocity 1
expect_fail 2 "--wall with --radius2" invert $GLASS --wall --radius2 1 --e 0.5 --tc 1 --velocity 1
expect_fail 2 "bad Poisson ratio of body 2" invert $GLASS --poisson-ratio2 0.7 --e 0.5 --tc 1 --velocity 1
check "bad Poisson ratio: names --poisson-ratio2" grep -q -- "--poisson-ratio2 0.7: invalid Poisson's ratio" "$ERR"
expect_fail 2 "negative density" invert --radius 1e-3 --density -2500 --e 0.5 --tc 1 --velocity 1
check "negative density: names --density" grep -q -- '--density -2500: invalid density' "$ERR"
# --mass with --radius and the elastic constants: the given mass, R* and k_phys from the radius
run invert --mass 1e-5 --radius 1e-3 --youngs-modulus 63e9 --poisson-ratio 0.24 --e 0.9 --tc 1e-5 --velocity 1 --format csv
check "--mass with --radius: mass as given, k_phys from the materials" python3 -c '
import sys
r = open(sys.argv[1]).read().splitlines()[1].split(",")
assert float(r[3]) == 1e-5 and abs(float(r[5]) - 9.965e8) < 0.0005e8' "$OUT"

# ------------------------------------------------------------ lists and statuses
run invert --e 0.5:0.9:3 --dt 1e-6,2e-6 --steps 10,20 --velocity 0.01:5:log20 --mass 1e-3 --format csv
check "lists: 3 x 4 x 20 = 240 rows (exit $RC)" test "$RC" -eq 0 -a "$(wc -l <"$OUT")" -eq 241
check "lists: tc = dt x steps in order 1e-5, 2e-5, 2e-5, 4e-5" python3 -c '
import sys
rows = [l.split(",") for l in open(sys.argv[1]).read().splitlines()[1:]]
tcs = [float(r[1]) for r in rows[0:80:20]]
assert all(abs(a / b - 1) < 1e-15 for a, b in zip(tcs, [1e-5, 2e-5, 2e-5, 4e-5])), tcs
v = [float(r[2]) for r in rows[:20]]
assert abs(v[0] - 0.01) < 1e-17 and v[-1] == 5 and all(b > a for a, b in zip(v, v[1:]))' "$OUT"
run invert --e 0.9,0.0005,1.5 --tc 1e-5 --mass 1e-3 --velocity 1 --format csv
check "bad rows do not suppress the good one: exit 3 (got $RC)" test "$RC" -eq 3
check "statuses ok, outside-validity, bad-input" test "$(cut -d, -f14 "$OUT" | tail -n 3 | tr '\n' ' ')" = "ok outside-validity bad-input "
check "one stderr line: how many and why" grep -q '^hertzdamp: 2 of 3 rows have no result (1 bad-input, 1 outside-validity); first: --e 0.0005: --method fit accepts 0.001 <= e <= 1' "$ERR"
check "exactly one stderr line" test "$(wc -l <"$ERR")" -eq 1
# messages name the argument and say what the method accepts
expect_fail 2 "negative velocity" invert --e 0.9 --tc 1e-5 --mass 1e-3 --velocity -1
check "negative velocity names --velocity (not e)" grep -q -- '--velocity -1: invalid impact velocity' "$ERR"
expect_fail 3 "compact below its range" invert --e 0.03 --tc 1e-4 --mass 1e-3 --velocity 1 --method compact
check "compact: quotes its own range 0.05" grep -q -- '--e 0.03: --method compact accepts 0.05 <= e <= 1' "$ERR"
expect_fail 3 "pade outside its range" invert --e 0.05 --tc 1e-4 --mass 1e-3 --velocity 1 --method pade
check "pade: suggests what invert accepts, not rk45" grep -q 'use --method fit (or iterative)' "$ERR"
check "pade: no rk45 in the advice" test -z "$(grep rk45 "$ERR")"
run invert --e 0.3 --tc 1e-4 --mass 1e-3 --velocity 1 --method series --format csv
check "series inverse at e = 0.3: inaccurate (exit $RC)" test "$RC" -eq 3 -a -n "$(grep -- '--accuracy 1e-10' "$ERR")"
run invert --e 0.3 --tc 1e-4 --mass 1e-3 --velocity 1 --method series --accuracy 1e-3 --format csv
check "series inverse at e = 0.3 with --accuracy 1e-3: ok" grep -q ',ok$' "$OUT"
run invert --e 0.5 --tc 1e-4,1e-300 --mass 1e10 --velocity 1 --format csv
check "k beyond double precision: out-of-range row (exit $RC)" test "$RC" -eq 3 -a "$(tail -n 1 "$OUT" | cut -d, -f14)" = "out-of-range"
check "out-of-range: the message says so" grep -q 'k or d is outside the double-precision range' "$ERR"
expect_fail 3 "e = 0 (no finite contact time)" invert --e 0 --tc 1e-4 --mass 1e-3 --velocity 1
expect_fail 2 "e = 1.5 (bad input)" invert --e 1.5 --tc 1e-4 --mass 1e-3 --velocity 1
expect_fail 3 "force end below 1e-4" invert --e 5e-5 --tc 1e-4 --mass 1e-3 --velocity 1 --end force
check "force end below 1e-4: its range" grep -q -- '--method fit accepts 0.0001 <= e <= 1 for --end force' "$ERR"
expect_fail 2 "negative tc" invert --e 0.5 --tc -1 --mass 1e-3 --velocity 1
check "negative tc names --tc" grep -q -- '--tc (contact time -1)' "$ERR"
expect_fail 2 "mass 0" invert --e 0.5 --tc 1e-4 --mass 0 --velocity 1
expect_fail 2 "k-phys 0" invert --e 0.5 --tc 1e-4 --mass 1e-3 --velocity 1 --k-phys 0
expect_fail 2 "missing --tc" invert --e 0.5 --tc 1e-4 --mass 1e-3
expect_fail 2 "missing --velocity" invert --e 0.5 --mass 1e-3 --velocity 1
expect_fail 2 "--tc with --dt" invert --e 0.5 --tc 1e-4 --dt 1e-5 --steps 10 --mass 1e-3 --velocity 1
expect_fail 2 "series with force" invert --e 0.5 --tc 1e-4 --mass 1e-3 --velocity 1 --method series --end force
expect_fail 2 "--steps not whole" invert --e 0.5 --dt 1e-5 --steps 2.5 --mass 1e-3 --velocity 1
expect_fail 2 "malformed e" invert --e abc --tc 1e-4 --mass 1e-3 --velocity 1
expect_fail 2 "--tol without iterative" invert --e 0.5 --tc 1e-4 --mass 1e-3 --velocity 1 --tol 1e-12
expect_fail 2 "too many combinations" invert --e 0.1:1:200 --tc 1e-4 --mass 1e-3 --velocity 1:2:100
run invert --help; check "help names the units" grep -q 'N m^-3/2' "$OUT"
check "help defines nothing twice: effective mass is in the top help" grep -q 'effective mass m\*' <("$BIN" --help)

# ------------------------------------------------------------ timestep
run timestep $GLASS --e 0.9 --velocity 0.01:5:log10 --steps 10 --format csv
check "timestep: exit 0 (got $RC)" test "$RC" -eq 0
check "timestep: shortest contact at 5 m/s, dt = tc/10, elastic estimate" python3 -c '
import sys, math
h, r = [l.split(",") for l in open(sys.argv[1]).read().splitlines()]
d = dict(zip(h, r))
m = 2500 * 4 / 3 * math.pi * 1e-9 / 2; rs = 5e-4; es = 63e9 / (2 * (1 - 0.24**2))
# the textbook elastic estimate 2.868 (m^2 / (R* E*^2 u))^(1/5) (4 digits)
th = 2.868 * (m**2 / (rs * es**2 * 5))**0.2
assert float(d["velocity_max"]) == 5 and abs(float(d["tc_elastic"]) / th - 1) < 2e-4
assert abs(float(d["dt_max"]) * 10 / float(d["tc_damped"]) - 1) < 1e-15
assert abs(float(d["elastic_excess"]) - (float(d["tc_elastic"]) / float(d["tc_damped"]) - 1)) < 1e-15
assert d["status"] == "ok"' "$OUT"
# the damped contact time of the physical model equals the rk45 contact time of k_phys and
# d = alpha m^(3/5) k_phys^(2/5) u^(1/5) at the fastest impact
row=$(tail -n 1 "$OUT")
inv=$("$BIN" invert $GLASS --e 0.9 --tc 1e-9 --velocity 5 --format csv | tail -n 1)
k=$(cut -d, -f10 <<<"$inv"); d=$(cut -d, -f11 <<<"$inv")
fwd=$("$BIN" forward --k "$k" --d "$d" --mass "$(cut -d, -f4 <<<"$inv")" --velocity 5 --format csv | tail -n 1)
check "timestep tc_damped = rk45 contact time of the physical contact" python3 -c '
import sys
row, fwd = sys.argv[1].split(","), sys.argv[2].split(",")
assert abs(float(fwd[9]) / float(row[8]) - 1) < 1e-11 and abs(float(fwd[8]) - 0.9) < 1e-11' "$row" "$fwd"
run timestep $GLASS --e 0.9,0.5,0.1 --velocity 1 --end force --format csv
check "timestep force end: the elastic estimate is too long, by more for smaller e" python3 -c '
import sys
rows = [l.split(",") for l in open(sys.argv[1]).read().splitlines()[1:]]
x = [float(r[10]) for r in rows]
assert 0 < x[0] < x[1] < x[2], x' "$OUT"
run timestep $GLASS --e 0.9 --velocity 1 --format csv
check "timestep overlap end: the damped contact is longer than the elastic estimate" \
  python3 -c 'import sys; r = open(sys.argv[1]).read().splitlines()[1].split(","); assert float(r[10]) < 0' "$OUT"
run timestep $GLASS --e 0.9,0.0001 --velocity 1 --format csv
check "timestep: a bad e is its own row (exit $RC)" test "$RC" -eq 3 -a "$(tail -n 1 "$OUT" | cut -d, -f16)" = "outside-validity"
# ranges of whole numbers are exact (A0 + (k (A1 - A0))/(N - 1)), and --steps takes a
# value within 4 ulp of a whole number (a logarithmic range) as it
run timestep --mass 1e-3 --k-phys 1e9 --e 0.5 --velocity 1 --steps 1:23:23,3:999:333 --format csv
check "--steps 1:23:23,3:999:333: exit 0, every step count whole and exact (exit $RC)" python3 -c '
import csv, sys
s = [float(r["steps"]) for r in csv.DictReader(open(sys.argv[1]))]
assert s == list(range(1, 24)) + list(range(3, 1000, 3)), s[:30]' "$OUT"
run timestep --mass 1e-3 --k-phys 1e9 --e 0.5 --velocity 1 --steps 1:1000:log4 --format csv
check "--steps 1:1000:log4: 1, 10, 100, 1000 (exit $RC)" test "$RC" -eq 0 -a \
  "$(cut -d, -f2 "$OUT" | tail -n +2 | tr '\n' ' ')" = "1.000000000000000E+000 1.000000000000000E+001 1.000000000000000E+002 1.000000000000000E+003 "
run forward --k 1e9 --d 0 --mass 1 --velocity -1e308:1e308:5 --format csv
check "a range whose width overflows: -1e308, -5e307, 0, 5e307, 1e308 (exit $RC)" \
  test "$(cut -d, -f3 "$OUT" | tail -n +2 | tr '\n' ' ')" = "-1.000000000000000E+308 -5.000000000000000E+307 0.000000000000000E+000 5.000000000000000E+307 1.000000000000000E+308 "
expect_fail 2 "--steps 1:2:3 (1.5 is not whole)" timestep --mass 1e-3 --k-phys 1e9 --e 0.5 --velocity 1 --steps 1:2:3
check "--steps 1:2:3: names 1.5" grep -q -- '--steps 1.5' "$ERR"
# dt x steps beyond double precision: an out-of-range row (exit 3), not bad usage; the
# other rows print
run invert --e 0.5 --dt 1e-6,1e308 --steps 10 --mass 1e-3 --velocity 1 --format csv
check "--dt 1e308 --steps 10 beside a valid dt: exit 3, both rows (exit $RC)" test "$RC" -eq 3 -a "$(wc -l <"$OUT")" -eq 3
check "--dt 1e308 --steps 10: out-of-range, tc empty" test "$(tail -n 1 "$OUT" | cut -d, -f2,14)" = ",out-of-range"
check "--dt 1e308 --steps 10: the message names both" grep -q -- '--dt 1e308 x --steps 10: the contact time is outside' "$ERR"
# timestep: a damped contact beyond double precision is out-of-range, with the reason
run timestep --e 1e-4,0.5 --damping kuwabara-kono --velocity 1e-300 --mass 1e300 --k-phys 1e-318 --format csv
check "timestep, tc_damped beyond double precision: exit 3, that row out-of-range (exit $RC)" \
  test "$RC" -eq 3 -a "$(sed -n 2p "$OUT" | cut -d, -f9,16)" = ",out-of-range"
check "timestep, tc_damped beyond double precision: the message says so" grep -q 'outside the double-precision range' "$ERR"
# E* out of range: the more compliant body is named, with its defaults shown
run invert --e 0.5 --tc 1e-5 --velocity 1 --radius 1e-3 --density 2500 --youngs-modulus 1e9 --poisson-ratio 0.3 \
  --youngs-modulus2 1e-320
check "E* from body 2's modulus: names --youngs-modulus2 and the defaulted --poisson-ratio2 ($(cat "$ERR"))" \
  grep -q -- '--youngs-modulus2 1e-320 with --poisson-ratio2 (= --poisson-ratio 0.3)' "$ERR"
run invert --e 0.5 --tc 1e-5 --velocity 1 --radius 1e-3 --density 2500 --youngs-modulus 1e-320 --poisson-ratio 0.3 \
  --youngs-modulus2 1e9
check "E* from body 1's modulus: names --youngs-modulus" grep -q -- '^hertzdamp: --youngs-modulus 1e-320 with' "$ERR"
expect_fail 2 "timestep without a stiffness" timestep --mass 1 --e 0.9 --velocity 1
expect_fail 2 "timestep bad velocity" timestep $GLASS --e 0.9 --velocity 0
# --host: the constants of the host's N-step collision (hertzdamp_pair_init); the rows add
# e_spread and tc_spread.  host none is the continuous model: the row of no --host.
HHEAD="e,tc,velocity,mass,radius_eff,k_phys,alpha,tau_c,t_star,k,d,bound_active,tc_actual,e_spread,tc_spread,status"
a=$("$BIN" invert --e 0.5 --dt 1e-6 --steps 10 --mass 1e-3 --velocity 1 --format csv | tail -n 1)
run invert --e 0.5 --dt 1e-6 --steps 10 --mass 1e-3 --velocity 1 --host none --format csv
check "--host none: exit 0, header with the spreads (exit $RC)" test "$RC" -eq 0 -a "$(head -n 1 "$OUT")" = "$HHEAD"
check "--host none: the row of no --host, spreads 0" test "$(tail -n 1 "$OUT" | cut -d, -f1-13,16)" = "$(cut -d, -f1-14 <<<"$a")" \
  -a "$(tail -n 1 "$OUT" | cut -d, -f14,15)" = "0.000000000000000E+000,0.000000000000000E+000"
run invert --e 0.2,0.5,0.9 --dt 1e-6 --steps 20 --mass 1e-3 --velocity 0.1,2 --host lammps --format csv
check "--host lammps: exit 0, six rows (exit $RC: $(cat "$ERR"))" test "$RC" -eq 0 -a "$(wc -l <"$OUT")" -eq 7
# each row: k = m (tau_c/T_c)^(5/2) u^(-1/2) and d = alpha m tau_c/T_c with its own alpha,
# tau_c; tc_actual = T_c (no bound); spreads finite and >= 0
check "--host lammps: k, d from the row's alpha, tau_c; tc_actual = T_c; spreads >= 0" python3 -c '
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
for r in rows:
    tc, m, u, a, tau = (float(r[x]) for x in ("tc", "mass", "velocity", "alpha", "tau_c"))
    k, d = float(r["k"]), float(r["d"])
    assert abs(k / (m * (tau / tc) ** 2.5 / u ** 0.5) - 1) < 1e-12, r
    assert abs(d / (a * m * tau / tc) - 1) < 1e-12, r
    assert abs(float(r["tc_actual"]) / tc - 1) < 1e-14 and r["bound_active"] == "false", r
    assert float(r["e_spread"]) >= 0 and float(r["tc_spread"]) >= 0 and r["status"] == "ok", r
' "$OUT"
run invert --e 0.5 --dt 1e-6 --steps 2,20 --mass 1e-3 --velocity 1 --host lammps --format csv
check "--host lammps, N = 2 beside N = 20: exit 3, both rows (exit $RC)" test "$RC" -eq 3 -a "$(wc -l <"$OUT")" -eq 3
check "--host lammps, N = 2: the row is outside-validity, N = 20 ok" \
  test "$(sed -n 2p "$OUT" | cut -d, -f7,16)" = ",outside-validity" -a "$(sed -n 3p "$OUT" | cut -d, -f16)" = "ok"
check "--host lammps, N = 2: says which N can ($(cat "$ERR"))" \
  grep -qE 'N = 2 steps cannot reach e = 0.5 with lammps; N >= [0-9]+ can' "$ERR"
# --host with the bound active (issue 30, defect 3): the contact keeps k_phys and lasts far
# more than N steps; tc_actual and the spreads are those of that contact, checked by this
# script's own LAMMPS-scheme stepper (force from z_n and the velocity that moved the body
# there, w += -dt F/m, z += dt w; touch at t_1 - phi dt; release interpolated in the overlap)
# over 8 onset phases (the old code printed tau_N t* = 1.3513e-2 and the N = 10 spreads)
run invert --e 0.5 --dt 1e-6 --steps 10 --velocity 1 --mass 1e-3 --host lammps --k-phys 1e3 --format csv
check "--host lammps with the bound: exit 0, bound active (exit $RC)" test "$RC" -eq 0 -a \
  "$(tail -n 1 "$OUT" | cut -d, -f12)" = "true"
check "--host lammps with the bound: tc_actual and e_spread of the bounded contact (own stepper)" python3 -c '
import csv, sys
r = next(csv.DictReader(open(sys.argv[1])))
k, d, m, u, dt = float(r["k"]), float(r["d"]), 1e-3, 1.0, 1e-6
ts, es = [], []
for j in range(8):
    phi = (j + 0.5) / 8
    z, w, zp = phi * u * dt, u, 0.0
    n = 1
    while z > 0:
        f = k * z ** 1.5 + d * w
        w -= dt * f / m
        zp, z = z, z + dt * w
        n += 1
    ts.append(dt * (n - 2 + zp / (zp - z) + phi))
    es.append(-w / u)
tm = sum(ts) / len(ts)
em = sum(es) / len(es)
sd = (sum((x - em) ** 2 for x in es) / len(es)) ** 0.5 / em
assert abs(float(r["tc_actual"]) / tm - 1) < 1e-4, (r["tc_actual"], tm)
assert abs(em - 0.5) < 5e-3 and float(r["e_spread"]) < 1e-3 and sd < 1e-3, (em, r["e_spread"], sd)
' "$OUT"
expect_fail 2 "--host with --tc" invert --e 0.5 --tc 1e-5 --mass 1e-3 --velocity 1 --host lammps
check "--host with --tc: asks for --dt and --steps" grep -q -- '--host needs --dt and --steps' "$ERR"
expect_fail 2 "--host without --steps" invert --e 0.5 --dt 1e-6 --mass 1e-3 --velocity 1 --host mfix-euler
expect_fail 2 "--host lammps --method compact" invert --e 0.5 --dt 1e-6 --steps 10 --mass 1e-3 --velocity 1 \
  --host lammps --method compact
check "--host with another method: says so" grep -q -- '--method applies to --host none' "$ERR"
expect_fail 2 "--host bogus" invert --e 0.5 --dt 1e-6 --steps 10 --mass 1e-3 --velocity 1 --host bogus
check "--host bogus: lists the hosts" grep -q 'none lammps mfix-euler mfix-ab2 verlet lammps-phase' "$ERR"
run timestep $GLASS --e 0.5 --velocity 0.1,5 --steps 10,20 --host mfix-ab2 --format csv
check "timestep --host mfix-ab2: exit 0, spread columns (exit $RC)" test "$RC" -eq 0 -a \
  "$(head -n 1 "$OUT")" = "e,steps,velocity_max,mass,radius_eff,k_phys,alpha,tau_c,tc_damped,tc_elastic,elastic_excess,dt_max,dt_elastic,t_rayleigh,dt_rayleigh,e_spread,tc_spread,status"
check "timestep --host: dt_max = tc_damped / N with the host's tau_c" python3 -c '
import csv, sys
for r in csv.DictReader(open(sys.argv[1])):
    assert abs(float(r["dt_max"]) * float(r["steps"]) / float(r["tc_damped"]) - 1) < 1e-14, r
' "$OUT"
expect_fail 2 "timestep --host without --steps" timestep $GLASS --e 0.5 --velocity 1 --host lammps
expect_fail 2 "--host with --fixed" invert --e 0.5 --dt 1e-6 --steps 10 --mass 1e-3 --velocity 0.5,2 --host lammps --fixed
check "--host with --fixed: says so" grep -q -- '--fixed takes no --host' "$ERR"

# timestep: the Rayleigh step pi R sqrt(rho/G)/(0.1631 nu + 0.8766), G = E/(2(1+nu)), of
# the smaller sphere (a wall has none), and dt_rayleigh = 0.2 of it; none without the
# materials (the formula's fit of the Rayleigh root: test/unit/test_materials.f90)
rayleigh() {  # R rho E nu -> t_R
  python3 -c 'import math, sys; r, rho, e, nu = map(float, sys.argv[1:]); print(repr(math.pi * r * math.sqrt(rho * 2 * (1 + nu) / e) / (0.1631 * nu + 0.8766)))' "$@"
}
col() { python3 -c 'import csv, sys; r = list(csv.DictReader(open(sys.argv[1]))); print(r[int(sys.argv[3]) - 1][sys.argv[2]])' "$OUT" "$1" "${2:-1}"; }
close() { python3 -c 'import sys; a, b, t = map(float, sys.argv[1:]); sys.exit(0 if abs(a - b) <= t * abs(b) else 1)' "$@"; }
run timestep $GLASS --e 0.9,0.5 --velocity 1 --format csv
tr=$(rayleigh 1e-3 2500 63e9 0.24)
check "rayleigh: glass beads, t_rayleigh = pi R sqrt(rho/G)/(0.1631 nu + 0.8766) ($(col t_rayleigh) vs $tr)" close "$(col t_rayleigh)" "$tr" 1e-15
check "rayleigh: dt_rayleigh = 0.2 t_rayleigh" close "$(col dt_rayleigh 2)" "$(python3 -c "print(0.2 * $tr)")" 1e-15
check "rayleigh: the same in every row" test "$(col t_rayleigh 1)" = "$(col t_rayleigh 2)"
run timestep $GLASS --radius2 0.5e-3 --density2 7800 --youngs-modulus2 2e11 --poisson-ratio2 0.3 --e 0.9 --velocity 1 --format csv
want=$(python3 -c "print(min($(rayleigh 1e-3 2500 63e9 0.24), $(rayleigh 0.5e-3 7800 2e11 0.3)))")
check "rayleigh: two materials, the shorter time ($(col t_rayleigh) vs $want)" close "$(col t_rayleigh)" "$want" 1e-15
run timestep $GLASS --wall --youngs-modulus2 1e6 --poisson-ratio2 0.45 --e 0.9 --velocity 1 --format csv
check "rayleigh: a wall has none, the sphere's" close "$(col t_rayleigh)" "$tr" 1e-15
run timestep --mass 1e-3 --k-phys 1e9 --e 0.9 --velocity 1 --format csv
check "rayleigh: without the materials, empty (status ok)" test "$(col t_rayleigh),$(col dt_rayleigh),$(col status)" = ",,ok"
run timestep --radius 1e-3 --mass 1e-3 --k-phys 1e9 --e 0.9 --velocity 1 --format json
check "rayleigh: JSON null without the materials" python3 -c 'import json, sys; r = json.load(open(sys.argv[1]))["rows"][0]; assert r["t_rayleigh"] is None and r["dt_rayleigh"] is None' "$OUT"
# --onset-phase (issue 32): one row per phase, that contact's k and d; a stepper written
# here (MFiX's EULER: v += h a; z += h v, a from the new z and v) gives each row's e and
# T_c = N dt to 1e-5
run invert --e 0.2,0.5 --dt 1e-6 --steps 10 --mass 1e-3 --velocity 1.5 --host mfix-euler \
  --onset-phase 0.016,0.25,0.5,0.999 --format csv
check "--onset-phase: exit 0, 8 rows (exit $RC: $(cat "$ERR"))" test "$RC" -eq 0 -a "$(wc -l <"$OUT")" -eq 9
check "--onset-phase: the onset_phase column" test "$(head -n 1 "$OUT" | cut -d, -f7)" = "onset_phase"
check "--onset-phase: every row's e and T_c exact in the host's Euler loop (own stepper, 1e-5)" python3 -c '
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
dt, n = 1e-6, 10
for r in rows:
    e, m, u, phi, k, d = (float(r[c]) for c in ("e", "mass", "velocity", "onset_phase", "k", "d"))
    z, v, a, t, zl = (phi - 1.0) * u * dt, u, 0.0, 0.0, 0.0
    ton = (1.0 - phi) * dt
    while True:
        v += dt * a; z += dt * v; t += dt; a = 0.0
        if z > 0:
            a = -(k * z ** 1.5 + d * v) / m; zl = z
        elif t > dt:
            trel = t - dt + dt * zl / (zl - z); break
    assert abs(-v / u / e - 1) < 1e-5 and abs((trel - ton) / (n * dt) - 1) < 1e-5, (r, -v / u, trel - ton)
' "$OUT"
expect_fail 2 "--onset-phase 1.5" invert --e 0.5 --dt 1e-6 --steps 10 --mass 1e-3 --velocity 1 --host lammps \
  --onset-phase 0.5,1.5
check "--onset-phase 1.5: names the option" grep -q -- '--onset-phase 1.5' "$ERR"
expect_fail 2 "--onset-phase without --host" invert --e 0.5 --dt 1e-6 --steps 10 --mass 1e-3 --velocity 1 \
  --onset-phase 0.5
run invert --e 0.99 --end force --dt 1e-6 --steps 10 --mass 1e-3 --velocity 1 --host lammps --onset-phase 0.5
check "--onset-phase unreachable at N = 10: exit 3, says which N can ($(cat "$ERR"))" \
  bash -c "test $RC -eq 3 && grep -q 'cannot reach it at every onset phase with lammps; N >= [0-9]* can' '$ERR'"
finish
