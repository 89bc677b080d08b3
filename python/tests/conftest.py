"""Shared helpers of the package's tests (run by test/integration/python.sh).

The CLI comparisons need the program: HERTZDAMP_BIN (test/run_tests.sh sets it); without
it they are skipped, and python.sh counts a skip as a failure (the minimal-root wheel
test deselects them with -m "not cli" instead)."""
import json
import os
import subprocess

import numpy as np
import pytest

import hertzdamp
from hertzdamp._lib import lib


def bits(x):
    """The bit patterns of float64 values (NaN-safe exact comparison)."""
    return np.ascontiguousarray(np.asarray(x, dtype=np.float64)).view(np.uint64)


def same_bits(a, b):
    return np.array_equal(bits(a), bits(b))


@pytest.fixture(scope="session")
def capi():
    return lib


@pytest.fixture(scope="session")
def cli():
    path = os.environ.get("HERTZDAMP_BIN")
    if not path:
        pytest.skip("HERTZDAMP_BIN is not set (the hertzdamp program)")

    def run(*args):
        """The rows of `hertzdamp ARGS --format json` (exit code 0 or 3: some rows without result)."""
        p = subprocess.run([path, *map(str, args), "--format", "json", "--quiet"], capture_output=True, text=True)
        assert p.returncode in (0, 3), p.stderr
        return json.loads(p.stdout)["rows"]
    return run


RNG_SEED = 20261202


def quiet(fn, *args, **kw):
    """fn(..., errors='nan', return_status=True) without its RuntimeWarning."""
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        return fn(*args, errors="nan", return_status=True, **kw)
