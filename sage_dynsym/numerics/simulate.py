r"""
Numerical integration of equations of motion

:func:`simulate` integrates the compiled right-hand side of a record of
:mod:`sage_dynsym.analysis.motion` (see :mod:`~sage_dynsym.numerics.rhs`)
with SciPy's ``solve_ivp`` and returns a
:class:`~sage_dynsym.numerics.trajectory.Trajectory` of ``points`` samples
from ``t0`` to ``t_end``, both included.

- ``method='auto'`` (or ``'nonstiff'``) uses the explicit Runge--Kutta
  method of order 8 ``DOP853``; ``method='stiff'`` uses the implicit
  ``Radau``; any method name of ``solve_ivp`` (``'RK45'``, ``'LSODA'``,
  ``'BDF'``, ...) is passed on.
- The default tolerances (``rtol=1e-10``, ``atol=1e-12``) keep the energy of
  conservative systems to about `10^{-9}` relative over many periods.
- Holonomic constraints `f(q, t) = 0` are kept by projection: the solution
  is integrated from sample to sample and at each sample the coordinates
  are projected onto `f = 0` (Gauss--Newton, minimum-norm steps) and the
  velocities onto `J \dot q + \partial f/\partial t = 0`.
- When the integration lasts more than a few seconds the progress is
  reported through :func:`sage.misc.verbose.verbose` (level
  1) and the logger ``sage_dynsym.numerics``. An interruption (Ctrl-C)
  propagates as ``KeyboardInterrupt``; nothing is left half-built.

EXAMPLES: the harmonic oscillator::

    sage: from sage_dynsym.analysis.motion import SecondOrderEquations
    sage: from sage_dynsym.numerics.simulate import simulate
    sage: x, dx, ddx, k = var('x dx ddx k')
    sage: E = SecondOrderEquations([ddx + k*x], [x], [dx], [ddx])
    sage: T = simulate(E, {k: 4}, {x: 1, dx: 0}, pi, points=3); T
    Trajectory in (x, dx): 3 samples, t from 0.0 to 3.141592653589793
    sage: T.values(x).round(9)
    array([ 1., -1.,  1.])
"""
import logging
import time

import numpy as np

from sage.misc.verbose import verbose
from sage.symbolic.ring import SR

from ..errors import ModelError, AnalysisError
from ..symbols import t as _t
from .form import as_form
from .rhs import RightHandSide, real_number
from .trajectory import Trajectory

_LOG = logging.getLogger('sage_dynsym.numerics')
_METHODS = {'auto': 'DOP853', 'nonstiff': 'DOP853', 'stiff': 'Radau'}
_SCIPY = ('RK45', 'RK23', 'DOP853', 'Radau', 'BDF', 'LSODA')
#: seconds after which the progress is reported
_REPORT_AFTER = 3.0


def initial_state(form, initial):
    r"""
    The initial state of ``form`` (a NumPy array) from the dict
    ``initial`` over its state variables (symbols or names).

    EXAMPLES::

        sage: from sage_dynsym.analysis.motion import SecondOrderEquations
        sage: from sage_dynsym.numerics.form import NumericalForm
        sage: from sage_dynsym.numerics.simulate import initial_state
        sage: x, dx, ddx = var('x dx ddx')
        sage: N = NumericalForm(SecondOrderEquations([ddx + x], [x], [dx], [ddx]))
        sage: initial_state(N, {x: 1/2, 'dx': 0})
        array([0.5, 0. ])

    TESTS::

        sage: initial_state(N, {x: 1})
        Traceback (most recent call last):
        ...
        ModelError: initial: missing initial values of dx (the state is x, dx)
        sage: initial_state(N, {x: 1, dx: 0, 'y': 2})
        Traceback (most recent call last):
        ...
        ModelError: initial: y is not a state variable (the state is x, dx)
    """
    state = form.state()
    described = f"(the state is {', '.join(map(str, state))})"
    if not isinstance(initial, dict):
        raise ModelError(f"initial must be a dict over the state variables {described}",
                         entry="initial")
    by_name = {str(k): v for k, v in initial.items()}
    unknown = [k for k in by_name if k not in {str(v) for v in state}]
    if unknown:
        raise ModelError(f"{', '.join(unknown)} {'is' if len(unknown) == 1 else 'are'} not a "
                         f"state variable {described}", entry="initial")
    missing = [str(v) for v in state if str(v) not in by_name]
    if missing:
        raise ModelError(f"missing initial values of {', '.join(missing)} {described}",
                         entry="initial")
    return np.array([real_number(by_name[str(v)], str(v), entry="initial") for v in state])


