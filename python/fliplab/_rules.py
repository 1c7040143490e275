"""_rules.py: flip rules and badness measures by name (built-in, formula,
plugin, empty-shape), and their vectorised evaluation on numpy arrays of
triangles and quadrilaterals."""
from __future__ import annotations

import ctypes
import os
from typing import Any, overload

import numpy as np
import numpy.typing as npt

from . import _lib
from ._args import tie_eps_arg
from ._arrays import as_coords, check_contract, cstr, points_ptr, ptr

lib = _lib.lib

AC, BD, EITHER, UNDECIDED = 0, 1, 2, -1
# The forms of a rule name (docs/rules.md): every docstring taking a rule
# names them (python/tests/test_package.py).
RULE_FORMS = ("DT", "MEASURE_JOINT", "ES:SHAPE")
SHAPE_MAX_VERTICES = 1024          # shapes/shape.h: a polygon's vertices at most
SIGNS = ("any", ">= 0", "<= 0")     # a measure's sign, as measures() and measure() name it
_SIGN_OF = {0: "any", 1: ">= 0", -1: "<= 0"}


def _raise_user_errors() -> None:
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
    """A flip rule, by name.

    Parameters
    ----------
    name : str or Rule
        A rule name, in one of the forms "DT" (the Delaunay rule),
        MEASURE_JOINT (a measure of measures() and a joint of joints(), as
        "P_1", "-alpha_inf"; a define()'d, plugin or Python measure too), a
        plugin's quadrilateral rule (quad_rules()), or ES:SHAPE (an
        empty-shape rule, docs/emptyshape.md).  A Rule is copied.
    tie_eps : float, optional
        The relative tie tolerance of a triangle-based rule, a finite number
        >= 0 (default: the library's RULE_DEFAULT_TIE_EPS, 1e-12, as the
        program's).

    Raises
    ------
    ValueError
        An unknown or malformed name (the library's message), a name with a
        NUL character, a bad tie_eps.
    TypeError
        name is neither a str nor a Rule.

    Attributes
    ----------
    name, measure, joint, is_triangle, is_delaunay, tie_eps
    """

    def __init__(self, name: str | Rule, tie_eps: float | None = None) -> None:
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
    def name(self) -> str:
        """The rule's name, as the library prints it."""
        return self._c.name.decode()

    @property
    def is_triangle(self) -> bool:
        """True for a triangle-based rule MEASURE_JOINT."""
        return self._c.kind == _lib.RULE_TRIANGLE

    @property
    def is_delaunay(self) -> bool:
        """True for DT."""
        return not self.is_triangle and self._c.quad == 0

    @property
    def measure(self) -> str:
        """The measure's name ("" for a quadrilateral rule)."""
        if not self.is_triangle:
            return ""
        return lib.measure_get(self._c.measure).contents.name.decode()

    @property
    def joint(self) -> str:
        """The joint's name, one of joints() ("" for a quadrilateral rule)."""
        if not self.is_triangle:
            return ""
        return lib.joint_get(self._c.joint).contents.name.decode()

    @property
    def tie_eps(self) -> float:
        """The relative tie tolerance."""
        return self._c.tie_eps

    def badness(self, triangles: npt.ArrayLike) -> npt.NDArray[np.float64]:
        """The rule's measure on triangles: badness(triangles, self).

        Parameters
        ----------
        triangles : array_like, shape (m, 3, 2)
            As badness()'s.

        Returns
        -------
        ndarray of float64, shape (m,)
            Each triangle's badness.

        Raises
        ------
        ValueError
            A quadrilateral rule (no triangle badness), or bad triangles.
        """
        if not self.is_triangle:
            raise ValueError("rule %s is a quadrilateral rule: no triangle badness" % self.name)
        return _badness_id(self._c.measure, triangles)

    def circumscribe(self, triangle: npt.ArrayLike,
                     points: int = 128) -> tuple[npt.NDArray[np.float64] | None, int | None]:
        """The circumscribing shape of a triangle under an empty-shape rule
        ES:SHAPE, to draw it (shape_circumscribe_draw; docs/emptyshape.md).

        Parameters
        ----------
        triangle : array_like, shape (3, 2)
            Its vertices, in any order.
        points : int
            How many points trace an ellipse (3 to 4096).

        Returns
        -------
        tuple (outline, corner)
            The homothet's outline, an ndarray of float64 (a polygon's
            vertices or an ellipse's points, anticlockwise), and None; or
            None and the corner (a vertex index of the shape) whose rounding
            shape it is.  The contact edges are exact, the outline rounded.

        Raises
        ------
        ValueError
            Not an empty-shape rule, a flat triangle, points out of range.
        """
        if not lib.rule_is_shape(ctypes.byref(self._c)):
            raise ValueError("rule %s is not an empty-shape rule ES:SHAPE" % self.name)
        if not isinstance(points, int) or not 3 <= points <= 4096:
            raise ValueError("points: expected an integer in 3..4096, got %r" % (points,))
        t = as_coords(triangle, "triangle", (3, 2))
        k = lib.rule_shape(ctypes.byref(self._c))
        out = (_lib.Point * max(points, SHAPE_MAX_VERTICES))()
        corner = ctypes.c_int(-1)
        for a, b, c in ((0, 1, 2), (0, 2, 1)):
            n = lib.shape_circumscribe_draw(k, _lib.Point(*t[a]), _lib.Point(*t[b]),
                                            _lib.Point(*t[c]), out, points, ctypes.byref(corner))
            if n > 0:
                return np.array([(p.x, p.y) for p in out[:n]]), None
            if n == 0:
                return None, corner.value
        raise ValueError("circumscribe: the triangle is flat")

    def decide(self, quads: npt.ArrayLike, values: bool = False) -> Any:
        """The rule's decision on quadrilaterals: decide(quads, self, values).

        Parameters
        ----------
        quads : array_like, shape (m, 4, 2)
        values : bool
            Also return the two joint values.

        Returns
        -------
        ndarray of int8, or a tuple (decisions, ac, bd) with values=True

        Raises
        ------
        ValueError
            Bad quadrilaterals.
        """
        return decide(quads, self, values)

    def __repr__(self) -> str:
        return "fliplab.Rule(%r)" % self.name

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Rule) and bytes(self._c) == bytes(other._c)

    def __hash__(self) -> int:
        return hash(bytes(self._c))


