"""test_lot.py: fliplab.lot against scipy.spatial.Delaunay (triangles and
neighbours on generic random input), matplotlib.tri (accepts every output,
including its trifinder's validity check) and the program (the same
triangles, badness and flips for the same input and seed)."""
import matplotlib
matplotlib.use("Agg")
import matplotlib.tri as mtri
import numpy as np
import pytest
import scipy.spatial

import fliplab
from conftest import stdout_field, write_points


def tri_sets(t):
    return set(map(tuple, np.sort(np.asarray(t), axis=1)))


@pytest.mark.parametrize("n,seed,kind", [(50, 1, "uniform"), (300, 2, "normal"),
                                         (1000, 3, "disc"), (2000, 4, "uniform")])
def test_dt_equals_scipy(n, seed, kind):
    p = fliplab.samplers.points(n, kind, seed)
    t = fliplab.lot(p, "DT", check=True)
    d = scipy.spatial.Delaunay(p)
    assert tri_sets(t.triangles) == tri_sets(d.simplices)
    # neighbours: the same triangle across the same edge, mapped through the vertex sets
    ours = {tuple(sorted(v)): i for i, v in enumerate(t.triangles)}
    nb = t.neighbors
    for s, simplex in enumerate(d.simplices):
        i = ours[tuple(sorted(simplex))]
        for k in range(3):
            vk = simplex[k]
            kk = list(t.triangles[i]).index(vk)
            theirs = d.neighbors[s, k]
            want = -1 if theirs < 0 else ours[tuple(sorted(d.simplices[theirs]))]
            assert nb[i, kk] == want


def test_conventions():
    p = fliplab.samplers.points(500, "uniform", 9)
    for rule in ("DT", "P_1", "-alpha_inf", "R_1"):
        t = fliplab.lot(p, rule)
        assert t.triangles.dtype == np.int32 and t.triangles.shape == (t.stats["triangles"], 3)
        assert t.points.dtype == np.float64 and t.points.shape == (500, 2)
        a, b, c = (p[t.triangles[:, i]] for i in range(3))
        cross = ((b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1])
                 - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0]))
        assert (cross > 0).all()                                     # anticlockwise
        assert (t.triangles[:, 0] < t.triangles[:, 1:].min(axis=1)).all()
        assert len(t.triangles) == 2 * 500 - len(t.hull) - 2          # Euler
        nb = t.neighbors
        assert ((nb == -1).sum()) == len(t.hull)                      # one per hull edge
        for tt, k in zip(*np.nonzero(nb >= 0)):                       # symmetric, shared edge
            u = nb[tt, k]
            assert tt in nb[u]
            edge = set(t.triangles[tt]) - {t.triangles[tt, k]}
            assert edge <= set(t.triangles[u])


@pytest.mark.parametrize("kind", ["uniform", "grid", "circle", "parabola", "normal"])
@pytest.mark.parametrize("rule", ["DT", "P_1", "-alpha_inf", "a_2"])
def test_matplotlib_accepts(kind, rule):
    p = fliplab.samplers.points(200, kind, 5)
    t = fliplab.lot(p, rule)
    tr = mtri.Triangulation(p[:, 0], p[:, 1], t.triangles)
    tr.get_trifinder()        # raises for overlapping or badly oriented triangles
    assert (tr.triangles == t.triangles).all()
    tr2 = mtri.Triangulation(p[:, 0], p[:, 1], t.triangles)
    assert tr2.neighbors.shape == t.neighbors.shape


@pytest.mark.parametrize("rule,kind,alg", [("DT", "uniform", "incremental"),
                                           ("P_1", "normal", "flip"),
                                           ("-alpha_inf", "grid", "incremental"),
                                           ("DT", "disc", "sweep"),
                                           ("R_2", "uniform", "flip")])
