r"""
First approximation: linearization and the structure of forces

Around an equilibrium `q = q^0`, `\dot q = 0` the Lagrange equations (5)
become (15)--(16) of :doc:`the method </method>`,

.. MATH::

    M \ddot\zeta + (D + 2G)\dot\zeta + (K + P)\zeta = 0,

with `M = M^T` (kinetic), `D = D^T` (dissipative), `G = -G^T`
(gyroscopic), `K = K^T` (potential), `P = -P^T` (non-conservative
positional): the matrices of the velocity and position terms are split
into their symmetric and skew-symmetric parts. A first-order system
`B \dot x = F(x)` (circuit state equations, Hamilton equations, Euler--
Poisson equations, ...) is linearized to `B \dot \xi = J \xi` with the
Jacobian `J`.

The characteristic polynomial is `\det(M\lambda^2 + S\lambda + W)`, resp.
`\det(B\lambda - J)`, computed fraction-free: each row is first multiplied
by the least common denominator of its entries, the determinant is taken
over a polynomial ring in the parameters, and the product of the
denominators is multiplied back in (common factors cancelled), so that the
result has the sign of the determinant whatever the signs of the
denominators. Non-polynomial parts of the entries (derivatives of
unspecified functions such as a diode characteristic, functions of
parameters) are treated as symbols.

EXAMPLES:

A pendulum with a damper, from its Lagrangian::

    sage: from sage_dynsym import Lagrangian
    sage: from sage_dynsym.analysis.linear import linearize
    sage: phi, dphi, m, l, g, c = var('phi dphi m l g c')
    sage: L = Lagrangian(m*l^2*dphi^2/2 + m*g*l*cos(phi), [phi],
    ....:                dissipation=c*dphi^2/2)
    sage: down = linearize(L, {phi: 0}); down
    Linear system M z'' + (D + 2G) z' + (K + P) z = 0 in (phi)
    sage: down.M(), down.D(), down.K()
    ([l^2*m], [c], [g*l*m])
    sage: lam = var('lam')
    sage: down.characteristic_polynomial(lam)
    l^2*lam^2*m + g*l*m + c*lam
    sage: linearize(L, {phi: pi}).K()
    [-g*l*m]
    sage: linearize(L, {phi: 1})
    Traceback (most recent call last):
    ...
    AnalysisError: linearize: the point {phi: 1} is not an equilibrium: equation 0 gives g*l*m*sin(1) != 0; for the linearization at any state numerically, give the parameters' values: linearize(system, state, values={parameter: number})
"""
from sage.matrix.constructor import matrix, identity_matrix
from sage.structure.sage_object import SageObject
from sage.symbolic.ring import SR

from ..arguments import expression_argument, expression_list, matrix_argument, symbol_arguments
from ..errors import AnalysisError, brief
from ..algebra.determinants import fraction_free_det as _fraction_free_det
from .motion import SecondOrderEquations, FirstOrderEquations
from ..algebra.solving import normalize, vanishes

__all__ = ['LinearSystem', 'linearize', 'equations_of_motion']


def _at(expr, point):
    try:
        return SR(expr).subs(point)
    except (ValueError, ZeroDivisionError, RuntimeError) as err:
        if not isinstance(err, ZeroDivisionError) and 'division by zero' not in str(err):
            raise
        raise _singularity(expr, point) from err


def _shown(point):
    return {k: point[k] for k in point if not str(k).startswith('dd')
            and not (str(k).startswith('d') and SR(point[k]).is_zero())}


def _singularity(expr, point, what="a denominator of the equations vanishes"):
    r"""The error for a point where the coordinates are singular: names the
    coordinates whose value alone makes ``expr`` singular."""
    culprits = []
    for k, v in point.items():
        try:
            e = SR(expr).subs({k: v})
            if what != "a denominator of the equations vanishes" and normalize(e).is_zero():
                culprits.append(k)
        except (ValueError, ZeroDivisionError, RuntimeError):
            culprits.append(k)
    names = ', '.join(f"{k} = {point[k]}" for k in culprits) or str(_shown(point))
    return AnalysisError(
        f"the point {_shown(point)} is a singularity of the coordinates: "
        f"{what} at {names} (the chart degenerates there, as Euler "
        "angles do at theta = 0); linearize in a regular chart instead (e.g. "
        "other angles for the axis)", entry="linearize")


def _tidy(expr):
    expr = SR(expr)
    if expr.is_numeric() or expr.is_symbol():
        return expr             # already in simplest form: no round trip to Maxima
    try:
        return expr.simplify_full() if expr.variables() else expr.simplify()
    except (TypeError, ValueError):
        return expr


def _check_equilibrium(values, point):
    for i, v in enumerate(values):
        if not vanishes(v):
            raise AnalysisError(f"the point {_shown(point)} is not an equilibrium: "
                                f"equation {i} gives {_tidy(v)} != 0; for the "
                                f"linearization at any state numerically, give the parameters' "
                                f"values: linearize(system, state, values={{parameter: number}})",
                                entry="linearize")


