"""_lot.py: locally optimal triangulations of point sets (lot/lot.h) from
numpy arrays, with scipy.spatial.Delaunay's conventions for the result.
The run's options go to C through the lot_options verbs and are checked
by lot_options_check; its statistics and checks come back by field name
(docs/python.md, "How the package talks to the library")."""
from __future__ import annotations

import ctypes
import os
import warnings
from typing import Any

import numpy as np
import numpy.typing as npt

from . import _lib, _scipy
from ._args import choice, u64
from ._arrays import as_coords, as_indices, cstr, frozen, points_ptr, ptr
from ._mirrors import LotDiff
from ._rules import Rule, as_rule, _raise_user_errors

lib = _lib.lib

# Indexed by lot/lot.h's lot_algorithm, lot_order and lot_status.
ALGORITHMS = ("incremental", "flip", "sweep")
ORDERS = ("spatial", "input", "random")
STATUS = ("converged", "cycle", "budget exhausted")


class CheckError(RuntimeError):
    """lot(..., check=True) found a triangulation that is not a valid LOT."""


class Check:
    """lot_check's verdict on a triangulation (check(), Triangulation.check()).

    Parameters
    ----------
    counts : dict of str to int
        lot_check_result's fields by name (lot_check_result_field).
    constrained : bool
        The check was lot_check_constrained's.
    missing_ok : int
        How many input segments may be missing (those in removed regions).

    Attributes
    ----------
    valid : bool
        A triangulation: anticlockwise, every edge in at most two
        triangles, Euler's count.
    locally_optimal : bool
        Valid, no interior edge the rule would flip, segments_missing equal
        to missing_ok; also the Check's truth value.
    interior_edges, boundary_edges, decided, not_optimal : int
        The counts.
    bad_edge : tuple of int or None
        The first edge the rule would flip.
    segments_missing : int
        Input segments that are no chain of triangle edges (constrained).
    missing_segment : int or None
        The first of them, an index into the segments.
    """

    def __init__(self, counts: dict[str, int], constrained: bool = False,
                 missing_ok: int = 0) -> None:
        self.valid = bool(counts["valid"])
        self.interior_edges = counts["interior_edges"]
        self.boundary_edges = counts["boundary_edges"]
        self.decided = counts["decided"]
        self.not_optimal = counts["not_optimal"]
        self.bad_edge = tuple(counts["bad_edge"]) if self.not_optimal else None
        self.constrained = constrained
        self.segments_missing = counts["segments_missing"] if constrained else 0
        self.missing_segment = counts["missing_segment"] if self.segments_missing else None
        self.locally_optimal = self.valid and self.not_optimal == 0 and \
            self.segments_missing == missing_ok

    def __bool__(self) -> bool:
        return self.locally_optimal

    def failure(self) -> str | None:
        """Why the check failed, in the words of the program's check.

        Returns
        -------
        str or None
            None when the check passed.
        """
        if self.locally_optimal:
            return None
        if not self.valid:
            return "not a valid triangulation"
        if self.not_optimal == 0:
            return ("%d input segments are not chains of triangle edges (first: segment %d)"
                    % (self.segments_missing, self.missing_segment))
        return ("%d of %d interior edges not locally optimal (first %d-%d)"
                % (self.not_optimal, self.interior_edges, self.bad_edge[0], self.bad_edge[1]))

    def __repr__(self) -> str:
        return ("Check(valid=%s, locally_optimal=%s, interior_edges=%d, decided=%d, "
                "not_optimal=%d%s)" % (self.valid, self.locally_optimal, self.interior_edges,
                                       self.decided, self.not_optimal,
                                       ", segments_missing=%d" % self.segments_missing
                                       if self.constrained else ""))


_CHECK_FIELDS = _lib.c_names(lib.lot_check_result_field)
_CHECK_PAIRS = ("bad_edge",)    # the arrays of lot_check_result: two elements each


def _check_counts(c: int) -> dict[str, Any]:
    """lot_check_result c by name (lot_check_result_get_u64)."""
    get = lib.lot_check_result_get_u64
    return {f: [_lib.get_u64(get, c, f, i) for i in range(2)] if f in _CHECK_PAIRS
            else _lib.get_u64(get, c, f) for f in _CHECK_FIELDS}


