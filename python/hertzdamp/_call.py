"""One array call of the library: broadcasting like a ufunc, the strides, the error policy.

run() broadcasts the inputs (numbers, lists, arrays) to one shape, hands each to the C
entry point as (address, stride) without a copy where one stride in elements describes
it (a scalar or any broadcast of one value: stride 0; a C-ordered array of the full
shape, or a 1-D slice with a step: its stride) and as a contiguous copy otherwise (an
integer or float32 array, an outer product of shapes), calls the entry point once over
all contacts, and applies the error policy (finish).
"""
from __future__ import annotations

import ctypes
import math
import warnings
from typing import Dict, Iterable, List, Optional, Sequence, Tuple

import numpy as np

from ._lib import lib

ERRORS = ("raise", "nan")


class HertzdampError(ValueError):
    """A contact the library could not compute, with the library's message.

    ``status`` is the library's status code, ``status_name`` its registry name (e.g.
    ``"bad-restitution"``), ``index`` the index of the first such contact (None for a
    single contact).
    """

    def __init__(self, message: str, status: int = 0, index: Optional[Tuple[int, ...]] = None) -> None:
        super().__init__(message)
        self.status = int(status)
        self.status_name = lib.status_names.get(self.status, "unknown")
        self.index = index


def code(kind: str, name: object, what: str) -> int:
    """The library's code of a law, end, host or method given by its name."""
    codes = lib.codes[kind]
    if not isinstance(name, str) or name not in codes:
        raise HertzdampError(f"{what} = {name!r}: use one of {', '.join(lib.names_of(kind))}",
                             lib.codes["status"]["bad-argument"])
    return codes[name]


def check_errors(errors: str) -> None:
    if errors not in ERRORS:
        raise ValueError(f"errors = {errors!r}: use 'raise' or 'nan'")


def _flat_stride(view: np.ndarray) -> Optional[int]:
    """The one stride in elements that walks view in C order, or None."""
    if view.size <= 1:
        return 0
    step: Optional[int] = None
    span = 1   # elements of the C-order flattening per step along the current axis
    for extent, stride in zip(reversed(view.shape), reversed(view.strides)):
        if extent > 1:
            if stride % view.itemsize:
                return None
            if step is None:
                step = stride // view.itemsize
                if step < 0:
                    return None
            elif stride != step * span * view.itemsize:
                return None
        span *= extent
    return step


class Inputs:
    """The broadcast inputs of one call: their shape and, per input, (address, stride)."""

    def __init__(self, fname: str, values: Dict[str, object]) -> None:
        self.fname = fname
        self.first = 1
        self.views: Dict[str, object] = {}
        self.args: Dict[str, Tuple[Optional[int], int]] = {}
        self._numbers: List[ctypes.c_double] = []
        arrays: Dict[str, np.ndarray] = {}
        for name, x in values.items():
            if x is None:
                continue
            if type(x) is int or isinstance(x, float):   # a plain number: a C double, no array
                c = ctypes.c_double(x)
                self._numbers.append(c)
                self.views[name] = c.value
                self.args[name] = (ctypes.addressof(c), 0)
                continue
            a = np.asarray(x)
            if a.dtype.kind not in "iuf":
                raise ValueError(f"hertzdamp.{fname}: {name} must be real numbers (got dtype {a.dtype})")
            arrays[name] = a
        shapes = {a.shape for a in arrays.values()}
        if len(shapes) <= 1:
            self.shape: Tuple[int, ...] = shapes.pop() if shapes else ()
        else:
            try:
                self.shape = np.broadcast_shapes(*shapes)
            except ValueError:
                given = ", ".join(f"{n} {np.shape(values[n])}" for n in values if values[n] is not None)
                raise ValueError(f"hertzdamp.{fname}: the shapes do not broadcast: {given}") from None
        self.n = math.prod(self.shape)
        for name, a in arrays.items():
            self.add(name, a)

    def add(self, name: str, a: np.ndarray) -> None:
        """Input `name` (a broadcast view, or a copy where no one stride walks it)."""
        a = np.asarray(a, dtype=np.float64)
        if a.shape == self.shape and a.flags.c_contiguous:   # the usual array: as it is
            view, stride = a, 1
        elif a.size == 1:                                     # one value for all: stride 0
            view, stride = np.broadcast_to(a, self.shape), 0
        else:
            view = np.broadcast_to(a, self.shape)
            stride = _flat_stride(view)
        if stride is None:
            view = np.ascontiguousarray(view)
            stride = 1
        self.views[name] = view
        self.args[name] = (view.ctypes.data if view.size else None, stride)

    def c_args(self, names: Iterable[str]) -> List[object]:
        """(address, stride) of each input in order; an absent one is (NULL, 0)."""
        out: List[object] = []
        for name in names:
            out.extend(self.args.get(name, (None, 0)))
        return out

    def value(self, name: str, flat: int) -> float:
        v = self.views[name]
        return float(v.reshape(-1)[flat]) if isinstance(v, np.ndarray) and v.ndim else float(v)


