r"""
Stability maps: the first approximation at many parameter points

:func:`stability_map` decides the stability of a linear system (from
:func:`~sage_dynsym.analysis.linear.linearize`) at every point of a grid,
or of random samples, in a space of parameters: the classical stability
diagrams of satellite and gyrostat studies, the design chart of a circuit.
The symbolic work is done once -- the fixed values substituted, the
characteristic polynomial (or the matrices) compiled into a vectorised
NumPy program -- and the points are cut into chunks that run as Dask tasks
(:mod:`sage_dynsym.scale.cluster`: a local cluster by default, any Dask
scheduler, or ``client=False`` for plain NumPy in this process).

At each point the map holds the largest real part `\alpha` of the
characteristic roots and the verdict *asymptotically stable in the first
approximation*, `\alpha < -\mathrm{tol}\cdot\rho` with `\rho` the largest
modulus of the roots (default ``tol = 1e-9``): rounding errors do not make
a critical point (`\alpha = 0`) stable. Its *class*
(:meth:`StabilityMap.classes`) also tells the points stable in first
approximation -- the roots of largest real part on the imaginary axis,
`-\mathrm{tol}\cdot\rho \le \alpha \le \mathrm{marginal\_tol}\cdot\rho`
(default `10^{-7}`): conservative and gyroscopic systems, circulatory ones
below flutter -- from the unstable ones: ``2``, ``1``, ``0``. Two methods
compute `\alpha`:

- ``'polynomial'`` (the default when the characteristic polynomial is
  available): its coefficients are compiled and its roots found by a
  vectorised Laguerre iteration (:func:`~sage_dynsym.scale.kernel.polynomial_abscissa`);
- ``'eigvals'``: the matrices `J, B` of the pencil `B\dot x = J x` (for a
  second-order system `x = (z, \dot z)`, `B = \mathrm{diag}(I, M)`) are
  compiled and ``numpy.linalg.eigvals`` runs on stacks of matrices
  (:func:`~sage_dynsym.scale.kernel.pencil_abscissa`).

The points and chunks do not depend on the number of workers, and random
samples are drawn per block from a fixed seed: a map is the same, to the
last bit, on one worker, on many, or without Dask.

EXAMPLES:

A damped oscillator `m\ddot x + c\dot x + k x = 0` in the plane of `c`
and `k`, without Dask (``client=False``)::

    sage: from sage_dynsym.analysis import linearize
    sage: from sage_dynsym.scale import stability_map
    sage: x, y, m, c, k = var('x y m c k')
    sage: osc = linearize([y, -(c*y + k*x)/m], {x: 0, y: 0}, [x, y])
    sage: S = stability_map(osc, {c: (-1, 2, 31), k: (-1, 2, 31)}, fixed={m: 1}, client=False)
    sage: S
    Stability map of 31 x 31 points in (c, k): 41.6% asymptotically stable, 4.3% stable in first approximation
    sage: S.axes()[c][:3], S.max_real_part().shape
    (array([-1. , -0.9, -0.8]), (31, 31))

The Liénard--Chipart conditions of `\lambda^2 + c\lambda + k` are
`c > 0, k > 0`; the map agrees with them everywhere, the boundary
included::

    sage: S.agreement([c > 0, k > 0])
    1.0
    sage: G = S.plot([c > 0, k > 0]); G  # long time
    Graphics object consisting of 6 graphics primitives

The picture has a legend naming the colours and the exact boundary, and a
title with the fixed values::

    sage: sorted(p.options()['legend_label'] for p in G if p.options().get('legend_label'))  # long time
    ['asymptotically stable', 'exact boundary', 'stable in first approximation', 'unstable']
    sage: G._extra_kwds['title']  # long time
    'stability map\n$m = 1$'

(on the lines `c = 0` and `k = 0` the roots of largest real part are on
the imaginary axis: those points are stable in first approximation.)

An undamped circulatory system, `\ddot x + x + py = 0`, `\ddot y + ky -
px = 0`, mapped in three classes: stable in first approximation (class
``1``) inside its flutter and divergence boundaries; the exact classes come
from the characteristic polynomial
(:func:`~sage_dynsym.analysis.spectrum.spectrum_regions`), and off a band
of one grid step along the boundaries the map agrees with them::

    sage: from sage_dynsym.analysis.linear import LinearSystem
    sage: p = var('p')
    sage: W = matrix([[1, p], [-p, k]])
    sage: C = stability_map(LinearSystem([x, y], M=identity_matrix(2), S=zero_matrix(2), W=W),
    ....:                   {k: (-1, 3, 41), p: (-1, 1, 41)}, client=False, classes='spectrum')
    sage: C
    Stability map of 41 x 41 points in (k, p): 0.0% asymptotically stable, 35.7% stable in first approximation
    sage: C.agreement(by_class=True, band=1)
    {0: 1.0, 1: 1.0, 2: nan}

The same map on a Dask cluster (here a local one, started and closed for
the computation) is identical::

    sage: T = stability_map(osc, {c: (-1, 2, 31), k: (-1, 2, 31)}, fixed={m: 1}, workers=1)
    sage: bool((T.max_real_part() == S.max_real_part()).all())
    True
"""
# Sage's symbolic functions, Maxima and coercions need the whole library initialised
# first (this subpackage's face stays Sage-free for the command line)
import sage.all
del sage  # imported for its effect alone: no name of this module

import numpy as np

from sage.matrix.constructor import block_matrix, identity_matrix, zero_matrix
from sage.misc.latex import latex
from sage.misc.superseded import deprecation
from sage.rings.rational_field import QQ
from sage.structure.sage_object import SageObject
from sage.symbolic.ring import SR

from ..algebra.conditions import as_relational
from ..errors import AnalysisError, DynSymError, brief
from ..io.files import write_atomically
from ..dynamics.hamiltonian import Hamiltonian
from ..dynamics.lagrangian import Lagrangian
from ..description import kinds
from ..numerics.values import check_model_values
from .cluster import run_chunks, chunks, DEFAULT_TIMEOUT
from .compile import compile_expressions
from .kernel import map_chunk, chunk_points, run_program
from .equilibria import point_diagnosis
from .points import (Points, parse_points, check_positive_ranges, number_text, result_arrays,
                     MAX_POINTS)

__all__ = ['CHUNK', 'MAX_POLYNOMIAL_DEGREE', 'stability_map', 'model_linear_system',
           'linear_symbols', 'CLASS_COLOURS', 'CLASS_NAMES', 'StabilityMap', 'class_plot',
           'BOUNDARY_POINTS']

CHUNK = 2 ** 15              # points per Dask task (fixed: results do not depend on it)
MAX_POLYNOMIAL_DEGREE = 16   # above: the 'eigvals' method


