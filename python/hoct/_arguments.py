"""The arguments of the `hoct` functions, checked as the command line checks its flags and the
readers their arrays: nothing is truncated, wrapped or dropped silently. Value problems raise
HoctError (a ValueError), wrong types TypeError; each message names the function, the argument,
the position and the value."""
import math
import numbers
import operator
import os

from ._hoct import HoctError

INT64_MIN, INT64_MAX = -(1 << 63), (1 << 63) - 1
MAX_THREADS = 1024  # as `--threads`
MAX_REFINE = 1024  # as `--refine`


def _position(index):
    return "[" + ", ".join(str(int(i)) for i in index) + "]"


def _count(n, one, many):
    return "%d %s" % (n, one if n == 1 else many)


def unmasked(a, what):
    """`a` as a plain array; a numpy masked array with a masked entry is refused (a mask hides
    values the mesh would otherwise use as they are)."""
    import numpy as np

    if isinstance(a, np.ma.MaskedArray):
        mask = np.ma.getmaskarray(a)
        if mask.any():
            first = np.argwhere(mask)[0]
            raise HoctError("%s has %s (the first at %s): fill them (a.filled(...)) or drop "
                            "them; hoct does not guess masked values"
                            % (what, _count(int(mask.sum()), "masked entry", "masked entries"),
                               _position(first)))
        return np.asarray(a.data)
    return np.asarray(a)


def real_array(a, what):
    """Points or values: an array of real numbers (integers or floating point)."""
    a = unmasked(a, what)
    if a.dtype.kind not in "biuf":
        raise TypeError("%s must be an array of real numbers, not of dtype %s" % (what, a.dtype))
    return a


def _first_bad_object(a, what):
    # An object array (e.g. Python ints beyond int64): each entry an integer in the int64 range.
    import numpy as np

    for index in np.ndindex(*a.shape):
        x = a[index]
        if isinstance(x, numbers.Integral) and not isinstance(x, bool):
            if not INT64_MIN <= int(x) <= INT64_MAX:
                raise HoctError("%s%s is %d, outside the int64 range of indices"
                                % (what, _position(index), int(x)))
        elif isinstance(x, numbers.Real) and not isinstance(x, bool):
            _check_float(float(x), index, what)
        else:
            raise TypeError("%s%s is %r, not an integer" % (what, _position(index), x))


def _check_float(x, index, what):
    if not math.isfinite(x) or x != math.floor(x):
        raise HoctError("%s%s is %r, not an integer" % (what, _position(index), x))
    if not -2.0**63 <= x < 2.0**63:
        raise HoctError("%s%s is %r, outside the int64 range of indices"
                        % (what, _position(index), x))


def index_array(a, what):
    """Cell indices (or codes) as int64, with the rules of the .vtu reader's connectivity: an
    integer array, or floating-point values that are all whole, finite and within int64; unsigned
    values beyond int64 and booleans, strings or complex numbers are refused."""
    import numpy as np

    a = unmasked(a, what)
    kind = a.dtype.kind
    if kind == "i":
        return np.ascontiguousarray(a, dtype=np.int64)
    if kind == "u":
        over = a > INT64_MAX
        if over.any():
            first = np.argwhere(over)[0]
            raise HoctError("%s%s is %d, outside the int64 range of indices (%s)"
                            % (what, _position(first), int(a[tuple(first)]),
                               _count(int(over.sum()), "such entry", "such entries")))
        return np.ascontiguousarray(a, dtype=np.int64)
    if kind == "f":
        with np.errstate(invalid="ignore"):
            bad = ~np.isfinite(a) | (a != np.floor(a)) | (a < -2.0**63) | (a >= 2.0**63)
        if bad.any():
            first = np.argwhere(bad)[0]
            _check_float(float(a[tuple(first)]), first, what)
        return np.ascontiguousarray(a, dtype=np.int64)
    if kind == "O":
        _first_bad_object(a, what)
        return np.array(a.tolist(), dtype=np.int64).reshape(a.shape)
    raise TypeError("%s must be an array of integers, not of dtype %s" % (what, a.dtype))


