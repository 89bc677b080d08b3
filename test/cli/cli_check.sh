#!/usr/bin/env bash
# CLI checks of `hertzdamp check`: the embedded specification and the documentation
# table are in sync, decks in each engine's syntax are read, the printed corrected
# parameter fed back gives the target, and bad input gives one line naming the key.
SUITE=cli_check
cd "$(dirname "$0")/../.." || exit 1
. test/cli/cli_common.bash
TMP=$(mktemp -d); trap 'rm -rf "$TMP" "$OUT" "$ERR"' EXIT

# --- the specification embedded in the program is the CSV (regenerated and compared)
python3 gen/peers_to_f90.py data/peers/peers_spec.csv "$TMP/data.f90"
check "packages/check/src/hertzdamp_check_data.f90 is gen/peers_to_f90.py of data/peers/peers_spec.csv" \
  cmp -s "$TMP/data.f90" packages/check/src/hertzdamp_check_data.f90

# --- the table in doc/peers.md is `check --table`
run check --table
check "check --table exits 0" test "$RC" -eq 0
sed -n '/^<!-- BEGIN hertzdamp check --table -->$/,/^<!-- END hertzdamp check --table -->$/p' doc/peers.md \
  | sed '1d;$d' >"$TMP/doc_table"
check "doc/peers.md has the table block" test -s "$TMP/doc_table"
check "doc/peers.md table equals hertzdamp check --table" cmp -s "$TMP/doc_table" "$OUT"
run check --table --format csv
check "check --table --format csv" test "$RC" -eq 0 -a "$(head -n 1 "$OUT")" = "id,law,end,formula,target,speed_ratio,e,status"

# --- a value of a CSV column by name (row n, 1-based) from a file, or from $OUT
colf() { python3 -c "import csv,sys; r=list(csv.DictReader(open(sys.argv[1]))); print(r[int(sys.argv[3])-1][sys.argv[2]])" "$1" "$2" "${3:-1}"; }
col() { colf "$OUT" "$@"; }
close() { python3 -c "import sys; a,b,t=map(float,sys.argv[1:]); sys.exit(0 if abs(a-b)<=t*abs(b) else 1)" "$@"; }

# --- LAMMPS: the literal pair_coeff line (one argument) and the same words as separate arguments
run check lammps "pair_coeff 1 1 hertz/material 1e8 0.02 0.3 tangential linear_nohistory 0 0.5 damping velocity" \
  --radius 1e-3 --density 2500 --velocity 0.01,1,5 --e 0.5 --format csv
check "lammps pair_coeff line: exit 0" test "$RC" -eq 0
check "lammps: csv header" test "$(head -n 1 "$OUT")" = \
  "velocity,alpha,e,e_error,t_c,t_attractive,dt_max,t_hertz,t_peer,corrected,method,status"
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

