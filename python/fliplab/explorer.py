"""explorer.py: the flip-graph explorer, a page served on the loopback address
over this package (docs/explorer.md).

    /usr/bin/python3 -m fliplab.explorer [--port P] [--time-limit S]

The page (web/: index.html, explorer.js, explorer.css) draws; every decision,
badness, flip, sink and count it shows comes from the library through this
server, which answers JSON:

    GET  /api/names    the rule forms, measures, joints, shapes, samplers, presets, limits
    POST /api/graph    {sites, rule[, define]}: the flip graph, its flips with the
                       rule's decisions and joint values, each triangle's badness,
                       the census counts of the set and a layout
    POST /api/tri      {sites, rule[, define]}: the rule's LOT of the sites alone
                       (a drag's re-triangulation: no flip graph, no child
                       process unless a formula is defined)
    POST /api/lot      {sites | random: {n, sampler, seed}, rule[, define]}: LOT
                       and DT with lot --compare DT's figures
    POST /api/lot.bin  the same, as one binary message (pack_arrays): typed arrays
    POST /api/sample   {kind, n, seed}: sites from a sampler
    POST /api/export   {sites | random, rule[, define]}: the sites as CSV and the
                       fliplab command lines that reproduce the view

Each computing request of unbounded work runs in a child process forked for
it: the time limit kills it (503), a formula's define() dies with it (names
stay free), and a crash in it cannot take the server down.  /api/tri without
a formula is bounded work (at most 12 sites and DRAG_FLIPS flips) and runs in
the server; /api/graph answers are kept in a small LRU cache.  Bad input gets
a 4xx with one line of JSON, {"error": "..."}; the server binds 127.0.0.1 only.
"""
from __future__ import annotations

import argparse
import collections
import json
import math
import os
import select
import shlex
import signal
import sys
import threading
import time
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from typing import Any, Callable

import numpy as np

SITES_MIN, SITES_MAX = 3, 12      # the flip graph's sites
LOT_MAX = 100000                  # random points of the LOT view
BODY_MAX = 65536                  # bytes of a request body
NODES_MAX = 5000                  # triangulations drawn; more: the LOT only
TIME_LIMIT = 10.0                 # seconds per computing request
DRAG_FLIPS = 10000                # flip budget of /api/tri (a LOT of 12 sites: about 20)
GRAPH_CACHE = 32                  # /api/graph answers kept (LRU)
PAGES = {"/": ("index.html", "text/html"), "/index.html": ("index.html", "text/html"),
         "/explorer.js": ("explorer.js", "text/javascript"),
         "/explorer.css": ("explorer.css", "text/css")}
# Shapes the page suggests (any ES:SPEC of docs/emptyshape.md is accepted).
SHAPE_EXAMPLES = ("square", "diamond", "triangle", "hexagon", "octagon", "ngon:5",
                  "ellipse:2 1", "ellipse:2 1 0.5", "poly:0 0;2 0;1 1")
# Thesis figure 3.8 with six sites: a square, a site inside as in the figure and a
# second one; -R_1 (the formula measure negR = -R) has two sinks, R_1 one, DT's.
PRESETS = {
    "fig38": {"sites": [[0, 0], [1, 0], [1, 1], [0, 1], [0.45, 0.4], [0.62, 0.66]],
              "rule": "negR_1", "define": "negR = -R"},
    "fig38-five": {"sites": [[0, 0], [1, 0], [1, 1], [0, 1], [0.45, 0.4]],
                   "rule": "negR_1", "define": "negR = -R"},
}


class Refusal(Exception):
    """A request the explorer refuses: an HTTP status and one line."""

    def __init__(self, status: int, message: str) -> None:
        super().__init__(message)
        self.status = status


