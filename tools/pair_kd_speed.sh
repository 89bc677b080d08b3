#!/usr/bin/env bash
# The per-contact cost of hertzdamp_c_pair_kd and of the onset-phase form
# hertzdamp_c_pair_kd_phase called from a C host against the bare formula, in one process
# (tools/pair_kd_speed.c says what it times): builds the core
# library of this tree with the Makefile's RELEASE_FLAGS (a temporary fpm package, as
# tools/core_build_time.sh) and the C driver with gcc -O2 at the same -march, then runs
# the driver RUNS times (default 3), each TURNS turns (default 101).  SRC=dir: another
# revision's src/ (git archive REV src | tar -x -C /tmp/old; SRC=/tmp/old/src), against
# this tree's include/hertzdamp.h.
#   bash tools/pair_kd_speed.sh [RUNS] [TURNS]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
runs=${1:-3}
turns=${2:-101}
fpm=${FPM:-$root/.venv/bin/fpm}
flags=$(grep -v '^#' "$root/data/release_flags.txt")
march=$(printf '%s\n' $flags | grep '^-march=' || true)
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
source "$root/tools/core_package.bash"
core_package "$tmp/core" "${SRC:-$root/src}"
(cd "$tmp/core" && "$fpm" build --flag "$flags" >"$tmp/log" 2>&1) || { cat "$tmp/log"; exit 1; }
lib=$(find "$tmp/core/build" -name libhertzdamp.a | head -1)
gcc -O2 $march -I"$root/include" "$root/tools/pair_kd_speed.c" "$lib" -lgfortran -lquadmath -lm -o "$tmp/pair_kd_speed"
for ((r = 1; r <= runs; r++)); do "$tmp/pair_kd_speed" "$turns"; done
echo "flags: $flags (library), gcc -O2 $march (driver); $(gcc --version | head -1)"
