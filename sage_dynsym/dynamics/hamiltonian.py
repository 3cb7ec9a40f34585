r"""
Hamiltonians: the Legendre transform, and Dirac's scheme when it fails

For a regular Lagrangian the momenta `p_i = \partial L/\partial \dot q_i`
are solved for the velocities and `H = p \cdot \dot q - L` is expressed in
`(q, p, t)`; Hamilton's equations are `\dot q = \partial H/\partial p`,
`\dot p = -\partial H/\partial q + Q - \partial R/\partial \dot q` (the
non-potential forces written in phase variables).

When `\det(\partial^2 L/\partial \dot q^2) = 0` the Hamiltonian carries a
:class:`~sage_dynsym.dynamics.dirac.DiracConstraints` analysis instead: primary
constraints, the canonical Hamiltonian `H_c`, secondary constraints, their
first/second-class split and Dirac brackets.

EXAMPLES:

A charged particle in a uniform magnetic field (vector potential
`A = B/2 (-y, x, 0)`)::

    sage: from sage_dynsym import Lagrangian
    sage: x, y, dx, dy, m, e, B = var('x y dx dy m e B')
    sage: L = Lagrangian(m*(dx^2 + dy^2)/2 + e*B/2*(x*dy - y*dx), [x, y])
    sage: H = L.hamiltonian(); H
    Hamiltonian in coordinates (x, y) and momenta (p_x, p_y) : 1/8*(B*e*x - 2*p_y)^2/m + 1/8*(B*e*y + 2*p_x)^2/m
    sage: H.equations()
    [(1/2*(B*e*y + 2*p_x)/m, -1/4*(B*e*x - 2*p_y)*B*e/m),
     (-1/2*(B*e*x - 2*p_y)/m, -1/4*(B*e*y + 2*p_x)*B*e/m)]
"""
from sage.matrix.constructor import matrix
from sage.misc.cachefunc import cached_method
from sage.misc.latex import latex
from sage.structure.sage_object import SageObject
from sage.symbolic.ring import SR

from ..arguments import model_argument
from ..errors import ModelError, brief
from ..symbols import momentum, t as _t
from ..algebra.trigonometric import trig_rational_simplify, NotPolynomial
from ..analysis.motion import FirstOrderEquations
from ..numerics.methods import NumericalMethods
from .brackets import poisson_bracket
from .natural_form import Elimination, LAGRANGIAN_METHODS, LAGRANGIAN_HINT

__all__ = ['Hamiltonian']


