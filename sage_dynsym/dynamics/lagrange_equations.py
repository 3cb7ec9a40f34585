r"""
The Lagrange equations of the second kind

:class:`LagrangeEquations` is a base class of
:class:`~sage_dynsym.dynamics.lagrangian.Lagrangian`: the equations (5),
in the structured form assembled from the decomposition (4) of a natural
Lagrangian (see :mod:`~sage_dynsym.dynamics.natural_equations`) or
differentiated directly, with the dissipation function, the generalized
forces and the constraint forces; the neutral record of the equations, and
the equations solved for the accelerations.

EXAMPLES::

    sage: from sage_dynsym import Lagrangian
    sage: r, phi, dr, dphi, m, k = var('r phi dr dphi m k')
    sage: L = Lagrangian(m*(dr^2 + r^2*dphi^2)/2 - k*r^2/2, [r, phi])
    sage: L.accelerations_solved()      # the equations (5) solved for ddr, ddphi
    [(dphi^2*m - k)*r/m, -2*dphi*dr/r]
"""
from sage.matrix.constructor import matrix
from sage.misc.cachefunc import cached_method
from sage.symbolic.ring import SR

from ..errors import ModelError
from ..symbols import time_derivative
from ..analysis.motion import SecondOrderEquations
from .natural_equations import natural_equations, SymbolicCalculus
from .compact import equations_cse
from .natural_form import is_singular

__all__ = ['LagrangeEquations']


