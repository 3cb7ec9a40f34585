r"""
The exact solving core: complete real solution sets of polynomial systems

Every polynomial system met in the analysis -- stationarity equations,
equilibria, stationary motions -- is solved here, exactly:

1. the equations are translated into polynomials (:mod:`.translation`):
   `\cos q, \sin q` become `c_q, s_q` with `c_q^2 + s_q^2 = 1`, the
   parameters form the coefficient field `\QQ(\text{parameters})` (the
   *generic* case), denominators containing unknowns are recorded;
2. the ideal is saturated by those denominators (and by expressions the
   caller requires to be nonzero) and decomposed into its minimal
   associated primes (Singular, ``minAssGTZ``) -- the irreducible
   components of the solution set; the saturation removes the components
   where one vanishes, and each solution carries the conditions that none
   vanishes at its points (a point where one vanishes identically is
   dropped);
3. each component gets its dimension (the number of unknowns it leaves
   free, multipliers not counted when the caller says so), and its points
   are written explicitly where possible:

   - a zero-dimensional component is solved along a triangular set
     (Singular, ``triangL``); steps of degree 1 give rational values, steps
     of degree 2 give the two conjugate branches `\pm\sqrt{D}`, which are
     reported as *separate* solutions, each with the condition `D > 0`
     under which it is real; an angle is written ``arccos(c)``,
     ``-arccos(c)`` or ``arctan2(s, c)``. Without parameters the real
     points are computed exactly in the real algebraic numbers;
   - a component of positive dimension is parametrised by a maximal set of
     its own unknowns that it leaves free; the other unknowns are written
     as rational functions of them where a Gröbner basis (block order)
     contains a linear equation for them, and the remaining relations are
     returned as equations;
   - a component that cannot be written explicitly (a step of degree 3 or
     more) is returned *implicitly*: its equations, and says so;
   - a family with parameters whose relations remain is written by other
     free unknowns where some choice makes it explicit (a rational
     parametrization, or branches by radicals); otherwise the conditions
     of its reality on the parameters and its free unknowns are decided
     by quantifier elimination (QEPCAD, within a budget), and where that
     does not decide, it says so
     (:meth:`~AlgebraicSolution.is_reality_decided`) -- never an
     exception;

4. only real components are kept: branches whose radicand can never be
   positive, and components over `\QQ` with no real point, are dropped.

An unsolved equation is never presented as a solution: every solution is
either explicit (values), or implicit with its defining equations.

EXAMPLES:

A bead on a hoop of radius `R` turning at the rate `w` about its vertical
diameter: besides the bottom and the top, the equilibria
`\cos\theta = g/(R w^2)` exist only when `R w^2 > g` (Goldstein, *Classical
Mechanics*, 3rd ed., §2.6, exercise; Arnold, *Mathematical Methods*, §25)::

    sage: from sage_dynsym.algebra.solving import solve_exactly
    sage: theta, R, w, g = var('theta R w g')
    sage: sols = solve_exactly([R*w^2*sin(theta)*cos(theta) - g*sin(theta)], [theta],
    ....:                      positive=[R, w, g])
    sage: for s in sols: print(s.values(), s.conditions())
    {theta: 0} []
    {theta: pi} []
    {theta: arccos(g/(R*w^2))} [R*w^2 - g > 0]
    {theta: -arccos(g/(R*w^2))} [R*w^2 - g > 0]

A curve of solutions (dimension 1), parametrised by its first unknown::

    sage: x, y = var('x y')
    sage: sols = solve_exactly([(x^2 + y^2 - 1)*x, (x^2 + y^2 - 1)*y], [x, y])
    sage: [(s.dimension(), s.values(), s.equations()) for s in sols]
    [(0, {x: 0, y: 0}, []), (1, {x: x, y: y}, [x^2 + y^2 - 1])]

An inconsistent system has no solutions::

    sage: sols = solve_exactly([x - 1, x - 2], [x]); len(sols), sols.is_empty()
    (0, True)

TESTS::

    sage: len(solve_exactly([x^2 + 1], [x]))
    0
    sage: [s.values() for s in solve_exactly([x^2 - 2], [x])]
    [{x: -sqrt(2)}, {x: sqrt(2)}]
"""
import operator
from itertools import combinations

from sage.functions.trig import arccos, arcsin, arctan2
from sage.matrix.constructor import matrix
from sage.libs.singular.function import singular_function
from sage.misc.verbose import verbose
from sage.rings.polynomial.polynomial_ring_constructor import PolynomialRing
from sage.rings.polynomial.term_order import TermOrder
from sage.rings.integer_ring import ZZ
from sage.rings.qqbar import AA
from sage.rings.rational_field import QQ
from sage.structure.sage_object import SageObject
from sage.symbolic.constants import pi
from sage.symbolic.ring import SR

from ..arguments import expression_list
from ..errors import AnalysisError
from .conditions import (positive_conditions, nonzero_conditions, conjunction,
                         simplify_conjunction)
from .decomposition import (minimal_primes, membership_by_specialization, is_unit_ideal,
                            distinct_random_values,
                            shape, ShapePrime, triangular_sets, linear_substitutions)
from .regions import prune_empty
from .expression_walk import ExpressionWalker
from .forked import within_processor_time
from .term_orders import block_order, fastest_order
from .translation import Translation, NotAlgebraic, translate_expressions

__all__ = ['MAX_EXPLICIT_DEGREE', 'CHOSEN_ORDER_SECONDS', 'BRANCH_SOLVE_SECONDS', 'REALITY_QE_VARIABLES', 'REALITY_QE_TIMEOUT', 'normalize',
           'vanishes', 'SolutionList', 'SolutionSet', 'SolutionSet_transcendental',
           'AlgebraicSolution', 'solve_exactly', 'REAL_POINT_SAMPLES', 'TranscendentalSolution',
           'PARAMETRIZATION_TRIES', 'PARAMETRIZATION_SECONDS', 'PARAMETRIZATION_VARIABLES',
           'FAMILY_QE_VARIABLES', 'MAX_DECIDED_TERMS', 'IMPLICIT_NONZERO_POWERS',
           'solve_transcendental']


#: Zero-dimensional components with parameters of a larger degree are not
#: solved by radicals (they are returned implicitly).
MAX_EXPLICIT_DEGREE = 16

#: Seconds of processor time for the branches of an implicit family in
#: several bound unknowns (:func:`_branches`); over them it stays implicit.
BRANCH_SOLVE_SECONDS = 30

#: Seconds of processor time for a system solved in the term order chosen
#: by trying, then as many in ``degrevlex``, before it is solved in the
#: chosen order without a limit (:func:`_in_chosen_order`).
CHOSEN_ORDER_SECONDS = 60

#: Powers `f^k` of a polynomial required nonzero tried on an implicit
#: solution, for one that is a function of its free unknowns and parameters
#: (then `f \ne 0` is a condition on those).
IMPLICIT_NONZERO_POWERS = (2, 3, 4)

#: Implicit components are tested for real points by quantifier elimination
#: only up to this many variables (parameters and unknowns together) ...
REALITY_QE_VARIABLES = 5

#: ... and for at most this many seconds of processor time (of QEPCAD).
REALITY_QE_TIMEOUT = 10


def normalize(expr, angles=(), factor=False):
    r"""
    A canonical form of a rational expression (rational-function
    normalization in Singular; non-polynomial parts are atoms): no Maxima,
    no assumption questions.

    INPUT:

    - ``expr`` -- a symbolic expression
    - ``angles`` -- (optional) symbols whose trigonometric functions are
      expanded (multiple angles, sums) and reduced modulo
      `\cos^2 + \sin^2 = 1`
    - ``factor`` -- (default: ``False``) return numerator and denominator
      factored

    EXAMPLES::

        sage: from sage_dynsym.algebra.solving import normalize
        sage: a, b, q, r = var('a b q r')
        sage: normalize((a^2 - b^2)/(a + b) + sqrt(a)^3/sqrt(a))
        2*a - b
        sage: e = a*(cos(r - q)*sin(q) + cos(q)*sin(r - q)) + b*a*sin(r)
        sage: normalize(e, angles=[q, r], factor=True)
        a*(b + 1)*sin(r)
    """
    expr = SR(expr)
    if not expr.variables() and expr.is_numeric():
        return expr
    try:
        if angles:
            return _shortest_trigonometric(expr, angles, factor)
        T = Translation([], [], extra=[expr])
        f = T.fraction(expr)
        if not factor or T.flat_ring() is None:
            return T.symbolic(f)
        flat = T.flat_ring()
        return T.factored(flat(f.numerator())) / T.factored(flat(f.denominator()))
    except AnalysisError:
        return expr


def vanishes(expr, maxima=True):
    r"""
    Whether ``expr`` is identically zero: its canonical form
    (:func:`normalize`) is zero, or Maxima's full simplification is (for
    what the rational normal form treats as atoms, e.g. `\sqrt{a}^2 - a`).

    INPUT:

    - ``expr`` -- a symbolic expression
    - ``maxima`` -- (default: ``True``) whether to ask Maxima when the
      canonical form is not zero; ``False`` is the fast test: Sage's own
      zero test and the canonical form only

    OUTPUT: ``True`` if ``expr`` is shown to be zero, ``False`` otherwise
    (also when the simplification cannot decide, or cannot be computed, as
    for a square root of a negative decimal)

    EXAMPLES::

        sage: from sage_dynsym.algebra.solving import vanishes
        sage: a, b = var('a b')
        sage: vanishes((a^2 - b^2)/(a + b) - a + b), vanishes(a - b)
        (True, False)
        sage: vanishes(sin(a)^2 + cos(a)^2 - 1)
        True
        sage: vanishes(log(exp(a)) - a), vanishes(log(exp(a)) - a, maxima=False)
        (True, False)

    TESTS::

        sage: vanishes(sqrt(-1.5)*a, maxima=False), vanishes(sqrt(-1.5)*a - sqrt(-1.5)*a)
        (False, True)
    """
    expr = SR(expr)
    try:
        if expr.is_zero() or normalize(expr).is_zero():
            return True
        return maxima and bool(expr.simplify_full().is_zero())
    except (TypeError, ValueError, ArithmeticError, RuntimeError):
        # the normal form, or Maxima, gives up: not shown to be zero
        return False


def _shortest_trigonometric(expr, angles, factor):
    r"""``expr`` reduced modulo `\cos^2 + \sin^2 = 1` of the ``angles``:
    the shortest of the forms without reduction, with the powers of sines
    reduced, and with the powers of cosines reduced."""
    T = Translation([], [SR(a) for a in angles], extra=[expr])
    f = T.fraction(expr)
    P = T.ring()
    num, den = T.to_ring(f.numerator()), T.to_ring(f.denominator())
    FF = f.parent()
    candidates = [f]
    relations = T.circle_relations()
    if relations:
        names = [str(g) for g in P.gens()]
        for order in (names, names[::-1]):
            Q = PolynomialRing(P.base_ring(), order, len(order), order='degrevlex')
            ideal = Q.ideal([Q(r) for r in relations])
            n, d = ideal.reduce(Q(num)), ideal.reduce(Q(den))
            (n1, n2), (d1, d2) = T.to_flat(P(n)), T.to_flat(P(d))
            candidates.append(FF(n1 * d2) / FF(n2 * d1))
    forms = []
    for c in candidates:
        if factor and T.flat_ring() is not None:
            flat = T.flat_ring()
            forms.append(T.factored(flat(c.numerator())) / T.factored(flat(c.denominator())))
        else:
            forms.append(T.symbolic(c))
    return min(forms, key=lambda e: len(str(e)))


class SolutionList(SageObject):
    r"""
    A list of solutions (iterable, indexable): the common behaviour of
    :class:`SolutionSet` and of the stationary sets of
    :mod:`~sage_dynsym.analysis.stationary`.

    EXAMPLES::

        sage: from sage_dynsym.algebra.solving import solve_exactly, SolutionList
        sage: x = var('x')
        sage: S = solve_exactly([x^2 - 1], [x]); isinstance(S, SolutionList), len(S)
        (True, 2)
    """

    def __init__(self, solutions):
        self._solutions = list(solutions)

    def __iter__(self):
        return iter(self._solutions)

    def __len__(self):
        return len(self._solutions)

    def __getitem__(self, i):
        return self._solutions[i]


class SolutionSet(SolutionList):
    r"""
    The real solutions of a polynomial system: a list of
    :class:`AlgebraicSolution` (iterable), created by :func:`solve_exactly`.

    EXAMPLES::

        sage: from sage_dynsym.algebra.solving import solve_exactly
        sage: x, y = var('x y')
        sage: S = solve_exactly([x*y], [x, y]); S
        2 solution components of 1 equation in x, y
        sage: S[0].values(), S[1].values()
        ({x: x, y: 0}, {x: 0, y: y})
    """

    def __init__(self, translation, solutions, n_equations):
        SolutionList.__init__(self, solutions)
        self._translation = translation
        self._n = n_equations

    def _repr_(self):
        what = ', '.join(map(str, self._translation.unknowns()))
        eq = f"{self._n} equation{'s' if self._n != 1 else ''}"
        if not self._solutions:
            return f"No real solutions of {eq} in {what}"
        return f"{len(self._solutions)} solution components of {eq} in {what}"

    def is_complete(self):
        r"""Whether the list is complete: ``True`` for exact decompositions.

        EXAMPLES::

            sage: from sage_dynsym.algebra.solving import solve_exactly
            sage: x = var('x')
            sage: solve_exactly([x^2 - 1], [x]).is_complete()
            True
        """
        return True

    def is_empty(self):
        r"""Whether there is no real solution (for generic parameters).

        EXAMPLES::

            sage: from sage_dynsym.algebra.solving import solve_exactly
            sage: x = var('x')
            sage: solve_exactly([x^2 + 1], [x]).is_empty()
            True
        """
        return not self._solutions

    def translation(self):
        r"""The :class:`~sage_dynsym.algebra.translation.Translation` used.

        EXAMPLES::

            sage: from sage_dynsym.algebra.solving import solve_exactly
            sage: x, a = var('x a')
            sage: solve_exactly([x - a], [x]).translation().parameters()
            [a]
        """
        return self._translation