def stability_map(system, parameters, fixed=None, client=None, samples=None, *, at=None,
                  variables=None, lhs_matrix=None, seed=0, method='auto', tol=1e-9,
                  marginal_tol=1e-7, conditions=None, classes=None, chunk_size=CHUNK,
                  workers=None, timeout=DEFAULT_TIMEOUT, progress=False, max_points=MAX_POINTS):
    r"""
    The stability map of a linear system over a grid (or random samples)
    of parameter values.

    INPUT:

    - ``system`` -- a :class:`~sage_dynsym.analysis.linear.LinearSystem`
      (from :func:`~sage_dynsym.analysis.linear.linearize`); or what
      ``linearize`` accepts, with ``at=`` (and ``variables=``,
      ``lhs_matrix=``); or a model: a circuit (its free state equations,
      sources off, around the zero state: ``linearize(model, at,
      sources=False)``)
      or a mechanical system (its Lagrangian around ``at``, default all
      coordinates 0)
    - ``parameters`` -- dict ``{symbol: (low, high, n)}`` (symbols or their
      names); the result arrays are indexed in this order. Or the
      :class:`~sage_dynsym.scale.points.Points` of
      :func:`~sage_dynsym.scale.points.parse_points`, already checked (as
      the command line does before loading the model; then ``samples``,
      ``seed`` and ``max_points`` are theirs)
    - ``fixed`` -- dict ``{symbol: number}``, the values of the other
      symbols; a key may also be an expression of the system such as
      ``diff(f(u), u).subs(u=0)``
    - ``client`` -- ``None`` (default: in this process, or a local Dask
      cluster when the estimated work exceeds
      :data:`~sage_dynsym.scale.cluster.CLUSTER_THRESHOLD` seconds),
      ``'local'`` (a local Dask cluster, started and closed), a Dask
      ``Client``, a scheduler address, or ``False`` (no Dask); see
      :mod:`sage_dynsym.scale.cluster`
    - ``samples`` -- (optional) a number of uniform random points in the box
      of the ranges instead of the grid, drawn from ``seed``
    - ``method`` -- ``'auto'`` (default), ``'polynomial'`` or ``'eigvals'``
      (see the module documentation)
    - ``tol`` -- the stability margin relative to the largest modulus of
      the roots
    - ``marginal_tol`` -- (default: `10^{-7}`) how far to the right of the
      imaginary axis, relative to the largest modulus, the roots of a point
      of class ``1`` (stable in first approximation) may be computed
    - ``conditions`` -- (optional) the exact stability conditions (see
      :meth:`StabilityMap.exact`), drawn by :meth:`StabilityMap.plot`; or
      ``'lienard-chipart'`` for those of asymptotic stability from the
      stability service (:meth:`~sage_dynsym.analysis.linear.LinearSystem.stability`)
    - ``classes`` -- (optional) the exact regions of the classes (see
      :meth:`StabilityMap.exact_classes`): a dict ``{2: region, 1:
      region}``, a :class:`~sage_dynsym.analysis.verdict.StabilityVerdict`,
      or ``'spectrum'`` for the cases of the stability service's verdict
      (:meth:`~sage_dynsym.analysis.linear.LinearSystem.stability`, with
      respect to every variable, as the map's eigenvalues)
    - ``chunk_size`` -- points per Dask task
    - ``workers`` -- the number of workers of the local cluster (default:
      one per core; giving it with ``client=None`` asks for a local cluster)
    - ``timeout`` -- seconds to reach a scheduler and get a worker
    - ``progress`` -- show Dask's progress bar
    - ``max_points`` -- (default: :data:`~sage_dynsym.scale.points.MAX_POINTS`)
      the most points, checked before anything is computed

    For a model, the values must respect its declared signs: a parameter
    declared positive gets a positive value in ``fixed`` and a range of
    positive values; ``at`` names its state variables (a circuit) or
    coordinates (a mechanical system).

    OUTPUT: a :class:`StabilityMap`

    EXAMPLES: see the module documentation. A system given as right-hand
    sides, on 2000 random points::

        sage: from sage_dynsym.scale import stability_map
        sage: x, y, a, b = var('x y a b')
        sage: S = stability_map([y, -sin(x) - a*y + b*x], {a: (-1, 1), b: (-1, 1)}, samples=2000,
        ....:                   at={x: 0, y: 0}, variables=[x, y], client=False)
        sage: S
        Stability map of 2000 random points in (a, b): 49.5% asymptotically stable
        sage: S.agreement([a > 0, 1 - b > 0])
        1.0

    TESTS::

        sage: S = stability_map([y, -a*x - b*y], {a: (0, 1, 5), var('z'): (0, 1, 5)},
        ....:                   at={x: 0, y: 0}, variables=[x, y], client=False)
        Traceback (most recent call last):
        ...
        AnalysisError: stability_map: unknown parameter z: the symbols of the system are a, b
        sage: S = stability_map([y, -a*x - b*y], {a: (0, 1, 5)}, at={x: 0, y: 0},
        ....:                   variables=[x, y], client=False)
        Traceback (most recent call last):
        ...
        AnalysisError: stability_map: no value for b: give it as a parameter or in fixed= (--param or --value on the command line)
        sage: S = stability_map([y, -a*x - b*y], {a: (0, 1, 5)}, fixed={'b': 'one'},
        ....:                   at={x: 0, y: 0}, variables=[x, y], client=False)
        Traceback (most recent call last):
        ...
        AnalysisError: stability_map: fixed[b]: expected a real number, got 'one'
        sage: S = stability_map([y, -a*x - b*y], {a: (0, 1, 5)}, fixed={a: 1, b: 1},
        ....:                   at={x: 0, y: 0}, variables=[x, y], client=False)
        Traceback (most recent call last):
        ...
        AnalysisError: stability_map: a is both a parameter and fixed
        sage: stability_map(x, {a: (0, 1, 5)})
        Traceback (most recent call last):
        ...
        AnalysisError: stability_map: expected a linear system (from linearize), or what linearize accepts with at=, or a circuit or mechanical model, got x
        sage: stability_map([y, -a*x - b*y], {a: (0, 1, 10^5), b: (0, 1, 10^5)}, at={x: 0, y: 0},
        ....:               variables=[x, y], client=False)
        Traceback (most recent call last):
        ...
        AnalysisError: parameters: 10000000000 points are more than the limit of 10000000; raise it with max_points= if that is what you want

    A model's declared signs and state variables::

        sage: from sage_dynsym.circuits import Circuit
        sage: C = Circuit([[1, 2, 'L1'], [2, 3, 'R1'], [3, 1, 'C1']], positive=['L1', 'C1'])
        sage: stability_map(C, {'R1': (-1, 1, 3)}, fixed={'L1': -1, 'C1': 1}, client=False)
        Traceback (most recent call last):
        ...
        ModelError: fixed: L1 is declared positive, got -1
        sage: stability_map(C, {'L1': (-1, 1, 3)}, fixed={'R1': 1, 'C1': 1}, client=False)
        Traceback (most recent call last):
        ...
        AnalysisError: parameters[L1]: L1 is declared positive: its values must be positive, got the range (-1.0, 1.0, 3)
        sage: stability_map(C, {'R1': (0, 1, 3)}, fixed={'L1': 1, 'C1': 1}, at={'zz': 1},
        ....:               client=False)
        Traceback (most recent call last):
        ...
        AnalysisError: at: zz is not a state variable of the model; the state variables are i1, u2

    A point of a model that is not a regular equilibrium: the coordinate at
    fault is named, and a point that works suggested (see
    :mod:`~sage_dynsym.scale.equilibria`)::

        sage: from sage_dynsym import load
        sage: from sage_dynsym.description import example_path
        sage: cart = load(example_path('cart_pendulum_spring_damper.yaml'))
        sage: stability_map(cart, {'k': (1, 2, 3)}, at={'theta': 3.14}, client=False)
        Traceback (most recent call last):
        ...
        AnalysisError: at: the point {y: 0, theta: 3.14} is not an equilibrium: ... did you mean theta = pi? ...
        sage: stability_map(load(example_path('spherical_pendulum.yaml')), {'m': (1, 2, 3)},
        ....:               at={'zz': 1}, client=False)
        Traceback (most recent call last):
        ...
        AnalysisError: at: zz is not a coordinate of the model; the coordinates are psi, theta
    """
    entry = "stability_map"
    if method not in ('auto', 'polynomial', 'eigvals'):
        raise AnalysisError(f"method must be 'auto', 'polynomial' or 'eigvals', got {method!r}",
                            entry=entry)
    tol = _tolerance(tol, "tol", entry)
    points = (parameters if isinstance(parameters, Points) else
              parse_points(parameters, samples, seed, max_points=max_points))
    for name, value in (('fixed', fixed), ('at', at)):
        if not isinstance(value, (dict, type(None))):
            raise AnalysisError(f"{name}= must be a dict, got {value!r}", entry=entry)
    if callable(getattr(system, 'positive_parameters', None)):     # declared signs, first
        check_model_values(system, dict(fixed or {}), entry="fixed")
        check_positive_ranges(points, system.positive_parameters())
    linear = _linear_system(system, at, variables, lhs_matrix)
    symbols = _symbols(linear)
    names = {str(s): s for s in symbols}
    keys = [_resolve(k, names, symbols, "unknown parameter") for k in points.keys]
    if len(set(keys)) < len(keys):
        raise AnalysisError("a parameter is given twice", entry=entry)
    values = {}
    for k, v in (fixed or {}).items():
        key = _resolve(k, names, symbols, "unknown symbol in fixed=", expressions=linear)
        if key in keys:
            raise AnalysisError(f"{key} is both a parameter and fixed", entry=entry)
        values[key] = _exact_number(v, f"fixed[{k}]")
    points = points.with_keys(keys)
    fixed_system = _substitute(linear, values)
    missing = sorted(set(_symbols(fixed_system)) - set(keys), key=str)
    if missing:
        raise AnalysisError(f"no value for {', '.join(map(str, missing))}: give "
                            f"{'it' if len(missing) == 1 else 'them'} as a parameter or in "
                            "fixed= (--param or --value on the command line)", entry=entry)
    lam = SR.symbol()                       # a fresh variable: no clash with the system's
    poly, note = None, None
    if method != 'eigvals' or conditions == 'lienard-chipart':
        poly, note = _characteristic_polynomial(fixed_system, lam, method == 'polynomial')
    if method == 'auto':
        method = 'polynomial' if poly is not None else 'eigvals'
    if method == 'polynomial':
        coefficients = poly.coefficients(lam, sparse=False)[::-1]
        task = dict(method='polynomial', program=compile_expressions(coefficients, keys, entry))
    else:
        J, B = _pencil(fixed_system)
        lhs = B != identity_matrix(SR, B.nrows())
        task = dict(method='eigvals', size=J.nrows(), lhs=lhs,
                    program=compile_expressions(J.list() + (B.list() if lhs else []), keys, entry))
    marginal_tol = _tolerance(marginal_tol, "marginal_tol", entry)
    task.update(points=points.layout, tol=tol, marginal_tol=marginal_tol)
    alpha = np.empty(points.size)
    stable = np.empty(points.size, dtype=bool)
    kinds = np.empty(points.size, dtype=np.int8)

    def collect(i, result):
        a, b = ranges[i]
        alpha[a:b], stable[a:b], kinds[a:b] = result

    ranges = chunks(points.size, chunk_size)
    run_chunks(map_chunk, task, ranges, collect, client=client, workers=workers,
               timeout=timeout, progress=progress, label='stability-map')
    if conditions == 'lienard-chipart':
        conditions, note = _lienard_chipart(fixed_system, note)
    if isinstance(classes, str):
        if classes != 'spectrum':
            raise AnalysisError(f"classes must be 'spectrum', a dict or a verdict, got "
                                f"{classes!r}", entry=entry)
        classes, note = _spectrum_classes(fixed_system, note)
    name = system.name() if _model_kind(system) is not None else None
    return StabilityMap(points, alpha.reshape(points.shape), stable.reshape(points.shape),
                        values, method, tol, conditions, note, name,
                        classes=kinds.reshape(points.shape), exact_classes=classes,
                        marginal_tol=marginal_tol,
                        at={k: v for k, v in _point(at).items() if not v.is_zero()})


