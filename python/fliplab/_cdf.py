"""_cdf.py: the convex-distance Delaunay graph of an empty-shape
triangulation (`fliplab lot --rule ES:SHAPE --cdf FILE`, lot/cdf.c,
docs/emptyshape.md): the triangles whose circumscribing shape is a
homothet of K, and the CDF-Delaunay edges that lie in no kept triangle."""
import ctypes
import numpy as np

from . import _lib
from ._arrays import points_ptr, ptr

lib = _lib.lib


class LotCdf(ctypes.Structure):
    """lot_cdf (lot/lot.h)."""
    _fields_ = [("triangles", ctypes.c_size_t), ("tri", ctypes.POINTER(ctypes.c_uint32)),
                ("edges", ctypes.c_size_t), ("edge", ctypes.POINTER(ctypes.c_uint32)),
                ("rounded", ctypes.c_size_t), ("conflicts", ctypes.c_size_t)]


lib.lot_cdf_extract.restype = ctypes.c_int
lib.lot_cdf_extract.argtypes = [_lib.Point_p, ctypes.POINTER(ctypes.c_uint32), ctypes.c_size_t,
                                ctypes.c_void_p, ctypes.POINTER(LotCdf)]
lib.lot_cdf_free.restype = None
lib.lot_cdf_free.argtypes = [ctypes.POINTER(LotCdf)]


class Cdf:
    """The CDF Delaunay graph: triangles (k, 3) int32 (the kept ones, rows
    of the triangulation), edges (e, 2) int32 (smaller index first,
    sorted), rounded (triangles dropped: their circumscribing shape is a
    corner's rounding shape) and conflicts (0 on an empty-shape
    triangulation)."""

    def __init__(self, triangles, edges, rounded, conflicts):
        self.triangles, self.edges = triangles, edges
        self.rounded, self.conflicts = rounded, conflicts

    def __repr__(self):
        return "<fliplab.Cdf: %d triangles, %d extra edges, %d dropped>" % (
            len(self.triangles), len(self.edges), self.rounded)


def _array(p, n, k):
    a = np.empty((n, k), dtype=np.int32)
    if n:
        ctypes.memmove(a.ctypes.data, p, a.nbytes)
    return a


def cdf(t):
    """The CDF Delaunay graph of a Triangulation made by lot() with an
    empty-shape rule ES:SHAPE, extracted as `lot --cdf` does.  A
    triangulation made with segments or holes is refused, as `lot --cdf`
    refuses a constrained run: its forced triangles have no empty shape."""
    from ._lot import Triangulation
    if not isinstance(t, Triangulation):
        raise TypeError("cdf: expected a fliplab.Triangulation (from fliplab.lot), got %s"
                        % type(t).__name__)
    if t.segments is not None or t.holes is not None:
        raise ValueError("cdf: the triangulation was made with segments or holes; the "
                         "convex-distance Delaunay graph of a constrained run is not defined "
                         "here (docs/emptyshape.md)")
    # the rule owns its shape (rule_shape): nothing is parsed again here
    r = ctypes.byref(t.rule._c)
    if not lib.rule_is_shape(r):
        raise ValueError("cdf needs an empty-shape rule (ES:SHAPE), not '%s'" % t.rule.name)
    g = LotCdf()
    tri = np.ascontiguousarray(t.triangles, dtype=np.int32).view(np.uint32)
    rc = lib.lot_cdf_extract(points_ptr(t.points), ptr(tri, ctypes.c_uint32), len(tri),
                             lib.rule_shape(r), ctypes.byref(g))
    if rc != 0:
        raise MemoryError("cdf: out of memory")
    try:
        return Cdf(_array(g.tri, g.triangles, 3), _array(g.edge, g.edges, 2), int(g.rounded),
                   int(g.conflicts))
    finally:
        lib.lot_cdf_free(ctypes.byref(g))
