"""test_layout.py: the package's view of the C structures agrees with the
layout the compiler gave the headers (python/tests/layout.c prints it;
ctest passes its path as FLIPLAB_LAYOUT).

- Every ctypes mirror (every ctypes.Structure of the package) has the same
  size, and each field the same offset and size; a partial mirror (the
  first fields only) is checked field by field.  Every mirror is listed
  here, and nothing is listed that is no mirror.
- The structures reached through verbs instead of a mirror: every field
  of lot_options and got_options has its setter (lot_options_set_FIELD), and
  every field of lot_stats, lot_check_result and got_result is readable by
  its name (the library's table, lot_stats_field, ...), the names tiling
  the structure as the compiler laid it out, so a field added to a header
  without its row in the table fails here."""
import ctypes
import importlib
import os
import pkgutil
import re
import subprocess

import pytest

import fliplab
from fliplab import _lib, _mirrors
from conftest import ROOT

# "module.Class" -> (C structure, complete: the sizes must agree too,
# {Python field: C designator})
_VERTS = {"%s%d" % (c, k + 1): "v[%d].%s" % (k, c) for k in range(3) for c in "xy"}
MIRRORS = {
    "_mirrors.Point": ("geom_point", True, {}),
    "_mirrors.GeomTri": ("geom_tri", True, dict(_VERTS, A="area")),
    "_mirrors.GeomPslg": ("geom_pslg", True, {}),
    "_mirrors.Rule": ("rule", True, {}),
    "_mirrors.Measure": ("measure", True, {}),
    "_mirrors.Joint": ("joint", False, {}),
    "_mirrors.RuleQuad": ("rule_quad", True, {}),
    "_mirrors.SamplerPentagons": ("sampler_pentagons", True, {}),
    "_mirrors.SamplerRng": ("sampler_rng", True, {}),
    "_mirrors.ReportPoly": ("report_poly", True, {}),
    "_mirrors.LotCdf": ("lot_cdf", True, {}),
    "_mirrors.LotDiff": ("lot_diff", True, {}),
    "_mirrors.FlipgraphCounts": ("flipgraph_counts", True, {}),
    "_mirrors.FlipgraphRun": ("flipgraph_run", True, {}),
    "_mirrors.StudyConvexRun": ("study_convex_run", True, {}),
    "_mirrors.SiteflipCounts": ("siteflip_counts", True, {}),
    "_mirrors.SiteflipQuad": ("siteflip_quad", True, {}),
    "_mirrors.SiteflipEdge": ("siteflip_edge", True, {}),
    "_mirrors.SiteflipGraph": ("siteflip_graph", True, {}),
    "_mirrors.SiteflipResult": ("siteflip_result", True, {}),
    "_mirrors.ReportRow": ("report_row", True, {}),
    "_mirrors.ReportRun": ("report_run", True, {}),
    "_mirrors.ReportMeta": ("report_meta", True, {}),
    "_mirrors.ReportCensusRow": ("report_census_row", True, {}),
    "_mirrors.ReportCensusMeta": ("report_census_meta", True, {}),
    "_classify.Flipgraph": ("flipgraph", True, {}),
    "_mirrors.OpsCounts": ("ops_counts", True, {}),
    "_mirrors.ParadigmAlgorithm": ("paradigm_algorithm", True, {}),
    "_mirrors.ParadigmInput": ("paradigm_input", True, {}),
    "_mirrors.ParadigmResult": ("paradigm_result", True, {}),
    "_mirrors.LinfCube": ("linf_cube", True, {}),
    "_mirrors.LinfSimplices": ("linf_simplices", True, {}),
    "_mirrors.LinfSelectStats": ("linf_select_stats", True, {}),
    "_mirrors.StudyLinfMc": ("study_linf_mc", True, {}),
}
# structures set by verbs: field -> the verb that sets it (default
# lot_options_set_FIELD), None for what a binding does not set
SETTERS = {
    "lot_options": {"r": "lot_options_new", "nsegments": "lot_options_set_segments",
                    "nholes": "lot_options_set_holes", "decide": None, "decide_ctx": None},
    "got_options": {},
}
# setters the design names that another part of the tree adds with its field
PENDING = {"lot_options_set_weights"}
# structures read by name: C structure -> the library's list of its field names
BY_NAME = {"lot_stats": "lot_stats_field", "lot_check_result": "lot_check_result_field",
           "got_result": "got_result_field"}


def _package_mirrors():
    """Every ctypes.Structure defined in a module of the package, as "module.Class"."""
    found = {}
    for m in pkgutil.iter_modules(fliplab.__path__):
        mod = importlib.import_module("fliplab." + m.name)
        for v in vars(mod).values():
            if isinstance(v, type) and issubclass(v, ctypes.Structure) \
                    and v.__module__ == mod.__name__:
                found["%s.%s" % (m.name, v.__name__)] = v
    return found


