"""_cdf.py: the convex-distance Delaunay graph of an empty-shape
triangulation (`fliplab lot --rule ES:SHAPE --cdf FILE`, lot/cdf.c,
docs/emptyshape.md): the triangles whose circumscribing shape is a
homothet of K, and the CDF-Delaunay edges that lie in no kept triangle."""
from __future__ import annotations

import ctypes
from typing import TYPE_CHECKING, Any

import numpy as np
import numpy.typing as npt

from . import _lib
from ._arrays import points_ptr, ptr
from ._mirrors import LotCdf

if TYPE_CHECKING:
    from ._lot import Triangulation

lib = _lib.lib


class Cdf:
    """The CDF Delaunay graph of an empty-shape triangulation (cdf()).

    Parameters
    ----------
    triangles : ndarray of int32, shape (k, 3)
    edges : ndarray of int32, shape (e, 2)
    rounded, conflicts : int

    Attributes
    ----------
    triangles : ndarray of int32, shape (k, 3)
        The kept triangles, rows of the triangulation.
    edges : ndarray of int32, shape (e, 2)
        CDF-Delaunay edges in no kept triangle, smaller index first, sorted.
    rounded : int
        Triangles dropped: their circumscribing shape is a corner's
        rounding shape.
    conflicts : int
        0 on an empty-shape triangulation.
    """

    def __init__(self, triangles: npt.NDArray[np.int32], edges: npt.NDArray[np.int32],
                 rounded: int, conflicts: int) -> None:
        self.triangles, self.edges = triangles, edges
        self.rounded, self.conflicts = rounded, conflicts

    def __repr__(self) -> str:
        return "<fliplab.Cdf: %d triangles, %d extra edges, %d dropped>" % (
            len(self.triangles), len(self.edges), self.rounded)


def _array(p: Any, n: int, k: int) -> npt.NDArray[np.int32]:
    a = np.empty((n, k), dtype=np.int32)
    if n:
        ctypes.memmove(a.ctypes.data, p, a.nbytes)
    return a


def cdf(t: Triangulation) -> Cdf:
    """The convex-distance Delaunay graph of an empty-shape triangulation,
    extracted as the program's lot command does (docs/emptyshape.md).

    Parameters
    ----------
    t : Triangulation
        Made by lot() with an empty-shape rule ES:SHAPE, without segments
        or holes (a constrained run's forced triangles have no empty shape).

    Returns
    -------
    Cdf

    Raises
    ------
    TypeError
        t is no Triangulation.
    ValueError
        A rule other than ES:SHAPE, or a constrained run.
    MemoryError
        The extraction ran out of memory.
    """
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