class _Projection:
    """Projection of a state onto the constraints and their derivative."""

    def __init__(self, form, values):
        from .compiler import python_function
        f, J, f_t = form.constraints()
        self._n, self._m = len(form.state()) // 2, len(f)
        q = form.state()[:self._n]
        exprs = [SR(e).subs(values) for e in f + [a for row in J for a in row] + f_t]
        self._evaluate = python_function(exprs, [_t] + q, entry="constraints")

    def _blocks(self, t, q):
        n, m = self._n, self._m
        v = np.array(self._evaluate(t, *q))
        return v[:m], v[m:m + m * n].reshape(m, n), v[m + m * n:]

    def __call__(self, t, x):
        n = self._n
        q, dq = x[:n].copy(), x[n:].copy()
        for _ in range(50):
            f, J, _ = self._blocks(t, q)
            if np.max(np.abs(f)) <= 1e-14 * max(1.0, np.max(np.abs(q))):
                break
            q -= J.T @ np.linalg.solve(J @ J.T, f)
        else:
            raise AnalysisError(f"cannot project the state at t = {t} onto the constraints",
                                entry="simulate")
        f, J, f_t = self._blocks(t, q)
        dq -= J.T @ np.linalg.solve(J @ J.T, J @ dq + f_t)
        return np.concatenate([q, dq])


class _Progress:
    """The right-hand side, reporting the progress of long integrations."""

    def __init__(self, rhs, t0, t_end):
        self._rhs, self._t0, self._span = rhs, t0, t_end - t0
        self._calls, self._start = 0, time.monotonic()
        self._last = self._start

    def __call__(self, t, x):
        self._calls += 1
        if not self._calls % 2000:
            now = time.monotonic()
            if now - self._last > _REPORT_AFTER:
                self._last = now
                message = (f"simulate: t = {t:g} ({100 * (t - self._t0) / self._span:.0f}%) "
                           f"after {now - self._start:.1f} s, {self._calls} evaluations")
                verbose(message, level=1)
                _LOG.info(message)
        return self._rhs(t, x)


