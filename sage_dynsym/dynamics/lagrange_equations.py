r"""
The Lagrange equations of a Lagrangian, with its constraints

:class:`LagrangeEquations` is the method object that forms the equations
of motion of a :class:`~sage_dynsym.dynamics.lagrangian.Lagrangian` (in the
spirit of the method classes of ``sympy.physics.mechanics``): the equations
(5), in the structured form assembled from the decomposition (4) of a
natural Lagrangian (see :mod:`~sage_dynsym.dynamics.natural_equations`) or
differentiated directly, with the dissipation function, the generalized
forces and the forces of a constraint set
(:class:`~sage_dynsym.dynamics.holonomic.HolonomicConstraints`); the
neutral record of the equations, and the equations solved for the
accelerations (and the multipliers). The Lagrangian's own methods
(:meth:`~sage_dynsym.dynamics.lagrangian.Lagrangian.lagrange_equations`,
...) ask it.

EXAMPLES::

    sage: from sage_dynsym import Lagrangian
    sage: from sage_dynsym.dynamics.lagrange_equations import LagrangeEquations
    sage: r, phi, dr, dphi, m, k = var('r phi dr dphi m k')
    sage: L = Lagrangian(m*(dr^2 + r^2*dphi^2)/2 - k*r^2/2, [r, phi])
    sage: E = LagrangeEquations(L); E
    Lagrange equations of Lagrangian in coordinates (r, phi) : ...
    sage: E.equations()
    [-dphi^2*m*r + ddr*m + k*r, 2*dphi*dr*m*r + ddphi*m*r^2]
    sage: E.accelerations_solved()      # the equations (5) solved for ddr, ddphi
    [(dphi^2*m - k)*r/m, -2*dphi*dr/r]
"""
from sage.matrix.constructor import matrix
from sage.misc.cachefunc import cached_method
from sage.structure.sage_object import SageObject
from sage.symbolic.ring import SR

from ..errors import ModelError
from ..symbols import time_derivative
from ..analysis.motion import SecondOrderEquations
from .natural_equations import natural_equations, SymbolicCalculus
from .natural_form import is_singular

__all__ = ['LagrangeEquations']


