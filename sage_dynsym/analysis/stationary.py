r"""
Stationary solutions and invariant manifolds (Routh--Lyapunov method)

For `\dot x = X(x)` with first integrals `V_0, \dots, V_k`, stationary
solutions are conditional extrema of the integrals: the stationarity
equations `\partial K/\partial x_i = 0` of `K = V_0 + \sum_{j\ge1}
\lambda_j V_j`, together with the levels `V_j = c_j` that are prescribed.
Their solution set is computed exactly (:mod:`~sage_dynsym.algebra.solving`): it is decomposed
into irreducible components, each with its dimension -- `0` for an
isolated solution, `k > 0` for a `k`-parameter family of stationary
solutions, a candidate *stationary invariant manifold* --, explicit values
where they can be written, the values of the multipliers, and the
conditions on the parameters under which it exists and is real.

The same `K` is a Lyapunov function: if its second variation `\delta^2 K`
on the tangent space of the level set of the integrals is definite, the
solution is stable (equation (14) of :doc:`the method </method>`). When
some multipliers are not fixed by the stationarity equations, stability
follows if *some* choice of them makes `\delta^2 K` definite:
:meth:`StationarySolution.stability_region` eliminates them (quantifier
elimination). :meth:`StationarySolution.stability` combines this with the
first approximation.

For a Lagrangian system with cyclic coordinates the stationary motions
come from the Routh function: `\partial R/\partial q = 0`, `\dot q = 0`
(:func:`stationary_motions`); their stability follows from the amended
potential `W = -R|_{\dot q = 0}` (Routh's theorem). The *modified* method
(:class:`ModifiedRouthLyapunov`) adds `c\, f(q)\dot q` to `R`.

EXAMPLES:

Permanent rotations of a free rigid body (Euler equations) from the energy
and the squared angular momentum (Merkin, *Introduction to the Theory of
Stability*, ch. 5; Arnold, *Mathematical Methods of Classical Mechanics*,
§29): the rest point, and a line of permanent rotations about each
principal axis::

    sage: from sage_dynsym.analysis.stationary import stationary_solutions
    sage: M1, M2, M3 = var('M1 M2 M3'); A1, A2, A3 = var('A1 A2 A3')
    sage: X = [(A2 - A3)/(A2*A3)*M2*M3, (A3 - A1)/(A3*A1)*M3*M1, (A1 - A2)/(A1*A2)*M1*M2]
    sage: H = (M1^2/A1 + M2^2/A2 + M3^2/A3)/2; V = M1^2 + M2^2 + M3^2
    sage: sols = stationary_solutions([H, V], [M1, M2, M3], equations=X, positive=[A1, A2, A3])
    sage: sols.stationarity_equations()
    [2*M1*lambda1 + M1/A1, 2*M2*lambda1 + M2/A2, 2*M3*lambda1 + M3/A3]
    sage: for s in sols: print(s)
    Stationary solution {M1: 0, M2: 0, M3: 0}, lambda1 free (isolated)
    Stationary solution {M1: M1, M2: 0, M3: 0}, lambda1 = -1/2/A1 (1-parameter family)
    Stationary solution {M1: 0, M2: M2, M3: 0}, lambda1 = -1/2/A2 (1-parameter family)
    Stationary solution {M1: 0, M2: 0, M3: M3}, lambda1 = -1/2/A3 (1-parameter family)

The rotation about the first axis: the second variation on the tangent
space of the sphere `V = M_1^2` is definite iff `A_1` is the largest or the
smallest moment of inertia; at the middle axis the first approximation has
a root with positive real part::

    sage: s = sols[1]
    sage: s.second_variation(restricted=True)
    1/2*(A1 - A2)*xi_M2^2/(A1*A2) + 1/2*(A1 - A3)*xi_M3^2/(A1*A3)
    sage: s.stability_region()
    [[A1 - A2 > 0, A1 - A3 > 0, M1 != 0]]
    sage: s.stability_region(sign='negative')
    [[A1 - A2 < 0, A1 - A3 < 0, M1 != 0]]
    sage: s.stability()
    depends on the parameters: see cases(): stable, unstable
    sage: for case in s.stability().cases(): print(case.verdict(), case.method(), case.region())
    stable Routh-Lyapunov [[A1 - A2 > 0, A1 - A3 > 0, M1 != 0], [A1 - A2 < 0, A1 - A3 < 0, M1 != 0]]
    unstable first approximation [[A1 - A3 > 0, A1 - A2 < 0], [A1 - A2 > 0, A1 - A3 < 0]]

With a prescribed level of `V` the families become isolated points, two
conjugate branches each::

    sage: c = var('c')
    sage: sols = stationary_solutions([H, V], [M1, M2, M3], levels=[c], positive=[A1, A2, A3])
    sage: [s.point() for s in sols][:2], sols[0].conditions()
    ([{M1: sqrt(c), M2: 0, M3: 0}, {M1: -sqrt(c), M2: 0, M3: 0}], [c > 0])

TESTS::

    sage: stationary_solutions([H, M1], [M1, M2, M3], equations=X)
    Traceback (most recent call last):
    ...
    AnalysisError: stationary_solutions: integral 1, M1, is not conserved: its derivative along the equations is (A2 - A3)*M2*M3/(A2*A3)
    sage: stationary_solutions([H, V], [M1, M2, M3], levels=[1, 2])
    Traceback (most recent call last):
    ...
    AnalysisError: stationary_solutions: levels has 2 entries; it needs one per integral after the first (1)
    sage: stationary_solutions([H, V, M1^2 + M2^2 + M3^2], [M1, M2, M3], levels=[1, 2])
    No stationary solutions: the equations are inconsistent (for generic parameter values)

REFERENCES:

- A. M. Lyapunov, *The General Problem of the Stability of Motion*,
  Taylor & Francis, 1992.
- V. V. Rumyantsev, *On the stability of steady motions*, J. Appl. Math.
  Mech. 30 (1966) 1090--1103.
- D. R. Merkin, *Introduction to the Theory of Stability*, Springer, 1997.
"""
import operator

from sage.functions.trig import arctan2
from sage.matrix.constructor import matrix
from sage.rings.qqbar import AA
from sage.misc.latex import latex
from sage.misc.superseded import deprecation
from sage.symbolic.ring import SR

from ..errors import AnalysisError, DynSymError, brief
from ..arguments import expression_list, known_symbols, symbol_arguments
from ..algebra.conditions import positive_conditions_all, conjunction, simplify_conjunction
from .motion_solution import MotionSolution
from .verdict import verdict_from_parts, StabilityVerdict
from .point_stability import point_verdict
from .linear import LinearSystem, equations_of_motion
from .motion import SecondOrderEquations
from .quadratic_forms import (restrict_to_subspace, sylvester_conditions, form_matrix,
                              signed_leading_minors)
from ..algebra.solving import solve_exactly, normalize, SolutionList
from ..algebra.forked import forked
# the modified method has a module of its own; this import keeps its old path
from .modified_routh import ModifiedRouthLyapunov

__all__ = ['check_integral', 'StationaryProblem', 'StationarySolution', 'StationarySolutions',
           'solve_stationary', 'stationary_solutions', 'stationary_motions',
           'ModifiedRouthLyapunov', 'ChartPointSolution']


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
    dV = normalize(sum(SR(V).diff(x) * SR(X) for x, X in zip(variables, equations)))
    if not dV.is_zero():
        dV = dV.factor()
        raise AnalysisError(f"integral {index}, {V}, is not conserved: its "
                            f"derivative along the equations is {dV}",
                            entry="stationary_solutions")


