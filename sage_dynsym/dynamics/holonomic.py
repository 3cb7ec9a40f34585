r"""
Holonomic constraints: their checks, their multipliers and Lagrange's
equations of the first kind

:func:`check_constraints` reads and checks holonomic constraints
`f_j(q, t) = 0`, for a :class:`~sage_dynsym.dynamics.lagrangian.Lagrangian`
and for a :class:`~sage_dynsym.mechanics.system.MechanicalSystem` alike.
:class:`HolonomicConstraints` is the constraint set a Lagrangian holds: its
constraints, their multipliers `\mu_j`, the generalized constraint forces
`J^T\mu` and the constraints differentiated twice, which
:class:`~sage_dynsym.dynamics.lagrange_equations.LagrangeEquations` solves
with the equations (see the module documentation of
:mod:`~sage_dynsym.dynamics.lagrangian`). :func:`independent_coordinates`
is the reduction to independent coordinates.

EXAMPLES::

    sage: from sage_dynsym import Lagrangian
    sage: x, y, dx, dy, m, g, l = var('x y dx dy m g l')
    sage: L = Lagrangian(m*(dx^2 + dy^2)/2 - m*g*y, [x, y], constraints=[x^2 + y^2 == l^2])
    sage: L.constraints(), L.multipliers()
    ([-l^2 + x^2 + y^2], [mu1])
"""
import operator

from sage.matrix.constructor import matrix
from sage.structure.sage_object import SageObject
from sage.symbolic.expression import Expression
from sage.symbolic.ring import SR

from ..arguments import expression_argument
from ..errors import ModelError, brief
from ..symbols import velocity, acceleration, time_derivative, t, constraint_multipliers, momentum
from ..numerics.form import constraint_terms
from .natural_form import symbol_list, has_full_row_rank

__all__ = ['zero_expression', 'check_constraints', 'HolonomicConstraints',
           'independent_coordinates']


def zero_expression(f, name, entry):
    r"""
    The symbolic expression ``f`` read as ``f = 0``; an equation
    ``a == b`` as ``a - b``.

    INPUT:

    - ``f`` -- a symbolic expression or equation
    - ``name`` -- the letter the error message gives the expression
    - ``entry`` -- the entry named by the error

    EXAMPLES::

        sage: from sage_dynsym.dynamics.holonomic import zero_expression
        sage: x, y = var('x y')
        sage: zero_expression(x^2 + y^2 == 1, 'f', 'constraints[0]')
        x^2 + y^2 - 1
        sage: zero_expression(x < y, 'g', 'nonholonomic[0]')
        Traceback (most recent call last):
        ...
        ModelError: nonholonomic[0]: expected an expression g meaning g = 0 or an equation, got the relation x < y
    """
    if f.is_relational():
        if f.operator() is not operator.eq:
            raise ModelError(f"expected an expression {name} meaning {name} = 0 or an "
                             f"equation, got the relation {f}", entry=entry)
        f = f.lhs() - f.rhs()
    return f


