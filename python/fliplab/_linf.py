"""_linf.py: section 4.2's l_inf circumballs in R^d (linf/linf.h,
studies/study_linf.h; docs/linf.md): the circumcubes of d + 1 points and
the point-in-cube test, exactly; the l_inf Delaunay simplices of a small
set (brute force, or the selection algorithm of 4.2.2); theorem 14's bound
and the set that attains it; the Monte Carlo of `fliplab linf
--montecarlo`."""
from __future__ import annotations

import ctypes
from typing import Any, Dict, List, Optional

import numpy as np
import numpy.typing as npt

from . import _lib
from ._args import count, is_int, threads_arg, u64
from ._arrays import as_coords, ptr
from ._mirrors import LinfCube as _CCube
from ._mirrors import (LINF_CUBES_MAX, LINF_DIM_MAX, LINF_DIM_MIN, LINF_INFINITE,
                       LinfSelectStats, LinfSimplices, StudyLinfMc)

lib = _lib.lib
LINF_METHODS = ("brute", "select")
LINF_POINTS_MAX = 64   # linf.h: the Delaunay verbs' largest set


def _dim(d: int, what: str = "d") -> int:
    if not is_int(d) or not LINF_DIM_MIN <= int(d) <= LINF_DIM_MAX:
        raise ValueError("%s: expected a dimension in %d .. %d, got %r"
                         % (what, LINF_DIM_MIN, LINF_DIM_MAX, d))
    return int(d)