# ---------------------------------------------------------------------------
# the system
# ---------------------------------------------------------------------------

def _tolerance(value, name, entry):
    # a tolerance given by the user, as a float (NaN and non-numbers refused)
    try:
        value = float(value)
    except (TypeError, ValueError):
        value = -1.0
    if not value >= 0:
        raise AnalysisError(f"{name} must be a non-negative number", entry=entry)
    return value


def _linear_system(system, at, variables, lhs_matrix):
    from ..analysis import LinearSystem, linearize
    if isinstance(system, LinearSystem):
        return system
    if _model_kind(system) is not None:
        return _free_linear_system(system, at)
    # right-hand sides, or a characteristic function (Lagrangian, Routh
    # function, Hamiltonian): linearize checks the rest
    if at is None or not isinstance(system, (list, tuple, Lagrangian, Hamiltonian)):
        raise AnalysisError("expected a linear system (from linearize), or what linearize "
                            "accepts with at=, or a circuit or mechanical model, got "
                            f"{_short(system)}", entry="stability_map")
    return linearize(system, _point(at), variables, lhs_matrix)


def _short(obj):
    text = str(obj)
    return text if len(text) < 80 else text[:77] + '...'


def _point(at):
    point = {}
    for k, v in (at or {}).items():
        if isinstance(k, str):
            if not k.isidentifier():
                raise AnalysisError(f"at: {k!r} is not a name", entry="stability_map")
            k = SR.var(k)
        if isinstance(v, str):
            raise AnalysisError(f"at[{k}]: expected a number or an expression, got {v!r}",
                                entry="stability_map")
        point[SR(k)] = SR(v)
    return point


def _model_kind(system):
    # the class of the registered kind of a model (``kinds()``), ``None``
    # for anything else: what differs per kind comes from that class
    cls = kinds().get(getattr(system, 'kind', None))
    return cls if cls is not None and isinstance(system, cls) else None


def _free_linear_system(model, at):
    # linearize(model, at, sources=False), a point that is not an
    # equilibrium diagnosed: which coordinate, and a point that works
    from ..analysis import linearize
    point = _point(at)
    try:
        return linearize(model, point, sources=False)
    except AnalysisError as err:
        if err.entry != "linearize":
            raise
        better = point_diagnosis(model, point)
        if better is None:
            raise
        raise better from err


def model_linear_system(model, at=None):
    r"""
    Deprecated: use ``linearize(model, at, sources=False)``
    (:func:`~sage_dynsym.analysis.linear.linearize`, the one way to build a
    linear system).

    The linear system whose stability :func:`stability_map` maps for a
    model (also the ``map`` command line): the model's
    :meth:`~sage_dynsym.dynamics.model.Model.free_linear_system` -- for a
    circuit its free state equations `B\dot x = F(x)` (sources off)
    around the zero state, for a mechanical system its Lagrangian
    (dissipation included) around all coordinates 0, for a Lie--Poisson
    system its first approximation at the origin; ``at`` gives other
    values to the state variables (or coordinates).

    EXAMPLES::

        sage: from sage_dynsym import load, linearize
        sage: from sage_dynsym.description import example_path
        sage: from sage_dynsym.scale.maps import model_linear_system
        sage: ladder = load(example_path('rlc_ladder.yaml'))
        sage: S = model_linear_system(ladder)
        doctest:warning...
        DeprecationWarning: model_linear_system(model, at) is deprecated; use linearize(model, at, sources=False)
        See https://github.com/sagemath/sage/issues/31 for details.
        sage: T = linearize(ladder, sources=False)
        sage: (S.jacobian(), S.lhs_matrix()) == (T.jacobian(), T.lhs_matrix())
        True
        sage: S.lhs_matrix()
        [L1  0  0  0  0  0]
        [ 0 L2  0  0  0  0]
        [ 0  0 L3  0  0  0]
        [ 0  0  0 C3  0  0]
        [ 0  0  0  0 C1  0]
        [ 0  0  0  0  0 C2]

    TESTS:

    A point that is not a regular equilibrium: the coordinate at fault is
    named, and a point that works suggested (see
    :mod:`~sage_dynsym.scale.equilibria`)::

        sage: cart = load(example_path('cart_pendulum_spring_damper.yaml'))
        sage: model_linear_system(cart, {'theta': pi}).W()
        [      k       0]
        [      0 -g*l*m]
        sage: model_linear_system(cart, {'theta': 3.14})
        Traceback (most recent call last):
        ...
        AnalysisError: at: the point {y: 0, theta: 3.14} is not an equilibrium: ... did you mean theta = pi? ...
    """
    deprecation(31, "model_linear_system(model, at) is deprecated; use "
                    "linearize(model, at, sources=False)")
    return _free_linear_system(model, at)


