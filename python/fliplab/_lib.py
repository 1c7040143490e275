"""_lib.py: loading libfliplab.so with ctypes and declaring the C functions
the package calls, with ctypes mirrors of the public structures they use.

Where the library is found, first match wins:
  1. the environment variable FLIPLAB_LIBRARY (a path to libfliplab.so:
     a build tree's, e.g. FLIPLAB_LIBRARY=build/libfliplab.so);
  2. the library installed with this package (``cmake --install`` writes
     _install.py beside this file, naming it relative to the package);
  3. the dynamic linker's search (ldconfig, LD_LIBRARY_PATH).

ctypes.CDLL releases the GIL for the duration of every call, so a long C
call (a triangulation of 10^6 points, a census) lets other Python threads
run.  The structure mirrors must match the C headers field for field:
python/tests/test_layout.py compares every mirror of the package with the
sizes and offsets the compiler gave the headers (python/tests/layout.c),
and _check_layout() verifies the rule and options against
lot_options_init's documented defaults when the module loads, so that a
library built from other headers fails at import instead of reading garbage.
"""
import ctypes
import os

import numpy as np

SONAME = "libfliplab.so.0.1"

c_double_p = ctypes.POINTER(ctypes.c_double)
c_uint32_p = ctypes.POINTER(ctypes.c_uint32)
c_int32_p = ctypes.POINTER(ctypes.c_int32)


class Point(ctypes.Structure):
    """geom_point (geom/predicates.h)."""
    _fields_ = [("x", ctypes.c_double), ("y", ctypes.c_double)]


Point_p = ctypes.POINTER(Point)


class Rule(ctypes.Structure):
    """rule (fliprules/rule.h)."""
    _fields_ = [("kind", ctypes.c_int), ("measure", ctypes.c_int), ("joint", ctypes.c_int),
                ("sign", ctypes.c_int), ("quad", ctypes.c_int), ("tie_eps", ctypes.c_double),
                ("name", ctypes.c_char * 1024)]   # RULE_NAME_MAX


Rule_p = ctypes.POINTER(Rule)
RULE_TRIANGLE, RULE_QUAD = 0, 1
RULE_DEFAULT_TIE_EPS = 1e-12


class LotOptions(ctypes.Structure):
    """lot_options (lot/lot.h), constraints included."""
    _fields_ = [("r", Rule), ("algorithm", ctypes.c_int), ("order", ctypes.c_int),
                ("seed", ctypes.c_uint64), ("max_flips", ctypes.c_uint64),
                ("tie_eps", ctypes.c_double), ("decide", ctypes.c_void_p),
                ("decide_ctx", ctypes.c_void_p), ("segments", c_uint32_p),
                ("nsegments", ctypes.c_size_t), ("holes", Point_p),
                ("nholes", ctypes.c_size_t), ("keep_hull", ctypes.c_int)]


class LotOptionsRoom(ctypes.Structure):
    """lot_options with room after it: fields a newer lot.h appends at the
    end are set by lot_options_init and left at their defaults."""
    _fields_ = [("o", LotOptions), ("_room", ctypes.c_char * 2048)]


LOT_CYCLE_QUADS = 8


class LotStats(ctypes.Structure):
    """lot_stats (lot/lot.h)."""
    _fields_ = [("n", ctypes.c_size_t), ("distinct", ctypes.c_size_t),
                ("duplicates", ctypes.c_size_t), ("hull", ctypes.c_size_t),
                ("triangles", ctypes.c_size_t), ("flips", ctypes.c_uint64),
                ("status", ctypes.c_int), ("cycle_length", ctypes.c_uint64),
                ("cycle_quads", ctypes.c_size_t),
                ("cycle_quad", (ctypes.c_uint32 * 4) * LOT_CYCLE_QUADS),
                ("max_flips", ctypes.c_uint64), ("seconds_init", ctypes.c_double),
                ("seconds_flip", ctypes.c_double),
                ("segments", ctypes.c_size_t), ("constrained", ctypes.c_size_t),
                ("segments_merged", ctypes.c_size_t), ("segments_split", ctypes.c_size_t),
                ("segments_removed", ctypes.c_size_t), ("holes", ctypes.c_size_t),
                ("removed", ctypes.c_size_t)]


class LotCheckResult(ctypes.Structure):
    """lot_check_result (lot/lot.h)."""
    _fields_ = [("interior_edges", ctypes.c_size_t), ("boundary_edges", ctypes.c_size_t),
                ("decided", ctypes.c_size_t), ("not_optimal", ctypes.c_size_t),
                ("bad_edge", ctypes.c_uint32 * 2), ("valid", ctypes.c_int),
                ("segments_missing", ctypes.c_size_t), ("missing_segment", ctypes.c_size_t)]


class GeomPslg(ctypes.Structure):
    """geom_pslg (geom/geom.h): vertices, segments, hole points."""
    _fields_ = [("pts", Point_p), ("npts", ctypes.c_size_t), ("seg", c_uint32_p),
                ("nseg", ctypes.c_size_t), ("hole", Point_p), ("nholes", ctypes.c_size_t)]


