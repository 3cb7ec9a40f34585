r"""
Trajectories: the samples of a numerical solution

A :class:`Trajectory` holds the sample times and the states of a solution
computed by :func:`~sage_dynsym.numerics.simulate.simulate`, with the
state variables, the parameter values and, when the model has one, its
conserved energy, so that any expression of the state can be followed
along the motion.

EXAMPLES::

    sage: import numpy as np
    sage: from sage_dynsym.numerics.trajectory import Trajectory
    sage: x, dx, w = var('x dx w')
    sage: ts = np.linspace(0, 1, 3)
    sage: T = Trajectory(ts, np.array([np.cos(ts), -np.sin(ts)]).T, [x, dx], {w: 1.0},
    ....:                energy=(dx^2 + w*x^2)/2)
    sage: T
    Trajectory in (x, dx): 3 samples, t from 0.0 to 1.0
    sage: T.values(x)
    array([1.        , 0.87758256, 0.54030231])
    sage: T.energy_drift() < 1e-15
    True
"""
import numpy as np

from sage.structure.sage_object import SageObject
from sage.symbolic.ring import SR

from ..errors import ModelError
from ..symbols import t as _t
from .form import deferred, resolved

__all__ = ['State', 'Trajectory', 'CURVES_PER_PANEL', 'DENSE_POINTS']


class State(dict):
    r"""
    A state of a trajectory: a dict over the state variables (symbols) that
    also finds a value by the variable's name, as :meth:`Trajectory.values`
    does (``state['dx']`` and ``state[dx]`` are the same value).

    EXAMPLES::

        sage: from sage_dynsym.numerics.trajectory import State
        sage: x, dx = var('x dx')
        sage: s = State({x: float(1), dx: float(-2)}); s
        {x: 1.0, dx: -2.0}
        sage: s['dx'], s[dx], 'x' in s, s.get('y', 0)
        (-2.0, -2.0, True, 0)

    TESTS::

        sage: s['y']
        Traceback (most recent call last):
        ...
        KeyError: "'y' is not a state variable (they are x, dx)"
    """

    def _key(self, key):
        if isinstance(key, str):
            for variable in self:
                if str(variable) == key:
                    return variable
        return key

    def __getitem__(self, key):
        try:
            return dict.__getitem__(self, self._key(key))
        except KeyError as err:
            # the mapping protocol's error, with what would have been found
            raise KeyError(f"{key!r} is not a state variable (they are "
                           f"{', '.join(map(str, self))})") from err

    def __contains__(self, key):
        return dict.__contains__(self, self._key(key))

    def get(self, key, default=None):
        r"""The value of the variable ``key`` (a symbol or its name), or
        ``default``.

        EXAMPLES::

            sage: from sage_dynsym.numerics.trajectory import State
            sage: x = var('x')
            sage: State({x: float(1)}).get('x'), State({x: float(1)}).get('y', 0)
            (1.0, 0)
        """
        return dict.get(self, self._key(key), default)