def check_constraints(constraints, coordinates, parameters=None, entry="constraints",
                      velocities=None):
    r"""
    The holonomic constraints `f_j(q, t)` as expressions (an equation
    ``lhs == rhs`` becomes ``lhs - rhs``), checked: each depends on a
    coordinate and on no velocity or acceleration; with ``parameters`` (a
    list) no other symbol than coordinates, parameters and ``t``; and the
    Jacobian `\partial f_j / \partial q_i` has full rank `m` at a generic
    point (:func:`~sage_dynsym.dynamics.natural_form.has_full_row_rank`), so
    that no constraint is redundant.

    INPUT:

    - ``constraints`` -- a list of expressions `f` (each meaning `f = 0`)
      or equations
    - ``coordinates`` -- the coordinates `q`
    - ``parameters`` -- (optional) the declared parameters
    - ``entry`` -- (default: ``"constraints"``) the name of the argument
      in error messages
    - ``velocities`` -- (default: ``d<q>``) the velocity symbols

    OUTPUT: a list of expressions

    EXAMPLES::

        sage: from sage_dynsym.dynamics.holonomic import check_constraints
        sage: x, y, z, l = var('x y z l')
        sage: check_constraints([x^2 + y^2 == l^2], [x, y])
        [-l^2 + x^2 + y^2]

    TESTS::

        sage: check_constraints([x^2 + y^2 - l^2, 2*x^2 + 2*y^2 - 2*l^2], [x, y])
        Traceback (most recent call last):
        ...
        ModelError: constraints: the 2 constraints are not independent: their Jacobian with respect to the coordinates has rank less than 2 at a generic point; remove the redundant ones
        sage: check_constraints([x - y, y - z, x - z], [x, y, z])
        Traceback (most recent call last):
        ...
        ModelError: constraints: the 3 constraints are not independent: their Jacobian with respect to the coordinates has rank less than 3 at a generic point; remove the redundant ones
        sage: check_constraints([x - z], [x], parameters=[l])
        Traceback (most recent call last):
        ...
        ModelError: constraints[0]: undeclared symbol z; declared are: l, t
        sage: check_constraints(["x"], [x])
        Traceback (most recent call last):
        ...
        ModelError: constraints[0]: expected an expression f(q, t) or an equation, got 'x'
        sage: check_constraints([None], [x])
        Traceback (most recent call last):
        ...
        ModelError: constraints[0]: expected an expression f(q, t) or an equation, got None
        sage: check_constraints([x < y], [x, y])
        Traceback (most recent call last):
        ...
        ModelError: constraints[0]: expected an expression f meaning f = 0 or an equation, got the relation x < y
        sage: check_constraints([x - var('ddy')], [x, y])
        Traceback (most recent call last):
        ...
        ModelError: constraints[0]: a holonomic constraint f(q, t) cannot depend on the acceleration ddy
        sage: check_constraints(x - y, [x, y])
        Traceback (most recent call last):
        ...
        ModelError: constraints: expected a list of constraints f(q, t), got x - y
    """
    if isinstance(constraints, (str, bytes, dict, Expression)) \
            or not hasattr(constraints, '__iter__'):
        raise ModelError(f"expected a list of constraints f(q, t), got {constraints!r}",
                         entry=entry)
    if velocities is None:
        velocities = [velocity(q) for q in coordinates]
    forbidden = {}
    for q, dq in zip(coordinates, velocities):
        forbidden[dq] = f"the velocity {dq}"
        forbidden[acceleration(q)] = f"the acceleration {acceleration(q)}"
    out = []
    for i, f in enumerate(constraints):
        sub = f"{entry}[{i}]"
        try:
            # text is parsed by the description reader, never here
            if isinstance(f, (str, bytes)):
                raise TypeError
            f = SR(f)
        except (TypeError, ValueError) as err:
            raise ModelError(f"expected an expression f(q, t) or an equation, got {f!r}",
                             entry=sub) from err
        f = zero_expression(f, "f", sub)
        for v in f.variables():
            if v in forbidden:
                raise ModelError("a holonomic constraint f(q, t) cannot depend on "
                                 f"{forbidden[v]}", entry=sub)
            if parameters is not None and v not in coordinates and v not in parameters \
                    and v != t:
                raise ModelError(f"undeclared symbol {v}; declared are: "
                                 + ", ".join(sorted(map(str, list(parameters) + [t]))),
                                 entry=sub)
        if not any(f.has(q) for q in coordinates):
            raise ModelError(f"the constraint {f} == 0 does not depend on the coordinates "
                             f"{', '.join(map(str, coordinates))}", entry=sub)
        out.append(f)
    if out:
        J = [[f.diff(q) for q in coordinates] for f in out]
        if len(out) > len(coordinates) or not has_full_row_rank(J):
            raise ModelError(f"the {len(out)} constraints are not independent: their Jacobian "
                             "with respect to the coordinates has rank less than "
                             f"{len(out)} at a generic point; remove the redundant ones",
                             entry=entry)
    return out


