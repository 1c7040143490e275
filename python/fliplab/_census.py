"""_census.py: table 3.4 (directed flip graphs of random convex pentagons,
classify/flipgraph.h) and the census of random site sets
(classify/siteflip.h), as numpy structured arrays of counts with the run's
metadata: the numbers of the program's CSV (`table34 --format csv`,
`census`) for the same rules, samples and seed."""
from __future__ import annotations

import ctypes
import os
from typing import Any, Callable, Iterable

import numpy as np
import numpy.typing as npt

from . import _lib
from ._args import is_int, threads_arg, tie_eps_arg, u64
from ._arrays import cstr
from ._mirrors import (FlipgraphCounts, FlipgraphRun, ProgressFn, SiteflipCounts,
                       SITEFLIP_MAX_SITES)
from ._rules import Rule, as_rule, _raise_user_errors
from .samplers import PENTAGON_SAMPLERS, SITE_SETS, _name

lib = _lib.lib
_table34_ids = (ctypes.c_int * 20).in_dll(lib, "measure_table34")

SITEFLIP_GAP_UNIT = 2.0 ** -20
FORMATS = ("csv", "md", "text")      # report_format_parse's names (reports/report.h)

TABLE34_DTYPE = np.dtype([("measure", "U64"), ("joint", "U16"), ("rule", "U96"),
                          ("samples", "u8"), ("type_I", "u8"), ("type_II", "u8"),
                          ("type_III", "u8"), ("type_IV", "u8"), ("type_V", "u8"),
                          ("dt", "u8")])
CENSUS_DTYPE = np.dtype([("measure", "U64"), ("joint", "U16"), ("rule", "U96"), ("sites", "i4"),
                         ("sampler", "U16"), ("samples", "u8"), ("tie", "u8"),
                         ("no_sink", "u8"), ("one_sink", "u8"), ("multi_sink", "u8"),
                         ("sink_dt", "u8"), ("mean_sinks", "f8"), ("max_sinks", "u8"),
                         ("mean_worst_gap", "f8"), ("sinks", "u8"), ("gap_units", "u8")])

Progress = Callable[[int, int], Any]
RulesArg = str | Rule | Iterable[str | Rule] | None
MeasuresArg = str | Iterable[str] | None


class Counts(np.ndarray):
    """A structured array of counts, one row per rule (table34(), census()),
    with the run's metadata in .meta (seed, tie_eps, first, end, total,
    rules, sampler, shard; census: sites).

    Parameters
    ----------
    arr : array_like
        The rows.
    meta : dict
        The run's metadata.
    """

    meta: dict[str, Any] | None

    def __new__(cls, arr: npt.ArrayLike, meta: dict[str, Any]) -> Counts:
        obj = np.asarray(arr).view(cls)
        obj.meta = meta
        return obj

    def __array_finalize__(self, obj: Any) -> None:
        self.meta = getattr(obj, "meta", None)

    def to_csv(self, path: str | os.PathLike[str] | None = None, format: str = "csv",
               columns: int = 0) -> str | None:
        """The table as the program writes it, by the library's own writers
        (report_write, report_census_write): the bytes of `table34` or
        `census --format FORMAT` for the same run, shards included.

        Parameters
        ----------
        path : str or os.PathLike, optional
            Where to write it (a temporary file renamed into place); None
            returns it.
        format : str
            "csv", "md" or "text".
        columns : int
            text's measures per block (0: all).

        Returns
        -------
        str or None
            The table when path is None.

        Raises
        ------
        ValueError
            An unknown format.
        OSError
            The file could not be written (an old file is left as it was).
        MemoryError
            Out of memory.
        """
        from ._report import to_csv
        return to_csv(self, path, format, columns)


def _rules(rules: RulesArg, measures: MeasuresArg) -> list[Rule]:
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
                raise ValueError("measures: unknown measure '%s'" % m)
            ids.append(i)
    cap = 6 * len(ids) + 1
    arr = (_lib.Rule * cap)()
    n = lib.rule_list_triangle((ctypes.c_int * len(ids))(*ids), len(ids), arr, cap - 1)
    if n <= 0:
        raise ValueError("measures: %s give no triangle-based rules" % (measures,))
    out = []
    for i in range(n):
        r = Rule.__new__(Rule)
        r._c = _lib.Rule.from_buffer_copy(arr[i])
        out.append(r)
    return out + [Rule("DT")]


def _progress(progress: Progress | None) -> Any:
    """A C progress callback calling progress(done, total), or a NULL one.
    The C library calls it from one thread; ctypes takes the GIL for it."""
    if progress is None:
        return ProgressFn()
    return ProgressFn(lambda done, total, ctx: progress(int(done), int(total)))


def _c_rules(rs: list[Rule], tie_eps: float) -> Any:
    arr = (_lib.Rule * len(rs))()
    for i, r in enumerate(rs):
        arr[i] = r._c
        arr[i].tie_eps = tie_eps
    return arr


def _shard(samples: int, shard: tuple[int, int] | None) -> tuple[int, int]:
    if shard is None:
        return 0, samples
    k, n = shard
    if not (1 <= k <= n <= 2 ** 32):
        raise ValueError("shard: expected (k, n) with 1 <= k <= n <= 2^32, got %r" % (shard,))
    first = (k - 1) * samples // n
    return first, k * samples // n - first


def _tie_eps(v: float | None) -> float:
    """A tie tolerance, the library's default when None."""
    return tie_eps_arg(v, _lib.RULE_DEFAULT_TIE_EPS)


