"""_mirrors.py: the ctypes mirrors of the C structures the package still
fills or reads field by field, and the C callback types.

What is mirrored and why (docs/python.md, "How the package talks to the
library"): values the package passes by value or in arrays (geom_point,
rule, the census counts and the rows of reports/ that embed them, the
report metadata), structures the library hands back for the package to
walk (the flip graph of classify/siteflip.h, a .poly file's graph, a CDF
graph, geom_tri), and the registry entries a Python measure fills.  The
run options and results of lot/ and got/ are not here: they go through
the library's verbs (lot_options_set_*, lot_stats_get_u64,
got_result_get_double, ...).  python/tests/test_layout.py compares every
mirror of this module with the layout the compiler gave the headers.
"""
import ctypes

c_double_p = ctypes.POINTER(ctypes.c_double)
c_uint32_p = ctypes.POINTER(ctypes.c_uint32)
c_int32_p = ctypes.POINTER(ctypes.c_int32)

RULE_NAME_MAX = 1024
LOT_CYCLE_QUADS = 8
SITEFLIP_MAX_SITES = 16      # classify/siteflip.h; the graph's site array
JOINT_NAME_MAX = 16          # reports/report.h's row fields
MEASURE_NAME_FIELD = 64
SAMPLER_NAME_FIELD = 16


class Point(ctypes.Structure):
    """geom_point (geom/predicates.h)."""
    _fields_ = [("x", ctypes.c_double), ("y", ctypes.c_double)]


Point_p = ctypes.POINTER(Point)


class Rule(ctypes.Structure):
    """rule (fliprules/rule.h): passed by value and in arrays everywhere."""
    _fields_ = [("kind", ctypes.c_int), ("measure", ctypes.c_int), ("joint", ctypes.c_int),
                ("sign", ctypes.c_int), ("quad", ctypes.c_int), ("tie_eps", ctypes.c_double),
                ("name", ctypes.c_char * RULE_NAME_MAX)]


Rule_p = ctypes.POINTER(Rule)
RULE_TRIANGLE, RULE_QUAD = 0, 1


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
    """measure (badness/measure.h): read by name, filled by measure()."""
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


TRI_VARS = ("x1", "y1", "x2", "y2", "x3", "y3", "a", "b", "c", "alpha", "beta", "gamma", "A",
            "P", "R", "r", "h", "rx", "ry")


class GeomTri(ctypes.Structure):
    """geom_tri (geom/geom.h): 19 doubles in TRI_VARS' order."""
    _fields_ = [(n, ctypes.c_double) for n in TRI_VARS]


MeasureFn = ctypes.CFUNCTYPE(ctypes.c_double, ctypes.POINTER(GeomTri), ctypes.c_void_p)
ProgressFn = ctypes.CFUNCTYPE(None, ctypes.c_uint64, ctypes.c_uint64, ctypes.c_void_p)


class LotCdf(ctypes.Structure):
    """lot_cdf (lot/lot.h): the CDF graph lot_cdf_extract hands back."""
    _fields_ = [("triangles", ctypes.c_size_t), ("tri", c_uint32_p),
                ("edges", ctypes.c_size_t), ("edge", c_uint32_p),
                ("rounded", ctypes.c_size_t), ("conflicts", ctypes.c_size_t)]


class LotDiff(ctypes.Structure):
    """lot_diff (lot/lot.h): lot_compare's edges and triangles of two triangulations."""
    _fields_ = [(n, ctypes.c_size_t) for n in ("edges_a", "edges_b", "edges_common",
                                                "triangles_a", "triangles_b",
                                                "triangles_common")]


class FlipgraphCounts(ctypes.Structure):
    """flipgraph_counts (classify/flipgraph.h): one per rule, and in report_row."""
    _fields_ = [("samples", ctypes.c_uint64), ("type", ctypes.c_uint64 * 5),
                ("dt", ctypes.c_uint64)]