def web_dir() -> str:
    """The page's folder: installed beside the package (fliplab/web), else the
    source tree's web/."""
    here = os.path.dirname(os.path.abspath(__file__))
    for d in (os.path.join(here, "web"), os.path.join(here, "..", "..", "web")):
        if os.path.isfile(os.path.join(d, "index.html")):
            return os.path.normpath(d)
    raise RuntimeError("explorer: the page (web/index.html) is not installed beside %s" % here)


# ---- reading requests ------------------------------------------------------

def _field(body: dict, key: str, kind: type, default: Any = None) -> Any:
    v = body.get(key, default)
    if v is None or (kind is int and isinstance(v, bool)) or not isinstance(v, kind):
        raise Refusal(400, "%s: expected %s" % (key, "an integer" if kind is int else
                                                  "a string" if kind is str else kind.__name__))
    return v


def _sites(v: Any, lo: int = SITES_MIN, hi: int = SITES_MAX) -> list[list[float]]:
    """The sites of a request: lo..hi pairs of finite numbers."""
    if not isinstance(v, list):
        raise Refusal(400, "sites: expected a list of [x, y] pairs")
    if not lo <= len(v) <= hi:
        raise Refusal(400, "sites: %d given; the flip graph takes %d to %d" % (len(v), lo, hi))
    out = []
    for i, p in enumerate(v):
        if (not isinstance(p, list) or len(p) != 2 or
                not all(isinstance(x, (int, float)) and not isinstance(x, bool) for x in p)
                or not all(math.isfinite(x) for x in p)):
            raise Refusal(400, "sites: site %d is not a pair of finite numbers" % (i + 1))
        out.append([float(p[0]), float(p[1])])
    return out


def _distinct(p: list[list[float]]) -> None:
    """Refuse two equal sites (lot() would merge them silently)."""
    seen: dict[tuple[float, float], int] = {}
    for i, q in enumerate(p):
        j = seen.setdefault((q[0], q[1]), i)
        if j != i:
            raise Refusal(400, "sites: site %d equals site %d" % (i + 1, j + 1))


def _random(v: Any) -> tuple[int, str, int]:
    if not isinstance(v, dict):
        raise Refusal(400, "random: expected {n, sampler, seed}")
    n = _field(v, "n", int)
    if not 3 <= n <= LOT_MAX:
        raise Refusal(400, "random: n = %d; the LOT view takes 3 to %d points" % (n, LOT_MAX))
    seed = _field(v, "seed", int, 1)
    if not 0 <= seed < 2 ** 64:
        raise Refusal(400, "random: seed out of [0, 2^64)")
    return n, _field(v, "sampler", str, "uniform"), seed


def _rule(body: dict) -> Any:
    """The request's rule, after its formula (in the child: define() is per process)."""
    import fliplab
    d = body.get("define")
    if d not in (None, ""):
        fliplab.define(_field(body, "define", str))
    return fliplab.Rule(_field(body, "rule", str))


def _num(x: float) -> float | None:
    """A number for JSON: None for NaN and the infinities."""
    x = float(x)
    return x if math.isfinite(x) else None


# ---- the flip graph --------------------------------------------------------

def _layout(N: int, adj: list[list[int]], sinks: list[int]) -> list[list[float]]:
    """Each node's place in [0, 1]^2: rows by flip distance to the nearest
    sink (breadth-first, sinks at the bottom; node 0 when there is none),
    each row ordered by the mean place of its neighbours in the row below.
    O(N + flips)."""
    dist = [-1] * N
    front = list(sinks) or [0]
    for u in front:
        dist[u] = 0
    rows = [front]
    while rows[-1]:
        nxt = []
        for u in rows[-1]:
            for v in adj[u]:
                if dist[v] < 0:
                    dist[v] = len(rows)
                    nxt.append(v)
        rows.append(nxt)
    rows.pop()
    pos = [[0.5, 0.5] for _ in range(N)]
    for r, row in enumerate(rows):
        if r:
            row.sort(key=lambda u: sum(pos[v][0] for v in adj[u] if dist[v] == r - 1)
                     / max(1, sum(1 for v in adj[u] if dist[v] == r - 1)))
        for k, u in enumerate(row):
            pos[u] = [(k + 0.5) / len(row), 1.0 - (r + 0.5) / len(rows)]
    return pos


