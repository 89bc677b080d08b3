#!/usr/bin/env python3
"""Are the force-end targets that the onset-phase table refuses really unreachable? (issue 32)

An independent search, sharing no code with the library: for a target e and N steps per
contact (force end, one law, the lammps / mfix-euler scheme: a from the state, v += h a,
z += h v, as test/unit/test_phase.f90's own stepper), at each of M stratified onset phases
phi, for every dimensionless step h of a fine grid the damping alpha(h) with e_host = e
(bisection on alpha, vectorised over h), and along that curve the contact-time residual
g(h) = tau_host / (N h) - 1.  Constants for that contact exist where g crosses 0 on the
curve; where it only jumps over 0, the best reachable T_c misses N dt by min |g|.
Prints, per phase, min |g| over the curve and whether g changes sign continuously (a sign
change between neighbouring grid points with |g| below 1e-3 on both sides).

    python3 tools/phase_force_reach.py [E] [N] [LAW] [M]     (defaults 0.9 10 linear 64)
"""
import sys
import numpy as np

E = float(sys.argv[1]) if len(sys.argv) > 1 else 0.9
N = float(sys.argv[2]) if len(sys.argv) > 2 else 10.0
LAW = sys.argv[3] if len(sys.argv) > 3 else "linear"
M = int(sys.argv[4]) if len(sys.argv) > 4 else 64
Q = {"linear": 0.0, "tsuji": 0.25, "kuwabara-kono": 0.5}[LAW]


def collide(alpha, h, phi):
    """e and tau (touch to release) of the force end, arrays alpha, h; one phase."""
    z = (phi - 1.0) * h
    v = np.ones_like(h)
    a = np.zeros_like(h)
    fl = np.zeros_like(h)
    t = np.zeros_like(h)
    trel = np.full_like(h, np.nan)
    released = np.zeros(h.shape, bool)
    for n in range(100000):
        v = v + h * a
        z = z + h * v
        t = t + h
        a = np.zeros_like(h)
        inside = z > 0.0
        zq = np.where(inside, np.maximum(z, 0.0) ** Q if Q > 0 else 1.0, 0.0)
        f = np.where(inside, np.maximum(z, 0.0) ** 1.5 + alpha * zq * v, 0.0)
        clip = inside & ~(f > 0.0)
        newrel = ~released & (clip | (~inside & (n > 0)))
        # release: the force zero (linear in the unclipped force) or, overlap gone first,
        # the overlap zero is not needed here: tau from the last positive force sample
        frac = np.where(clip, fl / np.where(fl - f == 0, 1.0, fl - f), 1.0)
        trel = np.where(newrel, t - h + h * frac, trel)
        released |= newrel
        act = inside & (f > 0.0)
        a = np.where(act, -f, 0.0)
        fl = np.where(act & ~released, f, fl)
        if released.all() and not (act.any()):
            break
    e = -v
    tau = trel - (1.0 - phi) * h
    return e, tau


def search(phi, hs):
    lo = np.zeros_like(hs)
    hi = np.full_like(hs, 2.0)
    for _ in range(50):
        mid = 0.5 * (lo + hi)
        e, _ = collide(mid, hs, phi)
        up = e >= E          # e falls with alpha: alpha too small
        lo = np.where(up, mid, lo)
        hi = np.where(up, hi, mid)
    e, tau = collide(lo, hs, phi)
    g = tau / (N * hs) - 1.0
    ok_e = np.abs(e / E - 1.0) < 1e-6
    return g, ok_e


hs = np.linspace(0.02, 1.2, 2400) * 3.2 / N
worst = 0.0
print(f"# e = {E}, N = {N}, {LAW}, force end, lammps/mfix-euler; {M} phases, {hs.size} steps h")
print("# phi  min|g| (T_c miss)  continuous zero of g")
for j in range(M):
    phi = (j + 0.5) / M
    g, ok = search(phi, hs)
    g = np.where(ok, g, np.nan)
    mg = np.nanmin(np.abs(g))
    s = np.sign(g)
    cross = np.where((s[:-1] * s[1:] < 0) & (np.abs(g[:-1]) < 1e-3) & (np.abs(g[1:]) < 1e-3))[0]
    worst = max(worst, mg if cross.size == 0 else 0.0)
    print(f"{phi:6.4f}  {mg:9.2e}  {'yes' if cross.size else 'no'}")
print(f"# largest T_c miss of a phase without a continuous zero: {worst:.2e}")
