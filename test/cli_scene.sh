#!/usr/bin/env bash
# CLI: hertzdamp scene - the four shipped scenes, formats, method choice, --plot,
# and invalid scenes (exit 2, one line on stderr, nothing on stdout, no files).
SUITE=cli_scene
source "$(dirname "$0")/cli_common.bash"
TMPD=$(mktemp -d)
trap 'rm -f "$OUT" "$ERR"; rm -rf "$TMPD"' EXIT
S=data/scenes

# every shipped scene runs, and all its checks pass (JSON, parsed)
for scene in binary drop chain bed; do
  run scene $S/$scene.nml --format json
  check "$scene: exit 0" test "$RC" -eq 0
  check "$scene: stderr empty" test ! -s "$ERR"
  check "$scene: json with method, contacts, checks, cost; no FAIL" python3 -c '
import json, sys
d = json.load(open(sys.argv[1]))
assert set(d) == {"method", "contacts", "checks", "cost"}, d.keys()
assert d["method"]["method"] in ("first-order", "compact", "series", "pade", "fit", "iterative")
assert all(r["result"] != "FAIL" for r in d["checks"]["rows"]), d["checks"]["rows"]
cost = d["cost"]["rows"]
assert cost[-1]["rule"] == "iterative" and all(r["total_time_s"] > 0 for r in cost)
' "$OUT"
  cp "$OUT" "$TMPD/$scene.json"
done

# binary: 15 binary contacts, achieved e and T_c within the stated bound, both regimes
check "binary: 15 contacts, within accuracy + 2/N^2, rule and physical" python3 -c '
import json, sys
d = json.load(open(sys.argv[1]))
rows = d["contacts"]["rows"]
assert len(rows) == 15
assert max(r["e_rel_err"] for r in rows) <= 1e-4 + 2 / 10**2
assert max(r["tc_rel_err"] for r in rows) <= 1e-4 + 2 / 10**2
assert {r["stiffness"] for r in rows} == {"rule", "physical"}
assert min(r["u_in"] for r in rows) < 2e-3 and max(r["u_in"] for r in rows) > 5   # four decades
' "$TMPD/binary.json"
# drop: at rest, and the early bounces (g T_c/u_in < 0.01) keep e to 0.5 %
check "drop: at rest, bounces keep e" python3 -c '
import json, sys
d = json.load(open(sys.argv[1]))
checks = {r["check"]: r for r in d["checks"]["rows"]}
assert checks["max_final_speed [m/s] (at rest)"]["result"] == "pass"
rows = [r for r in d["contacts"]["rows"] if 9.81 * r["tc"] / r["u_in"] < 0.01]
assert len(rows) >= 10 and all(r["e_rel_err"] < 5e-3 for r in rows)
' "$TMPD/drop.json"
# chain: momentum to round-off, energy never increases
check "chain: momentum and energy checks pass" python3 -c '
import json, sys
d = json.load(open(sys.argv[1]))
checks = {r["check"]: r for r in d["checks"]["rows"]}
assert checks["momentum_drift / sum m|v|"]["result"] == "pass"
assert checks["energy_rise / energy scale"]["result"] == "pass"
' "$TMPD/chain.json"
# method choice: the nearly elastic chain gets a cheaper rule than the damped bed
check "auto: chain (e = 0.98) cheaper than bed (e = 0.5), both within accuracy" python3 -c '
import json, sys
rank = lambda d: [r["rank"] for r in d["method"]["rows"] if r["used"] == "*"][0]
c, b = (json.load(open(f)) for f in sys.argv[1:3])
assert c["method"]["method"] == "first-order", c["method"]["method"]
assert int(rank(c)) < int(rank(b))
for d in (c, b):
    used = [r for r in d["method"]["rows"] if r["used"] == "*"][0]
    assert used["meets_accuracy"] == "yes" and used["max_error"] <= float(d["method"]["accuracy"])
' "$TMPD/chain.json" "$TMPD/bed.json"
# bed: >= 100 particles, none left the box, at rest
check "bed: 107 particles, in the box, at rest" python3 -c '
import json, sys
d = json.load(open(sys.argv[1]))
assert int(d["method"]["particles"]) >= 100
checks = {r["check"]: r for r in d["checks"]["rows"]}
assert checks["particles_left_domain"]["value"] == 0 and checks["particles_left_domain"]["result"] == "pass"
assert checks["max_final_speed [m/s] (at rest)"]["result"] == "pass"
' "$TMPD/bed.json"

