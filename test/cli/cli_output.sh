#!/usr/bin/env bash
# The output contract: text, CSV and JSON in linear time (10,000 rows, the list limit;
# text timed as a ratio to CSV in the same run, never an absolute time), aligned text,
# valid UTF-8 everywhere (a Latin-1 scene title in JSON, CSV and text; invalid bytes in
# an argument), one-line error messages (a newline in an argument), progress only on
# request or on a terminal.
SUITE=cli_output
source "$(dirname "$0")/cli_common.bash"
cd "$(dirname "$0")/../.."
T=$(mktemp -d); trap 'rm -rf "$T" "$OUT" "$ERR"' EXIT

# ---------------------------------------------------------------- linear time
# median of 3 wall times of each format, interleaved; the work (fit at 10,000 alpha)
# is the same, so text and JSON must cost about what CSV costs (quadratic column
# widths made text 1000x slower at 2,000 rows); a run over 60 s counts as failed
elapsed() {  # format -> seconds (or 999 on timeout/failure)
  local t0 t1
  t0=$(date +%s.%N)
  timeout 60 "$BIN" table --method fit --alpha 0:1.1:10000 --format "$1" >"$T/out.$1" 2>/dev/null || { echo 999; return; }
  t1=$(date +%s.%N)
  python3 -c "import sys; print(float(sys.argv[2]) - float(sys.argv[1]))" "$t0" "$t1"
}
declare -A times
for rep in 1 2 3; do
  for f in csv text json; do times[$f]="${times[$f]:-} $(elapsed $f)"; done
done
med() { python3 -c 'import sys, statistics; print(statistics.median(map(float, sys.argv[1:])))' $1; }
tc=$(med "${times[csv]}"); tt=$(med "${times[text]}"); tj=$(med "${times[json]}")
echo "cli_output: 10,000 rows: csv ${tc}s, text ${tt}s, json ${tj}s (medians of 3)"
check "10,000 rows: text within 4x of CSV (${tt}s vs ${tc}s)" python3 -c "import sys; sys.exit(0 if $tt <= 4 * $tc + 0.05 else 1)"
check "10,000 rows: JSON within 4x of CSV (${tj}s vs ${tc}s)" python3 -c "import sys; sys.exit(0 if $tj <= 4 * $tc + 0.05 else 1)"
check "10,000 rows: CSV has every row" test "$(wc -l <"$T/out.csv")" -eq 10001
check "10,000 rows: JSON parses with every row" python3 -c 'import json, sys; assert len(json.load(open(sys.argv[1]))["rows"]) == 10000' "$T/out.json"
check "10,000 rows: text aligned (every line as long as the header)" python3 -c '
import sys
lines = [l for l in open(sys.argv[1]).read().splitlines() if not l.startswith("#")]
assert len(lines) == 10001 and len(set(len(l) for l in lines)) == 1' "$T/out.text"
run invert --e 0.9,0.0005 --tc 1e-5 --mass 1e-3 --velocity 1
check "text with empty results stays aligned" python3 -c '
import sys
lines = [l for l in open(sys.argv[1]).read().splitlines() if not l.startswith("#")]
assert len(set(len(l) for l in lines)) == 1 and lines[2].split()[-1] == "outside-validity" and " - " in lines[2]' "$OUT"

# ---------------------------------------------------------------- UTF-8
utf8() { python3 -c 'import sys; open(sys.argv[1], "rb").read().decode("utf-8")' "$1"; }
printf "&scene title = 'caf\xe9 \"quoted\", tab\there', dt = 1e-5, steps_per_contact = 10, end_time = 2e-3,\n" >"$T/latin1.nml"
printf "  gravity = .false., contact_end = 'overlap', report = 'restitution duration' /\n" >>"$T/latin1.nml"
printf "&material name = 'steel', density = 7800, youngs_modulus = 2.1e11, poisson_ratio = 0.3, restitution = 0.8 /\n" >>"$T/latin1.nml"
printf "&particle material = 'steel', radius = 1e-3, position = 0, 0, 0, velocity = 1, 0, 0 /\n" >>"$T/latin1.nml"
printf "&particle material = 'steel', radius = 1e-3, position = 2.5e-3, 0, 0, velocity = -1, 0, 0 /\n" >>"$T/latin1.nml"
for f in json csv text; do
  run scene "$T/latin1.nml" --format $f
  check "Latin-1 scene title, $f: exit 0 (got $RC: $(head -c 200 "$ERR"))" test "$RC" -eq 0
  check "Latin-1 scene title, $f: valid UTF-8" utf8 "$OUT"
done
run scene "$T/latin1.nml" --format json
check "Latin-1 title in JSON: parses, the byte replaced by U+FFFD" python3 -c '
import json, sys
d = json.loads(open(sys.argv[1], "rb").read().decode("utf-8"))
def strings(x):
    if isinstance(x, dict): x = list(x.values())
    if isinstance(x, list): return [s for y in x for s in strings(y)]
    return [x] if isinstance(x, str) else []
