"""test_leaks.py: nothing leaks.  A loop of calls (lot with every result
attribute, badness, decide, check, samplers, constrained runs and read_poly,
failing calls) must not grow
the C heap (glibc's mallinfo2: bytes in use by malloc) nor the Python heap
(tracemalloc) once warmed up; nor must the small objects the package asks
the library for (options, results), refused calls included."""
import ctypes
import gc
import tracemalloc

import numpy as np

import fliplab


class _Mallinfo2(ctypes.Structure):
    _fields_ = [(n, ctypes.c_size_t) for n in
                ("arena", "ordblks", "smblks", "hblks", "hblkhd", "usmblks", "fsmblks",
                 "uordblks", "fordblks", "keepcost")]


_libc = ctypes.CDLL(None)
_libc.mallinfo2.restype = _Mallinfo2


def c_heap():
    """Bytes malloc has handed out and not taken back (small and mmapped blocks)."""
    m = _libc.mallinfo2()
    return m.uordblks + m.hblkhd


def _round(p, q, tri, seg, poly):
    c = fliplab.lot(p, "P_1", segments=seg, keep_hull=True)
    c.constrained, c.check()
    pts, s, h = fliplab.read_poly(poly)
    fliplab.lot(pts, "DT", segments=s, holes=h)
    for bad in ({"segments": [[0, 2], [1, 3]]}, {"segments": s, "holes": [[1, 2]]}):
        try:
            fliplab.lot(pts, "DT", **bad)
        except ValueError:
            pass
    t = fliplab.lot(p, "P_1")
    t.neighbors, t.badness, t.total(), t.check()
    fliplab.lot(p, "DT", algorithm="sweep").neighbors
    fliplab.badness(tri, "R")
    fliplab.decide(q, "-alpha_inf", values=True)
    fliplab.samplers.pentagons(20)
    try:
        fliplab.lot(np.zeros((5, 2)), "DT")
    except ValueError:
        pass


def test_no_leak(tmp_path):
    poly = str(tmp_path / "sq.poly")
    with open(poly, "w") as f:          # a square with a square hole
        f.write("8 2 0 0\n0 0 0\n1 4 0\n2 4 4\n3 0 4\n4 1 1\n5 3 1\n6 3 3\n7 1 3\n"
                "8 0\n0 0 1\n1 1 2\n2 2 3\n3 3 0\n4 4 5\n5 5 6\n6 6 7\n7 7 4\n1\n0 2 2\n")
    p = fliplab.samplers.points(3000, "uniform", 1)
    q = fliplab.samplers.quads(500)
    tri = fliplab.samplers.points(3000, "normal", 2).reshape(-1, 3, 2)
    e = fliplab.lot(p, "R_1").triangles[::5, :2]           # edges of one triangulation
    args = (p, q, tri, e, poly)
    for _ in range(5):
        _round(*args)                         # warm up (arenas, registries, caches)
    gc.collect()
    tracemalloc.start()
    c0, (py0, _) = c_heap(), tracemalloc.get_traced_memory()
    for _ in range(60):
        _round(*args)
    gc.collect()
    c1, (py1, _) = c_heap(), tracemalloc.get_traced_memory()
    tracemalloc.stop()
    # One round allocates about 1 MB in C and in numpy; a leak of any one
    # result array would add 60 times that.
    assert c1 - c0 < 256 * 1024, "C heap grew by %d bytes over 60 rounds" % (c1 - c0)
    assert py1 - py0 < 256 * 1024, "Python heap grew by %d bytes over 60 rounds" % (py1 - py0)


def _verbs_round(p, poly):
    """Each object the package asks the library for and hands back: the run's
    options (also when lot_options_check refuses them), a check's result, a
    GOT's options and result (also when got_solve refuses the polygon)."""
    for bad in ({"algorithm": "flip", "order": "input"}, {"keep_hull": True}):
        try:
            fliplab.lot(p, "DT", **bad)
        except ValueError:
            pass
    fliplab.check(p, fliplab.lot(p, "DT").triangles, "P_1")
    fliplab.got(poly, "P_1", threads=1)
    try:
        fliplab.got(poly[[0, 2, 1, 3]], "P_1", threads=1)          # crossing: refused
    except ValueError:
        pass


def test_verbs_no_leak():
    """Thousands of the library's small objects (got_result, the smallest,
    is 200 bytes): a leak of any one of them grows the C heap by 400 KB."""
    p = fliplab.samplers.points(12, "uniform", 3)
    poly = fliplab.samplers.polygon(5, "vector", seed=2)
    for _ in range(20):
        _verbs_round(p, poly)
    gc.collect()
    c0 = c_heap()
    for _ in range(2000):
        _verbs_round(p, poly)
    gc.collect()
    c1 = c_heap()
    assert c1 - c0 < 64 * 1024, "C heap grew by %d bytes over 2000 rounds" % (c1 - c0)
