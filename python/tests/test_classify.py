"""test_classify.py: classify() and verdicts() against `fliplab classify` and
`fliplab rule` run on the same pentagons and seeds, and against what the
thesis proves (DT is type I on every pentagon, theorem 3; a triangle-based
rule always has a sink, theorem 1; every empty-shape rule is type I,
theorem 13)."""
import csv
import io
import re

import numpy as np
import pytest

import fliplab


def _write_pentagons(path, p):
    with open(path, "w") as f:
        f.write("x1,y1,x2,y2,x3,y3,x4,y4,x5,y5\n")
        for q in p:
            f.write(",".join("%.17g" % x for x in q.reshape(-1)) + "\n")


def test_classify_equals_cli(cli, tmp_path):
    p = fliplab.samplers.pentagons(400, seed=3)
    p[1::2] = p[1::2, [0, 4, 3, 2, 1]]            # clockwise rows: renumbered as the CLI does
    path = tmp_path / "p.csv"
    _write_pentagons(path, p)
    rules = ["P_1", "-alpha_inf", "R_2", "DT"]
    rows = list(csv.DictReader(io.StringIO(
        cli.run("classify", "--input", path, "--rule", ",".join(rules)).stdout)))
    c = fliplab.classify(p, rules, threads=2)
    assert c.shape == (400, 4) and len(rows) == 400 * 4
    for row in rows:
        i, r = int(row["id"]) - 1, rules.index(row["rule"])
        g = c[i, r]
        assert row["decisions"] == g["decisions"] and row["type"] == g["type"]
        assert row["sink"] == " ".join(str(s) for s in g["sinks"] if s >= 0)
        assert int(row["dt"]) == int(g["dt"])
    assert (c[:, 3]["type"] == "I").all() and c[:, 3]["dt"].all()     # theorem 3
    assert not (c[:, :3]["type"] == "IV").any()                        # theorem 1
    one = fliplab.classify(p, "P_1", threads=1)
    assert one.shape == (400,) and (one == c[:, 0]).all()              # no output depends on threads


def test_classify_empty_shape_type_one():
    c = fliplab.classify(fliplab.samplers.pentagons(3000, seed=7),
                         ["ES:square", "ES:triangle", "ES:hexagon"])
    assert (c["type"] == "I").all()                                    # theorem 13


def test_classify_refuses():
    p = fliplab.samplers.pentagons(3, seed=1)
    p[2, 3] = p[2, 2]
    with pytest.raises(ValueError, match="pentagon 2"):
        fliplab.classify(p, "P_1")
    with pytest.raises(ValueError):
        fliplab.classify(np.zeros((2, 4, 2)), "P_1")


def _num(pattern, text):
    return [int(x) for x in re.search(pattern, text).groups()]


def test_verdicts_equal_cli(cli):
    out = cli.run("rule", "P_1", "--samples", 3000, "--quads", 3000, "--site-samples", 300,
                  "--seed", 2, "--threads", 2).stdout
    v = fliplab.verdicts("P_1", samples=3000, quads=3000, site_samples=300, seed=2, threads=2)
    for ty in fliplab._classify.TYPES + ("DT",):
        m = re.search(r"^  %s +(\d+) +[\d.]+%% +\[([\d.]+), ([\d.]+)\]" % ty, out, re.M)
        key = "dt" if ty == "DT" else ty
        assert int(m.group(1)) == v["counts"][key], ty
        lo, hi = v["intervals"][key]
        assert (m.group(2), m.group(3)) == ("%.3f" % lo, "%.3f" % hi), ty
    assert v["systematic"] == ("no counterexample to systematicity in" in out)
    assert v["local"] == ("no counterexample to locality" in out)
    q = v["quads"]
    assert _num(r"on (\d+) random convex quadrilaterals: (\d+) disagreements, (\d+) ties "
                r"\(either\), (\d+) cocircular", out) == [q["tested"], q["disagree"], q["ties"],
                                                         q["cocircular"]]
    assert _num(r"first disagreement, quadrilateral #(\d+)", out) == [q["first"]]
    for ty, ws in v["witnesses"].items():
        shown = [int(i) for i in re.findall(r"^    type %s +#(\d+):" % ty, out, re.M)]
        assert shown == [w["index"] for w in ws][:len(shown)] and len(shown) == len(ws), ty
        for w in ws:
            line = re.search(r"^    type %s +#%d: pentagon (\S+); decisions (\w+); sinks ([T\d ]+);"
                             % (ty, w["index"]), out, re.M)
            assert line.group(2) == w["decisions"]
            assert line.group(3).strip() == " ".join("T%d" % s for s in w["sinks"])
            xy = np.array([float(x) for x in line.group(1).split(",")]).reshape(5, 2)
            assert np.array_equal(xy, w["pentagon"])
    shown = [int(i) for i in re.findall(r"witness: set #(\d+):", out)]
    assert shown == [s["witness"]["index"] for s in v["sites"] if s["witness"]]
    assert [s["multi_sink"] for s in v["sites"] if s["multi_sink"]] == \
        [int(x) for x in re.findall(r"not systematic: (\d+) \S+ (?:sets )?with two or more", out)]


def test_verdicts_delaunay():
    v = fliplab.verdicts("DT", samples=2000, quads=2000, site_samples=100)
    assert v["counts"]["I"] == v["counts"]["dt"] == 2000
    assert v["systematic"] and v["local"] and v["delaunay_equivalent"]
    assert all(not w for w in v["witnesses"].values())
    assert all(s["multi_sink"] == 0 and s["witness"] is None for s in v["sites"])
    lo, hi = fliplab.wilson(0, 2000)
    assert lo == pytest.approx(0, abs=1e-12) and 0 < hi < 0.2
