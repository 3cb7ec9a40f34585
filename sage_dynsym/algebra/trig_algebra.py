r"""
The algebra of trigonometric polynomials, a Sage parent

Polynomials over `\QQ` in parameters and in the cosines and sines `c_i,
s_i` of angles `\theta_i`, modulo the relations `c_i^2 + s_i^2 = 1`:

.. MATH::

    A = \QQ[c_1, s_1, \dots, c_k, s_k, p_1, \dots, p_m] \,/\,
        (c_1^2 + s_1^2 - 1, \dots, c_k^2 + s_k^2 - 1).

The generators of the ideal are a Gröbner basis (their leading monomials
`c_i^2` are coprime), so every class has one representative of degree at
most one in each `c_i`: the elements of :class:`TrigAlgebra` are those
representatives (computed in linear time by
:func:`~sage_dynsym.algebra.trigonometric.circle_reduce`), equal exactly when
they are equal as functions. Each `c_i^2 + s_i^2 - 1` is irreducible and the
ideal is prime, so `A` is an integral domain.

Symbolic expressions convert into the algebra (``A(expr)``: the walk of
:mod:`~sage_dynsym.algebra.expression_walk`; sines and cosines of integer
multiples of the angles that are symbols, and of their sums, are expanded;
an expression that is not a polynomial in the generators raises
:class:`~sage_dynsym.algebra.trigonometric.NotPolynomial`) and elements
back (``SR(x)``, in the recursive form of
:meth:`~sage_dynsym.algebra.trigonometric.TrigPolynomialRing.to_symbolic`).
The arithmetic underneath -- the Singular polynomial ring of the
representatives (:meth:`TrigAlgebra.cover_ring`), what a kinematics backend
computes in before one reduction at the end -- is
:class:`~sage_dynsym.algebra.trigonometric.TrigPolynomialRing`
(:meth:`TrigAlgebra.polynomial_ring`); fractions and their linear algebra
are :class:`~sage_dynsym.algebra.trig_linear.TrigFractionField`.

EXAMPLES::

    sage: from sage_dynsym.algebra.trig_algebra import TrigAlgebra
    sage: a, b, m = var('a b m')
    sage: A = TrigAlgebra([a, b], [m]); A
    Algebra of polynomials in cos(a), cos(b), sin(a), sin(b), m over Rational Field modulo cos^2 + sin^2 = 1
    sage: x = A(m*cos(a)^2 + m*sin(a)^2*cos(b)^2 + m*sin(a)^2*sin(b)^2); x
    m
    sage: x == A(m), A(cos(a)^3)
    (True, -(sin(a)^2 - 1)*cos(a))
    sage: c, s = A.trig(a); SR(c^2 + s^2)
    1
    sage: latex(A(m*sin(a)))
    m \sin\left(a\right)
    sage: TestSuite(A).run()

Multiple angles and sums are expanded::

    sage: A(sin(2*a - b)), A(cos(a + b)^2 - cos(a - b)^2) == A(-sin(2*a)*sin(2*b))
    (2*cos(a)*cos(b)*sin(a) + 2*sin(a)^2*sin(b) - sin(b), True)

Expressions that are not polynomial in the generators are refused::

    sage: A(1/m)
    Traceback (most recent call last):
    ...
    NotPolynomial: 1/m is not polynomial in the rotation variables and parameters

REFERENCES:

- D. Cox, J. Little, D. O'Shea, *Ideals, Varieties, and Algorithms*, 4th
  ed., Springer, 2015, ch. 2 (normal forms modulo a Gröbner basis) and
  ch. 5 §2 (quotient rings `k[x]/I`).
"""
from sage.categories.commutative_algebras import CommutativeAlgebras
from sage.categories.fields import Fields
from sage.misc.latex import latex
from sage.rings.integer_ring import ZZ
from sage.rings.rational_field import QQ
from sage.structure.element import CommutativeAlgebraElement, Element
from sage.structure.parent import Parent
from sage.structure.richcmp import richcmp
from sage.structure.unique_representation import UniqueRepresentation
from sage.symbolic.expression import Expression
from sage.symbolic.ring import SR

