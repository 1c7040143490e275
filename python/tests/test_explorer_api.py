"""test_explorer_api.py: the explorer's server (fliplab.explorer) against the
library called directly.

- /api/graph: the nodes, directed arcs, ties, sinks, DT, GOT and counts equal
  fliplab.flipgraph's on the same sites and rule; each flip's decision and
  joint values equal fliplab.decide's on its quadrilateral; each triangle's
  badness equals fliplab.badness's; each flip joins the two triangulations
  that differ exactly by the quadrilateral's diagonals; the page's step (the
  first directed flip out of a node) ends at one of the library's sinks.
- /api/lot: the library's lot() of the same points, and compare figures
  counted here by brute force and printed by the program's lot --compare DT.
- /api/lot.bin: decoded here (unpack, numpy over the bytes) it is /api/lot's
  answer and lot()'s arrays exactly; bad requests get the same JSON errors.
- /api/tri (a drag's re-triangulation): lot() of the sites, also with a
  formula (in a child); run in the server without a child otherwise; equal,
  collinear and too many sites refused.
- The /api/graph cache: the same request gets the same bytes from the cache,
  at most GRAPH_CACHE answers are kept, and a time limit is not kept.
- /api/export: the printed command lines run and give the same sinks and
  figures; the CSV reads back bit for bit.
- Refusals: malformed, oversized, unknown and hostile requests get a 4xx
  and one line of JSON naming the problem, never a traceback; the time
  limit answers 503 and the server goes on; it binds 127.0.0.1 only.
- Triangulation.compare (lot_compare) against sets of edges and triangles.
"""
import http.client
import json
import math
import os
import shlex
import subprocess
import threading

import numpy as np
import pytest

import fliplab
from fliplab import explorer
from conftest import _bin as _bin_rel

def _bin():
    return os.path.abspath(_bin_rel())


NEG_R = "webnegR = -R"       # the test process's own name for -R (define: once per process)
fliplab.define(NEG_R)


def _start(**kw):
    srv = explorer.Server(0, **kw)
    threading.Thread(target=srv.serve_forever, daemon=True).start()
    return srv


@pytest.fixture(scope="module")
def server():
    srv = _start(time_limit=30)
    yield srv
    srv.shutdown()
    srv.server_close()


def request(srv, method, path, body=None, raw=None, headers=None):
    """(status, parsed JSON or text (None when binary), raw body) of one request."""
    c = http.client.HTTPConnection("127.0.0.1", srv.server_address[1], timeout=60)
    data = raw if raw is not None else None if body is None else json.dumps(body).encode()
    c.request(method, path, body=data, headers=headers or {})
    r = c.getresponse()
    text = r.read()
    c.close()
    if r.getheader("Content-Type") == explorer.BINARY:
        return r.status, None, text
    try:
        return r.status, json.loads(text), text
    except ValueError:
        return r.status, text.decode(), text


def post(srv, path, body):
    return request(srv, "POST", path, body)


SETS = [
    (explorer.PRESETS["fig38"]["sites"], "negR_1", "negR = -R", "webnegR_1"),
    (explorer.PRESETS["fig38-five"]["sites"], "negR_1", "negR = -R", "webnegR_1"),
] + [(s.tolist(), r, None, r) for s, r in zip(
    fliplab.samplers.site_sets(7, 6, "disc", seed=3),
    ["DT", "P_1", "-alpha_inf", "ES:hexagon", "R_3", "ES:ellipse:2 1 0.5"])]


