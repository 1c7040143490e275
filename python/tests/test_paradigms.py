"""test_paradigms.py: paradigms() and triangulate_by(): the rows are the
program's (`fliplab paradigms --list`); every row serving a problem gives
the same triangles as lot() of the same input (Delaunay and ES:square point
sets, constrained point sets, simple and convex polygons), and for DT every
triangle's circumcircle is empty (brute force over the points); counts are
the program's for the same points (its CSV) and obey Euler's relation for
divide and conquer; one thread and two give the same triangles; refusals
are the library's or name the keyword."""
import numpy as np
import pytest

import fliplab


def _canon(t):
    """lot's triangles in the runner's canonical order."""
    t = np.asarray(t)
    k = np.argmin(t, axis=1)
    r = np.array([np.roll(row, -i) for row, i in zip(t, k)])
    return r[np.lexsort((r[:, 2], r[:, 1], r[:, 0]))]


def _serving(problem, rule="DT"):
    want = "ES:SHAPE" if rule != "DT" else "DT"
    return [r["name"] for r in fliplab.paradigms()
            if problem in r["problems"] and want in r["rules"]]


def test_rows_are_the_programs(cli):
    out = cli.run("paradigms", "--list").stdout
    rows = fliplab.paradigms()
    assert tuple(r["name"] for r in rows) == fliplab.PARADIGM_ALGORITHMS
    for r in rows:
        assert "| %s | %s | %s |" % (r["name"], r["paradigm"], r["section"]) in out
        assert set(r["problems"]) <= set(fliplab.PARADIGM_PROBLEMS) and r["problems"]


def _empty_circles(p, t):
    """Brute force: no point strictly inside any triangle's circumcircle
    (a relative margin for rounding; the points are random)."""
    for a, b, c in t:
        m = np.array([[p[i][0] - p[a][0], p[i][1] - p[a][1]] for i in (b, c)])
        rhs = 0.5 * (m ** 2).sum(axis=1)
        o = np.linalg.solve(m, rhs)
        r2 = (o ** 2).sum()
        d2 = ((p - p[a] - o) ** 2).sum(axis=1)
        assert (d2 >= r2 * (1 - 1e-9)).all()


@pytest.mark.parametrize("rule", ["DT", "ES:square"])
def test_point_sets_agree_with_lot(rule):
    for kind, n in (("uniform", 200), ("grid", 49), ("dups", 120), ("circle", 40)):
        p = fliplab.samplers.points(n, kind, seed=3)
        want = _canon(fliplab.lot(p, rule).triangles)
        for a in _serving("delaunay", rule):
            if a.startswith("select-") and a != "select-buckets" and n > 150:
                continue                     # the O(n^2) scans: smaller sets below
            t, c = fliplab.triangulate_by(p, a, rule=rule)
            assert np.array_equal(t, want), (a, kind)
            assert c["distinct"] == len(np.unique(p, axis=0))
        if rule == "DT" and kind == "uniform":
            _empty_circles(p, want)


def test_counts_are_the_programs(cli):
    p = fliplab.samplers.points(300, "uniform", seed=4)
    cli.run("paradigms", "--algorithms", "dc-alternating,watson", "--sizes", "300", "--runs", 1,
            "--seed", 4, "--csv", cli.file("m.csv"))
    rows = cli.rows("m.csv")
    head = rows[0]
    for row in rows[1:]:
        _, c = fliplab.triangulate_by(p, row[0], seed=4)
        for k in fliplab.OPS_NAMES:
            assert round(float(row[head.index(k + "_per_site")]) * 300) == c[k], (row[0], k)
    t, c = fliplab.triangulate_by(p, "dc-alternating")
    hull = 2 * 300 - 2 - len(t)
    assert c["edges_made"] - c["edges_deleted"] == 3 * 300 - 3 - hull      # Euler


def test_threads_same_triangles():
    p = fliplab.samplers.points(20000, "uniform", seed=5)
    t1, c1 = fliplab.triangulate_by(p, "dc-alternating", threads=1)
    t2, c2 = fliplab.triangulate_by(p, "dc-alternating", threads=2)
    assert np.array_equal(t1, t2)
    assert all(c1[k] == c2[k] for k in fliplab.OPS_NAMES)


def test_constrained_and_polygons():
    p = fliplab.samplers.points(150, "uniform", seed=6)
    seg = np.array([[0, 1], [2, 3], [4, 5]])
    want = _canon(fliplab.lot(p, "DT", segments=seg, keep_hull=True).triangles)
    for a in _serving("constrained"):
        t, _ = fliplab.triangulate_by(p, a, problem="constrained", segments=seg)
        assert np.array_equal(t, want), a
    square = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [0.5, 0.2]])
    with pytest.raises(ValueError, match="segments 0 and 1 cross"):
        fliplab.triangulate_by(square, "dc-constrained", problem="constrained",
                               segments=np.array([[0, 2], [1, 3]]))
    for kind in ("star", "monotone"):
        poly = fliplab.samplers.polygon(60, kind, seed=2)
        for a in _serving("polygon"):
            if a == "sweep-monotone" and kind == "star":   # x-monotone polygons only
                with pytest.raises(ValueError, match="not x-monotone"):
                    fliplab.triangulate_by(poly, a, problem="polygon")
                continue
            t, _ = fliplab.triangulate_by(poly, a, problem="polygon")
            assert len(t) == 58, a
            assert np.array_equal(t, _canon(fliplab.lot(poly, "DT", segments=np.c_[
                np.arange(60), (np.arange(60) + 1) % 60]).triangles)), a
    conv = fliplab.convex_polygons(80, 1, sampler="valtr", seed=1).points[0]
    want = _canon(fliplab.convex_dt(conv)[0])
    for a in _serving("convex"):
        t, _ = fliplab.triangulate_by(conv, a, problem="convex")
        assert np.array_equal(t, want), a


def test_refusals():
    p = fliplab.samplers.points(20, "uniform", seed=1)
    cases = [(dict(algorithm="nope"), "algorithm: unknown algorithm 'nope'"),
             (dict(algorithm="sweep-constrained", rule="ES:square"), "needs the rule DT"),
             (dict(algorithm="sweep", problem="polygon"), "does not solve the polygon problem"),
             (dict(algorithm="flip", problem="bogus"), "problem: unknown problem"),
             (dict(algorithm="flip", segments=[[0, 1]]), "segments: only for problem"),
             (dict(algorithm="flip", problem="constrained", segments=[[0, 99]]),
              "segments 0 [0, 99]: an index outside"),
             (dict(algorithm="flip", threads=-1), "threads: expected"),
             (dict(algorithm="select-buckets", param=float("nan")), "param: expected")]
    for kw, msg in cases:
        a = kw.pop("algorithm")
        with pytest.raises(ValueError) as e:
            fliplab.triangulate_by(p, a, **kw)
        assert msg in str(e.value), (kw, str(e.value))
    with pytest.raises(ValueError, match="collinear"):
        fliplab.triangulate_by([[0, 0], [1, 1], [2, 2]], "incremental")
    with pytest.raises(ValueError, match="point 2: "):
        fliplab.triangulate_by([[0, 0], [1e300, 1], [2, 0]], "incremental")