def simulate(equations, values, initial, t_end, points=101, t0=0, method='auto', rtol=1e-10,
             atol=1e-12, backend='auto', energy=None, name=None, **options):
    r"""
    The solution of ``equations`` from ``initial`` at ``t0`` to ``t_end``.

    INPUT:

    - ``equations`` -- a record of :mod:`sage_dynsym.analysis.motion`, a
      :class:`~sage_dynsym.numerics.form.NumericalForm`, a
      :class:`~sage_dynsym.numerics.recursive.RecursiveForm` or a
      :class:`~sage_dynsym.numerics.rhs.RightHandSide`
    - ``values`` -- dict of the parameter values
    - ``initial`` -- dict over the state variables (coordinates and
      velocities for second-order equations)
    - ``t_end`` -- the final time; ``t0`` (default 0) the initial time
    - ``points`` -- (default 101) number of samples, both ends included
    - ``method`` -- ``'auto'``, ``'nonstiff'``, ``'stiff'`` or a method of
      ``scipy.integrate.solve_ivp``
    - ``rtol``, ``atol`` -- tolerances of the integrator
    - ``backend`` -- of the right-hand side: ``'auto'``, ``'c'``, ``'python'``
    - ``energy`` -- (optional) a conserved energy for
      :meth:`~sage_dynsym.numerics.trajectory.Trajectory.energy_drift`, or
      a function without arguments computing it (default: the one of the
      form, computed only when the trajectory needs it)
    - ``name`` -- (optional) the model's name, for the titles of the
      trajectory's pictures
    - other keywords are passed to ``solve_ivp`` (e.g. ``max_step``)

    OUTPUT: a :class:`~sage_dynsym.numerics.trajectory.Trajectory`

    EXAMPLES: see the module documentation; a Cartesian pendulum kept on
    its circle::

        sage: from sage_dynsym.analysis.motion import SecondOrderEquations
        sage: from sage_dynsym.numerics.simulate import simulate
        sage: x, y, dx, dy, ddx, ddy, mu, g = var('x y dx dy ddx ddy mu g')
        sage: E = SecondOrderEquations([ddx - 2*mu*x, ddy + g - 2*mu*y], [x, y], [dx, dy], [ddx, ddy],
        ....:                          constraints=[x^2 + y^2 - 1], multipliers=[mu])
        sage: T = simulate(E, {g: 1}, {x: 1, y: 0, dx: 0, dy: 0}, 10, energy=(dx^2 + dy^2)/2 + g*y)
        sage: bool(max(abs(T.values(x^2 + y^2 - 1))) < 1e-12), T.energy_drift() < 1e-8
        (True, True)

    TESTS::

        sage: simulate(E, {g: 1}, {x: 1, y: 0, dx: 0, dy: 0}, 1, points=1)
        Traceback (most recent call last):
        ...
        ModelError: points: at least 2 samples are needed (both ends), got 1
        sage: simulate(E, {g: 1}, {x: 1, y: 0, dx: 0, dy: 0}, 1, method='Euler')
        Traceback (most recent call last):
        ...
        ModelError: method: 'Euler' is not one of auto, nonstiff, stiff, RK45, RK23, DOP853, Radau, BDF, LSODA
        sage: simulate(E, {g: 1}, {x: 1, y: 0, dx: 0, dy: 0}, -1)
        Traceback (most recent call last):
        ...
        ModelError: t_end: the final time must be after t0 = 0.0, got -1.0
    """
    from scipy.integrate import solve_ivp
    if isinstance(equations, RightHandSide):
        rhs, form = equations, equations.form()
    else:
        form = as_form(equations)
        rhs = RightHandSide(form, values, backend)
    # the energy is computed only if the trajectory is asked for it
    energy = form.energy if energy is None else energy
    if method not in _METHODS and method not in _SCIPY:
        raise ModelError(f"{method!r} is not one of {', '.join(list(_METHODS) + list(_SCIPY))}",
                         entry="method")
    scipy_method = _METHODS.get(method, method)
    try:
        points = int(points)
    except (TypeError, ValueError):
        raise ModelError(f"points must be an integer, got {points}", entry="points") from None
    if points < 2:
        raise ModelError(f"at least 2 samples are needed (both ends), got {points}",
                         entry="points")
    t0, t_end = real_number(t0, 't0', entry="t0"), real_number(t_end, 't_end', entry="t_end")
    if not t_end > t0:
        raise ModelError(f"the final time must be after t0 = {t0}, got {t_end}", entry="t_end")
    x = initial_state(form, initial)
    parameters = rhs.parameters()
    project = _Projection(form, parameters) if form.constraints()[0] else None
    if project is not None:
        x = project(t0, x)
    times = np.linspace(t0, t_end, points)
    states = np.empty((points, len(x)))
    states[0] = x
    progress = _Progress(rhs, t0, t_end)
    # without constraints one integration (restarts cost steps); with them
    # one per sample interval, each followed by the projection
    step = 1 if project is not None else points - 1
    dense, breaks = [], [times[0]]
    i = 0
    while i < points - 1:
        j = min(i + step, points - 1)
        solution = solve_ivp(progress, (times[i], times[j]), states[i], method=scipy_method,
                             t_eval=times[i:j + 1], rtol=rtol, atol=atol, dense_output=True,
                             **options)
        if not solution.success:
            reached = solution.t[-1] if len(solution.t) else times[i]
            raise AnalysisError(f"the integration stopped at t = {reached}: "
                                f"{solution.message}", entry="simulate")
        states[i + 1:j + 1] = solution.y.T[1:]
        dense.append(solution.sol)
        breaks.append(times[j])
        if project is not None:
            states[j] = project(times[j], states[j])
        i = j
    return Trajectory(times, states, form.state(), parameters, energy=energy,
                      method=scipy_method, dense=dense, breaks=breaks, name=name)
