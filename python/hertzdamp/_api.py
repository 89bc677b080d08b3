"""invert, forward, materials, timestep: the library's array entry points over numpy."""
from __future__ import annotations

import ctypes
from typing import Dict, NamedTuple, Optional, Tuple, Union

import numpy as np

from ._call import Inputs, check_errors, code, finish, run
from ._lib import lib

ArrayLike = Union[float, "np.typing.ArrayLike"]

# which arguments a status names, per function (statuses by their registry names)
_CONTACT = {"bad-time": ("tc",), "bad-mass": ("m",), "bad-velocity": ("u",), "bad-kphys": ("k_phys",)}
_INVERT = dict(_CONTACT, **{"bad-restitution": ("e",), "outside-validity": ("e",), "bad-steps": ("steps",),
                            "host-unreachable": ("e", "steps"), "bad-law": (), "bad-end": ()})
_FORWARD = {"bad-stiffness": ("k",), "bad-damping": ("d",), "bad-mass": ("m",), "bad-velocity": ("u",),
            "bad-alpha": ("k", "d", "m", "u"), "bad-argument": (), "not-supported": ()}
_MATERIALS = {"bad-radius": ("radius", "radius2"), "bad-density": ("density", "density2"),
              "bad-modulus": ("youngs_modulus", "youngs_modulus2"),
              "bad-poisson": ("poisson_ratio", "poisson_ratio2")}
_TIMESTEP = dict(_INVERT, **{"bad-stiffness": ("k_phys",)})


def min_steps(e: float, law: str = "linear", end: str = "overlap", host: str = "lammps") -> int:
    """The fewest whole steps per contact N at which `host` reaches restitution e
    (hertzdamp_c_host_min_steps; host 'none': 2).  HertzdampError when no N up to 1024 can."""
    n = ctypes.c_int()
    st = lib.host_min_steps(float(e), code("law", law, "law"), code("end", end, "end"),
                            code("host", host, "host"), ctypes.addressof(n))
    if st:
        from ._call import HertzdampError
        raise HertzdampError(f"hertzdamp.min_steps: e = {float(e)!r}, host = {host!r}: {lib.message(st)}", st)
    return n.value


def onset_phase(delta1: float, u: float, dt: float) -> float:
    """The onset phase delta1 / (u dt) of a contact first seen with overlap delta1 [m] after a
    step dt [s] at approach speed u [m/s] (hertzdamp_c_onset_phase): in (0, 1], a contact
    detected late (phi > 1) gets 1.  HertzdampError for delta1, u or dt not finite and positive."""
    phi = ctypes.c_double()
    st = lib.onset_phase(float(delta1), float(u), float(dt), ctypes.addressof(phi))
    if st:
        from ._call import HertzdampError
        raise HertzdampError(f"hertzdamp.onset_phase: delta1 = {float(delta1)!r}, u = {float(u)!r}, "
                             f"dt = {float(dt)!r}: {lib.message(st)}", st)
    return phi.value


def phase_min_steps(e: float, law: str = "linear", end: str = "overlap", host: str = "lammps") -> int:
    """The fewest whole N at which every onset phase has per-contact constants
    (hertzdamp_c_phase_min_steps, the N of ``Pair(..., phase=True)``)."""
    n = ctypes.c_int()
    st = lib.phase_min_steps(float(e), code("law", law, "law"), code("end", end, "end"),
                             code("host", host, "host"), ctypes.addressof(n))
    if st:
        from ._call import HertzdampError
        raise HertzdampError(f"hertzdamp.phase_min_steps: e = {float(e)!r}, host = {host!r}: {lib.message(st)}", st)
    return n.value


def _steps_hint(inputs: Inputs, law: str, end: str, host: Optional[str]):
    """For a host that cannot reach e at so few steps: which N can (as the program says)."""
    def hint(sname: str, flat: int) -> str:
        if sname != "host-unreachable" or host is None:
            return ""
        e = inputs.value("e", flat)
        try:
            return f"N = {inputs.value('steps', flat):g} steps cannot reach e = {e:g} with {host}; " \
                   f"N >= {min_steps(e, law, end, host)} can"
        except ValueError:
            return ""
    return hint


