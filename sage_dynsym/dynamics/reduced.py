r"""
Equations of motion in independent speeds (Kane, Voronets, Chaplygin)

With `m` constraints at the level of velocities,
`C(q, t)\dot q + c(q, t) = 0` (holonomic constraints differentiated once,
velocity constraints as they are), `k = n - m` of the velocities can be
chosen freely: the *independent speeds* `u`. The constraints give the
others, `\dot q_w = B_w(q, t)\,u + \beta_w(q, t)`, i.e.
`\dot q = B u + \beta` with `B` the partial velocities (identity on the
speeds), and their derivative gives the accelerations,
`\ddot q = B\dot u + \beta_2`. Projecting Lagrange's equations with
multipliers on the partial velocities removes the constraint forces
(`B^T C^T = 0`):

.. MATH::

    B^T\, E\bigl(q,\; B u + \beta,\; B\dot u + \beta_2\bigr) = 0,

`k` equations in the speeds: Kane's equations [KL1985]_ with the
velocities of coordinates as generalized speeds, which are Voronets'
equations [NF1972]_; when nothing depends on the coordinates whose
velocities are eliminated, these coordinates drop out entirely:
Chaplygin's equations (:meth:`ReducedEquations.is_chaplygin`). Together with
`\dot q = Bu + \beta` they are `2n - m` first-order equations.

EXAMPLES:

The Chaplygin sleigh: a rigid body on a knife edge at `(x, y)`, heading
`\theta`, its mass centre at the distance `a` ahead of the edge, mass
`m`, moment of inertia `J` about the mass centre. With the speeds
`\dot x, \dot\theta` ([Blo2003]_, section 1.7; `\dot y = \tan\theta\,\dot x`)::

    sage: from sage_dynsym.dynamics.nonholonomic import NonholonomicLagrangian
    sage: x, y, th, dx, dy, dth, m, J, a = var('x y theta dx dy dtheta m J a')
    sage: xc, yc = x + a*cos(th), y + a*sin(th)
    sage: vx, vy = dx - a*sin(th)*dth, dy + a*cos(th)*dth
    sage: L = NonholonomicLagrangian(m*(vx^2 + vy^2)/2 + J*dth^2/2, [x, y, th],
    ....:                            nonholonomic=[sin(th)*dx - cos(th)*dy])
    sage: R = L.reduced_equations([dx, dth]); R
    Kane's equations in the speeds (dx, dtheta), 1 dependent velocity (dy)
    sage: R.dependent_velocities()
    {dy: dx*sin(theta)/cos(theta)}
    sage: R.mass_matrix()
    [m/cos(theta)^2              0]
    [             0      a^2*m + J]
    sage: R.is_chaplygin()
    True
"""
from sage.matrix.constructor import matrix
from sage.misc.cachefunc import cached_method
from sage.structure.sage_object import SageObject
from sage.symbolic.ring import SR

from ..arguments import expression_list, model_argument
from ..errors import AnalysisError, ModelError
from ..symbols import time_derivative
from ..algebra.trig_linear import TrigFractionField
from .natural_form import is_singular, LAGRANGIAN_METHODS, LAGRANGIAN_HINT

__all__ = ['ReducedEquations']


