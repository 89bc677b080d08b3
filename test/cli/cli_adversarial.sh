#!/usr/bin/env bash
# Adversarial checks of the stable commands (table, forward, invert, timestep,
# constants, check, calibrate): the output contract at the edges of double precision,
# results that a later command must reproduce, hostile data files and plot targets.
#
# The first part holds one minimal reproducer per defect found by the adversarial
# pass of the review branch (each says what is expected); the second part covers
# ground no other script covers and passes.  The numbers are extreme on purpose: the
# promise is "never a NaN or inf with exit 0, never bad usage for valid input", for
# every input the commands accept.
SUITE=cli_adversarial
source "$(dirname "$0")/cli_common.bash"
cd "$(dirname "$0")/../.."
T=$(mktemp -d)
cleanup() { mountpoint -q "$T/full" 2>/dev/null && umount "$T/full"; rm -rf "$T" "$OUT" "$ERR"; }
trap cleanup EXIT

# clean FORMAT FILE: every number of a table (text, csv or json) is finite when read
# back (Python's float / json), except the documented inf (json: null) contact time of a
# no-rebound row; no nan anywhere, no inf or Infinity in the comment lines.
cat >"$T/clean.py" <<'PYEOF'
import csv, io, json, math, re, sys
fmt, path = sys.argv[1], sys.argv[2]
text = open(path, encoding="utf-8").read()
bad = []
TC = {"t_c", "tau_c", "tc"}
def cell(row, key, v):
    if v is None or v in ("", "-") or key in ("status", "bound_active"):
        return
    if isinstance(v, str) and not re.match(r"^[-+]?(\d|inf|nan)", v, re.I):
        return
    x = float(v)
    if math.isnan(x) or (math.isinf(x) and not (row.get("status") == "no-rebound" and key in TC)):
        bad.append(f"{key}={v!r} (status {row.get('status')})")
if fmt == "json":
    doc = json.loads(text)
    for k, v in doc.items():
        if isinstance(v, str) and re.search(r"\b(nan|inf|infinity)\b", v, re.I):
            bad.append(f"{k}: {v[:120]}")
    rows = doc["rows"]
elif fmt == "csv":
    rows = list(csv.DictReader(io.StringIO(text)))
else:
    import hertzdamp_text   # columns that never change are the rows' cells, not comments
    rows = []
    for t in hertzdamp_text.tables(text):
        for k, v in t.meta.items():
            if re.search(r"\b(nan|inf|infinity)\b", v, re.I):
                bad.append(f"{k}: {v[:160]}")
        rows += t.rows
for r in rows:
    for k, v in r.items():
        cell(r, k, v)
for b in bad[:5]:
    print("   not finite:", b)
sys.exit(1 if bad else 0)
PYEOF
clean() { python3 "$T/clean.py" "$1" "$2"; }
utf8() { python3 -c 'import sys; open(sys.argv[1], "rb").read().decode("utf-8")' "$1" 2>/dev/null; }
col() {  # column [row]: a CSV field of $OUT
  python3 -c "import csv,sys; r=list(csv.DictReader(open(sys.argv[1]))); print(r[int(sys.argv[3])-1][sys.argv[2]])" \
    "$OUT" "$1" "${2:-1}"
}
rel_close() { python3 -c "import sys; a,b,t=map(float,sys.argv[1:]); sys.exit(0 if abs(a-b)<=t*abs(b) else 1)" "$@"; }

# ======================================================================= defects
# Each check below fails on the code this script was written against; the label says
# what is expected.

# --- forward: a no-rebound row whose u t* overflows gets zeta_max = inf, exit 0
# (src/hertzdamp_methods.f90, hertzdamp_forward_dim: zeta_max = u * tstar * r%z_max is
# checked for finiteness only when the status is HD_OK)
for f in csv text; do
  run forward --k 1e-320 --d 1 --velocity 1e300 --mass 1e-3 --format $f
  cp "$OUT" "$T/fwd.$f"
  check "forward no-rebound with u t* = 6e366, $f: exit 0 (got $RC)" test "$RC" -eq 0
  check "forward no-rebound with u t* = 6e366, $f: no inf but the contact time (zeta_max)" clean $f "$T/fwd.$f"
