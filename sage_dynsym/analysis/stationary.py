r"""
Stationary solutions and invariant manifolds (Routh--Lyapunov method)

For `\dot x = X(x)` with first integrals `V_0, \dots, V_k`, stationary
solutions are conditional extrema of the integrals: the stationarity
equations `\partial K/\partial x_i = 0` of `K = \sum_j \lambda_j V_j`
(`\lambda_0 = 1`). Where the Hessian of `K` is nondegenerate the solutions
are isolated stationary solutions; degenerate solution sets are
*stationary invariant manifolds* (IM). The same `K` is a Lyapunov
function: the second variation `\delta^2 K` on the tangent space of the
level set of the integrals gives sufficient stability conditions (14).

For a Lagrangian system with cyclic coordinates the stationary motions
come from the Routh function: `\partial R/\partial q = 0`, `\dot q = 0`
(:func:`stationary_motions`). The *modified* method
(:class:`ModifiedRouthLyapunov`) adds `c\, f(q)\dot q` to `R`: the
equations of motion do not change (it is a total derivative), but the
stationarity equations of `R + c f(q)\dot q` become degenerate exactly when
`f` solves an ODE; its solutions give families of IM.

EXAMPLES:

Permanent rotations of a free rigid body (Euler equations) from the energy
and the squared angular momentum; rotation about the axis of the largest
moment of inertia is stable (Merkin, ch. 5; Rumyantsev)::

    sage: from sage_dynsym.analysis.stationary import stationary_solutions
    sage: M1, M2, M3 = var('M1 M2 M3'); A1, A2, A3 = var('A1 A2 A3')
    sage: X = [(A2 - A3)/(A2*A3)*M2*M3, (A3 - A1)/(A3*A1)*M3*M1, (A1 - A2)/(A1*A2)*M1*M2]
    sage: H = (M1^2/A1 + M2^2/A2 + M3^2/A3)/2; V = M1^2 + M2^2 + M3^2
    sage: sols = stationary_solutions([H, V], [M1, M2, M3], equations=X)
    sage: sols.stationarity_equations()
    [2*M1*lambda1 + M1/A1, 2*M2*lambda1 + M2/A2, 2*M3*lambda1 + M3/A3]
    sage: for s in sols: print(s)
    Stationary solution {M1: 0, M2: 0, M3: 0}, lambda1 = r1 (isolated)
    Stationary solution {M1: r2, M2: 0, M3: 0}, lambda1 = -1/2/A1 (family, degenerate Hessian: invariant manifold)
    Stationary solution {M1: 0, M2: r3, M3: 0}, lambda1 = -1/2/A2 (family, degenerate Hessian: invariant manifold)
    Stationary solution {M1: 0, M2: 0, M3: r4}, lambda1 = -1/2/A3 (family, degenerate Hessian: invariant manifold)
    sage: s = sols[1]
    sage: s.second_variation(restricted=True)
    1/2*((A1 - A2)*A3*xi_M2^2 + (A1*A2 - A2*A3)*xi_M3^2)/(A1*A2*A3)
    sage: s.stability_conditions(positive=[A1, A2, A3])
    [A1 - A2, A1 - A3]

(the free parameters of families are renamed ``r1, r2, ...`` in order).

TESTS::

    sage: stationary_solutions([H, M1], [M1, M2, M3], equations=X)
    Traceback (most recent call last):
    ...
    AnalysisError: stationary_solutions: integral 1, M1, is not conserved: its derivative along the equations is (A2 - A3)*M2*M3/(A2*A3)
"""
from sage.matrix.constructor import matrix
from sage.misc.latex import latex
from sage.structure.sage_object import SageObject
from sage.symbolic.function_factory import function as symbolic_function
from sage.symbolic.relation import solve
from sage.symbolic.ring import SR

from ..errors import AnalysisError
from ..expressions import velocity
from .quadratic_forms import restrict_to_subspace, sylvester_conditions


def _simplify(e):
    try:
        return SR(e).simplify_full()
    except (TypeError, ValueError):
        return SR(e)


