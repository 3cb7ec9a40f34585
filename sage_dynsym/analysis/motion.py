r"""
Equations of motion as neutral data for the analysis

The analysis does not know the classes that produce equations (Lagrangians,
Routh functions, Hamiltonians, circuits, systems on Lie algebras): each of
them hands over its equations as one of two plain records through a
method ``equations_record()`` -- the pattern of SymPy's mechanics --, and
:func:`~sage_dynsym.analysis.linear.linearize`, the stationary-motion
search and the stability verdicts work on the records only.

- :class:`SecondOrderEquations`: expressions `E_i` (each ``== 0``) in
  coordinates, velocities and accelerations, e.g. Lagrange's equations;
- :class:`FirstOrderEquations`: right-hand sides `F` of `B\dot x = F(x)`,
  e.g. Hamilton's equations or a circuit's state equations.

EXAMPLES::

    sage: from sage_dynsym.analysis.motion import SecondOrderEquations, FirstOrderEquations
    sage: x, dx, ddx, k = var('x dx ddx k')
    sage: E = SecondOrderEquations([ddx + k*x], [x], [dx], [ddx]); E
    Second-order equations in (x): [k*x + ddx] == 0
    sage: F = FirstOrderEquations([dx, -k*x], [x, dx]); F
    First-order equations x' = F(x) in (x, dx)
    sage: F.lhs_matrix()
    [1 0]
    [0 1]
"""
from sage.matrix.constructor import matrix, identity_matrix
from sage.structure.sage_object import SageObject
from sage.symbolic.ring import SR

from ..errors import AnalysisError

__all__ = ['SecondOrderEquations', 'FirstOrderEquations']


def _with_multipliers(constraints, multipliers, what):
    r"""``constraints`` and their ``multipliers`` as lists of symbolic
    expressions, checked to be as many."""
    constraints = [SR(f) for f in constraints]
    multipliers = [SR(v) for v in multipliers]
    if len(constraints) != len(multipliers):
        raise AnalysisError(f"{len(constraints)} {what} for {len(multipliers)} multipliers",
                            entry="equations of motion")
    return constraints, multipliers