class LinearSystem(SageObject):
    r"""
    A linear system with constant coefficients: second-order
    `M\ddot z + (D + 2G)\dot z + (K + P) z = 0`, or first-order
    `B \dot x = J x`.

    Built by :func:`linearize`, or directly.

    INPUT:

    - ``variables`` -- list of the unknowns (coordinates or state variables)
    - ``M``, ``S``, ``W`` -- (second order) the matrices of accelerations,
      velocities and coordinates, `M\ddot z + S\dot z + W z = 0`
    - ``J``, ``B`` -- (first order) the Jacobian and the left-hand matrix
      (default identity)
    - ``steady_motion`` -- (optional) the
      :class:`~sage_dynsym.analysis.steady.SteadyMotion` the system
      linearizes (see :meth:`steady_motion`)

    EXAMPLES::

        sage: from sage_dynsym.analysis.linear import LinearSystem
        sage: x, y, g, k = var('x y g k')
        sage: Ls = LinearSystem([x, y], M=identity_matrix(2),
        ....:                   S=matrix([[0, -g], [g, 0]]), W=diagonal_matrix([k, k]))
        sage: Ls.G(), Ls.D()
        (
        [   0 -1/2*g]  [0 0]
        [ 1/2*g      0], [0 0]
        )
        sage: Ls.characteristic_polynomial(var('lam'))
        g^2*lam^2 + lam^4 + 2*k*lam^2 + k^2

    TESTS::

        sage: TestSuite(Ls).run()
        sage: TestSuite(LinearSystem([x], J=[[g - k]], B=[[2]])).run()
    """

    def __init__(self, variables, M=None, S=None, W=None, J=None, B=None, steady_motion=None):
        self._variables = expression_list(variables, "variables", AnalysisError,
                                          hint="linearize(system, at) builds a linear system")
        self._steady_motion = steady_motion
        n = len(self._variables)

        def square(X, name):
            X = matrix_argument(X, name, AnalysisError, square=True,
                                hint="give J= (first order) or M=, S=, W= (second order)")
            if X.nrows() != n:
                raise AnalysisError(f"expected a {n}x{n} matrix (one row per variable), got "
                                    f"{X.nrows()}x{X.ncols()}", entry=name)
            return X.change_ring(SR)

        if J is not None:
            self._order = 1
            self._J = square(J, "J")
            self._B = identity_matrix(SR, n) if B is None else square(B, "B")
        else:
            self._order = 2
            self._M, self._S, self._W = (square(X, name) for X, name in
                                         ((M, "M"), (S, "S"), (W, "W")))

    def _matrices(self):
        return (self._J, self._B) if self._order == 1 else (self._M, self._S, self._W)

    def __eq__(self, other):
        r"""
        Linear systems are values: equal when they have the same unknowns
        and the same matrices.

        EXAMPLES::

            sage: from sage_dynsym.analysis.linear import LinearSystem
            sage: x, a = var('x a')
            sage: LinearSystem([x], J=[[a]]) == LinearSystem([x], J=[[a]]), LinearSystem([x], J=[[a]]) != LinearSystem([x], J=[[-a]])
            (True, True)
        """
        return (isinstance(other, LinearSystem) and self._order == other._order
                and self._variables == other._variables
                and all(A == B for A, B in zip(self._matrices(), other._matrices())))

    def __hash__(self):
        return hash((self._order, tuple(map(str, self._variables))))

    def _test_sizes(self, **options):
        r"""Run by ``TestSuite``: square matrices, a row per unknown; `D, K`
        symmetric and `G, P` antisymmetric, `S = D + 2G`, `W = K + P`."""
        tester, n = self._tester(**options), len(self._variables)
        for X in self._matrices():
            tester.assertEqual((X.nrows(), X.ncols()), (n, n))
        if self._order == 2:
            D, G, K, P = self.D(), self.G(), self.K(), self.P()
            tester.assertTrue(D.is_symmetric() and K.is_symmetric())
            tester.assertEqual(G, -G.transpose())
            tester.assertEqual(P, -P.transpose())
            tester.assertEqual(D + 2*G, self._S)
            tester.assertEqual(K + P, self._W)

    def _repr_(self):
        vs = ', '.join(map(str, self._variables))
        if self._order == 1:
            return f"Linear system B x' = J x in ({vs})"
        return f"Linear system M z'' + (D + 2G) z' + (K + P) z = 0 in ({vs})"

    def variables(self):
        r"""The unknowns, in order.

        EXAMPLES::

            sage: from sage_dynsym.analysis.linear import LinearSystem
            sage: x, y, d, g, k, q = var('x y d g k q')
            sage: Ls = LinearSystem([x, y], M=identity_matrix(2),
            ....:                   S=matrix([[d, 2*g], [-2*g, d]]), W=matrix([[k, q], [-q, k]]))
            sage: Ls.variables()
            [x, y]
        """
        return list(self._variables)

    def steady_motion(self):
        r"""
        The steady motion this system linearizes, with the independent
        speeds, the velocities and constraint multipliers along it, the
        coordinates solved to first order and those left out (a
        :class:`~sage_dynsym.analysis.steady.SteadyMotion`); ``None`` for a
        linearization about an equilibrium.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: from sage_dynsym.analysis.linear import linearize
            sage: x, dx = var('x dx')
            sage: linearize(Lagrangian(dx^2/2 - x^2/2, [x]), {x: 0}).steady_motion() is None
            True
        """
        return self._steady_motion

    def order(self):
        r"""1 for `B\dot x = Jx`, 2 for the second-order form.

        EXAMPLES::

            sage: from sage_dynsym.analysis.linear import LinearSystem
            sage: x, y, d, g, k, q = var('x y d g k q')
            sage: Ls = LinearSystem([x, y], M=identity_matrix(2),
            ....:                   S=matrix([[d, 2*g], [-2*g, d]]), W=matrix([[k, q], [-q, k]]))
            sage: Ls.order()
            2
        """
        return self._order

    def _second(self):
        if self._order != 2:
            raise AnalysisError("the force structure M, D, G, K, P is defined for "
                                "second-order systems (from a Lagrangian or Routh "
                                "function)", entry="LinearSystem")

    def M(self):
        r"""The kinetic (mass) matrix `M`.

        EXAMPLES::

            sage: from sage_dynsym.analysis.linear import LinearSystem
            sage: x, y, d, g, k, q = var('x y d g k q')
            sage: Ls = LinearSystem([x, y], M=identity_matrix(2),
            ....:                   S=matrix([[d, 2*g], [-2*g, d]]), W=matrix([[k, q], [-q, k]]))
            sage: Ls.M()
            [1 0]
            [0 1]
        """
        self._second()
        return self._M

    def S(self):
        r"""The matrix of velocity terms `S = D + 2G`.

        EXAMPLES::

            sage: from sage_dynsym.analysis.linear import LinearSystem
            sage: x, y, d, g, k, q = var('x y d g k q')
            sage: Ls = LinearSystem([x, y], M=identity_matrix(2),
            ....:                   S=matrix([[d, 2*g], [-2*g, d]]), W=matrix([[k, q], [-q, k]]))
            sage: Ls.S()
            [   d  2*g]
            [-2*g    d]
        """
        self._second()
        return self._S

    def W(self):
        r"""The matrix of positional terms `W = K + P`.

        EXAMPLES::

            sage: from sage_dynsym.analysis.linear import LinearSystem
            sage: x, y, d, g, k, q = var('x y d g k q')
            sage: Ls = LinearSystem([x, y], M=identity_matrix(2),
            ....:                   S=matrix([[d, 2*g], [-2*g, d]]), W=matrix([[k, q], [-q, k]]))
            sage: Ls.W()
            [ k  q]
            [-q  k]
        """
        self._second()
        return self._W

    def D(self):
        r"""The dissipative matrix, symmetric part of `S`.

        EXAMPLES::

            sage: from sage_dynsym.analysis.linear import LinearSystem
            sage: x, y, d, g, k, q = var('x y d g k q')
            sage: Ls = LinearSystem([x, y], M=identity_matrix(2),
            ....:                   S=matrix([[d, 2*g], [-2*g, d]]), W=matrix([[k, q], [-q, k]]))
            sage: Ls.D()
            [d 0]
            [0 d]
        """
        return ((self.S() + self.S().transpose()) / 2).apply_map(_tidy)

    def G(self):
        r"""The gyroscopic matrix `G = (S - S^T)/4` (so that `S = D + 2G`).

        EXAMPLES::

            sage: from sage_dynsym.analysis.linear import LinearSystem
            sage: x, y, d, g, k, q = var('x y d g k q')
            sage: Ls = LinearSystem([x, y], M=identity_matrix(2),
            ....:                   S=matrix([[d, 2*g], [-2*g, d]]), W=matrix([[k, q], [-q, k]]))
            sage: Ls.G()
            [ 0  g]
            [-g  0]
        """
        return ((self.S() - self.S().transpose()) / 4).apply_map(_tidy)

    def K(self):
        r"""The potential matrix, symmetric part of `W`.

        EXAMPLES::

            sage: from sage_dynsym.analysis.linear import LinearSystem
            sage: x, y, d, g, k, q = var('x y d g k q')
            sage: Ls = LinearSystem([x, y], M=identity_matrix(2),
            ....:                   S=matrix([[d, 2*g], [-2*g, d]]), W=matrix([[k, q], [-q, k]]))
            sage: Ls.K()
            [k 0]
            [0 k]
        """
        return ((self.W() + self.W().transpose()) / 2).apply_map(_tidy)

    def P(self):
        r"""The non-conservative positional matrix, skew part of `W`.

        EXAMPLES::

            sage: from sage_dynsym.analysis.linear import LinearSystem
            sage: x, y, d, g, k, q = var('x y d g k q')
            sage: Ls = LinearSystem([x, y], M=identity_matrix(2),
            ....:                   S=matrix([[d, 2*g], [-2*g, d]]), W=matrix([[k, q], [-q, k]]))
            sage: Ls.P()
            [ 0  q]
            [-q  0]
        """
        return ((self.W() - self.W().transpose()) / 2).apply_map(_tidy)

    def jacobian(self):
        r"""
        The first-order matrix `A` of `\dot x = A x` (for the second-order
        form, `x = (z, \dot z)`).

        EXAMPLES::

            sage: from sage_dynsym.analysis.linear import LinearSystem
            sage: m, c, k = var('m c k')
            sage: LinearSystem([var('x')], M=[[m]], S=[[c]], W=[[k]]).jacobian()
            [   0    1]
            [-k/m -c/m]
        """
        if self._order == 1:
            return (self._B.inverse() * self._J).apply_map(_tidy)
        n = len(self._variables)
        Mi = self._M.inverse()
        top = matrix(SR, n, n).augment(identity_matrix(SR, n))
        bottom = (-Mi * self._W).augment(-Mi * self._S)
        return top.stack(bottom).apply_map(_tidy)

    def lhs_matrix(self):
        r"""The matrix `B` of a first-order system `B\dot x = Jx`.

        EXAMPLES::

            sage: from sage_dynsym.analysis.linear import LinearSystem
            sage: x, y, d, g, k, q = var('x y d g k q')
            sage: Ls = LinearSystem([x, y], M=identity_matrix(2),
            ....:                   S=matrix([[d, 2*g], [-2*g, d]]), W=matrix([[k, q], [-q, k]]))
            sage: LinearSystem([x], J=[[k]], B=[[d]]).lhs_matrix()
            [d]
        """
        return self._B if self._order == 1 else None

    def equations(self):
        r"""
        The linear equations as expressions (``== 0``), in the variables
        and their ``d``/``dd`` derivative symbols.

        EXAMPLES::

            sage: from sage_dynsym.analysis.linear import LinearSystem
            sage: x, a = var('x a')
            sage: LinearSystem([x], J=[[a]]).equations()
            [-a*x + dx]
        """
        from ..symbols import velocity, acceleration
        z = matrix(SR, [[v] for v in self._variables])
        dz = matrix(SR, [[velocity(v)] for v in self._variables])
        if self._order == 1:
            E = self._B * dz - self._J * z
        else:
            ddz = matrix(SR, [[acceleration(v)] for v in self._variables])
            E = self._M * ddz + self._S * dz + self._W * z
        return [e.expand() for e in E.column(0)]

    def characteristic_matrix(self, lam):
        r"""`M\lambda^2 + S\lambda + W`, resp. `B\lambda - J`.

        EXAMPLES::

            sage: from sage_dynsym.analysis.linear import LinearSystem
            sage: x, y, d, g, k, q = var('x y d g k q')
            sage: Ls = LinearSystem([x, y], M=identity_matrix(2),
            ....:                   S=matrix([[d, 2*g], [-2*g, d]]), W=matrix([[k, q], [-q, k]]))
            sage: Ls.characteristic_matrix(var('lam'))
            [d*lam + lam^2 + k       2*g*lam + q]
            [     -2*g*lam - q d*lam + lam^2 + k]
        """
        lam = expression_argument(lam, "lam", AnalysisError,
                                  expected="the variable of the polynomial (a symbol)")
        if self._order == 1:
            return self._B * lam - self._J
        return self._M * lam ** 2 + self._S * lam + self._W

    def characteristic_polynomial(self, lam, as_polynomial=False, positive=()):
        r"""
        The characteristic polynomial, fraction-free (see the module
        documentation), expanded.

        INPUT:

        - ``lam`` -- a symbolic variable
        - ``as_polynomial`` -- (default: ``False``) return an element of the
          polynomial ring over `\QQ` in ``lam`` and the parameters instead of
          a symbolic expression (faster for large systems)
        - ``positive`` -- (optional) symbols declared positive: factors of
          denominators positive by these declarations are not multiplied in

        OUTPUT: a polynomial with the same roots as, and a positive multiple
        of, the determinant

        EXAMPLES::

            sage: from sage_dynsym.analysis.linear import LinearSystem
            sage: L1, C1, r = var('L1 C1 r')
            sage: Ls = LinearSystem([var('i'), var('u')], J=[[0, 1], [-1, -r]],
            ....:                   B=diagonal_matrix([L1, C1]))
            sage: Ls.characteristic_polynomial(var('lam'))
            C1*L1*lam^2 + L1*lam*r + 1

        A generic diode characteristic `f` linearized at `v_0`: its
        derivative is a parameter of the polynomial::

            sage: v, v0, C = var('v v0 C'); f = function('f')
            sage: Ls = LinearSystem([v], J=[[-diff(f(v), v).subs(v=v0)/C]])
            sage: Ls.characteristic_polynomial(var('lam'))
            C^2*lam + C*diff(f(v0), v0)
            sage: Ls.characteristic_polynomial(var('lam'), positive=[C])
            C*lam + diff(f(v0), v0)
        """
        det = _fraction_free_det(self.characteristic_matrix(lam), as_polynomial, positive)
        return det if as_polynomial else det.expand()

    def force_structure(self):
        r"""
        A plain-language description of which forces are present.

        EXAMPLES::

            sage: from sage_dynsym.analysis.linear import LinearSystem
            sage: g, k = var('g k')
            sage: print(LinearSystem([var('x'), var('y')], M=identity_matrix(2),
            ....:       S=matrix([[0, g], [-g, 0]]), W=-identity_matrix(2)).force_structure())
            gyroscopic forces (G != 0); potential forces (K != 0)
        """
        self._second()
        parts = []
        for name, X, what in (("D", self.D(), "dissipative"), ("G", self.G(), "gyroscopic"),
                              ("K", self.K(), "potential"),
                              ("P", self.P(), "non-conservative positional")):
            if not X.is_zero():
                parts.append(f"{what} forces ({name} != 0)")
        return '; '.join(parts) if parts else "no forces"

    @classmethod
    def from_equations(cls, M, S, W, variables=None):
        r"""
        The system `M\ddot q + S\dot q + Wq = 0` from the matrices of the
        equations as they are written: the split of `S` into `D + 2G` and
        of `W` into `K + P` is done here (so a gyroscopic matrix of one's
        own equations is never doubled).

        INPUT:

        - ``M``, ``S``, ``W`` -- square matrices (or lists of rows) of the
          accelerations, velocities and coordinates
        - ``variables`` -- (default: ``q1, q2, ...``) the unknowns

        OUTPUT: a :class:`LinearSystem`

        EXAMPLES: `\ddot x - g\dot y + kx = 0`, `\ddot y + g\dot x + ky = 0`::

            sage: from sage_dynsym.analysis.linear import LinearSystem
            sage: g, k = var('g k')
            sage: Ls = LinearSystem.from_equations(identity_matrix(2), [[0, -g], [g, 0]],
            ....:                                  diagonal_matrix([k, k]))
            sage: Ls.variables(), Ls.G(), Ls.K()
            (
                      [   0 -1/2*g]  [k 0]
            [q1, q2], [ 1/2*g      0], [0 k]
            )

        TESTS::

            sage: LinearSystem.from_equations([[1]], [[0]], identity_matrix(2))
            Traceback (most recent call last):
            ...
            AnalysisError: LinearSystem.from_equations: W is 2x2, expected 1x1 like M
        """
        M, S, W = (matrix_argument(X, name, AnalysisError, entry="LinearSystem.from_equations",
                                   square=True) for X, name in ((M, 'M'), (S, 'S'), (W, 'W')))
        n = M.nrows()
        for name, X in (('M', M), ('S', S), ('W', W)):
            if X.nrows() != n or X.ncols() != n:
                raise AnalysisError(f"{name} is {X.nrows()}x{X.ncols()}, expected {n}x{n} "
                                    "like M", entry="LinearSystem.from_equations")
        if variables is None:
            variables = [SR.var(f'q{i + 1}') for i in range(n)]
        return cls(variables, M=M, S=S, W=W)

    def stability(self, positive=(), with_respect_to=None):
        r"""
        The stability of the zero solution: the one stability service of the
        package (see :mod:`~sage_dynsym.analysis.stability`), for second-
        and first-order systems alike.

        INPUT:

        - ``positive`` -- parameters declared positive
        - ``with_respect_to`` -- (optional) the variables whose values the
          question is about; by default all but the ignorable ones (those
          whose value does not enter the equations), whose rates only count

        OUTPUT: a :class:`~sage_dynsym.analysis.verdict.StabilityVerdict`
        whose cases partition the parameter space allowed by the declared
        signs (``'undecided'`` is a case of its own, with its region and
        reason)

        EXAMPLES: the sleeping top (Euler--Poisson equations about the
        upright axis, `\gamma_3 = 1`, `M_3` the spin momentum):
        gyroscopically stable in first approximation exactly where `M_3^2 >
        4Amgl`, unstable below (Maxwell's criterion)::

            sage: from sage_dynsym.analysis.linear import linearize
            sage: M1, M2, M3, g1, g2, g3 = var('M1 M2 M3 gamma1 gamma2 gamma3')
            sage: A, C, m, g, l = var('A C m g l')
            sage: f = [g*l*m*g2 + (A - C)*M2*M3/(A*C), -g*l*m*g1 - (A - C)*M1*M3/(A*C),
            ....:      M3*g2/C - M2*g3/A, -M3*g1/C + M1*g3/A]
            sage: Ls = linearize(f, {M1: 0, M2: 0, g1: 0, g2: 0, g3: 1}, [M1, M2, g1, g2])
            sage: v = Ls.stability(positive=[A, C, m, g, l])
            sage: [(c.verdict(), c.region()) for c in v.cases()]
            [('stable in first approximation', [[4*A*g*l*m - M3^2 < 0]]),
             ('unstable', [[4*A*g*l*m - M3^2 > 0]])]
            sage: v.at({A: 1, C: 3/2, m: 1, g: 1, l: 1, M3: sqrt(3.8)})
            'unstable'
        """
        from .stability import linear_stability
        positive = symbol_arguments(positive, 'positive', error=AnalysisError)
        return linear_stability(self, positive=positive, with_respect_to=with_respect_to)

    def kelvin_chetaev(self, positive=()):
        r"""
        The stability verdict from the structure of forces and the first
        approximation (Kelvin--Chetaev theorems, gyroscopic stabilization,
        circulatory forces), see
        :func:`~sage_dynsym.analysis.kelvin_chetaev.kelvin_chetaev`.

        EXAMPLES::

            sage: from sage_dynsym.analysis.linear import LinearSystem
            sage: m, c, k = var('m c k')
            sage: LinearSystem([var('x')], M=[[m]], S=[[c]], W=[[k]]).kelvin_chetaev(
            ....:     positive=[m, c, k]).verdict()
            'asymptotically stable'
        """
        from .kelvin_chetaev import kelvin_chetaev
        self._second()
        return kelvin_chetaev(self.M(), self.D(), self.G(), self.K(), self.P(),
                              positive=positive)

    def small_damping_limit(self, damping, positive=()):
        r"""
        The stability as damping of the shape ``damping`` vanishes, beside
        the undamped system (the damping `D` of this system is replaced):
        see :func:`~sage_dynsym.analysis.damping_limit.small_damping_limit`.

        EXAMPLES::

            sage: from sage_dynsym.analysis.linear import LinearSystem
            sage: k = var('k')
            sage: Ls = LinearSystem([var('x')], M=[[1]], S=[[0]], W=[[k]])
            sage: Ls.small_damping_limit(matrix([[1]])).region()
            [[k > 0]]
        """
        from .damping_limit import small_damping_limit
        self._second()
        return small_damping_limit(self.M(), damping, self.G(), self.K(), self.P(),
                                   positive=positive)

    def linear_integrals(self):
        r"""
        Linear first integrals `c^T x` of the first-order form
        `\dot x = A x`: the left null space of `A` (constant integrals
        `\frac{d}{dt} c^T x = c^T A x = 0`).

        OUTPUT: list of expressions in the variables (and their ``d``
        symbols for the second-order form)

        EXAMPLES: a free coordinate gives a conserved momentum::

            sage: from sage_dynsym.analysis.linear import LinearSystem
            sage: x, y, m, k = var('x y m k')
            sage: Ls = LinearSystem([x, y], M=diagonal_matrix([m, m]),
            ....:                   S=zero_matrix(2), W=matrix([[k, -k], [-k, k]]))
            sage: Ls.linear_integrals()
            [dx + dy]
        """
        from ..symbols import velocity
        A = self.jacobian()
        xs = list(self._variables)
        if self._order == 2:
            xs += [velocity(v) for v in self._variables]
        result = []
        for c in A.transpose().right_kernel().basis():
            result.append(sum(ci * xi for ci, xi in zip(c, xs)))
        return [r.expand() for r in result]

    def quadratic_integrals(self):
        r"""
        Quadratic first integrals `x^T X x` of `\dot x = A x`: the symmetric
        solutions of `A^T X + X A = 0` (a basis).

        OUTPUT: list of quadratic expressions

        EXAMPLES: the energy of an oscillator::

            sage: from sage_dynsym.analysis.linear import LinearSystem
            sage: x, m, k = var('x m k')
            sage: LinearSystem([x], M=[[m]], S=[[0]], W=[[k]]).quadratic_integrals()
            [dx^2*m/k + x^2]
        """
        from ..symbols import velocity
        A = self.jacobian()
        N = A.nrows()
        xs = list(self._variables)
        if self._order == 2:
            xs += [velocity(v) for v in self._variables]
        idx = [(i, j) for i in range(N) for j in range(i, N)]
        eqs = []
        for r in range(N):
            for s in range(r, N):
                # (A^T X + X A)_{rs} = sum_k A_kr X_ks + X_rk A_ks
                row = []
                for (i, j) in idx:
                    coef = 0
                    for (a, b) in ((i, j), (j, i)) if i != j else ((i, j),):
                        if b == s:
                            coef += A[a, r]
                        if a == r:
                            coef += A[b, s]
                    row.append(coef)
                eqs.append(row)
        E = matrix(SR, eqs)
        result = []
        for sol in E.right_kernel().basis():
            X = matrix(SR, N, N)
            for (i, j), v in zip(idx, sol):
                X[i, j] = X[j, i] = v
            xv = matrix(SR, [xs]).transpose()
            q = (xv.transpose() * X * xv)[0, 0]
            result.append(_tidy(q.expand()).expand())
        return result


