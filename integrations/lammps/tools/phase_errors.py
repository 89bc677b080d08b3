"""The largest single-contact error of e and T_c in real LAMMPS with phase exact, yes and no
(examples/in.phases: head-on pairs for e = 0.2, 0.5, 0.9 and beads on a wall at e = 0.5, at
`nphase` evenly spaced onset phases), N = 10 and 20, on both LAMMPS versions:

  python3 integrations/lammps/tools/phase_errors.py [--nphase 16]

Prints a markdown table: |e - target| and |T_c / (N dt) - 1| at their largest over the
contacts of each target (pairs; the wall at e = 0.5 in the last column).
"""
import argparse
import os
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "tests"))
sys.dont_write_bytecode = True
import hdlmp  # noqa: E402

TARGETS, DT = (0.2, 0.5, 0.9), 1.0e-7


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--nphase", type=int, default=16)
    a = ap.parse_args()
    tmp = tempfile.mkdtemp(prefix="hd_phase_errors_")
    print("| LAMMPS | phase | N | e = 0.2: e, T_c | e = 0.5 | e = 0.9 | wall, e = 0.5 |")
    print("|---|---|---|---|---|---|---|")
    try:
        for flavor in hdlmp.FLAVORS:
            hdlmp.CURRENT[0] = flavor
            for n in (10, 20):
                for phase in ("exact", "yes", "no"):
                    v = {"N": n, "nphase": a.nphase, "phase": phase, "log": "p.txt", "wlog": "w.txt"}
                    hdlmp.lmp(os.path.join(hdlmp.EXAMPLES, "in.phases"), v, tmp)
                    rows = hdlmp.read_log(os.path.join(tmp, "p.txt"))
                    groups = [(e, [r for r in rows if 2 * a.nphase * t < r["tag_i"] <= 2 * a.nphase * (t + 1)])
                              for t, e in enumerate(TARGETS)]
                    groups.append((0.5, hdlmp.read_log(os.path.join(tmp, "w.txt"))))
                    cells = []
                    for e, g in groups:
                        de = max(abs(r["e"] - e) for r in g)
                        dt = max(abs(r["tc"] / (n * DT) - 1) for r in g)
                        cells.append("%.1e, %.1e" % (de, dt))
                    print("| %s | %s | %d | %s |" % ({"debian": "2021", "pypi": "2025"}[flavor], phase, n,
                                                     " | ".join(cells)))
    finally:
        shutil.rmtree(tmp, True)


if __name__ == "__main__":
    main()
