"""_lib.py: loading libfliplab.so with ctypes, and every prototype of the
package: each C function it calls is declared here, in _PROTOS (restype,
argtypes), and nowhere else (python/tests/test_package.py checks).

Where the library is found, first match wins:
  1. the environment variable FLIPLAB_LIBRARY (a path to libfliplab.so:
     a build tree's, e.g. FLIPLAB_LIBRARY=build/libfliplab.so);
  2. the library installed with this package (``cmake --install`` writes
     _install.py beside this file, naming it relative to the package);
  3. the library pip installed inside this package (setup.py copies it here);
  4. the dynamic linker's search (ldconfig, LD_LIBRARY_PATH).

ctypes.CDLL releases the GIL for the duration of every call, so a long C
call (a triangulation of 10^6 points, a census) lets other Python threads
run.  What the package reads from the library rather than restating:
RULE_DEFAULT_TIE_EPS (the tie tolerance of a rule the library makes), the
names of lot_stats' fields, which options go together
(lot_options_check).  The structures it still mirrors are in _mirrors.py;
_check_layout() tests the rule mirror and MAX_THREADS when the module
loads, so that a library built from other headers fails at import
instead of reading garbage.
"""
import ctypes
import os

from ._args import MAX_THREADS
from ._mirrors import (FlipgraphCounts, FlipgraphRun, GeomTri, Joint, LotCdf, LotDiff, Measure,
                       Point, Point_p, ProgressFn, ReportCensusMeta, ReportCensusRow,
                       ReportMeta, ReportPoly, ReportRow, Rule, Rule_p, RuleQuad,
                       SamplerPentagons, SamplerRng, SiteflipCounts, SiteflipGraph_p,
                       SiteflipResult, StudyConvexRun, c_double_p, c_int32_p, c_uint32_p,
                       RULE_TRIANGLE, OPS_COUNT, LinfCube, LinfSelectStats, LinfSimplices,
                       ParadigmAlgorithm, ParadigmInput, ParadigmResult, StudyLinfMc)

SONAME = "libfliplab.so.0.1"


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
            "the path of libfliplab.so (a build tree's, e.g. build/libfliplab.so), or "
            "install the package with the library (docs/python.md)" % (path, e)) from None


lib, path = _load()
libc = ctypes.CDLL(None)     # open_memstream, for the tables written into memory

_size = ctypes.c_size_t
_size_p = ctypes.POINTER(ctypes.c_size_t)
_char_p = ctypes.c_char_p
_int = ctypes.c_int
_int_p = ctypes.POINTER(ctypes.c_int)
_u64 = ctypes.c_uint64
_u64_p = ctypes.POINTER(ctypes.c_uint64)
_i64_p = ctypes.POINTER(ctypes.c_int64)
_double = ctypes.c_double
_void_p = ctypes.c_void_p       # the library's own objects: lot, lot_options, got_result, ...
_rng_p = ctypes.POINTER(SamplerRng)

