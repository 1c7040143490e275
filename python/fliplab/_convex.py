"""_convex.py: random convex n-gons of any sampler of the registry
(samplers/gon.c; thesis chapter 6), the polygons of `fliplab convex`, with
their weights, hull changes and statistics (studies/convex.c): the same
numbers as the program's, for the same seed, whatever the threads."""
import ctypes
from dataclasses import dataclass
from typing import Optional

import numpy as np
import numpy.typing as npt

from . import _lib
from ._args import count as _count, threads_arg as _threads, u64 as _u64
from ._arrays import cstr as _cstr, points_ptr as _points_ptr
from ._mirrors import StudyConvexRun

lib = _lib.lib
# The registry's names, regions and statistics, as the library lists them.
CONVEX_SAMPLERS = tuple(lib.sampler_gon_names().decode().split(", "))
# The inner methods the dual takes (sampler_gon_inner).
CONVEX_INNER = tuple(s for s in CONVEX_SAMPLERS if lib.sampler_gon_inner(s.encode()))
REGIONS = tuple(lib.sampler_region_name(k).decode()
                for k in range(8) if lib.sampler_region_name(k) is not None)
STATS = tuple(lib.study_convex_stat_name(k).decode()
              for k in range(16) if lib.study_convex_stat_name(k) is not None)


@dataclass
class ConvexPolygons:
    """Random convex polygons, as convex_polygons() returns them.

    Parameters
    ----------
    points : ndarray of float64, shape (count, n, 2)
        Anticlockwise from the lexicographically smallest vertex.
    log_weight : ndarray of float64, shape (count,)
        The bias-correcting weights' logarithms (0 for an unweighted sampler).
    weight : ndarray of float64, shape (count,)
        exp(log_weight - max), normalised to sum 1.
    h : ndarray of uint64, shape (count,)
        The iteration method's hull changes (else 0).
    stats : dict or None
        When asked for: one array (count,) per name of STATS ("area",
        "perimeter", "h", "unimodal", "rect_differ").
    """
    points: npt.NDArray[np.float64]
    log_weight: npt.NDArray[np.float64]
    weight: npt.NDArray[np.float64]
    h: npt.NDArray[np.uint64]
    stats: Optional[dict]

    def summary(self) -> dict:
        """Weighted means and 95% half-widths of the statistics, and the
        effective sample size (the program's --stats, study_convex_summary).

        Returns
        -------
        dict
            {"area": (mean, half-width), ..., "ess": effective sample size}.

        Raises
        ------
        ValueError
            The polygons were drawn without stats=True.
        """
        if self.stats is None:
            raise ValueError("summary: draw with stats=True")
        st = np.ascontiguousarray(np.stack([self.stats[k] for k in STATS], axis=1))
        lw = np.ascontiguousarray(self.log_weight)
        mean, half, ess = np.empty(len(STATS)), np.empty(len(STATS)), ctypes.c_double()
        dp = ctypes.POINTER(ctypes.c_double)
        lib.study_convex_summary(st.ctypes.data_as(dp), lw.ctypes.data_as(dp), len(lw),
                                 mean.ctypes.data_as(dp), half.ctypes.data_as(dp),
                                 ctypes.byref(ess))
        out = {k: (float(mean[i]), float(half[i])) for i, k in enumerate(STATS)}
        out["ess"] = ess.value
        return out


def _region(region: Optional[str]) -> int:
    """The region's number, -1 for None."""
    r = -1
    if region is not None:
        r = lib.sampler_region_find(_cstr(region, "region"))
        if r < 0:
            raise ValueError("region: unknown region %r (valid: square, disc, triangle)" % region)
    return r


def convex_polygons(n: int, count: int, sampler: str = "rejection",
                    region: Optional[str] = None, seed: int = 1, first: int = 0,
                    law: int = 0, inner: Optional[str] = None, threads: int = 0,
                    stats: bool = False) -> ConvexPolygons:
    """Random convex n-gons: polygons first .. first + count - 1 of the
    program's `fliplab convex --sampler S --region R --n N --seed SEED
    --law L --inner M`.

    Parameters
    ----------
    n : int
        Vertices, 3 .. 2^40 (naive and dual-rejection: up to 10).
    count : int
        How many.
    sampler : str
        One of CONVEX_SAMPLERS: "rejection" (weighted), "naive" (n <= 10),
        "iteration", "valtr" (square only), and, taking no region,
        "vector", "circle", "triangulation", "bounce", "dual",
        "dual-rejection" (n <= 10), "geobench", "angles" (n up to about
        50); docs/sampling.md gives each one's law and cost.
    region : str or None
        One of REGIONS: "square" ([0, 1]^2), "disc" (the unit disc), "triangle"; None: the
        square, or no region for the samplers that take none.
    seed, first : int
        The stream and the first polygon's index.
    law : int
        The sampler's variant (iteration: 1 = the exterior-region path also
        for the disc below 17 vertices; bounce, and dual of bounce: 0 = the
        bounced velocity redrawn, 1 = reflected).
    inner : str or None
        The dual's inner method, one of CONVEX_INNER: "vector" (None),
        "circle", "triangulation", "bounce", "dual-rejection", "geobench",
        "angles"; only with sampler="dual".
    threads : int
        0 (all cores) or 1 .. 1024; the output does not depend on it.
    stats : bool
        Also compute area, perimeter, h, unimodal, rect_differ per polygon.

    Returns
    -------
    ConvexPolygons

    Raises
    ------
    ValueError
        An unknown sampler, region, law or inner method, one the sampler
        does not take, a number out of range, or an n the sampler cannot
        realise in doubles.
    """
    name = _cstr(sampler, "sampler")
    n, count = _count(n, "n", 3), _count(count, "count", 0)
    r, err = _region(region), _lib.errbuf()
    if lib.sampler_gon_check(name, r, n, err, _lib.ERRLEN) != 0:
        raise ValueError("sampler: " + err.value.decode())
    law = min(_u64(law, "law"), 2 ** 31 - 1)
    cin = None if inner is None else _cstr(inner, "inner")
    if lib.sampler_gon_check_variant(name, law, cin, n, err, _lib.ERRLEN) != 0:
        raise ValueError(("inner: " if "inner" in err.value.decode() else "law: ")
                         + err.value.decode())
    run = StudyConvexRun(name, max(r, 0), law, _threads(threads), n, _u64(seed, "seed"), cin)
    xy = np.empty((count, n, 2))
    lw, h = np.zeros(count), np.zeros(count, dtype=np.uint64)
    st = np.empty((count, len(STATS))) if stats else None
    failed = ctypes.c_uint64()
    dp, up = ctypes.POINTER(ctypes.c_double), ctypes.POINTER(ctypes.c_uint64)
    rc = lib.study_convex_draw(ctypes.byref(run), _u64(first, "first"), count, _points_ptr(xy),
                               lw.ctypes.data_as(dp), h.ctypes.data_as(up),
                               st.ctypes.data_as(dp) if stats else None, ctypes.byref(failed))
    if rc == -2:
        raise MemoryError("convex_polygons: out of memory")
    if rc != 0:
        raise ValueError("n: polygon %d: sampler %s could not realise a strictly convex %d-gon "
                         "in doubles; ask for a smaller n" % (failed.value, sampler, n))
    w = np.exp(lw - lw.max()) if count else lw
    w = w / w.sum() if count else w
    sd = {k: st[:, i].copy() for i, k in enumerate(STATS)} if stats else None
    return ConvexPolygons(xy, lw, w, h, sd)
