"""test_cdt.py: constrained triangulations from Python (lot(..., segments,
holes, keep_hull), read_poly) against the program on the same files (the
same triangles and counts), scipy.spatial.Delaunay (segments that are
Delaunay edges leave the DT unchanged), matplotlib (a point-in-polygon
oracle for the removed regions, Triangulation accepts every output) and
hypothesis (random non-crossing segment sets never crash and pass the
independent check); bad input raises ValueError with the C message."""
import matplotlib
matplotlib.use("Agg")
import matplotlib.path as mpath
import matplotlib.tri as mtri
import numpy as np
import pytest
import scipy.spatial
from hypothesis import given, strategies as st

import fliplab
from conftest import stdout_field, write_points


def tri_sets(t):
    return set(map(tuple, np.sort(np.asarray(t), axis=1)))


def edge_set(tri):
    t = np.asarray(tri)
    e = np.vstack([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]])
    return set(map(tuple, np.sort(e, axis=1)))


def some_edges(p, rule, k, seed):
    """k edges of a triangulation of p (never crossing, no point inside one)."""
    e = sorted(edge_set(fliplab.lot(p, rule).triangles))
    pick = np.random.default_rng(seed).choice(len(e), size=min(k, len(e)), replace=False)
    return np.array([e[i] for i in sorted(pick)], dtype=np.int64)


def ring(first, count):
    return np.array([(first + i, first + (i + 1) % count) for i in range(count)])


def star_with_hole(n=300, seed=1):
    """n uniform points in the unit square and two rings: a star-shaped
    12-gon around them (its notches leave part of the square outside) and
    a small square around the centre, with a hole point at the centre."""
    p = fliplab.samplers.points(n, "uniform", seed)
    p = (p - p.min(axis=0)) / (p.max(axis=0) - p.min(axis=0)) * 0.8 + 0.1
    ang = np.arange(12) * (2 * np.pi / 12) + 0.1
    rad = np.where(np.arange(12) % 2 == 0, 0.7, 0.45)
    star = 0.5 + rad[:, None] * np.c_[np.cos(ang), np.sin(ang)]
    hole = 0.5 + np.array([[-0.1, -0.1], [0.1, -0.1], [0.1, 0.1], [-0.1, 0.1]]) + 1e-3
    pts = np.vstack([p, star, hole])
    seg = np.vstack([ring(n, 12), ring(n + 12, 4)])
    return pts, seg, np.array([[0.5, 0.5]]), star, hole


def write_rows(path, header, rows, fmt):
    with open(path, "w") as f:
        f.write(header + "\n")
        for r in rows:
            f.write(",".join(fmt % v for v in r) + "\n")


def write_poly(path, p, seg, holes):
    with open(path, "w") as f:
        f.write("%d 2 0 0\n" % len(p))
        for i, (x, y) in enumerate(p):
            f.write("%d %r %r\n" % (i, float(x), float(y)))
        f.write("%d 0\n" % len(seg))
        for i, (a, b) in enumerate(seg):
            f.write("%d %d %d\n" % (i, a, b))
        f.write("%d\n" % len(holes))
        for i, (x, y) in enumerate(holes):
            f.write("%d %r %r\n" % (i, float(x), float(y)))


def cli_lot(cli, rule, p, seg, holes, keep_hull=False, extra=()):
    write_points(cli.file("p.csv"), p)
    args = ["lot", "--rule", rule, "--points", cli.file("p.csv"), "--out", cli.file("o.csv")]
    if seg is not None:
        write_rows(cli.file("s.csv"), "i,j", seg, "%d")
        args += ["--segments", cli.file("s.csv")]
    if holes is not None:
        write_points(cli.file("h.csv"), holes)
        args += ["--holes", cli.file("h.csv")]
    run = cli.run(*(args + (["--keep-hull"] if keep_hull else []) + list(extra)))
    return run, np.array([[int(x) for x in r[:3]] for r in cli.rows("o.csv")[1:]])


