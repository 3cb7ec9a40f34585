r"""
The points of a stability map or a sweep

:func:`parse_points` checks the user's ``parameters`` (ranges) and
``samples`` and returns a :class:`Points`: the parameter keys, the shape of
the results and the point specification that the kernels expand chunk by
chunk (see :mod:`sage_dynsym.scale.kernel`).

A range is ``(low, high, n)``: ``n`` equally spaced values from ``low`` to
``high``, both included (``n = 1``: ``low`` alone, then ``high`` must equal
``low``). A 1-D NumPy array gives the values of an axis explicitly. With
``samples=N`` the points are ``N`` uniform random points in the box of the
ranges (``(low, high)``; an ``n`` is ignored), drawn from ``seed`` (a
non-negative integer).

Everything is checked before any array is made: bounds finite real numbers
(not strings, not booleans) whose difference is finite, ``n`` and
``samples`` integers (not ``True``, not ``2.0``), and the number of points
at most :data:`MAX_POINTS` (``max_points=`` raises it; a point costs 9
bytes of results in a stability map, more in a sweep).

EXAMPLES::

    sage: from sage_dynsym.scale.points import parse_points
    sage: P = parse_points({'a': (0, 1, 3), 'b': (10, 20, 2)}); P
    6 points: a grid 3 x 2 in (a, b)
    sage: P.axes()
    [array([0. , 0.5, 1. ]), array([10., 20.])]
    sage: parse_points({'a': (0, 1)}, samples=1000, seed=5)
    1000 points: random samples in (a)
"""
import math

import numpy as np

from ..errors import AnalysisError, brief
from ..arguments import count, is_integer

__all__ = ['MAX_POINTS', 'result_arrays', 'Points', 'parse_points', 'number_text',
           'check_positive_ranges']

#: Most points of a map or a sweep (``max_points=`` raises it).
MAX_POINTS = 10**7


def result_arrays(points, arrays, owner):
    r"""
    Check the data of a result of the scale layer (a
    :class:`~sage_dynsym.scale.maps.StabilityMap` or a
    :class:`~sage_dynsym.scale.sweeps.Sweep`), which :func:`stability_map`
    and :func:`sweep` build: ``points`` a :class:`Points`, each of
    ``arrays`` a NumPy array with the points' shape first.

    EXAMPLES::

        sage: from sage_dynsym.scale.points import parse_points, result_arrays
        sage: import numpy as np
        sage: P = parse_points({'a': (0, 1, 3)})
        sage: result_arrays(P, [np.zeros(3)], 'StabilityMap')
        sage: result_arrays(None, [], 'StabilityMap')
        Traceback (most recent call last):
        ...
        AnalysisError: StabilityMap: expected the points of a computation, got None; maps come from stability_map(...), sweeps from sweep(...)
        sage: result_arrays(P, [np.zeros(2)], 'Sweep')
        Traceback (most recent call last):
        ...
        AnalysisError: Sweep: expected arrays of shape (3,) over the points, got array([0., 0.])
    """
    hint = "maps come from stability_map(...), sweeps from sweep(...)"
    if not isinstance(points, Points):
        raise AnalysisError(f"{owner}: expected the points of a computation, got {brief(points)}; "
                            + hint)
    for array in arrays:
        if not (isinstance(array, np.ndarray) and array.shape[:len(points.shape)] == points.shape):
            raise AnalysisError(f"{owner}: expected arrays of shape {points.shape} over the "
                                f"points, got {brief(array)}")