class ReducedEquations(SageObject):
    r"""
    Kane's equations in independent speeds of a Lagrangian with constraints
    (see the module documentation).

    INPUT:

    - ``lagrangian`` -- a :class:`~sage_dynsym.dynamics.lagrangian.Lagrangian`
      (holonomic constraints) or a
      :class:`~sage_dynsym.dynamics.nonholonomic.NonholonomicLagrangian`
    - ``speeds`` -- (optional) the `n - m` independent speeds: velocities
      (or their coordinates); default: the last velocities, in the order of
      the coordinates, the constraints leave free (the first ones that the
      constraints can be solved for are eliminated)

    EXAMPLES: see the module documentation.

    TESTS:

    The velocities it expresses by the speeds satisfy the constraints, and
    its mass matrix is symmetric. It has no value equality (two of them are
    equal only if they are the same object), so the pickling test, which
    compares the copy with the original, is skipped::

        sage: from sage_dynsym.dynamics.nonholonomic import NonholonomicLagrangian
        sage: x, y, dx, dy = var('x y dx dy')
        sage: L = NonholonomicLagrangian((dx^2 + dy^2)/2, [x, y], nonholonomic=[dx - y*dy])
        sage: L.reduced_equations().speeds()
        [dy]
        sage: TestSuite(L.reduced_equations()).run(skip=['_test_pickling'])
        sage: L.reduced_equations([dx, dy])
        Traceback (most recent call last):
        ...
        ModelError: speeds: expected 1 independent speed(s) (2 velocities, 1 constraint(s)), got dx, dy
        sage: L.reduced_equations([var('dz')])
        Traceback (most recent call last):
        ...
        ModelError: speeds: dz is not a velocity or coordinate; the velocities are dx, dy
        sage: NonholonomicLagrangian((dx^2 + dy^2)/2, [x, y], nonholonomic=[dx]).reduced_equations([dx])
        Traceback (most recent call last):
        ...
        ModelError: speeds: the constraints cannot be solved for the other velocities dy
    """

    def __init__(self, lagrangian, speeds=None):
        self._L = model_argument(lagrangian, LAGRANGIAN_METHODS, "lagrangian", "a Lagrangian",
                                 hint=LAGRANGIAN_HINT)
        q, dq = lagrangian.coordinates(), lagrangian.velocities()
        ddq = lagrangian.accelerations()
        self._q, self._dq, self._ddq = q, dq, ddq
        holonomic = lagrangian.constraints()
        velocity = getattr(lagrangian, 'nonholonomic_constraints', lambda: [])()
        Phi = [time_derivative(f, q, dq, [0] * len(q)) for f in holonomic] + velocity
        n, m = len(q), len(Phi)
        C = [[g.diff(v) for v in dq] for g in Phi]
        zero = {v: 0 for v in dq}
        c = [g.subs(zero) for g in Phi]
        if speeds is None:
            independent = self._default_speeds(C)
        else:
            independent = []
            for s in expression_list(speeds, "speeds", expected="a list of velocities",
                                     names=True):
                if s in q:
                    s = dq[q.index(s)]
                if s not in dq:
                    raise ModelError(f"{s} is not a velocity or coordinate; the velocities are "
                                     f"{', '.join(map(str, dq))}", entry="speeds")
                independent.append(dq.index(s))
            if len(independent) != n - m:
                raise ModelError(f"expected {n - m} independent speed(s) ({n} velocities, {m} "
                                 f"constraint(s)), got {', '.join(str(dq[i]) for i in independent)}",
                                 entry="speeds")
        self._u = independent
        self._w = [i for i in range(n) if i not in independent]
        Cw = matrix(SR, m, len(self._w), [[row[j] for j in self._w] for row in C])
        Cu = matrix(SR, m, len(self._u), [[row[j] for j in self._u] for row in C])
        if m and is_singular(Cw):
            raise ModelError("the constraints cannot be solved for the other velocities "
                             f"{', '.join(str(dq[i]) for i in self._w)}", entry="speeds")
        right = (-Cu).augment(matrix(SR, [[-x] for x in c])) if m else None
        solved = _solve(Cw, right) if m else None
        B = matrix(SR, n, len(self._u))
        beta = [SR(0)] * n
        for a, i in enumerate(self._u):
            B[i, a] = 1
        for r, i in enumerate(self._w):
            for a in range(len(self._u)):
                B[i, a] = solved[r][a]
            beta[i] = solved[r][len(self._u)]
        self._B, self._beta, self._C, self._Phi = B, beta, C, Phi

    def _default_speeds(self, C):
        # eliminate the first velocities the constraints can be solved for
        n = len(self._dq)
        if not C:
            return list(range(n))
        K = TrigFractionField([a for row in C for a in row])
        columns = list(zip(*K.matrix(C)))
        # the pivot columns of the elimination in the order of the columns:
        # those that raise the rank of the columns before them
        pivots, rank = [], 0
        for j in range(n):
            if rank == len(C):
                break
            if K.rank(list(zip(*columns[:j + 1]))) > rank:
                pivots.append(j)
                rank += 1
        return [i for i in range(n) if i not in pivots]

    def _test_constraints(self, **options):
        r"""The velocities of :meth:`dependent_velocities` satisfy the
        constraints of the Lagrangian (those on the velocities, and the
        holonomic ones differentiated once) whatever the speeds, and
        :meth:`mass_matrix` is symmetric.

        EXAMPLES: run by ``TestSuite`` (see the class).
        """
        from ..algebra.solving import vanishes
        tester = self._tester(**options)
        L, values = self._L, self.dependent_velocities()
        constraints = [time_derivative(f, self._q, self._dq, [0] * len(self._q))
                       for f in L.constraints()]
        constraints += getattr(L, 'nonholonomic_constraints', lambda: [])()
        for g in constraints:
            tester.assertTrue(vanishes(SR(g).subs(values)),
                              f"the velocities {values} do not satisfy {g} == 0")
        M = self.mass_matrix()
        tester.assertTrue(all(vanishes(M[i, j] - M[j, i]) for i in range(M.nrows())
                              for j in range(i)))

    def _repr_(self):
        speeds = ", ".join(str(self._dq[i]) for i in self._u)
        dependent = ", ".join(str(self._dq[i]) for i in self._w)
        return (f"Kane's equations in the speeds ({speeds}), {len(self._w)} dependent "
                f"velocit{'y' if len(self._w) == 1 else 'ies'} ({dependent})")

    def speeds(self):
        r"""The independent speeds (velocity symbols).

        EXAMPLES: see the class documentation.
        """
        return [self._dq[i] for i in self._u]

    def dependent_velocities(self):
        r"""
        The other velocities in terms of the coordinates, the speeds and
        `t`: a dict ``{velocity: expression}``.

        EXAMPLES: see the module documentation.
        """
        u = [self._dq[i] for i in self._u]
        return {self._dq[i]: _tidy(SR(0).add(*[self._B[i, a] * u[a] for a in range(len(u))])
                                   + self._beta[i]) for i in self._w}

    def partial_velocities(self):
        r"""
        The matrix `B` of `\dot q = B u + \beta` (rows: velocities, columns:
        speeds).

        EXAMPLES::

            sage: from sage_dynsym.dynamics.nonholonomic import NonholonomicLagrangian
            sage: x, y, dx, dy = var('x y dx dy')
            sage: NonholonomicLagrangian((dx^2 + dy^2)/2, [x, y], nonholonomic=[dx - y*dy]).reduced_equations().partial_velocities()
            [y]
            [1]
        """
        return self._B

    def _velocity_values(self):
        return self.dependent_velocities()

    def _acceleration_values(self):
        # ddq_w from C ddq + gamma = 0, gamma the constraints' derivative at zero acceleration
        q, dq, ddq = self._q, self._dq, self._ddq
        velocities = self._velocity_values()
        zero = {a: 0 for a in ddq}
        gamma = [time_derivative(g, q, dq, ddq).subs(zero).subs(velocities) for g in self._Phi]
        if not self._w:
            return {}
        Cw = matrix(SR, len(self._Phi), len(self._w),
                    [[SR(row[j]).subs(velocities) for j in self._w] for row in self._C])
        du = [ddq[i] for i in self._u]
        solved = _solve(Cw, matrix(SR, [[-x] for x in gamma]))
        return {ddq[i]: _tidy(SR(0).add(*[self._B[i, a] * du[a] for a in range(len(du))])
                              + solved[r][0]) for r, i in enumerate(self._w)}

    @cached_method
    def equations(self):
        r"""
        Kane's equations `B^T E = 0`, one per speed (expressions meaning
        ``== 0``), in the coordinates, the speeds and their accelerations.

        EXAMPLES::

            sage: from sage_dynsym.dynamics.nonholonomic import NonholonomicLagrangian
            sage: x, y, th, dx, dy, dth, m, I = var('x y theta dx dy dtheta m I')
            sage: L = NonholonomicLagrangian(m*(dx^2 + dy^2)/2 + I*dth^2/2, [x, y, th],
            ....:                            nonholonomic=[sin(th)*dx - cos(th)*dy])
            sage: L.reduced_equations([dx, dth]).equations()
            [(dtheta*dx*sin(theta) + ddx*cos(theta))*m/cos(theta)^3, I*ddtheta]
        """
        L = self._L
        zero = {mu: 0 for mu in L.multipliers()}
        substitution = dict(self._velocity_values())
        substitution.update(self._acceleration_values())
        E = [SR(e).subs(zero).subs(substitution) for e in L.lagrange_equations()]
        return [_tidy(SR(0).add(*[self._B[i, a] * E[i] for i in range(len(E))
                                  if not self._B[i, a].is_zero()]))
                for a in range(len(self._u))]

    def mass_matrix(self):
        r"""
        `B^T M B`, the matrix of the speeds' accelerations in
        :meth:`equations`.

        EXAMPLES: see the module documentation.
        """
        du = [self._ddq[i] for i in self._u]
        return matrix(SR, [[_tidy(e.diff(a)) for a in du] for e in self.equations()])

    def is_chaplygin(self):
        r"""
        Whether the coordinates whose velocities are eliminated appear
        neither in the Lagrangian, the forces and the dissipation nor in the
        constraints solved: then :meth:`equations` do not contain them
        (Chaplygin's equations).

        EXAMPLES: see the module documentation.
        """
        eliminated = [self._q[i] for i in self._w]
        L = self._L
        parts = ([L.expr(), L.dissipation()] + L.generalized_forces() + self._B.list()
                 + self._beta)
        return not any(SR(p).has(z) for p in parts for z in eliminated)


def _tidy(expr):
    from ..algebra.trigonometric import trig_rational_simplify
    return trig_rational_simplify(SR(expr))


def _solve(A, B):
    # A X = B exactly (rational functions of sines and cosines), else in SR
    try:
        K = TrigFractionField(A.list() + B.list())
        X = K.solve_right(K.matrix(A), K.matrix(B))
        if X is not None:
            return K.expressions(X)
    except AnalysisError:
        pass
    X = A.solve_right(B)
    return [[_tidy(e) for e in row] for row in X.rows()]