# --- the method of each row: the library's fitted maps, rk45 beyond their range; both
# agree with the reference integrator (table --method rk45 at the row's alpha) for every
# law and end: linear (velocity), tsuji (coeff_restitution), kuwabara-kono (viscoelastic)
ref() {  # law end alpha -> "e tau_c" of table --method rk45
  "$BIN" table --method rk45 --damping "$1" --end "$2" --alpha "$3" --format csv |
    python3 -c "import csv,sys; r=next(csv.DictReader(sys.stdin)); print(r['e'], r['tau_c'])"
}
for deck in "lammps|hertz/material 1e8 0.02 0.3 damping velocity|linear" \
            "lammps|hertz/material 1e8 0.3 0.3 damping coeff_restitution|tsuji" \
            "lammps|hertz/material 1e8 3e8 0.3 damping viscoelastic|kuwabara-kono"; do
  IFS='|' read -r eng words law <<<"$deck"
  for lim in "" " limit_damping"; do
    end=overlap; [ -n "$lim" ] && end=force
    run check "$eng" "$words$lim" --radius 1e-3 --density 2500 --velocity 0.01,1,1e7 --e 0.5 --format csv
    cp "$OUT" "$TMP/m.csv"
    for row in 1 2 3; do
      a=$(colf "$TMP/m.csv" alpha $row); e=$(colf "$TMP/m.csv" e $row); st=$(colf "$TMP/m.csv" status $row)
      me=$(colf "$TMP/m.csv" method $row)
      # tau_c = t_c / t* = tau_c(0) t_c / t_hertz
      ts=$(python3 -c "import sys; print(float(sys.argv[1]) / float(sys.argv[2]) * 3.2180654597190431)" \
        "$(colf "$TMP/m.csv" t_c $row)" "$(colf "$TMP/m.csv" t_hertz $row)" 2>/dev/null)
      if [ "$st" = ok ]; then
        read -r er tr <<<"$(ref "$law" "$end" "$a")"
        check "$law $end row $row ($me): e = rk45 at alpha $a to 1e-10 ($e vs $er)" close "$e" "$er" 1e-10
        check "$law $end row $row ($me): t_c/t* = rk45 tau_c to 1e-10 ($ts vs $tr)" close "$ts" "$tr" 1e-10
      else
        check "$law $end row $row: status $st is no-rebound (a law with alpha_c, overlap end)" \
          test "$st" = no-rebound -a "$law" != kuwabara-kono -a "$end" = overlap
      fi
    done
  done
done
run check lammps "hertz/material 1e8 3e8 0.3 damping viscoelastic" --radius 1e-3 --density 2500 --velocity 1,1e7 \
  --e 0.5 --format csv
check "kuwabara-kono overlap: fit within the fitted range (alpha 0.5), rk45 beyond (alpha 21)" \
  test "$(col method 1) $(col method 2)" = "fit rk45"
run check lammps "hertz/material 1e8 3e8 0.3 damping viscoelastic" --radius 1e-3 --density 2500 --velocity 1,1e7 --e 0.5
check "the method line counts the rows of each method" grep -q '^# method: fit .* at 1 of 2 speeds; rk45 .* at 1 of 2 speeds' "$OUT"

# --- row statuses and exit codes (hertzdamp_cli_rows: exit 0 when every row has a
# result, 3 or 4 with the table and one line on stderr when some have none, nothing on
# stdout when none has)
run check lammps "hertz/material 1e8 0.5 0.3 damping viscoelastic" --radius 1e-3 --density 2500 --velocity 1,1e100 \
  --e 0.5 --format csv --quiet
check "a speed whose computation fails (rk45 step limit): exit 4, the table, one line naming --velocity 1e100" \
  test "$RC" -eq 4 -a "$(wc -l <"$OUT")" -eq 3 -a "$(wc -l <"$ERR")" -eq 1 -a "$(grep -c -- '--velocity 1e100' "$ERR")" -eq 1
check "the failed row: status failed, results empty" test "$(col status 2),$(col e 2),$(col t_c 2)" = "failed,,"
expect_fail 3 "every speed out of range (e/e_target - 1 beyond double precision)" \
  check yade young=1e7 poisson=0.3 en=0.5 --radius 1e-3 --density 2500 --velocity 1,2 --e 1e-320
check "message names e/e_target: $(cat "$ERR")" grep -q 'e/e_target - 1 .* outside the double-precision range' "$ERR"
# an overdamped linear deck: alpha = 1e111 (and 1e191 with t* = 1e187 s) is no rebound
run check lammps "hertz 1e-320 1 damping velocity" --radius 1e-3 --density 2500 --velocity 1e-300,1 --e 0.5 \
  --format csv
check "overdamped linear overlap: no rebound at every speed, exit 0" \
  test "$RC" -eq 0 -a "$(col status 1) $(col status 2)" = "no-rebound no-rebound"
# the same with the force end: no method takes alpha > 1e100 (exit 3, outside-validity)
expect_fail 3 "overdamped linear force end: outside every method" \
  check lammps "hertz 1e-320 1 damping velocity limit_damping" --radius 1e-3 --density 2500 --velocity 1 --e 0.5