class Points:
    r"""
    The points of a computation: ``keys`` (the parameters, in order),
    ``shape`` (of the result arrays), ``size``, ``layout`` (for the kernels)
    and whether they form a grid.

    EXAMPLES: :func:`parse_points` makes them; the kernels expand ``layout``::

        sage: from sage_dynsym.scale.points import parse_points
        sage: from sage_dynsym.scale.kernel import chunk_points
        sage: P = parse_points({'a': (0, 1, 3), 'b': (10, 20, 2)})
        sage: P.keys, P.shape, P.size
        (['a', 'b'], (3, 2), 6)
        sage: chunk_points(P.layout, 0, P.size)
        [array([0. , 0. , 0.5, 0.5, 1. , 1. ]), array([10., 20., 10., 20., 10., 20.])]
    """

    def __init__(self, keys, layout, shape):
        self.keys, self.layout, self.shape = list(keys), layout, tuple(shape)
        self.size = math.prod(self.shape)

    def is_grid(self):
        r"""Whether the points form a grid (else random samples).

        EXAMPLES::

            sage: from sage_dynsym.scale.points import parse_points
            sage: parse_points({'a': (0, 1, 3)}).is_grid(), parse_points({'a': (0, 1)}, 9).is_grid()
            (True, False)
        """
        return self.layout[0] == 'grid'

    def axes(self):
        r"""The axes of a grid (list of 1-D arrays), ``None`` for samples.

        EXAMPLES::

            sage: from sage_dynsym.scale.points import parse_points
            sage: parse_points({'a': (0, 1, 3)}).axes(), parse_points({'a': (0, 1)}, 9).axes()
            ([array([0. , 0.5, 1. ])], None)
        """
        return list(self.layout[1]) if self.is_grid() else None

    def with_keys(self, keys):
        r"""The same points with other keys (one per parameter, in order):
        the symbols a map resolved the user's names to.

        EXAMPLES::

            sage: from sage_dynsym.scale.points import parse_points
            sage: P = parse_points({'a': (0, 1, 3)}).with_keys([var('a')]); P.keys, P.shape
            ([a], (3,))
        """
        if len(keys) != len(self.keys):
            raise AnalysisError(f"expected {len(self.keys)} keys, one per parameter, got "
                                f"{brief(keys)}", entry="parameters")
        return Points(keys, self.layout, self.shape)

    def __repr__(self):
        names = ', '.join(map(str, self.keys))
        if self.is_grid():
            return f"{self.size} points: a grid {' x '.join(map(str, self.shape))} in ({names})"
        return f"{self.size} points: random samples in ({names})"


