"""test_studies.py: the studies of studies/study.h seen from both front ends:
what `fliplab rule` prints and what verdicts() returns are the same numbers
(one library call behind both: counts, intervals, verdicts, the
Delaunay-equivalence check, the site sets, the witnesses), and so are
`fliplab lot --compare GOT`'s line and compare_got() (convex position and
simple polygons from .poly files), whose relations hold as theory demands
(a LOT never totals below its GOT; a rule whose GOT is the CDT has the
CDT's triangles)."""
import re

import numpy as np
import pytest

import fliplab

TYPES = ("I", "II", "III", "IV", "V")
RULE_RUN = dict(samples=4000, quads=4000, site_samples=300, seed=3, witnesses=2, threads=2)


def _rule_cli(cli, rule):
    return cli.run("rule", rule, "--samples", RULE_RUN["samples"], "--quads", RULE_RUN["quads"],
                   "--site-samples", RULE_RUN["site_samples"], "--seed", RULE_RUN["seed"],
                   "--witnesses", RULE_RUN["witnesses"], "--threads", 2).stdout


def _one(pattern, text):
    m = re.search(pattern, text, re.M)
    assert m is not None, pattern
    return m.groups()


def _check_rows(out, v):
    for ty in TYPES + ("DT",):
        key = "dt" if ty == "DT" else ty
        k, lo, hi = _one(r"^  %s +(\d+) +[\d.]+%% +\[([\d.]+), ([\d.]+)\]" % ty, out)
        assert int(k) == v["counts"][key], ty
        assert (lo, hi) == tuple("%.3f" % x for x in v["intervals"][key]), ty


def _check_verdicts(out, v):
    c = v["counts"]
    if v["systematic"]:
        assert int(_one(r"no counterexample to systematicity in (\d+) pentagons", out)[0]) \
            == v["decided"] == c["I"] + c["II"] + c["III"] + c["IV"]
    else:
        assert int(_one(r"verdict: not systematic: (\d+) counterexamples? \(type III", out)[0]) \
            == c["III"] > 0
    if v["local"]:
        assert int(_one(r"no counterexample to locality in (\d+) pentagons", out)[0]) \
            == v["decided"]
    else:
        assert int(_one(r"verdict: not local: (\d+) counterexamples?", out)[0]) == c["II"] > 0
    assert ("returns either on %d pentagon" % c["V"] in out) == (c["V"] > 0)
    assert ("agrees with Delaunay on all" in out) == v["always_delaunay"]
    assert ("BUG" in out) == v["sink_bug"] is False


def _check_quads(out, v):
    q = v["quads"]
    assert [int(x) for x in _one(r"on (\d+) random convex quadrilaterals: (\d+) disagreements, "
                                 r"(\d+) ties \(either\), (\d+) cocircular", out)] == \
        [q["tested"], q["disagree"], q["ties"], q["cocircular"]]
    assert v["delaunay_equivalent"] == q["equivalent"]
    if q["equivalent"]:
        assert int(_one(r"Delaunay equivalence in (\d+) quadrilaterals", out)[0]) == q["decided"]
    elif q["first"] is None:
        assert int(_one(r"either on (\d+) quadrilaterals where", out)[0]) == q["ties"]
    else:
        first, choice, dt = _one(r"quadrilateral #(\d+) ABCD = \S+: rule (\w+), DT (\w+)", out)
        names = {fliplab.AC: "AC", fliplab.BD: "BD"}
        assert (int(first), choice, dt) == (q["first"], names[q["choice"]], names[q["dt"]])
        ac, bd = _one(r"\(F_AC = (\S+), F_BD = (\S+)\)", out)
        assert (ac, bd) == ("%.17g" % q["ac"], "%.17g" % q["bd"])


def _check_sites(out, v):
    said = re.findall(r"verdict: (not systematic: (\d+) \S+ (?:sets )?with two or more LOTs "
                      r"among (\d+)|no counterexample to systematicity in (\d+) (?!pentagons))",
                      out)
    assert len(said) == len(v["sites"])
    for s, (_, multi, among, decided) in zip(v["sites"], said):
        if s["systematic"]:
            assert int(decided) == s["decided"] and s["witness"] is None
        else:
            assert (int(multi), int(among)) == (s["multi_sink"], s["samples"])
            w = _one(r"witness: set #%d: (.*)$" % s["witness"]["index"], out)[0]
            xy = np.array([[float(c) for c in p.split(",")] for p in w.split()])
            assert np.array_equal(xy, s["witness"]["sites"])


def _check_witnesses(out, v):
    for ty, ws in v["witnesses"].items():
        shown = [int(i) for i in re.findall(r"^    type %s +#(\d+):" % ty, out, re.M)]
        assert shown == [w["index"] for w in ws]
        for w in ws:
            pent, dec = _one(r"^    type %s +#%d: pentagon (\S+); decisions (\w+);"
                             % (ty, w["index"]), out)
            assert dec == w["decisions"]
            xy = np.array([float(x) for x in pent.split(",")]).reshape(5, 2)
            assert np.array_equal(xy, w["pentagon"])


