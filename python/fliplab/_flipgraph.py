"""_flipgraph.py: every triangulation of a small site set and its flip graph
directed by a rule (classify/siteflip.h, docs/sitesets.md)."""
import ctypes
import numpy as np

from . import _lib
from ._arrays import as_coords, frozen, points_ptr
from ._rules import as_rule, tie_eps_arg, _raise_user_errors

lib = _lib.lib
SITEFLIP_MAX_SITES = 16


class SiteflipQuad(ctypes.Structure):
    _fields_ = [("v", ctypes.c_ubyte * 4), ("tri", ctypes.c_int * 4)]


class SiteflipEdge(ctypes.Structure):
    _fields_ = [("ac", ctypes.c_int), ("bd", ctypes.c_int), ("quad", ctypes.c_int)]


class SiteflipGraph(ctypes.Structure):
    _fields_ = [("n", ctypes.c_int), ("p", _lib.Point * SITEFLIP_MAX_SITES),
                ("nnodes", ctypes.c_int), ("node", ctypes.c_void_p), ("per", ctypes.c_int),
                ("node_tri", ctypes.POINTER(ctypes.c_int)), ("ntris", ctypes.c_int),
                ("tri_v", ctypes.POINTER(ctypes.c_ubyte * 3)), ("tri", ctypes.c_void_p),
                ("nquads", ctypes.c_int), ("quad", ctypes.POINTER(SiteflipQuad)),
                ("nedges", ctypes.c_int), ("edge", ctypes.POINTER(SiteflipEdge)),
                ("adj_off", ctypes.c_void_p), ("adj", ctypes.c_void_p),
                ("delaunay", ctypes.c_int)]


class SiteflipResult(ctypes.Structure):
    _fields_ = [("nsinks", ctypes.c_int), ("nsources", ctypes.c_int), ("ties", ctypes.c_int),
                ("cycle", ctypes.c_int), ("sink_dt", ctypes.c_int), ("has_got", ctypes.c_int),
                ("got_node", ctypes.c_int), ("got_total", ctypes.c_double),
                ("worst_sink", ctypes.c_int), ("worst_gap", ctypes.c_double)]


_G = ctypes.POINTER(SiteflipGraph)
lib.siteflip_build.restype = _G
lib.siteflip_build.argtypes = [_lib.Point_p, ctypes.c_int, ctypes.c_char_p, ctypes.c_size_t]
lib.siteflip_free.restype = None
lib.siteflip_free.argtypes = [_G]
lib.siteflip_direct.restype = ctypes.c_int
lib.siteflip_direct.argtypes = [_G, _lib.Rule_p, ctypes.c_double, ctypes.POINTER(ctypes.c_int),
                                ctypes.POINTER(ctypes.c_int), ctypes.POINTER(SiteflipResult)]
lib.siteflip_node_key.restype = ctypes.c_double
lib.siteflip_node_key.argtypes = [_G, _lib.Rule_p, ctypes.c_int]


