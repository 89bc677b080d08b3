#!/usr/bin/env python3
"""Synthetic drop-test data for `hertzdamp calibrate` (data/calibrate/example.csv).

A steel bead of radius 1 mm dropped on a thick steel plate, at ten impact speeds
from 0.2 to 5 m/s.  The exact e(u) and T_c(u) of the chosen damping law come from the
reference integrator (`hertzdamp forward --method rk45`); then Gaussian noise is added
with a fixed seed: sigma_e = 0.005 on e and 2 % on T_c, the uncertainties written in
the sigma columns.  Usage (from the repository root, after `make build`):

    python3 tools/calibrate_example.py --bin "$(fpm run hertzdamp --runner echo)" \
        --out data/calibrate/example.csv
"""
import argparse
import math
import random
import subprocess

# steel on steel: E = 210 GPa, nu = 0.3; sphere radius R = 1 mm against a wall (R* = R)
DENSITY, YOUNG, POISSON, RADIUS = 7800.0, 210e9, 0.3, 1.0e-3
MASS = DENSITY * 4.0 / 3.0 * math.pi * RADIUS**3          # the bead against a wall
E_STAR = 1.0 / (2.0 * (1.0 - POISSON**2) / YOUNG)          # two equal materials
K = 4.0 / 3.0 * E_STAR * math.sqrt(RADIUS)                 # Hertz stiffness [N m^-3/2]
SPEEDS = [0.2, 0.3, 0.5, 0.7, 1.0, 1.5, 2.0, 3.0, 4.0, 5.0]
SIGMA_E, SIGMA_TC_REL, SEED = 0.005, 0.02, 16
# damping coefficient of each law: alpha = 0.1 at 1 m/s (e(1 m/s) about 0.83)
ALPHA_1 = 0.1


def damping(law):
    """d with alpha = ALPHA_1 at u = 1 m/s: alpha = d t* (u t*)^q / m."""
    q = {"linear": 0.0, "tsuji": 0.25, "kuwabara-kono": 0.5}[law]
    tstar = (MASS / K) ** 0.4
    return ALPHA_1 * MASS / (tstar * tstar**q)


def forward(binary, law, d, u):
    """e and T_c from the reference integrator (the CLI's CSV, 16 digits)."""
    cmd = [binary, "forward", "--k", repr(K), "--d", repr(d), "--mass", repr(MASS),
           "--velocity", repr(u), "--method", "rk45", "--format", "csv"]
    if law != "linear":
        cmd += ["--damping", law]
    out = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout.splitlines()
    row = dict(zip(out[0].split(","), out[1].split(",")))
    return float(row["e"]), float(row["t_c"])


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--bin", required=True, help="the hertzdamp executable")
    ap.add_argument("--out", required=True, help="CSV file to write")
    ap.add_argument("--damping", default="linear", choices=["linear", "tsuji", "kuwabara-kono"])
    args = ap.parse_args()
    d = damping(args.damping)
    rng = random.Random(SEED)
    lines = [
        "# Synthetic drop tests: steel bead, R = 1 mm, on a steel plate (E = 210 GPa, nu = 0.3).",
        "# Made by tools/calibrate_example.py --damping %s: exact e and tc from the reference" % args.damping,
        "# integrator, then Gaussian noise (seed %d): sigma_e = %g, sigma_tc = %g %% of tc." % (
            SEED, SIGMA_E, 100 * SIGMA_TC_REL),
        "# true values: damping = %s, k = %.6e N m^-3/2, d = %.6e (SI)" % (args.damping, K, d),
        "# mass = %.6e" % MASS,
        "velocity,e,tc,sigma_e,sigma_tc",
    ]
    for u in SPEEDS:
        e, tc = forward(args.bin, args.damping, d, u)
        e_obs = e + rng.gauss(0.0, SIGMA_E)
        s_tc = SIGMA_TC_REL * tc
        tc_obs = tc + rng.gauss(0.0, s_tc)
        lines.append("%g,%.5f,%.4e,%g,%.2e" % (u, e_obs, tc_obs, SIGMA_E, s_tc))
    with open(args.out, "w", encoding="ascii") as f:
        f.write("\n".join(lines) + "\n")
    print("wrote %s: %s law, k = %.6e, d = %.6e, mass = %.6e" % (args.out, args.damping, K, d, MASS))


if __name__ == "__main__":
    main()
