"""_lot.py: locally optimal triangulations of point sets (lot/lot.h) from
numpy arrays, with scipy.spatial.Delaunay's conventions for the result."""
import ctypes
import os
import warnings
import numpy as np

from . import _lib, _scipy
from ._arrays import as_coords, as_indices, cstr, frozen, points_ptr, ptr
from ._rules import as_rule, _raise_user_errors

lib = _lib.lib

ALGORITHMS = ("incremental", "flip", "sweep")
ORDERS = ("spatial", "input", "random")
STATUS = ("converged", "cycle", "budget exhausted")


class CheckError(RuntimeError):
    """lot(..., check=True) found a triangulation that is not a valid LOT."""


def _choice(v, names, what):
    if v not in names:
        raise ValueError("unknown %s '%s' (valid: %s)" % (what, v, ", ".join(names)))
    return names.index(v)


def _u64(v, what, lo=0):
    if isinstance(v, (bool, np.bool_)) or not isinstance(v, (int, np.integer)) \
            or not lo <= int(v) < 2 ** 64:
        raise ValueError("%s: expected an integer in [%d, 2^64), got %r" % (what, lo, v))
    return int(v)


class Check:
    """lot_check's verdict: valid (a triangulation), locally_optimal, the
    counts, and the first edge the rule would flip (bad_edge, or None).
    Constrained (lot_check_constrained): segments_missing, the input
    segments that are no chain of triangle edges, and missing_segment, the
    first of them (an index into the segments, or None); such a check
    passes when segments_missing equals the missing_ok it was given."""

    def __init__(self, c, constrained=False, missing_ok=0):
        self.valid = bool(c.valid)
        self.interior_edges = c.interior_edges
        self.boundary_edges = c.boundary_edges
        self.decided = c.decided
        self.not_optimal = c.not_optimal
        self.bad_edge = (c.bad_edge[0], c.bad_edge[1]) if c.not_optimal else None
        self.constrained = constrained
        self.segments_missing = c.segments_missing if constrained else 0
        self.missing_segment = c.missing_segment if self.segments_missing else None
        self.locally_optimal = self.valid and c.not_optimal == 0 and \
            self.segments_missing == missing_ok

    def __bool__(self):
        return self.locally_optimal

    def failure(self):
        """Why the check failed, in lot --check's words (None when it passed)."""
        if self.locally_optimal:
            return None
        if not self.valid:
            return "not a valid triangulation"
        if self.not_optimal == 0:
            return ("%d input segments are not chains of triangle edges (first: segment %d)"
                    % (self.segments_missing, self.missing_segment))
        return ("%d of %d interior edges not locally optimal (first %d-%d)"
                % (self.not_optimal, self.interior_edges, self.bad_edge[0], self.bad_edge[1]))

    def __repr__(self):
        return ("Check(valid=%s, locally_optimal=%s, interior_edges=%d, decided=%d, "
                "not_optimal=%d%s)" % (self.valid, self.locally_optimal, self.interior_edges,
                                       self.decided, self.not_optimal,
                                       ", segments_missing=%d" % self.segments_missing
                                       if self.constrained else ""))


def check(points, triangles, rule, segments=None, missing_ok=0):
    """Re-verify a triangulation from scratch (lot_check): structure
    (anticlockwise, every edge in at most two triangles, Euler's count) and
    local optimality of every interior edge for the rule.  With segments
    (a (k, 2) index array; an empty one for a triangulation with holes
    only) lot_check_constrained: each segment must be a chain of edges
    (missing_ok of them may not be: those in removed regions), its edges
    are not decided, and Euler's relation allows holes."""
    r = as_rule(rule)
    p = as_coords(points, "points", (-1, 2))
    t = as_indices(triangles, "triangles", 3, len(p))
    c = _lib.LotCheckResult()
    if segments is None:
        rc = lib.lot_check(points_ptr(p), len(p), ptr(t, ctypes.c_uint32), len(t),
                           ctypes.byref(r._c), ctypes.byref(c))
    else:
        s = as_indices(segments, "segments", 2, len(p))
        rc = lib.lot_check_constrained(points_ptr(p), len(p), ptr(t, ctypes.c_uint32), len(t),
                                       ptr(s, ctypes.c_uint32), len(s), ctypes.byref(r._c),
                                       ctypes.byref(c))
    if rc != 0:
        raise MemoryError("lot check: out of memory")
    _raise_user_errors()
    return Check(c, segments is not None, missing_ok)


