r"""
Invariant manifolds: the modified Routh--Lyapunov method

For a Routh function `R(q, \dot q; c)` with positional coordinates `q =
(q_1, \dots, q_n)` and a cyclic momentum `c`, the *extended* function

.. MATH::

    \tilde R = R + c \sum_{i=1}^n f_i(q)\,\dot q_i, \qquad f_i = \frac{\partial s}{\partial q_i},

adds the total derivative `c\,\dot s` of a generating function `s(q)`, so
`\tilde R` and `R` have the same equations of motion (:doc:`the method
</method>`, :ref:`the modified method <method-modified-routh-lyapunov>`).
The stationarity equations `\partial\tilde R/\partial\dot q_i = 0` give the
velocities on a manifold, `\dot q = \varphi(q)`; the equations
`\partial\tilde R/\partial q_i = 0` hold *identically* on it -- the
*degeneracy conditions*, a system of first-order partial differential
equations for the `f_i` (with the compatibility `\partial f_i/\partial q_j
= \partial f_j/\partial q_i` of a gradient) -- exactly when the manifold is
invariant: along the motion `\frac{d}{dt}\partial\tilde R/\partial\dot q =
\partial\tilde R/\partial q`, so the velocity field is tangent to the
manifold where both vanish.

The degeneracy conditions are the gradient of one equation: with `\hat H(q,
f) = \big(\dot q\cdot\partial R/\partial\dot q - R\big)_{\dot q =
\varphi(q)}` (the energy of the Routh system at the momenta `p = -c f`),
`\partial\tilde R/\partial q_i|_{\dot q=\varphi} = -\frac{d}{dq_i}\hat H(q,
f(q))`, so they say `\hat H(q, \nabla s) = E`, the Hamilton--Jacobi
equation of the Routh system (:meth:`ModifiedRouthLyapunov.energy_equation`).

- One coordinate: an ordinary differential equation for `f`, integrated by
  Sage (``desolve``); its general solution gives the family `\dot q =
  \varphi(q, C)` (Example 3).
- Several coordinates: solved exactly when the equation *separates* --
  multiplied by one of the candidate factors (`1`, or the reciprocal of
  the coefficient of some `f_i^2`), it becomes a sum of terms each in one
  pair `(q_i, f_i)`; each is set equal to a separation constant and
  solved for `f_i`. Otherwise an :class:`~sage_dynsym.errors.AnalysisError`
  says so.

Every family is verified to be invariant before it is returned: the
equations of motion of `R` vanish on it, with `\ddot q_i = \sum_j
\partial\varphi_i/\partial q_j\,\varphi_j` (exactly, or numerically at
random complex points for expressions Sage does not reduce to zero).

EXAMPLES: a particle in an axisymmetric field `V_1(r) + V_2(z)` in
cylindrical coordinates, the angle `\varphi` cyclic -- two positional
coordinates; the families are the levels of the energy `\_E` and of the
separation constant `\_C1` (the energy of the vertical motion)::

    sage: from sage_dynsym import Lagrangian
    sage: from sage_dynsym.analysis.modified_routh import ModifiedRouthLyapunov
    sage: r, z, phi, dr, dz, dphi = var('r z phi dr dz dphi')
    sage: V1, V2 = function('V1'), function('V2')
    sage: L = Lagrangian((dr^2 + r^2*dphi^2 + dz^2)/2 - V1(r) - V2(z), [r, z, phi])
    sage: MR = ModifiedRouthLyapunov(L.routh([phi])); MR
    Modified Routh-Lyapunov method for ... in (r, z)
    sage: MR.energy_equation()
    1/2*p_phi^2*f1(r, z)^2 + 1/2*p_phi^2*f2(r, z)^2 + 1/2*p_phi^2/r^2 + V1(r) + V2(z) == _E
    sage: families = MR.invariant_manifolds(); len(families)
    4
    sage: families[0]
    [dr == sqrt(-2*_C1*r^2 + 2*_E*r^2 - 2*r^2*V1(r) - p_phi^2)/r,
     dz == sqrt(2*_C1 - 2*V2(z))]

REFERENCES:

- A. M. Lyapunov, *The General Problem of the Stability of Motion*,
  Taylor & Francis, 1992.
- V. V. Rumyantsev, *On the stability of steady motions*, J. Appl. Math.
  Mech. 30 (1966) 1090--1103.
- V. I. Arnold, *Mathematical Methods of Classical Mechanics*, 2nd ed.,
  Springer, 1989, §47 (separation of variables in the Hamilton--Jacobi
  equation).
"""
import itertools
import random

