#!/usr/bin/env bash
# The text output for people (issue 25 item 6), against an independent rendering of
# the same command's CSV (or JSON) by the rules of app/hertzdamp_cli_output.f90,
# written here in Python: units in the header (the units each command documents),
# columns that never change printed once above the table in the short form, 7
# significant digits with two-digit exponents, whole numbers as integers, a table of
# one row as a list; calibrate through the same formatter.  CSV and JSON are checked
# elsewhere (cli_output, cli_invert, readme_sync); here only that text and CSV agree.
SUITE=cli_text
source "$(dirname "$0")/cli_common.bash"
cd "$(dirname "$0")/../.."
T=$(mktemp -d); trap 'rm -rf "$T" "$OUT" "$ERR"' EXIT

cat >"$T/render.py" <<'PYEOF'
"""render.py CSV TEXT UNITS_JSON: exit 0 when TEXT (minus its '# key: value' lines) is
CSV rendered by the text rules, with the units of UNITS_JSON in the header."""
import csv, json, re, sys

def whole(x):
    return x == int(x) and abs(x) < 1e7

def number(v):
    try:
        return float(v)
    except ValueError:
        return None

def cell(v):
    """A table cell: 7 significant digits, two-digit exponent; a whole number as an integer."""
    if v == "":
        return "-"
    x = number(v)
    if x is None or x != x:
        return v
    if x in (float("inf"), float("-inf")):
        return "inf" if x > 0 else "-inf"
    if whole(x):
        return str(int(x))
    return "%.6e" % x          # Python: at least two exponent digits, three from 1e100

def short(v):
    """One value: the shortest of at most 7 significant digits that reads back (or the
    rounding to 7), plain from 1e-4 to below 1e6, else with a two-digit exponent."""
    x = number(v)
    if x is None or v == "" or x in (float("inf"), float("-inf")):
        return cell(v)
    if whole(x):
        return str(int(x))
    for d in range(1, 8):
        s = "%.*e" % (d - 1, x)
        if float(s) == x:
            break
    mant, ex = s.split("e")
    ex = int(ex)
    if "." in mant:
        mant = mant.rstrip("0").rstrip(".")
    if -4 <= ex <= 5:
        sign = "-" if mant.startswith("-") else ""
        dig = mant.lstrip("-").replace(".", "")
        p = 1 + ex
        if p <= 0:
            return sign + "0." + "0" * (-p) + dig
        if p >= len(dig):
            return sign + dig + "0" * (p - len(dig))
        return sign + dig[:p] + "." + dig[p:]
    return "%se%s%02d" % (mant, "-" if ex < 0 else "+", abs(ex))

def render(rows, head, units):
    name = [h + (" [%s]" % units[h] if units.get(h) else "") for h in head]
    txt = [[cell(r[j]) for j in range(len(head))] for r in rows]
    const = [len(rows) >= 1 and all(t[j] == txt[0][j] for t in txt) for j in range(len(head))]
    if len(rows) >= 2 and all(const):
        const = [False] * len(head)
    w = max([len(name[j]) for j in range(len(head)) if const[j]] or [0])
    out = [("# " if len(rows) >= 2 else "") + name[j].ljust(w) + " = " + short(rows[0][j])
           for j in range(len(head)) if const[j]]
    if len(rows) == 1:
        return out
    keep = [j for j in range(len(head)) if not const[j]]
    width = {j: max([len(name[j])] + [len(t[j]) for t in txt]) for j in keep}
    out.append(" ".join(name[j].rjust(width[j]) for j in keep))
    out += [" ".join(t[j].rjust(width[j]) for j in keep) for t in txt]
    return out

if __name__ == "__main__":
    rows = list(csv.reader(open(sys.argv[1])))
    units = json.loads(sys.argv[3])
    text = [l for l in open(sys.argv[2]).read().splitlines() if not re.match(r"^# [^=]+?: ", l)]
    want = render(rows[1:], rows[0], units)
    if text != want:
        for a, b in zip(text + [""] * len(want), want + [""] * len(text)):
            if a != b:
                print("   got :", a[:150]); print("   want:", b[:150]); break
        sys.exit(1)
PYEOF

