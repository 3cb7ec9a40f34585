r"""
Integrals on an invariant level: polynomials modulo the ideal of the level

Some systems have an integral only on a level set of their Casimirs or
integrals: the Goryachev--Chaplygin top has a cubic integral on the level
`(M, \gamma) = 0` of the area integral. On a level `g_1 = c_1, \dots, g_k =
c_k` (each `g_j` a Casimir or an integral of `H`, so the level is
invariant) a polynomial `F` is an integral if `\{F, H\}` vanishes on it,
i.e. lies in the ideal `I = (g_1 - c_1, \dots, g_k - c_k)`.

With a Gröbner basis of `I` for a graded order, every polynomial of degree
`\le d` has a unique normal form, a combination of the *standard
monomials* (those not divisible by a leading monomial of the basis) of
degree `\le d`, and `F \equiv G` on the level iff their normal forms agree.
So the integrals on the level, modulo `I` and constants, are the kernel of
the linear map `F \mapsto \mathrm{NF}(\{F, H\})` on the span of the
standard monomials: computed as in :mod:`.integrals`, exactly, over the
field of the parameters.

EXAMPLES: the area integral is itself a level of a Casimir on `e(3)`; the
Goryachev--Chaplygin case `A = B = 4C` (here `C = 1`), centre of mass on
the first axis, on the level `(M, \gamma) = 0`::

    sage: from sage_dynsym.lie.algebras import lie_algebra
    sage: from sage_dynsym.lie.integrals import polynomial_integrals
    sage: E = lie_algebra('e3'); M1, M2, M3, g1, g2, g3 = E.variables()
    sage: c = var('c')
    sage: H = (M1^2 + M2^2 + 4*M3^2)/8 + c*g1
    sage: polynomial_integrals(E, H, 3, new_only=True)
    []
    sage: polynomial_integrals(E, H, 3, new_only=True, levels={M1*g1 + M2*g2 + M3*g3: 0})
    [M1^2*M3 + M2^2*M3 - 4*M1*c*gamma3]

REFERENCES:

- D. N. Goryachev, On the motion of a heavy rigid body about a fixed point
  in the case A = B = 4C, *Mat. Sb.* 21 (1900) 431--438; S. A. Chaplygin,
  A new particular solution of the problem of the rotation of a heavy rigid
  body about a fixed point (1901).
- A. V. Borisov, I. S. Mamaev, *Rigid Body Dynamics*, De Gruyter, 2018,
  ch. 2 (integrable cases on a level of the area integral).
- D. Cox, J. Little, D. O'Shea, *Ideals, Varieties, and Algorithms*,
  Springer, 4th ed., 2015, ch. 5, §3 (normal forms and standard monomials).
"""
from sage.arith.functions import lcm
from sage.rings.polynomial.polynomial_ring_constructor import PolynomialRing
from sage.symbolic.ring import SR

from ..errors import AnalysisError
from ..algebra.polynomial_spaces import LinearProblem

__all__ = ['InvariantLevel']


