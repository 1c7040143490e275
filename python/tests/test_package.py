"""test_package.py: the package's shape and how it talks to the library.

- fliplab, fliplab.samplers and fliplab.plot are the public modules (real
  submodules: `import fliplab.samplers` and `from fliplab.samplers import
  points` work); fliplab.explorer is a program (python3 -m fliplab.explorer,
  the page's server), no API; every other module is private (a leading underscore);
  each public module's __all__ lists its public API and nothing else of
  the package is reachable under a public name.
- Every public function, class and method carries type hints and a
  numpydoc docstring (Parameters naming every parameter, Returns, Raises),
  and the docstring of every string argument with a fixed set of values
  names each of them, taken from the package's own tuples (ALGORITHMS,
  samplers.POINT_SETS, ...), so a value added to a tuple and not to the
  documentation fails here.
- No message raised from Python names a flag of the program.
- Every ctypes prototype is declared in _lib.py (_PROTOS) and nowhere else;
  the tie tolerance is the library's (RULE_DEFAULT_TIE_EPS, read once);
  which options go together is the library's lot_options_check."""
import ast
import ctypes
import importlib
import inspect
import os
import pkgutil
import re
import types
import typing

import numpy as np
import pytest

import fliplab
import fliplab.plot
import fliplab.samplers
from fliplab import _lib, _mirrors, _rules
from fliplab.samplers import points

PKG = os.path.dirname(fliplab.__file__)
PUBLIC_MODULES = (fliplab, fliplab.samplers, fliplab.plot)
PROGRAMS = {"explorer"}         # run with python3 -m, not imported as API


def _sources():
    """(name, AST) of every module of the package."""
    out = []
    for m in pkgutil.iter_modules(fliplab.__path__):
        with open(os.path.join(PKG, m.name + ".py")) as f:
            out.append((m.name, ast.parse(f.read())))
    return out


# ---- the modules -----------------------------------------------------------

def test_public_submodules_import():
    assert points(3, "grid").shape == (3, 2)
    assert fliplab.samplers.__name__ == "fliplab.samplers"
    assert fliplab.plot.__name__ == "fliplab.plot"
    assert importlib.import_module("fliplab.samplers").points is points
    from fliplab import plot, samplers
    assert (plot, samplers) == (fliplab.plot, fliplab.samplers)


def test_every_other_module_private():
    names = {m.name for m in pkgutil.iter_modules(fliplab.__path__)}
    assert {"samplers", "plot"} <= names
    assert all(n.startswith("_") for n in names - {"samplers", "plot"} - PROGRAMS), names


def _ours(obj):
    """obj is a function, class or module of the package."""
    mod = obj.__name__ if inspect.ismodule(obj) else getattr(obj, "__module__", None)
    return isinstance(mod, str) and (mod == "fliplab" or mod.startswith("fliplab."))


@pytest.mark.parametrize("mod", PUBLIC_MODULES, ids=lambda m: m.__name__)
def test_all_is_the_public_api(mod):
    for name in mod.__all__:
        assert not name.startswith("_") and hasattr(mod, name), name
    for name, obj in vars(mod).items():
        if name.startswith("_") or name in mod.__all__ or name in PROGRAMS:
            continue
        # imports of other libraries (np, ctypes, typing's names) are no API
        assert not _ours(obj), "%s.%s is reachable but not in __all__" % (mod.__name__, name)


# ---- type hints and docstrings ---------------------------------------------

def _public_callables():
    """(qualified name, function) of every public function and method, and
    the classes (their docstring documents __init__)."""
    out = []
    for mod in PUBLIC_MODULES:
        for name in mod.__all__:
            obj = getattr(mod, name)
            q = "%s.%s" % (mod.__name__, name)
            if inspect.isfunction(obj):
                out.append((q, obj))
            elif inspect.isclass(obj) and _ours(obj):
                out.append((q, obj))
                for m, f in vars(obj).items():
                    if not m.startswith("_") and inspect.isfunction(f):
                        out.append(("%s.%s" % (q, m), f))
    return out


