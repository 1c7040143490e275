"""_flipgraph.py: every triangulation of a small site set and its flip graph
directed by a rule (classify/siteflip.h, docs/sitesets.md)."""
from __future__ import annotations

import ctypes
from typing import Any

import numpy as np
import numpy.typing as npt

from . import _lib
from ._args import tie_eps_arg
from ._arrays import as_coords, frozen, points_ptr, ptr
from ._mirrors import SiteflipResult
from ._rules import Rule, as_rule, _raise_user_errors

lib = _lib.lib


class FlipGraph:
    """The flip graph of a site set directed by a rule (flipgraph()).

    Parameters
    ----------
    g : ctypes pointer
        The library's siteflip_graph (read, not kept).
    dec : list of int
        The rule's decision on each of the graph's quadrilaterals.
    sinks : list of int
        The sinks, first nsinks of them.
    res : SiteflipResult
        siteflip_direct's result.
    rule : Rule
    points : ndarray of float64, shape (n, 2)

    Attributes
    ----------
    points : ndarray of float64, shape (n, 2)
        The sites.
    nodes : ndarray of int32, shape (N, T, 3)
        Triangulation u's T triangles (site indices, ascending), nodes in
        breadth-first order from triangulation 0.
    edges : ndarray of int32, shape (E, 2)
        Directed flips (from, to): the rule prefers `to`.
    ties : ndarray of int32, shape (K, 2)
        Flips the rule decides either way (no direction).
    flip_quads : ndarray of int32, shape (E + K, 4)
        Each flip's quadrilateral A B C D (anticlockwise, A the smallest site).
    flips : ndarray of int32, shape (E + K, 3)
        Each flip, row for row with flip_quads: the triangulation with
        diagonal AC, the one with BD, and the rule's decision (AC, BD or
        EITHER).
    sinks, sources : ndarray of int32
    dt : int
        The Delaunay triangulation, -1 when not unique.
    got, got_total : int or None, float or None
        The best triangulation of a triangle-based rule and its total.
    worst_sink, worst_gap : int or None, float or None
    keys : ndarray of float64, shape (N,)
        Each node's total in key space (a triangle-based rule).
    cycle : bool
        A directed cycle among the strict edges.
    sink_dt : bool or None
        The unique sink is DT (None when there is no unique sink or DT is
        not unique).
    """

    def __init__(self, g: Any, dec: list[int], sinks: list[int], res: SiteflipResult,
                 rule: Rule, points: npt.NDArray[np.float64]) -> None:
        G = g.contents
        self.rule = rule
        self.points = points
        per, N = G.per, G.nnodes
        tv = np.array([list(G.tri_v[t]) for t in range(G.ntris)], dtype=np.int32).reshape(-1, 3)
        nt = np.ctypeslib.as_array(G.node_tri, shape=(N * per,)).copy()
        self.nodes = tv[nt].reshape(N, per, 3)
        edges, ties, quads, flips = [], [], [], []
        for e in range(G.nedges):
            ed = G.edge[e]
            d = dec[ed.quad]
            quads.append(list(G.quad[ed.quad].v))
            flips.append((ed.ac, ed.bd, d))
            if d == 0:
                edges.append((ed.bd, ed.ac))      # AC preferred: the flip leads to ac
            elif d == 1:
                edges.append((ed.ac, ed.bd))
            else:
                ties.append((ed.ac, ed.bd))
        self.edges = np.array(edges, dtype=np.int32).reshape(-1, 2)
        self.ties = np.array(ties, dtype=np.int32).reshape(-1, 2)
        self.flip_quads = np.array(quads, dtype=np.int32).reshape(-1, 4)
        self.flips = np.array(flips, dtype=np.int32).reshape(-1, 3)
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

    def to_networkx(self) -> Any:
        """The graph for networkx.

        Returns
        -------
        networkx.DiGraph
            Node attributes triangles, sink, dt, got; an edge per directed
            flip, two (tie=True) per tie.

        Raises
        ------
        ImportError
            networkx is not installed.
        """
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

    def __repr__(self) -> str:
        return ("<fliplab.FlipGraph %s: %d sites, %d triangulations, %d flips, %d sinks%s>"
                % (self.rule.name, len(self.points), len(self.nodes),
                   len(self.edges) + len(self.ties), len(self.sinks),
                   ", ties" if len(self.ties) else ""))


