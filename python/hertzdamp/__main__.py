"""python -m hertzdamp: the version, where the core library was loaded from, and one check."""
import sys

import numpy as np

import hertzdamp


def main() -> int:
    print(f"hertzdamp {hertzdamp.__version__}")
    print(f"library: {hertzdamp.library_path}")
    print(f"numpy {np.__version__}, Python {sys.version.split()[0]}")
    print(f"laws: {' '.join(hertzdamp.LAWS)}; ends: {' '.join(hertzdamp.ENDS)}; hosts: {' '.join(hertzdamp.HOSTS)}")
    # the README's glass beads: e = 0.9 in 10 steps of 1 us at 1 m/s, and back
    k, d = hertzdamp.invert(0.9, 1e-5, 5.235987755982989e-06, 1.0)
    e, tc = hertzdamp.forward(k, d, 5.235987755982989e-06, 1.0)
    print(f"check: invert(e=0.9, tc=1e-5, m=5.236e-6, u=1) = k {k:.6e}, d {d:.6e}; forward gives e {e:.12f}, "
          f"tc {tc:.6e}")
    return 0 if abs(e - 0.9) < 1e-9 and abs(tc / 1e-5 - 1) < 1e-9 else 1


if __name__ == "__main__":
    sys.exit(main())