# text and csv
run scene $S/chain.nml
check "text: method line with the reason" grep -q '^# why: auto: cheapest rule' "$OUT"
check "text: cost table with iterative row" grep -q '^ *iterative ' "$OUT"
run scene $S/binary.nml --format csv --method iterative
check "csv: exit 0" test "$RC" -eq 0
check "csv: four sections" test "$(grep -c '^# ' "$OUT")" -eq 4
check "csv: contact header" grep -q '^contact,bodies,u_in,k,d,stiffness,e_target,e,e_rel_err,tc_target,tc,tc_rel_err$' "$OUT"
check "csv: requested method used" grep -q '^6,iterative,yes,.*,\*$' "$OUT"

# --plot: PNG written under its final name, no temporary files left
run scene $S/drop.nml --plot "$TMPD/drop.png"
check "plot: exit 0" test "$RC" -eq 0
check "plot: PNG written" python3 -c 'import sys; assert open(sys.argv[1], "rb").read(8) == b"\x89PNG\r\n\x1a\n"' "$TMPD/drop.png"
check "plot: no temporary files left" test "$(ls "$TMPD" | grep -c tmp)" -eq 0
expect_fail 2 "plot: unwritable path" scene $S/drop.nml --plot "$TMPD/no/such/dir/x.png"
check "plot: unwritable path leaves no file" test ! -e "$TMPD/no/such/dir/x.png"
mkdir "$TMPD/pd"
expect_fail 2 "plot: target is a directory" scene $S/chain.nml --plot "$TMPD/pd"
check "plot: directory target, nothing written into it" test -z "$(ls -A "$TMPD/pd")"
mkdir "$TMPD/ro"; chmod 555 "$TMPD/ro"
if [ "$(id -u)" != 0 ]; then
  expect_fail 2 "plot: unwritable directory" scene $S/chain.nml --plot "$TMPD/ro/x.png"
fi
check "plot: unwritable directory, no file" test ! -e "$TMPD/ro/x.png"
chmod 755 "$TMPD/ro"
# a name starting with '-' and one with quotes: written under their own names
BIN_ABS=$(cd "$(dirname "$BIN")" && pwd)/$(basename "$BIN"); SCENE_ABS=$PWD/$S/chain.nml
( cd "$TMPD" && "$BIN_ABS" scene "$SCENE_ABS" --plot -x.png >/dev/null 2>"$ERR" ); RC=$?
check "plot: file name starting with - (exit $RC)" test "$RC" -eq 0 -a -s "$TMPD/-x.png" -a ! -s "$ERR"
run scene $S/chain.nml --plot "$TMPD/it's \"q\".png"
check "plot: file name with quotes (exit $RC)" test "$RC" -eq 0 -a -s "$TMPD/it's \"q\".png"
check "plot: no temporary files left" test "$(ls "$TMPD" | grep -c tmp)" -eq 0
# the temporary name is never clobbered
echo keep >"$TMPD/t.png.hertzdamp-tmp"
expect_fail 2 "plot: temporary name in the way" scene $S/chain.nml --plot "$TMPD/t.png"
check "plot: temporary name in the way is kept" grep -q keep "$TMPD/t.png.hertzdamp-tmp"
rm -f "$TMPD/t.png.hertzdamp-tmp"
PATH=/nonexistent run scene $S/chain.nml --plot "$TMPD/nognuplot.png"
check "plot: gnuplot missing: exit 4 (got $RC)" test "$RC" -eq 4
check "plot: gnuplot missing: stdout empty" test ! -s "$OUT"
check "plot: gnuplot missing: one line on stderr" test "$(wc -l <"$ERR")" -eq 1
check "plot: gnuplot missing gives a clear message" grep -q 'needs gnuplot' "$ERR"
check "plot: gnuplot missing, no file" test ! -e "$TMPD/nognuplot.png"

# invalid scenes: exit 2, one line naming the line or key, nothing on stdout, no files
HEAD="&scene dt = 1e-6, steps_per_contact = 10, end_time = 1e-4 /
&material name = 's', density = 7800, youngs_modulus = 2e11, poisson_ratio = 0.3, restitution = 0.9 /"
bad() {  # label, expected text in the message, scene text
  local label=$1 want=$2
  printf '%s\n' "$3" >"$TMPD/bad.nml"
  expect_fail 2 "$label" scene "$TMPD/bad.nml" --plot "$TMPD/bad.png"
  check "$label: message names '$want'" grep -q -- "$want" "$ERR"
  check "$label: no output files" test -z "$(ls "$TMPD" | grep bad.png)"
}
bad "unknown key" 'line 3: &particle: unknown key "colour"' "$HEAD
&particle material = 's', radius = 1e-3, position = 0,0,0, colour = 1 /"
bad "unknown key, continuation line" 'line 4' "$HEAD
&particle material = 's', radius = 1e-3,
  position = 0,0,0, velocty = 1,0,0 /"
