"""_args.py: keyword arguments checked in their own terms, before anything
goes to C: each refusal is a ValueError (TypeError for what is not even
the right kind of thing) whose message starts with the keyword, never a
flag of the program, and lists the allowed values of a choice from the
package's own tuple."""
import numpy as np

MAX_THREADS = 1024   # GEOM_MAX_THREADS (geom/geom.h), checked against the library at import


def is_int(v):
    """v is an integer (Python's or numpy's), and no bool."""
    return isinstance(v, (int, np.integer)) and not isinstance(v, (bool, np.bool_))


def u64(v, what, lo=0):
    """v as an int in [lo, 2^64), else ValueError naming the keyword."""
    if not is_int(v) or not lo <= int(v) < 2 ** 64:
        raise ValueError("%s: expected an integer in [%d, 2^64), got %r" % (what, lo, v))
    return int(v)


def count(v, what, lo):
    """u64(v, what, lo), at most 2^40 (the size of an array to fill)."""
    v = u64(v, what, lo)
    if v > 2 ** 40:
        raise ValueError("%s: at most 2^40, got %d" % (what, v))
    return v


def choice(v, names, what, noun=None):
    """The index of v in the tuple names, else ValueError naming the keyword
    `what` and listing them ("kind: unknown point sampler 'x' (valid: ...)")."""
    if not isinstance(v, str) or v not in names:
        raise ValueError("%s: unknown %s %r (valid: %s)"
                         % (what, noun or what, v, ", ".join(names)))
    return names.index(v)


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


def threads_arg(v):
    """A thread count as every entry point of the library takes it: 0 (all
    cores) or 1 .. MAX_THREADS, as an int; anything else raises ValueError
    in the library's words (geom_threads_check)."""
    if not is_int(v) or not 0 <= int(v) <= MAX_THREADS:
        raise ValueError("threads: expected 0 (all cores) or 1 .. %d, got %r"
                         % (MAX_THREADS, v))
    return int(v)