def _census(g: Any) -> dict[str, Any]:
    """The set's counts, as the census counts a set: a tie first, else by sinks."""
    ns = len(g.sinks)
    kind = ("tie" if len(g.ties) else "no sink" if ns == 0 else "one sink" if ns == 1
            else "several sinks")
    return {"triangulations": len(g.nodes), "flips": len(g.flips), "directed": len(g.edges),
            "ties": len(g.ties), "sinks": ns, "sources": len(g.sources), "cycle": g.cycle,
            "type": kind, "sink_dt": g.sink_dt, "got_total": _num(g.got_total)
            if g.got_total is not None else None,
            "worst_gap": None if g.worst_gap is None else _num(g.worst_gap)}


def _shape_of(r: Any, tri: Any) -> dict[str, Any]:
    """A triangle's circumscribing shape under ES:SHAPE, to draw (Rule.circumscribe)."""
    outline, corner = r.circumscribe(tri, points=96)
    if outline is None:
        return {"corner": corner}
    return {"outline": outline.tolist()}


def api_graph(body: dict) -> dict[str, Any]:
    """The flip graph of the request's sites under its rule."""
    import fliplab
    p = np.array(_sites(body.get("sites")))
    r = _rule(body)
    # The enumeration stops past NODES_MAX: "too many" at once, not after all
    # of them (a convex 12-gon's 16 796), and no rule work for the count.
    if fliplab.count_triangulations(p, NODES_MAX) is None:
        return {"too_large": True, "triangulations": None, "more_than": NODES_MAX,
                "rule": r.name, "message": "more than %d triangulations: too many to draw; "
                "the LOT only" % NODES_MAX}
    g = fliplab.flipgraph(p, r)
    N = len(g.nodes)
    tris = sorted({tuple(t) for t in g.nodes.reshape(-1, 3).tolist()})
    tid = {t: i for i, t in enumerate(tris)}
    bad = r.badness(p[np.array(tris)]).tolist() if r.is_triangle else [None] * len(tris)
    shape = [_shape_of(r, p[list(t)]) for t in tris] if r.name.startswith("ES:") else None
    q = g.flip_quads
    _, vac, vbd = fliplab.decide(p[q], r, values=True)
    adj: list[list[int]] = [[] for _ in range(N)]
    for a, b, _d in g.flips.tolist():
        adj[a].append(b)
        adj[b].append(a)
    return {"rule": r.name, "triangle_rule": r.is_triangle, "shape": r.name.startswith("ES:"),
            "sites": p.tolist(),
            "triangles": [{"v": list(t), "badness": _num(b) if b is not None else None,
                           "shape": shape[i] if shape else None}
                          for i, (t, b) in enumerate(zip(tris, bad))],
            "nodes": [sorted(tid[tuple(t)] for t in node) for node in g.nodes.tolist()],
            "flips": [{"ac": a, "bd": b, "decision": ["AC", "BD", "either"][d],
                       "quad": quad, "ac_value": _num(x), "bd_value": _num(y)}
                      for (a, b, d), quad, x, y in zip(g.flips.tolist(), q.tolist(),
                                                       vac.tolist(), vbd.tolist())],
            "sinks": g.sinks.tolist(), "sources": g.sources.tolist(),
            "dt": int(g.dt), "got": g.got, "keys": g.keys.tolist() if r.is_triangle else None,
            "census": _census(g), "layout": _layout(N, adj, g.sinks.tolist())}


# ---- LOTs ------------------------------------------------------------------