from ..errors import AnalysisError
from .trigonometric import TrigPolynomialRing, NotPolynomial

__all__ = ['TrigAlgebra', 'TrigAlgebraElement', 'TrigFractions', 'TrigFraction']


class TrigAlgebraElement(CommutativeAlgebraElement):
    r"""
    An element of a :class:`TrigAlgebra`: a polynomial of its
    :meth:`~TrigAlgebra.cover_ring` of degree at most one in every cosine.

    EXAMPLES::

        sage: from sage_dynsym.algebra.trig_algebra import TrigAlgebra
        sage: a, m = var('a m'); A = TrigAlgebra([a], [m])
        sage: x = A(m*cos(a)^2); x, x.lift()
        (-(sin(a)^2 - 1)*m, -dynsymsin0^2*m + m)
        sage: TestSuite(x).run()
    """

    def __init__(self, parent, lift):
        r"""
        INPUT:

        - ``parent`` -- a :class:`TrigAlgebra`
        - ``lift`` -- a reduced polynomial of its cover ring

        TESTS::

            sage: from sage_dynsym.algebra.trig_algebra import TrigAlgebra
            sage: A = TrigAlgebra([var('a')], []); A(cos(a)^2).lift().degree(A.cover_ring().gen(0))
            0
        """
        CommutativeAlgebraElement.__init__(self, parent)
        self._lift = lift

    def lift(self):
        r"""The representative: a polynomial of the cover ring, of degree at
        most one in every cosine.

        EXAMPLES::

            sage: from sage_dynsym.algebra.trig_algebra import TrigAlgebra
            sage: a = var('a'); TrigAlgebra([a], [])(cos(a)^3).lift()
            -dynsymcos0*dynsymsin0^2 + dynsymcos0
        """
        return self._lift

    def _symbolic_(self, ring):
        r"""The element as a symbolic expression (``SR(x)``).

        EXAMPLES::

            sage: from sage_dynsym.algebra.trig_algebra import TrigAlgebra
            sage: a, m = var('a m'); A = TrigAlgebra([a], [m])
            sage: SR(A(m*cos(a) + m*sin(a)^2 + m*cos(a)^2))
            m*(cos(a) + 1)
        """
        return ring(self.parent().polynomial_ring().to_symbolic(self._lift, reduced=True))

    def _repr_(self):
        return repr(self._symbolic_(SR))

    def _latex_(self):
        return latex(self._symbolic_(SR))

    def _new(self, lift):
        return self.parent().element_class(self.parent(), lift)

    def _add_(self, other):
        # sums and differences of representatives are representatives
        return self._new(self._lift + other.lift())

    def _sub_(self, other):
        return self._new(self._lift - other.lift())

    def _neg_(self):
        return self._new(-self._lift)

    def _mul_(self, other):
        return self._new(self.parent().polynomial_ring().reduce(self._lift * other.lift()))

    def _div_(self, other):
        r"""
        Division by a nonzero rational number (the units of the algebra);
        fractions are :class:`~sage_dynsym.algebra.trig_linear.TrigFractionField`.

        EXAMPLES::

            sage: from sage_dynsym.algebra.trig_algebra import TrigAlgebra
            sage: a = var('a'); A = TrigAlgebra([a], [])
            sage: A(cos(a)) / 2
            1/2*cos(a)
            sage: A(1) / A(cos(a))
            Traceback (most recent call last):
            ...
            NotPolynomial: TrigAlgebra: 1/(cos(a)) is not in the algebra (only nonzero rational numbers divide); divide in A.fraction_field()
        """
        divisor = other.lift()
        if divisor.is_constant() and not divisor.is_zero():
            return self._new(self._lift / divisor.constant_coefficient())
        raise NotPolynomial(f"TrigAlgebra: {self}/({other}) is not in the algebra (only nonzero "
                            "rational numbers divide); divide in A.fraction_field()")

    def _richcmp_(self, other, op):
        # the representatives are a normal form: equal elements, equal lifts
        return richcmp(self._lift, other.lift(), op)

    def __hash__(self):
        return hash(self._lift)

    def __bool__(self):
        return not self._lift.is_zero()

    def __reduce__(self):
        return self.parent(), (self._lift,)