bad "missing radius" 'radius missing' "$HEAD
&particle material = 's', position = 0,0,0 /"
bad "missing dt" 'dt missing' "&scene end_time = 1 /"
bad "zero radius" 'radius must be positive' "$HEAD
&particle material = 's', radius = 0, position = 0,0,0 /"
bad "negative density" 'density must be positive' "&scene dt = 1e-6, steps_per_contact = 10, end_time = 1e-4 /
&material name = 's', density = -1, youngs_modulus = 2e11, poisson_ratio = 0.3, restitution = 0.9 /"
bad "overlapping particles" 'line 4: &particle overlaps the particle of line 3' "$HEAD
&particle material = 's', radius = 1e-3, position = 0,0,0 /
&particle material = 's', radius = 1e-3, position = 1.5e-3,0,0 /"
bad "overlap inside a count group" 'of this &particle group overlap' "$HEAD
&particle material = 's', radius = 1e-3, position = 0,0,0, count = 3, spacing = 1e-3,0,0 /"
bad "unknown material" "unknown material 't'" "$HEAD
&particle material = 't', radius = 1e-3, position = 0,0,0 /"
bad "bad contact_end" 'contact_end' "&scene dt = 1e-6, steps_per_contact = 10, end_time = 1e-4, contact_end = 'sometimes' /"
bad "malformed value" 'line 3: &particle: malformed value of radius' "$HEAD
&particle material = 's', radius = 1e-3x, position = 0,0,0 /"
bad "malformed value dt = abc" 'line 1: &scene: malformed value of dt' "&scene dt = abc, steps_per_contact = 10, end_time = 1e-4 /"
bad "malformed integer" 'malformed value of steps_per_contact' "&scene dt = 1e-6, steps_per_contact = 1.5, end_time = 1e-4 /"
bad "malformed vector" 'line 3: &particle: malformed value of position' "$HEAD
&particle material = 's', radius = 1e-3, position = 0,0,x /"
bad "NaN velocity" 'line 3: &particle velocity must be finite' "$HEAD
&particle material = 's', radius = 1e-3, position = 0,0,0, velocity = 0, 0, NaN /"
bad "Inf density" 'density must be finite' "&scene dt = 1e-6, steps_per_contact = 10, end_time = 1e-4 /
&material name = 's', density = Inf, youngs_modulus = 2e11, poisson_ratio = 0.3, restitution = 0.9 /
&particle material = 's', radius = 1e-3, position = 0,0,0 /"
bad "Inf gravity" 'g must be finite' "&scene dt = 1e-6, steps_per_contact = 10, end_time = 1e-4, gravity = .true., g = 0, 0, -Inf /
&material name = 's', density = 7800, youngs_modulus = 2e11, poisson_ratio = 0.3, restitution = 0.9 /
&particle material = 's', radius = 1e-3, position = 0,0,0 /"
bad "NaN wall normal" 'line 3: &wall: normal must be finite' "$HEAD
&wall material = 's', point = 0,0,0, normal = 0,0,NaN /
&particle material = 's', radius = 1e-3, position = 0,0,5e-3 /"
bad "NaN dt" 'dt must be finite' "&scene dt = NaN, steps_per_contact = 10, end_time = 1e-4 /
&material name = 's', density = 7800, youngs_modulus = 2e11, poisson_ratio = 0.3, restitution = 0.9 /
&particle material = 's', radius = 1e-3, position = 0,0,0 /"
# endless input without a newline fails fast (the read is bounded), exit 2
RC=0; timeout 20 "$BIN" scene /dev/zero >"$OUT" 2>"$ERR" || RC=$?
check "/dev/zero: exit 2 within 20 s (got $RC)" test "$RC" -eq 2
check "/dev/zero: one line on stderr naming the limit" test "$(grep -c 'longer than 1024 characters' "$ERR")" -eq 1
check "/dev/zero: stdout empty" test ! -s "$OUT"
expect_fail 2 "missing file argument" scene
expect_fail 2 "nonexistent file" scene "$TMPD/nothere.nml"
expect_fail 2 "bad method" scene $S/chain.nml --method magic
expect_fail 2 "bad format" scene $S/chain.nml --format xml
run scene --help
check "scene --help mentions tangential forces out of scope" grep -q 'tangential forces' "$OUT"
finish
