"""_samplers.py: the random polygons and point sets of samplers/sampler.h as
numpy arrays, with the streams of the program (the same seed gives the same
coordinates, bit for bit)."""
import ctypes
import numpy as np

from . import _lib
from ._arrays import points_ptr
from ._lot import _u64

lib = _lib.lib

POINT_SETS = ("uniform", "normal", "disc", "grid", "parabola", "circle")
PENTAGON_SAMPLERS = ("iteration", "vector", "circle", "disc-hull")
SITE_SETS = ("convex", "disc", "square", "normal")
POLYGONS = ("vector", "circle", "star", "monotone")
GEOM_STREAM_GOT_POLYGON = 0   # geom/splitmix.h: the stream of `got --random N`
SAMPLER_HULL_MAX = 17


def _name(v, names, what):
    if v not in names:
        raise ValueError("unknown %s '%s' (valid: %s)" % (what, v, ", ".join(names)))
    return v


def _count(v, what, lo):
    v = _u64(v, what, lo)
    if v > 2 ** 40:
        raise ValueError("%s: at most 2^40, got %d" % (what, v))
    return v


def points(n, kind="uniform", seed=1):
    """n points of a point set sampler, (n, 2) float64: the points of
    `fliplab lot --random N --sampler KIND --seed SEED`."""
    k = lib.sampler_points_find(_name(kind, POINT_SETS, "point sampler").encode())
    n = _count(n, "n", 1)
    out = np.empty((n, 2), dtype=np.float64)
    lib.sampler_points(k, _u64(seed, "seed"), n, points_ptr(out))
    return out


def pentagons(count, seed=1, first=0, sampler="iteration"):
    """Random convex pentagons, (count, 5, 2) float64, anticlockwise: sample
    first + i of the stream seed, those of `fliplab sample --seed S --first
    I` (iteration) and of `table34 --sampler NAME --seed S`."""
    s = lib.sampler_pentagons_find(_name(sampler, PENTAGON_SAMPLERS, "pentagon sampler").encode())
    count, seed, first = _count(count, "count", 0), _u64(seed, "seed"), _u64(first, "first")
    out = np.empty((count, 5, 2), dtype=np.float64)
    draw = s.contents.draw
    for i in range(count):
        if draw(seed, first + i, points_ptr(out[i])) != 0:
            raise MemoryError("pentagons: out of memory")
    return out


def site_sets(n, count, kind="convex", seed=1, first=0):
    """Random site sets of the census, (count, n, 2) float64: sample first + i
    of `fliplab census --sampler KIND --sites N --seed S` (convex: the
    iteration method's convex n-gons, anticlockwise; disc, square, normal:
    n independent points)."""
    k = lib.sampler_sites_find(_name(kind, SITE_SETS, "site sampler").encode())
    if not (isinstance(n, (int, np.integer)) and 3 <= n < SAMPLER_HULL_MAX):
        raise ValueError("n: expected 3 .. %d sites, got %r" % (SAMPLER_HULL_MAX - 1, n))
    count, seed, first = _count(count, "count", 0), _u64(seed, "seed"), _u64(first, "first")
    out = np.empty((count, n, 2), dtype=np.float64)
    for i in range(count):
        if lib.sampler_sites(k, seed, first + i, int(n), points_ptr(out[i])) != 0:
            raise ValueError("site_sets: sampler %s refused n = %d" % (kind, n))
    return out


def convex_polygons(n, count, seed=1, first=0):
    """Random convex n-gons by the iteration method, (count, n, 2)."""
    return site_sets(n, count, "convex", seed, first)


def polygon(n, sampler="vector", seed=1):
    """One random polygon with n vertices, (n, 2) float64, anticlockwise: the
    polygon of `fliplab got --random N --sampler NAME --seed S` (vector,
    circle: strictly convex; star, monotone: simple)."""
    _name(sampler, POLYGONS, "polygon sampler")
    n = _count(n, "n", 3)
    g = _lib.SamplerRng()
    lib.sampler_seed(ctypes.byref(g), _u64(seed, "seed"), GEOM_STREAM_GOT_POLYGON)
    out = np.empty((n, 2), dtype=np.float64)
    rc = getattr(lib, "sampler_" + sampler)(ctypes.byref(g), n, points_ptr(out))
    if rc == -2:
        raise MemoryError("polygon: out of memory")
    if rc != 0:
        raise ValueError("the %s sampler could not make a %d-gon in floating point (points too "
                         "close); use a smaller n" % (sampler, n))
    return out


def quads(count, seed=1, first=0):
    """Random strictly convex quadrilaterals, (count, 4, 2), anticlockwise:
    those of `fliplab rule`'s Delaunay-equivalence check (sampler_quad)."""
    count, seed, first = _count(count, "count", 0), _u64(seed, "seed"), _u64(first, "first")
    out = np.empty((count, 4, 2), dtype=np.float64)
    for i in range(count):
        lib.sampler_quad(seed, first + i, points_ptr(out[i]))
    return out