def invert(e: ArrayLike, tc: Optional[ArrayLike], m: ArrayLike, u: ArrayLike, *, law: str = "linear",
           end: str = "overlap", k_phys: Optional[ArrayLike] = None, host: Optional[str] = None,
           dt: Optional[ArrayLike] = None, steps: Optional[ArrayLike] = None, errors: str = "raise",
           return_status: bool = False):
    """Stiffness k [N m^-3/2] and damping d [kg s^-1 m^-q] that give restitution e and
    contact time tc [s] to contacts of effective mass m [kg] hit at speed u [m/s].

    Arguments broadcast like a ufunc; a 0-d result is a float.  ``tc=None`` with ``dt``
    and ``steps`` takes tc = steps * dt.  ``k_phys``: the physical stiffness bound (where
    k_phys <= k the contact keeps k = k_phys and lasts longer than tc).  ``host``: a DEM
    engine's time integrator ('lammps', 'mfix-euler', 'mfix-ab2', 'verlet',
    'lammps-phase', or 'none'), which needs ``steps`` (N = tc/dt): the constants that
    make the host's mean e and T_c exact at N steps.  law: 'linear', 'tsuji',
    'kuwabara-kono'; end: 'overlap' or 'force'.  Returns (k, d), and the statuses with
    return_status.  errors='raise': HertzdampError naming the bad argument; 'nan': NaN
    for failed contacts and one RuntimeWarning.
    """
    check_errors(errors)
    if tc is None:
        if dt is None or steps is None:
            raise ValueError("hertzdamp.invert: give tc, or dt with steps (tc = steps * dt)")
        tc = np.multiply(steps, dt)
    elif dt is not None:
        raise ValueError("hertzdamp.invert: give either tc or dt with steps, not both")
    elif steps is not None and host is None:
        raise ValueError("hertzdamp.invert: steps without host: give tc, or dt with steps")
    if host is not None and steps is None:
        raise ValueError(f"hertzdamp.invert: host = {host!r} needs steps (the steps per contact N, T_c = N dt)")
    law_, end_ = code("law", law, "law"), code("end", end, "end")
    host_ = code("host", "none" if host is None else host, "host")
    inputs = Inputs("invert", {"e": e, "tc": tc, "m": m, "u": u, "k_phys": k_phys,
                               "steps": steps if host is not None else None})
    res, status = run("invert", "hertzdamp_c_invert_array", inputs, ("e", "tc", "m", "u", "k_phys", "steps"),
                      (law_, end_, host_), ("k", "d"))
    return finish(inputs, [res["k"], res["d"]], status, errors, return_status, _INVERT,
                  hint=_steps_hint(inputs, law, end, host))


def forward(k: ArrayLike, d: ArrayLike, m: ArrayLike, u: ArrayLike, *, law: str = "linear", end: str = "overlap",
            method: str = "fit", tol: Optional[float] = None, order: Optional[int] = None,
            accuracy: Optional[float] = None, errors: str = "raise", return_status: bool = False):
    """Restitution e and contact time tc [s] of contacts of stiffness k [N m^-3/2],
    damping d [kg s^-1 m^-q], effective mass m [kg] hit at speed u [m/s].

    method: 'fit' (machine precision, no iteration), 'rk45' (the reference integrator;
    ``tol``), 'series' (``order``, ``accuracy``), 'pade' (``accuracy``), 'compact',
    'first-order'; the defaults of tol, order and accuracy are the library's.  No rebound
    (overlap end, too much damping) is a result: e = 0, tc = inf (status 'no-rebound').
    Broadcasting, errors and return_status as for invert.
    """
    check_errors(errors)
    law_, end_ = code("law", law, "law"), code("end", end, "end")
    method_ = code("method", method, "method")
    inputs = Inputs("forward", {"k": k, "d": d, "m": m, "u": u})
    res, status = run("forward", "hertzdamp_c_forward_array", inputs, ("k", "d", "m", "u"),
                      (law_, end_, method_, float(tol or 0.0), int(order or 0), float(accuracy or 0.0)),
                      ("e", "tc"))
    no_rebound = status == lib.codes["status"]["no-rebound"]
    if isinstance(res["tc"], np.ndarray):
        res["tc"][no_rebound] = np.inf
    elif no_rebound:
        res["tc"] = np.inf
    def hint(sname: str, flat: int) -> str:
        if sname in ("bad-argument", "not-supported", "bad-tol", "bad-order", "outside-validity", "inaccurate"):
            return f"method = {method!r}, law = {law!r}, end = {end!r}"
        return ""
    return finish(inputs, [res["e"], res["tc"]], status, errors, return_status, _FORWARD,
                  ok=("ok", "no-rebound"), hint=hint)


