"""The core library, loaded through ctypes, and the one table of the C signatures used.

The library is the shared core (libhertzdamp.so) in this package's folder, where the
wheel puts it, or the file named by the environment variable HERTZDAMP_LIBRARY (a build
tree, for development).  Codes and sizes are read from the library (its registries,
hertzdamp_c_code and hertzdamp_c_names), never written here.

Wrapping one more C function is one row of SIGNATURES (its return and argument types)
and a call of hertzdamp._call.run in the function that uses it.  ctypes releases the
GIL around every call.
"""
from __future__ import annotations

import ctypes
import os
from pathlib import Path
from typing import Dict, List

_P = ctypes.c_void_p  # an array (a numpy buffer's address) or a pointer to a result
_N = ctypes.c_ssize_t  # ptrdiff_t: a count of contacts or a stride in elements
_I = ctypes.c_int
_F = ctypes.c_double

#: name: (return type, argument types) of every C entry point the package calls.
SIGNATURES = {
    "hertzdamp_c_strerror": (ctypes.c_char_p, [_I]),
    "hertzdamp_c_code": (_I, [ctypes.c_char_p, ctypes.c_char_p, _P]),
    "hertzdamp_c_names": (_I, [ctypes.c_char_p, ctypes.c_char_p, _I]),
    # n, then (array, stride) per input, the codes, the results, the statuses
    "hertzdamp_c_invert_array": (_I, [_N] + [_P, _N] * 6 + [_I, _I, _I] + [_P] * 3),
    "hertzdamp_c_forward_array": (_I, [_N] + [_P, _N] * 4 + [_I, _I, _I, _F, _I, _F] + [_P] * 3),
    "hertzdamp_c_pair_kd_array": (_I, [_N, _P] + [_P, _N] * 4 + [_P] * 3),
    "hertzdamp_c_contact_array": (_I, [_N] + [_P, _N] * 8 + [_I] + [_P] * 6),
    "hertzdamp_c_timestep_array": (_I, [_N] + [_P, _N] * 5 + [_I, _I, _I] + [_P] * 5),
    # one material pair
    "hertzdamp_c_pair_init": (_I, [_F, _I, _I, _I, _F, _P]),
    "hertzdamp_c_pair_constants": (_I, [_P, _P, _P]),
    "hertzdamp_c_pair_stats": (_I, [_P, _I, _P]),
    "hertzdamp_c_host_min_steps": (_I, [_F, _I, _I, _I, _P]),
    # per-contact constants from the onset phase (issue 32)
    "hertzdamp_c_pair_init_phase": (_I, [_F, _I, _I, _I, _F, _P]),
    "hertzdamp_c_pair_kd_phase": (_I, [_P, _F, _F, _F, _F, _F, _P, _P]),
    "hertzdamp_c_onset_phase": (_I, [_F, _F, _F, _P]),
    "hertzdamp_c_phase_min_steps": (_I, [_F, _I, _I, _I, _P]),
    # the scalar and array entry points of C programs (the tests compare against them)
    "hertzdamp_c_invert_law": (_I, [_F, _F, _F, _F, _F, _I, _I, _P, _P]),
    "hertzdamp_c_invert_n": (_I, [_I, _P, _P, _P, _P, _I, _P, _P, _P]),
    "hertzdamp_c_forward_law": (_I, [_F, _F, _F, _F, _I, _I, _P, _P]),
    "hertzdamp_c_pair_kd": (_I, [_P, _F, _F, _F, _F, _P, _P]),
    # the oblique contact (doc/oblique.md)
    "hertzdamp_c_tangential_kt": (_I, [_I, _F, _F, _F, _P]),
    "hertzdamp_c_oblique_impact": (_I, [_F] * 6 + [_I] * 3 + [_F] * 3 + [_I, _F, _F, _P]),
    "hertzdamp_c_oblique_correct": (_I, [_F] * 5 + [_I] * 3 + [_F] * 3 + [_I] + [_F] * 4 + [_P]),
}

#: The registries read at import: kind -> {name: code}.
REGISTRIES = ("law", "end", "host", "method", "tangential", "lever", "status", "stats", "size")


def library_path() -> Path:
    """Where the core library is loaded from: $HERTZDAMP_LIBRARY, else the package folder."""
    env = os.environ.get("HERTZDAMP_LIBRARY")
    if env:
        return Path(env).resolve()
    return Path(__file__).resolve().parent / "libhertzdamp.so"


class Library:
    """The loaded core: one attribute per entry point of SIGNATURES, and the registries."""

    def __init__(self, path: Path) -> None:
        if not path.is_file():
            raise ImportError(
                f"hertzdamp: the core library {path} is missing (install the package with pip, "
                "or point HERTZDAMP_LIBRARY at a libhertzdamp.so)"
            )
        self.path = path
        self._dll = ctypes.CDLL(str(path))
        for name, (restype, argtypes) in SIGNATURES.items():
            fn = getattr(self._dll, name)
            fn.restype = restype
            fn.argtypes = argtypes
            setattr(self, name[len("hertzdamp_c_"):], fn)
        self.codes: Dict[str, Dict[str, int]] = {kind: self._registry(kind) for kind in REGISTRIES}
        self.status_names = {code: name for name, code in self.codes["status"].items()}

    def _registry(self, kind: str) -> Dict[str, int]:
        buf = ctypes.create_string_buffer(4096)
        if self.names(kind.encode(), buf, len(buf)) != 0:
            raise ImportError(f"hertzdamp: the library {self.path} has no registry {kind!r} (too old?)")
        out: Dict[str, int] = {}
        for name in buf.value.decode().split():
            code = ctypes.c_int()
            self.code(kind.encode(), name.encode(), ctypes.addressof(code))
            out[name] = code.value
        return out

    def message(self, status: int) -> str:
        """The library's message of a status code."""
        return self.strerror(int(status)).decode()

    def names_of(self, kind: str) -> List[str]:
        """The names of a registry in the order of their codes."""
        return sorted(self.codes[kind], key=self.codes[kind].__getitem__)


lib = Library(library_path())
