"""test_leaks.py: nothing leaks.  A loop of calls (lot with every result
attribute, badness, decide, check, samplers, a failing call) must not grow
the C heap (glibc's mallinfo2: bytes in use by malloc) nor the Python heap
(tracemalloc) once warmed up."""
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


def _round(p, q, tri):
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


def test_no_leak():
    p = fliplab.samplers.points(3000, "uniform", 1)
    q = fliplab.samplers.quads(500)
    tri = fliplab.samplers.points(3000, "normal", 2).reshape(-1, 3, 2)
    for _ in range(5):
        _round(p, q, tri)                          # warm up (arenas, registries, caches)
    gc.collect()
    tracemalloc.start()
    c0, (py0, _) = c_heap(), tracemalloc.get_traced_memory()
    for _ in range(60):
        _round(p, q, tri)
    gc.collect()
    c1, (py1, _) = c_heap(), tracemalloc.get_traced_memory()
    tracemalloc.stop()
    # One round allocates about 1 MB in C and in numpy; a leak of any one
    # result array would add 60 times that.
    assert c1 - c0 < 256 * 1024, "C heap grew by %d bytes over 60 rounds" % (c1 - c0)
    assert py1 - py0 < 256 * 1024, "Python heap grew by %d bytes over 60 rounds" % (py1 - py0)
