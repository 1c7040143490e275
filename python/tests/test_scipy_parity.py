"""test_scipy_parity.py: what the Delaunay test suites of scipy.spatial and
matplotlib.tri check, asked of fliplab.lot, written for this package: the
neighbours (read off the mesh, equal to lot_neighbors' and to scipy's),
find_simplex (exact: against an exact brute force, against scipy away
from edges, on vertices, edges and outside, in non-convex regions),
convex_hull, edges and vertex_neighbor_vertices against scipy,
degenerate input (collinear, duplicates, cocircular, too few points,
masked arrays), large offsets, orientation, to_matplotlib (its neighbours
against matplotlib's own) and shapely in and out (skipped without
shapely)."""
import sys
from fractions import Fraction

import matplotlib
matplotlib.use("Agg")
import matplotlib.tri as mtri
import numpy as np
import pytest
import scipy.spatial
from hypothesis import given, strategies as st

import fliplab


# ---- helpers ------------------------------------------------------------

def orient(a, b, c):
    """The exact sign of the orientation determinant of rows of a, b, c
    (float64 arrays (..., 2)): floating point where it clears a generous
    error bound, exact rationals (Fraction) elsewhere."""
    l = (b[..., 0] - a[..., 0]) * (c[..., 1] - a[..., 1])
    r = (b[..., 1] - a[..., 1]) * (c[..., 0] - a[..., 0])
    det = l - r
    s = np.sign(det).astype(int)
    unsure = ~(np.abs(det) > 1e-12 * (np.abs(l) + np.abs(r)))
    for i in zip(*np.nonzero(unsure)):
        A, B, C = ([Fraction(float(x)) for x in v[i]] for v in np.broadcast_arrays(a, b, c))
        d = (B[0] - A[0]) * (C[1] - A[1]) - (B[1] - A[1]) * (C[0] - A[0])
        s[i] = (d > 0) - (d < 0)
    return s


def brute_locate(p, tri, q):
    """For each query, the smallest triangle holding it (closed), or -1."""
    a, b, c = (p[tri[:, k]][None] for k in range(3))
    qq = q[:, None]
    inside = (orient(b, c, qq) >= 0) & (orient(c, a, qq) >= 0) & (orient(a, b, qq) >= 0)
    return np.where(inside.any(axis=1), inside.argmax(axis=1), -1)


def by_vertex_set(t):
    return {tuple(sorted(v)): i for i, v in enumerate(np.asarray(t))}


def edge_set(e):
    return set(map(tuple, np.sort(np.asarray(e), axis=1).tolist()))


def generic(n, seed):
    """Random points whose coordinates are multiples of 2^-20 in [0, 1): an
    offset of up to 2^32 added to them stays exact."""
    g = np.random.default_rng(seed)
    return g.integers(0, 2 ** 20, size=(n, 2)) / 2.0 ** 20


def mesh_and_lazy_neighbors(t):
    lazy = fliplab.Triangulation(t.points, t.triangles, t.hull, t.stats, t.rule, t.algorithm,
                                 t.order, t.seed)
    return t.neighbors, lazy.neighbors


# ---- neighbours ------------------------------------------------------------

@pytest.mark.parametrize("rule,alg", [("DT", "incremental"), ("DT", "sweep"), ("P_1", "flip"),
                                      ("R_inf", "incremental"), ("ES:square", "incremental")])
def test_neighbors_from_mesh_equal_lot_neighbors(rule, alg):
    p = fliplab.samplers.points(1500, "normal", 7)
    p = np.vstack([p, p[:30]])                               # duplicates too
    t = fliplab.lot(p, rule, algorithm=alg)
    mesh, lazy = mesh_and_lazy_neighbors(t)
    assert np.array_equal(mesh, lazy)