class HolonomicConstraints(SageObject):
    r"""
    The holonomic constraints `f_j(q, t) = 0` of a Lagrangian with their
    multipliers `\mu_j`: what the equations of motion need of them, the
    generalized constraint forces `J^T\mu` and the constraints at the level
    of accelerations.

    INPUT:

    - ``coordinates``, ``velocities`` -- the coordinates `q` and their
      velocity symbols
    - ``constraints`` -- (default: none) the constraints, checked by
      :func:`check_constraints`
    - ``taken`` -- (optional) a function without arguments returning the
      other expressions of the model (the Lagrangian, the dissipation
      function, the forces): the multipliers avoid their symbols; called
      only when there are constraints

    EXAMPLES::

        sage: from sage_dynsym.dynamics.holonomic import HolonomicConstraints
        sage: x, y, dx, dy, l = var('x y dx dy l')
        sage: C = HolonomicConstraints([x, y], [dx, dy], [x^2 + y^2 == l^2]); C
        Holonomic constraints -l^2 + x^2 + y^2 == 0 with multipliers mu1
        sage: C.generalized_forces()
        [2*mu1*x, 2*mu1*y]
        sage: C.acceleration_constraints()
        ([2*x 2*y], [-2*dx^2 - 2*dy^2], [mu1])
        sage: HolonomicConstraints([x], [dx], [x], taken=lambda: [var('mu1')]).multipliers()
        [mu2]
    """

    def __init__(self, coordinates, velocities, constraints=(), taken=None):
        self._coordinates, self._velocities = list(coordinates), list(velocities)
        self._constraints = check_constraints(constraints, self._coordinates,
                                              velocities=self._velocities)
        self._multipliers = []
        if self._constraints:
            used = set().union(*(SR(e).variables() for e in
                                 (taken() if taken else []) + self._constraints))
            used |= {momentum(q) for q in self._coordinates}
            self._multipliers = constraint_multipliers(len(self._constraints), used)

    def _repr_(self):
        if not self._constraints:
            return "No holonomic constraints"
        return ("Holonomic constraints " + ", ".join(f"{f} == 0" for f in self._constraints)
                + " with multipliers " + ", ".join(map(str, self._multipliers)))

    def expressions(self):
        r"""
        The constraints `f_j(q, t)`, each meaning `f_j = 0` (a new list).

        EXAMPLES: see the class documentation.
        """
        return list(self._constraints)

    def multipliers(self):
        r"""
        The multipliers of all the constraints (here `\mu_j`, one per
        constraint; see :func:`~sage_dynsym.symbols.constraint_multipliers`).

        EXAMPLES: see the class documentation.
        """
        return list(self._multipliers)

    def velocity_constraints(self):
        r"""
        The constraints on the velocities (none here; see
        :class:`~sage_dynsym.dynamics.nonholonomic.VelocityConstraints`).

        EXAMPLES::

            sage: from sage_dynsym.dynamics.holonomic import HolonomicConstraints
            sage: HolonomicConstraints([var('x')], [var('dx')]).velocity_constraints()
            []
        """
        return []

    def velocity_multipliers(self):
        r"""
        The multipliers of the constraints on the velocities (none here).

        EXAMPLES::

            sage: from sage_dynsym.dynamics.holonomic import HolonomicConstraints
            sage: HolonomicConstraints([var('x')], [var('dx')]).velocity_multipliers()
            []
        """
        return []

    def jacobian(self):
        r"""
        The Jacobian `J = \partial f/\partial q` of the constraints.

        EXAMPLES::

            sage: from sage_dynsym.dynamics.holonomic import HolonomicConstraints
            sage: x, y, dx, dy = var('x y dx dy')
            sage: HolonomicConstraints([x, y], [dx, dy], [x*y - 1]).jacobian()
            [y x]
        """
        return matrix(SR, len(self._constraints), len(self._coordinates),
                      constraint_terms(self._constraints, self._coordinates,
                                       self._velocities)[0])

    def generalized_forces(self):
        r"""
        The generalized constraint forces `J^T\mu`, one per coordinate (the
        equations of motion contain them with a minus sign).

        EXAMPLES: see the class documentation.
        """
        J = self.jacobian()
        return [sum(mu * J[j, i] for j, mu in enumerate(self._multipliers))
                for i in range(len(self._coordinates))]

    def acceleration_constraints(self):
        r"""
        The constraints at the level of accelerations, `G\ddot q = h`: the
        holonomic ones differentiated twice
        (:func:`~sage_dynsym.numerics.form.constraint_terms`).

        OUTPUT: a triple ``(G, h, multipliers)``, the multipliers in the
        order of the rows of ``G``

        EXAMPLES: see the class documentation.
        """
        J, h, _ = constraint_terms(self._constraints, self._coordinates, self._velocities)
        G = matrix(SR, len(self._constraints), len(self._coordinates), J)
        return G, h, list(self._multipliers)