def linear_symbols(linear):
    r"""
    The symbols (parameters) of the matrices of a linear system, sorted by
    name: what :func:`stability_map` needs values for.

    EXAMPLES::

        sage: from sage_dynsym.analysis.linear import LinearSystem
        sage: from sage_dynsym.scale.maps import linear_symbols
        sage: a, b, m = var('a b m')
        sage: linear_symbols(LinearSystem([var('x')], M=[[m]], S=[[a]], W=[[b^2]]))
        [a, b, m]
    """
    return _symbols(linear)


def _symbols(linear):
    entries = []
    for X in _matrices(linear):
        entries += X.list()
    return sorted(set().union(*(set(SR(e).variables()) for e in entries)), key=str)


def _matrices(linear):
    if linear.order() == 1:
        return [_jacobian(linear), linear.lhs_matrix()]
    return [linear.M(), linear.S(), linear.W()]


def _jacobian(linear):
    # J of B x' = J x (LinearSystem.jacobian() is B^{-1} J)
    return -linear.characteristic_matrix(SR(0))


def _resolve(key, names, symbols, what, expressions=None):
    if isinstance(key, str):
        if key in names:
            return names[key]
    else:
        try:
            k = SR(key)
        except (TypeError, ValueError):
            k = None
        if k is not None and k in symbols:
            return k
        if k is not None and expressions is not None and not k.is_symbol() and \
                any(_contains(e, k) for X in _matrices(expressions) for e in X.list()):
            return k
    raise AnalysisError(f"{what} {key}: the symbols of the system are "
                        f"{', '.join(map(str, symbols)) or '(none)'}", entry="stability_map")


def _contains(expr, part):
    # Expression.has does not see D[0](f)(0); a substitution does
    marker = SR.symbol()
    return marker in SR(expr).subs({part: marker}).variables()


def _exact_number(value, where, entry="stability_map"):
    # exact values keep the characteristic polynomial over QQ; a float is
    # taken as the binary rational it is
    from sage.rings.integer import Integer
    from sage.rings.rational import Rational
    from sage.symbolic.expression import Expression
    if isinstance(value, str) or isinstance(value, bool):
        z = None
    else:
        try:
            z = complex(value)
        except (TypeError, ValueError):
            z = None
    if z is None or z.imag != 0 or not np.isfinite(z.real):
        what = "a finite real number" if z is not None and z.imag == 0 else "a real number"
        raise AnalysisError(f"{where}: expected {what}, got {brief(value)}", entry=entry)
    if isinstance(value, (int, Integer, Rational)):
        return SR(QQ(value))
    if isinstance(value, Expression) and value.is_constant() and not value.variables():
        return value
    return SR(QQ(float(z.real)))


def _substitute(linear, values):
    from ..analysis import LinearSystem
    if not values:
        return linear
    sub = lambda X: X.subs(values)
    if linear.order() == 1:
        return LinearSystem(linear.variables(), J=sub(_jacobian(linear)),
                            B=sub(linear.lhs_matrix()))
    return LinearSystem(linear.variables(), M=sub(linear.M()), S=sub(linear.S()),
                        W=sub(linear.W()))


def _pencil(linear):
    r"""The matrices `J, B` of the first-order pencil `B\dot x = J x`."""
    if linear.order() == 1:
        return _jacobian(linear), linear.lhs_matrix()
    n = len(linear.variables())
    I, Z = identity_matrix(SR, n), zero_matrix(SR, n)
    J = block_matrix(SR, [[Z, I], [-linear.W(), -linear.S()]], subdivide=False)
    B = block_matrix(SR, [[I, Z], [Z, linear.M()]], subdivide=False)
    return J, B


def _characteristic_polynomial(linear, lam, required):
    try:
        order = len(linear.variables()) * linear.order()
        if order > MAX_POLYNOMIAL_DEGREE:       # not even worth computing
            raise AnalysisError(f"the system has order {order} > {MAX_POLYNOMIAL_DEGREE}",
                                entry="stability_map")
        poly = SR(linear.characteristic_polynomial(lam))
        degree = poly.degree(lam)
        if poly.is_zero():
            raise AnalysisError("the characteristic polynomial vanishes identically "
                                "(det(B lambda - J) = 0: a singular pencil)",
                                entry="stability_map")
        if degree > MAX_POLYNOMIAL_DEGREE:
            raise AnalysisError(f"the characteristic polynomial has degree {degree} > "
                                f"{MAX_POLYNOMIAL_DEGREE}", entry="stability_map")
        return poly, None
    except (DynSymError, TypeError, ValueError, ArithmeticError, RuntimeError) as err:
        if required or 'vanishes identically' in str(err):
            raise
        return None, f"no characteristic polynomial ({err}): eigenvalues of the matrices"


def _lienard_chipart(linear, note):
    r"""The conditions (each ``> 0``) of asymptotic stability: those of the
    asymptotically stable case of the stability service's verdict."""
    try:
        case = _exact_verdict(linear).case('asymptotically stable')
    except (DynSymError, ArithmeticError, ValueError, TypeError, RuntimeError) as err:
        return None, f"no Lienard-Chipart conditions ({err})"
    if case is None:
        return None, "no Lienard-Chipart conditions (never asymptotically stable)"
    return ([] if case.region() == [[]] else case.conditions() or None), note


def _exact_verdict(linear):
    # every variable: the map's eigenvalues are those of the whole system
    return linear.stability(with_respect_to=linear.variables())


def _spectrum_classes(linear, note):
    r"""The exact regions of the classes: the cases of the stability
    service's verdict."""
    try:
        verdict = _exact_verdict(linear)
    except (DynSymError, ArithmeticError, ValueError, TypeError, ZeroDivisionError) as err:
        return None, f"no exact classes ({err})"
    classes = {2: [], 1: []}
    for case in verdict.cases():
        kind = 2 if case.verdict() == 'asymptotically stable' else \
            1 if case.verdict() != 'unstable' else None
        if kind is not None:
            classes[kind] += case.region() or []
    return classes, note


# ---------------------------------------------------------------------------
# the result
# ---------------------------------------------------------------------------

#: Colours of the classes (2, 1, 0) and of the points where the system is
#: not defined, and their names.
CLASS_COLOURS = {2: '#b6e3b6', 1: '#9fc5e8', 0: '#f4cccc', -1: '#dddddd'}
CLASS_NAMES = {2: 'asymptotically stable', 1: 'stable in first approximation', 0: 'unstable',
               -1: 'not defined'}