@pytest.mark.parametrize("keep", [False, True])
def test_neighbors_from_mesh_constrained(keep):
    sq = np.array([[0, 0], [8, 0], [8, 8], [0, 8], [2, 2], [6, 2], [6, 6], [2, 6]], float)
    inner = fliplab.samplers.points(300, "uniform", 3) * 8
    p = np.vstack([sq, inner, [[9, 4], [4, -1]]])
    seg = [[0, 1], [1, 2], [2, 3], [3, 0], [4, 5], [5, 6], [6, 7], [7, 4]]
    t = fliplab.lot(p, "P_1", segments=seg, holes=[[4, 4]], keep_hull=keep)
    mesh, lazy = mesh_and_lazy_neighbors(t)
    assert np.array_equal(mesh, lazy)


def test_neighbors_equal_scipy():
    p = generic(800, 1)
    t, d = fliplab.lot(p), scipy.spatial.Delaunay(p)
    ours = by_vertex_set(t.triangles)
    for s, simplex in enumerate(d.simplices):
        i = ours[tuple(sorted(simplex))]
        for k in range(3):
            kk = list(t.triangles[i]).index(simplex[k])
            other = d.neighbors[s, k]
            want = -1 if other < 0 else ours[tuple(sorted(d.simplices[other]))]
            assert t.neighbors[i, kk] == want


# ---- find_simplex ----------------------------------------------------------

@pytest.mark.parametrize("rule", ["DT", "R_inf", "-alpha_inf", "ES:hexagon"])
def test_find_simplex_equals_brute_force(rule):
    p = fliplab.samplers.points(120, "uniform", 2)
    t = fliplab.lot(p, rule)
    g = np.random.default_rng(5)
    q = np.vstack([g.uniform(-0.3, 1.3, (300, 2)), p[::3],
                   (p[t.triangles[:40, 0]] + p[t.triangles[:40, 1]]) / 2])
    want = brute_locate(p, t.triangles, q)
    assert np.array_equal(t.find_simplex(q), want)
    assert np.array_equal(t.find_simplex(q, bruteforce=True), want)


def test_find_simplex_vertices_edges_outside():
    # an integer grid: every edge's midpoint is exact, many ties (cocircular)
    x, y = np.meshgrid(np.arange(7.0), np.arange(5.0))
    p = np.stack([x.ravel(), y.ravel()], axis=1)
    t = fliplab.lot(p)
    tri = t.triangles
    f = t.find_simplex(p)                                       # vertices
    for v, s in enumerate(f):
        holding = np.nonzero((tri == v).any(axis=1))[0]
        assert s == holding.min()
    e = t.edges
    mid = (p[e[:, 0]] + p[e[:, 1]]) / 2                          # on edges
    f = t.find_simplex(mid)
    for (a, b), s in zip(e, f):
        holding = np.nonzero((tri == a).any(axis=1) & (tri == b).any(axis=1))[0]
        assert s == holding.min()
    out = np.array([[-1, 0], [7, 2], [3, -1e-300], [6 + 2 ** -40, 4], [np.nan, 1], [1, np.inf]])
    assert (t.find_simplex(out) == -1).all()
    assert np.array_equal(t.find_simplex(p, bruteforce=True), t.find_simplex(p))


def test_find_simplex_non_convex_regions():
    # a square with a square hole and an island in the hole: walks leave the
    # region through the hole and the answer comes from the scan
    outer = [[0, 0], [10, 0], [10, 10], [0, 10]]
    hole = [[2, 2], [8, 2], [8, 8], [2, 8]]
    island = [[4, 4], [6, 4], [6, 6], [4, 6]]
    p = np.array(outer + hole + island, float)
    seg = [[i + o, (i + 1) % 4 + o] for o in (0, 4, 8) for i in range(4)]
    t = fliplab.lot(p, "DT", segments=seg, holes=[[3, 3]])
    assert t.stats["removed"] > 0
    g = np.random.default_rng(9)
    q = g.uniform(-1, 11, (2000, 2))
    f = t.find_simplex(q)
    assert np.array_equal(f, brute_locate(p, t.triangles, q))
    inside_hole = (q > 2).all(axis=1) & (q < 8).all(axis=1) & \
        ~((q >= 4).all(axis=1) & (q <= 6).all(axis=1))
    assert (f[inside_hole] == -1).all() and (f[~inside_hole & (q > 0).all(axis=1)
                                               & (q < 10).all(axis=1)] >= 0).all()