@pytest.mark.parametrize("rule,alg", [("DT", "incremental"), ("P_1", "incremental"),
                                      ("-alpha_inf", "flip"), ("DT", "sweep")])
def test_same_as_cli(cli, rule, alg):
    p, seg, holes, _, _ = star_with_hole()
    seg = np.vstack([seg, some_edges(p[:300], "R_1", 30, 2)])      # and free segments inside
    for keep in (False, True):
        run, cli_tri = cli_lot(cli, rule, p, seg, holes, keep, ["--algorithm", alg, "--check"])
        t = fliplab.lot(p, rule, algorithm=alg, segments=seg, holes=holes, keep_hull=keep,
                        check=True)
        assert np.array_equal(t.triangles, cli_tri)
        st_ = t.stats
        assert stdout_field(run.stdout, "segments").startswith(
            "%d (%d constrained edges; %d merged, %d split, %d in removed regions)"
            % (st_["segments"], st_["constrained"], st_["segments_merged"],
               st_["segments_split"], st_["segments_removed"]))
        assert stdout_field(run.stdout, "holes").startswith(
            "%d (%d triangles removed" % (st_["holes"], st_["removed"]))
        assert t.flips == int(stdout_field(run.stdout, "flips"))
        assert stdout_field(run.stdout, "check").startswith("ok")


def test_poly_same_as_cli(cli):
    p, seg, holes, _, _ = star_with_hole(200, 3)
    path = cli.file("in.poly")
    write_poly(path, p, seg, holes)
    pp, ss, hh = fliplab.read_poly(path)
    assert np.array_equal(pp, p) and np.array_equal(ss, seg) and np.array_equal(hh, holes)
    assert ss.dtype == np.int32 and pp.dtype == hh.dtype == np.float64
    cli.run("lot", "--rule", "P_1", "--poly", path, "--out", cli.file("o.csv"))
    cli_tri = np.array([[int(x) for x in r[:3]] for r in cli.rows("o.csv")[1:]])
    t = fliplab.lot(pp, "P_1", segments=ss, holes=hh)
    assert np.array_equal(t.triangles, cli_tri)


def test_poly_notes_and_errors(cli):
    path = cli.file("m.poly")
    with open(path, "w") as f:           # 1-based, an attribute, markers, a region line
        f.write("4 2 1 1\n1 0 0 5 1\n2 1 0 5 1\n3 1 1 5 1\n4 0 1 5 1\n"
                "4 1\n1 1 2 1\n2 2 3 1\n3 3 4 1\n4 4 1 1\n0\n1\n1 0.5 0.5 7 0.1\n")
    with pytest.warns(UserWarning, match="ignored: 1 vertex attribute"):
        p, s, h = fliplab.read_poly(path)
    assert s.tolist() == [[0, 1], [1, 2], [2, 3], [3, 0]] and h.shape == (0, 2)
    run = cli.run("lot", "--rule", "DT", "--poly", path)
    assert "ignored: 1 vertex attribute(s), 1 regional attribute/area line(s), boundary " \
           "markers" in run.stderr
    bad = cli.file("bad.poly")
    with open(bad, "w") as f:
        f.write("3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n1 0\n0 0 7\n0\n")
    with pytest.raises(ValueError) as e:
        fliplab.read_poly(bad)
    run = cli.run("lot", "--rule", "DT", "--poly", bad, ok=False)
    assert run.returncode != 0 and str(e.value) in run.stderr and "line 6" in str(e.value)
    with pytest.raises(ValueError, match="cannot read"):
        fliplab.read_poly(cli.file("missing.poly"))


