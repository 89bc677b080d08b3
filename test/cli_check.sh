#!/usr/bin/env bash
# CLI checks of `hertzdamp check`: the embedded specification and the documentation
# table are in sync, decks in each engine's syntax are read, the printed corrected
# parameter fed back gives the target, and bad input gives one line naming the key.
SUITE=cli_check
cd "$(dirname "$0")/.." || exit 1
. test/cli_common.bash
TMP=$(mktemp -d); trap 'rm -rf "$TMP" "$OUT" "$ERR"' EXIT

# --- the specification embedded in the program is the CSV (regenerated and compared)
python3 tools/peers_to_f90.py data/peers/peers_spec.csv "$TMP/data.f90"
check "apps/src/hertzdamp_peers_data.f90 is tools/peers_to_f90.py of data/peers/peers_spec.csv" \
  cmp -s "$TMP/data.f90" apps/src/hertzdamp_peers_data.f90

# --- the table in doc/peers.md is `check --table`
run check --table
check "check --table exits 0" test "$RC" -eq 0
sed -n '/^<!-- BEGIN hertzdamp check --table -->$/,/^<!-- END hertzdamp check --table -->$/p' doc/peers.md \
  | sed '1d;$d' >"$TMP/doc_table"
check "doc/peers.md has the table block" test -s "$TMP/doc_table"
check "doc/peers.md table equals hertzdamp check --table" cmp -s "$TMP/doc_table" "$OUT"
run check --table --format csv
check "check --table --format csv" test "$RC" -eq 0 -a "$(head -n 1 "$OUT")" = "id,law,end,formula,target,speed_ratio,e,status"

# --- a value of a CSV column by name (row n, 1-based) from $OUT
col() { python3 -c "import csv,sys; r=list(csv.DictReader(open(sys.argv[1]))); print(r[int(sys.argv[3])-1][sys.argv[2]])" "$OUT" "$1" "${2:-1}"; }
close() { python3 -c "import sys; a,b,t=map(float,sys.argv[1:]); sys.exit(0 if abs(a-b)<=t*abs(b) else 1)" "$@"; }

# --- LAMMPS: the literal pair_coeff line (one argument) and the same words as separate arguments
run check lammps "pair_coeff 1 1 hertz/material 1e8 0.02 0.3 tangential linear_nohistory 0 0.5 damping velocity" \
  --radius 1e-3 --density 2500 --velocity 0.01,1,5 --e 0.5 --format csv
check "lammps pair_coeff line: exit 0" test "$RC" -eq 0
check "lammps: csv header" test "$(head -n 1 "$OUT")" = \
  "velocity,alpha,e,e_error,t_c,t_attractive,dt_max,t_hertz,t_peer,corrected,status"
check "lammps: one row per speed" test "$(wc -l <"$OUT")" -eq 4
cp "$OUT" "$TMP/words1"
run check lammps hertz/material 1e8 0.02 0.3 tangential linear_nohistory 0 0.5 damping velocity \
  --radius=1e-3 --density 2500 --velocity=0.01,1,5 --e 0.5 --format csv
check "lammps: words as separate arguments give the same output" cmp -s "$OUT" "$TMP/words1"
# alpha = eta_n0 t*/m (doc/peers.md section 1), computed here from the materials
run check lammps "hertz/material 1e8 0.02 0.3 damping velocity" --radius 1e-3 --density 2500 --velocity 1 \
  --e 0.5 --format csv
