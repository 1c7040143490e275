"""test_silent_answers.py: inputs that used to get an answer without a word
are refused with a message, and results do not change behind the caller's
back: masked arrays, NUL characters in names, a Python measure returning
the wrong number of values inside the C algorithms, a caller's array
changed after lot(), error messages in keyword terms (not the program's
flags), cdf() of something that is no Triangulation."""
import pathlib

import numpy as np
import pytest

import fliplab

MASKED = "masked arrays are not supported (scipy refuses them too); use .filled() or " \
         ".compressed()"


def square_pts():
    return np.array([[0, 0], [4, 0], [4, 4], [0, 4], [1, 1], [3, 2]], dtype=float)


def test_masked_arrays_refused():
    p = fliplab.samplers.points(20, "uniform", 1)
    mp = np.ma.masked_array(p, mask=np.zeros_like(p, dtype=bool))
    mp.mask[3, 0] = True
    with pytest.raises(ValueError) as e:
        fliplab.lot(mp)
    assert str(e.value) == "points: " + MASKED
    with pytest.raises(ValueError, match="points: masked"):      # even with nothing masked
        fliplab.lot(np.ma.masked_array(p))
    sq = square_pts()
    seg = np.ma.masked_array([[0, 1], [1, 2]])
    with pytest.raises(ValueError, match="segments: masked"):
        fliplab.lot(sq, segments=seg)
    with pytest.raises(ValueError, match="holes: masked"):
        fliplab.lot(sq, segments=[[0, 1], [1, 2], [2, 3], [3, 0]],
                    holes=np.ma.masked_array([[2.0, 2.0]]))
    t = fliplab.lot(p)
    with pytest.raises(ValueError, match="triangles: masked"):
        fliplab.check(p, np.ma.masked_array(t.triangles), "DT")
    with pytest.raises(ValueError, match="triangles: masked"):
        fliplab.badness(np.ma.masked_array(p[:6].reshape(2, 3, 2)), "R")
    with pytest.raises(ValueError, match="polygon: masked"):
        fliplab.got(np.ma.masked_array(sq[:4]), "P_1")
    with pytest.raises(ValueError, match="xi: masked"):
        t.find_simplex(np.ma.masked_array(p[:2]))


def test_nul_in_names_refused():
    for name in ("P_1\x00junk", "DT\x00", "ES:square\x00x"):
        with pytest.raises(ValueError, match="NUL"):
            fliplab.Rule(name)
        with pytest.raises(ValueError, match="NUL"):
            fliplab.lot(square_pts(), name)
    with pytest.raises(ValueError, match="NUL"):
        fliplab.badness(np.zeros((1, 3, 2)), "R\x00junk")
    with pytest.raises(ValueError, match="NUL"):
        fliplab.define("nulmeasure = a\x00 + b")
    with pytest.raises(ValueError, match="NUL"):
        fliplab.load_plugin("plugins/x.so\x00junk")
    with pytest.raises(ValueError, match="NUL"):
        fliplab.read_poly("x.poly\x00junk")
    with pytest.raises(ValueError, match="NUL"):
        fliplab.measure("nulpy\x00x", lambda q: q["a"])
    with pytest.raises(ValueError, match="NUL"):
        fliplab.measure("nulpydesc", lambda q: q["a"], desc="a\x00b")
    assert "nulpydesc" not in [m["name"] for m in fliplab.measures()]
    with pytest.raises(TypeError, match="rule"):
        fliplab.Rule(b"P_1")
    # paths may still be pathlib objects
    with pytest.raises(ValueError, match="no-such.poly"):
        fliplab.read_poly(pathlib.Path("no-such.poly"))


def test_python_measure_wrong_length_refused_everywhere():
    name = fliplab.measure("pywronglen", lambda q: np.ones(len(q["a"]) + 1), sign=">= 0")
    tri = fliplab.samplers.points(30, "uniform", 1).reshape(-1, 3, 2)
    with pytest.raises(ValueError, match="returned 11 values for 10 triangles"):
        fliplab.badness(tri, name)
    p = fliplab.samplers.points(40, "uniform", 2)
    with pytest.raises(ValueError, match="returned 2 values for 1 triangles"):
        fliplab.lot(p, name + "_1")
    with pytest.raises(ValueError, match="returned 2 values for 1 triangles"):
        fliplab.got(fliplab.samplers.polygon(7, "vector", seed=1), name + "_1")
    with pytest.raises(ValueError, match="returned 2 values for 1 triangles"):
        fliplab.flipgraph(fliplab.samplers.site_sets(5, 1, "convex", seed=1)[0], name + "_1")
    with pytest.raises(ValueError, match="returned 2 values for 1 triangles"):
        fliplab.table34(5, rules=[name + "_1"], threads=1)
    with pytest.raises(ValueError, match="returned 2 values for 1 triangles"):
        fliplab.decide(fliplab.samplers.quads(3), name + "_1")
    t = fliplab.lot(p, "P_1")
    with pytest.raises(ValueError, match="returned 2 values for 1 triangles"):
        fliplab.check(p, t.triangles, name + "_1")
    # nothing is left pending: the next call is clean
    assert fliplab.lot(p, "P_1").flips == t.flips