class SecondOrderEquations(SageObject):
    r"""
    Equations `E_i(q, \dot q, \ddot q) = 0`.

    INPUT:

    - ``equations`` -- the expressions `E_i`
    - ``coordinates``, ``velocities``, ``accelerations`` -- the symbols, in
      the same order
    - ``function`` -- (optional) the characteristic function at rest whose
      negative is the potential of the equilibria (`-L|_{\dot q = 0}`
      enters as the amended potential), with ``kinetic`` the matrix of the
      velocities' quadratic part (the kinetic matrix)
    - ``constraints`` -- (optional) holonomic constraints `f_j(q, t)`, each
      ``== 0``
    - ``multipliers`` -- (optional) their multiplier symbols `\mu_j`, one per
      constraint
    - ``velocity_constraints`` -- (optional) constraints on the velocities
      `g_k = a_k(q, t)\cdot\dot q + b_k(q, t)`, each ``== 0`` (rolling
      without slipping, a knife edge)
    - ``velocity_multipliers`` -- (optional) their multiplier symbols
      `\lambda_k`, one per velocity constraint

    With constraints, the equations `E_i` contain the terms
    `-\sum_j \mu_j \partial f_j/\partial q_i`: for `E = M\ddot q - F` this
    is `M\ddot q = F + J^T\mu` with `J = \partial f/\partial q`, so `J^T\mu`
    are the generalized constraint forces. A velocity constraint `g_k`
    contributes `-\lambda_k\, \partial g_k/\partial\dot q_i` in the same way.

    EXAMPLES::

        sage: from sage_dynsym.analysis.motion import SecondOrderEquations
        sage: x, dx, ddx = var('x dx ddx')
        sage: SecondOrderEquations([ddx + x], [x], [dx], [ddx]).equations()
        [ddx + x]

    A particle on a line `x = y` (the multiplier is the constraint force)::

        sage: y, dy, ddy, mu1 = var('y dy ddy mu1')
        sage: E = SecondOrderEquations([ddx - mu1, ddy + mu1], [x, y], [dx, dy], [ddx, ddy],
        ....:                          constraints=[x - y], multipliers=[mu1])
        sage: E.constraints(), E.multipliers()
        ([x - y], [mu1])

    A knife edge (the velocity of its point across the blade vanishes)::

        sage: th, dth, ddth, la = var('theta dtheta ddtheta la')
        sage: E = SecondOrderEquations([ddx - la*sin(th), ddy + la*cos(th), ddth],
        ....:                          [x, y, th], [dx, dy, dth], [ddx, ddy, ddth],
        ....:                          velocity_constraints=[sin(th)*dx - cos(th)*dy],
        ....:                          velocity_multipliers=[la]); E
        Second-order equations in (x, y, theta): [-la*sin(theta) + ddx, la*cos(theta) + ddy, ddtheta] == 0 with velocity constraints [-dy*cos(theta) + dx*sin(theta)] == 0
        sage: E.velocity_constraints(), E.velocity_multipliers()
        ([-dy*cos(theta) + dx*sin(theta)], [la])

    TESTS::

        sage: SecondOrderEquations([ddx], [x], [dx], [ddx], constraints=[x], multipliers=[])
        Traceback (most recent call last):
        ...
        AnalysisError: equations of motion: 1 constraints for 0 multipliers
        sage: SecondOrderEquations([ddx], [x], [dx], [ddx], velocity_constraints=[dx])
        Traceback (most recent call last):
        ...
        AnalysisError: equations of motion: 1 velocity constraints for 0 multipliers
    """

    def __init__(self, equations, coordinates, velocities, accelerations, function=None,
                 kinetic=None, constraints=(), multipliers=(), velocity_constraints=(),
                 velocity_multipliers=()):
        self._equations = [SR(e) for e in equations]
        self._q = [SR(v) for v in coordinates]
        self._dq = [SR(v) for v in velocities]
        self._ddq = [SR(v) for v in accelerations]
        if not len(self._equations) == len(self._q) == len(self._dq) == len(self._ddq):
            raise AnalysisError(f"{len(self._equations)} equations for {len(self._q)} "
                                "coordinates", entry="equations of motion")
        self._function = None if function is None else SR(function)
        self._kinetic = None if kinetic is None else matrix(SR, kinetic)
        self._constraints, self._multipliers = _with_multipliers(
            constraints, multipliers, "constraints")
        self._velocity_constraints, self._velocity_multipliers = _with_multipliers(
            velocity_constraints, velocity_multipliers, "velocity constraints")

    def _repr_(self):
        text = (f"Second-order equations in ({', '.join(map(str, self._q))}): "
                f"{self._equations} == 0")
        if self._constraints:
            text += f" with constraints {self._constraints} == 0"
        if self._velocity_constraints:
            text += f" with velocity constraints {self._velocity_constraints} == 0"
        return text

    def equations(self):
        r"""The expressions `E_i`.

        EXAMPLES: see the class documentation.
        """
        return list(self._equations)

    def coordinates(self):
        r"""The coordinates `q`.

        EXAMPLES::

            sage: from sage_dynsym.analysis.motion import SecondOrderEquations
            sage: x, dx, ddx = var('x dx ddx')
            sage: SecondOrderEquations([ddx + x], [x], [dx], [ddx]).coordinates()
            [x]
        """
        return list(self._q)

    def velocities(self):
        r"""The velocities `\dot q`.

        EXAMPLES::

            sage: from sage_dynsym.analysis.motion import SecondOrderEquations
            sage: x, dx, ddx = var('x dx ddx')
            sage: SecondOrderEquations([ddx + x], [x], [dx], [ddx]).velocities()
            [dx]
        """
        return list(self._dq)

    def accelerations(self):
        r"""The accelerations `\ddot q`.

        EXAMPLES::

            sage: from sage_dynsym.analysis.motion import SecondOrderEquations
            sage: x, dx, ddx = var('x dx ddx')
            sage: SecondOrderEquations([ddx + x], [x], [dx], [ddx]).accelerations()
            [ddx]
        """
        return list(self._ddq)

    def function(self):
        r"""The characteristic function (``None`` if not given).

        EXAMPLES::

            sage: from sage_dynsym.analysis.motion import SecondOrderEquations
            sage: x, dx, ddx = var('x dx ddx')
            sage: SecondOrderEquations([ddx + x], [x], [dx], [ddx], function=dx^2/2 - x^2/2).function()
            1/2*dx^2 - 1/2*x^2
        """
        return self._function

    def kinetic_matrix(self):
        r"""The kinetic matrix (``None`` if not given).

        EXAMPLES::

            sage: from sage_dynsym.analysis.motion import SecondOrderEquations
            sage: x, dx, ddx = var('x dx ddx')
            sage: SecondOrderEquations([ddx + x], [x], [dx], [ddx], kinetic=[[1]]).kinetic_matrix()
            [1]
        """
        return self._kinetic

    def constraints(self):
        r"""The holonomic constraints `f_j` (each ``== 0``; empty if none).

        EXAMPLES::

            sage: from sage_dynsym.analysis.motion import SecondOrderEquations
            sage: x, dx, ddx = var('x dx ddx')
            sage: SecondOrderEquations([ddx + x], [x], [dx], [ddx]).constraints()
            []
        """
        return list(self._constraints)

    def multipliers(self):
        r"""The multipliers `\mu_j` of the constraints (empty if none).

        EXAMPLES::

            sage: from sage_dynsym.analysis.motion import SecondOrderEquations
            sage: x, dx, ddx = var('x dx ddx')
            sage: SecondOrderEquations([ddx + x], [x], [dx], [ddx]).multipliers()
            []
        """
        return list(self._multipliers)

    def velocity_constraints(self):
        r"""The constraints on the velocities `g_k(q, \dot q, t)`, linear in
        `\dot q` (each ``== 0``; empty if none).

        EXAMPLES::

            sage: from sage_dynsym.analysis.motion import SecondOrderEquations
            sage: x, dx, ddx = var('x dx ddx')
            sage: SecondOrderEquations([ddx + x], [x], [dx], [ddx]).velocity_constraints()
            []
        """
        return list(self._velocity_constraints)

    def velocity_multipliers(self):
        r"""The multipliers `\lambda_k` of the velocity constraints (empty if
        none).

        EXAMPLES::

            sage: from sage_dynsym.analysis.motion import SecondOrderEquations
            sage: x, dx, ddx = var('x dx ddx')
            sage: SecondOrderEquations([ddx + x], [x], [dx], [ddx]).velocity_multipliers()
            []
        """
        return list(self._velocity_multipliers)


