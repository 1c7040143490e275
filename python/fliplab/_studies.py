"""_studies.py: the lab's studies of a rule (studies/study.h), as numbers:
verdicts() is what `fliplab rule` prints and compare_got() what `fliplab
lot --compare GOT` prints, from the same library calls as the program.
This module only checks the arguments and reads the results, by the names
the library gives their fields (study_field_name): no layout is mirrored."""
from __future__ import annotations

import ctypes
from typing import Any, Iterable

import numpy as np
import numpy.typing as npt

from . import _lib
from ._args import threads_arg, u64
from ._arrays import points_ptr, ptr
from ._census import _c_rules, _tie_eps
from ._classify import TYPES, classify
from ._lot import Triangulation
from ._mirrors import FlipgraphRun, GeomPslg, SITEFLIP_MAX_SITES
from ._rules import Rule, as_rule, _raise_user_errors
from .samplers import SITE_SETS, _name, pentagons

lib = _lib.lib
WITNESS_MAX = 100     # STUDY_WITNESS_MAX (studies/study.h): witnesses per type


# the results' flags (0 or 1 in C), returned as bool
_FLAGS = ("systematic", "local", "sink_bug", "always_delaunay", "equivalent", "has_witness",
          "ring", "certified", "equal", "below", "same", "got_is_cdt", "failed")


class _Result:
    """A study_KIND on the C heap (study_KIND_new), deleted when done."""

    def __init__(self, kind: str) -> None:
        self.kind = kind
        self.ptr = getattr(lib, "study_%s_new" % kind)()
        if not self.ptr:
            raise MemoryError("%s: out of memory" % kind)

    def __enter__(self) -> _Result:
        return self

    def __exit__(self, *exc: Any) -> None:
        getattr(lib, "study_%s_delete" % self.kind)(self.ptr)

    def read(self) -> dict[str, Any]:
        """Every field readable by name (study_KIND_field): counts and
        indices as int (a list for an array), flags as bool, reals as float;
        the fields that have verbs of their own are left to them."""
        get_u64 = getattr(lib, "study_%s_get_u64" % self.kind)
        get_double = getattr(lib, "study_%s_get_double" % self.kind, None)
        out: dict[str, Any] = {}
        for name in _lib.c_names(getattr(lib, "study_%s_field" % self.kind)):
            v, d, vals = ctypes.c_uint64(), ctypes.c_double(), []
            while get_u64(self.ptr, name.encode(), len(vals), ctypes.byref(v)) == 0:
                vals.append(v.value)
            if vals:
                out[name] = bool(vals[0]) if name in _FLAGS else vals[0] if len(vals) == 1 \
                    else vals
            elif get_double and get_double(self.ptr, name.encode(), ctypes.byref(d)) == 0:
                out[name] = d.value
        return out


def wilson(k: int, n: int) -> tuple[float, float]:
    """The 95% Wilson score interval of k successes in n, in percent, as the
    program prints it (study_wilson).

    Parameters
    ----------
    k, n : int
        Successes and trials, 0 <= k <= n (n = 0: the whole of [0, 100]).

    Returns
    -------
    (lo, hi) : tuple of float

    Raises
    ------
    ValueError
        k or n no integer in [0, 2^64), or k > n.
    """
    n = u64(n, "n")
    k = u64(k, "k")
    if k > n:
        raise ValueError("k: at most n = %d, got %d" % (n, k))
    lo, hi = ctypes.c_double(), ctypes.c_double()
    lib.study_wilson(k, n, ctypes.byref(lo), ctypes.byref(hi))
    return lo.value, hi.value


def _witnesses(v: Any, seed: int, eps: float, r: Rule, threads: int) -> dict[str, list]:
    """The witness pentagons of each type but I, with their decisions and
    sinks (classify() on them, as the program re-derives its lines)."""
    found: dict[str, list] = {}
    for t, ty in enumerate(TYPES[1:], start=1):
        idx = []
        while (i := lib.study_verdict_witness(v, t, len(idx))) >= 0:
            idx.append(i)
        p = np.array([pentagons(1, seed, i)[0] for i in idx]).reshape(-1, 5, 2)
        c = classify(p, r, eps, threads) if idx else []
        found[ty] = [{"index": i, "pentagon": p[j], "decisions": str(c["decisions"][j]),
                      "sinks": [int(s) for s in c["sinks"][j] if s >= 0]}
                     for j, i in enumerate(idx)]
    return found