done

# --- timestep: tc_damped = t*_min tau_c overflows: tc_damped = dt_max = inf,
# elastic_excess = -1, status ok, exit 0 (app/hertzdamp_cmd_invert.f90, cmd_timestep)
run timestep --e 1e-4 --damping kuwabara-kono --velocity 1e-300 --mass 1e300 --k-phys 1e-318 --format csv
cp "$OUT" "$T/ts.csv"
check "timestep with tc_damped beyond double precision: exit 0 only with finite numbers (exit $RC)" \
  bash -c "[ $RC -ne 0 ] || python3 '$T/clean.py' csv '$T/ts.csv'"

# --- 16 significant digits: DBL_MAX is printed as 1.797693134862316E+308, which reads
# back as infinity (json.loads, strtod), exit 0 (app/hertzdamp_cli_text.f90, fmt_csv
# es24.15e3; 17 digits round-trip every double)
run forward --k 1e9 --d 0.5 --mass 1e-3 --velocity 1 --k-phys 1.7976931348623157e308 --format json
cp "$OUT" "$T/max.json"
check "forward --k-phys DBL_MAX, json: exit 0 (got $RC)" test "$RC" -eq 0
check "forward --k-phys DBL_MAX, json: every number reads back finite" clean json "$T/max.json"
run forward --k 1e9 --d 0.5 --mass 1e-3 --velocity 1 --k-phys 1.7976931348623157e308 --format csv
cp "$OUT" "$T/max.csv"
check "forward --k-phys DBL_MAX, csv: every number reads back finite" clean csv "$T/max.csv"

# --- a range of whole step counts refused as not whole: 1:23:23 gives 16 as
# 15.999999999999998 (app/hertzdamp_cli.f90 parse_range; app/hertzdamp_cmd_invert.f90
# parse_steps demands exact integers), and the message says "--steps 16: ... must be a
# whole number"
run timestep --e 0.5 --steps 1:23:23 --velocity 1 --mass 1e-3 --k-phys 1e9 --format csv
check "timestep --steps 1:23:23 (whole numbers): exit 0 with 23 rows (exit $RC: $(head -c 120 "$ERR"))" \
  test "$RC" -eq 0 -a "$(wc -l <"$OUT")" -eq 24
run invert --e 0.5 --dt 1e-6 --steps 1:100:100 --velocity 1 --mass 1e-3 --format csv
check "invert --dt 1e-6 --steps 1:100:100: exit 0 with 100 rows (exit $RC: $(head -c 120 "$ERR"))" \
  test "$RC" -eq 0 -a "$(wc -l <"$OUT")" -eq 101

# --- invert: a valid --dt and --steps whose product overflows is bad usage (exit 2);
# it is a contact time outside double precision (out-of-range, exit 3)
run invert --e 0.5 --dt 1e308 --steps 10 --velocity 1 --mass 1e-3 --format csv
check "invert --dt 1e308 --steps 10 (valid values, product not representable): not exit 2 (got $RC)" \
  test "$RC" -ne 2

# --- contact options: an out-of-range E* caused by body 2 is blamed on body 1
# (app/hertzdamp_cli_materials.f90, parse_contact: check(..., '--youngs-modulus',
# '--poisson-ratio', ' effective modulus E*'))
run invert --e 0.5 --tc 1e-5 --velocity 1 --radius 1e-3 --density 2500 --youngs-modulus 1e9 --poisson-ratio 0.3 \
  --youngs-modulus2 1e-320 --poisson-ratio2 0.3
check "E* out of range from --youngs-modulus2 1e-320: exit 2 (got $RC)" test "$RC" -eq 2
check "E* out of range from --youngs-modulus2 1e-320: the message names --youngs-modulus2 ($(cat "$ERR"))" \
  grep -q -- '--youngs-modulus2' "$ERR"