from sage.matrix.constructor import matrix
from sage.rings.complex_mpfr import ComplexField
from sage.structure.sage_object import SageObject
from sage.symbolic.function_factory import function as symbolic_function
from sage.symbolic.ring import SR

from ..arguments import symbol_arguments
from ..errors import AnalysisError, brief
from ..symbols import velocity
from .linear import equations_of_motion
from ..algebra.radicals import roots_in_radicals
from ..algebra.solving import solve_exactly, solve_transcendental, normalize, vanishes

__all__ = ['CHECK_POINTS', 'ModifiedRouthLyapunov']

#: Random complex points at which an equation of motion that Sage does not
#: simplify to zero is evaluated on a family.
CHECK_POINTS = 5

_WHAT = "ModifiedRouthLyapunov"


def _solve_linear(expr, v, what):
    r"""``v`` from ``expr == 0`` when ``expr`` is linear in ``v``."""
    expr = SR(expr)
    a = expr.diff(v)
    if a.has(v) or a.is_zero():
        raise AnalysisError(f"cannot solve {expr} == 0 for {v}: it is not linear in it",
                            entry=what)
    return normalize(-expr.subs({v: 0}) / a)


def _vanishes_numerically(expr, seed=0):
    r"""``expr`` at random complex points of its symbols, to 60 digits: all
    tiny. ``False`` if it has symbols that cannot be evaluated (unspecified
    functions)."""
    rng = random.Random(seed)
    C = ComplexField(200)
    symbols = expr.variables()
    for _ in range(CHECK_POINTS):
        point = {s: C(rng.uniform(0.3, 2), rng.uniform(-0.3, 0.3)) for s in symbols}
        try:
            value = C(expr.subs(point))
        except (TypeError, ValueError, ZeroDivisionError, ArithmeticError):
            return False
        if abs(value) > C(10) ** -50:
            return False
    return True


