#!/usr/bin/env bash
# The table of legacy argument codes in doc/library.md (IEND, ILAW, IHOST) agrees with
# include/hertzdamp.h (the C macros) and the modules that define them
# (src/hertzdamp_ends.f90 HD_END_*, src/hertzdamp_laws.f90 HD_DAMPING_*,
# src/hertzdamp_host.f90 HD_HOST_*): every code the header defines has its row, with
# the same value, and no row names a code the header does not have.
cd "$(dirname "$0")/../.."
p=0; f=0
out=$(mktemp); trap 'rm -f "$out"' EXIT
python3 - <<'PY' >"$out" 2>&1
import re
readme = open("doc/library.md", encoding="utf-8").read()
block = readme.split("<!-- BEGIN legacy codes -->")[1].split("<!-- END legacy codes -->")[0]
rows = [l for l in block.splitlines() if l.startswith("| `")]
table = {}
for r in rows:
    arg, code, meaning, macro = [c.strip() for c in r.strip("|").split("|")]
    table[macro.strip("`")] = (arg.strip("`"), int(code))
header = open("include/hertzdamp.h").read()
status = open("src/hertzdamp_status.f90").read()
status_codes = set(re.findall(r"::\s*HD_([A-Z0-9_]+)\s*=", status))
# the argument codes: the END, DAMPING and HOST macros that are not status codes
# (HERTZDAMP_HOST_UNREACHABLE is one)
macros = dict((m, int(v)) for m, v in re.findall(r"#define (HERTZDAMP_(?:END|DAMPING|HOST)_[A-Z0-9_]+) +(\d+)", header)
              if m[len("HERTZDAMP_"):] not in status_codes)
code = "".join(open(f).read() for f in ("src/hertzdamp_ends.f90", "src/hertzdamp_laws.f90", "src/hertzdamp_host.f90"))
fortran = dict((m, int(v)) for m, v in re.findall(r"::\s*HD_((?:END|DAMPING|HOST)_[A-Z0-9_]+)\s*=\s*(\d+)", code))
arg = lambda m: "IEND" if "_END_" in m else "ILAW" if "_DAMPING_" in m else "IHOST"
def say(ok, label): print(("ok " if ok else "FAIL ") + label)
say(len(macros) == 11, "hertzdamp.h defines 2 end, 3 law and 6 host codes (%d)" % len(macros))
for m, v in macros.items():
    say(m in table, "doc/library.md has a row for %s" % m)
    say(m in table and table[m][1] == v, "doc/library.md: the code of %s is hertzdamp.h's (%d)" % (m, v))
    say(m in table and table[m][0] == arg(m), "%s is an %s code" % (m, arg(m)))
    say(fortran.get(m[len("HERTZDAMP_"):]) == v, "HD_%s = %d in the module" % (m[len("HERTZDAMP_"):], v))
for m in table:
    say(m in macros, "doc/library.md: the row %s is a macro of hertzdamp.h" % m)
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