def test_same_as_cli_random(cli, rule, kind, alg):
    n, seed = 700, 11
    out = cli.file("lot.csv")
    run = cli.run("lot", "--rule", rule, "--random", n, "--sampler", kind, "--seed", seed,
                  "--algorithm", alg, "--out", out)
    rows = cli.rows("lot.csv")
    assert rows[0] == ["i", "j", "k", "badness"]
    cli_tri = np.array([[int(x) for x in r[:3]] for r in rows[1:]])
    t = fliplab.lot(fliplab.samplers.points(n, kind, seed), rule, algorithm=alg, seed=seed)
    assert (t.triangles == cli_tri).all()
    assert t.flips == int(stdout_field(run.stdout, "flips"))
    cli_bad = np.array([float(r[3]) if r[3] else np.nan for r in rows[1:]])
    assert np.array_equal(t.badness, cli_bad, equal_nan=True)


def test_same_as_cli_points_with_duplicates(cli):
    p = fliplab.samplers.points(300, "normal", 4)
    p = np.vstack([p, p[:20], p[5:7]])                     # exact duplicates, merged
    path = cli.file("p.csv")
    write_points(path, p)
    for order in ("input", "random", "spatial"):
        run = cli.run("lot", "--rule", "P_1", "--points", path, "--order", order, "--seed", 3,
                      "--out", cli.file("o.csv"))
        cli_tri = np.array([[int(x) for x in r[:3]] for r in cli.rows("o.csv")[1:]])
        t = fliplab.lot(p, "P_1", order=order, seed=3)
        assert (t.triangles == cli_tri).all()
        assert t.stats["duplicates"] == 22
        assert stdout_field(run.stdout, "points") == "%d (hull %d, duplicates 22)" % (
            len(p), len(t.hull))
        assert t.triangles.max() < 300                     # first occurrences represent them


def test_budget_and_check():
    p = fliplab.samplers.points(400, "uniform", 2)
    t = fliplab.lot(p, "P_1", max_flips=5)
    assert t.status == "budget exhausted" and t.flips == 5
    assert not t.check()
    with pytest.raises(fliplab.CheckError, match="not locally optimal"):
        fliplab.lot(p, "P_1", max_flips=5, check=True)


@pytest.mark.parametrize("points,msg", [
    ([[0, 0], [1, 1]], "at least three"),
    ([[0, 0], [1, 1], [2, 2], [3, 3]], "collinear"),
    ([[0, 0], [1, 0], [0, np.nan]], "not finite"),
    ([[0, 0], [1, 0], [0, 1e31]], "out of range"),
    ([[0, 0], [1, 0], [0, 1e-31]], "out of range"),
])
def test_bad_points_raise_c_message(cli, points, msg):
    with pytest.raises(ValueError) as e:
        fliplab.lot(np.array(points, dtype=float), "DT")
    assert msg in str(e.value)
    if not any(np.isnan(np.array(points, dtype=float)).ravel()):
        path = cli.file("bad.csv")
        write_points(path, points)
        run = cli.run("lot", "--rule", "DT", "--points", path, ok=False)
        assert run.returncode == 2
        # The library's message, word for word; a coordinate the program's CSV
        # reader refuses first, naming the file and line, for the same reason.
        words = str(e.value).split(": a coordinate ")[-1]
        assert words in run.stderr


@pytest.mark.parametrize("bad,msg", [
    (np.zeros((5, 3)), "shape"), (np.zeros(5), "shape"), (np.array([["a", "b"]] * 3), "dtype"),
    (np.zeros((3, 2), dtype=complex), "dtype"), (np.zeros((3, 2), dtype=bool), "dtype")])
def test_bad_arrays(bad, msg):
    with pytest.raises(ValueError, match=msg):
        fliplab.lot(bad, "DT")


def test_bad_options():
    p = fliplab.samplers.points(10)
    with pytest.raises(ValueError, match="unknown algorithm"):
        fliplab.lot(p, "DT", algorithm="magic")
    with pytest.raises(ValueError, match="order applies"):
        fliplab.lot(p, "DT", algorithm="flip", order="random")
    with pytest.raises(ValueError, match="seed"):
        fliplab.lot(p, "DT", seed=-1)
    with pytest.raises(ValueError) as e:
        fliplab.lot(p, "P_1", algorithm="sweep")
    assert "sweep" in str(e.value)
    with pytest.raises(ValueError, match="unknown"):
        fliplab.lot(p, "nonsense_1")