class Trajectory(SageObject):
    r"""
    The samples of a solution.

    INPUT:

    - ``times`` -- 1-D array of the sample times
    - ``states`` -- 2-D array, one row per sample, one column per variable
    - ``variables`` -- the state variables (symbols)
    - ``parameters`` -- dict of the parameter values used (symbol -> float)
    - ``energy`` -- (optional) a conserved energy in the variables and
      parameters, for :meth:`energy_drift`, or a function without
      arguments computing it (called when the energy is first needed)
    - ``method`` -- (optional) the integrator's name
    - ``dense`` -- (optional) the integrator's continuous solution: a list
      of callables ``f(times) -> states`` (one row per variable, as SciPy's
      ``OdeSolution``), each valid on the interval between two consecutive
      entries of ``breaks``; used to draw smooth curves between the samples
    - ``breaks`` -- the ends of the intervals of ``dense``
    - ``name`` -- (optional) the model's name, for the titles of pictures
    - ``events`` -- (optional) the recorded zero crossings, a list of
      ``(time, index, state)`` with ``state`` an array over the variables
      (see :mod:`~sage_dynsym.numerics.events`)
    - ``constraints`` -- (optional) the constraints the motion must keep
      (expressions in the state, each ``== 0``), for
      :meth:`constraint_residuals`

    EXAMPLES: see the module documentation.
    """

    def __init__(self, times, states, variables, parameters, energy=None, method=None,
                 dense=None, breaks=None, name=None, events=None, constraints=()):
        _check_samples(times, states, variables, parameters)
        self._constraints = [SR(c) for c in constraints]
        self._times = np.array(times, dtype=float)
        self._states = np.array(states, dtype=float).reshape(len(self._times), len(variables))
        self._variables = [SR(v) for v in variables]
        self._parameters = {SR(k): float(v) for k, v in parameters.items()}
        self._energy = energy if energy is None or deferred(energy) else SR(energy)
        self._method = method
        self._dense = list(dense) if dense else None
        self._breaks = None if breaks is None else np.array(breaks, dtype=float)
        self._name = name
        self._events = None if events is None else sorted(
            ((float(t), int(k), np.array(y, dtype=float)) for t, k, y in events),
            key=lambda e: e[0])

    def _test_samples(self, **options):
        r"""Run by ``TestSuite``: a row of states per time, a column per
        variable; the times run one way, the events lie within them; a
        piece of the continuous solution between each two breaks."""
        tester, times = self._tester(**options), self._times
        tester.assertEqual(self._states.shape, (len(times), len(self._variables)))
        steps = np.diff(times)
        tester.assertTrue((steps >= 0).all() or (steps <= 0).all())
        for t, _, state in self._events or []:
            low, high = times.min(), times.max()
            tester.assertTrue(low <= t <= high)
            tester.assertEqual(len(state), len(self._variables))
        if self._dense is not None:
            tester.assertEqual(len(self._dense), len(self._breaks) - 1)

    def __eq__(self, other):
        r"""
        Trajectories are values: equal when they have the same samples,
        variables, parameters and energy.

        EXAMPLES::

            sage: from sage_dynsym.numerics.trajectory import Trajectory
            sage: x = var('x')
            sage: T = Trajectory([0, 1], [[1], [2]], [x], {}, energy=x^2)
            sage: T == Trajectory([0, 1], [[1], [2]], [x], {}, energy=x^2), T == 1
            (True, False)
            sage: TestSuite(T).run()
        """
        return (isinstance(other, Trajectory) and
                np.array_equal(self._times, other._times) and
                np.array_equal(self._states, other._states) and
                [str(v) for v in self._variables] == [str(v) for v in other._variables] and
                {str(k): v for k, v in self._parameters.items()} ==
                {str(k): v for k, v in other._parameters.items()} and
                str(self.energy()) == str(other.energy()) and
                [e[:2] for e in self._events or []] == [e[:2] for e in other._events or []])

    def __ne__(self, other):
        return not self == other

    def __hash__(self):
        return hash((tuple(str(v) for v in self._variables), self._times.tobytes(),
                     self._states.tobytes()))

    def _repr_(self):
        return (f"Trajectory in ({', '.join(map(str, self._variables))}): "
                f"{len(self._times)} samples, t from {self._times[0]} to {self._times[-1]}")

    def times(self):
        r"""The sample times (a NumPy array).

        EXAMPLES::

            sage: from sage_dynsym.numerics.trajectory import Trajectory
            sage: x = var('x')
            sage: Trajectory([0, 1], [[1], [2]], [x], {}).times()
            array([0., 1.])
        """
        return self._times.copy()

    def states(self):
        r"""The states, one row per sample (a NumPy array).

        EXAMPLES::

            sage: from sage_dynsym.numerics.trajectory import Trajectory
            sage: x = var('x')
            sage: Trajectory([0, 1], [[1], [2]], [x], {}).states()
            array([[1.],
                   [2.]])
        """
        return self._states.copy()

    def variables(self):
        r"""The state variables, in the order of the columns of :meth:`states`.

        EXAMPLES::

            sage: from sage_dynsym.numerics.trajectory import Trajectory
            sage: x = var('x')
            sage: Trajectory([0, 1], [[1], [2]], [x], {}).variables()
            [x]
        """
        return list(self._variables)

    def parameters(self):
        r"""The parameter values of the simulation.

        EXAMPLES::

            sage: from sage_dynsym.numerics.trajectory import Trajectory
            sage: x, a = var('x a')
            sage: Trajectory([0, 1], [[1], [2]], [x], {a: 2}).parameters()
            {a: 2.0}
        """
        return dict(self._parameters)

    def method(self):
        r"""The name of the integrator used (``None`` if unknown).

        EXAMPLES::

            sage: from sage_dynsym.numerics.trajectory import Trajectory
            sage: x = var('x')
            sage: Trajectory([0, 1], [[1], [2]], [x], {}, method='DOP853').method()
            'DOP853'
        """
        return self._method

    def _array(self, expression, times=None, states=None):
        """The values of a variable, its name, or an expression of the state
        (at the samples, or at the given ``times`` and ``states``)."""
        if times is None:
            times, states = self._times, self._states
        names = {str(v): i for i, v in enumerate(self._variables)}
        if isinstance(expression, str):
            if expression not in names:
                raise ModelError(f"{expression!r} is not a state variable (they are "
                                 f"{', '.join(names)})", entry="values")
            return states[:, names[expression]]
        expression = SR(expression)
        if str(expression) in names and expression.is_symbol():
            return states[:, names[str(expression)]]
        from .compiler import python_function
        from .expressions import symbols_and_functions
        # one memoized walk, the parameters as arguments: the energy of a
        # large model shares its subexpressions many times over
        known = {str(v) for v in self._variables + list(self._parameters) + [_t]}
        unknown = sorted(set(symbols_and_functions([expression])[0]) - known)
        if unknown:
            raise ModelError(f"{expression} depends on {', '.join(unknown)}, which are not state "
                             "variables or parameters of the trajectory", entry="values")
        parameters = list(self._parameters)
        f = python_function([expression], [_t] + self._variables + parameters, entry="values")
        values = [self._parameters[p] for p in parameters]
        return np.array([f(s, *row, *values)[0] for s, row in zip(times, states.tolist())])

    def values(self, expression):
        r"""
        The values of a state variable (a symbol or its name), or of an
        expression in the state variables, the parameters and ``t``, at the
        samples (a 1-D NumPy array of floats, like :meth:`times`).

        EXAMPLES::

            sage: from sage_dynsym.numerics.trajectory import Trajectory
            sage: x, a = var('x a')
            sage: T = Trajectory([0, 1], [[1], [2]], [x], {a: 3})
            sage: from sage_dynsym.symbols import t
            sage: T.values('x'), T.values(a*x^2 + t)
            (array([1., 2.]), array([ 3., 13.]))

        TESTS::

            sage: T.values('y')
            Traceback (most recent call last):
            ...
            ModelError: values: 'y' is not a state variable (they are x)
            sage: T.values(x + var('b'))
            Traceback (most recent call last):
            ...
            ModelError: values: b + x depends on b, which are not state variables or parameters of the trajectory
        """
        return np.array(self._array(expression), dtype=float)

    def final_state(self):
        r"""The state at the last sample, a :class:`State` (a dict over the
        variables, also read by their names).

        EXAMPLES::

            sage: from sage_dynsym.numerics.trajectory import Trajectory
            sage: x = var('x')
            sage: s = Trajectory([0, 1], [[1], [2]], [x], {}).final_state(); s, s['x']
            ({x: 2.0}, 2.0)
        """
        return State(zip(self._variables, map(float, self._states[-1])))

    def constraint_residuals(self):
        r"""
        The values of the constraints along the motion: a dict
        ``{constraint: NumPy array over the samples}`` (empty when the
        model has none); zero up to the integration and projection errors.

        EXAMPLES::

            sage: from sage_dynsym.numerics.trajectory import Trajectory
            sage: x, dx = var('x dx')
            sage: T = Trajectory([0, 1], [[1, 0], [2, 1e-9]], [x, dx], {}, constraints=[dx])
            sage: T.constraint_residuals()
            {dx: array([0.e+00, 1.e-09])}
        """
        return {c: self._array(c) for c in self._constraints}

    def energy(self):
        r"""The conserved energy of the model (``None`` if it has none).

        EXAMPLES::

            sage: from sage_dynsym.numerics.trajectory import Trajectory
            sage: x = var('x')
            sage: Trajectory([0, 1], [[1], [2]], [x], {}, energy=x^2).energy()
            x^2
            sage: Trajectory([0, 1], [[1], [2]], [x], {}, energy=lambda: x^3).energy()
            x^3
        """
        self._energy = resolved(self._energy)
        return self._energy

    def __getstate__(self):
        # a pickled trajectory keeps its energy, not the function computing it
        self.energy()
        return self.__dict__

    def energy_drift(self):
        r"""
        The largest relative change of the energy along the samples,
        `\max_k |E(t_k) - E(t_0)| / |E(t_0)|` (absolute when `E(t_0) = 0`).

        Raises :class:`~sage_dynsym.errors.ModelError` when the model has no
        energy integral (explicit time, dissipation, non-potential forces).

        EXAMPLES::

            sage: from sage_dynsym.numerics.trajectory import Trajectory
            sage: x = var('x')
            sage: Trajectory([0, 1], [[1], [2]], [x], {}, energy=x^2).energy_drift()
            3.0

        TESTS::

            sage: Trajectory([0, 1], [[1], [2]], [x], {}).energy_drift()
            Traceback (most recent call last):
            ...
            ModelError: energy_drift: the model has no energy integral (explicit time, dissipation or non-potential forces)
        """
        if self.energy() is None:
            raise ModelError("the model has no energy integral (explicit time, dissipation or "
                             "non-potential forces)", entry="energy_drift")
        E = self._array(self._energy)
        scale = abs(E[0]) if E[0] != 0 else 1.0
        return float(np.max(np.abs(E - E[0])) / scale)

    def dense(self, points=None):
        r"""
        Times and states between the samples, from the integrator's
        continuous solution (its dense output, accurate to the integrator's
        tolerance): a pair of arrays like :meth:`times` and :meth:`states`,
        ``points`` of them (default: :data:`DENSE_POINTS`, at least 20 per
        sample interval). Without a continuous solution (a trajectory built
        from samples only), the samples themselves.

        EXAMPLES::

            sage: from sage_dynsym.numerics.trajectory import Trajectory
            sage: x = var('x')
            sage: times, states = Trajectory([0, 1], [[1], [2]], [x], {}).dense()
            sage: times, states.shape
            (array([0., 1.]), (2, 1))

        With the integrator's solution of `x' = x`, the values between two
        samples are `e^t` to the tolerance::

            sage: from sage_dynsym.analysis.motion import FirstOrderEquations
            sage: from sage_dynsym.numerics.simulate import simulate
            sage: import numpy as np
            sage: T = simulate(FirstOrderEquations([x], [x]), {}, {x: 1}, 1, points=2)
            sage: times, states = T.dense(5)
            sage: bool(max(abs(states[:, 0] - np.exp(times))) < 1e-8)
            True
        """
        if self._dense is None:
            return self._times, self._states
        n = max(DENSE_POINTS, 20 * (len(self._times) - 1)) if points is None else int(points)
        times = np.linspace(self._times[0], self._times[-1], n)
        states = np.empty((n, len(self._variables)))
        piece = np.clip(np.searchsorted(self._breaks, times, side='right') - 1, 0,
                        len(self._dense) - 1)
        for k, f in enumerate(self._dense):
            here = piece == k
            if here.any():
                states[here] = np.asarray(f(times[here])).T
        return times, states

    def _title(self, what):
        return f"{self._name}: {what}" if self._name else what

    def plot(self, *expressions, **options):
        r"""
        The graphs of state variables or expressions of the state against
        time, one colour each, drawn through the integrator's continuous
        solution (see :meth:`dense`); the quantity on the vertical axis, a
        legend outside the axes when there are several, and a title naming
        the model and the integrator. Options go to Sage's ``line`` (and
        ``title=`` replaces the title).

        Without ``expressions``, all the state variables, in readable
        groups: when the state holds coordinates and their velocities (and
        more than two variables), the positions and the velocities in
        separate panels, one above the other (a graphics array); any group
        of more than :data:`CURVES_PER_PANEL` curves is split further.

        OUTPUT: a Sage ``Graphics`` object (one panel), or a
        ``GraphicsArray`` of panels

        EXAMPLES::

            sage: from sage_dynsym.numerics.trajectory import Trajectory
            sage: x, dx = var('x dx')
            sage: T = Trajectory([0, 1, 2], [[1, 0], [0, -1], [-1, 0]], [x, dx], {})
            sage: G = T.plot(x, dx^2); G
            Graphics object consisting of 2 graphics primitives
            sage: G.axes_labels(), G._extra_kwds['title']
            (('$t$', '$x$, $\\mathit{dx}^{2}$'), 'trajectory')

        Two coordinates and their velocities: positions and velocities apart::

            sage: y, dy = var('y dy')
            sage: T = Trajectory([0, 1], [[1, 0, 0, 1], [0, 1, -1, 0]], [x, y, dx, dy], {},
            ....:                name='oscillator')
            sage: A = T.plot(); A
            Graphics Array of size 2 x 1
            sage: [(len(P), P.axes_labels()[1], P._extra_kwds['title']) for P in A]
            [(2, 'positions', 'oscillator: trajectory: positions'),
             (2, 'velocities', 'oscillator: trajectory: velocities')]
            sage: A[0].set_legend_options()['loc']           # outside, right of the axes
            (1.02, 0.0)
        """
        title = options.pop('title', None)
        what = 'trajectory' if self._method is None else f'trajectory ({self._method})'
        title = title if title is not None else self._title(what)
        times, states = self.dense()
        if expressions:
            return self._panel(expressions, times, states, title, options)
        groups = self._groups()
        if len(groups) == 1:
            return self._panel(groups[0][1], times, states, title, options)
        from sage.plot.plot import graphics_array
        return graphics_array([self._panel(group, times, states, f"{title}: {label}", options,
                                           ylabel=label)
                               for label, group in groups], nrows=len(groups), ncols=1)

    def _groups(self):
        # (label, variables): positions and velocities apart, at most
        # CURVES_PER_PANEL each
        # the velocity of q is named d<q> (symbols.velocity, whose symbol is
        # not made here: that would reset the LaTeX name of the user's own)
        names = {str(v) for v in self._variables}
        positions = [v for v in self._variables if f"d{v}" in names]
        rates = {f"d{v}" for v in positions}
        velocities = [v for v in self._variables if str(v) in rates]
        others = [v for v in self._variables if v not in positions and v not in velocities]
        if not positions or len(self._variables) <= 2:
            kinds = [('variables', list(self._variables))]
        else:
            kinds = [(label, group) for label, group in (
                ('positions', positions), ('velocities', velocities),
                ('other variables', others)) if group]
        groups = []
        for label, group in kinds:
            parts = [group[k:k + CURVES_PER_PANEL] for k in range(0, len(group),
                                                                   CURVES_PER_PANEL)]
            groups += [(label if len(parts) == 1 else f"{label} {k + 1} of {len(parts)}", part)
                       for k, part in enumerate(parts)]
        return groups

    def _panel(self, expressions, times, states, title, options, ylabel=None):
        # one Graphics: a curve per expression, the legend outside the axes
        # (a panel of a group names the group on its axis, the legend the curves)
        from sage.plot.graphics import Graphics
        from sage.plot.line import line
        from sage.plot.colors import rainbow
        colors = rainbow(max(len(expressions), 1))
        G = Graphics()
        for expression, color in zip(expressions, colors):
            values = self._array(expression, times, states)
            label = {} if len(expressions) == 1 else {'legend_label': _label(expression)}
            # the title as an option of the curves (Graphics keeps it)
            G += line(list(zip(times.tolist(), values.tolist())), color=color, title=title,
                      **label, **options)
        if len(expressions) > 1:
            # lower left corner of the legend just right of the axes
            G.set_legend_options(loc=(1.02, 0.0))
        G.axes_labels(['$t$', ylabel or ', '.join(_label(e) for e in expressions)])
        return G

    def phase_portrait(self, x, y, **options):
        r"""
        The curve `(x(t), y(t))` of two state variables or expressions,
        drawn through the integrator's continuous solution (see
        :meth:`dense`), with both quantities on the axes and a title.

        EXAMPLES::

            sage: from sage_dynsym.numerics.trajectory import Trajectory
            sage: x, dx = var('x dx')
            sage: T = Trajectory([0, 1, 2], [[1, 0], [0, -1], [-1, 0]], [x, dx], {})
            sage: G = T.phase_portrait(x, dx); G
            Graphics object consisting of 1 graphics primitive
            sage: G.axes_labels(), G._extra_kwds['title']
            (('$x$', '$\\mathit{dx}$'), 'phase portrait')
        """
        from sage.plot.line import line
        title = options.pop('title', None)
        times, states = self.dense()
        G = line(list(zip(self._array(x, times, states).tolist(),
                          self._array(y, times, states).tolist())),
                 title=title if title is not None else self._title('phase portrait'),
                 **options)
        G.axes_labels([_label(x), _label(y)])
        return G

    # -- events ------------------------------------------------------------

    def _recorded(self, index=None):
        if self._events is None:
            raise ModelError("no events were recorded: simulate with events=[...]",
                             entry="events")
        return [e for e in self._events if index is None or e[1] == index]

    def events(self, index=None):
        r"""
        The recorded zero crossings, in time order: a list of ``(time,
        index, state)``, ``index`` the position of the event in the list
        given to :func:`~sage_dynsym.numerics.simulate.simulate` and
        ``state`` a :class:`State` at the crossing (a dict over the state
        variables, also read by their names).

        INPUT:

        - ``index`` -- (optional) only the crossings of that event

        EXAMPLES::

            sage: from sage_dynsym.analysis.motion import SecondOrderEquations
            sage: from sage_dynsym.numerics.simulate import simulate
            sage: x, dx, ddx = var('x dx ddx')
            sage: T = simulate(SecondOrderEquations([ddx + x], [x], [dx], [ddx]), {},
            ....:              {x: 1, dx: 0}, 4, events=[x, dx])
            sage: [(round(t, 9), k) for t, k, _ in T.events()]
            [(1.570796327, 0), (3.141592654, 1)]
            sage: TestSuite(T).run()
            sage: t, k, state = T.events(0)[0]; round(state[dx], 9), round(state['dx'], 9)
            (-1.0, -1.0)

        TESTS::

            sage: simulate(SecondOrderEquations([ddx + x], [x], [dx], [ddx]), {},
            ....:          {x: 1, dx: 0}, 4).events()
            Traceback (most recent call last):
            ...
            ModelError: events: no events were recorded: simulate with events=[...]
        """
        return [(t, k, State(zip(self._variables, map(float, y))))
                for t, k, y in self._recorded(index)]

    def event_times(self, index=0):
        r"""The times of the crossings of one event (a NumPy array).

        EXAMPLES::

            sage: from sage_dynsym.analysis.motion import SecondOrderEquations
            sage: from sage_dynsym.numerics.simulate import simulate
            sage: x, dx, ddx = var('x dx ddx')
            sage: T = simulate(SecondOrderEquations([ddx + x], [x], [dx], [ddx]), {},
            ....:              {x: 1, dx: 0}, 7, events=[x])
            sage: T.event_times().round(9)
            array([1.57079633, 4.71238898])
        """
        return np.array([t for t, _, _ in self._recorded(index)])

    def period(self, index=0):
        r"""
        The mean time between successive crossings of one event: the
        period of a periodic motion when the event counts one direction
        (or a half period when it counts both).

        EXAMPLES: the period of a pendulum against the complete elliptic
        integral, `4\sqrt{l/g}\,K(\sin^2(\theta_0/2))`::

            sage: from sage_dynsym.analysis.motion import SecondOrderEquations
            sage: from sage_dynsym.numerics.simulate import simulate
            sage: from sage_dynsym.numerics.events import Event
            sage: th, dth, ddth = var('theta dtheta ddtheta')
            sage: E = SecondOrderEquations([ddth + sin(th)], [th], [dth], [ddth])
            sage: T = simulate(E, {}, {th: 2, dth: 0}, 30, events=[Event(th, direction=1)])
            sage: abs(T.period() - 4*elliptic_kc(sin(1.)^2)) < 1e-9
            True

        TESTS::

            sage: T = simulate(E, {}, {th: 2, dth: 0}, 1, events=[th])
            sage: T.period()
            Traceback (most recent call last):
            ...
            ModelError: period: event 0 crossed 0 times; a period needs at least 2 crossings
        """
        times = self.event_times(index)
        if len(times) < 2:
            raise ModelError(f"event {index} crossed {len(times)} times; a period needs at "
                             "least 2 crossings", entry="period")
        return float(np.mean(np.diff(times)))

    def section(self, expressions, index=0):
        r"""
        The values of ``expressions`` at the crossings of one event: the
        points of a Poincaré section (a NumPy array, one row per crossing).

        EXAMPLES: two uncoupled oscillators, cut where `x` increases through
        zero: the points lie on the ellipse of the energy of `y`::

            sage: from sage_dynsym.analysis.motion import SecondOrderEquations
            sage: from sage_dynsym.numerics.simulate import simulate
            sage: from sage_dynsym.numerics.events import Event
            sage: x, y, dx, dy, ddx, ddy = var('x y dx dy ddx ddy')
            sage: E = SecondOrderEquations([ddx + x, ddy + 2*y], [x, y], [dx, dy], [ddx, ddy])
            sage: T = simulate(E, {}, {x: 1, y: 1, dx: 0, dy: 0}, 60,
            ....:              events=[Event(x, direction=1)])
            sage: P = T.section([y, dy]); P.shape
            (9, 2)
            sage: bool(max(abs(2*a^2 + b^2 - 2) for a, b in P) < 1e-9)
            True
        """
        rows = self._recorded(index)
        times = np.array([t for t, _, _ in rows])
        states = np.array([y for _, _, y in rows]).reshape(len(rows), len(self._variables))
        return np.array([self._array(e, times, states) for e in expressions]).T \
            .reshape(len(rows), len(expressions))

    def poincare_section(self, x, y, index=0, **options):
        r"""The Poincaré section: the points `(x, y)` at the crossings of one
        event, plotted.

        EXAMPLES::

            sage: from sage_dynsym.analysis.motion import SecondOrderEquations
            sage: from sage_dynsym.numerics.simulate import simulate
            sage: x, y, dx, dy, ddx, ddy = var('x y dx dy ddx ddy')
            sage: E = SecondOrderEquations([ddx + x, ddy + 2*y], [x, y], [dx, dy], [ddx, ddy])
            sage: T = simulate(E, {}, {x: 1, y: 1, dx: 0, dy: 0}, 30, events=[x])
            sage: T.poincare_section(y, dy)
            Graphics object consisting of 1 graphics primitive
        """
        from sage.plot.point import point2d
        G = point2d([tuple(map(float, p)) for p in self.section([x, y], index)], **options)
        G.axes_labels([_label(x), _label(y)])
        return G