@pytest.mark.parametrize("sites,rule,define,local", SETS)
def test_graph_is_the_librarys(server, sites, rule, define, local):
    st, g, _ = post(server, "/api/graph", {"sites": sites, "rule": rule, "define": define})
    assert st == 200, g
    p = np.array(sites)
    f = fliplab.flipgraph(p, local)
    tri = [tuple(t["v"]) for t in g["triangles"]]
    nodes = [sorted(tri[t] for t in n) for n in g["nodes"]]
    assert nodes == [sorted(map(tuple, n)) for n in f.nodes.tolist()]
    arcs = {(fl["bd"], fl["ac"]) if fl["decision"] == "AC" else (fl["ac"], fl["bd"])
            for fl in g["flips"] if fl["decision"] != "either"}
    assert arcs == set(map(tuple, f.edges.tolist()))
    ties = {(fl["ac"], fl["bd"]) for fl in g["flips"] if fl["decision"] == "either"}
    assert ties == set(map(tuple, f.ties.tolist()))
    assert g["sinks"] == f.sinks.tolist() and g["dt"] == f.dt and g["got"] == f.got
    c = g["census"]
    assert (c["triangulations"], c["sinks"], c["ties"]) == (len(f.nodes), len(f.sinks),
                                                            len(f.ties))
    assert c["type"] == ("tie" if len(f.ties) else ["no sink", "one sink"][len(f.sinks)]
                         if len(f.sinks) < 2 else "several sinks")
    quads = np.array([fl["quad"] for fl in g["flips"]])
    dec, vac, vbd = fliplab.decide(p[quads], local, values=True)
    assert [fl["decision"] for fl in g["flips"]] == [["AC", "BD", "either"][d] for d in dec]
    for fl, a, b in zip(g["flips"], vac, vbd):
        assert fl["ac_value"] == (a if math.isfinite(a) else None)
        assert fl["bd_value"] == (b if math.isfinite(b) else None)
    r = fliplab.Rule(local)
    if r.is_triangle:
        assert [t["badness"] for t in g["triangles"]] == fliplab.badness(p[np.array(tri)],
                                                                         r).tolist()
    else:
        assert all(t["badness"] is None for t in g["triangles"])


def test_flips_join_their_diagonals(server):
    sites = fliplab.samplers.site_sets(8, 1, "disc", seed=5)[0].tolist()
    st, g, _ = post(server, "/api/graph", {"sites": sites, "rule": "P_1"})
    assert st == 200
    tri = [tuple(t["v"]) for t in g["triangles"]]
    node = [{tri[t] for t in n} for n in g["nodes"]]
    for fl in g["flips"]:
        a, b, c, d = fl["quad"]
        ac = {tuple(sorted(x)) for x in ((a, b, c), (a, c, d))}
        bd = {tuple(sorted(x)) for x in ((a, b, d), (b, c, d))}
        assert ac <= node[fl["ac"]] and bd <= node[fl["bd"]]
        assert node[fl["ac"]] - ac == node[fl["bd"]] - bd


def test_steps_end_at_a_sink(server):
    """The page's step: the first directed flip out of the node, in the flips' order."""
    sites = explorer.PRESETS["fig38"]["sites"]
    st, g, _ = post(server, "/api/graph", {"sites": sites, "rule": "negR_1",
                                           "define": "negR = -R"})
    assert st == 200
    for start in range(len(g["nodes"])):
        u = start
        for _ in range(len(g["nodes"])):
            out = [fl["ac"] if fl["decision"] == "AC" else fl["bd"] for fl in g["flips"]
                   if (fl["decision"] == "AC" and fl["bd"] == u)
                   or (fl["decision"] == "BD" and fl["ac"] == u)]
            if not out:
                break
            u = out[0]
        assert u in g["sinks"]


def test_fig38_preset_has_two_sinks(server):
    """The preset of docs/explorer.md: two LOTs under -R_1, one under R_1, the DT."""
    pre = explorer.PRESETS["fig38"]
    st, g, _ = post(server, "/api/graph", pre)
    assert st == 200 and g["census"]["sinks"] == 2 and g["census"]["ties"] == 0
    st, h, _ = post(server, "/api/graph", {"sites": pre["sites"], "rule": "R_1"})
    assert h["sinks"] == [h["dt"]]