def _pentagons(r: Rule, samples: int, seed: int, eps: float, k: int,
               threads: int) -> dict[str, Any]:
    """study_pentagons: counts, intervals, verdicts and witnesses."""
    run = FlipgraphRun(seed=seed, first=0, count=samples, tie_eps=eps, threads=threads)
    with _Result("verdict") as v:
        if lib.study_pentagons(_c_rules([r], eps), 1, ctypes.byref(run), k, v.ptr) != 0:
            _raise_user_errors()
            raise MemoryError("verdicts: out of memory")
        _raise_user_errors()
        f = v.read()
        lo, hi, rows = ctypes.c_double(), ctypes.c_double(), {}
        for row, key in enumerate(TYPES + ("dt",)):
            lib.study_verdict_interval(v.ptr, row, ctypes.byref(lo), ctypes.byref(hi))
            rows[key] = (lo.value, hi.value)
        res = {"counts": dict(zip(TYPES + ("dt",), f["type"] + [f["dt"]])), "intervals": rows,
               "witnesses": _witnesses(v.ptr, seed, eps, r, threads)}
    res.update({key: f[key] for key in ("decided", "systematic", "local", "sink_bug",
                                        "always_delaunay")})
    return res


def _quads(r: Rule, count: int, seed: int, threads: int) -> dict[str, Any]:
    """study_quads: the Delaunay-equivalence check (first: None when the
    rule never disagrees)."""
    e = _lib.errbuf()
    with _Result("quadcheck") as q:
        if lib.study_quads(_c_rules([r], r.tie_eps), seed, count, threads, q.ptr, e,
                           _lib.ERRLEN) != 0:
            raise ValueError(_lib.text(e))
        _raise_user_errors()
        f = q.read()
    f["first"] = f["first"] if f["disagree"] else None
    return f


def _site_spec(sites: Iterable[Any]) -> list[tuple[str, int]]:
    spec = []
    for s in sites:
        kind, n = (s.split(":", 1) if isinstance(s, str) else s)
        spec.append((_name(kind, SITE_SETS, "sites", "site sampler"), int(n)))
    return spec


def _sites(r: Rule, spec: list[tuple[str, int]], samples: int, seed: int, eps: float,
           threads: int) -> list[dict[str, Any]]:
    """study_sites for each (sampler, n) of spec: the census counts and the
    first set with two or more sinks (its index and sites)."""
    out = []
    for kind, n in spec:
        e, p = _lib.errbuf(), np.empty((SITEFLIP_MAX_SITES, 2), dtype=np.float64)
        k = lib.sampler_sites_find(kind.encode())
        with _Result("sitecheck") as s:
            if lib.study_sites(_c_rules([r], eps), k, n, seed, samples, eps, threads, s.ptr, e,
                               _lib.ERRLEN) != 0:
                _raise_user_errors()
                raise ValueError(_lib.text(e))
            _raise_user_errors()
            f = s.read()
            m = lib.study_sitecheck_sites(s.ptr, points_ptr(p))
        f["sampler"], f["sites"] = kind, f.pop("n")
        f["witness"] = {"index": f["witness"], "sites": p[:m].copy()} \
            if f.pop("has_witness") else None
        out.append(f)
    return out


def verdicts(rule: str | Rule, samples: int = 100000, seed: int = 1, witnesses: int = 3,
             quads: int = 100000, tie_eps: float | None = None, threads: int = 0,
             sites: Iterable[Any] = ("disc:5", "convex:6"),
             site_samples: int = 20000) -> dict[str, Any]:
    """What `fliplab rule RULE` reports, as numbers, from the program's own
    library calls (study_pentagons, study_quads, study_sites).

    Parameters
    ----------
    rule : str or Rule
        A rule name in the forms DT, MEASURE_JOINT or ES:SHAPE (or a
        plugin's quadrilateral rule), or a Rule; its tie tolerance is
        tie_eps's.
    samples : int
        Random convex pentagons (table34's stream `seed`), at least 1.
    seed : int
    witnesses : int
        Witness pentagons kept per type but I, 0 .. 100.
    quads : int
        Random convex quadrilaterals of the Delaunay-equivalence check (0:
        none).
    tie_eps : float, optional
    threads : int
        0 (all cores) or 1 .. 1024; no number depends on it.
    sites : iterable of "SAMPLER:N" or (sampler, n)
        The site sets of the census part.
    site_samples : int
        Sets per entry of sites.

    Returns
    -------
    dict
        counts ({"I": k, ..., "V": k, "dt": k}), intervals ({type: (lo,
        hi)}, 95% Wilson, percent), decided (pentagons of types I-IV),
        systematic (no type III), local (no type II), sink_bug (type IV
        under a triangle rule), always_delaunay, witnesses ({type: [{index,
        pentagon, decisions, sinks}]}); quads (tested, disagree, ties,
        cocircular, decided, equivalent, first, choice, dt, ac, bd) and
        delaunay_equivalent when quads > 0; sites (per entry: sampler,
        sites, samples, tie, no_sink, one_sink, multi_sink, sink_dt,
        decided, systematic, witness {index, sites} or None).

    Raises
    ------
    ValueError
        A bad rule, keyword or site set (the library's message or one
        naming the keyword).
    MemoryError
        Out of memory.
    """
    r = as_rule(rule)
    samples, seed = u64(samples, "samples", 1), u64(seed, "seed")
    eps = _tie_eps(tie_eps)
    r = Rule(r, tie_eps=eps)
    k = u64(witnesses, "witnesses")
    if k > WITNESS_MAX:
        raise ValueError("witnesses: at most %d, got %d" % (WITNESS_MAX, k))
    threads = threads_arg(threads)
    spec, site_samples = _site_spec(sites), u64(site_samples, "site_samples", 1)
    res: dict[str, Any] = {"rule": r.name, "samples": samples, "seed": seed, "tie_eps": eps}
    res.update(_pentagons(r, samples, seed, eps, k, threads))
    if quads:
        res["quads"] = _quads(r, u64(quads, "quads", 1), seed, threads)
        res["delaunay_equivalent"] = res["quads"]["equivalent"]
    res["sites"] = _sites(r, spec, site_samples, seed, eps, threads)
    return res