class SolutionSet_transcendental(SolutionSet):
    r"""
    Solutions found by the transcendental fallback (:func:`solve_transcendental`):
    verified, isolated and explicit, but possibly not all of them.

    EXAMPLES::

        sage: from sage_dynsym.algebra.solving import solve_transcendental
        sage: x = var('x')
        sage: S = solve_transcendental([exp(x) - 2], [x]); S
        1 solution of 1 transcendental equation in x, found by Maxima's solve (the list may be incomplete)
        sage: S.is_complete()
        False
    """

    def __init__(self, unknowns, solutions, n_equations):
        self._unknowns = unknowns
        SolutionSet.__init__(self, None, solutions, n_equations)

    def _repr_(self):
        what = ', '.join(map(str, self._unknowns))
        n = len(self._solutions)
        eq = f"{self._n} transcendental equation{'s' if self._n != 1 else ''}"
        return (f"{n} solution{'s' if n != 1 else ''} of {eq} in {what}, found by "
                "Maxima's solve (the list may be incomplete)")

    def is_complete(self):
        r"""Always ``False``: Maxima's ``solve`` may miss solutions.

        EXAMPLES::

            sage: from sage_dynsym.algebra.solving import solve_transcendental
            sage: x = var('x')
            sage: solve_transcendental([exp(x) - 2], [x]).is_complete()
            False
        """
        return False


class AlgebraicSolution(SageObject):
    r"""
    One real solution (a branch of an irreducible component) of a
    polynomial system; created by :func:`solve_exactly`.

    EXAMPLES::

        sage: from sage_dynsym.algebra.solving import solve_exactly
        sage: x, a = var('x a')
        sage: s = solve_exactly([x^2 - a], [x])[0]; s
        Solution {x: sqrt(a)} (dimension 0, if a > 0)
        sage: s.is_explicit(), s.dimension(), s.conditions()
        (True, 0, [a > 0])
    """

    def __init__(self, translation, prime, free, counted, values, ring_values,
                 relations, conditions, real_points=None, reality_known=True):
        self._T = translation
        self._prime = prime
        self._free = free                  # unknown indices left free
        self._counted = counted            # indices counted in the dimension
        self._values = values              # unknown index -> SR value (explicit)
        self._ring_values = ring_values    # ring variable name -> SR value
        self._relations = relations        # ring polynomials (implicit part)
        self._conditions = conditions
        self._real_points = real_points
        self._reality_known = reality_known
        self._membership = None            # contains() at random values, made once
        self._terms = None                 # the size of the relations, counted once

    def _repr_(self):
        kind = "" if self.is_explicit() else ", implicit: given by its equations"
        cond = f", if {' and '.join(map(str, self._conditions))}" if self._conditions else ""
        if not self._reality_known:
            cond += ", where it is real not decided"
        return f"Solution {self.values()} (dimension {self.dimension()}{kind}{cond})"

    def values(self):
        r"""
        Dict ``{unknown: value}`` over all unknowns: the value where the
        solution fixes it (possibly in terms of the free unknowns), the
        unknown itself where it does not.

        EXAMPLES::

            sage: from sage_dynsym.algebra.solving import solve_exactly
            sage: x, y = var('x y')
            sage: solve_exactly([y - x^2], [x, y])[0].values()
            {x: x, y: x^2}
        """
        unknowns = self._T.unknowns()
        return {u: self._values.get(i, u) for i, u in enumerate(unknowns)}

    def free_unknowns(self):
        r"""The unknowns the solution leaves free (its parameters).

        EXAMPLES::

            sage: from sage_dynsym.algebra.solving import solve_exactly
            sage: x, y = var('x y')
            sage: solve_exactly([y - x^2], [x, y])[0].free_unknowns()
            [x]
        """
        unknowns = self._T.unknowns()
        return [unknowns[i] for i in self._free]

    def dimension(self):
        r"""The number of free unknowns among the counted ones.

        EXAMPLES::

            sage: from sage_dynsym.algebra.solving import solve_exactly
            sage: x, y, l = var('x y l')
            sage: S = solve_exactly([x*l, y], [x, y, l], counted=[x, y])
            sage: [(s.values(), s.dimension()) for s in S]
            [({x: 0, y: 0, l: l}, 0), ({x: x, y: 0, l: 0}, 1)]
        """
        return sum(1 for i in self._free if i in self._counted)

    def equations(self):
        r"""
        The relations (expressions ``== 0``) that remain between the
        unknowns not given explicitly; empty for an explicit solution.

        EXAMPLES::

            sage: from sage_dynsym.algebra.solving import solve_exactly
            sage: x = var('x')
            sage: s = solve_exactly([x^5 - x - 1], [x])[0]
            sage: s.is_explicit(), s.equations()
            (False, [x^5 - x - 1])
        """
        subs = {k: v for k, v in self._ring_values.items()}
        # a relation in none of the unknowns given explicitly is already in
        # the normal form (normalizing it again parses it again: over a
        # minute for a family of a generic Kirchhoff Hamiltonian)
        relations = [r if r.parent() is SR else
                     self._T.symbolic(r) if all(str(v) not in subs for v in r.variables())
                     else normalize(self._T.symbolic(r, subs)) for r in self._relations]
        # a relation that the explicit values satisfy identically says nothing
        return [r for r in relations if not r.is_zero()]

    def is_explicit(self):
        r"""Whether every unknown is given explicitly (or is free).

        EXAMPLES::

            sage: from sage_dynsym.algebra.solving import solve_exactly
            sage: x = var('x')
            sage: solve_exactly([x - 1], [x])[0].is_explicit()
            True
        """
        return not self._relations

    def conditions(self):
        r"""
        Conditions on the parameters (and the free unknowns) for this
        solution to exist and be real, a list of relationals; ``[]`` when it
        exists for all admissible values. They include that the equations'
        denominators and the expressions required nonzero do not vanish
        (see :func:`solve_exactly`).

        For an implicit solution whose reality could not be decided (see
        :meth:`is_reality_decided`), the conditions found (e.g. nonzero
        denominators): it is real at most there, perhaps not everywhere
        there.

        EXAMPLES::

            sage: from sage_dynsym.algebra.solving import solve_exactly
            sage: x, a, b = var('x a b')
            sage: solve_exactly([a*x - b], [x])[0].conditions()
            [a != 0]

        An implicit family (a cubic in `y` over `x` and `z`) is real
        where the quantifier elimination says::

            sage: y, z = var('y z')
            sage: s = solve_exactly([y^3 - 3*y - x, z^2 - a], [x, y, z])[0]
            sage: s.is_explicit(), s.conditions()
            (True, [a > 0])

        Conditions on unknowns describe this parametrization of its
        component: the points of the component where they fail (a
        denominator or a radicand vanishes) are listed in other solutions,
        or in this one, its condition `D > 0` widened to `D \ge 0`, where
        its values are proved real, finite and on the component there.
        `x z = y` is `z = y/x` where `x \ne 0`; its points with `x = 0`
        are the line `x = y = 0`::

            sage: [(t.values(), t.conditions()) for t in solve_exactly([x*z - y], [x, y, z])]
            [({x: 0, y: 0, z: z}, []), ({x: x, y: y, z: y/x}, [x != 0])]
        """
        return list(self._conditions)

    def is_reality_decided(self):
        r"""
        Whether the conditions under which the solution is real are known
        (``False`` for an implicit solution with parameters whose reality
        neither a parametrization nor quantifier elimination within its
        budget decided: then :meth:`conditions` is the region where it may
        be real).

        EXAMPLES::

            sage: from sage_dynsym.algebra.solving import solve_exactly
            sage: x, y, a = var('x y a')
            sage: solve_exactly([y^4 + x^4 - a], [x, y])[0].is_reality_decided()
            True

        Without quantifier elimination its reality is not decided::

            sage: import sage_dynsym.algebra.solving as solving
            sage: solving.FAMILY_QE_VARIABLES = 0
            sage: s = solve_exactly([y^4 + x^4 - a], [x, y])[0]; s
            Solution {x: x, y: y} (dimension 1, implicit: given by its equations, where it is real not decided)
            sage: s.is_reality_decided(), s.conditions()
            (False, [])
            sage: solving.FAMILY_QE_VARIABLES = 7
        """
        return self._reality_known

    def known_conditions(self):
        r"""
        The conditions found for this solution to exist: those of
        :meth:`conditions` (kept under this name; also where whether an
        implicit solution is real could not be decided).

        EXAMPLES::

            sage: from sage_dynsym.algebra.solving import solve_exactly
            sage: x, a, b = var('x a b')
            sage: solve_exactly([a*x - b], [x])[0].known_conditions()
            [a != 0]
        """
        return list(self._conditions)

    def real_points(self):
        r"""
        For an implicit solution without parameters: its real points, exact
        (dicts of real algebraic numbers); ``None`` otherwise.

        EXAMPLES::

            sage: from sage_dynsym.algebra.solving import solve_exactly
            sage: x = var('x')
            sage: solve_exactly([x^5 - x - 1], [x])[0].real_points()
            [{x: 1.167303978261419?}]
        """
        return None if self._real_points is None else [dict(p) for p in self._real_points]

    def ideal(self):
        r"""The prime ideal of the component this solution belongs to.

        EXAMPLES::

            sage: from sage_dynsym.algebra.solving import solve_exactly
            sage: x = var('x')
            sage: solve_exactly([x^2 - 2], [x])[0].ideal()
            Ideal (x0^2 - 2) of Multivariate Polynomial Ring in x0 over Rational Field
        """
        return self._prime

    def translation(self):
        r"""The translation between the unknowns and the ring.

        EXAMPLES::

            sage: from sage_dynsym.algebra.solving import solve_exactly
            sage: x = var('x')
            sage: solve_exactly([x^2 - 2], [x])[0].translation().unknowns()
            [x]
        """
        return self._T

    def substitutions(self):
        r"""
        A dict to substitute into symbolic expressions in the unknowns:
        values of the explicit unknowns, and `\cos q`, `\sin q` of angles
        whose cosine and sine are known.

        EXAMPLES::

            sage: from sage_dynsym.algebra.solving import solve_exactly
            sage: q, a = var('q a')
            sage: s = solve_exactly([cos(q) - a], [q])[0]
            sage: s.substitutions()
            {sin(q): sqrt(-(a + 1)*(a - 1)), cos(q): a, q: arccos(a)}
        """
        subs = {}
        gens = self._T.symbolic_generators()
        for k, g in enumerate(gens):
            name = f"x{k}"
            if name in self._ring_values and not g.is_symbol():
                subs[g] = self._ring_values[name]
        for i, v in self._values.items():
            subs[self._T.unknowns()[i]] = v
        return subs

    def evaluate(self, expr):
        r"""
        The value of a symbolic expression at this solution: trigonometric
        functions of angles are expanded to `\cos q, \sin q` first, then the
        known values substituted and the result normalized: on an implicit
        family, in normal form modulo its relations, unless these have more
        than :data:`MAX_DECIDED_TERMS` terms.

        EXAMPLES::

            sage: from sage_dynsym.algebra.solving import solve_exactly
            sage: q, a = var('q a')
            sage: s = solve_exactly([cos(q) - a], [q])[0]
            sage: s.evaluate(sin(2*q) + cos(q)^2)
            a^2 + 2*sqrt(-(a + 1)*(a - 1))*a
        """
        from .translation import expand_angles
        angles = [u for u in self._T.unknowns() if self._T.is_angle(u)]
        e = expand_angles(SR(expr), angles)
        subs = self.substitutions()
        trig = {k: v for k, v in subs.items() if not k.is_symbol()}
        plain = {k: v for k, v in subs.items() if k.is_symbol() and not
                 (self._T.is_angle(k))}
        e = e.subs(trig).subs(plain)
        if self._relations and not isinstance(self._prime, ShapePrime) and \
                self._relation_terms() <= MAX_DECIDED_TERMS:
            reduced = self.reduce(e)
            if reduced is not None:
                return reduced
        return normalize(e)

    def _relation_terms(self):
        # the number of terms of the relations, each coefficient counted by
        # the terms of its numerator and denominator (read once)
        if self._terms is None:
            self._terms = sum(1 if c.parent() is QQ else
                              len(c.numerator().monomials()) + len(c.denominator().monomials())
                              for r in self._relations if r.parent() is not SR
                              for c in r.coefficients())
        return self._terms

    def reduce(self, expr):
        r"""
        ``expr`` (rational in the unknowns) in normal form modulo the
        component, or ``None`` if it cannot be translated or its denominator
        vanishes on the component.

        EXAMPLES: on the circle, `x^2 + y^2` is `1`::

            sage: from sage_dynsym.algebra.solving import solve_exactly
            sage: x, y = var('x y')
            sage: s = solve_exactly([x^2 + y^2 - 1], [x, y])[0]
            sage: s.reduce(x^2 + y^2 + x), s.reduce(1/(x^2 + y^2 - 1))
            (x + 1, None)
        """
        T = self._T
        try:
            f = T.fraction(expr)
        except AnalysisError:
            return None
        num, den = T.to_ring(f.numerator()), T.to_ring(f.denominator())
        num, den = self._prime.reduce(num), self._prime.reduce(den)
        if den == 0:
            return None
        return normalize(T.symbolic(num) / T.symbolic(den))

    def contains(self, expr):
        r"""
        Whether ``expr`` (rational in the unknowns, its symbols among those
        of the system) vanishes on the whole component: whether its
        numerator lies in the component's prime ideal.

        Over `\QQ` this is a normal form. With parameters it is decided at
        random rational values of them
        (:func:`~sage_dynsym.algebra.decomposition.membership_by_specialization`,
        with its probability-one argument): a normal form over the field of
        many parameters can take minutes (the family of a generic Kirchhoff
        Hamiltonian, 12 coefficients: over 20 s for one equation of
        motion), the specialized ones milliseconds.

        EXAMPLES::

            sage: from sage_dynsym.algebra.solving import solve_exactly
            sage: x, y, a = var('x y a')
            sage: s = solve_exactly([x^2 + y^2 - 1], [x, y])[0]
            sage: s.contains((x^2 + y^2 - 1)*x), s.contains(x)
            (True, False)
            sage: s = solve_exactly([x^2 - a*y^3], [x, y])[0]
            sage: s.contains((x^2 - a*y^3)*(x + a)/(y - a)), s.contains(x - a*y)
            (True, False)
        """
        num, _ = self._T.numerator(expr)
        if self._T.field() is QQ or isinstance(self._prime, ShapePrime):
            return self._prime.reduce(num) == 0
        if self._membership is None:
            self._membership = membership_by_specialization(self._prime)
        return self._membership(num)


