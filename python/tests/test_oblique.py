"""The oblique contact from Python (hertzdamp.oblique_impact, tangential_kt,
oblique_correct; doc/oblique.md): the registries read from the library, the k_t rules'
closed forms, the time-stretch identity of a softened sphere-wall contact with the
adapted k_t (to 1e-9), Maw-Barber-Fawcett gross sliding, the two-sphere correction, and
the errors."""
import math

import numpy as np
import pytest

import hertzdamp
from hertzdamp._lib import lib

R, RHO, E, NU = 1e-3, 2500.0, 63e9, 0.24
M = RHO * 4 / 3 * math.pi * R**3
KPHYS = 4 / 3 * E / (2 * (1 - NU**2)) * math.sqrt(R)          # glass on a glass wall
KT = 8 * E / (2 * 2 * (2 - NU) * (1 + NU))                    # mindlin 8 G*


def test_registries():
    assert hertzdamp.TANGENTIALS == ("linear_history", "mindlin")
    assert hertzdamp.LEVERS == ("radius", "contact")


def test_tangential_kt_rules():
    assert hertzdamp.tangential_kt(2.0, 1.0, 4.0) == 0.5
    np.testing.assert_allclose(hertzdamp.tangential_kt(2.0, [1.0, 32.0], 32.0**1.25, tangential="linear_history"),
                               [2.0 / 32.0, 2.0 * 32.0**-0.2], rtol=1e-14)


def test_stretch_identity_and_gross_sliding():
    th = np.array([10.0, 30.0, 50.0, 70.0])
    un = np.cos(np.radians(th))
    # the physical contact: k_phys, d of e = 0.5 at the normal speed (T_c far below the physical one)
    k, d = hertzdamp.invert(0.5, 1e-9, M, un, k_phys=KPHYS)
    phys = hertzdamp.oblique_impact(M, R, 0, 0, k, d, KT, 0.3, 1.0, th)
    for s in (10.0, 100.0):
        ks, ds = k * s**-2.5, d / s
        soft = hertzdamp.oblique_impact(M, R, 0, 0, ks, ds, hertzdamp.tangential_kt(KT, ks, k), 0.3, 1.0, th)
        for f in ("e_n", "e_t", "vt_ratio"):
            assert np.max(np.abs(soft[f] - phys[f])) < 1e-9, f
        assert np.max(np.abs(soft["omega1"] - phys["omega1"])) * R < 1e-9
    # elastic gross sliding at 80 degrees: e_t = -1 + mu (1 + e_n) 7/2 cot(theta)
    g = hertzdamp.oblique_impact(M, R, 0, 0, KPHYS, 0.0, KT, 0.1, 1.0, 80.0)
    assert g["slide_fraction"] == 1.0
    assert abs(g["e_t"] - (-1 + 0.1 * (1 + g["e_n"]) * 3.5 / math.tan(math.radians(80)))) < 1e-9


def test_two_sphere_correction():
    c = hertzdamp.oblique_correct(M, R, M, R, KPHYS * math.sqrt(0.5), KT, 0.0, 0.5, 2e-5, 5.0, [30.0, 75.0])
    r = hertzdamp.oblique_impact(M, R, M, R, c["k"], c["d"], c["kt"], 0.0, 5.0, [30.0, 75.0], lever="contact")
    assert np.max(np.abs(r["e_n"] - 0.5)) < 2e-5   # the fast correction (doc/oblique.md section 4)
    assert np.all(c["e_target"] < 0.5)


def test_errors():
    with pytest.raises(hertzdamp.HertzdampError) as err:
        hertzdamp.oblique_impact(M, R, 0, 0, KPHYS, 0.0, KT, 0.3, 1.0, 90.0)
    assert err.value.status == lib.codes["status"]["bad-oblique"]
    with pytest.raises(hertzdamp.HertzdampError, match="tangential = 'coulomb'"):
        hertzdamp.tangential_kt(1.0, 1.0, 1.0, tangential="coulomb")