def _diff(a, b):
    """lot_diff counted here: edges and triangles as sets."""
    def edges(t):
        return {tuple(sorted(e)) for x in t for e in ((x[0], x[1]), (x[1], x[2]), (x[0], x[2]))}
    ta, tb = {tuple(sorted(x)) for x in a}, {tuple(sorted(x)) for x in b}
    return {"edges_a": len(edges(a)), "edges_b": len(edges(b)),
            "edges_common": len(edges(a) & edges(b)), "triangles_a": len(ta),
            "triangles_b": len(tb), "triangles_common": len(ta & tb)}


def test_lot_is_the_librarys(server, cli):
    st, r, _ = post(server, "/api/lot", {"random": {"n": 3000, "sampler": "disc", "seed": 4},
                                         "rule": "ES:square"})
    assert st == 200, r
    p = fliplab.samplers.points(3000, "disc", 4)
    t, d = fliplab.lot(p, "ES:square"), fliplab.lot(p, "DT")
    assert r["points"] == p.tolist()
    assert r["triangles"] == t.triangles.tolist() and r["dt"] == d.triangles.tolist()
    assert r["compare"] == _diff(t.triangles, d.triangles) == t.compare(d)
    st, e, _ = post(server, "/api/export", {"random": {"n": 3000, "sampler": "disc", "seed": 4},
                                            "rule": "ES:square"})
    out = subprocess.run([_bin()] + shlex.split(e["commands"][0])[1:], capture_output=True,
                         text=True, check=True).stdout
    c = r["compare"]
    assert ("compare DT: %d of %d edges and %d of %d triangles shared"
            % (c["edges_common"], c["edges_a"], c["triangles_common"], c["triangles_a"])) in out


def test_export_commands_reproduce_the_view(server, tmp_path):
    pre = explorer.PRESETS["fig38"]
    st, e, _ = post(server, "/api/export", pre)
    assert st == 200
    (tmp_path / "sites.csv").write_text(e["csv"])
    assert np.array_equal(np.loadtxt(tmp_path / "sites.csv", delimiter=",", skiprows=1),
                          np.array(pre["sites"], dtype=float))
    st, g, _ = post(server, "/api/graph", pre)
    tri = [tuple(t["v"]) for t in g["triangles"]]
    want = sorted(sorted("(%d,%d,%d)" % tuple(v + 1 for v in tri[t]) for t in g["nodes"][s])
                  for s in g["sinks"])
    flip = subprocess.run([_bin()] + shlex.split(e["commands"][0])[1:], cwd=tmp_path,
                          capture_output=True, text=True, check=True).stdout
    got = sorted(sorted(line.split(":", 1)[1].split()) for line in flip.splitlines()
                 if line.startswith("  sink T"))
    assert got == want
    lot = subprocess.run([_bin()] + shlex.split(e["commands"][1])[1:], cwd=tmp_path,
                         capture_output=True, text=True, check=True).stdout
    st, r, _ = post(server, "/api/lot", pre)
    c = r["compare"]
    assert "compare DT: %d of %d edges" % (c["edges_common"], c["edges_a"]) in lot
    assert sorted(tuple(sorted(t)) for t in r["triangles"]) in [sorted(tri[t] for t in g["nodes"][s])
                                                   for s in g["sinks"]]


BAD = [
    ({"sites": [[0, 0], [1, 0]], "rule": "DT"}, "sites"),
    ({"sites": [[i, i * i] for i in range(13)], "rule": "DT"}, "3 to 12"),
    ({"sites": [[0, 0], [1, 1], [2, 2]], "rule": "DT"}, "collinear"),
    ({"sites": [[0, 0], [1, 0], [0, 1], [1, 0]], "rule": "DT"}, "equal"),
    ({"sites": [[0, 0], [1, 0], [0, "x"]], "rule": "DT"}, "site 3"),
    ({"sites": [[0, 0], [1, 0], [0, 1]], "rule": "Q_1"}, "unknown measure"),
    ({"sites": [[0, 0], [1, 0], [0, 1]], "rule": "x_1", "define": "x = sin("}, "syntax"),
    ({"sites": [[0, 0], [1, 0], [0, 1]], "rule": "ES:poly:0 0;1"}, "shape"),
    ({"sites": [[0, 0], [1, 0], [0, 1]], "rule": 3}, "rule"),
    ({"sites": "nope", "rule": "DT"}, "sites"),
]