class Triangulation:
    """The result of lot(): a LOT of the input points.  Its arrays are
    read-only copies: changing the caller's input afterwards changes nothing.

    points     (n, 2) float64, the input (duplicates included)
    triangles  (m, 3) int32, indices into points, anticlockwise, each
               starting at its smallest index, sorted (the rows of the
               program's --out CSV); a duplicate point is represented by
               its first occurrence
    neighbors  (m, 3) int32: neighbors[t, k] is the triangle across the
               edge opposite vertex k of triangle t, -1 on the hull
               (scipy.spatial.Delaunay.neighbors' convention)
    badness    (m,) float64, each triangle's badness under the rule (NaN
               for DT and quadrilateral rules)
    hull       the convex hull's vertices anticlockwise (collinear ones included)
    constrained (c, 2) int32: the constrained edges of a run with segments
               (the segments' pieces, split at the points on them, merged
               where they overlap; smaller index first, sorted); (0, 2)
               without; segments and holes are the run's input (or None)
    flips, status ("converged", "cycle", "budget exhausted"), stats (a dict
    of lot_stats: counts, cycle quadrilaterals, seconds), rule, algorithm,
    order, seed.
    badness is computed on first use; neighbors comes with lot()'s result
    (lot_get_neighbors, from the mesh), else on first use (lot_neighbors).

    Like scipy.spatial.Delaunay (docs/python.md, "Where it differs from
    scipy"): simplices, find_simplex(xi), convex_hull, edges,
    vertex_neighbor_vertices; and to_matplotlib(), to_shapely()."""

    def __init__(self, points, triangles, hull, stats, rule, algorithm, order, seed):
        self.points = points
        self.triangles = triangles
        self.hull = hull
        self.constrained = frozen(np.empty((0, 2), dtype=np.int32))
        self.segments = None
        self.holes = None
        self.rule = rule
        self.algorithm = algorithm
        self.order = order
        self.seed = seed
        self.stats = stats
        self.flips = stats["flips"]
        self.status = stats["status"]
        self._neighbors = None
        self._badness = None
        self._derived = {}      # convex_hull, edges, vertex_neighbor_vertices (_scipy)

    @property
    def neighbors(self):
        if self._neighbors is None:
            nb = np.empty(self.triangles.shape, dtype=np.int32)
            t = np.ascontiguousarray(self.triangles, dtype=np.int32).view(np.uint32)
            if lib.lot_neighbors(ptr(t, ctypes.c_uint32), len(t), len(self.points),
                                 ptr(nb, ctypes.c_int32)) != 0:
                raise MemoryError("lot neighbors: out of memory")
            self._neighbors = frozen(nb)
        return self._neighbors

    def find_simplex(self, xi, bruteforce=False, tol=None):
        """scipy.spatial.Delaunay.find_simplex, exact: for each point of xi
        (an array whose last axis is x, y) the index of a triangle holding
        it, -1 outside (and for NaN or infinite points); on an edge the
        smaller of its two triangles, on a vertex the smallest triangle
        with it.  lot_locate: walks in a spatial order; bruteforce=True
        scans every triangle instead (the same answers).  tol: the test is
        exact, so only None (or 0) is taken."""
        return _scipy.find_simplex(self, xi, bruteforce, tol)

    @property
    def convex_hull(self):
        """(h, 2) int32: the boundary edges (neighbors == -1), built as
        scipy.spatial.Delaunay.convex_hull is: row t's vertices without
        vertex k, in order, by triangle then k.  Without removed triangles
        these are the convex hull's edges (collinear points included);
        with holes or a removed outside, the region's boundary."""
        return _scipy.cached(self, "convex_hull", _scipy.convex_hull)

    @property
    def edges(self):
        """(e, 2) int32: every edge once, smaller index first, sorted."""
        return _scipy.cached(self, "edges", _scipy.edges)

    @property
    def vertex_neighbor_vertices(self):
        """(indptr, indices) as scipy.spatial.Delaunay's: the vertices joined
        to vertex k are indices[indptr[k]:indptr[k+1]], ascending (empty for
        a duplicate point or one in no kept triangle)."""
        return _scipy.cached(self, "vertex_neighbor_vertices",
                             _scipy.vertex_neighbor_vertices)

    def to_matplotlib(self):
        """matplotlib.tri.Triangulation(x, y, triangles), its neighbours given
        from ours in matplotlib's convention (docs/python.md)."""
        return _scipy.to_matplotlib(self)

    def to_shapely(self):
        """A list of shapely Polygons, one per triangle (row order)."""
        return _scipy.to_shapely(self)

    @property
    def simplices(self):
        """triangles, under scipy.spatial.Delaunay's name."""
        return self.triangles

    @property
    def badness(self):
        if self._badness is None:
            b = np.empty(len(self.triangles), dtype=np.float64)
            t = self.triangles.view(np.uint32)
            lib.lot_get_badness(points_ptr(self.points), ptr(t, ctypes.c_uint32), len(t),
                                ctypes.byref(self.rule._c), ptr(b, ctypes.c_double))
            _raise_user_errors()
            self._badness = frozen(b)
        return self._badness

    def total(self):
        """The triangulation's total badness: its badness values combined by
        the rule's joint (rule_total_key, then back to badness units)."""
        if not self.rule.is_triangle:
            raise ValueError("rule %s is a quadrilateral rule: no total badness"
                             % self.rule.name)
        b = np.ascontiguousarray(self.badness)
        return lib.rule_total_key(ctypes.byref(self.rule._c), ptr(b, ctypes.c_double), len(b))

    def check(self):
        """Re-verify from scratch (lot_check; lot_check_constrained for a run
        with segments or holes, as lot --check): a Check, true when locally
        optimal and every segment outside the removed regions is kept."""
        if self.segments is None and self.holes is None:
            return check(self.points, self.triangles, self.rule)
        seg = self.segments if self.segments is not None else np.empty((0, 2), np.uint32)
        return check(self.points, self.triangles, self.rule, seg,
                     self.stats["segments_removed"])

    def __repr__(self):
        return ("<fliplab.Triangulation LOT(%s): %d points, %d triangles, %d flips, %s>"
                % (self.rule.name, len(self.points), len(self.triangles), self.flips,
                   self.status))


