"""_scipy.py: what scipy.spatial.Delaunay, matplotlib.tri and shapely offer
on a triangulation, for fliplab's Triangulation: exact point location
(lot_locate), the boundary edges, the edges, the vertices' neighbours, and
conversions to matplotlib and shapely and from shapely polygons.  Where
the conventions differ from scipy's: docs/python.md."""
from __future__ import annotations

import ctypes
from typing import TYPE_CHECKING, Any

import numpy as np
import numpy.typing as npt

from . import _lib
from ._arrays import as_coords, frozen, points_ptr, ptr, refuse_masked

if TYPE_CHECKING:
    from ._lot import Triangulation
    from ._rules import Rule

lib = _lib.lib

LOCATE_CONVEX, LOCATE_SCAN = 1, 2      # lot.h's LOT_LOCATE_CONVEX, LOT_LOCATE_SCAN


def cached(t, key, make):
    """t's derived array `key`, made once by make(t)."""
    if key not in t._derived:
        t._derived[key] = make(t)
    return t._derived[key]


def _queries(xi):
    """xi (..., 2) as an (m, 2) float64 array, and the shape of the answer."""
    refuse_masked(xi, "xi")
    arr = np.asarray(xi)
    if arr.ndim == 0 or arr.shape[-1] != 2:
        raise ValueError("xi: expected an array of points, shape (..., 2), got shape %s"
                         % (arr.shape,))
    return as_coords(arr.reshape(-1, 2), "xi", (-1, 2)), arr.shape[:-1]


def find_simplex(t, xi, bruteforce=False, tol=None):
    """Triangulation.find_simplex: lot_locate on t's triangles and
    neighbours, an int32 array of xi's shape without its last axis."""
    if tol is not None and tol != 0:
        raise ValueError("tol: the location is exact; only tol=None (or 0) is taken, got %r"
                         % (tol,))
    q, shape = _queries(xi)
    tri = np.ascontiguousarray(t.triangles, dtype=np.int32).view(np.uint32)
    nb = np.ascontiguousarray(t.neighbors, dtype=np.int32)
    flags = LOCATE_SCAN if bruteforce else 0
    if t.stats.get("removed") == 0:        # the triangles cover the convex hull
        flags |= LOCATE_CONVEX
    out = np.empty(len(q), dtype=np.int32)
    if lib.lot_locate(points_ptr(t.points), len(t.points), ptr(tri, ctypes.c_uint32),
                      ptr(nb, ctypes.c_int32), len(tri), flags, points_ptr(q), len(q),
                      ptr(out, ctypes.c_int32)) != 0:
        raise MemoryError("find_simplex: out of memory")
    return out.reshape(shape)


def convex_hull(t):
    """The boundary edges as scipy builds convex_hull from its neighbours:
    for each (triangle, k) with neighbors[t, k] == -1, in that order, the
    triangle's vertices other than k in their order.  O(m)."""
    tri, nb = t.triangles, t.neighbors
    rows, ks = np.nonzero(nb == -1)
    keep = np.array([[1, 2], [0, 2], [0, 1]])[ks]      # the vertices other than k, in order
    return frozen(np.ascontiguousarray(tri[rows[:, None], keep], dtype=np.int32))


def _edge_keys(t):
    """Every edge once as lo * n + hi (int64), sorted: the edge opposite
    vertex k of row r is taken from r when its neighbour there is -1 or a
    later row, so no duplicates are made to be removed.  O(m log m)."""
    tri, nb = t.triangles, t.neighbors
    once = (nb < 0) | (nb > np.arange(len(tri))[:, None])
    a = tri[:, [1, 2, 0]][once].astype(np.int64)
    b = tri[:, [2, 0, 1]][once].astype(np.int64)
    k = np.minimum(a, b) * len(t.points) + np.maximum(a, b)
    k.sort()
    return k


