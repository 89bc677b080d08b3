#!/usr/bin/env bash
# The README and the guides in doc/ as written: the figures copied into them are what
# the programs print today (the series accuracy table, doc/accuracy.md), every
# `$ hertzdamp ...` command of README.md and doc/*.md prints exactly the output shown
# under it, every compile and link line (gfortran, cc, pkg-config) of README.md and
# doc/*.md builds a program against a fresh `make install` prefix that then runs from
# another directory (the static lines without libhertzdamp.so; a line written in two
# files is built once), and every relative link in README.md and doc/*.md resolves to
# a file (and, for a #fragment into a markdown file, to one of its headings).
cd "$(dirname "$0")/../.."
root=$PWD
fpm=${HERTZDAMP_FPM:-.venv/bin/fpm}
p=0; f=0
check() { local l=$1; shift; if "$@"; then p=$((p + 1)); else f=$((f + 1)); echo "FAIL readme_sync: $l"; fi; }
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT

# ------------------------------------------------------------ the series accuracy table
rows=$("$fpm" run --example series_accuracy --flag "${HERTZDAMP_RELEASE_FLAGS:-}" 2>/dev/null | grep '^|')
check "series accuracy table printed" test "$(wc -l <<<"$rows")" -eq 9
while IFS= read -r row; do
  check "README or a guide has the row: ${row:0:40}" bash -c 'cat README.md doc/*.md | grep -qxF -- "$1"' _ "$row"
done <<<"$rows"

# ------------------------------------------------------------ the README stays a README (issue 25)
# (400 until section 7, From Python, of issue 35 came: 20 lines with its figures; 420 until
# section 8, Oblique contacts, of issue 33: 16 lines with its figures)
check "README.md has at most 436 lines ($(wc -l <README.md))" test "$(wc -l <README.md)" -le 436

# ------------------------------------------------------------ README section 6: the spread figure
# The README rounds the rows of doc/host-schemes.md's table 3 (synced with the example by
# test/docs/host_schemes_sync.sh): e sd of lammps / lammps-phase, linear law, overlap end.
spread_ok() {
  python3 - "$@" <<'PY'
import re, sys
doc = open("doc/host-schemes.md", encoding="utf-8").read()
readme = open("README.md", encoding="utf-8").read()
sd = {}
for n in (10, 20):
    m = re.search(r"^\| linear \| overlap \| %d \| *([0-9.]+), *[0-9.]+; *[0-9.]+, *[0-9.]+ \| *([0-9.]+)," % n, doc, re.M)
    if not m: sys.exit(1)
    sd[n] = (float(m.group(1)), float(m.group(2)))
want = "%.1f / %.1f %% against %.2f / %.2f %%" % (sd[10][0], sd[20][0], sd[10][1], sd[20][1])
sys.exit(0 if want in readme else 1)
PY
}
check "README section 6: the spread of e is doc/host-schemes.md's table 3, rounded" spread_ok

