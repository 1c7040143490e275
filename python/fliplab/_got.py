"""_got.py: globally optimal triangulations of simple polygons (got/got.h)
with the certified verdict on uniqueness.  The options and the result go
through got.h's verbs (got_options_set_*, got_result_get_*): no layout of
either is restated here."""
from __future__ import annotations

import ctypes
from typing import Any

import numpy as np
import numpy.typing as npt

from . import _lib
from ._args import threads_arg, tie_eps_arg
from ._arrays import as_coords, points_ptr, ptr
from ._rules import Rule, as_rule, _raise_user_errors

lib = _lib.lib
_GETTERS = ((lib.got_result_get_i64, ctypes.c_int64),
            (lib.got_result_get_double, ctypes.c_double))
_FLAGS = ("has_runner_up", "unique", "simple", "cert_unique")
_NUMBERS = ("n", "key", "total", "key2", "total2", "gap", "rel_gap", "tie_eps", "cert_err",
            "cert_err2", "cert_gap", "cert_bound", "seconds", "threads", "ntri") + _FLAGS
# a point set's statistics (got_points_solve; 0 for a polygon)
_POINT_STATS = ("candidates", "edges", "certain", "rounds", "faces", "faces_left",
                "faces_general", "largest_face", "face_states", "seconds_candidates",
                "seconds_lmt", "seconds_faces", "seconds_solve", "seconds_delaunay")
SKELETONS = ("auto", "all", "lmt", "delaunay")   # got_skeleton's names, in its order


class Got:
    """The result of got(): the optimal triangulation of the polygon.

    Parameters
    ----------
    res : int
        The library's got_result (read by name, not kept).
    mapping : ndarray of int
        Vertex indices of the reversed polygon in the input's numbering.
    reversed_ : bool
        The input was clockwise and was reversed keeping vertex 0.
    rule : Rule

    Attributes
    ----------
    triangles : ndarray of int32, shape (n-2, 3)
        Vertex indices of the input (i < k < j of the anticlockwise polygon;
        for a clockwise input, reversed keeping vertex 0 as the program
        does, mapped back).
    badness : ndarray of float64, shape (n-2,)
        Each triangle's badness.
    total, key : float
        The optimal total, in badness units and in key space (docs/joints.md).
    total_text : str
        The total as the program prints it ("exp(K)" when l_0's product
        leaves the doubles).
    runner_up, runner_up_key : float or None
        The second best total over the other triangulations (None for n = 3).
    gap, rel_gap : float
    unique : bool
        The runner-up's gap exceeds tie_eps.
    certified_unique : bool
        The certified verdict: the optimum is proved unique.
    cert_err, cert_err2, cert_bound, cert_gap : float
    cert_why : str or None
        The certificate (docs/got.md).
    simple : bool
        Solved as a non-convex simple polygon.
    reversed : bool
        The input was clockwise.
    n, tie_eps, seconds, threads
    points : bool
        A point set's GOT (got_points): then triangles are point indices
        i < k < j, the runner-up is over the triangulations holding the
        skeleton, and the statistics below are set (0 for a polygon).
    skeleton : str or None
        "lmt" or "all".
    candidates, edges, certain, rounds : int
        The skeleton's candidate edges, edges kept, certain edges, rounds.
    faces, faces_left, faces_general, largest_face, face_states : int
        Bounded faces of the certain edges, those with more than a triangle,
        those with points inside or not simple, the largest's points, the
        exact search's states.
    seconds_candidates, seconds_lmt, seconds_faces, seconds_solve : float
    seconds_delaunay : float
        The Delaunay triangulation's time (skeleton "delaunay"; else 0).
    """

    def __init__(self, res: Any, mapping: npt.NDArray[np.int64], reversed_: bool,
                 rule: Rule) -> None:
        v = {f: _lib.get_value(res, f, _GETTERS) for f in _NUMBERS}
        self.rule = rule
        self.n = int(v["n"])
        tri = np.empty((int(v["ntri"]), 3), dtype=np.int32)
        self.badness = np.empty(len(tri), dtype=np.float64)
        lib.got_result_get_triangles(res, ptr(tri, ctypes.c_int32),
                                     ptr(self.badness, ctypes.c_double))
        self.triangles = mapping[tri].astype(np.int32) if reversed_ else tri
        self.total, self.key = v["total"], v["key"]
        buf = ctypes.create_string_buffer(64)
        lib.got_format_total(res, self.key, buf, 64)
        self.total_text = buf.value.decode()
        self.runner_up = v["total2"] if v["has_runner_up"] else None
        self.runner_up_key = v["key2"] if v["has_runner_up"] else None
        self.gap, self.rel_gap, self.unique = v["gap"], v["rel_gap"], bool(v["unique"])
        self.tie_eps = v["tie_eps"]
        self.certified_unique = bool(v["cert_unique"])
        self.cert_err, self.cert_err2 = v["cert_err"], v["cert_err2"]
        self.cert_gap, self.cert_bound = v["cert_gap"], v["cert_bound"]
        why = lib.got_result_get_text(res, b"cert_why")
        self.cert_why = why.decode() if why else None
        self.simple = bool(v["simple"])
        self.reversed = bool(reversed_)
        self.seconds, self.threads = v["seconds"], int(v["threads"])
        self.points = bool(_lib.get_value(res, "points", _GETTERS))
        sk = int(_lib.get_value(res, "skeleton", _GETTERS))
        self.skeleton = SKELETONS[sk] if self.points else None
        for f in _POINT_STATS:
            x = _lib.get_value(res, f, _GETTERS)
            setattr(self, f, x if f.startswith("seconds") else int(x))

    def __repr__(self) -> str:
        return ("<fliplab.Got GOT(%s) of %s: total %s, %s>"
                % (self.rule.name, "%d points" % self.n if self.points else "a %d-gon" % self.n,
                   self.total_text,
                   "certified unique" if self.certified_unique else
                   "unique" if self.unique else "not unique"))


