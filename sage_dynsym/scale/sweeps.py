r"""
Parameter sweeps: any function of the parameters, or a model's simulations

:func:`sweep` evaluates a function at every point of a grid (or of random
samples) of parameter values, with the chunking of
:func:`~sage_dynsym.scale.maps.stability_map`: the chunks run as Dask tasks
(see :mod:`sage_dynsym.scale.cluster`), the same whatever the number of
workers, so the results are too (for a deterministic function).

A function is called with the parameters as keyword arguments (their
names), once per point -- or once per chunk with NumPy arrays when
``vectorized=True``. It must be picklable to run on Dask: a function of a
module the workers can import, or one defined in the session (a notebook,
a script), which Dask ships by value.

**Models.** An object with a ``simulate`` method (duck typing) is run as
``model.simulate(values, **simulate)`` at each point, ``values`` the dict
of the parameter values (keys as given, the ``fixed`` ones included) and
``simulate`` the other arguments (initial state, final time, ...); the
result kept is ``reduce(trajectory)`` (default: the trajectory itself,
which must then be picklable). This is the calling convention of
``L.simulate(values, initial, t_end, points=..., t0=0)`` of the package's
numerics (:mod:`sage_dynsym.numerics.methods`): Lagrangians, Routh
functions, Hamiltonians, mechanical systems, circuits and Lie--Poisson
systems are swept as they are (and so is any other object with that
method, see :func:`sweep`).

EXAMPLES::

    sage: from sage_dynsym.scale import sweep
    sage: def energy(m, v, g=9.81, h=0):
    ....:     return m*v^2/2 + m*g*h
    sage: W = sweep(energy, {'m': (1, 2, 3), 'v': (0, 1, 2)}, fixed={'h': 1}, client=False)
    sage: W
    Sweep of 3 x 2 points in (m, v): values of shape (3, 2), float64
    sage: W.values()
    array([[ 9.81 , 10.31 ],
           [14.715, 15.465],
           [19.62 , 20.62 ]])

**Stability classes.** A function returning
:func:`~sage_dynsym.scale.kernel.stability_class` (``2`` asymptotically
stable, ``1`` stable in first approximation, ``0`` unstable; the classes of
:meth:`~sage_dynsym.scale.maps.StabilityMap.classes`) sweeps the stability
of anything whose roots or matrix the function computes, and
:meth:`Sweep.plot` draws the classes with a legend. A damped oscillator::

    sage: import numpy as np
    sage: from sage_dynsym.scale import stability_class
    sage: def oscillator(c, k):
    ....:     return stability_class(np.array([[0, 1], [-k, -c]]))
    sage: W = sweep(oscillator, {'c': (-1, 1, 5), 'k': (-1, 1, 5)}, client=False)
    sage: W.values()
    array([[0, 0, 0, 0, 0],
           [0, 0, 0, 0, 0],
           [0, 0, 1, 1, 1],
           [0, 0, 1, 2, 2],
           [0, 0, 1, 2, 2]])
    sage: W.plot()
    Graphics object consisting of 4 graphics primitives
"""
# Sage's symbolic functions, Maxima and coercions need the whole library initialised
# first (this subpackage's face stays Sage-free for the command line)
import sage.all
del sage  # imported for its effect alone: no name of this module
import math

import numpy as np

from sage.structure.sage_object import SageObject

from ..errors import AnalysisError
from ..numerics.values import check_model_values
from .cluster import run_chunks, chunks, DEFAULT_TIMEOUT
from .kernel import sweep_chunk, chunk_points
from .maps import CHUNK
from .points import parse_points, check_positive_ranges, result_arrays, MAX_POINTS

__all__ = ['sweep', 'ModelRun', 'Sweep']


