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
  velocities onto `J \dot q + \partial f/\partial t = 0` and the velocity
  constraints `A\dot q + b = 0` (a rolling wheel); the trajectory reports
  what is left of every constraint along the motion
  (:meth:`~sage_dynsym.numerics.trajectory.Trajectory.constraint_residuals`).
  The initial state must lie on the constraints (positions and velocities,
  to rounding): a state off them is refused with its residuals, unless
  ``project=True`` asks for its projection (then reported by a warning).
  Constraints without a regular real point there (an empty set such as
  `x^2 + 1 = 0`, a singular one such as `(x^2 + z^2 - 1)^2 = 0`) are
  refused before integrating.
- Sizes are checked before anything is allocated or integrated: at most
  :data:`MAX_POINTS` samples (``max_points=`` raises it) and at most
  :data:`MAX_EVALUATIONS` evaluations of the right-hand side
  (``max_evaluations=``): an integration that needs more (a final time far
  beyond the time scale of the motion, a stiff system integrated by an
  explicit method) stops with an error saying how far it got.
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
import warnings

import numpy as np

from sage.misc.verbose import verbose
from sage.symbolic.ring import SR

from ..errors import DynSymError, ModelError, AnalysisError
from ..arguments import choice, count, finite_real, flag
from ..symbols import t as _t
from .form import as_form
from .rhs import RightHandSide, StateJacobian, real_number
from .trajectory import Trajectory

__all__ = ['MAX_POINTS', 'MAX_EVALUATIONS', 'CONSTRAINT_TOLERANCE', 'initial_state', 'simulate']

_LOG = logging.getLogger('sage_dynsym.numerics')
_METHODS = {'auto': 'DOP853', 'nonstiff': 'DOP853', 'stiff': 'Radau'}
_SCIPY = ('RK45', 'RK23', 'DOP853', 'Radau', 'BDF', 'LSODA')
#: the methods of ``solve_ivp`` that use the Jacobian of the right-hand side
_IMPLICIT = ('Radau', 'BDF', 'LSODA')
#: the options of ``solve_ivp`` that :func:`simulate` passes on (step sizes)
_STEP_OPTIONS = ('max_step', 'first_step', 'min_step')
#: seconds after which the progress is reported
_REPORT_AFTER = 3.0
#: Most samples of a trajectory (``max_points=`` raises it): the samples
#: are stored, ``points`` times the size of the state in floats.
MAX_POINTS = 10**6
#: Most evaluations of the right-hand side in one simulation
#: (``max_evaluations=`` raises it): some twenty seconds of integration.
MAX_EVALUATIONS = 10**6
#: Residuals of the constraints below this (relative to the size of the
#: state) are rounding errors: such a state is on the constraints.
CONSTRAINT_TOLERANCE = 1e-9


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
        _, A, b = form.velocity_constraints()
        self._n, self._m, self._k = len(form.state()) // 2, len(f), len(A)
        self._state = form.state()
        q = form.state()[:self._n]
        exprs = [SR(e).subs(values) for e in f + [a for row in J + A for a in row] + f_t + b]
        self._evaluate = python_function(exprs, [_t] + q, entry="constraints")

    def _blocks(self, t, q):
        # f, the velocity rows [J; A] and their free terms [f_t; b] at (t, q);
        # nan where they have no value
        n, m, k = self._n, self._m, self._k
        rows = (m + k) * n
        try:
            v = np.array(self._evaluate(t, *q), dtype=float)
        except (ArithmeticError, ValueError, OverflowError):
            v = np.full(m + rows + m + k, np.nan)
        return v[:m], v[m:m + rows].reshape(m + k, n), v[m + rows:]

    def residuals(self, t, x):
        r"""The residuals of the constraints (positions) and of the velocity
        constraints, `J\dot q + f_t` and `A\dot q + b`, at the state ``x``,
        and whether they are rounding errors."""
        q, dq = x[:self._n], x[self._n:]
        f, G, h = self._blocks(t, q)
        velocity = G @ dq + h
        scale = np.max(np.abs(G), initial=0.0) * np.max(np.abs(dq), initial=0.0) + \
            np.max(np.abs(h), initial=0.0)
        small = (np.max(np.abs(f), initial=0.0) <= CONSTRAINT_TOLERANCE * max(1.0, np.max(
            np.abs(q), initial=0.0)) and np.max(np.abs(velocity), initial=0.0)
            <= CONSTRAINT_TOLERANCE * max(1.0, scale))
        return f, velocity, bool(small)

    def _refuse(self, t, q, why):
        where = ', '.join(f"{v} = {float(a):.6g}" for v, a in zip(self._state, q))
        return AnalysisError(f"the constraints have no regular real point near t = {t:g}, "
                             f"{where} ({why}): they are empty over the reals or singular "
                             "there", entry="constraints")

    def _solve(self, t, q, G, rhs):
        # minimum-norm step G^T (G G^T)^{-1} rhs; a rank-deficient G means
        # the constraints are not independent (singular) at q
        rank = np.linalg.matrix_rank(G) if np.isfinite(G).all() else 0
        if rank < len(G):
            raise self._refuse(t, q, f"the Jacobian of the constraints has rank {rank} < "
                                     f"{len(G)}")
        return G.T @ np.linalg.solve(G @ G.T, rhs)

    def __call__(self, t, x):
        n, m = self._n, self._m
        q, dq = x[:n].copy(), x[n:].copy()
        for _ in range(50):
            f, G, _ = self._blocks(t, q)
            if not np.isfinite(f).all():
                raise self._refuse(t, q, "the constraints have no value there")
            if not m or np.max(np.abs(f)) <= 1e-14 * max(1.0, np.max(np.abs(q))):
                break
            q -= self._solve(t, q, G[:m], f)
        else:
            raise self._refuse(t, q, "the Gauss-Newton projection does not converge")
        f, G, h = self._blocks(t, q)
        dq -= self._solve(t, q, G, G @ dq + h)
        return np.concatenate([q, dq])