def run(fname: str, entry: str, inputs: Inputs, order: Sequence[str], params: Sequence[object],
        outputs: Sequence[str], prefix: Sequence[object] = ()) -> Tuple[Dict[str, np.ndarray], np.ndarray]:
    """One call of the array entry point `entry` over every contact of `inputs`:
    entry(n, *prefix, (address, stride) of each input of `order`, *params, the result
    arrays of `outputs`, the statuses).  Returns the results and the statuses (arrays of
    the broadcast shape)."""
    fn = getattr(lib, entry[len("hertzdamp_c_"):])
    if not inputs.shape:   # one contact: C doubles in and out, no arrays
        cs = [ctypes.c_double() for _ in outputs]
        st = ctypes.c_int()
        inputs.first = fn(1, *prefix, *inputs.c_args(order), *params, *(ctypes.addressof(c) for c in cs),
                          ctypes.addressof(st))
        return {name: c.value for name, c in zip(outputs, cs)}, st.value
    res = {name: np.empty(inputs.shape) for name in outputs}
    status = np.empty(inputs.shape, dtype=np.intc)
    inputs.first = 0   # the entry point's own status: 0 when every contact succeeded
    if inputs.n:
        inputs.first = fn(inputs.n, *prefix, *inputs.c_args(order), *params,
                          *(res[name].ctypes.data for name in outputs), status.ctypes.data)
    return res, status


def describe(inputs: Inputs, status: np.ndarray, failed: np.ndarray, blame: Dict[str, Sequence[str]],
             hint=None) -> HertzdampError:
    """The error of the first failed contact: the arguments its status names with their
    values, the library's message, where it is and how many failed."""
    flat = int(np.flatnonzero(failed.reshape(-1))[0])
    st = int(status.reshape(-1)[flat])
    sname = lib.status_names.get(st, "unknown")
    names = [n for n in blame.get(sname, ()) if n in inputs.views] or list(inputs.views)
    where = ", ".join(f"{n} = {inputs.value(n, flat)!r}" for n in names)
    msg = f"hertzdamp.{inputs.fname}: {where}: {lib.message(st)}"
    if hint is not None:
        extra = hint(sname, flat)
        if extra:
            msg += f" ({extra})"
    index = None
    if inputs.shape:
        index = tuple(int(i) for i in np.unravel_index(flat, inputs.shape))
        msg += f" (at index {index if len(index) > 1 else index[0]}; {int(failed.sum())} of {inputs.n} contacts failed)"
    return HertzdampError(msg, st, index)


def finish(inputs: Inputs, results: Sequence, status, errors: str, return_status: bool,
           blame: Dict[str, Sequence[str]], ok: Sequence[str] = ("ok",), hint=None):
    """The error policy: errors='raise' raises HertzdampError for the first contact whose
    status is not in `ok`; errors='nan' gives such contacts NaN and warns once
    (RuntimeWarning) with their count.  One contact (results floats, status an int) gives
    floats; the statuses follow with return_status."""
    results = list(results)
    if inputs.first != 0:   # else the library says every contact succeeded: no scan
        codes = [lib.codes["status"][name] for name in ok]
        good = np.isin(status, codes) if isinstance(status, np.ndarray) else np.asarray(status in codes)
        if not good.all():
            failed = ~good
            err = describe(inputs, np.asarray(status), failed, blame, hint)
            if errors == "raise":
                raise err
            for i, r in enumerate(results):
                if isinstance(r, np.ndarray):
                    r[failed] = np.nan
                else:
                    results[i] = math.nan
            warnings.warn(f"{int(failed.sum())} of {inputs.n} contacts failed, NaN there; the first: {err}",
                          RuntimeWarning, stacklevel=3)
    out = [float(r) if not isinstance(r, np.ndarray) or r.ndim == 0 else r for r in results]
    if return_status:
        out.append(int(status) if not isinstance(status, np.ndarray) or status.ndim == 0 else status)
    return tuple(out)