def test_find_simplex_equals_scipy_away_from_edges():
    p = generic(1000, 2)
    t, d = fliplab.lot(p), scipy.spatial.Delaunay(p)
    q = np.random.default_rng(3).uniform(-0.2, 1.2, (5000, 2))
    theirs = d.find_simplex(q)
    bary = np.einsum("ijk,ik->ij", d.transform[theirs, :2], q - d.transform[theirs, 2])
    bary = np.hstack([bary, 1 - bary.sum(axis=1, keepdims=True)])
    away = (theirs < 0) | (bary.min(axis=1) > 1e-9)
    assert away.mean() > 0.99
    ours = by_vertex_set(t.triangles)
    want = np.array([ours[tuple(sorted(d.simplices[s]))] if s >= 0 else -1 for s in theirs])
    assert np.array_equal(t.find_simplex(q)[away], want[away])


def test_find_simplex_centroids_and_shapes():
    # scipy's check: each triangle's centroid is found in that triangle
    p = generic(500, 4)
    t = fliplab.lot(p, "P_1")
    c = p[t.triangles].mean(axis=1)
    assert np.array_equal(t.find_simplex(c), np.arange(len(t.triangles)))
    assert t.find_simplex(c[:6].reshape(3, 2, 2)).shape == (3, 2)
    assert t.find_simplex(c[0]).shape == ()
    assert t.find_simplex(np.empty((0, 2))).shape == (0,)
    assert t.find_simplex(c, tol=None).dtype == np.int32
    with pytest.raises(ValueError, match="tol"):
        t.find_simplex(c, tol=1e-9)
    with pytest.raises(ValueError, match="xi"):
        t.find_simplex(np.zeros((4, 3)))


def test_find_simplex_large_and_tiny_queries():
    p = generic(50, 5)
    t = fliplab.lot(p)
    q = np.array([[1e300, 1e300], [-1e300, 0.5], [0.5, 5e-324], [1e-40, 1e-40]])
    assert np.array_equal(t.find_simplex(q), brute_locate(p, t.triangles, q))


# ---- convex_hull, edges, vertex_neighbor_vertices --------------------------

@pytest.mark.parametrize("seed", [1, 2, 3])
def test_convex_hull_edges_vnv_equal_scipy(seed):
    p = generic(700, seed)
    t, d = fliplab.lot(p), scipy.spatial.Delaunay(p)
    assert edge_set(t.convex_hull) == edge_set(d.convex_hull)
    assert t.convex_hull.dtype == np.int32 and t.convex_hull.shape == (len(t.hull), 2)
    ip, ind = t.vertex_neighbor_vertices
    sip, sind = d.vertex_neighbor_vertices
    for k in range(len(p)):
        assert list(ind[ip[k]:ip[k + 1]]) == sorted(sind[sip[k]:sip[k + 1]])
    e = t.edges
    assert e.dtype == np.int32 and (e[:, 0] < e[:, 1]).all()
    assert np.array_equal(e, np.unique(e, axis=0))                  # sorted, unique
    assert edge_set(e) == edge_set(np.vstack([d.simplices[:, [0, 1]], d.simplices[:, [1, 2]],
                                              d.simplices[:, [0, 2]]]))
    assert len(e) == 3 * len(p) - len(t.hull) - 3                    # Euler


def test_convex_hull_rows_built_as_scipy():
    p = generic(200, 6)
    t = fliplab.lot(p)
    rows = []
    for i, k in zip(*np.nonzero(t.neighbors == -1)):
        rows.append([v for j, v in enumerate(t.triangles[i]) if j != k])
    assert np.array_equal(t.convex_hull, rows)