def sweep(function, parameters, client=None, *, fixed=None, samples=None, seed=0,
          vectorized=False, simulate=None, reduce=None, on_error='raise', chunk_size=None,
          workers=None, timeout=DEFAULT_TIMEOUT, progress=False, max_points=MAX_POINTS):
    r"""
    Evaluate ``function`` (or a model's simulation) at the points of a grid
    or of random samples of parameter values.

    INPUT:

    - ``function`` -- a function of the parameters (keyword arguments named
      after them), or a model with a ``simulate`` method (see the module
      documentation)
    - ``parameters`` -- dict ``{name: (low, high, n)}`` (names, or symbols
      whose names are used), or ``{name: 1-D NumPy array}``; the result is
      indexed in this order
    - ``client`` -- ``None`` (default: in this process, or a local Dask
      cluster when the estimated work exceeds
      :data:`~sage_dynsym.scale.cluster.CLUSTER_THRESHOLD` seconds),
      ``'local'``, a Dask ``Client``, a scheduler address, or ``False`` (no
      Dask); see :mod:`sage_dynsym.scale.cluster`
    - ``fixed`` -- dict of further keyword arguments (for a model: further
      values)
    - ``samples``, ``seed`` -- random points instead of the grid, as for
      :func:`~sage_dynsym.scale.maps.stability_map`
    - ``vectorized`` -- (default: ``False``) call ``function`` once per
      chunk with arrays of values; it returns an array with one entry (or
      row) per point
    - ``simulate`` -- (models) dict of the other arguments of
      ``model.simulate``
    - ``reduce`` -- (models) a function of the trajectory giving the value
      kept
    - ``on_error`` -- ``'raise'`` (default): a failure at a point is an
      error naming the point; ``'nan'``: such points get ``nan`` (``None``
      in an array of objects)
    - ``chunk_size`` -- points per Dask task (default: at most 1024, about
      64 chunks for small sweeps; `2^{15}` when vectorized)
    - ``workers``, ``timeout``, ``progress``, ``max_points`` -- as for
      :func:`~sage_dynsym.scale.maps.stability_map`

    A model's declared signs are checked before anything runs: a parameter
    declared positive gets a positive value in ``fixed`` and a range of
    positive values.

    OUTPUT: a :class:`Sweep`

    EXAMPLES: numbers give a float array; arrays of one shape an array with
    that trailing shape; anything else an array of objects::

        sage: from sage_dynsym.scale import sweep
        sage: sweep(lambda a: (a, 2*a), {'a': (0, 1, 3)}, client=False).values()
        array([[0. , 0. ],
               [0.5, 1. ],
               [1. , 2. ]])
        sage: sweep(lambda a: str(a), {'a': (0, 1, 2)}, client=False).values()
        array(['0.0', '1.0'], dtype=object)

    Vectorized, on 10^5 random points::

        sage: W = sweep(lambda x, y: x^2 + y^2 < 1, {'x': (-1, 1), 'y': (-1, 1)}, samples=10^5,
        ....:           vectorized=True, client=False)
        sage: bool(abs(4 * W.values().mean() - pi) < 0.01)
        True

    A model, here a stand-in with the calling convention of ``simulate``::

        sage: class Decay:
        ....:     def simulate(self, values, initial, t_end):
        ....:         return initial * exp(-values['k'] * t_end)
        sage: sweep(Decay(), {'k': (0, 1, 3)}, simulate=dict(initial=2, t_end=1),
        ....:       reduce=float, client=False).values()
        array([2.        , 1.21306132, 0.73575888])

    TESTS::

        sage: sweep(lambda a: 1/a, {'a': (0, 1, 3)}, client=False)
        Traceback (most recent call last):
        ...
        AnalysisError: sweep: the function raised ZeroDivisionError at {'a': 0.0}: float division by zero
        sage: sweep(lambda a: 1/a, {'a': (0, 1, 3)}, client=False, on_error='nan').values()
        array([nan,  2.,  1.])
        sage: sweep(42, {'a': (0, 1, 3)})
        Traceback (most recent call last):
        ...
        AnalysisError: sweep: expected a function of the parameters or a model with a simulate method, got 42
        sage: sweep(lambda a: a, {'a b': (0, 1, 3)})
        Traceback (most recent call last):
        ...
        AnalysisError: sweep: parameters: 'a b' is not a valid keyword name
        sage: sweep(lambda a: a, {'a': (0, 1, 3)}, fixed={'a': 2})
        Traceback (most recent call last):
        ...
        AnalysisError: sweep: a is both a parameter and fixed
        sage: sweep(lambda a, b: a*b, {'a': (0, 1, 10^5), 'b': (0, 1, 10^5)}, client=False)
        Traceback (most recent call last):
        ...
        AnalysisError: parameters: 10000000000 points are more than the limit of 10000000; raise it with max_points= if that is what you want
        sage: from sage_dynsym.circuits import Circuit
        sage: C = Circuit([[1, 2, 'L1'], [2, 3, 'R1'], [3, 1, 'C1']], positive=['L1', 'R1', 'C1'])
        sage: sweep(C, {'R1': (-1, 1, 3)}, fixed={'L1': 1, 'C1': 1}, client=False,
        ....:       simulate=dict(initial={'i1': 1, 'u2': 0}, t_end=1))
        Traceback (most recent call last):
        ...
        AnalysisError: parameters[R1]: R1 is declared positive: its values must be positive, got the range (-1.0, 1.0, 3)
    """
    entry = "sweep"
    if on_error not in ('raise', 'nan'):
        raise AnalysisError(f"on_error must be 'raise' or 'nan', got {on_error!r}", entry=entry)
    if not isinstance(parameters, dict) or not parameters:
        parse_points(parameters)            # the error for a missing or malformed dict
    if not isinstance(fixed, (dict, type(None))):
        raise AnalysisError(f"fixed= must be a dict, got {fixed!r}", entry=entry)
    keys = list(parameters)
    names = [str(k) for k in keys]
    for name in names:
        if not name.isidentifier():
            raise AnalysisError(f"parameters: {name!r} is not a valid keyword name", entry=entry)
    if len(set(names)) < len(names):
        raise AnalysisError("parameters: a name is given twice", entry=entry)
    fixed = dict(fixed or {})
    for k in fixed:
        if str(k) in names:
            raise AnalysisError(f"{k} is both a parameter and fixed", entry=entry)
    model = hasattr(function, 'simulate') and callable(function.simulate)
    if model:
        check_model_values(function, fixed, entry="fixed")
        if simulate is not None and not isinstance(simulate, dict):
            raise AnalysisError(f"simulate= must be a dict of the arguments of simulate, got "
                                f"{simulate!r}", entry=entry)
        call = ModelRun(function, dict(zip(names, keys)), fixed, simulate or {}, reduce)
        fixed = {}
    elif callable(function):
        if simulate is not None or reduce is not None:
            raise AnalysisError("simulate= and reduce= are for a model with a simulate "
                                "method", entry=entry)
        fixed = {str(k): v for k, v in fixed.items()}
        call = function
    else:
        raise AnalysisError("expected a function of the parameters or a model with a simulate "
                            f"method, got {function!r}", entry=entry)
    points = parse_points(dict(zip(names, parameters.values())), samples, seed,
                          max_points=max_points)
    if model and callable(getattr(function, 'positive_parameters', None)):
        check_positive_ranges(points, function.positive_parameters())
    if chunk_size is None:
        chunk_size = CHUNK if vectorized else max(1, min(1024, math.ceil(points.size / 64)))
    ranges = chunks(points.size, chunk_size)
    task = dict(points=points.layout, names=names, fixed=fixed, function=call,
                vectorized=bool(vectorized))
    results = [None] * len(ranges)
    failures = []

    def collect(i, result):
        a, b = ranges[i]
        if vectorized:
            result = np.asarray(result)
            if result.shape[:1] != (b - a,):
                raise AnalysisError(f"the vectorized function returned shape {result.shape} "
                                    f"for {b - a} points", entry=entry)
        else:
            for j, r in enumerate(result):
                if isinstance(r, tuple) and len(r) == 4 and r[0] == '__sweep_failure__':
                    failures.append(r)
                    result[j] = None
        results[i] = result

    run_chunks(sweep_chunk, task, ranges, collect, client=client, workers=workers,
               timeout=timeout, progress=progress, label='sweep')
    if failures and on_error == 'raise':
        _, point, kind, message = failures[0]
        more = f" (and {len(failures) - 1} other points)" if len(failures) > 1 else ""
        raise AnalysisError(f"the function raised {kind} at {point}: {message}{more}",
                            entry=entry)
    values = (np.concatenate(results) if vectorized and results
              else _assemble([r for part in results for r in part]))
    return Sweep(points, values.reshape(points.shape + values.shape[1:]), keys)


