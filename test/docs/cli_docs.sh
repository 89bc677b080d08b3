#!/usr/bin/env bash
# Documentation that ships with the program: one version everywhere (fpm.toml, which
# CMakeLists.txt reads (test/integration/install_consumers.sh checks the installed one), CITATION.cff, the man page, `hertzdamp --version`); the man page
# names every command and option that the help texts name, and renders without
# warnings; the license is MIT in LICENSE and fpm.toml; CITATION.cff is valid YAML
# with the fields the format requires; doc/theory.md holds the sections the sources
# cite and no file points to the internal THEORY.md any more.
SUITE=cli_docs
source "$(dirname "$0")/../cli/cli_common.bash"
cd "$(dirname "$0")/../.."

v_fpm=$(sed -nE 's/^version *= *"([^"]+)".*/\1/p' fpm.toml)
v_cff=$(sed -nE 's/^version: *"?([0-9.]+)"?.*/\1/p' CITATION.cff)
v_man=$(sed -nE 's/^\.TH HERTZDAMP 1 "[^"]*" "hertzdamp ([0-9.]+)".*/\1/p' doc/hertzdamp.1)
run --version
v_bin=$(sed -nE 's/^hertzdamp ([0-9.]+)$/\1/p' "$OUT")
check "--version exits 0 and prints one line" test "$RC" -eq 0 -a "$(wc -l <"$OUT")" -eq 1
check "fpm.toml has a version ($v_fpm)" test -n "$v_fpm"
for pair in "CITATION.cff:$v_cff" "man page:$v_man" "hertzdamp --version:$v_bin"; do
  check "version of ${pair%%:*} (${pair#*:}) = fpm.toml ($v_fpm)" test "${pair#*:}" = "$v_fpm"
done

# every command and option of the help texts is in the man page
man_text=$(sed 's/\\-/-/g; s/\\f[BIRP]//g' doc/hertzdamp.1)
cmds=$("$BIN" --help | sed -n '/^Commands:/,/^$/p' | awk 'NF > 1 && $1 != "Commands:" {print $1}')
check "the top help lists commands ($(echo $cmds))" test "$(wc -w <<<"$cmds")" -ge 7
for c in $cmds; do
  check "man page has the command $c" grep -qE "^\.(TP|B)? *$c\$|^\.B $c\$|^\.B hertzdamp $c" <<<"$man_text"
done
opts=$(for c in "" $cmds; do "$BIN" $c --help; done | grep -oE -- '--[a-z0-9][a-z0-9-]*' | sort -u)
check "help texts name options ($(wc -w <<<"$opts"))" test "$(wc -w <<<"$opts")" -ge 30
for o in $opts; do
  check "man page has the option $o" grep -qE -- "(^|[^a-z0-9-])$o([^a-z0-9-]|\$)" <<<"$man_text"
done
for c in $cmds; do
  run $c --help
  check "$c --help exits 0, stderr empty" test "$RC" -eq 0 -a ! -s "$ERR"
done
check "man page renders without warnings" bash -c "[ -z \"\$(groff -man -Tutf8 -ww -z doc/hertzdamp.1 2>&1)\" ]"

# license and citation
check "LICENSE is the MIT license" grep -q '^MIT License$' LICENSE
check "fpm.toml says MIT" grep -q '^license = "MIT"' fpm.toml
check "CITATION.cff: valid YAML with the required fields" "$PYTHON" -c '
import sys, yaml
c = yaml.safe_load(open("CITATION.cff", encoding="utf-8"))
assert c["cff-version"].startswith("1.2") and c["message"] and c["title"] and c["authors"]
assert c["license"] == "MIT"
titles = [r["title"] for r in c["references"]]
assert any("non-linear viscoelastic" in t for t in titles) and any("interface-resolved" in t for t in titles)'

# the theory note: the sections the sources cite, in the repository
for s in "1. The model" "2. One parameter" "3. When does the contact end" "4. Exact values" \
         "5. Why the problem is numerically delicate" "6. The inverse rule and the physical bound" "8. References"; do
  check "doc/theory.md has section '$s'" grep -q "^## $s" doc/theory.md
done
check "doc/theory.md cites Ray, Kempe & Froehlich (2015) and Kempe & Froehlich (2012)" \
  bash -c "grep -q 'Ray, T. Kempe and J. Fröhlich' doc/theory.md && grep -q 'Kempe and J. Fröhlich, \*Collision' doc/theory.md"
left=$(git grep -n 'THEORY\.md\|\.\./shared/' -- ':!test/docs/cli_docs.sh' 2>/dev/null)
check "no file points to THEORY.md or ../shared any more${left:+: $(head -c 200 <<<"$left")}" test -z "$left"
# the layout of issue 22: the old directories are gone and no file names a path in them
# (tools/calibrate_example.py stays in tools/; integrations/lammps/tools/ is the plugin's)
for d in cli apps peers; do check "no directory $d/ any more" test ! -e "$d"; done
left=$(git grep -nE '(^|[^a-z/_.-])(cli|apps)/[a-zA-Z_*]|peers/gsl|(^|[^/])tools/[a-z_]+_to_f90\.py|tools/compact_table|(^|[^a-z])test/[a-z_]+\.(f90|py|bash|in)|(^|[^a-z])test/[a-z_]+\.sh' \
       -- ':!test/docs/cli_docs.sh' 2>/dev/null | grep -v 'test/run_tests\.sh')
check "no file names a path of the old layout${left:+: $(head -c 300 <<<"$left")}" test -z "$left"
finish