# name: (restype, argtypes), by header
_PROTOS = {
    # fliprules/rule.h, badness/measure.h, badness/formula.h, joints/joint.h, plugins
    "rule_parse": (_int, [_char_p, Rule_p, _char_p, _size]),
    "rule_triangle": (_int, [_int, _int, Rule_p, _char_p, _size]),
    "rule_delaunay": (Rule, []),
    "rule_quad_count": (_int, []),
    "rule_quad_get": (ctypes.POINTER(RuleQuad), [_int]),
    "rule_eval_quads": (None, [Rule_p, Point_p, _size, ctypes.POINTER(ctypes.c_byte),
                               c_double_p, c_double_p]),
    "rule_total_key": (_double, [Rule_p, c_double_p, _size]),
    "rule_gap": (_double, [Rule_p, _double, _double]),
    "rule_list_triangle": (_int, [_int_p, _int, Rule_p, _int]),
    "rule_is_shape": (_int, [Rule_p]),
    "rule_shape": (_void_p, [Rule_p]),
    "shape_circumscribe_draw": (_int, [_void_p, Point, Point, Point, Point_p, _int, _int_p]),
    "measure_count": (_int, []),
    "measure_get": (ctypes.POINTER(Measure), [_int]),
    "measure_find": (_int, [_char_p]),
    "measure_eval_tris": (None, [_int, Point_p, _size, c_double_p]),
    "measure_register": (_int, [ctypes.POINTER(Measure)]),
    "measure_check_name": (_int, [_char_p, _char_p, _char_p, _size]),
    "joint_count": (_int, []),
    "joint_get": (ctypes.POINTER(Joint), [_int]),
    "formula_define": (_int, [_char_p, _char_p, _size]),
    "formula_check_errors": (_int, [_char_p, _size]),
    "formula_clear_errors": (None, []),
    "formula_check_value": (_double, [_char_p, ctypes.POINTER(GeomTri), _double, _int, _int]),
    "formula_note_message": (None, [_char_p]),
    "plugin_load": (_int, [_char_p, _char_p, _size]),
    # geom/geom.h
    "geom_coord_check": (_int, [_double]),
    "geom_coorderr_str": (_char_p, [_int]),
    "geom_coord_check_n": (_size, [c_double_p, _size]),
    "geom_threads_check": (_int, [ctypes.c_longlong, _char_p, _size]),
    "geom_weight_check": (_int, [ctypes.c_double]),
    "geom_weighterr_str": (_char_p, [_int]),
    "geom_tri_make_n": (None, [ctypes.POINTER(GeomTri), Point_p, _size]),
    "geom_simple_polygon_check": (_int, [Point_p, _size, _size_p, _size_p, _int_p]),
    # lot/lot.h: the run's options and results through verbs
    "lot_options_new": (_void_p, [Rule_p]),
    "lot_options_free": (None, [_void_p]),
    "lot_options_set_algorithm": (_int, [_void_p, _int]),
    "lot_options_set_order": (_int, [_void_p, _int]),
    "lot_options_set_seed": (None, [_void_p, _u64]),
    "lot_options_set_max_flips": (None, [_void_p, _u64]),
    "lot_options_set_tie_eps": (_int, [_void_p, _double]),
    "lot_options_set_segments": (None, [_void_p, c_uint32_p, _size]),
    "lot_options_set_holes": (None, [_void_p, Point_p, _size]),
    "lot_options_set_weights": (None, [_void_p, c_double_p]),
    "lot_options_set_ops": (None, [_void_p, _void_p]),
    "lot_get_redundant": (_size, [_void_p, c_uint32_p]),
    "lot_check_weighted": (_int, [Point_p, c_double_p, _size, c_uint32_p, _size, Rule_p,
                                  _void_p]),
    "lot_options_set_keep_hull": (None, [_void_p, _int]),
    "lot_options_check": (_int, [_void_p, _char_p, _size]),
    "lot_default_max_flips": (_u64, [_size]),
    "lot_check_memory": (_int, [_size, _char_p, _size]),
    "lot_build": (_int, [ctypes.POINTER(_void_p), Point_p, _size, _void_p, _char_p, _size]),
    "lot_free": (None, [_void_p]),
    "lot_get_stats": (_void_p, [_void_p]),
    "lot_stats_field": (_char_p, [_size]),
    "lot_stats_get_u64": (_int, [_void_p, _char_p, _size, _u64_p]),
    "lot_stats_get_double": (_int, [_void_p, _char_p, c_double_p]),
    "lot_get_triangles": (None, [_void_p, c_uint32_p]),
    "lot_get_hull": (_size, [_void_p, c_uint32_p]),
    "lot_get_constrained": (_size, [_void_p, c_uint32_p]),
    "lot_get_neighbors": (_int, [_void_p, c_int32_p]),
    "lot_get_badness": (None, [Point_p, c_uint32_p, _size, Rule_p, c_double_p]),
    "lot_neighbors": (_int, [c_uint32_p, _size, _size, c_int32_p]),
    "lot_locate": (_int, [Point_p, _size, c_uint32_p, c_int32_p, _size, _int, Point_p, _size,
                          c_int32_p]),
    "lot_check_result_new": (_void_p, []),
    "lot_check_result_free": (None, [_void_p]),
    "lot_check_result_field": (_char_p, [_size]),
    "lot_check_result_get_u64": (_int, [_void_p, _char_p, _size, _u64_p]),
    "lot_check": (_int, [Point_p, _size, c_uint32_p, _size, Rule_p, _void_p]),
    "lot_check_constrained": (_int, [Point_p, _size, c_uint32_p, _size, c_uint32_p, _size,
                                     Rule_p, _void_p]),
    "lot_cdf_extract": (_int, [Point_p, c_uint32_p, _size, _void_p, ctypes.POINTER(LotCdf)]),
    "lot_cdf_free": (None, [ctypes.POINTER(LotCdf)]),
    "lot_compare": (_int, [c_uint32_p, _size, c_uint32_p, _size, ctypes.POINTER(LotDiff)]),
    # got/got.h
    "got_options_new": (_void_p, []),
    "got_options_free": (None, [_void_p]),
    "got_options_set_threads": (_int, [_void_p, _int]),
    "got_options_set_tie_eps": (_int, [_void_p, _double]),
    "got_result_new": (_void_p, []),
    "got_result_delete": (None, [_void_p]),
    "got_result_field": (_char_p, [_size]),
    "got_result_get_i64": (_int, [_void_p, _char_p, _i64_p]),
    "got_result_get_double": (_int, [_void_p, _char_p, c_double_p]),
    "got_result_get_text": (_char_p, [_void_p, _char_p]),
    "got_result_get_triangles": (_size, [_void_p, c_int32_p, c_double_p]),
    "got_check_memory": (_int, [_size, _int, _char_p, _size]),
    "got_solve": (_int, [Point_p, _size, Rule_p, _void_p, _void_p, _char_p, _size]),
    "got_format_total": (None, [_void_p, _double, _char_p, _size]),
    "got_points_check_memory": (_int, [_size, _char_p, _size]),
    "got_points_solve": (_int, [Point_p, _size, Rule_p, _void_p, _int, _void_p, _char_p, _size]),
    "study_got_points": (_int, [Point_p, _size, Rule_p, _void_p, _int, _void_p, _char_p, _size]),
    "got_skeleton_find": (_int, [_char_p]),
    # classify/flipgraph.h, classify/siteflip.h
    "flipgraph_tally_run": (_int, [Rule_p, _int, ctypes.POINTER(FlipgraphRun),
                                   ctypes.POINTER(FlipgraphCounts)]),
    "siteflip_census": (_int, [Rule_p, _int, _int, _int, _u64, _u64, _u64, _double, _int, _size,
                               ctypes.POINTER(SiteflipCounts), ProgressFn, _void_p, _int_p,
                               _char_p, _size]),
    "siteflip_build": (SiteflipGraph_p, [Point_p, _int, _char_p, _size]),
    "siteflip_count_upto": (_int, [Point_p, _int, _int, _int_p, _char_p, _size]),
    "siteflip_free": (None, [SiteflipGraph_p]),
    "siteflip_direct": (_int, [SiteflipGraph_p, Rule_p, _double, _int_p, _int_p,
                               ctypes.POINTER(SiteflipResult)]),
    "siteflip_direct_weighted": (_int, [SiteflipGraph_p, Rule_p, c_double_p, _double, _int_p,
                                        _int_p, ctypes.POINTER(SiteflipResult)]),
    "siteflip_node_key": (_double, [SiteflipGraph_p, Rule_p, _int]),
    # samplers/sampler.h
    "sampler_points_find": (_int, [_char_p]),
    "sampler_points": (None, [_int, _u64, _size, Point_p]),
    "sampler_pentagons_find": (ctypes.POINTER(SamplerPentagons), [_char_p]),
    "sampler_sites_find": (_int, [_char_p]),
    "sampler_sites": (_int, [_int, _u64, _u64, _int, Point_p]),
    "sampler_quad": (None, [_u64, _u64, Point_p]),
    "sampler_gon_check": (_int, [_char_p, _int, _size, _char_p, _size]),
    "sampler_gon_check_variant": (_int, [_char_p, _int, _char_p, _size, _char_p, _size]),
    "sampler_gon_inner": (_void_p, [_char_p]),
    "sampler_region_find": (_int, [_char_p]),
    "sampler_region_name": (_char_p, [_int]),
    "sampler_gon_names": (_char_p, []),
    "sampler_seed": (None, [_rng_p, _u64, _u64]),
    "sampler_vector": (_int, [_rng_p, _size, Point_p]),
    "sampler_circle": (_int, [_rng_p, _size, Point_p]),
    "sampler_star": (_int, [_rng_p, _size, Point_p]),
    "sampler_monotone": (_int, [_rng_p, _size, Point_p]),
    # reports/report.h
    "report_poly_read": (_int, [_char_p, ctypes.POINTER(ReportPoly), _char_p, _size]),
    "report_poly_free": (None, [ctypes.POINTER(ReportPoly)]),
    "report_format_parse": (_int, [_char_p, _int_p]),
    "report_write": (_int, [_void_p, _int, ctypes.POINTER(ReportMeta),
                            ctypes.POINTER(ReportRow), _int]),
    "report_census_write": (_int, [_void_p, _int, ctypes.POINTER(ReportCensusMeta),
                                   ctypes.POINTER(ReportCensusRow), _int]),
    "report_svg_colour": (None, [_double, _char_p, _size]),
    # classify/flipgraph.h (flipgraph out: _classify.Flipgraph), geom/geom.h
    "flipgraph_classify_n": (_size, [Point_p, _size, Rule_p, _int, _double, _int, _void_p,
                                     _int_p, _size_p]),
    "geom_polyerr_str": (_char_p, [_int]),
    # cpdt/cpdt.h, studies/study_cpdt.h: chapter 5's workbench (_cpdt.py)
    "cpdt_algorithm_name": (_char_p, [_int]),
    "cpdt_check": (_int, [Point_p, _size, _size_p]),
    "cpdt_check_str": (_char_p, [_int]),
    "cpdt_triangulate": (_int, [Point_p, _size, _int, _u64, c_uint32_p, _void_p]),
    "cpdt_counts_new": (_void_p, []),
    "cpdt_counts_delete": (None, [_void_p]),
    "cpdt_counts_field": (_char_p, [_size]),
    "cpdt_counts_get_double": (_int, [_void_p, _char_p, c_double_p]),
    "cpdt_counts_get_u64": (_int, [_void_p, _char_p, _u64_p]),
    "study_cpdt_sampler_name": (_char_p, [_int]),
    "study_cpdt_sampler_check": (_int, [_int, _int, _int, _size, _char_p, _size]),
    "study_cpdt_count_name": (_char_p, [_int]),
    "study_cpdt_run": (_int, [_u64_p, _size, _int_p, _size, _u64, _u64, _int, _int, _int,
                              _void_p, _char_p, _size]),
    "study_cpdt_cells_new": (_void_p, [_size]),
    "study_cpdt_cells_delete": (None, [_void_p]),
    "study_cpdt_cell_get": (_int, [_void_p, _size, _int, c_double_p, c_double_p]),
    "study_cpdt_slope": (_double, [_void_p, _size, _int, _int]),
    # studies/study.h: the studies, their results through verbs (_studies.py)
    "study_wilson": (None, [_u64, _u64, c_double_p, c_double_p]),
    "study_convex_draw": (_int, [ctypes.POINTER(StudyConvexRun), _u64, _u64, Point_p, c_double_p,
                                 _u64_p, c_double_p, _u64_p]),
    "study_convex_summary": (None, [c_double_p, c_double_p, _size, c_double_p, c_double_p,
                                    c_double_p]),
    "study_convex_stat_name": (_char_p, [_int]),
    "study_pentagons": (_int, [Rule_p, _int, ctypes.POINTER(FlipgraphRun), _int, _void_p]),
    "study_quads": (_int, [Rule_p, _u64, _u64, _int, _void_p, _char_p, _size]),
    "study_sites": (_int, [Rule_p, _int, _int, _u64, _u64, _double, _int, _void_p, _char_p,
                           _size]),
    "study_lot_got": (_int, [_void_p, c_uint32_p, _size, c_uint32_p, _size, Rule_p, _int,
                             _void_p, _char_p, _size]),
    "study_verdict_new": (_void_p, []),
    "study_verdict_delete": (None, [_void_p]),
    "study_verdict_field": (_char_p, [_size]),
    "study_verdict_get_u64": (_int, [_void_p, _char_p, _size, _u64_p]),
    "study_verdict_interval": (_int, [_void_p, _int, c_double_p, c_double_p]),
    "study_verdict_witness": (ctypes.c_int64, [_void_p, _int, _int]),
    "study_quadcheck_new": (_void_p, []),
    "study_quadcheck_delete": (None, [_void_p]),
    "study_quadcheck_field": (_char_p, [_size]),
    "study_quadcheck_get_u64": (_int, [_void_p, _char_p, _size, _u64_p]),
    "study_quadcheck_get_double": (_int, [_void_p, _char_p, c_double_p]),
    "study_sitecheck_new": (_void_p, []),
    "study_sitecheck_delete": (None, [_void_p]),
    "study_sitecheck_field": (_char_p, [_size]),
    "study_sitecheck_get_u64": (_int, [_void_p, _char_p, _size, _u64_p]),
    "study_sitecheck_sites": (_int, [_void_p, Point_p]),
    "study_gotcheck_new": (_void_p, []),
    "study_gotcheck_delete": (None, [_void_p]),
    "study_gotcheck_field": (_char_p, [_size]),
    "study_gotcheck_get_u64": (_int, [_void_p, _char_p, _size, _u64_p]),
    "study_gotcheck_get_double": (_int, [_void_p, _char_p, c_double_p]),
    "study_gotcheck_get_text": (_char_p, [_void_p, _char_p]),
    "study_gotcheck_triangles": (c_uint32_p, [_void_p]),
    "study_gotcheck_got": (_void_p, [_void_p]),
    # studies/triavg.h: chapter 5's exact averages (_averages.py)
    "study_avg_name": (_char_p, [_int]),
    "study_avg_new": (_void_p, [_int, _int, _char_p, _size]),
    "study_avg_delete": (None, [_void_p]),
    "study_avg_text": (_size, [_void_p, _int, _int, _int, _char_p, _size]),
    "study_avg_degcount_text": (_size, [_void_p, _int, _int, _int, _char_p, _size]),
    "study_tri_measure": (_int, [c_uint32_p, _size, ctypes.c_uint32, _u64_p, c_uint32_p,
                                 _char_p, _size]),
    # paradigms/paradigm.h, geom/ops.h: chapter 2's registry and runner (_paradigms.py)
    "ops_name": (_char_p, [_int]),
    "paradigm_count": (_size, []),
    "paradigm_get": (ctypes.POINTER(ParadigmAlgorithm), [_size]),
    "paradigm_problem_name": (_char_p, [_int]),
    "paradigm_run": (_int, [ctypes.POINTER(ParadigmAlgorithm), ctypes.POINTER(ParadigmInput),
                            ctypes.POINTER(ParadigmResult), _char_p, _size]),
    "paradigm_result_free": (None, [ctypes.POINTER(ParadigmResult)]),
    # linf/linf.h, studies/study_linf.h: section 4.2's l_inf circumcubes (_linf.py)
    "linf_circumcubes": (_int, [c_double_p, _int, ctypes.POINTER(LinfCube)]),
    "linf_cube_side": (_int, [ctypes.POINTER(LinfCube), c_double_p]),
    "linf_cube_centre": (None, [ctypes.POINTER(LinfCube), _char_p, _size]),
    "linf_cube_distance": (None, [ctypes.POINTER(LinfCube), c_double_p, _char_p, _size]),
    "linf_bound": (_int, [_int]),
    "linf_extremal": (None, [_int, c_double_p]),
    "linf_simplices_init": (None, [ctypes.POINTER(LinfSimplices), _int]),
    "linf_simplices_free": (None, [ctypes.POINTER(LinfSimplices)]),
    "linf_delaunay_brute": (_int, [c_double_p, _size, _int, ctypes.POINTER(LinfSimplices),
                                   _u64_p]),
    "linf_delaunay_select": (_int, [c_double_p, _size, _int, ctypes.POINTER(LinfSimplices),
                                    ctypes.POINTER(LinfSelectStats)]),
    "study_linf_montecarlo": (_int, [_int, _u64, _u64, _int, ctypes.POINTER(StudyLinfMc),
                                     _char_p, _size]),
}