def check_integral(V, variables, equations, index=0):
    r"""
    Raise :class:`AnalysisError` unless `\dot V = \sum \partial_i V\, X_i`
    vanishes identically.

    EXAMPLES::

        sage: from sage_dynsym.analysis.stationary import check_integral
        sage: x, y = var('x y')
        sage: check_integral(x^2 + y^2, [x, y], [-y, x])
        sage: check_integral(x, [x, y], [-y, x])
        Traceback (most recent call last):
        ...
        AnalysisError: stationary_solutions: integral 0, x, is not conserved: its derivative along the equations is -y
    """
    dV = sum(SR(V).diff(x) * SR(X) for x, X in zip(variables, equations))
    dV = _simplify(dV)
    if not dV.is_zero():
        raise AnalysisError(f"integral {index}, {V}, is not conserved: its "
                            f"derivative along the equations is {dV}",
                            entry="stationary_solutions")


def _rename_free_parameters(sols, known):
    r"""Rename the free parameters ``r<N>`` that Maxima introduces (a
    global counter) to ``r1, r2, ...`` in order of appearance."""
    rename, count = {}, 0
    result = []
    for sol in sols:
        for v in sol.values():
            for s in SR(v).variables():
                if s not in known and s not in rename and str(s).startswith('r'):
                    count += 1
                    rename[s] = SR.var('r%d' % count)
        result.append({k: SR(v).subs(rename) for k, v in sol.items()})
    return result