class TrigAlgebra(UniqueRepresentation, Parent):
    r"""
    The algebra of polynomials over `\QQ` in the cosines and sines of
    ``angles`` and in ``symbols`` and ``atoms``, modulo `\cos^2 + \sin^2 =
    1` for every angle (see the module documentation).

    INPUT:

    - ``angles`` -- the angles (symbolic expressions; an angle and its
      negative share a pair, a constant angle whose sine and cosine
      evaluate has none)
    - ``symbols`` -- the other symbols
    - ``atoms`` -- (default: none) other non-polynomial parts held as
      generators (`\pi`, `\sqrt 2`, `1/m`, ...)

    or ``TrigAlgebra(R)``: the algebra of the
    :class:`~sage_dynsym.algebra.trigonometric.TrigPolynomialRing` ``R``
    (what a kinematics backend computes in).

    EXAMPLES::

        sage: from sage_dynsym.algebra.trig_algebra import TrigAlgebra
        sage: t, w, x = var('t w x')
        sage: A = TrigAlgebra([w*t], [x], [sqrt(2)]); A.gens()
        (cos(t*w), sin(t*w), x, sqrt(2))
        sage: A(x*cos(-w*t)^2 + x*sin(w*t)^2 - sqrt(2)*sin(-w*t))
        sqrt(2)*sin(t*w) + x
        sage: A is TrigAlgebra([w*t], [x], [sqrt(2)]) is TrigAlgebra(A.polynomial_ring())
        True
        sage: TestSuite(A).run()

    TESTS::

        sage: A('x')
        Traceback (most recent call last):
        ...
        AnalysisError: TrigAlgebra: expected a symbolic expression, a rational number or a polynomial of the cover ring, got 'x' (str)
    """
    Element = TrigAlgebraElement

    @staticmethod
    def __classcall_private__(cls, angles=(), symbols=(), atoms=()):
        # keyed by the normalized polynomial ring: equal algebras are one object
        ring = (angles if isinstance(angles, TrigPolynomialRing)
                else TrigPolynomialRing(angles, symbols, atoms))
        return super().__classcall__(cls, ring)

    def __init__(self, ring):
        r"""
        TESTS::

            sage: from sage_dynsym.algebra.trig_algebra import TrigAlgebra
            sage: TrigAlgebra([var('a')], []).category()
            Category of commutative algebras over Rational Field
        """
        self._ring = ring
        Parent.__init__(self, base=QQ, category=CommutativeAlgebras(QQ))
        self._populate_coercion_lists_(coerce_list=[ring.ring])

    @classmethod
    def for_expressions(cls, expressions, dynamic=()):
        r"""
        The algebra holding ``expressions``: a pair for every argument of a
        sine or cosine, a generator for every symbol and every other
        non-polynomial part (see
        :meth:`~sage_dynsym.algebra.trigonometric.TrigPolynomialRing.for_expressions`).

        EXAMPLES::

            sage: from sage_dynsym.algebra.trig_algebra import TrigAlgebra
            sage: a, g, l = var('a g l')
            sage: A = TrigAlgebra.for_expressions([sqrt(g/l)*cos(a)]); A.gens()
            (cos(a), sin(a), a, sqrt(g/l))

        (The symbols of the angles are generators too: their derivatives
        are.)
        """
        ring = TrigPolynomialRing.for_expressions(expressions, dynamic)
        return cls(ring.angles(), ring.symbols(), ring.atoms())

    def _repr_(self):
        return (f"Algebra of polynomials in {', '.join(map(str, self.gens()))} over "
                f"{self.base_ring()} modulo cos^2 + sin^2 = 1")

    def _latex_(self):
        gens = ', '.join(latex(SR(g)) for g in self.gens())
        return r"\Bold{Q}[%s] / (\cos^2 + \sin^2 - 1)" % gens

    def polynomial_ring(self):
        r"""The :class:`~sage_dynsym.algebra.trigonometric.TrigPolynomialRing`
        underneath: conversions and reduction on representatives.

        EXAMPLES::

            sage: from sage_dynsym.algebra.trig_algebra import TrigAlgebra
            sage: TrigAlgebra([var('a')], []).polynomial_ring().angles()
            [a]
        """
        return self._ring

    def cover_ring(self):
        r"""The Singular polynomial ring of the representatives.

        EXAMPLES::

            sage: from sage_dynsym.algebra.trig_algebra import TrigAlgebra
            sage: TrigAlgebra([var('a')], [var('m')]).cover_ring()
            Multivariate Polynomial Ring in dynsymcos0, dynsymsin0, m over Rational Field
        """
        return self._ring.ring

    def _element_constructor_(self, x):
        if isinstance(x, Element) and x.parent() is self.cover_ring():
            return self.element_class(self, self._ring.reduce(x))
        if isinstance(x, Expression):
            return self.element_class(self, self._ring.reduce(self._ring.convert(x,
                                                                                  multiples=True)))
        if x in QQ:
            return self.element_class(self, self.cover_ring()(QQ(x)))
        raise AnalysisError("expected a symbolic expression, a rational number or a "
                            f"polynomial of the cover ring, got {x!r} ({type(x).__name__})",
                            entry="TrigAlgebra")

    def ngens(self):
        r"""The number of generators: two per angle, one per symbol and atom.

        EXAMPLES::

            sage: from sage_dynsym.algebra.trig_algebra import TrigAlgebra
            sage: TrigAlgebra([var('a')], [var('m')]).ngens()
            3
        """
        return self.cover_ring().ngens()

    def gens(self):
        r"""The generators: the cosines, the sines, the symbols, the atoms.

        EXAMPLES::

            sage: from sage_dynsym.algebra.trig_algebra import TrigAlgebra
            sage: TrigAlgebra([var('a'), var('b')], [var('m')]).gens()
            (cos(a), cos(b), sin(a), sin(b), m)
        """
        return tuple(self(g) for g in self.cover_ring().gens())

    def gen(self, i=0):
        r"""The generator of index ``i`` (see :meth:`gens`).

        EXAMPLES::

            sage: from sage_dynsym.algebra.trig_algebra import TrigAlgebra
            sage: TrigAlgebra([var('a')], [var('m')]).gen(2)
            m
        """
        return self.gens()[i]

    def trig(self, angle):
        r"""The pair `(\cos, \sin)` of ``angle`` as elements.

        EXAMPLES::

            sage: from sage_dynsym.algebra.trig_algebra import TrigAlgebra
            sage: a = var('a'); TrigAlgebra([a], []).trig(-a)
            (cos(a), -sin(a))
        """
        return tuple(self(x) for x in self._ring.trig(angle))

    def angles(self):
        r"""The angles whose cosine and sine are generators.

        EXAMPLES::

            sage: from sage_dynsym.algebra.trig_algebra import TrigAlgebra
            sage: TrigAlgebra([var('a'), -var('a'), pi/2], []).angles()
            [a]
        """
        return self._ring.angles()

    def characteristic(self):
        r"""Zero: the algebra contains `\QQ`.

        EXAMPLES::

            sage: from sage_dynsym.algebra.trig_algebra import TrigAlgebra
            sage: TrigAlgebra([var('a')], []).characteristic()
            0
        """
        return ZZ.zero()

    def is_integral_domain(self, proof=True):
        r"""``True``: every `c^2 + s^2 - 1` is irreducible and they involve
        disjoint variables, so the ideal is prime.

        EXAMPLES::

            sage: from sage_dynsym.algebra.trig_algebra import TrigAlgebra
            sage: TrigAlgebra([var('a')], []).is_integral_domain()
            True
        """
        return True

    def some_elements(self):
        r"""A few elements for the tests: the generators, a sum, a
        polynomial of degree two, a product of three factors.

        EXAMPLES::

            sage: from sage_dynsym.algebra.trig_algebra import TrigAlgebra
            sage: a = var('a'); TrigAlgebra([a], []).some_elements()
            [0, 1, cos(a), sin(a), cos(a) + sin(a), 1/2*(4*sin(a) - 1)*cos(a),
             (sin(a) + 1)*cos(a) + sin(a) + 1]
        """
        gens = list(self.gens())
        elements = [self.zero(), self.one()] + gens
        # (the category checks run over triples of these: a few suffice)
        for g, h in zip(gens[:1], gens[1:2]):
            elements += [g + h, 2 * g * h - g / 2]
        product = self.one()
        for g in gens[:3]:
            product *= g + 1
        return elements + [product]

    def fraction_field(self):
        r"""The field of fractions of the algebra (an integral domain): a
        :class:`TrigFractions`.

        EXAMPLES::

            sage: from sage_dynsym.algebra.trig_algebra import TrigAlgebra
            sage: a = var('a'); K = TrigAlgebra([a], []).fraction_field(); K
            Fractions of Algebra of polynomials in cos(a), sin(a) over Rational Field modulo cos^2 + sin^2 = 1
            sage: K(sin(a)^2/(1 - cos(a)))
            cos(a) + 1
        """
        return TrigFractions(self)

    def _test_circle(self, **options):
        r"""
        `c^2 + s^2` is `1` for every angle, and the representatives have
        degree at most one in each cosine.

        EXAMPLES::

            sage: from sage_dynsym.algebra.trig_algebra import TrigAlgebra
            sage: TrigAlgebra([var('a'), var('b')], [var('m')])._test_circle()
        """
        tester = self._tester(**options)
        for angle in self.angles():
            c, s = self.trig(angle)
            tester.assertEqual(c * c + s * s, self.one())
            cosine = c.lift()
            for x in tester.some_elements():
                tester.assertLessEqual((x * x).lift().degree(cosine), 1)

    def _test_symbolic_roundtrip(self, **options):
        r"""
        From the symbolic ring and back gives the same expression; to the
        symbolic ring and back is the identity when there are no atoms (an
        atom such as `\sqrt 2` is an independent generator of the algebra,
        but the symbolic ring knows `\sqrt 2^2 = 2`).

        EXAMPLES::

            sage: from sage_dynsym.algebra.trig_algebra import TrigAlgebra
            sage: TrigAlgebra([var('a')], [var('m')])._test_symbolic_roundtrip()
            sage: A = TrigAlgebra([var('a')], [var('m')], [sqrt(2)])
            sage: A._test_symbolic_roundtrip()
            sage: x = A.gen(3); x, A(SR(x*x)) == x*x
            (sqrt(2), False)
        """
        tester = self._tester(**options)
        for x in tester.some_elements():
            e = SR(x)
            tester.assertTrue((SR(self(e)) - e).expand().is_trivial_zero())
            if not self._ring.atoms():
                tester.assertEqual(self(e), x)