# the C library's own, for a table written into memory (_report.py)
_LIBC_PROTOS = {
    "open_memstream": (_void_p, [ctypes.POINTER(_void_p), _size_p]),
    "fclose": (_int, [_void_p]),
    "free": (None, [_void_p]),
}


def _declare(dll, protos):
    for name, (res, args) in protos.items():
        f = getattr(dll, name)
        f.restype = res
        f.argtypes = args


_declare(lib, _PROTOS)
_declare(libc, _LIBC_PROTOS)

ERRLEN = 1024


def errbuf():
    """A buffer for a C message (char *err, size_t errlen = ERRLEN)."""
    return ctypes.create_string_buffer(ERRLEN)


def text(b):
    """A C message (a buffer or bytes) as str."""
    return b.value.decode("utf-8", "replace") if hasattr(b, "value") else b.decode()


def c_names(field):
    """The names field(0), field(1), ... until NULL (lot_stats_field, ...)."""
    out, i = [], 0
    while (name := field(i)) is not None:
        out.append(name.decode())
        i += 1
    return tuple(out)


def get_u64(getter, obj, name, i=0):
    """Element i of the count `name` of obj, by getter (lot_stats_get_u64,
    lot_check_result_get_u64)."""
    v = ctypes.c_uint64()
    if getter(obj, name.encode(), i, ctypes.byref(v)) != 0:
        raise LookupError("fliplab: the library has no count %s[%d]" % (name, i))
    return v.value