@pytest.mark.parametrize("rule", ["DT", "P_1", "R_1"])
def test_segments_are_edges(rule):
    p = fliplab.samplers.points(500, "normal", 7)
    seg = some_edges(p, "-alpha_inf", 80, 1)
    t = fliplab.lot(p, rule, segments=seg, keep_hull=True, check=True)
    assert set(map(tuple, np.sort(seg, axis=1))) <= edge_set(t.triangles)
    assert set(map(tuple, t.constrained)) == set(map(tuple, np.sort(seg, axis=1)))
    assert t.constrained.dtype == np.int32
    assert len(t.triangles) == 2 * len(p) - len(t.hull) - 2     # nothing removed
    assert t.stats["removed"] == 0 and t.stats["segments"] == len(seg)


def test_segments_through_points_are_split():
    g = np.array([(x, y) for x in range(6) for y in range(6)], dtype=float)
    g = g + np.array([0.0, 1e-9]) * (np.arange(36) % 7)[:, None] * (g[:, 1:] != 2)
    seg = np.array([[2, 32]])                                # (0,2) to (5,2): through 4 points
    t = fliplab.lot(g, "DT", segments=seg, keep_hull=True, check=True)
    row = [i for i in range(36) if g[i, 1] == 2]
    assert set(map(tuple, t.constrained)) == {(row[i], row[i + 1]) for i in range(5)}
    assert t.stats["segments_split"] == 1 and t.stats["constrained"] == 5


def test_delaunay_segments_keep_scipy():
    p = fliplab.samplers.points(800, "uniform", 12)
    d = scipy.spatial.Delaunay(p)
    e = sorted(edge_set(d.simplices))
    seg = np.array([e[i] for i in range(0, len(e), 7)])
    t = fliplab.lot(p, "DT", segments=seg, keep_hull=True, check=True)
    assert tri_sets(t.triangles) == tri_sets(d.simplices)
    # the hull as a ring of segments: nothing outside, the same triangles without keep_hull
    h = fliplab.lot(p, "DT").hull
    t2 = fliplab.lot(p, "DT", segments=np.vstack([seg, np.c_[h, np.roll(h, -1)]]), check=True)
    assert tri_sets(t2.triangles) == tri_sets(d.simplices) and t2.stats["removed"] == 0


def area(p, tri):
    a, b, c = (p[tri[:, i]] for i in range(3))
    return 0.5 * ((b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1])
                  - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0]))


def polygon_area(v):
    x, y = v[:, 0], v[:, 1]
    return 0.5 * abs(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))


@pytest.mark.parametrize("rule", ["DT", "P_1", "-alpha_inf"])
def test_holes_remove_inside(rule):
    p, seg, holes, star, hole = star_with_hole(400, 5)
    outer, inner = mpath.Path(star), mpath.Path(hole)
    full = fliplab.lot(p, rule, segments=seg, holes=holes, keep_hull=True, check=True)
    t = fliplab.lot(p, rule, segments=seg, holes=holes, check=True)
    for tr, keep in ((full, True), (t, False)):
        cen = p[tr.triangles].mean(axis=1)
        assert not inner.contains_points(cen).any()               # the hole is empty
        if not keep:
            assert outer.contains_points(cen).all()               # and so is the outside
        assert (area(p, tr.triangles) > 0).all()
    # what is kept covers the region: areas add up (the triangles do not overlap: check)
    assert np.isclose(area(p, t.triangles).sum(), polygon_area(star) - polygon_area(hole),
                      rtol=1e-12)
    hull_area = polygon_area(p[fliplab.lot(p, "DT").hull])
    assert np.isclose(area(p, full.triangles).sum(), hull_area - polygon_area(hole),
                      rtol=1e-12)
    removed = full.stats["triangles"] + full.stats["removed"] - t.stats["triangles"]
    assert t.stats["removed"] == removed