def as_rule(r: str | Rule) -> Rule:
    return r if isinstance(r, Rule) else Rule(r)


def measures() -> list[dict[str, str]]:
    """Every registered measure: built-in, then define()'d, plugin and
    Python ones.

    Returns
    -------
    list of dict
        One dict per measure with the keys name, symbol, sign (one of
        "any", ">= 0", "<= 0") and desc.
    """
    out = []
    for i in range(lib.measure_count()):
        m = lib.measure_get(i).contents
        out.append({"name": m.name.decode(), "symbol": m.symbol.decode() if m.symbol else "",
                    "sign": _SIGN_OF[m.sign], "desc": m.desc.decode() if m.desc else ""})
    return out


def joints() -> list[str]:
    """The joints' names, in the library's order.

    Returns
    -------
    list of str
        "-inf", "-1", "0", "1", "2", "inf" (docs/joints.md).
    """
    return [lib.joint_get(j).contents.name.decode() for j in range(lib.joint_count())]


def quad_rules() -> list[str]:
    """The quadrilateral rules registered.

    Returns
    -------
    list of str
        DT, the plugins' rules, and every ES:SHAPE used so far.
    """
    return [lib.rule_quad_get(i).contents.name.decode() for i in range(lib.rule_quad_count())]


def rules(measure_names: list[str] | None = None) -> list[str]:
    """Every triangle-based rule name MEASURE_JOINT of the given measures,
    joint-major as table 3.4, skipping the joints a measure's sign does
    not allow.

    Parameters
    ----------
    measure_names : list of str, optional
        Names of measures() (default: every registered measure).

    Returns
    -------
    list of str

    Raises
    ------
    ValueError
        A name with a NUL character.
    """
    names = [m["name"] for m in measures()] if measure_names is None else list(measure_names)
    out = []
    for j in joints():
        for m in names:
            try:
                out.append(Rule(m + "_" + j).name)
            except ValueError as e:
                if "NUL" in str(e):
                    raise
    return out