def _log(message):
    verbose(message, level=1, caller_name="solve_exactly")


def solve_exactly(equations, unknowns, counted=None, nonzero=(), positive=(),
                  extra=(), transcendental=False):
    r"""
    The real solutions of a polynomial system, exactly: its irreducible
    components with their dimensions, explicit values where they can be
    written, and existence conditions (see the module documentation).

    INPUT:

    - ``equations`` -- symbolic expressions (each ``== 0``) or relationals;
      rational in the unknowns after `\cos q, \sin q` of angles are replaced
      by `c_q, s_q`
    - ``unknowns`` -- the unknowns (symbols, or applications such as
      ``f(q)``); every other symbol is a parameter
    - ``counted`` -- (default: all) the unknowns counted in the dimension
      (e.g. not the Lagrange multipliers)
    - ``nonzero`` -- expressions that must not vanish: components inside
      the zero set of one are removed, and every solution carries the
      conditions that its numerator's factors do not vanish at its values
      (exactly as for the denominators of the equations, where the
      equations are not defined)
    - ``positive`` -- parameters declared positive (used in the conditions)
    - ``extra`` -- expressions to be evaluated or tested later (their
      symbols are registered as parameters)
    - ``transcendental`` -- (default: ``False``) if the equations are not
      algebraic, try the documented fallback :func:`solve_transcendental`
      instead of raising :class:`~sage_dynsym.algebra.translation.NotAlgebraic`

    OUTPUT: a :class:`SolutionSet`

    Progress is reported through Sage's ``verbose`` (level 1); the
    computation can be interrupted.

    Raises :class:`~sage_dynsym.algebra.translation.NotAlgebraic` (an
    :class:`~sage_dynsym.errors.AnalysisError`) if the equations are not
    algebraic in the unknowns.

    EXAMPLES: see the module documentation. Two conjugate branches of one
    component are separate solutions::

        sage: from sage_dynsym.algebra.solving import solve_exactly
        sage: x, y, c = var('x y c')
        sage: for s in solve_exactly([x^2 + y^2 - c, x - y], [x, y], positive=[c]):
        ....:     print(s)
        Solution {x: sqrt(1/2)*sqrt(c), y: sqrt(1/2)*sqrt(c)} (dimension 0)
        Solution {x: -sqrt(1/2)*sqrt(c), y: -sqrt(1/2)*sqrt(c)} (dimension 0)

    A solution holds only where the equations are defined and the
    expressions ``nonzero`` do not vanish, at each of its points: `x = y`
    solves `(x - y)/y = 0` only for `y \ne 0`, and likewise `x - y = 0`
    with `y` required nonzero; the branches `y = \pm\sqrt{x - a}` of
    `y^2 = x - a` end at `x = a` (where `y = 0`) without `y` required
    nonzero, and before it with::

        sage: a = var('a')
        sage: [(s.values(), s.conditions()) for s in solve_exactly([(x - y)/y], [x, y])]
        [({x: x, y: x}, [x != 0])]
        sage: [(s.values(), s.conditions()) for s in solve_exactly([x - y], [x, y], nonzero=[y])]
        [({x: x, y: x}, [x != 0])]
        sage: [s.conditions() for s in solve_exactly([y^2 - x + a], [x, y])]
        [[a - x <= 0], [a - x <= 0]]
        sage: [s.conditions() for s in solve_exactly([y^2 - x + a], [x, y], nonzero=[y])]
        [[a - x < 0], [a - x < 0]]

    An implicit solution carries these conditions where they are on its
    parameters and free unknowns (where one is on the unknowns it binds, the
    saturation still removed the components on which it vanishes).

    A point where a required nonzero expression vanishes is no solution;
    a point where it vanishes for some values of the parameters exists
    only for the others::

        sage: [s.values() for s in solve_exactly([x*(x - 1)], [x], nonzero=[x])]
        [{x: 1}]
        sage: [(s.values(), s.conditions()) for s in solve_exactly([x - a], [x], nonzero=[x - 1])]
        [({x: a}, [a - 1 != 0])]
    """
    unknowns = expression_list(unknowns, "unknowns", AnalysisError, names=True)
    equations = expression_list(equations, "equations", AnalysisError,
                                expected="a list of equations (symbolic expressions)")
    nonzero = expression_list(nonzero, "nonzero", AnalysisError)
    _log(f"translating {len(equations)} equations in {len(unknowns)} unknowns")
    try:
        T = Translation(equations, unknowns, extra=list(nonzero) + [SR(e) for e in extra])
    except NotAlgebraic as err:
        if not transcendental:
            raise
        return solve_transcendental(equations, unknowns, reason=err, positive=positive)
    counted_set = set(range(len(unknowns))) if counted is None else \
        {[str(u) for u in unknowns].index(str(SR(c))) for c in counted}
    if T.ring() is None:
        raise AnalysisError("no unknowns to solve for", entry="solve_exactly")
    chosen = _choose_order(T, counted_set)

    def solve():
        return _solve_translated(T, len(equations), nonzero, counted_set, positive)
    if chosen is None:
        return solve()
    return _in_chosen_order(T, chosen, solve)


def _solve_translated(T, n_eq, nonzero, counted_set, positive):
    r"""The :class:`SolutionSet` of the translated system ``T`` (of
    ``n_eq`` equations) in the term order of its ring: the work of
    :func:`solve_exactly` once the order is chosen."""
    P = T.ring()
    gens = T.equations()
    I = P.ideal(gens) if gens else P.ideal([P(0)])
    # the polynomials that must not vanish at a solution: the denominators
    # of the equations, the numerators of the expressions required nonzero
    required = list(T.denominators())
    for e in nonzero:
        num, dens = T.numerator(e)
        if num == 0:
            raise AnalysisError(f"{e} is required nonzero but is zero", entry="nonzero")
        required.append(num)
    for f in required:
        if f.degree() > 0:
            I = I.saturation(f)[0]
    if is_unit_ideal(I):
        _log("the equations are inconsistent")
        return SolutionSet(T, [], n_eq)
    _log("decomposing into irreducible components")
    primes = minimal_primes(I, shapes=True, split_points=T.field() is QQ)
    _log(f"{len(primes)} components")
    found = [s for prime, sh in primes for s in _solve_component(T, prime, sh, counted_set,
                                                                 positive)]
    found += _excluded_parts(T, [prime for prime, _ in primes], found, counted_set, positive,
                             required)
    solutions, seen = [], set()
    for s in found:
        key = str(s.values()) if s.is_explicit() and not s._free else None
        if key is None or key not in seen:     # parts of facstd may overlap
            seen.add(key)
            solutions.append(s)
    solutions = _pointwise(T, solutions, required, positive)
    solutions = _without_noise(T, solutions, positive, required)
    solutions.sort(key=_sort_key)
    return SolutionSet(T, solutions, n_eq)


def _choose_order(T, counted):
    r"""
    Solve in the term order where the system's Gröbner basis is found
    first (:func:`~sage_dynsym.algebra.term_orders.fastest_order`): the
    translation's ``degrevlex``, or the block order with the counted
    unknowns before the others (the multipliers), each block in the order
    the unknowns were given. Only systems with parameters and multipliers
    are tried: over `\QQ`, or without multipliers, the bases met are fast
    in ``degrevlex``.

    OUTPUT: the block order if it was taken (``T`` now uses it), else
    ``None``

    EXAMPLES: the Lagrange system of a generic Kirchhoff Hamiltonian with
    12 symbolic coefficients is solved in the block order (its basis takes
    a fraction of a second there, over 7 seconds in ``degrevlex``)::

        sage: from sage_dynsym.algebra.solving import _choose_order
        sage: from sage_dynsym.algebra.translation import Translation
        sage: M, p, l = list(var('M1 M2 M3')), list(var('p1 p2 p3')), list(var('l1 l2'))
        sage: a, c = list(var('a1 a2 a3')), list(var('c1 c2 c3'))
        sage: B = matrix(3, 3, lambda i, j: var(f"b{min(i, j) + 1}{max(i, j) + 1}"))
        sage: Bp, BM = B * vector(p), B * vector(M)
        sage: eqs = [a[i]*M[i] + Bp[i] + l[1]*p[i] for i in range(3)]
        sage: eqs += [BM[i] + l[1]*M[i] + c[i]*p[i] + 2*l[0]*p[i] for i in range(3)]
        sage: T = Translation(eqs, M + p + l)
        sage: _choose_order(T, set(range(6))) == T.ring().term_order()
        True
        sage: T.ring().term_order().name()
        'matrix'
    """
    n = len(T.unknowns())
    others = [i for i in range(n) if i not in counted]
    if T.field() is QQ or not others or len(others) == n or not T.equations():
        return
    P = T.ring()

    def positions(unknowns):
        return [P.gens().index(g) for i in unknowns for g in _unit_generators(T, i)]

    candidate = block_order([positions(sorted(counted)), positions(others)], P.ngens())
    if fastest_order(P.ideal(T.equations()), [None, candidate]) is not candidate:
        return None
    _log("the block order of the unknowns and the multipliers")
    T.use_order(candidate)
    return candidate


def _in_chosen_order(T, chosen, solve):
    r"""
    ``solve()`` in the term order ``chosen`` by trying, within
    :data:`CHOSEN_ORDER_SECONDS` of processor time; over it, within as
    much again in ``degrevlex``; then, without a limit, in ``chosen``.

    The order is chosen by the time of one Gröbner basis, and the later
    steps (decompositions, triangular sets of the components, nested
    solves of their branches) can be far slower there than in
    ``degrevlex``: Brun's problem on `(M, \gamma) = 0` solved in the block
    order runs for over a quarter of an hour in the characteristic sets
    of a part the factorizing basis gives there, and in 3 s in
    ``degrevlex``. Each try runs in a forked process (a Singular call
    cannot be stopped safely in this one), and its solutions come back
    pickled. The waste is bounded: at most twice
    :data:`CHOSEN_ORDER_SECONDS` before the last, unlimited, try.

    EXAMPLES: a computation over its budget in the order chosen is done
    in ``degrevlex``::

        sage: import sage_dynsym.algebra.solving as solving
        sage: from sage_dynsym.algebra.translation import Translation
        sage: from sage_dynsym.algebra.term_orders import block_order
        sage: x, y, l, a = var('x y l a')
        sage: T = Translation([x - a*l, y - l], [x, y, l])
        sage: chosen = block_order([[0, 1], [2]], 3)
        sage: T.use_order(chosen)
        sage: def solve():
        ....:     if T.ring().term_order() == chosen:
        ....:         while True: pass        # as if far slower in this order
        ....:     return T.ring().term_order().name()
        sage: solving.CHOSEN_ORDER_SECONDS = 1
        sage: solving._in_chosen_order(T, chosen, solve)
        'degrevlex'
        sage: solving.CHOSEN_ORDER_SECONDS = 60
    """
    for order in (chosen, TermOrder('degrevlex', T.ring().ngens())):
        T.use_order(order)
        done, value = within_processor_time(solve, CHOSEN_ORDER_SECONDS)
        if done:
            return value
        _log(f"not solved within {CHOSEN_ORDER_SECONDS} s of processor time in the term "
             f"order {order.name()} ({value})")
    T.use_order(chosen)
    return solve()


def _order_chosen(P):
    # whether the ring's order is one _choose_order took instead of the
    # translation's degrevlex (the steps that are slow there go other ways)
    return P.term_order() != TermOrder('degrevlex', P.ngens())


