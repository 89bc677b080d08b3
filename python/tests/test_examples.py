"""The examples of python/examples run and show what they say."""
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


def run(*args):
    p = subprocess.run([sys.executable, *map(str, args)], capture_output=True, text=True, timeout=600)
    return p.returncode, p.stdout, p.stderr


def test_e_vs_speed():
    rc, out, err = run(EXAMPLES / "e_vs_speed.py")
    assert rc == 0, err
    rows = np.array([[float(x) for x in line.split()] for line in out.splitlines() if not line.lstrip()[:1].isalpha()
                     and not line.startswith("#")])
    u, e_fixed, e_rule, k, d, tc = rows.T
    assert len(u) == 12 and np.all(np.diff(e_fixed) > 0)        # a fixed pair: e rises with u (alpha ~ u^-1/5)
    assert e_fixed[0] == pytest.approx(0.388827, abs=1e-6) and e_fixed[-1] == pytest.approx(0.781528, abs=1e-6)
    assert np.all(np.abs(e_rule - 0.9) < 1e-11)                 # the rule: e = 0.9 at every speed
    assert np.all(tc >= 1e-5 * (1 - 1e-4))                      # T_c, or longer where k = k_phys
    assert "k_phys = 9.9655e+08" in out


@pytest.mark.lammps
def test_lammps_pairs():
    load = os.environ.get("HERTZDAMP_LAMMPS_LOAD")
    if not load:
        pytest.skip("HERTZDAMP_LAMMPS_LOAD is not set (build/lammps/load.lmp of make lammps)")
    rc, out, err = run(EXAMPLES / "lammps_pairs.py", "--load", load)
    assert rc == 0, out + err
    assert out.count("\n") == 5 and "both runs within the predicted range" in out