class Contact(NamedTuple):
    """What material data give a contact."""

    m_eff: Union[float, np.ndarray]   #: effective mass [kg]
    r_eff: Union[float, np.ndarray]   #: effective radius [m]
    k_phys: Union[float, np.ndarray]  #: Hertz stiffness (4/3) E* sqrt(R*) [N m^-3/2]


def _contact(fname: str, radius, density, youngs_modulus, poisson_ratio, radius2, density2, youngs_modulus2,
             poisson_ratio2, wall: bool, extra: Dict[str, object]):
    """The contact array call: body 2 defaults to body 1 (the same buffer, no copy)."""
    if wall and (radius2 is not None or density2 is not None):
        raise ValueError(f"hertzdamp.{fname}: wall=True: body 2 has infinite radius and mass, "
                         "so radius2 and density2 do not apply")
    values = {"radius": radius, "density": density, "youngs_modulus": youngs_modulus, "poisson_ratio": poisson_ratio,
              "radius2": radius2, "density2": density2, "youngs_modulus2": youngs_modulus2,
              "poisson_ratio2": poisson_ratio2}
    for name, x in values.items():
        if x is None and not name.endswith("2"):
            raise TypeError(f"hertzdamp.{fname}: {name} is required")
    inputs = Inputs(fname, dict(values, **extra))
    for name in ("youngs_modulus2", "poisson_ratio2") + (() if wall else ("radius2", "density2")):
        if name not in inputs.views:
            inputs.views[name] = inputs.views[name[:-1]]
            inputs.args[name] = inputs.args[name[:-1]]
    res, status = run(fname, "hertzdamp_c_contact_array", inputs, list(values), (int(bool(wall)),),
                      ("m_eff", "r_eff", "k_phys", "t_rayleigh", "dt_rayleigh"))
    return inputs, res, status


def materials(radius: ArrayLike, density: ArrayLike, youngs_modulus: ArrayLike, poisson_ratio: ArrayLike, *,
              radius2: Optional[ArrayLike] = None, density2: Optional[ArrayLike] = None,
              youngs_modulus2: Optional[ArrayLike] = None, poisson_ratio2: Optional[ArrayLike] = None,
              wall: bool = False, errors: str = "raise", return_status: bool = False):
    """The contact of two spheres (or of a sphere and a wall, ``wall=True``) from material
    data, as the program's contact options define it: Contact(m_eff, r_eff, k_phys) with
    m_eff = m1 m2/(m1 + m2) (a wall: m1), 1/r_eff = 1/R1 + 1/R2 (a wall: R1) and
    k_phys = (4/3) E* sqrt(r_eff), 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2.  Body 2 (or
    the wall's E and nu) defaults to body 1's.  SI units; broadcasting and errors as for
    invert."""
    check_errors(errors)
    inputs, res, status = _contact("materials", radius, density, youngs_modulus, poisson_ratio, radius2, density2,
                                   youngs_modulus2, poisson_ratio2, wall, {})
    out = finish(inputs, [res["m_eff"], res["r_eff"], res["k_phys"]], status, errors, return_status, _MATERIALS)
    return (Contact(*out[:3]),) + out[3:] if return_status else Contact(*out)


