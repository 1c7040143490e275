"""test_cpdt.py: convex_dt(polygon, algorithm) and convex_dt_experiment():
every algorithm's triangles are lot()'s Delaunay triangles of the same
points (random, regular and integer cocircular polygons); the incremental
algorithm's flips are the sum of each vertex's interior degree in the
triangulation of its prefix, computed here from convex_dt's own results;
the circumcircle algorithm scans sum(k - i - 1); the experiment's slopes
are numpy's least-squares fits of its means; refusals name the keyword or
the vertex."""
import numpy as np
import pytest

import fliplab


def _vector(seed, n):
    """A random convex polygon from sorted edge vectors (the vector method)."""
    g = np.random.default_rng(seed)
    v = g.normal(size=(n, 2))
    v -= v.mean(axis=0)
    v = v[np.argsort(np.arctan2(v[:, 1], v[:, 0]))]
    return np.cumsum(v, axis=0)


def _lot_rows(p):
    t = np.sort(fliplab.lot(p, "DT").triangles, axis=1)
    return t[np.argsort(t[:, 1])]


def _pythagorean():
    r = 1105
    pts = [(x, y) for x in range(-r, r + 1) for y in {int(round((r * r - x * x) ** 0.5))}
           if x * x + y * y == r * r]
    pts += [(x, -y) for x, y in pts if y]
    pts.sort(key=lambda q: np.arctan2(q[1], q[0]))
    return np.array(pts, dtype=float)


@pytest.mark.parametrize("algorithm", fliplab.CPDT_ALGORITHMS)
def test_same_as_lot(algorithm):
    polys = [_vector(s, n) for s, n in ((1, 3), (2, 7), (3, 40), (4, 300))]
    t = np.linspace(0, 2 * np.pi, 25)[:-1]
    polys.append(np.c_[np.cos(t), np.sin(t)])
    polys.append(_pythagorean())
    for p in polys:
        tri, counts = fliplab.convex_dt(p, algorithm, seed=3)
        assert tri.shape == (len(p) - 2, 3)
        np.testing.assert_array_equal(tri, _lot_rows(p))
        if algorithm == "circum":
            assert counts["scanned"] == int((tri[:, 2] - tri[:, 0] - 1).sum())


def test_incremental_flips_are_degrees():
    p = _vector(9, 60)
    want = 0
    for i in range(3, len(p)):
        tri, _ = fliplab.convex_dt(p[:i + 1], "divide")
        want += int((tri == i).any(axis=1).sum()) - 1
    assert fliplab.convex_dt(p, "incremental")[1]["flips"] == want


def test_counts_repeat_with_seed():
    p = _vector(5, 500)
    assert fliplab.convex_dt(p, "random", seed=4)[1] == fliplab.convex_dt(p, "random", seed=4)[1]


def test_experiment():
    r = fliplab.convex_dt_experiment(sizes=(10, 30, 90), trials=3, sampler="circle",
                                     algorithms=("divide", "random"), seed=2)
    assert [(row["n"], row["algorithm"]) for row in r["rows"]] == \
        [(n, a) for n in (10, 30, 90) for a in ("divide", "random")]
    for a in ("divide", "random"):
        x = np.log([row["n"] for row in r["rows"] if row["algorithm"] == a])
        y = np.log([row["incircle"] for row in r["rows"] if row["algorithm"] == a])
        assert r["slopes"][a]["incircle"] == pytest.approx(np.polyfit(x, y, 1)[0], rel=1e-9)
    assert set(fliplab.CPDT_COUNTS) <= set(r["rows"][0])


@pytest.mark.parametrize("poly,says", [
    ([[0, 0], [0, 1], [1, 1], [1, 0]], "clockwise"),
    ([[0, 0], [2, 0], [2, 2], [1, 0.5], [0, 2]], "vertex"),
    ([[0, 0], [1, 0], [1, 0], [0, 1]], "vertex 2"),
    ([[0, 0], [1, 0]], "vertex"),
])
def test_refusals(poly, says):
    with pytest.raises(ValueError, match=says):
        fliplab.convex_dt(np.array(poly, dtype=float))


def test_experiment_draws_the_registry_polygons():
    """Polygon t of size n in the experiment is convex_polygons' polygon t:
    the circumcircle count of each recomputed by convex_dt, averaged."""
    for name, region in (("valtr", None), ("iteration", "disc"), ("circle", None)):
        r = fliplab.convex_dt_experiment(sizes=(12,), trials=5, sampler=name, region=region,
                                         algorithms=("circum",), seed=9)
        polys = fliplab.convex_polygons(12, 5, sampler=name, region=region, seed=9)
        mean = np.mean([fliplab.convex_dt(p, "circum")[1]["scanned"] for p in polys.points])
        assert r["rows"][0]["scanned"] == mean


def test_keyword_refusals():
    sq = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], dtype=float)
    with pytest.raises(ValueError, match="algorithm"):
        fliplab.convex_dt(sq, "walk")
    with pytest.raises(ValueError, match="sizes: 20"):
        fliplab.convex_dt_experiment(sizes=(10, 20), sampler="naive", trials=1)
    with pytest.raises(ValueError, match="weights"):
        fliplab.convex_dt_experiment(sizes=(10,), sampler="rejection", trials=1)
    with pytest.raises(ValueError, match="region"):
        fliplab.convex_dt_experiment(sizes=(10,), sampler="vector", region="disc", trials=1)
    with pytest.raises(ValueError, match="region"):
        fliplab.convex_dt_experiment(sizes=(10,), sampler="valtr", region="moon", trials=1)
    with pytest.raises(ValueError, match="sampler"):
        fliplab.convex_dt_experiment(sampler="disc", trials=1)
    with pytest.raises(ValueError, match="algorithms"):
        fliplab.convex_dt_experiment(sizes=(10,), algorithms=("divide", "divide"), trials=1)