def check(points: npt.ArrayLike, triangles: npt.ArrayLike, rule: str | Rule,
          segments: npt.ArrayLike | None = None, missing_ok: int = 0,
          weights: npt.ArrayLike | None = None) -> Check:
    """Re-verify a triangulation from scratch, as the program's check does.

    lot_check: structure (anticlockwise, every edge in at most two
    triangles, Euler's count) and local optimality of every interior edge
    for the rule.  With segments, lot_check_constrained: each segment must
    be a chain of edges (missing_ok of them may not be: those in removed
    regions), its edges are not decided, and Euler's relation allows holes.

    Parameters
    ----------
    points : array_like, shape (n, 2)
    triangles : array_like, shape (m, 3)
        Indices into points, anticlockwise.
    rule : str or Rule
        A Rule or a rule name: "DT", MEASURE_JOINT, ES:SHAPE or a plugin's
        quadrilateral rule (Rule).
    segments : array_like, shape (k, 2), optional
        Point indices of the segments; an empty (0, 2) array for a
        triangulation with holes only.
    missing_ok : int
        How many segments may be no chain of edges.
    weights : array_like, shape (n,), optional
        Per-site weights of rule "WDT" (lot_check_weighted): every interior
        edge, convex quadrilateral or not, must pass the power test, so the
        triangulation is the regular one of the sites it uses.

    Returns
    -------
    Check
        True when the triangulation is a valid LOT.

    Raises
    ------
    ValueError
        Bad arrays or rule.
    MemoryError
        The check ran out of memory.
    """
    r = as_rule(rule)
    p = as_coords(points, "points", (-1, 2))
    t = as_indices(triangles, "triangles", 3, len(p))
    s = None if segments is None else as_indices(segments, "segments", 2, len(p))
    w = None if weights is None else _weights(weights, len(p))
    c = lib.lot_check_result_new()
    if not c:
        raise MemoryError("check: out of memory")
    try:
        if w is not None and s is None:
            rc = lib.lot_check_weighted(points_ptr(p), ptr(w, ctypes.c_double), len(p),
                                        ptr(t, ctypes.c_uint32), len(t), ctypes.byref(r._c), c)
        elif s is None:
            rc = lib.lot_check(points_ptr(p), len(p), ptr(t, ctypes.c_uint32), len(t),
                               ctypes.byref(r._c), c)
        else:
            rc = lib.lot_check_constrained(points_ptr(p), len(p), ptr(t, ctypes.c_uint32),
                                           len(t), ptr(s, ctypes.c_uint32), len(s),
                                           ctypes.byref(r._c), c)
        counts = _check_counts(c)
    finally:
        lib.lot_check_result_free(c)
    if rc != 0:
        raise MemoryError("check: out of memory")
    _raise_user_errors()
    return Check(counts, s is not None, missing_ok)