class StationaryProblem:
    r"""
    What a list of stationary solutions solves, the data its solutions read:
    the function `K = V_0 + \sum_j \lambda_j V_j` (for stationary motions,
    the amended potential `W`) and the variables of its Hessian, the
    equations and their unknowns, the multipliers and the integrals, and
    what the stability tests need. Built by :func:`stationary_solutions`
    and :func:`stationary_motions`, solved by :func:`stationary_solutions`;
    nothing is computed here.

    INPUT:

    - ``function`` -- `K`, or `W`
    - ``variables`` -- the variables of the Hessian of ``function``
    - ``unknowns`` -- the unknowns of ``equations`` (variables, multipliers,
      or parameters solved for)
    - ``multipliers`` -- the multipliers `\lambda_1, \dots` (``[]`` for
      stationary motions)
    - ``equations`` -- the equations solved, each ``== 0``
    - ``integrals`` -- (default: ``()``) the integrals `V_0, \dots, V_k`;
      those after the first constrain the second variation
    - ``kinetic`` -- (optional) the kinetic matrix of stationary motions:
      it must be positive definite as well (Routh's theorem)
    - ``signs`` -- (default: both) the signs of definiteness of the second
      variation that give stability
    - ``linear`` -- (optional) a function giving the first-approximation
      system at a solution, from the solution's evaluation map
    - ``rhs`` -- (optional) the right-hand sides `X(x)` of the equations of
      motion
    - ``positive`` -- the symbols declared positive
    - ``description`` -- (optional) what is solved, for the listing
      (default: ``K = ...``)
    - ``shown`` -- (optional) the equations as they are shown, if not as
      solved

    EXAMPLES::

        sage: from sage_dynsym.analysis.stationary import StationaryProblem, stationary_solutions
        sage: x, y, l = var('x y l')
        sage: P = StationaryProblem(x^2 + l*(x^2 + y^2), [x, y], [x, y, l], [l],
        ....:                       [4*x + 2*l*x, 2*l*y], integrals=[x^2, x^2 + y^2])
        sage: P.solved_variables(), P.constraint_integrals()
        ([x, y], [x^2 + y^2])
        sage: stationary_solutions(P)
        3 stationary solutions of K = (x^2 + y^2)*l + x^2
    """

    def __init__(self, function, variables, unknowns, multipliers, equations, integrals=(),
                 kinetic=None, signs=('positive', 'negative'), linear=None, rhs=None,
                 positive=(), description=None, shown=None):
        self.function = SR(function)
        self.variables = [SR(x) for x in variables]
        self.unknowns = [SR(u) for u in unknowns]
        self.multipliers = [SR(l) for l in multipliers]
        self.equations = [SR(e) for e in equations]
        self.integrals = [SR(V) for V in integrals]
        self.kinetic = kinetic
        self.signs = tuple(signs)
        self.rhs = None if rhs is None else [SR(X) for X in rhs]
        self.positive = list(positive)
        self.description = description or f"K = {self.function}"
        self.shown = self.equations if shown is None else [SR(e) for e in shown]
        self._linear = linear

    def solved_variables(self):
        r"""The unknowns that are not multipliers (the counted dimensions).

        EXAMPLES::

            sage: from sage_dynsym.analysis.stationary import StationaryProblem
            sage: x, l = var('x l')
            sage: StationaryProblem(x^2 + l*x, [x], [x, l], [l], [2*x + l]).solved_variables()
            [x]
        """
        return [u for u in self.unknowns if all(str(u) != str(l) for l in self.multipliers)]

    def constraint_integrals(self):
        r"""The integrals after the first, whose level sets the second
        variation is restricted to.

        EXAMPLES::

            sage: from sage_dynsym.analysis.stationary import StationaryProblem
            sage: x, y, l = var('x y l')
            sage: P = StationaryProblem(x + l*y, [x, y], [x, y], [l], [1, l], integrals=[x, y])
            sage: P.constraint_integrals()
            [y]
        """
        return self.integrals[1:]

    def hessian(self):
        r"""The Hessian matrix of the function (symbolic).

        EXAMPLES::

            sage: from sage_dynsym.analysis.stationary import StationaryProblem
            sage: x, y, a = var('x y a')
            sage: StationaryProblem(x^2 + a*x*y, [x, y], [x, y], [], []).hessian()
            [2 a]
            [a 0]
        """
        v = self.variables
        return matrix(SR, [[self.function.diff(x).diff(y) for y in v] for x in v])

    def linear_system(self, evaluate):
        r"""
        The first-approximation system at a solution, given the solution's
        evaluation map ``evaluate`` (an expression to its value on the
        solution); ``None`` when the equations of motion are not known.

        EXAMPLES::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: x, y = var('x y')
            sage: s = stationary_solutions([(x^2 + y^2)/2], [x, y], equations=[y, -x])[0]
            sage: s.stationary_problem().linear_system(s.solution().evaluate).jacobian()
            [ 0  1]
            [-1  0]
        """
        return None if self._linear is None else self._linear(evaluate)


def _radicands(expr, found):
    r"""Append to ``found`` the radicands `D` of the square roots (powers
    `D^{k/2}`) in ``expr``, each once."""
    from sage.rings.rational_field import QQ
    if expr.operator() is None:
        return
    base, *rest = expr.operands()
    if expr.operator() is operator.pow and rest[0] in QQ and QQ(rest[0]).denominator() == 2 \
            and not any(bool((base - D).is_zero()) for D in found):
        found.append(base)
    for e in expr.operands():
        _radicands(e, found)


def _root_substitution(D, values):
    r"""
    A symbol ``r`` for `\sqrt D` and a symbol `p` of `D` with `p` as a
    rational function of `r` making `D = r^2` (`D` of degree at most 1 in
    `p` in its numerator and denominator), ``p`` chosen among those that
    occur least in ``values``; ``None`` if there is none.
    """
    r = SR.var("sqrt_radicand")
    num, den = D.numerator(), D.denominator()
    candidates = sorted((v for v in D.variables() if num.degree(v) <= 1 and den.degree(v) <= 1),
                        key=lambda v: (sum(str(e).count(str(v)) for e in values), str(v)))
    for v in candidates:
        n1, n0 = num.coefficient(v, 1), num.coefficient(v, 0)
        d1, d0 = den.coefficient(v, 1), den.coefficient(v, 0)
        # (n1 p + n0) = r^2 (d1 p + d0)
        if not (n1 - r**2 * d1).is_zero():
            return r, v, ((r**2 * d0 - n0) / (n1 - r**2 * d1)).factor()
    return None


def _with_root(expr, D, r, p, value):
    r"""``expr`` with `D^{k/2}` written `r^k`, then `p` replaced by its
    value in `r`."""
    def walk(e):
        op = e.operator()
        if op is None:
            return e
        args = e.operands()
        if op is operator.pow and bool((args[0] - D).is_zero()):
            return r ** (2 * args[1])
        return op(*[walk(a) for a in args])
    return walk(SR(expr)).subs({p: value})