def _without_noise(T, solutions, positive, required):
    r"""
    The solutions without those that are no solutions: the branches whose
    conditions no real values satisfy, and the points that a branch
    contains.

    A branch (see :func:`_branches`) is dropped only when quantifier
    elimination proves that no real values of its unknowns and parameters
    (the declared ``positive`` ones positive) satisfy its conditions: then
    it has no real point. Where that is undecided (QEPCAD missing, over
    its budget, conditions not rational) it stays, with its conditions.

    The ends of a branch, where a radicand vanishes (its condition `D > 0`
    fails), were solved as components of their own by
    :func:`_excluded_parts`. A solution is dropped only if a branch that
    stays (of more free unknowns) contains it, decided exactly: the
    branch's strict conditions widened to `D \ge 0` (after checking exactly
    that the values are real, finite and on the component at every point
    the widening adds, and that no polynomial of ``required`` -- the
    equations' denominators, the numerators of the expressions required
    nonzero -- vanishes there), the solution satisfying them and equal to the
    branch's values there -- for a branch of one free unknown without
    parameters at the points in ``AA`` (:func:`_closed_branch`), otherwise
    by identities (:func:`_closed_symbolically`). Where that is not proved
    the solution stays listed (redundant, never wrong).

    EXAMPLES: the branches of `y^2 = x - a`, `z^2 = -x - a` are real
    where `a < x < -a`: nowhere when `a` is declared positive::

        sage: from sage_dynsym.algebra.solving import solve_exactly
        sage: x, y, z, a = var('x y z a')
        sage: list(solve_exactly([y^2 - x + a, z^2 + x + a], [x, y, z], positive=[a]))
        []
        sage: len(solve_exactly([y^2 - x + a, z^2 + x + a], [x, y, z]))
        8

    Without parameters, a curve is written in branches only when whether
    it is real is not decided otherwise (here the random fibres and
    quantifier elimination are switched off to show it). The branches of
    `y^2 = x - 1`, `z^2 = 3 - x` end where `y = 0` or `z = 0`: those four
    points are on the branches, which are listed for `1 \le x \le 3`;
    `y^2 = x - 1`, `z^2 = -x - 1` has no real point::

        sage: import sage_dynsym.algebra.solving as solving
        sage: solving.REAL_POINT_SAMPLES, solving.REALITY_QE_VARIABLES = 0, 0
        sage: sols = solve_exactly([y^2 - x + 1, z^2 + x - 3], [x, y, z])
        sage: [(s.dimension(), s.conditions()) for s in sols]
        [(1, [x - 1 >= 0, x - 3 <= 0]),
         (1, [x - 1 >= 0, x - 3 <= 0]),
         (1, [x - 1 >= 0, x - 3 <= 0]),
         (1, [x - 1 >= 0, x - 3 <= 0])]
        sage: list(solve_exactly([y^2 - x + 1, z^2 + x + 1], [x, y, z]))
        []

    The point `(1, 0, 0)` at the end of the branches `y = \pm\sqrt{x - 1}`,
    `z = 1/y` is not on them (`z` is infinite there): it stays::

        sage: C, Q = [y^2 - x + 1, y*z - 1], [x - 1, y, z]
        sage: for s in solve_exactly([c*q for c in C for q in Q], [x, y, z]):
        ....:     print(s)
        Solution {x: 1, y: 0, z: 0} (dimension 0)
        Solution {x: x, y: sqrt(x - 1), z: 1/sqrt(x - 1)} (dimension 1, if x - 1 > 0)
        Solution {x: x, y: -sqrt(x - 1), z: -1/sqrt(x - 1)} (dimension 1, if x - 1 > 0)
        sage: solving.REAL_POINT_SAMPLES, solving.REALITY_QE_VARIABLES = 12, 5

    With parameters (and with several free unknowns) a branch is widened
    when identities prove it (:func:`_closed_symbolically`): the end
    `(a, 0)` of the branches `y = \pm\sqrt{x - a}` is on them, the ends
    `(\pm\sqrt a, 0)` of `y = \pm\sqrt{a - x^2}` likewise::

        sage: [(s.values(), s.conditions()) for s in solve_exactly([y^2 - x + a], [x, y])]
        [({x: x, y: sqrt(-a + x)}, [a - x <= 0]), ({x: x, y: -sqrt(-a + x)}, [a - x <= 0])]
        sage: [s.conditions() for s in solve_exactly([x^2 + y^2 - a], [x, y])]
        [[x^2 - a <= 0], [x^2 - a <= 0]]

    The line `x = a, y = z = 0` at the end of the branches
    `y = \pm\sqrt{x - a}`, `w = z/y` is not on them (`w` is infinite
    there): it stays::

        sage: w = var('w')
        sage: [(s.dimension(), s.conditions()) for s in solve_exactly([y^2 - x + a, z - w*y], [x, y, z, w])]
        [(1, []), (2, [a - x < 0]), (2, [a - x < 0])]
    """
    cache = {}
    kept = [s for s in solutions if not _never_real(s, positive, cache)]
    explicit = [s for s in kept if s.is_explicit()]
    dropped, widened = set(), {}
    # the largest branches first: a branch that contains another is kept
    # (a branch dropped into a larger one would not carry what it contains)
    for f in sorted((s for s in explicit if s._free), key=lambda s: -len(s._free)):
        if id(f) in dropped:
            continue
        smaller = [s for s in explicit if len(s._free) < len(f._free) and id(s) not in widened]
        if len(f._free) == 1 and not T.parameters():
            closed, inside = _closed_branch(T, f, [s for s in smaller if not s._free],
                                            required)
        else:
            closed, inside = _closed_symbolically(T, f, smaller, positive, required)
        if inside:
            widened[id(f)] = closed
            dropped.update(id(p) for p in inside)
    return [widened.get(id(s), s) for s in kept if id(s) not in dropped]


def _pointwise(T, solutions, required, positive):
    r"""
    The solutions with the conditions that the polynomials ``required``
    (the equations' denominators, the numerators of the expressions
    required nonzero) do not vanish at their values: for each factor `f`
    of one at the values, `f \ne 0` -- unless it is a nonzero constant, a
    parameter declared positive, or implied by the solution's conditions
    (:func:`_implied_nonzero`). A solution where one vanishes identically
    is no solution: dropped. The saturation removed only the components
    inside their zero sets; this removes the points of the others there.

    An implicit solution gets the conditions on its parameters and free
    unknowns only (its conditions are stated on those): a factor in its
    bound unknowns is not a condition of it (the saturation guarantees
    that it does not vanish on the whole component).

    EXAMPLES: `x = y` is a solution of `(x - y)/y = 0` only where
    `y \ne 0`::

        sage: from sage_dynsym.algebra.solving import solve_exactly
        sage: x, y, a = var('x y a')
        sage: [(s.values(), s.conditions()) for s in solve_exactly([(x - y)/y], [x, y])]
        [({x: x, y: x}, [x != 0])]

    The point `x = a` of `x^2 = a x` (besides `x = 0`, which is required
    nonzero) exists where `a \ne 0`; where `a = 1` too, `x - 1` vanishes::

        sage: [(s.values(), s.conditions()) for s in solve_exactly([x^2 - a*x], [x],
        ....:                                                        nonzero=[x*(x - 1)])]
        [({x: a}, [a - 1 != 0, a != 0])]

    An implicit family: `\cos q = x` over `x` with `\sin q` in a
    denominator holds where `\sin^2 q = 1 - x^2` is not zero; `y^3 = x`
    with `y` in a denominator where `x \ne 0`::

        sage: q = var('q')
        sage: s = solve_exactly([(x - cos(q))/sin(q)], [x, q])[0]
        sage: s.is_explicit(), s.free_unknowns(), s.conditions()
        (False, [x], [x - 1 != 0, x + 1 != 0])
        sage: s = solve_exactly([(y^3 - x)/y], [x, y])[0]
        sage: s.is_explicit(), s.free_unknowns(), s.conditions()
        (False, [x], [x != 0])
    """
    result = []
    for s in solutions:
        conditions = _nonzero_at(T, s, required, positive)
        if conditions is None:
            _log(f"a solution {s.values()} where a required nonzero polynomial vanishes: dropped")
        elif len(conditions) == len(s._conditions):
            result.append(s)
        else:
            result.append(AlgebraicSolution(T, s._prime, s._free, s._counted, dict(s._values),
                                            dict(s._ring_values), s._relations, conditions,
                                            s._real_points, s._reality_known))
    return result


def _nonzero_at(T, solution, required, positive):
    r"""The conditions of ``solution`` with those that no polynomial of
    ``required`` vanishes at its values (see :func:`_pointwise`); ``None``
    if one vanishes identically there."""
    unknowns = T.unknowns()
    stated = {str(p) for p in T.parameters()} | {str(unknowns[i]) for i in solution._free}

    def at_values(f):
        return nonzero_conditions(SR(solution.evaluate(T.symbolic(f))).numerator(), positive)

    def statable(found):
        return all(set(map(str, c.lhs().variables())) <= stated for c in found)

    conditions = list(solution._conditions)
    for f in required:
        found = at_values(f)
        if found is None:
            return None
        # modulo an implicit component a power `f^k` may be a function of
        # the free unknowns and parameters (`\sin^2 q = 1 - x^2` where
        # `\cos q = x`; `y^3 = x`): `f \ne 0` exactly where it is not zero
        for k in IMPLICIT_NONZERO_POWERS if solution._relations else ():
            if statable(found):
                break
            power = at_values(f ** k)
            found = power if power is not None and statable(power) else found
        for c in found:
            h = SR(c.lhs() - c.rhs())
            if set(map(str, h.variables())) <= stated and \
                    not _implied_nonzero(h, conditions, positive):
                conditions.append(c)
    return conditions


def _implied_nonzero(h, conditions, positive):
    r"""Whether the ``conditions`` imply `h \ne 0`: each factor of `h` is
    required nonzero by one (up to a constant factor, see
    :func:`_required_nonzero`), or `h` or `h^2` is a constant multiple of
    the side of a strict inequality."""
    nonzero = [SR(c.lhs() - c.rhs()) for c in conditions if c.operator() is operator.ne]
    strict = [SR(c.lhs() - c.rhs()) for c in conditions
              if c.operator() in (operator.gt, operator.lt)]
    return _required_nonzero(h, nonzero, [], positive) or \
        any(_positive_multiple(D, g) or _positive_multiple(-D, g)
            for D in strict for g in (h, h ** 2))


def _never_real(solution, positive, cache):
    r"""Whether quantifier elimination proves that no real values satisfy
    the conditions of ``solution`` (``False`` when undecided, or when a
    sample point satisfies them: see
    :func:`~sage_dynsym.algebra.regions.prune_empty`)."""
    conditions = solution._conditions
    # points: their conditions are on the parameters only, simplified when
    # made; a call of QEPCAD for each would cost more than it finds
    if not conditions or not solution._reality_known or not solution._free:
        return False
    symbols = sorted({v for c in conditions for v in SR(c.lhs() - c.rhs()).variables()},
                     key=str)
    key = tuple(sorted(map(str, conditions)))
    if not symbols or key in cache:
        return cache.get(key, False)
    try:
        field = PolynomialRing(QQ, [str(v) for v in symbols]).fraction_field()
        for c in conditions:
            field(SR(c.lhs() - c.rhs()))
    except (TypeError, ValueError):
        cache[key] = False      # not rational: quantifier elimination would take atoms
        return False
    cache[key] = not prune_empty([list(conditions)], positive, timeout=REALITY_QE_TIMEOUT)
    if cache[key]:
        _log(f"a branch real nowhere under {list(conditions)}: dropped")
    return cache[key]


def _closed_branch(T, family, points, required):
    r"""
    The branch ``family`` (one free unknown, no parameters) with its strict
    conditions widened (`D > 0` to `D \ge 0`) and the ``points`` it then
    contains; ``(family, [])`` when no point is contained or the widening
    cannot be proved right. It is right when at every point it adds (the
    real roots of the boundaries that satisfy the widened conditions) the
    branch's values are real, finite and on the component, and no
    polynomial of ``required`` vanishes there: exact
    arithmetic in ``AA``, the generators of the component's prime ideal
    evaluated there.
    """
    u = T.unknowns()[family._free[0]]
    conditions = family._conditions
    if T.parameters() or isinstance(family._prime, ShapePrime) or \
            any(T.is_angle(v) for v in T.unknowns()) or \
            any(set(map(str, SR(c.lhs() - c.rhs()).variables())) - {str(u)}
                for c in conditions):
        return family, []
    strict = [c for c in conditions if c.operator() in (operator.gt, operator.lt)]
    if not strict:
        return family, []
    wide = {operator.gt: operator.ge, operator.lt: operator.le}
    closed = [wide[c.operator()](c.lhs(), c.rhs()) if c.operator() in wide else c
              for c in conditions]
    R = PolynomialRing(QQ, 'u')
    for c in strict:
        try:
            boundary = R(SR(c.lhs() - c.rhs()).numerator().subs({u: R.gen()}))
        except (TypeError, ValueError):
            return family, []
        for r, _ in boundary.roots(AA):
            at = SR(QQ(r)) if r in QQ else r.radical_expression()
            if at.parent() is not SR:
                return family, []       # no radicals: not compared exactly here
            if _holds_at(closed, u, at) and \
                    _values_at(T, family, u, at, check=True, required=required) is None:
                return family, []
    inside = []
    for p in points:
        at = p._values.get(family._free[0])
        if at is None or not _holds_at(closed, u, at):
            continue
        here = _values_at(T, family, u, at)
        try:
            if here is not None and all(here[i] == AA(SR(v))
                                        for i, v in enumerate(p.values().values())):
                inside.append(p)
        except (TypeError, ValueError, ArithmeticError):
            continue
    if not inside:
        return family, []
    return AlgebraicSolution(T, family._prime, family._free, family._counted,
                             dict(family._values), dict(family._ring_values), [],
                             closed), inside


def _closed_symbolically(T, family, others, positive, required):
    r"""
    The branch ``family`` with its strict conditions widened (`D > 0` to
    `D \ge 0`) and the solutions among ``others`` (explicit, with fewer
    free unknowns) that it then contains; ``(family, [])`` when none is
    contained or the widening cannot be proved right.

    The widening is proved by identities, for every value of the
    parameters and free unknowns at once: each square root `\sqrt R` in
    the values is a new variable `s` with `s^2 = R`; `R \ge 0` must be
    one of the widened conditions (so `s` is real), no denominator -- of
    the values, of the equations, or a polynomial of ``required`` (the
    numerators required nonzero) at the values -- may hold an `s` (it
    could vanish where `R = 0`) and each of its factors must be required
    nonzero by a condition; then the generators of the
    component, at the values, must lie in the ideal of the `s^2 - R`
    (a Gröbner basis decides it): they vanish wherever the values are
    defined, at the points the widening adds too. A solution is
    contained if the branch's values at its values are its values and its
    conditions imply the widened ones there (each holds identically or is
    one of its conditions).
    """
    unknowns = T.unknowns()
    conditions = family._conditions
    strict = [c for c in conditions if c.operator() in (operator.gt, operator.lt)]
    if not strict or not others or isinstance(family._prime, ShapePrime) or \
            any(T.is_angle(v) for v in unknowns):
        return family, []
    wide = {operator.gt: operator.ge, operator.lt: operator.le}
    closed = [wide[c.operator()](c.lhs(), c.rhs()) if c.operator() in wide else c
              for c in conditions]
    if not _widening_holds(T, family, closed, positive, required):
        return family, []
    inside = [s for s in others if _inside(T, family, closed, s)]
    if not inside:
        return family, []
    return AlgebraicSolution(T, family._prime, family._free, family._counted,
                             dict(family._values), dict(family._ring_values), [],
                             closed), inside