class StabilityMap(SageObject):
    r"""
    The result of :func:`stability_map`.

    The arrays (:meth:`max_real_part`, :meth:`stable`) are indexed in the
    order of the parameters: ``A[i, j]`` is at the ``i``-th value of the
    first parameter and the ``j``-th of the second. For random samples they
    are 1-D, and :meth:`axes` gives the coordinates of the samples.

    EXAMPLES: see :func:`stability_map`.

    TESTS:

    Maps have no value equality (they hold NumPy arrays), so the pickling
    test is skipped; the counts of the classes add up::

        sage: from sage_dynsym.analysis.linear import LinearSystem
        sage: from sage_dynsym.scale import stability_map
        sage: x, y, c = var('x y c')
        sage: S = stability_map(LinearSystem([x, y], J=[[0, 1], [-1, -c]]), {c: (-1, 1, 5)},
        ....:                   client=False)
        sage: TestSuite(S).run(skip='_test_pickling')
        sage: R = stability_map(LinearSystem([x], J=[[1/c]]), {c: (-1, 1)}, samples=7, client=False)
        sage: TestSuite(R).run(skip='_test_pickling')
    """

    def __init__(self, points, alpha, stable, fixed, method, tol, conditions=None, note=None,
                 name=None, classes=None, exact_classes=None, marginal_tol=1e-7, at=None):
        result_arrays(points, [alpha, stable], 'StabilityMap')
        self._points, self._alpha, self._stable = points, alpha, stable
        self._fixed, self._method, self._tol = dict(fixed), method, tol
        self._conditions, self._note, self._name = conditions, note, name
        self._classes = classes
        self._exact_classes, self._marginal_tol = exact_classes, marginal_tol
        self._at = dict(at or {})       # the point of linearization, where not 0

    def _repr_(self):
        names = ', '.join(map(str, self._points.keys))
        share = 100 * self._stable.mean() if self._stable.size else 0
        where = (' x '.join(map(str, self._points.shape)) + " points" if self._points.is_grid()
                 else f"{self._points.size} random points")
        text = f"Stability map of {where} in ({names}): {share:.1f}% asymptotically stable"
        marginal = (self.classes() == 1).mean() if self._stable.size else 0
        if marginal:
            text += f", {100 * marginal:.1f}% stable in first approximation"
        return text

    def _test_counts(self, **options):
        r"""The arrays have the shape of the points, every point has one
        class (the counts add up to the number of points), the stable
        points are those of class 2, with a negative largest real part, and
        the points where the system is not defined are those of class -1.

        EXAMPLES: run by ``TestSuite`` (see the class).
        """
        tester = self._tester(**options)
        classes, alpha = self.classes(), self._alpha
        for array in (alpha, self._stable, classes):
            tester.assertEqual(array.shape, self._stable.shape)
        tester.assertEqual(self._stable.size, self._points.size)
        counts = {k: int((classes == k).sum()) for k in (-1, 0, 1, 2)}
        tester.assertEqual(sum(counts.values()), self._points.size)
        tester.assertTrue((self._stable == (classes == 2)).all())
        tester.assertTrue((alpha[classes == 2] < 0).all())
        tester.assertTrue((~np.isfinite(alpha) == (classes == -1)).all())
        for axis in self.axes().values():
            tester.assertIn(len(axis), self._points.shape if self.is_grid() else [self._points.size])

    def parameters(self):
        r"""The parameters (symbols), in the order of the array indices.

        EXAMPLES::

            sage: from sage_dynsym.analysis.linear import LinearSystem
            sage: from sage_dynsym.scale import stability_map
            sage: a, b = var('a b')
            sage: S = stability_map(LinearSystem([var('x')], J=[[a - b]]), {b: (0, 1, 3), a: (0, 1, 2)},
            ....:                   client=False)
            sage: S.parameters(), S.stable()
            ([b, a],
             array([[False, False],
                    [ True, False],
                    [ True, False]]))
        """
        return list(self._points.keys)

    def is_grid(self):
        r"""Whether the points form a grid (else random samples).

        EXAMPLES::

            sage: from sage_dynsym.analysis.linear import LinearSystem
            sage: from sage_dynsym.scale import stability_map
            sage: a = var('a')
            sage: stability_map(LinearSystem([var('x')], J=[[a]]), {a: (-1, 1)}, samples=5,
            ....:               client=False).is_grid()
            False
        """
        return self._points.is_grid()

    def axes(self):
        r"""
        Dict ``{symbol: 1-D array}``: the values of each parameter along its
        axis; for random samples, the coordinates of the samples.

        EXAMPLES::

            sage: from sage_dynsym.analysis.linear import LinearSystem
            sage: from sage_dynsym.scale import stability_map
            sage: a = var('a')
            sage: stability_map(LinearSystem([var('x')], J=[[a]]), {a: (-1, 1, 5)}, client=False).axes()
            {a: array([-1. , -0.5,  0. ,  0.5,  1. ])}
        """
        if self._points.is_grid():
            columns = self._points.axes()
        else:
            columns = chunk_points(self._points.layout, 0, self._points.size)
        return dict(zip(self._points.keys, columns))

    def max_real_part(self):
        r"""The largest real part of the characteristic roots at each point
        (``nan`` where the system is not defined).

        EXAMPLES::

            sage: from sage_dynsym.analysis.linear import LinearSystem
            sage: from sage_dynsym.scale import stability_map
            sage: a = var('a')
            sage: S = stability_map(LinearSystem([var('x')], J=[[1/a]]), {a: (-1, 1, 3)}, client=False)
            sage: S.max_real_part()
            array([-1., nan,  1.])
        """
        return self._alpha

    def stable(self):
        r"""Boolean array: asymptotically stable in the first approximation.

        EXAMPLES::

            sage: from sage_dynsym.analysis.linear import LinearSystem
            sage: from sage_dynsym.scale import stability_map
            sage: a = var('a')
            sage: stability_map(LinearSystem([var('x')], J=[[a]]), {a: (-1, 1, 3)}, client=False).stable()
            array([ True, False, False])
        """
        return self._stable

    def classes(self):
        r"""
        The class of each point, an integer array: ``2`` asymptotically
        stable (where :meth:`stable` is true), ``1`` stable in first
        approximation (the roots of largest real part on the imaginary
        axis, within the tolerances), ``0`` unstable, ``-1`` where the
        system is not defined.

        EXAMPLES: `\dot x = y`, `\dot y = -x - cy` for `c = -1, 0, 1`::

            sage: from sage_dynsym.analysis.linear import LinearSystem
            sage: from sage_dynsym.scale import stability_map
            sage: c = var('c')
            sage: S = stability_map(LinearSystem([var('x'), var('y')], J=[[0, 1], [-1, -c]]),
            ....:                   {c: (-1, 1, 3)}, client=False)
            sage: S.classes(), S.stable()
            (array([0, 1, 2], dtype=int8), array([False, False,  True]))
        """
        if self._classes is None:       # a map made without them: from the verdict alone
            return np.where(self._stable, 2, np.where(np.isfinite(self._alpha),
                                                      np.where(self._alpha > 0, 0, 1), -1)
                            ).astype(np.int8)
        return self._classes

    def exact_classes(self, regions=None):
        r"""
        The classes of exact conditions at the points of the map (an
        integer array of the map's shape, ``2``, ``1``, ``0`` as in
        :meth:`classes`; ``-1`` on a boundary: where an expression of the
        regions' relations vanishes, to `10^{-9}` of its largest value on
        the map).

        INPUT: ``regions`` -- (default: those of the map) a dict ``{2:
        region, 1: region}`` (each region a list of alternatives, as for
        :meth:`exact`), or a :class:`~sage_dynsym.analysis.verdict.StabilityVerdict`
        (its cases: asymptotically stable is ``2``; stable, stable in first
        approximation and undecided ``1``; unstable ``0``)

        EXAMPLES::

            sage: from sage_dynsym.analysis.linear import LinearSystem
            sage: from sage_dynsym.scale import stability_map
            sage: c = var('c')
            sage: S = stability_map(LinearSystem([var('x'), var('y')], J=[[0, 1], [-1, -c]]),
            ....:                   {c: (-1, 1, 5)}, client=False)
            sage: S.exact_classes({2: [[c > 0]], 1: [[c == 0]]})
            array([ 0,  0, -1,  2,  2], dtype=int8)
        """
        regions = self._exact_classes if regions is None else regions
        if regions is None:
            raise AnalysisError("no exact classes: give them (a dict {2: region, 1: region} "
                                "or a stability verdict), or map with classes='spectrum'",
                                entry="StabilityMap")
        regions = _class_regions(regions)
        result = np.zeros(self._points.shape, dtype=np.int8)
        for k in (1, 2):
            if regions.get(k):
                result[self.exact(regions[k])] = k
        relations = [r for k in (1, 2) for alt in regions.get(k, []) for r in alt]
        if relations:
            values = self._values([SR(r.lhs() - r.rhs()).subs(self._fixed) for r in relations])
            for f in values:
                with np.errstate(invalid='ignore'):
                    scale = 1 + np.nanmax(np.abs(f)) if np.isfinite(f).any() else 1
                    result[np.abs(f) <= 1e-9 * scale] = -1
        return result

    def _values(self, expressions):
        r"""The values of expressions of the parameters at the points (arrays
        of the map's shape)."""
        program = compile_expressions(expressions, self._points.keys,
                                      entry="StabilityMap.exact_classes")
        out = [np.empty(self._points.size) for _ in expressions]
        for a, b in chunks(self._points.size, CHUNK):
            for o, v in zip(out, run_program(program, chunk_points(self._points.layout, a, b),
                                             b - a)):
                o[a:b] = v
        return [o.reshape(self._points.shape) for o in out]

    def fixed(self):
        r"""The values of the other symbols, a dict.

        EXAMPLES::

            sage: from sage_dynsym.analysis.linear import LinearSystem
            sage: from sage_dynsym.scale import stability_map
            sage: a, b = var('a b')
            sage: stability_map(LinearSystem([var('x')], J=[[a - b]]), {a: (-1, 1, 3)}, {b: 0.5},
            ....:               client=False).fixed()
            {b: 1/2}
        """
        return dict(self._fixed)

    def method(self):
        r"""``'polynomial'`` or ``'eigvals'`` (see :mod:`sage_dynsym.scale.maps`).

        EXAMPLES::

            sage: from sage_dynsym.analysis.linear import LinearSystem
            sage: from sage_dynsym.scale import stability_map
            sage: a = var('a')
            sage: stability_map(LinearSystem([var('x')], J=[[a]]), {a: (-1, 1, 3)}, client=False,
            ....:               method='eigvals').method()
            'eigvals'
        """
        return self._method

    def conditions(self):
        r"""The exact conditions given to (or derived by) :func:`stability_map`,
        or ``None``.

        EXAMPLES::

            sage: from sage_dynsym.analysis.linear import LinearSystem
            sage: from sage_dynsym.scale import stability_map
            sage: a, b = var('a b')
            sage: S = stability_map(LinearSystem([var('x'), var('y')], J=[[0, 1], [-a, -b]]),
            ....:                   {a: (-1, 1, 3), b: (-1, 1, 3)}, client=False,
            ....:                   conditions='lienard-chipart')
            sage: S.conditions()
            [a, b]
        """
        return None if self._conditions is None else list(self._conditions)

    def note(self):
        r"""A remark on how the map was computed, or ``None``.

        EXAMPLES::

            sage: from sage_dynsym.analysis.linear import LinearSystem
            sage: from sage_dynsym.scale import stability_map
            sage: a = var('a')
            sage: print(stability_map(LinearSystem([var('x')], J=[[a]]), {a: (-1, 1, 3)},
            ....:                     client=False).note())
            None
        """
        return self._note

    def exact(self, conditions=None):
        r"""
        The verdict of exact conditions at the points of the map (a boolean
        array of the map's shape).

        INPUT: ``conditions`` -- (default: those of the map) a list of
        expressions (each meaning ``> 0``, as returned by
        :func:`~sage_dynsym.analysis.hurwitz.lienard_chipart_conditions`) or
        relationals, all to hold (an empty list always holds); or a list of
        alternatives, each such a list (as returned by
        ``stability_region``), one of which must hold. The fixed values are
        substituted; the conditions must not contain other symbols.

        EXAMPLES::

            sage: from sage_dynsym.analysis.linear import LinearSystem
            sage: from sage_dynsym.scale import stability_map
            sage: a = var('a')
            sage: S = stability_map(LinearSystem([var('x')], J=[[a]]), {a: (-1, 1, 3)}, client=False)
            sage: S.exact([-a]), S.exact([[a < -1/2], [a > 1/2]]), S.exact([])
            (array([ True, False, False]), array([ True, False,  True]), array([ True,  True,  True]))
        """
        if conditions is None:
            conditions = self._conditions
        if conditions is None:
            raise AnalysisError("no conditions: give them (e.g. from "
                                "lienard_chipart_conditions)", entry="StabilityMap")
        alternatives, program = _compiled_conditions(conditions, self._fixed, self._points.keys,
                                                     "StabilityMap.exact")
        result = np.empty(self._points.size, dtype=bool)
        for a, b in chunks(self._points.size, CHUNK):
            result[a:b] = _holds(program, alternatives, chunk_points(self._points.layout, a, b),
                                 b - a)
        return result.reshape(self._points.shape)

    def agreement(self, conditions=None, band=0, by_class=False):
        r"""
        The share of the points where the numerical verdict agrees with
        exact conditions (see :meth:`exact`), among the points where the
        system is defined; with ``by_class=True``, for each class of
        :meth:`classes`, the share of the points of that exact class
        (:meth:`exact_classes`) where the map has the same class.

        INPUT:

        - ``conditions`` -- as for :meth:`exact`; with ``by_class``, as for
          :meth:`exact_classes`
        - ``band`` -- (default: 0) for a grid, leave out the points within
          ``band`` grid steps (along every axis) of a point where the exact
          verdict (or class) changes: a band of that width along the
          boundary
        - ``by_class`` -- (default: ``False``) per class: a dict ``{0: share,
          1: share, 2: share}`` (``nan`` for a class with no point)

        EXAMPLES: `\dot x = (a - b^2) x` is stable for `a < b^2`::

            sage: from sage_dynsym.analysis.linear import LinearSystem
            sage: from sage_dynsym.scale import stability_map
            sage: a, b = var('a b')
            sage: S = stability_map(LinearSystem([var('x')], J=[[a - b^2]]),
            ....:                   {a: (-1, 1, 41), b: (-1, 1, 41)}, client=False)
            sage: S.agreement([b^2 - a]), S.agreement([b - a])     # the second is wrong
            (1.0, 0.75...)
            sage: S.agreement([b - a], band=20)
            1.0

        Per class, against the verdict of
        :func:`~sage_dynsym.analysis.kelvin_chetaev.kelvin_chetaev`: an
        oscillator `\ddot x + c\dot x + kx = 0`::

            sage: from sage_dynsym.analysis import kelvin_chetaev
            sage: c, k = var('c k')
            sage: S = stability_map(LinearSystem([var('x')], M=[[1]], S=[[c]], W=[[k]]),
            ....:                   {c: (-1, 1, 21), k: (-1, 1, 21)}, client=False)
            sage: v = kelvin_chetaev(matrix([[1]]), matrix([[c]]), matrix([[0]]), matrix([[k]]))
            sage: S.agreement(v, by_class=True, band=1)
            {0: 1.0, 1: nan, 2: 1.0}

        (the exact verdict is stable, not asymptotically, only on the lines
        `c = 0` and `k = 0`: no point of class ``1`` is off the band.)
        """
        if by_class:
            return self._class_agreement(conditions, band)
        exact = self.exact(conditions)
        considered = np.isfinite(self._alpha)
        if band:
            if not self._points.is_grid():
                raise AnalysisError("band= needs a grid (the map has random samples)",
                                    entry="StabilityMap.agreement")
            considered &= ~_near_change(exact, int(band))
        if not considered.any():
            return float('nan')
        return float((exact == self._stable)[considered].mean())

    def _class_agreement(self, regions, band):
        exact = self.exact_classes(regions)
        considered = np.isfinite(self._alpha) & (exact >= 0)
        if band:
            if not self._points.is_grid():
                raise AnalysisError("band= needs a grid (the map has random samples)",
                                    entry="StabilityMap.agreement")
            for k in (0, 1, 2):
                considered &= ~_near_change(exact == k, int(band))
        found = {}
        for k in (0, 1, 2):
            inside = considered & (exact == k)
            found[k] = float((self.classes()[inside] == k).mean()) if inside.any() \
                else float('nan')
        return found

    def plot(self, conditions=None, section=None, **options):
        r"""
        The map in its three classes, with a legend: asymptotically stable
        points green, stable in first approximation blue, unstable red,
        undefined grey; the boundary of the region of exact conditions
        (given here or to :func:`stability_map`) drawn over it.

        INPUT:

        - ``conditions`` -- as for :meth:`exact` (default: the map's)
        - ``section`` -- for a map of more than two parameters, a dict
          ``{symbol: value}`` fixing all but two of them (the nearest grid
          value is taken)
        - ``options`` -- graphics options (e.g. ``figsize``, ``title``)

        OUTPUT: a Sage graphics object (a line of the largest real part
        for one parameter)

        EXAMPLES::

            sage: from sage_dynsym.analysis.linear import LinearSystem
            sage: from sage_dynsym.scale import stability_map
            sage: a, b, c = var('a b c')
            sage: S = stability_map(LinearSystem([var('x')], J=[[a + b + c]]),
            ....:                   {a: (-1, 1, 5), b: (-1, 1, 5), c: (-1, 1, 3)}, client=False)
            sage: S.plot([-a - b - c], section={c: 0.4})  # long time
            Graphics object consisting of 6 graphics primitives
            sage: S.plot()
            Traceback (most recent call last):
            ...
            AnalysisError: StabilityMap.plot: a map of 3 parameters: give section={...} fixing all but two
        """
        from sage.plot.graphics import Graphics
        conditions = self._conditions if conditions is None else conditions
        keys = list(self._points.keys)
        if not self._points.is_grid():
            return self._plot_samples(keys, options)
        axes, stable, alpha = self._points.axes(), self._stable, self._alpha
        section = {SR(k) if not isinstance(k, str) else SR.var(k): v
                   for k, v in (section or {}).items()}
        index = [slice(None)] * len(keys)
        fixed = dict(self._fixed)
        for k, v in section.items():
            if k not in keys:
                raise AnalysisError(f"section: {k} is not a parameter of the map",
                                    entry="StabilityMap.plot")
            i = keys.index(k)
            index[i] = int(np.abs(axes[i] - float(v)).argmin())
            fixed[k] = SR(QQ(float(axes[i][index[i]])))
        free = [i for i in range(len(keys)) if not isinstance(index[i], int)]
        if len(free) > 2:
            raise AnalysisError(f"a map of {len(keys)} parameters: give section={{...}} fixing "
                                "all but two", entry="StabilityMap.plot")
        stable, alpha = stable[tuple(index)], alpha[tuple(index)]
        kinds = self.classes()[tuple(index)]
        title = options.pop('title', None)
        # the title as an option of the first picture (Graphics keeps it)
        title = dict(title=self._title(fixed) if title is None else title)
        G = Graphics()
        if len(free) == 1:
            G += self._plot_line(keys[free[0]], axes[free[0]], alpha, kinds,
                                 dict(options, **title))
            G.axes_labels([f"${latex(keys[free[0]])}$", r"max $\mathrm{Re}\,\lambda$"])
        else:
            # a frame with ticks, not axes through the origin
            options = dict(dict(frame=True, axes=False, ticks_integer=False), **options)
            plane = [keys[i] for i in free], [axes[i] for i in free]
            G += _class_picture(*plane[1], kinds, dict(options, **title))
            boundary = Graphics() if conditions is None else \
                _exact_boundary(conditions, fixed, *plane, options)
            G += boundary
            G += _legend(plane[1], _class_entries(kinds)
                         + ([('black', 'exact boundary')] if boundary else []))
            G.set_legend_options(**_LEGEND)
            G.axes_labels([f"${latex(k)}$" for k in plane[0]])
        G.set_aspect_ratio('automatic')
        return G

    def _title(self, fixed):
        r"""The title of the map's pictures: the system's name and the fixed
        values (the section's included)."""
        head = f"{self._name}: stability map" if self._name else "stability map"
        if self._at:
            head += " at " + ", ".join(f"${latex(k)} = {number_text(v, latex=True)}$"
                                       for k, v in self._at.items())
        if not fixed:
            return head
        values = ', '.join(f"${latex(k)} = {number_text(v, latex=True)}$" for k, v in
                           sorted(fixed.items(), key=lambda kv: str(kv[0])))
        return f"{head}\n{values}"

    def _plot_line(self, key, axis, alpha, kinds, options):
        from sage.plot.line import line
        from sage.plot.point import point
        G = line([(float(a), float(b)) for a, b in zip(axis, alpha) if np.isfinite(b)],
                 color='black', **options)
        for k in (2, 1):
            chosen = [(float(a), float(b)) for a, b, c in zip(axis, alpha, kinds) if c == k]
            if chosen:
                G += point(chosen, color=_DARK[k], size=10, legend_label=CLASS_NAMES[k])
        return G

    def _plot_samples(self, keys, options):
        from sage.plot.graphics import Graphics
        from sage.plot.point import point
        if len(keys) != 2:
            raise AnalysisError("a map of random samples is drawn in two parameters",
                                entry="StabilityMap.plot")
        n = min(self._points.size, 20000)        # enough points to see the regions
        X, Y = chunk_points(self._points.layout, 0, n)
        kinds = self.classes()[:n]
        G = Graphics()
        for k in (2, 1, 0):
            s = kinds == k
            if s.any():
                G += point(list(zip(X[s], Y[s])), color=_DARK[k], size=4,
                           legend_label=CLASS_NAMES[k], **options)
        G.axes_labels([f"${keys[0]}$", f"${keys[1]}$"])
        return G

    def save(self, path):
        r"""
        Write the map to a NumPy ``.npz`` file: ``parameters`` (names),
        ``axis_0, axis_1, ...`` (the axes, or the coordinates of the
        samples), ``max_real_part``, ``stable``, ``fixed_names``,
        ``fixed_values``. The file is replaced atomically.

        EXAMPLES::

            sage: from sage_dynsym.analysis.linear import LinearSystem
            sage: from sage_dynsym.scale import stability_map
            sage: a, b = var('a b')
            sage: S = stability_map(LinearSystem([var('x')], J=[[a - b]]), {a: (-1, 1, 3)}, {b: 0},
            ....:                   client=False)
            sage: path = tmp_filename(ext='.npz'); S.save(path)
            sage: import numpy as np
            sage: data = np.load(path); data['parameters'], data['stable'], data['fixed_values']
            (array(['a'], dtype='<U1'), array([ True, False, False]), array([0.]))
        """
        arrays = {f"axis_{i}": a for i, a in enumerate(self.axes().values())}
        arrays.update(parameters=np.array([str(k) for k in self._points.keys]),
                      max_real_part=self._alpha, stable=self._stable, classes=self.classes(),
                      fixed_names=np.array([str(k) for k in self._fixed], dtype=str),
                      fixed_values=np.array([float(v) for v in self._fixed.values()]))
        write_atomically(path, lambda stream: np.savez_compressed(stream, **arrays), binary=True)