def parse_points(parameters, samples=None, seed=0, entry="parameters", max_points=MAX_POINTS,
                 samples_entry="samples", raise_with="max_points="):
    r"""
    Check ``parameters`` (a dict ``{key: range}``), ``samples`` and
    ``seed``, and the number of points against ``max_points``, and return
    the :class:`Points`: parsed once, then passed on (a map renames its
    keys with :meth:`Points.with_keys`).

    ``entry`` and ``samples_entry`` name the parameters and the number of
    samples in the messages, ``raise_with`` how to raise ``max_points``
    (the command line says ``--param``, ``--samples``, ``--max-points``).

    TESTS::

        sage: from sage_dynsym.scale.points import parse_points
        sage: parse_points({'a': (1, 0, 5)})
        Traceback (most recent call last):
        ...
        AnalysisError: parameters[a]: empty range (1, 0, 5): expected low < high (or low = high with n = 1)
        sage: parse_points({'a': (0, 1, 0)})
        Traceback (most recent call last):
        ...
        AnalysisError: parameters[a]: empty range (0, 1, 0): n must be a positive integer
        sage: parse_points({'a': (0, 'x', 3)})
        Traceback (most recent call last):
        ...
        AnalysisError: parameters[a]: expected (low, high, n) with real numbers low, high and an integer n, got (0, 'x', 3)
        sage: parse_points({})
        Traceback (most recent call last):
        ...
        AnalysisError: parameters: no parameters: expected a dict {parameter: (low, high, n)}
        sage: parse_points({'a': (0, 1, 3)}, samples=0)
        Traceback (most recent call last):
        ...
        AnalysisError: samples: expected a positive number of random points, got 0
        sage: parse_points({'a': (0, float('inf'), 3)})
        Traceback (most recent call last):
        ...
        AnalysisError: parameters[a]: the bounds must be finite, got (0, inf, 3)
        sage: import numpy as np
        sage: parse_points({'a': np.array([])})
        Traceback (most recent call last):
        ...
        AnalysisError: parameters[a]: empty range: an array of values must be 1-D, finite and not empty
        sage: parse_points({'a': (0, 1, True)})
        Traceback (most recent call last):
        ...
        AnalysisError: parameters[a]: expected (low, high, n) with real numbers low, high and an integer n, got (0, 1, True)
        sage: parse_points({'a': ('0', 1, 3)})
        Traceback (most recent call last):
        ...
        AnalysisError: parameters[a]: expected (low, high, n) with real numbers low, high and an integer n, got ('0', 1, 3)
        sage: parse_points({'a': (float(-1e308), float(1e308), 5)})
        Traceback (most recent call last):
        ...
        AnalysisError: parameters[a]: the range (-1e+308, 1e+308, 5) is too wide for floating point (high - low overflows)
        sage: parse_points({'a': (0, 1, 10^5), 'b': (0, 1, 10^5)})
        Traceback (most recent call last):
        ...
        AnalysisError: parameters: 10000000000 points are more than the limit of 10000000; raise it with max_points= if that is what you want
        sage: parse_points({'a': (0, 1, 10^5), 'b': (0, 1, 10^5)}, entry='--param',
        ....:              raise_with='--max-points')
        Traceback (most recent call last):
        ...
        AnalysisError: --param: 10000000000 points are more than the limit of 10000000; raise it with --max-points if that is what you want
        sage: parse_points({'a': (0, 1)}, samples=10^10)
        Traceback (most recent call last):
        ...
        AnalysisError: samples: 10000000000 points are more than the limit of 10000000; raise it with max_points= if that is what you want
        sage: parse_points({'a': (0, 1)}, samples=5, seed=-1)
        Traceback (most recent call last):
        ...
        AnalysisError: seed: expected at least 0, got -1
    """
    if not isinstance(parameters, dict) or not parameters:
        raise AnalysisError("no parameters: expected a dict {parameter: (low, high, n)}",
                            entry=entry)
    max_points = count(max_points, 'max_points', error=AnalysisError)
    if samples is not None:
        if not is_integer(samples) or int(samples) < 1:
            raise AnalysisError(f"expected a positive number of random points, got {samples!r}",
                                entry=samples_entry)
        samples = count(samples, samples_entry, maximum=max_points, error=AnalysisError,
                        what="points", raise_with=raise_with)
        seed = count(seed, 'seed', minimum=0, error=AnalysisError)
        lows, highs = [], []
        for key, axis_range in parameters.items():
            low, high, _ = _range(key, axis_range, entry, samples=True)
            lows.append(low)
            highs.append(high)
        return Points(parameters, ('samples', lows, highs, seed), (samples,))
    shape = []
    for key, axis_range in parameters.items():
        if isinstance(axis_range, np.ndarray):
            shape.append(len(axis_range) if axis_range.ndim == 1 else 0)
        else:
            shape.append(_range(key, axis_range, entry)[2])
    count(math.prod(shape), entry, maximum=max_points, error=AnalysisError, what="points",
          raise_with=raise_with, minimum=0)
    axes = []
    for key, axis_range in parameters.items():
        if isinstance(axis_range, np.ndarray):
            try:
                values = np.asarray(axis_range, dtype=float)
            except (TypeError, ValueError):
                values = np.array([])
            if values.ndim != 1 or not len(values) or not np.isfinite(values).all():
                raise AnalysisError("empty range: an array of values must be 1-D, finite and "
                                    "not empty", entry=f"{entry}[{key}]")
            axes.append(values)
            continue
        low, high, n = _range(key, axis_range, entry)
        axes.append(np.linspace(low, high, n))
    return Points(parameters, ('grid', axes), [len(a) for a in axes])