class StationarySolution(MotionSolution):
    r"""
    One stationary solution: a real branch of an irreducible component of
    the stationary set. Created by :func:`stationary_solutions` and
    :func:`stationary_motions`. It answers :meth:`point`, :meth:`values`,
    :meth:`conditions` and :meth:`stability` as a steady motion does (see
    :mod:`~sage_dynsym.analysis.motion_solution`).

    EXAMPLES::

        sage: from sage_dynsym.analysis.stationary import stationary_solutions
        sage: x, y, a = var('x y a')
        sage: sols = stationary_solutions([(x^2 + a*y^2)/2, x^2 + y^2], [x, y])
        sage: s = sols[1]; s
        Stationary solution {x: x, y: 0}, lambda1 = -1/2 (1-parameter family)

    It has no value equality (two of them are equal only if they are the
    same object), so the pickling test, which compares the copy with the
    original, is skipped::

        sage: TestSuite(s).run(skip=['_test_pickling'])
    """

    def __init__(self, problem, solution):
        self._problem = problem
        self._solution = solution

    def _positive(self, positive):
        return self._problem.positive if positive is None else positive

    def _kind(self):
        r"""What the solution is, for its listing: ``'isolated'``, a family
        of some dimension in the unknowns, or a family over the variables
        that were not unknowns (e.g. the coordinates when solving for the
        cyclic momenta), which its values depend on."""
        d = self.dimension()
        solved = {str(u) for u in self._problem.unknowns}
        over = [str(x) for x in self._problem.variables if str(x) not in solved and
                any(SR(e).has(x) for e in self.point().values())]
        kind = "isolated" if d == 0 else f"{d}-parameter family"
        if over:
            kind = ("a family" if d == 0 else kind) + " over " + ", ".join(over)
        return kind

    def _repr_(self):
        free = {str(l) for l in self.free_multipliers()}
        mult = ', '.join(f"{k} free" if str(k) in free else f"{k} = {v}"
                         for k, v in self.multipliers().items() if str(k) != str(v) or
                         str(k) in free)
        kind = self._kind()
        if self.is_equilibrium() is False:
            kind += ", an invariant manifold of non-equilibrium motions"
        if not self.is_explicit():
            kind += ", implicit: see equations()"
        conds = self._solution.known_conditions()
        if conds:
            kind += ", if " + " and ".join(map(str, conds))
        if not self._solution.is_reality_decided():
            kind += ", where it is real not decided"
        return f"Stationary solution {self.point()}" + (f", {mult}" if mult else "") + \
            f" ({kind})"

    def _latex_(self):
        return latex(self.point())

    def __iter__(self):
        # the old stationary_motions returned a pair (equations, solutions):
        # unpacking the new result into two names must not go unnoticed
        raise TypeError("a StationarySolution is not a sequence: stationary_motions and "
                        "stationary_solutions return StationarySolutions (use "
                        ".equations() for the equations, iterate for the solutions, "
                        "s.point() for a solution's values)")

    # -- the solution ------------------------------------------------------

    def point(self):
        r"""
        The solution as a dict ``{variable: value}`` over all variables:
        the value where the solution fixes it, the variable itself where it
        does not (a family is parametrised by some of its own variables;
        :meth:`equations` holds the relations between them).

        EXAMPLES::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: x, y, a = var('x y a')
            sage: stationary_solutions([(x^2 + a*y^2)/2, x^2 + y^2], [x, y])[1].point()
            {x: x, y: 0}
        """
        values = self._solution.values()
        return {x: values[x] for x in self._problem.solved_variables()}

    def multipliers(self):
        r"""
        The values of the multipliers `\lambda_j`, a dict; a multiplier
        the solution leaves free maps to itself.

        EXAMPLES::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: x, y, a = var('x y a')
            sage: sols = stationary_solutions([(x^2 + a*y^2)/2, x^2 + y^2], [x, y])
            sage: sols[0].multipliers(), sols[1].multipliers()
            ({lambda1: lambda1}, {lambda1: -1/2})
        """
        values = self._solution.values()
        return {l: values.get(l, l) for l in self._problem.multipliers}

    def free_multipliers(self):
        r"""The multipliers that the stationarity equations leave free.

        EXAMPLES::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: x, y, a = var('x y a')
            sage: stationary_solutions([(x^2 + a*y^2)/2, x^2 + y^2], [x, y])[0].free_multipliers()
            [lambda1]
        """
        free = {str(u) for u in self._solution.free_unknowns()}
        return [l for l in self._problem.multipliers if str(l) in free]

    def is_equilibrium(self):
        r"""
        Whether the right-hand sides vanish on the solution (``None`` when
        they were not given). A component of the stationary set that is not
        made of equilibria is an invariant manifold of the motion.

        EXAMPLES: a symmetric free top: with the integrals `H`, `|M|^2` and
        `M_3` the whole space is stationary -- each level set of the
        integrals is a circle on which `H` is constant, an invariant
        manifold --, besides the rotations about the symmetry axis::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: M1, M2, M3, A, C = var('M1 M2 M3 A C')
            sage: X = [(A - C)/(A*C)*M2*M3, (C - A)/(C*A)*M3*M1, 0]
            sage: H = (M1^2 + M2^2)/(2*A) + M3^2/(2*C)
            sage: sols = stationary_solutions([H, M1^2 + M2^2 + M3^2, M3], [M1, M2, M3],
            ....:                             equations=X, positive=[A, C])
            sage: [(s.dimension(), s.is_equilibrium()) for s in sols]
            [(1, True), (3, False)]
        """
        rhs = self._problem.rhs
        if rhs is None:
            return None
        if not self.is_explicit():
            # an implicit family: the equations' membership in its prime, not
            # a normal form of the values put in them (minutes over a field
            # of many parameters: a generic Kirchhoff Hamiltonian's family)
            try:
                return all(self._solution.contains(X) for X in rhs)
            except AnalysisError:
                pass        # a symbol the system does not know: the values put in
        return all(normalize(self._at(X)).is_zero() for X in rhs)

    def stationary_problem(self):
        r"""The :class:`StationaryProblem` the solution solves.

        EXAMPLES::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: x = var('x')
            sage: stationary_solutions([x^2], [x])[0].stationary_problem().equations
            [2*x]
        """
        return self._problem

    def _at(self, expr):
        return self._solution.evaluate(expr)

    # -- second variation ----------------------------------------------------

    def deviations(self):
        r"""The deviation variables `\xi` (``xi_<x>``), in order.

        EXAMPLES::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: x, y, a = var('x y a')
            sage: stationary_solutions([(x^2 + a*y^2)/2, x^2 + y^2], [x, y])[1].deviations()
            [xi_x, xi_y]
        """
        return [SR.var('xi_' + str(x), latex_name=r'\xi_{%s}' % latex(x))
                for x in self._problem.variables]

    def hessian(self):
        r"""
        The Hessian matrix at the solution of `K` (or, for stationary
        motions, of the amended potential `W = -R|_{\dot q=0}`).

        EXAMPLES::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: x, y, a = var('x y a')
            sage: stationary_solutions([(x^2 + a*y^2)/2, x^2 + y^2], [x, y])[1].hessian()
            [    0     0]
            [    0 a - 1]
        """
        return self._problem.hessian().apply_map(self._at)

    def is_degenerate(self):
        r"""Whether the Hessian is singular on the solution.

        EXAMPLES::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: x, y, a = var('x y a')
            sage: [s.is_degenerate() for s in stationary_solutions([(x^2 + a*y^2)/2, x^2 + y^2], [x, y])]
            [False, True, True]
        """
        return self._at(self._problem.hessian().det()).is_zero()

    def tangent_constraints(self):
        r"""The linear forms `dV_j|_{x^0}\cdot\xi` (`j \ge 1`).

        EXAMPLES::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: x, y, a = var('x y a')
            sage: stationary_solutions([(x^2 + a*y^2)/2, x^2 + y^2], [x, y])[1].tangent_constraints()
            [2*x*xi_x]
        """
        xi = self.deviations()
        variables = self._problem.variables
        return [sum(self._at(SR(V).diff(x)) * d for x, d in zip(variables, xi))
                for V in self._problem.constraint_integrals()]

    def _restricted(self):
        r"""The restricted second variation, its free deviations and the
        conditions of the elimination."""
        xi = self.deviations()
        x = matrix(SR, [xi]).transpose()
        form = (x.transpose() * self.hessian() * x)[0, 0] / 2
        return restrict_to_subspace(form, self.tangent_constraints(), xi, with_conditions=True)

    def second_variation(self, restricted=False):
        r"""
        The second variation `\delta^2 K = \frac12 \xi^T H \xi`, optionally
        restricted to the tangent space of the level set of the integrals.

        EXAMPLES::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: x, y, a = var('x y a')
            sage: s = stationary_solutions([(x^2 + a*y^2)/2, x^2 + y^2], [x, y])[1]
            sage: s.second_variation(), s.second_variation(restricted=True)
            (1/2*(a - 1)*xi_y^2, 1/2*(a - 1)*xi_y^2)
        """
        if restricted:
            return self._restricted()[0]
        xi = self.deviations()
        x = matrix(SR, [xi]).transpose()
        form = (x.transpose() * self.hessian() * x)[0, 0] / 2
        return restrict_to_subspace(form, [], xi)[0]

    def _check_sign(self, sign):
        if sign not in self._problem.signs:
            raise AnalysisError(f"sign must be one of {self._problem.signs}, got {sign!r}"
                                + (" (the kinetic energy is positive: only a positive "
                                   "definite amended potential gives stability)"
                                   if self._problem.kinetic is not None else ""),
                                entry="stability")

    def stability_conditions(self, positive=None, sign='positive'):
        r"""
        Sufficient conditions for stability (Routh--Lyapunov): the
        restricted second variation is positive (``sign='positive'``) or
        negative (``'negative'``) definite, by Sylvester's criterion. Free
        multipliers may occur (see :meth:`stability_region`).

        OUTPUT: list of expressions ``> 0`` (``[-1]`` if they cannot hold)

        EXAMPLES::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: x, y, a = var('x y a')
            sage: s = stationary_solutions([(x^2 + a*y^2)/2, x^2 + y^2], [x, y])[1]
            sage: s.stability_conditions()
            [a - 1]
        """
        self._check_sign(sign)
        positive = self._positive(positive)
        form, free, _ = self._restricted()
        conds = sylvester_conditions(form, free, sign=sign, positive=positive) if free else []
        if self._problem.kinetic is not None:
            conds = conds + sylvester_conditions(self._kinetic_at(), positive=positive)
        return conds

    def _kinetic_at(self):
        return self._problem.kinetic.apply_map(self._at)

    def _definiteness_region(self, positive, sign):
        r"""Alternatives (without the existence conditions) where some
        choice of the free multipliers makes the restricted second
        variation definite."""
        from ..algebra.quantifier_elimination import exists
        form, free, pivots = self._restricted()
        exprs = signed_leading_minors(form_matrix(form, free), sign) if free else []
        if self._problem.kinetic is not None:
            exprs += signed_leading_minors(self._kinetic_at(), 'positive')
        exprs = [self._at(e) for e in exprs]
        multipliers = [l for l in self.free_multipliers()
                       if any(e.has(l) for e in exprs)]
        if multipliers:
            return exists(multipliers, [e > 0 for e in exprs] + pivots, positive)
        kept = positive_conditions_all(exprs, positive)
        return [] if kept is None else [conjunction(kept, pivots)]

    def stability_region(self, positive=None, sign='positive'):
        r"""
        Where the solution is stable by the Routh--Lyapunov method: the
        region of the parameters (and of the family's own variables) where
        some choice of the free multipliers makes the restricted second
        variation definite of the given ``sign``.

        OUTPUT: a list of alternatives (a disjunction), each a list of
        relationals (a conjunction); the conditions the solution itself
        needs are included; ``[]`` if there is no such region

        The free multipliers are eliminated in closed form where they occur
        quadratically in a single condition, by QEPCAD otherwise.

        EXAMPLES: the rest point of the Euler top, where the multiplier of
        `V = |M|^2` is free, is stable for all positive moments of inertia
        (a large enough multiplier makes `K` positive definite)::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: M1, M2, M3, A1, A2, A3 = var('M1 M2 M3 A1 A2 A3')
            sage: H = (M1^2/A1 + M2^2/A2 + M3^2/A3)/2; V = M1^2 + M2^2 + M3^2
            sage: s = stationary_solutions([H, V], [M1, M2, M3])[0]; s.free_multipliers()
            [lambda1]
            sage: s.stability_conditions()
            [(2*A1*lambda1 + 1)*A1, (2*A2*lambda1 + 1)*A2, (2*A3*lambda1 + 1)*A3]
            sage: s.stability_region(positive=[A1, A2, A3])
            [[]]
        """
        self._check_sign(sign)
        positive = self._positive(positive)
        existence = self.conditions()
        result = []
        for alt in self._definiteness_region(positive, sign):
            joined = simplify_conjunction(existence + alt, positive)
            if joined is not None and joined not in result:
                result.append(joined)
        return result

    # -- first approximation -------------------------------------------------

    def linear_system(self):
        r"""
        The first-approximation system at the solution (a
        :class:`~sage_dynsym.analysis.linear.LinearSystem`), or ``None``
        when the equations of motion are not known.

        EXAMPLES::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: x, y = var('x y')
            sage: s = stationary_solutions([(x^2 + y^2)/2], [x, y], equations=[y, -x])[0]
            sage: s.linear_system().jacobian()
            [ 0  1]
            [-1  0]
        """
        return self._problem.linear_system(self._at)

    def stability(self, positive=None):
        r"""
        A stability verdict combining the Routh--Lyapunov method (a definite
        second variation: :meth:`stability_region`) with the first
        approximation (the Liénard--Chipart conditions for asymptotic
        stability; a root with positive real part -- a coefficient of the
        characteristic polynomial of the sign opposite to the leading one,
        or, for a polynomial in `\lambda^2`, of its polynomial in `\mu =
        \lambda^2` -- for instability).

        OUTPUT: a :class:`~sage_dynsym.analysis.kelvin_chetaev.StabilityVerdict`;
        its :meth:`~sage_dynsym.analysis.kelvin_chetaev.StabilityVerdict.method`
        says which method decided, its ``region()`` where; with several
        possible verdicts, ``'depends on the parameters'`` and the cases

        EXAMPLES: the double pendulum's lower equilibrium is stable::

            sage: from sage_dynsym import Lagrangian
            sage: from sage_dynsym.analysis.stationary import stationary_motions
            sage: t1, t2, d1, d2, m, l, g = var('theta1 theta2 dtheta1 dtheta2 m l g')
            sage: L = Lagrangian(m*l^2*(d1^2 + d2^2/2 + d1*d2*cos(t1 - t2))
            ....:                + m*g*l*(2*cos(t1) + cos(t2)), [t1, t2])
            sage: [(s.point(), s.stability(positive=[m, l, g]).verdict())
            ....:  for s in stationary_motions(L)]
            [({theta1: 0, theta2: 0}, 'stable'),
             ({theta1: 0, theta2: pi}, 'unstable'),
             ({theta1: pi, theta2: 0}, 'unstable'),
             ({theta1: pi, theta2: pi}, 'unstable')]
            sage: stationary_motions(L)[3].stability(positive=[m, l, g]).method()
            'first approximation'

        Where the second variation does not decide, the first approximation
        (:meth:`~sage_dynsym.analysis.linear.LinearSystem.stability`) covers
        the rest: the sleeping top, gyroscopically stabilized -- stable in
        first approximation -- exactly for `p^2 > 4Amgl`, unstable below
        (Maxwell's criterion)::

            sage: from sage_dynsym import MechanicalSystem, RigidBody, UniformGravity
            sage: alpha, beta, phi, A, C = var('alpha beta phi A C')
            sage: top = RigidBody('top', rotations=[(1, alpha), (2, beta), (3, phi)],
            ....:                 mass_center=[0, 0, l], mass=m, inertia=diagonal_matrix([A, A, C]))
            sage: R = MechanicalSystem([top], [alpha, beta, phi], parameters=[A, C, m, g, l],
            ....:     force_function=UniformGravity([0, 0, -g])).lagrangian().routh([phi])
            sage: sols = stationary_motions(R, positive=[A, C, m, g, l])
            sage: v = next(s for s in sols if s.point() == {alpha: 0, beta: 0}).stability()
            sage: [(case.verdict(), case.region()) for case in v.cases()]
            [('stable in first approximation', [[4*A*g*l*m - p_phi^2 < 0]]),
             ('unstable', [[4*A*g*l*m - p_phi^2 > 0]])]

        A family whose values hold square roots of parameters is tested in
        first approximation too (`\varepsilon = r^2` there): Brun's problem,
        `H = \tfrac12 (M, I^{-1} M) + \tfrac\varepsilon2 (\gamma, I\gamma)`
        (Borisov and Mamaev, *Rigid Body Dynamics*, the Brun case), whose
        uniform rotations `\gamma = \pm I^{-1} M/\sqrt\varepsilon` are
        unstable where a polynomial of the moments of inertia and of `M` is
        negative (only for moments of inertia of both signs)::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: M1, M2, M3, g1, g2, g3 = var('M1 M2 M3 g1 g2 g3')
            sage: I1, I2, I3, eps = var('I1 I2 I3 epsilon')
            sage: Mv, gv, I = vector([M1, M2, M3]), vector([g1, g2, g3]), [I1, I2, I3]
            sage: H = sum(Mv[i]^2/I[i] + eps*I[i]*gv[i]^2 for i in range(3))/2
            sage: w = vector([H.diff(v) for v in Mv]); u = vector([H.diff(v) for v in gv])
            sage: X = list(Mv.cross_product(w) + gv.cross_product(u)) + list(gv.cross_product(w))
            sage: sols = stationary_solutions([H, gv*gv, Mv*gv], list(Mv) + list(gv), equations=X)
            sage: s = next(s for s in sols if s.point()[g3] == M3/(I3*sqrt(eps))
            ....:          and not s.point()[g1].is_zero())
            sage: s.point()[g1], s.conditions()  # long time
            (M1/(I1*sqrt(epsilon)), [g3 != 0, I3 != 0, epsilon > 0, I1 != 0, M1 != 0, I2 != 0])
            sage: [c.verdict() for c in s.stability().cases()]  # long time
            ['undecided', 'unstable']
        """
        positive = self._positive(positive)
        region = []
        first, why = [], "neither the second variation nor the first approximation decides"
        existence = simplify_conjunction(self.conditions(), positive) or []
        try:
            for sign in self._problem.signs:
                for alt in self.stability_region(positive, sign):
                    if alt not in region:
                        region.append(alt)
        except AnalysisError as err:
            # the second variation is not decided (e.g. QEPCAD's budget):
            # the first approximation may still decide
            region, why = [], why + f" (second variation: {err})"
        # the first approximation is the one stability service's; the
        # Routh-Lyapunov theorem adds 'stable' (for the nonlinear system)
        try:
            first = self._first_approximation_cases(positive)
        except AnalysisError as err:
            why += f" ({err})"
        order = ('asymptotically stable', 'stable', 'stable in first approximation',
                 'undecided', 'unstable')
        regions = {}
        for name, alts in [(c.verdict(), c.region()) for c in first] + [('stable', region)]:
            if alts:
                regions[name] = regions.get(name, []) + [a for a in alts
                                                         if a not in regions.get(name, [])]
        parts = sorted(regions.items(), key=lambda part: order.index(part[0]))
        reasons = {c.verdict(): c.reason() for c in first}
        reasons['stable'] = "the second variation of the Lyapunov function is definite"
        reasons.setdefault('undecided', why)
        if not self._solution.is_reality_decided():
            # each case holds at the family's real points in its region;
            # where they exist there is not known
            reasons = {k: f"{r}; where the family is real within this region is not "
                       f"decided" for k, r in reasons.items()}
        return verdict_from_parts(parts, reasons, {}, positive, domain=[existence],
                                  methods={'stable': 'Routh-Lyapunov'}, rest='undecided')

    def _first_approximation_cases(self, positive):
        r"""The cases of the first approximation's verdict (``[]`` when it
        is not known). A square root `\sqrt D` in the solution (of
        `\varepsilon`, of `\theta a_1 a_2 a_3`) is a new positive parameter
        `r` first, a symbol of `D` written as a rational function of `r`
        with `D = r^2`: the test needs rational coefficients; the regions
        are written back with `r = \sqrt D`."""
        if not self.is_explicit() or self.is_equilibrium() is False:
            return []
        values = list(self.point().values()) + list(self.multipliers().values())
        radicands = []
        for v in values:
            _radicands(SR(v), radicands)
        found = _root_substitution(radicands[0], values) if len(radicands) == 1 else None
        lin = None
        if found is not None:
            (D,), (r, p, value) = radicands, found
            try:
                lin = self._problem.linear_system(
                    lambda e: _with_root(self._at(e), D, r, p, value))
            except (TypeError, ValueError, ArithmeticError):
                found = None    # an expression the substitution cannot rebuild
        if found is None:
            lin = self.linear_system()
            return [] if lin is None else lin.stability(positive=positive).cases()
        if lin is None:
            return []
        cases = lin.stability(positive=list(positive) + [r]).cases()
        return [StabilityVerdict(c.verdict(), c.reason(), method=c.method(),
                                 region=None if c.region() is None else
                                 [[SR(rel).subs({r: D.sqrt()}) for rel in alt]
                                  for alt in c.region()])
                for c in cases]

    def check(self, equations):
        r"""
        Verify that the solution annuls the right-hand sides ``equations``
        (exactly, on the whole component); returns ``True`` or raises
        :class:`AnalysisError`.

        EXAMPLES::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: x, y = var('x y')
            sage: s = stationary_solutions([(x^2 + y^2)/2], [x, y])[0]
            sage: s.check([y, -x])
            True
            sage: s.check([y + 1, -x])
            Traceback (most recent call last):
            ...
            AnalysisError: stationary_solutions: {x: 0, y: 0} does not annul the right-hand side 0, y + 1
        """
        for k, X in enumerate(equations):
            if not normalize(self._at(X)).is_zero():
                raise AnalysisError(f"{self.point()} does not annul the right-hand "
                                    f"side {k}, {X}", entry="stationary_solutions")
        return True