def linearize(system, at=None, variables=None, lhs_matrix=None, coordinates=None, speeds=None,
              values=None, sources=True):
    r"""
    The first-approximation system around an equilibrium, or around a
    steady motion (an operating point): the one way to build a linear
    system from a model, a characteristic function or right-hand sides.

    INPUT:

    - ``system`` -- either a list of right-hand sides `F` of a first-order
      system `B\dot x = F(x)`, or a characteristic-function object: a
      :class:`~sage_dynsym.dynamics.lagrangian.Lagrangian` (also a Routh function:
      linearization in the positional coordinates, cyclic momenta are
      parameters) or a :class:`~sage_dynsym.dynamics.hamiltonian.Hamiltonian`
    - ``at`` -- dict ``{variable: value}`` giving the point (coordinates for
      a Lagrangian; velocities are zero; missing coordinates are an error)
    - ``variables`` -- the list `x` (first-order systems; for a Hamiltonian
      the default is coordinates then momenta)
    - ``lhs_matrix`` -- (optional, first-order systems) the matrix `B`, or
      the list of its diagonal entries; default the identity. E.g. the
      inductances and capacitances of circuit state equations (8).
    - ``coordinates`` -- (optional) linearize about the steady motion ``at``
      (an :class:`~sage_dynsym.analysis.operating_point.OperatingPoint`,
      e.g. ``S.operating_point('upright')``, or a dict over coordinates and
      velocities) in these coordinates, the others being ignorable or tied
      to them by holonomic constraints; this is also the way for models
      with constraints, holonomic or on the velocities (rolling wheels), see
      :mod:`~sage_dynsym.analysis.steady`
    - ``speeds`` -- (optional, with ``coordinates``) the independent speeds
    - ``values`` -- (optional) dict ``{parameter: number}``: linearize
      numerically at any state ``at`` (a dict over the coordinates and
      velocities, or a sequence in the order `x = (q, \dot q)`), not only
      at equilibria, through the compiled Jacobian of the model's
      right-hand side (a model with ``numerical_linearization``, e.g. a
      :class:`~sage_dynsym.mechanics.system.MechanicalSystem`; the same as
      ``system.numerical_linearization(values, at)``)
    - ``sources`` -- (default: ``True``) with ``False``, a model (a
      circuit, a mechanical or a Lie--Poisson system) is linearized with
      its sources switched off, around its zero state or the state ``at``
      (a dict over its state variables or coordinates, others 0): its
      :meth:`~sage_dynsym.dynamics.model.Model.free_linear_system`, what a
      stability map maps

    OUTPUT: a :class:`LinearSystem`; second-order for a Lagrangian, else
    first-order. With ``values``: the matrix `A` over ``RDF`` of
    `\dot x = A x`, `x` the deviation of the state from ``at``

    Raises :class:`AnalysisError` if the point is not an equilibrium
    (without ``values``).

    EXAMPLES: see the module documentation, and Example 4 in
    :mod:`sage_dynsym.analysis.tutorial`. A first-order system::

        sage: from sage_dynsym.analysis.linear import linearize
        sage: x, y, a = var('x y a')
        sage: Ls = linearize([y, -sin(x) - a*y], {x: 0, y: 0}, [x, y]); Ls.jacobian()
        [ 0  1]
        [-1 -a]
        sage: linearize([y, -sin(x) - a*y], {x: 0, y: 1}, [x, y])
        Traceback (most recent call last):
        ...
        AnalysisError: linearize: the point {x: 0, y: 1} is not an equilibrium: equation 0 gives 1 != 0; for the linearization at any state numerically, give the parameters' values: linearize(system, state, values={parameter: number})

    At any state numerically, with the parameters' values (a pendulum,
    `\ddot\varphi = -(g/l)\sin\varphi`, moving through `\varphi = \pi/3`:
    `\partial\ddot\varphi/\partial\varphi = -(g/l)\cos\varphi`)::

        sage: from sage_dynsym import MechanicalSystem, RigidBody, UniformGravity
        sage: phi, m, l, g = var('phi m l g')
        sage: P = MechanicalSystem([RigidBody('rod', rotations=[(1, phi)], mass=m,
        ....:                      mass_center=[0, 0, -l], inertia=diagonal_matrix([m*l^2, m*l^2, 0]))],
        ....:                      [phi], force_function=UniformGravity([0, 0, -g]))
        sage: A = linearize(P, {phi: pi/3, 'dphi': 1}, values={m: 1, l: 2, g: 9.81})
        sage: A.parent(), A[0, 1], bool(abs(A[1, 0] + 9.81*cos(pi/3)/2) < 1e-14)
        (Full MatrixSpace of 2 by 2 dense matrices over Real Double Field, 1.0, True)

    A circuit with its sources off, around the zero state (`L_1 C_1
    \lambda^2 + R_1 C_1 \lambda + 1` for a series RLC circuit)::

        sage: from sage_dynsym import Circuit
        sage: C = Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 3, 'L1'], [3, 0, 'C1']])
        sage: linearize(C, sources=False).characteristic_polynomial(var('lam'))
        C1*L1*lam^2 + C1*R1*lam + 1

    TESTS::

        sage: linearize([y, x], {x: 0, y: 0}, [x, y], sources=False)
        Traceback (most recent call last):
        ...
        AnalysisError: sources: linearize(..., sources=False) switches off the sources of a model (a circuit, a mechanical or a Lie-Poisson system), got [y, x]; for right-hand sides, set the sources to 0 in them
        sage: linearize([y, x], {x: 1, y: 0}, [x, y], values={})
        Traceback (most recent call last):
        ...
        AnalysisError: values: linearize(..., values=...) linearizes a model with a compiled Jacobian (a mechanical system), got [y, x]; without values, linearize about an equilibrium symbolically
        sage: linearize(P, {phi: 1, 'dphi': 0}, values=[1, 2, 3])
        Traceback (most recent call last):
        ...
        AnalysisError: values: expected the parameters' values as a dict {parameter: number}, got [1, 2, 3]

        sage: linearize([y, x], {x: 0}, [x, y])
        Traceback (most recent call last):
        ...
        AnalysisError: linearize: no value given for y (the point must give every variable)

    A coordinate singularity is named (a heavy top in Euler angles, whose
    chart degenerates at `\theta = 0`)::

        sage: from sage_dynsym import Lagrangian
        sage: psi, th, phi, dpsi, dth, dphi, A, C = var('psi theta phi dpsi dtheta dphi A C')
        sage: L = Lagrangian(A/2*(dth^2 + sin(th)^2*dpsi^2) + C/2*(dphi + cos(th)*dpsi)^2,
        ....:                [psi, th, phi])
        sage: linearize(L, {psi: 0, th: 0, phi: 0})
        Traceback (most recent call last):
        ...
        AnalysisError: linearize: the point {psi: 0, theta: 0, phi: 0} is a singularity of the coordinates: the kinetic matrix is singular at theta = 0 (the chart degenerates there, as Euler angles do at theta = 0); linearize in a regular chart instead (e.g. other angles for the axis)
        sage: linearize(L.routh([psi, phi]), {th: 0})
        Traceback (most recent call last):
        ...
        AnalysisError: linearize: the point {theta: 0} is a singularity of the coordinates: a denominator of the equations vanishes at theta = 0 (the chart degenerates there, as Euler angles do at theta = 0); linearize in a regular chart instead (e.g. other angles for the axis)
    """
    from .operating_point import OperatingPoint
    if values is not None:
        return _linearize_numerically(system, at, values)
    if not sources:
        if not callable(getattr(system, 'free_linear_system', None)):
            raise AnalysisError("linearize(..., sources=False) switches off the sources of a "
                                "model (a circuit, a mechanical or a Lie-Poisson system), got "
                                f"{brief(system)}; for right-hand sides, set the sources to 0 "
                                "in them", entry="sources")
        return system.free_linear_system(at)
    data = _record(system)
    if coordinates is not None or speeds is not None or isinstance(at, OperatingPoint) or (
            isinstance(data, SecondOrderEquations) and data.velocity_constraints()):
        from .steady import steady_linearization
        if not isinstance(data, SecondOrderEquations):
            raise AnalysisError("steady motions are linearized from second-order equations "
                                "(a Lagrangian or a mechanical system)", entry="linearize")
        motion = steady_linearization(data, at, coordinates, speeds)
        return LinearSystem(motion.coordinates(), M=motion.M(), S=motion.S(), W=motion.W(),
                            steady_motion=motion)
    if data is None:
        system = expression_list(system, "system", AnalysisError, expected="a model, a "
                                 "Lagrangian, a Routh function, a Hamiltonian or a list of "
                                 "right-hand sides", hint="e.g. linearize(model.lagrangian(), "
                                 "{q: 0})")
    if not isinstance(at, dict):
        raise AnalysisError(f"expected the point as a dict {{variable: value}}, got "
                            f"{brief(at)}", entry="at")
    at = {SR.var(k) if isinstance(k, str) and k.isidentifier() else
          expression_argument(k, "at", AnalysisError, expected="variables or their names as keys"):
          expression_argument(v, f"at[{k}]", AnalysisError, expected="a number or an expression")
          for k, v in at.items()}
    data = _without_constraints(data)
    if isinstance(data, SecondOrderEquations):
        return _linearize_second_order(data, at)
    if isinstance(data, FirstOrderEquations):
        return _linearize_first_order(data.rhs(), at,
                                      variables if variables is not None else data.variables(),
                                      data.lhs_matrix())
    if variables is None:
        raise AnalysisError("a list of right-hand sides needs the list of "
                            "variables", entry="linearize")
    return _linearize_first_order(list(system), at, variables, lhs_matrix)


