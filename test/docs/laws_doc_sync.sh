#!/usr/bin/env bash
# doc/damping-laws.md holds the tables that `fpm run --example damping_laws` prints
# (figures computed by the library, never typed): each between the markers
# <!-- BEGIN damping_laws example --> and <!-- END damping_laws example -->.  The
# marked blocks, in order, must equal the example's tables line for line, so a
# changed, missing or stale extra row (or table) fails, as test/cli/cli_check.sh does for
# doc/peers.md.
cd "$(dirname "$0")/../.."
fpm=${HERTZDAMP_FPM:-.venv/bin/fpm}
p=0; f=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$fpm" run --example damping_laws --flag "${HERTZDAMP_RELEASE_FLAGS:-}" 2>/dev/null | grep '^|' >"$tmp/example"
n=$(grep -c '^| --- ' "$tmp/example")
if [ -s "$tmp/example" ] && [ "$n" -ge 5 ] && [ "$(wc -l <"$tmp/example")" -ge 30 ]; then p=$((p + 1)); else
  f=$((f + 1)); echo "FAIL laws_doc_sync: the example printed no tables (or fewer than 5)"
fi
# the marked blocks, without the markers; an unclosed or nested marker fails
if awk '/^<!-- BEGIN damping_laws example -->$/ { if (inb) exit 1; inb = 1; nb++; next }
        /^<!-- END damping_laws example -->$/   { if (!inb) exit 1; inb = 0; next }
        inb { print }
        END { if (inb) exit 1; print nb > "/dev/stderr" }' doc/damping-laws.md >"$tmp/doc" 2>"$tmp/nblocks"; then
  p=$((p + 1))
else
  f=$((f + 1)); echo "FAIL laws_doc_sync: unbalanced damping_laws example markers in doc/damping-laws.md"
fi
nb=$(cat "$tmp/nblocks")
if [ "$nb" = "$n" ]; then p=$((p + 1)); else
  f=$((f + 1)); echo "FAIL laws_doc_sync: doc/damping-laws.md marks ${nb:-0} tables, the example prints $n"
fi
if cmp -s "$tmp/doc" "$tmp/example"; then p=$((p + 1)); else
  f=$((f + 1)); echo "FAIL laws_doc_sync: the marked tables of doc/damping-laws.md differ from the example's:"
  diff "$tmp/doc" "$tmp/example" | head -n 20
fi
echo "laws_doc_sync: $p passed, $f failed"
[ "$f" -eq 0 ]