def _init(obj):
    return obj.__new__ if "__new__" in vars(obj) else obj.__init__


def _cases():
    return [pytest.param(n, o, id=n) for n, o in _public_callables()]


@pytest.mark.parametrize("name,obj", _cases())
def test_type_hints(name, obj):
    if inspect.isclass(obj) and issubclass(obj, BaseException):
        return
    f = _init(obj) if inspect.isclass(obj) else obj
    sig = inspect.signature(f)
    for p in sig.parameters.values():
        if p.name not in ("self", "cls"):
            assert p.annotation is not inspect.Parameter.empty, "%s: %s" % (name, p.name)
    assert sig.return_annotation is not inspect.Signature.empty, "%s: return" % name


def test_properties_typed():
    for mod in PUBLIC_MODULES:
        for name in mod.__all__:
            obj = getattr(mod, name)
            if inspect.isclass(obj) and _ours(obj):
                for m, p in vars(obj).items():
                    if isinstance(p, property) and not m.startswith("_"):
                        ann = inspect.signature(p.fget).return_annotation
                        assert ann is not inspect.Signature.empty, "%s.%s" % (name, m)
                        assert p.__doc__, "%s.%s has no docstring" % (name, m)


def _section(doc, title):
    """The text of numpydoc section `title` of doc, or None."""
    m = re.search(r"\n *%s\n *%s\n(.*?)(\n *[A-Z][a-z]+\n *-+\n|$)" % (title, "-" * len(title)),
                  doc, re.S)
    return m.group(1) if m else None


@pytest.mark.parametrize("name,obj", _cases())
def test_numpydoc(name, obj):
    doc = inspect.getdoc(obj) or ""
    assert doc, "%s has no docstring" % name
    doc = "\n" + doc
    f = _init(obj) if inspect.isclass(obj) else obj
    params = [p for p in inspect.signature(f).parameters.values()
              if p.name not in ("self", "cls") and p.kind != p.VAR_KEYWORD] \
        if not (inspect.isclass(obj) and issubclass(obj, BaseException)) else []
    if params:
        sec = _section(doc, "Parameters")
        assert sec is not None, "%s: no Parameters section" % name
        for p in params:
            assert re.search(r"^\s*(\w+, )*%s\b" % p.name, sec, re.M), \
                "%s: parameter %s undocumented" % (name, p.name)
    if inspect.isclass(obj):
        return
    if inspect.signature(f).return_annotation not in ("None", None):
        assert _section(doc, "Returns") is not None, "%s: no Returns section" % name
    if params:
        assert _section(doc, "Raises") is not None, "%s: no Raises section" % name


