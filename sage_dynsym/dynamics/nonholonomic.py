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
(:meth:`~NonholonomicLagrangian.accelerations_and_multipliers`).
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
import operator

from sage.matrix.constructor import matrix
from sage.symbolic.ring import SR

from ..errors import AnalysisError, ModelError
from ..symbols import acceleration, constraint_multipliers, momentum, t, exact_decimals
from ..symbols import time_derivative
from ..analysis.motion import SecondOrderEquations
from ..algebra.trig_linear import TrigFractionField
from .lagrangian import Lagrangian, substitution
from .natural_form import has_full_row_rank

__all__ = ['check_velocity_constraints', 'NonholonomicLagrangian']


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
        g = SR(g)
        if g.is_relational():
            if g.operator() is not operator.eq:
                raise ModelError("expected an expression g meaning g = 0 or an equation, got "
                                 f"the relation {g}", entry=sub)
            g = g.lhs() - g.rhs()
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
        sage: loads(dumps(L)) == L, L == NonholonomicLagrangian((dx^2 + dy^2 + dz^2)/2, [x, y, z])
        (True, False)
    """

    def __init__(self, expr, coordinates, velocities=None, *, nonholonomic=(), **options):
        Lagrangian.__init__(self, expr, coordinates, velocities, **options)
        self._nonholonomic = check_velocity_constraints(nonholonomic, self._coordinates,
                                                        self._velocities, self._constraints)
        taken = set().union(*(SR(e).variables() for e in [self._expr, self._dissipation]
                              + self._forces + self._constraints + self._nonholonomic))
        taken |= {momentum(q) for q in self._coordinates} | set(self._multipliers)
        self._velocity_multipliers = constraint_multipliers(len(self._nonholonomic), taken)

    # ------------------------------------------------------------------
    # accessors

    def nonholonomic_constraints(self):
        r"""
        The velocity constraints `g_k`, each meaning `g_k = 0` (a new list).

        EXAMPLES::

            sage: from sage_dynsym.dynamics.nonholonomic import NonholonomicLagrangian
            sage: x, y, dx, dy = var('x y dx dy')
            sage: NonholonomicLagrangian((dx^2 + dy^2)/2, [x, y], nonholonomic=[dx - x*dy]).nonholonomic_constraints()
            [-dy*x + dx]
        """
        return list(self._nonholonomic)

    def multipliers(self):
        r"""
        The multipliers of all constraints: those of the holonomic ones
        (`\mu_j`, see :meth:`Lagrangian.multipliers
        <sage_dynsym.dynamics.lagrangian.Lagrangian.multipliers>`), then those
        of the velocity constraints (:meth:`velocity_multipliers`).

        EXAMPLES: see the class documentation.
        """
        return list(self._multipliers) + list(self._velocity_multipliers)

    def velocity_multipliers(self):
        r"""
        The multipliers `\lambda_k` of the velocity constraints: the
        equations contain `-\sum_k \lambda_k \partial g_k/\partial\dot q_i`.

        EXAMPLES: see the class documentation.
        """
        return list(self._velocity_multipliers)

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
        A = matrix(SR, len(self._nonholonomic), len(self._velocities),
                   [[g.diff(v) for v in self._velocities] for g in self._nonholonomic])
        zero = {v: 0 for v in self._velocities}
        return A, [g.subs(zero) for g in self._nonholonomic]

    # ------------------------------------------------------------------
    # equations

    def _constraint_forces(self):
        A, _ = self.velocity_constraint_matrix()
        holonomic = Lagrangian._constraint_forces(self)
        return [f + sum(la * A[k, i] for k, la in enumerate(self._velocity_multipliers))
                for i, f in enumerate(holonomic)]

    def _acceleration_constraints(self):
        # the velocity constraints differentiated once: A ddq = -(d/dt g at ddq = 0)
        G, h, multipliers = Lagrangian._acceleration_constraints(self)
        q, dq, ddq = self._coordinates, self._velocities, self._accelerations
        A, _ = self.velocity_constraint_matrix()
        zero = {a: 0 for a in ddq}
        h = h + [-time_derivative(g, q, dq, ddq).subs(zero) for g in self._nonholonomic]
        return G.stack(A), h, multipliers + self._velocity_multipliers

    def accelerations_and_multipliers(self):
        r"""
        The accelerations and the multipliers of all constraints, solved from
        the `n` equations together with the holonomic constraints
        differentiated twice and the velocity constraints differentiated once
        (see :meth:`Lagrangian.accelerations_and_multipliers
        <sage_dynsym.dynamics.lagrangian.Lagrangian.accelerations_and_multipliers>`);
        exactly, modulo `\cos^2 + \sin^2 = 1`, where the equations are
        rational in the sines and cosines (see
        :mod:`~sage_dynsym.algebra.trig_linear`).

        OUTPUT: a dict ``{ddq_i: ..., mu_j: ...}``, valid where the
        constraints hold

        EXAMPLES: see the module documentation.
        """
        if not hasattr(self, '_solved'):
            K, rhs, unknowns = self._acceleration_system()
            try:
                field = TrigFractionField(K.list() + rhs)
                X = field.solve_right(field.matrix(K), [[field(v)] for v in rhs])
                values = [field.expression(x[0]) for x in X]
            except AnalysisError:   # not rational in the sines and cosines
                X = K.solve_right(matrix(SR, [[v] for v in rhs]))
                values = [X[i, 0].simplify_rational() for i in range(len(unknowns))]
            self._solved = dict(zip(unknowns, values))
        return dict(self._solved)

    def accelerations_solved(self):
        r"""
        The accelerations of :meth:`accelerations_and_multipliers`, in the
        order of the coordinates.

        EXAMPLES::

            sage: from sage_dynsym.dynamics.nonholonomic import NonholonomicLagrangian
            sage: x, y, dx, dy = var('x y dx dy')
            sage: NonholonomicLagrangian((dx^2 + dy^2)/2 - y, [x, y], nonholonomic=[dx - dy]).accelerations_solved()
            [-1/2, -1/2]
        """
        solution = self.accelerations_and_multipliers()
        return [solution[a] for a in self._accelerations]

    def _conserved_energy(self):
        r"""
        The energy, when the velocity constraints are homogeneous and
        stationary (`b = 0`, no explicit time): then they do no work.

        EXAMPLES::

            sage: from sage_dynsym.dynamics.nonholonomic import NonholonomicLagrangian
            sage: x, y, dx, dy = var('x y dx dy')
            sage: NonholonomicLagrangian((dx^2 + dy^2)/2, [x, y], nonholonomic=[dx - y*dy])._conserved_energy()
            1/2*dx^2 + 1/2*dy^2
            sage: NonholonomicLagrangian((dx^2 + dy^2)/2, [x, y], nonholonomic=[dx - 1])._conserved_energy() is None
            True
        """
        _, b = self.velocity_constraint_matrix()
        if any(not SR(e).is_zero() for e in b) or any(g.has(t) for g in self._nonholonomic):
            return None
        return Lagrangian._conserved_energy(self)

    def equations_record(self):
        r"""
        The equations as neutral data, with the velocity constraints and
        their multipliers (see :class:`~sage_dynsym.analysis.motion.SecondOrderEquations`).

        EXAMPLES::

            sage: from sage_dynsym.dynamics.nonholonomic import NonholonomicLagrangian
            sage: x, y, dx, dy = var('x y dx dy')
            sage: NonholonomicLagrangian((dx^2 + dy^2)/2, [x, y], nonholonomic=[dx - y*dy]).equations_record()
            Second-order equations in (x, y): [ddx - mu1, mu1*y + ddy] == 0 with velocity constraints [-dy*y + dx] == 0
        """
        kinetic = self.mass_matrix() if self.is_natural() else None
        return SecondOrderEquations(self.lagrange_equations(), self._coordinates,
                                    self._velocities, self._accelerations,
                                    function=self._expr, kinetic=kinetic,
                                    constraints=self._constraints,
                                    multipliers=self._multipliers,
                                    velocity_constraints=self._nonholonomic,
                                    velocity_multipliers=self._velocity_multipliers)

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
        return Lagrangian._content(self) + (tuple(self._nonholonomic),)

    def __reduce__(self):
        function, (expr, coordinates, velocities, keywords) = Lagrangian.__reduce__(self)
        return (_rebuild, (expr, coordinates, velocities,
                           dict(keywords, nonholonomic=self._nonholonomic)))

    def _repr_(self):
        return Lagrangian._repr_(self) + ", with velocity constraints " + ", ".join(
            f"{g} == 0" for g in self._nonholonomic)

    def _latex_(self):
        from sage.misc.latex import latex
        return Lagrangian._latex_(self) + "".join(r", \quad " + latex(g) + " = 0"
                                                  for g in self._nonholonomic)

    def _derived(self, expr, **changes):
        options = dict(velocities=self._velocities, dissipation=self._dissipation,
                       forces=self._forces, name=self._name, constraints=self._constraints,
                       nonholonomic=self._nonholonomic, positive=self._positive)
        options.update(changes)
        coordinates = options.pop('coordinates', self._coordinates)
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
        derived = Lagrangian.subs(self, *args, **kwds)
        args = [substitution(a) for a in args]
        kwds = {k: exact_decimals(v) for k, v in kwds.items()}
        return derived._derived(derived.expr(), nonholonomic=[g.subs(*args, **kwds)
                                                              for g in self._nonholonomic])

    def _not_cyclic(self, q):
        reason = Lagrangian._not_cyclic(self, q)
        if reason is None:
            dq = self._velocities[self._coordinates.index(q)]
            if any(g.has(q) or g.has(dq) for g in self._nonholonomic):
                return "a velocity constraint involves it or its velocity"
        return reason

    def routh(self, cyclic):
        r"""
        Not available: the Routh function of a Lagrangian would lose the
        velocity constraints.

        EXAMPLES: see the class documentation.
        """
        raise ModelError("Routh's reduction does not apply with velocity constraints; use "
                         "reduced_equations() (Kane's equations in independent speeds)",
                         entry="nonholonomic")

    def hamiltonian(self):
        r"""
        Not available: Hamilton's equations need a Legendre transform of
        unconstrained velocities.

        EXAMPLES: see the class documentation.
        """
        raise ModelError("the Legendre transform of a Lagrangian with velocity constraints is "
                         "not supported: use reduced_equations() (Kane's equations in "
                         "independent speeds)", entry="nonholonomic")

    def reduce(self, independent, parametrization):
        r"""
        Not available: a parametrization of the holonomic constraints would
        have to be carried into the velocity constraints.

        EXAMPLES::

            sage: from sage_dynsym.dynamics.nonholonomic import NonholonomicLagrangian
            sage: x, y, dx, dy = var('x y dx dy')
            sage: NonholonomicLagrangian((dx^2 + dy^2)/2, [x, y], nonholonomic=[dx - y*dy]).reduce([x], {y: x})
            Traceback (most recent call last):
            ...
            ModelError: nonholonomic: reduce() does not carry velocity constraints; use reduced_equations() (Kane's equations in independent speeds)
        """
        raise ModelError("reduce() does not carry velocity constraints; use "
                         "reduced_equations() (Kane's equations in independent speeds)",
                         entry="nonholonomic")


def _rebuild(expr, coordinates, velocities, keywords):
    return NonholonomicLagrangian(expr, coordinates, velocities, **keywords)
