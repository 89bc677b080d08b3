#!/usr/bin/env bash
# Speed of the fit's entry points, REF (default main, exported with `git archive`) and
# this work tree side by side: both cores built with the Makefile's RELEASE_FLAGS, each
# with tools/fit_speed.f90 as its program, run in turns ROUNDS times (default 5); prints
# per entry point the shortest batch over all runs (ns per value: the figure least
# disturbed by other jobs on a shared machine) for both, and their ratio (this tree / REF).
#   bash tools/fit_speed.sh [REF] [ROUNDS]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
ref=${1:-main}
rounds=${2:-5}
fpm=${FPM:-$root/.venv/bin/fpm}
flags=$(grep -v '^#' "$root/data/release_flags.txt")
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/refsrc"
git -C "$root" archive "$ref" src | tar -x -C "$tmp/refsrc"
source "$root/tools/core_package.bash"
core_package "$tmp/ref" "$tmp/refsrc/src" "$root/tools/fit_speed.f90"
core_package "$tmp/new" "$root/src" "$root/tools/fit_speed.f90"
for side in ref new; do
  (cd "$tmp/$side" && "$fpm" build --flag "$flags" >"$tmp/$side.log" 2>&1) || { tail -20 "$tmp/$side.log"; echo "fit_speed: $side build failed"; exit 2; }
  find "$tmp/$side/build" -type f -name fit_speed -perm -u+x -exec cp {} "$tmp/$side.exe" \;
done
for ((r = 1; r <= rounds; r++)); do
  for side in ref new; do "$tmp/$side.exe" > "$tmp/$side.$r"; done
done
python3 - "$tmp" "$rounds" "$ref" <<'PY'
import sys
tmp, rounds, ref = sys.argv[1], int(sys.argv[2]), sys.argv[3]
def read(side):
    runs = []
    for r in range(1, rounds + 1):
        with open('%s/%s.%d' % (tmp, side, r)) as f:
            runs.append([(l[:39].strip(), float(l[39:])) for l in f if l.strip()])
    return {name: min(run[i][1] for run in runs) for i, (name, _) in enumerate(runs[0])}
old, new = read('ref'), read('new')
print('%-36s %10s %10s %7s' % ('ns per value (best of %d runs)' % rounds, ref, 'this tree', 'ratio'))
for name in old:
    print('%-36s %10.2f %10.2f %7.2f' % (name, old[name], new[name], new[name] / old[name]))
PY