class ReportPoly(ctypes.Structure):
    """report_poly (reports/report.h): a .poly file's graph and what was ignored."""
    _fields_ = [("g", GeomPslg), ("seg_line", ctypes.POINTER(ctypes.c_uint64)),
                ("attributes", ctypes.c_size_t), ("regions", ctypes.c_size_t),
                ("markers", ctypes.c_int), ("first", ctypes.c_int)]


class Measure(ctypes.Structure):
    """measure (badness/measure.h)."""
    _fields_ = [("name", ctypes.c_char_p), ("symbol", ctypes.c_char_p),
                ("desc", ctypes.c_char_p), ("sign", ctypes.c_int), ("fn", ctypes.c_void_p),
                ("ctx", ctypes.c_void_p)]


class Joint(ctypes.Structure):
    """The first fields of joint (joints/joint.h): its name."""
    _fields_ = [("name", ctypes.c_char_p)]


class RuleQuad(ctypes.Structure):
    """rule_quad (fliprules/rule.h)."""
    _fields_ = [("name", ctypes.c_char_p), ("desc", ctypes.c_char_p), ("fn", ctypes.c_void_p),
                ("ctx", ctypes.c_void_p)]


PentagonFn = ctypes.CFUNCTYPE(ctypes.c_int, ctypes.c_uint64, ctypes.c_uint64, Point_p)


class SamplerPentagons(ctypes.Structure):
    """sampler_pentagons (samplers/sampler.h)."""
    _fields_ = [("name", ctypes.c_char_p), ("draw", PentagonFn)]


class SamplerRng(ctypes.Structure):
    """sampler_rng (samplers/sampler.h)."""
    _fields_ = [("s", ctypes.c_uint64 * 4)]


def _find():
    """The library to load: FLIPLAB_LIBRARY, the library of a cmake --install
    (_install.py), the library shipped inside this package (pip install:
    setup.py copies it here as SONAME), else the dynamic linker's search."""
    env = os.environ.get("FLIPLAB_LIBRARY")
    if env:
        return env
    here = os.path.dirname(os.path.abspath(__file__))
    try:
        from . import _install
        path = os.path.normpath(os.path.join(here, _install.LIBDIR, SONAME))
        if os.path.exists(path):
            return path
    except ImportError:
        pass
    path = os.path.join(here, SONAME)
    if os.path.exists(path):
        return path
    return SONAME


def _load():
    path = _find()
    try:
        return ctypes.CDLL(path), path
    except OSError as e:
        raise ImportError(
            "fliplab: cannot load the shared library %r (%s); set FLIPLAB_LIBRARY to "
            "the path of libfliplab.so (a build tree's, e.g. build/libfliplab.so) or "
            "install fliplab with cmake --install" % (path, e)) from None


lib, path = _load()

_size = ctypes.c_size_t
_char_p = ctypes.c_char_p
_int = ctypes.c_int
_u64 = ctypes.c_uint64
_void_p = ctypes.c_void_p