def compare_got(t: Triangulation, threads: int = 0) -> dict[str, Any]:
    """A LOT against the GOT of its polygon, as `fliplab lot --compare GOT`
    (study_lot_got): for an unconstrained run the points' hull (the points
    must be in strictly convex position), for a constrained one the simple
    polygon its segments form (one closed ring through every point, no
    holes, the outside removed).

    Parameters
    ----------
    t : Triangulation
        lot()'s result under a triangle-based rule.
    threads : int
        The GOT's threads: 0 (all cores) or 1 .. 1024; no number depends on
        it.

    Returns
    -------
    dict
        lot_total, got_total (badness units), lot_key, got_key (key space),
        lot_text, got_text (as the program prints them), rel (relative
        difference, rule_gap), equal, below (LOT < GOT: impossible),
        certified (told by certified error bounds; else uncertified says
        why and the rule's tie tolerance decided), triangles_lot,
        triangles_got, triangles_shared, edges_*, same, got_is_cdt (the
        rule's GOT is the CDT), failed (below, or a CDT rule's other
        triangles with another total), ring (the polygon of a constrained
        run), n (its vertices), got_triangles ((n - 2, 3) int32 input
        indices).

    Raises
    ------
    TypeError
        t is no Triangulation.
    ValueError
        A quadrilateral rule, points not in convex position, segments that
        form no simple polygon (the library's message).
    """
    if not isinstance(t, Triangulation):
        raise TypeError("compare_got: expected a Triangulation (lot()'s result), got %r"
                        % type(t).__name__)
    threads = threads_arg(threads)
    seg = np.ascontiguousarray(t.segments if t.segments is not None else np.empty((0, 2)),
                               dtype=np.uint32)
    hol = np.ascontiguousarray(t.holes if t.holes is not None else np.empty((0, 2)),
                               dtype=np.float64)
    pts = np.ascontiguousarray(t.points, dtype=np.float64)
    g = GeomPslg(points_ptr(pts), len(pts), ptr(seg, ctypes.c_uint32), len(seg),
                 points_ptr(hol), len(hol))
    tri = np.ascontiguousarray(t.triangles).view(np.uint32)
    hull = np.ascontiguousarray(t.hull).view(np.uint32)
    e = _lib.errbuf()
    with _Result("gotcheck") as c:
        if lib.study_lot_got(ctypes.byref(g), ptr(hull, ctypes.c_uint32), len(hull),
                             ptr(tri, ctypes.c_uint32), len(tri),
                             _c_rules([t.rule], t.rule.tie_eps), threads, c.ptr, e,
                             _lib.ERRLEN) != 0:
            _raise_user_errors()
            msg = _lib.text(e)
            raise (MemoryError if "out of memory" in msg else ValueError)(msg)
        _raise_user_errors()
        f = c.read()
        for name in ("lot_text", "got_text", "uncertified"):
            f[name] = lib.study_gotcheck_get_text(c.ptr, name.encode()).decode() or None
        got, d = lib.study_gotcheck_got(c.ptr), ctypes.c_double()
        for name in ("key", "total"):
            lib.got_result_get_double(got, name.encode(), ctypes.byref(d))
            f["got_" + name] = d.value
        f["got_triangles"] = np.ctypeslib.as_array(lib.study_gotcheck_triangles(c.ptr),
                                                   (f["n"] - 2, 3)).astype(np.int32)
    return f