def timestep(e: ArrayLike, u: ArrayLike, *, m: Optional[ArrayLike] = None, k_phys: Optional[ArrayLike] = None,
             radius: Optional[ArrayLike] = None, density: Optional[ArrayLike] = None,
             youngs_modulus: Optional[ArrayLike] = None, poisson_ratio: Optional[ArrayLike] = None,
             radius2: Optional[ArrayLike] = None, density2: Optional[ArrayLike] = None,
             youngs_modulus2: Optional[ArrayLike] = None, poisson_ratio2: Optional[ArrayLike] = None,
             wall: bool = False, steps: ArrayLike = 10, law: str = "linear", end: str = "overlap",
             host: Optional[str] = None, errors: str = "raise", return_status: bool = False):
    """The time step that resolves the physical contact (k = k_phys, d from e) at impact
    speed u with ``steps`` steps, as the program's `timestep` defines it, per contact: a
    dict of arrays alpha, tau_c, tc_damped = t* tau_c, tc_elastic (the elastic Hertz time),
    elastic_excess = tc_elastic/tc_damped - 1, dt_max = tc_damped/steps and dt_elastic =
    tc_elastic/steps; from material data (radius, density, youngs_modulus, poisson_ratio
    and the 2-suffixed ones, as materials) also m_eff, k_phys, t_rayleigh and
    dt_rayleigh = 0.2 t_rayleigh (0 where not representable).  Give m and k_phys, or the
    material data.  The program's dt_max over a velocity list is the smallest (the
    fastest contact).  ``host``: the host scheme's constants at ``steps``.  Bad material
    data raise HertzdampError even with errors='nan' (they leave no contact to compute)."""
    check_errors(errors)
    law_, end_ = code("law", law, "law"), code("end", end, "end")
    host_ = code("host", "none" if host is None else host, "host")
    out: Dict[str, np.ndarray] = {}
    if radius is not None or density is not None:
        if m is not None or k_phys is not None:
            raise ValueError("hertzdamp.timestep: give either m and k_phys or the material data, not both")
        cinputs, cres, cstatus = _contact("timestep", radius, density, youngs_modulus, poisson_ratio, radius2,
                                          density2, youngs_modulus2, poisson_ratio2, wall, {})
        finish(cinputs, [], cstatus, "raise", False, _MATERIALS)
        m, k_phys = cres["m_eff"], cres["k_phys"]
        out.update(m_eff=m, k_phys=k_phys, t_rayleigh=cres["t_rayleigh"], dt_rayleigh=cres["dt_rayleigh"])
    elif m is None or k_phys is None:
        raise TypeError("hertzdamp.timestep: give m and k_phys, or radius, density, youngs_modulus, poisson_ratio")
    inputs = Inputs("timestep", {"e": e, "u": u, "m": m, "k_phys": k_phys, "steps": steps})
    n_steps = inputs.views["steps"]
    if not np.all((n_steps >= 1) & (n_steps <= 1e9)):
        raise ValueError("hertzdamp.timestep: steps must lie in [1, 1e9] (time steps per contact)")
    if host is None:   # the continuous constants: the steps only divide
        inputs.args["steps"] = (None, 0)
    res, status = run("timestep", "hertzdamp_c_timestep_array", inputs, ("e", "steps", "m", "k_phys", "u"),
                      (law_, end_, host_), ("alpha", "tau_c", "tc_damped", "tc_elastic"))
    res = {name: np.asarray(x, dtype=np.float64) for name, x in res.items()}   # one contact too
    status = np.asarray(status)
    with np.errstate(divide="ignore", invalid="ignore"):
        res["elastic_excess"] = np.asarray(res["tc_elastic"] / res["tc_damped"] - 1.0)
        res["dt_max"] = np.asarray(res["tc_damped"] / n_steps)
        res["dt_elastic"] = np.asarray(res["tc_elastic"] / n_steps)
    for name, x in out.items():
        res[name] = np.array(np.broadcast_to(x, inputs.shape))
    res["elastic_excess"][status != 0] = 0.0
    names = list(res)
    values = finish(inputs, [res[n] for n in names], status, errors, return_status, _TIMESTEP,
                    hint=_steps_hint(inputs, law, end, host))
    table = dict(zip(names, values))
    return (table, values[-1]) if return_status else table
