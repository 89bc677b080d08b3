"""hertzdamp.Pair: the constants of one material pair, set once, then k and d per contact."""
from __future__ import annotations

import ctypes
from typing import Dict, Optional

import numpy as np

from ._api import _CONTACT, ArrayLike, min_steps, phase_min_steps
from ._call import HertzdampError, Inputs, check_errors, code, finish, run
from ._lib import lib


class Pair:
    """The constants of a material pair (hertzdamp_c_pair_init): target restitution e,
    damping law, contact end, and the host scheme with its steps per contact N (host
    None: the continuous model, no steps).  ``kd`` gives every contact its k and d;
    ``stats`` what the constants achieve in a host scheme; ``min_steps`` the fewest N at
    which the host reaches e.  ``phase=True`` also builds the onset-phase table
    (hertzdamp_c_pair_init_phase): ``kd_phase`` then gives each contact the constants of its
    own onset phase, which make that contact's e and T_c exact in the host's scheme.  The
    constants live in the library's opaque pair (its size read from the library), so a
    Pair is a small copyable value."""

    def __init__(self, e: float, *, law: str = "linear", end: str = "overlap", host: Optional[str] = None,
                 steps: Optional[float] = None, phase: bool = False) -> None:
        if np.ndim(e) != 0:
            raise ValueError("hertzdamp.Pair: one e per pair (hertzdamp.invert takes arrays of e)")
        if host not in (None, "none") and steps is None:
            raise ValueError(f"hertzdamp.Pair: host = {host!r} needs steps (the steps per contact N)")
        self.e, self.law, self.end, self.host = float(e), law, end, host
        self.steps = None if steps is None else float(steps)
        self.phase = bool(phase)
        self._codes = (code("law", law, "law"), code("end", end, "end"),
                       code("host", "none" if host is None else host, "host"))
        self._buf = np.zeros(lib.codes["size"]["pair"])
        init = lib.pair_init_phase if self.phase else lib.pair_init
        st = init(self.e, *self._codes, self.steps or 0.0, self._buf.ctypes.data)
        if st:
            msg = f"hertzdamp.Pair: e = {self.e!r}, law = {law!r}, end = {end!r}, host = {host!r}"
            if steps is not None:
                msg += f", steps = {self.steps:g}"
            msg += f": {lib.message(st)}"
            if lib.status_names.get(st) in ("host-unreachable", "phase-unreachable"):
                try:
                    n = (phase_min_steps if self.phase else min_steps)(self.e, law, end, host)
                    msg += f" (N >= {n} can)"
                except ValueError:
                    pass
            raise HertzdampError(msg, st)
        a, t = ctypes.c_double(), ctypes.c_double()
        lib.pair_constants(self._buf.ctypes.data, ctypes.addressof(a), ctypes.addressof(t))
        #: alpha and tau_c of the pair's k, d formulas (a host: alpha_N, tau_N)
        self.alpha, self.tau_c = a.value, t.value

    def __repr__(self) -> str:
        steps = "" if self.steps is None else f", steps={self.steps:g}"
        return f"Pair({self.e!r}, law={self.law!r}, end={self.end!r}, host={self.host!r}{steps})"

    def kd(self, tc: ArrayLike, m: ArrayLike, u: ArrayLike, k_phys: Optional[ArrayLike] = None, *,
           errors: str = "raise", return_status: bool = False):
        """k [N m^-3/2] and d [kg s^-1 m^-q] of contacts with target time tc = N dt [s],
        effective mass m [kg] and impact speed u [m/s], with the physical bound k_phys
        (None: none); broadcasting, errors and return_status as for hertzdamp.invert."""
        check_errors(errors)
        inputs = Inputs("Pair.kd", {"tc": tc, "m": m, "u": u, "k_phys": k_phys})
        res, status = run("Pair.kd", "hertzdamp_c_pair_kd_array", inputs, ("tc", "m", "u", "k_phys"), (),
                          ("k", "d"), prefix=(self._buf.ctypes.data,))
        return finish(inputs, [res["k"], res["d"]], status, errors, return_status, _CONTACT)

    def kd_phase(self, tc: ArrayLike, m: ArrayLike, u: ArrayLike, phi: ArrayLike,
                 k_phys: Optional[ArrayLike] = None):
        """k and d of contacts with onset phases phi in (0, 1] (hertzdamp.onset_phase), from
        the pair's onset-phase table (``phase=True``): one hertzdamp_c_pair_kd_phase call per
        contact over the broadcast arrays; k_phys as for ``kd``.  HertzdampError at the first
        contact the library refuses (no table, a bad phase or argument)."""
        arrays = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in
                                       (tc, m, u, phi, 0.0 if k_phys is None else k_phys)))
        k = np.empty(arrays[0].shape)
        d = np.empty(arrays[0].shape)
        kk, dd = ctypes.c_double(), ctypes.c_double()
        for idx in np.ndindex(k.shape):
            t, mm, uu, ph, kp = (float(a[idx]) for a in arrays)
            st = lib.pair_kd_phase(self._buf.ctypes.data, t, mm, uu, kp, ph, ctypes.addressof(kk),
                                   ctypes.addressof(dd))
            if st:
                raise HertzdampError(f"hertzdamp.Pair.kd_phase: contact {idx}: {lib.message(st)}", st,
                                     idx if k.ndim else None)
            k[idx], d[idx] = kk.value, dd.value
        if k.ndim == 0:
            return float(k), float(d)
        return k, d

    def stats(self, host: Optional[str] = None) -> Dict[str, float]:
        """What the constants achieve in the host scheme `host` (default: the pair's own;
        'none': the continuous model) at the pair's N, over the onset phase: e_mean, e_sd,
        e_min, e_max, and tau_mean, tau_sd, tau_min, tau_max, the contact time in units of
        the target T_c = N dt."""
        h = self.host if host is None else host
        if h not in (None, "none") and self.steps is None:
            raise ValueError(f"hertzdamp.Pair.stats: host = {h!r} needs a pair with steps")
        names = lib.names_of("stats")
        out = np.zeros(lib.codes["size"]["stats"])
        st = lib.pair_stats(self._buf.ctypes.data, code("host", "none" if h is None else h, "host"),
                            out.ctypes.data)
        if st:
            raise HertzdampError(f"hertzdamp.Pair.stats: host = {h!r}: {lib.message(st)}", st)
        return {name: float(out[lib.codes["stats"][name]]) for name in names}

    @property
    def min_steps(self) -> int:
        """The fewest whole steps per contact N at which the pair's host reaches e (host
        None or 'none': 2)."""
        return min_steps(self.e, self.law, self.end, "none" if self.host is None else self.host)