class Triangulation:
    """The result of lot(): a LOT of the input points.

    Its arrays are read-only copies: changing the caller's input afterwards
    changes nothing.  Like scipy.spatial.Delaunay (docs/python.md, "Where
    it differs from scipy"): simplices, find_simplex(xi), convex_hull,
    edges, vertex_neighbor_vertices; and to_matplotlib(), to_shapely().

    Parameters
    ----------
    points, triangles, hull, stats, rule, algorithm, order, seed
        The attributes of those names (lot() makes Triangulations).

    Attributes
    ----------
    points : ndarray of float64, shape (n, 2)
        The input, duplicates included.
    triangles : ndarray of int32, shape (m, 3)
        Indices into points, anticlockwise, each starting at its smallest
        index, sorted (the rows of the program's output file); a duplicate
        point is represented by its first occurrence.
    neighbors : ndarray of int32, shape (m, 3)
        neighbors[t, k] is the triangle across the edge opposite vertex k of
        triangle t, -1 on the boundary (scipy.spatial.Delaunay.neighbors'
        convention): read off the mesh by lot(), else made on first use.
    badness : ndarray of float64, shape (m,)
        Each triangle's badness under the rule (NaN for DT and
        quadrilateral rules), computed on first use.
    hull : ndarray of int32
        The convex hull's vertices anticlockwise (collinear ones included).
    constrained : ndarray of int32, shape (c, 2)
        The constrained edges of a run with segments (the segments' pieces,
        split at the points on them, merged where they overlap; smaller
        index first, sorted); (0, 2) without.
    segments, holes : ndarray or None
        The run's constraints.
    weights : ndarray of float64, shape (n,), or None
        The run's per-site weights (rule "WDT").
    redundant : ndarray of int32
        A weighted run's redundant sites, ascending: their power cells are
        empty, no regular triangulation keeps them, and the triangles leave
        them out (empty without weights).
    flips : int
    status : str
        One of "converged", "cycle", "budget exhausted" (STATUS).
    stats : dict
        lot_stats by field name (counts, the cycle's quadrilaterals, seconds).
    rule : Rule
    algorithm : str
        lot()'s: "incremental", "flip" or "sweep" (ALGORITHMS).
    order : str
        lot()'s: "spatial", "input" or "random" (ORDERS).
    seed : int
    """

    def __init__(self, points: npt.NDArray[np.float64], triangles: npt.NDArray[np.int32],
                 hull: npt.NDArray[np.int32], stats: dict[str, Any], rule: Rule,
                 algorithm: str, order: str, seed: int) -> None:
        self.points = points
        self.triangles = triangles
        self.hull = hull
        self.constrained = frozen(np.empty((0, 2), dtype=np.int32))
        self.segments: npt.NDArray[np.int32] | None = None
        self.holes: npt.NDArray[np.float64] | None = None
        self.weights: npt.NDArray[np.float64] | None = None
        self.redundant = frozen(np.empty(0, dtype=np.int32))
        self.rule = rule
        self.algorithm = algorithm
        self.order = order
        self.seed = seed
        self.stats = stats
        self.flips = stats["flips"]
        self.status = stats["status"]
        self._neighbors: npt.NDArray[np.int32] | None = None
        self._badness: npt.NDArray[np.float64] | None = None
        self._derived: dict[str, Any] = {}    # convex_hull, edges, ... (_scipy)

    @property
    def neighbors(self) -> npt.NDArray[np.int32]:
        """(m, 3) int32: the triangle across the edge opposite each vertex, -1
        on the boundary (lot_get_neighbors in lot(), else lot_neighbors)."""
        if self._neighbors is None:
            nb = np.empty(self.triangles.shape, dtype=np.int32)
            t = np.ascontiguousarray(self.triangles, dtype=np.int32).view(np.uint32)
            if lib.lot_neighbors(ptr(t, ctypes.c_uint32), len(t), len(self.points),
                                 ptr(nb, ctypes.c_int32)) != 0:
                raise MemoryError("neighbors: out of memory")
            self._neighbors = frozen(nb)
        return self._neighbors

    def find_simplex(self, xi: npt.ArrayLike, bruteforce: bool = False,
                     tol: float | None = None) -> npt.NDArray[np.int32]:
        """scipy.spatial.Delaunay.find_simplex, exact (lot_locate).

        Parameters
        ----------
        xi : array_like, shape (..., 2)
            Query points.
        bruteforce : bool
            Scan every triangle instead of walking (the same answers).
        tol : None or 0
            The test is exact: no tolerance is taken.

        Returns
        -------
        ndarray of int32, shape xi.shape[:-1]
            For each point the index of a triangle holding it, -1 outside
            (and for NaN or infinite points); on an edge the smaller of its
            two triangles, on a vertex the smallest triangle with it.

        Raises
        ------
        ValueError
            xi of another shape or dtype, a tol other than None or 0.
        MemoryError
            The location ran out of memory.
        """
        return _scipy.find_simplex(self, xi, bruteforce, tol)

    @property
    def convex_hull(self) -> npt.NDArray[np.int32]:
        """(h, 2) int32: the boundary edges (neighbors == -1), built as
        scipy.spatial.Delaunay.convex_hull is: row t's vertices without
        vertex k, in order, by triangle then k.  Without removed triangles
        these are the convex hull's edges (collinear points included);
        with holes or a removed outside, the region's boundary."""
        return _scipy.cached(self, "convex_hull", _scipy.convex_hull)

    @property
    def edges(self) -> npt.NDArray[np.int32]:
        """(e, 2) int32: every edge once, smaller index first, sorted."""
        return _scipy.cached(self, "edges", _scipy.edges)

    @property
    def vertex_neighbor_vertices(self) -> tuple[npt.NDArray[np.int32], npt.NDArray[np.int32]]:
        """(indptr, indices) as scipy.spatial.Delaunay's: the vertices joined
        to vertex k are indices[indptr[k]:indptr[k+1]], ascending (empty for
        a duplicate point or one in no kept triangle)."""
        return _scipy.cached(self, "vertex_neighbor_vertices",
                             _scipy.vertex_neighbor_vertices)

    def to_matplotlib(self) -> Any:
        """The triangulation for matplotlib.

        Returns
        -------
        matplotlib.tri.Triangulation
            Triangulation(x, y, triangles), its neighbours given from ours
            in matplotlib's convention (docs/python.md).

        Raises
        ------
        ImportError
            matplotlib is not installed.
        """
        return _scipy.to_matplotlib(self)

    def to_shapely(self) -> list[Any]:
        """The triangles as shapely polygons.

        Returns
        -------
        list of shapely.geometry.Polygon
            One per triangle, anticlockwise, in row order.

        Raises
        ------
        ImportError
            shapely is not installed.
        """
        return _scipy.to_shapely(self)

    @property
    def simplices(self) -> npt.NDArray[np.int32]:
        """triangles, under scipy.spatial.Delaunay's name."""
        return self.triangles

    @property
    def badness(self) -> npt.NDArray[np.float64]:
        """(m,) float64: each triangle's badness under the rule (lot_get_badness)."""
        if self._badness is None:
            b = np.empty(len(self.triangles), dtype=np.float64)
            t = self.triangles.view(np.uint32)
            lib.lot_get_badness(points_ptr(self.points), ptr(t, ctypes.c_uint32), len(t),
                                ctypes.byref(self.rule._c), ptr(b, ctypes.c_double))
            _raise_user_errors()
            self._badness = frozen(b)
        return self._badness

    def total(self) -> float:
        """The triangulation's total badness.

        Returns
        -------
        float
            The badness values combined by the rule's joint (rule_total_key,
            then back to badness units).

        Raises
        ------
        ValueError
            The rule is a quadrilateral rule.
        """
        if not self.rule.is_triangle:
            raise ValueError("rule %s is a quadrilateral rule: no total badness"
                             % self.rule.name)
        b = np.ascontiguousarray(self.badness)
        return lib.rule_total_key(ctypes.byref(self.rule._c), ptr(b, ctypes.c_double), len(b))

    def compare(self, other: Triangulation) -> dict[str, int]:
        """The edges and triangles this triangulation shares with another of
        the same points, as the program's compare DT line counts them
        (lot_compare).

        Parameters
        ----------
        other : Triangulation
            A triangulation of the same points (lot()'s result).

        Returns
        -------
        dict
            edges_a, edges_b, edges_common, triangles_a, triangles_b,
            triangles_common (a: this one, b: other).

        Raises
        ------
        ValueError
            other is of other points.
        MemoryError
            Out of memory.
        """
        if not isinstance(other, Triangulation) or not np.array_equal(self.points,
                                                                      other.points):
            raise ValueError("compare: expected a triangulation of the same points")
        a = np.ascontiguousarray(self.triangles, dtype=np.uint32)
        b = np.ascontiguousarray(other.triangles, dtype=np.uint32)
        d = LotDiff()
        if lib.lot_compare(ptr(a, ctypes.c_uint32), len(a), ptr(b, ctypes.c_uint32), len(b),
                           ctypes.byref(d)) != 0:
            raise MemoryError("compare: out of memory")
        return {n: int(getattr(d, n)) for n, _ in LotDiff._fields_}

    def check(self) -> Check:
        """Re-verify from scratch, as the program's check does.

        Returns
        -------
        Check
            lot_check's verdict (lot_check_constrained's for a run with
            segments or holes): true when locally optimal and every segment
            outside the removed regions is kept.

        Raises
        ------
        MemoryError
            The check ran out of memory.
        """
        if self.segments is None and self.holes is None:
            return check(self.points, self.triangles, self.rule, weights=self.weights)
        seg = self.segments if self.segments is not None else np.empty((0, 2), np.uint32)
        return check(self.points, self.triangles, self.rule, seg,
                     self.stats["segments_removed"])

    def __repr__(self) -> str:
        return ("<fliplab.Triangulation LOT(%s): %d points, %d triangles, %d flips, %s>"
                % (self.rule.name, len(self.points), len(self.triangles), self.flips,
                   self.status))