# The string arguments whose values are fixed, and the package's tuple of
# them: (function's qualified name or "*", parameter) -> tuple.  Every other
# string argument names something open (a registry, a path, a text).
CHOICES = {
    ("fliplab.lot", "algorithm"): fliplab.ALGORITHMS,
    ("fliplab.lot", "order"): fliplab.ORDERS,
    ("fliplab.Triangulation", "algorithm"): fliplab.ALGORITHMS,
    ("fliplab.Triangulation", "order"): fliplab.ORDERS,
    ("fliplab.samplers.points", "kind"): fliplab.samplers.POINT_SETS,
    ("fliplab.samplers.pentagons", "sampler"): fliplab.samplers.PENTAGON_SAMPLERS,
    ("fliplab.samplers.site_sets", "kind"): fliplab.samplers.SITE_SETS,
    ("fliplab.samplers.polygon", "sampler"): fliplab.samplers.POLYGONS,
    ("fliplab.table34", "sampler"): fliplab.samplers.PENTAGON_SAMPLERS,
    ("fliplab.census", "sampler"): fliplab.samplers.SITE_SETS,
    ("fliplab.convex_polygons", "sampler"): fliplab.CONVEX_SAMPLERS,
    ("fliplab.convex_polygons", "region"): fliplab.REGIONS,
    ("fliplab.convex_polygons", "inner"): fliplab.CONVEX_INNER,
    ("fliplab.Counts.to_csv", "format"): fliplab.FORMATS,
    ("fliplab.measure", "sign"): fliplab.SIGNS,
    ("fliplab.ch5_averages", "method"): fliplab.CH5_METHODS,
    ("fliplab.convex_dt", "algorithm"): fliplab.CPDT_ALGORITHMS,
    ("fliplab.convex_dt_experiment", "sampler"): fliplab.CPDT_SAMPLERS,
    ("fliplab.convex_dt_experiment", "region"): fliplab.REGIONS,
    ("fliplab.got_points", "skeleton"): fliplab.SKELETONS,
    ("fliplab.triangulate_by", "algorithm"): fliplab.PARADIGM_ALGORITHMS,
    ("fliplab.triangulate_by", "problem"): fliplab.PARADIGM_PROBLEMS,
    ("fliplab.linf_delaunay", "method"): fliplab.LINF_METHODS,
    ("fliplab.Rule", "name"): _rules.RULE_FORMS,
    ("*", "rule"): _rules.RULE_FORMS,
    ("*", "rules"): _rules.RULE_FORMS,
}
OPEN = {"measure", "measures", "measure_names", "definition", "name", "desc", "path", "title",
        "titles", "sites"}


def _takes_str(f, param):
    """The parameter's type is str or a union holding str, but no array
    (numpy.typing.ArrayLike is a union of scalars, str and complex among
    them) and no container of str (dict[str, int])."""
    t = typing.get_type_hints(f, localns=vars(fliplab)).get(param)
    if t is str:
        return True
    args = typing.get_args(t) if typing.get_origin(t) in (typing.Union, types.UnionType) else ()
    return str in args and complex not in args


def _str_params():
    for name, obj in _public_callables():
        f = _init(obj) if inspect.isclass(obj) else obj
        for p in inspect.signature(f).parameters.values():
            if p.name not in ("self", "cls") and _takes_str(f, p.name):
                yield pytest.param(name, obj, p.name, id="%s-%s" % (name, p.name))


@pytest.mark.parametrize("name,obj,param", list(_str_params()))
def test_string_choices_documented(name, obj, param):
    values = CHOICES.get((name, param), CHOICES.get(("*", param)))
    if values is None:
        assert param in OPEN, "%s(%s=...): a string argument with no CHOICES entry" % (name, param)
        return
    doc = inspect.getdoc(obj)
    quoted = values is not _rules.RULE_FORMS
    for v in values:
        assert ('"%s"' % v if quoted else v) in doc, "%s(%s): %r undocumented" % (name, param, v)


def test_choices_are_the_librarys():
    """The tuples name what the library takes: every value is accepted, and
    the package's own check lists them all in its refusal."""
    lib = _lib.lib
    names = (ctypes.c_char * 4096).in_dll(lib, "sampler_points_names").value.decode()
    assert tuple(names.split(", ")) == fliplab.samplers.POINT_SETS
    for k in fliplab.samplers.SITE_SETS:
        assert lib.sampler_sites_find(k.encode()) >= 0
    assert [lib.got_skeleton_find(k.encode()) for k in fliplab.SKELETONS] == [0, 1, 2, 3]
    for k in fliplab.samplers.PENTAGON_SAMPLERS:
        assert lib.sampler_pentagons_find(k.encode())
    for k in fliplab.samplers.POLYGONS:
        assert hasattr(lib, "sampler_" + k) and "sampler_" + k in _lib._PROTOS
    fmt = ctypes.c_int()
    assert [lib.report_format_parse(f.encode(), ctypes.byref(fmt)) for f in fliplab.FORMATS] \
        == [0] * len(fliplab.FORMATS)
    for a, _ in enumerate(fliplab.ALGORITHMS):
        o = lib.lot_options_new(ctypes.byref(fliplab.Rule("DT")._c))
        assert lib.lot_options_set_algorithm(o, a) == 0 and lib.lot_options_set_order(o, a) == 0
        assert lib.lot_options_set_algorithm(o, len(fliplab.ALGORITHMS)) == -1
        assert lib.lot_options_set_order(o, len(fliplab.ORDERS)) == -1
        lib.lot_options_free(o)
    with pytest.raises(ValueError) as e:
        fliplab.samplers.points(3, "nope")
    assert str(e.value).startswith("kind: ") and all(k in str(e.value) for k in
                                                      fliplab.samplers.POINT_SETS)