class TrigFraction(Element):
    r"""
    An element of :class:`TrigFractions`: a fraction of polynomials of the
    cover ring. The arithmetic is that of the fractions (Singular's, the
    greatest common divisors cancelled); the reduction modulo
    `\cos^2 + \sin^2 = 1` is done by :meth:`normal`, and by the comparisons
    (so that ``x == 0`` exactly when ``x`` vanishes as a function).

    EXAMPLES::

        sage: from sage_dynsym.algebra.trig_algebra import TrigAlgebra
        sage: a, m = var('a m'); K = TrigAlgebra([a], [m]).fraction_field()
        sage: x = K(cos(a))^2 + K(sin(a))^2; x.numerator()
        dynsymcos0^2 + dynsymsin0^2
        sage: x == 1, x.normal().numerator()
        (True, 1)
        sage: TestSuite(x).run()
    """

    def __init__(self, parent, value):
        r"""
        INPUT:

        - ``parent`` -- a :class:`TrigFractions`
        - ``value`` -- an element of the fraction field of the cover ring

        TESTS::

            sage: from sage_dynsym.algebra.trig_algebra import TrigAlgebra
            sage: K = TrigAlgebra([var('a')], []).fraction_field(); K(1/2), K(1/2).numerator()
            (1/2, 1/2)
        """
        Element.__init__(self, parent)
        self._value = value

    def numerator(self):
        r"""The numerator, a polynomial of the cover ring.

        EXAMPLES::

            sage: from sage_dynsym.algebra.trig_algebra import TrigAlgebra
            sage: a = var('a'); x = TrigAlgebra([a], []).fraction_field()(cos(a)/sin(a))
            sage: x.numerator(), x.denominator()
            (dynsymcos0, dynsymsin0)
        """
        return self._value.numerator()

    def denominator(self):
        r"""The denominator, a polynomial of the cover ring.

        EXAMPLES: see :meth:`numerator`.
        """
        return self._value.denominator()

    def normal(self):
        r"""The fraction with numerator and denominator reduced modulo
        `\cos^2 + \sin^2 = 1` and their common factors cancelled.

        EXAMPLES::

            sage: from sage_dynsym.algebra.trig_algebra import TrigAlgebra
            sage: a = var('a'); K = TrigAlgebra([a], []).fraction_field()
            sage: x = K(cos(a)^2 - 1) / K(sin(a)); x.numerator(), x.normal().numerator()
            (dynsymcos0^2 - 1, -dynsymsin0)
        """
        reduce, field = self.parent().algebra().polynomial_ring().reduce, self._value.parent()
        return self._new(field(reduce(self.numerator())) / field(reduce(self.denominator())))

    def _new(self, value):
        return self.parent().element_class(self.parent(), value)

    def _add_(self, other):
        return self._new(self._value + other._value)

    def _sub_(self, other):
        return self._new(self._value - other._value)

    def _neg_(self):
        return self._new(-self._value)

    def _mul_(self, other):
        return self._new(self._value * other._value)

    def _div_(self, other):
        r"""
        The quotient; a divisor that vanishes as a function (modulo the
        circle relations, even if its numerator is not the zero polynomial)
        raises ``ZeroDivisionError``.

        EXAMPLES::

            sage: from sage_dynsym.algebra.trig_algebra import TrigAlgebra
            sage: a = var('a'); K = TrigAlgebra([a], []).fraction_field()
            sage: K(sin(a)) / K(cos(a)), ~K(cos(a))
            (sin(a)/cos(a), 1/cos(a))
            sage: K(1) / K(cos(a)^2 + sin(a)^2 - 1)
            Traceback (most recent call last):
            ...
            ZeroDivisionError: TrigFractions: cos(a)^2 + sin(a)^2 - 1 is zero modulo cos^2 + sin^2 = 1
        """
        return self._new(self._value / other._nonzero()._value)

    def __invert__(self):
        return self._new(~self._nonzero()._value)

    def _nonzero(self):
        if not self:
            # the numerator as written (reduced it would print 0)
            written = self.parent().algebra().polynomial_ring().to_symbolic(self.numerator(),
                                                                            reduced=True)
            raise ZeroDivisionError(f"TrigFractions: {written} is zero modulo "
                                    "cos^2 + sin^2 = 1")
        return self

    def __bool__(self):
        return not self.parent().algebra().polynomial_ring().reduce(self.numerator()).is_zero()

    def _richcmp_(self, other, op):
        # a field of functions: equality (zero difference modulo the circle
        # relations) is the only comparison
        difference = bool(self._sub_(other))
        return richcmp(difference, False, op)

    def __hash__(self):
        # equal fractions have the same reduced, cancelled, monic form
        x = self.normal()
        unit = x.denominator().lc()
        return hash((x.numerator() / unit, x.denominator() / unit))

    def _symbolic_(self, ring):
        r"""The fraction as a symbolic expression, in the shortest form found
        (see :meth:`~sage_dynsym.algebra.trigonometric.TrigPolynomialRing.simplest_fraction`).

        EXAMPLES::

            sage: from sage_dynsym.algebra.trig_algebra import TrigAlgebra
            sage: a, m = var('a m'); K = TrigAlgebra([a], [m]).fraction_field()
            sage: SR(K(m*sin(a)^2)/K(m - m*cos(a)))
            cos(a) + 1
        """
        return ring(self.parent().algebra().polynomial_ring().simplest_fraction(
            self.numerator(), self.denominator()))

    def _repr_(self):
        return repr(self._symbolic_(SR))

    def _latex_(self):
        return latex(self._symbolic_(SR))

    def __reduce__(self):
        return self.parent(), (self._value,)


