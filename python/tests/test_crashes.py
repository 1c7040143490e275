"""test_crashes.py: the two crashes and the C-side silent answers found from
outside, each as it was met through Python or the program: the polygon
sweep on sites sharing a sweepline, thread counts outside the library's
range, --cdf / cdf() on constrained runs, rule names longer than 79
characters, and blanks around names and numbers."""
import math

import numpy as np
import pytest

import fliplab
from conftest import write_points


# ---- the sweep on sites that share a vertical line ------------------------

SWEEP_SHAPES = ["ES:square", "ES:poly:0,0;3,0;3,1;0,1", "ES:diamond", "ES:hexagon"]


def _tri_set(t):
    return sorted(map(tuple, t.triangles.tolist()))


def test_sweep_first_crash_set():
    """(0,0), (10,6), (10,4), (30,20) with ES:square killed the interpreter."""
    p = np.array([[0, 0], [10, 6], [10, 4], [30, 20]], dtype=float)
    for rule in SWEEP_SHAPES:
        s = fliplab.lot(p, rule, algorithm="sweep", check=True)
        i = fliplab.lot(p, rule, check=True)
        assert _tri_set(s) == _tri_set(i)


def test_sweep_small_integer_sets():
    """Random sets of 4-9 small integer points: 10 in 1,500 crashed."""
    rng = np.random.default_rng(7)
    done = 0
    for _ in range(300):
        n, R = rng.integers(4, 10), rng.choice([3, 5, 10, 30])
        p = rng.integers(0, R + 1, size=(n, 2)).astype(float)
        q = np.unique(p, axis=0)
        if len(q) < 3 or np.linalg.matrix_rank(q[1:] - q[0]) < 2:
            continue
        for rule in SWEEP_SHAPES[:2]:
            s = fliplab.lot(p, rule, algorithm="sweep", check=True)
            assert _tri_set(s) == _tri_set(fliplab.lot(p, rule))
        done += 1
    assert done > 200


def test_sweep_cli(cli):
    write_points(cli.file("p.csv"), [(0, 0), (10, 6), (10, 4), (30, 20)])
    r = cli.run("lot", "--rule", "ES:square", "--points", cli.file("p.csv"), "--algorithm",
                "sweep", "--check", ok=False)
    assert r.returncode == 0, r.stderr


# ---- thread counts ---------------------------------------------------------

PENTAGON = np.array([[0, 0], [2, 0], [3, 1], [1, 3], [-1, 1]], dtype=float)


@pytest.mark.parametrize("threads", [100000, -1, 1025, 2 ** 40, 1.5, True, "2", None])
def test_threads_refused(threads):
    calls = [lambda: fliplab.got(PENTAGON, "P_1", threads=threads),
             lambda: fliplab.table34(10, threads=threads),
             lambda: fliplab.census(5, 10, threads=threads),
             lambda: fliplab.classify(PENTAGON[None], threads=threads)]
    for call in calls:
        with pytest.raises(ValueError, match=r"threads: expected 0 \(all cores\) or 1 \.\. 1024"):
            call()


def test_threads_accepted():
    a = fliplab.got(PENTAGON, "P_1", threads=0)
    b = fliplab.got(PENTAGON, "P_1", threads=np.int64(2))
    assert a.total == b.total and 1 <= b.threads <= 1024
    a, b = fliplab.table34(50, threads=1), fliplab.table34(50, threads=1024)
    assert (a == b).all()


# ---- the CDF of constrained runs -------------------------------------------

SQUARE = np.array([[0, 0], [4, 0], [4, 4], [0, 4], [1, 2], [3, 2]], dtype=float)


