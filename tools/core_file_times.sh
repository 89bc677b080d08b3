#!/usr/bin/env bash
# Per-file compile time of the core library: `gfortran -c` of every src/*.f90 of SRC_DIR
# (default: this tree's src/) with the Makefile's RELEASE_FLAGS, one file at a time in an
# order that satisfies the module dependencies (a file whose modules are not built yet is
# tried again in the next pass), printing each file's user CPU seconds, largest first,
# and the sum.  What the core's build time goes to (doc/performance.md, "Build time"):
#   git archive f991267 src | tar -x -C /tmp/old && bash tools/core_file_times.sh /tmp/old/src
#   bash tools/core_file_times.sh
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
src=$(cd "${1:-$root/src}" && pwd)
flags=$(grep -v '^#' "$root/data/release_flags.txt")
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cp -r "$src"/. "$tmp"/
cd "$tmp"
left=$(ls ./*.f90)
: > times
for ((pass = 1; pass <= 30; pass++)); do
  next=""
  for f in $left; do
    # shellcheck disable=SC2086
    if /usr/bin/time -f '%U' -o t gfortran $flags -c "$f" -o "${f%.f90}.o" 2>/dev/null; then
      echo "$(cat t) $(basename "$f")" >> times
    else
      next="$next $f"
    fi
  done
  left=$next
  [ -z "$left" ] && break
done
[ -z "$left" ] || { echo "core_file_times: could not compile:$left" >&2; exit 1; }
sort -rn times | awk '{printf "%6.2f s  %s\n", $1, $2; s += $1} END {printf "%6.2f s  total (%d files)\n", s, NR}'