def api_tri(body: dict) -> dict[str, Any]:
    """The rule's LOT of the sites alone, as a drag redraws it: no flip graph.
    Bounded: at most SITES_MAX sites and DRAG_FLIPS flips (status 'budget
    exhausted' past it), so the server runs it itself (docs/explorer.md)."""
    import fliplab
    sites = _sites(body.get("sites"))
    _distinct(sites)
    r = _rule(body)
    t = fliplab.lot(np.array(sites), r, max_flips=DRAG_FLIPS)
    return {"rule": r.name, "status": t.status, "flips": int(t.flips),
            "triangles": t.triangles.tolist(),
            "badness": [_num(b) for b in t.badness.tolist()] if r.is_triangle else None}


def _lots(body: dict) -> tuple[Any, Any, Any, Any]:
    """(rule, points, LOT(rule), DT) of a LOT request."""
    import fliplab
    r = _rule(body)
    if "random" in body:
        n, kind, seed = _random(body["random"])
        p = fliplab.samplers.points(n, kind, seed)
    else:
        p = np.array(_sites(body.get("sites"), 3, LOT_MAX))
    # DT in a second thread meanwhile (ctypes lets the GIL go; the two runs share
    # nothing but the points, which neither writes): for 10^5 points DT's 0.09 s
    # (at load 1) is hidden behind the LOT's 0.16 s on a second core.
    d: list[Any] = []
    th = threading.Thread(target=lambda: d.append(fliplab.lot(p, "DT")))
    th.start()
    try:
        t = fliplab.lot(p, r)
    finally:
        th.join()
    if not d:
        raise MemoryError("the Delaunay triangulation beside the LOT failed")
    return r, p, t, d[0]


def api_lot(body: dict) -> dict[str, Any]:
    """LOT(rule) of the sites or of random points, beside DT, with the figures
    of lot --compare DT."""
    r, p, t, d = _lots(body)
    out = {"rule": r.name, "status": t.status, "flips": int(t.flips),
           "triangles": t.triangles.tolist(), "dt": d.triangles.tolist(),
           "compare": t.compare(d)}
    out["points"] = p.tolist()
    out["badness"] = [_num(b) for b in t.badness.tolist()] if r.is_triangle else None
    return out


def pack_arrays(head: dict[str, Any], arrays: list[tuple[str, Any]]) -> bytes:
    """head and arrays as one message: a little-endian uint32 n, n bytes of
    JSON (head plus "arrays": [{name, dtype, shape, offset}], padded with
    spaces so that 4 + n is a multiple of 8), then each array's bytes,
    little-endian, at offset (a multiple of 8) from the end of the JSON.
    The page reads them as typed arrays without copying (docs/explorer.md)."""
    meta, parts, at = [], [], 0
    for name, a in arrays:
        kind = "<f8" if np.asarray(a).dtype.kind == "f" else "<i4"
        data = np.ascontiguousarray(a, dtype=kind).tobytes()
        meta.append({"name": name, "dtype": kind, "shape": list(np.shape(a)), "offset": at})
        parts.append(data + b"\0" * (-len(data) % 8))
        at += len(parts[-1])
    j = json.dumps(dict(head, arrays=meta), allow_nan=False, separators=(",", ":")).encode()
    j += b" " * (-(4 + len(j)) % 8)
    return len(j).to_bytes(4, "little") + j + b"".join(parts)


def api_lot_bin(body: dict) -> bytes:
    """api_lot's answer as pack_arrays: float64 points, int32 triangles of the
    LOT and of DT (anticlockwise), the hull's vertices (anticlockwise), float64
    badness (triangle rules)."""
    r, p, t, d = _lots(body)
    arrays = [("points", p), ("triangles", t.triangles), ("dt", d.triangles), ("hull", d.hull)]
    if r.is_triangle:
        arrays.append(("badness", t.badness))
    return pack_arrays({"rule": r.name, "status": t.status, "flips": int(t.flips),
                        "compare": t.compare(d)}, arrays)


# ---- samplers and exports ----------------------------------------------------

