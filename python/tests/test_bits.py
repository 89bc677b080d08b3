"""The package's results are the C entry points', bit for bit, on the same inputs."""
import ctypes

import numpy as np
import pytest

import hertzdamp
from conftest import RNG_SEED, quiet, same_bits

LAWS = hertzdamp.LAWS
ENDS = hertzdamp.ENDS


def contacts(n=300, seed=RNG_SEED, bad=True):
    """Random contacts over many decades, with some invalid values among them."""
    rng = np.random.default_rng(seed)
    e = rng.uniform(0.0005 if bad else 0.002, 1.0, n)
    tc = 10 ** rng.uniform(-7, -3, n)
    m = 10 ** rng.uniform(-9, 1, n)
    u = 10 ** rng.uniform(-3, 2, n)
    kp = 10 ** rng.uniform(5, 11, n)
    if bad:
        e[::37] = 1.5
        m[5::41] = -1.0
        u[7::43] = 0.0
        tc[9::47] = np.inf
        kp[11::53] = -2.0
    return e, tc, m, u, kp


def c_invert(capi, e, tc, m, u, kp, law, end):
    k, d = ctypes.c_double(), ctypes.c_double()
    out = np.empty((3, e.size))
    for i in range(e.size):
        st = capi.invert_law(e[i], tc[i], m[i], u[i], kp[i], law, end, ctypes.addressof(k), ctypes.addressof(d))
        out[:, i] = k.value, d.value, st
    return out


@pytest.mark.parametrize("law", LAWS)
@pytest.mark.parametrize("end", ENDS)
@pytest.mark.parametrize("bound", [False, True])
def test_invert_is_hertzdamp_c_invert_law(capi, law, end, bound):
    e, tc, m, u, kp = contacts()
    if not bound:
        kp = np.zeros_like(kp)   # 0: no bound in the C call, None here
    want = c_invert(capi, e, tc, m, u, kp, capi.codes["law"][law], capi.codes["end"][end])
    k, d, st = quiet(hertzdamp.invert, e, tc, m, u, law=law, end=end, k_phys=kp if bound else None)
    assert np.array_equal(st, want[2])
    ok = st == 0
    assert ok.sum() > 200
    assert same_bits(k[ok], want[0][ok]) and same_bits(d[ok], want[1][ok])


def test_invert_is_hertzdamp_c_invert_n(capi):
    """The array call and the C array entry point of a C host, on the same arrays."""
    e, tc, m, u, _ = contacts(5000, bad=False)
    k = np.empty_like(e)
    d = np.empty_like(e)
    st = np.empty(e.size, dtype=np.intc)
    capi.invert_n(e.size, e.ctypes.data, tc.ctypes.data, m.ctypes.data, u.ctypes.data, capi.codes["end"]["overlap"],
                  k.ctypes.data,
                  d.ctypes.data, st.ctypes.data)
    k2, d2, st2 = hertzdamp.invert(e, tc, m, u, return_status=True)
    assert np.array_equal(st, st2) and same_bits(k, k2) and same_bits(d, d2)


@pytest.mark.parametrize("host", hertzdamp.HOSTS)
def test_invert_with_a_host_is_pair_init_and_pair_kd(capi, host):
    """Per contact hertzdamp_c_pair_init + hertzdamp_c_pair_kd; e and N in runs (one init per run)."""
    rng = np.random.default_rng(RNG_SEED + 1)
    n = 60
    e = np.repeat([0.3, 0.7, 0.95], n // 3)
    steps = np.tile([20.0, 20.0, 50.0], n // 3)
    tc = steps * 1e-6
    m = 10 ** rng.uniform(-8, -2, n)
    u = 10 ** rng.uniform(-2, 1, n)
    kp = 10 ** rng.uniform(7, 10, n)
    k, d, st = hertzdamp.invert(e, tc, m, u, k_phys=kp, host=host, steps=steps, return_status=True)
    buf = np.zeros(capi.codes["size"]["pair"])
    kk, dd = ctypes.c_double(), ctypes.c_double()
    for i in range(n):
        assert capi.pair_init(e[i], capi.codes["law"]["linear"], capi.codes["end"]["overlap"], capi.codes["host"][host],
                              steps[i], buf.ctypes.data) == 0
        s = capi.pair_kd(buf.ctypes.data, tc[i], m[i], u[i], kp[i], ctypes.addressof(kk), ctypes.addressof(dd))
        assert s == st[i] == 0
        assert same_bits([k[i], d[i]], [kk.value, dd.value]), i


def test_host_none_with_steps_is_the_continuous_model():
    e, tc, m, u, kp = contacts(200, bad=False)
    a = hertzdamp.invert(e, tc, m, u, k_phys=kp)
    b = hertzdamp.invert(e, tc, m, u, k_phys=kp, host="none", steps=20)
    assert same_bits(a[0], b[0]) and same_bits(a[1], b[1])


@pytest.mark.parametrize("host", [None, "lammps", "mfix-ab2"])
def test_pair_kd_is_hertzdamp_c_pair_kd(capi, host):
    pair = hertzdamp.Pair(0.6, law="tsuji", host=host, steps=None if host is None else 25)
    e, tc, m, u, kp = contacts(400)
    k, d, st = quiet(pair.kd, tc, m, u, np.where(kp > 0, kp, 1.0))
    kk, dd = ctypes.c_double(), ctypes.c_double()
    for i in range(e.size):
        s = capi.pair_kd(pair._buf.ctypes.data, tc[i], m[i], u[i], max(kp[i], 1.0), ctypes.addressof(kk),
                         ctypes.addressof(dd))
        assert s == st[i]
        if s == 0:
            assert same_bits([k[i], d[i]], [kk.value, dd.value]), i


@pytest.mark.parametrize("law", LAWS)
@pytest.mark.parametrize("end", ENDS)
def test_forward_is_hertzdamp_c_forward_law(capi, law, end):
    rng = np.random.default_rng(RNG_SEED + 2)
    n = 300
    k = 10 ** rng.uniform(4, 11, n)
    d = 10 ** rng.uniform(-6, 1, n)
    m = 10 ** rng.uniform(-8, 0, n)
    u = 10 ** rng.uniform(-3, 2, n)
    d[::29] = -1.0
    e, tc, st = quiet(hertzdamp.forward, k, d, m, u, law=law, end=end)
    ee, tt = ctypes.c_double(), ctypes.c_double()
    nrb = capi.codes["status"]["no-rebound"]
    seen = set()
    for i in range(n):
        s = capi.forward_law(k[i], d[i], m[i], u[i], capi.codes["law"][law], capi.codes["end"][end],
                             ctypes.addressof(ee), ctypes.addressof(tt))
        assert s == st[i]
        seen.add(s)
        if s == 0:
            assert same_bits([e[i], tc[i]], [ee.value, tt.value]), i
        elif s == nrb:   # the C call's DBL_MAX is inf here
            assert e[i] == ee.value == 0.0 and tc[i] == np.inf and tt.value == np.finfo(float).max
    assert 0 in seen and capi.codes["status"]["bad-damping"] in seen