def _stats(st):
    quads = [tuple(st.cycle_quad[q][i] for i in range(4)) for q in range(st.cycle_quads)]
    return {"n": st.n, "distinct": st.distinct, "duplicates": st.duplicates, "hull": st.hull,
            "triangles": st.triangles, "flips": st.flips, "status": STATUS[st.status],
            "cycle_length": st.cycle_length, "cycle_quads": quads, "max_flips": st.max_flips,
            "seconds_init": st.seconds_init, "seconds_flip": st.seconds_flip,
            "segments": st.segments, "constrained": st.constrained,
            "segments_merged": st.segments_merged, "segments_split": st.segments_split,
            "segments_removed": st.segments_removed, "holes": st.holes, "removed": st.removed}


def _constraints(o, n, segments, holes, keep_hull):
    """segments, holes and keep_hull into the options o, validated as the
    program's readers do (the arrays returned must outlive the call)."""
    s = None if segments is None else as_indices(segments, "segments", 2, n)
    h = None if holes is None else frozen(as_coords(holes, "holes", (-1, 2), own=True))
    if keep_hull and s is None and h is None:
        raise ValueError("keep_hull applies to constrained runs (segments, holes)")
    if s is not None:
        o.o.segments, o.o.nsegments = ptr(s, ctypes.c_uint32), len(s)
    if h is not None:
        o.o.holes, o.o.nholes = points_ptr(h), len(h)
    o.o.keep_hull = 1 if keep_hull else 0
    return s, h