# lot_stats' fields are counts or times: read each by the getter that has it
_STAT_GETTERS = ((lambda s, f, v: lib.lot_stats_get_u64(s, f, 0, v), ctypes.c_uint64),
                 (lib.lot_stats_get_double, ctypes.c_double))


def _stats(L: Any) -> dict[str, Any]:
    """lot_stats of L by field name, as the library names them; status as
    its name in STATUS, cycle_quads as the list of the cycle's
    quadrilaterals (cycle_quad's rows) rather than their count."""
    s = lib.lot_get_stats(L)
    out = {f: _lib.get_value(s, f, _STAT_GETTERS) for f in _lib.LOT_STATS_FIELDS
           if f != "cycle_quad"}
    out["status"] = STATUS[out["status"]]
    out["cycle_quads"] = [tuple(_lib.get_u64(lib.lot_stats_get_u64, s, "cycle_quad", 4 * q + k)
                                for k in range(4)) for q in range(out["cycle_quads"])]
    return out


def _options(o: int, r: Rule, alg: int, odr: int, seed: int, max_flips: int) -> None:
    """The run's options into the lot_options o (each checked before)."""
    if lib.lot_options_set_algorithm(o, alg) != 0 or lib.lot_options_set_order(o, odr) != 0 \
            or lib.lot_options_set_tie_eps(o, r.tie_eps) != 0:
        raise ValueError("lot: the library refused algorithm %r, order %r or tie_eps %r"
                         % (ALGORITHMS[alg], ORDERS[odr], r.tie_eps))
    lib.lot_options_set_seed(o, seed)
    lib.lot_options_set_max_flips(o, max_flips)