#: Darker colours of the classes, for points and lines.
_DARK = {2: 'green', 1: 'blue', 0: 'red', -1: 'grey'}


def class_plot(X, Y, classes, options=None):
    r"""
    A picture of stability classes on a grid (``classes[i, j]`` at
    ``X[i], Y[j]``; ``2``, ``1``, ``0``, ``-1`` as in
    :meth:`StabilityMap.classes`), with a legend of the classes present;
    also for the results of a :func:`~sage_dynsym.scale.sweeps.sweep`.

    EXAMPLES::

        sage: from sage_dynsym.scale.maps import class_plot
        sage: import numpy as np
        sage: X = Y = np.linspace(0, 1, 3)
        sage: class_plot(X, Y, np.array([[2, 2, 1], [2, 1, 0], [1, 0, 0]]))
        Graphics object consisting of 4 graphics primitives
    """
    kinds = np.asarray(classes)
    G = _class_picture(X, Y, kinds, dict(options or {}))
    G += _legend((X, Y), _class_entries(kinds))
    G.set_legend_options(**_LEGEND)
    return G


def _class_picture(X, Y, kinds, options):
    from matplotlib.colors import ListedColormap
    from sage.plot.matrix_plot import matrix_plot
    colours = ListedColormap([CLASS_COLOURS[k] for k in (-1, 0, 1, 2)])
    return matrix_plot((np.asarray(kinds).T + 1).astype(float), xrange=_extent(X),
                       yrange=_extent(Y), flip_y=False, cmap=colours, vmin=0, vmax=3, **options)


