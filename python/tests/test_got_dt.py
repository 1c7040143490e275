"""test_got_dt.py: fliplab.got_points for the rules whose GOT is a Delaunay
triangulation (R_1, -r_1, abc_1, ...): the skeleton "delaunay" (lot's exact
Delaunay triangulation, certified by got), against the LMT path on small sets, on
10^5 uniform points, on a grid (every square a tie), and its refusals."""
import numpy as np
import pytest

import fliplab


def _points(n, seed):
    return np.random.default_rng(seed).random((n, 2))


@pytest.mark.parametrize("rule", ["R_1", "-r_1", "R_-1"])
def test_same_as_lmt(rule):
    for seed in range(3):
        p = _points(60, seed)
        d = fliplab.got_points(p, rule)
        m = fliplab.got_points(p, rule, skeleton="lmt")
        assert d.skeleton == "delaunay" and m.skeleton == "lmt"
        assert abs(d.key - m.key) <= d.cert_err + m.cert_err
        if m.certified_unique:
            assert d.certified_unique
            assert np.array_equal(d.triangles, m.triangles)


def test_large_uniform():
    n = 100000
    g = fliplab.got_points(_points(n, 5), "R_1")
    assert g.skeleton == "delaunay" and g.certified_unique
    assert g.certain == g.edges == g.candidates and g.faces_left == 0
    assert 0 < 2 * n - 2 - len(g.triangles) < 200   # 2n - h - 2: h hull points
    assert g.seconds_delaunay > 0


def test_grid_ties():
    s = 7
    p = np.array([(i % s, i // s) for i in range(s * s)], dtype=float)
    g = fliplab.got_points(p, "R_1")
    assert g.skeleton == "delaunay" and not g.certified_unique and not g.unique
    assert g.faces_left == (s - 1) ** 2 and g.largest_face == 4
    assert len(g.triangles) == 2 * (s - 1) ** 2


def test_refusals():
    p = _points(20, 1)
    with pytest.raises(ValueError, match="need not be a Delaunay triangulation"):
        fliplab.got_points(p, "P_1", skeleton="delaunay")
    with pytest.raises(ValueError, match="are equal"):
        fliplab.got_points(np.vstack([p, p[:1]]), "R_1")
    with pytest.raises(ValueError, match="collinear"):
        fliplab.got_points([(0, 0), (1, 1), (2, 2)], "R_1")