class _SquareRoots(ExpressionWalker):
    r"""A rational expression in symbols and square roots of rational
    expressions without roots, each `R^{n/2}` written `s^n` with a new
    symbol `s` for `\sqrt R` (:attr:`roots`: the pairs `(s, R)`); any
    other atom is refused (``ValueError``)."""

    def __init__(self):
        self.roots = {}

    def symbol(self, e):
        return e

    def number(self, e):
        return e

    def atom(self, e):
        if e.operator() is operator.pow:
            base, exponent = e.operands()
            n = QQ(exponent.pyobject()) if exponent.is_numeric() else None
            if n is not None and n.denominator() == 2:
                _SquareRoots().walk(base)       # no root inside a root
                key = str(base)
                if key not in self.roots:
                    self.roots[key] = (SR.symbol(f"root_of_{len(self.roots)}_"), base)
                return self.roots[key][0] ** ZZ(2 * n)
        raise ValueError(f"{e} is not a square root of a rational expression")


def _widening_holds(T, family, closed, positive, required):
    r"""Whether the values of ``family`` are real, finite and on its
    component wherever the ``closed`` conditions hold (see
    :func:`_closed_symbolically`)."""
    roots = _SquareRoots()
    try:
        values = [roots.walk(SR(family._values.get(i, v))) for i, v in enumerate(T.unknowns())]
    except (ValueError, TypeError):
        return False
    s_symbols = [s for s, _ in roots.roots.values()]
    if {str(v) for v in T.unknowns() + list(T.parameters())} & set(map(str, s_symbols)):
        return False
    nonzero = [SR(c.lhs() - c.rhs()) for c in closed if c.operator() is operator.ne]
    nonnegative = [SR(c.lhs() - c.rhs()) * (1 if c.operator() is operator.ge else -1)
                   for c in closed if c.operator() in (operator.ge, operator.le)]
    for s, R in roots.roots.values():
        if not (R.is_numeric() and R > 0) and \
                not any(_positive_multiple(D, R) for D in nonnegative):
            return False
    at = dict(zip(T.unknowns(), values))
    try:
        # finite, and where the equations are defined and the expressions
        # required nonzero are not zero (no polynomial of ``required``
        # vanishing at the values)
        if not all(_required_nonzero(SR(v).denominator(), nonzero, s_symbols, positive)
                   for v in values + [R for _, R in roots.roots.values()]) or \
                not all(_required_nonzero(SR(T.symbolic(d)).subs(at).numerator(), nonzero,
                                          s_symbols, positive) for d in required):
            return False
    except (TypeError, ValueError, ArithmeticError):
        return False
    relations = [(s ** 2 - R).numerator() for s, R in roots.roots.values()]
    try:
        images = [SR(T.symbolic(g)).subs(at).numerator() for g in family._prime.gens()]
        names = sorted({str(x) for e in images + relations for x in SR(e).variables()})
        if not names:
            return all(SR(e).is_zero() for e in images)
        R = PolynomialRing(QQ, names)
        ideal = R.ideal([R(r) for r in relations]) if relations else R.ideal([R(0)])
        return all(ideal.reduce(R(e)) == 0 for e in images)
    except (TypeError, ValueError, ArithmeticError):
        return False


def _required_nonzero(expr, nonzero, s_symbols, positive):
    r"""Whether each factor of ``expr`` is a nonzero number, a parameter
    declared positive, or required nonzero by one of the conditions
    ``nonzero`` (up to a constant factor); never where it holds one of the
    ``s_symbols`` (square roots, which may vanish)."""
    for f, _ in SR(expr).factor_list():
        if f.is_numeric():
            if f.is_zero():
                return False
            continue
        if any(f.has(s) for s in s_symbols) or \
                not any(_positive_multiple(g, f) or _positive_multiple(g, -f) for g in nonzero) \
                and str(f) not in map(str, positive):
            return False
    return True


def _positive_multiple(D, R):
    r"""Whether ``D`` is ``R`` times a positive rational number."""
    try:
        q = normalize(SR(D) / SR(R))
        return q.is_numeric() and QQ(q.pyobject()) > 0
    except (TypeError, ValueError, ArithmeticError, ZeroDivisionError):
        return False


def _inside(T, family, closed, solution):
    r"""Whether every point of the explicit ``solution`` is the point of
    the widened branch (values of ``family``, conditions ``closed``) at
    the same free unknowns (see :func:`_closed_symbolically`)."""
    if solution._prime is None or not solution.is_explicit():
        return False
    unknowns = T.unknowns()
    at = {unknowns[i]: SR(solution._values.get(i, unknowns[i])) for i in family._free}
    try:
        for i, v in enumerate(unknowns):
            here = SR(family._values.get(i, v)).subs(at)
            if not normalize(here - SR(solution._values.get(i, v))).is_zero():
                return False
        own = {str(c) for c in solution._conditions}
        for c in closed:
            c = c.subs(at)
            lhs = normalize(SR(c.lhs() - c.rhs()))
            if lhs.is_numeric():
                if not c.operator()(lhs, 0):
                    return False
            elif str(c.operator()(lhs, 0)) not in own and str(c) not in own:
                return False
    except (TypeError, ValueError, ArithmeticError):
        return False
    return True


def _holds_at(conditions, u, at):
    r"""Whether the conditions (in the unknown ``u`` only) hold at the
    exact value ``at`` (compared in ``AA``; ``False`` when not real)."""
    try:
        return all(bool(c.operator()(AA(SR(c.lhs() - c.rhs()).subs({u: at})), 0))
                   for c in conditions)
    except (TypeError, ValueError, ArithmeticError):
        return False


def _values_at(T, family, u, at, check=False, required=()):
    r"""The values (index: element of ``AA``) of the branch at ``u =
    at``; ``None`` where one is not real or finite or (``check``) the
    point is not on the component or one of the polynomials ``required``
    (the equations' denominators, the numerators required nonzero)
    vanishes there."""
    unknowns = T.unknowns()
    values = {}
    try:
        for i, v in enumerate(unknowns):
            values[i] = AA(SR(family._values.get(i, v)).subs({u: at}))
    except (TypeError, ValueError, ArithmeticError):
        return None
    if check:
        P = family._prime.ring()
        images = [None] * P.ngens()
        for i, v in enumerate(unknowns):
            gens = T.generators_of(v)
            if len(gens) != 1:
                return None
            images[P.gens().index(P(gens[0]))] = values[i]
        if any(x is None for x in images) or \
                any(g(*images) != 0 for g in family._prime.gens()) or \
                any(f(*images) == 0 for f in required):
            return None
    return values


def _sort_key(s):
    # isolated before families; solutions off the first axes first (the
    # pattern of zero values); numerical points in increasing order;
    # conjugate branches stay together, in the order they were made
    pattern, numeric = [], []
    for i in sorted(s._counted):
        v = s._values.get(i)
        pattern.append(0 if v is not None and SR(v).is_zero() else -1)
    for v in s._values.values():
        try:
            numeric.append(float(v))
        except (TypeError, ValueError):
            numeric = []
            break
    return (s.dimension(), len(s._free), not s.is_explicit(), bool(s._conditions),
            pattern if s._free else [], numeric, pattern,
            str(s._prime.gens()) if s._prime is not None else '')


# ---------------------------------------------------------------------------
# one component
# ---------------------------------------------------------------------------

def _excluded_parts(T, known, solutions, counted, positive, required):
    r"""
    The solutions on the points of a component that the strict conditions
    of its solutions on unknowns exclude: where a denominator of a value or
    of a multiplier vanishes (`u \ne 0`), where the radicand of two
    branches vanishes (`D > 0`: the branches meet there). Each such part,
    the component with `u = 0` added, is solved as a further case -- unless
    it lies on another component (in ``known``, or found here), whose
    solutions and their own excluded parts list its points.

    EXAMPLES: `x z = y` over `(x, y)` is `z = y/x` for `x \ne 0`; the line
    `x = y = 0` is a further solution. The branches
    `y = x \pm \sqrt{x^2 - a}` of `y^2 - 2 x y + a = 0`, `y z = 1` meet
    at the points `x = y = \pm\sqrt{a}`::

        sage: from sage_dynsym.algebra.solving import solve_exactly
        sage: x, y, z, a = var('x y z a')
        sage: [(s.values(), s.conditions()) for s in solve_exactly([x*z - y], [x, y, z])]
        [({x: 0, y: 0, z: z}, []), ({x: x, y: y, z: y/x}, [x != 0])]
        sage: [s.values() for s in solve_exactly([y^2 - 2*x*y + a, y*z - 1], [x, y, z])
        ....:  if not s.dimension()]
        [{x: sqrt(a), y: sqrt(a), z: 1/sqrt(a)}, {x: -sqrt(a), y: -sqrt(a), z: -1/sqrt(a)}]

    A part where an expression required nonzero vanishes is no solution:
    with `x` (or `x + y`) required nonzero, the line `x = y = 0` is not
    one; with `z - 1`, it is where `z \ne 1`::

        sage: [(s.values(), s.conditions()) for s in solve_exactly([x*z - y], [x, y, z],
        ....:                                                        nonzero=[x + y])]
        [({x: x, y: y, z: y/x}, [x != 0, x + y != 0])]
        sage: [(s.values(), s.conditions()) for s in solve_exactly([x*z - y], [x, y, z],
        ....:                                                        nonzero=[z - 1])]
        [({x: 0, y: 0, z: z}, [z - 1 != 0]), ({x: x, y: y, z: y/x}, [x != 0, x - y != 0])]
    """
    known, todo, found, done = list(known), list(solutions), [], set()
    # the primes each part contains because it was cut out of them: no
    # normal form of their (possibly large) generators is needed for these
    inside = {}
    while todo:
        s = todo.pop()
        P = s._prime
        for d in _excluded_by(T, s):
            # P is prime: d lies in it if one of its factors does (the
            # factors are cheap to reduce where a power of one took minutes)
            if (id(P), d) in done or any(P.reduce(f) == 0 for f, _ in d.factor()):
                continue
            done.add((id(P), d))
            J = P.ring().ideal(list(P.gens()) + [d])
            above = inside.get(id(P), set()) | {id(P)}
            for Q, sh in minimal_primes(J, shapes=True, split_points=T.field() is QQ):
                if any(id(K) not in above and not _contains(P, K) and _contains(Q, K)
                       for K in known) or \
                        any(not isinstance(Q, ShapePrime) and Q.reduce(f) == 0
                            for f in required):
                    # on another component, or where the equations are not
                    # defined or an expression required nonzero vanishes
                    continue
                inside[id(Q)] = above
                known.append(Q)
                new = _solve_component(T, Q, sh, counted, positive)
                found += new
                todo += new
    return found


def _excluded_by(T, solution):
    r"""The polynomials whose zero sets the strict conditions of the
    solution on unknowns exclude (their numerators and denominators)."""
    unknowns = T.unknowns()
    for c in solution._conditions:
        lhs = SR(c.lhs() - c.rhs())
        if c.operator() in (operator.ne, operator.gt, operator.lt) and \
                any(lhs.has(u) for u in unknowns):
            num, dens = T.numerator(lhs)
            yield from [num] + dens


def _contains(Q, K):
    r"""Whether the ideal ``Q`` contains ``K`` (``False`` for a
    :class:`~sage_dynsym.algebra.decomposition.ShapePrime` ``K``, whose
    generators are not the prime's)."""
    return not isinstance(K, ShapePrime) and all(Q.reduce(g) == 0 for g in K.gens())


def _unit_generators(T, i):
    return T.generators_of(T.unknowns()[i])


def _projection_dimension(prime, keep):
    P = prime.ring()
    others = [v for v in P.gens() if v not in keep]
    if not others:
        return prime.dimension()
    return prime.elimination_ideal(others).dimension() - len(others)


def _free_unknowns(T, prime, counted):
    r"""A maximal set of unknowns that the component leaves free, chosen
    among the counted unknowns first (so their number is the dimension of
    the projection to them).

    The unknowns are tried one by one, each by the dimension of an
    elimination ideal. In a ring whose order was chosen by trying
    (:func:`_choose_order`), where these eliminations take minutes over a
    field of many parameters, the strongly independent sets of the
    prime's basis (no leading monomial in their variables: Singular's
    ``indepSet``) are read off the basis at hand instead: the first of
    full size in the order of preference is taken if all its unknowns are
    counted (no set has more counted unknowns then)."""
    n = len(T.unknowns())
    total = prime.dimension()
    order = [i for i in range(n) if i in counted] + [i for i in range(n) if i not in counted]
    if _order_chosen(prime.ring()):
        free = _strongly_independent_unknowns(T, prime, total, order)
        if free is not None and all(i in counted for i in free):
            return free
    free, keep = [], []
    for i in order:
        if len(free) == total:
            break
        trial = keep + list(_unit_generators(T, i))
        if _projection_dimension(prime, trial) == len(free) + 1:
            free.append(i)
            keep = trial
    return free


def _strongly_independent_unknowns(T, prime, total, order):
    # the unknowns of each strongly independent set of full size; the first
    # in the order of preference (``None`` if there is none to read)
    if total == 0 or isinstance(prime, ShapePrime):
        return None
    P = prime.ring()
    basis = P.ideal(prime.groebner_basis())
    candidates = []
    for flags in singular_function('indepSet')(basis, 1, attributes={basis: {'isSB': 1}}):
        variables = {k for k, flag in enumerate(flags) if flag}
        unknowns = [i for i in order
                    if any(P.gens().index(g) in variables for g in _unit_generators(T, i))]
        if len(variables) == total and len(unknowns) == total:
            candidates.append(unknowns)
    if not candidates:
        return None
    rank = {i: k for k, i in enumerate(order)}
    return min(candidates, key=lambda u: sorted(rank[i] for i in u))