class ModifiedRouthLyapunov(SageObject):
    r"""
    The modified Routh--Lyapunov method for families of invariant manifolds
    of a system with positional coordinates `q` and a cyclic momentum `c`
    (see the module documentation; Example 3 of :doc:`the method
    </method>` for one coordinate).

    INPUT:

    - ``routh`` -- a :class:`~sage_dynsym.dynamics.lagrangian.RouthFunction`,
      or a :class:`~sage_dynsym.dynamics.lagrangian.Lagrangian` (a system
      without cyclic coordinates: the Routh function is the Lagrangian
      itself, and `c = 1`, so `\tilde R = L + \sum_i f_i(q)\dot q_i` and
      the families are the solutions of the Hamilton--Jacobi equation of
      `L`)
    - ``momentum`` -- (default: the first cyclic momentum, or `1` when
      there is none) the constant `c`
    - ``f`` -- (default: ``function('f')`` for one coordinate, ``f1, f2,
      ...`` for several) the unknown function(s)
    - ``positive`` -- (optional) symbols declared positive, used as
      assumptions when the equation is integrated (Maxima); a sign it still
      needs is an :class:`~sage_dynsym.errors.AnalysisError` naming it

    EXAMPLES: see :mod:`sage_dynsym.analysis.tutorial` (Example 3). ::

        sage: from sage_dynsym import Lagrangian
        sage: from sage_dynsym.analysis.modified_routh import ModifiedRouthLyapunov
        sage: r, phi, dr, dphi = var('r phi dr dphi')
        sage: MR = ModifiedRouthLyapunov(Lagrangian((dr^2 + r^2*dphi^2)/2 + 1/r, [r, phi]).routh([phi]))
        sage: MR.velocity_on_manifold()
        -p_phi*f(r)

    It has no value equality (two of them are equal only if they are the
    same object), so the pickling test, which compares the copy with the
    original, is skipped::

        sage: TestSuite(MR).run(skip=['_test_pickling'])

    A Lagrangian without cyclic coordinates is its own Routh function: for
    the pendulum `L = \dot\theta^2/2 + \omega^2\cos\theta` the families
    are the levels of the energy `\dot\theta^2/2 - \omega^2\cos\theta`::

        sage: theta, dtheta, w = var('theta dtheta omega')
        sage: P = ModifiedRouthLyapunov(Lagrangian(dtheta^2/2 + w^2*cos(theta), [theta]))
        sage: P.extended_function()
        omega^2*cos(theta) + 1/2*dtheta^2 + dtheta*f(theta)
        sage: P.invariant_manifolds()
        [dtheta == -sqrt(-2*_C + 2*cos(theta))*omega, dtheta == sqrt(-2*_C + 2*cos(theta))*omega]
        sage: [diff(m.rhs()^2/2 - w^2*cos(theta), theta) for m in P.invariant_manifolds()]
        [0, 0]

    TESTS::

        sage: x, dx = var('x dx')
        sage: ModifiedRouthLyapunov(Lagrangian(dx^2/2, [x]).routh([x]))
        Traceback (most recent call last):
        ...
        AnalysisError: ModifiedRouthLyapunov: the Routh function has no positional coordinates
        sage: ModifiedRouthLyapunov(Lagrangian(dx^2/2, [x]).hamiltonian())
        Traceback (most recent call last):
        ...
        AnalysisError: ModifiedRouthLyapunov: expected a Routh function (L.routh([cyclic coordinates])) or a Lagrangian, got Hamiltonian ...
        sage: ModifiedRouthLyapunov(None)
        Traceback (most recent call last):
        ...
        AnalysisError: ModifiedRouthLyapunov: expected a Routh function (L.routh([cyclic coordinates])) or a Lagrangian, got None
    """

    def __init__(self, routh, momentum=None, f=None, positive=()):
        if not all(callable(getattr(routh, name, None)) for name in
                   ('coordinates', 'velocities', 'expr', 'lagrange_equations')):
            raise AnalysisError("expected a Routh function (L.routh([cyclic coordinates])) or "
                                f"a Lagrangian, got {brief(routh)}", entry=_WHAT)
        self._positive = symbol_arguments(positive, "positive", AnalysisError, entry=_WHAT)
        q = list(routh.coordinates())
        if not q:
            raise AnalysisError("the Routh function has no positional coordinates",
                                entry=_WHAT)
        momenta = routh.momenta() if callable(getattr(routh, 'momenta', None)) else []
        self._routh = routh
        self._qs, self._dqs = q, list(routh.velocities())
        self._n = len(q)
        # without a cyclic momentum R is L itself and c only scales f: c = 1
        self._c = SR(momentum) if momentum is not None else SR(momenta[0] if momenta else 1)
        if self._n == 1:
            self._q, self._dq = q[0], self._dqs[0]
            self._f = f if f is not None else symbolic_function('f')
            self._fs = [self._f(self._q)]
            self._Rt = SR(routh.expr()) + self._c * self._fs[0] * self._dq
        else:
            functions = f if f is not None else [symbolic_function(f"f{i + 1}")
                                                  for i in range(self._n)]
            if len(functions) != self._n:
                raise AnalysisError(f"expected {self._n} functions f, got {len(functions)}",
                                    entry=_WHAT)
            self._fs = [fi(*q) for fi in functions]
            self._Rt = SR(routh.expr()) + self._c * sum(fi * v for fi, v in
                                                         zip(self._fs, self._dqs))
        self._families = None

    def _repr_(self):
        if self._n == 1:
            return f"Modified Routh-Lyapunov method for {self._Rt}"
        return (f"Modified Routh-Lyapunov method for {self._Rt} in "
                f"({', '.join(map(str, self._qs))})")

    def extended_function(self):
        r"""`\tilde R = R + c\sum_i f_i(q)\dot q_i`.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: from sage_dynsym.analysis.modified_routh import ModifiedRouthLyapunov
            sage: r, phi, dr, dphi = var('r phi dr dphi')
            sage: L = Lagrangian((dr^2 + r^2*dphi^2)/2 + 1/r, [r, phi])
            sage: ModifiedRouthLyapunov(L.routh([phi])).extended_function()
            dr*p_phi*f(r) + 1/2*dr^2 - 1/2*p_phi^2/r^2 + 1/r
        """
        return self._Rt

    def stationarity_equations(self):
        r"""
        The derivatives of `\tilde R` (each ``== 0``): by the positional
        coordinates, then by their velocities.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: from sage_dynsym.analysis.modified_routh import ModifiedRouthLyapunov
            sage: r, phi, dr, dphi = var('r phi dr dphi')
            sage: L = Lagrangian((dr^2 + r^2*dphi^2)/2 + 1/r, [r, phi])
            sage: ModifiedRouthLyapunov(L.routh([phi])).stationarity_equations()
            [dr*p_phi*diff(f(r), r) + p_phi^2/r^3 - 1/r^2, p_phi*f(r) + dr]
        """
        return [self._Rt.diff(v) for v in self._qs] + [self._Rt.diff(v) for v in self._dqs]

    def velocity_on_manifold(self):
        r"""
        The velocities from `\partial\tilde R/\partial\dot q = 0`, in terms
        of the `f_i`: an expression for one coordinate, a list for several.

        EXAMPLES: see the class documentation. Two coordinates::

            sage: from sage_dynsym import Lagrangian
            sage: from sage_dynsym.analysis.modified_routh import ModifiedRouthLyapunov
            sage: r, z, phi, dr, dz, dphi = var('r z phi dr dz dphi')
            sage: L = Lagrangian((dr^2 + r^2*dphi^2 + dz^2)/2 - z, [r, z, phi])
            sage: ModifiedRouthLyapunov(L.routh([phi])).velocity_on_manifold()
            [-p_phi*f1(r, z), -p_phi*f2(r, z)]
        """
        if self._n == 1:
            return _solve_linear(self.stationarity_equations()[1], self._dq, _WHAT)
        eqs = self.stationarity_equations()[self._n:]
        A = matrix(SR, [[e.diff(v) for v in self._dqs] for e in eqs])
        if any(x.has(v) for x in A.list() for v in self._dqs):
            raise AnalysisError("the Routh function is not quadratic in the velocities",
                                entry=_WHAT)
        b = matrix(SR, [[e.subs({v: 0 for v in self._dqs})] for e in eqs])
        try:
            solution = -A.solve_right(b)
        except (ValueError, ZeroDivisionError) as err:
            raise AnalysisError(f"the kinetic matrix {A} of the Routh function is singular",
                                entry=_WHAT) from err
        return [normalize(solution[i, 0]) for i in range(self._n)]

    def _velocities(self):
        v = self.velocity_on_manifold()
        return [v] if self._n == 1 else v

    def degeneracy_condition(self):
        r"""
        The ODE for `f` (one positional coordinate): the equation
        `\partial\tilde R/\partial q = 0` with `\dot q` from
        :meth:`velocity_on_manifold` must hold for every `q`. Returned
        solved for the derivative, ``diff(f(q), q) == ...``. For several
        coordinates see :meth:`degeneracy_conditions`.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: from sage_dynsym.analysis.modified_routh import ModifiedRouthLyapunov
            sage: r, phi, dr, dphi = var('r phi dr dphi')
            sage: L = Lagrangian((dr^2 + r^2*dphi^2)/2 + 1/r, [r, phi])
            sage: ModifiedRouthLyapunov(L.routh([phi])).degeneracy_condition()
            diff(f(r), r) == (p_phi^2 - r)/(p_phi^2*r^3*f(r))
        """
        if self._n != 1:
            raise AnalysisError(f"{self._n} positional coordinates: the degeneracy "
                                "conditions are a system (degeneracy_conditions())", entry=_WHAT)
        dRq = self.stationarity_equations()[0]
        e = dRq.subs({self._dq: self.velocity_on_manifold()})
        fq = self._fs[0]
        fp = fq.diff(self._q)
        tmp = SR.symbol('fprime_')
        e = e.subs({fp: tmp})
        try:
            return fp == _solve_linear(e, tmp, _WHAT).subs({tmp: fp})
        except AnalysisError:
            return normalize(e.subs({tmp: fp})) == 0

    def degeneracy_conditions(self):
        r"""
        The degeneracy conditions: the equations `\partial\tilde
        R/\partial q_i = 0` with the velocities of
        :meth:`velocity_on_manifold`, each ``== 0`` for every `q` -- partial
        differential equations for the `f_i` --, followed by the conditions
        `\partial f_i/\partial q_j - \partial f_j/\partial q_i = 0` that
        make `f` a gradient (so that `\tilde R` has the equations of `R`).

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: from sage_dynsym.analysis.modified_routh import ModifiedRouthLyapunov
            sage: r, z, phi, dr, dz, dphi = var('r z phi dr dz dphi')
            sage: L = Lagrangian((dr^2 + r^2*dphi^2 + dz^2)/2 - z, [r, z, phi])
            sage: for e in ModifiedRouthLyapunov(L.routh([phi])).degeneracy_conditions(): print(e)
            -p_phi^2*f1(r, z)*diff(f1(r, z), r) - p_phi^2*f2(r, z)*diff(f2(r, z), r) + p_phi^2/r^3 == 0
            -p_phi^2*f1(r, z)*diff(f1(r, z), z) - p_phi^2*f2(r, z)*diff(f2(r, z), z) - 1 == 0
            diff(f1(r, z), z) - diff(f2(r, z), r) == 0
        """
        at = dict(zip(self._dqs, self._velocities()))
        eqs = [e.subs(at).expand() == 0 for e in self.stationarity_equations()[:self._n]]
        for i, j in itertools.combinations(range(self._n), 2):
            eqs.append(self._fs[i].diff(self._qs[j]) - self._fs[j].diff(self._qs[i]) == 0)
        return eqs

    def energy_equation(self):
        r"""
        The degeneracy conditions integrated once: `\hat H(q, f(q)) = E`,
        with `\hat H = (\dot q\cdot\partial R/\partial\dot q - R)` at the
        velocities of :meth:`velocity_on_manifold` and `E` (``_E``) a
        constant; for `f = \nabla s` the Hamilton--Jacobi equation of the
        Routh system. The degeneracy condition `i` is `-d\hat H/dq_i = 0`.

        EXAMPLES: the one-coordinate case of the class documentation::

            sage: from sage_dynsym import Lagrangian
            sage: from sage_dynsym.analysis.modified_routh import ModifiedRouthLyapunov
            sage: r, phi, dr, dphi = var('r phi dr dphi')
            sage: L = Lagrangian((dr^2 + r^2*dphi^2)/2 + 1/r, [r, phi])
            sage: ModifiedRouthLyapunov(L.routh([phi])).energy_equation()
            1/2*p_phi^2*f(r)^2 + 1/2*p_phi^2/r^2 - 1/r == _E
        """
        at = dict(zip(self._dqs, self._velocities()))
        R = SR(self._routh.expr())
        H = sum(v * R.diff(v) for v in self._dqs) - R
        return H.subs(at).expand() == self._constant('_E')

    def _constant(self, name):
        used = {str(v) for v in SR(self._Rt).variables()}
        while name in used:
            name += '_'
        return SR.var(name)

    def solve_degeneracy(self):
        r"""
        The solutions of the degeneracy conditions.

        One coordinate: the general solution of the ODE (``desolve``), as a
        list of explicit solutions ``f(q) == ...`` (with the integration
        constant ``_C``; the implicit solution is solved for `f` exactly),
        or the implicit one if it cannot be solved for `f`.

        Several coordinates: the separated solutions of
        :meth:`energy_equation`, a list of dicts ``{f_i(q): ...}`` with the
        constants ``_E`` (energy) and ``_C1, _C2, ...`` (separation), one
        per choice of the branches; an :class:`~sage_dynsym.errors.AnalysisError`
        if the equation does not separate in these coordinates.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: from sage_dynsym.analysis.modified_routh import ModifiedRouthLyapunov
            sage: r, phi, dr, dphi = var('r phi dr dphi')
            sage: L = Lagrangian((dr^2 + r^2*dphi^2)/2 + 1/r, [r, phi])
            sage: sols = ModifiedRouthLyapunov(L.routh([phi])).solve_degeneracy(); len(sols)
            2

        The Kepler problem in spherical coordinates separates once
        multiplied by `r^2` (the coefficient of `f_\theta^2` is `1/r^2`)::

            sage: th, dth, k = var('theta dtheta k')
            sage: K = Lagrangian((dr^2 + r^2*dth^2 + r^2*sin(th)^2*dphi^2)/2 + k/r, [r, th, phi])
            sage: sols = ModifiedRouthLyapunov(K.routh([phi])).solve_degeneracy(); len(sols)
            4
            sage: sols[0]
            {f1(r, theta): -sqrt(-_C1*p_phi^2 + 2*_E*r^2 + 2*k*r)/(p_phi*r),
             f2(r, theta): -sqrt(_C1*sin(theta)^2 - 1)/sin(theta)}

        TESTS: a sign the integration needs is asked for, not assumed::

            sage: q, dq, a = var('q dq a')
            sage: La = Lagrangian(dq^2/2 + (q^2 + 1)*dphi^2/2 + arctan(q/sqrt(a))/sqrt(a), [q, phi])
            sage: ModifiedRouthLyapunov(La.routh([phi])).solve_degeneracy()
            Traceback (most recent call last):
            ...
            AnalysisError: ModifiedRouthLyapunov: Maxima needs the sign of a: declare it with positive=[a]
            sage: len(ModifiedRouthLyapunov(La.routh([phi]), positive=[a]).solve_degeneracy())
            2

        The Kepler problem in cylindrical coordinates does not separate::

            sage: z, dz = var('z dz')
            sage: Kc = Lagrangian((dr^2 + r^2*dphi^2 + dz^2)/2 + k/sqrt(r^2 + z^2), [r, z, phi])
            sage: ModifiedRouthLyapunov(Kc.routh([phi])).solve_degeneracy()
            Traceback (most recent call last):
            ...
            AnalysisError: ModifiedRouthLyapunov: the degeneracy conditions (the equation 1/2*p_phi^2*f1(r, z)^2 + 1/2*p_phi^2*f2(r, z)^2 - k/sqrt(r^2 + z^2) + 1/2*p_phi^2/r^2 == _E) do not separate in the coordinates r, z (tried the factors [1]); use coordinates in which they do (spherical or parabolic ones for a Newtonian field)
        """
        if self._n == 1:
            return self._solve_ode()
        return self._separate()

    def _solve_ode(self):
        from sage.calculus.desolvers import desolve
        from ..algebra.polynomials import maxima_without_questions
        fq = self._fs[0]
        with maxima_without_questions(_WHAT, self._positive):
            sol = desolve(self.degeneracy_condition(), fq, ivar=self._q)
        try:
            found = solve_exactly([sol], [fq])
        except AnalysisError:
            return [sol]
        explicit = [s for s in found if s.is_explicit() and s.dimension() == 0]
        return [fq == normalize(s.values()[fq]) for s in explicit] if explicit else [sol]

    def _separate(self):
        equation = self.energy_equation()
        E = equation.rhs()
        u = [SR.symbol(f"u{i}") for i in range(self._n)]
        Phi = (equation.lhs() - E).subs(dict(zip(self._fs, u)))
        factors = _candidate_factors(Phi, u, self._qs)
        groups = [[q, ui] for q, ui in zip(self._qs, u)]
        for mu in factors:
            parts = _split(mu * Phi, groups)
            if parts is not None:
                break
        else:
            raise AnalysisError(
                f"the degeneracy conditions (the equation {equation}) do not separate in the "
                f"coordinates {', '.join(map(str, self._qs))} (tried the factors {factors}); "
                "use coordinates in which they do (spherical or parabolic ones for a "
                "Newtonian field)", entry=_WHAT)
        separated, rest = parts
        # the separation constants belong to q_2, ..., q_n; the energy stays with q_1
        constants = [self._constant(f"_C{i + 1}") for i in range(self._n - 1)]
        rhs = [-rest - sum(constants)] + constants
        branches = []
        for F, ui, c in zip(separated, u, rhs):
            branches.append(self._separated_roots(F - c, ui))
        return [{f: x for f, x in zip(self._fs, choice)}
                for choice in itertools.product(*branches)]

    @staticmethod
    def _separated_roots(equation, ui):
        r"""The values of the unknown function ``ui`` solving ``equation = 0``:
        by the formulas of degrees one and two, else by the documented
        fallback for equations that are not algebraic (explicit, verified
        solutions only)."""
        if equation.has(ui) and equation.is_polynomial(ui) and equation.degree(ui) <= 2:
            return roots_in_radicals(equation, ui, entry=_WHAT)
        found, why = [], None
        try:
            found = solve_transcendental([equation], [ui], reason="a separated equation")
        except AnalysisError as err:    # reported below, as the cause
            why = err
        roots = [s.values()[ui] for s in found]
        if not roots:
            raise AnalysisError(f"cannot solve the separated equation {equation} == 0 for the "
                                "unknown function explicitly", entry=_WHAT) from why
        return roots

    def invariant_manifolds(self):
        r"""
        The families of invariant manifolds in explicit form, each verified
        to be invariant (the equations of motion of `R` vanish on it).

        OUTPUT: one coordinate: a list of equations ``dq == phi(q, _C)``;
        several: a list of families, each a list of equations ``dq_i ==
        phi_i(q, _E, _C1, ...)``, one per positional velocity

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: from sage_dynsym.analysis.modified_routh import ModifiedRouthLyapunov
            sage: r, phi, dr, dphi = var('r phi dr dphi')
            sage: L = Lagrangian((dr^2 + r^2*dphi^2)/2 + 1/r, [r, phi])
            sage: [im.lhs() for im in ModifiedRouthLyapunov(L.routh([phi])).invariant_manifolds()]
            [dr, dr]
        """
        if self._families is None:
            velocities = self._velocities()
            families = []
            for solution in self.solve_degeneracy():
                if self._n == 1:
                    if not solution.lhs() == self._fs[0]:
                        raise AnalysisError(f"the degeneracy ODE has only the implicit "
                                            f"solution {solution}", entry=_WHAT)
                    solution = {self._fs[0]: solution.rhs()}
                phi = [normalize(v.subs(solution)) for v in velocities]
                self._verify(phi)
                families.append([dq == p for dq, p in zip(self._dqs, phi)])
            self._families = families
        if self._n == 1:
            return [family[0] for family in self._families]
        return [list(family) for family in self._families]

    def _verify(self, phi):
        r"""Raise unless the equations of motion vanish on `\dot q = \varphi(q)`."""
        data = equations_of_motion(self._routh)
        at = dict(zip(data.velocities(), phi))
        for acc, p in zip(data.accelerations(), phi):
            at[acc] = sum(p.diff(q) * v for q, v in zip(self._qs, phi))
        for k, E in enumerate(data.equations()):
            value = SR(E).subs(at)
            if not (vanishes(value) or _vanishes_numerically(value)):
                raise AnalysisError(f"the family {phi} is not invariant: equation {k} of "
                                    f"motion gives {value}", entry=_WHAT)

    def lifted_manifolds(self, lagrangian=None):
        r"""
        The families of invariant manifolds lifted to the full phase space:
        each family (its equations) together with the cyclic integrals
        `\partial L/\partial \dot q_l = c_l` written as equations for the
        cyclic velocities.

        INPUT:

        - ``lagrangian`` -- (default: the Lagrangian the Routh function was
          made from) the full Lagrangian

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: from sage_dynsym.analysis.modified_routh import ModifiedRouthLyapunov
            sage: r, phi, dr, dphi = var('r phi dr dphi')
            sage: L = Lagrangian((dr^2 + r^2*dphi^2)/2 + 1/r, [r, phi])
            sage: ModifiedRouthLyapunov(L.routh([phi])).lifted_manifolds()[0][1]
            dphi == p_phi/r^2

        A Lagrangian without cyclic coordinates has nothing to lift::

            sage: x, dx = var('x dx')
            sage: ModifiedRouthLyapunov(Lagrangian(dx^2/2 - x^2/2, [x])).lifted_manifolds()
            [[dx == -sqrt(-x^2 - 2*_C)], [dx == sqrt(-x^2 - 2*_C)]]
        """
        if not callable(getattr(self._routh, 'momenta', None)):     # a Lagrangian
            return [family if self._n > 1 else [family] for family in self.invariant_manifolds()]
        L = lagrangian if lagrangian is not None else self._routh.lagrangian()
        cyc = self._routh.cyclic_coordinates()
        momenta = self._routh.momenta()
        integrals = []
        for qc, c in zip(cyc, momenta):
            dqc = velocity(qc)
            eq = SR(L.expr()).diff(dqc) - c
            try:
                integrals.append(dqc == _solve_linear(eq, dqc, _WHAT))
            except AnalysisError:
                integrals.append(eq == 0)
        families = self.invariant_manifolds()
        if self._n == 1:
            return [[im] + integrals for im in families]
        return [family + integrals for family in families]


def _candidate_factors(Phi, u, coordinates):
    r"""`1` and the reciprocals of the coefficients of the `u_i^2` that
    depend on the coordinates: the factors tried to separate `\Phi`."""
    factors = [SR(1)]
    expanded = Phi.expand()
    for ui in u:
        a = expanded.coefficient(ui, 2)
        if not any(a.has(q) for q in coordinates):
            continue
        mu = normalize(1 / a)
        if all(str(mu) != str(x) for x in factors):
            factors.append(mu)
    return factors


def _split(expr, groups):
    r"""``expr`` as a sum of parts each in the symbols of one group (and
    parameters): the list of parts and the rest free of all groups, or
    ``None`` if a term mixes two groups."""
    expanded = SR(expr).expand()
    terms = expanded.operands() if expanded.operator() is not None and \
        expanded.operator().__name__ == 'add_vararg' else [expanded]
    names = [{str(x) for x in group} for group in groups]
    parts, rest = [SR(0)] * len(groups), SR(0)
    for term in terms:
        used = {str(v) for v in term.variables()}
        owners = [k for k, group in enumerate(names) if used & group]
        if len(owners) > 1:
            return None
        if owners:
            parts[owners[0]] += term
        else:
            rest += term
    return parts, rest
