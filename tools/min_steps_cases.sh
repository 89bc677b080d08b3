#!/usr/bin/env bash
# hertzdamp_c_host_min_steps over 93 fixed targets (doc/host-schemes.md section 4, the
# fewest steps; issue 30): 48 drawn with a fixed seed (e log-uniform in [3e-4, 0.9], law,
# end and scheme lammps .. lammps-phase) and 45 force-end targets (e = 1e-3 .. 2e-2, every
# law, lammps, mfix-ab2, lammps-phase).  Builds the core of this tree (or SRC=dir, another
# revision's src/) with the release flags and a C driver; prints per target
# "e law end host st S n_min N | the init statuses at N - 1 .. N + 3 | at N = 2, 3, 4 | cpu s"
# and the total CPU time.  Compare two revisions with diff (cut off the cpu column).
#   bash tools/min_steps_cases.sh
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
source "$root/tools/core_package.bash"
lib=$(release_core "$tmp/core" "$root")
cat >"$tmp/ms.c" <<'C'
#include <stdio.h>
#include <time.h>
#include "hertzdamp.h"
int main(void) {
    double e, total = 0.0;
    int law, end, host;
    while (scanf("%lf %d %d %d", &e, &law, &end, &host) == 4) {
        int n = 0;
        clock_t c0 = clock();
        int st = hertzdamp_c_host_min_steps(e, law, end, host, &n);
        double cpu = (double)(clock() - c0) / CLOCKS_PER_SEC;
        hertzdamp_pair_t p;
        total += cpu;
        printf("%.6g %d %d %d st %d n_min %d |", e, law, end, host, st, n);
        for (int k = -1; k <= 3; k++) {
            if (n == 0 || n + k < 2) printf(" -");
            else printf(" %d", hertzdamp_c_pair_init(e, law, end, host, (double)(n + k), &p));
        }
        printf(" | N=2,3,4:");
        for (int nn = 2; nn <= 4; nn++) printf(" %d", hertzdamp_c_pair_init(e, law, end, host, (double)nn, &p));
        printf(" | cpu %.2f\n", cpu);
        fflush(stdout);
    }
    printf("total cpu %.1f s, load average ", total);
    return 0;
}
C
gcc -O2 -I"$root/include" "$tmp/ms.c" "$lib" -lgfortran -lquadmath -lm -o "$tmp/ms"
python3 - >"$tmp/cases" <<'PY'
import random
r = random.Random(20261202)
for i in range(48):
    e = 10 ** r.uniform(-3.5, -0.05)
    law = r.randint(0, 2); end = r.randint(0, 1); host = r.choice([1, 2, 3, 4, 5])
    print(f"{e:.6g} {law} {end} {host}")
for e in [1e-3, 2e-3, 5e-3, 1e-2, 2e-2]:
    for law in range(3):
        for host in [1, 3, 5]:
            print(f"{e} {law} 1 {host}")
PY
"$tmp/ms" <"$tmp/cases"
cut -d' ' -f1-3 /proc/loadavg