def test_cdf_refuses_constrained():
    t = fliplab.lot(SQUARE, "ES:square", segments=[[4, 5]], keep_hull=True)
    with pytest.raises(ValueError, match="constrained run"):
        fliplab.cdf(t)
    h = fliplab.lot(SQUARE, "ES:square", segments=[[0, 1], [1, 2], [2, 3], [3, 0]])
    with pytest.raises(ValueError, match="constrained run"):
        fliplab.cdf(h)
    assert len(fliplab.cdf(fliplab.lot(SQUARE, "ES:square")).triangles) > 0


@pytest.mark.parametrize("bad", [None, "ES:square", SQUARE])
def test_cdf_wants_a_triangulation(bad):
    with pytest.raises(TypeError, match="cdf: expected a fliplab.Triangulation"):
        fliplab.cdf(bad)


def test_cdf_cli_constrained(cli):
    write_points(cli.file("p.csv"), SQUARE)
    with open(cli.file("s.csv"), "w") as f:
        f.write("4,5\n")
    r = cli.run("lot", "--rule", "ES:square", "--points", cli.file("p.csv"), "--segments",
                cli.file("s.csv"), "--cdf", cli.file("g.csv"), ok=False)
    assert r.returncode == 2 and r.stderr.count("\n") == 1
    assert "--cdf takes an unconstrained run" in r.stderr


# ---- long rule names, blanks -------------------------------------------------

def _pentagon_rule():
    return "ES:poly:" + ";".join("%.17g %.17g" % (math.cos(2 * math.pi * k / 5 + 0.3),
                                                  math.sin(2 * math.pi * k / 5 + 0.3))
                                 for k in range(5))


def test_full_precision_pentagon_rule(cli):
    name = _pentagon_rule()
    assert len(name) > 79
    p = fliplab.samplers.points(300, "uniform", seed=2)
    t = fliplab.lot(p, name, check=True)
    assert t.rule.name == name
    write_points(cli.file("p.csv"), p)
    r = cli.run("lot", "--rule", name, "--points", cli.file("p.csv"), "--out", cli.file("t.csv"))
    assert name in r.stdout
    rows = np.array(cli.rows("t.csv")[1:], dtype=object)[:, :3].astype(int)
    assert sorted(map(tuple, rows.tolist())) == _tri_set(t)
    with pytest.raises(ValueError, match="at most 1023"):
        fliplab.Rule("ES:poly:" + ";".join(["0 0", "1 0", "1 1"] * 200))


def test_blanks_around_rule_names(cli):
    """--rule 'ES:square ' is read as --rules 'ES:square ,DT' reads it."""
    one = cli.run("lot", "--rule", "ES:square ", "--random", "30")
    assert "rule ES:square," in one.stdout
    lst = cli.run("lot", "--rule", " ES:square ,DT", "--random", "30")
    assert "ES:square" in lst.stdout


def test_blanks_in_quoted_fields(cli):
    """Unquoted blanks are dropped by the CSV layer; a quoted ' 1' is no
    number and no index, in the points and the segments alike."""
    with open(cli.file("p.csv"), "w") as f:
        f.write("0,0\n1, 0\n0,1\n")
    cli.run("lot", "--rule", "DT", "--points", cli.file("p.csv"))
    with open(cli.file("q.csv"), "w") as f:
        f.write('0,0\n1," 0"\n0,1\n')
    r = cli.run("lot", "--rule", "DT", "--points", cli.file("q.csv"), ok=False)
    assert r.returncode == 2 and "line 2" in r.stderr and "not a number" in r.stderr
    with open(cli.file("s.csv"), "w") as f:
        f.write('0," 1"\n')
    r = cli.run("lot", "--rule", "DT", "--points", cli.file("p.csv"), "--segments",
                cli.file("s.csv"), "--keep-hull", ok=False)
    assert r.returncode == 2 and "line 1" in r.stderr
    with open(cli.file("s.csv"), "w") as f:
        f.write("0, 1\n")
    cli.run("lot", "--rule", "DT", "--points", cli.file("p.csv"), "--segments",
            cli.file("s.csv"), "--keep-hull")