class ModelRun:
    r"""
    The function of the parameters that a model sweep evaluates:
    ``reduce(model.simulate(values, **options))``.

    INPUT:

    - ``model`` -- an object with a ``simulate(values, **options)`` method
    - ``keys`` -- dict from the keyword names to the keys of ``values``
      (e.g. symbols)
    - ``fixed`` -- further entries of ``values``
    - ``options`` -- the other arguments of ``simulate``
    - ``reduce`` -- (optional) applied to the trajectory

    EXAMPLES::

        sage: from sage_dynsym.scale.sweeps import ModelRun
        sage: class Echo:
        ....:     def simulate(self, values, scale=1):
        ....:         return {str(k): scale * v for k, v in values.items()}
        sage: k = var('k')
        sage: ModelRun(Echo(), {'k': k}, {'c': 1}, {'scale': int(10)}, None)(k=float(2))
        {'c': 10, 'k': 20.0}
    """

    def __init__(self, model, keys, fixed, options, reduce):
        self.model, self.keys, self.fixed = model, keys, fixed
        self.options, self.reduce = options, reduce

    def __call__(self, **values):
        point = dict(self.fixed)
        point.update({self.keys[name]: v for name, v in values.items()})
        trajectory = self.model.simulate(point, **self.options)
        return trajectory if self.reduce is None else self.reduce(trajectory)


