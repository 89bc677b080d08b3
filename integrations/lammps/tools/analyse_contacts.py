"""Summarise a per-contact log of granular/hertzdamp or hertzdamp/wall (`log FILE`).

  python3 analyse_contacts.py FILE [--dt DT] [--target E]

Prints the number of contacts, the ranges of impact speed u_in, k and d, and the
achieved e and contact time (median, 10 %..90 %), overall and per decade of u_in, over
the isolated binary collisions (log column `isolated`: no other contact meanwhile, impact
speed not raised to vmin), as compute hertzdamp/stats does; --all takes every contact.
"""
import argparse
import math
import statistics

COLS = ["t_on", "tag_i", "tag_j", "m", "u_in", "u_used", "k", "d", "bounded", "tc",
        "u_out", "e", "t_end", "isolated"]


def pct(xs, f):
    xs = sorted(xs)
    return xs[min(len(xs) - 1, int(f * len(xs)))]


def line(name, rows, target):
    es = [r["e"] for r in rows]
    s = "%-16s %6d contacts  e median %.4f  10%%..90%% %.4f..%.4f" % (
        name, len(rows), statistics.median(es), pct(es, 0.1), pct(es, 0.9))
    if target is not None:
        s += "  rms(e - %g) %.4f" % (target, math.sqrt(sum((x - target) ** 2 for x in es) / len(es)))
    steps = [r["t_end"] - r["t_on"] for r in rows]
    return s + "  T_c median %.2f steps" % statistics.median(steps)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("file")
    ap.add_argument("--target", type=float, default=None)
    ap.add_argument("--all", action="store_true", help="every contact, not only isolated collisions")
    a = ap.parse_args()
    rows = []
    with open(a.file) as f:
        for l in f:
            if l.strip() and not l.startswith("#"):
                rows.append(dict(zip(COLS, map(float, l.split()))))
    if not rows:
        print("no finished contacts")
        return
    for name, key in (("u_in", "u_in"), ("k", "k"), ("d", "d")):
        print("%-10s %.6g .. %.6g   (all %d contacts)" % (name, min(r[key] for r in rows),
                                                          max(r[key] for r in rows), len(rows)))
    print("k = k_phys in %d contacts" % sum(1 for r in rows if r["bounded"]))
    if not a.all:
        rows = [r for r in rows if r.get("isolated", 1.0) == 1.0]
        print("%d isolated binary collisions (the rest had other contacts meanwhile, or an impact "
              "speed below vmin)" % len(rows))
        if not rows:
            return
    walls = [r for r in rows if r["tag_j"] < 0]
    pairs = [r for r in rows if r["tag_j"] > 0]
    for name, sel in (("particle pairs", pairs), ("wall", walls)):
        if sel:
            print(line(name, sel, a.target))
    speeds = [r["u_in"] for r in pairs or rows if r["u_in"] > 0]
    if not speeds:
        return
    lo = math.floor(math.log10(min(speeds)))
    hi = math.ceil(math.log10(max(speeds)))
    for p in range(lo, hi):
        sel = [r for r in pairs if 10 ** p <= r["u_in"] < 10 ** (p + 1)]
        if sel:
            print(line("  u_in 1e%+d..1e%+d" % (p, p + 1), sel, a.target))


if __name__ == "__main__":
    main()
