"""Cost of pair_style granular/hertzdamp against stock pair_style granular on the pour
deck (examples/in.pour: LAMMPS's in.pour.flatwall, 2 x npour beads, the same tangential,
rolling and twisting sub-models in every mode), one process:

  python3 integrations/lammps/tools/bench_pour.py [--flavor pypi|debian] [--npour 1500]
                                                  [--steps 5000] [--repeat 5]

Runs the modes stock (hertz kn D damping velocity), fixed (granular/hertzdamp fixed K D)
and hertzdamp (per-contact k and d, steps 10) one after the other, `repeat` times, and
prints the median loop time and pair time of each and their ratios to stock.
"""
import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "tests"))
sys.dont_write_bytecode = True
import hdlmp  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--flavor", default="pypi", choices=hdlmp.FLAVORS)
    ap.add_argument("--npour", type=int, default=1500)
    ap.add_argument("--steps", type=int, default=5000)
    ap.add_argument("--repeat", type=int, default=5)
    a = ap.parse_args()
    tmp = tempfile.mkdtemp(prefix="hd_bench_pour_")
    modes = ("stock", "fixed", "hertzdamp")
    times = {m: {"loop": [], "pair": [], "contacts": []} for m in modes}
    for _ in range(a.repeat):
        for m in modes:
            out = hdlmp.lmp(os.path.join(hdlmp.EXAMPLES, "in.pour"),
                            {"rule": m, "npour": a.npour, "steps": a.steps, "log": "none.txt"}, tmp,
                            flavor=a.flavor)
            loop = [float(x) for x in re.findall(r"Loop time of (\S+) on 1 procs for %d steps" % a.steps, out)]
            pair = [float(x) for x in re.findall(r"^Pair +\| +\S+ +\| +(\S+)", out, re.M)]
            times[m]["loop"].append(loop[0])
            times[m]["pair"].append(pair[0])
    print("pour deck, LAMMPS %s, 2 x %d beads, %d steps, %d runs of each mode, alternated; medians:" %
          (a.flavor, a.npour, a.steps, a.repeat))
    ref = {k: statistics.median(times["stock"][k]) for k in ("loop", "pair")}
    for m in modes:
        loop, pair = statistics.median(times[m]["loop"]), statistics.median(times[m]["pair"])
        print("  %-10s loop %8.3f s (%.2fx stock, runs %s)  pair %8.3f s (%.2fx stock)" %
              (m, loop, loop / ref["loop"], " ".join("%.2f" % x for x in times[m]["loop"]), pair,
               pair / ref["pair"]))


if __name__ == "__main__":
    main()
