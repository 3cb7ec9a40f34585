r"""
Lagrangians with constraints on the velocities (nonholonomic systems)

A wheel rolling without slipping, a knife edge, a skate: their constraints
restrict the velocities, `g_k = a_k(q, t)\cdot\dot q + b_k(q, t) = 0`,
without restricting the positions reachable. Lagrange's equations get one
multiplier `\lambda_k` per velocity constraint, as for holonomic ones
(d'Alembert's principle with the virtual displacements allowed by the
constraints [NF1972]_):

.. MATH::

    E_i = \frac{d}{dt}\frac{\partial L}{\partial \dot q_i}
          - \frac{\partial L}{\partial q_i}
          + \frac{\partial R}{\partial \dot q_i} - Q_i
          - \sum_j \mu_j \frac{\partial f_j}{\partial q_i}
          - \sum_k \lambda_k \frac{\partial g_k}{\partial \dot q_i} = 0,

i.e. `M\ddot q = F + J^T\mu + A^T\lambda`: `A^T\lambda` is the generalized
force of the velocity constraints (for a rolling wheel, the friction force
at the contact). Together with the holonomic constraints differentiated
twice and the velocity constraints differentiated once they determine the
accelerations and the multipliers
(:meth:`~sage_dynsym.dynamics.lagrangian.Lagrangian.accelerations_and_multipliers`, solved by :class:`NonholonomicEquations` with the constraint set :class:`VelocityConstraints`).
:meth:`~NonholonomicLagrangian.reduced_equations` eliminates the
multipliers: Kane's equations in independent speeds
(:mod:`~sage_dynsym.dynamics.reduced`).

A velocity constraint that is the derivative of a relation between the
coordinates is holonomic and belongs with ``constraints``; the ones here
are not checked for integrability.

EXAMPLES:

A knife edge: a blade at `(x, y)` heading `\theta` cannot slide across
itself [Blo2003]_, section 1.6::

    sage: from sage_dynsym.dynamics.nonholonomic import NonholonomicLagrangian
    sage: x, y, th, dx, dy, dth, m, I = var('x y theta dx dy dtheta m I')
    sage: L = NonholonomicLagrangian(m*(dx^2 + dy^2)/2 + I*dth^2/2, [x, y, th],
    ....:                            nonholonomic=[sin(th)*dx - cos(th)*dy]); L
    Lagrangian in coordinates (x, y, theta) : 1/2*I*dtheta^2 + 1/2*(dx^2 + dy^2)*m, with velocity constraints -dy*cos(theta) + dx*sin(theta) == 0
    sage: L.lagrange_equations()
    [ddx*m - mu1*sin(theta), ddy*m + mu1*cos(theta), I*ddtheta]
    sage: L.multipliers(), L.nonholonomic_constraints()
    ([mu1], [-dy*cos(theta) + dx*sin(theta)])

The force across the blade turns the velocity with the blade:
`\lambda = -m\dot\theta(\cos\theta\,\dot x + \sin\theta\,\dot y)`::

    sage: sol = L.accelerations_and_multipliers()
    sage: sol[L.multipliers()[0]]
    -(dx*cos(theta) + dy*sin(theta))*dtheta*m

REFERENCES:

.. [NF1972] J. I. Neimark, N. A. Fufaev, *Dynamics of Nonholonomic
   Systems*, Translations of Mathematical Monographs 33, AMS 1972,
   chapters I--III.
.. [Blo2003] A. M. Bloch, *Nonholonomic Mechanics and Control*, Springer
   2003, sections 1.6--1.7 (the knife edge, the Chaplygin sleigh).
"""

from sage.matrix.constructor import matrix
from sage.misc.cachefunc import cached_method
from sage.structure.sage_object import SageObject
from sage.symbolic.ring import SR

from ..errors import AnalysisError, ModelError
from ..symbols import acceleration, constraint_multipliers, momentum, t, exact_decimals
from ..algebra.trig_linear import TrigFractionField
from ..numerics.form import velocity_constraint_terms
from .lagrangian import Lagrangian, substitution
from .lagrange_equations import LagrangeEquations
from .holonomic import zero_expression
from .natural_form import has_full_row_rank

