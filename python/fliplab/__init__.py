"""fliplab: flip rules, locally and globally optimal triangulations and
directed flip graphs, from numpy (a ctypes layer over libfliplab.so; no
compiler needed).  Needs numpy 1.24 (Debian 12's python3-numpy; use
/usr/bin/python3).  The API, its conventions and where they differ from
scipy's: docs/python.md.

    import fliplab
    p = fliplab.samplers.points(1000, "uniform", seed=1)
    t = fliplab.lot(p, "P_1")          # t.triangles, t.neighbors, t.badness

The public modules are this one, fliplab.samplers and fliplab.plot; every
module whose name starts with an underscore is internal.
"""
from . import _lib
from ._rules import (AC, BD, EITHER, SIGNS, UNDECIDED, Rule, badness, decide, define, joints,
                     load_plugin, measures, quad_rules, rules)
from ._lot import (ALGORITHMS, ORDERS, STATUS, Check, CheckError, Triangulation, check, lot,
                   read_poly)
from . import plot, samplers
from ._census import FORMATS, Counts, census, table34
from ._got import SKELETONS, Got, got, got_points
from ._flipgraph import FlipGraph, count_triangulations, flipgraph
from ._pymeasure import measure, quantities
from ._classify import classify
from ._studies import compare_got, verdicts, wilson
from ._averages import CH5_METHODS, CH5_QUANTITIES, ch5_averages, ch5_measure
from ._cdf import Cdf, cdf
from ._convex import CONVEX_INNER, CONVEX_SAMPLERS, REGIONS, ConvexPolygons, convex_polygons
from ._scipy import from_shapely, lot_polygon
from ._cpdt import (CPDT_ALGORITHMS, CPDT_COUNTS, CPDT_SAMPLERS, convex_dt,
                    convex_dt_experiment)
from ._paradigms import OPS_NAMES, PARADIGM_ALGORITHMS, PARADIGM_PROBLEMS, paradigms, triangulate_by
from ._linf import (LINF_METHODS, LinfCube, linf_bound, linf_circumcubes, linf_delaunay,
                    linf_extremal, linf_montecarlo)

__version__ = "0.1.0"
library_path: str = _lib.path

__all__ = ["AC", "BD", "EITHER", "UNDECIDED", "Rule", "badness", "decide", "define", "joints",
           "load_plugin", "measures", "quad_rules", "rules", "SIGNS", "ALGORITHMS", "ORDERS",
           "STATUS", "Check", "CheckError", "Triangulation", "check", "lot", "read_poly",
           "samplers", "plot", "library_path", "FORMATS", "Counts", "census", "table34", "Got",
           "got", "got_points", "SKELETONS", "FlipGraph", "flipgraph", "count_triangulations",
           "measure", "quantities", "classify", "verdicts", "wilson", "Cdf", "cdf",
           "from_shapely", "lot_polygon",
           "compare_got", "ch5_averages", "ch5_measure", "CH5_METHODS", "CH5_QUANTITIES",
           "CPDT_ALGORITHMS", "CPDT_COUNTS", "CPDT_SAMPLERS", "convex_dt", "convex_dt_experiment",
           "CONVEX_INNER", "CONVEX_SAMPLERS", "REGIONS", "ConvexPolygons", "convex_polygons",
           "OPS_NAMES", "PARADIGM_ALGORITHMS", "PARADIGM_PROBLEMS", "paradigms", "triangulate_by",
           "LINF_METHODS", "LinfCube", "linf_bound", "linf_circumcubes", "linf_delaunay",
           "linf_extremal", "linf_montecarlo"]