def test_python_measure_length_one_still_fine():
    name = fliplab.measure("pyscalarP", lambda q: q["a"] + q["b"] + q["c"], sign=">= 0")
    p = fliplab.samplers.points(60, "uniform", 3)
    assert np.array_equal(fliplab.lot(p, name + "_1").triangles, fliplab.lot(p, "P_1").triangles)


def test_result_does_not_follow_the_callers_array():
    p = fliplab.samplers.points(200, "uniform", 4)
    keep = p.copy()
    t = fliplab.lot(p, "P_1")
    assert not np.shares_memory(t.points, p)
    b, tot = t.badness.copy(), t.total()
    p[:] = 0                        # the caller reuses its buffer
    assert np.array_equal(t.points, keep)
    assert np.array_equal(t.badness, b) and t.total() == tot
    assert t.check()
    for a in (t.points, t.triangles, t.neighbors, t.badness, t.hull, t.constrained):
        assert not a.flags.writeable
        with pytest.raises(ValueError):
            a[0] = 0
    holes = np.array([[2.0, 2.0]])
    sq = np.array([[0, 0], [4, 0], [4, 4], [0, 4], [1, 1], [3, 1], [3, 3], [1, 3]], float)
    seg = np.array([[0, 1], [1, 2], [2, 3], [3, 0], [4, 5], [5, 6], [6, 7], [7, 4]], np.int32)
    c = fliplab.lot(sq, "DT", segments=seg, holes=holes)
    holes[:] = 9
    seg[:] = 0
    assert np.array_equal(c.holes, [[2.0, 2.0]]) and c.segments[1].tolist() == [1, 2]
    assert c.check()
    sites = fliplab.samplers.site_sets(6, 1, "convex", seed=2)[0]
    s0 = sites.copy()
    g = fliplab.flipgraph(sites, "P_1")
    sites[:] = 0
    assert np.array_equal(g.points, s0) and not g.points.flags.writeable


def test_messages_in_keyword_terms():
    p = fliplab.samplers.points(30, "uniform", 5)
    for bad in ("x", "1e-9", [1e-9], True, -1.0, float("nan"), float("inf")):
        with pytest.raises(ValueError) as e:
            fliplab.lot(p, "P_1", tie_eps=bad)
        assert str(e.value) == "tie_eps: expected a finite number >= 0, got %r" % (bad,)
    with pytest.raises(ValueError, match="tie_eps: expected a finite number"):
        fliplab.Rule("P_1", tie_eps="x")
    with pytest.raises(ValueError, match="tie_eps: expected a finite number"):
        fliplab.got(fliplab.samplers.polygon(6, "vector", seed=1), "P_1", tie_eps="x")
    with pytest.raises(ValueError, match="tie_eps: expected a finite number"):
        fliplab.flipgraph(fliplab.samplers.site_sets(5, 1, "convex", seed=1)[0], "P_1",
                          tie_eps="x")
    with pytest.raises(ValueError, match="tie_eps: expected a finite number"):
        fliplab.table34(5, tie_eps="x")
    assert fliplab.lot(p, "P_1", tie_eps=0).rule.tie_eps == 0.0
    assert fliplab.lot(p, "P_1", tie_eps=np.float32(1e-6)).rule.tie_eps == np.float32(1e-6)
    # a message from the library names no flag of the program
    sq = np.array([[0, 0], [4, 0], [4, 4], [0, 4], [1, 1]], dtype=float)
    with pytest.raises(ValueError) as e:
        fliplab.lot(sq, "DT", segments=[[0, 2]])
    assert "no triangle is left" in str(e.value) and "--" not in str(e.value)


def test_cdf_of_something_else():
    with pytest.raises(TypeError, match="cdf: expected a fliplab.Triangulation"):
        fliplab.cdf(None)
    with pytest.raises(TypeError, match="cdf: expected a fliplab.Triangulation"):
        fliplab.cdf(np.zeros((3, 2)))
