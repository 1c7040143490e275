"""_rules.py: flip rules and badness measures by name (built-in, formula,
plugin, empty-shape), and their vectorised evaluation on numpy arrays of
triangles and quadrilaterals."""
import ctypes
import numpy as np

from . import _lib
from ._arrays import as_coords, check_contract, cstr, points_ptr, ptr

lib = _lib.lib

AC, BD, EITHER, UNDECIDED = 0, 1, 2, -1
_SIGNS = {-1: "<= 0", 0: "any", 1: ">= 0"}


def tie_eps_arg(v, default=None):
    """A tie tolerance: a finite real number >= 0 as a float (None: default).
    Strings, booleans and anything else raise ValueError naming the keyword,
    never a bare TypeError from a comparison."""
    if v is None:
        return default
    ok = isinstance(v, (int, float, np.integer, np.floating)) and \
        not isinstance(v, (bool, np.bool_))
    if not (ok and np.isfinite(v) and v >= 0):
        raise ValueError("tie_eps: expected a finite number >= 0, got %r" % (v,))
    return float(v)


def _raise_user_errors():
    """An exception a Python measure raised during the last call, or a bad
    value a formula, plugin or Python measure produced (formula_check_errors)
    as ValueError, cleared for the next call."""
    from . import _pymeasure
    msg = ctypes.create_string_buffer(_lib.ERRLEN)
    bad = lib.formula_check_errors(msg, _lib.ERRLEN)
    if bad:
        lib.formula_clear_errors()
    _pymeasure.raise_pending()
    if bad:
        raise ValueError(_lib.text(msg))


class Rule:
    """A flip rule: "DT", MEASURE_JOINT ("P_1", "-alpha_inf"), a measure of
    define() or load_plugin() with a joint, a plugin's quadrilateral rule, or
    an empty-shape rule "ES:SHAPE".  tie_eps: the relative tie tolerance of
    triangle-based rules (default 1e-12, as the program's --tie-eps)."""

    def __init__(self, name, tie_eps=None):
        if isinstance(name, Rule):
            self._c = _lib.Rule.from_buffer_copy(name._c)
        else:
            if not isinstance(name, str):
                raise TypeError("rule: expected a rule name (str), got %r" % (name,))
            self._c = _lib.Rule()
            e = _lib.errbuf()
            if lib.rule_parse(cstr(name, "rule"), ctypes.byref(self._c), e, _lib.ERRLEN) != 0:
                raise ValueError(_lib.text(e))
        if tie_eps is not None:
            self._c.tie_eps = tie_eps_arg(tie_eps)

    @property
    def name(self):
        return self._c.name.decode()

    @property
    def is_triangle(self):
        """True for a triangle-based rule MEASURE_JOINT."""
        return self._c.kind == _lib.RULE_TRIANGLE

    @property
    def is_delaunay(self):
        return self._c.kind == _lib.RULE_QUAD and self._c.quad == 0

    @property
    def measure(self):
        """The measure's name ("" for a quadrilateral rule)."""
        if not self.is_triangle:
            return ""
        return lib.measure_get(self._c.measure).contents.name.decode()

    @property
    def joint(self):
        """The joint's name, "-inf" .. "inf" ("" for a quadrilateral rule)."""
        if not self.is_triangle:
            return ""
        return lib.joint_get(self._c.joint).contents.name.decode()

    @property
    def tie_eps(self):
        return self._c.tie_eps

    def badness(self, triangles):
        """The rule's measure on an (m, 3, 2) array of triangles: badness()."""
        if not self.is_triangle:
            raise ValueError("rule %s is a quadrilateral rule: no triangle badness" % self.name)
        return _badness_id(self._c.measure, triangles)

    def decide(self, quads, values=False):
        """decide(quads, self, values)."""
        return decide(quads, self, values)

    def __repr__(self):
        return "fliplab.Rule(%r)" % self.name

    def __eq__(self, other):
        return isinstance(other, Rule) and bytes(self._c) == bytes(other._c)

    def __hash__(self):
        return hash(bytes(self._c))


def as_rule(r):
    return r if isinstance(r, Rule) else Rule(r)


def measures():
    """Every registered measure (built-in, then define()'d and plugin ones):
    a list of dicts name, symbol, sign (">= 0", "<= 0", "any"), desc."""
    out = []
    for i in range(lib.measure_count()):
        m = lib.measure_get(i).contents
        out.append({"name": m.name.decode(), "symbol": m.symbol.decode() if m.symbol else "",
                    "sign": _SIGNS[m.sign], "desc": m.desc.decode() if m.desc else ""})
    return out


