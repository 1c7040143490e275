"""_averages.py: chapter 5's exact averages over all triangulations of a
convex polygon (studies/triavg.h, docs/averages.md) as fractions.Fraction:
each closed form for any n, the same averages by enumerating every
triangulation for small n, and the quantities of one given triangulation.
The values are the library's, read as exact text ("p/q"), never recomputed
here."""
from __future__ import annotations

import ctypes
from fractions import Fraction
from typing import Any

import numpy as np

from . import _lib
from ._args import is_int

lib = _lib.lib
N_MAX = 100000        # STUDY_AVG_NMAX (studies/triavg.h)
ENUM_N_MAX = 18       # STUDY_AVG_ENUM_NMAX
CH5_METHODS = ("closed", "enumerate")
CH5_QUANTITIES = _lib.c_names(lib.study_avg_name)


def _value(fn, *args):
    """A value of the library (study_avg_text's protocol, in hexadecimal: no
    limit on the digits int() converts) as a Fraction, or None."""
    size = fn(*args, 1, None, 0)
    if size == 0:
        return None
    buf = ctypes.create_string_buffer(size + 1)
    fn(*args, 1, buf, size + 1)
    num, _, den = buf.value.decode().partition("/")
    return Fraction(int(num, 16), int(den or "1", 16))


def ch5_averages(n: int, method: str = "closed", degrees: bool = True) -> dict[str, Any]:
    """Chapter 5's averages over the C_n triangulations of the convex
    (n+2)-gon, each triangulation equally likely.

    Parameters
    ----------
    n : int
        The polygon p_0 .. p_{n+1}: 1 <= n <= 100000 (closed forms), n <= 18
        to enumerate.
    method : {"closed", "enumerate"} (CH5_METHODS)
        The closed forms, or the averages over every triangulation counted
        one by one (C_18 = 477,638,700 of them at the bound: about 20 s).
    degrees : bool
        Include "G" (n binomial differences of O(n) digits each: seconds
        past n = 10^4).

    Returns
    -------
    dict
        CH5_QUANTITIES' names ("Tc", "Tc_min", "Tc_max", "A", "La", "Lmin",
        "Lmax", "deg", "Ti": docs/averages.md) to Fraction ("La", "Lmin"
        and "Lmax" are absent at n = 1: the triangle has no diagonal), and
        with degrees "G": the list of G^d_n (triangulations in which p_n
        has interior degree d), d = 0 .. n-1, as int.

    Raises
    ------
    ValueError
        n or method out of range.
    """
    if method not in CH5_METHODS:
        raise ValueError("method: expected one of %s, got %r" % (", ".join(CH5_METHODS), method))
    top = ENUM_N_MAX if method == "enumerate" else N_MAX
    if not is_int(n) or not 1 <= int(n) <= top:
        raise ValueError("n: expected an integer in [1, %d], got %r" % (top, n))
    err = _lib.errbuf()
    enum = int(method == "enumerate")
    a = lib.study_avg_new(int(n), enum, err, _lib.ERRLEN)
    if not a:
        msg = "ch5_averages: " + _lib.text(err)
        raise (MemoryError if "out of memory" in msg else ValueError)(msg)
    try:
        out: dict[str, Any] = {}
        for k, name in enumerate(CH5_QUANTITIES):
            v = _value(lib.study_avg_text, a, k, enum)
            if v is not None:
                out[name] = v
        if degrees:
            out["G"] = [int(_value(lib.study_avg_degcount_text, a, d, enum))
                        for d in range(int(n))]
        return out
    finally:
        lib.study_avg_delete(a)


def ch5_measure(triangles: Any, n_vertices: int) -> dict[str, Any]:
    """The quantities of one triangulation of the convex polygon
    p_0 .. p_{N-1} (docs/averages.md), whatever its coordinates.

    Parameters
    ----------
    triangles : array_like of int, shape (N-2, 3)
        Its triangles by vertex index, in any order.
    n_vertices : int
        N >= 3.

    Returns
    -------
    dict
        "Tc": vertices the circumcircle algorithm scans building on the
        newest side from p_0 p_{N-1}; "A": diagonals crossing the cut from
        the middle of p_{N-1} p_0 to the middle of p_k p_{k+1},
        k = floor((N-2)/2); "len_sum": the sum of the diagonals' index
        lengths; "L": len_sum / (N-3) as a Fraction (absent for N = 3);
        "degree": each vertex's interior degree (numpy uint32 array).

    Raises
    ------
    ValueError
        The triangles are no triangulation of the N-gon (the message names
        the triangle at fault).
    """
    if not is_int(n_vertices) or not 3 <= int(n_vertices) < 2 ** 32:
        raise ValueError("n_vertices: expected an integer in [3, 2^32), got %r" % (n_vertices,))
    tri = np.asarray(triangles)
    if tri.ndim != 2 or tri.shape[1] != 3 or (tri.size and tri.dtype.kind not in "iu"):
        raise ValueError("triangles: expected an integer array of shape (N-2, 3), got shape %s"
                         % (tri.shape,))
    if tri.size and (tri.min() < 0 or tri.max() >= 2 ** 32):
        raise ValueError("triangles: vertex indices must lie in [0, 2^32)")
    nv = int(n_vertices)
    tri = np.ascontiguousarray(tri, dtype=np.uint32)
    deg = np.zeros(nv, dtype=np.uint32)
    stats = (ctypes.c_uint64 * 3)()
    err = _lib.errbuf()
    if lib.study_tri_measure(tri.ctypes.data_as(_lib.c_uint32_p), tri.shape[0], nv, stats,
                             deg.ctypes.data_as(_lib.c_uint32_p), err, _lib.ERRLEN) != 0:
        msg = "triangles: " + _lib.text(err)
        raise (MemoryError if "out of memory" in msg else ValueError)(msg)
    out: dict[str, Any] = {"Tc": stats[0], "A": stats[1], "len_sum": stats[2], "degree": deg}
    if nv > 3:
        out["L"] = Fraction(stats[2], nv - 3)
    return out