def _linearize_numerically(system, at, values):
    # the model's own compiled Jacobian (duck typing: the analysis layer
    # does not know the mechanical models)
    if not hasattr(system, 'numerical_linearization'):
        raise AnalysisError(f"linearize(..., values=...) linearizes a model with a compiled "
                            f"Jacobian (a mechanical system), got {brief(system)}; without "
                            f"values, linearize about an equilibrium symbolically",
                            entry="values")
    if not isinstance(values, dict):
        raise AnalysisError(f"expected the parameters' values as a dict {{parameter: number}}, "
                            f"got {brief(values)}", entry="values")
    return system.numerical_linearization(values, at)


def equations_of_motion(system):
    r"""
    The neutral record of a system's equations (see
    :mod:`~sage_dynsym.analysis.motion`): ``system.equations_record()`` when
    the object has it; ``None`` for a plain list of right-hand sides.

    EXAMPLES::

        sage: from sage_dynsym import Lagrangian
        sage: from sage_dynsym.analysis.linear import equations_of_motion
        sage: x, dx = var('x dx')
        sage: equations_of_motion(Lagrangian(dx^2/2 - x^2/2, [x]))
        Second-order equations in (x): [ddx + x] == 0
        sage: equations_of_motion([x]) is None
        True

    Equations with constraint multipliers are refused (the stationary-motion
    search and the linearization about equilibria work in independent
    coordinates; :func:`linearize` with ``coordinates=`` eliminates them)::

        sage: from sage_dynsym.analysis.linear import linearize
        sage: y, dy = var('y dy')
        sage: L = Lagrangian((dx^2 + dy^2)/2 - x^2/2, [x, y], constraints=[x - y])
        sage: equations_of_motion(L)
        Traceback (most recent call last):
        ...
        AnalysisError: constraints: the equations have the constraints [x - y] with multipliers [mu1], which the analysis does not handle; reduce the model to independent coordinates first (Lagrangian.reduce), or linearize in chosen coordinates (linearize(..., coordinates=[...]))
        sage: Ls = linearize(L, {x: 0, y: 0}, coordinates=[x]); Ls.M(), Ls.K()
        ([2], [1])

    A rolling (nonholonomic) model is pointed to its steady motions (a
    knife edge)::

        sage: from sage_dynsym import MechanicalSystem, RigidBody
        sage: th, m = var('theta m')
        sage: knife = MechanicalSystem([RigidBody('blade', joint=[x, y, 0], rotations=[(3, th)],
        ....:                                     mass=m, inertia=m*identity_matrix(3))],
        ....:                          [x, y, th], nonholonomic=[sin(th)*dx - cos(th)*var('dy')])
        sage: equations_of_motion(knife)
        Traceback (most recent call last):
        ...
        AnalysisError: constraints: the equations have the velocity constraints [-dy*cos(theta) + dx*sin(theta)] (a rolling or nonholonomic model), which no choice of coordinates removes; find its steady motions with steady_motions(system, OperatingPoint(name, at, velocities), solve_for=[...]) and linearize about one in chosen coordinates (linearize(system, point, coordinates=[...]))
    """
    return _without_constraints(_record(system))


