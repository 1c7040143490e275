"""test_layout.py: every ctypes mirror of a C structure in python/fliplab
has the layout the compiler gave the header: the same size, and each
field at the same offset with the same size (python/tests/layout.c prints
them; ctest passes its path as FLIPLAB_LAYOUT).  A partial mirror (the
first fields only) is checked field by field; every mirror in the package
is in the list below, and every structure of the list is mirrored."""
import ctypes
import os
import subprocess

import pytest

from fliplab import _cdf, _census, _classify, _flipgraph, _got, _lib, _pymeasure, _report
from conftest import ROOT

# mirror -> (C structure, complete: the sizes must agree too, {Python field: C designator})
_VERTS = {"%s%d" % (c, k + 1): "v[%d].%s" % (k, c) for k in range(3) for c in "xy"}
MIRRORS = {
    _lib.Point: ("geom_point", True, {}),
    _pymeasure.GeomTri: ("geom_tri", True, dict(_VERTS, A="area")),
    _lib.GeomPslg: ("geom_pslg", True, {}),
    _lib.Rule: ("rule", True, {}),
    _lib.Measure: ("measure", True, {}),
    _lib.Joint: ("joint", False, {}),
    _lib.RuleQuad: ("rule_quad", True, {}),
    _lib.SamplerPentagons: ("sampler_pentagons", True, {}),
    _lib.SamplerRng: ("sampler_rng", True, {}),
    _lib.LotOptions: ("lot_options", True, {}),
    _lib.LotStats: ("lot_stats", True, {}),
    _lib.LotCheckResult: ("lot_check_result", True, {}),
    _lib.ReportPoly: ("report_poly", True, {}),
    _census.FlipgraphCounts: ("flipgraph_counts", True, {}),
    _classify.Flipgraph: ("flipgraph", True, {}),
    _cdf.LotCdf: ("lot_cdf", True, {}),
    _report.ReportRow: ("report_row", True, {}),
    _report.ReportRun: ("report_run", True, {}),
    _report.ReportMeta: ("report_meta", True, {}),
    _report.ReportCensusRow: ("report_census_row", True, {}),
    _report.ReportCensusMeta: ("report_census_meta", True, {}),
    _census.FlipgraphRun: ("flipgraph_run", True, {}),
    _census.SiteflipCounts: ("siteflip_counts", True, {}),
    _flipgraph.SiteflipQuad: ("siteflip_quad", True, {}),
    _flipgraph.SiteflipEdge: ("siteflip_edge", True, {}),
    _flipgraph.SiteflipGraph: ("siteflip_graph", True, {}),
    _flipgraph.SiteflipResult: ("siteflip_result", True, {}),
    _got.GotTriangle: ("got_triangle", True, {}),
    _got.GotOptions: ("got_options", True, {}),
    _got.GotResult: ("got_result", True, {}),
}


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


@pytest.mark.parametrize("mirror", list(MIRRORS), ids=lambda m: m.__name__)
def test_mirror_matches_c(layout, mirror):
    assert mismatches(layout, mirror, *MIRRORS[mirror]) == []


def test_mismatches_are_found(layout):
    """The comparison sees what a stale mirror gets wrong: lot_options as
    the package mirrored it before the constraint fields (8 fields), and a
    lot_stats with one field a size_t too narrow."""
    class OldOptions(ctypes.Structure):
        _fields_ = _lib.LotOptions._fields_[:8]

    class NarrowStats(ctypes.Structure):
        _fields_ = [(n, ctypes.c_uint32 if n == "flips" else t)
                    for n, t in _lib.LotStats._fields_]
    old = mismatches(layout, OldOptions, "lot_options", True, {})
    assert len(old) == 6 and "C lot_options.keep_hull is not mirrored" in " ".join(old)
    narrow = mismatches(layout, NarrowStats, "lot_stats", True, {})
    f, s = layout[1]["lot_stats"]["flips"][0], layout[1]["lot_stats"]["status"][0]
    assert narrow[:2] == [
        "NarrowStats.flips at %d (4 bytes), C lot_stats.flips at %d (8 bytes)" % (f, f),
        "NarrowStats.status at %d (4 bytes), C lot_stats.status at %d (4 bytes)" % (f + 4, s)]


def test_every_mirror_listed(layout):
    """Each ctypes.Structure of the package is in MIRRORS (LotOptionsRoom
    wraps LotOptions), and each structure layout.c prints has a mirror."""
    import fliplab
    found = set()
    for mod in (_lib, _cdf, _census, _classify, _flipgraph, _got, _pymeasure, _report) + tuple(
            getattr(fliplab, m) for m in ("_lot", "_rules", "_samplers")):
        found |= {v for v in vars(mod).values()
                  if isinstance(v, type) and issubclass(v, ctypes.Structure)}
    assert found - set(MIRRORS) == {_lib.LotOptionsRoom}
    assert {m[0] for m in MIRRORS.values()} == set(layout[0])