# --- compact forward, overlap: rows beyond alpha(e = 0.05) are "ok" with errors up to
# 36 % (README: compact 1e-5 for e >= 0.05; the inverse refuses e < 0.05, the force
# end refuses alpha > 2.9; src/hertzdamp_compact.f90 accepts every alpha < alpha_c)
# (now refused with exit 3 and a message naming the method's range; an ok row would have
# to be within 1e-3 of rk45)
run table --method compact --alpha 1.1279 --format csv
if [ "$RC" -eq 3 ]; then
  check "compact forward at alpha = 1.1279: refused (exit 3), the message names --method compact's range" \
    grep -q -- 'outside the range of --method compact' "$ERR"
else
  st=$(col status); ec=$(col e)
  run table --method rk45 --alpha 1.1279 --format csv
  er=$(col e)
  check "compact forward at alpha = 1.1279: an ok row is within 1e-3 of rk45 (compact e = $ec, rk45 e = $er, $st)" \
    bash -c "[ '$st' = ok ] && python3 -c 'import sys; a,b=float(sys.argv[1]),float(sys.argv[2]); sys.exit(0 if abs(a-b)<=1e-3*b else 1)' '$ec' '$er'"
fi

# --- check: some speeds fail, exit 4, the table on stdout and NOTHING on stderr
# (app/hertzdamp_cmd_check.f90, run_check: quit(exit_code_of(...)) without a message)
run check lammps "hertz/material 1e8 0.5 0.3 damping viscoelastic" --radius 1e-3 --density 2500 \
  --velocity 1,1e100 --e 0.5 --format csv --quiet
check "check with one of two speeds failing: exit 3 or 4 (got $RC)" test "$RC" -eq 3 -o "$RC" -eq 4
check "check with one of two speeds failing: one line on stderr (got $(wc -l <"$ERR"))" test "$(wc -l <"$ERR")" -eq 1

# --- check: an overdamped deck (alpha > 1e100) is bad usage (exit 2, "invalid damping
# parameter alpha"), while the same deck with eta_n0 = 1e90 and forward --k 1e7 --d 1e110
# say no-rebound, exit 0 (packages/check/src/hertzdamp_peers.f90 has no `overdamped` path)
run check lammps "hertz 1e7 1e110 damping velocity" --radius 1e-3 --density 2500 --velocity 1 --e 0.5 --format csv
check "check lammps 'hertz 1e7 1e110 damping velocity' (overlap end, no rebound): exit 0 (got $RC: $(head -c 100 "$ERR"))" \
  test "$RC" -eq 0
check "check lammps 'hertz 1e7 1e110 damping velocity': status no-rebound" \
  bash -c "[ $RC -eq 0 ] && grep -q 'no-rebound$' '$OUT'"

# --- check: the engine's own time estimate overflows in its intermediate (E^2 = 1e-600):
# t_peer = inf, "= inf s ... +Infinity % against t_c", exit 0 (packages/check/src/hertzdamp_peers.f90,
# peer_time_estimate)
for f in csv text; do
  run check mercurydpm setEffectiveElasticModulusAndRestitutionCoefficient=1e-300,0.5 --radius 1e-3 --density 2500 \
    --velocity 1 --format $f
  cp "$OUT" "$T/tpeer.$f"
  check "check mercurydpm E = 1e-300, $f: exit 0 only without inf (exit $RC)" \
    bash -c "[ $RC -ne 0 ] || python3 '$T/clean.py' $f '$T/tpeer.$f'"
done

# --- check: a target e = 1e-320 is accepted; e_error = e/e_target - 1 = inf and
# "+Infinity %" in the achieved line, exit 0 (app/hertzdamp_cmd_check.f90, --e)
run check yade young=1e7 poisson=0.3 en=0.5 --radius 1e-3 --density 2500 --velocity 1 --e 1e-320
cp "$OUT" "$T/etiny.txt"
check "check --e 1e-320: refused (exit 2) or no inf/Infinity in the report (exit $RC)" \
  bash -c "[ $RC -ne 0 ] || python3 '$T/clean.py' text '$T/etiny.txt'"