assert "caf\ufffd \"quoted\", tab\there" in strings(d), strings(d)[:3]' "$OUT"
run table --alpha "$(printf '0.5\xe9')"
check "invalid byte in an argument: exit 2, stderr valid UTF-8" test "$RC" -eq 2
check "invalid byte in an argument: escaped as \\xe9" grep -qF '0.5\xe9' "$ERR"
check "invalid byte in an argument: stderr is UTF-8" utf8 "$ERR"
run table --alpha "$(printf '\xc3\xa9')"
check "valid UTF-8 in an argument is kept as is" grep -q 'é' "$ERR"

# ---------------------------------------------------------------- one-line errors
for args in "table --alpha" "invert --e" "forward --k" "scene" "table --format"; do
  run $args "$(printf '1\n2')"
  check "newline in an argument ($args): one line on stderr" test "$RC" -eq 2 -a "$(wc -l <"$ERR")" -eq 1
done
run "$(printf 'ta\nble')"
check "newline in the command name: one line, escaped" test "$(wc -l <"$ERR")" -eq 1 -a -n "$(grep -F 'ta\nble' "$ERR")"
run table --alpha "$(printf '1\r\t\0332')"
check "control characters escaped" grep -qF '1\r\t\x1b2' "$ERR"

# ---------------------------------------------------------------- numbers read back
# Every CSV and JSON number reads back as the same double (Python's float is correctly
# rounded): 3000 random bit patterns over the whole range (subnormals, huge(1.0)) and
# 1000 decimals of 1 to 15 significant digits, which must show their own digits
# (0.78719 as 7.871900000000000E-001), echoed as the k column of forward (the inputs
# of every row are printed); a few negative --d values (bad-input rows keep them).
python3 - "$T" <<'PY'
import random, struct, sys
rnd = random.Random(20240607)
xs = []
while len(xs) < 3000:
    x = struct.unpack("<d", struct.pack("<Q", rnd.getrandbits(63)))[0]
    if x > 0 and x != float("inf") and x == x:
        xs.append(x)
xs[:6] = [1.7976931348623157e308, 2.2250738585072014e-308, 5e-324, 1.0, 0.1, 9007199254740993.0]
ds = []
for _ in range(1000):
    n = rnd.randint(1, 15)
    ds.append(f"{rnd.randint(10**(n - 1), 10**n - 1)}e{rnd.randint(-300, 290)}")
open(sys.argv[1] + "/rand.txt", "w").write(",".join(repr(x) for x in xs[:1500]))
open(sys.argv[1] + "/rand2.txt", "w").write(",".join(repr(x) for x in xs[1500:]))
open(sys.argv[1] + "/dec.txt", "w").write(",".join(ds))
PY
cat >"$T/readback.py" <<'PY'
import csv, json, re, sys
fmt, path, given = sys.argv[1], sys.argv[2], open(sys.argv[3]).read().split(",")
short = sys.argv[3].endswith("dec.txt")
if fmt == "csv":
    rows = list(csv.DictReader(open(path)))
    got = [r["k"] for r in rows]
else:
    got = [r["k"] for r in json.load(open(path), parse_float=str)["rows"]]
assert len(got) == len(given), (len(got), len(given))
bad = 0
for g, w in zip(got, given):
    s = g
    if float(s) != float(w) or not re.fullmatch(r"\d\.\d{15,16}E[-+]\d{3}", s):
        bad += 1; print("   ", w, "->", s)
    elif short:  # a decimal of at most 15 digits: its digits, then zeros
        digits = w.split("e")[0]
        m = s.split("E")[0].replace(".", "")
        if m.rstrip("0") != digits.rstrip("0") or len(m) != 16:
            bad += 1; print("   ", w, "->", s, "(not its own digits)")
sys.exit(1 if bad else 0)
PY
for f in rand rand2 dec; do
  for fmt in csv json; do
    run forward --k "$(cat "$T/$f.txt")" --d 0 --velocity 1 --mass 1 --method compact --format $fmt
    cp "$OUT" "$T/rb.$fmt"
    check "numbers read back ($f, $fmt): every k as given" python3 "$T/readback.py" $fmt "$T/rb.$fmt" "$T/$f.txt"
  done
done
run forward --k 1e9 --d -1.7976931348623157e308,-5e-324,-0.78719,0.5 --velocity 1 --mass 1 --format csv
check "negative numbers read back (bad-input rows keep their inputs)" python3 -c '
import csv, sys
d = [r["d"] for r in csv.DictReader(open(sys.argv[1]))]
assert d == ["-1.7976931348623157E+308", "-4.940656458412465E-324", "-7.871900000000000E-001",
             "5.000000000000000E-001"], d' "$OUT"

