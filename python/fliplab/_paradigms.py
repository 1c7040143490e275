"""_paradigms.py: chapter 2's algorithms behind the library's registry
(paradigms/paradigm.h): the rows (paradigms), and one run of a row on a
point set, a constrained point set or a polygon (triangulate_by), exact and
counted.  The rows are read from the library (paradigm_get), so a row it
gains is here at once; a run goes through the one runner of paradigm.c,
which checks, merges duplicates and writes the triangles in its canonical
order, as `fliplab paradigms` runs them."""
from __future__ import annotations

import ctypes
import os
from typing import Any, Dict, List

import numpy as np
import numpy.typing as npt

from . import _lib
from ._args import MAX_THREADS, choice, threads_arg, u64
from ._arrays import as_coords, as_indices, points_ptr, ptr
from ._mirrors import ParadigmInput, ParadigmResult
from ._rules import Rule, as_rule

lib = _lib.lib
PARADIGM_ALGORITHMS = tuple(lib.paradigm_get(i).contents.name.decode()
                            for i in range(lib.paradigm_count()))
PARADIGM_PROBLEMS = tuple(lib.paradigm_problem_name(1 << k).decode() for k in range(4))
OPS_NAMES = _lib.c_names(lib.ops_name)


def paradigms() -> List[Dict[str, Any]]:
    """The rows of the registry, as `fliplab paradigms --list` prints them.

    Returns
    -------
    list of dict
        One per algorithm, in the registry's order: name, paradigm ("flip",
        "incremental", "selection", "sweepline", "divide"), section (of the
        thesis, "2.6.1"), problems (a tuple of PARADIGM_PROBLEMS it
        serves), rules (("DT",) or ("DT", "ES:SHAPE")), cost, refusal (why
        it does not serve the others), param (what `param` of
        triangulate_by means, or None).
    """
    out = []
    for i in range(lib.paradigm_count()):
        a = lib.paradigm_get(i).contents
        out.append({"name": a.name.decode(), "paradigm": a.paradigm.decode(),
                    "section": a.section.decode(),
                    "problems": tuple(p for k, p in enumerate(PARADIGM_PROBLEMS)
                                      if a.problems & (1 << k)),
                    "rules": ("DT", "ES:SHAPE") if a.rules & 2 else ("DT",),
                    "cost": a.cost.decode(), "refusal": a.refusal.decode(),
                    "param": a.param.decode() if a.param else None})
    return out


def _param(v: float) -> float:
    ok = isinstance(v, (int, float, np.integer, np.floating)) and \
        not isinstance(v, (bool, np.bool_))
    if not (ok and np.isfinite(v) and v >= 0):
        raise ValueError("param: expected a finite number >= 0, got %r" % (v,))
    return float(v)


def _segments(segments: npt.ArrayLike | None, problem: str, n: int) -> Any:
    if segments is None:
        return None
    if problem != "constrained":
        raise ValueError("segments: only for problem 'constrained', not %r" % problem)
    return as_indices(segments, "segments", 2, n)


def triangulate_by(points: npt.ArrayLike, algorithm: str, rule: str | Rule = "DT",
                   problem: str = "delaunay", segments: npt.ArrayLike | None = None,
                   seed: int = 1, threads: int = 1,
                   param: float = 0.0) -> tuple[npt.NDArray[np.int32], Dict[str, Any]]:
    """One algorithm of chapter 2 on one input, exact and counted.

    Parameters
    ----------
    points : array_like, shape (n, 2)
        The points (duplicates are merged, each index taking its first
        occurrence's); for the polygon problems the vertices in boundary
        order (a convex polygon anticlockwise).
    algorithm : str
        A row of the registry (PARADIGM_ALGORITHMS, `paradigms()`):
        ALGORITHM_NAMES.
    rule : str or Rule
        "DT", or an empty-shape rule ES:SHAPE for the rows that serve it; a
        MEASURE_JOINT rule is refused (no row serves it).
    problem : str
        "delaunay" (the points), "constrained" (with `segments`),
        "polygon" (a simple polygon) or "convex" (a convex polygon).
    segments : array_like, shape (k, 2), optional
        Point indices of segments (problem "constrained" only).
    seed : int
        For the randomised algorithms: same seed, same run.
    threads : int
        1 .. MAX_THREADS, or 0 for all cores; the result is the same for any.
    param : float
        The row's parameter (`paradigms()`'s param; 0: its default).

    Returns
    -------
    triangles : ndarray of int32, shape (m, 3)
        Indices into points, anticlockwise, in the runner's canonical order
        (each triangle from its smallest index, rows sorted): two
        algorithms agree exactly when these arrays are equal.
    counts : dict
        Every count of geom/ops.h by name (orient, incircle, inshape, exact,
        flips, locate, edges_made, edges_deleted, events, buckets,
        peak_bytes), seconds (the wall time) and distinct (the points after
        merging duplicates).

    Raises
    ------
    ValueError
        An unknown algorithm or problem, a rule or problem the algorithm
        does not serve (its reason), segments outside the constrained
        problem or naming no point, bad points (a coordinate outside the
        contract, fewer than three distinct, all collinear, a polygon that
        is not one), in the library's words.
    MemoryError
        Out of memory.
    """
    a = choice(algorithm, PARADIGM_ALGORITHMS, "algorithm")
    pb = choice(problem, PARADIGM_PROBLEMS, "problem")
    r = as_rule(rule)
    seed = u64(seed, "seed")
    th = threads_arg(threads) or min(os.cpu_count() or 1, MAX_THREADS)
    p = as_coords(points, "points", (-1, 2))
    seg = _segments(segments, problem, len(p))
    inp = ParadigmInput(p=points_ptr(p), n=len(p), r=ctypes.pointer(r._c), problem=1 << pb,
                        seed=seed, threads=th, param=_param(param))
    if seg is not None:
        inp.segments, inp.nsegments = ptr(seg, ctypes.c_uint32), len(seg)
    res, e = ParadigmResult(), _lib.errbuf()
    if lib.paradigm_run(lib.paradigm_get(a), ctypes.byref(inp), ctypes.byref(res), e,
                        _lib.ERRLEN) != 0:
        msg = _lib.text(e)
        raise (MemoryError if msg.startswith("out of memory") else ValueError)(msg)
    try:
        tri = np.ctypeslib.as_array(res.tri, shape=(3 * res.ntri,)).reshape(-1, 3) \
            .astype(np.int32) if res.ntri else np.empty((0, 3), np.int32)
        counts: Dict[str, Any] = {k: int(res.ops.v[i]) for i, k in enumerate(OPS_NAMES)}
        counts["seconds"], counts["distinct"] = float(res.seconds), int(res.distinct)
    finally:
        lib.paradigm_result_free(ctypes.byref(res))
    return tri, counts


# The algorithm names are the library's: the docstring lists them as they are.
triangulate_by.__doc__ = (triangulate_by.__doc__ or "").replace(
    "ALGORITHM_NAMES", ",\n        ".join('"%s"' % n for n in PARADIGM_ALGORITHMS))
