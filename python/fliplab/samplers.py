"""fliplab.samplers: the random point sets, pentagons, site sets, polygons
and quadrilaterals of samplers/sampler.h as numpy arrays, drawn from the
streams of the program: the same seed gives the same coordinates, bit for
bit (docs/sampling.md).

    from fliplab.samplers import points
    p = points(1000, "uniform", seed=1)     # lot --random 1000 --seed 1
"""
import ctypes

import numpy as np
import numpy.typing as npt

from . import _lib
from ._args import choice as _choice, count as _count, is_int as _is_int, u64 as _u64
from ._arrays import points_ptr as _points_ptr
from ._mirrors import SamplerRng as _SamplerRng

__all__ = ["POINT_SETS", "PENTAGON_SAMPLERS", "SITE_SETS", "POLYGONS", "points", "pentagons",
           "site_sets", "convex_polygons", "polygon", "quads"]

POINT_SETS = ("uniform", "normal", "disc", "grid", "parabola", "circle", "clustered", "jittered",
              "lines", "dups")
PENTAGON_SAMPLERS = ("iteration", "vector", "circle", "disc-hull")
SITE_SETS = ("convex", "disc", "square", "normal")
POLYGONS = ("vector", "circle", "star", "monotone")
_GEOM_STREAM_GOT_POLYGON = 0   # geom/splitmix.h: the stream of `got --random N`
_SAMPLER_HULL_MAX = 17         # samplers/sampler.h: site sets of 3 .. 16


def _name(v: str, names: tuple[str, ...], what: str, noun: str | None = None) -> str:
    """v, one of names, else ValueError naming the keyword (_args.choice)."""
    return names[_choice(v, names, what, noun)]


def points(n: int, kind: str = "uniform", seed: int = 1) -> npt.NDArray[np.float64]:
    """n points of a point set sampler: those of the program's
    `lot --random N --sampler KIND --seed SEED`.

    Parameters
    ----------
    n : int
        How many, 1 .. 2^40.
    kind : str
        "uniform" (the unit square), "normal", "disc", "grid" (the integer
        grid, row by row), "parabola" ((i, i^2), i = n .. 1), "circle",
        "clustered" (20 Gaussian clusters, sigma 0.01), "jittered" (the
        grid, each coordinate moved by up to 2^-10), "lines" (integer
        points on 8 random lines, exactly collinear) or "dups" (a quarter
        of the points distinct, the rest copies of them): docs/sampling.md.
    seed : int
        The stream, in [0, 2^64).

    Returns
    -------
    ndarray of float64, shape (n, 2)

    Raises
    ------
    ValueError
        An unknown kind, n or seed out of range.
    """
    k = _lib.lib.sampler_points_find(_name(kind, POINT_SETS, "kind", "point sampler").encode())
    n = _count(n, "n", 1)
    out = np.empty((n, 2), dtype=np.float64)
    _lib.lib.sampler_points(k, _u64(seed, "seed"), n, _points_ptr(out))
    return out


def pentagons(count: int, seed: int = 1, first: int = 0,
              sampler: str = "iteration") -> npt.NDArray[np.float64]:
    """Random convex pentagons: sample first + i of the stream seed, those of
    the program's `sample --seed S --first I` (iteration) and of
    `table34 --sampler NAME --seed S`.

    Parameters
    ----------
    count : int
        How many, 0 .. 2^40.
    seed : int
        The stream, in [0, 2^64).
    first : int
        The index of the first sample.
    sampler : str
        "iteration" (the iteration method), "vector", "circle" or
        "disc-hull" (docs/sampling.md).

    Returns
    -------
    ndarray of float64, shape (count, 5, 2)
        Anticlockwise.

    Raises
    ------
    ValueError
        An unknown sampler, a number out of range.
    MemoryError
        A sampler ran out of memory.
    """
    name = _name(sampler, PENTAGON_SAMPLERS, "sampler", "pentagon sampler")
    s = _lib.lib.sampler_pentagons_find(name.encode())
    count, seed, first = _count(count, "count", 0), _u64(seed, "seed"), _u64(first, "first")
    out = np.empty((count, 5, 2), dtype=np.float64)
    draw = s.contents.draw
    for i in range(count):
        if draw(seed, first + i, _points_ptr(out[i])) != 0:
            raise MemoryError("pentagons: out of memory")
    return out