# ---------------------------------------------------------------- progress
run table --alpha 0.1:1:20
check "no progress when stderr is not a terminal" test ! -s "$ERR"
run table --alpha 0.1:1:20 --progress --format csv
check "--progress: exit 0, stdout untouched" test "$RC" -eq 0 -a "$(wc -l <"$OUT")" -eq 21
check "--progress: percentage and time left on stderr" grep -Eq '^hertzdamp: table: +[0-9.]+ % done, about [0-9]+ s left$' "$ERR"
# --progress into a file, and the command fails: the progress lines asked for stay, the
# error is the one other line and the last (a failing row: exit 3 with the table; no
# row with a result: exit 2, stdout empty)
prog_then_error() {  # the last line of stderr is an error, every other one a progress line
  python3 -c '
import re, sys
lines = open(sys.argv[1]).read().splitlines()
prog = re.compile(r"hertzdamp: [a-z0-9 ()-]+: ( *[0-9.]+ % done, about .* left|starting)$")
sys.exit(0 if lines and not prog.match(lines[-1]) and all(prog.match(l) for l in lines[:-1]) else 1)' "$ERR"
}
run invert --e 0.5,2 --tc 1e-5 --mass 1 --velocity 1 --progress --format csv
check "--progress, a failing row: exit 3 with the table" test "$RC" -eq 3 -a "$(wc -l <"$OUT")" -eq 3
check "--progress, a failing row: progress lines, then the error as the last line" prog_then_error
check "--progress, a failing row: the error names the row" grep -q '^hertzdamp: 1 of 2 rows have no result.*--e 2' "$ERR"
run invert --e 2 --tc 1e-5 --mass 1 --velocity 1 --progress
check "--progress, no result: exit 2, stdout empty" test "$RC" -eq 2 -a ! -s "$OUT"
check "--progress, no result: progress lines, then the error as the last line" prog_then_error
# --progress with stderr a pipe nobody reads (issue 21): the progress writes fail
# silently, the results still reach stdout with the command's own exit code (before:
# killed by SIGPIPE, exit 141, nothing on stdout)
broken_stderr() {  # stdout file, command...: stderr a pipe whose read end is closed
  "$PYTHON" -c '
import os, subprocess, sys
r, w = os.pipe(); os.close(r)
with open(sys.argv[1], "w") as out:
    sys.exit(subprocess.run(sys.argv[2:], stdout=out, stderr=w).returncode % 256)' "$@"
}
run invert --e 0.5 --tc 1e-5 --mass 1e-3 --velocity 1:2:4 --format csv
cp "$OUT" "$T/plain.csv"
broken_stderr "$T/bp.csv" "$BIN" invert --e 0.5 --tc 1e-5 --mass 1e-3 --velocity 1:2:4 --progress --format csv
check "invert --progress, stderr a closed pipe: exit 0 (got $?)" test "$?" -eq 0
check "invert --progress, stderr a closed pipe: the results on stdout" cmp -s "$T/bp.csv" "$T/plain.csv"
broken_stderr "$T/bp3.csv" "$BIN" invert --e 0.5,2 --tc 1e-5 --mass 1e-3 --velocity 1 --progress --format csv
check "invert --progress, stderr a closed pipe, a failing row: exit 3 (got $?)" test "$?" -eq 3
check "... and the table" test "$(wc -l <"$T/bp3.csv")" -eq 3
broken_stderr "$T/bps.csv" "$BIN" scene data/scenes/drop.nml --progress --format csv
check "scene --progress, stderr a closed pipe: exit 0 (got $?)" test "$?" -eq 0
run scene data/scenes/drop.nml --format csv
check "scene --progress, stderr a closed pipe: the whole report on stdout" \
  test "$(wc -l <"$T/bps.csv")" -eq "$(wc -l <"$OUT")" -a "$(head -n 3 "$T/bps.csv")" = "$(head -n 3 "$OUT")"

if command -v script >/dev/null 2>&1; then
  # on a terminal (script(1) gives one), progress appears without --progress once the
  # work takes longer than 2 s, on one line rewritten in place and erased at the end;
  # the run has one bad row (exit 3): what the terminal shows on stderr is then the
  # error line alone (carriage returns and erase-line applied as a terminal does)
  script -qec "$BIN invert --method iterative --tol 1e-15 --e 0.01:1:5000,1.5 --tc 1e-5 --mass 1 --velocity 1 --format csv >$T/tty.csv" \
    "$T/tty.log" >/dev/null 2>&1
  if [ "$(wc -l <"$T/tty.csv")" -eq 5002 ] && grep -q '% done' "$T/tty.log"; then
    check "terminal: progress line rewritten with carriage returns" grep -q $'\r' "$T/tty.log"
    check "terminal, a failing row: the screen shows one line on stderr, the error" python3 -c '
import re, sys
text = open(sys.argv[1], encoding="utf-8", errors="replace", newline="").read()
text = "\n".join(l for l in text.split("\n") if not l.startswith("Script "))
screen = []
for raw in text.replace("\r\n", "\n").split("\n"):
    line = []
    col = 0
    for tok in re.findall(r"\x1b\[K|\r|[^\r\x1b]", raw):
        if tok == "\r":
            col = 0
        elif tok == "\x1b[K":
            del line[col:]
        else:
            line[col:col + 1] = [tok]
            col += 1
    screen.append("".join(line))
shown = [l for l in screen if l.strip()]
sys.exit(0 if len(shown) == 1 and shown[0].startswith("hertzdamp: 1 of 5001 rows have no result") else 1)' "$T/tty.log"
  else
    echo "SKIPPED $SUITE: the iterative run took under 2 s here, no terminal progress to see"
  fi
fi
finish