def _class_entries(kinds):
    r"""Legend entries (colour, name) of the classes present."""
    return [(CLASS_COLOURS[k], CLASS_NAMES[k]) for k in (2, 1, 0, -1) if (kinds == k).any()]


#: Where the legend of a plane picture goes: outside the box, on the right.
_LEGEND = dict(loc='upper left', bbox_to_anchor=(1.02, 1), borderaxespad=0, font_size='small')


def _class_regions(regions):
    r"""``{2: region, 1: region}`` from a dict or a stability verdict."""
    if isinstance(regions, dict):
        unknown = [k for k in regions if k not in (1, 2)]
        if unknown:
            raise AnalysisError(f"the classes with exact regions are 2 and 1, got {unknown}",
                                entry="StabilityMap")
        return {k: [list(alt) for alt in v] for k, v in regions.items()}
    if hasattr(regions, 'cases') and hasattr(regions, 'verdict'):
        found = {2: [], 1: []}
        for case in regions.cases():
            k = {'asymptotically stable': 2, 'stable': 1, 'stable in first approximation': 1,
                 'undecided': 1}.get(case.verdict())
            if k is not None:
                if case.region() is None:
                    raise AnalysisError(f"the case {case.verdict()} has no region",
                                        entry="StabilityMap")
                found[k] += [list(alt) for alt in case.region()]
        return found
    raise AnalysisError(f"expected a dict {{2: region, 1: region}} or a stability verdict, got "
                        f"{regions!r}", entry="StabilityMap")