def independent_coordinates(lagrangian, independent, parametrization):
    r"""
    The data of ``lagrangian`` in independent coordinates: the constrained
    coordinates replaced by functions of the independent ones (what
    :meth:`Lagrangian.reduce
    <sage_dynsym.dynamics.lagrangian.Lagrangian.reduce>` returns as a
    Lagrangian; see there for the arguments and the checks).

    OUTPUT: a tuple ``(expr, coordinates, velocities, dissipation,
    forces)``: `L(\varphi(s, t), \dot\varphi, t)`, the independent
    coordinates and their velocities, the dissipation function substituted
    the same way and the generalized forces by virtual work,
    `Q'_k = \sum_i Q_i\,\partial\varphi_i/\partial s_k`

    EXAMPLES::

        sage: from sage_dynsym import Lagrangian
        sage: from sage_dynsym.dynamics.holonomic import independent_coordinates
        sage: x, y, dx, dy, l, th = var('x y dx dy l theta')
        sage: L = Lagrangian((dx^2 + dy^2)/2 - y, [x, y], constraints=[x^2 + y^2 - l^2])
        sage: E, q, dq, R, Q = independent_coordinates(L, [th], {x: l*sin(th), y: -l*cos(th)})
        sage: E.simplify_full(), q, dq, Q
        (1/2*dtheta^2*l^2 + l*cos(theta), [theta], [dtheta], [0])

    TESTS::

        sage: L.reduce([th], {x: l*sin(th), y: l*sin(th)})
        Traceback (most recent call last):
        ...
        ModelError: parametrization: the constraint constraints[0] = -l^2 + x^2 + y^2 does not hold identically under the parametrization {x: l*sin(theta), y: l*sin(theta)}
        sage: L.reduce([x, th], {y: th})
        Traceback (most recent call last):
        ...
        ModelError: independent: expected 1 independent coordinate(s) (2 coordinates, 1 constraint(s)), got [x, theta]
        sage: L.reduce([th], {x: l*sin(th)})
        Traceback (most recent call last):
        ...
        ModelError: parametrization: the coordinate y is neither independent nor given
        sage: L.reduce([th], [l*sin(th), -l*cos(th)])
        Traceback (most recent call last):
        ...
        ModelError: parametrization: expected a dict {coordinate: expression in the independent ones}, got [l*sin(theta), -l*cos(theta)]
    """
    if lagrangian.nonholonomic_constraints():
        raise ModelError("reduce() does not carry velocity constraints; use "
                         "reduced_equations() (Kane's equations in independent speeds)",
                         entry="nonholonomic")
    coordinates, velocities = lagrangian.coordinates(), lagrangian.velocities()
    expr, dissipation = lagrangian.expr(), lagrangian.dissipation()
    constraints, generalized_forces = lagrangian.constraints(), lagrangian.generalized_forces()
    independent = symbol_list(independent, "independent")
    if not isinstance(parametrization, dict):
        raise ModelError(f"expected a dict {{coordinate: expression in the independent "
                         f"ones}}, got {brief(parametrization)}", entry="parametrization")
    sub = {SR.var(k) if isinstance(k, str) and k.isidentifier() else
           expression_argument(k, "parametrization"): expression_argument(v, "parametrization")
           for k, v in parametrization.items()}
    n, m = len(coordinates), len(constraints)
    if len(independent) != n - m:
        raise ModelError(f"expected {n - m} independent coordinate(s) ({n} coordinates, "
                         f"{m} constraint(s)), got {independent}", entry="independent")
    for k in sub:
        if k not in coordinates:
            raise ModelError(f"{k} is not a coordinate of the Lagrangian; coordinates "
                             f"are {coordinates}", entry="parametrization")
        if k in independent:
            raise ModelError(f"the coordinate {k} is both independent and given",
                             entry="parametrization")
    parts = [expr, dissipation] + generalized_forces + constraints
    for q in coordinates:
        if q not in sub and q not in independent:
            raise ModelError(f"the coordinate {q} is neither independent nor given",
                             entry="parametrization")
    for s_k in independent:
        if s_k not in coordinates and any(p.has(s_k) for p in parts):
            raise ModelError(f"the new coordinate {s_k} is already a symbol of the model",
                             entry="independent")
    removed = [q for q in coordinates if q in sub]
    for k, v in sub.items():
        bad = [w for w in removed + velocities if v.has(w)]
        if bad:
            raise ModelError(f"the value of {k} depends on {bad[0]}; give it in the "
                             "independent coordinates and t", entry="parametrization")
    ds = [velocity(s_k) for s_k in independent]
    position = {q: sub.get(q, q) for q in coordinates}
    rate = {dq: time_derivative(position[q], independent, ds)
            for q, dq in zip(coordinates, velocities)}
    for j, f in enumerate(constraints):
        if not bool(f.subs(position).simplify_full() == 0):
            raise ModelError(f"the constraint constraints[{j}] = {f} does not hold "
                             f"identically under the parametrization {sub}",
                             entry="parametrization")
    full = {**position, **rate}
    forces = [sum(Q.subs(full) * position[q].diff(s_k)
                  for q, Q in zip(coordinates, generalized_forces))
              for s_k in independent]
    return expr.subs(full), independent, ds, dissipation.subs(full), forces