def api_sample(body: dict) -> dict[str, Any]:
    """Sites from a site-set sampler (convex, disc, ...) or a point sampler (grid, ...)."""
    import fliplab
    kind = _field(body, "kind", str)
    n = _field(body, "n", int)
    seed = _field(body, "seed", int, 1)
    if not SITES_MIN <= n <= SITES_MAX or not 0 <= seed < 2 ** 64:
        raise Refusal(400, "sample: n must be %d to %d and seed in [0, 2^64)"
                      % (SITES_MIN, SITES_MAX))
    if kind in fliplab.samplers.SITE_SETS:
        p = fliplab.samplers.site_sets(n, 1, kind, seed=seed)[0]
    else:
        p = fliplab.samplers.points(n, kind, seed)
    return {"sites": p.tolist()}


def sites_csv(sites: list[list[float]]) -> str:
    """The sites as the CSV flipgraph --points reads (repr: read back bit for bit)."""
    return "x,y\n" + "".join("%r,%r\n" % (x, y) for x, y in sites)


def api_export(body: dict) -> dict[str, Any]:
    """The command lines that reproduce the view, and the sites' CSV."""
    r = _rule(body)
    pre = "fliplab"
    if body.get("define"):
        pre += " --define " + shlex.quote(body["define"])
    rule = shlex.quote(r.name)
    if "random" in body:
        n, kind, seed = _random(body["random"])
        return {"csv": None, "commands": ["%s lot --random %d --sampler %s --seed %d --rule %s "
                                          "--compare DT" % (pre, n, shlex.quote(kind), seed,
                                                            rule)]}
    sites = _sites(body.get("sites"))
    return {"csv": sites_csv(sites),
            "commands": ["%s flipgraph --rule %s --points sites.csv" % (pre, rule),
                         "%s lot --rule %s --points sites.csv --compare DT" % (pre, rule)]}


def api_names() -> dict[str, Any]:
    """What the page offers: every name checked by the library's parser."""
    import fliplab
    shapes = []
    for s in SHAPE_EXAMPLES:
        try:
            shapes.append(fliplab.Rule("ES:" + s).name)
        except ValueError:
            pass
    buf = fliplab._lib.errbuf()
    scale = []
    for i in range(64):       # the SVGs' badness scale (report_svg_colour), good to bad
        fliplab._lib.lib.report_svg_colour(i / 63, buf, fliplab._lib.ERRLEN)
        scale.append(buf.value.decode())
    return {"measures": fliplab.measures(), "joints": fliplab.joints(), "shapes": shapes,
            "scale": scale,
            "site_samplers": list(fliplab.samplers.SITE_SETS),
            "point_samplers": list(fliplab.samplers.POINT_SETS), "presets": PRESETS,
            "limits": {"sites_min": SITES_MIN, "sites_max": SITES_MAX, "lot_max": LOT_MAX,
                       "nodes_max": NODES_MAX, "body_max": BODY_MAX}}


ROUTES: dict[str, Callable[[dict], Any]] = {
    "/api/graph": api_graph, "/api/tri": api_tri, "/api/lot": api_lot,
    "/api/lot.bin": api_lot_bin, "/api/sample": api_sample, "/api/export": api_export}
BINARY = "application/octet-stream"


# ---- running a request in a child ------------------------------------------

def answer(fn: Callable[[dict], Any], body: dict) -> tuple[int, str, bytes]:
    """fn(body) as (status, content type, body): JSON, or bytes as BINARY;
    a refusal or the library's ValueError as a 4xx line of JSON."""
    try:
        status, out = 200, fn(body)
    except Refusal as e:
        status, out = e.status, {"error": str(e)}
    except (ValueError, TypeError) as e:
        status, out = 400, {"error": str(e).splitlines()[0] if str(e) else "bad request"}
    except MemoryError as e:
        status, out = 503, {"error": "out of memory: %s" % e}
    except Exception as e:
        status, out = 500, {"error": "internal error: %s" % type(e).__name__}
    if isinstance(out, bytes):
        return status, BINARY, out
    return status, "application/json", json.dumps(out, allow_nan=False,
                                                  separators=(",", ":")).encode()