def test_vnv_skips_duplicates():
    p = generic(60, 7)
    p = np.vstack([p, p[:5]])
    ip, ind = fliplab.lot(p).vertex_neighbor_vertices
    assert len(ip) == 66 and (np.diff(ip)[60:] == 0).all() and ind.max() < 60


# ---- degenerate input, offsets, orientation ---------------------------------

def test_degenerate_input():
    with pytest.raises(ValueError, match="collinear"):
        fliplab.lot([[0, 0], [1, 1], [2, 2], [3, 3], [4, 4]])
    with pytest.raises(ValueError, match="collinear"):
        fliplab.lot([[0, 0], [1e-20, 1e-20], [1, 1]])
    for few in ([[0, 0], [1, 0]], [[0, 0], [1, 0], [1, 0]], np.empty((0, 2))):
        with pytest.raises(ValueError):
            fliplab.lot(few)
    with pytest.raises(ValueError, match="masked"):
        fliplab.lot(np.ma.masked_array([[0, 0], [1, 0], [0, 1]]))
    # duplicates are merged, not dropped: the first occurrence represents them
    p = np.array([[0, 0], [1, 0], [0, 1], [1, 1], [0, 0], [1, 1], [0.5, 0.25]])
    t = fliplab.lot(p)
    assert t.stats["duplicates"] == 2 and not np.isin([4, 5], t.triangles).any()
    u = fliplab.lot(np.delete(p, [4, 5], axis=0)).triangles      # point 6 is its point 4
    assert np.array_equal(t.triangles, np.where(u == 4, 6, u))


def test_cocircular_square():
    p = np.array([[0, 0], [0, 1], [1, 1], [1, 0]], float)        # scipy's 2-d square
    t = fliplab.lot(p)
    assert len(t.triangles) == 2 and t.check()
    assert edge_set(t.convex_hull) == {(0, 1), (1, 2), (2, 3), (0, 3)}
    assert sorted(t.neighbors.ravel().tolist()) == [-1, -1, -1, -1, 0, 1]
    assert t.find_simplex([0.5, 0.5]) == 0                          # on the diagonal: the smaller
    assert t.find_simplex([0.25, 0.5]) in (0, 1)
    assert (t.find_simplex([[1.5, 0.5], [-0.5, 0.5]]) == -1).all()


def test_pathological_cocircular_sets_keep_every_point():
    # points on circles and on a grid: many cocircular and collinear subsets,
    # which Qhull joggles or reports as coplanar; the exact DT keeps them all
    a = np.arange(24) * 2 * np.pi / 24
    circle = np.stack([np.cos(a), np.sin(a)], axis=1)
    x, y = np.meshgrid(np.arange(-3.0, 4.0), np.arange(-3.0, 4.0))
    grid = np.stack([x.ravel(), y.ravel()], axis=1)
    for p in (circle, np.vstack([circle * 4, grid]), grid):
        t = fliplab.lot(p, check=True)
        assert set(t.triangles.ravel()) == set(range(len(p)))
        assert len(t.triangles) == 2 * len(p) - len(t.hull) - 2


@pytest.mark.parametrize("offset", [1e6, -3e7, 2.0 ** 31])
def test_large_offsets_give_the_same_triangles(offset):
    # generic points on a 2^-20 grid: p + offset is exact, and the exact DT
    # (ties included: the tie-break is by lexicographic order) is invariant
    p = generic(2000, 8)
    t = fliplab.lot(p)
    for q in (p + offset, p + [offset, 0], p + [0, offset]):
        assert np.array_equal(fliplab.lot(q).triangles, t.triangles)
    x, y = np.meshgrid(np.arange(10.0), np.arange(10.0))             # a grid: ties everywhere
    g = np.stack([x.ravel(), y.ravel()], axis=1)
    assert np.array_equal(fliplab.lot(g + offset).triangles, fliplab.lot(g).triangles)
    d = scipy.spatial.Delaunay(p)
    assert edge_set(fliplab.lot(p + offset).edges) == edge_set(
        np.vstack([d.simplices[:, [0, 1]], d.simplices[:, [1, 2]], d.simplices[:, [0, 2]]]))