def _legend(axes, entries):
    r"""Legend entries (colour, label) for a plane picture: lines of no
    length at a corner of the box, seen only in the legend (a thick stroke
    for a colour of the map, a thin one for a boundary)."""
    from sage.plot.graphics import Graphics
    from sage.plot.line import line
    corner = (float(axes[0][0]), float(axes[1][0]))
    G = Graphics()
    for colour, label in entries:
        G += line([corner, corner], color=colour, legend_label=label,
                  thickness=1.5 if colour == 'black' else 10)
    return G


def _compiled_conditions(conditions, fixed, keys, entry):
    r"""The alternatives of ``conditions`` (a list of lists of relationals,
    the fixed values substituted) and their relations compiled in ``keys``."""
    conditions = list(conditions)
    if conditions and all(isinstance(c, (list, tuple)) for c in conditions):
        alternatives = [[as_relational(SR(c).subs(fixed)) for c in alt] for alt in conditions]
    else:
        alternatives = [[as_relational(SR(c).subs(fixed)) for c in conditions]]
    flat = [c for alt in alternatives for c in alt]
    return alternatives, compile_expressions(flat, keys, entry=entry)


def _holds(program, alternatives, inputs, size):
    r"""Where one of the alternatives holds, at ``size`` points (``inputs``
    one array per key of the compiled program)."""
    held = iter(run_program(program, inputs, size))
    verdict = np.zeros(size, dtype=bool)
    for alt in alternatives:
        ok = np.ones(size, dtype=bool)
        for _ in alt:
            ok &= next(held)
        verdict |= ok
    return verdict


def _extent(axis):
    step = (axis[-1] - axis[0]) / (len(axis) - 1) if len(axis) > 1 else 1.0
    return float(axis[0] - step / 2), float(axis[-1] + step / 2)


def _near_change(exact, band):
    r"""Points within ``band`` steps (a box) of a point with the other verdict."""
    hi, lo = exact.copy(), exact.copy()
    for axis in range(exact.ndim):
        for _ in range(band):
            hi, lo = _shift(hi, axis, np.maximum), _shift(lo, axis, np.minimum)
    return hi != lo


def _shift(a, axis, combine):
    # one step of a box filter along ``axis``: combine with both neighbours
    out = a.copy()
    front = [slice(None)] * a.ndim
    back = [slice(None)] * a.ndim
    front[axis], back[axis] = slice(1, None), slice(None, -1)
    out[tuple(front)] = combine(out[tuple(front)], a[tuple(back)])
    out[tuple(back)] = combine(out[tuple(back)], a[tuple(front)])
    return out


#: Points per axis of the grid on which the exact region is drawn.
BOUNDARY_POINTS = 600

#: The options of a contour primitive (``ContourPlot``) that the boundary
#: takes from the caller's, and the defaults ``contour_plot`` would give it.
_CONTOUR_OPTIONS = ('linewidths', 'linestyles', 'zorder')
_CONTOUR_DEFAULTS = dict(
    fill=False, contours=[0.5], cmap=['black'], linewidths=None, linestyles=None, labels=False,
    colorbar=False, legend_label=None,
    colorbar_options=dict(orientation='vertical', format=None, spacing='uniform'),
    label_options=dict(fontsize=9, colors='blue', inline=True, inline_spacing=3, fmt="%1.2f"))


def _exact_boundary(conditions, fixed, keys, axes, options):
    r"""
    The boundary of the region where the exact ``conditions`` hold, in the
    plane of ``keys`` (``fixed`` the other values): the level 1/2 of its
    indicator on a fine grid, so that only the boundary of the union of the
    alternatives is drawn -- never a line between two alternatives, nor a
    line where the conditions hold (or fail) on both sides. Empty when the
    boundary does not cross the plotted box.
    """
    from sage.plot.contour_plot import ContourPlot
    from sage.plot.graphics import Graphics
    (x, y), (X, Y) = keys, axes
    alternatives, program = _compiled_conditions(conditions, fixed, [x, y],
                                                 "StabilityMap.plot")
    n = BOUNDARY_POINTS
    xs = np.linspace(float(X[0]), float(X[-1]), n)
    ys = np.linspace(float(Y[0]), float(Y[-1]), n)
    gx, gy = np.meshgrid(xs, ys, indexing='ij')
    inside = _holds(program, alternatives, [gx.ravel(), gy.ravel()], n * n).reshape(n, n)
    if inside.all() or not inside.any():
        return Graphics()
    # The indicator is already on the grid: it goes to the contour primitive
    # as data (rows along y), not through contour_plot, which would call a
    # Python function at each of the n^2 points again.
    settings = dict(_CONTOUR_DEFAULTS, plot_points=n)
    settings.update((key, options[key]) for key in _CONTOUR_OPTIONS if key in options)
    boundary = Graphics()
    boundary.add_primitive(ContourPlot(inside.T.astype(float), (xs[0], xs[-1]),
                                       (ys[0], ys[-1]), settings))
    return boundary
