"""test_samplers.py: the samplers give the program's coordinates, bit for bit
(the program writes %.17g, which reads back exactly)."""
import numpy as np
import pytest

import fliplab


def test_pentagons_equal_sample(cli):
    run = cli.run("sample", "--count", 30, "--seed", 7, "--first", 5)
    lines = run.stdout.splitlines()
    assert lines[0] == "x1,y1,x2,y2,x3,y3,x4,y4,x5,y5"
    want = np.array([[float(x) for x in l.split(",")] for l in lines[1:]]).reshape(-1, 5, 2)
    assert np.array_equal(fliplab.samplers.pentagons(30, seed=7, first=5), want)


@pytest.mark.parametrize("kind", fliplab.samplers.POINT_SETS)
def test_points_equal_lot_random(cli, kind):
    # lot --random N --sampler KIND writes triangles; the points are checked
    # through them: the same triangles from the same coordinates.
    t = fliplab.lot(fliplab.samplers.points(60, kind, 3), "DT", seed=3)
    cli.run("lot", "--rule", "DT", "--random", 60, "--sampler", kind, "--seed", 3,
            "--out", cli.file("t.csv"))
    tri = np.array([[int(x) for x in r[:3]] for r in cli.rows("t.csv")[1:]])
    assert (tri == t.triangles).all()


def test_points_properties():
    g = fliplab.samplers.points(30, "grid")
    assert np.array_equal(g, np.array([[i % 6, i // 6] for i in range(30)], dtype=float))
    par = fliplab.samplers.points(5, "parabola")
    assert np.array_equal(par, np.array([[i, i * i] for i in range(5, 0, -1)], dtype=float))
    u = fliplab.samplers.points(1000, "uniform", 2)
    assert ((u >= 0) & (u < 1)).all()
    assert np.array_equal(u, fliplab.samplers.points(1000, "uniform", 2))
    assert not np.array_equal(u, fliplab.samplers.points(1000, "uniform", 3))


@pytest.mark.parametrize("sampler", fliplab.samplers.POLYGONS)
def test_polygon_equals_got_random(cli, sampler):
    # got --random N --svg draws the polygon; its --csv rows name vertices,
    # so compare GOT totals of the same polygon (totals: test_got.py) and
    # the polygon's own properties here.
    p = fliplab.samplers.polygon(12, sampler, seed=5)
    assert p.shape == (12, 2)
    area = 0.5 * np.sum(p[:, 0] * np.roll(p[:, 1], -1) - np.roll(p[:, 0], -1) * p[:, 1])
    assert area > 0                                       # anticlockwise
    assert np.array_equal(p, fliplab.samplers.polygon(12, sampler, seed=5))


@pytest.mark.parametrize("kind", fliplab.samplers.SITE_SETS)
def test_site_sets(kind):
    s = fliplab.samplers.site_sets(6, 20, kind, seed=2)
    assert s.shape == (20, 6, 2)
    assert np.array_equal(s[5:], fliplab.samplers.site_sets(6, 15, kind, seed=2, first=5))
    if kind == "convex":
        assert np.array_equal(fliplab.samplers.site_sets(5, 10, "convex", seed=2),
                              fliplab.samplers.pentagons(10, seed=2))


def test_bad_sampler_args():
    with pytest.raises(ValueError, match="unknown point sampler"):
        fliplab.samplers.points(10, "nope")
    with pytest.raises(ValueError, match="sites"):
        fliplab.samplers.site_sets(2, 10)
    with pytest.raises(ValueError, match="seed"):
        fliplab.samplers.pentagons(3, seed=-2)


@pytest.mark.parametrize("kind", ["clustered", "jittered", "lines", "dups"])
def test_input_families(kind):
    # The benchmark families through the package: their stated laws, and a
    # triangulation of each that lot's own check accepts.
    n = 4000
    p = fliplab.samplers.points(n, kind, seed=2)
    assert np.array_equal(p, fliplab.samplers.points(n, kind, seed=2))
    if kind == "jittered":
        g = fliplab.samplers.points(n, "grid")
        assert np.abs(p - g).max() <= 2.0 ** -10
    elif kind == "lines":                # integers; line k holds points k, k + 8, ...
        assert (p == np.floor(p)).all()
        for k in range(8):
            d = p[k::8] - p[k]
            assert (d[:, 0] * d[1, 1] - d[:, 1] * d[1, 0] == 0).all()    # exact: small ints
    elif kind == "dups":
        assert len(np.unique(p, axis=0)) == n // 4
        assert np.array_equal(p[:n // 4], fliplab.samplers.points(n // 4, "uniform", seed=2))
    t = fliplab.lot(p, "DT")
    assert t.check()
    assert len(t.triangles) > 0
