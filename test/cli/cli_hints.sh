#!/usr/bin/env bash
# Help for a new user (issue 25 items 4 and 5): plausibility warnings for magnitudes
# outside what granular materials have (the option, the range, the likely unit slip;
# the results printed all the same, exit unchanged; --quiet silences them), "did you
# mean" for unknown options, commands and choices, and the range syntax named when a
# list item is a range written otherwise.
SUITE=cli_hints
source "$(dirname "$0")/cli_common.bash"
cd "$(dirname "$0")/../.."
T=$(mktemp -d); trap 'rm -rf "$T" "$OUT" "$ERR"' EXIT
GLASS="--radius 1e-3 --density 2500 --youngs-modulus 63e9 --poisson-ratio 0.24"

# ---------------------------------------------------------------- plausible input: silence
for cmd in "invert $GLASS --e 0.9 --dt 1e-6 --steps 10 --velocity 0.01:5:log5" \
           "forward --k 1e9 --d 0.5 $GLASS --velocity 1" \
           "timestep $GLASS --e 0.9 --velocity 0.01:1e3:log5" \
           "check lammps hertz/material 63e9 0.5 0.24 damping tsuji --radius 1e-3 --density 2500 --velocity 1" \
           "calibrate data/calibrate/example.csv --radius 1e-3 --density 2500"; do
  run $cmd
  check "plausible: exit 0, stderr empty: ${cmd:0:60}" test "$RC" -eq 0 -a ! -s "$ERR"
done
# the ends of the ranges are plausible: E 1e5 and 1e13 Pa, R 1e-7 m, rho 10 and 3e4, u 1e3 m/s
for ends in "--radius 1e-7 --density 10 --youngs-modulus 1e5" "--radius 0.999 --density 3e4 --youngs-modulus 1e13"; do
  run forward --d 0.5 $ends --poisson-ratio 0.3 --velocity 1e-3,1e3
  check "range ends are plausible ($ends): no warning" test "$RC" -eq 0 -a ! -s "$ERR"
done

# ---------------------------------------------------------------- one warning per slip
# warn LABEL PATTERN... -- ARGS: exit 0, stdout as with --quiet, one stderr line per
# pattern, in order, each naming the --quiet hint
warn() {
  local label=$1; shift
  local pats=()
  while [ "$1" != "--" ]; do pats+=("$1"); shift; done; shift
  "$BIN" "$@" --quiet >"$T/quiet.out" 2>"$T/quiet.err"
  local qrc=$?
  run "$@"
  check "$label: exit as with --quiet ($RC)" test "$RC" -eq "$qrc"
  check "$label: the results printed, the same as with --quiet" cmp -s "$OUT" "$T/quiet.out"
  check "$label: --quiet: no warning" bash -c "! grep -q 'warning' '$T/quiet.err'"
  check "$label: ${#pats[@]} warning line(s)" test "$(grep -c '^hertzdamp: warning: .* (--quiet silences this)$' "$ERR")" -eq "${#pats[@]}"
  local i=1
  for p in "${pats[@]}"; do
    check "$label: warning $i: $p" bash -c "sed -n ${i}p '$ERR' | grep -qF -- \"\$1\"" _ "$p"
    i=$((i + 1))
  done
}
warn "E in GPa" "--youngs-modulus 63: below 1e5 Pa, softer than granular materials (rubber: 1e6 Pa); it looks like GPa: did you mean 63e9?" -- \
  invert --radius 1e-3 --density 2500 --youngs-modulus 63 --poisson-ratio 0.24 --e 0.9 --dt 1e-6 --steps 10 --velocity 1
check "E in GPa: the warning is one line" test "$(wc -l <"$ERR")" -eq 1
warn "radius in mm" "--radius 1: at or above 1 m, a particle 2 m or more across; it looks like mm: did you mean 1e-3?" -- \
  forward --k 1e9 --d 0.5 --radius 1 --density 2500 --velocity 1
warn "density in g/cm^3, body 2" "--density2 2.5: below 10 kg/m^3, lighter than granular materials (aerogel: 10 kg/m^3); it looks like g/cm^3: did you mean 2.5e3?" -- \
  timestep $GLASS --radius2 2e-3 --density2 2.5 --e 0.9 --velocity 1
