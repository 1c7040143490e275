"""test_weighted.py: lot(points, "WDT", weights=w), the regular
triangulation, against an oracle written here in exact rational arithmetic
(fractions): the lower convex hull of the sites lifted to
(x, y, x^2 + y^2 - w), found by brute force over all triples, and the
redundant sites, those whose lifted point lies above it."""
from fractions import Fraction
from itertools import permutations

import numpy as np
import pytest

import fliplab
from conftest import write_points


def _lift(p, w):
    return [(Fraction(x), Fraction(y), Fraction(x) ** 2 + Fraction(y) ** 2 - Fraction(c))
            for (x, y), c in zip(p.tolist(), w.tolist())]


def _orient(a, b, c):
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])


def _above(a, b, c, d):
    """Signed height of d's lifted point over the plane of a, b, c (abc
    anticlockwise): > 0 above."""
    m = [[a[k] - d[k] for k in range(3)], [b[k] - d[k] for k in range(3)],
         [c[k] - d[k] for k in range(3)]]
    det = (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
           - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
           + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]))
    return -det      # the lifted determinant is positive when d is below


def _inside(a, b, c, d):
    return _orient(a, b, d) >= 0 and _orient(b, c, d) >= 0 and _orient(c, a, d) >= 0


def _oracle(p, w):
    """(faces as sorted rows from the smallest index, redundant sites)."""
    q = _lift(p, w)
    n = len(q)
    red = [l for l in range(n)
           if any(_orient(q[i], q[j], q[k]) > 0 and _inside(q[i], q[j], q[k], q[l])
                  and _above(q[i], q[j], q[k], q[l]) > 0
                  for i, j, k in permutations([x for x in range(n) if x != l], 3))]
    keep = [i for i in range(n) if i not in red]
    faces = []
    for i, j, k in permutations(keep, 3):
        if i < j and i < k and _orient(q[i], q[j], q[k]) > 0 and \
                all(_above(q[i], q[j], q[k], q[l]) > 0 for l in keep if l not in (i, j, k)):
            faces.append((i, j, k))
    return sorted(faces), red


@pytest.mark.parametrize("seed", range(12))
def test_small_sets_against_exact_lifting(seed):
    rng = np.random.default_rng(seed)
    n = int(rng.integers(4, 9))
    p = rng.random((n, 2))
    w = rng.random(n) * 0.15 * (seed % 3)
    faces, red = _oracle(p, w)
    for algorithm in ("incremental", "flip"):
        t = fliplab.lot(p, "WDT", algorithm=algorithm, weights=w, check=True)
        assert sorted(map(tuple, t.triangles.tolist())) == faces
        assert t.redundant.tolist() == red
        assert t.stats["redundant"] == len(red)


def test_some_sets_have_redundant_sites():
    rng = np.random.default_rng(5)
    found = sum(len(fliplab.lot(rng.random((30, 2)), "WDT",
                                weights=rng.random(30) * 0.05).redundant) > 0
                for _ in range(10))
    assert found >= 5


def test_equal_weights_give_dt():
    p = fliplab.samplers.points(500, "grid", seed=1)
    dt = fliplab.lot(p, "DT")
    for w in (np.zeros(500), np.full(500, 7.5)):
        t = fliplab.lot(p, "WDT", weights=w)
        assert np.array_equal(t.triangles, dt.triangles)
        assert len(t.redundant) == 0
    assert np.array_equal(fliplab.lot(p, "WDT").triangles, dt.triangles)


def test_same_as_the_program(cli):
    rng = np.random.default_rng(2)
    p, w = rng.random((200, 2)), rng.random(200) * 3e-3
    write_points(cli.file("p.csv"), p)
    with open(cli.file("w.csv"), "w") as f:
        f.write("w\n" + "".join("%r\n" % float(x) for x in w))
    r = cli.run("lot", "--rule", "WDT", "--points", cli.file("p.csv"), "--weights",
                cli.file("w.csv"), "--out", cli.file("t.csv"))
    t = fliplab.lot(p, "WDT", weights=w)
    rows = [tuple(map(int, row[:3])) for row in cli.rows("t.csv")[1:]]
    assert rows == list(map(tuple, t.triangles.tolist()))
    assert "redundant: %d sites" % len(t.redundant) in r.stdout


def test_weights_kept_and_checked():
    p = np.array([[0, 0], [4, 0], [2, 3], [2, 1]], dtype=float)
    w = np.array([0, 0, 0, 5.0])       # (2, 1) lifted to 0, below the hull's plane
    t = fliplab.lot(p, "WDT", weights=w)
    w[3] = -100.0                      # the caller's array changes afterwards
    assert t.weights[3] == 5.0 and not t.weights.flags.writeable
    assert len(t.triangles) == 3 and t.check()
    assert not fliplab.check(p, t.triangles, "WDT", weights=[0, 0, 0, -100.0])
    hidden = fliplab.lot(p, "WDT", weights=[0, 0, 0, -100.0])
    assert hidden.triangles.tolist() == [[0, 1, 2]] and hidden.redundant.tolist() == [3]


@pytest.mark.parametrize("weights, rule, match", [
    ([0, 0, 0], "WDT", r"weights: expected an array of shape \(4,\)"),
    ([0, 0, np.nan, 0], "WDT", "point 2: weight nan is not finite"),
    ([0, 0, 1e70, 0], "WDT", "out of range"),
    ([0, 0, 0, 0], "P_1", "weights apply to the weighted Delaunay rule WDT, not P_1"),
    (np.ma.masked_array([0, 0, 0, 0.0], mask=[0, 1, 0, 0]), "WDT", "masked"),
    (["a", "b", "c", "d"], "WDT", "real numbers"),
])
def test_refused(weights, rule, match):
    p = np.array([[0, 0], [1, 0], [0, 1], [1, 1]], dtype=float)
    with pytest.raises(ValueError, match=match):
        fliplab.lot(p, rule, weights=weights)


def test_sweep_refused():
    p = np.array([[0, 0], [1, 0], [0, 1], [1, 1]], dtype=float)
    with pytest.raises(ValueError, match="sweep"):
        fliplab.lot(p, "WDT", algorithm="sweep", weights=np.zeros(4))


def test_flipgraph_weights(cli):
    """flipgraph(..., weights=): without a redundant site the one sink is
    lot's regular triangulation, as the program's flipgraph --weights says."""
    rng = np.random.default_rng(8)
    for _ in range(6):
        p, w = rng.random((7, 2)), rng.random(7) * 0.05
        t = fliplab.lot(p, "WDT", weights=w)
        g = fliplab.flipgraph(p, "WDT", weights=w)
        if len(t.redundant) == 0:
            assert len(g.sinks) == 1
            sink = sorted(tuple(sorted(x)) for x in g.nodes[g.sinks[0]].tolist())
            assert sink == sorted(tuple(sorted(x)) for x in t.triangles.tolist())
    write_points(cli.file("p.csv"), p)
    with open(cli.file("w.csv"), "w") as f:
        f.write("".join("%r\n" % float(x) for x in w))
    r = cli.run("flipgraph", "--rule", "WDT", "--points", cli.file("p.csv"), "--weights",
                cli.file("w.csv"))
    assert "sinks: %d" % len(g.sinks) in r.stdout
    with pytest.raises(ValueError, match="WDT, not DT"):
        fliplab.flipgraph(p, "DT", weights=w)
    with pytest.raises(ValueError, match="site 2: weight inf is not finite"):
        fliplab.flipgraph(p, "WDT", weights=[0, 0, np.inf, 0, 0, 0, 0])