def table34(samples: int = 5000, seed: int = 1, rules: RulesArg = None,
            measures: MeasuresArg = None,
            tie_eps: float | None = None, threads: int = 0, sampler: str = "iteration",
            shard: tuple[int, int] | None = None,
            progress: Progress | None = None) -> Counts:
    """Classify random convex pentagons under every rule, as the program's
    `table34 --samples N --seed S` (docs/classification.md).

    Parameters
    ----------
    samples : int
        Pentagons, at least 1.
    seed : int
        The sampler's stream, in [0, 2^64).
    rules : str, Rule or iterable of them, optional
        The rules (names "DT", MEASURE_JOINT, ES:SHAPE, or Rules); they
        exclude measures.
    measures : str or iterable of str, optional
        Names of measures(): every MEASURE_JOINT of theirs, joint-major, then
        DT (default: table 3.4's twenty measures).
    tie_eps : float, optional
        The tie tolerance of every rule (default the library's, 1e-12).
    threads : int
        0 (all cores) or 1 .. 1024; the counts do not depend on it.
    sampler : str
        The pentagon sampler: "iteration", "vector", "circle" or "disc-hull".
    shard : tuple of int, optional
        (k, n): only the samples [floor((k-1)S/n), floor(kS/n)), for the
        program's merge.
    progress : callable, optional
        progress(done, total), called now and then from the library.

    Returns
    -------
    Counts
        The columns of the CSV (measure, joint, rule, samples, type_I ..
        type_V, dt), the run's columns in .meta.

    Raises
    ------
    ValueError
        A bad rule, measure, sampler, number or shard; a bad value of a
        user measure.
    MemoryError
        Out of memory.
    """
    rs = _rules(rules, measures)
    samples, seed = u64(samples, "samples", 1), u64(seed, "seed")
    eps = _tie_eps(tie_eps)
    first, count = _shard(samples, shard)
    _name(sampler, PENTAGON_SAMPLERS, "sampler", "pentagon sampler")
    counts = (FlipgraphCounts * len(rs))()
    cb = _progress(progress)
    run = FlipgraphRun(seed=seed, first=first, count=count, tie_eps=eps,
                       threads=threads_arg(threads), progress=cb)
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


def _census_row(r: Rule, c: Any, count: int, sites: int, sampler: str) -> tuple:
    """One row of CENSUS_DTYPE: the counts and the means the CSV shows."""
    d = count - c.tie
    ms = c.sinks / d if d > 0 else np.nan
    w = c.one_sink + c.multi_sink
    mg = c.gap_units * SITEFLIP_GAP_UNIT / w if (r.is_triangle and w > 0) else np.nan
    return (r.measure, r.joint, r.name, sites, sampler, count, c.tie, c.no_sink, c.one_sink,
            c.multi_sink, c.sink_dt, ms, c.max_sinks, mg, c.sinks, c.gap_units)


def census(sites: int = 6, samples: int = 1000, sampler: str = "convex", seed: int = 1,
           rules: RulesArg = None, measures: MeasuresArg = None, tie_eps: float | None = None,
           threads: int = 0, memory: int | None = None, shard: tuple[int, int] | None = None,
           progress: Progress | None = None) -> Counts:
    """The census of random site sets, as the program's `census --sites N
    --sampler S --samples M --seed K` (docs/sitesets.md): for every rule,
    how many sets have a tie, no, one or several sinks, a sink equal to DT,
    the mean number of sinks and of the worst sink's gap to the GOT.

    Parameters
    ----------
    sites : int
        Sites per set, 3 .. 16.
    samples : int
        Sets, at least 1.
    sampler : str
        The site sampler: "convex", "disc", "square" or "normal".
    seed : int
        The sampler's stream, in [0, 2^64).
    rules, measures, tie_eps, threads, shard, progress
        As table34()'s (rules: names "DT", MEASURE_JOINT, ES:SHAPE, or Rules).
    memory : int, optional
        The budget of each set's flip graph in bytes (default the library's).

    Returns
    -------
    Counts
        The CSV's columns (sinks and gap_units are the integer sums the
        means come from); .meta adds sites.

    Raises
    ------
    ValueError
        A bad rule, measure, sampler or number, a set over the memory
        budget; a bad value of a user measure.
    MemoryError
        Out of memory.
    """
    rs = _rules(rules, measures)
    k = lib.sampler_sites_find(_name(sampler, SITE_SETS, "sampler", "site sampler").encode())
    if not (is_int(sites) and 3 <= sites <= SITEFLIP_MAX_SITES):
        raise ValueError("sites: expected 3 to %d, got %r" % (SITEFLIP_MAX_SITES, sites))
    samples, seed = u64(samples, "samples", 1), u64(seed, "seed")
    eps = _tie_eps(tie_eps)
    first, count = _shard(samples, shard)
    counts = (SiteflipCounts * len(rs))()
    over = ctypes.c_int(0)
    e = _lib.errbuf()
    if count > 0 and lib.siteflip_census(
            _c_rules(rs, eps), len(rs), k, int(sites), seed, first, count, eps,
            threads_arg(threads),
            0 if memory is None else int(memory), counts, _progress(progress), None,
            ctypes.byref(over), e, _lib.ERRLEN) != 0:
        _raise_user_errors()
        msg = _lib.text(e)
        raise (ValueError if over.value else MemoryError)(msg)
    _raise_user_errors()
    out = np.zeros(len(rs), dtype=CENSUS_DTYPE)
    for i, (r, c) in enumerate(zip(rs, counts)):
        out[i] = _census_row(r, c, count, int(sites), sampler)
    meta = {"seed": seed, "tie_eps": eps, "first": first, "end": first + count,
            "total": samples, "rules": len(rs), "sites": int(sites), "sampler": sampler,
            "shard": None if shard is None else tuple(shard)}
    return Counts(out, meta)