class _Progress:
    """The right-hand side, reporting the progress of long integrations and
    stopping after ``limit`` evaluations."""

    def __init__(self, rhs, t0, t_end, limit):
        self._rhs, self._t0, self._t_end, self._span = rhs, t0, t_end, t_end - t0
        self._limit = limit
        self._calls, self._start = 0, time.monotonic()
        self._last = self._start

    def __call__(self, t, x):
        self._calls += 1
        if self._calls > self._limit:
            raise AnalysisError(f"the integration needed more than {self._limit} evaluations "
                                f"of the right-hand side and reached t = {t:g} of "
                                f"{self._t_end:g}; raise max_evaluations= (or shorten t_end, "
                                "or use method='stiff' for a stiff system)", entry="simulate")
        if not self._calls % 2000:
            now = time.monotonic()
            if now - self._last > _REPORT_AFTER:
                self._last = now
                message = (f"simulate: t = {t:g} ({100 * (t - self._t0) / self._span:.0f}%) "
                           f"after {now - self._start:.1f} s, {self._calls} evaluations")
                verbose(message, level=1)
                _LOG.info(message)
        return self._rhs(t, x)


def _start_on_constraints(project, t0, x, state, allow):
    r"""The initial state ``x`` on the constraints: refused with its
    residuals when it is off them, unless ``allow`` (then projected and
    reported)."""
    f, velocity, small = project.residuals(t0, x)
    if not small and not allow:
        shown = ', '.join(f"{v:.6g}" for v in f)
        moving = ', '.join(f"{v:.6g}" for v in velocity)
        raise ModelError(f"the initial state is off the constraints: residuals f = [{shown}] "
                         f"(positions), J dq + df/dt = [{moving}] (velocities); give a state "
                         "on the constraints, or project=True to project it onto them",
                         entry="initial")
    projected = project(t0, x)
    if not small:
        message = ("simulate: the initial state was projected onto the constraints: "
                   + ', '.join(f"{v} = {a:.12g} (given {b:.12g})"
                               for v, a, b in zip(state, projected, x) if a != b))
        warnings.warn(message, stacklevel=3)
        _LOG.info(message)
    return projected