check "message: the largest alpha any method takes ($(cat "$ERR"))" grep -q 'largest alpha any method takes' "$ERR"
# values beyond double precision are never printed as inf: the engine's estimate and
# the corrected value are left empty with the reason
run check mercurydpm setEffectiveElasticModulusAndRestitutionCoefficient=1e-300,0.5 --radius 1e-3 --density 2500 \
  --velocity 1 --format csv
tp=$(col t_peer)
want=$(python3 -c "print(2.214 * (2500 / 1e-300)**0.4 * 1.0**-0.2 * 2 * 1e-3)")   # (rho/E)^(2/5) u^(-1/5) 2r
check "MercuryDPM estimate with E = 1e-300: finite, 2.214 (rho^2/(E^2 u))^(1/5) 2r ($tp vs $want)" close "$tp" "$want" 1e-12
run check lammps "hertz 2e7 0" --radius 1e-100 --radius2 1e-3 --density 2500 --velocity 1 --e 0.5
check "corrected value beyond double precision: said so, exit 0" \
  test "$RC" -eq 0 -a "$(grep -c '^# corrected: no value .*outside the double-precision range' "$OUT")" -eq 1
# no inf and no NaN in any report but the contact time of a no-rebound row
for f in text csv json; do
  run check lammps "hertz 1e7 1e110 damping velocity" --radius 1e-3 --density 2500 --velocity 1,1e300 --e 0.5 --format $f
  check "no-rebound deck, $f: no nan, inf only as t_c" python3 - "$f" "$OUT" <<'PYEOF'
import csv, io, json, re, sys
fmt, path = sys.argv[1], sys.argv[2]
text = open(path).read()
if fmt == "json":
    doc = json.loads(text)   # Python reads NaN and Infinity: refuse them, and in the strings
    meta = " ".join(v for v in doc.values() if isinstance(v, str))
    sys.exit(1 if re.search(r"\bNaN\b|Infinity", text) or re.search(r"\b(nan|inf)\b", meta, re.I) else 0)
lines = [l for l in text.splitlines() if not l.startswith("#")]
if fmt == "csv":
    rows = list(csv.DictReader(io.StringIO("\n".join(lines))))
else:
    import hertzdamp_text   # the metadata must be finite; columns that never change are rows' cells
    t = hertzdamp_text.tables(text)[0]; rows = t.rows
    if re.search(r"\b(nan|inf|infinity)\b", " ".join(t.meta.values()), re.I):
        sys.exit(1)
for r in rows:
    for k, v in r.items():
        if re.match(r"^[-+]?(nan|inf)", v or "", re.I) and not (k == "t_c" and r["status"] == "no-rebound"):
            sys.exit(1)
PYEOF
done

# --progress: progress on stderr, the same stdout
run check yade young=1e7 poisson=0.3 en=0.5 --radius 1e-3 --density 2500 --velocity 0.1:1:50 --format csv
cp "$OUT" "$TMP/noprog"
run check yade young=1e7 poisson=0.3 en=0.5 --radius 1e-3 --density 2500 --velocity 0.1:1:50 --format csv --progress
check "--progress: exit 0, stdout unchanged, progress on stderr" \
  bash -c "[ $RC -eq 0 ] && cmp -s '$OUT' '$TMP/noprog' && grep -q 'check' '$ERR'"

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

# --- a softened normal contact that keeps a physical tangential stiffness (issue 33): stock
# pair_style granular with mindlin kt far above what any material gives for its kn (8 G* =
# 1 to 2 times (4/3) E*), and the hertzdamp plugin with tangential_stiffness physical
run check lammps "hertz 1e7 0.01 tangential mindlin 5.77e10 0.5 0.3 damping velocity" --radius 1e-3 \
  --density 2500 --velocity 1 --e 0.5
