"""_arrays.py: numpy arrays in and out of the C library: validation of
point arrays against the coordinate contract of geom.h (with the C
library's own wording), pointers into arrays for ctypes, and strings for
C (cstr)."""
import ctypes
import os
import numpy as np

from . import _lib


def ptr(a, ctype):
    """A ctypes pointer to the first element of the C-contiguous array a."""
    return a.ctypes.data_as(ctypes.POINTER(ctype))


def points_ptr(a):
    return a.ctypes.data_as(_lib.Point_p)


def cstr(s, what, path=False):
    """s as the bytes of a NUL-terminated C string.  C stops reading at the
    first NUL, so "P_1\\x00junk" would silently be taken as "P_1": a str
    with a NUL inside is a ValueError, anything but a str a TypeError.
    path=True also takes bytes and os.PathLike (os.fsencode)."""
    if path and isinstance(s, (str, bytes, os.PathLike)):
        b = os.fsencode(s)
    elif isinstance(s, str):
        b = s.encode()
    else:
        raise TypeError("%s: expected a str, got %r" % (what, s))
    if b"\0" in b:
        raise ValueError("%s: %r contains a NUL character (C would read only the text "
                         "before it)" % (what, s))
    return b


def refuse_masked(a, what):
    """numpy masked arrays are refused rather than read with their masked
    values, which np.asarray keeps (scipy.spatial.Delaunay refuses them too)."""
    if isinstance(a, np.ma.MaskedArray):
        raise ValueError("%s: masked arrays are not supported (scipy refuses them too); use "
                         ".filled() or .compressed()" % what)


def frozen(a):
    """a, made read-only (a result's stored array: mutating it would
    silently disagree with what was computed from it); returns a."""
    a.flags.writeable = False
    return a


def as_coords(a, what, shape, own=False):
    """a as a C-contiguous float64 array of the given shape (None: any
    length in that axis, -1 in shape), refusing what is not real numbers.
    Integers are converted exactly when below 2^53; booleans, complex
    numbers, strings, objects and masked arrays are refused.  own=True: a
    copy even when a already is such an array (a result keeps it, and the
    caller may change a afterwards)."""
    refuse_masked(a, what)
    arr = np.asarray(a)
    if arr.dtype.kind not in "fiu":
        raise ValueError("%s: expected an array of real numbers, got dtype %s" % (what, arr.dtype))
    if arr.dtype.kind in "iu" and arr.size and np.abs(arr).max() >= 2 ** 53:
        raise ValueError("%s: an integer coordinate of magnitude 2^53 or more is not a double"
                         % what)
    if arr.ndim != len(shape) or any(s >= 0 and d != s for d, s in zip(arr.shape, shape)):
        want = "(" + ", ".join("m" if s < 0 else str(s) for s in shape) + \
            ("," if len(shape) == 1 else "") + ")"
        raise ValueError("%s: expected an array of shape %s, got shape %s"
                         % (what, want.replace("m", "n", 1) if len(shape) == 2 else want,
                            arr.shape))
    if own:
        return np.array(arr, dtype=np.float64, order="C", copy=True)
    return np.ascontiguousarray(arr, dtype=np.float64)


def check_contract(arr, what):
    """Every coordinate of arr (float64, last axis x, y) is 0 or of magnitude
    in [1e-30, 1e30] (geom_coord_check), else ValueError naming the first
    offending point, in the words of the C library."""
    flat = arr.reshape(-1, 2)
    k = _lib.lib.geom_coord_check_n(ptr(flat, ctypes.c_double), flat.size)
    if k < flat.size:
        i = k // 2
        x, y = flat[i]
        e = _lib.lib.geom_coord_check(float(x))
        if e == 0:
            e = _lib.lib.geom_coord_check(float(y))
        where = np.unravel_index(i, arr.shape[:-1])
        idx = " ".join(str(int(k)) for k in where)
        raise ValueError("%s %s (%.6g, %.6g): a coordinate %s"
                         % (what, idx, x, y, _lib.lib.geom_coorderr_str(e).decode()))


def as_indices(a, what, cols, n):
    """a as a C-contiguous uint32 array of shape (m, cols) of indices into n
    points (triangles, segments).  Integer arrays, and float arrays holding
    whole numbers only (np.loadtxt's), are accepted; NaN, fractions, indices
    outside [0, n) and other dtypes raise ValueError naming the first bad row;
    masked arrays are refused."""
    refuse_masked(a, what)
    arr = np.asarray(a)
    if arr.ndim != 2 or arr.shape[1] != cols or arr.dtype.kind not in "iuf":
        raise ValueError("%s: expected an integer array of shape (m, %d), got %s of shape %s"
                         % (what, cols, arr.dtype, arr.shape))
    if arr.dtype.kind == "f":
        bad = np.nonzero(~(np.isfinite(arr) & (arr == np.round(arr))).all(axis=1))[0]
        if len(bad):
            raise ValueError("%s %d %s: an index that is %s" % (
                what, bad[0], arr[bad[0]].tolist(),
                "NaN" if np.isnan(arr[bad[0]]).any() else "not a whole number"))
    bad = np.nonzero(((arr < 0) | (arr >= n)).any(axis=1))[0]
    if len(bad):
        raise ValueError("%s %d %s: an index outside [0, %d)"
                         % (what, bad[0], arr[bad[0]].tolist(), n))
    return np.ascontiguousarray(arr, dtype=np.uint32)