class FlipgraphRun(ctypes.Structure):
    """flipgraph_run (classify/flipgraph.h)."""
    _fields_ = [("seed", ctypes.c_uint64), ("first", ctypes.c_uint64),
                ("count", ctypes.c_uint64), ("tie_eps", ctypes.c_double),
                ("threads", ctypes.c_int), ("progress", ProgressFn),
                ("progress_ctx", ctypes.c_void_p), ("each", ctypes.c_void_p),
                ("each_ctx", ctypes.c_void_p), ("sampler", PentagonFn)]


class StudyConvexRun(ctypes.Structure):
    """study_convex_run (studies/study.h)."""
    _fields_ = [("sampler", ctypes.c_char_p), ("region", ctypes.c_int), ("law", ctypes.c_int),
                ("threads", ctypes.c_int), ("n", ctypes.c_size_t), ("seed", ctypes.c_uint64),
                ("inner", ctypes.c_char_p)]


SITEFLIP_COUNTS = ("samples", "tie", "no_sink", "one_sink", "multi_sink", "sink_dt", "sinks",
                   "max_sinks", "gap_units")


class SiteflipCounts(ctypes.Structure):
    """siteflip_counts (classify/siteflip.h): one per rule, and in report_census_row."""
    _fields_ = [(n, ctypes.c_uint64) for n in SITEFLIP_COUNTS]


class SiteflipQuad(ctypes.Structure):
    """siteflip_quad (classify/siteflip.h)."""
    _fields_ = [("v", ctypes.c_ubyte * 4), ("tri", ctypes.c_int * 4)]


class SiteflipEdge(ctypes.Structure):
    """siteflip_edge (classify/siteflip.h)."""
    _fields_ = [("ac", ctypes.c_int), ("bd", ctypes.c_int), ("quad", ctypes.c_int)]


class SiteflipGraph(ctypes.Structure):
    """siteflip_graph (classify/siteflip.h): the graph flipgraph() walks."""
    _fields_ = [("n", ctypes.c_int), ("p", Point * SITEFLIP_MAX_SITES),
                ("nnodes", ctypes.c_int), ("node", ctypes.c_void_p), ("per", ctypes.c_int),
                ("node_tri", ctypes.POINTER(ctypes.c_int)), ("ntris", ctypes.c_int),
                ("tri_v", ctypes.POINTER(ctypes.c_ubyte * 3)), ("tri", ctypes.c_void_p),
                ("nquads", ctypes.c_int), ("quad", ctypes.POINTER(SiteflipQuad)),
                ("nedges", ctypes.c_int), ("edge", ctypes.POINTER(SiteflipEdge)),
                ("adj_off", ctypes.c_void_p), ("adj", ctypes.c_void_p),
                ("delaunay", ctypes.c_int)]


SiteflipGraph_p = ctypes.POINTER(SiteflipGraph)


class SiteflipResult(ctypes.Structure):
    """siteflip_result (classify/siteflip.h)."""
    _fields_ = [("nsinks", ctypes.c_int), ("nsources", ctypes.c_int), ("ties", ctypes.c_int),
                ("cycle", ctypes.c_int), ("sink_dt", ctypes.c_int), ("has_got", ctypes.c_int),
                ("got_node", ctypes.c_int), ("got_total", ctypes.c_double),
                ("worst_sink", ctypes.c_int), ("worst_gap", ctypes.c_double)]


class ReportRow(ctypes.Structure):
    """report_row (reports/report.h)."""
    _fields_ = [("measure", ctypes.c_char * MEASURE_NAME_FIELD),
                ("joint", ctypes.c_char * JOINT_NAME_MAX),
                ("rule", ctypes.c_char * RULE_NAME_MAX), ("c", FlipgraphCounts)]


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
    _fields_ = [("measure", ctypes.c_char * MEASURE_NAME_FIELD),
                ("joint", ctypes.c_char * JOINT_NAME_MAX),
                ("rule", ctypes.c_char * RULE_NAME_MAX), ("sites", ctypes.c_int),
                ("sampler", ctypes.c_char * SAMPLER_NAME_FIELD), ("c", SiteflipCounts)]