# --- check: the corrected parameter overflows and is prescribed as "inf", exit 0
# (packages/check/src/hertzdamp_peers.f90, peer_evaluate: p_corrected not checked for finiteness)
run check lammps "hertz 2e7 0" --radius 1e-100 --radius2 1e-3 --density 2500 --velocity 1 --e 0.5
cp "$OUT" "$T/corr.txt"
check "check: corrected parameter beyond double precision is not printed as 'inf' (exit $RC)" \
  bash -c "[ $RC -ne 0 ] || ! grep -Eq '^# corrected: .*\binf\b' '$T/corr.txt'"
check "check: corrected column has no inf (exit $RC)" \
  bash -c "[ $RC -ne 0 ] || python3 '$T/clean.py' text '$T/corr.txt'"

# --- check: --wall with --radius2/--density2 is silently ignored (exit 0); invert,
# forward, timestep and calibrate refuse it (exit 2): check parses its own options
expect_fail 2 "check --wall --radius2 (body 2 is a wall)" check yade young=1e7 poisson=0.3 en=0.5 --radius 1e-3 \
  --density 2500 --velocity 1 --wall --radius2 1

# --- calibrate --help into a full device: exit 0 with nothing written
# (app/hertzdamp_cmd_calibrate.f90 writes its help with an unchecked write)
"$BIN" calibrate --help >/dev/full 2>"$ERR"; RC=$?
check "calibrate --help > /dev/full: exit 4 (got $RC)" test "$RC" -eq 4
check "calibrate --help > /dev/full: one line on stderr" test "$(wc -l <"$ERR")" -eq 1

# --- calibrate text output: the file name is printed raw ('# hertzdamp calibrate FILE',
# app/hertzdamp_cmd_calibrate.f90 write_text): a Latin-1 byte makes the output invalid
# UTF-8, a newline breaks the comment line
F=$T/$(printf 'caf\xe9\nx.csv')
printf 'velocity,e\n1,0.5\n2,0.6\n' >"$F"
run calibrate "$F" --mass 1e-3 --k-phys 1e9
check "calibrate text, file name with a Latin-1 byte and a newline: exit 0 (got $RC)" test "$RC" -eq 0
check "calibrate text, file name with a Latin-1 byte: output is valid UTF-8" utf8 "$OUT"
check "calibrate text, file name with a newline: the first two lines are comments" \
  bash -c "[ \"\$(head -n 2 '$OUT' | grep -c '^#')\" -eq 2 ]"

# ======================================================================= new ground (passes)

# --- every command, every law and end, JSON that parses and numbers that read back
for law in linear tsuji kuwabara-kono; do
  for end in overlap force; do
    for cmd in "table --alpha 0,0.5,2,60" \
               "forward --k 1e9 --d 0,0.5,1e4 --velocity 0.01,1,50 --mass 1e-3" \
               "invert --e 1e-3,0.5,1 --tc 1e-5 --velocity 0.01,1,50 --radius 1e-3 --density 2500 --youngs-modulus 63e9 --poisson-ratio 0.24" \
               "timestep --e 0.1,0.9 --velocity 0.01:5:log4 --radius 1e-3 --density 2500 --wall --youngs-modulus 63e9 --poisson-ratio 0.24"; do
      # shellcheck disable=SC2086
      run $cmd --damping $law --end $end --format json
      cp "$OUT" "$T/j.json"
      check "${cmd%% *} --damping $law --end $end json: exit 0 or 3 (got $RC), parses, finite" \
        bash -c "[ $RC -eq 0 -o $RC -eq 3 ] && python3 '$T/clean.py' json '$T/j.json'"
    done
  done
  run constants --damping $law --format json
  check "constants --damping $law: JSON parses" python3 -c 'import json,sys; json.load(open(sys.argv[1]))' "$OUT"
done

