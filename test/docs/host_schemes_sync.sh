#!/usr/bin/env bash
# doc/host-schemes.md holds the tables that `fpm run --example host_schemes` prints
# (figures computed by the library, never typed): the table of the example's section K
# ("## K. ..." in its output) between the markers <!-- BEGIN host_schemes example K -->
# and <!-- END host_schemes example K -->.  Every marked block must equal the table
# lines (those starting with "|") of its section line for line, every section but the
# timings (5) must be marked, and no marker may be unbalanced, as laws_doc_sync.sh
# does for doc/damping-laws.md.
cd "$(dirname "$0")/../.."
fpm=${HERTZDAMP_FPM:-.venv/bin/fpm}
p=0; f=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
ok() { p=$((p + 1)); }
bad() { f=$((f + 1)); echo "FAIL host_schemes_sync: $*"; }
"$fpm" run --example host_schemes --flag "${HERTZDAMP_RELEASE_FLAGS:-}" >"$tmp/out" 2>/dev/null
# the example's sections: section K's table lines into $tmp/ex.K
awk -v dir="$tmp" '/^## [0-9]+\. / { k = $2; sub(/\./, "", k); next }
                   /^\|/ && k != "" { print > (dir "/ex." k) }' "$tmp/out"
sections=$(cd "$tmp" && ls ex.* 2>/dev/null | sed 's/^ex\.//' | sort -n | tr '\n' ' ')
if [ "$(wc -w <<<"$sections")" -ge 6 ]; then ok; else bad "the example printed the tables of ${sections:-no} sections (6 expected)"; fi
# the doc's marked blocks: block K into $tmp/doc.K; unbalanced, nested or repeated markers fail
if awk -v dir="$tmp" '/^<!-- BEGIN host_schemes example [0-9]+ -->$/ { if (k != "") exit 1; k = $5; if (seen[k]++) exit 1
                                                                   printf "" > (dir "/doc." k); next }
        /^<!-- END host_schemes example [0-9]+ -->$/ { if (k != $5) exit 1; k = ""; next }
        k != "" { print > (dir "/doc." k) }
        END { if (k != "") exit 1 }' doc/host-schemes.md; then ok; else
  bad "unbalanced, nested or repeated host_schemes example markers in doc/host-schemes.md"
fi
for k in $sections; do
  if [ "$k" = 5 ]; then   # timings: stated in the doc, not compared
    if [ -f "$tmp/doc.5" ]; then bad "section 5 (timings) is marked in the doc"; else ok; fi
    continue
  fi
  if [ ! -f "$tmp/doc.$k" ]; then bad "doc/host-schemes.md does not mark the table of section $k"; continue; fi
  if cmp -s "$tmp/doc.$k" "$tmp/ex.$k"; then ok; else
    bad "the marked table $k of doc/host-schemes.md differs from the example's:"
    diff "$tmp/doc.$k" "$tmp/ex.$k" | head -n 20
  fi
done
for d in "$tmp"/doc.*; do
  [ -f "$d" ] || continue
  k=${d##*.}
  if [ -f "$tmp/ex.$k" ]; then ok; else bad "doc/host-schemes.md marks a table $k the example does not print"; fi
done
# section 6.3's first table (issue 32) is what `fpm run --example phase_figures` prints
# between its markers (the second, a search of N per case, is printed with -- min-steps and
# not rerun here)
"$fpm" run --example phase_figures --flag "${HERTZDAMP_RELEASE_FLAGS:-}" >"$tmp/phase" 2>/dev/null
sed -n '/^<!-- BEGIN phase_figures 1 -->$/,/^<!-- END phase_figures 1 -->$/p' "$tmp/phase" >"$tmp/phase.ex"
sed -n '/^<!-- BEGIN phase_figures 1 -->$/,/^<!-- END phase_figures 1 -->$/p' doc/host-schemes.md >"$tmp/phase.doc"
if [ -s "$tmp/phase.ex" ] && cmp -s "$tmp/phase.ex" "$tmp/phase.doc"; then ok; else
  bad "doc/host-schemes.md's phase_figures 1 table is not what the example phase_figures prints"
fi
echo "host_schemes_sync: $p passed, $f failed"
[ "$f" -eq 0 ]
