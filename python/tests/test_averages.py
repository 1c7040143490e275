"""test_averages.py: chapter 5's averages from Python (fliplab.ch5_averages,
fliplab.ch5_measure) against computations written here with fractions:
T_c = 4^n/C_n - (2n+1), A by the chord sum, L_a = (n+2) A / (2(n-1)),
T_i = 2n - 6 H_{n+2} + 9, G^d_n's closed form; the enumeration equals the
closed forms; ch5_measure of every triangulation of small polygons (made
here by the recursion on the root side's apex) averages to the closed
forms; what `fliplab averages` prints is the same; refusals are
ValueErrors naming the argument."""
from fractions import Fraction
from math import comb

import numpy as np
import pytest

import fliplab


def _catalan(n):
    return comb(2 * n, n) // (n + 1)


def _triangulations(a, b):
    """Every triangulation of the polygon p_a .. p_b as lists of triangles."""
    if b - a < 2:
        yield []
        return
    for k in range(a + 1, b):
        for left in _triangulations(a, k):
            for right in _triangulations(k, b):
                yield [(a, k, b)] + left + right


@pytest.mark.parametrize("n", [1, 2, 3, 7, 20, 61])
def test_closed_forms(n):
    v = fliplab.ch5_averages(n)
    c = [_catalan(m) for m in range(n + 1)]
    assert v["Tc"] == Fraction(4 ** n, c[n]) - (2 * n + 1)
    cross = Fraction(sum((min(m, n - m) + 1) * c[m] * c[n - m] for m in range(1, n)), c[n])
    assert v["A"] == cross
    assert v["Ti"] == 2 * n - 6 * sum(Fraction(1, i) for i in range(1, n + 3)) + 9
    assert v["deg"] == Fraction(2 * (n - 1), n + 2)
    assert v["Tc_max"] == n * (n + 1) // 2
    if n >= 2:
        assert v["La"] == Fraction(n + 2, 2 * (n - 1)) * cross
        assert v["Lmax"] == 1 + Fraction(n * n // 4, n - 1)
    else:
        assert "La" not in v
    g = [comb(2 * n - 3 - d, n - 2) - comb(2 * n - 3 - d, n) for d in range(n)] if n > 1 else [1]
    assert v["G"] == g and sum(g) == c[n]
    assert all(isinstance(x, Fraction) for k, x in v.items() if k != "G")


@pytest.mark.parametrize("n", range(1, 10))
def test_enumeration_equals_closed(n):
    assert fliplab.ch5_averages(n, "enumerate") == fliplab.ch5_averages(n)


@pytest.mark.parametrize("n", [1, 2, 5, 8])
def test_measure_averages(n):
    nv = n + 2
    rows = [fliplab.ch5_measure(np.array(t), nv) for t in _triangulations(0, nv - 1)]
    assert len(rows) == _catalan(n)
    v = fliplab.ch5_averages(n)
    assert Fraction(sum(r["Tc"] for r in rows), len(rows)) == v["Tc"]
    assert min(r["Tc"] for r in rows) == v["Tc_min"]
    assert Fraction(sum(r["A"] for r in rows), len(rows)) == v["A"]
    hist = np.bincount([r["degree"][n] for r in rows], minlength=n)
    assert list(hist) == v["G"]
    if n >= 2:
        assert sum(r["L"] for r in rows) / len(rows) == v["La"]
        assert min(r["L"] for r in rows) == v["Lmin"]
        assert max(r["L"] for r in rows) == v["Lmax"]


def test_large_n_exact():
    """Past Python's 4300-digit limit on decimal conversion (the values
    come in hexadecimal): T_c(n) at n = 8000, whose C_n has over 4800 digits."""
    n = 8000
    v = fliplab.ch5_averages(n, degrees=False)
    assert "G" not in v
    assert v["Tc"] == Fraction(4 ** n, _catalan(n)) - (2 * n + 1)
    assert v["Tc"].denominator.bit_length() > 4300 * 3


def test_measure_any_row_order():
    t = np.array([(0, 1, 2), (0, 2, 5), (2, 3, 5), (3, 4, 5)])
    a = fliplab.ch5_measure(t, 6)
    b = fliplab.ch5_measure(t[::-1, ::-1], 6)
    assert (a["Tc"], a["A"], a["len_sum"]) == (b["Tc"], b["A"], b["len_sum"])
    assert a["Tc"] == 4 + 3 + 1                  # scan 4, then p_0..p_2 and p_2..p_5
    assert list(a["degree"]) == [1, 0, 2, 1, 0, 2]


def test_cli_prints_the_same(cli):
    out = cli.run("averages", "--n", "9").stdout
    v = fliplab.ch5_averages(9)
    for name in fliplab.CH5_QUANTITIES:
        row = [line.split() for line in out.splitlines() if line.split()[:1] == [name]]
        assert Fraction(row[0][1]) == v[name]


def test_refusals():
    with pytest.raises(ValueError, match="^n:"):
        fliplab.ch5_averages(0)
    with pytest.raises(ValueError, match="^n:"):
        fliplab.ch5_averages(19, "enumerate")
    with pytest.raises(ValueError, match="^n:"):
        fliplab.ch5_averages(2.0)
    with pytest.raises(ValueError, match="^method:"):
        fliplab.ch5_averages(3, "guess")
    with pytest.raises(ValueError, match="^triangles:.*triangle 1"):
        fliplab.ch5_measure([(0, 1, 2), (0, 2, 2)], 4)
    with pytest.raises(ValueError, match="^triangles:"):
        fliplab.ch5_measure([(0, 1, 2)], 5)
    with pytest.raises(ValueError, match="^triangles:"):
        fliplab.ch5_measure([[0.5, 1, 2]], 3)
    with pytest.raises(ValueError, match="^n_vertices:"):
        fliplab.ch5_measure([(0, 1, 2)], 2)