@pytest.mark.parametrize("keep", [False, True])
def test_matplotlib_accepts(keep):
    p, seg, holes, _, _ = star_with_hole(300, 8)
    for rule in ("DT", "P_1", "a_2"):
        t = fliplab.lot(p, rule, segments=seg, holes=holes, keep_hull=keep)
        tr = mtri.Triangulation(p[:, 0], p[:, 1], t.triangles)
        tr.get_trifinder()              # raises for overlapping or badly oriented triangles
        assert (tr.triangles == t.triangles).all()


def test_check_standalone():
    p, seg, holes, _, _ = star_with_hole(100, 9)
    t = fliplab.lot(p, "P_1", segments=seg, holes=holes)
    c = fliplab.check(p, t.triangles, "P_1", seg)
    assert c and c.constrained and c.segments_missing == 0 and c.missing_segment is None
    assert not fliplab.check(p, t.triangles, "P_1").valid      # Euler without holes fails
    u = fliplab.lot(p, "P_1", keep_hull=True, segments=seg[:12])   # the star only
    c = fliplab.check(p, u.triangles, "P_1", seg)                  # the hole ring is missing
    assert not c and c.segments_missing >= 1 and c.missing_segment >= 12
    assert "not chains of triangle edges" in c.failure()


def collinear_unions(q, seg):
    """(a, c) for each two segments (a, b), (b, c) on one line with b
    between: a segment through the point b, overlapping both (exact on the
    integer grid q)."""
    out = []
    for (a, b) in seg:
        for (c, d) in seg:
            shared = {a, b} & {c, d}
            if len(shared) != 1:
                continue
            y = shared.pop()
            x, z = (a if b == y else b), (c if d == y else d)
            u, v = q[x] - q[y], q[z] - q[y]
            if u[0] * v[1] == u[1] * v[0] and u @ v < 0 and x < z:
                out.append((x, z))
    return out


@st.composite
def constrained_inputs(draw):
    """Grid points (collinear and cocircular subsets, duplicates), segments
    drawn from the edges of another rule's triangulation (never crossing),
    sometimes the union of two collinear ones (through a point), sometimes
    the hull as a ring, hole points anywhere (maybe on a segment, outside
    every region)."""
    n = draw(st.integers(4, 40))
    q = np.array(draw(st.lists(st.tuples(st.integers(-5, 5), st.integers(-5, 5)), min_size=n,
                               max_size=n)), dtype=np.int64)
    if draw(st.booleans()):
        q = np.vstack([q, q[:draw(st.integers(1, n))]])
    scale = draw(st.sampled_from([1.0, 1e-29, 3.7e12]))
    p = q.astype(float) * scale
    try:
        t = fliplab.lot(p, draw(st.sampled_from(["DT", "R_1", "-alpha_inf"])))
    except ValueError:
        return p, None, None
    e = sorted(edge_set(t.triangles))
    idx = draw(st.lists(st.integers(0, len(e) - 1), max_size=len(e), unique=True))
    seg = [e[i] for i in idx]
    seg += collinear_unions(q, seg)[:draw(st.integers(0, 3))]
    if draw(st.booleans()):
        seg += [(a, b) for a, b in zip(t.hull, np.roll(t.hull, -1))]
    if seg and draw(st.booleans()):          # an edge given again, reversed
        seg.append(seg[0][::-1])
    holes = None
    if draw(st.integers(0, 3)) == 0:
        holes = np.array(draw(st.lists(st.tuples(st.integers(-10, 10), st.integers(-10, 10)),
                                       min_size=1, max_size=3)), dtype=float) / 2 * scale
    return p, np.array(seg, dtype=np.int64).reshape(-1, 2), holes


HOLE_ERRORS = ("outside the convex hull", "a hole point must lie inside", "lies on segment",
               "lies outside every region", "no triangle is left")


@given(constrained_inputs(), st.sampled_from(["DT", "P_1", "-alpha_inf", "R_2"]),
       st.booleans())