def test_nearly_collinear_rows():
    # two rows of points whose x steps and y values round, nearly collinear:
    # a classic failure of non-robust Delaunay codes (matplotlib's robustness test)
    top = np.stack([0.8660254037844384 - np.arange(4) * 0.10825317547305482,
                    np.full(4, -0.5000000000000004)], axis=1)
    top[2:, 1] = -0.5000000000000003
    low = np.stack([0.811898816047911 - np.arange(3) * 0.10825317547305482,
                    [-0.40625000000000044, -0.4062500000000004, -0.40625000000000033]], axis=1)
    p = np.vstack([top, low])
    q = np.array([[0.58, -0.46], [0.65, -0.46], [0.65, -0.42], [0.7, -0.48], [0.7, -0.44],
                  [0.75, -0.44], [0.8, -0.48]])
    for pts in (p, p[1:]):
        t = fliplab.lot(pts, check=True)
        a, b, c = (pts[t.triangles[:, k]][None] for k in range(3))
        inside = (orient(b, c, q[:, None]) > 0) & (orient(c, a, q[:, None]) > 0) & \
            (orient(a, b, q[:, None]) > 0)
        assert (inside.sum(axis=1) <= 1).all()                       # no overlaps
        f = t.find_simplex(q)
        assert np.array_equal(f, brute_locate(pts, t.triangles, q))


@pytest.mark.parametrize("rule", ["DT", "P_1", "R_inf", "ES:square"])
def test_all_triangles_anticlockwise(rule):
    p = np.vstack([generic(400, 9), [[0.5, 0.5], [0.5 + 2 ** -40, 0.5]]])
    t = fliplab.lot(p, rule)
    a, b, c = (p[t.triangles[:, k]] for k in range(3))
    assert (orient(a, b, c) > 0).all()


# ---- matplotlib ------------------------------------------------------------

@pytest.mark.parametrize("rule", ["DT", "P_1"])
def test_to_matplotlib(rule):
    p = fliplab.samplers.points(400, "normal", 3)
    t = fliplab.lot(p, rule)
    m = t.to_matplotlib()
    assert isinstance(m, mtri.Triangulation)
    assert np.array_equal(m.triangles, t.triangles)
    assert np.array_equal(m.x, p[:, 0]) and np.array_equal(m.y, p[:, 1])
    own = mtri.Triangulation(p[:, 0], p[:, 1], np.array(t.triangles))
    assert np.array_equal(m.neighbors, own.neighbors)                # matplotlib's own result
    assert np.array_equal(m.neighbors, t.neighbors[:, [2, 0, 1]])    # the conventions' link
    assert edge_set(m.edges) == edge_set(t.edges)
    c = p[t.triangles].mean(axis=1)
    assert np.array_equal(m.get_trifinder()(c[:, 0], c[:, 1]), t.find_simplex(c))


def test_to_matplotlib_constrained():
    p, seg = np.array([[0, 0], [4, 0], [4, 4], [0, 4], [1, 1], [3, 1], [3, 3], [1, 3]], float), \
        [[0, 1], [1, 2], [2, 3], [3, 0], [4, 5], [5, 6], [6, 7], [7, 4]]
    t = fliplab.lot(p, "DT", segments=seg, holes=[[2, 2]])
    own = mtri.Triangulation(p[:, 0], p[:, 1], np.array(t.triangles))
    assert np.array_equal(t.to_matplotlib().neighbors, own.neighbors)


