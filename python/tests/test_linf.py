"""test_linf.py: section 4.2 from Python (linf_circumcubes, LinfCube,
linf_delaunay, linf_bound, linf_extremal, linf_montecarlo): the thesis's
pseudo-degenerate tetrahedron has its two cubes of radius 4; every cube of
random points has every point on its boundary, its radius half the l_inf
diameter, and there are never more than theorem 14's bound, which the
extremal set attains; the Delaunay simplices are a brute force's over the
cubes (every subset, every point) and the selection algorithm's are among
them; the 3-D example gives the program's four simplices; the Monte Carlo
gives the program's counts for the same seed and any thread count, within
a 5-sigma interval of the exact law; refusals name the keyword."""
import itertools

import numpy as np
import pytest

import fliplab


def test_pseudo_tetrahedron():
    cubes = fliplab.linf_circumcubes([[1, 1, 7], [5, 3, 0], [3, 5, 8], [8, 6, 1]])
    assert sorted(c.centre for c in cubes) == ["(4, 5, 4)", "(5, 2, 4)"]
    assert all(c.radius == "4" and c.d == 3 for c in cubes)
    assert cubes[0].side([100, 0, 0]) == 1 and cubes[0].distance([4, 5, 4]) in ("1", "3")


@pytest.mark.parametrize("d", [2, 3, 4, 5])
def test_random_cubes(d):
    g = np.random.default_rng(d)
    for _ in range(200):
        p = g.integers(0, 20, size=(d + 1, d)).astype(float) + g.random((d + 1, d))
        cubes = fliplab.linf_circumcubes(p)
        assert cubes is not None and len(cubes) <= fliplab.linf_bound(d)
        diam = max(p[:, i].max() - p[:, i].min() for i in range(d))
        for c in cubes:
            assert all(c.side(q) == 0 for q in p)
            assert float(c.radius) == pytest.approx(diam / 2, rel=1e-12)
        assert len({c.centre for c in cubes}) == len(cubes)


@pytest.mark.parametrize("d", range(2, 9))
def test_extremal_attains_the_bound(d):
    assert fliplab.linf_bound(d) == 2 ** ((d - 1) // 2)
    p = fliplab.linf_extremal(d)
    assert p.shape == (d + 1, d)
    assert len(fliplab.linf_circumcubes(p)) == fliplab.linf_bound(d)


def _brute(p):
    """Every (d+1)-subset, affinely independent, with a cube that holds no
    point strictly inside."""
    n, d = p.shape
    out = []
    for s in itertools.combinations(range(n), d + 1):
        q = p[list(s)]
        if abs(np.linalg.det(q[1:] - q[0])) < 1e-9:
            continue
        cubes = fliplab.linf_circumcubes(q) or []
        if any(all(c.side(x) >= 0 for x in p) for c in cubes):
            out.append(s)
    return np.array(out, dtype=np.int32).reshape(-1, d + 1)


@pytest.mark.parametrize("d,n", [(2, 9), (3, 8), (4, 7)])
def test_delaunay_brute_force(d, n):
    g = np.random.default_rng(10 + d)
    for _ in range(3):
        p = g.random((n, d))
        b = fliplab.linf_delaunay(p)
        assert np.array_equal(b, _brute(p))
        s = fliplab.linf_delaunay(p, method="select")
        assert {tuple(r) for r in s} <= {tuple(r) for r in b} and len(s) > 0


def test_example_3d(cli):
    pts = [[6, 6, 2], [10, 4, 8], [0, 2, 6], [2, 12, 0], [4, 8, 10], [8, 0, 4]]
    out = cli.run("linf", "--example", "3d").stdout
    line = [s for s in out.splitlines() if s.startswith("l_inf Delaunay simplices")][0]
    names = ["".join("ABCDEF"[i] for i in r) for r in fliplab.linf_delaunay(pts)]
    assert " ".join(names) == line.split(": ")[1]


def test_montecarlo_is_the_programs(cli):
    out = cli.run("linf", "--montecarlo", "--dim", 3, "--trials", 20000, "--seed", 7).stdout
    want = {int(s.split()[0]): int(s.split()[1]) for s in out.splitlines()
            if s[:1].isdigit() and len(s.split()) > 3}
    for threads in (1, 2):
        mc = fliplab.linf_montecarlo(3, 20000, seed=7, threads=threads)
        assert {k: v for k, v in enumerate(mc["counts"]) if v or k in want} == want
    assert mc["law_total"] == 144 and mc["law"][:3] == [76, 64, 4]
    for k, m in enumerate(mc["law"]):
        q = m / 144
        assert abs(mc["counts"][k] - 20000 * q) <= 5 * np.sqrt(20000 * q * (1 - q)) + 1e-9


def test_refusals():
    for call, msg in [(lambda: fliplab.linf_bound(9), "d: expected a dimension in 2 .. 8"),
                      (lambda: fliplab.linf_circumcubes([[0, 0], [1, 1]]), "points: expected d + 1"),
                      (lambda: fliplab.linf_circumcubes(np.zeros((10, 9))), "dimension"),
                      (lambda: fliplab.linf_circumcubes([[0, 0], [1, 2], [1e40, 0]]),
                       "points row 2: coordinate 0"),
                      (lambda: fliplab.linf_delaunay(np.zeros((65, 2))), "points: at most 64"),
                      (lambda: fliplab.linf_delaunay(np.zeros((5, 2)), method="x"), "method: "),
                      (lambda: fliplab.linf_montecarlo(3, 0), "trials: "),
                      (lambda: fliplab.linf_montecarlo(3, 10, threads=-2), "threads: ")]:
        with pytest.raises(ValueError) as e:
            call()
        assert msg in str(e.value), str(e.value)
    c = fliplab.linf_circumcubes([[1, 1, 7], [5, 3, 0], [3, 5, 8], [8, 6, 1]])[0]
    with pytest.raises(ValueError, match="q: expected an array of shape"):
        c.side([1, 2])