def _orient(p: npt.NDArray[np.float64]) -> tuple[npt.NDArray[np.float64], bool]:
    """The polygon as got_solve takes it: a clockwise simple one reversed
    keeping vertex 0 (geom_simple_polygon_check on a copy); else as given,
    for got_solve to refuse in its own words."""
    q = p.copy()
    bad, bad2, rev = ctypes.c_size_t(), ctypes.c_size_t(), ctypes.c_int()
    ok = len(p) >= 3 and lib.geom_simple_polygon_check(
        points_ptr(q), len(p), ctypes.byref(bad), ctypes.byref(bad2), ctypes.byref(rev)) == 0
    return (q, True) if ok and rev.value else (p, False)


def got(polygon: npt.ArrayLike, rule: str | Rule, threads: int = 0,
        tie_eps: float | None = None) -> Got:
    """GOT(rule) of a simple polygon: the triangulation minimising the rule's
    total badness, by the dynamic programme of got/got.h, with the
    runner-up and the certified verdict, as the program's `got --polygon`.

    Parameters
    ----------
    polygon : array_like, shape (n, 2)
        The vertices in order, anticlockwise (a clockwise polygon is
        reversed keeping vertex 0, as the program does).
    rule : str or Rule
        A triangle-based rule: a Rule or a name MEASURE_JOINT (not "DT",
        ES:SHAPE or a plugin's quadrilateral rule).
    threads : int
        0 (all cores) or 1 .. 1024; the result does not depend on it.
    tie_eps : float, optional
        The relative tie tolerance of the uniqueness verdict (default the
        rule's).

    Returns
    -------
    Got

    Raises
    ------
    ValueError
        A rule that is not triangle-based, a polygon that is not simple or
        outside the coordinate contract (the library's message), a bad
        keyword; a bad value of a user measure.
    MemoryError
        The programme's tables do not fit in memory.
    """
    r = as_rule(rule)
    if not r.is_triangle:
        raise ValueError("rule: got needs a triangle-based rule (MEASURE_JOINT), not %s"
                         % r.name)
    eps = tie_eps_arg(tie_eps, r.tie_eps)
    nthreads = threads_arg(threads)
    p = as_coords(polygon, "polygon", (-1, 2))
    n = len(p)
    use, rev = _orient(p)
    e = _lib.errbuf()
    if lib.got_check_memory(n, r._c.measure, e, _lib.ERRLEN) != 0:
        raise MemoryError(_lib.text(e))
    return _solve(lambda opt, res: lib.got_solve(points_ptr(use), n, ctypes.byref(r._c), opt,
                                                 res, e, _lib.ERRLEN),
                  nthreads, eps, e, lambda res: Got(res, (n - np.arange(n)) % n, rev, r))