class InvariantLevel:
    r"""
    The level `g_j = c_j` of some integrals, for the searches of
    :mod:`.integrals`: the Gröbner basis of its ideal, normal forms, and
    the linear problems of the integrals modulo the ideal.

    INPUT:

    - ``search`` -- the search of :mod:`.integrals` (its polynomial context
      and the vector field `J\nabla H`)
    - ``levels`` -- dict ``{g: c}``, ``g`` a polynomial in the variables,
      ``c`` a value (number or expression in the parameters)

    EXAMPLES::

        sage: from sage_dynsym.lie.algebras import lie_algebra
        sage: from sage_dynsym.lie.integrals import _Search
        sage: from sage_dynsym.lie.levels import InvariantLevel
        sage: E = lie_algebra('so3'); M1, M2, M3 = E.variables()
        sage: level = InvariantLevel(_Search(E, (M1^2 + M2^2 + M3^2)/2), {M1^2 + M2^2 + M3^2: 1})
        sage: level.groebner_basis()
        [M1^2 + M2^2 + M3^2 - 1]

    TESTS::

        sage: InvariantLevel(_Search(E, M1^2/2 + M2^2), {M3: 0})
        Traceback (most recent call last):
        ...
        AnalysisError: levels: the level M3 == 0 is not invariant: the bracket of M3 with H is M1*M2, not zero on the level
        sage: InvariantLevel(_Search(E, M1^2/2 + M2^2), {M1^2 + M2^2 + M3^2: 1, 1: 2})
        Traceback (most recent call last):
        ...
        AnalysisError: levels: the level {M1^2 + M2^2 + M3^2: 1, 1: 2} is empty (its equations are inconsistent)
    """

    def __init__(self, search, levels):
        self.search = search
        P = search.context
        self.context = P
        self.ring = PolynomialRing(P.field, [str(v) for v in P.variables], order='degrevlex')
        gens = []
        for g, value in levels.items():
            f, _ = P.element(SR(g) - SR(value), "levels")
            gens.append(self.lift(f))
        ideal = self.ring.ideal(gens)
        if ideal.is_one():
            raise AnalysisError(f"the level {levels} is empty (its equations are "
                                "inconsistent)", entry="levels")
        self._gb = list(ideal.groebner_basis())
        self._leading = [g.lm().exponents()[0] for g in self._gb]
        X = [self.lift(x) for x in search.X]
        self._X = X
        for g, value in levels.items():
            f = self.lift(P.element(SR(g), "levels")[0])
            bracket = self.reduce(self._bracket(f))
            if bracket != 0:
                raise AnalysisError(
                    f"the level {SR(g)} == {SR(value)} is not invariant: the bracket of "
                    f"{SR(g)} with H is {self._true_bracket(f)}, not zero on the "
                    "level", entry="levels")
        self._problems = {}

    def groebner_basis(self):
        r"""The Gröbner basis of the ideal of the level, as symbolic
        expressions.

        EXAMPLES: see the class documentation.
        """
        return [self.symbolic(g) for g in self._gb]

    def lift(self, f):
        r"""A polynomial of the search's ring (parameters and variables) as
        an element of the ring over the field of the parameters.

        EXAMPLES::

            sage: from sage_dynsym.lie.algebras import lie_algebra
            sage: from sage_dynsym.lie.integrals import _Search
            sage: from sage_dynsym.lie.levels import InvariantLevel
            sage: E = lie_algebra('so3'); M1, M2, M3 = E.variables()
            sage: level = InvariantLevel(_Search(E, (M1^2 + M2^2 + M3^2)/2), {M1^2 + M2^2 + M3^2: 1})
            sage: level.lift(level.context.ring('M1^2'))
            M1^2
        """
        P = self.context
        n = P.np
        parameters = [P.field(a) for a in P.coefficients.gens()] if n else []
        result = self.ring.zero()
        for exps, c in f.dict().items():
            coefficient = P.field(c)
            for a, k in zip(parameters, exps[:n]):
                coefficient *= a ** k
            result += coefficient * self.ring.monomial(*exps[n:])
        return result

    def symbolic(self, f):
        r"""A polynomial of the level's ring as a symbolic expression.

        EXAMPLES::

            sage: from sage_dynsym.lie.algebras import lie_algebra
            sage: from sage_dynsym.lie.integrals import _Search
            sage: from sage_dynsym.lie.levels import InvariantLevel
            sage: E = lie_algebra('so3'); M1, M2, M3 = E.variables()
            sage: level = InvariantLevel(_Search(E, (M1^2 + M2^2 + M3^2)/2), {M1^2 + M2^2 + M3^2: 1})
            sage: level.symbolic(level.ring('M1*M2 - 1')).parent()
            Symbolic Ring
        """
        P = self.context
        return sum((SR(c) * SR(P.to_sr({tuple(m): 1})) for m, c in
                    zip(f.exponents(), f.coefficients())), SR(0))

    def reduce(self, f):
        r"""The normal form of ``f`` (in the level's ring).

        EXAMPLES::

            sage: from sage_dynsym.lie.algebras import lie_algebra
            sage: from sage_dynsym.lie.integrals import _Search
            sage: from sage_dynsym.lie.levels import InvariantLevel
            sage: E = lie_algebra('so3'); M1, M2, M3 = E.variables()
            sage: level = InvariantLevel(_Search(E, (M1^2 + M2^2 + M3^2)/2), {M1^2 + M2^2 + M3^2: 1})
            sage: level.reduce(level.ring('M1^2 + 2'))
            -M2^2 - M3^2 + 3
        """
        return f.reduce(self._gb)

    def _true_bracket(self, f):
        # X is J grad H times the denominators cleared by the search
        return (self.symbolic(self._bracket(f)) / SR(self.search.denominator)).expand()

    def _bracket(self, f):
        return sum(f.derivative(x) * X for x, X in zip(self.ring.gens(), self._X))

    def is_standard(self, m):
        r"""Whether the monomial (exponent tuple) is not divisible by a
        leading monomial of the Gröbner basis.

        EXAMPLES::

            sage: from sage_dynsym.lie.algebras import lie_algebra
            sage: from sage_dynsym.lie.integrals import _Search
            sage: from sage_dynsym.lie.levels import InvariantLevel
            sage: E = lie_algebra('so3'); M1, M2, M3 = E.variables()
            sage: level = InvariantLevel(_Search(E, (M1^2 + M2^2 + M3^2)/2), {M1^2 + M2^2 + M3^2: 1})
            sage: level.is_standard((2, 0, 0)), level.is_standard((1, 1, 0))
            (False, True)
        """
        return not any(all(a >= b for a, b in zip(m, lead)) for lead in self._leading)

    def vector(self, f):
        r"""The normal form of a polynomial of the search's ring, as a vector
        (constant dropped).

        EXAMPLES::

            sage: from sage_dynsym.lie.algebras import lie_algebra
            sage: from sage_dynsym.lie.integrals import _Search
            sage: from sage_dynsym.lie.levels import InvariantLevel
            sage: E = lie_algebra('so3'); M1, M2, M3 = E.variables()
            sage: level = InvariantLevel(_Search(E, (M1^2 + M2^2 + M3^2)/2), {M1^2 + M2^2 + M3^2: 1})
            sage: sorted(level.vector(level.context.ring('M1^2')).items())
            [((0, 0, 2), -1), ((0, 2, 0), -1)]
        """
        g = self.reduce(self.lift(f))
        return {tuple(m): c for m, c in zip(g.exponents(), g.coefficients()) if any(m)}

    def problem(self, d):
        r"""
        The linear problem `F \mapsto \mathrm{NF}(\{F, H\})` on the standard
        monomials of degree `1..d` (images cleared of the denominators of
        the parameters by one common factor, which leaves the kernel as it
        is). Cached.

        EXAMPLES::

            sage: from sage_dynsym.lie.algebras import lie_algebra
            sage: from sage_dynsym.lie.integrals import _Search
            sage: from sage_dynsym.lie.levels import InvariantLevel
            sage: E = lie_algebra('so3'); M1, M2, M3 = E.variables()
            sage: level = InvariantLevel(_Search(E, (M1^2 + M2^2 + M3^2)/2), {M1^2 + M2^2 + M3^2: 1})
            sage: level.problem(2).columns        # the standard monomials of degree <= 2
            [(1, 1, 0), (1, 0, 1), (0, 2, 0), (0, 1, 1), (0, 0, 2), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
            sage: len(level.problem(2).kernel())  # H is a Casimir: all are integrals
            8
        """
        if d not in self._problems:
            P = self.context
            columns = [m for m in P.monomials(d) if self.is_standard(m)]
            normal = [self.reduce(self._bracket(self.ring.monomial(*m))) for m in columns]
            denominators = [c.denominator() for g in normal for c in g.coefficients()] \
                if P.np else []
            D = lcm(denominators) if denominators else 1
            images = []
            for g in normal:
                image = {}
                for m, c in zip(g.exponents(), g.coefficients()):
                    c = c * D
                    image[tuple(m)] = P.coefficients(c.numerator()) if P.np else c
                images.append(image)
            self._problems[d] = LinearProblem(P, columns, images)
        return self._problems[d]
