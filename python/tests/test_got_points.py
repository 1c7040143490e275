"""test_got_points.py: fliplab.got_points (got/got_points.c) against the program run
on the same points, against fliplab.got on points in convex position (the same bits),
against every triangulation of small sets (fliplab.flipgraph's GOT), and its one-line
refusals."""
import numpy as np
import pytest

import fliplab
from conftest import stdout_field, write_points


def _points(n, seed):
    return np.random.default_rng(seed).random((n, 2))


def test_got_points_equals_cli(cli):
    p = _points(30, 1)
    path = cli.file("p.csv")
    write_points(path, p)
    for rule in ("P_1", "a_2"):
        g = fliplab.got_points(p, rule)
        out = cli.run("got", "--rule", rule, "--points", path,
                      "--print-triangles", "--no-lot").stdout
        assert stdout_field(out, "total badness") == g.total_text
        rows = [tuple(map(int, line.split()[:3])) for line in out.splitlines()
                if line[:1].isdigit()]
        assert rows == [tuple(t) for t in g.triangles]
        assert ("certified: unique" in out) == g.certified_unique
        assert g.points and g.skeleton == "lmt" and g.n == 30
        assert len(g.triangles) == 2 * 30 - len(_hull(p)) - 2
        assert g.certain >= len(_hull(p)) and g.faces >= 1
        joined = g.badness.sum() if rule == "P_1" else np.sqrt((g.badness ** 2).sum())
        assert np.isclose(joined, g.total, rtol=1e-12)


def _hull(p):
    from scipy.spatial import ConvexHull
    return ConvexHull(p).vertices


def test_convex_equals_polygon():
    p = fliplab.samplers.convex_polygons(12, 1, seed=4)[0]
    for rule in ("P_1", "sigma_2", "-A_1"):
        a, b = fliplab.got(p, rule), fliplab.got_points(p, rule)
        assert a.key == b.key and a.certified_unique == b.certified_unique
        assert sorted(map(tuple, np.sort(a.triangles, axis=1))) == \
            sorted(map(tuple, b.triangles))


@pytest.mark.parametrize("rule", ["P_1", "R_1", "a_2", "-alpha_1"])
def test_enumeration(rule):
    for seed in range(3):
        p = _points(7, 10 + seed)
        best = fliplab.flipgraph(p, rule).got_total
        for sk in ("all", "auto"):
            g = fliplab.got_points(p, rule, skeleton=sk)
            assert abs(g.total - best) <= 1e-9 * abs(best)


def test_refusals():
    p = _points(6, 2)
    with pytest.raises(ValueError, match="not a sum rule"):
        fliplab.got_points(p, "P_inf")
    with pytest.raises(ValueError, match="points 1 and 4"):
        q = p.copy()
        q[4] = q[1]
        fliplab.got_points(q, "P_1")
    with pytest.raises(ValueError, match="collinear"):
        fliplab.got_points([[0, 0], [1, 1], [2, 2]], "P_1")
    with pytest.raises(ValueError, match="skeleton"):
        fliplab.got_points(p, "P_1", skeleton="none")
    with pytest.raises(ValueError):
        fliplab.got_points(p, "P_1", threads=-1)