def _constraints(o: int, n: int, segments: npt.ArrayLike | None, holes: npt.ArrayLike | None,
                 keep_hull: bool) -> tuple[Any, Any]:
    """segments, holes and keep_hull into the options o, validated as the
    program's readers do (the arrays returned must outlive the call)."""
    s = None if segments is None else as_indices(segments, "segments", 2, n)
    h = None if holes is None else frozen(as_coords(holes, "holes", (-1, 2), own=True))
    if s is not None:
        lib.lot_options_set_segments(o, ptr(s, ctypes.c_uint32), len(s))
    if h is not None:
        lib.lot_options_set_holes(o, points_ptr(h), len(h))
    lib.lot_options_set_keep_hull(o, 1 if keep_hull else 0)
    return s, h


def lot(points: npt.ArrayLike, rule: str | Rule = "DT", algorithm: str = "incremental",
        order: str = "spatial", seed: int = 1, max_flips: int | None = None,
        tie_eps: float | None = None, check: bool = False,
        segments: npt.ArrayLike | None = None, holes: npt.ArrayLike | None = None,
        keep_hull: bool = False, weights: npt.ArrayLike | None = None) -> Triangulation:
    """A locally optimal triangulation LOT(rule) of a point set, as the
    program's lot command makes it (the same algorithm, order and seed: the
    same triangles).

    Exact duplicates are merged (the first occurrence represents them).
    Constrained (for DT the constrained Delaunay triangulation): segments
    stay edges, holes remove the regions holding them, and the triangles
    outside the outermost segment-bounded region are removed unless
    keep_hull.

    Parameters
    ----------
    points : array_like, shape (n, 2)
        Coordinates 0 or of magnitude in [1e-30, 1e30].
    rule : str or Rule
        A Rule or a rule name: "DT", MEASURE_JOINT ("P_1", "-alpha_inf"),
        ES:SHAPE or a plugin's quadrilateral rule (Rule).
    algorithm : str
        "incremental" (insert, then flip back to a LOT), "flip" (a sweep
        triangulation, then Lawson's flips) or "sweep" (the sweepline
        algorithm: rule DT or ES:SHAPE).
    order : str
        The insertion order of algorithm "incremental": "spatial" (BRIO
        rounds along a Hilbert curve), "input" or "random".
    seed : int
        The random order's seed, in [0, 2^64).
    max_flips : int, optional
        Stop after this many flips (status "budget exhausted"); default
        1000 n + 10^7.
    tie_eps : float, optional
        The rule's relative tie tolerance (default the rule's).
    check : bool
        Re-verify the result from scratch (Triangulation.check()).
    segments : array_like, shape (k, 2), optional
        Point indices of segments that must stay edges.
    holes : array_like, shape (h, 2), optional
        Hole points: the regions holding them are removed.
    keep_hull : bool
        With segments or holes: keep the triangles outside the outermost
        segment-bounded region.
    weights : array_like, shape (n,), optional
        Per-site weights of rule "WDT", the weighted Delaunay rule (each 0
        or of magnitude in [1e-60, 1e60]): the regular triangulation, with
        the redundant sites left out and listed (Triangulation.redundant).

    Returns
    -------
    Triangulation

    Raises
    ------
    ValueError
        Fewer than three distinct points, all on one line, a coordinate
        outside the contract, crossing segments, a misplaced hole, options
        that do not go together (order with another algorithm, keep_hull
        without constraints: the library's lot_options_check), a bad rule
        or keyword (the library's message, or one naming the keyword).
    MemoryError
        The points do not fit in memory.
    CheckError
        check=True and the result is not locally optimal (a cycle, an
        exhausted budget).
    """
    r = as_rule(rule)
    if tie_eps is not None:
        r = Rule(r, tie_eps=tie_eps)
    alg = choice(algorithm, ALGORITHMS, "algorithm")
    odr = choice(order, ORDERS, "order")
    seed = u64(seed, "seed")
    flips = 0 if max_flips is None else u64(max_flips, "max_flips", 1)
    p = frozen(as_coords(points, "points", (-1, 2), own=True))
    n = len(p)
    o = lib.lot_options_new(ctypes.byref(r._c))
    if not o:
        raise MemoryError("lot: out of memory")
    try:
        _options(o, r, alg, odr, seed, flips)
        seg, hol = _constraints(o, n, segments, holes, keep_hull)
        w = None if weights is None else _weights(weights, n)
        if w is not None:
            lib.lot_options_set_weights(o, ptr(w, ctypes.c_double))
        e = _lib.errbuf()
        if lib.lot_options_check(o, e, _lib.ERRLEN) != 0:     # which options go together
            raise ValueError(_lib.text(e))
        res = _build(p, o, r, algorithm, order, seed)
    finally:
        lib.lot_options_free(o)
    res.holes, res.weights = hol, w
    res.segments = None if seg is None else frozen(seg.astype(np.int32))
    if check:
        c = res.check()
        if not c:
            raise CheckError("check: FAILED: %s" % c.failure())
    return res