def flipgraph(sites: npt.ArrayLike, rule: str | Rule, tie_eps: float | None = None,
              weights: npt.ArrayLike | None = None) -> FlipGraph:
    """Every triangulation of a small site set and its flip graph directed by
    the rule, as the program's `flipgraph --sites FILE --rule R`
    (docs/sitesets.md).

    Parameters
    ----------
    sites : array_like, shape (n, 2)
        3 to 16 sites, no two equal, not all on a line; convex or not.
    rule : str or Rule
        A Rule or a rule name: "DT", MEASURE_JOINT, ES:SHAPE or a plugin's
        quadrilateral rule (Rule).
    tie_eps : float, optional
        The relative tie tolerance (default the rule's).
    weights : array_like, shape (n,), optional
        Per-site weights of rule "WDT" (each 0 or of magnitude in [1e-60,
        1e60]), as `flipgraph --weights`: every triangulation keeps every
        site, so with a redundant site no node is regular.

    Returns
    -------
    FlipGraph

    Raises
    ------
    ValueError
        Bad sites (the library's message), a bad rule or tie_eps, weights
        with another rule or outside their contract; a bad value of a user
        measure.
    MemoryError
        Out of memory.
    """
    r = as_rule(rule)
    eps = tie_eps_arg(tie_eps, r.tie_eps)
    p = frozen(as_coords(sites, "sites", (-1, 2), own=True))   # kept as .points
    w = None if weights is None else _weights(weights, len(p), r)
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
        wp = None if w is None else ptr(w, ctypes.c_double)
        if lib.siteflip_direct_weighted(g, ctypes.byref(r._c), wp, eps, dec, sinks,
                                        ctypes.byref(res)) != 0:
            _raise_user_errors()
            raise MemoryError("flipgraph: out of memory")
        _raise_user_errors()
        out = FlipGraph(g, list(dec), list(sinks), res, r, p)
        _raise_user_errors()        # the nodes' keys call the measure too
        return out
    finally:
        lib.siteflip_free(g)


def _weights(weights: npt.ArrayLike, n: int, r: Rule) -> npt.NDArray[np.float64]:
    """Per-site weights for WDT, each checked against the weight contract
    (geom_weight_check), in the library's words."""
    if r.name != "WDT":
        raise ValueError("weights apply to the weighted Delaunay rule WDT, not %s" % r.name)
    w = as_coords(weights, "weights", (n,), own=True)
    for i, x in enumerate(w.tolist()):
        e = lib.geom_weight_check(x)
        if e != 0:
            raise ValueError("weights: site %d: weight %g %s"
                             % (i, x, lib.geom_weighterr_str(e).decode()))
    return w


def count_triangulations(sites: npt.ArrayLike, at_most: int) -> int | None:
    """How many triangulations a small site set has, if at most at_most: the
    enumeration of flipgraph() stopped as soon as it finds at_most + 1, so
    "too many" costs no more than at_most + 1 of them (docs/sitesets.md).

    Parameters
    ----------
    sites : array_like, shape (n, 2)
        3 to 16 sites, no two equal, not all on a line; convex or not.
    at_most : int
        The cap, at least 1 (and below 2^31 - 1).

    Returns
    -------
    int or None
        The number of triangulations, or None when there are more than at_most.

    Raises
    ------
    ValueError
        Bad sites (the library's message) or a cap below 1.
    MemoryError
        Out of memory.
    """
    if isinstance(at_most, bool) or not isinstance(at_most, int) or \
            not 1 <= at_most < 2 ** 31 - 1:
        raise ValueError("count_triangulations: at_most must be an integer in [1, 2^31 - 1)")
    p = as_coords(sites, "sites", (-1, 2))
    e = _lib.errbuf()
    count = ctypes.c_int(0)
    rc = lib.siteflip_count_upto(points_ptr(p), len(p), at_most, ctypes.byref(count), e,
                                 _lib.ERRLEN)
    if rc < 0:
        msg = _lib.text(e)
        raise (MemoryError if "memory" in msg else ValueError)(msg)
    return None if rc == 1 else count.value
