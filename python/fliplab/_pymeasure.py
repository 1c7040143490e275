"""_pymeasure.py: badness measures written in Python.

measure(name, fn, sign) registers fn as a measure of the registry
(measure_register), usable by name wherever a built-in one is:
badness(), rules NAME_JOINT in lot(), table34(), census(), got(),
flipgraph().  fn is called on numpy arrays of triangle quantities, a
dict of arrays keyed by the formula variables of docs/measures.md (a b c
alpha beta gamma A P R r h rx ry x1 y1 x2 y2 x3 y3), and returns an array
of the same length:

    fliplab.measure("aspect", lambda q: q["a"] / q["h"], sign=">= 0")

badness() evaluates it once on the whole array of triangles; the C
algorithms ask for one triangle at a time, and get fn on arrays of length
one through a ctypes callback (correct, about a microsecond per call
slower than a formula).  Values are checked as a plugin's are
(formula_check_value): NaN or a value outside the declared sign is an
error after the call.  An exception raised by fn is re-raised after the
call, and so is a result of the wrong length (one value per triangle, in
badness() as in the callback: _values), as the ValueError badness() gives."""
from __future__ import annotations

import ctypes
from typing import Any, Callable

import numpy as np
import numpy.typing as npt

from . import _lib
from ._arrays import as_coords, check_contract, cstr, points_ptr
from ._mirrors import TRI_VARS as VARS, GeomTri, MeasureFn
from ._rules import SIGNS

lib = _lib.lib

TRI_DTYPE = np.dtype([(n, "f8") for n in VARS])   # geom_tri's layout: 19 doubles

_SIGN = dict(zip(SIGNS, (0, 1, -1)))      # the library's measure_sign
_registry = {}      # measure id -> (fn, sign, keep-alive objects)
_pending = []       # the first exception a callback raised, re-raised after the call


def quantities(triangles: npt.ArrayLike) -> npt.NDArray[np.void]:
    """The quantities of every triangle, as the C library computes them
    (geom_tri_make: vertices in canonical order; one C pass).

    Parameters
    ----------
    triangles : array_like, shape (m, 3, 2)

    Returns
    -------
    ndarray, shape (m,)
        A structured array with the fields of the formula variables
        (docs/measures.md): x1 y1 x2 y2 x3 y3 a b c alpha beta gamma A P R r
        h rx ry.

    Raises
    ------
    ValueError
        Triangles of another shape or outside the coordinate contract.
    """
    t = as_coords(triangles, "triangles", (-1, 3, 2))
    check_contract(t, "triangle")
    out = np.empty(len(t), dtype=TRI_DTYPE)
    lib.geom_tri_make_n(out.ctypes.data_as(ctypes.POINTER(GeomTri)), points_ptr(t), len(t))
    return out


def _as_dict(rec: Any) -> dict[str, Any]:
    return {n: rec[n] for n in VARS}


def _values(out: Any, m: int, name: str) -> npt.NDArray[np.float64]:
    """fn's result as m float64 values; another length is a ValueError (a
    scalar counts as one value), the same from badness() and from the C
    algorithms' callback."""
    v = np.asarray(out, dtype=np.float64).reshape(-1)
    if v.shape != (m,):
        raise ValueError("measure %s returned %d values for %d triangles" % (name, v.size, m))
    return v


def measure(name: str, fn: Callable[[dict[str, Any]], Any], sign: str = "any",
            desc: str = "a Python measure") -> str:
    """Register a badness measure written in Python, usable by name wherever a
    built-in one is (badness(), and rules NAME_JOINT in lot(), table34(),
    census(), got(), flipgraph()).

    Parameters
    ----------
    name : str
        The new measure's name (the alphabet of measure names; not taken).
    fn : callable
        fn(q) -> array: q is a dict of numpy arrays of triangle quantities,
        keyed by the formula variables (quantities()); it returns one
        badness per triangle (small is good).
    sign : str
        "any", ">= 0" or "<= 0": the values' sign, which decides the
        joints the measure takes (docs/joints.md).
    desc : str
        A description, as measures() lists it.

    Returns
    -------
    str
        name.

    Raises
    ------
    ValueError
        An unknown sign, a name refused or taken, a NUL character, a full
        registry.
    """
    if sign not in _SIGN:
        raise ValueError("sign: expected one of %s, got %r"
                         % (", ".join(repr(x) for x in SIGNS), sign))
    bname, bdesc = cstr(name, "measure"), cstr(desc, "desc")
    e = _lib.errbuf()
    if lib.measure_check_name(b"measure", bname, e, _lib.ERRLEN) != 0:
        raise ValueError(_lib.text(e))
    if lib.measure_find(bname) >= 0:
        raise ValueError("measure '%s' is already defined" % name)
    s = _SIGN[sign]

    def one(tp, ctx):
        t = tp.contents
        try:
            q = {n: np.array([getattr(t, n)]) for n in VARS}
            v = float(_values(fn(q), 1, name)[0])
        except BaseException as ex:          # noqa: B902 - kept, re-raised after the call
            if not _pending:
                _pending.append(ex)
            v = float("nan")
        return lib.formula_check_value(bname, tp, v, s, 1)

    cb = MeasureFn(one)
    nbuf, dbuf = ctypes.create_string_buffer(bname), ctypes.create_string_buffer(bdesc)
    m = _lib.Measure(name=ctypes.cast(nbuf, ctypes.c_char_p),
                     symbol=ctypes.cast(nbuf, ctypes.c_char_p),
                     desc=ctypes.cast(dbuf, ctypes.c_char_p), sign=s,
                     fn=ctypes.cast(cb, ctypes.c_void_p), ctx=None)
    keep = [nbuf, dbuf, cb, m]      # the registry keeps pointers into these
    mid = lib.measure_register(ctypes.byref(m))
    if mid < 0:
        raise ValueError("measure '%s': the registry is full" % name)
    _registry[mid] = (fn, s, keep)
    return name


def is_python(mid: int) -> bool:
    """The measure mid was registered by measure()."""
    return mid in _registry


def raise_pending() -> None:
    """Raise the first exception a callback kept during the last C call (fn's
    own, or _values' ValueError), clearing it; called by every path into C
    that may call Python measures (_rules._raise_user_errors)."""
    if _pending:
        ex = _pending.pop()
        _pending.clear()
        raise ex


def badness_python(mid: int, triangles: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """badness() of a Python measure: fn once on the whole array."""
    fn, s, _ = _registry[mid]
    q = quantities(triangles)
    v = _values(fn(_as_dict(q)), len(q), lib.measure_get(mid).contents.name.decode())
    bad = np.isnan(v) | ((s > 0) & (v < 0)) | ((s < 0) & (v > 0))
    if bad.any():
        i = int(np.argmax(bad))
        g = GeomTri(*[float(q[i][n]) for n in VARS])
        lib.formula_check_value(lib.measure_get(mid).contents.name, ctypes.byref(g),
                                float(v[i]), s, 1)
    return v