@pytest.mark.parametrize("body,word", BAD)
def test_bad_requests_one_line(server, body, word):
    st, r, raw = post(server, "/api/graph", body)
    assert 400 <= st < 500 and word in r["error"], r
    assert raw.count(b"\n") <= 1 and b"Traceback" not in raw


def test_hostile_requests(server):
    port = server.server_address[1]
    cases = [
        request(server, "POST", "/api/graph", raw=b"{bad"),
        request(server, "POST", "/api/graph", raw=b"[1, 2]"),
        request(server, "POST", "/api/graph", raw=b"\xff\xfe"),
        request(server, "POST", "/api/graph", raw=b"NaN"),
        request(server, "POST", "/api/graph", {"sites": [[0, 0], [1, 0], [float("nan"), 1]],
                                               "rule": "DT"}),
        request(server, "POST", "/api/graph", raw=b"x" * (explorer.BODY_MAX + 1)),
        request(server, "POST", "/api/nothing", {}),
        request(server, "GET", "/../../etc/passwd"),
        request(server, "PUT", "/api/graph", {}),
        request(server, "POST", "/api/lot", {"random": {"n": 10 ** 9}, "rule": "DT"}),
        request(server, "POST", "/api/sample", {"kind": "nope", "n": 5}),
        request(server, "POST", "/api/sample", {"kind": "disc", "n": True}),
    ]
    for st, r, raw in cases:
        assert 400 <= st < 500 and isinstance(r, dict) and r["error"], (st, raw)
        assert raw.count(b"\n") <= 1 and b"Traceback" not in raw
    assert [c[0] for c in cases][5:9] == [413, 404, 404, 405]
    c = http.client.HTTPConnection("127.0.0.1", port, timeout=10)   # no Content-Length
    c.putrequest("POST", "/api/graph")
    c.endheaders()
    assert c.getresponse().status == 411
    c.close()
    st, r, _ = request(server, "GET", "/api/names")        # still answering
    assert st == 200 and r["limits"]["sites_max"] == explorer.SITES_MAX


def test_too_large_offers_the_lot(server):
    """A convex 12-gon has Catalan(10) = 16796 triangulations: over NODES_MAX."""
    th = 2 * np.pi * np.arange(12) / 12
    st, g, _ = post(server, "/api/graph", {"sites": np.c_[np.cos(th), np.sin(th)].tolist(),
                                           "rule": "DT"})
    assert st == 200 and g["too_large"] and g["more_than"] == explorer.NODES_MAX
    assert g["triangulations"] is None and "LOT" in g["message"]


def test_capped_count_decides_too_large(server):
    """The server's answer says "too large" exactly when fliplab.flipgraph
    finds more than NODES_MAX triangulations: sets on both sides of the cap
    (convex 11-gon 4862, convex 12-gon 16796, 12 random sites) and the cap
    moved to a set's own count and one below it."""
    th = 2 * np.pi * np.arange(12) / 12
    sets = [np.c_[np.cos(th[:11] * 12 / 11), np.sin(th[:11] * 12 / 11)],
            np.c_[np.cos(th), np.sin(th)], fliplab.samplers.points(12, "uniform", 3)]
    for p in sets:
        n = len(fliplab.flipgraph(p, "DT").nodes)
        st, g, _ = post(server, "/api/graph", {"sites": p.tolist(), "rule": "DT"})
        assert st == 200 and bool(g.get("too_large")) == (n > explorer.NODES_MAX)
        if n <= explorer.NODES_MAX:
            assert g["census"]["triangulations"] == n
        for cap in (n - 1, n, n + 1):
            assert fliplab.count_triangulations(p, cap) == (None if n > cap else n)
    with pytest.raises(ValueError, match="at_most"):
        fliplab.count_triangulations(sets[0], 0)
    with pytest.raises(ValueError, match="equal"):
        fliplab.count_triangulations([[0, 0], [1, 0], [0, 0]], 10)