__all__ = ['check_velocity_constraints', 'VelocityConstraints', 'NonholonomicEquations',
           'NonholonomicLagrangian']


def check_velocity_constraints(constraints, coordinates, velocities, holonomic=(),
                               parameters=None, entry="nonholonomic"):
    r"""
    The velocity constraints `g_k` as expressions (a relation ``a == b``
    becomes ``a - b``), checked: each depends on a velocity, linearly, on
    no acceleration; with ``parameters`` (a list) on no other symbol than
    the coordinates, their velocities, the parameters and ``t``; together
    with the holonomic constraints differentiated once, they are independent
    at a generic point (no redundant constraint).

    EXAMPLES::

        sage: from sage_dynsym.dynamics.nonholonomic import check_velocity_constraints
        sage: x, y, th, dx, dy, dth = var('x y theta dx dy dtheta')
        sage: check_velocity_constraints([sin(th)*dx == cos(th)*dy], [x, y, th], [dx, dy, dth])
        [-dy*cos(theta) + dx*sin(theta)]

    TESTS::

        sage: check_velocity_constraints([dx^2 - dy], [x, y], [dx, dy])
        Traceback (most recent call last):
        ...
        ModelError: nonholonomic[0]: the constraint dx^2 - dy == 0 is not linear in the velocities dx, dy
        sage: check_velocity_constraints([x - y], [x, y], [dx, dy])
        Traceback (most recent call last):
        ...
        ModelError: nonholonomic[0]: the constraint x - y == 0 does not depend on the velocities: a relation f(q, t) == 0 between the coordinates is a holonomic constraint (constraints)
        sage: check_velocity_constraints([var('ddx')], [x], [dx])
        Traceback (most recent call last):
        ...
        ModelError: nonholonomic[0]: a velocity constraint cannot depend on the acceleration ddx
        sage: check_velocity_constraints([dx - dy, 2*dy - 2*dx], [x, y], [dx, dy])
        Traceback (most recent call last):
        ...
        ModelError: nonholonomic: the constraints are not independent: with the holonomic ones differentiated, their matrix of velocity coefficients has rank less than 2 at a generic point; remove the redundant ones
        sage: check_velocity_constraints([dx - y], [x, y], [dx, dy], holonomic=[x - y])
        [dx - y]
        sage: check_velocity_constraints([dx - dy], [x, y], [dx, dy], holonomic=[x - y])
        Traceback (most recent call last):
        ...
        ModelError: nonholonomic: the constraints are not independent: with the holonomic ones differentiated, their matrix of velocity coefficients has rank less than 2 at a generic point; remove the redundant ones
        sage: check_velocity_constraints([dx - var('k')], [x], [dx], parameters=[])
        Traceback (most recent call last):
        ...
        ModelError: nonholonomic[0]: undeclared symbol k; declared are: t
        sage: check_velocity_constraints([dx < 1], [x], [dx])
        Traceback (most recent call last):
        ...
        ModelError: nonholonomic[0]: expected an expression g meaning g = 0 or an equation, got the relation dx < 1
    """
    coordinates, velocities = list(coordinates), list(velocities)
    accelerations = [acceleration(q) for q in coordinates]
    out = []
    for i, g in enumerate(constraints):
        sub = f"{entry}[{i}]"
        if isinstance(g, str):
            raise ModelError(f"expected an expression or a relation, got {g!r}", entry=sub)
        g = zero_expression(SR(g), "g", sub)
        for a in accelerations:
            if g.has(a):
                raise ModelError(f"a velocity constraint cannot depend on the acceleration {a}",
                                 entry=sub)
        if not any(g.has(v) for v in velocities):
            raise ModelError(f"the constraint {g} == 0 does not depend on the velocities: a "
                             "relation f(q, t) == 0 between the coordinates is a holonomic "
                             "constraint (constraints)", entry=sub)
        gradient = [g.diff(v) for v in velocities]
        if any(a.has(v) for a in gradient for v in velocities):
            raise ModelError(f"the constraint {g} == 0 is not linear in the velocities "
                             f"{', '.join(map(str, velocities))}", entry=sub)
        if parameters is not None:
            declared = set(coordinates) | set(velocities) | set(parameters) | {t}
            for v in g.variables():
                if v not in declared:
                    raise ModelError(f"undeclared symbol {v}; declared are: "
                                     + ", ".join(sorted(map(str, list(parameters) + [t]))),
                                     entry=sub)
        out.append(g)
    if out:
        rows = [[SR(f).diff(q) for q in coordinates] for f in holonomic]
        rows += [[g.diff(v) for v in velocities] for g in out]
        if len(rows) > len(velocities) or not has_full_row_rank(rows):
            raise ModelError("the constraints are not independent: with the holonomic ones "
                             "differentiated, their matrix of velocity coefficients has rank "
                             f"less than {len(rows)} at a generic point; remove the redundant "
                             "ones", entry=entry)
    return out