# ------------------------------------------------------------ every `$ hertzdamp` command and its output
if [ -n "${HERTZDAMP_BIN:-}" ]; then
  python3 - "$tmp/cmds" README.md doc/*.md <<'PY'
import os, sys
out = sys.argv[1]
os.makedirs(out)
n = 0
for md in sys.argv[2:]:
  lines = open(md, encoding="utf-8").read().splitlines()
  i = 0
  while i < len(lines):
    if lines[i].startswith("    $ hertzdamp "):
        cmd = lines[i][6:]
        body = []
        i += 1
        while i < len(lines) and lines[i].startswith("    ") and not lines[i].startswith("    $ "):
            body.append(lines[i][4:])
            i += 1
        n += 1
        open(f"{out}/{n}.cmd", "w").write(cmd)
        open(f"{out}/{n}.file", "w").write(md)
        if body and body[-1] == "...":
            # an excerpt: the lines shown must appear in the output, in this order
            body.pop()
            open(f"{out}/{n}.excerpt", "w").write("")
        open(f"{out}/{n}.want", "w").write("".join(l + "\n" for l in body))
    else:
        i += 1
PY
  ncmd=$(ls "$tmp/cmds" | grep -c '\.cmd$')
  check "README and guides show at least 5 hertzdamp commands with their output ($ncmd)" test "$ncmd" -ge 5
  check "README itself shows at least 5 of them ($(grep -c '^    \$ hertzdamp ' README.md))" test "$(grep -c '^    \$ hertzdamp ' README.md)" -ge 5
  bindir=$tmp/bin; mkdir -p "$bindir"; ln -s "$(realpath "$HERTZDAMP_BIN")" "$bindir/hertzdamp"
  for c in "$tmp"/cmds/*.cmd; do
    PATH=$bindir:$PATH bash -c "$(cat "$c")" >"${c%.cmd}.got" 2>/dev/null
    if [ -e "${c%.cmd}.excerpt" ]; then
      check "$(cat "${c%.cmd}.file") command prints the lines it shows: $(head -c 90 "$c")" python3 -c '
import sys
got = open(sys.argv[1]).read().splitlines(); it = iter(got)
sys.exit(0 if all(any(g == w for g in it) for w in open(sys.argv[2]).read().splitlines()) else 1)' \
        "${c%.cmd}.got" "${c%.cmd}.want"
    else
      check "$(cat "${c%.cmd}.file") command prints what it shows: $(head -c 90 "$c")" cmp -s "${c%.cmd}.got" "${c%.cmd}.want"
    fi
  done
  # the glass-bead answer of issue 12 is among them: one invert, one forward
  check "README answers the glass-bead question with invert from material data" \
    grep -q '^    \$ hertzdamp invert --radius 1e-3 --density 2500 --youngs-modulus 63e9 --poisson-ratio 0.24 --e 0.9 --dt 1e-6 --steps 10 --velocity 0.01:5' README.md
  check "README answers the glass-bead question with forward at k = 1e9, d = 0.5, 1 m/s" \
    grep -q '^    \$ hertzdamp forward --k 1e9 --d 0.5 --radius 1e-3 .*--velocity 1$' README.md
fi

# ------------------------------------------------------------ compile and link lines, as written
prefix=$tmp/prefix
if ! make --no-print-directory install PREFIX="$prefix" >"$tmp/install.log" 2>&1; then
  tail -n 20 "$tmp/install.log"; check "make install for the compile lines" false
else
  work=$tmp/work; mkdir -p "$work" "$tmp/elsewhere"
  cp example/legacy_dem/dem.f "$work/dem.f"
  cat >"$work/prog.f90" <<'F90'
program prog
    use hertzdamp
    implicit none
    real(hertzdamp_rk) :: m, r, es, kp, k, d
    integer :: st
    call hertzdamp_pair_contact(1.0e-3_hertzdamp_rk, 2500.0_hertzdamp_rk, 63.0e9_hertzdamp_rk, 0.24_hertzdamp_rk, &
                                1.0e-3_hertzdamp_rk, 2500.0_hertzdamp_rk, 63.0e9_hertzdamp_rk, 0.24_hertzdamp_rk, &
                                m, r, es, kp, st)
    if (st /= HD_OK) error stop 1
    call hertzdamp_invert(0.9_hertzdamp_rk, 1.0e-5_hertzdamp_rk, m, 1.0_hertzdamp_rk, HD_END_OVERLAP, k, d, st, k_phys=kp)
    if (st /= HD_OK) error stop 2
    print '(a,es12.4)', 'k =', k
end program prog
F90
  cat >"$work/prog.c" <<'C'
#include <stdio.h>
#include <hertzdamp.h>
int main(void) {
    double k, d;
    int st = hertzdamp_c_invert(0.9, 1e-5, 5.236e-6, 1.0, HERTZDAMP_END_OVERLAP, &k, &d);
    if (st != HERTZDAMP_OK) { fprintf(stderr, "%s\n", hertzdamp_c_strerror(st)); return 1; }
    printf("k = %.4e\n", k);
    return 0;
}
C
  n=0
  while IFS= read -r line; do
    cmd=${line#    }
    cmd=${cmd%%#*}
    if [[ $cmd == export* ]]; then eval "$cmd"; continue; fi
    n=$((n + 1))
    rm -f "$work/a.out"
    ( cd "$work" && PREFIX=$prefix eval "$cmd" ) >"$tmp/cc.log" 2>&1
    check "compile line builds: $cmd" test -x "$work/a.out"
    if [ -x "$work/a.out" ]; then
      mv "$work/a.out" "$tmp/elsewhere/prog$n"
      ( cd / && "$tmp/elsewhere/prog$n" ) >"$tmp/run.log" 2>&1
      check "compile line's program runs from another directory: $cmd" grep -Eq '^ *(k =|contact)' "$tmp/run.log"
      if [[ $cmd == *static* || $cmd == *libhertzdamp.a* ]]; then
        check "static line links the archive (no libhertzdamp.so): $cmd" \
          bash -c "! ldd '$tmp/elsewhere/prog$n' | grep -q libhertzdamp"
      fi
    fi
  done < <(grep -hE '^    (gfortran|cc|export PKG_CONFIG_PATH)[ =]' README.md doc/*.md | awk '!seen[$0]++' | sed "s|\\\$PREFIX|$prefix|g")
  check "README and guides have compile lines for Fortran, legacy Fortran, C shared/static and pkg-config ($n)" test "$n" -ge 7
  check "README itself has compile lines for Fortran, legacy Fortran, C and pkg-config" \
    bash -c "grep -q '^    gfortran .*prog.f90' README.md && grep -q '^    gfortran dem.f' README.md && grep -q '^    cc prog.c -I' README.md && grep -q '^    cc prog.c .*pkg-config' README.md"
fi

# ------------------------------------------------------------ relative links resolve
python3 - README.md doc/*.md <<'PY' >"$tmp/links" 2>&1
import os, re, sys
def slug(h):
    h = h.strip().lower()
    h = re.sub(r"[^\w\- ]", "", h)
    return h.replace(" ", "-")
def anchors(path):
    try:
        text = open(path, encoding="utf-8").read()
    except OSError:
        return set()
    return {slug(m.group(1)) for m in re.finditer(r"^#+ +(.*)$", text, re.M)}
bad = 0; n = 0
for md in sys.argv[1:]:
    text = open(md, encoding="utf-8").read()
    for m in re.finditer(r"\]\(([^)\s]+)\)", text):
        target = m.group(1)
        if re.match(r"^[a-z]+:", target) or target.startswith("#") and False:
            continue
        n += 1
        path, _, frag = target.partition("#")
        full = os.path.normpath(os.path.join(os.path.dirname(md), path)) if path else md
        if not os.path.exists(full):
            print(f"{md}: {target}: no such file"); bad += 1
        elif frag and full.endswith(".md") and frag not in anchors(full):
            print(f"{md}: {target}: no such heading"); bad += 1
print(f"links: {n} checked, {bad} broken")
sys.exit(1 if bad or n == 0 else 0)
PY
rc=$?
grep -v '^links:' "$tmp/links" | head -n 20
check "relative links of README.md and doc/*.md resolve ($(tail -n 1 "$tmp/links"))" test "$rc" -eq 0
echo "readme_sync: $p passed, $f failed"
[ "$f" -eq 0 ]
