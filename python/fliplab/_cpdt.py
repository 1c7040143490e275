"""_cpdt.py: chapter 5's workbench (cpdt/cpdt.h, studies/study_cpdt.h): the
Delaunay triangulation of a convex polygon by each algorithm of the
thesis's chapter 5, exact and counted, and the experiment of
`fliplab cpdt`.  Counts and cells are read through the library's verbs by
name (cpdt_counts_get_u64, study_cpdt_cell_get): no layout restated."""
from __future__ import annotations

import ctypes
from typing import Any, Dict, Optional, Sequence

import numpy as np
import numpy.typing as npt

from . import _lib
from ._args import choice, count, is_int, u64
from ._convex import _region
from ._arrays import as_coords, check_contract, points_ptr, ptr

lib = _lib.lib
CPDT_ALGORITHMS = _lib.c_names(lib.cpdt_algorithm_name)
CPDT_SAMPLERS = _lib.c_names(lib.study_cpdt_sampler_name)
CPDT_COUNTS = _lib.c_names(lib.study_cpdt_count_name)
_FIELDS = _lib.c_names(lib.cpdt_counts_field)


def _counts(c: Any) -> Dict[str, Any]:
    out: Dict[str, Any] = {}
    for f in _FIELDS:
        u, d = ctypes.c_uint64(), ctypes.c_double()
        if lib.cpdt_counts_get_u64(c, f.encode(), ctypes.byref(u)) == 0:
            out[f] = int(u.value)
        elif lib.cpdt_counts_get_double(c, f.encode(), ctypes.byref(d)) == 0:
            out[f] = float(d.value)
    return out


def convex_dt(polygon: npt.ArrayLike, algorithm: str = "divide",
              seed: int = 1) -> tuple[npt.NDArray[np.int32], Dict[str, Any]]:
    """The Delaunay triangulation of a strictly convex anticlockwise polygon
    by one of chapter 5's algorithms, with its operation counts.

    Parameters
    ----------
    polygon : array_like, shape (n, 2)
        The vertices, anticlockwise (a clockwise polygon is refused).
    algorithm : str
        One of CPDT_ALGORITHMS: "circum", "circum-random", "circum-walk",
        "divide", "incremental", "random", "flip", "corners".  All give the same
        triangles: lot's Delaunay triangulation, cocircular ties included.
    seed : int
        For the randomised algorithms: same seed, same counts.

    Returns
    -------
    triangles : ndarray of int32, shape (n-2, 3)
        i < j < k per row, row j-1 holding the triangle whose middle vertex
        is j.
    counts : dict
        scanned, incircle, orient, flips, merges, cross_sum, cross_max,
        added, deleted, depth, memory (ints) and index_length (float)
        (docs/cpdt.md).

    Raises
    ------
    ValueError
        An unknown algorithm, a bad seed, or a polygon that is not strictly
        convex and anticlockwise (clockwise, a reflex or collinear vertex,
        a repeated vertex, fewer than 3, a coordinate outside the contract),
        named by its vertex in the library's words.
    MemoryError
        Out of memory.
    """
    a = choice(algorithm, CPDT_ALGORITHMS, "algorithm")
    seed = u64(seed, "seed")
    p = as_coords(polygon, "polygon", (-1, 2))
    check_contract(p, "polygon vertex")
    n = len(p)
    bad = ctypes.c_size_t()
    e = lib.cpdt_check(points_ptr(p), n, ctypes.byref(bad))
    if e != 0:
        raise ValueError("polygon: vertex %d: %s" % (bad.value, lib.cpdt_check_str(e).decode()))
    tri = np.empty((n - 2, 3), dtype=np.uint32)
    c = lib.cpdt_counts_new()
    if not c:
        raise MemoryError("convex_dt: out of memory")
    try:
        rc = lib.cpdt_triangulate(points_ptr(p), n, a, seed, ptr(tri, ctypes.c_uint32), c)
        if rc != 0:
            raise MemoryError("convex_dt: out of memory")
        counts = _counts(c)
    finally:
        lib.cpdt_counts_delete(c)
    return tri.astype(np.int32), counts


