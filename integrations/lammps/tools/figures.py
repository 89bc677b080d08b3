"""Figures of the LAMMPS plugin, measured on the granular gas example
(examples/in.gas: 2925 steel beads, 20 steps per contact, e = 0.5, overlap end).

  python3 integrations/lammps/tools/figures.py [--steps S] [--repeats R] [--nphase P]

writes integrations/lammps/results/:
  phases.txt               head-on collisions at N = 20 (examples/in.phases, P evenly
                           spaced onset phases, e = 0.2, 0.5, 0.9, overlap end): mean
                           error and spread of e and T_c over the phase as LAMMPS
                           achieves them, with host lammps / none and phase yes / no,
                           next to what the plugin reports from the library
  e_vs_u.dat, e_vs_u.png   achieved e per contact against the impact speed, with
                           per-contact k and d (granular/hertzdamp steps 20) and with
                           the best single fixed (k, d) (granular/hertzdamp fixed K D),
                           which `hertzdamp invert --fixed` gives for the speed range
                           of the per-contact run (the program `make run` installs)
  speed.txt                cost per time step of granular/hertzdamp against stock
                           pair_style granular hertz ... damping velocity with that
                           fixed (k, d): medians of R runs measured side by side
  summary.txt              the numbers quoted in README.md (the gas also with host none)
Run `make lammps` first.
"""
import argparse
import csv
import io
import math
import os
import re
import statistics
import subprocess
import sys
import tempfile

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "tests"))
import hdlmp  # noqa: E402

RESULTS = os.path.join(hdlmp.ROOT, "integrations", "lammps", "results")
GAS = os.path.join(hdlmp.EXAMPLES, "in.gas")
E, NSTEP, DT = 0.5, 20, 1.0e-6


def hertzdamp_bin():
    """The hertzdamp program: $HERTZDAMP_BIN, else the one `make run` installs."""
    b = os.environ.get("HERTZDAMP_BIN") or os.path.join(hdlmp.ROOT, "build", "prefix", "bin", "hertzdamp")
    if not os.access(b, os.X_OK):
        sys.exit("figures.py: no hertzdamp program at %s: run `make run` (or set HERTZDAMP_BIN)" % b)
    return b


def best_fixed(u, m):
    """The best single fixed (k, d) over the impact speeds u, as `hertzdamp invert
    --fixed` defines it: the worst relative error of e over [min u, max u] as small as
    one pair makes it, the shortest contact of that range NSTEP steps of DT long."""
    cmd = [hertzdamp_bin(), "invert", "--fixed", "--mass", repr(m), "--e", repr(E), "--dt", repr(DT),
           "--steps", str(NSTEP), "--velocity", "%r,%r" % (min(u), max(u)), "--format", "csv", "--quiet"]
    rows = list(csv.DictReader(io.StringIO(subprocess.run(cmd, capture_output=True, text=True,
                                                          check=True).stdout)))
    return float(rows[0]["k"]), float(rows[0]["d"]), float(rows[0]["worst_e_error"]), " ".join(cmd[1:])


def timing(out):
    loop = float(re.search(r"Loop time of ([0-9.eE+-]+)", out).group(1))
    pair = float(re.search(r"^Pair\s*\|\s*([0-9.eE+-]+)", out, re.M).group(1))
    steps = int(re.search(r"for (\d+) steps", out).group(1))
    return loop / steps, pair / steps


