"""The Python code shown in README.md (section 7) and doc/python.md runs and gives the
numbers its comments state."""
import re
from pathlib import Path

import numpy as np
import pytest

import hertzdamp

ROOT = Path(__file__).resolve().parents[2]


def readme_block():
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    section = text.split("\n## 7. From Python\n", 1)[1].split("\n## ", 1)[0]
    return "\n".join(line[4:] for line in section.splitlines() if line.startswith("    "))


def guide_block():
    text = (ROOT / "doc" / "python.md").read_text(encoding="utf-8")
    return re.search(r"## A first session\n.*?```python\n(.*?)```", text, re.S).group(1)


pytestmark = pytest.mark.skipif(not (ROOT / "README.md").is_file(), reason="no README.md beside the tests")


def test_readme_section_7():
    ns = {}
    exec(compile(readme_block(), "README.md section 7", "exec"), ns)
    assert np.all(np.abs(ns["e"] - 0.9) < 1e-12)
    assert ns["pair"].min_steps <= 20 and ns["m"] == pytest.approx(5.235988e-06, rel=1e-6)


def test_guide_first_session():
    ns = {}
    exec(compile(guide_block(), "doc/python.md", "exec"), ns)
    assert np.all(np.abs(ns["e"] - 0.9) < 1e-12)
    assert (f"{ns['m']:.3e}", f"{ns['r']:.0e}", f"{ns['k_phys']:.3e}") == ("5.236e-06", "5e-04", "9.965e+08")
    assert f"{ns['dt_max']:.6e}" == "4.578466e-07"
    assert (round(ns["spread"], 4), ns["n_min"]) == (0.0165, 3)
    # n_min is the fewest N the pair init accepts: N - 1 is refused, N .. N + 3 are not
    n_min = ns["n_min"]
    with pytest.raises(hertzdamp.HertzdampError):
        hertzdamp.Pair(0.2, host="lammps", steps=n_min - 1)
    for n in range(n_min, n_min + 4):
        hertzdamp.Pair(0.2, host="lammps", steps=n)
    assert ns["k20"].shape == (5,)