def _solve_component(T, prime, sh, counted, positive):
    if sh == 'points':      # a zero-dimensional part over a field of parameters
        if prime.vector_space_dimension() > MAX_EXPLICIT_DEGREE:
            return [_implicit(T, prime, counted, positive)]
        return _parametric_points(T, prime, counted, positive, split=True)
    free = [] if sh is not None else _free_unknowns(T, prime, counted)
    if free:
        family = _family(T, prime, free, counted, positive)
        if family is not None and not family._reality_known \
                and family._relation_terms() <= MAX_DECIDED_TERMS:
            # where its reality is not known, its branches may say, or a
            # rational parametrization, or quantifier elimination
            found = _branches(T, family, positive)
            if len(found) != 1 or found[0] is not family:
                return found
            found = _parametrized(T, prime, family, counted, positive)
            if found is not None:
                return found
            family = _qe_family(T, family, positive)
        if family is not None:
            return [family]
        return _singular_locus_solutions(T, prime, len(free), counted, positive)
    if T.field() is QQ:
        return _rational_points(T, prime, sh, counted)
    if sh is not None and sh[1].degree() > MAX_EXPLICIT_DEGREE:
        return [_implicit(T, prime, counted, positive)]
    return _parametric_points(T, prime, counted, positive)


#: Implicit families whose relations have more terms than this (counting
#: the terms of their coefficients in the parameters) are returned with
#: their reality undecided: their branches would be radicals of
#: expressions of that size, and writing the relations symbolically for
#: the tries takes minutes (a family of a generic Kirchhoff Hamiltonian:
#: one relation of about 3000 terms over 12 parameters). Expressions
#: evaluated on such a family are not put in normal form modulo its
#: relations (:meth:`AlgebraicSolution.evaluate`): each normal form took
#: seconds there.
MAX_DECIDED_TERMS = 1000



def _branches(T, family, positive):
    r"""
    An implicit family parametrised by its free unknowns: its relations
    solved for the unknowns they bind, the free unknowns and the
    parameters taken as parameters (a zero-dimensional system over their
    field: radicals, with the conditions of reality). Each real branch is
    an explicit family; the family is returned unchanged when a branch
    cannot be written (or an unknown it binds is an angle), or when the
    branches in several bound unknowns are not found within
    :data:`BRANCH_SOLVE_SECONDS` of processor time.

    Only families whose reality is not known otherwise are split (a curve
    without parameters stays one implicit family).

    EXAMPLES: the cone `x^2 = a y^2` over `x`, two branches real for
    `a > 0`, besides the line `x = y = 0`::

        sage: from sage_dynsym.algebra.solving import solve_exactly
        sage: x, y, z, a = var('x y z a')
        sage: [(s.values(), s.conditions()) for s in solve_exactly([x^2 - a*y^2, z*x - y], [x, y, z])]
        [({x: 0, y: 0, z: z}, []),
         ({x: x, y: x/sqrt(a), z: 1/sqrt(a)}, [a > 0, x != 0]),
         ({x: x, y: -x/sqrt(a), z: -1/sqrt(a)}, [a > 0, x != 0])]
    """
    unknowns = T.unknowns()
    free = set(family._free)
    bound = [i for i in range(len(unknowns)) if i not in free and i not in family._values]
    if not bound or any(T.is_angle(unknowns[i]) for i in bound):
        return [family]
    if not _radicals_at_random_values(T, family.equations(), [unknowns[i] for i in bound]):
        _log("a branch needs a step of degree above 2 at random values: kept implicit")
        return [family]
    equations = [SR(e).numerator() for e in family.equations()]
    unknowns_bound = [unknowns[i] for i in bound]

    def solve():
        return solve_exactly(equations, unknowns_bound, positive=positive)
    try:
        if len(bound) == 1:
            found = solve()
        else:
            # the test at random values above decides with probability one,
            # not always: a system of several unknowns whose triangular sets
            # over the field of the parameters run long is left implicit
            done, found = within_processor_time(solve, BRANCH_SOLVE_SECONDS)
            if not done:
                _log(f"the branches not solved within {BRANCH_SOLVE_SECONDS} s of processor "
                     f"time ({found}): kept implicit")
                return [family]
    except (AnalysisError, ValueError, TypeError, NotImplementedError):
        return [family]
    if not found.is_complete() or any(b.dimension() or not b.is_explicit() for b in found):
        return [family]
    result = []
    for b in found:
        at = {unknowns[i]: b.values()[unknowns[i]] for i in bound}
        values = {i: normalize(SR(v).subs(at)) for i, v in family._values.items()}
        values.update({i: at[unknowns[i]] for i in bound})
        conditions = conjunction(list(family._conditions), b.conditions())
        if conditions is None:
            continue
        result.append(AlgebraicSolution(T, family._prime, family._free, family._counted,
                                        values, dict(family._ring_values), [], conditions))
    return result


#: At most this many other choices of the free unknowns are tried when
#: looking for a rational parametrization of an implicit family ...
PARAMETRIZATION_TRIES = 24

#: ... and no new one after this many seconds of processor time ...
PARAMETRIZATION_SECONDS = 20

#: ... and only with at most this many unknowns and parameters together:
#: each try is a Gröbner basis in another order over the field of the
#: parameters, a library call that the seconds above cannot stop (Brun's
#: problem on a level `M \cdot \gamma = c`, 9 unknowns and 5 parameters,
#: spent minutes in one).
PARAMETRIZATION_VARIABLES = 8

#: Implicit families with parameters are decided by quantifier elimination
#: (over their bound unknowns) only up to this many variables.
FAMILY_QE_VARIABLES = 7


def _parametrized(T, prime, family, counted, positive):
    r"""
    The family written by other free unknowns, if some choice of them
    gives every other unknown explicitly (rationally, or on branches by
    radicals, see :func:`_branches`): then it is real wherever the
    conditions of the values hold (denominators not zero, radicands
    positive); ``None`` if no choice tried does.

    EXAMPLES: `a x = y^3 + y` over `x` needs a cubic; over `y` it is
    rational, real for `a \ne 0`; `y^3 = a x y - 1`, `y z = 1` likewise::

        sage: from sage_dynsym.algebra.solving import solve_exactly
        sage: x, y, z, a = var('x y z a')
        sage: s = solve_exactly([y^3 + y - a*x], [x, y])[0]
        sage: s.values(), s.conditions()
        ({x: (y^3 + y)/a, y: y}, [a != 0])
        sage: s = solve_exactly([y^3 - a*x*y + 1, z*y - 1], [x, y, z])[0]
        sage: s.values(), s.conditions()
        ({x: (y^3 + 1)/(a*y), y: y, z: 1/y}, [y != 0, a != 0])
    """
    from itertools import combinations
    # processor time of this thread (the computing is Singular's, here),
    # not the clock: the families parametrized must not depend on the
    # machine's load, nor on other threads of this process
    from time import thread_time
    n, d = len(T.unknowns()), len(family._free)
    if n + len(T.parameters()) > PARAMETRIZATION_VARIABLES:
        _log(f"an implicit family in {n} unknowns and {len(T.parameters())} parameters: "
             "not tried by other free unknowns")
        return None
    order = [i for i in range(n) if i in counted] + [i for i in range(n) if i not in counted]
    tried, start = 0, thread_time()
    _log(f"an implicit family of dimension {d}: trying other free unknowns")
    for choice in combinations(order, d):
        if tried >= PARAMETRIZATION_TRIES or thread_time() - start > PARAMETRIZATION_SECONDS:
            break
        if sorted(choice) == sorted(family._free):
            continue
        keep = [g for i in choice for g in _unit_generators(T, i)]
        if _projection_dimension(prime, keep) != d:
            continue
        tried += 1
        other = _family(T, prime, list(choice), counted, positive)
        if other is None:
            continue
        found = _branches(T, other, positive) if other._relations else [other]
        if found and all(s.is_explicit() for s in found):
            return [_with_denominators(s, positive) for s in found]
    return None


def _with_denominators(solution, positive):
    r"""The solution with its values' denominators required nonzero (the
    coefficients of a parametrization are over the field of parameters)."""
    conditions = list(solution._conditions)
    for v in solution._values.values():
        conditions = conjunction(conditions, nonzero_conditions(SR(v).denominator(),
                                                                positive)) or conditions
    return AlgebraicSolution(solution._T, solution._prime, solution._free, solution._counted,
                             dict(solution._values), dict(solution._ring_values), [],
                             conditions)


def _qe_family(T, family, positive):
    r"""
    The family with the conditions of its reality decided by quantifier
    elimination: those on the parameters and its free unknowns for its
    bound unknowns to have real values (``None`` if they never have: its
    real points, if any, are singular). The family is returned unchanged
    (its reality undecided) when the problem is too large, QEPCAD is not
    available or over its budget, or the answer is not one conjunction.

    EXAMPLES: `y^4 = a - x^4` over `x` is real where `a \ge x^4`::

        sage: from sage_dynsym.algebra.solving import solve_exactly
        sage: x, y, a = var('x y a')
        sage: s = solve_exactly([y^4 + x^4 - a], [x, y])[0]
        sage: s.is_explicit(), s.conditions(), s.is_reality_decided()
        (False, [x^4 - a <= 0], True)
    """
    from .quantifier_elimination import exists
    unknowns = T.unknowns()
    free = set(family._free)
    bound = [unknowns[i] for i in range(len(unknowns))
             if i not in free and i not in family._values]
    if any(T.is_angle(u) for u in unknowns):
        return family
    relations = [SR(e).numerator() for e in family.equations()]
    symbols = set().union(*(set(map(str, e.variables())) for e in relations))
    if not relations or len(symbols) > FAMILY_QE_VARIABLES:
        return family
    _log(f"deciding where a family is real: quantifier elimination in {len(symbols)} variables")
    try:
        alternatives = exists(bound, [e == 0 for e in relations], positive,
                              timeout=REALITY_QE_TIMEOUT)
    except AnalysisError:
        return family
    if not alternatives:
        return None
    if len(alternatives) > 1:
        return family
    conditions = conjunction(list(family._conditions), alternatives[0])
    if conditions is None:
        return None
    return AlgebraicSolution(T, family._prime, family._free, family._counted,
                             dict(family._values), dict(family._ring_values),
                             family._relations, conditions)


def _radicals_at_random_values(T, equations, bound, attempts=2):
    r"""
    Whether the ``equations``, solved for the unknowns ``bound`` at random
    rational values of every other symbol, have finitely many solutions
    along triangular sets with steps of degree at most 2 (what
    :func:`_solve_triangular` writes with radicals), at each of
    ``attempts`` draws. A specialization only splits factors, and the
    dimension only grows at special values, so infinitely many solutions
    or a step of larger degree there is the same for the symbols too (with
    probability one): the symbolic solve (far slower) would not give
    radicals either. ``True`` when it cannot be tried (angles among the
    symbols) or no solution is found at any draw (the symbolic solve
    decides).

    The values are distinct: equal values are the special ones met most
    often (equal moments of inertia), where the steps can factor into
    quadratic ones although the symbolic system's do not. Brun's problem
    on `M \cdot \gamma = 0` drew two equal values once in about thirty
    runs, and its symbolic solve then went on for over half an hour on a
    component of degree 12. Each draw must agree, for the same reason.

    EXAMPLES::

        sage: from sage_dynsym.algebra.solving import _radicals_at_random_values
        sage: x, y, a = var('x y a')
        sage: _radicals_at_random_values(None, [x^2 - a*y, y - a], [x, y])
        True
        sage: _radicals_at_random_values(None, [x^3 + a*x + 1], [x])
        False

    TESTS: a step of degree 5 that splits into steps of degrees 2 and 1
    where `a = b` (drawn from 2 to 97 with repeats, as before, such a draw
    came about twice in 200) is never taken for radicals::

        sage: b = var('b')
        sage: f = (x^2 - a)*(x^2 - b)*(x - 1) + (a - b)*x^3
        sage: any(_radicals_at_random_values(None, [f], [x]) for _ in range(200))
        False
    """
    names = {str(b) for b in bound}
    others = sorted({v for e in equations for v in SR(e).variables()
                     if str(v) not in names}, key=str)
    if T is not None and any(T.is_angle(u) for u in T.unknowns() if u in others):
        return True
    for _ in range(attempts):
        at = dict(zip(others, distinct_random_values(len(others))))
        try:
            S = Translation([SR(e).subs(at) for e in equations], bound)
            I = S.ring().ideal(S.equations())
            dimension = I.dimension()
            if dimension < 0:       # no solution at these values
                continue
            if dimension > 0:
                return False
            sets = triangular_sets(I)
        except (AnalysisError, ArithmeticError, ValueError, TypeError):
            return True
        if any(t.degree(v) > 2 for tri in sets for t in tri for v in t.variables()):
            return False
    return True


def _singular_locus_solutions(T, prime, dimension, counted, positive):
    r"""The real points of a component without smooth real points lie in
    its singular locus: solve that (lower-dimensional) system."""
    from itertools import combinations
    P = prime.ring()
    gens = list(prime.gens())
    J = matrix(P, [[f.derivative(x) for x in P.gens()] for f in gens])
    rank = P.ngens() - (dimension + len(T.circle_relations()))
    minors = [J.matrix_from_rows_and_columns(list(r), list(c)).det()
              for r in combinations(range(J.nrows()), rank)
              for c in combinations(range(J.ncols()), rank)]
    locus = P.ideal(gens + [m for m in minors if m != 0])
    if is_unit_ideal(locus):
        return []
    result = []
    for Q, sh in minimal_primes(locus, shapes=True):
        if Q.dimension() < prime.dimension():
            result += _solve_component(T, Q, sh, counted, positive)
    return result


def _angle_value(c, s, c_sign=None, s_sign=None):
    r"""The angle with cosine ``c`` and sine ``s``; ``s_sign`` is the sign
    of the square root when ``s = \pm\sqrt{1 - c^2}`` (likewise ``c_sign``)."""
    if s_sign is not None:
        return arccos(c) if s_sign > 0 else -arccos(c)
    if c_sign is not None:
        return arcsin(s) if c_sign > 0 else pi - arcsin(s)
    return arctan2(s, c)


def _assemble(T, ring_values, signs):
    r"""Values of the unknowns from values of the ring variables."""
    values = {}
    for i, u in enumerate(T.unknowns()):
        gens = _unit_generators(T, i)
        names = [str(g) for g in gens]
        if not all(n in ring_values for n in names):
            continue
        if len(gens) == 1:
            values[i] = ring_values[names[0]]
        else:
            c, s = ring_values[names[0]], ring_values[names[1]]
            values[i] = _angle_value(c, s, signs.get(names[0]), signs.get(names[1]))
    return values