class VelocityConstraints(SageObject):
    r"""
    A constraint set with constraints on the velocities: the holonomic
    constraints of a :class:`~sage_dynsym.dynamics.holonomic.HolonomicConstraints`
    and the velocity constraints `g_k = A_k(q, t)\dot q + b_k(q, t) = 0`
    with their multipliers `\lambda_k`, which follow those of the holonomic
    ones. It has the interface of
    :class:`~sage_dynsym.dynamics.holonomic.HolonomicConstraints`, the
    generalized constraint forces being `J^T\mu + A^T\lambda`.

    INPUT:

    - ``coordinates``, ``velocities`` -- the coordinates `q` and their
      velocity symbols
    - ``holonomic`` -- the
      :class:`~sage_dynsym.dynamics.holonomic.HolonomicConstraints`
    - ``nonholonomic`` -- the velocity constraints, checked by
      :func:`check_velocity_constraints`
    - ``taken`` -- (optional) a function without arguments returning the
      other expressions of the model: the multipliers avoid their symbols

    EXAMPLES::

        sage: from sage_dynsym.dynamics.holonomic import HolonomicConstraints
        sage: from sage_dynsym.dynamics.nonholonomic import VelocityConstraints
        sage: x, y, dx, dy = var('x y dx dy')
        sage: H = HolonomicConstraints([x, y], [dx, dy])
        sage: C = VelocityConstraints([x, y], [dx, dy], H, [y*dx - dy]); C
        Velocity constraints dx*y - dy == 0 with multipliers mu1
        sage: C.generalized_forces(), C.multipliers(), C.velocity_multipliers()
        ([mu1*y, -mu1], [mu1], [mu1])
        sage: C.acceleration_constraints()
        ([ y -1], [-dx*dy], [mu1])
    """

    def __init__(self, coordinates, velocities, holonomic, nonholonomic, taken=None):
        self._coordinates, self._velocities = list(coordinates), list(velocities)
        self._holonomic = holonomic
        self._nonholonomic = check_velocity_constraints(nonholonomic, self._coordinates,
                                                        self._velocities, holonomic.expressions())
        self._lambdas = []
        if self._nonholonomic:
            used = set().union(*(SR(e).variables() for e in (taken() if taken else [])
                                 + holonomic.expressions() + self._nonholonomic))
            used |= {momentum(q) for q in self._coordinates} | set(holonomic.multipliers())
            self._lambdas = constraint_multipliers(len(self._nonholonomic), used)

    def _repr_(self):
        return ("Velocity constraints " + ", ".join(f"{g} == 0" for g in self._nonholonomic)
                + " with multipliers " + ", ".join(map(str, self._lambdas))
                + ("; " + repr(self._holonomic) if self._holonomic.expressions() else ""))

    def expressions(self):
        r"""
        The holonomic constraints `f_j(q, t)`.

        EXAMPLES::

            sage: from sage_dynsym.dynamics.holonomic import HolonomicConstraints
            sage: from sage_dynsym.dynamics.nonholonomic import VelocityConstraints
            sage: x, y, dx, dy = var('x y dx dy')
            sage: H = HolonomicConstraints([x, y], [dx, dy], [x - y^2])
            sage: VelocityConstraints([x, y], [dx, dy], H, [dx - x*dy]).expressions()
            [-y^2 + x]
        """
        return self._holonomic.expressions()

    def multipliers(self):
        r"""
        The multipliers of all the constraints: those of the holonomic ones,
        then those of the velocity constraints.

        EXAMPLES: see the class documentation.
        """
        return self._holonomic.multipliers() + list(self._lambdas)

    def velocity_constraints(self):
        r"""
        The velocity constraints `g_k`, each meaning `g_k = 0` (a new list).

        EXAMPLES: see the class documentation.
        """
        return list(self._nonholonomic)

    def velocity_multipliers(self):
        r"""
        The multipliers `\lambda_k` of the velocity constraints.

        EXAMPLES: see the class documentation.
        """
        return list(self._lambdas)

    def matrix(self):
        r"""
        The velocity constraints as `A(q, t)\dot q + b(q, t) = 0`: the pair
        ``(A, b)``.

        EXAMPLES::

            sage: from sage_dynsym.dynamics.holonomic import HolonomicConstraints
            sage: from sage_dynsym.dynamics.nonholonomic import VelocityConstraints
            sage: x, y, dx, dy = var('x y dx dy')
            sage: H = HolonomicConstraints([x, y], [dx, dy])
            sage: VelocityConstraints([x, y], [dx, dy], H, [dx - x*dy + 1]).matrix()
            ([ 1 -x], [1])
        """
        rows, _, b = velocity_constraint_terms(self._nonholonomic, self._coordinates,
                                               self._velocities)
        return matrix(SR, len(rows), len(self._velocities), rows), b

    def generalized_forces(self):
        r"""
        The generalized constraint forces `J^T\mu + A^T\lambda`, one per
        coordinate.

        EXAMPLES: see the class documentation.
        """
        A, _ = self.matrix()
        return [f + sum(la * A[k, i] for k, la in enumerate(self._lambdas))
                for i, f in enumerate(self._holonomic.generalized_forces())]

    def acceleration_constraints(self):
        r"""
        The constraints at the level of accelerations, `G\ddot q = h`: the
        holonomic ones differentiated twice, then the velocity constraints
        differentiated once (:func:`~sage_dynsym.numerics.form.velocity_constraint_terms`).

        OUTPUT: a triple ``(G, h, multipliers)``

        EXAMPLES: see the class documentation.
        """
        G, h, multipliers = self._holonomic.acceleration_constraints()
        rows, gamma, _ = velocity_constraint_terms(self._nonholonomic, self._coordinates,
                                                   self._velocities)
        A = matrix(SR, len(rows), len(self._velocities), rows)
        return G.stack(A), h + gamma, multipliers + self._lambdas


