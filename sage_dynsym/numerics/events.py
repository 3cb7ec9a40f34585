r"""
Events: zero crossings of expressions along a numerical solution

An *event* is an expression `g(t, x)` of the time, the state variables and
the parameters; it occurs where `g` crosses zero. :func:`~sage_dynsym.numerics.simulate.simulate`
hands the events to SciPy's ``solve_ivp``, which locates each crossing by
root finding on the integrator's dense output -- to the integrator's
tolerance, not to the sampling --, and records the time and the state
there (:meth:`~sage_dynsym.numerics.trajectory.Trajectory.events`). Each
event may count only increasing crossings (``direction=1``), only
decreasing ones (``-1``) or both (``0``), and may end the integration
(``terminal=True``).

A plain expression is an event counting both directions, not terminal.

EXAMPLES: a pendulum released at rest, `\theta` decreasing through zero
every period::

    sage: from sage_dynsym.analysis.motion import SecondOrderEquations
    sage: from sage_dynsym.numerics.simulate import simulate
    sage: from sage_dynsym.numerics.events import Event
    sage: th, dth, ddth = var('theta dtheta ddtheta')
    sage: E = SecondOrderEquations([ddth + sin(th)], [th], [dth], [ddth])
    sage: T = simulate(E, {}, {th: 1, dth: 0}, 20, events=[Event(th, direction=-1)])
    sage: T.period()           # 4 K(sin(1/2)^2) for a unit pendulum
    6.69997566...
    sage: 4*elliptic_kc(sin(1/2.)^2)
    6.69997566...
"""
from sage.structure.sage_object import SageObject
from sage.symbolic.ring import SR

from ..errors import ModelError
from ..symbols import t as _t

__all__ = ['Event', 'event_functions']


class Event(SageObject):
    r"""
    A zero crossing to record: an expression, the direction of the
    crossings counted and whether the integration stops at the first one.

    INPUT:

    - ``expression`` -- an expression in ``t``, the state variables and the
      parameters
    - ``direction`` -- (default: 0) ``1`` increasing crossings only, ``-1``
      decreasing ones only, ``0`` both
    - ``terminal`` -- (default: ``False``) stop the integration at the first
      crossing

    EXAMPLES::

        sage: from sage_dynsym.numerics.events import Event
        sage: x = var('x')
        sage: Event(x - 1, direction=1, terminal=True)
        Event x - 1 == 0, increasing, terminal

    It has no value equality (two of them are equal only if they are the
    same object), so the pickling test, which compares the copy with the
    original, is skipped::

        sage: TestSuite(Event(x)).run(skip=['_test_pickling'])

    TESTS::

        sage: Event(x, direction=2)
        Traceback (most recent call last):
        ...
        ModelError: events: direction must be 1, -1 or 0, got 2
        sage: Event(x, terminal='yes')
        Traceback (most recent call last):
        ...
        ModelError: events: terminal must be True or False, got 'yes'
    """

    def __init__(self, expression, direction=0, terminal=False):
        try:
            self._expression = SR(expression)
        except (TypeError, ValueError) as err:
            raise ModelError(f"an event is an expression, got {expression!r}",
                             entry="events") from err
        if direction not in (-1, 0, 1):
            raise ModelError(f"direction must be 1, -1 or 0, got {direction!r}", entry="events")
        if terminal is not True and terminal is not False:
            raise ModelError(f"terminal must be True or False, got {terminal!r}", entry="events")
        self._direction, self._terminal = int(direction), terminal

    def _repr_(self):
        what = {1: "increasing", -1: "decreasing", 0: "both directions"}[self._direction]
        return f"Event {self._expression} == 0, {what}" + (", terminal" if self._terminal else "")

    def expression(self):
        r"""The expression whose zero crossings are recorded.

        EXAMPLES::

            sage: from sage_dynsym.numerics.events import Event
            sage: Event(var('x') - 1).expression()
            x - 1
        """
        return self._expression

    def direction(self):
        r"""``1``, ``-1`` or ``0`` (see the class documentation).

        EXAMPLES::

            sage: from sage_dynsym.numerics.events import Event
            sage: Event(var('x'), direction=-1).direction()
            -1
        """
        return self._direction

    def is_terminal(self):
        r"""Whether the integration stops at the first crossing.

        EXAMPLES::

            sage: from sage_dynsym.numerics.events import Event
            sage: Event(var('x')).is_terminal()
            False
        """
        return self._terminal


def event_functions(events, variables, parameters):
    r"""
    The events as functions ``g(t, x)`` for ``solve_ivp`` (with their
    ``direction`` and ``terminal`` attributes), the parameter values
    substituted.

    INPUT:

    - ``events`` -- a list of :class:`Event` or expressions
    - ``variables`` -- the state variables, in the order of the state
    - ``parameters`` -- dict of the parameter values

    OUTPUT: a list of callables

    EXAMPLES::

        sage: from sage_dynsym.numerics.events import event_functions
        sage: x, dx, a = var('x dx a')
        sage: (g,) = event_functions([x - a], [x, dx], {a: 2.0})
        sage: g(0.0, [3.0, 0.0]), g.direction, g.terminal
        (1.0, 0, False)

    TESTS::

        sage: event_functions([x - var('b')], [x, dx], {a: 2.0})
        Traceback (most recent call last):
        ...
        ModelError: events: event 0, -b + x, depends on b, which is not a state variable, a parameter or t
        sage: event_functions(x, [x, dx], {})
        Traceback (most recent call last):
        ...
        ModelError: events: expected a list of expressions or Event objects, got x
    """
    from .compiler import python_function
    if not isinstance(events, (list, tuple)):
        raise ModelError(f"expected a list of expressions or Event objects, got {events}",
                         entry="events")
    known = {str(v) for v in list(variables) + list(parameters) + [_t]}
    functions = []
    for k, event in enumerate(events):
        event = event if isinstance(event, Event) else Event(event)
        expression = event.expression()
        unknown = sorted({str(v) for v in expression.variables()} - known)
        if unknown:
            names = ', '.join(unknown)
            raise ModelError(f"event {k}, {expression}, depends on {names}, which "
                             f"{'is' if len(unknown) == 1 else 'are'} not a state variable, "
                             "a parameter or t", entry="events")
        f = python_function([expression.subs(parameters)], [_t] + list(variables),
                            entry="events")

        def g(time, x, f=f):
            return float(f(time, *x)[0])

        g.direction, g.terminal = event.direction(), event.is_terminal()
        functions.append(g)
    return functions