class StationarySolution(SageObject):
    r"""
    One solution of the stationarity equations of `K = \sum\lambda_j V_j`.
    Created by :func:`stationary_solutions`.
    """

    def __init__(self, family, point, multipliers):
        self._family = family
        self._point = point
        self._multipliers = multipliers

    def _repr_(self):
        mult = ', '.join(f"{k} = {v}" for k, v in self._multipliers.items())
        kind = ("family, degenerate Hessian: invariant manifold" if self.is_degenerate()
                else "isolated")
        return f"Stationary solution {self._point}" + (f", {mult}" if mult else "") + \
            f" ({kind})"

    def point(self):
        r"""The solution as a dict ``{variable: value}`` (may contain free
        parameters ``r1, r2, ...`` of a family).

        EXAMPLES::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: x, y, a = var('x y a')
            sage: sols = stationary_solutions([(x^2 + a*y^2)/2, x^2 + y^2], [x, y])
            sage: s = sols[1]; s
            Stationary solution {x: r2, y: 0}, lambda1 = -1/2 (family, degenerate Hessian: invariant manifold)
            sage: s.point()
            {x: r2, y: 0}
        """
        return dict(self._point)

    def multipliers(self):
        r"""The values of the multipliers `\lambda_j`, a dict.

        EXAMPLES::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: x, y, a = var('x y a')
            sage: sols = stationary_solutions([(x^2 + a*y^2)/2, x^2 + y^2], [x, y])
            sage: s = sols[1]; s
            Stationary solution {x: r2, y: 0}, lambda1 = -1/2 (family, degenerate Hessian: invariant manifold)
            sage: s.multipliers()
            {lambda1: -1/2}
        """
        return dict(self._multipliers)

    def _subs(self):
        d = dict(self._point)
        d.update(self._multipliers)
        return d

    def hessian(self):
        r"""The Hessian matrix of `K` at the solution.

        EXAMPLES::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: x, y, a = var('x y a')
            sage: sols = stationary_solutions([(x^2 + a*y^2)/2, x^2 + y^2], [x, y])
            sage: s = sols[1]; s
            Stationary solution {x: r2, y: 0}, lambda1 = -1/2 (family, degenerate Hessian: invariant manifold)
            sage: s.hessian()
            [    0     0]
            [    0 a - 1]
        """
        F = self._family
        return F.hessian().apply_map(lambda e: _simplify(e.subs(self._subs())))

    def is_degenerate(self):
        r"""Whether the Hessian of `K` is singular at the solution.

        EXAMPLES::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: x, y, a = var('x y a')
            sage: sols = stationary_solutions([(x^2 + a*y^2)/2, x^2 + y^2], [x, y])
            sage: s = sols[1]; s
            Stationary solution {x: r2, y: 0}, lambda1 = -1/2 (family, degenerate Hessian: invariant manifold)
            sage: s.is_degenerate()
            True
        """
        return _simplify(self.hessian().det()).is_zero()

    def deviations(self):
        r"""The deviation variables `\xi` (``xi_<x>``), in order.

        EXAMPLES::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: x, y, a = var('x y a')
            sage: sols = stationary_solutions([(x^2 + a*y^2)/2, x^2 + y^2], [x, y])
            sage: s = sols[1]; s
            Stationary solution {x: r2, y: 0}, lambda1 = -1/2 (family, degenerate Hessian: invariant manifold)
            sage: s.deviations()
            [xi_x, xi_y]
        """
        return [SR.var('xi_' + str(x), latex_name=r'\xi_{%s}' % latex(x))
                for x in self._family.variables()]

    def second_variation(self, restricted=False):
        r"""
        The second variation `\delta^2 K = \frac12 \xi^T (\partial^2 K)\xi`
        at the solution, as a quadratic form in :meth:`deviations`.

        INPUT:

        - ``restricted`` -- (default: ``False``) restrict to the tangent
          space of the level set of the integrals with multipliers
          (`dV_j \cdot \xi = 0`, `j \ge 1`): the result is a form in the
          remaining deviations

        EXAMPLES::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: x, y, a = var('x y a')
            sage: s = stationary_solutions([(x^2 + a*y^2)/2, x^2 + y^2], [x, y])[1]
            sage: s.second_variation(), s.second_variation(restricted=True)
            (1/2*(a - 1)*xi_y^2, 1/2*(a - 1)*xi_y^2)
        """
        xi = self.deviations()
        x = matrix(SR, [xi]).transpose()
        form = ((x.transpose() * self.hessian() * x)[0, 0] / 2)
        if not restricted:
            return _simplify(form)
        cons = self.tangent_constraints()
        restricted_form, _ = restrict_to_subspace(form, cons, xi)
        return _simplify(restricted_form)

    def tangent_constraints(self):
        r"""The linear forms `dV_j|_{x^0}\cdot\xi` (`j \ge 1`).

        EXAMPLES::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: x, y, a = var('x y a')
            sage: sols = stationary_solutions([(x^2 + a*y^2)/2, x^2 + y^2], [x, y])
            sage: s = sols[1]; s
            Stationary solution {x: r2, y: 0}, lambda1 = -1/2 (family, degenerate Hessian: invariant manifold)
            sage: s.tangent_constraints()
            [2*r2*xi_x]
        """
        F = self._family
        xi = self.deviations()
        return [_simplify(sum(SR(V).diff(x).subs(self._subs()) * d
                              for x, d in zip(F.variables(), xi)))
                for V in F.integrals()[1:]]

    def stability_conditions(self, positive=(), sign='positive'):
        r"""
        Sufficient conditions for stability (Routh--Lyapunov): the
        restricted second variation is positive (``sign='positive'``) or
        negative (``'negative'``) definite; Sylvester's criterion.

        OUTPUT: list of expressions ``> 0``

        EXAMPLES::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: x, y, a = var('x y a')
            sage: s = stationary_solutions([(x^2 + a*y^2)/2, x^2 + y^2], [x, y])[1]
            sage: s.stability_conditions()
            [a - 1]
        """
        form = self.second_variation(restricted=True)
        xi = [v for v in self.deviations() if form.has(v)]
        if not xi:
            return []
        return sylvester_conditions(form, xi, sign=sign, positive=positive)

    def check(self, equations):
        r"""
        Verify that the solution annuls the right-hand sides ``equations``;
        returns the list of residuals (all zero).
        """
        res = [_simplify(SR(X).subs(self._point)) for X in equations]
        if not all(r.is_zero() for r in res):
            raise AnalysisError(f"{self._point} does not annul the right-hand "
                                f"sides: residuals {res}", entry="stationary_solutions")
        return res