def bins(rows, edges):
    out = []
    for lo, hi in zip(edges, edges[1:]):
        es = sorted(r["e"] for r in rows if lo <= r["u_in"] < hi)
        if len(es) < 5:
            continue
        q = lambda f: es[min(len(es) - 1, int(f * len(es)))]
        out.append((math.sqrt(lo * hi), len(es), statistics.median(es), q(0.1), q(0.9)))
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--steps", type=int, default=20000)
    ap.add_argument("--repeats", type=int, default=7)
    ap.add_argument("--nphase", type=int, default=256)
    args = ap.parse_args()
    api = hdlmp.CApi()
    tmp = tempfile.mkdtemp(prefix="hd_lmp_fig_")
    phase_table(tmp, args.nphase)
    base = {"n": 15, "steps": args.steps, "N": NSTEP, "e": E, "data": "start.data"}
    hdlmp.lmp(GAS, dict(base, mkdata=1), tmp)

    hdlmp.lmp(GAS, dict(base, usedata=1, log="adaptive.log", stats="a.stats"), tmp)
    ad = [r for r in hdlmp.read_log(os.path.join(tmp, "adaptive.log"))]
    hdlmp.lmp(GAS, dict(base, usedata=1, host="none", log="none.log", stats="n.stats"), tmp)
    an = [r for r in hdlmp.read_log(os.path.join(tmp, "none.log"))]
    m = ad[0]["m"]
    k, d, worst, fixed_cmd = best_fixed([r["u_in"] for r in ad], m)
    hdlmp.lmp(GAS, dict(base, usedata=1, rule="fixed", K=repr(k), D=repr(d), log="fixed.log",
                        stats="f.stats"), tmp)
    fx = hdlmp.read_log(os.path.join(tmp, "fixed.log"))

    umin = min(r["u_in"] for r in ad + fx)
    umax = max(r["u_in"] for r in ad + fx)
    nb = 24
    edges = [umin * (umax / umin) ** (i / nb) for i in range(nb + 1)]
    edges[-1] *= 1.0001
    ba, bf = bins(ad, edges), bins(fx, edges)
    with open(os.path.join(RESULTS, "e_vs_u.dat"), "w") as f:
        f.write("# gas: 2925 beads, %d steps, N = %d, target e = %g (overlap end)\n" % (args.steps, NSTEP, E))
        f.write("# best fixed pair: k %.6e d %.6e (hertzdamp %s: worst |e/%g - 1| %.4f)\n" % (k, d, fixed_cmd, E, worst))
        f.write("# rule u_mid count e_median e_p10 e_p90   (rule 1 = per-contact k, d; 2 = fixed k, d)\n")
        for tag, b in ((1, ba), (2, bf)):
            for row in b:
                f.write("%d %.6e %d %.6f %.6f %.6f\n" % ((tag,) + row))
        f.write("\n\n# model curve: e of the fixed pair in the continuous model (library forward)\n")
        for i in range(60):
            u = umin * (umax / umin) ** (i / 59)
            f.write("3 %.6e 0 %.6f 0 0\n" % (u, api.forward(k, d, m, u, "overlap")[0]))

    def spread(rows):
        es = sorted(r["e"] for r in rows)
        rms = math.sqrt(sum((x - E) ** 2 for x in es) / len(es))
        return statistics.median(es), es[len(es) // 10], es[9 * len(es) // 10], rms, len(es)

    sa, sn, sf = spread(ad), spread(an), spread(fx)
    gp = """set terminal pngcairo size 900,600
set output '%s'
set logscale x
set xlabel 'impact speed u_{in} (relative normal approach speed at onset) [m/s]'
set ylabel 'achieved restitution e per contact'
set key bottom right
set title 'granular gas, 2925 beads, 20 steps per contact, target e = 0.5'
set yrange [0:1]
plot '%s' index 0 u ($1==1?$2:NaN):4:5:6 with yerrorlines lw 2 title 'per-contact k, d (granular/hertzdamp): median, 10-90%%', \\
     '' index 0 u ($1==2?$2:NaN):4:5:6 with yerrorlines lw 2 title 'best single fixed (k, d): median, 10-90%%', \\
     '' index 1 u 2:4 with lines dt 2 lw 1 title 'fixed (k, d), continuous model', \\
     %g with lines lc rgb 'black' title 'target'
""" % (os.path.join(RESULTS, "e_vs_u.png"), os.path.join(RESULTS, "e_vs_u.dat"), E)
    subprocess.run(["gnuplot"], input=gp, universal_newlines=True, check=True)

    # cost per time step, side by side: hertzdamp (adaptive) vs stock granular with (k, d)
    t_hd, t_st, p_hd, p_st, ratio, pratio = [], [], [], [], [], []
    for _ in range(args.repeats):
        a = timing(hdlmp.lmp(GAS, dict(base, usedata=1, log="t.log", stats="t.stats"), tmp))
        s = timing(hdlmp.lmp(GAS, dict(base, usedata=1, rule="stock", K=repr(k), D=repr(d),
                                       log="t.log", stats="t.stats"), tmp))
        t_hd.append(a[0]); t_st.append(s[0]); p_hd.append(a[1]); p_st.append(s[1])
        ratio.append(a[0] / s[0]); pratio.append(a[1] / s[1])
    med = statistics.median
    with open(os.path.join(RESULTS, "speed.txt"), "w") as f:
        f.write("# cost per time step, gas example (2925 beads, %d steps, 1 process), %d pairs of runs side by side\n" % (args.steps, args.repeats))
        f.write("# run hertzdamp_loop_s stock_loop_s hertzdamp_pair_s stock_pair_s loop_ratio pair_ratio\n")
        for i in range(args.repeats):
            f.write("%d %.4e %.4e %.4e %.4e %.4f %.4f\n" % (i + 1, t_hd[i], t_st[i], p_hd[i], p_st[i], ratio[i], pratio[i]))
        f.write("median %.4e %.4e %.4e %.4e %.4f %.4f\n" % (med(t_hd), med(t_st), med(p_hd), med(p_st), med(ratio), med(pratio)))
    with open(os.path.join(RESULTS, "summary.txt"), "w") as f:
        f.write("command: python3 integrations/lammps/tools/figures.py --steps %d --repeats %d\n" % (args.steps, args.repeats))
        f.write("best fixed pair: k %.6e N/m^1.5, d %.6e kg/s, worst |e/%g - 1| %.4f over the speeds of the per-contact run "
                "(hertzdamp %s)\n" % (k, d, E, worst, fixed_cmd))
        f.write("impact speeds: %.4g .. %.4g m/s\n" % (umin, umax))
        for name, s in (("per-contact k, d", sa), ("  with host none", sn), ("fixed k, d", sf)):
            f.write("%-17s contacts %d, e median %.4f, 10%%..90%% %.4f..%.4f, rms(e - %.1f) %.4f\n" % ((name, s[4], s[0], s[1], s[2], E, s[3])))
        f.write("cost per step, median of %d: loop %.4f x stock, pair %.4f x stock\n" % (args.repeats, med(ratio), med(pratio)))
        f.write(open(os.path.join(RESULTS, "phases.txt")).read())
    print(open(os.path.join(RESULTS, "summary.txt")).read())


def phase_table(tmp, nphase):
    """results/phases.txt: examples/in.phases (N = 20, overlap end) at nphase onset phases
    per e: mean error and standard deviation over the phase of e and T_c, in LAMMPS and as
    the plugin reports them (library phase statistics of the constants)."""
    targets = (0.2, 0.5, 0.9)
    lines = ["head-on, N = 20, overlap end, %d evenly spaced onset phases per e (examples/in.phases, "
             "both LAMMPS versions give the same); errors in %% of the target, spreads (standard deviation "
             "over the phase) in %% of the mean:" % nphase,
             "| host | phase | e | mean e error | e sd | mean T_c error | T_c sd | reported: mean e error, e sd |",
             "|---|---|---|---|---|---|---|---|"]
    for host, phase in (("lammps", "yes"), ("lammps", "no"), ("none", "yes"), ("none", "no")):
        out = hdlmp.lmp(os.path.join(hdlmp.EXAMPLES, "in.phases"),
                        {"host": host, "phase": phase, "nphase": nphase, "log": "ph.txt", "wlog": "phw.txt"}, tmp)
        rows = hdlmp.read_log(os.path.join(tmp, "ph.txt"))
        pred = {}
        for line in out.splitlines():
            w = line.split()
            if w and w[0] == "PREDICTED" and w[1] != "wall":
                pred[targets[int(w[1]) - 1]] = [float(x) for x in w[3:7]]
        for t, e in enumerate(targets, 1):
            rr = [r for r in rows if 2 * nphase * (t - 1) < r["tag_i"] <= 2 * nphase * t]
            es = [r["e"] / e for r in rr]
            ts = [r["tc"] / (NSTEP * 1.0e-7) for r in rr]
            p = pred[e]
            # spreads relative to the mean (as the CLI's e_spread, tc_spread and the plugin report them)
            lines.append("| %s | %s | %.1f | %+.3f %% | %.3f %% | %+.4f %% | %.3f %% | %+.3f %%, %.3f %% |" % (
                host, phase, e, 100 * (statistics.mean(es) - 1), 100 * statistics.pstdev(es) / statistics.mean(es),
                100 * (statistics.mean(ts) - 1), 100 * statistics.pstdev(ts) / statistics.mean(ts),
                100 * (p[0] / e - 1), 100 * p[1]))
    with open(os.path.join(RESULTS, "phases.txt"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
