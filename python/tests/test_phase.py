"""Per-contact constants from the onset phase (issue 32): Pair(..., phase=True).kd_phase gives
each contact k and d that a stepper written here (MFiX's EULER loop: v += h a, z += h v, a
from the new z and v) turns into the target e and T_c = N dt; onset_phase's rules; the
statuses of a pair without the table and of a bad phase."""
import numpy as np
import pytest

import hertzdamp


def euler_contact(k, d, m, u, dt, phi):
    """e and T_c of one head-on contact stepped as MFiX's EULER, first overlap phi u dt."""
    z, v, a, t, zl = (phi - 1.0) * u * dt, u, 0.0, 0.0, 0.0
    while True:
        v += dt * a
        z += dt * v
        t += dt
        a = 0.0
        if z > 0:
            a = -(k * z ** 1.5 + d * v) / m
            zl = z
        elif t > dt:
            return -v / u, t - dt + dt * zl / (zl - z) - (1.0 - phi) * dt


@pytest.mark.parametrize("e", [0.2, 0.5, 0.9])
def test_every_contact_exact(e):
    m, u, dt, n = 1e-3, 1.3, 1e-6, 10
    pair = hertzdamp.Pair(e, host="mfix-euler", steps=n, phase=True)
    phis = (np.arange(16) + 0.5) / 16
    k, d = pair.kd_phase(n * dt, m, u, phis)
    for kk, dd, ph in zip(k, d, phis):
        ea, tc = euler_contact(kk, dd, m, u, dt, ph)
        assert abs(ea / e - 1) < 1e-5 and abs(tc / (n * dt) - 1) < 1e-5
    # the mean-exact constants scatter
    k0, d0 = pair.kd(n * dt, m, u)
    es = [euler_contact(k0, d0, m, u, dt, ph)[0] for ph in phis]
    assert np.std(es) / e > 100 * max(abs(euler_contact(kk, dd, m, u, dt, ph)[0] / e - 1)
                                      for kk, dd, ph in zip(k, d, phis))


def test_onset_phase():
    assert hertzdamp.onset_phase(0.375e-6, 2.0, 0.5e-6) == pytest.approx(0.375, rel=1e-15)
    assert hertzdamp.onset_phase(3e-6, 1.0, 1e-6) == 1.0           # late: clamped
    with pytest.raises(hertzdamp.HertzdampError) as err:
        hertzdamp.onset_phase(0.0, 1.0, 1e-6)
    assert err.value.status_name == "bad-phase"


def test_statuses():
    plain = hertzdamp.Pair(0.5, host="lammps", steps=10)
    with pytest.raises(hertzdamp.HertzdampError) as err:
        plain.kd_phase(1e-5, 1e-3, 1.0, 0.5)
    assert err.value.status_name == "no-phase-table"
    pair = hertzdamp.Pair(0.5, host="lammps", steps=10, phase=True)
    with pytest.raises(hertzdamp.HertzdampError) as err:
        pair.kd_phase(1e-5, 1e-3, 1.0, 1.5)
    assert err.value.status_name == "bad-phase"
    with pytest.raises(hertzdamp.HertzdampError) as err:
        hertzdamp.Pair(0.99, end="force", host="lammps", steps=10, phase=True)
    assert err.value.status_name == "phase-unreachable" and "N >= " in str(err.value)
    assert hertzdamp.phase_min_steps(0.99, end="force", host="lammps") > 10