class StationarySolutions(SageObject):
    r"""
    The stationarity equations of `K = \sum \lambda_j V_j` and their
    solutions (iterable). Created by :func:`stationary_solutions`.
    """

    def __init__(self, integrals, variables, multipliers, equations, solve_for):
        self._integrals = [SR(V) for V in integrals]
        self._variables = [SR(x) for x in variables]
        self._multipliers = multipliers
        self._equations = equations
        self._K = self._integrals[0] + sum(l * V for l, V in
                                           zip(multipliers, self._integrals[1:]))
        unknowns = list(self._variables) + list(multipliers) if solve_for is None \
            else [SR(u) for u in solve_for]
        self._solutions = []
        eqs = self.stationarity_equations()
        known = set().union(*(set(V.variables()) for V in self._integrals)) | set(unknowns)
        sols = solve([e == 0 for e in eqs], *unknowns, solution_dict=True)
        for sol in _rename_free_parameters(sols, known):
            point = {x: sol.get(x, x) for x in self._variables}
            mult = {l: sol[l] for l in multipliers if l in sol}
            s = StationarySolution(self, point, mult)
            if equations is not None:
                s.check(equations)
            self._solutions.append(s)

    def _repr_(self):
        return (f"{len(self._solutions)} stationary solutions of K = {self._K}")

    def __iter__(self):
        return iter(self._solutions)

    def __len__(self):
        return len(self._solutions)

    def __getitem__(self, i):
        return self._solutions[i]

    def integrals(self):
        r"""The integrals `V_0, \dots, V_k`.

        EXAMPLES::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: x, y, a = var('x y a')
            sage: sols = stationary_solutions([(x^2 + a*y^2)/2, x^2 + y^2], [x, y])
            sage: s = sols[1]; s
            Stationary solution {x: r2, y: 0}, lambda1 = -1/2 (family, degenerate Hessian: invariant manifold)
            sage: sols.integrals()
            [1/2*a*y^2 + 1/2*x^2, x^2 + y^2]
        """
        return list(self._integrals)

    def variables(self):
        r"""The phase variables `x`.

        EXAMPLES::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: x, y, a = var('x y a')
            sage: sols = stationary_solutions([(x^2 + a*y^2)/2, x^2 + y^2], [x, y])
            sage: s = sols[1]; s
            Stationary solution {x: r2, y: 0}, lambda1 = -1/2 (family, degenerate Hessian: invariant manifold)
            sage: sols.variables()
            [x, y]
        """
        return list(self._variables)

    def K(self):
        r"""`K = V_0 + \sum_{j\ge1}\lambda_j V_j`.

        EXAMPLES::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: x, y, a = var('x y a')
            sage: sols = stationary_solutions([(x^2 + a*y^2)/2, x^2 + y^2], [x, y])
            sage: s = sols[1]; s
            Stationary solution {x: r2, y: 0}, lambda1 = -1/2 (family, degenerate Hessian: invariant manifold)
            sage: sols.K()
            1/2*a*y^2 + (x^2 + y^2)*lambda1 + 1/2*x^2
        """
        return self._K

    def stationarity_equations(self):
        r"""The expressions `\partial K/\partial x_i` (each ``== 0``).

        EXAMPLES::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: x, y, a = var('x y a')
            sage: sols = stationary_solutions([(x^2 + a*y^2)/2, x^2 + y^2], [x, y])
            sage: s = sols[1]; s
            Stationary solution {x: r2, y: 0}, lambda1 = -1/2 (family, degenerate Hessian: invariant manifold)
            sage: sols.stationarity_equations()
            [2*lambda1*x + x, a*y + 2*lambda1*y]
        """
        return [self._K.diff(x).expand() for x in self._variables]

    def hessian(self):
        r"""The Hessian matrix of `K` (symbolic).

        EXAMPLES::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: x, y, a = var('x y a')
            sage: sols = stationary_solutions([(x^2 + a*y^2)/2, x^2 + y^2], [x, y])
            sage: s = sols[1]; s
            Stationary solution {x: r2, y: 0}, lambda1 = -1/2 (family, degenerate Hessian: invariant manifold)
            sage: sols.hessian()
            [2*lambda1 + 1             0]
            [            0 a + 2*lambda1]
        """
        return matrix(SR, [[self._K.diff(x).diff(y) for y in self._variables]
                           for x in self._variables])