#: The most curves :meth:`Trajectory.plot` draws in one panel by default.
CURVES_PER_PANEL = 8

#: Points drawn through the continuous solution by :meth:`Trajectory.plot`
#: and :meth:`Trajectory.phase_portrait` (at least 20 per sample interval).
DENSE_POINTS = 2000


def _label(expression):
    r"""The LaTeX of a quantity for an axis or a legend (a name as given).

    EXAMPLES::

        sage: from sage_dynsym.numerics.trajectory import _label
        sage: _label(var('theta')), _label('x')
        ('$\\theta$', 'x')
    """
    return expression if isinstance(expression, str) else f'${SR(expression)._latex_()}$'


def _check_samples(times, states, variables, parameters):
    r"""
    The samples of a :class:`Trajectory` (what ``simulate`` passes it):
    times and states of numbers, one row of states per time over the
    variables, parameters a dict of numbers; else a
    :class:`~sage_dynsym.errors.ModelError`.

    EXAMPLES::

        sage: from sage_dynsym.numerics.trajectory import _check_samples
        sage: _check_samples([0, 1], [[1], [2]], [var('x')], {})
        sage: _check_samples(None, None, None, None)
        Traceback (most recent call last):
        ...
        ModelError: Trajectory: expected sample times, states over the variables and a dict of parameter values (a trajectory comes from simulate()), got times None
    """
    from ..arguments import expression_list
    try:
        shape = (len(np.array(times, dtype=float)), len(expression_list(variables, "variables")))
        ok = isinstance(parameters, dict) and np.array(states, dtype=float).size == \
            shape[0] * shape[1]
    except (TypeError, ValueError, ModelError):
        ok = False
    if not ok:
        raise ModelError("expected sample times, states over the variables and a dict of "
                         "parameter values (a trajectory comes from simulate()), got times "
                         f"{str(times)[:40]}", entry="Trajectory")
