"""_report.py: the program's tables from Python: Counts.to_csv() writes a
table34() or census() result with the C library's own writers
(report_write, report_census_write: reports/), so the bytes are those of
`fliplab table34 --format csv` and `fliplab census --format csv` for the
same run, and `fliplab merge` takes shards written either way.  A file is
written to a temporary name beside it and renamed into place only when
the whole table is out, as the program does."""
from __future__ import annotations

import ctypes
import os
import tempfile
from typing import Any, Callable

from . import _lib
from ._args import choice
from ._census import FORMATS
from ._mirrors import ReportCensusMeta, ReportCensusRow, ReportMeta, ReportRow, ReportRun, \
    SITEFLIP_COUNTS

lib = _lib.lib
libc = _lib.libc


def _memstream(write: Callable[[Any], int]) -> bytes:
    """What write(FILE *) puts into a memory stream, as bytes."""
    buf, size = ctypes.c_void_p(), ctypes.c_size_t()
    f = libc.open_memstream(ctypes.byref(buf), ctypes.byref(size))
    if not f:
        raise MemoryError("to_csv: out of memory")
    rc = write(f)
    if libc.fclose(f) != 0 or rc != 0:
        libc.free(buf)
        raise MemoryError("to_csv: out of memory")
    try:
        return ctypes.string_at(buf, size.value)
    finally:
        libc.free(buf)


def _shard(meta):
    k, n = meta.get("shard") or (0, 0)
    return k, n


def _table34_bytes(t, fmt, columns):
    m = t.meta
    rows = (ReportRow * len(t))()
    for row, x in zip(rows, t):
        row.measure, row.joint, row.rule = (x[k].encode() for k in ("measure", "joint", "rule"))
        row.c.samples = int(x["samples"])
        for i, ty in enumerate(("I", "II", "III", "IV", "V")):
            row.c.type[i] = int(x["type_" + ty])
        row.c.dt = int(x["dt"])
    sampler = None if m["sampler"] == "iteration" else m["sampler"].encode()
    run = ReportRun(known=1, seed=m["seed"], tie_eps=m["tie_eps"], first=m["first"],
                    end=m["end"], total=m["total"], rules=len(t), sampler=sampler)
    k, n = _shard(m)
    meta = ReportMeta(samples=m["end"] - m["first"], has_seed=1, seed=m["seed"], has_tie_eps=1,
                      tie_eps=m["tie_eps"], shard_k=k, shard_n=n, shard_first=m["first"],
                      shard_total=m["total"], sampler=sampler, text_columns=columns,
                      run=ctypes.pointer(run))
    return _memstream(lambda f: lib.report_write(f, fmt, ctypes.byref(meta), rows, len(t)))


def _census_bytes(t, fmt):
    m = t.meta
    rows = (ReportCensusRow * len(t))()
    for row, x in zip(rows, t):
        row.measure, row.joint, row.rule = (x[k].encode() for k in ("measure", "joint", "rule"))
        row.sites, row.sampler = int(x["sites"]), x["sampler"].encode()
        for f in SITEFLIP_COUNTS:
            setattr(row.c, f, int(x[f]))
    k, n = _shard(m)
    meta = ReportCensusMeta(has_seed=1, seed=m["seed"], has_tie_eps=1, tie_eps=m["tie_eps"],
                            shard_k=k, shard_n=n)
    return _memstream(lambda f: lib.report_census_write(f, fmt, ctypes.byref(meta), rows,
                                                        len(t)))


def _write_atomic(path, data):
    d = os.path.dirname(os.path.abspath(path))
    fd, tmp = tempfile.mkstemp(prefix="." + os.path.basename(path) + ".", dir=d)
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(data)
        os.replace(tmp, path)
    except BaseException:
        os.unlink(tmp)
        raise


def to_csv(counts: Any, path: str | os.PathLike[str] | None = None, format: str = "csv",
           columns: int = 0) -> str | None:
    """Counts.to_csv: the table of a table34() or census() result as the
    program writes it (format one of FORMATS; columns: text's measures per
    block, 0 all), returned as a str when path is None, else written to
    path (a temporary file renamed into place)."""
    choice(format, FORMATS, "format")
    fmt = ctypes.c_int()
    if lib.report_format_parse(format.encode(), ctypes.byref(fmt)) != 0:
        raise ValueError("format: the library does not know %r" % (format,))
    data = (_census_bytes(counts, fmt.value) if "sites" in counts.meta
            else _table34_bytes(counts, fmt.value, int(columns)))
    if path is None:
        return data.decode()
    _write_atomic(path, data)
    return None