class StationarySolutions(SolutionList):
    r"""
    The stationary solutions of a problem (iterable): created by
    :func:`stationary_solutions` (conditional extrema of first integrals)
    or :func:`stationary_motions` (a Lagrangian or Routh function at rest),
    through :func:`stationary_solutions`. It holds the results only.

    INPUT:

    - ``problem`` -- the :class:`StationaryProblem` solved
    - ``solutions`` -- its solution set, a
      :class:`~sage_dynsym.algebra.solving.SolutionSet`

    EXAMPLES::

        sage: from sage_dynsym.analysis.stationary import stationary_solutions
        sage: x, y, a = var('x y a')
        sage: sols = stationary_solutions([(x^2 + a*y^2)/2, x^2 + y^2], [x, y]); sols
        3 stationary solutions of K = 1/2*a*y^2 + (x^2 + y^2)*lambda1 + 1/2*x^2

    TESTS::

        sage: TestSuite(sols).run()
    """

    def __init__(self, problem, solutions, chart=None, regular=None):
        if not isinstance(problem, StationaryProblem):
            raise AnalysisError(f"expected a stationary problem, got {brief(problem)}; the "
                                "solutions come from stationary_solutions(integrals, variables)",
                                entry="StationarySolutions")
        self._problem = problem
        self._set = solutions
        self._raw = [StationarySolution(problem, s) for s in solutions]
        self._chart = chart
        self._artifacts = []
        SolutionList.__init__(self, self._raw if chart is None else
                              self._points(chart, regular))

    def _points(self, chart, regular):
        r"""The listing in ``chart``: one :class:`ChartPointSolution` per point
        of the configuration space, then the families of configurations."""
        from .charts import points_of_chart, same_point
        variables = self._problem.solved_variables()
        if [str(q) for q in chart.coordinates()] != [str(x) for x in variables]:
            raise AnalysisError(f"the chart's coordinates {chart.coordinates()} are not the "
                                f"variables solved for, {variables}; give a chart of "
                                f"{', '.join(map(str, variables))}", entry="chart")
        names = {str(x) for x in variables}
        exact = all(str(v) in names or str(v) == 't'
                    for e in self._problem.equations for v in SR(e).variables())
        families = []
        points = points_of_chart(self._raw, variables, self._problem.function, chart, families,
                                 self._artifacts, exact=exact)
        others = [] if regular is None else \
            [(s.configuration_point(), s) for s in regular if isinstance(s, ChartPointSolution)]
        listed = []
        for point in points:
            partner = None
            if point.is_singular() and regular is not None:
                j = same_point(point, [p for p, _ in others])
                if j is None or others[j][0].is_singular():
                    raise AnalysisError(f"the equilibrium {point.embedding()} on the singular set "
                                        "of the chart is not a regular point of the listing "
                                        "given as regular=: give the same model in a chart "
                                        "regular there", entry="regular")
                partner = others[j][1]
            listed.append(ChartPointSolution(self._problem, point, partner))
        return listed + families

    def _repr_(self):
        what = self._problem.description
        if not self._solutions:
            return ("No stationary solutions: the equations are inconsistent (for "
                    "generic parameter values)")
        n = len(self._solutions)
        note = "" if self._set.is_complete() else \
            " (transcendental equations: found by Maxima's solve, possibly not all)"
        if self._chart is not None:
            note += f" (points of the configuration space; {len(self._raw)} in the chart)"
        return f"{n} stationary solution{'s' if n != 1 else ''} of {what}{note}"

    def chart(self):
        r"""
        The chart of the configuration space the listing is made in, or
        ``None`` (then every solution of the equations is listed).

        EXAMPLES::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: x = var('x')
            sage: stationary_solutions([x^2], [x]).chart() is None
            True
        """
        return self._chart

    def in_chart(self, chart, regular=None):
        r"""
        The same solutions listed as points of the configuration space of
        which ``chart`` is a chart: the solutions of the chart over one point
        (its covers) are one :class:`ChartPointSolution`, a family of
        solutions of the chart over one point (on its singular set) is that
        point, a solution on the singular set is kept only if it is an
        equilibrium (:meth:`~sage_dynsym.analysis.charts.ConfigurationChart.equilibrium_obstruction`,
        exact), the real points of implicit zero-dimensional components are
        listed one by one; the families of configurations follow.

        INPUT:

        - ``chart`` -- a :class:`~sage_dynsym.analysis.charts.ConfigurationChart`
          of the variables (e.g. :func:`~sage_dynsym.mechanics.charts.euler_angles`)
        - ``regular`` -- (optional) the stationary solutions of the same
          model in a chart regular on the singular set of ``chart``, listed
          in that chart: the stability of a point on the singular set is
          decided there (otherwise it is ``'undecided'``)

        OUTPUT: a :class:`StationarySolutions`; its :meth:`chart_solutions`
        are the solutions of the chart, :meth:`chart_artifacts` those left
        out. With numerical parameter values the points are compared as
        real algebraic numbers; with symbolic parameters the images are
        compared symbolically, and a solution on the singular set is left
        out when it is an equilibrium for no generic value of them.

        EXAMPLES: the critical points of `W = \operatorname{tr}(M^T R)` on
        `SO(3)` (module :mod:`~sage_dynsym.analysis.charts`): sixteen
        solutions of the angles, four orientations::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: from sage_dynsym.mechanics.charts import euler_angles
            sage: a, b, c = var('a b c')
            sage: chart = euler_angles([(3, a), (1, b), (2, c)])
            sage: R = chart.rotation_matrix()
            sage: sols = stationary_solutions([R[0, 0] + 2*R[1, 1] + 3*R[2, 2] + R[2, 1]/3],
            ....:                             [a, b, c]).in_chart(chart); sols
            4 stationary solutions of K = ... (points of the configuration space; 16 in the chart)
            sage: [len(s.chart_solutions()) for s in sols], len(sols.chart_artifacts())
            ([2, 2, 2, 2], 8)
        """
        return StationarySolutions(self._problem, self._set, chart, regular)

    def chart_solutions(self):
        r"""
        Every solution of the equations in the chart's coordinates, as
        solved (covers and solutions on the chart's singular set included):
        a :class:`StationarySolutions` without a chart.

        EXAMPLES: see :meth:`in_chart`::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: x = var('x')
            sage: len(stationary_solutions([x^2], [x]).chart_solutions())
            1
        """
        return self if self._chart is None else StationarySolutions(self._problem, self._set)

    def chart_artifacts(self):
        r"""
        The solutions of the chart left out of the listing: on its singular
        set, and not equilibria.

        EXAMPLES: see :meth:`in_chart`::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: stationary_solutions([var('x')^2], [var('x')]).chart_artifacts()
            []
        """
        return list(self._artifacts)
    def _test_solutions(self, **options):
        r"""Each solution annuls the equations of the problem (an unsolved
        equation is never a solution).

        EXAMPLES: run by ``TestSuite`` (see the class).
        """
        tester = self._tester(**options)
        for solution in self._solutions:
            tester.assertTrue(solution.check(self._problem.equations))

    def __eq__(self, other):
        return isinstance(other, StationarySolutions) and \
            str(self._problem.equations) == str(other._problem.equations) and \
            str(self._problem.unknowns) == str(other._problem.unknowns)

    def __ne__(self, other):
        return not self == other

    def __hash__(self):
        return hash((str(self._problem.equations), str(self._problem.unknowns)))

    def is_complete(self):
        r"""Whether the list is known to be complete (always, unless the
        transcendental fallback was used).

        EXAMPLES::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: x = var('x')
            sage: stationary_solutions([x^2], [x]).is_complete()
            True
        """
        return self._set.is_complete()

    def is_empty(self):
        r"""Whether there is no stationary solution.

        EXAMPLES::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: x = var('x')
            sage: stationary_solutions([x^2, x, x^3], [x], levels=[1, 2]).is_empty()
            True
        """
        return not self._solutions

    def report_lines(self, equation=None):
        r"""
        The solutions as lines of a text report: whether there are none,
        whether the list may be incomplete, then for each solution its
        values (or that it is a family, or implicit), the equations left, the
        existence conditions and the stability verdict -- or why it was not
        decided.

        INPUT:

        - ``equation`` -- (optional) a function ``(lines, expr)`` appending
          the lines of an equation ``0 = expr`` (default: one line)

        OUTPUT: a list of strings

        EXAMPLES: the equilibria of a pendulum::

            sage: from sage_dynsym import Lagrangian, stationary_motions
            sage: th, dth, m, g, l = var('theta dtheta m g l')
            sage: L = Lagrangian(m*l^2*dth^2/2 + m*g*l*cos(th), [th])
            sage: for line in stationary_motions(L, positive=[m, g, l]).report_lines():
            ....:     print(line)
              solution 1 (isolated): theta = 0
                stability: stable (Routh-Lyapunov): the second variation of the Lyapunov function is definite
              solution 2 (isolated): theta = pi
                stability: unstable (first approximation): the potential energy has an odd degree of instability (1): no gyroscopic or dissipative forces can stabilize it (Thomson-Tait-Chetaev; Kelvin-Chetaev, 3rd theorem)
        """
        if equation is None:
            def equation(lines, e):
                lines.append(f"    0 = {e}")
        lines = []
        if self.is_empty():
            lines.append("  no real solutions (for generic parameter values)")
        # the equations left of a family may hold multipliers: say what they are
        used = [m for m in self.multipliers()
                if any(SR(e).has(m) for s in self for e in s.equations())]
        if used:
            lines.append(f"  ({', '.join(map(str, used))}: the multipliers of the Lyapunov "
                         f"function K = {self.lyapunov_function()})")
        if not self.is_complete():
            lines.append("  (transcendental equations: solutions found by Maxima's solve, "
                         "possibly not all)")
        if self._chart is not None:
            lines.append(f"  (points of the configuration space of the chart {self._chart}: "
                         f"{len(self._raw)} solutions of the chart, covers merged, "
                         f"{len(self._artifacts)} on its singular set that are not "
                         "equilibria left out; chart_solutions() lists them all)")
        for k, s in enumerate(self, 1):
            values = ", ".join(f"{v} = {e}" for v, e in s.point().items() if str(v) != str(e))
            kind = s._kind()
            if not s.is_explicit():
                kind += ", implicit"
            lines.append(f"  solution {k} ({kind}): {values or 'given by its equations'}")
            for e in s.equations():
                if not SR(e).is_zero():     # an identity says nothing
                    equation(lines, e)
            try:
                conditions = s.conditions()
                decided = s.is_reality_decided()
                if conditions:
                    lead = "exists if" if decided else "real at most where (not decided)"
                    lines.append(f"    {lead}: " + ", ".join(map(str, conditions)))
                elif not decided:
                    lines.append("    where it is real: not decided")
                verdict = s.stability()
            except DynSymError as err:
                lines.append(f"    stability: not decided ({err})")
                continue
            if verdict.verdict() != 'depends on the parameters':
                method = f" ({verdict.method()})" if verdict.method() else ""
                lines.append(f"    stability: {verdict.verdict()}{method}: {verdict.reason()}")
                continue
            lines.append("    stability depends on the parameters:")
            for v in verdict.cases():
                where = " or ".join("[" + ", ".join(map(str, alt)) + "]" for alt in v.region())
                lines.append(f"      {v.verdict()} ({v.method()}) where {where}")
        return lines

    def equations(self):
        r"""
        The equations solved (expressions ``== 0``): the stationarity
        equations and the prescribed levels; for stationary motions, the
        equations of motion at rest.

        EXAMPLES::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: x, y, c = var('x y c')
            sage: stationary_solutions([x^2 + y^2, x], [x, y], levels=[c]).equations()
            [lambda1 + 2*x, 2*y, -c + x]
        """
        return list(self._problem.shown)

    def integrals(self):
        r"""The integrals `V_0, \dots, V_k` (``[]`` for stationary motions).

        EXAMPLES::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: x, y = var('x y')
            sage: stationary_solutions([x^2 + y^2, x], [x, y]).integrals()
            [x^2 + y^2, x]
        """
        return list(self._problem.integrals)

    def variables(self):
        r"""The variables of the stationary set (without the multipliers).

        EXAMPLES::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: x, y = var('x y')
            sage: stationary_solutions([x^2 + y^2], [x, y]).variables()
            [x, y]
        """
        return self._problem.solved_variables()

    def multipliers(self):
        r"""The multipliers `\lambda_1, \dots`.

        EXAMPLES::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: x, y = var('x y')
            sage: stationary_solutions([x^2 + y^2, x], [x, y]).multipliers()
            [lambda1]
        """
        return list(self._problem.multipliers)

    def lyapunov_function(self):
        r"""The Lyapunov function whose critical points are the solutions:
        `K = V_0 + \sum_{j\ge1}\lambda_j V_j` (for stationary motions, the
        amended potential `W = -R|_{\dot q = 0}`). ``K()`` is an alias.

        EXAMPLES::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: x, y, a = var('x y a')
            sage: sols = stationary_solutions([(x^2 + a*y^2)/2, x^2 + y^2], [x, y])
            sage: sols.lyapunov_function()
            1/2*a*y^2 + (x^2 + y^2)*lambda1 + 1/2*x^2
            sage: bool(sols.K() == sols.lyapunov_function())
            True
        """
        return self._problem.function

    K = lyapunov_function

    def stationary_problem(self):
        r"""The :class:`StationaryProblem` solved.

        EXAMPLES::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: x, y = var('x y')
            sage: stationary_solutions([x^2 + y^2, x], [x, y]).stationary_problem().unknowns
            [x, y, lambda1]
        """
        return self._problem

    def stationarity_equations(self):
        r"""The expressions `\partial K/\partial x_i` (each ``== 0``).

        EXAMPLES::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: x, y, a = var('x y a')
            sage: stationary_solutions([(x^2 + a*y^2)/2, x^2 + y^2], [x, y]).stationarity_equations()
            [2*lambda1*x + x, a*y + 2*lambda1*y]
        """
        return [self._problem.function.diff(x).expand() for x in self._problem.variables]

    def hessian(self):
        r"""The Hessian matrix of `K` (symbolic).

        EXAMPLES::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: x, y, a = var('x y a')
            sage: stationary_solutions([(x^2 + a*y^2)/2, x^2 + y^2], [x, y]).hessian()
            [2*lambda1 + 1             0]
            [            0 a + 2*lambda1]
        """
        return self._problem.hessian()

    def configuration_points(self, chart=None, families=None):
        r"""
        The distinct points of the configuration space where the solutions
        lie, at numerical values of the parameters: covers of the chart
        merged, solutions on its singular set kept only if they are
        equilibria, implicit components' points listed (see
        :func:`~sage_dynsym.analysis.charts.configuration_points`).

        EXAMPLES: `\cos 2x` has four critical points on the circle::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: x = var('x')
            sage: [p.embedding() for p in stationary_solutions([cos(2*x)], [x]).configuration_points()]
            [(-1, 0), (0, -1), (0, 1), (1, 0)]
        """
        from .charts import configuration_points
        return configuration_points(self, chart, families)


