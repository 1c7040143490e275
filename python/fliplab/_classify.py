"""_classify.py: the directed flip graph of given pentagons (`fliplab
classify`, classify/flipgraph.h) and a rule's verdicts (`fliplab rule`):
flip-graph types with their Wilson intervals, witnesses, the Delaunay
equivalence check on quadrilaterals and the census of other site sets, as
numbers rather than sentences."""
import ctypes
import numpy as np

from . import _lib
from ._arrays import as_coords, check_contract, points_ptr
from ._census import _c_rules, _rules, _tie_eps, census, table34
from ._lot import _u64
from ._rules import AC, BD, EITHER, Rule, as_rule, decide, _raise_user_errors
from ._samplers import SITE_SETS, _name, pentagons, quads

lib = _lib.lib
TYPES = ("I", "II", "III", "IV", "V")
_LETTER = {AC: "A", BD: "B", EITHER: "E"}


class Flipgraph(ctypes.Structure):
    """flipgraph (classify/flipgraph.h)."""
    _fields_ = [("dec", ctypes.c_int * 5), ("type", ctypes.c_int), ("nsinks", ctypes.c_int),
                ("sink", ctypes.c_int * 2), ("delaunay", ctypes.c_int)]


lib.flipgraph_classify_n.restype = ctypes.c_size_t
lib.flipgraph_classify_n.argtypes = [_lib.Point_p, ctypes.c_size_t, _lib.Rule_p, ctypes.c_int,
                                     ctypes.c_double, ctypes.c_int, ctypes.POINTER(Flipgraph),
                                     ctypes.POINTER(ctypes.c_int),
                                     ctypes.POINTER(ctypes.c_size_t)]
lib.geom_polyerr_str.restype = ctypes.c_char_p
lib.geom_polyerr_str.argtypes = [ctypes.c_int]
lib.study_wilson.restype = None
lib.study_wilson.argtypes = [ctypes.c_uint64, ctypes.c_uint64, ctypes.POINTER(ctypes.c_double),
                              ctypes.POINTER(ctypes.c_double)]
lib.siteflip_find_multi.restype = ctypes.c_int64
lib.siteflip_find_multi.argtypes = [_lib.Rule_p, ctypes.c_int, ctypes.c_int, ctypes.c_uint64,
                                    ctypes.c_uint64, ctypes.c_uint64, ctypes.c_double,
                                    _lib.Point_p]

CLASSIFY_DTYPE = np.dtype([("decisions", "U5"), ("type", "U3"), ("sinks", "i1", (2,)),
                           ("dt", "?")])


def classify(pentagons, rules="DT", tie_eps=None, threads=0):
    """The directed flip graph of every pentagon of an (m, 5, 2) array under
    every rule, as `fliplab classify --input FILE --rule RULES`: a
    structured (m, len(rules)) array (m, when rules is one name) with the
    columns of its CSV: decisions (five letters for Q_0..Q_4: A = diagonal
    v_{j+1}v_{j+3}, B = v_{j+2}v_{j+4}, E = either), type ("I".."V"), sinks
    (the fan indices of the sinks, -1 for none) and dt (type I with the
    Delaunay triangulation as sink).  Either orientation: a clockwise
    pentagon p1..p5 is renumbered v0..v4 = p1, p5, p4, p3, p2 as the program
    does.  A pentagon that is not strictly convex raises ValueError naming
    it and its vertex."""
    one = isinstance(rules, (str, Rule))
    rs = _rules(rules, None)
    eps = _tie_eps(tie_eps)
    v = np.array(as_coords(pentagons, "pentagons", (-1, 5, 2)), dtype=np.float64, order="C")
    check_contract(v, "pentagon")
    m, nr = len(v), len(rs)
    g = (Flipgraph * max(1, m * nr))()
    err, bad = ctypes.c_int(0), ctypes.c_size_t(0)
    k = lib.flipgraph_classify_n(points_ptr(v), m, _c_rules(rs, eps), nr, eps,
                                 _lib.threads_arg(threads), g,
                                 ctypes.byref(err), ctypes.byref(bad))
    if k < m:
        _raise_user_errors()
        raise ValueError("pentagon %d, vertex %d: %s"
                         % (k, bad.value, lib.geom_polyerr_str(err.value).decode()))
    _raise_user_errors()
    out = np.zeros(m * nr, dtype=CLASSIFY_DTYPE)
    for i in range(m * nr):
        x = g[i]
        s = [x.sink[j] if j < x.nsinks else -1 for j in range(2)]
        out[i] = ("".join(_LETTER[d] for d in x.dec), TYPES[x.type], s, bool(x.delaunay))
    out = out.reshape(m, nr)
    return out[:, 0] if one else out


def wilson(k, n):
    """The 95% Wilson score interval of k successes in n, in percent, as the
    program prints it (study_wilson)."""
    lo, hi = ctypes.c_double(), ctypes.c_double()
    lib.study_wilson(int(k), int(n), ctypes.byref(lo), ctypes.byref(hi))
    return lo.value, hi.value