def _solve(call: Any, nthreads: int, eps: float, e: Any, make: Any) -> Got:
    """call(opt, res) (got_solve or got_points_solve) with the options set, e its error
    buffer; make(res) the result.  Errors raised as the library words them."""
    opt, res = lib.got_options_new(), lib.got_result_new()
    try:
        if not opt or not res:
            raise MemoryError("got: out of memory")
        lib.got_options_set_threads(opt, nthreads)
        lib.got_options_set_tie_eps(opt, eps)
        if call(opt, res) != 0:
            _raise_user_errors()        # a Python measure's own error comes first
            msg = _lib.text(e)
            raise (MemoryError if "out of memory" in msg else ValueError)(msg)
        _raise_user_errors()
        return make(res)
    finally:
        lib.got_options_free(opt)
        lib.got_result_delete(res)


def got_points(points: npt.ArrayLike, rule: str | Rule, skeleton: str = "auto",
               threads: int = 0, tie_eps: float | None = None) -> Got:
    """GOT(rule) of a point set: the triangulation of the points minimising the
    rule's total badness, exactly, for a sum rule (joint l_1, l_2, l_0, l_-1
    or a power mean), as the program's `got --points` (docs/got.md, "Point
    sets"): the skeleton's certain edges, then each face they leave solved
    exactly.

    Parameters
    ----------
    points : array_like, shape (n, 2)
        Distinct points, not all collinear, within the coordinate contract.
    rule : str or Rule
        A sum rule: a Rule or a name MEASURE_JOINT (e.g. "P_1", the
        minimum-weight triangulation; not "DT", ES:SHAPE or a joint min or
        max).
    skeleton : str
        One of SKELETONS: "lmt" (the LMT-skeleton), "all" (every edge: tiny
        sets), "delaunay" (the rules whose GOT is a Delaunay triangulation
        by a theorem: R_1, R_2, R_0, R_-1, -r_1, abc_1; lot's exact Delaunay
        triangulation, certified, its subdivision's edges certain), "auto"
        (delaunay where it applies, else lmt).
    threads : int
        0 (all cores) or 1 .. 1024; the result does not depend on it.
    tie_eps : float, optional
        The relative tie tolerance of the heuristic verdict (default the
        rule's); the certified verdict does not use it.

    Returns
    -------
    Got
        With points True: triangles are point indices (n rows of `points`),
        and the skeleton's and faces' statistics.

    Raises
    ------
    ValueError
        A rule that is no sum rule, duplicate points (both rows named),
        collinear points, a coordinate outside the contract, a bad keyword,
        skeleton "delaunay" for a rule whose GOT need not be Delaunay, or is
        Delaunay on samples only (-r/R_1, -r2/A_0).
    MemoryError
        The points do not fit in memory.
    """
    r = as_rule(rule)
    sk = lib.got_skeleton_find(skeleton.encode()) if isinstance(skeleton, str) else -1
    if sk < 0:
        raise ValueError("skeleton: expected one of %s, got %r" % (", ".join(SKELETONS),
                                                                   skeleton))
    eps = tie_eps_arg(tie_eps, r.tie_eps)
    nthreads = threads_arg(threads)
    p = as_coords(points, "points", (-1, 2))
    e = _lib.errbuf()
    if lib.got_points_check_memory(len(p), e, _lib.ERRLEN) != 0:
        raise MemoryError(_lib.text(e))
    return _solve(lambda opt, res: lib.study_got_points(points_ptr(p), len(p),
                                                        ctypes.byref(r._c), opt, sk, res, e,
                                                        _lib.ERRLEN),
                  nthreads, eps, e, lambda res: Got(res, np.arange(len(p)), False, r))
