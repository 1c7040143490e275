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
import ctypes
import numpy as np

from . import _lib
from ._arrays import as_coords, check_contract, cstr, points_ptr

lib = _lib.lib

TRI_DTYPE = np.dtype([("x1", "f8"), ("y1", "f8"), ("x2", "f8"), ("y2", "f8"), ("x3", "f8"),
                      ("y3", "f8"), ("a", "f8"), ("b", "f8"), ("c", "f8"), ("alpha", "f8"),
                      ("beta", "f8"), ("gamma", "f8"), ("A", "f8"), ("P", "f8"), ("R", "f8"),
                      ("r", "f8"), ("h", "f8"), ("rx", "f8"), ("ry", "f8")])
VARS = TRI_DTYPE.names


class GeomTri(ctypes.Structure):
    """geom_tri (geom/geom.h): 19 doubles in TRI_DTYPE's order."""
    _fields_ = [(n, ctypes.c_double) for n in VARS]


MeasureFn = ctypes.CFUNCTYPE(ctypes.c_double, ctypes.POINTER(GeomTri), ctypes.c_void_p)
lib.measure_register.restype = ctypes.c_int
lib.measure_register.argtypes = [ctypes.POINTER(_lib.Measure)]
lib.measure_check_name.restype = ctypes.c_int
lib.measure_check_name.argtypes = [ctypes.c_char_p, ctypes.c_char_p, ctypes.c_char_p,
                                   ctypes.c_size_t]
lib.formula_check_value.restype = ctypes.c_double
lib.formula_check_value.argtypes = [ctypes.c_char_p, ctypes.POINTER(GeomTri), ctypes.c_double,
                                    ctypes.c_int, ctypes.c_int]
lib.formula_note_message.restype = None
lib.formula_note_message.argtypes = [ctypes.c_char_p]
lib.geom_tri_make_n.restype = None
lib.geom_tri_make_n.argtypes = [ctypes.POINTER(GeomTri), _lib.Point_p,
                                ctypes.c_size_t]

_SIGN = {">= 0": 1, "<= 0": -1, "any": 0}
_registry = {}      # measure id -> (fn, sign, keep-alive objects)
_pending = []       # the first exception a callback raised, re-raised after the call


def quantities(triangles):
    """The quantities of every triangle of an (m, 3, 2) array, as the C
    library computes them (geom_tri_make: vertices in canonical order): a
    structured (m,) array with the fields of VARS."""
    t = as_coords(triangles, "triangles", (-1, 3, 2))
    check_contract(t, "triangle")
    out = np.empty(len(t), dtype=TRI_DTYPE)    # geom_tri's layout: 19 doubles
    lib.geom_tri_make_n(out.ctypes.data_as(ctypes.POINTER(GeomTri)), points_ptr(t), len(t))
    return out


def _as_dict(rec):
    return {n: rec[n] for n in VARS}


def _values(out, m, name):
    """fn's result as m float64 values; another length is a ValueError (a
    scalar counts as one value), the same from badness() and from the C
    algorithms' callback."""
    v = np.asarray(out, dtype=np.float64).reshape(-1)
    if v.shape != (m,):
        raise ValueError("measure %s returned %d values for %d triangles" % (name, v.size, m))
    return v


def measure(name, fn, sign="any", desc="a Python measure"):
    """Register fn (arrays of triangle quantities -> array of badness; small
    is good) as the measure NAME; sign ">= 0", "<= 0" or "any" (the joints'
    sign convention, docs/joints.md).  Returns NAME."""
    if sign not in _SIGN:
        raise ValueError("sign: expected '>= 0', '<= 0' or 'any', got %r" % (sign,))
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


def raise_pending():
    """Raise the first exception a callback kept during the last C call (fn's
    own, or _values' ValueError), clearing it; called by every path into C
    that may call Python measures (_rules._raise_user_errors)."""
    if _pending:
        ex = _pending.pop()
        _pending.clear()
        raise ex


def badness_python(mid, triangles):
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