def _bound(value):
    r"""``value`` as a float (possibly not finite), ``None`` if it is not a
    real number (a string, a boolean, a symbol, a complex number)."""
    if isinstance(value, (str, bytes, bool)) or value is None:
        return None
    try:
        return float(value)
    except (TypeError, ValueError, OverflowError):
        return None


def _range(key, axis_range, entry, samples=False):
    where = f"{entry}[{key}]"
    shape = "(low, high)" if samples else "(low, high, n)"
    ok = (isinstance(axis_range, (tuple, list))
          and len(axis_range) in ((2, 3) if samples else (3,)))
    if ok:
        low, high = _bound(axis_range[0]), _bound(axis_range[1])
        ok = (low is not None and high is not None
              and (len(axis_range) == 2 or is_integer(axis_range[2])))
    if not ok:
        raise AnalysisError(f"expected {shape} with real numbers low, high"
                            f"{'' if samples else ' and an integer n'}, got {axis_range!r}",
                            entry=where)
    if not (math.isfinite(low) and math.isfinite(high)):
        raise AnalysisError(f"the bounds must be finite, got {tuple(axis_range)!r}", entry=where)
    n = int(axis_range[2]) if len(axis_range) == 3 else 2
    if n < 1:
        raise AnalysisError(f"empty range {tuple(axis_range)!r}: n must be a positive integer",
                            entry=where)
    if not (low < high or (low == high and n == 1 and not samples)):
        raise AnalysisError(f"empty range {tuple(axis_range)!r}: expected low < high (or low = "
                            "high with n = 1)", entry=where)
    if not math.isfinite(high - low):
        raise AnalysisError(f"the range {tuple(axis_range)!r} is too wide for floating point "
                            "(high - low overflows)", entry=where)
    return low, high, n


def number_text(value, latex=False):
    r"""
    A value of a point as a person writes it: an integer, or a decimal for
    a rational (``9.81``, not ``981/100``; the shortest decimal that gives
    back its floating-point value); other
    constants exactly (``1/2*pi``, or their LaTeX with ``latex=True``).

    EXAMPLES::

        sage: from sage_dynsym.scale.points import number_text
        sage: number_text(981/100), number_text(QQ(0.1)), number_text(-3), number_text(1/3)
        ('9.81', '0.1', '-3', '0.3333333333333333')
        sage: number_text(pi/2), number_text(sqrt(2)/2, latex=True)
        ('1/2*pi', '\\frac{1}{2} \\, \\sqrt{2}')
    """
    from sage.rings.rational_field import QQ
    try:
        q = QQ(value)
    except (TypeError, ValueError, ArithmeticError):
        if latex:
            from sage.misc.latex import latex as to_latex
            return str(to_latex(value))
        return str(value)
    return str(q) if q.denominator() == 1 else repr(float(q))


def check_positive_ranges(points, positive, entry="parameters"):
    r"""
    Check that the parameters of ``points`` declared positive (in the list
    ``positive``) only take positive values.

    EXAMPLES::

        sage: from sage_dynsym.scale.points import parse_points, check_positive_ranges
        sage: m, k = var('m k')
        sage: check_positive_ranges(parse_points({m: (1, 2, 3), k: (-1, 1, 3)}), [m])
        sage: check_positive_ranges(parse_points({m: (0, 2, 3)}), [m])
        Traceback (most recent call last):
        ...
        AnalysisError: parameters[m]: m is declared positive: its values must be positive, got the range (0.0, 2.0, 3)
    """
    declared = {str(p) for p in positive}
    for i, key in enumerate(points.keys):
        if str(key) not in declared:
            continue
        if points.is_grid():
            axis = points.layout[1][i]
            low = float(np.min(axis))
            shown = f"the range ({float(axis[0])!r}, {float(axis[-1])!r}, {len(axis)})"
        else:
            low = float(points.layout[1][i])
            shown = f"the range ({low!r}, {float(points.layout[2][i])!r})"
        if not low > 0:
            raise AnalysisError(f"{key} is declared positive: its values must be positive, got "
                                f"{shown}", entry=f"{entry}[{key}]")
