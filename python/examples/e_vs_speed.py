"""Restitution against impact speed: one fixed (k, d) against the rule (k, d per contact).

The README's glass beads (two of radius 1 mm, 2500 kg/m^3, E = 63 GPa, nu = 0.24): a
fixed k = 1e9 N m^-3/2, d = 0.5 kg/s gives e that drifts with the speed (alpha ~ u^-1/5);
the rule, hertzdamp.invert for e = 0.9 in T_c = 10 us with the material's stiffness as
the bound, gives every contact e = 0.9 (hertzdamp.forward checks it).  Prints the table;
with matplotlib (optional) also writes the plot:

    python python/examples/e_vs_speed.py [--plot e_vs_speed.png]
"""
import argparse
import sys

import numpy as np

import hertzdamp


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--plot", help="write the plot to this file (needs matplotlib)")
    args = ap.parse_args()

    m, r, k_phys = hertzdamp.materials(1e-3, 2500, 63e9, 0.24)
    u = np.geomspace(0.01, 5, 12)
    e_fixed, tc_fixed = hertzdamp.forward(1e9, 0.5, m, u)
    k, d = hertzdamp.invert(0.9, 1e-5, m, u, k_phys=k_phys)
    e_rule, tc_rule = hertzdamp.forward(k, d, m, u)
    print(f"# glass beads: m_eff = {m:.6g} kg, r_eff = {r:.6g} m, k_phys = {k_phys:.6g} N m^-3/2")
    print(f"{'u [m/s]':>10} {'e fixed':>10} {'e rule':>14} {'k rule':>12} {'d rule':>12} {'tc rule [s]':>12}")
    for row in zip(u, e_fixed, e_rule, k, d, tc_rule):
        print("{:10.4g} {:10.6f} {:14.12f} {:12.5g} {:12.5g} {:12.5g}".format(*row))
    if args.plot:
        try:
            import matplotlib
            matplotlib.use("Agg")
            import matplotlib.pyplot as plt
        except ImportError:
            print("e_vs_speed: no plot: matplotlib is not installed (pip install matplotlib)", file=sys.stderr)
            return 2
        fig, ax = plt.subplots(figsize=(6, 4))
        ax.semilogx(u, e_fixed, "o-", label="fixed k = 1e9, d = 0.5")
        ax.semilogx(u, e_rule, "s-", label="hertzdamp.invert per contact (e = 0.9, T_c = 10 us)")
        ax.set_xlabel("impact speed u [m/s]")
        ax.set_ylabel("restitution coefficient e")
        ax.legend()
        fig.tight_layout()
        fig.savefig(args.plot, dpi=120)
        print(f"e_vs_speed: wrote {args.plot}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
