"""test_pymeasure_plot.py: measures written in Python (on whole arrays for
badness(), through the callback in lot/got/table34) equal the built-in ones
they restate; errors inside them surface; the plotting helpers draw."""
import numpy as np
import pytest

import fliplab


def test_python_measure_equals_builtin():
    name = fliplab.measure("pyP", lambda q: q["a"] + q["b"] + q["c"], sign=">= 0")
    tri = fliplab.samplers.points(600, "normal", 1).reshape(-1, 3, 2)
    assert np.array_equal(fliplab.badness(tri, name), fliplab.badness(tri, "P"))
    q = fliplab.quantities(tri[:5])
    assert np.array_equal(q["P"], fliplab.badness(tri[:5], "P"))
    p = fliplab.samplers.points(150, "uniform", 2)
    assert (fliplab.lot(p, "pyP_1").triangles == fliplab.lot(p, "P_1").triangles).all()
    poly = fliplab.samplers.polygon(9, "vector", seed=1)
    assert fliplab.got(poly, "pyP_1").total == fliplab.got(poly, "P_1").total
    t = fliplab.table34(200, rules=["pyP_1", "P_1"], threads=1)
    assert t["type_I"][0] == t["type_I"][1] and t["dt"][0] == t["dt"][1]


def test_quantities_are_the_measures():
    # one C pass (geom_tri_make_n) gives the fields the built-in measures
    # read, bit for bit, and the vertices in canonical (lexicographic) order
    tri = fliplab.samplers.points(3 * 20000, "normal", 3).reshape(-1, 3, 2)
    q = fliplab.quantities(tri)
    for field, name, s in [("alpha", "-alpha", -1), ("beta", "beta", 1), ("gamma", "gamma", 1),
                           ("a", "a", 1), ("c", "-c", -1), ("P", "P", 1), ("A", "-A", -1),
                           ("R", "R", 1), ("r", "-r", -1), ("h", "-a'", -1)]:
        assert np.array_equal(s * q[field], fliplab.badness(tri, name)), field
    v = np.stack([q[["x%d" % k, "y%d" % k]].tolist() for k in (1, 2, 3)], axis=1)
    assert np.array_equal(np.sort(v.view("f8,f8"), axis=1), v.view("f8,f8"))
    assert np.array_equal(np.sort(tri.view("f8,f8"), axis=1)[..., 0], v.view("f8,f8")[..., 0])
    with pytest.raises(ValueError, match="triangle"):
        fliplab.quantities(np.array([[[0, 0], [1, 0], [np.nan, 1]]]))


def test_python_measure_errors():
    fliplab.measure("pyneg", lambda q: q["a"] - 1.0, sign=">= 0")
    tri = np.array([[[0, 0], [0.5, 0], [0, 0.5]]])
    with pytest.raises(ValueError, match="pyneg"):
        fliplab.badness(tri, "pyneg")

    def boom(q):
        raise ZeroDivisionError("inside the measure")
    fliplab.measure("pyboom", boom)
    with pytest.raises(ZeroDivisionError):
        fliplab.lot(fliplab.samplers.points(20), "pyboom_inf")
    assert fliplab.lot(fliplab.samplers.points(20), "P_1").check()   # nothing left over
    with pytest.raises(ValueError, match="already"):
        fliplab.measure("pyP2", lambda q: q["P"]) and fliplab.measure("pyP2", lambda q: q["P"])
    with pytest.raises(ValueError):
        fliplab.measure("bad_name", lambda q: q["P"])


def test_plots(tmp_path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from fliplab import plot
    p = fliplab.samplers.points(200, "uniform", 1)
    a, b = fliplab.lot(p, "P_1"), fliplab.lot(p, "DT")
    ax = plot.triangulation(a)
    ax.figure.savefig(tmp_path / "a.png")
    fig = plot.compare(a, fliplab.lot(p, "-alpha_inf"))
    fig.savefig(tmp_path / "b.png")
    plot.compare(a, b)
    g = fliplab.flipgraph(fliplab.samplers.site_sets(6, 1, "disc", seed=2)[0], "P_1")
    plot.flipgraph(g).figure.savefig(tmp_path / "g.png")
    cm = plot.badness_cmap(4)
    assert np.allclose(cm(0)[:3], (255 / 255, 247 / 255, 214 / 255))
    assert np.allclose(cm(1.0)[:3], (103 / 255, 0, 13 / 255))
    plt.close("all")
    assert all((tmp_path / f).stat().st_size > 1000 for f in ("a.png", "b.png", "g.png"))