# ---- messages ---------------------------------------------------------------

_FLAG = re.compile(r"(^|[\s'`(])--[a-z]")


def test_no_flag_in_raised_messages():
    """Every string inside a raise statement of the package names keywords,
    not the program's flags."""
    bad = []
    for name, tree in _sources():
        for node in ast.walk(tree):
            if isinstance(node, ast.Raise):
                for c in ast.walk(node):
                    if isinstance(c, ast.Constant) and isinstance(c.value, str) \
                            and _FLAG.search(c.value):
                        bad.append("%s.py:%d: %r" % (name, c.lineno, c.value))
    assert bad == []


def test_refusals_name_keywords():
    """Refusals from Python and from the library, as the caller sees them."""
    p = points(20, "uniform", 1)
    cases = [
        (dict(algorithm="flip", order="random"), "order applies to algorithm 'incremental'"),
        (dict(algorithm="sweep", order="input"), "order applies to algorithm 'incremental'"),
        (dict(keep_hull=True), "keep_hull applies to constrained runs"),
        (dict(algorithm="fast"), "algorithm: unknown algorithm 'fast'"),
        (dict(order="hilbert"), "order: unknown order 'hilbert'"),
        (dict(max_flips=0), "max_flips: expected an integer in [1, 2^64)"),
        (dict(tie_eps=-1.0), "tie_eps: expected a finite number >= 0")]
    for kw, msg in cases:
        with pytest.raises(ValueError) as e:
            fliplab.lot(p, "DT", **kw)
        assert msg in str(e.value) and not _FLAG.search(str(e.value)), (kw, str(e.value))
    for call, msg in [(lambda: fliplab.got(p[:5], "P_1", threads=2000), "threads: "),
                      (lambda: fliplab.table34(10, sampler="x"), "sampler: unknown"),
                      (lambda: fliplab.census(6, 10, "x"), "sampler: unknown"),
                      (lambda: fliplab.samplers.polygon(5, "x"), "sampler: unknown"),
                      (lambda: fliplab.measure("pysignbad", len, sign="+"), "sign: expected"),
                      (lambda: fliplab.table34(10).to_csv(format="xml"), "format: unknown")]:
        with pytest.raises(ValueError) as e:
            call()
        assert msg in str(e.value) and not _FLAG.search(str(e.value)), str(e.value)


# ---- how the package talks to the library -----------------------------------

def test_prototypes_only_in_lib():
    """No module but _lib.py sets a ctypes prototype (restype, argtypes)."""
    bad = []
    for name, tree in _sources():
        for node in ast.walk(tree):
            if isinstance(node, ast.Attribute) and node.attr in ("restype", "argtypes") \
                    and isinstance(node.ctx, ast.Store) and name != "_lib":
                bad.append("%s.py:%d" % (name, node.lineno))
    assert bad == []
    assert all(getattr(_lib.lib, f).argtypes is not None for f in _lib._PROTOS)


def test_one_tie_tolerance():
    """The default tie tolerance is read from the library once: a rule the
    library makes carries it, every default of the package is it, and no
    module writes the number itself."""
    eps = _lib.RULE_DEFAULT_TIE_EPS
    assert eps == fliplab.Rule("P_1").tie_eps == fliplab.Rule("DT").tie_eps > 0
    assert fliplab.table34(10, rules=["P_1"]).meta["tie_eps"] == eps
    assert fliplab.census(5, 10, rules=["P_1"]).meta["tie_eps"] == eps
    assert fliplab.got(fliplab.samplers.polygon(6), "P_1").tie_eps == eps
    lit = ["%s.py:%d" % (name, n.lineno) for name, tree in _sources() for n in ast.walk(tree)
           if isinstance(n, ast.Constant) and isinstance(n.value, float) and n.value == eps]
    assert lit == []