class FlipGraph:
    """The flip graph of a site set directed by a rule.

    points     (n, 2) the sites
    nodes      (N, T, 3) int32: triangulation u's T triangles (site indices,
               ascending), nodes in breadth-first order from triangulation 0
    edges      (E, 2) int32 directed flips (from, to): the rule prefers `to`
    ties       (K, 2) int32 flips the rule decides `either` (no direction)
    quads      (E, 4) the flip's quadrilateral A B C D (anticlockwise, A the
               smallest site), its diagonal AC in edges' ac node
    sinks, sources   arrays of nodes; dt the Delaunay triangulation (-1 when
               not unique); got the best triangulation of a triangle-based
               rule (None otherwise), got_total its total; worst_sink,
               worst_gap; cycle (a directed cycle among the strict edges);
               sink_dt (True / False: the unique sink is / is not DT; None
               when there is no unique sink or DT is not unique)."""

    def __init__(self, g, dec, sinks, res, rule, points):
        G = g.contents
        self.rule = rule
        self.points = points
        per, N = G.per, G.nnodes
        tv = np.array([list(G.tri_v[t]) for t in range(G.ntris)], dtype=np.int32).reshape(-1, 3)
        nt = np.ctypeslib.as_array(G.node_tri, shape=(N * per,)).copy()
        self.nodes = tv[nt].reshape(N, per, 3)
        edges, ties, quads = [], [], []
        for e in range(G.nedges):
            ed = G.edge[e]
            d = dec[ed.quad]
            quads.append(list(G.quad[ed.quad].v))
            if d == 0:
                edges.append((ed.bd, ed.ac))      # AC preferred: the flip leads to ac
            elif d == 1:
                edges.append((ed.ac, ed.bd))
            else:
                ties.append((ed.ac, ed.bd))
        self.edges = np.array(edges, dtype=np.int32).reshape(-1, 2)
        self.ties = np.array(ties, dtype=np.int32).reshape(-1, 2)
        self.flip_quads = np.array(quads, dtype=np.int32).reshape(-1, 4)
        self.sinks = np.array(sinks[:res.nsinks], dtype=np.int32)
        indeg = np.zeros(N, dtype=int)
        np.add.at(indeg, self.edges[:, 1], 1)
        self.sources = np.nonzero(indeg == 0)[0].astype(np.int32)
        self.dt = G.delaunay
        self.cycle = bool(res.cycle)
        self.sink_dt = None if res.sink_dt < 0 else bool(res.sink_dt)
        self.got = res.got_node if res.has_got else None
        self.got_total = res.got_total if res.has_got else None
        self.worst_sink = res.worst_sink if res.has_got else None
        self.worst_gap = res.worst_gap if res.has_got else None
        if rule.is_triangle:
            # each node's total badness, as a key (keys compare as totals do)
            self.keys = np.array([lib.siteflip_node_key(g, ctypes.byref(rule._c), u)
                                  for u in range(N)])

    def to_networkx(self):
        """A networkx.DiGraph: node attributes triangles, sink, dt, got; an
        edge per directed flip, two (tie=True) per tie."""
        import networkx as nx
        G = nx.DiGraph()
        sinks = set(self.sinks.tolist())
        for u in range(len(self.nodes)):
            G.add_node(u, triangles=self.nodes[u].tolist(), sink=u in sinks, dt=u == self.dt,
                       got=u == self.got)
        G.add_edges_from(map(tuple, self.edges.tolist()), tie=False)
        for a, b in self.ties.tolist():
            G.add_edge(a, b, tie=True)
            G.add_edge(b, a, tie=True)
        return G

    def __repr__(self):
        return ("<fliplab.FlipGraph %s: %d sites, %d triangulations, %d flips, %d sinks%s>"
                % (self.rule.name, len(self.points), len(self.nodes),
                   len(self.edges) + len(self.ties), len(self.sinks),
                   ", ties" if len(self.ties) else ""))


def flipgraph(sites, rule, tie_eps=None):
    """Every triangulation of a site set (3 to 16 sites, no two equal, not
    all on a line; convex or not) and its flip graph directed by the rule,
    as `fliplab flipgraph --sites FILE --rule R`."""
    r = as_rule(rule)
    eps = tie_eps_arg(tie_eps, r.tie_eps)
    p = frozen(as_coords(sites, "sites", (-1, 2), own=True))   # kept as .points
    e = _lib.errbuf()
    g = lib.siteflip_build(points_ptr(p), len(p), e, _lib.ERRLEN)
    if not g:
        msg = _lib.text(e)
        raise (MemoryError if "memory" in msg and "budget" not in msg else ValueError)(msg)
    try:
        G = g.contents
        dec = (ctypes.c_int * max(G.nquads, 1))()
        sinks = (ctypes.c_int * max(G.nnodes, 1))()
        res = SiteflipResult()
        if lib.siteflip_direct(g, ctypes.byref(r._c), eps, dec, sinks, ctypes.byref(res)) != 0:
            _raise_user_errors()
            raise MemoryError("flipgraph: out of memory")
        _raise_user_errors()
        out = FlipGraph(g, list(dec), list(sinks), res, r, p)
        _raise_user_errors()        # the nodes' keys call the measure too
        return out
    finally:
        lib.siteflip_free(g)