# text = CSV rendered (command, units as JSON)
same() {
  local label=$1 units=$2; shift 2
  "$BIN" "$@" --format csv >"$T/c.csv" 2>/dev/null
  local rc_csv=$?
  run "$@"
  check "$label: exit code as CSV's ($RC)" test "$RC" -eq "$rc_csv"
  check "$label: text = CSV by the text rules" python3 "$T/render.py" "$T/c.csv" "$OUT" "$units"
  check "$label: no three-digit exponent below 1e100, no E" bash -c "! grep -qE '[0-9]E|e[-+]0[0-9][0-9]' '$OUT'"
}
GLASS="--radius 1e-3 --density 2500 --youngs-modulus 63e9 --poisson-ratio 0.24"
U_INV='{"tc":"s","velocity":"m/s","mass":"kg","radius_eff":"m","k_phys":"N m^-3/2","t_star":"s","k":"N m^-3/2","d":"kg/s","tc_actual":"s"}'
U_FWD='{"k":"N m^-3/2","d":"kg/s","velocity":"m/s","mass":"kg","radius_eff":"m","k_phys":"N m^-3/2","t_star":"s","t_c":"s","zeta_max":"m"}'
U_TS='{"velocity_max":"m/s","mass":"kg","radius_eff":"m","k_phys":"N m^-3/2","tc_damped":"s","tc_elastic":"s","dt_max":"s","dt_elastic":"s","t_rayleigh":"s","dt_rayleigh":"s"}'
U_CHK='{"velocity":"m/s","t_c":"s","t_attractive":"s","dt_max":"s","t_hertz":"s","t_peer":"s"}'
same "invert, glass beads" "$U_INV" invert $GLASS --e 0.9 --dt 1e-6 --steps 10 --velocity 0.01:5:log5
same "invert, a row without result" "$U_INV" invert --e 0.9,0.0005 --tc 1e-5 --mass 1e-3 --velocity 1
same "invert, kuwabara-kono" '{"tc":"s","velocity":"m/s","mass":"kg","radius_eff":"m","k_phys":"N m^-3/2","t_star":"s","k":"N m^-3/2","d":"kg s^-1 m^-1/2","tc_actual":"s"}' \
  invert --damping kuwabara-kono --e 0.5 --dt 1e-6 --steps 10 $GLASS --velocity 0.1,1,5
same "forward, one row: a list" "$U_FWD" forward --k 1e9 --d 0.5 $GLASS --velocity 1
same "forward, no rebound (inf)" "$U_FWD" forward --k 1e9 --d 0.5,1e6 --mass 1e-3 --velocity 1,2
same "timestep, steps whole" "$U_TS" timestep $GLASS --e 0.9,0.5 --steps 10,20 --velocity 0.01:5:log20
same "timestep, no materials: no Rayleigh step" "$U_TS" timestep --mass 1e-3 --k-phys 1e9 --e 0.9 --velocity 1
same "table" '{}' table --alpha 0:1.2:13
same "table, every column varies but status" '{}' table --method compact --alpha 0.1,0.2
same "constants" '{}' constants
same "check" "$U_CHK" check lammps "hertz/material 63e9 0.5 0.24 damping tsuji" --radius 1e-3 --density 2500 \
  --velocity 0.1,1,5
same "identical rows stay a table" "$U_INV" invert --e 0.9 --tc 1e-5 --mass 1e-3 --velocity 1,1

# calibrate: the summary and the residuals through the same formatter (JSON values)
"$BIN" calibrate data/calibrate/example.csv --radius 1e-3 --density 2500 --format json >"$T/cal.json"
run calibrate data/calibrate/example.csv --radius 1e-3 --density 2500
check "calibrate text: exit 0" test "$RC" -eq 0
check "calibrate text: the same formatter as every table" python3 - "$T/cal.json" "$OUT" "$T" <<'PYEOF'
import json, sys
sys.path.insert(0, sys.argv[3])
import hertzdamp_text
from render import cell, short
j = json.load(open(sys.argv[1]))
t = hertzdamp_text.tables(open(sys.argv[2]).read())
summary = [x for x in t if x.rows and "damping" in x.rows[0]][0]
res = [x for x in t if x.rows and "e_fit" in x.rows[0]][0]
assert summary.units["k"] == "N m^-3/2" and summary.units["rms_residual_tc"] == "s", summary.units
assert res.units == {"velocity": "m/s", "tc": "s", "tc_fit": "s", "residual_tc": "s"}, res.units
for law in j["laws"]:
    row = [r for r in summary.rows if r["damping"] == law["damping"]][0]
    for k in ("k", "d", "k_err", "d_err"):
        v = repr(law[k])
        assert row[k] in (cell(v), short(v)), (k, row[k], v)
chosen = j["chosen"]
data = [r for r in j["residuals"] if r["damping"] == chosen]
assert len(data) == len(res.rows) == 10
for r, d in zip(res.rows, data):
    for k in ("velocity", "e", "e_fit", "tc", "tc_fit"):
        assert r[k] in (cell(repr(d[k])), short(repr(d[k]))), (k, r[k], d[k])
    assert r["residual_e"] in (cell(repr(d["e"] - d["e_fit"])), short(repr(d["e"] - d["e_fit"]))), r
PYEOF
check "calibrate text: the prose numbers in the short form (mass 5.235988e-06 kg)" \
  grep -q '^# mass 5.235988e-06 kg (two spheres)' "$OUT"
# one law: a list, with the unit of that law's d
run calibrate data/calibrate/example.csv --radius 1e-3 --density 2500 --damping tsuji
check "calibrate, one law: the summary as a list, d in kg s^-1 m^-1/4" grep -qE '^d \[kg s\^-1 m\^-1/4\] += [0-9]' "$OUT"

# scene: the sentences of the report in the short form (CSV and JSON keep 16 digits)
run scene data/scenes/binary.nml --no-compare
check "scene text: dt in the short form" grep -qx '# dt: 1e-06 s' "$OUT"
check "scene text: units in the contact table's header" grep -qE '^contact +bodies +u_in \[m/s\] +k \[N m\^-3/2\]' "$OUT"
run scene data/scenes/binary.nml --no-compare --format json
check "scene JSON: dt as before, 16 digits" grep -q '"dt": "1.000000000000000E-006 s"' "$OUT"
finish