def test_lot_options_verbs():
    """lot_options through its verbs: the defaults are lot_options_init's,
    each setter refuses what is outside its type, and lot_options_check says
    which options go together, in the words of their fields."""
    lib, e = _lib.lib, _lib.errbuf()
    o = lib.lot_options_new(ctypes.byref(fliplab.Rule("P_1", tie_eps=0.5)._c))
    assert o
    try:
        assert lib.lot_options_check(o, e, _lib.ERRLEN) == 0
        assert lib.lot_options_set_tie_eps(o, float("nan")) == -1
        assert lib.lot_options_set_tie_eps(o, -1.0) == -1
        assert lib.lot_options_set_algorithm(o, -1) == -1
        assert lib.lot_options_set_order(o, 2) == 0 and lib.lot_options_set_algorithm(o, 1) == 0
        assert lib.lot_options_check(o, e, _lib.ERRLEN) == -1
        assert _lib.text(e).startswith("order applies to algorithm 'incremental' only")
        lib.lot_options_set_order(o, 0)
        lib.lot_options_set_keep_hull(o, 7)
        assert lib.lot_options_check(o, e, _lib.ERRLEN) == -1 and "keep_hull" in _lib.text(e)
        hole = (_mirrors.Point * 1)()
        lib.lot_options_set_holes(o, hole, 0)       # an empty array counts as given
        assert lib.lot_options_check(o, e, _lib.ERRLEN) == 0
    finally:
        lib.lot_options_free(o)
    # keep_hull with an empty segment list is taken, as the program takes an empty file
    sq = np.array([[0, 0], [1, 0], [1, 1], [0, 1], [0.5, 0.4]])
    t = fliplab.lot(sq, "DT", segments=np.empty((0, 2), int), keep_hull=True)
    assert len(t.triangles) == 4 and t.stats["segments"] == 0


def test_results_by_name():
    """lot_stats, lot_check_result and got_result read by field name give
    what the results mean: counts that agree with the arrays, a got_result
    whose every field has a getter of its type."""
    p = points(300, "disc", 4)
    t = fliplab.lot(p, "P_1", max_flips=10 ** 6)
    s = t.stats
    assert set(_lib.LOT_STATS_FIELDS) - {"cycle_quad"} <= set(s)
    assert s["triangles"] == len(t.triangles) and s["hull"] == len(t.hull)
    assert s["n"] == 300 and s["distinct"] + s["duplicates"] == 300
    assert 2 * s["distinct"] - s["hull"] - 2 == s["triangles"]          # Euler
    assert s["status"] == "converged" and s["max_flips"] == 10 ** 6
    assert isinstance(s["seconds_flip"], float) and s["cycle_quads"] == []
    big = fliplab.lot(p, "DT", max_flips=2 ** 64 - 1).stats["max_flips"]
    assert big == 2 ** 64 - 1                   # beyond int64: read as the count it is
    c = t.check()
    assert c and c.interior_edges == (3 * s["triangles"] - s["hull"]) // 2
    assert c.boundary_edges == s["hull"] and c.bad_edge is None
    res = _lib.lib.got_result_new()
    try:
        for f in _lib.c_names(_lib.lib.got_result_field):
            ok = [g(res, f.encode(), ctypes.byref(t())) == 0 for g, t in
                  ((_lib.lib.got_result_get_i64, ctypes.c_int64),
                   (_lib.lib.got_result_get_double, ctypes.c_double))]
            assert sum(ok) == 1 or f in ("tri", "cert_why"), f
    finally:
        _lib.lib.got_result_delete(res)