def test_time_limit():
    srv = _start(time_limit=0.02)
    try:        # a convex 11-gon: 4862 triangulations, under NODES_MAX, all enumerated
        th = 2 * np.pi * np.arange(11) / 11
        st, r, raw = post(srv, "/api/graph", {"sites": np.c_[np.cos(th), np.sin(th)].tolist(),
                                              "rule": "P_1"})
        assert st == 503 and "time limit" in r["error"] and raw.count(b"\n") == 0
        srv.time_limit = 30
        st, r, _ = post(srv, "/api/graph", {"sites": [[0, 0], [1, 0], [0, 1]], "rule": "DT"})
        assert st == 200 and r["census"]["triangulations"] == 1
    finally:
        srv.shutdown()
        srv.server_close()


def test_loopback_only(server):
    assert server.server_address[0] == "127.0.0.1"
    p = subprocess.run(["ss", "-ltn"], capture_output=True, text=True)
    if p.returncode == 0:
        port = ":%d " % server.server_address[1]
        lines = [x for x in p.stdout.splitlines() if port in x + " "]
        assert lines and all("127.0.0.1" + port.strip() in x for x in lines)


def test_page_and_names(server):
    st, html, _ = request(server, "GET", "/")
    assert st == 200 and "explorer.js" in html and "http" not in html.replace(
        "http://www.w3.org", "")
    for f in ("/explorer.js", "/explorer.css"):
        assert request(server, "GET", f)[0] == 200
    st, n, _ = request(server, "GET", "/api/names")
    assert [m["name"] for m in n["measures"]] == [m["name"] for m in fliplab.measures()]
    assert all(fliplab.Rule(s).name == s for s in n["shapes"])
    assert len(n["scale"]) == 64 and n["scale"][0] != n["scale"][-1]


def test_sample_is_the_samplers(server):
    st, r, _ = post(server, "/api/sample", {"kind": "convex", "n": 7, "seed": 9})
    assert r["sites"] == fliplab.samplers.site_sets(7, 1, "convex", seed=9)[0].tolist()
    st, r, _ = post(server, "/api/sample", {"kind": "grid", "n": 9, "seed": 1})
    assert r["sites"] == fliplab.samplers.points(9, "grid", 1).tolist()


def test_compare_counts_shared_edges_and_triangles():
    """lot_compare's radix sorts against sets: 500 points (keys of 9 bits a
    vertex), 3000 and 20000 (15 bits: several passes of the sort)."""
    for seed, n in ((1, 500), (2, 500), (3, 3000), (4, 20000)):
        p = fliplab.samplers.points(n, "uniform", seed)
        a, b = fliplab.lot(p, "P_1"), fliplab.lot(p, "DT")
        assert a.compare(b) == _diff(a.triangles, b.triangles)
        assert b.compare(b)["triangles_common"] == len(b.triangles)
    with pytest.raises(ValueError):
        a.compare(fliplab.lot(fliplab.samplers.points(50, "uniform", 1), "DT"))


