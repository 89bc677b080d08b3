"""invert then forward (the fit) gives back e and T_c to 1e-11, every law and end, and
the reference integrator agrees with the fit's inverse."""
import numpy as np
import pytest

import hertzdamp


@pytest.mark.parametrize("law", hertzdamp.LAWS)
@pytest.mark.parametrize("end", hertzdamp.ENDS)
def test_invert_then_forward(law, end):
    rng = np.random.default_rng(7)
    e_min = 1e-3 if end == "overlap" and law == "linear" else 1e-4
    e = np.concatenate([np.geomspace(e_min, 1, 200), rng.uniform(e_min, 1, 200)])
    tc = 10 ** rng.uniform(-7, -3, e.size)
    m = 10 ** rng.uniform(-9, 1, e.size)
    u = 10 ** rng.uniform(-3, 2, e.size)
    k, d = hertzdamp.invert(e, tc, m, u, law=law, end=end)
    e2, tc2 = hertzdamp.forward(k, d, m, u, law=law, end=end)
    assert np.max(np.abs(e2 - e) / e) < 1e-11
    assert np.max(np.abs(tc2 / tc - 1)) < 1e-11


@pytest.mark.parametrize("law", hertzdamp.LAWS)
def test_invert_then_rk45(law):
    e = np.array([0.05, 0.3, 0.6, 0.9, 0.99])
    k, d = hertzdamp.invert(e, 1e-5, 1e-6, 1.0, law=law)
    e2, tc2 = hertzdamp.forward(k, d, 1e-6, 1.0, law=law, method="rk45")
    assert np.max(np.abs(e2 / e - 1)) < 1e-9 and np.max(np.abs(tc2 / 1e-5 - 1)) < 1e-9


def test_pair_kd_then_forward():
    pair = hertzdamp.Pair(0.35, law="kuwabara-kono", end="force")
    u = np.geomspace(0.01, 20, 50)
    k, d = pair.kd(3e-5, 2e-6, u)
    e, tc = hertzdamp.forward(k, d, 2e-6, u, law="kuwabara-kono", end="force")
    assert np.max(np.abs(e / 0.35 - 1)) < 1e-11 and np.max(np.abs(tc / 3e-5 - 1)) < 1e-11