# name: (restype, argtypes)
_PROTOS = {
    "rule_parse": (_int, [_char_p, Rule_p, _char_p, _size]),
    "rule_is_shape": (_int, [Rule_p]),
    "rule_shape": (_void_p, [Rule_p]),
    "rule_triangle": (_int, [_int, _int, Rule_p, _char_p, _size]),
    "rule_delaunay": (Rule, []),
    "rule_quad_count": (_int, []),
    "rule_quad_get": (ctypes.POINTER(RuleQuad), [_int]),
    "rule_eval_quads": (None, [Rule_p, Point_p, _size, ctypes.POINTER(ctypes.c_byte),
                               c_double_p, c_double_p]),
    "rule_total_key": (ctypes.c_double, [Rule_p, c_double_p, _size]),
    "rule_gap": (ctypes.c_double, [Rule_p, ctypes.c_double, ctypes.c_double]),
    "measure_count": (_int, []),
    "measure_get": (ctypes.POINTER(Measure), [_int]),
    "measure_find": (_int, [_char_p]),
    "measure_eval_tris": (None, [_int, Point_p, _size, c_double_p]),
    "joint_count": (_int, []),
    "joint_get": (ctypes.POINTER(Joint), [_int]),
    "formula_define": (_int, [_char_p, _char_p, _size]),
    "formula_check_errors": (_int, [_char_p, _size]),
    "formula_clear_errors": (None, []),
    "plugin_load": (_int, [_char_p, _char_p, _size]),
    "geom_coord_check": (_int, [ctypes.c_double]),
    "geom_coorderr_str": (_char_p, [_int]),
    "geom_coord_check_n": (_size, [c_double_p, _size]),
    "geom_threads_check": (_int, [ctypes.c_longlong, _char_p, _size]),
    "lot_options_init": (None, [ctypes.POINTER(LotOptionsRoom), Rule_p]),
    "lot_default_max_flips": (_u64, [_size]),
    "lot_build": (_int, [ctypes.POINTER(_void_p), Point_p, _size,
                         ctypes.POINTER(LotOptionsRoom), _char_p, _size]),
    "lot_get_stats": (ctypes.POINTER(LotStats), [_void_p]),
    "lot_get_triangles": (None, [_void_p, c_uint32_p]),
    "lot_get_hull": (_size, [_void_p, c_uint32_p]),
    "lot_check_memory": (_int, [_size, _char_p, _size]),
    "lot_free": (None, [_void_p]),
    "lot_check": (_int, [Point_p, _size, c_uint32_p, _size, Rule_p,
                         ctypes.POINTER(LotCheckResult)]),
    "lot_get_constrained": (_size, [_void_p, c_uint32_p]),
    "lot_check_constrained": (_int, [Point_p, _size, c_uint32_p, _size, c_uint32_p, _size,
                                     Rule_p, ctypes.POINTER(LotCheckResult)]),
    "report_poly_read": (_int, [_char_p, ctypes.POINTER(ReportPoly), _char_p, _size]),
    "report_poly_free": (None, [ctypes.POINTER(ReportPoly)]),
    "lot_neighbors": (_int, [c_uint32_p, _size, _size, c_int32_p]),
    "lot_get_badness": (None, [Point_p, c_uint32_p, _size, Rule_p, c_double_p]),
    "lot_get_neighbors": (_int, [_void_p, c_int32_p]),
    "lot_locate": (_int, [Point_p, _size, c_uint32_p, c_int32_p, _size, _int, Point_p, _size,
                          c_int32_p]),
    "sampler_points_find": (_int, [_char_p]),
    "sampler_points": (None, [_int, _u64, _size, Point_p]),
    "sampler_pentagon": (None, [_u64, _u64, Point_p]),
    "sampler_pentagons_find": (ctypes.POINTER(SamplerPentagons), [_char_p]),
    "sampler_convex": (None, [_u64, _u64, _int, Point_p]),
    "sampler_sites_find": (_int, [_char_p]),
    "sampler_sites": (_int, [_int, _u64, _u64, _int, Point_p]),
    "sampler_quad": (None, [_u64, _u64, Point_p]),
    "sampler_seed": (None, [ctypes.POINTER(SamplerRng), _u64, _u64]),
    "sampler_vector": (_int, [ctypes.POINTER(SamplerRng), _size, Point_p]),
    "sampler_circle": (_int, [ctypes.POINTER(SamplerRng), _size, Point_p]),
    "sampler_star": (_int, [ctypes.POINTER(SamplerRng), _size, Point_p]),
    "sampler_monotone": (_int, [ctypes.POINTER(SamplerRng), _size, Point_p]),
}

for _name, (_res, _args) in _PROTOS.items():
    _f = getattr(lib, _name)
    _f.restype = _res
    _f.argtypes = _args

ERRLEN = 1024


def errbuf():
    return ctypes.create_string_buffer(ERRLEN)


MAX_THREADS = 1024   # GEOM_MAX_THREADS (geom/geom.h), checked at import


def threads_arg(v):
    """A thread count as every entry point of the library takes it: 0 (all
    cores) or 1 .. MAX_THREADS, as an int; anything else raises ValueError
    in the library's words (geom_threads_check)."""
    ok = isinstance(v, (int, np.integer)) and not isinstance(v, (bool, np.bool_))
    if not ok or not 0 <= int(v) <= MAX_THREADS:
        raise ValueError("threads: expected 0 (all cores) or 1 .. %d, got %r"
                         % (MAX_THREADS, v))
    return int(v)


def text(b):
    """A C message (bytes) as str."""
    return b.value.decode("utf-8", "replace") if hasattr(b, "value") else b.decode()


def _check_layout():
    r = Rule()
    e = errbuf()
    if lib.rule_parse(b"P_1", ctypes.byref(r), e, ERRLEN) != 0 or r.name != b"P_1" \
            or r.kind != RULE_TRIANGLE or r.tie_eps != RULE_DEFAULT_TIE_EPS:
        raise ImportError("fliplab: python/fliplab/_lib.py's Rule does not match rule.h")
    o = LotOptionsRoom()
    lib.lot_options_init(ctypes.byref(o), ctypes.byref(r))
    oo = o.o
    if (oo.r.name, oo.algorithm, oo.order, oo.seed, oo.max_flips, oo.tie_eps, oo.decide,
            bool(oo.segments), oo.nsegments, bool(oo.holes), oo.nholes, oo.keep_hull) != \
            (b"P_1", 0, 0, 1, 0, RULE_DEFAULT_TIE_EPS, None, False, 0, False, 0, 0):
        raise ImportError("fliplab: python/fliplab/_lib.py's LotOptions does not match lot.h")
    if lib.geom_threads_check(MAX_THREADS, None, 0) != 0 or \
            lib.geom_threads_check(MAX_THREADS + 1, None, 0) == 0:
        raise ImportError("fliplab: python/fliplab/_lib.py's MAX_THREADS does not match geom.h")


_check_layout()