def test_es_triangles_carry_their_circumscribing_shape(server):
    """Each triangle's outline under ES:SHAPE passes through its three sites,
    and equals Rule.circumscribe's; a corner's rounding shape names the corner."""
    sites = fliplab.samplers.site_sets(6, 1, "disc", seed=2)[0]
    for rule in ("ES:hexagon", "ES:square", "ES:ellipse:2 1 0.5"):
        st, g, _ = post(server, "/api/graph", {"sites": sites.tolist(), "rule": rule})
        assert st == 200
        r = fliplab.Rule(rule)
        for t in g["triangles"]:
            outline, corner = r.circumscribe(sites[t["v"]], points=96)
            if outline is None:
                assert t["shape"] == {"corner": corner}
                continue
            assert t["shape"]["outline"] == outline.tolist()
            if "ellipse" not in rule:   # a polygon: each site on a side (to rounding)
                o = np.array(outline)
                for q in sites[t["v"]]:
                    e = np.roll(o, -1, axis=0) - o
                    d = (e[:, 0] * (q[1] - o[:, 1]) - e[:, 1] * (q[0] - o[:, 0])) \
                        / np.hypot(e[:, 0], e[:, 1])
                    assert abs(d.min()) < 1e-9
    with pytest.raises(ValueError):
        fliplab.Rule("DT").circumscribe([[0, 0], [1, 0], [0, 1]])
    with pytest.raises(ValueError):
        fliplab.Rule("ES:square").circumscribe([[0, 0], [1, 1], [2, 2]])


def unpack(raw):
    """pack_arrays' message read back: the header and numpy arrays over the bytes."""
    n = int.from_bytes(raw[:4], "little")
    assert (4 + n) % 8 == 0
    head = json.loads(raw[4:4 + n].decode())
    for a in head["arrays"]:
        assert a["offset"] % 8 == 0
        count = int(np.prod(a["shape"]))
        head[a["name"]] = np.frombuffer(raw, dtype=a["dtype"], count=count,
                                        offset=4 + n + a["offset"]).reshape(a["shape"])
    return head


@pytest.mark.parametrize("body,local", [
    ({"random": {"n": 3000, "sampler": "disc", "seed": 4}, "rule": "P_1"}, "P_1"),
    ({"random": {"n": 500, "sampler": "grid", "seed": 2}, "rule": "ES:hexagon"}, "ES:hexagon"),
    (dict(explorer.PRESETS["fig38"]), "webnegR_1")])
def test_lot_bin_is_the_librarys(server, body, local):
    st, r, raw = post(server, "/api/lot.bin", body)
    assert st == 200, r
    m = unpack(raw)
    if "random" in body:
        p = fliplab.samplers.points(body["random"]["n"], body["random"]["sampler"],
                                    body["random"]["seed"])
    else:
        p = np.array(body["sites"], dtype=float)
    t, d = fliplab.lot(p, local), fliplab.lot(p, "DT")
    assert np.array_equal(m["points"], p) and m["points"].dtype == np.float64
    assert np.array_equal(m["triangles"], t.triangles) and np.array_equal(m["dt"], d.triangles)
    assert np.array_equal(m["hull"], d.hull) and np.array_equal(m["hull"], t.hull)
    assert m["compare"] == t.compare(d) and m["status"] == t.status and m["flips"] == t.flips
    if t.rule.is_triangle:
        assert np.array_equal(m["badness"], t.badness, equal_nan=True)
    else:
        assert "badness" not in m
    st, j, _ = post(server, "/api/lot", body)          # the JSON answer says the same
    assert j["triangles"] == m["triangles"].tolist() and j["compare"] == m["compare"]


def test_lot_bin_refusals(server):
    for body, word in (({"random": {"n": 10 ** 9}, "rule": "DT"}, "random"),
                       ({"random": {"n": 50, "sampler": "nope"}, "rule": "DT"}, "nope"),
                       ({"sites": [[0, 0], [1, 1], [2, 2]], "rule": "DT"}, "collinear"),
                       ({"sites": [[0, 0], [1, 0], [0, 1]], "rule": "Q_1"}, "measure"),
                       ({"random": "x", "rule": "DT"}, "random")):
        st, r, raw = post(server, "/api/lot.bin", body)
        assert 400 <= st < 500 and word in r["error"], (st, raw)
    st, r, _ = request(server, "POST", "/api/lot.bin", raw=b"{bad")
    assert st == 400 and "JSON" in r["error"]


@pytest.mark.parametrize("sites,rule,define,local", SETS[:2] + SETS[3:6])
def test_tri_is_the_librarys(server, sites, rule, define, local):
    st, r, _ = post(server, "/api/tri", {"sites": sites, "rule": rule, "define": define})
    assert st == 200, r
    t = fliplab.lot(np.array(sites), local)
    assert r["triangles"] == t.triangles.tolist() and r["status"] == t.status
    if t.rule.is_triangle:
        assert r["badness"] == t.badness.tolist()


