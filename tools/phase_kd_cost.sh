#!/usr/bin/env bash
# Where the time of hertzdamp_c_pair_kd_phase goes (doc/host-schemes.md section 6.3): runs
# tools/pair_kd_speed.sh (a C host loop: the bare formula, hertzdamp_c_pair_kd and the
# phase form side by side in one process) against this tree's src/ and three timing-only
# variants of it, each one step less of the phase form's usual contact (their k, d are
# wrong; nothing of them is kept):
#   no-marker: the markers of the table and of the half's record not hashed
#              (hertzdamp_phase_marker.inc, hertzdamp_phase_half_marker.inc skipped);
#   no-sqrt:   that, and no square root in the lookup (t = d instead of d^(1/r));
#   no-lookup: that, and no lookup at all (K, A two fixed entries of the table).
#   bash tools/phase_kd_cost.sh [RUNS] [TURNS]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
runs=${1:-2}
turns=${2:-101}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
variant() {   # variant NAME STEPS: a copy of src/ with the first STEPS replacements
    mkdir -p "$tmp/$1" && cp -r "$root/src" "$tmp/$1/"
    python3 - "$tmp/$1/src" "$2" <<'PY'
import sys
src, steps = sys.argv[1], int(sys.argv[2])
fast = src + '/hertzdamp_phase_fast.inc'
body = src + '/hertzdamp_phase_eval_body.inc'
# the lookup without square roots is a copy of its text (init checks the table with the real one)
text = open(body).read()
open(src + '/nosqrt_eval_body.inc', 'w').write(
    text.replace("    t = sqrt(abs(phi - tab(b)) * tab(b + 1))\n    if (root4) t = sqrt(t)\n",
                 "    t = abs(phi - tab(b)) * tab(b + 1)\n"))
edits = [(fast, "    include 'hertzdamp_phase_marker.inc'\n", "    phase_bits = transfer(pair%phase(1), 0_int64)\n"),
         (fast, "    include 'hertzdamp_phase_half_marker.inc'\n", "    half_bits = transfer(pair%phase(hb + 5), 0_int64)\n"),
         (fast, "include 'hertzdamp_phase_eval_body.inc'", "include 'nosqrt_eval_body.inc'"),
         (fast, "            include 'nosqrt_eval_body.inc'\n", "            kk = tab(35)\n            aa = tab(36)\n")]
if 'sqrt' in open(src + '/nosqrt_eval_body.inc').read():
    sys.exit('phase_kd_cost.sh: the lookup no longer holds the square roots this variant removes')
for path, old, new in edits[:steps]:
    text = open(path).read()
    if text.count(old) != 1:
        sys.exit('phase_kd_cost.sh: %s no longer holds the text this variant replaces' % path)
    open(path, 'w').write(text.replace(old, new))
PY
}
variant no-marker 2
variant no-sqrt 3
variant no-lookup 4
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg)"
for v in src no-marker no-sqrt no-lookup; do
    if [ "$v" = src ]; then s=$root/src; else s=$tmp/$v/src; fi
    echo "== $v"
    SRC=$s bash "$root/tools/pair_kd_speed.sh" "$runs" "$turns" | grep -v '^flags:' || true
done
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg)"
