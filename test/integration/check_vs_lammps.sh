#!/usr/bin/env bash
# `hertzdamp check lammps --release 2021` against the LAMMPS that Debian 12 ships
# (29 Sep 2021 update 2, package lammps): for decks of pair_style granular and
# fix wall/gran granular, the restitution coefficient LAMMPS produces in a head-on
# collision (two 2 mm spheres, rho = 2500, relative speed 1 m/s; or one against a
# zplane wall at 1 m/s), run at dt = 2.5e-8 s (about 3000 steps per contact), equals
# the e that `check` predicts to 3e-4 (LAMMPS's own first-order time-step error; seen:
# below 6e-5).  The current-release prediction for tsuji must differ (the test tells the
# formulas apart).  Needs the Debian package lammps (`make lammps` installs it).
cd "$(dirname "$0")/../.." || exit 1
BIN=${HERTZDAMP_BIN:?set HERTZDAMP_BIN}
LMP=$(command -v lmp || true)
if [ -z "$LMP" ]; then
  echo "FAIL check_vs_lammps: lmp not found (Debian package lammps; make lammps installs it)"
  echo "check_vs_lammps: 0 passed, 1 failed"; exit 1
fi
TMP=$(mktemp -d); trap 'rm -rf "$TMP"' EXIT
# the common head and tail, then the pair and the wall set-ups
head='units si
atom_style sphere
atom_modify map array
boundary f f f
region box block -0.01 0.01 -0.01 0.01 -0.01 0.01
create_box 1 box'
tail='comm_modify vel yes
fix 1 all nve/sphere
timestep 2.5e-8
thermo 100000
run 10000'
cat >"$TMP/in.pair" <<EOF
$head
create_atoms 1 single -0.0010005 0 0
create_atoms 1 single  0.0010005 0 0
set type 1 diameter 0.002
set type 1 density 2500
group a id 1
group b id 2
velocity a set 0.5 0 0
velocity b set -0.5 0 0
pair_style granular
pair_coeff * * \${deck}
neighbor 0.0005 bin
$tail
variable e equal vx[2]-vx[1]
print "RESULT \$(v_e:%.15g)"
EOF
cat >"$TMP/in.wall" <<EOF
$head
create_atoms 1 single 0 0 0.0010005
set type 1 diameter 0.002
set type 1 density 2500
velocity all set 0 0 -1
pair_style none
fix 2 all wall/gran granular \${deck} zplane 0 NULL
$tail
variable e equal vz[1]
print "RESULT \$(v_e:%.15g)"
EOF
p=0; f=0
T="tangential linear_nohistory 0 0"
compare() {  # kind (pair|wall), deck
  local kind=$1 deck=$2 e_lmp e_chk args
  # a LAMMPS run that ends without its RESULT line (seen once under heavy machine load:
  # the engine itself failed) is run once more; its message is shown if it fails again
  local try
  for try in 1 2; do
    e_lmp=$(cd "$TMP" && "$LMP" -in "in.$kind" -var deck "$deck" -log none -echo none 2>"$TMP/lmp.err" | \
            sed -n 's/^RESULT //p')
    [ -n "$e_lmp" ] && break
  done
  [ -n "$e_lmp" ] || tail -n 5 "$TMP/lmp.err" | sed 's/^/    lmp: /'
  if [ "$kind" = wall ]; then args=("fix 1 all wall/gran granular $deck zplane 0 NULL"); else args=("$deck"); fi
  e_chk=$("$BIN" check lammps "${args[@]}" --release 2021 --radius 1e-3 --density 2500 --velocity 1 --e 0.5 \
          --format csv | python3 -c "import csv,sys; print(list(csv.DictReader(sys.stdin))[0]['e'])")
  if python3 -c "import sys; a,b=map(float,sys.argv[1:]); sys.exit(0 if abs(a-b)<=3e-4 else 1)" "$e_lmp" "$e_chk" \
       2>/dev/null; then
    p=$((p + 1))
  else
    f=$((f + 1)); echo "FAIL check_vs_lammps: $kind $deck"
  fi
  printf '%-4s %-80s LAMMPS e %-18s check e %s\n' "$kind" "$deck" "$e_lmp" "$e_chk"
}
compare pair "hertz/material 1e8 0.5 0.3 $T damping tsuji"
compare pair "hertz/material 1e8 0.5 0.3 $T damping tsuji limit_damping"
compare pair "hertz/material 1e8 0.02 0.3 $T damping velocity"
compare pair "hertz 2e8 0.02 $T damping velocity limit_damping"
compare pair "hertz/material 1e8 1.2e4 0.3 $T damping mass_velocity"
compare pair "hertz/material 1e8 1e8 0.3 $T damping viscoelastic"
compare pair "hertz/material 1e8 1e8 0.3 $T damping viscoelastic limit_damping"
compare wall "hertz/material 1e8 0.02 0.3 $T damping velocity"
compare wall "hertz/material 1e8 1e8 0.3 $T damping viscoelastic"
compare wall "hertz/material 1e8 0.5 0.3 $T damping tsuji"
# the formulas of the other releases are told apart: current tsuji (sqrt(2) P6) is far from LAMMPS 2021
e_cur=$("$BIN" check lammps "hertz/material 1e8 0.5 0.3 $T damping tsuji" --release current --radius 1e-3 \
        --density 2500 --velocity 1 --format csv | python3 -c "import csv,sys; print(list(csv.DictReader(sys.stdin))[0]['e'])")
e_cur_wall=$("$BIN" check lammps "hertz/material 1e8 0.02 0.3 $T damping velocity" --wall --release current \
             --radius 1e-3 --density 2500 --velocity 1 --e 0.5 --format csv | \
             python3 -c "import csv,sys; print(list(csv.DictReader(sys.stdin))[0]['e'])")
if python3 -c "import sys; a,b=map(float,sys.argv[1:]); sys.exit(0 if abs(a-0.616)>0.1 and abs(b-0.914)>5e-3 else 1)" \
     "$e_cur" "$e_cur_wall"; then p=$((p + 1)); else f=$((f + 1)); echo "FAIL check_vs_lammps: releases told apart"; fi
echo "check_vs_lammps: $p passed, $f failed"
[ "$f" -eq 0 ]