class NonholonomicEquations(LagrangeEquations):
    r"""
    The Lagrange equations with velocity constraints: those of
    :class:`~sage_dynsym.dynamics.lagrange_equations.LagrangeEquations`,
    the accelerations and multipliers solved exactly modulo
    `\cos^2 + \sin^2 = 1` where the equations are rational in the sines and
    cosines (see :mod:`~sage_dynsym.algebra.trig_linear`), the accelerations
    always through them.

    INPUT: as :class:`~sage_dynsym.dynamics.lagrange_equations.LagrangeEquations`

    EXAMPLES::

        sage: from sage_dynsym.dynamics.nonholonomic import NonholonomicLagrangian, NonholonomicEquations
        sage: x, y, dx, dy = var('x y dx dy')
        sage: L = NonholonomicLagrangian((dx^2 + dy^2)/2 - y, [x, y], nonholonomic=[dx - dy])
        sage: E = NonholonomicEquations(L); E.equations()
        [ddx - mu1, ddy + mu1 + 1]
        sage: E.accelerations_solved()
        [-1/2, -1/2]
    """

    def _solve(self, K, rhs):
        try:
            field = TrigFractionField(K.list() + rhs)
            X = field.solve_right(field.matrix(K), [[field(v)] for v in rhs])
            return [field.expression(x[0]) for x in X]
        except AnalysisError:   # not rational in the sines and cosines
            return super()._solve(K, rhs)

    def accelerations_solved(self):
        r"""
        The accelerations of :meth:`~sage_dynsym.dynamics.lagrange_equations.LagrangeEquations.accelerations_and_multipliers`
        (solved exactly where the equations are rational in the sines and
        cosines), in the order of the coordinates.

        EXAMPLES: see the class documentation.
        """
        solution = self.accelerations_and_multipliers()
        return [solution[a] for a in self.lagrangian().accelerations()]