def edges(t):
    k = _edge_keys(t)
    n = len(t.points)
    return frozen(np.stack([k // n, k % n], axis=1).astype(np.int32))


def vertex_neighbor_vertices(t):
    """scipy's CSR pair from the edges taken both ways, sorted by (vertex,
    neighbour) as one int64 key.  O(m log m)."""
    k = _edge_keys(t)
    n = len(t.points)
    lo, hi = k // n, k % n
    both = np.concatenate([k, hi * n + lo])
    both.sort()
    indptr = np.searchsorted(both, np.arange(n + 1, dtype=np.int64) * n).astype(np.int32)
    return frozen(indptr), frozen((both % n).astype(np.int32))


def to_matplotlib(t):
    """matplotlib.tri.Triangulation of t, its neighbours given from ours:
    matplotlib's neighbors[t, j] is the triangle across the edge from
    vertex j to vertex j+1, which is ours (scipy's) opposite vertex j+2."""
    try:
        import matplotlib.tri as mtri
    except ImportError:
        raise ImportError("to_matplotlib needs matplotlib (Debian: python3-matplotlib; "
                          "pip: matplotlib)") from None
    m = mtri.Triangulation(t.points[:, 0], t.points[:, 1], np.array(t.triangles))
    if getattr(m, "_neighbors", 0) is None:        # as its own Delaunay path fills it
        m._neighbors = np.ascontiguousarray(t.neighbors[:, [2, 0, 1]], dtype=np.int32)
    return m


def _shapely():
    try:
        import shapely.geometry as sg
    except ImportError:
        raise ImportError("shapely is not installed (Debian: python3-shapely; pip: "
                          "shapely)") from None
    return sg


def to_shapely(t):
    """One shapely Polygon per triangle, anticlockwise, in row order."""
    sg = _shapely()
    coords = t.points[t.triangles]
    return [sg.Polygon(c) for c in coords]


def _ring(coords, base):
    """A ring's vertices (the closing repeat dropped) and its segments,
    numbered from base."""
    c = np.asarray(coords, dtype=np.float64)[:, :2]
    if len(c) > 1 and (c[0] == c[-1]).all():
        c = c[:-1]
    k = len(c)
    i = np.arange(k)
    return c, np.stack([base + i, base + (i + 1) % k], axis=1)


def _polygons(geom, sg):
    if isinstance(geom, sg.Polygon):
        return [geom]
    if isinstance(geom, sg.MultiPolygon):
        return list(geom.geoms)
    raise TypeError("from_shapely: expected a shapely Polygon or MultiPolygon, got %s"
                    % type(geom).__name__)


def from_shapely(geom: Any) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.int32],
                                     npt.NDArray[np.float64]]:
    """The points, segments and holes of a shapely polygon, for lot(points,
    rule, segments=segments, holes=holes).

    Every ring's vertices and edges; for each interior ring a point
    strictly inside it and outside the geometry (representative_point of
    the ring's area minus the geometry, so an island inside a hole is
    kept).  Shared vertices are repeated; lot() merges them.

    Parameters
    ----------
    geom : shapely.geometry.Polygon or shapely.geometry.MultiPolygon

    Returns
    -------
    points : ndarray of float64, shape (n, 2)
    segments : ndarray of int32, shape (k, 2)
    holes : ndarray of float64, shape (h, 2)

    Raises
    ------
    TypeError
        geom is no Polygon or MultiPolygon.
    ValueError
        The geometry is empty.
    ImportError
        shapely is not installed.
    """
    sg = _shapely()
    pts, segs, holes = [], [], []
    base = 0
    for poly in _polygons(geom, sg):
        if poly.is_empty:
            continue
        for ring in [poly.exterior] + list(poly.interiors):
            c, s = _ring(ring.coords, base)
            pts.append(c)
            segs.append(s)
            base += len(c)
        for ring in poly.interiors:
            inside = sg.Polygon(ring).difference(geom).representative_point()
            holes.append((inside.x, inside.y))
    if not pts:
        raise ValueError("from_shapely: the geometry is empty")
    return (np.concatenate(pts), np.concatenate(segs).astype(np.int32),
            np.array(holes, dtype=np.float64).reshape(-1, 2))


def lot_polygon(polygon: Any, rule: str | Rule = "DT", **kw: Any) -> Triangulation:
    """The constrained LOT of a shapely polygon (for DT the constrained
    Delaunay triangulation), its holes and outside removed: lot() of
    from_shapely(polygon).

    Parameters
    ----------
    polygon : shapely.geometry.Polygon or shapely.geometry.MultiPolygon
    rule : str or Rule
        A Rule or a rule name: "DT", MEASURE_JOINT, ES:SHAPE or a plugin's
        quadrilateral rule (Rule).
    **kw
        lot()'s other keywords (algorithm, order, seed, max_flips, tie_eps,
        check, keep_hull).

    Returns
    -------
    Triangulation

    Raises
    ------
    TypeError, ValueError, ImportError
        As from_shapely() and lot().
    """
    from ._lot import lot
    p, s, h = from_shapely(polygon)
    return lot(p, rule, segments=s, holes=h if len(h) else None, **kw)