warn "speed in mm/s" "--velocity 5000: above 1e3 m/s, faster than granular impacts; it looks like mm/s: did you mean 5?" -- \
  invert --e 0.9 --tc 1e-5 $GLASS --velocity 100:5000:3
warn "E above diamond, no unit guess" "--youngs-modulus2 2e14: above 1e13 Pa, stiffer than any solid (diamond: 1.2e12 Pa) (--quiet" -- \
  forward --d 0.5 $GLASS --youngs-modulus2 2e14 --poisson-ratio2 0.3 --wall --velocity 1
warn "two slips, in the order of the options' table" "--youngs-modulus 210" "--radius 5" -- \
  forward --d 0.5 --radius 5 --density 7800 --youngs-modulus 210 --poisson-ratio 0.3 --velocity 1
warn "check" "--radius 2: at or above 1 m" "--velocity 3000: above 1e3 m/s" -- \
  check lammps "hertz/material 63e9 0.5 0.24 damping tsuji" --radius 2 --density 2500 --velocity 1,3000
printf 'velocity,e\n200,0.8\n3000,0.85\n' >"$T/mm.csv"
warn "calibrate: options and the data file's speeds" "--density 7.8: below 10" "$T/mm.csv: velocity 3000: above 1e3 m/s" -- \
  calibrate "$T/mm.csv" --radius 1e-3 --density 7.8
# a warning, then the error: the error is the last line
run invert --e 0.9 --tc -1 --radius 1e-3 --density 2500 --youngs-modulus 63 --poisson-ratio 0.24 --velocity 1
check "warning and error: the warning first, the error last, exit 2" \
  test "$RC" -eq 2 -a "$(wc -l <"$ERR")" -eq 2 -a -n "$(head -n 1 "$ERR" | grep 'warning: --youngs')" -a -n "$(tail -n 1 "$ERR" | grep -- '--tc')"

# ---------------------------------------------------------------- did you mean
hint() {  # label, expected suffix of the message, args
  local label=$1 want=$2; shift 2
  expect_fail 2 "$label" "$@"
  check "$label: '$want'" grep -qF -- "$want" "$ERR"
}
hint "--youngs" "unknown option --youngs; did you mean --youngs-modulus? (see --help)" invert --youngs 63e9
hint "a typo" "unknown option --veloctiy; did you mean --velocity?" forward --veloctiy 1
hint "a swap of neighbours" "unknown option --raidus; did you mean --radius?" timestep --raidus 1e-3
hint "--quik" "did you mean --quick?" bench --quik
hint "a command" 'unknown command "inverse"; did you mean invert?' inverse --e 0.9
hint "a command's start" 'unknown command "calib"; did you mean calibrate?' calib
hint "a choice" 'choose one of linear tsuji kuwabara-kono; did you mean tsuji?' table --damping tsjui
hint "a format" 'choose one of text csv json; did you mean json?' constants --format jsno
hint "ties are all named" "did you mean --radius or --radius2?" forward --radius3 1
expect_fail 2 "nothing close: no guess" table --frob 1
check "nothing close: no guess" bash -c "! grep -q 'did you mean' '$ERR'"
expect_fail 2 "a two-letter stem: no guess" invert --kk 1
check "a two-letter stem: no guess" bash -c "! grep -q 'did you mean' '$ERR'"

# ---------------------------------------------------------------- the range syntax
hint "0.05-3" 'malformed number "0.05-3" for --velocity: a range is A0:A1:N (N values from A0 to A1) or A0:A1:logN, e.g. 0.05:3:20' \
  invert --e 0.9 --tc 1e-5 --mass 1e-3 --velocity 0.05-3
hint "0.1..1" 'e.g. 0.1:1:20' forward --k 1e9 --d 0.1..1 --mass 1e-3 --velocity 1
hint "1e-3-2" 'e.g. 1e-3:2:20' table --alpha 1e-3-2
run invert --e 0.9 --tc 1e-5 --mass 1e-3 --velocity 1e-3,2e-3 --format csv
check "an exponent's minus is no range" test "$RC" -eq 0
finish