def _contract(p: npt.NDArray[np.float64], what: str) -> npt.NDArray[np.float64]:
    """p, every coordinate within the contract of geom.h, else ValueError
    naming the row and coordinate in the library's words."""
    k = lib.geom_coord_check_n(ptr(p, ctypes.c_double), p.size)
    if k < p.size:
        e = lib.geom_coord_check(float(p.flat[k]))
        row = " row %d" % (k // p.shape[1]) if p.ndim == 2 else ""
        raise ValueError("%s%s: coordinate %d (%.6g) %s" % (
            what, row, k % p.shape[-1], p.flat[k], lib.geom_coorderr_str(e).decode()))
    return p


def _rows(points: npt.ArrayLike, what: str) -> npt.NDArray[np.float64]:
    """points as rows of d coordinates, d in 2 .. 8, within the contract."""
    shape = np.shape(points)
    p = as_coords(points, what, (-1, shape[1] if len(shape) == 2 else 2))
    _dim(p.shape[1], "%s: the dimension (columns)" % what)
    return _contract(p, what)


class LinfCube:
    """An l_inf circumball (an axis-parallel cube) of d + 1 points, held
    exactly as the library holds it (linf_cube): its centre, radius and
    distances are exact decimals.

    Parameters
    ----------
    c : object
        The library's cube (made by linf_circumcubes, not by hand).
    """

    def __init__(self, c: Any) -> None:
        self._c = c

    @property
    def d(self) -> int:
        """The dimension."""
        return int(self._c.d)

    @property
    def centre(self) -> str:
        """The centre, exactly: "(c_1, ..., c_d)"."""
        b = ctypes.create_string_buffer(1024)
        lib.linf_cube_centre(ctypes.byref(self._c), b, len(b))
        return b.value.decode()

    @property
    def radius(self) -> str:
        """The radius D/2 (half the points' l_inf diameter), exactly."""
        b = ctypes.create_string_buffer(256)
        lib.linf_cube_distance(ctypes.byref(self._c), None, b, len(b))
        return b.value.decode()

    @property
    def sides(self) -> tuple[int, ...]:
        """Per coordinate, the face that holds points: +1 the max face, -1
        the min face, 0 both (a coordinate of the largest extent)."""
        return tuple(int(self._c.side[i]) for i in range(self.d))

    def _point(self, q: npt.ArrayLike) -> npt.NDArray[np.float64]:
        return _contract(as_coords(q, "q", (self.d,)), "q")

    def side(self, q: npt.ArrayLike) -> int:
        """Where q lies, exactly (linf_cube_side).

        Parameters
        ----------
        q : array_like, shape (d,)
            A point.

        Returns
        -------
        int
            -1 strictly inside the cube, 0 on its boundary, +1 outside.

        Raises
        ------
        ValueError
            q is not d real numbers within the coordinate contract.
        """
        p = self._point(q)
        return int(lib.linf_cube_side(ctypes.byref(self._c), ptr(p, ctypes.c_double)))

    def distance(self, q: npt.ArrayLike) -> str:
        """The l_inf distance from the centre to q, exactly, as decimal text.

        Parameters
        ----------
        q : array_like, shape (d,)
            A point.

        Returns
        -------
        str
            The distance ("4", "4.5").

        Raises
        ------
        ValueError
            q is not d real numbers within the coordinate contract.
        """
        p = self._point(q)
        b = ctypes.create_string_buffer(256)
        lib.linf_cube_distance(ctypes.byref(self._c), ptr(p, ctypes.c_double), b, len(b))
        return b.value.decode()

    def __repr__(self) -> str:
        return "LinfCube(centre=%s, radius=%s)" % (self.centre, self.radius)


def linf_circumcubes(points: npt.ArrayLike) -> Optional[List[LinfCube]]:
    """The l_inf circumballs (circumcubes) of d + 1 points in R^d, exactly.

    Parameters
    ----------
    points : array_like, shape (d + 1, d)
        The points, 2 <= d <= 8.

    Returns
    -------
    list of LinfCube, or None
        Every circumcube (at most 2^(d-1); of radius D/2, D the points'
        l_inf diameter), or None when there are infinitely many (the points
        are degenerate).

    Raises
    ------
    ValueError
        Not d + 1 rows of d real numbers, d out of 2 .. 8, a coordinate
        outside the contract.
    """
    p = _rows(points, "points")
    d = p.shape[1]
    if len(p) != d + 1:
        raise ValueError("points: expected d + 1 = %d rows of %d coordinates, got %d rows"
                         % (d + 1, d, len(p)))
    out = (_CCube * LINF_CUBES_MAX)()
    k = lib.linf_circumcubes(ptr(p, ctypes.c_double), d, out)
    if k == LINF_INFINITE:
        return None
    return [LinfCube(_CCube.from_buffer_copy(out[i])) for i in range(k)]


def linf_delaunay(points: npt.ArrayLike, method: str = "brute") -> npt.NDArray[np.int32]:
    """The l_inf Delaunay simplices of a small set: the (d + 1)-subsets,
    affinely independent, with a circumcube that holds no point strictly
    inside.

    Parameters
    ----------
    points : array_like, shape (n, d)
        At most 64 points, 2 <= d <= 8.
    method : str
        "brute" (every subset, every circumcube, every point) or "select"
        (the selection algorithm of section 4.2.2: from every hull facet,
        through shared facets; it finds the simplices reachable so).

    Returns
    -------
    ndarray of int32, shape (k, d + 1)
        One simplex per row, increasing indices, rows sorted.

    Raises
    ------
    ValueError
        An unknown method, more than 64 points, bad points.
    MemoryError
        Out of memory.
    """
    if method not in LINF_METHODS:
        raise ValueError("method: unknown method %r (valid: %s)"
                         % (method, ", ".join(LINF_METHODS)))
    p = _rows(points, "points")
    n, d = p.shape
    if n > LINF_POINTS_MAX:
        raise ValueError("points: at most %d, got %d" % (LINF_POINTS_MAX, n))
    s = LinfSimplices()
    lib.linf_simplices_init(ctypes.byref(s), d)
    try:
        rc = lib.linf_delaunay_brute(ptr(p, ctypes.c_double), n, d, ctypes.byref(s), None) \
            if method == "brute" else \
            lib.linf_delaunay_select(ptr(p, ctypes.c_double), n, d, ctypes.byref(s),
                                     ctypes.byref(LinfSelectStats()))
        if rc != 0:
            raise MemoryError("linf_delaunay: out of memory")
        v = np.ctypeslib.as_array(s.v, shape=(s.n * (d + 1),)).copy() if s.n else \
            np.empty(0, np.uint8)
    finally:
        lib.linf_simplices_free(ctypes.byref(s))
    return v.reshape(-1, d + 1).astype(np.int32)


def linf_bound(d: int) -> int:
    """Theorem 14: the most circumcubes of d + 1 non-degenerate points in
    R^d, 2^floor((d - 1) / 2).

    Parameters
    ----------
    d : int
        The dimension, 2 .. 8.

    Returns
    -------
    int
        The bound.

    Raises
    ------
    ValueError
        d out of 2 .. 8.
    """
    return int(lib.linf_bound(_dim(d)))


def linf_extremal(d: int) -> npt.NDArray[np.float64]:
    """The d + 1 points of theorem 14 that attain its bound (the thesis's
    R^5 example, generalised to every d).

    Parameters
    ----------
    d : int
        The dimension, 2 .. 8.

    Returns
    -------
    ndarray of float64, shape (d + 1, d)
        The points.

    Raises
    ------
    ValueError
        d out of 2 .. 8.
    """
    d = _dim(d)
    p = np.zeros((d + 1, d))
    lib.linf_extremal(d, ptr(p, ctypes.c_double))
    return p


def linf_montecarlo(d: int, trials: int, seed: int = 1, threads: int = 0) -> Dict[str, Any]:
    """Section 4.2.1's Monte Carlo, as `fliplab linf --montecarlo` runs it:
    d + 1 points uniform in the unit cube of R^d, how many circumcubes.

    Parameters
    ----------
    d : int
        The dimension, 2 .. 8 (the thesis: 5).
    trials : int
        Configurations drawn, 1 .. 2^40.
    seed : int
        Trial t comes from the stream of sample t of the seed.
    threads : int
        0 (all cores) or 1 .. MAX_THREADS; the counts are the same for any.

    Returns
    -------
    dict
        counts (a list: counts[k] trials with k circumcubes, k = 0 ..
        2^(d-1)), infinite (trials with infinitely many), law (the exact
        law's numerators, the same length) and law_total (their
        denominator; 0 above d = 5, where it is not computed), d, trials,
        seed.

    Raises
    ------
    ValueError
        d, trials, seed or threads out of range.
    """
    d, t = _dim(d), count(trials, "trials", 1)
    seed, th = u64(seed, "seed"), threads_arg(threads)
    mc, e = StudyLinfMc(), _lib.errbuf()
    if lib.study_linf_montecarlo(d, t, seed, th, ctypes.byref(mc), e, _lib.ERRLEN) != 0:
        raise ValueError(_lib.text(e))
    top = 1 << (d - 1)
    return {"d": d, "trials": t, "seed": seed,
            "counts": [int(mc.count[k]) for k in range(top + 1)], "infinite": int(mc.infinite), "law": [int(mc.law[k]) for k in range(top + 1)],
            "law_total": int(mc.law_total)}
