"""test_convex.py: fliplab.convex_polygons, the random convex n-gons of
chapter 6 from Python:
- the polygons, log weights and h are the program's (`fliplab convex`), bit
  for bit, and do not depend on the thread count; summary() prints the
  program's --stats numbers;
- every polygon is strictly convex and anticlockwise (shapely's area and
  a cross-product check), weights sum to 1, unweighted samplers weigh 0;
- the iteration method below 17 vertices on the disc is
  samplers.convex_polygons (sampler_convex);
- weighted rejection and Valtr's sampler agree on the mean area at n = 6
  (a two-sided z-test at level 1e-4);
- bad arguments are ValueErrors naming the problem."""
import csv
import io
import math

import numpy as np
import pytest

import fliplab


def test_same_as_program(cli):
    c = fliplab.convex_polygons(7, 20, sampler="rejection", region="disc", seed=5, first=3)
    out = cli.run("convex", "--sampler", "rejection", "--region", "disc", "--n", 7, "--count", 20,
                  "--seed", 5, "--first", 3).stdout
    rows = list(csv.reader(io.StringIO(out)))[1:]
    assert len(rows) == 20 * 7
    for r in rows:
        i, j = int(r[0]) - 3, int(r[1])
        assert c.points[i, j, 0] == float(r[2]) and c.points[i, j, 1] == float(r[3])
        assert c.log_weight[i] == float(r[4]) and c.h[i] == int(r[5])


def test_threads_and_summary(cli):
    a = fliplab.convex_polygons(12, 200, sampler="iteration", region="triangle", threads=1,
                                stats=True)
    b = fliplab.convex_polygons(12, 200, sampler="iteration", region="triangle", threads=2,
                                stats=True)
    assert np.array_equal(a.points, b.points) and np.array_equal(a.h, b.h)
    s = a.summary()
    out = cli.run("convex", "--sampler", "iteration", "--region", "triangle", "--n", 12,
                  "--count", 200, "--stats").stdout
    for line in out.splitlines():
        f = line.split()
        if f and f[0] in fliplab._convex.STATS and f[1] != "-":
            assert float(f[1]) == pytest.approx(s[f[0]][0], rel=1e-7)


def test_convex_and_weights():
    """Every sampler of the registry, each law, the dual of every inner method."""
    regions = {"rejection": "square", "valtr": "square", "naive": "disc", "iteration": "disc"}
    cases = [(s, regions.get(s), 0, None) for s in fliplab.CONVEX_SAMPLERS]
    cases += [("bounce", None, 1, None), ("dual", None, 1, "bounce")]
    cases += [("dual", None, 0, m) for m in fliplab.CONVEX_INNER]
    assert set(fliplab.CONVEX_SAMPLERS) >= {"triangulation", "bounce", "dual", "dual-rejection",
                                            "geobench", "angles"}
    assert "dual" not in fliplab.CONVEX_INNER and "rejection" not in fliplab.CONVEX_INNER
    for sampler, region, law, inner in cases:
        n = 7 if "dual-rejection" in (sampler, inner) else 9
        c = fliplab.convex_polygons(n, 30, sampler=sampler, region=region, law=law, inner=inner)
        d = fliplab.convex_polygons(n, 30, sampler=sampler, region=region, law=law, inner=inner,
                                    threads=1)
        assert np.array_equal(c.points, d.points)
        e1 = np.roll(c.points, -1, axis=1) - c.points
        e2 = np.roll(e1, -1, axis=1)
        assert (e1[..., 0] * e2[..., 1] - e1[..., 1] * e2[..., 0] > 0).all()
        assert c.weight.sum() == pytest.approx(1.0)
        if sampler != "rejection":
            assert (c.log_weight == 0).all()


def test_iteration_is_sampler_convex():
    a = fliplab.convex_polygons(8, 50, sampler="iteration", region="disc", seed=3)
    b = fliplab.samplers.convex_polygons(8, 50, seed=3)
    assert np.array_equal(a.points, b)


def test_rejection_valtr_law():
    r = fliplab.convex_polygons(6, 20000, sampler="rejection", seed=1, stats=True).summary()
    v = fliplab.convex_polygons(6, 20000, sampler="valtr", seed=2, stats=True).summary()
    (ma, ha), (mb, hb) = r["area"], v["area"]
    assert abs(ma - mb) <= 3.89 * math.hypot(ha, hb) / 1.96


def test_errors():
    with pytest.raises(ValueError, match="unknown sampler"):
        fliplab.convex_polygons(5, 1, sampler="bogus")
    with pytest.raises(ValueError, match="unknown region"):
        fliplab.convex_polygons(5, 1, region="moon")
    with pytest.raises(ValueError, match="does not draw in the disc"):
        fliplab.convex_polygons(5, 1, sampler="valtr", region="disc")
    with pytest.raises(ValueError, match="n up to 10"):
        fliplab.convex_polygons(11, 1, sampler="naive")
    with pytest.raises(ValueError, match="n up to 10"):
        fliplab.convex_polygons(11, 1, sampler="dual-rejection")
    with pytest.raises(ValueError, match="^law: law 1: sampler valtr takes laws 0 .. 0"):
        fliplab.convex_polygons(5, 1, sampler="valtr", law=1)
    with pytest.raises(ValueError, match="^law: law 2: sampler bounce"):
        fliplab.convex_polygons(5, 1, sampler="bounce", law=2)
    with pytest.raises(ValueError, match="^inner: unknown inner method 'moon'"):
        fliplab.convex_polygons(5, 1, sampler="dual", inner="moon")
    with pytest.raises(ValueError, match="^inner: sampler bounce takes no inner method"):
        fliplab.convex_polygons(5, 1, sampler="bounce", inner="vector")
    with pytest.raises(ValueError, match="n"):
        fliplab.convex_polygons(2, 1)
    with pytest.raises(ValueError, match="smaller n"):
        fliplab.convex_polygons(3000, 1, sampler="iteration", region="square")
    with pytest.raises(ValueError, match="summary"):
        fliplab.convex_polygons(5, 1).summary()
