"""_lot.py: locally optimal triangulations of point sets (lot/lot.h) from
numpy arrays, with scipy.spatial.Delaunay's conventions for the result."""
import ctypes
import numpy as np

from . import _lib
from ._arrays import as_coords, points_ptr, ptr
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
    counts, and the first edge the rule would flip (bad_edge, or None)."""

    def __init__(self, c):
        self.valid = bool(c.valid)
        self.interior_edges = c.interior_edges
        self.boundary_edges = c.boundary_edges
        self.decided = c.decided
        self.not_optimal = c.not_optimal
        self.bad_edge = (c.bad_edge[0], c.bad_edge[1]) if c.not_optimal else None
        self.locally_optimal = self.valid and c.not_optimal == 0

    def __bool__(self):
        return self.locally_optimal

    def __repr__(self):
        return ("Check(valid=%s, locally_optimal=%s, interior_edges=%d, decided=%d, "
                "not_optimal=%d)" % (self.valid, self.locally_optimal, self.interior_edges,
                                     self.decided, self.not_optimal))


def check(points, triangles, rule):
    """Re-verify a triangulation from scratch (lot_check): structure
    (anticlockwise, every edge in at most two triangles, Euler's count) and
    local optimality of every interior edge for the rule."""
    r = as_rule(rule)
    p = as_coords(points, "points", (-1, 2))
    t = np.asarray(triangles)
    if t.ndim != 2 or t.shape[1] != 3 or t.dtype.kind not in "iu":
        raise ValueError("triangles: expected an integer array of shape (m, 3)")
    if t.size and (t.min() < 0 or t.max() >= len(p)):
        raise ValueError("triangles: an index outside [0, %d)" % len(p))
    t = np.ascontiguousarray(t, dtype=np.uint32)
    c = _lib.LotCheckResult()
    if lib.lot_check(points_ptr(p), len(p), ptr(t, ctypes.c_uint32), len(t),
                     ctypes.byref(r._c), ctypes.byref(c)) != 0:
        raise MemoryError("lot check: out of memory")
    _raise_user_errors()
    return Check(c)


class Triangulation:
    """The result of lot(): a LOT of the input points.

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
    flips, status ("converged", "cycle", "budget exhausted"), stats (a dict
    of lot_stats: counts, cycle quadrilaterals, seconds), rule, algorithm,
    order, seed.
    neighbors and badness are computed on first use."""

    def __init__(self, points, triangles, hull, stats, rule, algorithm, order, seed):
        self.points = points
        self.triangles = triangles
        self.hull = hull
        self.rule = rule
        self.algorithm = algorithm
        self.order = order
        self.seed = seed
        self.stats = stats
        self.flips = stats["flips"]
        self.status = stats["status"]
        self._neighbors = None
        self._badness = None

    @property
    def neighbors(self):
        if self._neighbors is None:
            nb = np.empty(self.triangles.shape, dtype=np.int32)
            t = self.triangles.view(np.uint32)
            if lib.lot_neighbors(ptr(t, ctypes.c_uint32), len(t), len(self.points),
                                 ptr(nb, ctypes.c_int32)) != 0:
                raise MemoryError("lot neighbors: out of memory")
            self._neighbors = nb
        return self._neighbors

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
            self._badness = b
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
        """Re-verify from scratch (lot_check): a Check, true when locally optimal."""
        return check(self.points, self.triangles, self.rule)

    def __repr__(self):
        return ("<fliplab.Triangulation LOT(%s): %d points, %d triangles, %d flips, %s>"
                % (self.rule.name, len(self.points), len(self.triangles), self.flips,
                   self.status))


def _stats(st):
    quads = [tuple(st.cycle_quad[q][i] for i in range(4)) for q in range(st.cycle_quads)]
    return {"n": st.n, "distinct": st.distinct, "duplicates": st.duplicates, "hull": st.hull,
            "triangles": st.triangles, "flips": st.flips, "status": STATUS[st.status],
            "cycle_length": st.cycle_length, "cycle_quads": quads, "max_flips": st.max_flips,
            "seconds_init": st.seconds_init, "seconds_flip": st.seconds_flip}


def lot(points, rule="DT", algorithm="incremental", order="spatial", seed=1, max_flips=None,
        tie_eps=None, check=False):
    """A locally optimal triangulation LOT(rule) of an (n, 2) array of points,
    as `fliplab lot --rule RULE` (same algorithm, order and seed: the same
    triangles).  Exact duplicates are merged (the first occurrence
    represents them); fewer than three distinct points, all points on one
    line, or a coordinate outside the contract (0 or magnitude in [1e-30,
    1e30]) raise ValueError with the C library's message.  check=True
    re-verifies the result from scratch and raises CheckError when it is
    not locally optimal (a cycle, an exhausted budget)."""
    r = as_rule(rule)
    if tie_eps is not None:
        r = type(r)(r, tie_eps=tie_eps)
    alg = _choice(algorithm, ALGORITHMS, "algorithm")
    odr = _choice(order, ORDERS, "order")
    if odr != 0 and alg != 0:
        raise ValueError("order applies to algorithm 'incremental' only")
    p = as_coords(points, "points", (-1, 2))
    n = len(p)
    o = _lib.LotOptionsRoom()
    lib.lot_options_init(ctypes.byref(o), ctypes.byref(r._c))
    o.o.algorithm = alg
    o.o.order = odr
    o.o.seed = _u64(seed, "seed")
    o.o.max_flips = 0 if max_flips is None else _u64(max_flips, "max_flips", 1)
    o.o.tie_eps = r.tie_eps
    e = _lib.errbuf()
    if lib.lot_check_memory(n, e, _lib.ERRLEN) != 0:
        raise MemoryError(_lib.text(e))
    L = ctypes.c_void_p()
    if lib.lot_build(ctypes.byref(L), points_ptr(p), n, ctypes.byref(o), e, _lib.ERRLEN) != 0:
        msg = _lib.text(e)
        raise (MemoryError if "out of memory" in msg else ValueError)(msg)
    try:
        _raise_user_errors()
        st = lib.lot_get_stats(L).contents
        stats = _stats(st)
        tri = np.empty((st.triangles, 3), dtype=np.int32)
        lib.lot_get_triangles(L, ptr(tri, ctypes.c_uint32))
        hull = np.empty(st.hull, dtype=np.int32)
        lib.lot_get_hull(L, ptr(hull, ctypes.c_uint32))
    finally:
        lib.lot_free(L)
    res = Triangulation(p, tri, hull, stats, r, algorithm, order, int(seed))
    if check:
        c = res.check()
        if not c:
            raise CheckError("check: FAILED: %s" % (
                "not a valid triangulation" if not c.valid else
                "%d of %d interior edges not locally optimal (first %d-%d)"
                % (c.not_optimal, c.interior_edges, c.bad_edge[0], c.bad_edge[1])))
    return res
