"""_report.py: the program's tables from Python: Counts.to_csv() writes a
table34() or census() result with the C library's own writers
(report_write, report_census_write: reports/), so the bytes are those of
`fliplab table34 --format csv` and `fliplab census --format csv` for the
same run, and `fliplab merge` takes shards written either way.  A file is
written to a temporary name beside it and renamed into place only when
the whole table is out, as the program does."""
import ctypes
import os
import tempfile

from . import _lib
from ._census import FlipgraphCounts, SiteflipCounts

lib = _lib.lib
_libc = ctypes.CDLL(None)
_libc.open_memstream.restype = ctypes.c_void_p
_libc.open_memstream.argtypes = [ctypes.POINTER(ctypes.c_void_p), ctypes.POINTER(ctypes.c_size_t)]
_libc.fclose.restype = ctypes.c_int
_libc.fclose.argtypes = [ctypes.c_void_p]
_libc.free.restype = None
_libc.free.argtypes = [ctypes.c_void_p]
JOINT_NAME_MAX = 16
FORMATS = {"text": 0, "md": 1, "csv": 2}


class ReportRow(ctypes.Structure):
    """report_row (reports/report.h)."""
    _fields_ = [("measure", ctypes.c_char * 64), ("joint", ctypes.c_char * JOINT_NAME_MAX),
                ("rule", ctypes.c_char * 1024), ("c", FlipgraphCounts)]


class ReportRun(ctypes.Structure):
    """report_run (reports/report.h)."""
    _fields_ = [("known", ctypes.c_int), ("seed", ctypes.c_uint64), ("tie_eps", ctypes.c_double),
                ("first", ctypes.c_uint64), ("end", ctypes.c_uint64), ("total", ctypes.c_uint64),
                ("rules", ctypes.c_uint64), ("sampler", ctypes.c_char_p)]


class ReportMeta(ctypes.Structure):
    """report_meta (reports/report.h)."""
    _fields_ = [("samples", ctypes.c_uint64), ("has_seed", ctypes.c_int),
                ("seed", ctypes.c_uint64), ("has_tie_eps", ctypes.c_int),
                ("tie_eps", ctypes.c_double), ("shard_k", ctypes.c_uint64),
                ("shard_n", ctypes.c_uint64), ("shard_first", ctypes.c_uint64),
                ("shard_total", ctypes.c_uint64), ("sampler", ctypes.c_char_p),
                ("note", ctypes.c_char_p), ("text_columns", ctypes.c_int),
                ("run", ctypes.POINTER(ReportRun))]


class ReportCensusRow(ctypes.Structure):
    """report_census_row (reports/report.h)."""
    _fields_ = [("measure", ctypes.c_char * 64), ("joint", ctypes.c_char * JOINT_NAME_MAX),
                ("rule", ctypes.c_char * 1024), ("sites", ctypes.c_int),
                ("sampler", ctypes.c_char * 16), ("c", SiteflipCounts)]


class ReportCensusMeta(ctypes.Structure):
    """report_census_meta (reports/report.h)."""
    _fields_ = [("has_seed", ctypes.c_int), ("seed", ctypes.c_uint64),
                ("has_tie_eps", ctypes.c_int), ("tie_eps", ctypes.c_double),
                ("shard_k", ctypes.c_uint64), ("shard_n", ctypes.c_uint64)]


lib.report_write.restype = ctypes.c_int
lib.report_write.argtypes = [ctypes.c_void_p, ctypes.c_int, ctypes.POINTER(ReportMeta),
                             ctypes.POINTER(ReportRow), ctypes.c_int]
lib.report_census_write.restype = ctypes.c_int
lib.report_census_write.argtypes = [ctypes.c_void_p, ctypes.c_int,
                                    ctypes.POINTER(ReportCensusMeta),
                                    ctypes.POINTER(ReportCensusRow), ctypes.c_int]


def _memstream(write):
    """What write(FILE *) puts into a memory stream, as bytes."""
    buf, size = ctypes.c_void_p(), ctypes.c_size_t()
    f = _libc.open_memstream(ctypes.byref(buf), ctypes.byref(size))
    if not f:
        raise MemoryError("to_csv: out of memory")
    rc = write(f)
    if _libc.fclose(f) != 0 or rc != 0:
        _libc.free(buf)
        raise MemoryError("to_csv: out of memory")
    try:
        return ctypes.string_at(buf, size.value)
    finally:
        _libc.free(buf)


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
        for f, _ in SiteflipCounts._fields_:
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


def to_csv(counts, path=None, format="csv", columns=0):
    """The table of a table34() or census() result as the program writes it
    (format "csv", "md" or "text"; columns: text's measures per block, 0
    all): returned as a str when path is None, else written to path (a
    temporary file renamed into place)."""
    if format not in FORMATS:
        raise ValueError("format must be text, md or csv, got %r" % (format,))
    fmt = FORMATS[format]
    data = (_census_bytes(counts, fmt) if "sites" in counts.meta
            else _table34_bytes(counts, fmt, int(columns)))
    if path is None:
        return data.decode()
    _write_atomic(path, data)
    return None