class LagrangeEquations:
    r"""
    The Lagrange equations of a
    :class:`~sage_dynsym.dynamics.lagrangian.Lagrangian` (a base class of
    it, see the module documentation).

    EXAMPLES: see :class:`~sage_dynsym.dynamics.lagrangian.Lagrangian`.
    """

    def _nonpotential_terms(self):
        return [self._dissipation.diff(v) - Q
                for v, Q in zip(self._velocities, self._forces)]

    @cached_method
    def lagrange_equations(self, form=None):
        r"""
        The Lagrange equations of the second kind (5), with dissipation and
        generalized forces: a list of expressions `E_i` meaning `E_i = 0`.

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
            sage: r, phi, dr, dphi, m, k = var('r phi dr dphi m k')
            sage: L = Lagrangian(m*(dr^2 + r^2*dphi^2)/2 - k*r^2/2, [r, phi])
            sage: L.lagrange_equations()
            [-dphi^2*m*r + ddr*m + k*r, 2*dphi*dr*m*r + ddphi*m*r^2]

        A relativistic particle (not natural) is differentiated directly::

            sage: x, dx = var('x dx')
            sage: Lagrangian(-sqrt(1 - dx^2), [x]).lagrange_equations()
            [ddx*(dx^2/(-dx^2 + 1)^(3/2) + 1/sqrt(-dx^2 + 1))]

        TESTS::

            sage: t = var('t')
            sage: L = Lagrangian(m*(dr^2 + r^2*dphi^2)/2 + r*dphi*t, [r, phi])
            sage: S, D = L.lagrange_equations('structured'), L.lagrange_equations('direct')
            sage: all(bool((s - d).expand() == 0) for s, d in zip(S, D))
            True
            sage: L.lagrange_equations('nonsense')
            Traceback (most recent call last):
            ...
            ModelError: form: expected 'structured' or 'direct', got 'nonsense'
        """
        if form is None:
            form = "structured" if self.is_natural() else "direct"
        if form == "structured":
            equations = self._structured_equations()
        elif form == "direct":
            equations = self._direct_equations()
        else:
            raise ModelError(f"expected 'structured' or 'direct', got {form!r}", entry='form')
        return [e + extra - force for e, extra, force in
                zip(equations, self._nonpotential_terms(), self._constraint_forces())]

    def equations(self):
        r"""
        The equations of motion: :meth:`lagrange_equations` (the name every
        model and characteristic function of the package shares).

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, dx = var('x dx')
            sage: Lagrangian(dx^2/2 - x^2/2, [x]).equations()
            [ddx + x]
        """
        return self.lagrange_equations()

    def equations_cse(self):
        r"""
        The Lagrange equations written with their common subexpressions
        (see :func:`~sage_dynsym.dynamics.compact.equations_cse`): a compact
        form for the largest models, exactly equal to
        :meth:`lagrange_equations` after ``expand()``.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: psi, theta, dpsi, dtheta, m, l, g = var('psi theta dpsi dtheta m l g')
            sage: L = Lagrangian(m*l^2*(dtheta^2 + sin(theta)^2*dpsi^2)/2 + m*g*l*cos(theta),
            ....:                [psi, theta])
            sage: C = L.equations_cse(); C.subexpressions()
            [(x1_, cos(theta)), (x2_, sin(theta))]
            sage: C.expand() == L.lagrange_equations()
            True
        """
        return equations_cse(self.lagrange_equations())

    def equations_record(self):
        r"""
        The equations as neutral data for the analysis
        (:class:`~sage_dynsym.analysis.motion.SecondOrderEquations`, with
        the Lagrangian and its kinetic matrix).

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, dx = var('x dx')
            sage: Lagrangian(dx^2/2 - x^2/2, [x]).equations_record()
            Second-order equations in (x): [ddx + x] == 0
            sage: y, dy = var('y dy')
            sage: E = Lagrangian((dx^2 + dy^2)/2, [x, y], constraints=[x - y]).equations_record()
            sage: E.constraints(), E.multipliers()
            ([x - y], [mu1])
        """
        kinetic = self.mass_matrix() if self.is_natural() else None
        return SecondOrderEquations(self.lagrange_equations(), self._coordinates,
                                    self._velocities, self._accelerations,
                                    function=self._expr, kinetic=kinetic,
                                    constraints=self._constraints,
                                    multipliers=self._multipliers)

    def _direct_equations(self):
        q, dq, ddq = self._coordinates, self._velocities, self._accelerations
        return [time_derivative(p, q, dq, ddq) - self._expr.diff(qi)
                for qi, p in zip(q, self.generalized_momenta())]

    def _structured_equations(self):
        r"""
        Equations (5) from `A, A_1, A_0`, see
        :mod:`~sage_dynsym.dynamics.natural_equations`.
        """
        if self._equation_builder is not None:
            return self._equation_builder()
        A, A1, A0 = self.decomposition()
        return natural_equations([list(row) for row in A.rows()], list(A1), A0,
                                 self._coordinates, self._velocities, self._accelerations,
                                 SymbolicCalculus(self._coordinates))

    def accelerations_solved(self):
        r"""
        The equations solved for the accelerations: a list of expressions
        `\ddot q_i = f_i(q, \dot q, t)` (only for natural Lagrangians with an
        invertible mass matrix). With constraints: the accelerations of
        :meth:`accelerations_and_multipliers` (valid on the constraint
        surface).

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, dx, m, k = var('x dx m k')
            sage: Lagrangian(m*dx^2/2 - k*x^2/2, [x]).accelerations_solved()
            [-k*x/m]

        TESTS::

            sage: y, dy = var('y dy')
            sage: Lagrangian(dx^2 + x*dy, [x, y]).accelerations_solved()
            Traceback (most recent call last):
            ...
            ModelError: the mass matrix is singular: the accelerations cannot be solved for
        """
        if self._constraints:
            solution = self.accelerations_and_multipliers()
            return [solution[a] for a in self._accelerations]
        A = self.mass_matrix()
        if is_singular(A):
            raise ModelError("the mass matrix is singular: the accelerations cannot be solved for")
        zero = {a: 0 for a in self._accelerations}
        rest = matrix(SR, [[-e.subs(zero)] for e in self.lagrange_equations()])
        solution = A.solve_right(rest)
        return [solution[i, 0].simplify_rational() for i in range(A.nrows())]

    def first_order_system(self):
        r"""
        The equations as a first-order system `\dot x = F(x, t)` with state
        `x = (q, \dot q)`.

        OUTPUT: a pair ``(state, rhs)`` of lists.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, dx, m, k = var('x dx m k')
            sage: Lagrangian(m*dx^2/2 - k*x^2/2, [x]).first_order_system()
            ([x, dx], [dx, -k*x/m])
        """
        state = self._coordinates + self._velocities
        return state, list(self._velocities) + self.accelerations_solved()
