"""The oblique frictional contact (doc/oblique.md): thin wrappers of the C entry points
hertzdamp_c_tangential_kt, hertzdamp_c_oblique_impact and hertzdamp_c_oblique_correct,
one C call per contact (an oblique impact is an integration of tens of microseconds, not
a hot-loop formula), broadcast like a numpy ufunc."""
from __future__ import annotations

import ctypes
from typing import Dict

import numpy as np

from ._call import HertzdampError, code
from ._lib import lib

#: the fields of hertzdamp_c_oblique_impact's out[8]
IMPACT_FIELDS = ("e_n", "e_t", "vt_ratio", "rebound_angle", "omega1", "omega2", "slide_fraction", "t_c")
#: the fields of hertzdamp_c_oblique_correct's out[4]
CORRECT_FIELDS = ("k", "d", "kt", "e_target")


def _fail(fname: str, st: int, index) -> None:
    raise HertzdampError(f"hertzdamp.{fname}: contact {index}: {lib.message(st)}", st, index)


def tangential_kt(kt_phys, k, k_phys, tangential: str = "mindlin"):
    """The k_t of a softened contact (normal stiffness k instead of k_phys) whose outcome is
    a time-stretched copy of the physical one: mindlin kt_phys k/k_phys, linear_history
    kt_phys (k/k_phys)^(4/5)."""
    t = code("tangential", tangential, "tangential")
    a, b, c = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in (kt_phys, k, k_phys)))
    out = np.empty(a.shape)
    v = ctypes.c_double()
    for i in np.ndindex(a.shape):
        st = lib.tangential_kt(t, a[i], b[i], c[i], ctypes.addressof(v))
        if st:
            _fail("tangential_kt", st, i)
        out[i] = v.value
    return out if out.ndim else float(out)


def oblique_impact(m1, r1, m2, r2, k, d, kt, mu, speed, angle, *, xgammat=0.0, law: str = "linear",
                   end: str = "overlap", tangential: str = "mindlin", lever: str = "radius") -> Dict[str, np.ndarray]:
    """The oblique impact of sphere 1 on sphere 2 at rest (m2 = r2 = 0: a wall) at speed
    [m/s] and angle [degrees from the normal]: a dict of arrays (IMPACT_FIELDS)."""
    codes = (code("law", law, "law"), code("end", end, "end"), code("tangential", tangential, "tangential"),
             code("lever", lever, "lever"))
    args = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in (m1, r1, m2, r2, k, d, kt, xgammat, mu,
                                                                       speed, angle)))
    shape = args[0].shape
    res = np.empty(shape + (8,))
    out = (ctypes.c_double * 8)()
    for i in np.ndindex(shape):
        a = [x[i] for x in args]
        st = lib.oblique_impact(a[0], a[1], a[2], a[3], a[4], a[5], codes[0], codes[1], codes[2], a[6], a[7], a[8],
                                codes[3], a[9], a[10], ctypes.addressof(out))
        if st:
            _fail("oblique_impact", st, i)
        res[i] = list(out)
    return {f: res[..., j] for j, f in enumerate(IMPACT_FIELDS)}


def oblique_correct(m1, r1, m2, r2, k_phys, kt_phys, mu, e, tc, speed, angle, *, xgammat=0.0,
                    law: str = "linear", end: str = "overlap", tangential: str = "mindlin",
                    lever: str = "contact") -> Dict[str, np.ndarray]:
    """The oblique normal correction (a solve of the oblique contact per element): the k, d
    of the target e' at contact time tc for which the oblique e_n equals e, the k_t scaled
    to that k, and e' (CORRECT_FIELDS)."""
    codes = (code("law", law, "law"), code("end", end, "end"), code("tangential", tangential, "tangential"),
             code("lever", lever, "lever"))
    args = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in (m1, r1, m2, r2, k_phys, kt_phys, xgammat, mu,
                                                                       e, tc, speed, angle)))
    shape = args[0].shape
    res = np.empty(shape + (4,))
    out = (ctypes.c_double * 4)()
    for i in np.ndindex(shape):
        a = [x[i] for x in args]
        st = lib.oblique_correct(a[0], a[1], a[2], a[3], a[4], codes[0], codes[1], codes[2], a[5], a[6], a[7],
                                 codes[3], a[8], a[9], a[10], a[11], ctypes.addressof(out))
        if st:
            _fail("oblique_correct", st, i)
        res[i] = list(out)
    return {f: res[..., j] for j, f in enumerate(CORRECT_FIELDS)}