def get_value(obj, name, getters):
    """The field `name` of obj by the first getter of (getter, ctype) that
    has it: an int or a float (got_result_get_i64, got_result_get_double)."""
    for getter, ctype in getters:
        v = ctype()
        if getter(obj, name.encode(), ctypes.byref(v)) == 0:
            return v.value
    raise LookupError("fliplab: the library has no field %s" % name)


# the library's default tie tolerance: the one of a rule it makes (rule.h)
RULE_DEFAULT_TIE_EPS = lib.rule_delaunay().tie_eps
LOT_STATS_FIELDS = c_names(lib.lot_stats_field)


def _check_layout():
    r = Rule()
    e = errbuf()
    if lib.rule_parse(b"P_1", ctypes.byref(r), e, ERRLEN) != 0 or r.name != b"P_1" \
            or r.kind != RULE_TRIANGLE or r.tie_eps != RULE_DEFAULT_TIE_EPS:
        raise ImportError("fliplab: python/fliplab/_mirrors.py's Rule does not match rule.h")
    if lib.geom_threads_check(MAX_THREADS, None, 0) != 0 or \
            lib.geom_threads_check(MAX_THREADS + 1, None, 0) == 0:
        raise ImportError("fliplab: python/fliplab/_args.py's MAX_THREADS does not match geom.h")
    if len(c_names(lib.ops_name)) != OPS_COUNT:
        raise ImportError("fliplab: python/fliplab/_mirrors.py's OPS_COUNT does not match ops.h")


_check_layout()
