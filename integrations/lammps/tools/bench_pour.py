"""Cost of pair_style granular/hertzdamp against stock pair_style granular on the pour
deck (examples/in.pour: LAMMPS's in.pour.flatwall, 2 x npour beads, the same tangential,
rolling and twisting sub-models in every mode):

  python3 integrations/lammps/tools/bench_pour.py [--flavor pypi|debian] [--npour 1500]
                                                  [--steps 5000] [--repeat 5] [--np 1]
                                                  [--modes stock,fixed,hertzdamp,hertzdamp+log,hertzdamp+nocorr]

Runs the modes stock (hertz kn D damping velocity), fixed (granular/hertzdamp fixed K D),
hertzdamp (per-contact k and d, steps 10, no log), hertzdamp+log (the same with the
per-contact log) and hertzdamp+nocorr (normal_correction no: without the oblique normal
correction) one after the other, `repeat` times, under mpirun -np NP when NP > 1, and
prints the medians of the whole run (the process's wall clock: start-up, pour, loop,
the log's last flush), of the loop time and of the pair time of each, and their ratios
to stock, with the load average before and after.
"""
import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "tests"))
sys.dont_write_bytecode = True
import hdlmp  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--flavor", default="pypi", choices=hdlmp.FLAVORS)
    ap.add_argument("--npour", type=int, default=1500)
    ap.add_argument("--steps", type=int, default=5000)
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--np", type=int, default=1)
    ap.add_argument("--modes", default="stock,fixed,hertzdamp,hertzdamp+log")
    a = ap.parse_args()
    tmp = tempfile.mkdtemp(prefix="hd_bench_pour_")
    modes = a.modes.split(",")
    times = {m: {"run": [], "loop": [], "pair": []} for m in modes}
    load0 = os.getloadavg()
    for _ in range(a.repeat):
        for m in modes:
            v = {"rule": m.split("+")[0], "npour": a.npour, "steps": a.steps,
                 "log": "pour_contacts.txt" if m.endswith("+log") else "none",
                 "hdopts": "normal_correction no" if m.endswith("+nocorr") else ""}
            t0 = time.perf_counter()
            out = hdlmp.lmp(os.path.join(hdlmp.EXAMPLES, "in.pour"), v, tmp, np=a.np, flavor=a.flavor)
            times[m]["run"].append(time.perf_counter() - t0)
            loop = [float(x) for x in re.findall(r"Loop time of (\S+) on \d+ procs for %d steps" % a.steps, out)]
            pair = [float(x) for x in re.findall(r"^Pair +\| +\S+ +\| +(\S+)", out, re.M)]
            times[m]["loop"].append(loop[0])
            times[m]["pair"].append(pair[0])
    load1 = os.getloadavg()
    print("pour deck, LAMMPS %s, -np %d, 2 x %d beads, %d steps, %d runs of each mode, alternated; medians "
          "(load average %.2f before, %.2f after, %d cores):" % (a.flavor, a.np, a.npour, a.steps, a.repeat,
                                                               load0[0], load1[0], os.cpu_count()))
    ref = {k: statistics.median(times[modes[0]][k]) for k in ("run", "loop", "pair")}
    for m in modes:
        med = {k: statistics.median(times[m][k]) for k in ("run", "loop", "pair")}
        print("  %-14s run %7.3f s (%.2fx)  loop %7.3f s (%.2fx, runs %s)  pair %7.3f s (%.2fx)" %
              (m, med["run"], med["run"] / ref["run"], med["loop"], med["loop"] / ref["loop"],
               " ".join("%.2f" % x for x in times[m]["loop"]), med["pair"], med["pair"] / ref["pair"]))


if __name__ == "__main__":
    main()
