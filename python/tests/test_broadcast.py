"""Shapes and dtypes: broadcasting like a ufunc, 0-d gives floats, lists, copies only where needed."""
import numpy as np
import pytest

import hertzdamp
from hertzdamp._call import Inputs
from conftest import same_bits

M = 5.235987755982989e-06


def reference(e, tc, m, u):
    """One contact at a time (0-d calls), in the broadcast shape."""
    e, tc, m, u = np.broadcast_arrays(*map(np.asarray, (e, tc, m, u)))
    out = np.empty((2,) + e.shape)
    for i in np.ndindex(e.shape):
        out[(slice(None),) + i] = hertzdamp.invert(float(e[i]), float(tc[i]), float(m[i]), float(u[i]))
    return out


def test_scalars_give_floats():
    k, d = hertzdamp.invert(0.9, 1e-5, M, 1.0)
    assert type(k) is float and type(d) is float
    k, d, st = hertzdamp.invert(0.9, 1e-5, M, 1.0, return_status=True)
    assert type(st) is int and st == 0
    e, tc = hertzdamp.forward(np.float64(k), np.array(d), M, 1)
    assert type(e) is float and type(tc) is float
    c = hertzdamp.materials(1e-3, 2500, 63e9, 0.24)
    assert all(type(x) is float for x in c)


@pytest.mark.parametrize("shapes", [((3,), (), (), ()), ((2, 1), (1, 3), (), (3,)), ((4, 1, 2), (), (3, 1), (2,)),
                                    ((), (), (), (0,)), ((5,), (5,), (5,), (5,))])
def test_broadcast_shapes(shapes):
    rng = np.random.default_rng(1)
    e, tc, m, u = (rng.uniform(0.1, 1, s) if s else rng.uniform(0.1, 1) for s in shapes)
    tc = tc * 1e-5
    m = m * 1e-5
    k, d = hertzdamp.invert(e, tc, m, u)
    shape = np.broadcast_shapes(*shapes)
    assert k.shape == d.shape == shape
    want = reference(e, tc, m, u)
    assert same_bits(k, want[0]) and same_bits(d, want[1])


def test_lists_and_integers():
    k, d = hertzdamp.invert([0.9, 0.5], [1e-5], M, [1, 2])
    want = hertzdamp.invert(np.array([0.9, 0.5]), 1e-5, M, np.array([1.0, 2.0]))
    assert same_bits(k, want[0]) and same_bits(d, want[1])
    assert same_bits(hertzdamp.invert(0.5, 1e-5, M, np.arange(1, 4))[0],
                     hertzdamp.invert(0.5, 1e-5, M, np.arange(1, 4, dtype=np.float32))[0])


def test_no_copy_of_broadcasts_and_strided_arrays():
    """A scalar or any broadcast of one value (stride 0), a C-ordered array of the full shape
    (stride 1), a 1-D slice with a step (its stride): passed as they are, no copy.  A row or a
    column broadcast over a matrix takes no one stride: a contiguous copy."""
    u = np.linspace(0.1, 5, 120)
    grid = u.reshape(40, 3)
    inp = Inputs("invert", {"e": 0.9, "one": [2.0], "m": grid, "row": grid[0], "col": grid[:, :1]})
    assert inp.shape == (40, 3)
    assert inp.args["e"][1] == 0 and inp.args["one"][1] == 0
    assert inp.args["m"][1] == 1 and np.shares_memory(inp.views["m"], u)
    for name in ("row", "col"):
        assert inp.args[name][1] == 1 and not np.shares_memory(inp.views[name], u)
    step = Inputs("invert", {"e": 0.9, "u": u[::2]})
    assert step.args["u"][1] == 2 and np.shares_memory(step.views["u"], u)
    back = Inputs("invert", {"u": u[::-1]})
    assert back.args["u"][1] == 1 and not np.shares_memory(back.views["u"], u)   # negative: a copy


def test_strided_and_fortran_order_give_the_same_bits():
    u = np.linspace(0.1, 5, 60)
    m = np.asfortranarray(np.linspace(1e-6, 1e-5, 60).reshape(6, 10))
    a = hertzdamp.invert(0.8, 1e-5, m, u[::-1][::-1].reshape(6, 10))
    b = hertzdamp.invert(0.8, 1e-5, np.ascontiguousarray(m), u.reshape(6, 10).copy())
    assert same_bits(a[0], b[0])
    c = hertzdamp.invert(0.8, 1e-5, M, u[::3])
    assert same_bits(c[0], hertzdamp.invert(0.8, 1e-5, M, u[::3].copy())[0])
    r = hertzdamp.invert(0.8, 1e-5, M, u[::-2])   # a negative stride: a copy
    assert same_bits(r[0], hertzdamp.invert(0.8, 1e-5, M, u[::-2].copy())[0])


@pytest.mark.parametrize("bad", [np.array([1 + 2j]), np.array(["0.5"]), np.array([None]), np.array([True])])
def test_dtypes_that_are_not_real_numbers(bad):
    with pytest.raises(ValueError, match="must be real numbers"):
        hertzdamp.invert(bad, 1e-5, M, 1.0)


def test_shapes_that_do_not_broadcast():
    with pytest.raises(ValueError, match="do not broadcast: .*m \\(2,\\).*u \\(3,\\)"):
        hertzdamp.invert(0.9, 1e-5, [M, M], [1, 2, 3])
    with pytest.raises(ValueError):
        hertzdamp.forward([1e9, 2e9], 0.1, M, [1, 2, 3])


def test_pair_kd_and_timestep_broadcast():
    pair = hertzdamp.Pair(0.5)
    k, d = pair.kd([[1e-5], [2e-5]], M, [1, 2, 3])
    assert k.shape == (2, 3)
    t = hertzdamp.timestep([0.5, 0.9], [[1.0], [5.0]], m=M, k_phys=1e9)
    assert t["dt_max"].shape == (2, 2) and t["dt_max"][1, 0] < t["dt_max"][0, 0]
