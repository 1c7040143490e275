"""fliplab.plot: matplotlib pictures: a triangulation shaded by badness on the
colour scale of the program's SVGs (report_svg_colour: light yellow = good,
dark red = bad; the smallest finite badness of the picture at one end, the
largest at the other, a NaN or infinite value light grey), two
triangulations side by side on one scale, and a directed flip graph.
matplotlib is imported only when a function here is called."""
import ctypes
from typing import TYPE_CHECKING, Any, Sequence

import numpy as np

from . import _lib

if TYPE_CHECKING:
    from ._flipgraph import FlipGraph
    from ._lot import Triangulation

__all__ = ["badness_cmap", "triangulation", "compare", "flipgraph"]


def badness_cmap(n: int = 256) -> Any:
    """The SVGs' badness scale as a matplotlib colormap.

    Parameters
    ----------
    n : int
        Colours sampled from the library's report_svg_colour.

    Returns
    -------
    matplotlib.colors.ListedColormap
        Named "fliplab_badness"; NaN and infinite values light grey.

    Raises
    ------
    ImportError
        matplotlib is not installed.
    """
    from matplotlib.colors import ListedColormap
    buf = ctypes.create_string_buffer(16)
    cols = []
    for i in range(n):
        _lib.lib.report_svg_colour(i / (n - 1), buf, 16)
        h = buf.value.decode()
        cols.append((int(h[1:3], 16) / 255, int(h[3:5], 16) / 255, int(h[5:7], 16) / 255))
    cm = ListedColormap(cols, name="fliplab_badness")
    cm.set_bad("#dddddd")
    return cm


def _range(*bads: Any) -> tuple[float, float]:
    vals = np.concatenate([b[np.isfinite(b)] for b in bads if b is not None] or [np.zeros(0)])
    return (vals.min(), vals.max()) if vals.size else (0.0, 1.0)


def triangulation(t: "Triangulation", ax: Any = None, shade: bool = True,
                  vmin: float | None = None, vmax: float | None = None, title: str | None = None,
                  colorbar: bool = True, points: bool = True) -> Any:
    """Draw a triangulation: edges as hairlines, triangles filled by badness.

    Parameters
    ----------
    t : Triangulation
        A result of lot().
    ax : matplotlib.axes.Axes, optional
        Where to draw (default a new figure).
    shade : bool
        Fill the triangles by badness, when the rule has one.
    vmin, vmax : float, optional
        The badness scale's ends (default the picture's finite extremes).
    title : str, optional
        The axes' title (default "LOT(RULE): M triangles").
    colorbar : bool
        Draw the badness scale beside.
    points : bool
        Mark the points.

    Returns
    -------
    matplotlib.axes.Axes

    Raises
    ------
    ImportError
        matplotlib is not installed.
    """
    import matplotlib.pyplot as plt
    import matplotlib.tri as mtri
    if ax is None:
        _, ax = plt.subplots(figsize=(6, 6))
    p = t.points
    tr = mtri.Triangulation(p[:, 0], p[:, 1], t.triangles)
    bad = t.badness if shade else None
    if bad is not None and np.isfinite(bad).any():
        lo, hi = _range(bad) if vmin is None or vmax is None else (vmin, vmax)
        col = ax.tripcolor(tr, facecolors=np.ma.masked_invalid(bad), cmap=badness_cmap(),
                           vmin=lo, vmax=hi if hi > lo else lo + 1)
        if colorbar:
            ax.figure.colorbar(col, ax=ax, shrink=0.7, label="badness (%s)" % t.rule.measure)
    n = len(p)
    ax.triplot(tr, color="#1f4e79", lw=0.2 if n > 2000 else 0.4 if n > 300 else 0.8)
    if points:
        ax.plot(p[:, 0], p[:, 1], "k.", ms=1 if n > 2000 else 2 if n > 300 else 4)
    ax.set_aspect("equal")
    ax.set_title(title if title is not None else "LOT(%s): %d triangles"
                 % (t.rule.name, len(t.triangles)))
    ax.set_xticks([])
    ax.set_yticks([])
    return ax


