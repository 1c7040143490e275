"""_classify.py: the directed flip graph of given pentagons (`fliplab
classify`, classify/flipgraph.h).  A rule's verdicts over random pentagons
(`fliplab rule`) are the studies' (_studies.py)."""
from __future__ import annotations

import ctypes
from typing import Any

import numpy as np
import numpy.typing as npt

from . import _lib
from ._arrays import as_coords, check_contract, points_ptr
from ._args import threads_arg
from ._census import RulesArg, _c_rules, _rules, _tie_eps
from ._rules import AC, BD, EITHER, Rule, _raise_user_errors

lib = _lib.lib
TYPES = ("I", "II", "III", "IV", "V")
_LETTER = {AC: "A", BD: "B", EITHER: "E"}


class Flipgraph(ctypes.Structure):
    """flipgraph (classify/flipgraph.h)."""
    _fields_ = [("dec", ctypes.c_int * 5), ("type", ctypes.c_int), ("nsinks", ctypes.c_int),
                ("sink", ctypes.c_int * 2), ("delaunay", ctypes.c_int)]


CLASSIFY_DTYPE = np.dtype([("decisions", "U5"), ("type", "U3"), ("sinks", "i1", (2,)),
                           ("dt", "?")])


def classify(pentagons: npt.ArrayLike, rules: RulesArg = "DT", tie_eps: float | None = None,
             threads: int = 0) -> npt.NDArray[Any]:
    """The directed flip graph of every pentagon under every rule, as
    `fliplab classify --input FILE --rule RULES` (flipgraph_classify_n).

    Parameters
    ----------
    pentagons : array_like, shape (m, 5, 2)
        Strictly convex pentagons, either orientation: a clockwise pentagon
        p1..p5 is renumbered v0..v4 = p1, p5, p4, p3, p2 as the program does.
    rules : str, Rule or iterable of them
        Rule names in the forms DT, MEASURE_JOINT or ES:SHAPE (or a
        plugin's quadrilateral rule), or Rules.
    tie_eps : float, optional
        The rules' relative tie tolerance (default the library's).
    threads : int
        0 (all cores) or 1 .. 1024; no output depends on it.

    Returns
    -------
    ndarray
        A structured (m, len(rules)) array (m, when rules is one name or
        Rule) with the columns of the program's CSV: decisions (five letters
        for Q_0..Q_4: A = diagonal v_{j+1}v_{j+3}, B = v_{j+2}v_{j+4}, E =
        either), type ("I".."V"), sinks (the fan indices of the sinks, -1
        for none) and dt (type I with the Delaunay triangulation as sink).

    Raises
    ------
    ValueError
        A pentagon that is not strictly convex (naming it and its vertex), a
        bad rule or keyword.
    """
    one = isinstance(rules, (str, Rule))
    rs = _rules(rules, None)
    eps = _tie_eps(tie_eps)
    v = np.array(as_coords(pentagons, "pentagons", (-1, 5, 2)), dtype=np.float64, order="C")
    check_contract(v, "pentagon")
    m, nr = len(v), len(rs)
    g = (Flipgraph * max(1, m * nr))()
    err, bad = ctypes.c_int(0), ctypes.c_size_t(0)
    k = lib.flipgraph_classify_n(points_ptr(v), m, _c_rules(rs, eps), nr, eps,
                                 threads_arg(threads), g,
                                 ctypes.byref(err), ctypes.byref(bad))
    if k < m:
        _raise_user_errors()
        raise ValueError("pentagon %d, vertex %d: %s"
                         % (k, bad.value, lib.geom_polyerr_str(err.value).decode()))
    _raise_user_errors()
    out = np.zeros(m * nr, dtype=CLASSIFY_DTYPE)
    for i in range(m * nr):
        x = g[i]
        s = [x.sink[j] if j < x.nsinks else -1 for j in range(2)]
        out[i] = ("".join(_LETTER[d] for d in x.dec), TYPES[x.type], s, bool(x.delaunay))
    out = out.reshape(m, nr)
    return out[:, 0] if one else out