def define(definition: str) -> str:
    """Register a formula measure, as the program's define option.

    Parameters
    ----------
    definition : str
        "NAME = EXPR", "NAME >= 0 : EXPR" or "NAME <= 0 : EXPR" (the
        variables and functions: docs/measures.md).  NAME_JOINT then names a
        rule everywhere.  A name may be defined once per process.

    Returns
    -------
    str
        NAME.

    Raises
    ------
    ValueError
        A malformed definition or a name already taken (the library's message).
    """
    e = _lib.errbuf()
    mid = lib.formula_define(cstr(definition, "definition"), e, _lib.ERRLEN)
    if mid < 0:
        raise ValueError(_lib.text(e))
    return lib.measure_get(mid).contents.name.decode()


def load_plugin(path: str | bytes | os.PathLike[str]) -> None:
    """Load a plugin (fliplab/plugin.h, docs/plugins.md), as the program's
    plugin option: its measures and quadrilateral rules become usable by
    name.

    Parameters
    ----------
    path : str, bytes or os.PathLike
        The plugin's shared object.

    Raises
    ------
    ValueError
        The library's message: the file cannot be loaded, or is no plugin.
    """
    e = _lib.errbuf()
    if lib.plugin_load(cstr(path, "path", path=True), e, _lib.ERRLEN) != 0:
        raise ValueError(_lib.text(e))


def _measure_id(m: str | Rule) -> int:
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
        raise ValueError("measure: unknown measure '%s' (valid: %s)"
                         % (m, ", ".join(x["name"] for x in measures())))
    return mid


def _badness_id(mid: int, triangles: npt.ArrayLike) -> npt.NDArray[np.float64]:
    from . import _pymeasure
    if _pymeasure.is_python(mid):
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


def badness(triangles: npt.ArrayLike, measure: str | Rule) -> npt.NDArray[np.float64]:
    """The badness of every triangle, bit for bit what the C library computes
    (measure_eval on geom_tri_make's triangle).

    Parameters
    ----------
    triangles : array_like, shape (m, 3, 2)
        The triangles' vertices, in any order.  Degenerate (flat) triangles
        get what their quantities give (inf or NaN), as in C.
    measure : str or Rule
        A name of measures(), or a triangle-based rule (a Rule, or a name
        MEASURE_JOINT: its measure).

    Returns
    -------
    ndarray of float64, shape (m,)

    Raises
    ------
    ValueError
        An unknown measure, a quadrilateral rule, triangles of another shape
        or outside the coordinate contract, a bad value of a user measure.
    TypeError
        measure is neither a str nor a Rule.
    """
    return _badness_id(_measure_id(measure), triangles)


@overload
def decide(quads: npt.ArrayLike, rule: str | Rule) -> npt.NDArray[np.int8]: ...


@overload
def decide(quads: npt.ArrayLike, rule: str | Rule, values: bool) -> Any: ...


def decide(quads: npt.ArrayLike, rule: str | Rule, values: bool = False) -> Any:
    """The rule's decision on every quadrilateral ABCD.

    Parameters
    ----------
    quads : array_like, shape (m, 4, 2)
        Quadrilaterals, anticlockwise.
    rule : str or Rule
        A Rule or a rule name: "DT", MEASURE_JOINT, ES:SHAPE or a plugin's
        quadrilateral rule (Rule).
    values : bool
        Also return the joint values f(b(ABC), b(ACD)) and f(b(ABD), b(BCD))
        (NaN for quadrilateral rules and undecided quadrilaterals).

    Returns
    -------
    ndarray of int8, shape (m,)
        AC (0: keep the diagonal q[0] q[2]), BD (1), EITHER (2: a tie) or
        UNDECIDED (-1: not strictly convex and anticlockwise); with
        values=True the tuple (decisions, ac, bd), two float64 arrays.

    Raises
    ------
    ValueError
        A bad rule, quadrilaterals of another shape or outside the
        coordinate contract, a bad value of a user measure.
    """
    r = as_rule(rule)
    q = as_coords(quads, "quads", (-1, 4, 2))
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