def test_random_constraints_pass_check(inp, rule, keep):
    p, seg, holes = inp
    if seg is None:
        return
    try:
        t = fliplab.lot(p, rule, segments=seg, holes=holes, keep_hull=keep)
    except ValueError as e:
        assert any(m in str(e) for m in HOLE_ERRORS), str(e)
        assert holes is not None or "no triangle is left" in str(e)
        return
    c = t.check()
    assert c.valid and c.locally_optimal, c
    kept = edge_set(t.triangles)
    assert set(map(tuple, t.constrained)) <= kept
    assert c.segments_missing == t.stats["segments_removed"]     # the others are chains
    if holes is None and keep and t.stats["segments_split"] == 0:
        assert set(map(tuple, np.sort(seg, axis=1))) <= kept    # each segment an edge


def test_bad_inputs_raise_c_message(cli):
    p = np.array([[0, 0], [4, 0], [4, 4], [0, 4], [1, 1]], dtype=float)
    cases = [({"segments": [[0, 2], [1, 3]]}, "segments 1 (1-3) and 0 (0-2) cross"),
             ({"segments": [[0, 1], [1, 2], [2, 3], [3, 0], [0, 2]], "holes": [[2, 2]]},
              "lies on segment 4"),
             ({"segments": [[0, 2]], "holes": [[9, 9]]}, "outside the convex hull"),
             ({"segments": [[0, 2]]}, "no triangle is left"),
             ({"segments": [[1, 5]], "keep_hull": True}, "both ends are point 1")]
    p = np.vstack([p, p[1]])                          # point 5 is point 1 again
    for kw, msg in cases:
        with pytest.raises(ValueError) as e:
            fliplab.lot(p, "DT", **kw)
        assert msg in str(e.value)
        run = cli_lot_fails(cli, p, kw)
        assert str(e.value) in run.stderr, (run.stderr, str(e.value))


def cli_lot_fails(cli, p, kw):
    seg = np.array(kw["segments"])
    write_points(cli.file("p.csv"), p)
    write_rows(cli.file("s.csv"), "i,j", seg, "%d")
    args = ["--points", cli.file("p.csv"), "--segments", cli.file("s.csv")]
    if "holes" in kw:
        write_points(cli.file("h.csv"), kw["holes"])
        args += ["--holes", cli.file("h.csv")]
    if kw.get("keep_hull"):
        args.append("--keep-hull")
    run = cli.run("lot", "--rule", "DT", *args, ok=False)
    assert run.returncode != 0
    return run


@pytest.mark.parametrize("kw,msg", [
    ({"segments": [[0, 5]]}, r"segments 0 \[0, 5\]: an index outside \[0, 5\)"),
    ({"segments": [[0, -1]]}, "an index outside"),
    ({"segments": [[0, np.nan]]}, "NaN"),
    ({"segments": [[0, 1.5]]}, "not a whole number"),
    ({"segments": [0, 1]}, "shape"),
    ({"segments": [["a", "b"]]}, "integer array"),
    ({"segments": [[0, 1, 2]]}, "shape"),
    ({"segments": [[1, 1]], "keep_hull": True}, "segment 0: both ends are point 1"),
    ({"holes": [[np.nan, 1]]}, "hole 0"),
    ({"holes": [[1, 1, 1]]}, "shape"),
    ({"keep_hull": True}, "keep_hull applies to constrained runs")])
def test_bad_arrays(kw, msg):
    p = np.array([[0, 0], [4, 0], [4, 4], [0, 4], [1, 1]], dtype=float)
    with pytest.raises(ValueError, match=msg):
        fliplab.lot(p, "DT", **kw)


def test_float_indices_accepted():
    p = fliplab.samplers.points(100, "uniform", 1)
    seg = some_edges(p, "P_1", 10, 3)
    a = fliplab.lot(p, "DT", segments=seg, keep_hull=True)
    b = fliplab.lot(p, "DT", segments=seg.astype(float), keep_hull=True)
    assert np.array_equal(a.triangles, b.triangles)
