"""test_report.py: Counts.to_csv() writes the program's bytes: table34 and
census tables equal `fliplab table34/census --format csv|md|text` for the
same run byte for byte (shards and another sampler included), shards
written from Python sum with `fliplab merge` to the unsharded table, and a
failing write leaves the old file as it was."""
import os

import pytest

import fliplab


def test_table34_csv_bytes(cli, tmp_path):
    for fmt in ("csv", "md", "text"):
        want = cli.run("table34", "--samples", 1500, "--seed", 4, "--measures", "R,-alpha",
                       "--format", fmt, "--columns", 20).stdout
        t = fliplab.table34(1500, seed=4, measures=["R", "-alpha"])
        assert t.to_csv(format=fmt, columns=20 if fmt == "text" else 0) == want, fmt
    want = cli.run("table34", "--samples", 900, "--seed", 2, "--rules", "P_1,DT", "--sampler",
                   "circle", "--format", "csv").stdout
    assert fliplab.table34(900, seed=2, rules=["P_1", "DT"], sampler="circle").to_csv() == want


def test_census_csv_bytes(cli):
    want = cli.run("census", "--sites", 6, "--samples", 200, "--sampler", "disc", "--seed", 3,
                   "--rules", "P_1,R_inf,DT", "--format", "csv").stdout
    c = fliplab.census(6, 200, "disc", 3, rules=["P_1", "R_inf", "DT"])
    assert c.to_csv() == want


def test_shards_merge(cli, tmp_path):
    files = []
    for k in (1, 2, 3):
        path = tmp_path / ("s%d.csv" % k)
        fliplab.table34(2000, seed=6, measures=["P"], shard=(k, 3)).to_csv(str(path))
        want = cli.run("table34", "--samples", 2000, "--seed", 6, "--measures", "P",
                       "--shard", "%d/3" % k, "--format", "csv").stdout
        assert path.read_text() == want
        files.append(path)
    merged = cli.run("merge", *files, "--format", "csv").stdout.splitlines()
    whole = fliplab.table34(2000, seed=6, measures=["P"]).to_csv().splitlines()
    assert len(merged) == len(whole) == 1 + 6 + 1
    for a, b in zip(merged, whole):                 # the ten columns: the same counts
        assert a.split(",")[:10] == b.split(",")[:10]


def test_failed_write_keeps_old_file(tmp_path):
    path = tmp_path / "t.csv"
    path.write_text("old\n")
    t = fliplab.table34(100, rules=["DT"])
    with pytest.raises(ValueError, match="format"):
        t.to_csv(str(path), format="xml")
    (tmp_path / "d").mkdir()
    (tmp_path / "d" / "x").write_text("kept\n")
    with pytest.raises(OSError):             # the rename over a directory fails
        t.to_csv(str(tmp_path / "d"))
    assert sorted(os.listdir(tmp_path)) == ["d", "t.csv"]        # no temporary file left
    assert (tmp_path / "d" / "x").read_text() == "kept\n" and path.read_text() == "old\n"
    t.to_csv(str(path))
    assert path.read_text() == t.to_csv() and sorted(os.listdir(tmp_path)) == ["d", "t.csv"]
