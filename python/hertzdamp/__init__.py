"""hertzdamp: the damped Hertzian normal collision over numpy arrays.

    m z'' = -d z^q z' - k z^{3/2},   z(0) = 0,  z'(0) = u

k and d from a wanted restitution e and contact time T_c (invert, Pair), e and T_c of
given k and d (forward), the contact of two spheres from material data (materials) and
the time step its physical contact needs (timestep).  Every function runs one call of
the core library (the Fortran hertzdamp, loaded through ctypes, the GIL released) over
all contacts and broadcasts like a numpy ufunc.  Guide: doc/python.md.
"""
from ._api import Contact, forward, invert, materials, min_steps, onset_phase, phase_min_steps, timestep
from ._call import HertzdampError
from ._lib import lib as _lib
from ._oblique import oblique_correct, oblique_impact, tangential_kt
from ._pair import Pair

try:
    from ._version import __version__
except ImportError:  # a source tree (HERTZDAMP_LIBRARY): the version of fpm.toml
    import re as _re
    from pathlib import Path as _Path

    _fpm = _Path(__file__).resolve().parents[2] / "fpm.toml"
    _m = _re.search(r'(?m)^version *= *"([0-9.]+)"', _fpm.read_text()) if _fpm.is_file() else None
    __version__ = (_m.group(1) if _m else "0") + "+source"

#: the core library's file
library_path = str(_lib.path)
#: the names the library knows: laws, contact ends, host schemes, forward methods
LAWS = tuple(_lib.names_of("law"))
ENDS = tuple(_lib.names_of("end"))
HOSTS = tuple(_lib.names_of("host"))
METHODS = tuple(_lib.names_of("method"))
#: the tangential models and torque lever arms of the oblique contact
TANGENTIALS = tuple(_lib.names_of("tangential"))
LEVERS = tuple(_lib.names_of("lever"))

__all__ = ["invert", "forward", "Pair", "materials", "timestep", "min_steps", "onset_phase", "phase_min_steps",
           "Contact", "HertzdampError",
           "LAWS", "ENDS", "HOSTS", "METHODS", "library_path", "__version__", "tangential_kt", "oblique_impact",
           "oblique_correct", "TANGENTIALS", "LEVERS"]