check "lammps: softened kn 1e7 with the physical mindlin kt 5.77e10: warning with the ratio 5770" \
  grep -q '^# note.*warning: tangential mindlin kt = 5.77e10 is 5770 times the normal kn = 1e7' "$OUT"
for d in "hertz 1e7 0.01 tangential mindlin 1.3e7 0.5 0.3 damping velocity" \
         "hertz/material 1e8 0.01 0.3 tangential mindlin NULL 0.5 0.3 damping velocity" \
         "hertz 1e7 0.01 tangential linear_nohistory 0 0.5 damping velocity"; do
  run check lammps "$d" --radius 1e-3 --density 2500 --velocity 1 --e 0.5
  check "lammps '$d': exit 0, no tangential warning (kt in the materials' range, NULL, or no mindlin)" \
    test "$RC" -eq 0 -a "$(grep -c 'tangential mindlin kt' "$OUT")" -eq 0
done
plugin_deck() {  # the pair style's and the wall fix's extra keywords
  cat >"$TMP/plugin.in" <<EOF2
units si
atom_style sphere
region b block 0 0.01 0 0.01 0 0.01
create_box 1 b
create_atoms 1 single 0.005 0.005 0.005
set type 1 diameter 0.002
set type 1 density 2500
pair_style granular/hertzdamp steps 20 $1
pair_coeff * * e 0.5 youngs 63e9 poisson 0.24 tangential mindlin NULL 0.5 0.3
fix w all hertzdamp/wall steps 20 e 0.5 $2 youngs 63e9 poisson 0.24 tangential mindlin NULL 0.5 0.3 zplane 0 NULL
EOF2
}
plugin_deck "tangential_stiffness physical" ""
run check lammps "$TMP/plugin.in" --velocity 1
check "plugin deck, pair_style tangential_stiffness physical: the warning names the pair style" \
  grep -q 'plugin.in:9: warning: pair_style granular/hertzdamp (the hertzdamp LAMMPS plugin) softens the normal contact and keeps the physical tangential stiffness' "$ERR"
plugin_deck "" "tangential_stiffness physical"
sed -i 's/^pair_style.*/pair_style granular/; s/^pair_coeff.*/pair_coeff * * hertz 1e7 0.01 damping velocity tangential linear_nohistory 0 0.3/' "$TMP/plugin.in"
run check lammps "$TMP/plugin.in" --velocity 1 --e 0.5
check "plugin deck, fix hertzdamp/wall tangential_stiffness physical: the warning names the wall fix" \
  grep -q 'plugin.in:10: warning: fix hertzdamp/wall (the hertzdamp LAMMPS plugin) softens' "$OUT"
plugin_deck "" ""
run check lammps "$TMP/plugin.in" --velocity 1
check "plugin deck with the default tangential_stiffness adapted: no warning" \
  test "$(grep -c 'tangential stiffness' "$OUT" "$ERR" | awk -F: '{s += $2} END {print s}')" -eq 0

# --- options through the shared parser and contact options (as invert, forward, timestep)
M1="--density 2500 --velocity 1"
# shellcheck disable=SC2086
{
bad '--radius2' check yade young=1e7 poisson=0.3 en=0.5 --radius 1e-3 $M1 --wall --radius2 1
bad '--density2' check yade young=1e7 poisson=0.3 en=0.5 --radius 1e-3 $M1 --wall --density2 1
bad '--radius' check yade young=1e7 poisson=0.3 en=0.5 --radius2 1e-3 $M1
bad '--radius' check yade young=1e7 poisson=0.3 en=0.5 --radius 0 $M1
bad '--wall' check yade young=1e7 poisson=0.3 en=0.5 --radius 1e-3 $M1 --wall=1
bad '--velocity' check yade young=1e7 poisson=0.3 en=0.5 --radius 1e-3 --density 2500 --velocity
bad '--format' check yade young=1e7 poisson=0.3 en=0.5 --radius 1e-3 $M1 --format xml
bad '--release' check yade young=1e7 poisson=0.3 en=0.5 --radius 1e-3 $M1 --release 2021
}
finish