class ChartPointSolution(StationarySolution):
    r"""
    One stationary solution listed as a point of the configuration space
    (see :meth:`StationarySolutions.in_chart`): the solutions of the chart
    over it, its values taken at one of them (on a family over the point,
    at a point of the family), and its stability decided there -- or, on
    the chart's singular set, in the regular chart when one was given
    (``'undecided'`` otherwise: the chart's Hessian is degenerate there).

    INPUT:

    - ``problem`` -- the :class:`StationaryProblem`
    - ``point`` -- a :class:`~sage_dynsym.analysis.charts.ConfigurationPoint`
    - ``regular`` -- (optional) the same point as a stationary solution in
      a regular chart

    EXAMPLES: the angles `a, b, c` about the axes `z, x, y` are singular at
    `b = \pm\pi/2`; the four critical points of `W = R_{00} + 2R_{12} +
    3R_{21}` on `SO(3)` are there, each a curve of angles::

        sage: from sage_dynsym.analysis.stationary import stationary_solutions
        sage: from sage_dynsym.mechanics.charts import euler_angles
        sage: a, b, c = var('a b c')
        sage: def W(chart):
        ....:     R = chart.rotation_matrix()
        ....:     return R[0, 0] + 2*R[1, 2] + 3*R[2, 1]
        sage: chart = euler_angles([(3, a), (1, b), (2, c)])
        sage: sols = stationary_solutions([W(chart)], [a, b, c], chart=chart)
        sage: [(s.dimension(), s.is_singular(), s.point()) for s in sols]
        [(0, True, {a: 0, b: -1/2*pi, c: pi}),
         (0, True, {a: 0, b: 1/2*pi, c: pi}),
         (0, True, {a: 0, b: 1/2*pi, c: 0}),
         (0, True, {a: 0, b: -1/2*pi, c: 0})]
        sage: [s.dimension() for s in sols.chart_solutions()]
        [1, 1, 1, 1]
        sage: sols[0].stability()
        undecided: the point is on the singular set of the chart, ...

    In the angles about `z, y, x` (singular where `|R_{20}| = 1`) the four
    points are regular: the minimum and the maximum of `W`, where `K = W`
    is definite, and two saddles (no equations of motion were given, so
    they stay undecided)::

        sage: second = euler_angles([(3, a), (2, b), (1, c)])
        sage: sols = stationary_solutions([W(chart)], [a, b, c], chart=chart,
        ....:     regular=stationary_solutions([W(second)], [a, b, c], chart=second))
        sage: [(s.regular_solution().point(), s.stability().verdict()) for s in sols]
        [({a: 0, b: pi, c: 1/2*pi}, 'stable'),
         ({a: 0, b: pi, c: -1/2*pi}, 'stable'),
         ({a: 0, b: 0, c: 1/2*pi}, 'undecided'),
         ({a: 0, b: 0, c: -1/2*pi}, 'undecided')]
        sage: [s.regular_solution().hessian().eigenvalues() for s in sols]
        [[3, 4, 5], [-5, -2, -1], [-4, -1, 1], [-3, 1, 2]]
    """

    def __init__(self, problem, point, regular=None):
        StationarySolution.__init__(self, problem, point.solutions()[0].solution())
        self._configuration_point = point
        self._regular = regular

    def _kind(self):
        n = len(self._configuration_point.solutions())
        where = ", on the chart's singular set" if self.is_singular() else ""
        return f"isolated, a point of the configuration space: {n} in the chart{where}"

    def _at(self, expr):
        return self._configuration_point.value(expr)

    def configuration_point(self):
        r"""The :class:`~sage_dynsym.analysis.charts.ConfigurationPoint`.

        EXAMPLES: see :class:`ChartPointSolution`.
        """
        return self._configuration_point

    def chart_solutions(self):
        r"""The solutions of the chart over the point.

        EXAMPLES: see :meth:`StationarySolutions.in_chart`.
        """
        return self._configuration_point.solutions()

    def embedding(self):
        r"""The point's image in the chart's embedding (e.g. the rotation matrix).

        EXAMPLES: see :meth:`StationarySolutions.in_chart`.
        """
        return self._configuration_point.embedding()

    def is_singular(self):
        r"""Whether the point is on the chart's singular set.

        EXAMPLES: see :class:`ChartPointSolution`.
        """
        return self._configuration_point.is_singular()

    def regular_solution(self):
        r"""The point as a stationary solution of the regular chart, or ``None``.

        EXAMPLES: see :class:`ChartPointSolution`.
        """
        return self._regular

    def dimension(self):
        r"""``0``: one point of the configuration space.

        EXAMPLES: see :class:`ChartPointSolution`.
        """
        return 0

    def is_explicit(self):
        r"""``True``: the point's values are known (exact).

        EXAMPLES: see :class:`ChartPointSolution`.
        """
        return True

    def equations(self):
        r"""``[]``: the point is given by its values.

        EXAMPLES: see :class:`ChartPointSolution`.
        """
        return []

    def point(self):
        r"""
        The values of the variables at one solution of the chart over the
        point (on a family over it, the free variables set to a value where
        the family is defined).

        EXAMPLES: see :class:`ChartPointSolution`.
        """
        values = StationarySolution.point(self)
        free = self._solution.free_unknowns()
        angles = self._solution.translation().is_angle if \
            self._solution.translation() is not None else (lambda u: False)
        for x, v in values.items():
            if str(v) == str(x) and all(str(x) != str(u) for u in free):
                # a point of an implicit component: its exact values
                values[x] = SR(self._at(x)) if not angles(x) else \
                    SR(arctan2(self._at(x.sin()), self._at(x.cos())))
        free = [u for u in free if any(SR(v).has(u) for v in values.values())]
        for trial in (0, 1, 2, 3):
            try:
                at = {x: normalize(SR(v).subs({u: trial for u in free}))
                      for x, v in values.items()}
            except (ValueError, ZeroDivisionError, RuntimeError):
                continue
            if not any(SR(v).has(u) for v in at.values() for u in free):
                return at
        return values

    def stability(self, positive=None):
        r"""
        The stability verdict of the point: as for any stationary solution
        at a regular point of the chart; on its singular set, that of the
        regular chart if one was given, ``'undecided'`` otherwise.

        EXAMPLES: see :class:`ChartPointSolution`.
        """
        if self._regular is not None:
            return self._regular.stability(positive)
        if self.is_singular():
            return StabilityVerdict(
                'undecided', "the point is on the singular set of the chart, where its "
                "Hessian is degenerate: list the solutions with in_chart(chart, regular=...), "
                "the same model in a chart regular there")
        if not self._problem.constraint_integrals() and \
                all(getattr(x, 'parent', lambda: None)() is AA for x in self.embedding()):
            # a point of real algebraic numbers: decided exactly there
            verdict = point_verdict(self._configuration_point, self._problem)
            return StabilityVerdict(verdict, "decided exactly at the point (real algebraic "
                                    "numbers): the Hessian and the first approximation")
        return StationarySolution.stability(self, positive)


