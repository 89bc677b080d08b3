#!/usr/bin/env bash
# Where the time of hertzdamp_c_pair_kd_phase goes (doc/host-schemes.md section 6.3): runs
# tools/pair_kd_speed.sh (a C host loop: the bare formula, hertzdamp_c_pair_kd and the
# phase form side by side in one process) against this tree's src/ and three timing-only
# variants of it, each one step less of the phase form's usual contact (their k, d are
# wrong; nothing of them is kept):
#   no-marker: the markers of the table and of the half's record not hashed
#              (hertzdamp_phase_marker.inc, hertzdamp_phase_half_marker.inc skipped);
#   no-sqrt:   that, and no square root in the lookup (t = d instead of d^(1/r));
#   no-lookup: that, and no lookup at all (K, A two fixed entries of the table);
# and two of a grid uniform in phi itself (issue 32: the lookup without the square root and
# the half's record; the markers kept, the cell's nodes arbitrary entries of the table):
#   uniform:        every phase by the cubic on 60 uniform cells of (0, 1] (no other path);
#   uniform-branch: the same for the phases of cells 1 .. 58, the others (3 %) by the graded
#                   halves behind a branch, as a table with such a grid would read them.
#   bash tools/phase_kd_cost.sh [RUNS] [TURNS]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
runs=${1:-2}
turns=${2:-101}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
variant() {   # variant NAME STEPS [GRID]: a copy of src/ with the first STEPS replacements
    mkdir -p "$tmp/$1" && cp -r "$root/src" "$tmp/$1/"
    python3 - "$tmp/$1/src" "$2" "${3:-}" <<'PY'
import sys
src, steps, grid = sys.argv[1], int(sys.argv[2]), sys.argv[3]
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
# the uniform grid: x = 60 phi - 1.5 the node coordinate less 1.5, the cell's cubic as the
# graded lookup's (the same weights), its first node's index clamped into the block
cell = '''    jf = min(max((x + round_shift) - round_shift, 0.0_wp), 57.0_wp)
    i = min(iand(int(34.0_wp + 2.0_wp * jf), 255), hertzdamp_pair_phase_size - 8)
    v = x - jf
    u = v + 1.5_wp
    um1 = v + 0.5_wp
    um2 = v - 0.5_wp
    um3 = v - 1.5_wp
    w0 = -(um1 * um2) * (um3 * (1.0_wp / 6.0_wp))
    w1 = (u * um2) * (um3 * 0.5_wp)
    w2 = -(u * um1) * (um3 * 0.5_wp)
    w3 = (u * um1) * (um2 * (1.0_wp / 6.0_wp))
    kk = (w0 * tab(i + 1) + w1 * tab(i + 3)) + (w2 * tab(i + 5) + w3 * tab(i + 7))
    aa = (w0 * tab(i + 2) + w1 * tab(i + 4)) + (w2 * tab(i + 6) + w3 * tab(i + 8))
'''
head = '''block
    real(wp), parameter :: round_shift = 6755399441055744.0_wp
    real(wp) :: x, jf, v, u, w0, w1, w2, w3, um1, um2, um3
    integer :: i
    x = phi * 60.0_wp - 1.5_wp
'''
if grid == 'uniform':
    open(src + '/uniform_eval_body.inc', 'w').write(head + cell + 'end block\n')
elif grid == 'uniform-branch':
    open(src + '/uniform_eval_body.inc', 'w').write(
        head + '    if (x >= -0.5_wp .and. x <= 57.5_wp) then\n' + cell +
        "    else\n        include 'hertzdamp_phase_eval_body.inc'\n    end if\nend block\n")
if grid:
    edits = [(fast, "include 'hertzdamp_phase_eval_body.inc'", "include 'uniform_eval_body.inc'")]
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
variant uniform 1 uniform
variant uniform-branch 1 uniform-branch
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg)"
for v in src no-marker no-sqrt no-lookup uniform uniform-branch; do
    if [ "$v" = src ]; then s=$root/src; else s=$tmp/$v/src; fi
    echo "== $v"
    SRC=$s bash "$root/tools/pair_kd_speed.sh" "$runs" "$turns" | grep -v '^flags:' || true
done
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg)"
