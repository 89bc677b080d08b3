#!/usr/bin/env bash
# The CPU time of hertzdamp_c_host_min_steps called from C (doc/host-schemes.md, the fewest
# steps of a host; issue 30): builds the core library of this tree with the Makefile's
# RELEASE_FLAGS (a temporary fpm package, as tools/pair_kd_speed.sh) and a C driver that
# calls it once, then times RUNS runs (default 3) of each case and prints their median.
# SRC=dir: another revision's src/ (git archive REV src | tar -x -C /tmp/old).
#   bash tools/min_steps_time.sh [RUNS]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
runs=${1:-3}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
source "$root/tools/core_package.bash"
lib=$(release_core "$tmp/core" "$root")
cat >"$tmp/ms.c" <<'C'
#include <stdio.h>
#include <stdlib.h>
#include "hertzdamp.h"
int main(int argc, char **argv) {
    int n = 0;
    int st = hertzdamp_c_host_min_steps(atof(argv[1]), atoi(argv[2]), atoi(argv[3]), atoi(argv[4]), &n);
    printf("status %d n_min %d", st, n);
    return st != 0;
}
C
gcc -O2 -I"$root/include" "$tmp/ms.c" "$lib" -lgfortran -lquadmath -lm -o "$tmp/ms"
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg)"
# e law end host: lammps, linear, overlap end, e = 1e-3; mfix-euler, kuwabara-kono, e = 1e-4
for args in "1e-3 HERTZDAMP_DAMPING_LINEAR HERTZDAMP_END_OVERLAP HERTZDAMP_HOST_LAMMPS" \
            "1e-4 HERTZDAMP_DAMPING_KUWABARA_KONO HERTZDAMP_END_OVERLAP HERTZDAMP_HOST_MFIX_EULER"; do
    set -- $args
    num=()
    for name in "$2" "$3" "$4"; do
        num+=("$(printf '#include "hertzdamp.h"\n%s\n' "$name" | gcc -E -P -I"$root/include" - | tail -1)")
    done
    times=()
    for ((r = 1; r <= runs; r++)); do
        /usr/bin/time -f '%U' -o "$tmp/t" "$tmp/ms" "$1" "${num[@]}" >"$tmp/out"
        times+=("$(cat "$tmp/t")")
    done
    median=$(printf '%s\n' "${times[@]}" | sort -g | sed -n "$(( (runs + 1) / 2 ))p")
    echo "e = $1 ${2#HERTZDAMP_DAMPING_} ${4#HERTZDAMP_HOST_}: $(cat "$tmp/out"), median CPU ${median} s of $runs"
done
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg)"