@pytest.mark.parametrize("rule", ["P_1", "-c_1", "R_1", "-alpha_inf", "sigma_0"])
def test_verdicts_are_the_programs(cli, rule):
    """The program's printed numbers are verdicts()'s, rule by rule."""
    out = _rule_cli(cli, rule)
    v = fliplab.verdicts(rule, **RULE_RUN)
    _check_rows(out, v)
    _check_verdicts(out, v)
    _check_quads(out, v)
    _check_sites(out, v)
    _check_witnesses(out, v)
    assert v["systematic"] == (v["counts"]["III"] == 0)
    assert v["local"] == (v["counts"]["II"] == 0)


def test_verdicts_threads_and_refusals():
    a = fliplab.verdicts("P_1", samples=2000, quads=500, site_samples=50, threads=1)
    b = fliplab.verdicts("P_1", samples=2000, quads=500, site_samples=50, threads=2)
    assert repr(a) == repr(b)
    with pytest.raises(ValueError, match="witnesses"):
        fliplab.verdicts("P_1", samples=10, witnesses=101)
    with pytest.raises(ValueError, match="threads"):
        fliplab.verdicts("P_1", samples=10, threads=5000)
    with pytest.raises(ValueError, match="sites"):
        fliplab.verdicts("P_1", samples=10, sites=["moon:5"])
    lo, hi = fliplab.wilson(3, 10)
    assert lo < 30 < hi
    with pytest.raises(ValueError, match="k"):
        fliplab.wilson(11, 10)


def _cmp_line(out):
    return _one(r"^compare GOT: LOT total (\S+), GOT total (\S+): (.*)$", out)


@pytest.mark.parametrize("rule", ["P_1", "-r_1", "-alpha_inf", "R_inf", "P_2"])
def test_compare_got_convex_is_the_programs(cli, rule):
    p = fliplab.samplers.points(40, "circle", seed=2)
    out = cli.run("lot", "--rule", rule, "--random", 40, "--sampler", "circle", "--seed", 2,
                  "--compare", "GOT").stdout
    c = fliplab.compare_got(fliplab.lot(p, rule, seed=2))
    lot, got, rest = _cmp_line(out)
    assert (lot, got) == (c["lot_text"], c["got_text"])
    assert rest.startswith("equal (" if c["equal"] else "NOT equal (")
    assert "relative difference %.3g, " % c["rel"] in rest
    assert ("GOT computed to within rounding" in rest) == c["certified"]
    if not c["certified"]:
        assert rest.endswith("no certified bound: %s)" % c["uncertified"])
    assert not c["ring"] and not c["below"] and c["lot_key"] >= c["got_key"] or c["equal"]


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_compare_got_polygon_is_the_programs(cli, seed):
    path = cli.file("p.poly")
    cli.run("sample", "--sampler", "holes", "--points", 24 + 4 * seed, "--holes", 0, "--seed",
            seed, "--out", path)
    p, s, h = fliplab.read_poly(path)
    for rule in ("R_1", "P_1", "abc_1", "R_inf"):
        out = cli.run("lot", "--rule", rule, "--poly", path, "--compare", "GOT").stdout
        c = fliplab.compare_got(fliplab.lot(p, rule, segments=s, holes=h))
        lot, got, rest = _cmp_line(out)
        assert (lot, got) == (c["lot_text"], c["got_text"])
        word = "LOT < GOT" if c["below"] else "LOT = GOT" if c["equal"] else "LOT > GOT"
        assert rest.startswith(word) and not c["below"] and not c["failed"]
        shared, total = _one(r"; (\d+) of (\d+) triangles shared", rest)
        assert (int(shared), int(total)) == (c["triangles_shared"], c["triangles_got"])
        assert c["ring"] and c["n"] == len(p) and c["got_triangles"].shape == (len(p) - 2, 3)
        # the rules whose GOT is the CDT (rule_got_is_cdt): the LOT is the GOT
        assert c["got_is_cdt"] == (rule in ("R_1", "abc_1"))
        assert ("the rule's GOT is the CDT" in rest) == c["got_is_cdt"]
        if c["got_is_cdt"]:
            assert c["same"] and c["triangles_shared"] == len(p) - 2


def test_compare_got_refusals():
    p = fliplab.samplers.points(30, "uniform", seed=1)
    with pytest.raises(ValueError, match="strictly convex position"):
        fliplab.compare_got(fliplab.lot(p, "P_1"))
    q = fliplab.samplers.points(20, "circle", seed=1)
    with pytest.raises(ValueError, match="triangle-based rule"):
        fliplab.compare_got(fliplab.lot(q, "DT"))
    with pytest.raises(TypeError, match="Triangulation"):
        fliplab.compare_got(q)
    sq = np.array([[0, 0], [4, 0], [4, 4], [0, 4], [1, 1], [3, 1]], dtype=float)
    t = fliplab.lot(sq, "P_1", segments=[[0, 1], [1, 2], [2, 3], [3, 0]])
    with pytest.raises(ValueError, match=r"\(4 segments, 6 points\)"):
        fliplab.compare_got(t)