def stationary_solutions(integrals, variables, equations=None, multipliers=None,
                         solve_for=None):
    r"""
    Routh--Lyapunov: stationary solutions as conditional extrema of the
    first integrals.

    INPUT:

    - ``integrals`` -- list `[V_0, V_1, \dots, V_k]` of first integrals;
      `K = V_0 + \lambda_1 V_1 + \dots + \lambda_k V_k`
    - ``variables`` -- the phase variables `x`
    - ``equations`` -- (optional) the right-hand sides `X(x)`; if given,
      every integral is checked to be conserved and every solution to annul
      `X` (:class:`AnalysisError` otherwise)
    - ``multipliers`` -- (optional) names or symbols for `\lambda_1, \dots`
      (default ``lambda1, lambda2, ...``)
    - ``solve_for`` -- (optional) the unknowns to solve the stationarity
      equations for (default: the variables and the multipliers)

    OUTPUT: a :class:`StationarySolutions`; iterate over it for the
    :class:`StationarySolution` objects

    EXAMPLES: see the module documentation.
    """
    integrals = [SR(V) for V in integrals]
    variables = [SR(x) for x in variables]
    if not integrals:
        raise AnalysisError("at least one integral is needed", entry="stationary_solutions")
    if equations is not None:
        if len(equations) != len(variables):
            raise AnalysisError(f"{len(equations)} right-hand sides for "
                                f"{len(variables)} variables", entry="stationary_solutions")
        for j, V in enumerate(integrals):
            check_integral(V, variables, equations, j)
    if multipliers is None:
        multipliers = [SR.var('lambda%d' % j) for j in range(1, len(integrals))]
    multipliers = [SR(l) if not isinstance(l, str) else SR.var(l) for l in multipliers]
    return StationarySolutions(integrals, variables, multipliers, equations, solve_for)


def stationary_motions(routh, solve_for=None):
    r"""
    Stationary motions of a system with cyclic coordinates: the positional
    velocities vanish and `\partial R/\partial q = 0` for the Routh
    function `R` (cyclic momenta constant).

    INPUT:

    - ``routh`` -- a :class:`~sage_dynsym.routh.RouthFunction` (any
      Lagrangian object works: then these are its equilibria)
    - ``solve_for`` -- (optional) unknowns to solve for, e.g. the cyclic
      momenta when the equations are transcendental in the coordinates;
      default: the positional coordinates

    OUTPUT: a pair ``(equations, solutions)``: the equations of motion at
    rest, `-\partial R/\partial q_i` at `\dot q = 0` (each ``== 0``), and
    the list of solution dicts

    EXAMPLES: the conical motions of the spherical pendulum
    (Example 1 of the method)::

        sage: from sage_dynsym import load
        sage: from sage_dynsym.analysis.stationary import stationary_motions
        sage: L = load('examples/spherical_pendulum.yaml').lagrangian()
        sage: psi, theta = L.coordinates()
        sage: R = L.routh([psi]); p = R.momenta()[0]
        sage: eqs, sols = stationary_motions(R, solve_for=[p])
        sage: eqs
        [-(g*l^3*m^2*sin(theta)^4 + p_psi^2*cos(theta))/(l^2*m*sin(theta)^3)]
        sage: sols
        [{p_psi: -l*m*sqrt(-g*l/cos(theta))*sin(theta)^2},
         {p_psi: l*m*sqrt(-g*l/cos(theta))*sin(theta)^2}]
    """
    q = routh.coordinates()
    rest = {v: 0 for v in list(routh.velocities()) + list(routh.accelerations())}
    # the equations of motion at rest: -dR/dq (plus forces depending on q only)
    eqs = [_simplify(SR(E).subs(rest)) for E in routh.lagrange_equations()]
    unknowns = list(q) if solve_for is None else [SR(u) for u in solve_for]
    sols = solve([e == 0 for e in eqs], *unknowns, solution_dict=True)
    return eqs, sols