def _witnesses(rule, samples, seed, eps, k, threads):
    """The first k pentagons of each type other than I (lowest indices):
    classify() on the stream, in blocks, until each type has k or the
    stream ends."""
    found = {t: [] for t in TYPES[1:]}
    block = 1 << 16
    for first in range(0, samples, block):
        if all(len(w) >= k for w in found.values()):
            break
        p = pentagons(min(block, samples - first), seed, first)
        c = classify(p, rule, eps, threads)
        for t in TYPES[1:]:
            for i in np.flatnonzero(c["type"] == t)[:k - len(found[t])]:
                found[t].append({"index": first + int(i), "pentagon": p[i],
                                 "decisions": str(c["decisions"][i]),
                                 "sinks": [int(s) for s in c["sinks"][i] if s >= 0]})
    return found


def _quad_check(rule, count, seed):
    """`fliplab rule`'s Delaunay-equivalence check on `count` random convex
    quadrilaterals: disagreements, ties of the rule, cocircular ones
    (DT either: skipped), the first disagreement's index (None)."""
    q = quads(count, seed)
    d, c = decide(q, "DT"), decide(q, rule)
    coc = d == EITHER
    dis = ~coc & (c != EITHER) & (c != d)
    first = int(np.argmax(dis)) if dis.any() else None
    return {"tested": count, "disagree": int(dis.sum()), "ties": int((~coc & (c == EITHER)).sum()),
            "cocircular": int(coc.sum()), "first": first}


def _sites(rule, spec, samples, seed, eps, threads):
    """The census part of the verdicts: for each (sampler, n) of spec, the
    counts and the first set with two or more sinks (its index, sites)."""
    out = []
    for kind, n in spec:
        c = census(n, samples, kind, seed, rules=[rule], tie_eps=eps, threads=threads)[0]
        w = None
        if c["multi_sink"] > 0:
            p = np.empty((n, 2), dtype=np.float64)
            s = lib.sampler_sites_find(_name(kind, SITE_SETS, "site sampler").encode())
            r = _c_rules([rule], eps)
            i = lib.siteflip_find_multi(r, s, n, seed, 0, samples, eps, points_ptr(p))
            _raise_user_errors()
            w = {"index": int(i), "sites": p} if i >= 0 else None
        out.append({"sampler": kind, "sites": n, "samples": samples, "tie": int(c["tie"]),
                    "no_sink": int(c["no_sink"]), "multi_sink": int(c["multi_sink"]),
                    "witness": w})
    return out


def _site_spec(sites):
    spec = []
    for s in sites:
        kind, n = (s.split(":", 1) if isinstance(s, str) else s)
        spec.append((_name(kind, SITE_SETS, "site sampler"), int(n)))
    return spec


def verdicts(rule, samples=100000, seed=1, witnesses=3, quads=100000, tie_eps=None, threads=0,
             sites=("disc:5", "convex:6"), site_samples=20000):
    """What `fliplab rule RULE` reports, as numbers: a dict with
    counts        the flip-graph types of `samples` random convex pentagons
                  (table34's stream `seed`): {"I": k, ..., "V": k, "dt": k}
    intervals     {type: (lo, hi)} 95% Wilson intervals in percent
    systematic, local   no counterexample (no type III, no type II)
    witnesses     {type: [{"index", "pentagon", "decisions", "sinks"}]} the
                  first `witnesses` pentagons of each type but I
    quads         the Delaunay-equivalence check (tested, disagree, ties,
                  cocircular, first), and delaunay_equivalent
    sites         per (sampler, n) of `sites`: the census counts (tie,
                  no_sink, multi_sink) and the first set with two LOTs."""
    r = as_rule(rule)
    samples, seed = _u64(samples, "samples", 1), _u64(seed, "seed")
    eps = _tie_eps(tie_eps)
    t = table34(samples, seed, rules=[r], tie_eps=eps, threads=threads)[0]
    counts = {ty: int(t["type_" + ty]) for ty in TYPES}
    counts["dt"] = int(t["dt"])
    res = {"rule": r.name, "samples": samples, "seed": seed, "tie_eps": eps, "counts": counts,
           "intervals": {ty: wilson(counts[ty], samples) for ty in TYPES + ("dt",)},
           "systematic": counts["III"] == 0, "local": counts["II"] == 0,
           "witnesses": _witnesses(r, samples, seed, eps, int(witnesses), threads)}
    if quads:
        qc = _quad_check(r, _u64(quads, "quads", 1), seed)
        res["quads"] = qc
        res["delaunay_equivalent"] = qc["disagree"] == 0 and qc["ties"] == 0
    res["sites"] = _sites(r, _site_spec(sites), _u64(site_samples, "site_samples", 1), seed,
                          eps, threads)
    return res
