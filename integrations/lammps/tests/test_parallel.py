"""pair_style granular/hertzdamp under MPI.

- Granular gas (2925 beads, 3000 steps, 20 steps per contact, hertzdamp walls),
  started from one data file: the per-contact statistics (compute hertzdamp/stats,
  fix hertzdamp/wall) and the per-contact log are identical, bit for bit, under
  mpirun -np 1 and -np 2 (newton on).  With newton off the same contacts occur
  (same pairs) and every logged value agrees to 1e-9.
- A contact that migrates between processors: two beads in contact drift across
  the processor boundary (processors 2 1 1) while the neighbor list is rebuilt
  during the contact.  One contact; its k and d are those of the C API for the
  onset (bit for bit); e and T_c equal those of the same collision at rest on one
  processor; the owners of both atoms change from processor 0 to 1 during it.
"""
import atexit
import os
import shutil
import sys
import tempfile

sys.dont_write_bytecode = True

import hdlmp

NAME = "lammps_parallel"


def stats_line(path):
    with open(path) as f:
        return f.read().split()


def sorted_rows(path):
    with open(path) as f:
        return sorted(l for l in f if not l.startswith("#"))


def run(c):
    api = hdlmp.CApi()
    tmp = tempfile.mkdtemp(prefix="hd_lmp_par_")
    atexit.register(shutil.rmtree, tmp, True)
    gas = os.path.join(hdlmp.EXAMPLES, "in.gas")
    base = {"n": 15, "steps": 3000, "N": 20, "e": 0.5, "data": "start.data"}
    hdlmp.lmp(gas, dict(base, mkdata=1), tmp)
    runs = {}
    for np, newton in ((1, "on"), (2, "on"), (2, "off")):
        tag = "np%d_%s" % (np, newton)
        hdlmp.lmp(gas, dict(base, usedata=1, newton=newton, log=tag + ".log",
                            stats=tag + ".stats"), tmp, np=np)
        runs[tag] = (stats_line(os.path.join(tmp, tag + ".stats")),
                     sorted_rows(os.path.join(tmp, tag + ".log")))
    s1, l1 = runs["np1_on"]
    s2, l2 = runs["np2_on"]
    print("np1: " + " ".join(s1))
    print("np2: " + " ".join(s2))
    c.check("gas has contacts (pair and wall)", float(s1[1]) > 1000 and float(s1[13]) > 10, " ".join(s1))
    c.check("gas statistics identical under -np 1 and -np 2", s1 == s2)
    c.check("gas per-contact log identical under -np 1 and -np 2",
            len(l1) == len(l2) and l1 == l2, "%d vs %d rows" % (len(l1), len(l2)))
    s3, l3 = runs["np2_off"]
    c.check("newton off: same contact count", s3[1] == s1[1] and len(l3) == len(l1))
    worst = 0.0
    same_pairs = len(l3) == len(l1)
    for a, b in zip(l1, l3):
        va, vb = [float(x) for x in a.split()], [float(x) for x in b.split()]
        same_pairs &= va[1:3] == vb[1:3]
        worst = max(worst, max(abs(x - y) / max(abs(x), 1e-300) for x, y in zip(va, vb)))
    print("newton off: largest relative difference %.2e" % worst)
    c.check("newton off: the same pairs collide", same_pairs)
    c.check("newton off: all logged values within 1e-9", worst <= 1e-9, repr(worst))

    # migration of a contact between processors
    binary = os.path.join(hdlmp.EXAMPLES, "in.binary")
    dt, N = 1.0e-7, 200
    common = {"e": 0.5, "N": N, "end": "overlap", "gap": repr(100.3 * dt)}
    at_rest = {}
    for end in ("overlap", "force"):
        hdlmp.lmp(binary, dict(common, end=end, log="rest.txt"), tmp)
        at_rest[end] = hdlmp.read_log(os.path.join(tmp, "rest.txt"))[0]
    for newton in ("on", "off"):
        for end in ("overlap", "force"):
            tag = "migration newton %s end %s" % (newton, end)
            rest = at_rest[end]
            # centre of the pair at -1.5 mm at the onset, +1.5 mm at the end
            out = hdlmp.lmp(binary, dict(common, end=end, drift=150, x0=-0.003, dump=5,
                                         newton=newton, log="m.txt"), tmp, np=2)
            res = [l for l in out.splitlines() if l.startswith("RESULT")][0].split()
            rows = hdlmp.read_log(os.path.join(tmp, "m.txt"))
            if not c.check(tag + ": one contact", len(rows) == 1 and float(res[10]) == 1, str(res)):
                continue
            r = rows[0]
            # the default constants: host lammps with the phase correction
            k, d = api.pair_kd(0.5, end, "lammps-phase", N, N * dt, r["m"], r["u_used"])
            c.check(tag + ": k, d of the onset kept (C API bit for bit)", r["k"] == k and r["d"] == d,
                    "%r %r vs %r %r" % (r["k"], r["d"], k, d))
            c.check(tag + ": carried through neighbor-list rebuilds", float(res[14]) > 0, res[14])
            c.check(tag + ": e and T_c as at rest on one processor",
                    abs(r["e"] / rest["e"] - 1) <= 1e-9 and abs(r["tc"] / rest["tc"] - 1) <= 1e-9,
                    "%r %r vs %r %r" % (r["e"], r["tc"], rest["e"], rest["tc"]))
            owner = {}
            step = None
            with open(os.path.join(tmp, "m.txt.dump")) as f:
                lines = f.read().splitlines()
            for i, l in enumerate(lines):
                if l.startswith("ITEM: TIMESTEP"):
                    step = int(lines[i + 1])
                parts = l.split()
                if len(parts) == 3 and parts[0] in ("1", "2") and not l.startswith("ITEM"):
                    owner[(step, int(parts[0]))] = int(parts[1])
            on = int(r["t_on"]) // 5 * 5 + 5
            off = int(r["t_end"]) // 5 * 5
            moved = all(owner.get((on, a)) == 0 and owner.get((off, a)) == 1 for a in (1, 2))
            c.check(tag + ": both atoms change processor during the contact", moved,
                    "%s %s" % ([owner.get((on, a)) for a in (1, 2)], [owner.get((off, a)) for a in (1, 2)]))
            print("%s: e %.12f T_c %.6e (at rest %.12f %.6e), carried %s" %
                  (tag, r["e"], r["tc"], rest["e"], rest["tc"], res[14]))


if __name__ == "__main__":
    hdlmp.main_each_flavor(NAME, run)