def convex_dt_experiment(sizes: Sequence[int] = (31, 62, 124, 248, 496, 992),
                         trials: int = 70, sampler: str = "vector",
                         algorithms: Sequence[str] | None = None,
                         seed: int = 1, region: Optional[str] = None,
                         law: int = 0) -> Dict[str, Any]:
    """Chapter 5's experiment, as `fliplab cpdt` runs it: for each size,
    `trials` random convex polygons from `sampler` triangulated by each
    algorithm, every algorithm's triangles compared.

    Parameters
    ----------
    sizes : sequence of int
        Polygon sizes, each at least 3.
    trials : int
        Polygons per size (the thesis: 70).
    sampler : str
        A name of CPDT_SAMPLERS, the registry of random convex n-gons of
        `convex_polygons` ("rejection", "naive", "iteration", "valtr",
        "vector", "circle", "triangulation", "bounce", "dual",
        "dual-rejection", "geobench", "angles"; docs/sampling.md; the dual's
        inner method is "vector"): polygon t of size n is
        `convex_polygons(n, sampler=..., seed=seed)`'s polygon t.  "rejection"
        is refused (its polygons carry weights and the means are unweighted:
        "valtr" draws its law in the square unweighted).
    algorithms : sequence of str, optional
        Names of CPDT_ALGORITHMS (default: all of them).
    seed : int
        Polygon (n, t) of a seed is the program's for the same seed.
    region : str or None
        One of REGIONS ("square", "disc", "triangle") for the samplers that
        draw points from one; None: the square, or none for the others.
    law : int
        The sampler's variant, as `convex_polygons`' law.

    Returns
    -------
    dict
        "rows": a list of dicts, one per size and algorithm (n, algorithm,
        and for each name of CPDT_COUNTS its mean and NAME_half, the
        half-width of its 95% interval); "slopes": {algorithm: {count:
        least-squares slope of log mean against log n}}.

    Raises
    ------
    ValueError
        Bad sizes (a size the sampler cannot draw), an unknown sampler or
        algorithm, a repeated algorithm, bad trials or seed.
    MemoryError
        Out of memory.
    """
    if isinstance(sizes, (str, bytes)) or not all(is_int(n) for n in sizes) or not sizes:
        raise ValueError("sizes: expected a non-empty sequence of integers, got %r" % (sizes,))
    algs = list(CPDT_ALGORITHMS) if algorithms is None else list(algorithms)
    ids = [choice(x, CPDT_ALGORITHMS, "algorithms", "algorithm") for x in algs]
    if len(set(ids)) != len(ids) or not ids:
        raise ValueError("algorithms: expected distinct names, got %r" % (algs,))
    s = choice(sampler, CPDT_SAMPLERS, "sampler")
    trials, seed = count(trials, "trials", 1), u64(seed, "seed")
    r, law = _region(region), count(law, "law", 0)
    if law > 2 ** 31 - 1:
        raise ValueError("law: at most 2^31 - 1, got %d" % law)
    why = ctypes.create_string_buffer(256)
    for n in sizes:
        if lib.study_cpdt_sampler_check(s, r, law, max(int(n), 0), why, 256) != 0:
            raise ValueError("sizes: %d: %s" % (n, why.value.decode()))
    sz = np.array([int(n) for n in sizes], dtype=np.uint64)
    ia = np.array(ids, dtype=np.intc)
    nc = len(sz) * len(ia)
    cells = lib.study_cpdt_cells_new(nc)
    if not cells:
        raise MemoryError("convex_dt_experiment: out of memory")
    try:
        err = ctypes.create_string_buffer(256)
        rc = lib.study_cpdt_run(ptr(sz, ctypes.c_uint64), len(sz), ptr(ia, ctypes.c_int),
                                len(ia), trials, seed, s, r, law, cells, err, 256)
        if rc != 0:
            raise (MemoryError if rc == -2 else ValueError)("convex_dt_experiment: " +
                                                             err.value.decode())
        return _experiment_result(cells, sz, ids)
    finally:
        lib.study_cpdt_cells_delete(cells)


def _experiment_result(cells: Any, sz: npt.NDArray[np.uint64], ids: list) -> Dict[str, Any]:
    rows = []
    m, h = ctypes.c_double(), ctypes.c_double()
    for i, n in enumerate(sz):
        for j, a in enumerate(ids):
            row: Dict[str, Any] = {"n": int(n), "algorithm": CPDT_ALGORITHMS[a]}
            for k, name in enumerate(CPDT_COUNTS):
                lib.study_cpdt_cell_get(cells, i * len(ids) + j, k, ctypes.byref(m),
                                        ctypes.byref(h))
                row[name], row[name + "_half"] = m.value, h.value
            rows.append(row)
    nc = len(sz) * len(ids)
    slopes = {CPDT_ALGORITHMS[a]: {name: lib.study_cpdt_slope(cells, nc, a, k)
                                   for k, name in enumerate(CPDT_COUNTS)} for a in ids}
    return {"rows": rows, "slopes": slopes}