a=$(col alpha)
want=$(python3 -c "
import math
r=1e-3; rho=2500; E=1e8; nu=0.3; eta=0.02; u=1.0
m=0.5*4/3*math.pi*rho*r**3; R=r/2; k=4/3*E/(2*(1-nu**2))*math.sqrt(R)
ts=(m/(k*math.sqrt(u)))**0.4; print(eta*ts/m)")
check "lammps velocity: alpha = eta_n0 t*/m ($a vs $want)" close "$a" "$want" 1e-13
# the corrected eta_n0 printed at u = 1, fed back, gives e = 0.5
p=$(col corrected)
run check lammps "hertz/material 1e8 $p 0.3 damping velocity" --radius 1e-3 --density 2500 --velocity 1 \
  --e 0.5 --format csv
e=$(col e)
check "lammps velocity: the printed corrected eta_n0 ($p) gives e = 0.5 (got $e)" close "$e" 0.5 1e-10
# the same with limit_damping (force end)
run check lammps "hertz 2e6 0.05 damping velocity limit_damping" --radius 1e-3 --density 2500 --velocity 1 \
  --e 0.3 --format csv
p=$(col corrected)
run check lammps "hertz 2e6 $p damping velocity limit_damping" --radius 1e-3 --density 2500 --velocity 1 \
  --e 0.3 --format csv
check "lammps velocity + limit_damping: corrected eta_n0 gives e = 0.3" close "$(col e)" 0.3 1e-10
# fix wall/gran line
run check lammps "fix 1 all wall/gran granular hertz/material 1e8 0.02 0.3 tangential linear_nohistory 0 0" \
  "damping velocity zplane 0 NULL" --radius 1e-3 --density 2500 --velocity 1 --e 0.5 --release 2021
check "lammps fix wall/gran: exit 0" test "$RC" -eq 0
check "lammps 2021 wall: the 1-nu stiffness is noted" grep -q '1-nu, not 1-nu^2' "$OUT"
check "lammps 2021 wall: the other releases' result is noted" grep -q '^# note.*LAMMPS 28 Mar 2023.*gives e' "$OUT"
# no rebound: the text says so and exits 0 (a physical answer)
run check lammps "hertz/material 1e8 0.5 0.3 damping velocity" --radius 1e-3 --density 2500 --velocity 0.01 --e 0.5
check "no rebound: exit 0" test "$RC" -eq 0
check "no rebound: warning" grep -q '^# warning.*no rebound at 1 of 1 speeds.*alpha_c' "$OUT"
check "no rebound: status column" grep -q 'no-rebound$' "$OUT"
# attractive force warning for the overlap end
run check lammps "hertz/material 1e8 0.02 0.3 damping velocity" --radius 1e-3 --density 2500 --velocity 1 --e 0.5
check "overlap end: attractive-force warning names limit_damping" \
  grep -q '^# warning.*turns attractive before the particles separate.*limit_damping' "$OUT"
# JSON
run check lammps "hertz/material 1e8 0.02 0.3 damping velocity" --radius 1e-3 --density 2500 --velocity 0.1:1:log3 \
  --e 0.5 --format json
check "json parses, 3 rows, cites the source file" python3 -c "
import json,sys; d=json.load(open(sys.argv[1])); assert len(d['rows'])==3; assert 'gran_sub_mod_damping.cpp' in d['source']
assert d['rows'][0]['t_peer'] is None" "$OUT"

# --- every engine's syntax is read (the law may still be missing from the library: exit 0 or 4)
for args in \
  "liggghts youngsModulus=5e6 poissonsRatio=0.45 coefficientRestitution=0.5" \
  "liggghts model=hertz/stiffness kn=1e7 gamman=1e3 limitForce=on --e 0.5" \
  "mercurydpm setEffectiveElasticModulusAndRestitutionCoefficient=1e7,0.5" \
  "mercurydpm species=HertzianViscoelasticSpecies setElasticModulus=1e7 setDissipation=1e-3 --e 0.5" \
  "yade young=1e7 poisson=0.3 en=0.5" \
  "mfix des_coll_model='HERTZIAN' E_YOUNG=1e7 V_POISSON=0.3 DES_EN_INPUT=0.5" \
  "chrono SetYoungModulus=1e7 SetPoissonRatio=0.3 SetRestitution=0.5 SetCollisionSystemType=MULTICORE"; do
  # shellcheck disable=SC2086
  run check $args --radius 1e-3 --density 2500 --velocity 1
  check "reads: $args (exit $RC: $(head -c 150 "$ERR"))" test "$RC" -eq 0 -o "$RC" -eq 2 -a "$(grep -c 'not available in this build' "$ERR")" -eq 1
done
# MercuryDPM Beta 2015 setStiffnessAndRestitutionCoefficient: 1 mm steel, no rebound (doc/peers.md 3b)
run check mercurydpm species=HertzianViscoelasticSpecies setStiffnessAndRestitutionCoefficient=2e11,0.5,4.0841e-6 \
  --radius 5e-4 --density 7800 --velocity 1 --format csv
check "old MercuryDPM 1 mm steel: no rebound" test "$RC" -eq 0 -a "$(col status)" = no-rebound
check "old MercuryDPM 1 mm steel: alpha about 88 (doc/peers.md 3b)" close "$(col alpha)" 88 0.05

# --- the README example runs as written and prints the lines it shows
check "README check example: the command runs and prints the lines shown" python3 - "$BIN" <<'PYEOF'
import shlex, subprocess, sys
lines = open("README.md").read().splitlines()
i = next(k for k, l in enumerate(lines) if l.startswith("    $ hertzdamp check lammps"))
cmd = shlex.split(lines[i][len("    $ "):])
cmd[0] = sys.argv[1]
out = subprocess.run(cmd, capture_output=True, text=True, check=True).stdout.splitlines()
shown = []
for l in lines[i + 1:]:
    if not l.startswith("    # "):
        break
    shown.append(l[4:])
missing = [l for l in shown if l not in out]
for l in missing:
    print("not in the output:", l)
sys.exit(1 if missing or len(shown) < 5 else 0)
PYEOF

# --- help
run check --help
check "check --help" test "$RC" -eq 0 -a "$(grep -c 'pair_coeff' "$OUT")" -ge 1
run --help
check "hertzdamp --help lists check" grep -q '^  check ' "$OUT"

# --- bad input: exit 2, nothing on stdout, one line on stderr naming the culprit
bad() {  # word-in-message, args...
  local word=$1; shift
  expect_fail 2 "$*" "$@"
  check "message names $word: $(cat "$ERR")" grep -qF -- "$word" "$ERR"
}
M="--radius 1e-3 --density 2500 --velocity 1"
# shellcheck disable=SC2086
{
bad 'foo' check foo x=1 $M
bad 'engine' check $M
bad 'frobnicate' check lammps "hertz/material 1e8 0.5 0.3 frobnicate" $M
bad 'E' check lammps "hertz/material -1e8 0.5 0.3 damping tsuji" $M
bad 'nu' check lammps "hertz/material 1e8 0.5 0.7" $M
bad 'coeff_restitution' check lammps "hertz 1e5 0.5 damping coeff_restitution" --release 2021 $M
bad '--release' check lammps "hertz 1e5 0.5" --release 2019 $M
bad '--e' check lammps "hertz 1e5 0.5 damping velocity" $M
bad 'tsuji' check lammps "hertz 1e5 1.5 damping tsuji" $M
bad 'youngsModulus' check liggghts youngsModulus=-5e6 poissonsRatio=0.4 coefficientRestitution=0.5 $M
bad 'coefficientRestitution' check liggghts youngsModulus=5e6 poissonsRatio=0.4 $M
bad 'coefficientRestitution' check liggghts youngsModulus=5e6 poissonsRatio=0.4 coefficientRestitution=0.01 $M
bad 'bogus' check liggghts youngsModulus=5e6 poissonsRatio=0.4 coefficientRestitution=0.5 bogus=1 $M
bad 'malformed' check yade young=1e7x poisson=0.3 en=0.5 $M
bad 'betan' check yade young=1e7 poisson=0.3 en=0.5 betan=0.1 $M
bad 'KN' check mfix DES_COLL_MODEL=HERTZIAN KN=1e5 DES_EN_INPUT=0.9 $M
bad 'DES_COLL_MODEL' check mfix E_YOUNG=1e7 V_POISSON=0.3 DES_EN_INPUT=0.9 $M
bad 'SetKn' check chrono SetYoungModulus=1e7 SetPoissonRatio=0.3 SetRestitution=0.5 SetKn=1 $M
bad 'key=value' check chrono SetYoungModulus 1e7 $M
bad '--radius' check yade young=1e7 poisson=0.3 en=0.5 --density 2500 --velocity 1
bad '--velocity' check yade young=1e7 poisson=0.3 en=0.5 --radius 1e-3 --density 2500
bad '--velocity' check yade young=1e7 poisson=0.3 en=0.5 --radius 1e-3 --density 2500 --velocity -1
bad '--velocity' check yade young=1e7 poisson=0.3 en=0.5 --radius 1e-3 --density 2500 --velocity 0:1:log3
bad '--density' check yade young=1e7 poisson=0.3 en=0.5 --radius 1e-3 --density -5 --velocity 1
bad '--bogus' check yade young=1e7 poisson=0.3 en=0.5 $M --bogus 1
bad '--radius' check yade young=1e7 poisson=0.3 en=0.5 $M --radius 2e-3
bad '--table' check --table lammps
}
finish
