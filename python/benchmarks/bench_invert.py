"""Speed of the package against the C entry point it wraps, timed in one process.

For n contacts (default 10^6): hertzdamp.invert(e, tc, m, u) against
hertzdamp_c_invert_n on the same arrays (called through ctypes with its outputs
allocated beforehand), alternated, the median of --repeats runs each; and the broadcast
form (e, tc scalars: stride 0, no copy) against the C call on full arrays.  Then the
fixed overhead of one call: hertzdamp.invert of one contact (floats in, floats out)
against a bare ctypes call of hertzdamp_c_invert_law.  Prints the machine's load.

    .venv/bin/python python/benchmarks/bench_invert.py [--n 1000000] [--repeats 15]
"""
import argparse
import ctypes
import os
import statistics
import time

import numpy as np

import hertzdamp
from hertzdamp._lib import lib


def median_time(fn, repeats):
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


def alternated(fa, fb, repeats):
    """Medians of fa and fb, run in turns (so that a change of load hits both)."""
    ta, tb = [], []
    for _ in range(repeats):
        for f, t in ((fa, ta), (fb, tb)):
            t0 = time.perf_counter()
            f()
            t.append(time.perf_counter() - t0)
    return statistics.median(ta), statistics.median(tb)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--n", type=int, default=1_000_000)
    ap.add_argument("--repeats", type=int, default=15)
    args = ap.parse_args()
    n = args.n
    rng = np.random.default_rng(1)
    e = rng.uniform(0.1, 0.99, n)
    tc = 10 ** rng.uniform(-6, -4, n)
    m = 10 ** rng.uniform(-7, -3, n)
    u = 10 ** rng.uniform(-2, 1, n)
    k, d, st = np.empty(n), np.empty(n), np.empty(n, dtype=np.intc)
    overlap = lib.codes["end"]["overlap"]

    def c_call():
        lib.invert_n(n, e.ctypes.data, tc.ctypes.data, m.ctypes.data, u.ctypes.data, overlap, k.ctypes.data,
                     d.ctypes.data, st.ctypes.data)

    c_call()
    kp, dp = hertzdamp.invert(e, tc, m, u)
    assert np.array_equal(k, kp) and np.array_equal(d, dp)
    print(f"load before: {os.getloadavg()[0]:.2f} (1-min average), {os.cpu_count()} cores")
    tp, tcal = alternated(lambda: hertzdamp.invert(e, tc, m, u), c_call, args.repeats)
    print(f"n = {n}: hertzdamp.invert {tp * 1e3:.2f} ms, hertzdamp_c_invert_n {tcal * 1e3:.2f} ms: "
          f"ratio {tp / tcal:.3f} ({tp / n * 1e9:.1f} vs {tcal / n * 1e9:.1f} ns per contact; medians of "
          f"{args.repeats} alternated)")
    e_full, tc_full = np.full(n, 0.7), np.full(n, 1e-5)

    def c_full():
        lib.invert_n(n, e_full.ctypes.data, tc_full.ctypes.data, m.ctypes.data, u.ctypes.data, overlap, k.ctypes.data,
                     d.ctypes.data, st.ctypes.data)

    tp2, tc2 = alternated(lambda: hertzdamp.invert(0.7, 1e-5, m, u), c_full, args.repeats)
    print(f"broadcast e, tc (stride 0): hertzdamp.invert {tp2 * 1e3:.2f} ms, hertzdamp_c_invert_n on full arrays "
          f"{tc2 * 1e3:.2f} ms: ratio {tp2 / tc2:.3f}")

    kk, dd = ctypes.c_double(), ctypes.c_double()
    law, end = lib.codes["law"]["linear"], lib.codes["end"]["overlap"]
    pk, pd = ctypes.addressof(kk), ctypes.addressof(dd)
    calls = 20000
    one_py = lambda: [hertzdamp.invert(0.9, 1e-5, 5.2e-6, 1.0) for _ in range(calls)]
    one_c = lambda: [lib.invert_law(0.9, 1e-5, 5.2e-6, 1.0, 0.0, law, end, pk, pd) for _ in range(calls)]
    t1, t0 = alternated(one_py, one_c, 7)
    print(f"one contact: hertzdamp.invert {t1 / calls * 1e6:.1f} us per call, a bare ctypes call of "
          f"hertzdamp_c_invert_law {t0 / calls * 1e6:.2f} us (medians of 7 runs of {calls} calls)")
    print(f"load after: {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()