def test_missing_packages_say_so(monkeypatch):
    t = fliplab.lot(generic(10, 1))
    monkeypatch.setitem(sys.modules, "matplotlib.tri", None)
    with pytest.raises(ImportError, match="to_matplotlib needs matplotlib"):
        t.to_matplotlib()
    monkeypatch.setitem(sys.modules, "shapely", None)
    monkeypatch.setitem(sys.modules, "shapely.geometry", None)
    with pytest.raises(ImportError, match="shapely is not installed"):
        t.to_shapely()
    with pytest.raises(ImportError, match="shapely is not installed"):
        fliplab.from_shapely(None)


# ---- shapely ---------------------------------------------------------------

def test_shapely_in_and_out():
    sg = pytest.importorskip("shapely.geometry")
    from shapely.ops import unary_union
    outer = [(0, 0), (10, 0), (10, 10), (0, 10)]
    hole = [(2, 2), (2, 8), (8, 8), (8, 2)]
    poly = sg.Polygon(outer, [hole])
    p, s, h = fliplab.from_shapely(poly)
    assert p.shape == (8, 2) and s.shape == (8, 2) and h.shape == (1, 2)
    assert s.dtype == np.int32 and set(s.ravel()) == set(range(8))
    assert sg.Polygon(hole).contains(sg.Point(h[0]))
    t = fliplab.lot_polygon(poly, "DT", check=True)
    tris = t.to_shapely()
    assert len(tris) == len(t.triangles)
    assert all(isinstance(x, sg.Polygon) and len(x.exterior.coords) == 4 for x in tris)
    assert sum(x.area for x in tris) == pytest.approx(poly.area, rel=1e-12)
    assert unary_union(tris).symmetric_difference(poly).area == pytest.approx(0, abs=1e-9)
    assert np.array_equal(np.array(tris[0].exterior.coords)[:3], t.points[t.triangles[0]])


def test_shapely_island_in_a_hole_and_multipolygons():
    sg = pytest.importorskip("shapely.geometry")
    ring = sg.Polygon([(0, 0), (10, 0), (10, 10), (0, 10)], [[(1, 1), (9, 1), (9, 9), (1, 9)]])
    island = sg.Polygon([(3, 3), (7, 3), (7, 7), (3, 7)])
    far = sg.Polygon([(20, 0), (24, 0), (22, 3)])
    multi = sg.MultiPolygon([ring, island, far])
    p, s, h = fliplab.from_shapely(multi)
    assert len(h) == 1 and not island.contains(sg.Point(h[0]))       # the island is kept
    t = fliplab.lot_polygon(multi, "P_1", check=True)
    assert sum(x.area for x in t.to_shapely()) == pytest.approx(multi.area, rel=1e-12)
    assert t.find_simplex([5, 5]) >= 0 and t.find_simplex([2, 2]) == -1
    assert t.find_simplex([15, 1]) == -1 and t.find_simplex([22, 1]) >= 0
    with pytest.raises(TypeError, match="Polygon or MultiPolygon"):
        fliplab.from_shapely(sg.Point(0, 0))
    with pytest.raises(ValueError, match="empty"):
        fliplab.from_shapely(sg.Polygon())


# ---- property: find_simplex and the mesh's neighbours on degenerate sets -----

@given(st.lists(st.tuples(st.integers(-4, 4), st.integers(-4, 4)), min_size=3, max_size=30),
       st.sampled_from(["DT", "P_1", "R_inf", "ES:square"]))
def test_find_simplex_on_lattices(pts, rule):
    # integer points: collinear and cocircular subsets, duplicates; the
    # queries are every half-integer point around them (on vertices, on
    # edges, inside, outside)
    p = np.array(pts, dtype=float)
    try:
        t = fliplab.lot(p, rule)
    except ValueError:
        return                                       # too few or all collinear
    mesh, lazy = mesh_and_lazy_neighbors(t)
    assert np.array_equal(mesh, lazy)
    x, y = np.meshgrid(np.arange(-9, 10) / 2, np.arange(-9, 10) / 2)
    q = np.stack([x.ravel(), y.ravel()], axis=1)
    assert np.array_equal(t.find_simplex(q), brute_locate(p, t.triangles, q))
