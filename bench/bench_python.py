#!/usr/bin/python3
"""bench_python.py: the Python package's speed (python/, docs/python.md).
Run with Debian's interpreter, which sees python3-numpy and python3-scipy:

    FLIPLAB_LIBRARY=build/libfliplab.so PYTHONPATH=python /usr/bin/python3 bench/bench_python.py

Prints medians of --runs runs (default 3; the two sides of each comparison
of lot() run alternately) of:
  1. DT of N = 10^6 uniform points from one numpy array: fliplab.lot(p, "DT")
     against scipy.spatial.Delaunay(p), side by side in one process;
  2. the module's overhead: lot() in full (validation, conversion, result
     arrays) against the C calls it makes (the lot_options verbs, lot_build,
     lot_get_triangles, lot_get_hull, lot_get_neighbors, lot_free called
     directly through ctypes on the same array);
  3. vectorised badness of 10^7 triangles (fliplab.badness(t, "R")) against a
     Python loop computing the same formula R = abc / (4A) with math, timed
     on the first 10^5 triangles and scaled by 100; and where the vectorised
     time goes: the coordinate contract check (geom_coord_check_n) and the
     C measure loop (measure_eval_tris) timed on their own.
"""
import argparse
import ctypes
import math
import os
import statistics
import time

import numpy as np
import scipy.spatial

import fliplab
from fliplab import _lib
from fliplab._arrays import check_contract, points_ptr, ptr
from fliplab._rules import _measure_id


def median_time(fn, runs):
    ts = []
    for _ in range(runs):
        t0 = time.perf_counter()
        fn()
        ts.append(time.perf_counter() - t0)
    return statistics.median(ts)


def paired_medians(fa, fb, runs):
    """Medians of fa's and fb's times, run alternately, so that a change of
    load on a shared machine falls on both alike."""
    ta, tb = [], []
    for _ in range(runs):
        ta.append(median_time(fa, 1))
        tb.append(median_time(fb, 1))
    return statistics.median(ta), statistics.median(tb)


def c_only(p):
    """The C calls lot(p, "DT") makes, and nothing else: the options, the
    build, the triangles, the hull and the neighbours (lot() reads both
    off the mesh), through ctypes on the same array."""
    lib = _lib.lib
    r = fliplab.Rule("DT")
    o = lib.lot_options_new(ctypes.byref(r._c))
    L = ctypes.c_void_p()
    e = _lib.errbuf()
    try:
        if lib.lot_build(ctypes.byref(L), points_ptr(p), len(p), o, e, _lib.ERRLEN):
            raise RuntimeError(_lib.text(e))
    finally:
        lib.lot_options_free(o)
    s = lib.lot_get_stats(L)
    m = _lib.get_u64(lib.lot_stats_get_u64, s, "triangles")
    tri = np.empty((m, 3), dtype=np.int32)
    lib.lot_get_triangles(L, ptr(tri, ctypes.c_uint32))
    hull = np.empty(_lib.get_u64(lib.lot_stats_get_u64, s, "hull"), dtype=np.int32)
    lib.lot_get_hull(L, ptr(hull, ctypes.c_uint32))
    nb = np.empty((m, 3), dtype=np.int32)
    if lib.lot_get_neighbors(L, ptr(nb, ctypes.c_int32)) != 0:
        raise MemoryError("lot_get_neighbors: out of memory")
    lib.lot_free(L)


def python_R(t):
    out = []
    for (x1, y1), (x2, y2), (x3, y3) in t.tolist():
        a = math.hypot(x2 - x3, y2 - y3)
        b = math.hypot(x1 - x3, y1 - y3)
        c = math.hypot(x1 - x2, y1 - y2)
        area = abs((x2 - x1) * (y3 - y1) - (y2 - y1) * (x3 - x1)) / 2
        out.append(a * b * c / (4 * area))
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--n", type=int, default=10 ** 6)
    ap.add_argument("--triangles", type=int, default=10 ** 7)
    ap.add_argument("--runs", type=int, default=3)
    a = ap.parse_args()
    print("# bench_python: %s, numpy %s, scipy %s, %d runs (medians); load average %.2f"
          % (fliplab.library_path, np.__version__, scipy.__version__, a.runs,
             os.getloadavg()[0]))
    p = fliplab.samplers.points(a.n, "uniform", 1)
    tf, ts = paired_medians(lambda: fliplab.lot(p, "DT"), lambda: scipy.spatial.Delaunay(p),
                            a.runs)
    print("DT of %d points: fliplab.lot %.3f s, scipy.spatial.Delaunay %.3f s: %.1fx faster"
          % (a.n, tf, ts, ts / tf))
    tf, tc = paired_medians(lambda: fliplab.lot(p, "DT"), lambda: c_only(p), a.runs)
    print("lot() overhead over its C calls: lot() %.3f s, C %.3f s: %.1f%%"
          % (tf, tc, 100 * (tf - tc) / tc))
    t = fliplab.samplers.points(3 * a.triangles, "normal", 2).reshape(-1, 3, 2)
    tv = median_time(lambda: fliplab.badness(t, "R"), a.runs)
    k = min(10 ** 5, len(t))
    tl = median_time(lambda: python_R(t[:k]), a.runs) * (len(t) / k)
    print("badness R of %d triangles: vectorised %.3f s, Python loop %.1f s (from %d): %.0fx"
          % (len(t), tv, tl, k, tl / tv))
    out = np.empty(len(t))
    mid = _measure_id("R")
    tk = median_time(lambda: check_contract(t, "triangle"), a.runs)
    te = median_time(lambda: _lib.lib.measure_eval_tris(mid, points_ptr(t), len(t),
                                                        ptr(out, ctypes.c_double)), a.runs)
    print("  of which: contract check %.3f s, C measure loop %.3f s, the rest %.3f s"
          % (tk, te, tv - tk - te))
    print("# load average %.2f at the end" % os.getloadavg()[0])


if __name__ == "__main__":
    main()
