"""_got.py: globally optimal triangulations of simple polygons (got/got.h)
with the certified verdict on uniqueness."""
import ctypes
import numpy as np

from . import _lib
from ._arrays import as_coords, points_ptr
from ._rules import as_rule, tie_eps_arg, _raise_user_errors

lib = _lib.lib


class GotTriangle(ctypes.Structure):
    _fields_ = [("i", ctypes.c_int), ("k", ctypes.c_int), ("j", ctypes.c_int),
                ("badness", ctypes.c_double)]


class GotOptions(ctypes.Structure):
    _fields_ = [("threads", ctypes.c_int), ("tie_eps", ctypes.c_double)]


class GotResult(ctypes.Structure):
    _fields_ = [("n", ctypes.c_size_t), ("measure", ctypes.c_int), ("joint", ctypes.c_int),
                ("sign", ctypes.c_int), ("key", ctypes.c_double), ("total", ctypes.c_double),
                ("has_runner_up", ctypes.c_int), ("key2", ctypes.c_double),
                ("total2", ctypes.c_double), ("gap", ctypes.c_double),
                ("rel_gap", ctypes.c_double), ("unique", ctypes.c_int),
                ("tie_eps", ctypes.c_double), ("tri", ctypes.POINTER(GotTriangle)),
                ("ntri", ctypes.c_size_t), ("simple", ctypes.c_int),
                ("cert_err", ctypes.c_double), ("cert_err2", ctypes.c_double),
                ("cert_gap", ctypes.c_double), ("cert_bound", ctypes.c_double),
                ("cert_unique", ctypes.c_int), ("cert_why", ctypes.c_char_p),
                ("cert_rho", ctypes.c_double), ("cert_alpha", ctypes.c_double),
                ("seconds", ctypes.c_double), ("threads", ctypes.c_int)]


lib.got_solve.restype = ctypes.c_int
lib.got_solve.argtypes = [_lib.Point_p, ctypes.c_size_t, _lib.Rule_p,
                          ctypes.POINTER(GotOptions), ctypes.POINTER(GotResult),
                          ctypes.c_char_p, ctypes.c_size_t]
lib.got_result_free.restype = None
lib.got_result_free.argtypes = [ctypes.POINTER(GotResult)]
lib.got_check_memory.restype = ctypes.c_int
lib.got_check_memory.argtypes = [ctypes.c_size_t, ctypes.c_int, ctypes.c_char_p,
                                 ctypes.c_size_t]
lib.got_format_total.restype = None
lib.got_format_total.argtypes = [ctypes.POINTER(GotResult), ctypes.c_double, ctypes.c_char_p,
                                 ctypes.c_size_t]
lib.geom_simple_polygon_check.restype = ctypes.c_int
lib.geom_simple_polygon_check.argtypes = [_lib.Point_p, ctypes.c_size_t,
                                          ctypes.POINTER(ctypes.c_size_t),
                                          ctypes.POINTER(ctypes.c_size_t),
                                          ctypes.POINTER(ctypes.c_int)]


class Got:
    """The result of got(): the optimal triangulation of the polygon.

    triangles  (n-2, 3) int32 vertex indices of the input (i < k < j of the
               anticlockwise polygon; for a clockwise input, reversed
               keeping vertex 0 as the program does, mapped back)
    badness    (n-2,) each triangle's badness
    total, key the optimal total (badness units; key space, joints.md)
    total_text the total as the program prints it ("exp(K)" when l_0's
               product leaves the doubles)
    runner_up  the second best total over the other triangulations (None for n = 3)
    gap, rel_gap, unique   the runner-up's gap and the verdict within tie_eps
    certified_unique       the certified verdict: the optimum is proved unique
    cert_err, cert_bound, cert_gap, cert_why   the certificate (docs/got.md)
    simple     solved as a non-convex simple polygon; reversed: the input was clockwise."""

    def __init__(self, res, mapping, reversed_, rule):
        t = res.tri
        self.rule = rule
        self.n = res.n
        tri = np.array([[t[q].i, t[q].k, t[q].j] for q in range(res.ntri)], dtype=np.int32)
        self.triangles = mapping[tri] if reversed_ else tri
        self.badness = np.array([t[q].badness for q in range(res.ntri)], dtype=np.float64)
        self.total, self.key = res.total, res.key
        buf = ctypes.create_string_buffer(64)
        lib.got_format_total(ctypes.byref(res), res.key, buf, 64)
        self.total_text = buf.value.decode()
        self.runner_up = res.total2 if res.has_runner_up else None
        self.runner_up_key = res.key2 if res.has_runner_up else None
        self.gap, self.rel_gap, self.unique = res.gap, res.rel_gap, bool(res.unique)
        self.tie_eps = res.tie_eps
        self.certified_unique = bool(res.cert_unique)
        self.cert_err, self.cert_err2 = res.cert_err, res.cert_err2
        self.cert_gap, self.cert_bound = res.cert_gap, res.cert_bound
        self.cert_why = res.cert_why.decode() if res.cert_why else None
        self.simple = bool(res.simple)
        self.reversed = bool(reversed_)
        self.seconds, self.threads = res.seconds, res.threads

    def __repr__(self):
        return ("<fliplab.Got GOT(%s) of a %d-gon: total %s, %s>"
                % (self.rule.name, self.n, self.total_text,
                   "certified unique" if self.certified_unique else
                   "unique" if self.unique else "not unique"))


def got(polygon, rule, threads=0, tie_eps=None):
    """GOT(rule) of a simple polygon, an (n, 2) array of vertices in order
    (anticlockwise; a clockwise one is reversed keeping vertex 0, as
    `fliplab got --polygon` does): the triangulation minimising the rule's
    total badness, by the dynamic programme of got/got.h, with the runner-up
    and the certified verdict.  The rule must be triangle-based."""
    r = as_rule(rule)
    if not r.is_triangle:
        raise ValueError("got needs a triangle-based rule (MEASURE_JOINT), not %s" % r.name)
    eps = tie_eps_arg(tie_eps, r.tie_eps)
    p = as_coords(polygon, "polygon", (-1, 2))
    n = len(p)
    q = p.copy()
    bad, bad2, rev = ctypes.c_size_t(), ctypes.c_size_t(), ctypes.c_int()
    ok = n >= 3 and lib.geom_simple_polygon_check(points_ptr(q), n, ctypes.byref(bad),
                                                  ctypes.byref(bad2), ctypes.byref(rev)) == 0
    use = q if ok and rev.value else p        # reversed keeping vertex 0
    mapping = (n - np.arange(n)) % n
    e = _lib.errbuf()
    if lib.got_check_memory(n, r._c.measure, e, _lib.ERRLEN) != 0:
        raise MemoryError(_lib.text(e))
    res = GotResult()
    opt = GotOptions(_lib.threads_arg(threads), eps)
    if lib.got_solve(points_ptr(use), n, ctypes.byref(r._c), ctypes.byref(opt),
                     ctypes.byref(res), e, _lib.ERRLEN) != 0:
        _raise_user_errors()        # a Python measure's own error comes first
        msg = _lib.text(e)
        raise (MemoryError if "out of memory" in msg else ValueError)(msg)
    try:
        _raise_user_errors()
        return Got(res, mapping, ok and rev.value, r)
    finally:
        lib.got_result_free(ctypes.byref(res))