def site_sets(n: int, count: int, kind: str = "convex", seed: int = 1,
              first: int = 0) -> npt.NDArray[np.float64]:
    """Random site sets of the census: sample first + i of the program's
    `census --sampler KIND --sites N --seed S`.

    Parameters
    ----------
    n : int
        Sites per set, 3 .. 16.
    count : int
        How many sets, 0 .. 2^40.
    kind : str
        "convex" (the iteration method's convex n-gons, anticlockwise),
        "disc", "square" or "normal" (n independent points).
    seed : int
        The stream, in [0, 2^64).
    first : int
        The index of the first sample.

    Returns
    -------
    ndarray of float64, shape (count, n, 2)

    Raises
    ------
    ValueError
        An unknown kind, a number out of range.
    """
    k = _lib.lib.sampler_sites_find(_name(kind, SITE_SETS, "kind", "site sampler").encode())
    if not (_is_int(n) and 3 <= n < _SAMPLER_HULL_MAX):
        raise ValueError("n: expected 3 .. %d sites, got %r" % (_SAMPLER_HULL_MAX - 1, n))
    count, seed, first = _count(count, "count", 0), _u64(seed, "seed"), _u64(first, "first")
    out = np.empty((count, n, 2), dtype=np.float64)
    for i in range(count):
        if _lib.lib.sampler_sites(k, seed, first + i, int(n), _points_ptr(out[i])) != 0:
            raise ValueError("n: the %s sampler refused n = %d" % (kind, n))
    return out


def convex_polygons(n: int, count: int, seed: int = 1,
                    first: int = 0) -> npt.NDArray[np.float64]:
    """Random convex n-gons by the iteration method: site_sets(n, count,
    "convex", seed, first).

    Parameters
    ----------
    n, count, seed, first : int
        As site_sets()'s.

    Returns
    -------
    ndarray of float64, shape (count, n, 2)
        Anticlockwise.

    Raises
    ------
    ValueError
        A number out of range.
    """
    return site_sets(n, count, "convex", seed, first)


def polygon(n: int, sampler: str = "vector", seed: int = 1) -> npt.NDArray[np.float64]:
    """One random polygon: that of the program's
    `got --random N --sampler NAME --seed S`.

    Parameters
    ----------
    n : int
        Vertices, 3 .. 2^40.
    sampler : str
        "vector", "circle" (strictly convex), "star" or "monotone" (simple).
    seed : int
        The stream, in [0, 2^64).

    Returns
    -------
    ndarray of float64, shape (n, 2)
        Anticlockwise.

    Raises
    ------
    ValueError
        An unknown sampler, a number out of range, or an n too large for
        the sampler in floating point (points too close).
    MemoryError
        The sampler ran out of memory.
    """
    _name(sampler, POLYGONS, "sampler", "polygon sampler")
    n = _count(n, "n", 3)
    g = _SamplerRng()
    _lib.lib.sampler_seed(ctypes.byref(g), _u64(seed, "seed"), _GEOM_STREAM_GOT_POLYGON)
    out = np.empty((n, 2), dtype=np.float64)
    rc = getattr(_lib.lib, "sampler_" + sampler)(ctypes.byref(g), n, _points_ptr(out))
    if rc == -2:
        raise MemoryError("polygon: out of memory")
    if rc != 0:
        raise ValueError("n: the %s sampler could not make a %d-gon in floating point (points "
                         "too close); use a smaller n" % (sampler, n))
    return out


def quads(count: int, seed: int = 1, first: int = 0) -> npt.NDArray[np.float64]:
    """Random strictly convex quadrilaterals: those of the program's rule
    command's Delaunay-equivalence check (sampler_quad).

    Parameters
    ----------
    count, seed, first : int
        As pentagons()'s.

    Returns
    -------
    ndarray of float64, shape (count, 4, 2)
        Anticlockwise.

    Raises
    ------
    ValueError
        A number out of range.
    """
    count, seed, first = _count(count, "count", 0), _u64(seed, "seed"), _u64(first, "first")
    out = np.empty((count, 4, 2), dtype=np.float64)
    for i in range(count):
        _lib.lib.sampler_quad(seed, first + i, _points_ptr(out[i]))
    return out
