#!/usr/bin/env bash
# Time `hertzdamp check` on a 40,038-word LAMMPS deck (10,000 chained equal-style variables)
# and on 40,000 key=value words (doc/peers.md section 11a).  Usage: tools/deck_speed.sh [hertzdamp]
set -eu
bin=${1:-hertzdamp}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
python3 - "$tmp" <<'PY'
import sys
d = sys.argv[1]
with open(d + "/big.in", "w") as f:
    f.write("units si\ncreate_box 1 box\ncreate_atoms 1 single 0 0 0\nvariable v0 equal 1.0e-3\n")
    for i in range(1, 10001):
        f.write("variable v%d equal ${v%d}\n" % (i, i - 1))
    f.write("set type 1 diameter ${v10000}\nset type 1 density 2500\npair_style granular\n"
            "pair_coeff * * hertz/material 1e8 0.5 0.3 damping tsuji\ntimestep 1e-7\n")
with open(d + "/words.txt", "w") as f:
    f.write(" ".join("X%d=1" % i for i in range(1, 40001)))
PY
echo "deck of $(wc -w <"$tmp/big.in") words:"
time "$bin" check lammps "$tmp/big.in" --velocity 1 --format csv >/dev/null
echo "40000 key=value words (an unknown key: exit 2 after reading them all):"
# shellcheck disable=SC2046
time "$bin" check mfix DES_COLL_MODEL=HERTZIAN E_YOUNG=1e7 V_POISSON=0.3 DES_EN_INPUT=0.5 --radius 1e-3 \
  --density 2500 --velocity 1 $(cat "$tmp/words.txt") 2>/dev/null || true
