"""The error policy: HertzdampError (a ValueError) with the library's message naming the
argument; errors='nan' with one RuntimeWarning; return_status; no rebound is a result."""
import numpy as np
import pytest

import hertzdamp
from hertzdamp._lib import lib

M = 5.235987755982989e-06
S = lib.codes["status"]


@pytest.mark.parametrize("args,name,status", [
    ((1.5, 1e-5, M, 1.0), "e = 1.5", "bad-restitution"),
    ((0.9, -1e-5, M, 1.0), "tc = -1e-05", "bad-time"),
    ((0.9, 1e-5, 0.0, 1.0), "m = 0.0", "bad-mass"),
    ((0.9, 1e-5, M, np.inf), "u = inf", "bad-velocity"),
    ((0.9, 1e-5, M, np.nan), "u = nan", "bad-velocity"),
])
def test_invert_names_the_argument(args, name, status):
    with pytest.raises(hertzdamp.HertzdampError) as err:
        hertzdamp.invert(*args)
    assert isinstance(err.value, ValueError)
    assert err.value.status == S[status] and err.value.status_name == status and err.value.index is None
    assert str(err.value) == f"hertzdamp.invert: {name}: {lib.message(S[status])}"


def test_bound_steps_and_host_messages():
    with pytest.raises(hertzdamp.HertzdampError, match="k_phys = -3.0: invalid physical stiffness bound"):
        hertzdamp.invert(0.9, 1e-5, M, 1.0, k_phys=-3.0)
    with pytest.raises(hertzdamp.HertzdampError, match="steps = 1.0: invalid steps per contact"):
        hertzdamp.invert(0.9, 1e-6, M, 1.0, host="lammps", steps=1)
    with pytest.raises(hertzdamp.HertzdampError, match=r"N = 3 steps cannot reach e = 0.1 with verlet; N >= \d+ can"):
        hertzdamp.invert(0.1, None, M, 1.0, host="verlet", dt=1e-6, steps=3)
    with pytest.raises(hertzdamp.HertzdampError, match=r"\(N >= \d+ can\)"):
        hertzdamp.Pair(0.1, host="verlet", steps=3)


def test_index_and_count_of_an_array():
    e = np.full((3, 4), 0.9)
    e[1, 2] = 2.0
    e[2, 0] = -1.0
    with pytest.raises(hertzdamp.HertzdampError, match=r"e = 2.0: .*\(at index \(1, 2\); 2 of 12 contacts failed\)") \
            as err:
        hertzdamp.invert(e, 1e-5, M, 1.0)
    assert err.value.index == (1, 2)


def test_errors_nan_warns_once_with_the_count():
    e = np.array([0.9, 1.5, 0.5, -1.0])
    with pytest.warns(RuntimeWarning, match="2 of 4 contacts failed") as rec:
        k, d, st = hertzdamp.invert(e, 1e-5, M, 1.0, errors="nan", return_status=True)
    assert len(rec) == 1
    assert np.array_equal(np.isnan(k), [False, True, False, True]) and np.array_equal(np.isnan(d), np.isnan(k))
    assert list(st) == [0, S["bad-restitution"], 0, S["bad-restitution"]]
    assert np.all(k[[0, 2]] > 0)


def test_no_rebound_is_a_result():
    e, tc, st = hertzdamp.forward(1e9, [0.1, 1e3], M, 1.0, return_status=True)
    assert e[1] == 0.0 and tc[1] == np.inf and st[1] == S["no-rebound"] and st[0] == 0 and 0 < e[0] < 1


def test_forward_bad_arguments():
    with pytest.raises(hertzdamp.HertzdampError, match="hertzdamp.forward: d = -1.0: invalid damping"):
        hertzdamp.forward(1e9, -1.0, M, 1.0)
    with pytest.raises(hertzdamp.HertzdampError, match="k = 0.0: invalid stiffness"):
        hertzdamp.forward(0.0, 1.0, M, 1.0)
    with pytest.raises(hertzdamp.HertzdampError, match="method = 'iterative'"):
        hertzdamp.forward(1e9, 0.1, M, 1.0, method="iterative")
    with pytest.raises(hertzdamp.HertzdampError, match="method = 'series', law = 'tsuji'"):
        hertzdamp.forward(1e9, 0.1, M, 1.0, method="series", law="tsuji")
    with pytest.raises(hertzdamp.HertzdampError, match="invalid tolerance"):
        hertzdamp.forward(1e9, 0.1, M, 1.0, method="rk45", tol=1.0)


@pytest.mark.parametrize("kw,match", [(dict(law="hertz"), "law = 'hertz': use one of linear, tsuji, kuwabara-kono"),
                                      (dict(end="contact"), "end = 'contact': use one of overlap, force"),
                                      (dict(host="yade", steps=10), "host = 'yade': use one of none, lammps")])
def test_names(kw, match):
    with pytest.raises(hertzdamp.HertzdampError, match=match):
        hertzdamp.invert(0.9, 1e-5, M, 1.0, **kw)


def test_argument_combinations():
    for kw in (dict(), dict(dt=1e-6), dict(tc=1e-5, dt=1e-6, steps=10), dict(tc=1e-5, steps=10)):
        tc = kw.pop("tc", None)
        with pytest.raises(ValueError):
            hertzdamp.invert(0.9, tc, M, 1.0, **kw)
    with pytest.raises(ValueError, match="needs steps"):
        hertzdamp.invert(0.9, 1e-5, M, 1.0, host="lammps")
    with pytest.raises(ValueError, match="errors = 'ignore'"):
        hertzdamp.invert(0.9, 1e-5, M, 1.0, errors="ignore")
    with pytest.raises(ValueError, match="radius2 and density2 do not apply"):
        hertzdamp.materials(1e-3, 2500, 63e9, 0.24, radius2=1e-3, wall=True)
    with pytest.raises(ValueError, match="one e per pair"):
        hertzdamp.Pair([0.5, 0.6])


def test_materials_and_timestep_errors():
    with pytest.raises(hertzdamp.HertzdampError, match="poisson_ratio = 0.7, poisson_ratio2 = 0.7: invalid Poisson"):
        hertzdamp.materials(1e-3, 2500, 63e9, 0.7)
    with pytest.raises(hertzdamp.HertzdampError, match="density = 2500.0, density2 = -1.0: invalid density"):
        hertzdamp.materials(1e-3, 2500, 63e9, 0.3, radius2=1e-3, density2=-1)
    with pytest.raises(hertzdamp.HertzdampError, match="hertzdamp.timestep: u = -5.0: invalid impact velocity"):
        hertzdamp.timestep(0.9, -5.0, m=M, k_phys=1e9)
    with pytest.raises(ValueError, match="steps must lie in"):
        hertzdamp.timestep(0.9, 5.0, m=M, k_phys=1e9, steps=0)