def integer(x, what, low, high):
    """An int (or numpy integer, not a bool) in [low, high]."""
    if isinstance(x, bool):
        raise TypeError("%s must be an integer, not a bool (%r)" % (what, x))
    try:
        value = operator.index(x)
    except TypeError:
        raise TypeError("%s must be an integer, not %s (%r)" % (what, type(x).__name__, x))
    if not low <= value <= high:
        raise HoctError("%s must be between %d and %d, got %d" % (what, low, high, value))
    return value


def threads(x, what):
    """None (every hardware thread) or 1 .. 1024 (the range of `--threads`)."""
    if x is None:
        return 0
    if isinstance(x, bool) or not isinstance(x, numbers.Integral) or not 1 <= x <= MAX_THREADS:
        raise HoctError("%s: threads must be a positive integer, got %r (at most %d, as "
                        "--threads)" % (what, x, MAX_THREADS))
    return int(x)


def flag(x, what):
    """A bool (or numpy bool, 0 or 1): bool('no') is True, so strings are refused."""
    import numpy as np

    if isinstance(x, (bool, np.bool_)) or (isinstance(x, numbers.Integral) and x in (0, 1)):
        return bool(x)
    raise TypeError("%s must be True or False, not %r" % (what, x))


def text(x, what):
    """A str without NUL characters (the command line cannot pass one either)."""
    if not isinstance(x, str):
        raise TypeError("%s must be a str, not %s (%r)" % (what, type(x).__name__, x))
    if "\0" in x:
        raise HoctError("%s contains a NUL character at position %d: %r"
                        % (what, x.index("\0"), x))
    return x


def path(x, what):
    """A file name: str, bytes or os.PathLike, without NUL (which would end it early: the file
    opened would be its prefix); as the file system's bytes (os.fsencode)."""
    try:
        p = os.fspath(x)
    except TypeError:
        raise TypeError("%s must be a str, bytes or os.PathLike, not %s (%r)"
                        % (what, type(x).__name__, x))
    if isinstance(p, str):
        p = os.fsencode(text(p, what))
    if b"\0" in p:
        raise HoctError("%s contains a NUL byte at position %d: %r" % (what, p.index(b"\0"), p))
    return p


def threshold(x, what):
    """A persistence threshold as the library parses it (as `--simplify`): a finite number >= 0,
    or a text such as "0.5%"; None for none."""
    if x is None:
        return ""
    if isinstance(x, str):
        return text(x, what)
    if isinstance(x, bool) or not isinstance(x, numbers.Real):
        raise TypeError("%s must be a number or a text such as '0.5%%', not %s (%r)"
                        % (what, type(x).__name__, x))
    try:
        return repr(float(x))  # nan, inf and negatives are refused by the library's parser
    except OverflowError:
        raise HoctError("%s: %r is not a threshold (a number, or a percentage like 0.5%%)"
                        % (what, x))


def merge_tolerance(x, what):
    """merge_duplicates=: None/False (no merge, -1), True (1e-9) or a tolerance in [0, 0.1]."""
    if x is None or x is False:
        return -1.0
    if x is True:
        return 1e-9
    if isinstance(x, numbers.Real) and not isinstance(x, bool) and 0 <= x <= 0.1:
        return float(x)
    raise HoctError("%s: merge_duplicates must be True or a tolerance between 0 and 0.1, got %r"
                    % (what, x))


def component(x, what):
    """component=: None (a scalar field), an index >= 0, 'x' / 'y' / 'z' or 'magnitude'; as
    the text --component takes."""
    if x is None:
        return ""
    if isinstance(x, str):
        if x.lower() in ("x", "y", "z", "magnitude", "mag", "norm"):
            return x.lower()
        raise HoctError("%s: component must be an index, 'x', 'y', 'z' or 'magnitude', got %r"
                        % (what, x))
    return str(integer(x, what + ": component", 0, 63))


def step(x, what):
    """step=: None (the last) or an index (negative from the end)."""
    if x is None:
        return -1
    return integer(x, what + ": step", -(1 << 62), 1 << 62)


def time(x, what):
    """time=: None or a finite number."""
    if x is None:
        return None
    if isinstance(x, bool) or not isinstance(x, numbers.Real) or not math.isfinite(x):
        raise HoctError("%s: time must be a finite number, got %r" % (what, x))
    return float(x)