class ReportCensusMeta(ctypes.Structure):
    """report_census_meta (reports/report.h)."""
    _fields_ = [("has_seed", ctypes.c_int), ("seed", ctypes.c_uint64),
                ("has_tie_eps", ctypes.c_int), ("tie_eps", ctypes.c_double),
                ("shard_k", ctypes.c_uint64), ("shard_n", ctypes.c_uint64)]


# ---- chapter 2's registry (paradigms/paradigm.h, geom/ops.h) ----------------
OPS_COUNT = 11   # ops_kind's OPS_COUNT, checked against ops_name at import (_lib.py)


class OpsCounts(ctypes.Structure):
    """ops_counts (geom/ops.h)."""
    _fields_ = [("v", ctypes.c_uint64 * OPS_COUNT), ("bytes", ctypes.c_uint64)]


class ParadigmAlgorithm(ctypes.Structure):
    """paradigm_algorithm (paradigms/paradigm.h): a row of the registry."""
    _fields_ = [("name", ctypes.c_char_p), ("paradigm", ctypes.c_char_p),
                ("section", ctypes.c_char_p), ("problems", ctypes.c_uint),
                ("rules", ctypes.c_uint), ("refusal", ctypes.c_char_p), ("cost", ctypes.c_char_p),
                ("param", ctypes.c_char_p), ("run", ctypes.c_void_p)]


class ParadigmInput(ctypes.Structure):
    """paradigm_input (paradigms/paradigm.h)."""
    _fields_ = [("p", Point_p), ("n", ctypes.c_size_t), ("r", Rule_p), ("problem", ctypes.c_int),
                ("segments", c_uint32_p), ("nsegments", ctypes.c_size_t),
                ("seed", ctypes.c_uint64), ("threads", ctypes.c_int), ("param", ctypes.c_double)]


class ParadigmResult(ctypes.Structure):
    """paradigm_result (paradigms/paradigm.h)."""
    _fields_ = [("tri", c_uint32_p), ("ntri", ctypes.c_size_t), ("ops", OpsCounts),
                ("seconds", ctypes.c_double), ("distinct", ctypes.c_size_t)]


# ---- section 4.2's l_inf circumcubes (linf/linf.h, studies/study_linf.h) -----
LINF_DIM_MIN, LINF_DIM_MAX = 2, 8
LINF_CUBES_MAX = 1 << (LINF_DIM_MAX - 1)
LINF_INFINITE = -1


class LinfCube(ctypes.Structure):
    """linf_cube (linf/linf.h)."""
    _fields_ = [("d", ctypes.c_int), ("side", ctypes.c_byte * LINF_DIM_MAX),
                ("face", ctypes.c_double * LINF_DIM_MAX), ("top", ctypes.c_double),
                ("bottom", ctypes.c_double)]


class LinfSimplices(ctypes.Structure):
    """linf_simplices (linf/linf.h)."""
    _fields_ = [("d", ctypes.c_int), ("n", ctypes.c_size_t), ("cap", ctypes.c_size_t),
                ("v", ctypes.POINTER(ctypes.c_ubyte))]


class LinfSelectStats(ctypes.Structure):
    """linf_select_stats (linf/linf.h)."""
    _fields_ = [(n, ctypes.c_uint64) for n in ("facets", "hull_facets", "cube_tests",
                                               "largest_set", "degenerate")]


class StudyLinfMc(ctypes.Structure):
    """study_linf_mc (studies/study_linf.h)."""
    _fields_ = [("d", ctypes.c_int), ("trials", ctypes.c_uint64), ("seed", ctypes.c_uint64),
                ("count", ctypes.c_uint64 * (LINF_CUBES_MAX + 1)), ("infinite", ctypes.c_uint64),
                ("law", ctypes.c_uint64 * (LINF_CUBES_MAX + 1)), ("law_total", ctypes.c_uint64)]