def _child(fn: Callable[[dict], Any], body: dict, w: int) -> None:
    """In the forked child: "status content-type\\n" and the answer on w, then exit."""
    try:
        status, ctype, data = answer(fn, body)
        os.write(w, b"%d %s\n" % (status, ctype.encode()))
        view = memoryview(data)
        while view:
            view = view[os.write(w, view):]
    finally:
        os._exit(0)


def run_limited(fn: Callable[[dict], Any], body: dict,
                limit: float) -> tuple[int, str, bytes]:
    """fn(body) in a forked child within limit seconds: answer()'s triple.
    The child is killed when the limit passes."""
    r, w = os.pipe()
    pid = os.fork()
    if pid == 0:
        os.close(r)
        _child(fn, body, w)
    os.close(w)
    chunks, deadline = [], time.monotonic() + limit
    try:
        while True:
            left = deadline - time.monotonic()
            if left <= 0 or not select.select([r], [], [], left)[0]:
                os.kill(pid, signal.SIGKILL)
                return 503, "application/json", _error(
                    "time limit of %g s passed: try fewer sites" % limit)
            chunk = os.read(r, 1 << 16)
            if not chunk:
                break
            chunks.append(chunk)
    finally:
        os.close(r)
        os.waitpid(pid, 0)
    head, _, data = b"".join(chunks).partition(b"\n")
    if not head:
        return 500, "application/json", _error("internal error: the worker died")
    status, ctype = head.decode().split(" ", 1)
    return int(status), ctype, data


def _error(msg: str) -> bytes:
    return json.dumps({"error": msg}).encode()


# ---- HTTP --------------------------------------------------------------------

class Handler(BaseHTTPRequestHandler):
    """GET the page and /api/names; POST the computing requests."""
    server_version = "fliplab-explorer"
    protocol_version = "HTTP/1.1"     # keep-alive: a drag's requests share one connection
    timeout = 60                      # seconds an idle connection is kept
    disable_nagle_algorithm = True    # headers and body go out at once, not 40 ms apart
    error_content_type = "application/json"
    error_message_format = '{"error": "%(code)d %(message)s"}'

    def log_message(self, format: str, *args: Any) -> None:
        if self.server.verbose:          # type: ignore[attr-defined]
            super().log_message(format, *args)

    def _send(self, status: int, data: bytes, ctype: str = "application/json",
              ms: float | None = None) -> None:
        self.send_response(status)
        if ms is not None:                # the page splits its round trip with it
            self.send_header("Server-Timing", "compute;dur=%.3f" % ms)
        self.send_header("Content-Type", ctype if ctype == BINARY else ctype + "; charset=utf-8")
        self.send_header("Content-Length", str(len(data)))
        self.send_header("Cache-Control", "no-store")
        if self.close_connection:
            self.send_header("Connection", "close")
        self.end_headers()
        self.wfile.write(data)

    def do_GET(self) -> None:
        path = self.path.split("?", 1)[0]
        if path == "/api/names":
            self._send(200, json.dumps(self.server.names).encode())  # type: ignore
        elif path in PAGES:
            name, ctype = PAGES[path]
            with open(os.path.join(self.server.web, name), "rb") as f:  # type: ignore
                self._send(200, f.read(), ctype)
        else:
            self._send(404, _error("no such page: %s" % path[:80]))

    def do_POST(self) -> None:
        fn = ROUTES.get(self.path)
        if fn is None:
            self.close_connection = True  # its body unread: not the next request's start
            return self._send(404, _error("no such request: %s" % self.path[:80]))
        try:
            body = self._body()
        except Refusal as e:
            self.close_connection = True
            return self._send(e.status, _error(str(e)))
        t0 = time.perf_counter()
        status, ctype, data = self.server.compute(self.path, fn, body)  # type: ignore
        self._send(status, data, ctype, 1000 * (time.perf_counter() - t0))

    def _body(self) -> dict:
        n = self.headers.get("Content-Length")
        if n is None or not n.isdigit():
            raise Refusal(411, "a request body needs a Content-Length")
        if int(n) > BODY_MAX:
            raise Refusal(413, "request body of %s bytes: at most %d" % (n, BODY_MAX))
        try:
            body = json.loads(self.rfile.read(int(n)).decode("utf-8"))
        except (UnicodeDecodeError, json.JSONDecodeError) as e:
            raise Refusal(400, "malformed JSON: %s" % e) from None
        if not isinstance(body, dict):
            raise Refusal(400, "expected a JSON object")
        return body

    def _refuse_method(self) -> None:
        self.close_connection = True      # a body, if any, is not read
        self._send(405, _error("method %s not allowed: GET or POST" % self.command))

    do_PUT = do_DELETE = do_PATCH = do_OPTIONS = do_HEAD = _refuse_method