def solve_stationary(problem, chart=None, regular=None):
    r"""
    Deprecated: use ``stationary_solutions(problem)``
    (:func:`stationary_solutions`, the one way to ask for stationary
    solutions).

    With a ``chart`` of the variables (and optionally the solutions of the
    same model in a ``regular`` chart), the solutions are listed as points
    of the configuration space (:meth:`StationarySolutions.in_chart`).

    EXAMPLES::

        sage: from sage_dynsym.analysis.stationary import StationaryProblem, solve_stationary
        sage: x, a = var('x a')
        sage: sols = solve_stationary(StationaryProblem(x^3/3 - a*x, [x], [x], [], [x^2 - a],
        ....:                                           positive=[a]))
        doctest:warning...
        DeprecationWarning: solve_stationary(problem) is deprecated; use stationary_solutions(problem)
        See https://github.com/sagemath/sage/issues/31 for details.
        sage: [s.point() for s in sols]
        [{x: sqrt(a)}, {x: -sqrt(a)}]
    """
    deprecation(31, "solve_stationary(problem) is deprecated; use stationary_solutions(problem)")
    return stationary_solutions(problem, chart=chart, regular=regular)


def _solved(problem, chart=None, regular=None, budget=None):
    # the equations of the problem solved exactly (Maxima's solve the
    # fallback for transcendental equations), the dimensions counted in the
    # unknowns that are not multipliers
    def compute():
        return solve_exactly(problem.equations, problem.unknowns,
                             counted=problem.solved_variables(), positive=problem.positive,
                             extra=[problem.function] + list(problem.rhs or []),
                             transcendental=True)
    found = compute() if budget is None else _within_budget(compute, budget)
    return StationarySolutions(problem, found, chart, regular)