def joints():
    """The joint names ("-inf", "-1", "0", "1", "2", "inf")."""
    return [lib.joint_get(j).contents.name.decode() for j in range(lib.joint_count())]


def quad_rules():
    """The quadrilateral rules registered: DT, plugins' rules, ES:SHAPE used so far."""
    return [lib.rule_quad_get(i).contents.name.decode() for i in range(lib.rule_quad_count())]


def rules(measure_names=None):
    """Every triangle-based rule name MEASURE_JOINT for the given measures
    (default: every registered measure), joint-major as table 3.4, skipping
    joints a measure's sign does not allow."""
    names = [m["name"] for m in measures()] if measure_names is None else list(measure_names)
    out = []
    for j in joints():
        for m in names:
            try:
                out.append(Rule(m + "_" + j).name)
            except ValueError:
                pass
    return out


def define(definition):
    """Register a formula measure, as the program's --define: "NAME = EXPR",
    "NAME >= 0 : EXPR" or "NAME <= 0 : EXPR" (variables: docs/measures.md).
    Returns NAME; NAME_JOINT then names a rule everywhere.  A definition
    may be given once per process (a second one of the same name is refused,
    as a second --define would be); ValueError with the C message."""
    e = _lib.errbuf()
    mid = lib.formula_define(cstr(definition, "define"), e, _lib.ERRLEN)
    if mid < 0:
        raise ValueError(_lib.text(e))
    return lib.measure_get(mid).contents.name.decode()


def load_plugin(path):
    """Load a plugin (fliplab/plugin.h), as the program's --plugin FILE.so:
    its measures and quadrilateral rules become usable by name."""
    e = _lib.errbuf()
    if lib.plugin_load(cstr(path, "plugin", path=True), e, _lib.ERRLEN) != 0:
        raise ValueError(_lib.text(e))


def _measure_id(m):
    if isinstance(m, Rule):
        if not m.is_triangle:
            raise ValueError("rule %s is a quadrilateral rule: no triangle badness" % m.name)
        return m._c.measure
    if not isinstance(m, str):
        raise TypeError("measure: expected a measure name or a Rule, got %r" % (m,))
    mid = lib.measure_find(cstr(m, "measure"))
    if mid < 0:
        # A rule name MEASURE_JOINT: its measure.
        try:
            r = Rule(m)
        except ValueError:
            r = None
        if r is not None:
            return _measure_id(r)
        raise ValueError("unknown measure '%s' (valid: %s)"
                         % (m, ", ".join(x["name"] for x in measures())))
    return mid


def _badness_id(mid, triangles):
    from . import _pymeasure
    if mid in _pymeasure._registry:
        try:
            return _pymeasure.badness_python(mid, triangles)
        finally:
            _raise_user_errors()
    t = as_coords(triangles, "triangles", (-1, 3, 2))
    check_contract(t, "triangle")
    out = np.empty(t.shape[0], dtype=np.float64)
    lib.measure_eval_tris(mid, points_ptr(t), t.shape[0], ptr(out, ctypes.c_double))
    _raise_user_errors()
    return out


def badness(triangles, measure):
    """The badness measure (a name, or a triangle-based Rule or rule name:
    its measure) of every triangle of an (m, 3, 2) array (vertices in any
    order): an (m,) float64 array, bit for bit what the C library computes
    (measure_eval on geom_tri_make's triangle).  Degenerate (flat) triangles
    get what their quantities give (inf or NaN), as in C."""
    return _badness_id(_measure_id(measure), triangles)


def decide(quads, rule, values=False):
    """The rule's decision on every quadrilateral ABCD of an (m, 4, 2)
    array (anticlockwise): an (m,) int8 array of AC (0: keep the diagonal
    q[0] q[2]), BD (1), EITHER (2: a tie) or UNDECIDED (-1: not strictly
    convex and anticlockwise, decided by no rule).  values=True also
    returns the joint values f(b(ABC), b(ACD)) and f(b(ABD), b(BCD)) (NaN
    for quadrilateral rules and undecided quadrilaterals)."""
    r = as_rule(rule)
    q = as_coords(quads, "quadrilaterals", (-1, 4, 2))
    check_contract(q, "quadrilateral")
    m = q.shape[0]
    out = np.empty(m, dtype=np.int8)
    ac = np.empty(m, dtype=np.float64) if values else None
    bd = np.empty(m, dtype=np.float64) if values else None
    lib.rule_eval_quads(ctypes.byref(r._c), points_ptr(q), m, ptr(out, ctypes.c_byte),
                        ptr(ac, ctypes.c_double) if values else None,
                        ptr(bd, ctypes.c_double) if values else None)
    _raise_user_errors()
    return (out, ac, bd) if values else out
