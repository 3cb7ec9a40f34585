r"""
Holonomic constraints: their checks, their multipliers and Lagrange's
equations of the first kind

:func:`check_constraints` reads and checks holonomic constraints
`f_j(q, t) = 0`, for a :class:`~sage_dynsym.dynamics.lagrangian.Lagrangian`
and for a :class:`~sage_dynsym.mechanics.system.MechanicalSystem` alike.
:class:`HolonomicConstraints` gives a Lagrangian its constraints, their
multipliers `\mu_j`, the generalized constraint forces `J^T\mu` and the
accelerations and multipliers solved together (see the module
documentation of :mod:`~sage_dynsym.dynamics.lagrangian`), and the
reduction to independent coordinates.

EXAMPLES::

    sage: from sage_dynsym import Lagrangian
    sage: x, y, dx, dy, m, g, l = var('x y dx dy m g l')
    sage: L = Lagrangian(m*(dx^2 + dy^2)/2 - m*g*y, [x, y], constraints=[x^2 + y^2 == l^2])
    sage: L.constraints(), L.multipliers()
    ([-l^2 + x^2 + y^2], [mu1])
"""
import operator

from sage.matrix.constructor import matrix
from sage.misc.cachefunc import cached_method
from sage.symbolic.expression import Expression
from sage.symbolic.ring import SR

from ..arguments import expression_argument
from ..errors import ModelError, brief
from ..symbols import velocity, acceleration, time_derivative, t, constraint_multipliers, momentum
from .natural_form import symbol_list, is_singular, has_full_row_rank

__all__ = ['check_constraints', 'HolonomicConstraints']


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
        if f.is_relational():
            if f.operator() is not operator.eq:
                raise ModelError("expected an expression f meaning f = 0 or an equation, "
                                 f"got the relation {f}", entry=sub)
            f = f.lhs() - f.rhs()
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