def _within_budget(compute, budget):
    r"""
    ``compute()`` in a forked process stopped after ``budget`` seconds: a
    Singular computation interrupted in this process could leave Singular's
    interpreter without a ring, a killed child leaves nothing behind. The
    wait uses no signal (:func:`~sage_dynsym.algebra.forked.forked`): it
    works in any thread, e.g. a Dask worker's. Over the budget, an :class:`~sage_dynsym.errors.AnalysisError` says so (no
    partial result is passed off as the answer).

    EXAMPLES::

        sage: from sage_dynsym.analysis.stationary import _within_budget
        sage: _within_budget(lambda: 1 + 1, 60)
        2
        sage: _within_budget(lambda: sleep(5), 1)
        Traceback (most recent call last):
        ...
        AnalysisError: budget: the stationary set was not found within 1 s; give the parameters values, or a larger budget (budget=None waits)

    An error of the solving is raised as it is::

        sage: _within_budget(lambda: 1/0, 60)
        Traceback (most recent call last):
        ...
        ZeroDivisionError: rational division by zero
    """
    _, (outcome, value) = forked(lambda send: compute(), budget)
    if outcome == 'timeout':
        raise AnalysisError(f"the stationary set was not found within {budget} s; give "
                            "the parameters values, or a larger budget (budget=None waits)",
                            entry="budget")
    if outcome == 'error':
        # an error of the solving is raised as it is, not taken for a timeout
        raise value
    if outcome == 'died':
        raise AnalysisError(f"the process solving the stationary set ended without an "
                            f"answer ({value})", entry="budget")
    return value


def stationary_solutions(integrals, variables=None, equations=None, multipliers=None,
                         levels=None, positive=(), solve_for=None, chart=None, regular=None,
                         budget=None):
    r"""
    Routh--Lyapunov: stationary solutions as conditional extrema of the
    first integrals, computed exactly (see the module documentation). The
    one way to ask for stationary solutions: of first integrals, of a
    Routh function or a Lagrangian (its stationary motions, as
    :func:`stationary_motions`), or of a :class:`StationaryProblem`
    written out.

    INPUT:

    - ``integrals`` -- list `[V_0, V_1, \dots, V_k]` of first integrals;
      `K = V_0 + \lambda_1 V_1 + \dots + \lambda_k V_k`. Or a
      :class:`~sage_dynsym.dynamics.lagrangian.RouthFunction` or
      :class:`~sage_dynsym.dynamics.lagrangian.Lagrangian`: its stationary
      motions (see :func:`stationary_motions`; then only ``solve_for``
      and ``positive`` apply). Or a :class:`StationaryProblem`, solved as
      it is (no other argument applies).
    - ``variables`` -- the phase variables `x` (with integrals)
    - ``equations`` -- (optional) the right-hand sides `X(x)`; if given,
      every integral is checked to be conserved, each solution says whether
      it is made of equilibria (:meth:`StationarySolution.is_equilibrium`)
      or is an invariant manifold of other motions, and the first
      approximation is available for the stability verdict at equilibria
    - ``multipliers`` -- (optional) names or symbols for `\lambda_1, \dots`
      (default ``lambda1, lambda2, ...``)
    - ``levels`` -- (optional) one entry per integral after the first: its
      prescribed value `V_j = c_j`, or ``None`` (free)
    - ``positive`` -- parameters declared positive (used in the conditions)
    - ``solve_for`` -- (optional) the unknowns (default: the variables and
      the multipliers)
    - ``chart``, ``regular`` -- (optional) a chart of the configuration
      space whose coordinates are the variables, and the same solutions in
      a chart regular on its singular set: the solutions are then listed as
      points of the configuration space (:meth:`StationarySolutions.in_chart`)
    - ``budget`` -- (optional) seconds: the solving runs in a forked process
      stopped after that time, and raises an
      :class:`~sage_dynsym.errors.AnalysisError` saying so

    OUTPUT: a :class:`StationarySolutions`; iterate over it for the
    :class:`StationarySolution` objects

    Progress is reported through Sage's ``verbose``.

    EXAMPLES: see the module documentation. A conservative system whose
    equilibria form a curve (one component of dimension 1) besides the
    origin::

        sage: from sage_dynsym.analysis.stationary import stationary_solutions
        sage: x, y = var('x y')
        sage: sols = stationary_solutions([(x^2 + y^2 - 1)^2/4], [x, y])
        sage: [(s.dimension(), s.point(), s.equations()) for s in sols]
        [(0, {x: 0, y: 0}, []), (1, {x: x, y: y}, [x^2 + y^2 - 1])]

    The stationary motions of a Routh function (the same as
    :func:`stationary_motions`): a particle on a smooth cone of half-angle
    `\alpha`, `R = m(\dot r^2/\sin^2\alpha)/2 - p^2/(2 m r^2) - m g r
    \cot\alpha`, circles at `r^3 = p^2 \tan\alpha/(m^2 g)`::

        sage: from sage_dynsym import Lagrangian
        sage: r, phi, dr, dphi, m, g, al = var('r phi dr dphi m g alpha')
        sage: L = Lagrangian(m/2*(dr^2/sin(al)^2 + r^2*dphi^2) - m*g*r*cot(al), [r, phi])
        sage: R = L.routh([phi]); p = R.momenta()[0]
        sage: sols = stationary_solutions(R, solve_for=[p], positive=[m, g, r])
        sage: [s.point()[p]^2 for s in sols]
        [g*m^2*r^3*cot(alpha), g*m^2*r^3*cot(alpha)]

    A problem written out: the critical points of `x^3/3 - a x`::

        sage: from sage_dynsym.analysis.stationary import StationaryProblem
        sage: a = var('a')
        sage: sols = stationary_solutions(StationaryProblem(x^3/3 - a*x, [x], [x], [], [x^2 - a],
        ....:                                               positive=[a]))
        sage: [s.point() for s in sols]
        [{x: sqrt(a)}, {x: -sqrt(a)}]

    TESTS::

        sage: stationary_solutions([x^2])
        Traceback (most recent call last):
        ...
        AnalysisError: stationary_solutions: the phase variables are needed with integrals: stationary_solutions(integrals, variables)
        sage: stationary_solutions(R, [r])
        Traceback (most recent call last):
        ...
        AnalysisError: stationary_solutions: variables, equations, multipliers and levels are for integrals; the stationary motions of a Routh function or Lagrangian take solve_for= and positive= only
        sage: stationary_solutions([exp(x) - x], [x])
        1 stationary solution of K = -x + e^x (transcendental equations: found by Maxima's solve, possibly not all)
        sage: stationary_solutions([x*cos(x)], [x])
        Traceback (most recent call last):
        ...
        AnalysisError: solve_exactly: the equations are not algebraic in x (x occurs both inside and outside trigonometric functions) and Maxima's solve could not solve them: [-x*sin(x) + cos(x)]
    """
    if isinstance(integrals, StationaryProblem):
        return _solved(integrals, chart, regular, budget)
    if isinstance(equations_of_motion(integrals), SecondOrderEquations):
        if (variables, equations, multipliers, levels) != (None,) * 4:
            raise AnalysisError("variables, equations, multipliers and levels are for "
                                "integrals; the stationary motions of a Routh function or "
                                "Lagrangian take solve_for= and positive= only",
                                entry="stationary_solutions")
        return _solved(_motions_problem(integrals, solve_for, positive), chart, regular, budget)
    if variables is None:
        raise AnalysisError("the phase variables are needed with integrals: "
                            "stationary_solutions(integrals, variables)",
                            entry="stationary_solutions")
    integrals = expression_list(integrals, "integrals", AnalysisError,
                                expected="a list of integrals (symbolic expressions)")
    variables = expression_list(variables, "variables", AnalysisError, names=True)
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
    multipliers = [SR.var(l) if isinstance(l, str) else SR(l) for l in multipliers]
    if len(multipliers) != len(integrals) - 1:
        raise AnalysisError(f"{len(multipliers)} multipliers for {len(integrals) - 1} "
                            "integrals after the first", entry="stationary_solutions")
    if levels is not None and len(levels) != len(integrals) - 1:
        raise AnalysisError(f"levels has {len(levels)} entries; it needs one per integral "
                            f"after the first ({len(integrals) - 1})",
                            entry="stationary_solutions")
    K = integrals[0] + sum(l * V for l, V in zip(multipliers, integrals[1:]))
    system = [K.diff(x).expand() for x in variables]
    for V, c in zip(integrals[1:], levels or []):
        if c is not None:
            system.append((V - SR(c)).expand())
    positive = symbol_arguments(positive, 'positive', error=AnalysisError)
    unknowns = variables + multipliers if solve_for is None else \
        _unknowns(solve_for, variables + multipliers, system, "stationary_solutions")
    rhs = [SR(X) for X in equations] if equations is not None else None

    def linear(at):
        J = matrix(SR, [[at(X.diff(x)) for x in variables] for X in rhs])
        return LinearSystem(variables, J=J)

    return _solved(StationaryProblem(
        K, variables, unknowns, multipliers, system, integrals=integrals,
        linear=None if rhs is None else linear, rhs=rhs, positive=positive), chart, regular,
        budget)


