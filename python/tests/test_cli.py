"""The package agrees with the hertzdamp program (its JSON output: round-trip digits),
for every law, contact end and host scheme, every forward method, the materials and
the time step.  Marked `cli`: they need HERTZDAMP_BIN."""
import numpy as np
import pytest

import hertzdamp

pytestmark = pytest.mark.cli

M = 5.235987755982989e-06
U = [0.003, 0.05, 1.0, 7.0, 90.0]
GLASS = ["--radius", "1e-3", "--density", "2500", "--youngs-modulus", "63e9", "--poisson-ratio", "0.24"]


def column(rows, name):
    return np.array([np.nan if r[name] is None else r[name] for r in rows], dtype=float)


@pytest.mark.parametrize("law", hertzdamp.LAWS)
@pytest.mark.parametrize("end", hertzdamp.ENDS)
@pytest.mark.parametrize("e", [0.05, 0.5, 0.97])
def test_invert(cli, law, end, e):
    rows = cli("invert", "--mass", M, "--e", e, "--tc", 2e-5, "--velocity", ",".join(map(str, U)),
               "--k-phys", 3e8, "--damping", law, "--end", end)
    k, d = hertzdamp.invert(e, 2e-5, M, U, k_phys=3e8, law=law, end=end)
    assert np.array_equal(column(rows, "k"), k) and np.array_equal(column(rows, "d"), d)
    assert [r["bound_active"] for r in rows] == list(k == 3e8)


@pytest.mark.parametrize("host", hertzdamp.HOSTS)
@pytest.mark.parametrize("law", hertzdamp.LAWS)
def test_invert_host(cli, host, law):
    rows = cli("invert", "--mass", M, "--e", 0.4, "--dt", 1e-6, "--steps", 20, "--velocity", ",".join(map(str, U)),
               "--host", host, "--damping", law)
    k, d = hertzdamp.invert(0.4, None, M, U, dt=1e-6, steps=20, host=host, law=law)
    assert np.array_equal(column(rows, "k"), k) and np.array_equal(column(rows, "d"), d)
    pair = hertzdamp.Pair(0.4, law=law, host=host, steps=20)
    assert column(rows, "alpha")[0] == pair.alpha and column(rows, "tau_c")[0] == pair.tau_c
    s = pair.stats()
    assert column(rows, "e_spread")[0] == pytest.approx(s["e_sd"] / s["e_mean"], rel=1e-15)


FORWARD = [(method, law, end) for method in ("rk45", "series", "pade", "compact", "fit")
           for law in hertzdamp.LAWS for end in hertzdamp.ENDS
           if (method in ("rk45", "fit") or law == "linear") and (method not in ("series", "pade") or end == "overlap")]


@pytest.mark.parametrize("method,law,end", FORWARD)
def test_forward(cli, method, law, end):
    d = 0.05 if law == "linear" else (0.3 * np.sqrt(M * 1e9) if law == "tsuji" else 50.0)
    rows = cli("forward", "--k", 1e9, "--d", d, "--mass", M, "--velocity", ",".join(map(str, U)), "--method", method,
               "--damping", law, "--end", end)
    e, tc, st = hertzdamp.forward(1e9, d, M, U, method=method, law=law, end=end, errors="nan", return_status=True)
    have = ~np.isnan(column(rows, "e"))
    assert have.sum() >= 3
    assert np.array_equal(column(rows, "e")[have], e[have]) and np.array_equal(column(rows, "t_c")[have], tc[have])
    assert np.all(st[have] == 0)


@pytest.mark.parametrize("wall", [False, True])
@pytest.mark.parametrize("second", [[], ["--youngs-modulus2", "200e9", "--poisson-ratio2", "0.3"]])
def test_materials(cli, wall, second):
    extra = (["--wall"] if wall else ["--radius2", "3e-3", "--density2", "7800"]) + second
    rows = cli("invert", *GLASS, *extra, "--e", 0.9, "--tc", 1e-5, "--velocity", 1)
    kw = dict(wall=wall) if wall else dict(radius2=3e-3, density2=7800)
    if second:
        kw.update(youngs_modulus2=200e9, poisson_ratio2=0.3)
    c = hertzdamp.materials(1e-3, 2500, 63e9, 0.24, **kw)
    assert (rows[0]["mass"], rows[0]["radius_eff"], rows[0]["k_phys"]) == (c.m_eff, c.r_eff, c.k_phys)


@pytest.mark.parametrize("host", [None, "lammps", "verlet"])
@pytest.mark.parametrize("law", hertzdamp.LAWS)
def test_timestep(cli, host, law):
    args = ["timestep", *GLASS, "--e", 0.7, "--velocity", 5, "--steps", 12, "--damping", law]
    if host:
        args += ["--host", host]
    row = cli(*args)[0]
    t = hertzdamp.timestep(0.7, 5.0, steps=12, law=law, host=host, radius=1e-3, density=2500, youngs_modulus=63e9,
                           poisson_ratio=0.24)
    for name in ("alpha", "tau_c", "tc_damped", "tc_elastic", "elastic_excess", "dt_max", "dt_elastic",
                 "t_rayleigh", "dt_rayleigh", "k_phys"):
        assert row[name] == t[name], name
    # the program's dt_max over a list of speeds is that of the fastest
    row = cli("timestep", *GLASS, "--e", 0.7, "--velocity", "0.1,2,5", "--damping", law)[0]
    assert row["dt_max"] == hertzdamp.timestep(0.7, [0.1, 2, 5], law=law, radius=1e-3, density=2500,
                                               youngs_modulus=63e9, poisson_ratio=0.24)["dt_max"].min()
