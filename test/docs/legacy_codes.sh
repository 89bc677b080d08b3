#!/usr/bin/env bash
# The table of legacy argument codes in README.md (IEND, ILAW; a marked place for
# IHOST) agrees with include/hertzdamp.h (the C macros) and src/hertzdamp_status.f90
# (the module's HD_END_*, HD_DAMPING_*): every code the header defines has its row,
# with the same value, and no row names a code the header does not have.
cd "$(dirname "$0")/../.."
p=0; f=0
out=$(mktemp); trap 'rm -f "$out"' EXIT
python3 - <<'PY' >"$out" 2>&1
import re
readme = open("README.md", encoding="utf-8").read()
block = readme.split("<!-- BEGIN legacy codes -->")[1].split("<!-- END legacy codes -->")[0]
rows = [l for l in block.splitlines() if l.startswith("| `")]
table = {}
for r in rows:
    arg, code, meaning, macro = [c.strip() for c in r.strip("|").split("|")]
    table[macro.strip("`")] = (arg.strip("`"), int(code))
header = open("include/hertzdamp.h").read()
macros = dict((m, int(v)) for m, v in re.findall(r"#define (HERTZDAMP_(?:END|DAMPING)_[A-Z_]+) +(\d+)", header))
status = open("src/hertzdamp_status.f90").read()
fortran = dict((m, int(v)) for m, v in re.findall(r"::\s*HD_((?:END|DAMPING)_[A-Z_]+)\s*=\s*(\d+)", status))
def say(ok, label): print(("ok " if ok else "FAIL ") + label)
say(len(macros) == 5, "hertzdamp.h defines 2 end and 3 law codes (%d)" % len(macros))
for m, v in macros.items():
    say(m in table, "README has a row for %s" % m)
    say(m in table and table[m][1] == v, "README's code of %s is hertzdamp.h's (%d)" % (m, v))
    say(m in table and table[m][0] == ("IEND" if "_END_" in m else "ILAW"), "%s is an %s code" % (m, "IEND" if "_END_" in m else "ILAW"))
    say(fortran.get(m[len("HERTZDAMP_"):]) == v, "HD_%s = %d in the module" % (m[len("HERTZDAMP_"):], v))
for m in table:
    say(m in macros, "README's row %s is a macro of hertzdamp.h" % m)
say("<!-- IHOST:" in block, "the marked place for the IHOST codes")
PY
while IFS= read -r line; do
  case "$line" in
    "ok "*) p=$((p + 1)) ;;
    "FAIL "*) f=$((f + 1)); echo "FAIL legacy_codes: ${line#FAIL }" ;;
    *) f=$((f + 1)); echo "FAIL legacy_codes: $line" ;;
  esac
done <"$out"
echo "legacy_codes: $p passed, $f failed"
[ "$f" -eq 0 ]
