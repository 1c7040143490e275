"""_census.py: table 3.4 (directed flip graphs of random convex pentagons,
classify/flipgraph.h) and the census of random site sets
(classify/siteflip.h), as numpy structured arrays of counts with the run's
metadata: the numbers of the program's CSV (`table34 --format csv`,
`census`) for the same rules, samples and seed."""
import ctypes
import numpy as np

from . import _lib
from ._lot import _u64
from ._arrays import cstr
from ._rules import Rule, as_rule, tie_eps_arg, _raise_user_errors
from ._samplers import SITE_SETS, PENTAGON_SAMPLERS, _name

lib = _lib.lib

ProgressFn = ctypes.CFUNCTYPE(None, ctypes.c_uint64, ctypes.c_uint64, ctypes.c_void_p)


class FlipgraphCounts(ctypes.Structure):
    _fields_ = [("samples", ctypes.c_uint64), ("type", ctypes.c_uint64 * 5),
                ("dt", ctypes.c_uint64)]


class FlipgraphRun(ctypes.Structure):
    _fields_ = [("seed", ctypes.c_uint64), ("first", ctypes.c_uint64),
                ("count", ctypes.c_uint64), ("tie_eps", ctypes.c_double),
                ("threads", ctypes.c_int), ("progress", ProgressFn),
                ("progress_ctx", ctypes.c_void_p), ("each", ctypes.c_void_p),
                ("each_ctx", ctypes.c_void_p), ("sampler", _lib.PentagonFn)]


class SiteflipCounts(ctypes.Structure):
    _fields_ = [(n, ctypes.c_uint64) for n in
                ("samples", "tie", "no_sink", "one_sink", "multi_sink", "sink_dt", "sinks",
                 "max_sinks", "gap_units")]


lib.flipgraph_tally_run.restype = ctypes.c_int
lib.flipgraph_tally_run.argtypes = [_lib.Rule_p, ctypes.c_int, ctypes.POINTER(FlipgraphRun),
                                    ctypes.POINTER(FlipgraphCounts)]
lib.siteflip_census.restype = ctypes.c_int
lib.siteflip_census.argtypes = [_lib.Rule_p, ctypes.c_int, ctypes.c_int, ctypes.c_int,
                                ctypes.c_uint64, ctypes.c_uint64, ctypes.c_uint64,
                                ctypes.c_double, ctypes.c_int, ctypes.c_size_t,
                                ctypes.POINTER(SiteflipCounts), ProgressFn, ctypes.c_void_p,
                                ctypes.POINTER(ctypes.c_int), ctypes.c_char_p, ctypes.c_size_t]
lib.rule_list_triangle.restype = ctypes.c_int
lib.rule_list_triangle.argtypes = [ctypes.POINTER(ctypes.c_int), ctypes.c_int, _lib.Rule_p,
                                   ctypes.c_int]
_table34_ids = (ctypes.c_int * 20).in_dll(lib, "measure_table34")

SITEFLIP_GAP_UNIT = 2.0 ** -20
SITEFLIP_MAX_SITES = 16

TABLE34_DTYPE = np.dtype([("measure", "U64"), ("joint", "U16"), ("rule", "U96"),
                          ("samples", "u8"), ("type_I", "u8"), ("type_II", "u8"),
                          ("type_III", "u8"), ("type_IV", "u8"), ("type_V", "u8"),
                          ("dt", "u8")])
CENSUS_DTYPE = np.dtype([("measure", "U64"), ("joint", "U16"), ("rule", "U96"), ("sites", "i4"),
                         ("sampler", "U16"), ("samples", "u8"), ("tie", "u8"),
                         ("no_sink", "u8"), ("one_sink", "u8"), ("multi_sink", "u8"),
                         ("sink_dt", "u8"), ("mean_sinks", "f8"), ("max_sinks", "u8"),
                         ("mean_worst_gap", "f8"), ("sinks", "u8"), ("gap_units", "u8")])


class Counts(np.ndarray):
    """A structured array of counts, one row per rule, with the run's
    metadata in .meta (seed, tie_eps, first, end, total, rules, sampler)."""

    def __new__(cls, arr, meta):
        obj = np.asarray(arr).view(cls)
        obj.meta = meta
        return obj

    def __array_finalize__(self, obj):
        self.meta = getattr(obj, "meta", None)

    def to_csv(self, path=None, format="csv", columns=0):
        """The table as the program writes it (_report.to_csv): the bytes of
        `table34`/`census --format FORMAT` for the same run."""
        from ._report import to_csv
        return to_csv(self, path, format, columns)


def _rules(rules, measures):
    """The rule list of the program: rules as given, else every MEASURE_JOINT
    of the measures (default table 3.4's twenty) joint-major, then DT."""
    if rules is not None and measures is not None:
        raise ValueError("measures and rules exclude each other")
    if rules is not None:
        rs = [as_rule(r) for r in ([rules] if isinstance(rules, (str, Rule)) else rules)]
        if not rs:
            raise ValueError("rules: none given")
        return rs
    if measures is None:
        ids = list(_table34_ids)
    else:
        ids = []
        for m in ([measures] if isinstance(measures, str) else measures):
            i = lib.measure_find(cstr(m, "measures"))
            if i < 0:
                raise ValueError("unknown measure '%s'" % m)
            ids.append(i)
    cap = 6 * len(ids) + 1
    arr = (_lib.Rule * cap)()
    n = lib.rule_list_triangle((ctypes.c_int * len(ids))(*ids), len(ids), arr, cap - 1)
    if n <= 0:
        raise ValueError("measures %s give no triangle-based rules" % (measures,))
    out = []
    for i in range(n):
        r = Rule.__new__(Rule)
        r._c = _lib.Rule.from_buffer_copy(arr[i])
        out.append(r)
    return out + [Rule("DT")]