def _rational_points(T, prime, sh, counted):
    r"""Real points of a zero-dimensional prime over `\QQ`, exactly: the
    coordinates as polynomials in a separating linear form (the shape
    lemma), evaluated at the real roots of its minimal polynomial."""
    found = sh if sh is not None else shape(prime)
    if found is None:
        points = prime.variety(AA)
    else:
        _, F, gs = found
        gens = prime.ring().gens()
        points = [{g: gi(z) for g, gi in zip(gens, gs)} for z in F.roots(AA, multiplicities=False)]
    if not points:
        return []
    if found is None or found[1].degree() <= 2:
        result = []
        for p in points:
            ring_values, signs = {}, {}
            for g, a in p.items():
                ring_values[str(g)] = SR(QQ(a)) if a in QQ else SR(a.radical_expression())
            for i, u in enumerate(T.unknowns()):
                if T.is_angle(u):
                    c, s = _unit_generators(T, i)
                    if p[s] != 0:
                        signs[str(s)] = 1 if p[s] > 0 else -1
            values = _assemble(T, ring_values, signs)
            result.append(AlgebraicSolution(T, prime, [], counted, values, ring_values,
                                            [], []))
        return result
    symbolic = T.symbolic_generators()
    real = [{symbolic[k]: p[g] for k, g in enumerate(prime.ring().gens())} for p in points]
    return [AlgebraicSolution(T, prime, [], counted, {}, {}, _defining(T, prime), [],
                              real_points=real)]


def _defining(T, prime):
    r"""Equations of a component: a lexicographic Gröbner basis of a small
    zero-dimensional one (triangular: the first unknown alone first),
    without the relations `\cos^2 + \sin^2 = 1`; its generators; or for a
    :class:`~sage_dynsym.algebra.decomposition.ShapePrime` the radical's
    generators and `G(u)` with `u` left unexpanded."""
    if not isinstance(prime, ShapePrime):
        gens = list(prime.gens())
        if prime.dimension() == 0 and prime.vector_space_dimension() <= MAX_EXPLICIT_DEGREE:
            P = prime.ring()
            Pl = _lex_ring(P)
            gens = [P(g) for g in Pl.ideal([Pl(g) for g in gens]).groebner_basis('libsingular:stdfglm')]
            gens.reverse()
        circle = {str(r) for r in T.circle_relations()}
        return [g for g in gens if str(g) not in circle]
    u, G = prime.defining_polynomial()
    return list(prime.gens()) + [G.change_ring(SR)(T.symbolic(u))]


def _lex_ring(P):
    return PolynomialRing(P.base_ring(), [str(g) for g in P.gens()], P.ngens(), order='lex')


def _parametric_points(T, prime, counted, positive, split=False):
    r"""Zero-dimensional component (or, with ``split``, a zero-dimensional
    part not yet split into primes) over `\QQ(\text{parameters})`: along
    triangular sets (factorized), with radicals for steps of degree 2."""
    P = prime.ring()
    degree = prime.vector_space_dimension()
    # explicit values of a prime need a tower of quadratic steps: degree a
    # power of 2
    if not split and (degree & (degree - 1) or degree > MAX_EXPLICIT_DEGREE):
        return [_implicit(T, prime, counted, positive)]
    _log(f"triangular decomposition of a component of degree {degree}")
    sets = triangular_sets(prime)
    Pl = sets[0][0].parent() if sets and sets[0] else _lex_ring(P)
    result = []
    for tri in sets:
        component = P.ideal([P(g) for g in tri]) if split else prime
        branches = _solve_triangular(T, Pl, list(tri), positive)
        if branches is None:
            result.append(_implicit(T, component, counted, positive))
            continue
        for ring_values, signs, conditions in branches:
            values = _assemble(T, ring_values, signs)
            result.append(AlgebraicSolution(T, component, [], counted, values, ring_values,
                                            [], conditions))
    return result


def _solve_triangular(T, Pl, triangular, positive):
    r"""Branches ``(ring values, radical signs, conditions)`` of a
    triangular set, or ``None`` if a step has degree above 2."""
    gens = Pl.gens()
    index = {str(g): k for k, g in enumerate(gens)}

    def main(t):        # the leading variable in the lexicographic order
        return min(index[str(v)] for v in t.variables())

    # the cosine or sine of an angle keeps the sign of its square root
    # (its angle is written with arccos / arcsin)
    angular = {str(g): T.is_trigonometric(k) for k, g in enumerate(gens)}
    branches = [({}, {}, [])]
    for t in sorted(triangular, key=main, reverse=True):
        v = gens[main(t)]
        d = t.degree(v)
        if d > 2:
            return None
        coefficients = t.polynomial(v)
        new = []
        for values, signs, conds in branches:
            cs = [normalize(T.symbolic(coefficients[k], values)) for k in range(d + 1)]
            for value, sign, extra in _roots(cs, positive, angular[str(v)]):
                c = conjunction(conds, extra)
                if c is None:
                    continue
                vals = dict(values)
                vals[str(v)] = value
                sg = dict(signs)
                if sign is not None:
                    sg[str(v)] = sign
                new.append((vals, sg, c))
        branches = new
    result = []
    for values, signs, conds in branches:
        conds = simplify_conjunction(conds, positive)
        if conds is not None:
            result.append((values, signs, conds))
    return result


def _roots(cs, positive, keep_sign):
    r"""Real roots of ``cs[0] + cs[1] v (+ cs[2] v^2)``: triples
    ``(value, sign of the square root or None, conditions)``."""
    if len(cs) == 2:
        c0, c1 = cs
        value = normalize(-c0 / c1)
        cond = conjunction(nonzero_conditions(c1, positive),
                           nonzero_conditions(value.denominator(), positive))
        return [] if cond is None else [(value, None, cond)]
    c0, c1, c2 = cs
    lead = nonzero_conditions(c2, positive)
    if lead is None:
        return []
    if c1.is_zero():
        D = normalize(-c0 / c2)
        base = SR(0)
    else:
        D = normalize((c1 ** 2 - 4 * c0 * c2) / (4 * c2 ** 2))
        base = normalize(-c1 / (2 * c2))
    if D.is_numeric():
        if D < 0:
            return []
        if D == 0:
            return [(base, None, lead)]
        real = []
    else:
        real = positive_conditions(D, positive)
        if real is None:
            return []
    root = _square_root(D, positive, keep_sign)
    cond = conjunction(lead, real)
    if c1.is_zero():      # v = +-sqrt(D): the sign of each branch is known
        return [(root, 1, cond), (-root, -1, cond)]
    return [(normalize(base + root), None, cond), (normalize(base - root), None, cond)]


def _square_root(D, positive, keep_sign=True):
    r"""`\sqrt D`, factored, with square factors taken out: only those
    known to be positive (or even powers of squares) when ``keep_sign``,
    so that the sign of the result is that of the root; all of them
    otherwise (the pair `\pm\sqrt D` is the same either way)."""
    from .polynomials import positive_polynomial
    T, (f,) = translate_expressions([D])
    names = T.positive_names(positive)
    flat = T.flat_ring()
    if flat is None:
        return SR(D).sqrt()
    outside, inside = SR(1), SR(1)
    for part, sign in ((f.numerator(), 1), (f.denominator(), -1)):
        part = flat(part)
        if part.is_constant():
            inside *= SR(QQ(part.constant_coefficient())) ** sign
            continue
        F = part.factor()
        inside *= SR(QQ(F.unit())) ** sign
        for g, e in F:
            g_sr = T.symbolic(g)
            # sqrt(g^e) = |g|^(e/2): g^(e/2) when g > 0 (or when the sign
            # of the root does not matter), else only the even part of e/2
            out = e // 2 if positive_polynomial(g, names) or not keep_sign else 2 * (e // 4)
            outside *= g_sr ** (sign * out)
            inside *= g_sr ** (sign * (e - 2 * out))
    return outside * inside.sqrt()


def _implicit(T, prime, counted, positive):
    r"""A zero-dimensional component that is not written explicitly; its
    reality is decided by quantifier elimination where possible."""
    from .quantifier_elimination import exists_real_solution
    conditions, known = [], False
    # cylindrical algebraic decomposition is doubly exponential in the
    # number of variables: only small problems are tried, briefly
    if len(T.parameters()) + prime.ring().ngens() <= REALITY_QE_VARIABLES:
        try:
            conditions = exists_real_solution(T, prime, positive, timeout=REALITY_QE_TIMEOUT)
            known = True
        except AnalysisError:
            pass
    if conditions is None:
        return []
    return AlgebraicSolution(T, prime, [], counted, {}, {}, _defining(T, prime), conditions,
                             reality_known=known)


def _family(T, prime, free, counted, positive):
    r"""A component of positive dimension, parametrised by the unknowns
    ``free``, or ``None`` if it has no real points of that dimension (then
    its real points, if any, are found in its singular locus).

    A Gröbner basis in a block order -- the bound unknowns not counted
    (multipliers) above the bound counted ones above the free ones --
    gives: multipliers as rational functions of the variables where it has
    an equation linear in one multiplier; bound variables as rational
    functions of the free ones where it has an equation linear in them;
    the remaining equations are the relations of the family.

    A system solved with its multipliers last (:func:`_choose_order`: the
    basis with the multipliers first is the slow one there) gets its
    multipliers from its own equations instead
    (:func:`_family_from_equations`)."""
    P = prime.ring()
    free_gens = [g for i in free for g in _unit_generators(T, i)]
    bound = [g for g in P.gens() if g not in free_gens]
    if not bound:
        return AlgebraicSolution(T, prime, free, counted, {}, {}, [], [])
    index = {str(g): i for i in range(len(T.unknowns())) for g in _unit_generators(T, i)}
    upper = [g for g in bound if index[str(g)] not in counted]
    middle = [g for g in bound if index[str(g)] in counted]
    found = None
    if upper and _order_chosen(P):
        found = _family_from_equations(T, prime, upper, middle, positive)
    if found is None:
        found = _family_from_basis(T, prime, upper, middle, free_gens, positive)
    ring_values, relations, conditions = found
    circle = {str(r) for r in T.circle_relations()}
    relations = [r for r in relations if str(r) not in circle]
    real = None
    if any(all(not r.degree(v) for v in upper) for r in relations):
        real = _has_smooth_real_point(T, prime, len(free))
        if real is False:
            return None
    # multipliers in terms of the variables: put in the explicit ones
    for name in [str(g) for g in upper]:
        if name in ring_values:
            subs = {k: v for k, v in ring_values.items() if k != name}
            ring_values[name] = normalize(SR(ring_values[name]).subs(
                {T.symbolic_generators()[int(k[1:])]: v for k, v in subs.items()
                 if T.symbolic_generators()[int(k[1:])].is_symbol()}))
    values = _assemble(T, ring_values, {})
    # without parameters too: a search that found no smooth real point and
    # could not prove there is none (quantifier elimination too large, or
    # over its time) leaves the reality undecided, never taken for real
    return AlgebraicSolution(T, prime, free, counted, values, ring_values,
                             relations, conditions,
                             reality_known=real is not None or not relations)


def _family_from_basis(T, prime, upper, middle, free_gens, positive):
    r"""``(ring_values, relations, conditions)`` of a family from its
    Gröbner basis in the block order (multipliers ``upper``, lexicographic
    | bound counted ``middle`` | free), see :func:`_family`."""
    P = prime.ring()
    blocks = [(b, kind) for b, kind in ((upper, 'lex'), (middle, 'degrevlex'),
                                         (free_gens, 'degrevlex')) if b]
    order = TermOrder(blocks[0][1], len(blocks[0][0]))
    for b, kind in blocks[1:]:
        order = order + TermOrder(kind, len(b))
    names = [str(g) for b, _ in blocks for g in b]
    Pb = PolynomialRing(P.base_ring(), names, len(names), order=order)
    basis = _block_basis(Pb, [Pb(g) for g in prime.gens()], [Pb(str(g)) for g in upper])
    upper_b = [Pb(str(g)) for g in upper]
    middle_b = [Pb(str(g)) for g in middle]
    ring_values, relations, conditions = {}, [], []
    with_multipliers = [g for g in basis if any(g.degree(v) for v in upper_b)]
    solved = _multipliers_on_family(T, P, prime, with_multipliers, upper_b)
    if solved is None:
        relations += [P(g) for g in with_multipliers]
    else:
        for v, (value, denominator) in solved.items():
            ring_values[v] = value
            conditions = conjunction(conditions, nonzero_conditions(denominator, positive)) or []
    found = _bound_values(T, [P(g) for g in basis if all(not g.degree(v) for v in upper_b)],
                          [P(v) for v in middle_b], ring_values, positive)
    return ring_values, relations + found[0], conjunction(conditions, found[1]) or []


def _family_from_equations(T, prime, upper, middle, positive):
    r"""
    ``(ring_values, relations, conditions)`` of a family whose multipliers
    ``upper`` the equations of the system determine on it, or ``None``.

    The equations are linear in the multipliers (a Lagrange system), so on
    the component they are the values of :func:`_multipliers_on_family`
    with the equations themselves as the linear system, `\lambda = N/D`
    with `D` not vanishing on the component. Where `D \ne 0` the
    component is the graph of these values over the set where the prime's
    generators with `\lambda = N/D` put in vanish: its basis (in the order
    with the multipliers last) is the relations, the multipliers in them
    standing for their values -- no Gröbner basis with the multipliers
    first (the slow one for these systems), and no substitution into its
    large elements. Bound counted unknowns that a relation free of
    multipliers gives linearly in the free ones get their values.
    """
    P = prime.ring()
    # membership in the prime at random values of the parameters: a normal
    # form over their field took minutes (generic Kirchhoff)
    values = _multiplier_values(T, P, prime, T.equations(), upper,
                                member=membership_by_specialization(prime))
    if values is None:
        return None
    ring_values, conditions = {}, []
    for name, value in values.items():
        ring_values[name] = normalize(T.symbolic(value))
        conditions = conjunction(conditions, nonzero_conditions(
            T.symbolic(value.denominator()), positive)) or []
    basis = list(prime.groebner_basis())
    with_multipliers = [g for g in basis if any(g.degree(v) for v in upper)]
    relations, found = _bound_values(T, [g for g in basis if g not in with_multipliers],
                                     middle, ring_values, positive)
    return ring_values, with_multipliers + relations, conjunction(conditions, found) or []