class HolonomicConstraints:
    r"""
    The holonomic constraints of a
    :class:`~sage_dynsym.dynamics.lagrangian.Lagrangian` and their
    multipliers (a base class of it, see the module documentation).

    EXAMPLES: see :class:`~sage_dynsym.dynamics.lagrangian.Lagrangian`.
    """

    def _set_constraints(self, constraints):
        # after the coordinates, velocities, expression, dissipation and forces
        self._constraints = check_constraints(constraints, self._coordinates,
                                              velocities=self._velocities)
        self._multipliers = []
        if self._constraints:
            taken = set().union(*(SR(e).variables() for e in [self._expr, self._dissipation]
                                  + self._forces + self._constraints))
            taken |= {momentum(q) for q in self._coordinates}
            self._multipliers = constraint_multipliers(len(self._constraints), taken)

    def constraints(self):
        r"""
        The holonomic constraints `f_j(q, t)`, each meaning `f_j = 0` (a new
        list, empty if none).

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, y, dx, dy, l = var('x y dx dy l')
            sage: L = Lagrangian((dx^2 + dy^2)/2, [x, y], constraints=[x^2 + y^2 - l^2])
            sage: L.constraints()
            [-l^2 + x^2 + y^2]
            sage: Lagrangian(dx^2, [x]).constraints()
            []
        """
        return list(self._constraints)

    def multipliers(self):
        r"""
        The multipliers `\mu_j`, one per constraint: symbols ``mu1, mu2,
        ...`` that occur nowhere else in the model (see
        :func:`~sage_dynsym.symbols.constraint_multipliers`).

        The equations contain `-\sum_j \mu_j \partial f_j/\partial q_i`,
        so `\mu_j \partial f_j/\partial q` is the generalized force of the
        constraint `j`.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, y, dx, dy, mu1 = var('x y dx dy mu1')
            sage: Lagrangian((dx^2 + dy^2)/2, [x, y], constraints=[x - y]).multipliers()
            [mu1]
            sage: Lagrangian((dx^2 + dy^2)/2 + mu1*x, [x, y], constraints=[x - y]).multipliers()
            [mu2]
        """
        return list(self._multipliers)

    def nonholonomic_constraints(self):
        r"""
        The constraints on the velocities (none here; see
        :class:`~sage_dynsym.dynamics.nonholonomic.NonholonomicLagrangian`).

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, dx = var('x dx')
            sage: Lagrangian(dx^2/2, [x]).nonholonomic_constraints()
            []
        """
        return []

    def velocity_multipliers(self):
        r"""
        The multipliers of the constraints on the velocities (none here;
        see :class:`~sage_dynsym.dynamics.nonholonomic.NonholonomicLagrangian`).

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, dx = var('x dx')
            sage: Lagrangian(dx^2/2, [x]).velocity_multipliers()
            []
        """
        return []

    def _subject_to(self):
        if not self._constraints:
            return ""
        return ", subject to " + ", ".join(f"{f} == 0" for f in self._constraints)

    def _constraint_forces(self):
        # the generalized constraint forces J^T mu, one per coordinate
        J = self._constraint_jacobian()
        return [sum(mu * J[j, i] for j, mu in enumerate(self._multipliers))
                for i in range(len(self._coordinates))]

    def _constraint_jacobian(self):
        return matrix(SR, len(self._constraints), len(self._coordinates),
                      [[f.diff(q) for q in self._coordinates] for f in self._constraints])

    def _acceleration_constraints(self):
        # the constraints at the level of accelerations, G ddq = h: the
        # holonomic ones differentiated twice; with their multipliers
        q, dq, ddq = self._coordinates, self._velocities, self._accelerations
        zero = {v: 0 for v in ddq}
        h = [-time_derivative(time_derivative(f, q, dq, ddq), q, dq, ddq).subs(zero)
             for f in self._constraints]
        return self._constraint_jacobian(), h, list(self._multipliers)

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
            sage: x, y, dx, dy, m, g, l, th, dth = var('x y dx dy m g l theta dtheta')
            sage: L = Lagrangian(m*(dx^2 + dy^2)/2 - m*g*y, [x, y], constraints=[x^2 + y^2 - l^2])
            sage: sol = L.accelerations_and_multipliers(); sol
            {ddx: (g*x*y - (dx^2 + dy^2)*x)/(x^2 + y^2),
             ddy: -(g*x^2 + (dx^2 + dy^2)*y)/(x^2 + y^2),
             mu1: 1/2*(g*m*y - (dx^2 + dy^2)*m)/(x^2 + y^2)}
            sage: polar = {x: l*sin(th), y: -l*cos(th), dx: l*cos(th)*dth, dy: l*sin(th)*dth}
            sage: (-2*sol[L.multipliers()[0]]*l).subs(polar).full_simplify()
            dtheta^2*l*m + g*m*cos(theta)

        Without constraints, the accelerations alone::

            sage: Lagrangian(m*dx^2/2 - x^2/2, [x]).accelerations_and_multipliers()
            {ddx: -x/m}

        TESTS::

            sage: Lagrangian(-sqrt(1 - dx^2), [x], constraints=[x - var('t')]).accelerations_and_multipliers()
            Traceback (most recent call last):
            ...
            ModelError: the Lagrangian is not quadratic in the velocities (dx)

        REFERENCES:

        .. [Gol2002] H. Goldstein, C. Poole, J. Safko, *Classical Mechanics*,
           3rd ed., Addison-Wesley 2002, section 2.4 (Lagrange multipliers
           and forces of constraint).
        """
        K, rhs, unknowns = self._acceleration_system()
        solution = K.solve_right(matrix(SR, [[v] for v in rhs]))
        return {v: solution[i, 0].simplify_rational() for i, v in enumerate(unknowns)}

    def _acceleration_system(self):
        # the linear system [[M, -G^T], [G, 0]] (ddq, multipliers) = (F, h),
        # as (matrix, right-hand side, unknowns)
        q, ddq = self._coordinates, self._accelerations
        M = self.decomposition()[0]
        G, h, multipliers = self._acceleration_constraints()
        n, m = len(q), len(multipliers)
        zero = {v: 0 for v in ddq + multipliers}
        F = [-e.subs(zero) for e in self.lagrange_equations()]
        K = matrix(SR, n + m, n + m)
        K.set_block(0, 0, M)
        if m:
            K.set_block(0, n, -G.transpose())
            K.set_block(n, 0, G)
        if is_singular(K):
            raise ModelError("the equations cannot be solved for the accelerations and "
                             "multipliers (the matrix [[M, -J^T], [J, 0]] is singular)")
        return K, F + h, ddq + multipliers

    def reduce(self, independent, parametrization):
        r"""
        The Lagrangian in independent coordinates: the constrained
        coordinates are replaced by functions of the independent ones.

        INPUT:

        - ``independent`` -- the `n - m` independent coordinates `s_k`: kept
          coordinates of `L` or new symbols
        - ``parametrization`` -- a dict ``{q_i: phi_i(s, t)}`` giving every
          other coordinate; the constraints must hold identically under it

        OUTPUT: a :class:`Lagrangian` in ``independent`` without
        constraints: `L(\varphi(s, t), \dot\varphi, t)`, the dissipation
        function substituted the same way, and the generalized forces by
        virtual work, `Q'_k = \sum_i Q_i\,\partial\varphi_i/\partial s_k`.

        EXAMPLES:

        The Cartesian pendulum reduced to its angle::

            sage: from sage_dynsym import Lagrangian
            sage: x, y, dx, dy, m, g, l, th = var('x y dx dy m g l theta')
            sage: L = Lagrangian(m*(dx^2 + dy^2)/2 - m*g*y, [x, y], constraints=[x^2 + y^2 - l^2])
            sage: P = L.reduce([th], {x: l*sin(th), y: -l*cos(th)})
            sage: P.lagrange_equations()[0].simplify_full()
            ddtheta*l^2*m + g*l*m*sin(theta)

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
        independent = symbol_list(independent, "independent")
        if not isinstance(parametrization, dict):
            raise ModelError(f"expected a dict {{coordinate: expression in the independent "
                             f"ones}}, got {brief(parametrization)}", entry="parametrization")
        sub = {SR.var(k) if isinstance(k, str) and k.isidentifier() else
               expression_argument(k, "parametrization"): expression_argument(v, "parametrization")
               for k, v in parametrization.items()}
        n, m = len(self._coordinates), len(self._constraints)
        if len(independent) != n - m:
            raise ModelError(f"expected {n - m} independent coordinate(s) ({n} coordinates, "
                             f"{m} constraint(s)), got {independent}", entry="independent")
        for k in sub:
            if k not in self._coordinates:
                raise ModelError(f"{k} is not a coordinate of the Lagrangian; coordinates "
                                 f"are {self._coordinates}", entry="parametrization")
            if k in independent:
                raise ModelError(f"the coordinate {k} is both independent and given",
                                 entry="parametrization")
        parts = [self._expr, self._dissipation] + self._forces + self._constraints
        for q in self._coordinates:
            if q not in sub and q not in independent:
                raise ModelError(f"the coordinate {q} is neither independent nor given",
                                 entry="parametrization")
        for s_k in independent:
            if s_k not in self._coordinates and any(p.has(s_k) for p in parts):
                raise ModelError(f"the new coordinate {s_k} is already a symbol of the model",
                                 entry="independent")
        removed = [q for q in self._coordinates if q in sub]
        for k, v in sub.items():
            bad = [w for w in removed + self._velocities if v.has(w)]
            if bad:
                raise ModelError(f"the value of {k} depends on {bad[0]}; give it in the "
                                 "independent coordinates and t", entry="parametrization")
        ds = [velocity(s_k) for s_k in independent]
        position = {q: sub.get(q, q) for q in self._coordinates}
        rate = {dq: time_derivative(position[q], independent, ds)
                for q, dq in zip(self._coordinates, self._velocities)}
        for j, f in enumerate(self._constraints):
            if not bool(f.subs(position).simplify_full() == 0):
                raise ModelError(f"the constraint constraints[{j}] = {f} does not hold "
                                 f"identically under the parametrization {sub}",
                                 entry="parametrization")
        full = {**position, **rate}
        forces = [sum(Q.subs(full) * position[q].diff(s_k)
                      for q, Q in zip(self._coordinates, self._forces))
                  for s_k in independent]
        # a plain Lagrangian, whatever the kind of this one
        return self._derived(self._expr.subs(full), coordinates=independent, velocities=ds,
                             dissipation=self._dissipation.subs(full), forces=forces,
                             constraints=())
