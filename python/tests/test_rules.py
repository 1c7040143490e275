"""test_rules.py: rules and measures by name, vectorised badness and
decisions against the per-item C results and independent formulas, user
measures (formulas, plugins) and empty-shape rules."""
import math
import os
import subprocess

import numpy as np
import pytest

import fliplab
from conftest import ROOT


def test_names():
    ms = [m["name"] for m in fliplab.measures()]
    assert len(ms) >= 23 and ms[:3] == ["-alpha", "beta", "gamma"]
    assert fliplab.joints()[:6] == ["-inf", "-1", "0", "1", "2", "inf"]
    assert "DT" in fliplab.quad_rules()
    names = fliplab.rules()
    assert "P_1" in names and "-alpha_inf" in names
    r = fliplab.Rule("-alpha_inf")
    assert (r.measure, r.joint, r.is_triangle, r.is_delaunay) == ("-alpha", "inf", True, False)
    assert fliplab.Rule("DT").is_delaunay and fliplab.Rule("DT").measure == ""
    with pytest.raises(ValueError, match="unknown|valid"):
        fliplab.Rule("P_7x")


def test_badness_independent_formulas():
    tri = fliplab.samplers.points(3000, "normal", 5).reshape(-1, 3, 2)
    a = np.linalg.norm(tri[:, 1] - tri[:, 2], axis=1)
    b = np.linalg.norm(tri[:, 0] - tri[:, 2], axis=1)
    c = np.linalg.norm(tri[:, 0] - tri[:, 1], axis=1)
    area = 0.5 * np.abs(np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0]))
    assert np.allclose(fliplab.badness(tri, "P"), a + b + c, rtol=1e-14)
    assert np.allclose(fliplab.badness(tri, "-A"), -area, rtol=1e-9)
    assert np.allclose(fliplab.badness(tri, "R"), a * b * c / (4 * area), rtol=1e-9)
    assert np.allclose(fliplab.badness(tri, "a"), np.maximum(np.maximum(a, b), c), rtol=1e-14)
    # a rule name means its measure; vertex order does not matter, bit for bit
    assert np.array_equal(fliplab.badness(tri, "R_1"), fliplab.badness(tri[:, ::-1], "R"))
    assert np.array_equal(fliplab.Rule("P_inf").badness(tri), fliplab.badness(tri, "P"))


def test_badness_equals_lot_badness():
    p = fliplab.samplers.points(400, "disc", 8)
    for rule in ("P_1", "-alpha_inf", "R_2", "lambda_-1"):
        t = fliplab.lot(p, rule)
        assert np.array_equal(t.badness, fliplab.badness(p[t.triangles], rule))


def test_decide():
    q = fliplab.samplers.quads(2000, seed=4)
    d = fliplab.decide(q, "DT")
    # DT: keep AC unless D lies inside circle ABC (exact; a float check off the ties)
    A, B, C, D = (q[:, i] for i in range(4))
    def incircle(a, b, c, d):
        m = np.stack([a - d, b - d, c - d], axis=1)
        return np.linalg.det(np.concatenate([m, (m ** 2).sum(axis=2, keepdims=True)], axis=2))
    inside = incircle(A, B, C, D) > 0
    assert ((d == fliplab.BD) == inside).all()
    # P_1 from the badness of the four triangles
    choice, ac, bd = fliplab.decide(q, "P_1", values=True)
    P = lambda t: fliplab.badness(t, "P")
    assert np.array_equal(ac, P(q[:, [0, 1, 2]]) + P(q[:, [0, 2, 3]]))
    assert np.array_equal(bd, P(q[:, [0, 1, 3]]) + P(q[:, [1, 2, 3]]))
    assert ((choice == fliplab.AC) == (ac < bd * (1 - 1e-12))).all()
    # not strictly convex or clockwise: undecided
    assert (fliplab.decide(q[:, ::-1], "P_1") == fliplab.UNDECIDED).all()
    flat = np.array([[[0, 0], [1, 0], [2, 0], [1, 1]]], dtype=float)
    assert fliplab.decide(flat, "DT")[0] == fliplab.UNDECIDED


def test_bad_arrays():
    with pytest.raises(ValueError, match="shape"):
        fliplab.badness(np.zeros((4, 2)), "P")
    with pytest.raises(ValueError, match="triangle 1 .*not finite"):
        fliplab.badness(np.array([[[0, 0], [1, 0], [0, 1]], [[0, 0], [np.inf, 0], [0, 1]]]), "P")
    with pytest.raises(ValueError, match="out of range"):
        fliplab.decide(np.full((1, 4, 2), 1e40), "DT")
    with pytest.raises(ValueError, match="quadrilateral rule"):
        fliplab.badness(np.zeros((1, 3, 2)), "DT")
    with pytest.raises(ValueError, match="unknown measure"):
        fliplab.badness(np.zeros((1, 3, 2)), "nope")


def test_define_formula_equals_builtin():
    name = fliplab.define("perim2 = a + b + c")
    assert name == "perim2"
    tri = fliplab.samplers.points(300, "uniform", 2).reshape(-1, 3, 2)
    assert np.allclose(fliplab.badness(tri, "perim2"), fliplab.badness(tri, "P"), rtol=1e-15)
    p = fliplab.samplers.points(300, "uniform", 3)
    assert (fliplab.lot(p, "perim2_1").triangles == fliplab.lot(p, "P_1").triangles).all()
    with pytest.raises(ValueError) as e:
        fliplab.define("bad = a +* b")
    assert "position" in str(e.value) or "bad" in str(e.value)
    with pytest.raises(ValueError, match="taken|already|exists"):
        fliplab.define("perim2 = a")


def test_formula_bad_value_raises():
    fliplab.define("inv5 >= 0 : 1 / abs(x1 - 5)")
    tri = np.array([[[5, 0], [6, 0], [5, 1]]], dtype=float)   # x1 = 5: an infinite value
    with pytest.raises(ValueError, match="inv5"):
        fliplab.badness(tri, "inv5")
    assert fliplab.badness(tri + 1, "inv5")[0] == 1.0          # the error was cleared


def _plugin(tmp_path, name):
    src = os.path.join(ROOT, "plugins", name + ".c")
    inc = os.path.join(os.environ.get("FLIPLAB_BUILD_DIR", os.path.join(ROOT, "build")), "include")
    so = str(tmp_path / (name + ".so"))
    subprocess.run(["cc", "-std=c11", "-O2", "-shared", "-fPIC", "-I" + inc, src, "-o", so, "-lm"],
                   check=True)
    return so


def test_plugin(tmp_path):
    fliplab.load_plugin(_plugin(tmp_path, "rule109"))
    assert "rule109" in fliplab.quad_rules()
    p = fliplab.samplers.points(200, "uniform", 1)
    t = fliplab.lot(p, "rule109")
    assert t.status == "converged" and t.check()
    with pytest.raises(ValueError):
        fliplab.load_plugin(str(tmp_path / "missing.so"))


def test_shape_rule():
    p = fliplab.samplers.points(300, "uniform", 6)
    t = fliplab.lot(p, "ES:square")
    assert t.check() and np.isnan(t.badness).all()
    assert "ES:square" in fliplab.quad_rules()
    q = fliplab.samplers.quads(100)
    assert set(np.unique(fliplab.decide(q, "ES:square"))) <= {0, 1, 2}