class FirstOrderEquations(SageObject):
    r"""
    Equations `B\dot x = F(x)`.

    INPUT:

    - ``rhs`` -- the right-hand sides `F`
    - ``variables`` -- the state `x`, in order
    - ``lhs_matrix`` -- (optional) `B`, or the list of its diagonal entries;
      default the identity

    EXAMPLES::

        sage: from sage_dynsym.analysis.motion import FirstOrderEquations
        sage: i, u, L, C = var('i u L C')
        sage: F = FirstOrderEquations([-u, i], [i, u], lhs_matrix=[L, C]); F.lhs_matrix()
        [L 0]
        [0 C]
    """

    def __init__(self, rhs, variables, lhs_matrix=None):
        self._rhs = [SR(f) for f in rhs]
        self._x = [SR(v) for v in variables]
        if len(self._rhs) != len(self._x):
            raise AnalysisError(f"{len(self._rhs)} right-hand sides for {len(self._x)} "
                                "variables", entry="equations of motion")
        n = len(self._x)
        if lhs_matrix is None:
            self._B = identity_matrix(SR, n)
        elif hasattr(lhs_matrix, 'nrows') or (len(lhs_matrix) and
                                              isinstance(lhs_matrix[0], (list, tuple))):
            self._B = matrix(SR, lhs_matrix)
        else:
            self._B = matrix.diagonal(SR, list(lhs_matrix))

    def _repr_(self):
        left = "x'" if self._B.is_one() else "B x'"
        return f"First-order equations {left} = F(x) in ({', '.join(map(str, self._x))})"

    def rhs(self):
        r"""The right-hand sides `F`.

        EXAMPLES::

            sage: from sage_dynsym.analysis.motion import FirstOrderEquations
            sage: x, y = var('x y')
            sage: FirstOrderEquations([y, -x], [x, y]).rhs()
            [y, -x]
        """
        return list(self._rhs)

    def variables(self):
        r"""The state `x`.

        EXAMPLES::

            sage: from sage_dynsym.analysis.motion import FirstOrderEquations
            sage: x, y = var('x y')
            sage: FirstOrderEquations([y, -x], [x, y]).variables()
            [x, y]
        """
        return list(self._x)

    def lhs_matrix(self):
        r"""The matrix `B`.

        EXAMPLES: see the class documentation.
        """
        return self._B