def _without_constraints(data):
    # the record, refused when it has constraint multipliers
    if isinstance(data, SecondOrderEquations) and (data.constraints()
                                                   or data.velocity_constraints()):
        constraints = data.constraints() + data.velocity_constraints()
        multipliers = data.multipliers() + data.velocity_multipliers()
        if data.velocity_constraints():
            # a rolling (nonholonomic) model: there are no independent
            # coordinates to reduce to, its motions are steady motions
            raise AnalysisError(f"the equations have the velocity constraints "
                                f"{data.velocity_constraints()} (a rolling or nonholonomic "
                                "model), which no choice of coordinates removes; find its "
                                "steady motions with steady_motions(system, "
                                "OperatingPoint(name, at, velocities), solve_for=[...]) and "
                                "linearize about one in chosen coordinates (linearize(system, "
                                "point, coordinates=[...]))", entry="constraints")
        raise AnalysisError(f"the equations have the constraints {constraints} with "
                            f"multipliers {multipliers}, which the analysis does not handle; "
                            "reduce the model to independent coordinates first "
                            "(Lagrangian.reduce), or linearize in chosen coordinates "
                            "(linearize(..., coordinates=[...]))", entry="constraints")
    return data


def _record(system):
    # the neutral record of a model or characteristic function, unchecked
    # to_linearizer: the name of earlier versions, still honoured for other classes
    record = getattr(system, 'equations_record', None) or getattr(system, 'to_linearizer', None)
    if record is not None:
        return record()
    if hasattr(system, 'lagrange_equations'):
        return SecondOrderEquations(system.lagrange_equations(), system.coordinates(),
                                    system.velocities(), system.accelerations())
    if hasattr(system, 'momenta') and hasattr(system, 'equations'):
        pairs = system.equations()
        return FirstOrderEquations([a for a, _ in pairs] + [b for _, b in pairs],
                                   list(system.coordinates()) + list(system.momenta()))
    return None