def _build(p: npt.NDArray[np.float64], o: int, r: Rule, algorithm: str, order: str,
           seed: int) -> Triangulation:
    """lot_build with the options o, and its Triangulation."""
    n = len(p)
    e = _lib.errbuf()
    if lib.lot_check_memory(n, e, _lib.ERRLEN) != 0:
        raise MemoryError(_lib.text(e))
    L = ctypes.c_void_p()
    if lib.lot_build(ctypes.byref(L), points_ptr(p), n, o, e, _lib.ERRLEN) != 0:
        _raise_user_errors()        # a Python measure's own error comes first
        raise _build_error(_lib.text(e))
    try:
        _raise_user_errors()
        return _result(L, p, r, algorithm, order, seed)
    finally:
        lib.lot_free(L)


def _build_error(msg: str) -> Exception:
    """lot_build's message as the exception to raise (its words name no
    flag of the program, so they read the same here)."""
    return (MemoryError if "out of memory" in msg else ValueError)(msg)


def _result(L: Any, p: npt.NDArray[np.float64], r: Rule, algorithm: str, order: str,
            seed: int) -> Triangulation:
    """The Triangulation of a built lot L (still alive): triangles, hull,
    constrained edges and neighbours read off it, all read-only."""
    stats = _stats(L)
    m = stats["triangles"]
    tri = np.empty((m, 3), dtype=np.int32)
    lib.lot_get_triangles(L, ptr(tri, ctypes.c_uint32))
    hull = np.empty(stats["hull"], dtype=np.int32)
    lib.lot_get_hull(L, ptr(hull, ctypes.c_uint32))
    con = np.empty((stats["constrained"], 2), dtype=np.int32)
    lib.lot_get_constrained(L, ptr(con, ctypes.c_uint32))
    nb = np.empty((m, 3), dtype=np.int32)
    if lib.lot_get_neighbors(L, ptr(nb, ctypes.c_int32)) != 0:
        raise MemoryError("neighbors: out of memory")
    red = np.empty(stats["redundant"], dtype=np.int32)
    lib.lot_get_redundant(L, ptr(red, ctypes.c_uint32))
    res = Triangulation(p, frozen(tri), frozen(hull), stats, r, algorithm, order, seed)
    res.constrained, res._neighbors, res.redundant = frozen(con), frozen(nb), frozen(red)
    return res