# --- check: the corrected parameter of every engine, fed back, gives the target e
# (test/cli/cli_check.sh does this for LAMMPS velocity); Chrono stores SetRestitution and
# SetGn as floats (the deck says so), hence 1e-6 there
M="--radius 1e-3 --density 2500 --velocity 0.7"
feed() {  # tolerance, key-of-corrected, engine words... (with the target via --e)
  local tol=$1 key=$2; shift 2
  run check "$@" $M --e 0.42 --format csv
  local p
  p=$(col corrected)
  if [ "$RC" -ne 0 ] || [ -z "$p" ]; then check "feed back $key: corrected value given (exit $RC)" false; return; fi
  local args=() a
  for a in "$@"; do case "$a" in "$key="*) args+=("$key=$p") ;; *) args+=("$a") ;; esac; done
  run check "${args[@]}" $M --e 0.42 --format csv
  check "$1 $key=$p fed back gives e = 0.42 (got $(col e), tolerance $tol)" rel_close "$(col e)" 0.42 "$tol"
}
feed 1e-10 coefficientRestitution liggghts youngsModulus=5e6 poissonsRatio=0.45 coefficientRestitution=0.5
feed 1e-10 coefficientRestitution liggghts youngsModulus=5e6 poissonsRatio=0.45 coefficientRestitution=0.5 limitForce=on
feed 1e-10 gamman liggghts model=hertz/stiffness kn=1e7 gamman=1e3
feed 1e-10 setDissipation mercurydpm setEffectiveElasticModulus=1e7 setDissipation=1e-3
feed 1e-10 en yade young=1e7 poisson=0.3 en=0.5
feed 1e-10 betan yade young=1e7 poisson=0.3 betan=0.3
feed 1e-10 DES_EN_INPUT mfix DES_COLL_MODEL=HERTZIAN E_YOUNG=1e7 V_POISSON=0.3 DES_EN_INPUT=0.5
feed 1e-6 SetRestitution chrono SetYoungModulus=1e7 SetPoissonRatio=0.3 SetRestitution=0.5
feed 1e-6 SetGn chrono UseMaterialProperties=false SetKn=1e5 SetGn=1

# --- calibrate: hostile data files
printf 'velocity,e\n0.5,0.62\n1,0.6\n2,0.58\n' >"$T/lf.csv"
printf 'velocity,e\r\n0.5,0.62\r\n1,0.6\r\n2,0.58' >"$T/crlf.csv"
run calibrate "$T/lf.csv" --mass 1e-3 --k-phys 1e9 --format csv; cp "$OUT" "$T/lf.out"
run calibrate "$T/crlf.csv" --mass 1e-3 --k-phys 1e9 --format csv
check "calibrate: CRLF and no final newline give the LF result" cmp -s "$OUT" "$T/lf.out"
printf 'velocity,e,velocity\n1,0.5,1\n2,0.6,2\n' >"$T/dup.csv"
expect_fail 2 "calibrate: a column given twice" calibrate "$T/dup.csv" --mass 1e-3
check "calibrate: a column given twice names it" grep -q 'velocity.*given twice' "$ERR"
printf 'veloc\xefty,e\n1,0.5\n2,0.6\n' >"$T/latin.csv"
expect_fail 2 "calibrate: a Latin-1 header" calibrate "$T/latin.csv" --mass 1e-3
check "calibrate: a Latin-1 header: stderr valid UTF-8" utf8 "$ERR"
printf 'velocity,e\n1,0.5\n' >"$T/one.csv"
expect_fail 3 "calibrate: one row" calibrate "$T/one.csv" --mass 1e-3
: >"$T/empty.csv"
expect_fail 2 "calibrate: an empty file" calibrate "$T/empty.csv" --mass 1e-3
printf 'velocity,e\n1,inf\n2,0.6\n' >"$T/inf.csv"
expect_fail 2 "calibrate: inf" calibrate "$T/inf.csv" --mass 1e-3
printf 'velocity,e\n1,0.5\n1e309,0.6\n' >"$T/ovf.csv"
expect_fail 2 "calibrate: 1e309" calibrate "$T/ovf.csv" --mass 1e-3
python3 -c "print('velocity,e'); [print(f'{1 + i * 1e-3},0.5') for i in range(100001)]" >"$T/many.csv"
expect_fail 2 "calibrate: more than 100000 data rows" calibrate "$T/many.csv" --mass 1e-3
mkdir "$T/adir"
expect_fail 2 "calibrate: a directory as data file" calibrate "$T/adir" --mass 1e-3
for data in 'velocity,e\n1e-300,0.5\n1e300,0.6\n' 'velocity,e,tc\n1,0.5,1e-300\n2,0.6,1e300\n' \
            'velocity,e,tc,sigma_e,sigma_tc\n1,0.5,1e-5,1e-300,1e-300\n2,0.6,1e-5,1e300,1e300\n'; do
  printf "$data" >"$T/ext.csv"
  for f in csv json; do
    run calibrate "$T/ext.csv" --mass 1e-300 --k-phys 1e300 --format $f
    cp "$OUT" "$T/ext.$f"
    check "calibrate extreme values ($(head -c 40 "$T/ext.csv" | tr '\n' ' ')), $f: exit 0 only without nan/inf (exit $RC)" \
      bash -c "[ $RC -ne 0 ] || ! grep -Eqi '\\bnan\\b|\\binf\\b|infinity' '$T/ext.$f'"
    if [ "$f" = json ] && [ "$RC" -eq 0 ]; then
      check "calibrate extreme values: JSON parses" python3 -c 'import json,sys; json.load(open(sys.argv[1]))' "$T/ext.json"
    fi
  done