def stationary_motions(routh_or_lagrangian, solve_for=None, positive=(), chart=None,
                       regular=None):
    r"""
    Stationary motions of a system with cyclic coordinates: the positional
    velocities vanish and `\partial R/\partial q = 0` for the Routh
    function `R` (cyclic momenta constant); for a Lagrangian, its
    equilibria.

    INPUT:

    - ``routh_or_lagrangian`` -- a :class:`~sage_dynsym.dynamics.lagrangian.RouthFunction`
      or a :class:`~sage_dynsym.dynamics.lagrangian.Lagrangian`
    - ``solve_for`` -- (optional) the unknowns, e.g. the cyclic momenta
      (then the coordinates are parameters: a family of motions
      parametrised by them); default: the positional coordinates
    - ``positive`` -- parameters declared positive
    - ``chart``, ``regular`` -- (optional) a chart of the configuration
      space whose coordinates are the positional coordinates (e.g.
      :func:`~sage_dynsym.mechanics.charts.euler_angles`), and the
      stationary motions of the same model in a chart regular on its
      singular set: the solutions are then listed as points of the
      configuration space (:meth:`StationarySolutions.in_chart`)

    OUTPUT: a :class:`StationarySolutions` (the same kind of object as
    :func:`stationary_solutions`); its ``equations()`` are the equations of
    motion at rest. The stability of each solution follows from the amended
    potential `W = -R|_{\dot q = 0}` (Routh's theorem: stable where `W` has
    a nondegenerate minimum and the kinetic matrix is positive definite)
    and from the first approximation.

    EXAMPLES: the conical motions of the spherical pendulum (Example 1 of
    :doc:`the method </method>`): the momentum is
    `p^2 = -g l^3 m^2\sin^4\theta/\cos\theta`, real only where
    `\cos\theta < 0` (the bob below the suspension point;
    Goldstein, *Classical Mechanics*, §3.11)::

        sage: from sage_dynsym import load
        sage: from sage_dynsym.analysis.stationary import stationary_motions
        sage: L = load('examples/spherical_pendulum.yaml').lagrangian()
        sage: psi, theta = L.coordinates()
        sage: R = L.routh([psi]); p = R.momenta()[0]
        sage: sols = stationary_motions(R, solve_for=[p], positive=var('m l g'))
        sage: sols.equations()
        [-(g*l^3*m^2*sin(theta)^4 + p_psi^2*cos(theta))/(l^2*m*sin(theta)^3)]
        sage: [(s.point(), s.conditions()) for s in sols]
        [({p_psi: l*m*sqrt(-g*l/cos(theta))*sin(theta)^2},
          [cos(theta) < 0, sin(theta) != 0]),
         ({p_psi: -l*m*sqrt(-g*l/cos(theta))*sin(theta)^2},
          [cos(theta) < 0, sin(theta) != 0])]
        sage: sols[0].stability(positive=var('m l g')).verdict()
        'stable'

    TESTS::

        sage: stationary_motions(R, solve_for=[var('zz')])
        Traceback (most recent call last):
        ...
        AnalysisError: solve_for: zz is not an unknown of the model; the unknowns are theta, g, l, m, p_psi
        sage: stationary_motions(R, positive=['not a name'])
        Traceback (most recent call last):
        ...
        AnalysisError: positive: expected symbols or their names, got 'not a name'
    """
    if not isinstance(equations_of_motion(routh_or_lagrangian), SecondOrderEquations):
        raise AnalysisError(f"expected a Lagrangian or Routh function, got "
                            f"{type(routh_or_lagrangian).__name__}", entry="stationary_motions")
    return stationary_solutions(routh_or_lagrangian, solve_for=solve_for, positive=positive,
                                chart=chart, regular=regular)


def _motions_problem(system, solve_for, positive):
    # the StationaryProblem of the stationary motions of a Routh function
    # or Lagrangian (see stationary_motions)
    data = equations_of_motion(system)
    if not isinstance(data, SecondOrderEquations):
        raise AnalysisError(f"expected a Lagrangian or Routh function, got "
                            f"{type(system).__name__}", entry="stationary_motions")
    q = data.coordinates()
    rest = {v: 0 for v in data.velocities() + data.accelerations()}
    E = data.equations()
    at_rest = [normalize(e.subs(rest)) for e in E]
    positive = symbol_arguments(positive, 'positive', error=AnalysisError)
    unknowns = list(q) if solve_for is None else \
        _unknowns(solve_for, list(q), at_rest, "stationary_motions")
    function = data.function() if data.function() is not None else SR(system.expr())
    W = -function.subs({v: 0 for v in data.velocities()})
    kinetic = data.kinetic_matrix()
    if kinetic is None and hasattr(system, 'mass_matrix'):
        kinetic = matrix(SR, system.mass_matrix())

    def linear(at):
        def mat(xs):
            return matrix(SR, [[at(e.diff(x).subs(rest)) for x in xs] for e in E])
        return LinearSystem(q, M=mat(data.accelerations()), S=mat(data.velocities()),
                            W=mat(q))

    what = "equations at rest of " + ("the Routh function" if hasattr(system, 'momenta')
                                      else "the Lagrangian")
    shown = [normalize(e, angles=q, factor=True) for e in at_rest]
    return StationaryProblem(
        W, q, unknowns, [], at_rest, kinetic=kinetic, signs=('positive',), linear=linear,
        positive=positive, description=what, shown=shown)


def _unknowns(solve_for, first, equations, entry):
    r"""
    The unknowns ``solve_for`` of a problem whose own unknowns are
    ``first`` and whose ``equations`` are given: each must be one of
    ``first`` or a symbol of the equations (a parameter solved for), and
    every equation must involve one of them -- an equation free of the
    unknowns is a condition on what is held fixed, and "no solution for
    generic values" would then be a false answer.

    EXAMPLES::

        sage: from sage_dynsym.analysis.stationary import _unknowns
        sage: x, y, a = var('x y a')
        sage: _unknowns([a, 'x'], [x, y], [x - a, y], 'stationary_motions')
        Traceback (most recent call last):
        ...
        AnalysisError: solve_for: the equation y == 0 does not involve the unknowns a, x: it is a condition on the symbols held fixed; solve for y as well
        sage: _unknowns([var('zz')], [x, y], [x - a, y], 'stationary_motions')
        Traceback (most recent call last):
        ...
        AnalysisError: solve_for: zz is not an unknown of the model; the unknowns are x, y, a
    """
    valid = list(first)
    for e in equations:
        for v in sorted(SR(e).variables(), key=str):
            if all(str(v) != str(u) for u in valid) and str(v) != 't':
                valid.append(v)
    unknowns = known_symbols(solve_for, valid, 'solve_for', error=AnalysisError,
                             what="unknown")
    if len({str(u) for u in unknowns}) < len(unknowns):
        raise AnalysisError(f"an unknown is given twice: {unknowns}", entry='solve_for')
    for e in equations:
        e = SR(e)
        if not e.is_zero() and not any(e.has(u) for u in unknowns):
            raise AnalysisError(f"the equation {e} == 0 does not involve the unknowns "
                                f"{', '.join(map(str, unknowns))}: it is a condition on the "
                                "symbols held fixed; solve for "
                                f"{', '.join(map(str, sorted(e.variables(), key=str)))} as well",
                                entry='solve_for')
    return unknowns