class NonholonomicLagrangian(Lagrangian):
    r"""
    A Lagrangian with constraints on the velocities (see the module
    documentation).

    INPUT:

    - ``expr``, ``coordinates``, ``velocities`` and the keywords of
      :class:`~sage_dynsym.dynamics.lagrangian.Lagrangian` (``dissipation``,
      ``forces``, ``name``, ``decomposition``, ``equation_builder``,
      holonomic ``constraints``)
    - ``nonholonomic`` -- constraints `g_k(q, \dot q, t)` linear in the
      velocities, each meaning `g_k = 0` (or equations ``a == b``)

    The multipliers of the velocity constraints follow those of the
    holonomic ones (``mu1, mu2, ...``, see :meth:`multipliers`).

    EXAMPLES: see the module documentation. With a holonomic constraint
    too::

        sage: from sage_dynsym.dynamics.nonholonomic import NonholonomicLagrangian
        sage: x, y, z, dx, dy, dz = var('x y z dx dy dz')
        sage: L = NonholonomicLagrangian((dx^2 + dy^2 + dz^2)/2, [x, y, z], constraints=[z],
        ....:                            nonholonomic=[dx - y*dz + dy])
        sage: L.multipliers(), L.velocity_multipliers()
        ([mu1, mu2], [mu2])
        sage: L.lagrange_equations()
        [ddx - mu2, ddy - mu2, mu2*y + ddz - mu1]

    TESTS::

        sage: NonholonomicLagrangian(dx^2, [x], nonholonomic=[dx^2])
        Traceback (most recent call last):
        ...
        ModelError: nonholonomic[0]: the constraint dx^2 == 0 is not linear in the velocities dx
        sage: L.routh([x])
        Traceback (most recent call last):
        ...
        ModelError: nonholonomic: Routh's reduction does not apply with velocity constraints; use reduced_equations() (Kane's equations in independent speeds)
        sage: L.cyclic_coordinates()
        []
        sage: L.hamiltonian()
        Traceback (most recent call last):
        ...
        ModelError: nonholonomic: the Legendre transform of a Lagrangian with velocity constraints is not supported: use reduced_equations() (Kane's equations in independent speeds)
        sage: L.reduce([x, y], {z: 0})
        Traceback (most recent call last):
        ...
        ModelError: nonholonomic: reduce() does not carry velocity constraints; use reduced_equations() (Kane's equations in independent speeds)
        sage: loads(dumps(L)) == L, L == NonholonomicLagrangian((dx^2 + dy^2 + dz^2)/2, [x, y, z])
        (True, False)
        sage: L.conserved_energy()
        1/2*dx^2 + 1/2*dy^2 + 1/2*dz^2
        sage: NonholonomicLagrangian((dx^2 + dy^2)/2, [x, y], nonholonomic=[dx - 1]).conserved_energy() is None
        True
        sage: NonholonomicLagrangian((dx^2 + dy^2)/2, [x, y], nonholonomic=[dx - y*dy]).equations_record()
        Second-order equations in (x, y): [ddx - mu1, mu1*y + ddy] == 0 with velocity constraints [-dy*y + dx] == 0

    Its equations take the constraint forces along the rows the numerics
    impose on the accelerations, and its conserved energy is an integral
    of its equations::

        sage: TestSuite(L).run()
    """

    def __init__(self, expr, coordinates, velocities=None, *, nonholonomic=(), **options):
        super().__init__(expr, coordinates, velocities, **options)
        self._constraint_set = VelocityConstraints(
            self.coordinates(), self.velocities(), self.constraint_set(), nonholonomic,
            taken=lambda: [self.expr(), self.dissipation()] + self.generalized_forces())

    @cached_method
    def _equations_method(self):
        return NonholonomicEquations(self, self.constraint_set())

    def _test_constraint_forces(self, **options):
        r"""The equations contain each multiplier `\mu_k` with the
        coefficients `-G_k` (the forces `G^T\mu` moved to the left), where
        `G\ddot q = h` are the constraints on the accelerations that the
        numerics impose (:meth:`acceleration_constraints
        <sage_dynsym.dynamics.nonholonomic.VelocityConstraints.acceleration_constraints>`):
        the holonomic rows first, then those of the velocity constraints.

        EXAMPLES: run by ``TestSuite`` (see the class).
        """
        tester = self._tester(**options)
        G, _, multipliers = self.constraint_set().acceleration_constraints()
        tester.assertEqual(multipliers, self.multipliers())
        equations = self.lagrange_equations()
        for mu, row in zip(multipliers, G.rows()):
            for e, a in zip(equations, row):
                tester.assertTrue(bool((SR(e).diff(mu) + a).simplify_full() == 0),
                                  f"the coefficient of {mu} in {e} is not {-a}")

    def velocity_constraint_matrix(self):
        r"""
        The velocity constraints as `A(q, t)\dot q + b(q, t) = 0`: the pair
        ``(A, b)``.

        EXAMPLES::

            sage: from sage_dynsym.dynamics.nonholonomic import NonholonomicLagrangian
            sage: x, y, th, dx, dy, dth = var('x y theta dx dy dtheta')
            sage: L = NonholonomicLagrangian((dx^2 + dy^2 + dth^2)/2, [x, y, th],
            ....:                            nonholonomic=[sin(th)*dx - cos(th)*dy])
            sage: L.velocity_constraint_matrix()
            ([ sin(theta) -cos(theta)           0], [0])
        """
        return self.constraint_set().matrix()

    def reduced_equations(self, speeds=None):
        r"""
        Kane's equations in independent speeds: see
        :class:`~sage_dynsym.dynamics.reduced.ReducedEquations`.

        EXAMPLES::

            sage: from sage_dynsym.dynamics.nonholonomic import NonholonomicLagrangian
            sage: x, y, dx, dy = var('x y dx dy')
            sage: L = NonholonomicLagrangian((dx^2 + dy^2)/2 - y, [x, y], nonholonomic=[dx - dy])
            sage: L.reduced_equations([dy]).equations()
            [2*ddy + 1]
        """
        from .reduced import ReducedEquations
        return ReducedEquations(self, speeds)

    # ------------------------------------------------------------------
    # value semantics and derived Lagrangians

    def _content(self):
        return super()._content() + (tuple(self.nonholonomic_constraints()),)

    def __reduce__(self):
        function, (expr, coordinates, velocities, keywords) = super().__reduce__()
        return (_rebuild, (expr, coordinates, velocities,
                           dict(keywords, nonholonomic=self.nonholonomic_constraints())))

    def _repr_(self):
        return super()._repr_() + ", with velocity constraints " + ", ".join(
            f"{g} == 0" for g in self.nonholonomic_constraints())

    def _latex_(self):
        from sage.misc.latex import latex
        return super()._latex_() + "".join(r", \quad " + latex(g) + " = 0"
                                           for g in self.nonholonomic_constraints())

    def _derived(self, expr, **changes):
        options = dict(velocities=self.velocities(), dissipation=self.dissipation(),
                       forces=self.generalized_forces(), name=self.name(),
                       constraints=self.constraints(),
                       nonholonomic=self.nonholonomic_constraints(),
                       positive=self.positive_parameters())
        options.update(changes)
        coordinates = options.pop('coordinates', self.coordinates())
        return NonholonomicLagrangian(expr, coordinates, **options)

    def subs(self, *args, **kwds):
        r"""
        Substitute values for parameters, also in the velocity constraints
        (see :meth:`Lagrangian.subs <sage_dynsym.dynamics.lagrangian.Lagrangian.subs>`).

        EXAMPLES::

            sage: from sage_dynsym.dynamics.nonholonomic import NonholonomicLagrangian
            sage: x, y, dx, dy, r = var('x y dx dy r')
            sage: L = NonholonomicLagrangian((dx^2 + dy^2)/2, [x, y], nonholonomic=[dx - r*dy])
            sage: L.subs(r=2).nonholonomic_constraints()
            [dx - 2*dy]
        """
        derived = super().subs(*args, **kwds)
        args = [substitution(a) for a in args]
        kwds = {k: exact_decimals(v) for k, v in kwds.items()}
        return derived._derived(derived.expr(), nonholonomic=[
            g.subs(*args, **kwds) for g in self.nonholonomic_constraints()])


def _rebuild(expr, coordinates, velocities, keywords):
    return NonholonomicLagrangian(expr, coordinates, velocities, **keywords)
