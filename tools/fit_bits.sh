#!/usr/bin/env bash
# Bit-identity of the fit between two trees (issue 22): builds the core of REF (a git
# revision, default main, exported with `git archive` into a temporary directory) and
# of this work tree, each with tools/fit_dump.f90 as its only program, under each set of
# FLAGS (default: the Makefile's RELEASE_FLAGS, then -O2 -g -fPIC), runs both dumps
# (every public fit result on dense grids with edges, NaN, inf, subnormals; see
# tools/fit_dump.f90) and compares them byte for byte.
#   bash tools/fit_bits.sh [REF] [FLAGS...]
# Exit status 0 when every dump is identical; prints the first differing lines if not.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
ref=${1:-main}
shift || true
release=$(grep -v '^#' "$root/data/release_flags.txt")
if [ $# -gt 0 ]; then flagsets=("$@"); else flagsets=("$release" "-O2 -g -fPIC"); fi
fpm=${FPM:-$root/.venv/bin/fpm}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/refsrc"
git -C "$root" archive "$ref" src | tar -x -C "$tmp/refsrc"
source "$root/tools/core_package.bash"
core_package "$tmp/ref" "$tmp/refsrc/src" "$root/tools/fit_dump.f90"
core_package "$tmp/new" "$root/src" "$root/tools/fit_dump.f90"
fail=0
for flags in "${flagsets[@]}"; do
  for side in ref new; do
    (cd "$tmp/$side" && "$fpm" run fit_dump --flag "$flags" -- "$tmp/$side.dump" >/dev/null 2>"$tmp/$side.log") || {
      cat "$tmp/$side.log"; echo "fit_bits: the $side build failed ($flags)"; exit 2; }
  done
  lines=$(wc -l < "$tmp/new.dump")
  if cmp -s "$tmp/ref.dump" "$tmp/new.dump"; then
    echo "fit_bits: identical ($lines lines, $(wc -c < "$tmp/new.dump") bytes) against $ref with flags: $flags"
  else
    echo "fit_bits: DIFFERENT from $ref with flags: $flags"
    diff "$tmp/ref.dump" "$tmp/new.dump" | cut -c1-300 | head -20
    fail=1
  fi
done
exit $fail
