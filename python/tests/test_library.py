"""The package reads codes and sizes from the library: its registries equal the C
header's #defines, the messages are the library's, python -m hertzdamp reports where
the library came from."""
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

import hertzdamp
from hertzdamp._lib import lib

HEADER = Path(__file__).resolve().parents[2] / "include" / "hertzdamp.h"


def defines():
    text = HEADER.read_text()
    return {m.group(1): int(m.group(2)) for m in re.finditer(r"^#define HERTZDAMP_([A-Z0-9_]+) +([0-9]+)", text, re.M)}


@pytest.mark.skipif(not HEADER.is_file(), reason="no include/hertzdamp.h beside the tests")
@pytest.mark.parametrize("kind,prefix", [("status", ""), ("end", "END_"), ("law", "DAMPING_"), ("host", "HOST_"),
                                         ("tangential", "TANGENTIAL_"), ("lever", "LEVER_")])
def test_registries_equal_the_header(kind, prefix):
    d = defines()
    names = {n: c for n, c in lib.codes[kind].items()}
    status = {k: v for k, v in d.items()
              if not k.startswith(("END_", "DAMPING_", "HOST_", "PAIR_SIZE", "TANGENTIAL_", "LEVER_"))
              or k == "HOST_UNREACHABLE"}
    if kind == "status":   # the status codes: every #define that is not an end, law, host, tangential or lever
        want = status
    else:
        want = {k[len(prefix):]: v for k, v in d.items() if k.startswith(prefix) and k not in status}
    assert {n.upper().replace("-", "_"): c for n, c in names.items()} == want


def test_sizes_and_messages():
    # the doubles of hertzdamp_pair_t: the header's HERTZDAMP_PAIR_SIZE, which the library reports
    assert lib.codes["size"]["pair"] == defines()["PAIR_SIZE"]
    assert lib.codes["size"]["stats"] == len(lib.codes["stats"])
    assert lib.message(0) == "success"
    assert lib.message(10 ** 6) == "unknown status code"
    assert hertzdamp.METHODS[:5] == ("rk45", "series", "pade", "compact", "fit")


def test_python_m_hertzdamp():
    p = subprocess.run([sys.executable, "-m", "hertzdamp"], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    assert p.stdout.startswith(f"hertzdamp {hertzdamp.__version__}\n")
    assert f"library: {hertzdamp.library_path}\n" in p.stdout
    assert Path(hertzdamp.library_path).is_file()
    if not os.environ.get("HERTZDAMP_LIBRARY"):   # an installed package: its own library, beside it
        assert Path(hertzdamp.library_path).parent == Path(hertzdamp.__file__).resolve().parent


def test_c_block_refuses_bad_calls():
    """The C block's contract (include/hertzdamp.h): unknown registries and names, short
    buffers, NULL required arrays and negative strides give HERTZDAMP_BAD_ARGUMENT and
    touch no result; n <= 0 does nothing."""
    import ctypes
    import numpy as np
    bad = lib.codes["status"]["bad-argument"]
    code = ctypes.c_int(7)
    assert lib.code(b"laws", b"linear", ctypes.addressof(code)) == bad and code.value == -1
    assert lib.code(b"law", b"hertz", ctypes.addressof(code)) == bad and code.value == -1
    assert lib.code(b"law", b"tsuji", None) == bad
    buf = ctypes.create_string_buffer(b"x" * 8)
    assert lib.names(b"law", buf, 8) == bad and buf.value == b""
    assert lib.names(b"law", buf, 0) == bad
    e, k, d, st = np.full(3, 0.5), np.full(3, -1.0), np.full(3, -1.0), np.full(3, 99, dtype=np.intc)
    law, end, none = lib.codes["law"]["linear"], lib.codes["end"]["overlap"], lib.codes["host"]["none"]
    args = [e.ctypes.data, 1] * 4 + [None, 0, None, 0, law, end, none, k.ctypes.data, d.ctypes.data, st.ctypes.data]
    assert lib.invert_array(3, *args) == 0 and np.all(st == 0) and np.all(k > 0)
    k[:] = -1.0
    st[:] = 99
    for i, value in ((1, -1), (0, None), (len(args) - 1, None)):   # a negative stride, a NULL input, NULL statuses
        a = list(args)
        a[i] = value
        assert lib.invert_array(3, *a) == bad
        assert np.all(k == -1.0) and np.all(st == 99)
    assert lib.invert_array(0, *[None, 0] * 6, law, end, none, None, None, None) == 0
    steps_missing = lib.invert_array(3, *args[:-3], k.ctypes.data, d.ctypes.data, st.ctypes.data)
    assert steps_missing == 0   # host none without steps: the continuous model
    a = list(args)
    a[14] = lib.codes["host"]["lammps"]   # a host without steps
    assert lib.invert_array(3, *a) == lib.codes["status"]["bad-steps"]


def test_one_call_of_the_entry_point_per_array(monkeypatch):
    """An array call runs the array entry point once (no Python loop over contacts), through
    a ctypes.CDLL function (ctypes releases the GIL around it)."""
    import ctypes
    import numpy as np
    assert type(lib._dll) is ctypes.CDLL
    calls = []
    for name in ("invert_array", "forward_array", "pair_kd_array", "timestep_array", "contact_array"):
        fn = getattr(lib, name)
        monkeypatch.setattr(lib, name, lambda *a, _fn=fn, _name=name: calls.append(_name) or _fn(*a))
    u = np.linspace(0.1, 5, 10000)
    k, d = hertzdamp.invert(0.9, 1e-5, 1e-6, u, host="lammps", steps=20)
    hertzdamp.forward(k, d, 1e-6, u)
    hertzdamp.Pair(0.9).kd(1e-5, 1e-6, u)
    hertzdamp.timestep(0.9, u, radius=1e-3, density=2500, youngs_modulus=63e9, poisson_ratio=0.24)
    assert calls == ["invert_array", "forward_array", "pair_kd_array", "contact_array", "timestep_array"]