class TrigFractions(UniqueRepresentation, Parent):
    r"""
    The field of fractions of a :class:`TrigAlgebra` (an integral domain):
    rational functions of the parameters and of the sines and cosines,
    equal when they are equal as functions.

    INPUT:

    - ``algebra`` -- a :class:`TrigAlgebra`

    Symbolic expressions that are rational functions of the generators
    convert (inexact numbers are refused: see
    :class:`~sage_dynsym.algebra.trig_linear.TrigFractionField` for their
    rational values).

    EXAMPLES::

        sage: from sage_dynsym.algebra.trig_algebra import TrigAlgebra
        sage: a, m = var('a m'); A = TrigAlgebra([a], [m]); K = A.fraction_field()
        sage: K(m/sin(a)) * K(sin(a)) == K(m), K(A(cos(a))) == K(cos(a))
        (True, True)
        sage: TestSuite(K).run()

    TESTS::

        sage: K(sqrt(m))
        Traceback (most recent call last):
        ...
        NotPolynomial: sqrt(m) is not a rational function of the generators
    """
    Element = TrigFraction

    def __init__(self, algebra):
        r"""
        TESTS::

            sage: from sage_dynsym.algebra.trig_algebra import TrigAlgebra
            sage: TrigAlgebra([var('a')], []).fraction_field().category()
            Category of fields
        """
        self._algebra = algebra
        self._field = algebra.cover_ring().fraction_field()
        Parent.__init__(self, base=QQ, category=Fields())
        self._populate_coercion_lists_(coerce_list=[algebra, algebra.cover_ring(), self._field])

    def _repr_(self):
        return f"Fractions of {self._algebra}"

    def _latex_(self):
        return r"\operatorname{Frac}(%s)" % latex(self._algebra)

    def algebra(self):
        r"""The :class:`TrigAlgebra` of the numerators and denominators.

        EXAMPLES::

            sage: from sage_dynsym.algebra.trig_algebra import TrigAlgebra
            sage: A = TrigAlgebra([var('a')], []); A.fraction_field().algebra() is A
            True
        """
        return self._algebra

    def _element_constructor_(self, x):
        if isinstance(x, Element) and x.parent() is self._algebra:
            x = x.lift()
        if isinstance(x, Expression):
            numerator, denominator = self._algebra.polynomial_ring().fraction(x, multiples=True)
            return self.element_class(self, self._field(numerator) / self._field(denominator))
        if isinstance(x, Element) and self._field.has_coerce_map_from(x.parent()):
            return self.element_class(self, self._field(x))
        if x in QQ:
            return self.element_class(self, self._field(QQ(x)))
        raise AnalysisError("expected a symbolic expression, a rational number or an element "
                            f"of the algebra, got {x!r} ({type(x).__name__})",
                            entry="TrigFractions")

    def characteristic(self):
        r"""Zero.

        EXAMPLES::

            sage: from sage_dynsym.algebra.trig_algebra import TrigAlgebra
            sage: TrigAlgebra([var('a')], []).fraction_field().characteristic()
            0
        """
        return ZZ.zero()

    def some_elements(self):
        r"""The algebra's elements for the tests, and quotients of them.

        EXAMPLES::

            sage: from sage_dynsym.algebra.trig_algebra import TrigAlgebra
            sage: a = var('a'); TrigAlgebra([a], []).fraction_field().some_elements()[-1]
            2*(cos(a) + 1)*(sin(a) + 1)/((4*sin(a) - 1)*cos(a))
        """
        elements = [self(x) for x in self._algebra.some_elements()]
        nonzero = [x for x in elements if x]
        return elements + [x / y for x, y in zip(nonzero[-2:], nonzero[-3:-1])]

    def _test_circle(self, **options):
        r"""
        `c^2 + s^2 = 1` and `c/s \cdot s/c = 1` for every angle.

        EXAMPLES::

            sage: from sage_dynsym.algebra.trig_algebra import TrigAlgebra
            sage: TrigAlgebra([var('a'), var('b')], []).fraction_field()._test_circle()
        """
        tester = self._tester(**options)
        for angle in self._algebra.angles():
            c, s = (self(x) for x in self._algebra.trig(angle))
            tester.assertEqual(c * c + s * s, self.one())
            tester.assertTrue((c / s) * (s / c) == self.one())