def lot(points, rule="DT", algorithm="incremental", order="spatial", seed=1, max_flips=None,
        tie_eps=None, check=False, segments=None, holes=None, keep_hull=False):
    """A locally optimal triangulation LOT(rule) of an (n, 2) array of points,
    as `fliplab lot --rule RULE` (same algorithm, order and seed: the same
    triangles).  Exact duplicates are merged (the first occurrence
    represents them); fewer than three distinct points, all points on one
    line, or a coordinate outside the contract (0 or magnitude in [1e-30,
    1e30]) raise ValueError with the C library's message.  check=True
    re-verifies the result from scratch and raises CheckError when it is
    not locally optimal (a cycle, an exhausted budget).

    Constrained (`lot --segments S.csv --holes H.csv [--keep-hull]`, the
    CDT for DT): segments, a (k, 2) integer array of point indices, stay
    edges; holes, (h, 2) points, remove the regions holding them; the
    triangles outside the outermost segment-bounded region are removed
    unless keep_hull.  Crossing segments, a hole on a segment or outside
    every region raise ValueError with the C library's message."""
    r = as_rule(rule)
    if tie_eps is not None:
        r = type(r)(r, tie_eps=tie_eps)
    alg = _choice(algorithm, ALGORITHMS, "algorithm")
    odr = _choice(order, ORDERS, "order")
    if odr != 0 and alg != 0:
        raise ValueError("order applies to algorithm 'incremental' only")
    p = frozen(as_coords(points, "points", (-1, 2), own=True))
    n = len(p)
    o = _lib.LotOptionsRoom()
    lib.lot_options_init(ctypes.byref(o), ctypes.byref(r._c))
    o.o.algorithm = alg
    o.o.order = odr
    o.o.seed = _u64(seed, "seed")
    o.o.max_flips = 0 if max_flips is None else _u64(max_flips, "max_flips", 1)
    o.o.tie_eps = r.tie_eps
    seg, hol = _constraints(o, n, segments, holes, keep_hull)
    e = _lib.errbuf()
    if lib.lot_check_memory(n, e, _lib.ERRLEN) != 0:
        raise MemoryError(_lib.text(e))
    L = ctypes.c_void_p()
    if lib.lot_build(ctypes.byref(L), points_ptr(p), n, ctypes.byref(o), e, _lib.ERRLEN) != 0:
        _raise_user_errors()        # a Python measure's own error comes first
        raise _build_error(_lib.text(e))
    try:
        _raise_user_errors()
        res = _result(L, p, r, algorithm, order, int(seed))
    finally:
        lib.lot_free(L)
    res.holes = hol
    res.segments = None if seg is None else frozen(seg.astype(np.int32))
    if check:
        c = res.check()
        if not c:
            raise CheckError("check: FAILED: %s" % c.failure())
    return res


def _build_error(msg):
    """lot_build's message as the exception to raise (its words name no
    flag of the program, so they read the same here)."""
    return (MemoryError if "out of memory" in msg else ValueError)(msg)


def _result(L, p, r, algorithm, order, seed):
    """The Triangulation of a built lot L (still alive): triangles, hull,
    constrained edges and neighbours read off it, all read-only."""
    st = lib.lot_get_stats(L).contents
    stats = _stats(st)
    tri = np.empty((st.triangles, 3), dtype=np.int32)
    lib.lot_get_triangles(L, ptr(tri, ctypes.c_uint32))
    hull = np.empty(st.hull, dtype=np.int32)
    lib.lot_get_hull(L, ptr(hull, ctypes.c_uint32))
    con = np.empty((st.constrained, 2), dtype=np.int32)
    lib.lot_get_constrained(L, ptr(con, ctypes.c_uint32))
    nb = np.empty((st.triangles, 3), dtype=np.int32)
    if lib.lot_get_neighbors(L, ptr(nb, ctypes.c_int32)) != 0:
        raise MemoryError("lot neighbors: out of memory")
    res = Triangulation(p, frozen(tri), frozen(hull), stats, r, algorithm, order, seed)
    res.constrained, res._neighbors = frozen(con), frozen(nb)
    return res


def _copy(ptr_, count, cols, dtype):
    if count == 0:
        return np.empty((0, cols), dtype=dtype)
    return np.ctypeslib.as_array(ptr_, (count, cols)).astype(dtype)


def read_poly(path):
    """Triangle's .poly file as `lot --poly FILE.poly` reads it (the same C
    reader, report_poly_read, docs/formats.md): (points (n, 2) float64,
    segments (k, 2) int32 0-based, holes (h, 2) float64), ready for
    lot(points, rule, segments=segments, holes=holes).  A malformed file
    raises ValueError "FILE line N: problem"; what the file has beyond the
    graph (vertex attributes, regional attribute / area lines, boundary
    markers) is ignored with a warning, as the program's note."""
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
