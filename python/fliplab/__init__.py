"""fliplab: flip rules, locally and globally optimal triangulations and
directed flip graphs, from numpy (a ctypes layer over libfliplab.so; no
compiler needed).  Needs numpy 1.24 (Debian 12's python3-numpy; use
/usr/bin/python3).  The API, its conventions and where they differ from
scipy's: docs/python.md.

    import fliplab, numpy as np
    p = fliplab.samplers.points(1000, "uniform", seed=1)
    t = fliplab.lot(p, "P_1")          # t.triangles, t.neighbors, t.badness
"""
from . import _lib
from ._rules import (AC, BD, EITHER, UNDECIDED, Rule, badness, decide, define, joints,
                     load_plugin, measures, quad_rules, rules)
from ._lot import (ALGORITHMS, ORDERS, Check, CheckError, Triangulation, check, lot,
                   read_poly)
from . import _samplers as samplers
from ._census import Counts, census, table34
from ._got import Got, got
from ._flipgraph import FlipGraph, flipgraph
from ._pymeasure import measure, quantities
from ._classify import classify, verdicts, wilson
from ._cdf import Cdf, cdf
from ._scipy import from_shapely, lot_polygon

__version__ = "0.1.0"
library_path = _lib.path

__all__ = ["AC", "BD", "EITHER", "UNDECIDED", "Rule", "badness", "decide", "define", "joints",
           "load_plugin", "measures", "quad_rules", "rules", "ALGORITHMS", "ORDERS", "Check",
           "CheckError", "Triangulation", "check", "lot", "read_poly", "samplers",
           "library_path", "Counts", "census", "table34", "Got", "got", "FlipGraph", "flipgraph",
           "measure", "quantities", "classify", "verdicts", "wilson", "Cdf", "cdf",
           "from_shapely", "lot_polygon"]