def _assemble(results):
    r"""An array of the results: numeric when they are numbers or arrays of
    one shape (failures -- ``None`` -- are ``nan``), else of objects."""
    known = [r for r in results if r is not None]
    try:
        shapes = {np.shape(r) for r in known}
        if len(shapes) <= 1:
            shape = shapes.pop() if shapes else ()
            filler = np.full(shape, np.nan)
            array = np.array([filler if r is None else r for r in results])
            if array.dtype.kind in 'biuf':
                return array.astype(float) if any(r is None for r in results) else array
    except (TypeError, ValueError):
        pass
    array = np.empty(len(results), dtype=object)
    array[:] = results
    return array


class Sweep(SageObject):
    r"""
    The result of :func:`sweep`: the values of the function at the points,
    an array indexed in the order of the parameters (1-D for random
    samples), with any trailing dimensions of the function's values.

    EXAMPLES: see :func:`sweep`.

    TESTS:

    Sweeps have no value equality (they hold NumPy arrays), so the pickling
    test is skipped; the values stand over the points, one axis a
    parameter::

        sage: from sage_dynsym.scale import sweep
        sage: W = sweep(lambda a, b: (a, a*b), {'a': (0, 1, 3), 'b': (1, 2, 2)}, client=False)
        sage: TestSuite(W).run(skip='_test_pickling')
        sage: R = sweep(lambda a: a, {'a': (0, 1)}, samples=5, client=False)
        sage: TestSuite(R).run(skip='_test_pickling')
    """

    def __init__(self, points, values, keys):
        result_arrays(points, [values], 'Sweep')
        self._points, self._values, self._keys = points, values, list(keys)

    def _test_points(self, **options):
        r"""The values have the shape of the points first; there is one
        axis per parameter, in their order, as long as its dimension of the
        grid (for random samples: as the number of samples), with finite
        values.

        EXAMPLES: run by ``TestSuite`` (see the class).
        """
        tester = self._tester(**options)
        shape = self._points.shape
        tester.assertEqual(self._values.shape[:len(shape)], shape)
        axes = self.axes()
        tester.assertEqual(list(axes), self.parameters())
        lengths = shape if self._points.is_grid() else [self._points.size] * len(axes)
        tester.assertEqual([len(axis) for axis in axes.values()], list(lengths))
        tester.assertTrue(all(np.isfinite(axis).all() for axis in axes.values()))

    def _repr_(self):
        names = ', '.join(map(str, self._keys))
        where = (' x '.join(map(str, self._points.shape)) + " points" if self._points.is_grid()
                 else f"{self._points.size} random points")
        return (f"Sweep of {where} in ({names}): values of shape {self._values.shape}, "
                f"{self._values.dtype}")

    def parameters(self):
        r"""The parameters, as given, in the order of the array indices.

        EXAMPLES::

            sage: from sage_dynsym.scale import sweep
            sage: sweep(lambda a, b: a*b, {'b': (0, 1, 2), 'a': (0, 1, 3)}, client=False).parameters()
            ['b', 'a']
        """
        return list(self._keys)

    def axes(self):
        r"""
        Dict ``{parameter: 1-D array}``: the values along each axis; for
        random samples, the coordinates of the samples.

        EXAMPLES::

            sage: from sage_dynsym.scale import sweep
            sage: sweep(lambda a: a, {'a': (0, 1, 3)}, client=False).axes()
            {'a': array([0. , 0.5, 1. ])}
        """
        if self._points.is_grid():
            columns = self._points.axes()
        else:
            columns = chunk_points(self._points.layout, 0, self._points.size)
        return dict(zip(self._keys, columns))

    def values(self):
        r"""The array of the values.

        EXAMPLES::

            sage: from sage_dynsym.scale import sweep
            sage: sweep(lambda a: a + 1, {'a': (0, 1, 3)}, client=False).values()
            array([1. , 1.5, 2. ])
        """
        return self._values

    def plot(self, **options):
        r"""
        The values against one parameter (a line), or, for two parameters
        on a grid and values that are stability classes (``2``, ``1``,
        ``0``, ``-1``), the picture of the classes with a legend (see
        :func:`~sage_dynsym.scale.maps.class_plot`).

        EXAMPLES: see the module documentation; one parameter::

            sage: from sage_dynsym.scale import sweep
            sage: sweep(lambda a: a^2, {'a': (0, 1, 5)}, client=False).plot()
            Graphics object consisting of 1 graphics primitive

        TESTS::

            sage: sweep(lambda a, b: a*b, {'a': (0, 1, 3), 'b': (0, 1, 3)}, client=False).plot()
            Traceback (most recent call last):
            ...
            AnalysisError: Sweep.plot: draws numbers against one parameter, or stability classes (2, 1, 0, -1) over two on a grid
        """
        values = self._values
        numeric = values.dtype.kind in 'biuf'
        if numeric and len(self._keys) == 1 and self._points.is_grid() and values.ndim == 1:
            from sage.plot.line import line
            G = line(list(zip(map(float, self._points.axes()[0]), map(float, values))),
                     **options)
            G.axes_labels([f"${self._keys[0]}$", ""])
            return G
        is_class = numeric and values.size and np.all(np.isin(values, (-1, 0, 1, 2)))
        if is_class and len(self._keys) == 2 and self._points.is_grid() and values.ndim == 2:
            from .maps import class_plot
            X, Y = self._points.axes()
            options = dict(dict(frame=True, axes=False, ticks_integer=False), **options)
            G = class_plot(X, Y, values.astype(int), options)
            G.axes_labels([f"${k}$" for k in self._keys])
            return G
        raise AnalysisError("draws numbers against one parameter, or stability classes (2, 1, "
                            "0, -1) over two on a grid", entry="Sweep.plot")