done

# --- calibrate --plot: special files refused before any work, a full disk leaves nothing
if command -v gnuplot >/dev/null 2>&1; then
  D="data/calibrate/example.csv --radius 1e-3 --density 7800 --wall"
  mkfifo "$T/fifo"
  # shellcheck disable=SC2086
  timeout 20 "$BIN" calibrate $D --plot "$T/fifo" >"$OUT" 2>"$ERR"; RC=$?
  check "calibrate --plot FIFO: refused at once (exit $RC)" test "$RC" -eq 2 -a ! -s "$OUT" -a "$(wc -l <"$ERR")" -eq 1
  check "calibrate --plot FIFO: still a FIFO" test -p "$T/fifo"
  # shellcheck disable=SC2086
  expect_fail 2 "calibrate --plot a directory" calibrate $D --plot "$T/adir"
  if mknod "$T/null" c 1 3 2>/dev/null; then
    # shellcheck disable=SC2086
    expect_fail 2 "calibrate --plot a character device" calibrate $D --plot "$T/null"
    check "calibrate --plot device: still a device" test -c "$T/null"
  fi
  mkdir -p "$T/full" "$T/scratch"
  if mount -t tmpfs -o size=64k tmpfs "$T/full" 2>/dev/null; then
    dd if=/dev/zero of="$T/full/fill" bs=1k count=60 2>/dev/null
    # shellcheck disable=SC2086
    run calibrate $D --plot "$T/full/x.png"
    check "calibrate --plot on a full disk: exit 4 (got $RC)" test "$RC" -eq 4
    check "calibrate --plot on a full disk: stdout empty, one line on stderr" \
      test ! -s "$OUT" -a "$(wc -l <"$ERR")" -eq 1
    check "calibrate --plot on a full disk: nothing left" test "$(ls -A "$T/full")" = fill
    # shellcheck disable=SC2086
    TMPDIR=$T/full "$BIN" calibrate $D --plot "$T/scratch/y.png" >"$OUT" 2>"$ERR"; RC=$?
    check "calibrate --plot, TMPDIR full: exit 4 (got $RC)" test "$RC" -eq 4
    check "calibrate --plot, TMPDIR full: no plot, no scratch file" \
      test ! -e "$T/scratch/y.png" -a "$(ls -A "$T/full")" = fill
  else
    echo "SKIPPED $SUITE: full-disk calibrate --plot (cannot mount a tmpfs)"
  fi
fi
finish