def _progress(progress):
    """A C progress callback calling progress(done, total), or a NULL one.
    The C library calls it from one thread; ctypes takes the GIL for it."""
    if progress is None:
        return ProgressFn()
    return ProgressFn(lambda done, total, ctx: progress(int(done), int(total)))


def _c_rules(rs, tie_eps):
    arr = (_lib.Rule * len(rs))()
    for i, r in enumerate(rs):
        arr[i] = r._c
        arr[i].tie_eps = tie_eps
    return arr


def _shard(samples, shard):
    if shard is None:
        return 0, samples
    k, n = shard
    if not (1 <= k <= n <= 2 ** 32):
        raise ValueError("shard: expected (k, n) with 1 <= k <= n <= 2^32, got %r" % (shard,))
    first = (k - 1) * samples // n
    return first, k * samples // n - first


def _tie_eps(v):
    return tie_eps_arg(v, _lib.RULE_DEFAULT_TIE_EPS)


def table34(samples=5000, seed=1, rules=None, measures=None, tie_eps=None, threads=0,
            sampler="iteration", shard=None, progress=None):
    """Classify `samples` random convex pentagons (the stream `seed` of
    `sampler`) under every rule, as `fliplab table34 --samples N --seed S`:
    a Counts array with the columns of its CSV (measure, joint, rule,
    samples, type_I .. type_V, dt) and .meta its run columns.  rules: names
    or Rules (the program's --rules), else every MEASURE_JOINT of measures
    (default table 3.4's twenty) joint-major, then DT.  shard=(k, n): the
    samples [floor((k-1)S/n), floor(kS/n)).  progress(done, total) is called
    now and then.  The counts do not depend on threads."""
    rs = _rules(rules, measures)
    samples, seed = _u64(samples, "samples", 1), _u64(seed, "seed")
    eps = _tie_eps(tie_eps)
    first, count = _shard(samples, shard)
    _name(sampler, PENTAGON_SAMPLERS, "pentagon sampler")
    counts = (FlipgraphCounts * len(rs))()
    cb = _progress(progress)
    run = FlipgraphRun(seed=seed, first=first, count=count, tie_eps=eps,
                       threads=_lib.threads_arg(threads), progress=cb)
    if sampler != "iteration":
        run.sampler = lib.sampler_pentagons_find(sampler.encode()).contents.draw
    if count > 0 and lib.flipgraph_tally_run(_c_rules(rs, eps), len(rs), ctypes.byref(run),
                                             counts) != 0:
        _raise_user_errors()
        raise MemoryError("table34: out of memory")
    _raise_user_errors()
    out = np.zeros(len(rs), dtype=TABLE34_DTYPE)
    for i, (r, c) in enumerate(zip(rs, counts)):
        out[i] = (r.measure, r.joint, r.name, count, *c.type, c.dt)
    meta = {"seed": seed, "tie_eps": eps, "first": first, "end": first + count,
            "total": samples, "rules": len(rs), "sampler": sampler,
            "shard": None if shard is None else tuple(shard)}
    return Counts(out, meta)


def census(sites=6, samples=1000, sampler="convex", seed=1, rules=None, measures=None,
           tie_eps=None, threads=0, memory=None, shard=None, progress=None):
    """The census of random site sets, as `fliplab census --sites N --sampler
    S --samples M --seed K`: for every rule, how many sets have a tie, no,
    one or several sinks, a sink equal to DT, the mean number of sinks and
    of the worst sink's gap to the GOT (the CSV's columns; sinks and
    gap_units are the integer sums the means come from).  A Counts array;
    .meta has seed, tie_eps, first, end, total, rules, sites, sampler."""
    rs = _rules(rules, measures)
    k = lib.sampler_sites_find(_name(sampler, SITE_SETS, "site sampler").encode())
    if not (isinstance(sites, (int, np.integer)) and 3 <= sites <= SITEFLIP_MAX_SITES):
        raise ValueError("sites: expected 3 to %d, got %r" % (SITEFLIP_MAX_SITES, sites))
    samples, seed = _u64(samples, "samples", 1), _u64(seed, "seed")
    eps = _tie_eps(tie_eps)
    first, count = _shard(samples, shard)
    counts = (SiteflipCounts * len(rs))()
    over = ctypes.c_int(0)
    e = _lib.errbuf()
    if count > 0 and lib.siteflip_census(
            _c_rules(rs, eps), len(rs), k, int(sites), seed, first, count, eps,
            _lib.threads_arg(threads),
            0 if memory is None else int(memory), counts, _progress(progress), None,
            ctypes.byref(over), e, _lib.ERRLEN) != 0:
        _raise_user_errors()
        msg = _lib.text(e)
        raise (ValueError if over.value else MemoryError)(msg)
    _raise_user_errors()
    out = np.zeros(len(rs), dtype=CENSUS_DTYPE)
    for i, (r, c) in enumerate(zip(rs, counts)):
        d = count - c.tie
        ms = c.sinks / d if d > 0 else np.nan
        w = c.one_sink + c.multi_sink
        mg = c.gap_units * SITEFLIP_GAP_UNIT / w if (r.is_triangle and w > 0) else np.nan
        out[i] = (r.measure, r.joint, r.name, sites, sampler, count, c.tie, c.no_sink,
                  c.one_sink, c.multi_sink, c.sink_dt, ms, c.max_sinks, mg, c.sinks,
                  c.gap_units)
    meta = {"seed": seed, "tie_eps": eps, "first": first, "end": first + count,
            "total": samples, "rules": len(rs), "sites": int(sites), "sampler": sampler,
            "shard": None if shard is None else tuple(shard)}
    return Counts(out, meta)