class Server(ThreadingHTTPServer):
    """The explorer's server on 127.0.0.1 (port 0: any free port)."""
    daemon_threads = True

    def __init__(self, port: int = 0, time_limit: float = TIME_LIMIT,
                 verbose: bool = False) -> None:
        self.time_limit, self.verbose = time_limit, verbose
        self.web, self.names = web_dir(), api_names()
        self.cache: collections.OrderedDict[str, tuple[int, str, bytes]] = \
            collections.OrderedDict()
        self.lock = threading.Lock()      # the cache, and the library in this process
        super().__init__(("127.0.0.1", port), Handler)

    def compute(self, path: str, fn: Callable[[dict], Any],
                body: dict) -> tuple[int, str, bytes]:
        """A computing request's answer: /api/tri without a formula here (bounded
        work, a few hundred microseconds), /api/graph from the cache when the same
        sites, rule and formula were asked before, the rest in a child."""
        if path == "/api/tri" and body.get("define") in (None, ""):
            with self.lock:
                return answer(fn, body)
        if path != "/api/graph":
            return run_limited(fn, body, self.time_limit)
        key = json.dumps([body.get("sites"), body.get("rule"), body.get("define")])
        with self.lock:
            hit = self.cache.get(key)
            if hit:
                self.cache.move_to_end(key)
                return hit
        out = run_limited(fn, body, self.time_limit)
        if out[0] != 503:                 # a time limit may pass another time
            with self.lock:
                self.cache[key] = out
                while len(self.cache) > GRAPH_CACHE:
                    self.cache.popitem(last=False)
        return out


def main(argv: list[str] | None = None) -> int:
    """python3 -m fliplab.explorer [--port P] [--time-limit S] [--verbose]"""
    ap = argparse.ArgumentParser(prog="python3 -m fliplab.explorer",
                                 description="The flip-graph explorer on http://127.0.0.1:PORT/")
    ap.add_argument("--port", type=int, default=8765, help="port (0: any free one)")
    ap.add_argument("--time-limit", type=float, default=TIME_LIMIT,
                    help="seconds per request (default %g)" % TIME_LIMIT)
    ap.add_argument("--verbose", action="store_true", help="log every request")
    a = ap.parse_args(argv)
    if not 0 <= a.port < 65536 or not 0 < a.time_limit <= 3600:
        ap.error("--port must be 0..65535 and --time-limit in (0, 3600]")
    try:
        srv = Server(a.port, a.time_limit, a.verbose)
    except OSError as e:
        print("fliplab explorer: port %d: %s" % (a.port, e.strerror), file=sys.stderr)
        return 2
    print("fliplab explorer: http://127.0.0.1:%d/ (Ctrl-C stops it)" % srv.server_address[1],
          flush=True)
    try:
        srv.serve_forever()
    except KeyboardInterrupt:
        pass
    srv.server_close()
    return 0


if __name__ == "__main__":
    sys.exit(main())
