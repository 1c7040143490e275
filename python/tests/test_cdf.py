"""test_cdf.py: cdf() against `fliplab lot --rule ES:SHAPE --cdf` on the same
points, and what the extraction must give: every kept triangle is one of
the triangulation's, no conflict on an empty-shape triangulation, and for a
smooth shape (an ellipse) every triangle is kept."""
import csv

import numpy as np
import pytest

import fliplab
from conftest import write_points


@pytest.mark.parametrize("shape", ["square", "triangle", "hexagon", "poly:0,0;3,1;1,2"])
def test_cdf_equals_cli(cli, tmp_path, shape):
    p = fliplab.samplers.points(300, "uniform", 4)
    write_points(tmp_path / "p.csv", p)
    rule = "ES:" + shape
    run = cli.run("lot", "--rule", rule, "--points", tmp_path / "p.csv", "--cdf",
                  tmp_path / "g.csv")
    with open(tmp_path / "g.csv") as f:
        rows = list(csv.DictReader(f))
    tri = [[int(r["i"]), int(r["j"]), int(r["k"])] for r in rows if r["k"] != ""]
    edg = [[int(r["i"]), int(r["j"])] for r in rows if r["k"] == ""]
    t = fliplab.lot(p, rule)
    g = fliplab.cdf(t)
    assert g.triangles.tolist() == tri and g.edges.tolist() == edg
    assert "cdf: %d triangles, %d extra edges (%d triangles dropped)" % (
        len(tri), len(edg), g.rounded) in run.stdout
    assert g.conflicts == 0
    assert len(g.triangles) + g.rounded == len(t.triangles)
    assert {tuple(x) for x in g.triangles} <= {tuple(x) for x in t.triangles}


def test_cdf_ellipse_keeps_everything():
    p = fliplab.samplers.points(200, "normal", 5)
    t = fliplab.lot(p, "ES:ellipse:2,1,0.5")
    g = fliplab.cdf(t)
    assert np.array_equal(g.triangles, t.triangles) and len(g.edges) == 0 and g.rounded == 0


def test_cdf_refuses():
    t = fliplab.lot(fliplab.samplers.points(50, "uniform", 1), "DT")
    with pytest.raises(ValueError, match="empty-shape"):
        fliplab.cdf(t)