class LagrangeEquations(SageObject):
    r"""
    The Lagrange equations of a Lagrangian with a set of constraints (see
    the module documentation).

    INPUT:

    - ``lagrangian`` -- a :class:`~sage_dynsym.dynamics.lagrangian.Lagrangian`
    - ``constraints`` -- (default: ``lagrangian.constraint_set()``) a
      constraint set: a
      :class:`~sage_dynsym.dynamics.holonomic.HolonomicConstraints` or a
      :class:`~sage_dynsym.dynamics.nonholonomic.VelocityConstraints` in the
      coordinates of ``lagrangian``

    EXAMPLES:

    A pendulum in Cartesian coordinates, with the constraint given here::

        sage: from sage_dynsym import Lagrangian
        sage: from sage_dynsym.dynamics.holonomic import HolonomicConstraints
        sage: from sage_dynsym.dynamics.lagrange_equations import LagrangeEquations
        sage: x, y, dx, dy, m, g, l = var('x y dx dy m g l')
        sage: L = Lagrangian(m*(dx^2 + dy^2)/2 - m*g*y, [x, y])
        sage: C = HolonomicConstraints([x, y], [dx, dy], [x^2 + y^2 - l^2])
        sage: E = LagrangeEquations(L, C); E.equations()
        [ddx*m - 2*mu1*x, ddy*m + g*m - 2*mu1*y]
        sage: E.accelerations_and_multipliers()[var('mu1')]
        1/2*(g*m*y - (dx^2 + dy^2)*m)/(x^2 + y^2)
    """

    def __init__(self, lagrangian, constraints=None):
        self._lagrangian = lagrangian
        self._constraints = lagrangian.constraint_set() if constraints is None else constraints

    def _repr_(self):
        return f"Lagrange equations of {self._lagrangian}"

    def lagrangian(self):
        r"""
        The Lagrangian.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: from sage_dynsym.dynamics.lagrange_equations import LagrangeEquations
            sage: L = Lagrangian(var('dx')^2, [var('x')])
            sage: LagrangeEquations(L).lagrangian() is L
            True
        """
        return self._lagrangian

    def constraint_set(self):
        r"""
        The constraint set whose forces the equations contain.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: from sage_dynsym.dynamics.lagrange_equations import LagrangeEquations
            sage: x, y, dx, dy = var('x y dx dy')
            sage: L = Lagrangian((dx^2 + dy^2)/2, [x, y], constraints=[x - y])
            sage: LagrangeEquations(L).constraint_set()
            Holonomic constraints x - y == 0 with multipliers mu1
        """
        return self._constraints

    def nonpotential_terms(self):
        r"""
        The terms `\partial R/\partial \dot q_i - Q_i` of the dissipation
        function and the generalized forces.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: from sage_dynsym.dynamics.lagrange_equations import LagrangeEquations
            sage: x, dx, c, F = var('x dx c F')
            sage: L = Lagrangian(dx^2/2, [x], dissipation=c*dx^2/2, forces=[F])
            sage: LagrangeEquations(L).nonpotential_terms()
            [c*dx - F]
        """
        L = self._lagrangian
        R = L.dissipation()
        return [R.diff(v) - Q for v, Q in zip(L.velocities(), L.generalized_forces())]

    def equations(self, form=None):
        r"""
        The Lagrange equations of the second kind (5), with dissipation,
        generalized forces and constraint forces: a list of expressions `E_i` meaning `E_i = 0`.

        INPUT:

        - ``form`` -- (default: ``"structured"`` for a natural Lagrangian,
          ``"direct"`` otherwise) ``"structured"`` assembles (5) from the
          decomposition (4); ``"direct"`` differentiates
          `d/dt (\partial L/\partial \dot q_i) - \partial L/\partial q_i`.
          Both are equal as functions.

        With constraints, `E_i` contains `-\sum_j \mu_j \partial f_j/\partial
        q_i` (`M\ddot q = F + J^T\mu`, see the module documentation).

        EXAMPLES:

        The structured form keeps the mass matrix entries as factors of the
        accelerations::

            sage: from sage_dynsym import Lagrangian
            sage: from sage_dynsym.dynamics.lagrange_equations import LagrangeEquations
            sage: r, phi, dr, dphi, m, k = var('r phi dr dphi m k')
            sage: L = Lagrangian(m*(dr^2 + r^2*dphi^2)/2 - k*r^2/2, [r, phi])
            sage: LagrangeEquations(L).equations()
            [-dphi^2*m*r + ddr*m + k*r, 2*dphi*dr*m*r + ddphi*m*r^2]

        A relativistic particle (not natural) is differentiated directly::

            sage: x, dx = var('x dx')
            sage: LagrangeEquations(Lagrangian(-sqrt(1 - dx^2), [x])).equations()
            [ddx*(dx^2/(-dx^2 + 1)^(3/2) + 1/sqrt(-dx^2 + 1))]

        TESTS::

            sage: t = var('t')
            sage: L = Lagrangian(m*(dr^2 + r^2*dphi^2)/2 + r*dphi*t, [r, phi])
            sage: E = LagrangeEquations(L)
            sage: S, D = E.equations('structured'), E.equations('direct')
            sage: all(bool((s - d).expand() == 0) for s, d in zip(S, D))
            True
            sage: E.equations('nonsense')
            Traceback (most recent call last):
            ...
            ModelError: form: expected 'structured' or 'direct', got 'nonsense'
        """
        if form is None:
            form = "structured" if self._lagrangian.is_natural() else "direct"
        if not isinstance(form, str) or form not in ("structured", "direct"):
            raise ModelError(f"expected 'structured' or 'direct', got {form!r}", entry='form')
        return self._formed(form)

    @cached_method
    def _formed(self, form):
        if form == "structured":
            equations = self._structured_equations()
        else:
            equations = self._direct_equations()
        return [e + extra - force for e, extra, force in
                zip(equations, self.nonpotential_terms(),
                    self._constraints.generalized_forces())]

    def _direct_equations(self):
        L = self._lagrangian
        q, dq, ddq = L.coordinates(), L.velocities(), L.accelerations()
        expr = L.expr()
        return [time_derivative(p, q, dq, ddq) - expr.diff(qi)
                for qi, p in zip(q, L.generalized_momenta())]

    def _structured_equations(self):
        # equations (5) from A, A_1, A_0 (dynamics.natural_equations), or
        # from the faster arithmetic of the Lagrangian's origin
        L = self._lagrangian
        builder = L.equation_builder()
        if builder is not None:
            return builder()
        A, A1, A0 = L.decomposition()
        q = L.coordinates()
        return natural_equations([list(row) for row in A.rows()], list(A1), A0,
                                 q, L.velocities(), L.accelerations(), SymbolicCalculus(q))

    def record(self):
        r"""
        The equations as neutral data for the analysis
        (:class:`~sage_dynsym.analysis.motion.SecondOrderEquations`, with
        the Lagrangian, its kinetic matrix and the constraints).

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: from sage_dynsym.dynamics.lagrange_equations import LagrangeEquations
            sage: x, dx = var('x dx')
            sage: LagrangeEquations(Lagrangian(dx^2/2 - x^2/2, [x])).record()
            Second-order equations in (x): [ddx + x] == 0
        """
        L, C = self._lagrangian, self._constraints
        kinetic = L.mass_matrix() if L.is_natural() else None
        return SecondOrderEquations(self.equations(), L.coordinates(), L.velocities(),
                                    L.accelerations(), function=L.expr(), kinetic=kinetic,
                                    constraints=C.expressions(),
                                    # the multipliers of the holonomic constraints come first
                                    multipliers=C.multipliers()[:len(C.expressions())],
                                    velocity_constraints=C.velocity_constraints(),
                                    velocity_multipliers=C.velocity_multipliers())

    def acceleration_system(self):
        r"""
        The linear system of the accelerations and the multipliers:
        `\begin{pmatrix} M & -G^T \\ G & 0\end{pmatrix}
        \begin{pmatrix}\ddot q \\ \mu\end{pmatrix}
        = \begin{pmatrix} F \\ h\end{pmatrix}`, with `G\ddot q = h` the
        constraints at the level of accelerations.

        OUTPUT: a triple ``(K, rhs, unknowns)``

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: from sage_dynsym.dynamics.lagrange_equations import LagrangeEquations
            sage: x, y, dx, dy = var('x y dx dy')
            sage: L = Lagrangian((dx^2 + dy^2)/2 - y, [x, y], constraints=[x - y])
            sage: LagrangeEquations(L).acceleration_system()
            (
            [ 1  0 -1]
            [ 0  1  1]
            [ 1 -1  0], [0, -1, 0], [ddx, ddy, mu1]
            )
        """
        L = self._lagrangian
        ddq = L.accelerations()
        M = L.decomposition()[0]
        G, h, multipliers = self._constraints.acceleration_constraints()
        n, m = len(ddq), len(multipliers)
        zero = {v: 0 for v in ddq + multipliers}
        F = [-e.subs(zero) for e in self.equations()]
        K = matrix(SR, n + m, n + m)
        K.set_block(0, 0, M)
        if m:
            K.set_block(0, n, -G.transpose())
            K.set_block(n, 0, G)
        if is_singular(K):
            raise ModelError("the equations cannot be solved for the accelerations and "
                             "multipliers (the matrix [[M, -J^T], [J, 0]] is singular)")
        return K, F + h, ddq + multipliers

    @cached_method
    def accelerations_and_multipliers(self):
        r"""
        The accelerations and the multipliers, solved from the `n` equations
        together with the twice-differentiated constraints (Lagrange's
        equations of the first kind).

        With `E = M\ddot q - F - J^T\mu` and
        `\ddot f = J\ddot q + b(q, \dot q, t)`, the linear system
        `\begin{pmatrix} M & -J^T \\ J & 0\end{pmatrix}
        \begin{pmatrix}\ddot q \\ \mu\end{pmatrix}
        = \begin{pmatrix} F \\ -b\end{pmatrix}` is solved exactly.
        `J^T\mu` is the generalized constraint force.

        OUTPUT: a dict ``{ddq_i: ..., mu_j: ...}`` of functions of `q`,
        `\dot q` and `t` (valid on the constraint surface, where
        `f = \dot f = 0`).

        EXAMPLES:

        A pendulum of length `l` in Cartesian coordinates: with
        `x = l\sin\theta`, `y = -l\cos\theta` the tension of the rod is
        `-2\mu_1 l = m(l\dot\theta^2 + g\cos\theta)` [Gol2002]_::

            sage: from sage_dynsym import Lagrangian
            sage: from sage_dynsym.dynamics.lagrange_equations import LagrangeEquations
            sage: x, y, dx, dy, m, g, l, th, dth = var('x y dx dy m g l theta dtheta')
            sage: L = Lagrangian(m*(dx^2 + dy^2)/2 - m*g*y, [x, y], constraints=[x^2 + y^2 - l^2])
            sage: sol = LagrangeEquations(L).accelerations_and_multipliers(); sol
            {ddx: (g*x*y - (dx^2 + dy^2)*x)/(x^2 + y^2),
             ddy: -(g*x^2 + (dx^2 + dy^2)*y)/(x^2 + y^2),
             mu1: 1/2*(g*m*y - (dx^2 + dy^2)*m)/(x^2 + y^2)}
            sage: polar = {x: l*sin(th), y: -l*cos(th), dx: l*cos(th)*dth, dy: l*sin(th)*dth}
            sage: (-2*sol[L.multipliers()[0]]*l).subs(polar).full_simplify()
            dtheta^2*l*m + g*m*cos(theta)

        Without constraints, the accelerations alone::

            sage: LagrangeEquations(Lagrangian(m*dx^2/2 - x^2/2, [x])).accelerations_and_multipliers()
            {ddx: -x/m}

        TESTS::

            sage: LagrangeEquations(Lagrangian(-sqrt(1 - dx^2), [x], constraints=[x - var('t')])).accelerations_and_multipliers()
            Traceback (most recent call last):
            ...
            ModelError: the Lagrangian is not quadratic in the velocities (dx)

        REFERENCES:

        .. [Gol2002] H. Goldstein, C. Poole, J. Safko, *Classical Mechanics*,
           3rd ed., Addison-Wesley 2002, section 2.4 (Lagrange multipliers
           and forces of constraint).
        """
        K, rhs, unknowns = self.acceleration_system()
        return dict(zip(unknowns, self._solve(K, rhs)))

    def _solve(self, K, rhs):
        # the solution of K x = rhs, each entry simplified
        X = K.solve_right(matrix(SR, [[v] for v in rhs]))
        return [X[i, 0].simplify_rational() for i in range(X.nrows())]

    def accelerations_solved(self):
        r"""
        The equations solved for the accelerations: a list of expressions
        `\ddot q_i = f_i(q, \dot q, t)` (only for natural Lagrangians with an
        invertible mass matrix). With constraints: the accelerations of
        :meth:`accelerations_and_multipliers` (valid on the constraint
        surface).

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: from sage_dynsym.dynamics.lagrange_equations import LagrangeEquations
            sage: x, dx, m, k = var('x dx m k')
            sage: LagrangeEquations(Lagrangian(m*dx^2/2 - k*x^2/2, [x])).accelerations_solved()
            [-k*x/m]

        TESTS::

            sage: y, dy = var('y dy')
            sage: LagrangeEquations(Lagrangian(dx^2 + x*dy, [x, y])).accelerations_solved()
            Traceback (most recent call last):
            ...
            ModelError: the mass matrix is singular: the accelerations cannot be solved for
        """
        L = self._lagrangian
        if self._constraints.expressions():
            solution = self.accelerations_and_multipliers()
            return [solution[a] for a in L.accelerations()]
        A = L.mass_matrix()
        if is_singular(A):
            raise ModelError("the mass matrix is singular: the accelerations cannot be solved for")
        zero = {a: 0 for a in L.accelerations()}
        rest = matrix(SR, [[-e.subs(zero)] for e in self.equations()])
        solution = A.solve_right(rest)
        return [solution[i, 0].simplify_rational() for i in range(A.nrows())]

    def first_order_system(self):
        r"""
        The equations as a first-order system `\dot x = F(x, t)` with state
        `x = (q, \dot q)`: a pair ``(state, rhs)`` of lists.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: from sage_dynsym.dynamics.lagrange_equations import LagrangeEquations
            sage: x, dx, m, k = var('x dx m k')
            sage: LagrangeEquations(Lagrangian(m*dx^2/2 - k*x^2/2, [x])).first_order_system()
            ([x, dx], [dx, -k*x/m])
        """
        L = self._lagrangian
        return L.coordinates() + L.velocities(), L.velocities() + self.accelerations_solved()