def compare(a: "Triangulation", b: "Triangulation", shade: bool = True,
            titles: Sequence[str] | None = None) -> Any:
    """Two triangulations of the same points side by side on one badness
    scale, as the program's lot command draws a comparison with DT.

    Parameters
    ----------
    a, b : Triangulation
        Results of lot().
    shade : bool
        Fill the triangles by badness.
    titles : sequence of two str, optional
        The panels' titles.

    Returns
    -------
    matplotlib.figure.Figure

    Raises
    ------
    ImportError
        matplotlib is not installed.
    """
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(12, 6))
    ba = a.badness if shade else None
    bb = b.badness if shade else None
    lo, hi = _range(ba, bb)
    for k, (t, ax) in enumerate(zip((a, b), axes)):
        triangulation(t, ax, shade=shade, vmin=lo, vmax=hi, colorbar=False,
                      title=None if titles is None else titles[k])
    if shade and (np.isfinite(ba).any() or np.isfinite(bb).any()):
        import matplotlib.cm as cm
        from matplotlib.colors import Normalize
        sm = cm.ScalarMappable(Normalize(lo, hi if hi > lo else lo + 1), badness_cmap())
        fig.colorbar(sm, ax=axes, shrink=0.7, label="badness")
    return fig


def flipgraph(g: "FlipGraph", ax: Any = None, size: tuple[float, float] | None = None) -> Any:
    """Draw a directed flip graph: each triangulation a small picture, in
    columns by flip distance from triangulation 0, an arrow on each flip
    towards the preferred one (a dashed line for a tie), sinks framed in
    thick green, sources in dashed red, the Delaunay triangulation tagged DT.

    Parameters
    ----------
    g : FlipGraph
        A result of fliplab.flipgraph().
    ax, size : matplotlib.axes.Axes, tuple of two float, optional
        Where to draw; without, a new figure of that size in inches.

    Returns
    -------
    matplotlib.axes.Axes
        ax, or the new figure's axes.

    Raises
    ------
    ImportError
        Without matplotlib.
    """
    import matplotlib.pyplot as plt
    from matplotlib.patches import FancyArrowPatch, Rectangle
    N = len(g.nodes)
    adj = [[] for _ in range(N)]
    for a, b in np.vstack([g.edges, g.ties]).tolist():
        adj[a].append(b)
        adj[b].append(a)
    dist = [-1] * N
    dist[0], queue = 0, [0]
    for u in queue:
        for v in adj[u]:
            if dist[v] < 0:
                dist[v] = dist[u] + 1
                queue.append(v)
    cols = {}
    for u in range(N):
        cols.setdefault(dist[u], []).append(u)
    ncol, nrow = len(cols), max(len(c) for c in cols.values())
    if ax is None:
        _, ax = plt.subplots(figsize=size or (2.2 * ncol, 2.2 * nrow))
    pos = {}
    for c, us in cols.items():
        for r, u in enumerate(us):
            pos[u] = (3.0 * c, -3.0 * r - 1.5 * (nrow - len(us)))
    p = g.points
    span = np.ptp(p, axis=0).max() or 1.0
    q = (p - p.min(axis=0) - np.ptp(p, axis=0) / 2) / span * 2.0   # within [-1, 1]
    sinks, sources = set(g.sinks.tolist()), set(g.sources.tolist())
    for u in range(N):
        x, y = pos[u]
        for tri in g.nodes[u]:
            v = q[tri] + (x, y)
            ax.fill(v[:, 0], v[:, 1], fc="none", ec="#1f4e79", lw=0.6)
        if u in sinks:
            ax.add_patch(Rectangle((x - 1.2, y - 1.2), 2.4, 2.4, fc="none", ec="green", lw=2.5))
        elif u in sources:
            ax.add_patch(Rectangle((x - 1.2, y - 1.2), 2.4, 2.4, fc="none", ec="#c0392b",
                                   lw=1, ls="--"))
        if u == g.dt:
            ax.text(x - 1.15, y + 1.25, "DT", fontsize=8)
        ax.text(x + 0.6, y + 1.25, "T%d" % (u + 1), fontsize=7)
    for a, b in g.edges.tolist():
        ax.add_patch(FancyArrowPatch(pos[a], pos[b], arrowstyle="-|>", mutation_scale=10,
                                     shrinkA=28, shrinkB=28, color="k", lw=0.8))
    for a, b in g.ties.tolist():
        ax.add_patch(FancyArrowPatch(pos[a], pos[b], arrowstyle="-", shrinkA=28, shrinkB=28,
                                     color="k", lw=0.8, ls="--"))
    xs = [v[0] for v in pos.values()]
    ys = [v[1] for v in pos.values()]
    ax.set_xlim(min(xs) - 1.5, max(xs) + 1.5)
    ax.set_ylim(min(ys) - 1.5, max(ys) + 1.8)
    ax.set_aspect("equal")
    ax.axis("off")
    ax.set_title("%s: %d triangulations, %d sinks" % (g.rule.name, N, len(g.sinks)))
    return ax