class Hamiltonian(SageObject, NumericalMethods):
    r"""
    The Hamiltonian of a :class:`~sage_dynsym.dynamics.lagrangian.Lagrangian`.

    INPUT:

    - ``lagrangian`` -- a Lagrangian (natural or not; regular or singular)
    - ``momenta`` -- (default: ``p_<q>``) symbols of the momenta

    EXAMPLES::

        sage: from sage_dynsym import Lagrangian
        sage: x, dx, m, k, c = var('x dx m k c')
        sage: H = Lagrangian(m*dx^2/2 - k*x^2/2, [x], dissipation=c*dx^2/2).hamiltonian()
        sage: H.expr(), H.coordinates(), H.momenta()
        (1/2*k*x^2 + 1/2*p_x^2/m, [x], [p_x])
        sage: H.equations()
        [(p_x/m, -k*x - c*p_x/m)]
        sage: H.velocities()
        [p_x/m]

    A Lagrangian that is not quadratic in the velocities is inverted with
    Sage's solver (here with the assumption `m > 0` it needs)::

        sage: assume(m > 0)
        sage: H = Lagrangian(-m*sqrt(1 - dx^2), [x]).hamiltonian(); H.expr()
        sqrt(m^2 + p_x^2)
        sage: forget()

    TESTS::

        sage: Lagrangian(exp(dx) + dx, [x]).hamiltonian().expr()
        p_x*(log(p_x - 1) - 1) - log(p_x - 1) + 1
    """

    def __init__(self, lagrangian, momenta=None):
        self._lagrangian = model_argument(lagrangian, LAGRANGIAN_METHODS, "lagrangian",
                                          "a Lagrangian", hint=LAGRANGIAN_HINT)
        self._coordinates = lagrangian.coordinates()
        if momenta is None:
            momenta = [momentum(q) for q in self._coordinates]
        self._momenta = [SR(p) for p in momenta]
        self._dirac = None
        if lagrangian.is_singular():
            from .dirac import DiracConstraints
            self._dirac = DiracConstraints(lagrangian, self._momenta)
            self._velocity_map = self._dirac.velocity_map()
            self._expr = self._dirac.canonical_hamiltonian()
        elif lagrangian.is_natural():
            self._legendre_natural()
        else:
            self._legendre_general()

    def _legendre_natural(self):
        A, A1, A0 = self._lagrangian.decomposition()
        n = A.nrows()
        shifted = [p - a for p, a in zip(self._momenta, A1)]
        velocities = self._lagrangian.velocities()
        try:
            elimination = Elimination(A)
        except NotPolynomial:
            elimination = None
        if elimination is not None:
            # H = 1/2 (p - A1) A^{-1} (p - A1) - A0 as a sum of squares over
            # the pivots of A (textbook form, e.g. the heavy top's
            # p_theta^2/(2A) + (p_psi - p_phi cos)^2/(2A sin^2) + p_phi^2/(2C))
            self._expr = (SR(0).add(*elimination.squares(shifted, self._momenta)) / 2
                          - trig_rational_simplify(A0))
            # dq = A^{-1} (p - A1) = dH/dp, in the (compact) form of H
            self._velocity_map = {v: self._expr.diff(p) for v, p in
                                  zip(velocities, self._momenta)}
            return
        # mass matrices too large for the simplifications (or with inexact
        # numbers): dq = A^{-1} (p - A1) with A^{-1} = adj(A)/det(A),
        # each entry normalized by GiNaC (cancelling common factors): no
        # Gaussian elimination with symbolic pivots, no Maxima
        if A.is_diagonal():
            inverse = matrix(SR, n, n, {(i, i): 1 / A[i, i] for i in range(n)})
        else:
            det = A.det()
            inverse = A.adjugate().apply_map(lambda e: (e / det).normalize())
        self._velocity_map = {v: sum(inverse[i, j] * shifted[j] for j in range(n))
                              for i, v in enumerate(velocities)}
        quadratic = sum(inverse[i, i] * shifted[i] ** 2 for i in range(n)) / 2 + sum(
            inverse[i, j] * shifted[i] * shifted[j] for i in range(n) for j in range(i + 1, n))
        self._expr = quadratic - A0

    def _legendre_general(self):
        from sage.symbolic.relation import solve
        velocities = self._lagrangian.velocities()
        equations = [p == pi for p, pi in zip(self._momenta,
                                              self._lagrangian.generalized_momenta())]
        solutions = solve(equations, velocities, solution_dict=True, to_poly_solve=True)
        if len(solutions) != 1 or any(v not in solutions[0] or
                                      any(solutions[0][v].has(w) for w in velocities)
                                      for v in velocities):
            raise ModelError("cannot invert the momentum map p = dL/d(dq) "
                             f"uniquely for {velocities}: solutions {solutions}",
                             entry="lagrangian")
        self._velocity_map = {v: solutions[0][v] for v in velocities}
        H = sum(p * v for p, v in zip(self._momenta, velocities)) - self._lagrangian.expr()
        self._expr = H.subs(self._velocity_map).simplify_full()

    def __eq__(self, other):
        r"""
        Hamiltonians are values: equal when made from equal Lagrangians with
        the same momenta.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, dx = var('x dx')
            sage: L = Lagrangian(dx^2/2 - x^2/2, [x])
            sage: L.hamiltonian() == Lagrangian(dx^2/2 - x^2/2, [x]).hamiltonian()
            True
        """
        return isinstance(other, Hamiltonian) and self._lagrangian == other._lagrangian and \
            all(a.is_trivially_equal(b) for a, b in zip(self._momenta, other._momenta))

    def __ne__(self, other):
        return not self == other

    def __hash__(self):
        return hash((hash(self._lagrangian), tuple(hash(p) for p in self._momenta)))

    def __reduce__(self):
        r"""
        Pickling: the Lagrangian and the momenta.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, dx, m, k = var('x dx m k')
            sage: H = Lagrangian(m*dx^2/2 - k*x^2/2, [x]).hamiltonian()
            sage: loads(dumps(H)) == H
            True
            sage: TestSuite(H).run()
        """
        return (Hamiltonian, (self._lagrangian, self._momenta))

    def equations_record(self):
        r"""
        Hamilton's equations as neutral data for the analysis
        (:class:`~sage_dynsym.analysis.motion.FirstOrderEquations` in the
        coordinates, then the momenta).

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, dx = var('x dx')
            sage: Lagrangian(dx^2/2 - x^2/2, [x]).hamiltonian().equations_record().rhs()
            [p_x, -x]
        """
        pairs = self.equations()
        return FirstOrderEquations([a for a, _ in pairs] + [b for _, b in pairs],
                                   list(self._coordinates) + list(self._momenta))

    def conserved_energy(self):
        r"""
        `H` when it is conserved: no explicit time, no dissipation or
        generalized forces, a regular Lagrangian; else ``None``.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, dx, c = var('x dx c')
            sage: H = Lagrangian(dx^2/2 - x^2/2, [x]).hamiltonian()
            sage: H.conserved_energy()
            1/2*p_x^2 + 1/2*x^2
            sage: T = H.simulate({}, {x: 1, 'p_x': 0}, 2*pi, points=3)
            sage: T.values(x).round(8), T.energy_drift() < 1e-9
            (array([ 1., -1.,  1.]), True)
            sage: Lagrangian(dx^2/2 - x^2/2, [x], dissipation=c*dx^2/2).hamiltonian().conserved_energy() is None
            True
        """
        if self._dirac is not None or self._expr.has(_t) or any(
                not F.is_zero() for F in self._nonpotential_forces()):
            return None
        return self._expr

    def _conserved_energy(self):
        # the hook of NumericalMethods
        return self.conserved_energy()

    def _repr_(self):
        kind = "Hamiltonian" if self._dirac is None else "Canonical Hamiltonian (singular Lagrangian)"
        return (f"{kind} in coordinates ({', '.join(map(str, self._coordinates))}) and "
                f"momenta ({', '.join(map(str, self._momenta))}) : {self._expr}")

    def _latex_(self):
        return "H = " + latex(self._expr)

    def expr(self):
        r"""
        `H(q, p, t)`; for a singular Lagrangian, the canonical Hamiltonian
        `H_c` (defined up to the primary constraints).

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, dx = var('x dx')
            sage: Lagrangian(dx^2/2 - x^2/2, [x]).hamiltonian().expr()
            1/2*p_x^2 + 1/2*x^2
        """
        return self._expr

    def positive_parameters(self):
        r"""
        The parameters declared positive (those of the Lagrangian): the
        values given to :meth:`subs`, :meth:`numerical_rhs` and
        :meth:`simulate` must respect them.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, dx, m, k = var('x dx m k')
            sage: H = Lagrangian(m*dx^2/2 - k*x^2/2, [x], positive=[m]).hamiltonian()
            sage: H.positive_parameters()
            [m]
            sage: H.numerical_rhs({m: -1, k: 1})
            Traceback (most recent call last):
            ...
            ModelError: values: m is declared positive, got -1
        """
        return self._lagrangian.positive_parameters()

    def subs(self, values):
        r"""
        The Hamiltonian of the Lagrangian with the parameter values
        ``values`` (a dict; exact numbers or floats, a float being the exact
        decimal it prints as) substituted.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, dx, m, k = var('x dx m k')
            sage: H = Lagrangian(m*dx^2/2 - k*x^2/2, [x]).hamiltonian()
            sage: H.subs({m: 2, k: 0.5}).expr()
            1/4*p_x^2 + 1/4*x^2
        """
        if not isinstance(values, dict):
            raise ModelError(f"expected a dict {{parameter: value}}, got {brief(values)}",
                             entry="subs")
        return Hamiltonian(self._lagrangian.subs(values), self._momenta)

    def coordinates(self):
        r"""
        The coordinates `q` (a new list).

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: Lagrangian(var('dx')^2, [var('x')]).hamiltonian().coordinates()
            [x]
        """
        return list(self._coordinates)

    def momenta(self):
        r"""
        The momentum symbols `p` (a new list), in the order of the coordinates.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: Lagrangian(var('dx')^2, [var('x')]).hamiltonian().momenta()
            [p_x]
        """
        return list(self._momenta)

    def lagrangian(self):
        r"""
        The Lagrangian this Hamiltonian was obtained from.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: L = Lagrangian(var('dx')^2, [var('x')])
            sage: L.hamiltonian().lagrangian() is L
            True
        """
        return self._lagrangian

    def velocities(self):
        r"""
        The velocities as functions of `(q, p, t)` (for a singular
        Lagrangian: one particular solution, the undetermined velocities
        set to zero).

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, dx, m = var('x dx m')
            sage: Lagrangian(m*dx^2/2, [x]).hamiltonian().velocities()
            [p_x/m]
        """
        return [self._velocity_map[v] for v in self._lagrangian.velocities()]

    def is_singular(self):
        r"""
        Whether the Lagrangian is singular (Dirac's scheme applies).

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, y, dx, dy = var('x y dx dy')
            sage: Lagrangian(x*dy - y*dx, [x, y]).hamiltonian().is_singular()
            True
        """
        return self._dirac is not None

    def constraints(self):
        r"""
        Dirac's constraint analysis (``None`` for a regular Lagrangian).

        See :class:`~sage_dynsym.dynamics.dirac.DiracConstraints`.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, y, dx, dy = var('x y dx dy')
            sage: Lagrangian(x*dy - y*dx - x^2 - y^2, [x, y]).hamiltonian().constraints()
            Dirac constraints: 2 second-class, 0 first-class
            sage: Lagrangian(dx^2 + dy^2, [x, y]).hamiltonian().constraints() is None
            True
        """
        return self._dirac

    def poisson_bracket(self, f, g):
        r"""
        The canonical Poisson bracket `\{f, g\}` in this Hamiltonian's
        variables.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, dx = var('x dx')
            sage: H = Lagrangian(dx^2/2 - x^2/2, [x]).hamiltonian()
            sage: H.poisson_bracket(x, H.expr())
            p_x
        """
        return poisson_bracket(f, g, self._coordinates, self._momenta)

    def _nonpotential_forces(self):
        L = self._lagrangian
        return [(Q - L.dissipation().diff(v)).subs(self._velocity_map)
                for v, Q in zip(L.velocities(), L.generalized_forces())]

    @cached_method
    def equations(self):
        r"""
        Hamilton's equations as a list of pairs
        `(\dot q_i, \dot p_i)` of right-hand sides, one pair per coordinate.

        For a singular Lagrangian these are the Hamilton--Dirac equations
        `\dot f = \{f, H_c + \sum_k v_k \varphi_k\}_D` with Dirac brackets for
        the second-class constraints and arbitrary multipliers `v_k` for the
        first-class primary constraints `\varphi_k` (gauge freedom).

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, y, dx, dy = var('x y dx dy')
            sage: H = Lagrangian(x*dy - y*dx - x^2 - y^2, [x, y]).hamiltonian()
            sage: H.equations()
            [(-y, -x), (x, -y)]

        These agree with the Lagrange equations `\dot x = -y`, `\dot y = x`
        (and `p_x = -y`, `p_y = x` on the constraint surface).
        """
        if self._dirac is not None:
            return self._dirac.equations()
        H = self._expr
        return [(H.diff(p), -H.diff(q) + F)
                for q, p, F in zip(self._coordinates, self._momenta,
                                   self._nonpotential_forces())]