@pytest.fixture(scope="module")
def layout():
    exe = os.environ.get("FLIPLAB_LAYOUT",
                         os.path.join(ROOT, "build", "python", "fliplab_py_layout"))
    if not os.path.exists(exe):
        pytest.skip("python/tests/layout.c is not built (set FLIPLAB_LAYOUT)")
    out = subprocess.run([exe], capture_output=True, text=True, check=True).stdout
    sizes, fields = {}, {}
    for line in out.splitlines():
        w = line.split()
        if w[1] == "sizeof":
            sizes[w[0]] = int(w[2])
        else:
            fields.setdefault(w[0], {})[w[1]] = (int(w[2]), int(w[3]))
    return sizes, fields


def mismatches(layout, mirror, cname, complete, rename):
    """What differs between the ctypes mirror and C's cname, one line each."""
    sizes, fields = layout
    c = fields[cname]
    mine = {rename.get(name, name): (getattr(mirror, name).offset, getattr(mirror, name).size)
            for name, _ in mirror._fields_}
    out = ["%s.%s: no such field in C %s" % (mirror.__name__, f, cname)
           for f in mine if f not in c]
    out += ["%s.%s at %d (%d bytes), C %s.%s at %d (%d bytes)"
            % (mirror.__name__, f, off, size, cname, f, c[f][0], c[f][1])
            for f, (off, size) in mine.items() if f in c and (off, size) != c[f]]
    if complete:
        out += ["%s: C %s.%s is not mirrored" % (mirror.__name__, cname, f)
                for f in c if f not in mine]
        if ctypes.sizeof(mirror) != sizes[cname]:
            out.append("%s: %d bytes, C %s %d" % (mirror.__name__, ctypes.sizeof(mirror),
                                                  cname, sizes[cname]))
    return out


@pytest.mark.parametrize("name", sorted(_package_mirrors()))
def test_mirror_matches_c(layout, name):
    assert name in MIRRORS, "%s mirrors a C structure: list it in MIRRORS" % name
    assert mismatches(layout, _package_mirrors()[name], *MIRRORS[name]) == []


def test_mismatches_are_found(layout):
    """The comparison sees what a stale mirror gets wrong: a rule without its
    name (the last field), and a flipgraph_counts with one field too narrow."""
    class OldRule(ctypes.Structure):
        _fields_ = _mirrors.Rule._fields_[:-1]

    class NarrowCounts(ctypes.Structure):
        _fields_ = [(n, ctypes.c_uint32 if n == "samples" else t)
                    for n, t in _mirrors.FlipgraphCounts._fields_]
    old = mismatches(layout, OldRule, "rule", True, {})
    assert old == ["OldRule: C rule.name is not mirrored",
                   "OldRule: %d bytes, C rule %d" % (ctypes.sizeof(OldRule), layout[0]["rule"])]
    narrow = mismatches(layout, NarrowCounts, "flipgraph_counts", True, {})
    assert narrow == [
        "NarrowCounts.samples at 0 (4 bytes), C flipgraph_counts.samples at 0 (8 bytes)"]


def test_every_structure_accounted_for(layout):
    """Each structure layout.c prints is mirrored, set by verbs or read by
    name; each mirror's C structure is printed."""
    mirrored = {m[0] for m in MIRRORS.values()}
    assert set(layout[0]) == mirrored | set(SETTERS) | set(BY_NAME)
    assert not mirrored & (set(SETTERS) | set(BY_NAME))


def _setter_cases():
    return [(s, f) for s in ("lot_options", "got_options") for f in _fields_of(s)]


def _fields_of(cname):
    """The fields layout.c prints for cname (read from its source: the
    parametrisation is made before the layout program runs)."""
    with open(os.path.join(ROOT, "python", "tests", "layout.c")) as f:
        return re.findall(r"\bF\(%s, (\w+)\)" % cname, f.read())


@pytest.mark.parametrize("cname,field", _setter_cases())
def test_every_option_has_a_setter(layout, cname, field):
    assert field in layout[1][cname]
    verb = SETTERS[cname].get(field, "%s_set_%s" % (cname, field))
    if verb is None:
        return
    if verb in PENDING and not hasattr(_lib.lib, verb):
        pytest.xfail("%s: designed (docs/python.md), not yet in the library" % verb)
    assert hasattr(_lib.lib, verb), "C %s.%s has no setter %s" % (cname, field, verb)
    assert verb in _lib._PROTOS, "%s is not declared in _lib._PROTOS" % verb


@pytest.mark.parametrize("cname", sorted(BY_NAME))
def test_every_field_readable_by_name(layout, cname):
    """The library's names are the fields layout.c prints, in declaration
    order, and they tile the structure: between two fields, and after the
    last, only the padding the next field's alignment needs."""
    sizes, fields = layout
    names = _lib.c_names(getattr(_lib.lib, BY_NAME[cname]))
    c = fields[cname]
    assert list(names) == sorted(c, key=lambda f: c[f][0])
    end = 0
    for f in names:
        off, size = c[f]
        assert 0 <= off - end < 8, "%s: %d bytes before %s are no field" % (cname, off - end, f)
        end = off + size
    assert 0 <= sizes[cname] - end < 8, "%s: bytes after its last field" % cname