def simulate(equations, values, initial, t_end, points=101, t0=0, method='auto', rtol=1e-10,
             atol=1e-12, backend='auto', energy=None, name=None, events=None, project=False,
             max_points=MAX_POINTS, max_evaluations=MAX_EVALUATIONS, **options):
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
    - ``events`` -- (optional) a list of expressions in ``t``, the state
      variables and the parameters, or of
      :class:`~sage_dynsym.numerics.events.Event` (with a direction and
      termination): their zero crossings, located to the integrator's
      tolerance, are recorded
      (:meth:`~sage_dynsym.numerics.trajectory.Trajectory.events`); after a
      terminal one the trajectory ends at the crossing, its last sample
    - ``project`` -- (default: ``False``) with constraints, project an
      initial state that is off them onto them (reported by a warning)
      instead of refusing it
    - ``max_points`` -- (default: :data:`MAX_POINTS`) the most samples
    - ``max_evaluations`` -- (default: :data:`MAX_EVALUATIONS`) the most
      evaluations of the right-hand side
    - ``max_step``, ``first_step``, ``min_step`` -- step sizes passed to
      ``solve_ivp``

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
        sage: bool(max(abs(T.constraint_residuals()[x^2 + y^2 - 1])) < 1e-12)
        True

    A point that must move along the direction of ``(1, y)`` (the velocity
    constraint `y\dot x - \dot y = 0`, not integrable), pushed along `x`::

        sage: la = var('la')
        sage: E = SecondOrderEquations([ddx - 1 - la*y, ddy + la], [x, y], [dx, dy], [ddx, ddy],
        ....:                          velocity_constraints=[y*dx - dy], velocity_multipliers=[la])
        sage: T = simulate(E, {}, {x: 0, y: 1, dx: 0, dy: 0}, 2)
        sage: residual = T.constraint_residuals()[y*dx - dy]
        sage: bool(max(abs(residual)) < 1e-10)
        True

    The oscillator crossing `x = 0` upwards, and stopped there the second
    time (its period is `\pi`)::

        sage: from sage_dynsym.numerics.events import Event
        sage: O = SecondOrderEquations([ddx + 4*x], [x], [dx], [ddx])
        sage: T = simulate(O, {}, {x: 1, dx: 0}, 10, events=[Event(x, direction=1)])
        sage: [round(t, 10) for t, k, state in T.events()]
        [2.3561944902, 5.4977871438, 8.6393797974]
        sage: T = simulate(O, {}, {x: 1, dx: 0}, 10, events=[Event(x, terminal=True)])
        sage: bool(abs(T.times()[-1] - pi/4) < 1e-10), abs(T.final_state()[x]) < 1e-12
        (True, True)

    TESTS::

        sage: E = SecondOrderEquations([ddx - 2*mu*x, ddy + g - 2*mu*y], [x, y], [dx, dy], [ddx, ddy],
        ....:                          constraints=[x^2 + y^2 - 1], multipliers=[mu])
        sage: simulate(E, {g: 1}, {x: 1, y: 0, dx: 0, dy: 0}, 1, points=1)
        Traceback (most recent call last):
        ...
        ModelError: points: expected at least 2 samples, got 1
        sage: simulate(E, {g: 1}, {x: 1, y: 0, dx: 0, dy: 0}, 1, method='Euler')
        Traceback (most recent call last):
        ...
        ModelError: method: 'Euler' is not one of auto, nonstiff, stiff, RK45, RK23, DOP853, Radau, BDF, LSODA
        sage: simulate(E, {g: 1}, {x: 1, y: 0, dx: 0, dy: 0}, -1)
        Traceback (most recent call last):
        ...
        ModelError: t_end: the final time must be after t0 = 0.0, got -1.0
        sage: simulate(E, {g: 1}, {x: 1, y: 0, dx: 0, dy: 0}, 1, points=float(2.9))
        Traceback (most recent call last):
        ...
        ModelError: points: expected an integer, got 2.9 (float)
        sage: simulate(E, {g: 1}, {x: 1, y: 0, dx: 0, dy: 0}, 1, points=10^9)
        Traceback (most recent call last):
        ...
        ModelError: points: 1000000000 samples are more than the limit of 1000000; raise it with max_points= if that is what you want
        sage: simulate(E, {g: 1}, {x: 1, y: 0, dx: 0, dy: 0}, 1, rtol=-1)
        Traceback (most recent call last):
        ...
        ModelError: rtol: the value of rtol must be greater than 0, got -1
        sage: simulate(E, {g: 1}, {x: 1, y: 0, dx: 0, dy: 0}, 10^12, points=2, max_evaluations=1000)
        Traceback (most recent call last):
        ...
        AnalysisError: simulate: the integration needed more than 1000 evaluations of the right-hand side and reached t = ... of 1e+12; raise max_evaluations= (or shorten t_end, or use method='stiff' for a stiff system)

    An initial state off the constraints is refused, or projected on
    request::

        sage: simulate(E, {g: 1}, {x: 2, y: 0, dx: 0, dy: 1}, 1)
        Traceback (most recent call last):
        ...
        ModelError: initial: the initial state is off the constraints: residuals f = [3] (positions), J dq + df/dt = [0] (velocities); give a state on the constraints, or project=True to project it onto them
        sage: T = simulate(E, {g: 1}, {x: 2, y: 0, dx: 0, dy: 1}, 1, project=True)
        doctest:warning...
        UserWarning: simulate: the initial state was projected onto the constraints: x = 1 (given 2)
        sage: bool(abs(T.values(x)[0] - 1) < 1e-14)
        True

    Constraints that have no regular real point are refused before
    integrating::

        sage: F = SecondOrderEquations([ddx - 2*mu*x, ddy + g - 2*mu*y], [x, y], [dx, dy], [ddx, ddy],
        ....:                          constraints=[x^2 + y^2 + 1], multipliers=[mu])
        sage: simulate(F, {g: 1}, {x: 1, y: 0, dx: 0, dy: 0}, 1, project=True)
        Traceback (most recent call last):
        ...
        AnalysisError: constraints: the constraints have no regular real point near t = 0, x = ..., y = ... (...): they are empty over the reals or singular there

    The velocity constraint `y\dot x - \dot y = 0` above, broken by the
    initial velocity::

        sage: N = SecondOrderEquations([ddx - 1 - la*y, ddy + la], [x, y], [dx, dy], [ddx, ddy],
        ....:                          velocity_constraints=[y*dx - dy], velocity_multipliers=[la])
        sage: simulate(N, {}, {x: 0, y: 1, dx: 0, dy: 1}, 1)
        Traceback (most recent call last):
        ...
        ModelError: initial: the initial state is off the constraints: residuals f = [] (positions), J dq + df/dt = [-1] (velocities); give a state on the constraints, or project=True to project it onto them
    """
    from scipy.integrate import solve_ivp
    method = choice(method, list(_METHODS) + list(_SCIPY), 'method')
    scipy_method = _METHODS.get(method, method)
    max_points = count(max_points, 'max_points', minimum=2)
    max_evaluations = count(max_evaluations, 'max_evaluations')
    points = count(points, 'points', minimum=2, maximum=max_points, what="samples",
                   raise_with="max_points=")
    t0, t_end = real_number(t0, 't0', entry="t0"), real_number(t_end, 't_end', entry="t_end")
    if not t_end > t0:
        raise ModelError(f"the final time must be after t0 = {t0}, got {t_end}", entry="t_end")
    if not np.isfinite(t_end - t0):
        raise ModelError(f"the interval from t0 = {t0} to t_end = {t_end} is too long for "
                         "floating point", entry="t_end")
    rtol = finite_real(rtol, 'rtol', minimum=0, strict=True)
    atol = finite_real(atol, 'atol', minimum=0)
    project_initial = flag(project, 'project')
    for key, value in options.items():
        if key not in _STEP_OPTIONS:
            raise ModelError(f"unknown option {key!r}; the options of the integrator are "
                             f"{', '.join(_STEP_OPTIONS)}", entry="simulate")
        options[key] = finite_real(value, key, minimum=0, strict=True)
    if isinstance(equations, RightHandSide):
        rhs, form = equations, equations.form()
    else:
        form = as_form(equations)
        rhs = RightHandSide(form, values, backend)
    if scipy_method in _IMPLICIT and hasattr(form, 'jacobian_kernel'):
        # the implicit methods take the compiled Jacobian, not finite
        # differences of the right-hand side (one call for 2n of them)
        options['jac'] = StateJacobian(form, rhs.parameters(), backend)
    # the energy is computed only if the trajectory is asked for it
    energy = form.energy if energy is None else energy
    x = initial_state(form, initial)
    parameters = rhs.parameters()
    constraints = form.constraints()[0] + form.velocity_constraints()[0]
    project = _Projection(form, parameters) if constraints else None
    if project is not None:
        x = _start_on_constraints(project, t0, x, form.state(), project_initial)
    times = np.linspace(t0, t_end, points)
    states = np.empty((points, len(x)))
    states[0] = x
    progress = _Progress(rhs, t0, t_end, max_evaluations)
    if events is not None:
        from .events import event_functions
        options['events'] = event_functions(events, form.state(), parameters)
    found = []
    # without constraints one integration (restarts cost steps); with them
    # one per sample interval, each followed by the projection
    step = 1 if project is not None else points - 1
    dense, breaks = [], [times[0]]
    i = 0
    while i < points - 1:
        j = min(i + step, points - 1)
        try:
            solution = solve_ivp(progress, (times[i], times[j]), states[i],
                                 method=scipy_method, t_eval=times[i:j + 1], rtol=rtol,
                                 atol=atol, dense_output=True, **options)
        except DynSymError:
            raise
        except (ValueError, ArithmeticError, np.linalg.LinAlgError) as err:
            # the integrator's own failure (a step with infinite values, a
            # singular iteration matrix): no result, said so
            raise AnalysisError(f"the integrator {scipy_method} failed between t = "
                                f"{times[i]:g} and t = {times[j]:g}: {err}",
                                entry="simulate") from err
        if not solution.success:
            reached = solution.t[-1] if len(solution.t) else times[i]
            raise AnalysisError(f"the integration stopped at t = {reached}: "
                                f"{solution.message}", entry="simulate")
        if events is not None:
            found += _crossings(solution, found, t0)
        if solution.status == 1:          # a terminal event: end at the crossing
            kept = i + len(solution.t)
            states[i + 1:kept] = solution.y.T[1:]
            if found[-1][0] <= times[kept - 1]:     # the crossing is a sample
                kept -= 1
            times, states = np.append(times[:kept], found[-1][0]), states[:kept + 1]
            states[kept] = found[-1][2]
            dense.append(solution.sol)
            breaks.append(found[-1][0])
            break
        states[i + 1:j + 1] = solution.y.T[1:]
        dense.append(solution.sol)
        breaks.append(times[j])
        if project is not None:
            states[j] = project(times[j], states[j])
        i = j
    return Trajectory(times, states, form.state(), parameters, energy=energy,
                      method=scipy_method, dense=dense, breaks=breaks, name=name,
                      events=found if events is not None else None, constraints=constraints)


def _crossings(solution, earlier, t0):
    r"""The crossings of one ``solve_ivp`` run as ``(t, index, state)``,
    by time, without a zero at the initial time (not a crossing) or one
    already recorded at the start of the run (the restarts of a
    constrained integration)."""
    new = [(float(t), k, np.array(y)) for k, (ts, ys) in
           enumerate(zip(solution.t_events, solution.y_events)) for t, y in zip(ts, ys)
           if t > t0]
    new.sort(key=lambda e: e[0])
    return [e for e in new if not any(k == e[1] and abs(t - e[0]) <= 1e-12 * max(1, abs(t))
                                      for t, k, _ in earlier[-len(new) - 1:])]
