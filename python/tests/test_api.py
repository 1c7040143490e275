"""test_api.py: table34, census, got and flip graphs against the program
run on the same input and seed, and against theorems (DT always type I;
triangle rules never give a cycle; the GOT is a sink for joint 1; brute
force over all triangulations of a small convex polygon)."""
import csv
import io
import itertools

import numpy as np
import pytest

import fliplab
from conftest import stdout_field, write_points


def _csv(text):
    return list(csv.DictReader(io.StringIO(text)))


def test_table34_equals_cli(cli):
    run = cli.run("table34", "--samples", 3000, "--seed", 5, "--format", "csv",
                  "--measures", "R,P,-alpha")
    rows = _csv(run.stdout)
    seen = []
    t = fliplab.table34(3000, seed=5, measures=["R", "P", "-alpha"],
                        progress=lambda d, n: seen.append((d, n)))
    assert len(rows) == len(t) == 3 * 6 + 1          # three measures x six joints, then DT
    for row, mine in zip(rows, t):
        for k in ("measure", "joint", "rule"):
            assert row[k] == mine[k]
        for k in ("samples", "type_I", "type_II", "type_III", "type_IV", "type_V", "dt"):
            assert int(row[k]) == int(mine[k]), (row["rule"], k)
        for k in ("seed", "first", "end", "total", "rules"):
            assert int(row[k]) == t.meta[k]
        assert float(row["tie_eps"]) == t.meta["tie_eps"]
    assert seen and seen[-1] == (3000, 3000)
    dt = t[t["rule"] == "DT"][0]
    assert dt["type_I"] == dt["samples"] == dt["dt"]        # DT: always type I, sink DT
    assert (t[t["measure"] != ""]["type_IV"] == 0).all()     # theorem 1


def test_table34_threads_and_shards():
    a = fliplab.table34(2000, seed=2, rules=["P_1", "R_inf", "DT"], threads=1)
    b = fliplab.table34(2000, seed=2, rules=["P_1", "R_inf", "DT"], threads=2)
    assert np.array_equal(a, b)
    s1 = fliplab.table34(2000, seed=2, rules=["P_1", "R_inf", "DT"], shard=(1, 2))
    s2 = fliplab.table34(2000, seed=2, rules=["P_1", "R_inf", "DT"], shard=(2, 2))
    for k in ("type_I", "type_II", "type_III", "type_V", "dt", "samples"):
        assert (s1[k] + s2[k] == a[k]).all()
    assert s1.meta["end"] == s2.meta["first"] == 1000


def test_census_equals_cli(cli):
    run = cli.run("census", "--sites", 6, "--sampler", "disc", "--samples", 300, "--seed", 4,
                  "--rules", "P_1,-alpha_inf,R_1,DT", "--format", "csv")
    rows = _csv(run.stdout)
    c = fliplab.census(6, 300, "disc", seed=4, rules=["P_1", "-alpha_inf", "R_1", "DT"])
    assert len(rows) == len(c) == 4
    for row, mine in zip(rows, c):
        for k in ("measure", "joint", "rule", "sampler"):
            assert row[k] == mine[k]
        for k in ("sites", "samples", "tie", "no_sink", "one_sink", "multi_sink", "sink_dt",
                  "max_sinks"):
            assert int(row[k]) == int(mine[k]), (row["rule"], k)
        for k in ("mean_sinks", "mean_worst_gap"):
            if row[k] == "":
                assert np.isnan(mine[k])
            else:
                assert float(row[k]) == mine[k]           # %.17g reads back exactly


def _got_cli(cli, p, rule):
    path = cli.file("poly.csv")
    write_points(path, p)
    return cli.run("got", "--rule", rule, "--polygon", path).stdout


@pytest.mark.parametrize("sampler,rule", [("vector", "P_1"), ("circle", "-alpha_inf"),
                                          ("star", "R_1"), ("monotone", "a_2")])
def test_got_equals_cli(cli, sampler, rule):
    p = fliplab.samplers.polygon(14, sampler, seed=3)
    g = fliplab.got(p, rule)
    out = _got_cli(cli, p, rule)
    assert stdout_field(out, "total badness") == g.total_text
    assert float(g.total_text) == g.total
    # the same polygon from the program's own sampler: the same total
    out2 = cli.run("got", "--rule", rule, "--random", 14, "--sampler", sampler, "--seed", 3).stdout
    assert stdout_field(out2, "total badness") == g.total_text
    assert ("certified: unique" in out) == g.certified_unique