class ModifiedRouthLyapunov(SageObject):
    r"""
    The modified Routh--Lyapunov method for families of invariant manifolds
    of a system with one positional coordinate `q` and a cyclic momentum
    `c` (Example 3 of the method).

    The extended Routh function `\tilde R = R + c\, f(q)\,\dot q` (unknown
    `f`) has the same equations of motion as `R`. Its stationarity
    equations are `\partial\tilde R/\partial\dot q = 0` (solved for
    `\dot q`) and `\partial\tilde R/\partial q = 0`; they define a curve
    `\dot q = \varphi(q)` -- an invariant manifold -- exactly when the
    second equation holds identically after substituting the first: an
    ODE for `f`. Its general solution (Sage's ``desolve``, Maxima) gives the
    family of IM in explicit form, lifted to the full phase space with the
    cyclic integrals.

    INPUT:

    - ``routh`` -- a :class:`~sage_dynsym.routh.RouthFunction` with one
      positional coordinate
    - ``momentum`` -- (default: the first cyclic momentum) the constant `c`
    - ``f`` -- (default: ``function('f')``) the unknown function

    EXAMPLES: see :mod:`sage_dynsym.analysis.tutorial` (Example 3).
    """

    def __init__(self, routh, momentum=None, f=None):
        q = routh.coordinates()
        if len(q) != 1:
            raise AnalysisError("the modified method is implemented for one "
                                f"positional coordinate, got {q}",
                                entry="ModifiedRouthLyapunov")
        self._routh = routh
        self._q, self._dq = q[0], routh.velocities()[0]
        self._c = SR(momentum) if momentum is not None else SR(routh.momenta()[0])
        self._f = f if f is not None else symbolic_function('f')
        self._Rt = SR(routh.expr()) + self._c * self._f(self._q) * self._dq

    def extended_function(self):
        r"""`\tilde R = R + c f(q)\dot q`."""
        return self._Rt

    def stationarity_equations(self):
        r"""
        `[\partial\tilde R/\partial q, \partial\tilde R/\partial\dot q]`
        (each ``== 0``).
        """
        return [self._Rt.diff(self._q), self._Rt.diff(self._dq)]

    def velocity_on_manifold(self):
        r"""`\dot q` from `\partial\tilde R/\partial \dot q = 0`, in terms of `f`."""
        dRq, dRdq = self.stationarity_equations()
        sol = solve(dRdq == 0, self._dq, solution_dict=True)
        if len(sol) != 1:
            raise AnalysisError("cannot solve the velocity equation "
                                f"{dRdq} == 0 uniquely", entry="ModifiedRouthLyapunov")
        return sol[0][self._dq]

    def degeneracy_condition(self):
        r"""
        The ODE for `f`: the equation `\partial\tilde R/\partial q = 0` with
        `\dot q` from :meth:`velocity_on_manifold` must hold for every `q`.
        Returned solved for the derivative, ``diff(f(q), q) == ...``.
        """
        dRq = self.stationarity_equations()[0]
        e = dRq.subs({self._dq: self.velocity_on_manifold()})
        fq = self._f(self._q)
        fp = fq.diff(self._q)
        tmp = SR.var('fprime_')
        sol = solve(e.subs({fp: tmp}) == 0, tmp, solution_dict=True)
        if len(sol) != 1:
            return _simplify(e) == 0
        return fp == _simplify(sol[0][tmp])

    def solve_degeneracy(self):
        r"""
        The general solution of the degeneracy ODE (``desolve``), as a list
        of explicit solutions ``f(q) == ...`` (with the integration constant
        ``_C``), or the implicit one if it cannot be solved for `f`.
        """
        from sage.calculus.desolvers import desolve
        fq = self._f(self._q)
        sol = desolve(self.degeneracy_condition(), fq, ivar=self._q)
        explicit = solve(sol, fq)
        return [fq == _simplify(e.rhs()) for e in explicit] if explicit else [sol]

    def invariant_manifolds(self):
        r"""
        The families of IM in explicit form: equations
        ``dq == phi(q, _C)`` in the phase plane of the Routh system.
        """
        v = self.velocity_on_manifold()
        fq = self._f(self._q)
        return [self._dq == _simplify(v.subs({fq: s.rhs()})) for s in self.solve_degeneracy()]

    def lifted_manifolds(self, lagrangian=None):
        r"""
        The families of IM lifted to the full phase space: each IM together
        with the cyclic integrals `\partial L/\partial \dot q_l = c_l`
        written as equations for the cyclic velocities.

        INPUT:

        - ``lagrangian`` -- (default: the Lagrangian the Routh function was
          made from) the full Lagrangian
        """
        L = lagrangian if lagrangian is not None else self._routh.lagrangian()
        lifted = []
        cyc = self._routh.cyclic_coordinates()
        momenta = self._routh.momenta()
        integrals = []
        for qc, c in zip(cyc, momenta):
            dqc = velocity(qc)
            eq = SR(L.expr()).diff(dqc) == c
            s = solve(eq, dqc, solution_dict=True)
            integrals.append(dqc == _simplify(s[0][dqc]) if len(s) == 1 else eq)
        for im in self.invariant_manifolds():
            lifted.append([im] + integrals)
        return lifted