def test_tri_runs_in_the_server(server, monkeypatch):
    """Without a formula /api/tri forks no child (bounded work); with one it does."""
    def no_child(*a):
        raise AssertionError("a child for a bounded request")
    monkeypatch.setattr(explorer, "run_limited", no_child)
    th = 2 * np.pi * np.arange(12) / 12
    st, r, _ = post(server, "/api/tri", {"sites": np.c_[np.cos(th), np.sin(th)].tolist(),
                                         "rule": "P_1"})
    assert st == 200 and len(r["triangles"]) == 10
    monkeypatch.undo()
    st, r, _ = post(server, "/api/tri", dict(explorer.PRESETS["fig38"]))
    assert st == 200 and len(r["triangles"]) == 6


def test_tri_refusals(server):
    for sites, word in (([[0, 0], [1, 0], [0, 1], [1, 0]], "site 4 equals site 2"),
                        ([[0, 0], [1, 1], [2, 2]], "collinear"),
                        ([[i, i * i] for i in range(13)], "3 to 12"),
                        ([[0, 0], [1, 0], [0, float("inf")]], "site 3")):
        st, r, raw = post(server, "/api/tri", {"sites": sites, "rule": "P_1"})
        assert 400 <= st < 500 and word in r["error"], (st, raw)
    st, r, _ = post(server, "/api/tri", {"sites": [[0, 0], [1, 0], [0, 1]], "rule": "nope"})
    assert st == 400 and r["error"]


def test_graph_cache():
    srv = _start(time_limit=30)
    try:
        body = {"sites": explorer.PRESETS["fig38"]["sites"], "rule": "P_1"}
        st, a, raw = post(srv, "/api/graph", body)
        assert st == 200 and len(srv.cache) == 1
        st, b, raw2 = post(srv, "/api/graph", body)
        assert raw2 == raw and len(srv.cache) == 1
        g = fliplab.flipgraph(np.array(body["sites"]), "P_1")
        assert b["census"]["triangulations"] == len(g.nodes) and b["sinks"] == g.sinks.tolist()
        for k in range(explorer.GRAPH_CACHE + 3):          # the oldest go first
            post(srv, "/api/graph", {"sites": [[0, 0], [1, 0], [0, 1 + k]], "rule": "DT"})
        assert len(srv.cache) == explorer.GRAPH_CACHE
        assert json.dumps([body["sites"], "P_1", None]) not in srv.cache
        srv.time_limit = 0.02
        th = 2 * np.pi * np.arange(11) / 11      # 4862 triangulations, all drawn
        big = {"sites": np.c_[np.cos(th), np.sin(th)].tolist(), "rule": "P_1"}
        assert post(srv, "/api/graph", big)[0] == 503
        srv.time_limit = 30
        st, r, _ = post(srv, "/api/graph", big)
        assert st == 200 and r["census"]["triangulations"] == 4862
    finally:
        srv.shutdown()
        srv.server_close()


def test_keep_alive_after_a_refusal(server):
    """One connection: a refused request's unread body is not taken for the next
    request (the server closes it), and good requests share the connection."""
    c = http.client.HTTPConnection("127.0.0.1", server.server_address[1], timeout=10)
    body = json.dumps({"sites": [[0, 0], [1, 0], [0, 1]], "rule": "DT"})
    for _ in range(3):
        c.request("POST", "/api/tri", body=body)
        r = c.getresponse()
        assert r.status == 200 and json.loads(r.read())["triangles"] == [[0, 1, 2]]
    c.request("POST", "/api/nothing", body="GET /api/names HTTP/1.1\r\n\r\n")
    r = c.getresponse()
    assert r.status == 404 and r.getheader("Connection") == "close"
    r.read()
    c.close()