def _bound_values(T, relations, middle, ring_values, positive):
    r"""The bound counted unknowns (``middle``) that one of ``relations``
    gives linearly in the others, put in ``ring_values``: returns the
    relations not used and the conditions (their coefficients nonzero)."""
    rest, conditions = [], []
    for g in relations:
        found = _linear_in(g, [v for v in middle if g.degree(v) > 0], middle)
        if found is not None and str(found[0]) not in ring_values:
            v, a, b = found
            a_sr, b_sr = T.symbolic(a), T.symbolic(b)
            ring_values[str(v)] = normalize(-b_sr / a_sr)
            conditions = conjunction(conditions, nonzero_conditions(a_sr, positive)) or []
        else:
            rest.append(g)
    return rest, conditions


def _block_basis(Pb, gens, upper):
    r"""
    A Gröbner basis of the ideal of ``gens`` in the block order of ``Pb``
    whose first (lexicographic) block is ``upper``. Where generators give
    the first variables of ``upper`` linearly (the multipliers, usually),
    the basis is the `x - v` (`v` free of them) together with a basis of
    what remains without them: the leading terms of the `x - v` are the
    `x` alone, prime to the others, so no S-polynomial is left -- and the
    (slow) basis over a field of parameters is computed without them.

    EXAMPLES::

        sage: from sage_dynsym.algebra.solving import _block_basis
        sage: P.<l, m, x, y> = PolynomialRing(QQ, order=TermOrder('lex', 2) + TermOrder('degrevlex', 2))
        sage: _block_basis(P, [x*l - y + l, x^2 - y], [l, m])
        [l*x + l - y, l*y - l - x*y + y, x^2 - y]
        sage: _block_basis(P, [2*l - y + x, x^2 - y, m*x - 1], [l, m])
        [l + 1/2*x - 1/2*y, m*x - 1, m*y - x, x^2 - y]

    A linear generator in a later multiplier only (``m``) is not used (its
    value could hold ``l``)::

        sage: _block_basis(P, [m - l*x, l^2 - y], [l, m])
        [l^2 - y, l*m - x*y, l*x - m, m^2 - x^2*y]
    """
    rest, substitutions = linear_substitutions(gens, variables=upper)
    left = [v for v in upper if all(v != x for x, _ in substitutions)]
    if substitutions and left and \
            max(Pb.gens().index(x) for x, _ in substitutions) > Pb.gens().index(left[0]):
        rest, substitutions = gens, []
    basis = list(Pb.ideal(rest).groebner_basis()) if rest else []
    reduced = [x - (Pb.ideal(basis).reduce(v) if basis else v) for x, v in substitutions]
    return sorted(reduced, reverse=True) + basis


def _multipliers_on_family(T, P, prime, elements, multipliers):
    r"""
    The multipliers (the generators ``multipliers`` of a block-order ring)
    on a family: the stationarity equations are linear in them, so the
    Gröbner basis elements that contain them are solved by linear algebra
    over the function field of the component. Returns ``{name: (value,
    denominator)}`` (symbolic), or ``None`` when they are not determined
    (or the solution does not hold on the whole component).
    """
    values = _multiplier_values(T, P, prime, elements, multipliers)
    if values is None:
        return None
    return {name: (normalize(T.symbolic(value)), T.symbolic(value.denominator()))
            for name, value in values.items()}


def _multiplier_values(T, P, prime, elements, multipliers, member=None):
    r"""The multipliers on the component of ``prime`` from the
    ``elements`` linear in them, as elements of the translation's flat
    fraction field ``{name: value}``, or ``None`` (see
    :func:`_multipliers_on_family`); ``member(f)`` tells whether ``f``
    lies in the prime (default: its normal form is zero)."""
    if not multipliers:
        return {}
    if member is None:
        def member(f):
            return prime.reduce(f) == 0
    F = T.fraction(SR(0)).parent()
    linear = [g for g in elements
              if all(sum(m.degree(v) for v in multipliers) <= 1 for m in g.monomials())]

    def flat(poly):
        num, den = T.to_flat(P(poly))
        return F(num) / F(den)

    rows, rhs = [], []
    for g in linear:
        coefficients = [g.coefficient({v: 1}) for v in multipliers]
        rest = g - sum(c * v for c, v in zip(coefficients, multipliers))
        rows.append([flat(c) for c in coefficients])
        rhs.append(-flat(rest))
    A = matrix(F, rows)
    if A.rank() < len(multipliers):
        return None
    # independent rows only: the others agree with them on the component
    # (its relations), not over the whole function field; the first rows
    # whose minor does not vanish on the component (on a component inside
    # the zero set of the first independent ones, others give the values)
    for pivots in combinations(range(A.nrows()), len(multipliers)):
        minor = A.matrix_from_rows(list(pivots)).det()
        if minor != 0 and not member(T.to_ring(T.flat_ring()(minor.numerator()))):
            break
    else:
        return None
    x = A.matrix_from_rows(list(pivots)).solve_right(
        matrix(F, [[rhs[k]] for k in pivots])).column(0)
    result = {}
    for v, value in zip(multipliers, x):
        # the value must make sense on the component: its denominator may
        # not vanish there
        if member(T.to_ring(T.flat_ring()(value.denominator()))):
            return None
        result[str(v)] = value
    # and it must solve every equation on the component (not only generically)
    at = _generators_at(T, P, result)
    for g in elements:
        value = _evaluate_in(T, P(g), at)
        if not member(T.to_ring(T.flat_ring()(value.numerator()))):
            return None
    return result


def _generators_at(T, P, values):
    r"""The generators of ``P`` as elements of the flat fraction field,
    those named in ``values`` replaced by their values there."""
    F = T.fraction(SR(0)).parent()
    return [values[str(w)] if str(w) in values else
            F(T.flat_ring()(T.to_flat(w)[0])) / F(T.flat_ring()(T.to_flat(w)[1]))
            for w in P.gens()]


def _evaluate_in(T, poly, at):
    r"""A polynomial of ``T.ring()`` at values in the flat fraction field."""
    F = T.fraction(SR(0)).parent()
    total = F(0)
    for exps, c in poly.dict().items():
        term = F(T.to_flat(c)[0]) / F(T.to_flat(c)[1])
        for k, e in enumerate(exps):
            if e:
                term *= at[k] ** e
        total += term
    return total


def _linear_in(g, candidates, block):
    r"""``(v, a, b)`` with ``g = a v + b`` when ``g`` contains exactly one of
    ``candidates``, to degree 1, and no other variable of ``block``."""
    if len(candidates) != 1 or g.degree(candidates[0]) != 1:
        return None
    v = candidates[0]
    if any(m.degree(v) and any(m.degree(w) for w in block if w != v) for m in g.monomials()):
        return None
    a = g.coefficient({v: 1})
    if any(a.degree(w) for w in block):
        return None
    return v, a, g - a * v


#: Random fibres tried when looking for a smooth real point of a family.
REAL_POINT_SAMPLES = 12


def _has_smooth_real_point(T, prime, dimension):
    r"""``True`` if a smooth real point of the component was found (it then
    has real points of full dimension), ``False`` if it has none (for a
    system without parameters: exact, by quantifier elimination when the
    random fibres show none), ``None`` if undecided."""
    from sage.misc.prandom import randint
    P = prime.ring()
    if T.field() is not QQ:
        return None
    gens = list(prime.gens())
    J = matrix(P, [[f.derivative(x) for x in P.gens()] for f in gens])
    rank = P.ngens() - (dimension + len(T.circle_relations()))
    free_sets = _free_generator_choice(T, prime, dimension)
    for attempt in range(REAL_POINT_SAMPLES):
        values = {}
        for gs in free_sets:
            t = QQ(randint(-6, 6)) / randint(1, 4)
            if len(gs) == 1:
                values[gs[0]] = t
            else:               # a rational point of the circle
                c, s = gs
                values[c], values[s] = (1 - t ** 2) / (1 + t ** 2), 2 * t / (1 + t ** 2)
        fibre = P.ideal([f.subs(values) for f in gens] + [g - v for g, v in values.items()])
        if fibre.dimension() != 0:
            continue
        for point in fibre.variety(AA):
            at = [point[k] for k in sorted(point, key=lambda k: [str(g) for g in P.gens()].index(str(k)))]
            if matrix(AA, [[f(*at) for f in row] for row in J.rows()]).rank() == rank:
                return True
    return None if not _small_for_qe(T, prime) else _qe_smooth_real_point(T, prime, J, rank)


def _free_generator_choice(T, prime, dimension):
    r"""Groups of ring variables (one unknown each) to fix in a fibre."""
    free = _free_unknowns(T, prime, set(range(len(T.unknowns()))))
    return [_unit_generators(T, i) for i in free[:dimension]]


def _small_for_qe(T, prime):
    return len(T.parameters()) + prime.ring().ngens() <= REALITY_QE_VARIABLES


def _qe_smooth_real_point(T, prime, J, rank):
    r"""Exact decision, by quantifier elimination, whether the component has
    a real point where the Jacobian has full rank."""
    from itertools import combinations
    from .quantifier_elimination import exists
    unknowns = [SR.var(f"qe_unknown{k}") for k in range(prime.ring().ngens())]
    subs = {g: u for g, u in zip(prime.ring().gens(), unknowns)}
    rows, cols = J.nrows(), J.ncols()
    minors = [J.matrix_from_rows_and_columns(r, c).det()
              for r in combinations(range(rows), rank) for c in combinations(range(cols), rank)]
    minors = [m for m in minors if m != 0]
    if not minors:
        return False
    equations = [T.symbolic(g, subs) == 0 for g in prime.gens()]
    try:
        for m in minors:
            if exists(unknowns, equations + [T.symbolic(m, subs) != 0],
                      timeout=REALITY_QE_TIMEOUT):
                return True
    except AnalysisError:
        return None
    return False


class TranscendentalSolution(AlgebraicSolution):
    r"""
    An isolated explicit solution found by :func:`solve_transcendental`.

    EXAMPLES::

        sage: from sage_dynsym.algebra.solving import solve_transcendental
        sage: x = var('x')
        sage: s = solve_transcendental([exp(x) - 2], [x])[0]; s
        Solution {x: log(2)} (dimension 0)
        sage: s.evaluate(exp(2*x)), s.contains(exp(x) - 2)
        (4, True)
    """

    def __init__(self, unknowns, values):
        self._unknowns = unknowns
        AlgebraicSolution.__init__(self, None, None, [], set(range(len(unknowns))),
                                   dict(enumerate(values)), {}, [], [])

    def values(self):
        return dict(zip(self._unknowns, [self._values[i] for i in range(len(self._unknowns))]))

    def free_unknowns(self):
        return []

    def substitutions(self):
        return self.values()

    def evaluate(self, expr):
        return normalize(SR(expr).subs(self.values()))

    def contains(self, expr):
        return self.evaluate(expr).is_zero()


def solve_transcendental(equations, unknowns, reason=None, positive=()):
    r"""
    The documented fallback for equations that are not algebraic in the
    unknowns (``exp``, ``log``, an angle also outside trigonometric
    functions, ...): Maxima's ``solve``, accepted only where every solution
    it returns is explicit and verified by substitution.

    The result is marked incomplete (:meth:`SolutionSet.is_complete` is
    ``False``): Maxima may miss solutions. When it returns an unsolved
    equation, a parametric family or nothing, an
    :class:`~sage_dynsym.errors.AnalysisError` says so -- an unsolved
    equation is never reported as a solution.

    EXAMPLES::

        sage: from sage_dynsym.algebra.solving import solve_transcendental
        sage: x, a = var('x a')
        sage: [s.values() for s in solve_transcendental([exp(x) - a], [x])]
        [{x: log(a)}]
        sage: solve_transcendental([x - cos(x)], [x])
        Traceback (most recent call last):
        ...
        AnalysisError: solve_exactly: the equations are not algebraic in x and Maxima's solve could not solve them: [x - cos(x)]
    """
    from sage.symbolic.relation import solve
    unknowns = [SR(u) for u in unknowns]
    equations = [SR(e) for e in equations]
    equations = [e.lhs() - e.rhs() if e.is_relational() else e for e in equations]
    why = f" ({reason})" if reason else ""
    failure = AnalysisError(
        f"the equations are not algebraic in {', '.join(map(str, unknowns))}{why} and "
        f"Maxima's solve could not solve them: {equations}", entry="solve_exactly")
    _log("transcendental equations: trying Maxima's solve")
    from .polynomials import maxima_without_questions
    try:
        with maxima_without_questions("solve_exactly", positive):
            found = solve([e == 0 for e in equations], *unknowns, solution_dict=True)
    except AnalysisError:
        raise       # Maxima asked for a sign (an AnalysisError is also a ValueError)
    except (TypeError, ValueError, NotImplementedError, RuntimeError) as err:
        raise failure from err
    solutions = []
    for sol in found:
        values = [SR(sol.get(u, u)) for u in unknowns]
        names = {str(u) for u in unknowns}
        if any(u not in sol for u in unknowns) or \
                any(str(v) in names for val in values for v in val.variables()):
            raise failure       # an unsolved equation echoed back
        known = set().union(*(set(map(str, e.variables())) for e in equations))
        if any(str(v) not in known for val in values for v in val.variables()):
            raise failure       # a free parameter r<N> / z<N> of Maxima: not isolated
        s = TranscendentalSolution(unknowns, values)
        if not all(s.contains(e) for e in equations):
            raise failure
        solutions.append(s)
    if not solutions:
        raise failure
    return SolutionSet_transcendental(unknowns, solutions, len(equations))
