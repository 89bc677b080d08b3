"""MPI messages per time step of pair_style granular/hertzdamp against stock pair_style
granular, on the pour deck (examples/in.pour, rule hertzdamp or stock), counted with
tools/mpi_count.c (an LD_PRELOAD library on the MPI profiling interface):

  python3 integrations/lammps/tools/count_messages.py [--np 2 4] [--npour 300]
                                                     [--steps 1000 2000]

Each mode runs twice, for steps S1 and S2 (after the same pour set-up); the difference of
the counts over S2 - S1 steps is what a time step costs: point-to-point sends per process
and step, their bytes, collective calls per process and step.  Oversubscribed runs are
fine for counting (not for timing).
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "tests"))
sys.dont_write_bytecode = True
import hdlmp  # noqa: E402

MPICC = {"debian": "/usr/bin/mpicc", "pypi": os.path.join(hdlmp.ROOT, ".venv", "bin", "mpicc")}


def shim(flavor, tmp):
    out = os.path.join(tmp, "mpi_count_%s.so" % flavor)
    src = os.path.join(os.path.dirname(os.path.abspath(__file__)), "mpi_count.c")
    subprocess.run([MPICC[flavor], "-shared", "-fPIC", "-O2", "-o", out, src], check=True)
    return out


def count(flavor, lib, np, v, tmp):
    env = ["-x", "LD_PRELOAD=" + lib] if flavor == "debian" else ["-genv", "LD_PRELOAD", lib]
    cmd = hdlmp.MPIRUN[flavor] + env + ["-np", str(np), hdlmp.lmp_exe(flavor), "-in",
                                        os.path.join(hdlmp.EXAMPLES, "in.pour"), "-log", "none",
                                        "-var", "load", hdlmp.LOAD]
    for k, x in v.items():
        cmd += ["-var", k, str(x)]
    r = subprocess.run(cmd, cwd=tmp, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, universal_newlines=True)
    rows = [list(map(int, m)) for m in re.findall(r"MPICOUNT rank \d+ send (\d+) bytes (\d+) coll (\d+)", r.stdout)]
    if r.returncode != 0 or len(rows) != np:
        sys.stderr.write(r.stdout[-2000:])
        raise RuntimeError("run failed: " + " ".join(cmd))
    return [sum(x[k] for x in rows) / np for k in range(3)]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--np", type=int, nargs="+", default=[2, 4])
    ap.add_argument("--npour", type=int, default=300)
    ap.add_argument("--steps", type=int, nargs=2, default=[1000, 2000])
    ap.add_argument("--flavors", nargs="+", default=list(hdlmp.FLAVORS))
    a = ap.parse_args()
    tmp = tempfile.mkdtemp(prefix="hd_count_")
    s1, s2 = a.steps
    print("MPI messages per process and time step, pour deck (2 x %d beads), steps %d..%d:" % (a.npour, s1, s2))
    for flavor in a.flavors:
        lib = shim(flavor, tmp)
        for np in a.np:
            res = {}
            for mode in ("stock", "hertzdamp"):
                c1 = count(flavor, lib, np, {"rule": mode, "npour": a.npour, "steps": s1}, tmp)
                c2 = count(flavor, lib, np, {"rule": mode, "npour": a.npour, "steps": s2}, tmp)
                res[mode] = [(y - x) / (s2 - s1) for x, y in zip(c1, c2)]
            st, hd = res["stock"], res["hertzdamp"]
            print("  %-6s -np %d: stock %.2f sends (%.0f bytes), %.3f collectives; granular/hertzdamp %.2f sends "
                  "(%.0f bytes), %.3f collectives; ratio of sends %.2f"
                  % (flavor, np, st[0], st[1], st[2], hd[0], hd[1], hd[2], hd[0] / st[0] if st[0] else 0.0))


if __name__ == "__main__":
    main()
