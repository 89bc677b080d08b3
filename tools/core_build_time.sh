#!/usr/bin/env bash
# Wall time of a fresh -O3 build of the core library alone (src/ with the Makefile's
# RELEASE_FLAGS), the build-time figure of issue 22.  Each SRC_DIR (default: this tree's
# src/) is copied into a temporary fpm package with no programs or tests, and `fpm build`
# runs there from an empty build directory, RUNS times (default 3); the trees take turns,
# so that a change in the machine's load reaches all of them alike.  Prints each run
# (wall and user CPU seconds) and the medians.
#   bash tools/core_build_time.sh [-n RUNS] [SRC_DIR...]
# Side by side with main:  git archive main src | tar -x -C /tmp/old
#                          bash tools/core_build_time.sh /tmp/old/src src
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
runs=3
if [ "${1:-}" = "-n" ]; then runs=$2; shift 2; fi
[ $# -gt 0 ] || set -- "$root/src"
fpm=${FPM:-$root/.venv/bin/fpm}
flags=$(grep -v '^#' "$root/data/release_flags.txt")
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
source "$root/tools/core_package.bash"
n=0
for src in "$@"; do
  n=$((n + 1))
  core_package "$tmp/$n" "$src"
done
for ((r = 1; r <= runs; r++)); do
  for ((i = 1; i <= n; i++)); do
    rm -rf "$tmp/$i/build"
    /usr/bin/time -f '%e %U' -o "$tmp/time" bash -c "cd '$tmp/$i' && '$fpm' build --flag '$flags' >'$tmp/log' 2>&1" ||
      { cat "$tmp/log"; echo "core_build_time: build of ${!i} failed"; exit 1; }
    read -r wall user < "$tmp/time"
    echo "$wall $user" >> "$tmp/times.$i"
    printf 'run %d  %-40s wall %5.1f s  user %5.1f s\n' "$r" "${!i}" "$wall" "$user"
  done
done
median() { sort -g | sed -n "$(( (runs + 1) / 2 ))p"; }
for ((i = 1; i <= n; i++)); do
  printf 'median of %d  %-40s wall %5.1f s  user %5.1f s\n' "$runs" "${!i}" \
    "$(cut -d' ' -f1 "$tmp/times.$i" | median)" "$(cut -d' ' -f2 "$tmp/times.$i" | median)"
done
echo "flags: $flags; fpm $("$fpm" --version 2>/dev/null | head -1 | awk '{print $2}'); $(gfortran --version | head -1)"