def _triangulations(idx):
    """Every triangulation of the convex polygon idx (a list of vertex ids)."""
    if len(idx) < 3:
        yield []
        return
    a, b = idx[0], idx[-1]
    for k in range(1, len(idx) - 1):
        for left in _triangulations(idx[:k + 1]):
            for right in _triangulations(idx[k:]):
                yield left + [(a, idx[k], b)] + right


def test_got_brute_force():
    for seed in range(4):
        p = fliplab.samplers.convex_polygons(8, 1, seed=seed)[0]
        g = fliplab.got(p, "P_1")
        best = min(sum(fliplab.badness(p[np.array(t)], "P"))
                   for t in _triangulations(list(range(8))))
        assert abs(g.total - best) <= 1e-12 * best
        assert len(g.triangles) == 6 and np.isclose(g.badness.sum(), g.total)
    cw = p[::-1].copy()                                 # clockwise: reversed keeping vertex 0?
    gc = fliplab.got(cw, "P_1")
    assert gc.reversed and np.isclose(gc.total, fliplab.got(p, "P_1").total, rtol=1e-12)
    with pytest.raises(ValueError, match="triangle-based"):
        fliplab.got(p, "DT")
    with pytest.raises(ValueError):
        fliplab.got(np.array([[0, 0], [1, 1], [1, 0], [0, 1]], dtype=float), "P_1")   # crossing


def test_flipgraph_convex_pentagon_matches_table34():
    pent = fliplab.samplers.pentagons(200, seed=9)
    t = fliplab.table34(200, seed=9, rules=["P_1"])
    one = two = 0
    for v in pent:
        g = fliplab.flipgraph(v, "P_1")
        assert len(g.nodes) == 5 and len(g.edges) + len(g.ties) == 5 and len(g.ties) == 0
        one += len(g.sinks) == 1
        two += len(g.sinks) == 2
    # docs/classification.md: types I and II have one sink, type III two
    assert one == int(t["type_I"][0] + t["type_II"][0]) and two == int(t["type_III"][0])


def test_flipgraph_theorems(cli):
    sites = fliplab.samplers.site_sets(7, 5, "disc", seed=3)
    for s in sites:
        d = fliplab.flipgraph(s, "DT")
        assert len(d.sinks) == 1 and d.sinks[0] == d.dt and not d.cycle
        g = fliplab.flipgraph(s, "P_1")
        assert not g.cycle and len(g.sinks) >= 1
        assert g.got in g.sinks.tolist()                  # joint 1: the GOT is a sink
        assert g.keys[g.got] == g.keys.min()
        for a, b in g.edges:                              # every flip improves the total
            assert g.keys[b] <= g.keys[a] * (1 + 1e-9)
    # the program's flipgraph on the same sites: the same counts, sinks and GOT
    for rule in ("P_1", "DT", "-alpha_inf"):
        path = cli.file("sites.csv")
        write_points(path, sites[1])
        out = cli.run("flipgraph", "--points", path, "--rule", rule).stdout
        g = fliplab.flipgraph(sites[1], rule)
        assert int(stdout_field(out, "triangulations")) == len(g.nodes)
        assert int(stdout_field(out, "flip edges")) == len(g.edges) + len(g.ties)
        assert int(stdout_field(out, "sinks")) == len(g.sinks)
        assert int(stdout_field(out, "sources")) == len(g.sources)
        assert (stdout_field(out, "ties") == "no") == (len(g.ties) == 0)
        sink_lines = [l.split(": ", 1)[1] for l in out.splitlines() if l.startswith("  sink T")]
        for u, text in zip(g.sinks, sink_lines):
            assert text == " ".join("(%d,%d,%d)" % tuple(t + 1) for t in g.nodes[u])
        if g.got is not None:
            assert stdout_field(out, "GOT").split()[0] == "%.17g" % g.got_total


def test_flipgraph_networkx():
    nx = pytest.importorskip("networkx")
    g = fliplab.flipgraph(fliplab.samplers.site_sets(6, 1, "convex", seed=1)[0], "P_1")
    G = g.to_networkx()
    assert G.number_of_nodes() == 14                    # Catalan(4)
    assert sorted(u for u in G if G.out_degree(u) == 0) == sorted(g.sinks.tolist())
