#!/usr/bin/env bash
# doc/damping-laws.md holds the tables that `fpm run --example damping_laws` prints
# (figures computed by the library, never typed).
cd "$(dirname "$0")/.."
fpm=${HERTZDAMP_FPM:-.venv/bin/fpm}
p=0; f=0
out=$("$fpm" run --example damping_laws --flag "${HERTZDAMP_RELEASE_FLAGS:-}" 2>/dev/null | grep '^|')
if [ -n "$out" ]; then p=$((p + 1)); else f=$((f + 1)); echo "FAIL laws_doc_sync: the example printed no table"; fi
n=$(wc -l <<<"$out")
missing=$(grep -vxFf doc/damping-laws.md <<<"$out")
if [ -z "$missing" ] && [ "$n" -ge 30 ]; then p=$((p + 1)); else
  f=$((f + 1)); echo "FAIL laws_doc_sync: lines of the example missing from doc/damping-laws.md:"; echo "$missing" | head -n 10
fi
echo "laws_doc_sync: $p passed, $f failed"
[ "$f" -eq 0 ]