def _point_for(variables, at):
    for v in variables:
        if SR(v) not in at:
            raise AnalysisError(f"no value given for {v} (the point must give "
                                f"every variable)", entry="linearize")
    return {SR(v): at[SR(v)] for v in variables}


def _linearize_first_order(rhs, at, variables, lhs_matrix):
    variables = [SR(v) for v in variables]
    point = _point_for(variables, at)
    point.update(at)
    rhs = [SR(f) for f in rhs]
    if len(rhs) != len(variables):
        raise AnalysisError(f"{len(rhs)} right-hand sides for {len(variables)} "
                            f"variables", entry="linearize")
    _check_equilibrium([_at(f, point) for f in rhs], point)
    J = matrix(SR, [[_tidy(_at(f.diff(v), point)) for v in variables] for f in rhs])
    B = None
    if lhs_matrix is not None:
        B = matrix(SR, lhs_matrix) if isinstance(lhs_matrix[0], (list, tuple)) or \
            hasattr(lhs_matrix, 'nrows') else matrix.diagonal(SR, list(lhs_matrix))
        B = B.apply_map(lambda e: _at(e, point))
    return LinearSystem(variables, J=J, B=B)


def _linearize_second_order(L, at):
    q, dq, ddq = L.coordinates(), L.velocities(), L.accelerations()
    point = _point_for(q, at)
    for v in list(dq) + list(ddq):
        if v in at and not SR(at[v]).is_zero():
            raise AnalysisError(f"linearization of a Lagrangian is around an "
                                f"equilibrium (velocities zero), got {v} = {at[v]}; "
                                f"for steady motions use the Routh function",
                                entry="linearize")
        point[v] = SR(0)
    point.update({k: v for k, v in at.items() if k not in point})
    E = [SR(e) for e in L.equations()]
    _check_equilibrium([_at(e, point) for e in E], point)
    mat = lambda xs: matrix(SR, [[_tidy(_at(e.diff(x), point)) for x in xs] for e in E])
    M = mat(ddq)
    if vanishes(_fraction_free_det(M)):
        # singular at this point only: a chart singularity (a kinetic matrix
        # singular everywhere -- loops without inductance -- is structural)
        kinetic = matrix(SR, [[e.diff(x) for x in ddq] for e in E])
        if not vanishes(_fraction_free_det(kinetic)):
            raise _singularity(kinetic.det(), point, what="the kinetic matrix is singular")
    return LinearSystem(q, M=M, S=mat(dq), W=mat(q))