def _weights(weights: npt.ArrayLike, n: int) -> npt.NDArray[np.float64]:
    """Per-site weights as a read-only float64 copy of n values (the library
    checks each against the weight contract)."""
    w = as_coords(weights, "weights", (n,), own=True)
    return frozen(w)


def _copy(ptr_: Any, count: int, cols: int, dtype: Any) -> np.ndarray:
    if count == 0:
        return np.empty((0, cols), dtype=dtype)
    return np.ctypeslib.as_array(ptr_, (count, cols)).astype(dtype)


def read_poly(path: str | bytes | os.PathLike[str]) -> tuple[
        npt.NDArray[np.float64], npt.NDArray[np.int32], npt.NDArray[np.float64]]:
    """Triangle's .poly file, read by the program's own reader
    (report_poly_read, docs/formats.md).

    What the file has beyond the graph (vertex attributes, regional
    attribute / area lines, boundary markers) is ignored with a
    UserWarning, as the program's note.

    Parameters
    ----------
    path : str, bytes or os.PathLike
        The .poly file.

    Returns
    -------
    points : ndarray of float64, shape (n, 2)
    segments : ndarray of int32, shape (k, 2)
        Numbered from 0.
    holes : ndarray of float64, shape (h, 2)
        Ready for lot(points, rule, segments=segments, holes=holes).

    Raises
    ------
    ValueError
        A malformed file: "FILE line N: problem" (the program's message).
    MemoryError
        The file does not fit in memory.
    """
    pf = _lib.ReportPoly()
    e = _lib.errbuf()
    if lib.report_poly_read(cstr(path, "path", path=True), ctypes.byref(pf), e,
                            _lib.ERRLEN) != 0:
        msg = _lib.text(e)
        raise (MemoryError if "out of memory" in msg else ValueError)(msg)
    try:
        g = pf.g
        pts = _copy(ctypes.cast(g.pts, _lib.c_double_p), g.npts, 2, np.float64)
        seg = _copy(g.seg, g.nseg, 2, np.int32)
        hol = _copy(ctypes.cast(g.hole, _lib.c_double_p), g.nholes, 2, np.float64)
        note = (pf.attributes, pf.regions, pf.markers)
    finally:
        lib.report_poly_free(ctypes.byref(pf))
    if any(note):
        warnings.warn("%s: ignored: %d vertex attribute(s), %d regional attribute/area "
                      "line(s)%s" % (os.fsdecode(path), note[0], note[1],
                                     ", boundary markers" if note[2] else ""), stacklevel=2)
    return pts, seg, hol
