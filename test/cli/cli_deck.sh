#!/usr/bin/env bash
# `hertzdamp check ENGINE FILE...`: whole decks read the way the engines read them.
# - LAMMPS: the examples Debian ships (package lammps-examples) and data/peers/decks/lammps_include.in;
# - LIGGGHTS: the tutorials Debian ships (package liggghts-doc) and data/peers/decks/liggghts_two_types.in;
# - MFiX and Yade: decks written after the engines' documentation and examples (data/peers/decks);
# each checked against values the test computes itself from the deck (the stiffness, the time step,
# the pair order of the restitution inputs) and e_model against the reference integrator (table
# --method rk45 at the alpha the test computes); what cannot be read names file:line.
SUITE=cli_deck
cd "$(dirname "$0")/../.." || exit 1
. test/cli/cli_common.bash
BIN=$(realpath "$BIN")   # the test runs in the examples' directories too
TMP=$(mktemp -d); trap 'rm -rf "$TMP" "$OUT" "$ERR"' EXIT
D=$PWD/data/peers/decks
LEX=/usr/share/lammps/examples
GEX=/usr/share/doc/liggghts/examples/LIGGGHTS/Tutorials_public

# a value of a CSV column by name and row (1-based) of $OUT, or of the row whose pair is given
col() { python3 -c "import csv,sys; r=list(csv.DictReader(open(sys.argv[1]))); print(r[int(sys.argv[3])-1][sys.argv[2]])" "$OUT" "$@"; }
pcol() { python3 -c "
import csv,sys; r=[x for x in csv.DictReader(open(sys.argv[1])) if x['pair']==sys.argv[2]]
print(r[int(sys.argv[4])-1 if len(sys.argv)>4 else 0][sys.argv[3]])" "$OUT" "$@"; }
close() { python3 -c "import sys; a,b,t=map(float,sys.argv[1:]); sys.exit(0 if abs(a-b)<=t*abs(b) else 1)" "$@"; }
# e of the reference integrator (table --method rk45) at alpha
rk45() { "$BIN" table --method rk45 --damping "$1" --end "$2" --alpha "$3" --format csv |
           python3 -c "import csv,sys; print(next(csv.DictReader(sys.stdin))['e'])"; }
py() { python3 -c "$@"; }

# ------------------------------------------------------------------ LAMMPS examples (Debian)
cd "$LEX/granular" || exit 1
run check lammps in.pour.flatwall --velocity 1 --format csv
check "in.pour.flatwall: exit 0 ($(head -c 200 "$ERR"))" test "$RC" -eq 0
check "in.pour.flatwall: contacts 2-2, 1-wall, 2-wall" \
  test "$(python3 -c "import csv,sys; print(' '.join(r['pair'] for r in csv.DictReader(open(sys.argv[1]))))" "$OUT")" = "2-2 1-wall 2-wall"
run check lammps in.pour.flatwall --velocity 1
check "in.pour.flatwall: the jkr pairs 1-1 and 1-2 are not checked, naming in.pour.flatwall:39" \
  test "$(grep -c '^# not checked [12]: in.pour.flatwall:39: contact 1-[12]: normal model jkr is cohesive' "$OUT")" -eq 2
check "in.pour.flatwall: timestep 0.001 of in.pour.flatwall:61" grep -q '^# time step: dt = 0.001: timestep 0.001 (in.pour.flatwall:61)' "$OUT"
check "in.pour.flatwall: fix pour diam range 0.5 1.0: the smallest diameter" \
  grep -q '^# contact 2-2: .*type 2: diameter 0.5, density 1 from fix pour ins2 (in.pour.flatwall:50)' "$OUT"
# 2-2: hertz kn = 200, eta_n0 = 20 viscoelastic: k = kn sqrt(R), d = eta_n0 m sqrt(R), alpha = d t*^(3/2) u^(1/2)/m
a=$(py "
import math
r=0.25; rho=1.0; m=0.5*4/3*math.pi*rho*r**3; R=r/2; k=200*math.sqrt(R); d=20*m*math.sqrt(R); u=1.0
ts=(m/(k*math.sqrt(u)))**0.4; print(repr(d*ts**1.5*math.sqrt(u)/m))")
run check lammps in.pour.flatwall --velocity 1 --format csv
em=$(pcol 2-2 e_model); er=$(rk45 kuwabara-kono overlap "$a")
check "in.pour.flatwall 2-2: e_model = rk45 at alpha $a ($em vs $er)" close "$em" "$er" 1e-10
check "in.pour.flatwall: steps_per_contact = t_c/dt" close "$(pcol 2-2 steps_per_contact)" "$(py "print($(pcol 2-2 t_c)/0.001)")" 1e-12

run check lammps in.pour.drum --velocity 1 --release 2021 --format csv
check "in.pour.drum: exit 0" test "$RC" -eq 0
check "in.pour.drum: pair_coeff 1 * tsuji 0.2 covers 1-1 and 1-2 (e_target)" \
  test "$(pcol 1-1 e_target) $(pcol 1-2 e_target)" = "2.000000000000000E-001 2.000000000000000E-001"
check "in.pour.drum: three region walls (fixes 3, 4, 5) with type 1" \
  test "$(grep -c '^1-wall:[345],' "$OUT")" -eq 3
# tsuji 2021: gamma = P6(0.2), overlap end
g=$(py "e=0.2; print(repr(1.2728-4.2783*e+11.087*e**2-22.348*e**3+27.467*e**4-18.022*e**5+4.8218*e**6))")
check "in.pour.drum 1-1: e_model = rk45 at gamma = P6(0.2) = $g" close "$(pcol 1-1 e_model)" "$(rk45 tsuji overlap "$g")" 1e-10
run check lammps in.pour.drum --velocity 1
check "in.pour.drum: 2-2 (jkr) not checked, naming in.pour.drum:47" grep -q '^# not checked: in.pour.drum:47: contact 2-2' "$OUT"
check "in.pour.drum: region walls noted as flat" grep -q 'wall/gran/region: the region.s surface is checked as a flat wall' "$OUT"

cd "$LEX/granregion" || exit 1
run check lammps in.granregion.funnel --velocity 1
check "in.granregion.funnel: exit 0" test "$RC" -eq 0
# the deck's own formulas, evaluated here: dt = 0.05 tcol (variables equal, ^, log, sqrt, ${}, $a)
dt=$(py "
import math
PI=3.141592653589; rlo=0.25; rhi=0.5; density=1.0; E=10**5; nu=2.0/7.0; G=E/(2*(1+nu)); e=0.1
g15=lambda x: float('%.15g' % x)   # LAMMPS substitutes equal-style variables with %.15g
G=g15(G); kn=g15(4.0*G/(3*(1-nu))); min_mass=g15(density*4.0/3.0*PI*rlo*rlo*rlo)
a=g15((-2.0*math.log(e)/PI)**2); gn=g15(math.sqrt(a*2*kn/min_mass/(1+0.25*a)))
tcol=g15(PI/math.sqrt(2*kn/min_mass-gn/4.0)); print(repr(g15(tcol*0.05)))")
got=$(sed -n 's/^# time step: dt = \([^:]*\):.*/\1/p' "$OUT")
check "in.granregion.funnel: dt from the deck's variables ($got vs $dt)" close "$got" "$dt" 1e-14
check "in.granregion.funnel: gran/hertz/history pair and region wall" \
  bash -c "grep -q '^# contact 1-1: gran/hertz/history' '$OUT' && grep -q '^# contact 1-wall: fix wall/gran hertz/history' '$OUT'"

cd "$LEX/pour" || exit 1
expect_fail 2 "in.pour (gran/hooke/history): no contact to check" check lammps in.pour
check "in.pour: message names in.pour:19 and the linear spring ($(cat "$ERR"))" grep -q 'in.pour:19: contact 1-1: pair_style gran/hooke/history is a linear spring' "$ERR"
run check lammps in.pour.2d --velocity 1 --format csv
check "in.pour.2d: gran/hertz/history and two wall fixes" \
  test "$(python3 -c "import csv,sys; print(' '.join(r['pair'] for r in csv.DictReader(open(sys.argv[1]))))" "$OUT")" = "1-1 1-wall:xwalls 1-wall:ywalls"
cd - >/dev/null || exit 1

# ------------------------------------------------------------------ LAMMPS: include, variables, continuation
run check lammps "$D/lammps_include.in" --velocity 1 --release 2021 --format csv
check "lammps_include: exit 0" test "$RC" -eq 0
check "lammps_include: pair_coeff 2 2 (continued) overrides * * for 2-2 only" \
  test "$(pcol 1-1 e_target) $(pcol 1-2 e_target) $(pcol 2-2 e_target)" = \
       "6.000000000000000E-001 6.000000000000000E-001 7.000000000000000E-001"
run check lammps "$D/lammps_include.in" --velocity 1 --release 2021
check "lammps_include: both files read (the include beside its deck)" \
  grep -q "^# deck: $D/lammps_include.in, $D/lammps_materials.in\$" "$OUT"
check "lammps_include: 2-2 has limit_damping (force end)" grep -q '^# contact 2-2: .*damping tsuji limit_damping .*force end' "$OUT"
check "lammps_include: fix pour diam poly: the smallest of \$(3*v_r), \$(4*v_r), 0.005 and dens 2400" \
  grep -q '^# contact 2-2: .*type 2: diameter 0.003, density 2400 from fix pour ins' "$OUT"
check "lammps_include: the unknown command names lammps_include.in:30" \
  grep -q '^# not interpreted: .*lammps_include.in:30: command frobnicate is not interpreted' "$OUT"
check "lammps_include: timestep \$(2.0e-7)" grep -q '^# time step: dt = 2e-7: timestep 2e-7 (.*lammps_include.in:29)' "$OUT"
# 1-wall, LAMMPS 2021: k = (4/3) E/(2(1-nu)) sqrt(R) (the 1-nu of fix wall/gran)
k=$(py "import math; print(('%.6g' % (4/3*6.3e10/(2*(1-0.23))*math.sqrt(1e-3))).replace('e+0', 'e'))")
check "lammps_include 1-wall: the 2021 wall stiffness k = $k" grep -q "^# contact 1-wall: .*k = $k," "$OUT"

# ------------------------------------------------------------------ LIGGGHTS tutorials (Debian)
cd "$GEX/packing" || exit 1
run check liggghts in.packing --velocity 1 --format csv
check "in.packing: exit 0" test "$RC" -eq 0
check "in.packing: six primitive walls and the particle pair" test "$(wc -l <"$OUT")" -eq 8
check "in.packing: model hertz, overlap end, gamma = sqrt(5) beta(e): e_model = e_target (Antypov & Elliott)" \
  close "$(pcol 1-1 e_model)" 0.3 1e-12
run check liggghts in.packing --velocity 1
k=$(py "import math; Ys=5e6/(2*(1-0.45**2)); print('%.6g' % (4/3*Ys*math.sqrt(0.0025)))")
check "in.packing: k = (4/3) Y* sqrt(R) = $k (radius constant 0.005, the smaller template)" grep -q "^# contact 1-1: .*k = $k," "$OUT"
cd "$GEX/chute_wear" || exit 1
run check liggghts in.chute_wear --velocity 1 --format csv
check "in.chute_wear: the mesh wall (material type of fix mesh/surface)" test "$RC" -eq 0 -a "$(pcol 1-wall e_target)" = "3.000000000000000E-001"
cd - >/dev/null || exit 1
run check liggghts "$D/liggghts_two_types.in" --velocity 1 --format csv
check "liggghts_two_types: peratomtypepair row by row (1-2: 0.4, 1-wall of type 3: 0.5, 2-wall: 0.7)" \
  test "$(pcol 1-2 e_target) $(pcol 1-wall e_target) $(pcol 2-wall e_target)" = \
       "4.000000000000000E-001 5.000000000000000E-001 7.000000000000000E-001"
g=$(py "import math; e=0.4; l=-math.log(e); print(repr(math.sqrt(5)*l/math.sqrt(math.pi**2+l*l)))")
check "liggghts_two_types 1-2: limitForce on: e_model = rk45 force end at sqrt(5) beta(0.4)" \
  close "$(pcol 1-2 e_model)" "$(rk45 tsuji force "$g")" 1e-10

sed 's/^                0.3 0.4 0.5 &$/                0.06 0.4 0.5 \&/' "$D/liggghts_two_types.in" >"$TMP/lig_low.in"
run check liggghts "$TMP/lig_low.in" --velocity 1
check "liggghts: a target below what limitForce can reach: the header says why" \
  grep -q '^# corrected: contact 1-1 at u = 1: no value of coefficientRestitution gives e_target' "$OUT"
run check liggghts "$TMP/lig_low.in" --velocity 1 --format csv
check "liggghts: a target below what limitForce can reach: corrected empty, the row ok" \
  test "$(pcol 1-1 corrected),$(pcol 1-1 status)" = ",ok"

# ------------------------------------------------------------------ MFiX
run check mfix "$D/mfix_two_phases.dat" --velocity 1 --format csv
check "mfix_two_phases: exit 0" test "$RC" -eq 0
check "mfix_two_phases: DES_EN_INPUT(1:3) in MFiX's order 1-1, 1-2, 2-2; DES_EN_WALL_INPUT per phase" \
  test "$(pcol 1-1 e_target) $(pcol 1-2 e_target) $(pcol 2-2 e_target) $(pcol 1-wall e_target) $(pcol 2-wall e_target)" = \
       "9.100000000000000E-001 9.200000000000000E-001 9.300000000000000E-001 8.100000000000000E-001 8.200000000000000E-001"
g=$(py "import math; e=0.92; l=-math.log(e); print(repr(2*l/math.sqrt(math.pi**2+l*l)))")
check "mfix_two_phases 1-2: e_model = rk45 (overlap end) at gamma = 2 beta(0.92)" close "$(pcol 1-2 e_model)" "$(rk45 tsuji overlap "$g")" 1e-10
run check mfix "$D/mfix_two_phases.dat" --velocity 1
# DTSOLID = min over the particle pairs of pi/sqrt(k/m - (eta/m)^2/4), eta = 2 beta(e) sqrt(k m), / 50
dt=$(py "
import math
def ph(i): return [(2e-3, 2500.0, 6.3e10, 0.23), (3e-3, 7.8e3, 2.0e11, 0.30)][i]
t = []
for (i, j, e) in [(0, 0, 0.91), (0, 1, 0.92), (1, 1, 0.93)]:
    (d1, r1, E1, n1), (d2, r2, E2, n2) = ph(i), ph(j)
    m1 = math.pi/6*d1**3*r1; m2 = math.pi/6*d2**3*r2; m = m1*m2/(m1+m2); R = (d1*d2/4)/((d1+d2)/2)
    Es = 1/((1-n1**2)/E1 + (1-n2**2)/E2); k = 4/3*Es*math.sqrt(R)
    l = -math.log(e); eta = 2*l/math.sqrt(math.pi**2+l*l)*math.sqrt(k*m)
    t.append(math.pi/math.sqrt(k/m - (eta/m)**2/4))
print(repr(min(t)/50))")
got=$(sed -n 's/^# time step: dt = \([^:]*\):.*/\1/p' "$OUT")
check "mfix_two_phases: DTSOLID = min TCOLL / @(100/2) ($got vs $dt)" close "$got" "$dt" 1e-12
check "mfix_two_phases: ADAMS_BASHFORTH is the host scheme mfix-ab2" grep -q '^# integrator: DES_INTG_METHOD = ADAMS_BASHFORTH .*mfix-ab2' "$OUT"
run check mfix "$D/mfix_hopper.mfx" --velocity 1 --format csv
check "mfix_hopper.mfx: lower-case keys and #!MFIX-GUI comments: 1-1 and 1-wall" \
  test "$RC" -eq 0 -a "$(pcol 1-1 e_target) $(pcol 1-wall e_target)" = "5.000000000000000E-001 6.000000000000000E-001"
run check mfix "$D/mfix_hopper.mfx" --velocity 1
check "mfix_hopper.mfx: EULER by default (mfix-euler)" grep -q '^# integrator: DES_INTG_METHOD = EULER (MFiX.s default).*mfix-euler' "$OUT"
# a malformed line and a missing DES_EN_INPUT name their file:line
printf "  MMAX = 1\n  SOLIDS_MODEL(1) = 'DEM'\n  D_P0(1) = 1e-3  RO_S0(1) = 2500\n  DES_COLL_MODEL = 'HERTZIAN'\n  E_YOUNG(1) = 1e7  V_POISSON(1) = 0.3\n  EW_YOUNG = 1e9  VW_POISSON = 0.3\n  this is not MFiX\n  DES_EN_WALL_INPUT(1) = 0.5\n" >"$TMP/bad.dat"
run check mfix "$TMP/bad.dat" --velocity 1
check "mfix: a line that is no assignment names bad.dat:7" grep -q "^# not interpreted.*bad.dat:7: not an assignment" "$OUT"
check "mfix: the pair without DES_EN_INPUT(1) is not checked and says so" grep -q "^# not checked: .*contact 1-1: missing DES_EN_INPUT(1)" "$OUT"

# ------------------------------------------------------------------ Yade
run check yade "$D/yade_spheres.py" --velocity 1 --release 2023 --format csv
check "yade_spheres 2023: exit 0" test "$RC" -eq 0
check "yade_spheres: MatchMaker matches per material pair (glass-steel 0.6, steel-Wall:box 0.55)" \
  test "$(pcol glass-steel e_target) $(pcol steel-Wall:box e_target)" = "6.000000000000000E-001 5.500000000000000E-001"
g=$(py "
import math
h=[-6.918798,-16.41105,146.8049,-796.4559,2928.711,-7206.864,11494.29,-11342.18,6276.757,-1489.915]
e=0.6; a=sum(h[i]*e**(i+1) for i in range(10)); print(repr(math.sqrt(6)*math.sqrt(1/(1-(1+e)**2*math.exp(a))-1)))")
check "yade_spheres 2023 glass-steel: e_model = rk45 force end at sqrt(6) betan_Thornton(0.6) = $g" \
  close "$(pcol glass-steel e_model)" "$(rk45 tsuji force "$g")" 1e-10
run check yade "$D/yade_spheres.py" --velocity 1 --release 2022 --format csv
g=$(py "import math; e=0.6; l=-math.log(e); print(repr(math.sqrt(5)*l/math.sqrt(math.pi**2+l*l)))")
check "yade_spheres 2022 glass-steel: e_model = rk45 force end at sqrt(5) beta(0.6)" \
  close "$(pcol glass-steel e_model)" "$(rk45 tsuji force "$g")" 1e-10
run check yade "$D/yade_spheres.py" --velocity 1
dt=$(py "import math; print(repr(0.5*min(1e-3/math.sqrt(63e9/2500), 1.5e-3/math.sqrt(210e9/7800))))")
got=$(sed -n 's/^# time step: dt = \([^:]*\):.*/\1/p' "$OUT")
check "yade_spheres: O.dt = 0.5*PWaveTimeStep() = 0.5 min r/sqrt(E/rho) ($got vs $dt)" close "$got" "$dt" 1e-14
check "yade_spheres: NewtonIntegrator(damping=0) is the lammps scheme" grep -q '^# integrator: NewtonIntegrator(damping=0) .*host scheme lammps' "$OUT"
run check yade "$D/yade_vn.py" --velocity 2 --format csv
check "yade_vn: at u = vn the Pade gives en: e_model = 0.8 within the fit (2e-3)" close "$(col e_model 1)" 0.8 2.5e-3
check "yade_vn: e_target at u = vn is en" close "$(col e_target 1)" 0.8 1e-14
run check yade "$D/yade_vn.py" --velocity 20 --format csv
et=$(py "
a=[1,1.07232,0.574198,0.141552]; b=[1,1.07232,1.72765,1.37842,1.19449,0.467273,0.235585]
P=lambda v: sum(c*v**i for i,c in enumerate(a))/sum(c*v**i for i,c in enumerate(b))
lo,hi=0.0,10.0
for _ in range(200):
    m=(lo+hi)/2
    if P(m)>0.8: lo=m
    else: hi=m
print(repr(P(lo*(20/2.0)**0.1)))")
check "yade_vn: e_target at u = 10 vn is Pade(V* 10^(1/10)) ($(col e_target 1) vs $et)" close "$(col e_target 1)" "$et" 1e-12
check "yade_vn: e_model follows it within the Pade's accuracy" close "$(col e_model 1)" "$et" 2.5e-3
expect_fail 2 "yade_vn with --release 2023: vn does not exist there" check yade "$D/yade_vn.py" --release 2023
check "message names vn and 2024.02a: $(cat "$ERR")" grep -q 'vn.*2024.02a' "$ERR"
run check yade "$D/yade_damping.py" --velocity 1 --format csv
check "yade_damping: NewtonIntegrator's default damping: no e_host, verdict unchecked" \
  test "$(col e_host 1),$(col dt_verdict 1)" = ",unchecked"
run check yade "$D/yade_damping.py" --velocity 1
check "yade_damping: the ViscElMat pairs are not checked, naming yade_damping.py:6" grep -q '^# not checked 2: .*yade_damping.py:6: contact visc-visc: ViscElMat' "$OUT"
check "yade_damping: the loop radius names yade_damping.py:11" grep -q '^# not interpreted 1: .*yade_damping.py:11: sphere: the radius is not evaluated' "$OUT"

# ------------------------------------------------------------------ JSON rows and errors
run check lammps "$D/lammps_include.in" --velocity 0.5,2 --format json
check "JSON rows carry exactly the names of issue 24 (and status)" python3 - "$OUT" <<'PYEOF'
import json, sys
d = json.load(open(sys.argv[1]))
want = ["pair", "velocity", "e_target", "e_model", "e_host", "e_spread", "steps_per_contact", "t_c", "dt_verdict",
        "corrected", "status"]
sys.exit(0 if d["rows"] and all(list(r) == want for r in d["rows"]) and len(d["rows"]) == 10 else 1)
PYEOF
printf 'units si\ninclude no_such_file.in\n' >"$TMP/inc.in"
expect_fail 2 "a missing include" check lammps "$TMP/inc.in"
check "message names inc.in:2 and the file: $(cat "$ERR")" grep -q 'inc.in:2: include no_such_file.in: no such file' "$ERR"
printf 'units si\ncreate_box 1 box\ncreate_atoms 1 single 0 0 0\nvariable a equal ${b}*2\npair_style granular\npair_coeff * * hertz 1e5 ${a} damping velocity\ntimestep 1e-6\n' >"$TMP/var.in"
expect_fail 2 "an undefined variable" check lammps "$TMP/var.in"
check "message names var.in:4 and the variable: $(cat "$ERR")" grep -q 'var.in:4: variable b is not defined' "$ERR"
expect_fail 2 "files and words mixed" check lammps "$D/lammps_include.in" damping tsuji
expect_fail 2 "a MercuryDPM deck file" check mercurydpm "$D/lammps_include.in"
check "MercuryDPM: key=value words, not files: $(cat "$ERR")" grep -q 'C++ or Python programs' "$ERR"
expect_fail 2 "deck files with --radius" check lammps "$D/lammps_include.in" --radius 1e-3

# ------------------------------------------------------------------ units of the header, plausible speeds
run check lammps "$D/lammps_include.in" --velocity 1,2
check "units si: velocity [m/s] and t_c [s] in the text header" \
  bash -c "grep -qE '^ *pair +velocity \[m/s\] .* t_c \[s\]' '$OUT' && test ! -s '$ERR'"
run check lammps "$D/lammps_include.in" --velocity 1,3000
check "units si, --velocity 3000: one warning, the results all the same (exit $RC)" \
  test "$RC" -eq 0 -a "$(grep -c '^hertzdamp: warning: --velocity 3000: above 1e3 m/s' "$ERR")" -eq 1 -a -s "$OUT"
run check lammps "$D/lammps_include.in" --velocity 1,3000 --quiet
check "--quiet: no warning" test "$RC" -eq 0 -a ! -s "$ERR"
sed 's/^units           si$/units           cgs/' "$D/lammps_include.in" >"$TMP/cgs.in"
cp "$D/lammps_materials.in" "$TMP/"
run check lammps "$TMP/cgs.in" --velocity 1,3000
check "units cgs: velocity [cm/s], t_c [s]; 3000 cm/s is no warning" \
  bash -c "grep -qE '^ *pair +velocity \[cm/s\] .* t_c \[s\]' '$OUT' && test ! -s '$ERR'"
sed 's/^units           si$/units           lj/' "$D/lammps_include.in" >"$TMP/lj.in"
run check lammps "$TMP/lj.in" --velocity 1,2
check "units lj: no unit in the header" bash -c "grep -qE '^ *pair +velocity +e_target .* t_c +corrected' '$OUT'"

# ------------------------------------------------------------------ defects of issue 30 (each failed on 56a29ad)
# item 4: a deck from a pipe, a FIFO or a process substitution is read to its end (the
# size the system gives for them is 0); its include is found in the working directory
cd "$D" || exit 1
run check lammps lammps_include.in --velocity 1 --release 2021 --format csv
cp "$OUT" "$TMP/from_file.csv"
cat lammps_include.in | "$BIN" check lammps /dev/stdin --velocity 1 --release 2021 --format csv >"$OUT" 2>"$ERR"; RC=$?
check "a deck from a pipe (cat deck | check lammps /dev/stdin): the rows of the file (exit $RC: $(head -c 150 "$ERR"))" \
  cmp -s "$OUT" "$TMP/from_file.csv"
mkfifo "$TMP/deck.fifo"
cat lammps_include.in >"$TMP/deck.fifo" &
run check lammps "$TMP/deck.fifo" --velocity 1 --release 2021 --format csv
wait
check "a deck from a FIFO: the rows of the file (exit $RC)" cmp -s "$OUT" "$TMP/from_file.csv"
run check lammps <(cat lammps_include.in) --velocity 1 --release 2021 --format csv
check "a deck from <(...): the rows of the file (exit $RC)" cmp -s "$OUT" "$TMP/from_file.csv"
cd - >/dev/null || exit 1
# item 9: an argument that is neither a file nor the engine's words is a missing deck file
expect_fail 2 "a missing deck file (lammps)" check lammps nonexist.in --radius 1e-3 --density 2500 --velocity 1
check "message names nonexist.in, no such file: $(cat "$ERR")" grep -q '^hertzdamp: nonexist.in: no such deck file' "$ERR"
expect_fail 2 "a missing deck file (mfix)" check mfix nonexist.dat --velocity 1
check "message names nonexist.dat, no such file: $(cat "$ERR")" grep -q '^hertzdamp: nonexist.dat: no such deck file' "$ERR"
expect_fail 2 "a missing second deck file" check lammps "$D/lammps_include.in" nonexist.in
check "message names the second file: $(cat "$ERR")" grep -q '^hertzdamp: nonexist.in: no such deck file' "$ERR"
run check lammps "hertz/material 1e8 0.5 0.3 damping tsuji" --radius 1e-3 --density 2500 --velocity 1
check "LAMMPS's own words that name no file are still words (exit $RC)" test "$RC" -eq 0
# a deck whose one token is 4 MB long (the adversarial round: a message quoting it
# overflowed the stack, SIGSEGV): the engines' readers report it, exit 2, one line
head -c 4000000 /dev/zero | tr '\0' a >"$TMP/long_token.in"
for engine in lammps liggghts mfix; do
  expect_fail 2 "a 4 MB token ($engine)" check "$engine" "$TMP/long_token.in"
done
# item 7: the whole deck notes what the other LAMMPS releases give (LAMMPS's own example:
# the 2021 fix wall/gran stiffness); the note's e_host is the --release 2021 row's
cd "$LEX/granular" || exit 1
run check lammps in.pour.flatwall --velocity 1 --release 2021 --format csv
eh=$(pcol 1-wall e_host)
run check lammps in.pour.flatwall --velocity 1
note=$(sed -n 's/^# note[ 0-9]*: contacts 1-wall, 2-wall: LAMMPS 29 Sep 2021 update 2 (Debian 12) (--release 2021) gives e_model = [^,]*, e_host = \([^,]*\),.*/\1/p' "$OUT")
check "in.pour.flatwall: a note gives the 2021 release's e_host of the walls (${note:-none} vs $eh of --release 2021)" \
  close "${note:-0}" "$eh" 5e-6
cd - >/dev/null || exit 1
# minor: a deck that includes itself is an error, as LAMMPS never finishes reading it
cp "$D/lammps_materials.in" "$TMP/"
{ cat "$D/lammps_include.in"; echo "include self.in"; } >"$TMP/self.in"
expect_fail 2 "a deck that includes itself" check lammps "$TMP/self.in" --velocity 1
check "message names self.in and the nesting: $(cat "$ERR")" grep -q 'self.in:[0-9]*: include [^:]*: nested deeper than 20 files (does the deck include itself?)' "$ERR"
# found here: a pair style the checker does not read, with a name of 25 characters or more,
# crashed the program (gfortran 12 built the words 'pair_style STYLE' with an empty STYLE)
cd "$LEX/PACKAGES/dpd-smooth/equipartition-verification" || exit 1
expect_fail 2 "LAMMPS's dpd-smooth example (pair_style sdpd/taitwater/isothermal)" check lammps in.lammps
check "message names the pair style: $(cat "$ERR")" grep -q 'pair_style sdpd/taitwater/isothermal is not a granular style' "$ERR"
cd - >/dev/null || exit 1
finish
