r"""
Symbolic expressions as polynomials: the translation under the exact algebra

The exact algebra of the analysis (decomposition of solution sets,
definiteness, quantifier elimination) works over polynomial rings. This
module translates symbolic expressions into them and back:

- the *unknowns* become polynomial variables; an unknown `q` that occurs in
  trigonometric functions becomes the pair `(c_q, s_q) = (\cos q, \sin q)`
  with the relation `c_q^2 + s_q^2 = 1` (multiple angles `\sin(2q)`, sums
  `\cos(q_1 - q_2)` and `\tan q` are expanded first);
- every other symbol is a *parameter*, and so is every subexpression free of
  the unknowns that is not polynomial -- a derivative `D[0](f)(u)` of an
  unspecified function, `\cos\alpha` of a parameter, `\sqrt{g l}`, `\pi`.
  Such *atoms* are treated as independent parameters, which is right for
  generic values of them;
- floating-point numbers become the simplest rational number that rounds
  to them (`0.1` becomes `1/10`); complex numbers are refused;
- a rational function `N/D` gives the equation `N = 0` and records the
  factors of `D` that contain unknowns (the solution set is taken where
  they do not vanish).

An expression in which an unknown occurs otherwise (`\exp q`, `q \sin q`,
`\sin(q/2)`) is *not algebraic*: :class:`NotAlgebraic` names the
subexpression.

The trigonometric part is the package's one algebra: the expressions are
read in the :class:`~sage_dynsym.algebra.trig_algebra.TrigAlgebra` of the
unknowns' angles, the other unknowns, the parameters and the atoms
(:meth:`Translation.algebra`, built by
:meth:`~sage_dynsym.algebra.trigonometric.TrigPolynomialRing.for_unknowns`,
which also expands the multiple angles and sums and gives the pairs of the
circle relations); the translation only splits its generators into the
parameters (the coefficient field) and the unknowns (the ring variables).
These get internal names (``x0, x1, ...``, ``a0, a1, ...``), mapped back by
position, so no user name can clash with them.

EXAMPLES::

    sage: from sage_dynsym.algebra.translation import Translation
    sage: theta, g, R, w = var('theta g R w')
    sage: T = Translation([R*w^2*sin(theta)*cos(theta) - g*sin(theta)], [theta])
    sage: T.ring()
    Multivariate Polynomial Ring in x0, x1 over Fraction Field of Multivariate Polynomial Ring in a0, a1, a2 over Rational Field
    sage: T.parameters()
    [R, g, w]
    sage: T.symbolic_generators()
    [sin(theta), cos(theta)]
    sage: T.equations()
    [(a0*a2^2)*x0*x1 + (-a1)*x0, x0^2 + x1^2 - 1]
    sage: [T.symbolic(f) for f in T.equations()]
    [R*w^2*cos(theta)*sin(theta) - g*sin(theta), cos(theta)^2 + sin(theta)^2 - 1]

Unspecified functions and their derivatives are parameters; denominators
in the unknowns are recorded::

    sage: u, v = var('u v'); f = function('f')
    sage: T = Translation([diff(f(u), u)*v - 1/v], [v])
    sage: T.parameters()
    [diff(f(u), u)]
    sage: T.equations(), T.denominators()
    ([a0*x0^2 - 1], [x0])

TESTS::

    sage: Translation([exp(u) - 1], [u])
    Traceback (most recent call last):
    ...
    NotAlgebraic: e^u
    sage: Translation([u*sin(u)], [u])
    Traceback (most recent call last):
    ...
    NotAlgebraic: u occurs both inside and outside trigonometric functions
    sage: Translation([I*u], [u])
    Traceback (most recent call last):
    ...
    AnalysisError: equations: complex numbers are not supported (got I)
    sage: Translation([0.1*u - 1/5], [u]).equations()
    [1/10*x0 - 1/5]
"""
import operator

from sage.functions.trig import sin, cos
from sage.misc.misc_c import prod
from sage.rings.fraction_field import FractionField
from sage.rings.integer_ring import ZZ
from sage.rings.polynomial.polynomial_ring_constructor import PolynomialRing
from sage.rings.rational_field import QQ
from sage.rings.real_mpfr import RR
from sage.symbolic.ring import SR

from ..errors import AnalysisError
from .expression_walk import (ExpressionWalker, MAX_ANGLE_MULTIPLE, split_angle, angle_sum,
                              trig_value)
from .trigonometric import TrigPolynomialRing, NotAlgebraic, NotPolynomial
from .trig_algebra import TrigAlgebra
from .polynomials import polynomial_to_sr, is_constant, FACTOR_LIMIT

__all__ = ['Translation', 'NotAlgebraic', 'exact_rational', 'translate_expressions',
           'expand_angles', 'ParameterAtoms', 'MAX_ANGLE_MULTIPLE']


def exact_rational(number, what="equations"):
    r"""
    The rational number for a numeric constant: exact for integers and
    rationals, the simplest rational that rounds to a floating-point number.

    EXAMPLES::

        sage: from sage_dynsym.algebra.translation import exact_rational
        sage: exact_rational(0.1), exact_rational(SR(3/4)), exact_rational(float(2.5))
        (1/10, 3/4, 5/2)
        sage: exact_rational(float('nan'))
        Traceback (most recent call last):
        ...
        AnalysisError: equations: not a finite real number: nan
    """
    value = number.pyobject() if hasattr(number, 'pyobject') else number
    try:
        return QQ(value)
    except (TypeError, ValueError, ArithmeticError):
        pass
    if isinstance(value, float):
        value = RR(value)
    if hasattr(value, 'imag') and not hasattr(value, 'simplest_rational'):
        try:
            imaginary = value.imag()
        except (TypeError, AttributeError):
            imaginary = 0
        if imaginary:
            raise AnalysisError(f"complex numbers are not supported (got {number})",
                                entry=what)
        value = value.real()
    if not hasattr(value, 'simplest_rational') or not value.is_real() or \
            value.is_infinity() or value.is_NaN():
        raise AnalysisError(f"not a finite real number: {number}", entry=what)
    return value.simplest_rational()


class Translation:
    r"""
    The translation of a list of symbolic expressions into polynomials over
    the field of rational functions of the parameters (see the module
    documentation).

    INPUT:

    - ``expressions`` -- symbolic expressions (equations ``== 0``); a
      relational ``a == b`` stands for ``a - b``
    - ``unknowns`` -- the unknowns: symbols, or function applications such
      as ``f(q)`` (they are replaced by symbols first)
    - ``extra`` -- (optional) further expressions whose symbols and atoms
      are registered as parameters without becoming equations (e.g. the
      expressions to be evaluated later at the solutions)

    EXAMPLES::

        sage: from sage_dynsym.algebra.translation import Translation
        sage: x, y, a = var('x y a')
        sage: T = Translation([x^2 + y^2 - a, x - y], [x, y]); T
        Translation of 2 equations in x, y (parameters a)
        sage: T.equations()
        [x0^2 + x1^2 + (-a0), -x0 + x1]
    """

    def __init__(self, expressions, unknowns, extra=()):
        self._unknowns = [SR(u) for u in unknowns]
        # unknowns that are not symbols (f(q)) become fresh symbols
        self._stand_ins = {}
        symbols = []
        for u in self._unknowns:
            if u.is_symbol():
                symbols.append(u)
            else:
                s = SR.symbol()
                self._stand_ins[u] = s
                symbols.append(s)
        self._symbols = symbols
        self._index = {str(s): i for i, s in enumerate(symbols)}
        if len(self._index) != len(symbols):
            raise AnalysisError(f"the unknowns {self._unknowns} are not distinct",
                                entry="unknowns")
        expressions = [self._prepare(e) for e in expressions]
        extra = [self._prepare(e) for e in extra]
        # the one trigonometric algebra: the pairs of the angles among the
        # unknowns, the other symbols and the atoms as its generators
        try:
            self._trig = TrigPolynomialRing.for_unknowns(expressions + extra, symbols,
                                                         numbers=exact_rational)
        except NotAlgebraic as error:
            raise NotAlgebraic(self._named(str(error))) from error
        self._build_rings()
        self._equations, self._denominators = [], []
        for e in expressions:
            num, dens = self.numerator(e)
            if num != 0:
                self._equations.append(num)
            for d in dens:
                if d not in self._denominators:
                    self._denominators.append(d)
        self._equations += self.circle_relations()

    # -- preparation and the walk ------------------------------------------

    def _prepare(self, e):
        e = SR(e)
        if e.is_relational():
            e = e.lhs() - e.rhs()
        return e.subs(self._stand_ins) if self._stand_ins else e

    # -- rings -----------------------------------------------------------

    def _named(self, text):
        # the unknowns f(q) by their names instead of their stand-ins
        for u, stand_in in self._stand_ins.items():
            text = text.replace(str(stand_in), str(u))
        return text

    def _build_rings(self):
        trig = self._trig
        self._angles = {self._index[str(a)] for a in trig.angles()}
        names = [n for n in trig.symbols() if n not in self._index]
        self._params = [SR.var(n) for n in names] + trig.atoms()
        self._is_atom = [False] * len(names) + [True] * len(trig.atoms())
        # ring variables: the last unknown first, so that a lexicographic
        # order solves the first unknown first; an angle gives (s, c)
        gens, self._generator_of = [], {}
        for i in reversed(range(len(self._symbols))):
            kinds = ('s', 'c') if i in self._angles else ('x',)
            for kind in kinds:
                self._generator_of[(i, kind)] = len(gens)
                gens.append((i, kind))
        self._gens = gens
        pnames = [f"a{k}" for k in range(len(self._params))]
        vnames = [f"x{k}" for k in range(len(gens))]
        self._field = QQ if not pnames else FractionField(PolynomialRing(QQ, pnames, len(pnames)))
        self._ring = (PolynomialRing(self._field, vnames, len(vnames), order="degrevlex")
                      if vnames else None)
        flat = pnames + vnames
        self._flat = PolynomialRing(QQ, flat, len(flat)) if flat else None
        self._FF = self._flat.fraction_field() if self._flat is not None else QQ
        self._nparams = len(self._params)
        # the algebra's generators in the flat ring: cosines, sines, symbols
        # (parameters or plain unknowns), atoms
        images = [self._ring_gen(self._index[str(a)], 'c') for a in trig.angles()]
        images += [self._ring_gen(self._index[str(a)], 's') for a in trig.angles()]
        images += [self._ring_gen(self._index[n], 'x') if n in self._index
                   else self._flat.gen(names.index(n)) for n in trig.symbols()]
        images += [self._flat.gen(len(names) + k) for k in range(len(trig.atoms()))]
        self._to_flat = trig.ring.hom(images, self._flat) if images else None

    def _ring_gen(self, i, kind):
        return self._flat.gen(self._nparams + self._generator_of[(i, kind)])

    # -- accessors ---------------------------------------------------------

    def __repr__(self):
        unknowns = ', '.join(map(str, self._unknowns))
        params = ', '.join(map(str, self._params))
        return (f"Translation of {len(self._equations) - len(self.circle_relations())} "
                f"equations in {unknowns}" + (f" (parameters {params})" if params else ""))

    def unknowns(self):
        r"""The unknowns, as given.

        EXAMPLES::

            sage: from sage_dynsym.algebra.translation import Translation
            sage: x, a = var('x a')
            sage: Translation([a*x], [x]).unknowns()
            [x]
        """
        return list(self._unknowns)

    def algebra(self):
        r"""The trigonometric algebra the expressions are read in (the one
        of the package, :class:`~sage_dynsym.algebra.trig_algebra.TrigAlgebra`):
        the pairs `(\cos, \sin)` of the unknowns that occur in
        trigonometric functions, the other unknowns and the parameters, the
        atoms. :meth:`fraction` is its conversion, the variables of
        :meth:`flat_ring` renamed.

        EXAMPLES::

            sage: from sage_dynsym.algebra.translation import Translation
            sage: from sage_dynsym.algebra.trig_algebra import TrigAlgebra
            sage: q, m, l, g, a = var('q m l g a')
            sage: T = Translation([m*l*cos(q) - g*sin(2*q + a)], [q])
            sage: A = T.algebra(); A is TrigAlgebra([q], [g, l, m], [cos(a), sin(a)])
            True
            sage: bool(T.symbolic(T.equations()[0]) == SR(A(m*l*cos(q) - g*sin(2*q + a))))
            True
        """
        return TrigAlgebra(self._trig)

    def ring(self):
        r"""The polynomial ring of the unknowns over the parameters' field
        (``None`` without unknowns).

        EXAMPLES::

            sage: from sage_dynsym.algebra.translation import Translation
            sage: x, a = var('x a')
            sage: Translation([a*x], [x]).ring()
            Multivariate Polynomial Ring in x0 over Fraction Field of Multivariate Polynomial Ring in a0 over Rational Field
        """
        return self._ring

    def use_order(self, order):
        r"""Give :meth:`ring` the term order ``order`` (its variables stay
        where they are): the equations, denominators and everything
        translated later are polynomials of the new ring.

        The translation's own order is ``degrevlex``; a system whose Gröbner
        bases are far faster in another order (a block order with the
        multipliers last, say) is solved there.

        EXAMPLES::

            sage: from sage_dynsym.algebra.translation import Translation
            sage: x, y = var('x y')
            sage: T = Translation([x^2 + y - 1], [x, y])
            sage: T.use_order(TermOrder('lex')); T.ring().term_order()
            Lexicographic term order
            sage: T.equations()
            [x0 + x1^2 - 1]
        """
        self._ring = self._ring.change_ring(order=order)
        self._equations = [self._ring(g) for g in self._equations]
        self._denominators = [self._ring(g) for g in self._denominators]

    def field(self):
        r"""The field of the parameters: `\QQ`, or rational functions in them.

        EXAMPLES::

            sage: from sage_dynsym.algebra.translation import Translation
            sage: x = var('x')
            sage: Translation([x^2 - 2], [x]).field()
            Rational Field
        """
        return self._field

    def flat_ring(self):
        r"""The polynomial ring over `\QQ` in the parameters and the ring
        variables together (parameters first).

        EXAMPLES::

            sage: from sage_dynsym.algebra.translation import Translation
            sage: x, a = var('x a')
            sage: Translation([a*x], [x]).flat_ring()
            Multivariate Polynomial Ring in a0, x0 over Rational Field
        """
        return self._flat

    def parameters(self):
        r"""The parameters (symbols and atoms), in the order of the field's
        generators.

        EXAMPLES::

            sage: from sage_dynsym.algebra.translation import Translation
            sage: x, b, a = var('x b a')
            sage: Translation([b*x - cos(a)], [x]).parameters()
            [b, cos(a)]
        """
        return list(self._params)

    def symbolic_generators(self):
        r"""What each ring variable stands for: an unknown, or `\cos`/`\sin`
        of an unknown angle.

        EXAMPLES::

            sage: from sage_dynsym.algebra.translation import Translation
            sage: x, q = var('x q')
            sage: Translation([x - cos(q)], [x, q]).symbolic_generators()
            [sin(q), cos(q), x]
        """
        return [self._symbolic_gen(i, kind) for i, kind in self._gens]

    def _symbolic_gen(self, i, kind):
        u = self._unknowns[i]
        return {'x': u, 'c': cos(u), 's': sin(u)}[kind]

    def is_trigonometric(self, k):
        r"""Whether the ``k``-th ring variable is the cosine or sine of an
        angle.

        EXAMPLES::

            sage: from sage_dynsym.algebra.translation import Translation
            sage: x, q = var('x q')
            sage: T = Translation([x - cos(q)], [x, q])
            sage: [T.is_trigonometric(k) for k in range(3)]
            [True, True, False]
        """
        return self._gens[k][1] in ('c', 's')

    def generators_of(self, unknown):
        r"""The ring variables of one unknown: ``(x,)`` or ``(c, s)``.

        EXAMPLES::

            sage: from sage_dynsym.algebra.translation import Translation
            sage: x, q = var('x q')
            sage: T = Translation([x - cos(q)], [x, q])
            sage: T.generators_of(q), T.generators_of(x)
            ((x1, x0), (x2,))
        """
        i = [str(u) for u in self._unknowns].index(str(SR(unknown)))
        kinds = ('c', 's') if i in self._angles else ('x',)
        return tuple(self._ring.gen(self._generator_of[(i, k)]) for k in kinds)

    def is_angle(self, unknown):
        r"""Whether the unknown occurs in trigonometric functions.

        EXAMPLES::

            sage: from sage_dynsym.algebra.translation import Translation
            sage: x, q = var('x q')
            sage: T = Translation([x - cos(q)], [x, q]); T.is_angle(q), T.is_angle(x)
            (True, False)
        """
        return [str(u) for u in self._unknowns].index(str(SR(unknown))) in self._angles

    def equations(self):
        r"""The polynomial equations (numerators, and the circle relations
        `c^2 + s^2 - 1` of the angles), elements of :meth:`ring`.

        EXAMPLES: see the module documentation.
        """
        return list(self._equations)

    def denominators(self):
        r"""The distinct irreducible factors of the denominators that
        contain unknowns (where the equations are not defined).

        EXAMPLES: see the module documentation.
        """
        return list(self._denominators)

    def circle_relations(self):
        r"""`c^2 + s^2 - 1` for every angle.

        EXAMPLES::

            sage: from sage_dynsym.algebra.translation import Translation
            sage: q = var('q')
            sage: Translation([sin(2*q)], [q]).circle_relations()
            [x0^2 + x1^2 - 1]
        """
        return [self.to_ring(self._to_flat(c) ** 2 + self._to_flat(s) ** 2 - 1)
                for c, s in map(self._trig.trig, self._trig.angles())]

    def positive_names(self, positive=()):
        r"""The names (in :meth:`flat_ring`) of the parameters known to be
        positive: those declared in ``positive``, atoms that are positive
        constants, and square roots (taken where they are real).

        EXAMPLES::

            sage: from sage_dynsym.algebra.translation import Translation
            sage: x, a, b = var('x a b')
            sage: T = Translation([a*x - pi*sqrt(b)], [x])
            sage: T.parameters(), sorted(T.positive_names([a]))
            ([a, pi, sqrt(b)], ['a0', 'a1', 'a2'])
        """
        declared = {str(SR(p)) for p in positive}
        names = set()
        for k, (p, atom) in enumerate(zip(self._params, self._is_atom)):
            if str(p) in declared:
                names.add(f"a{k}")
            elif atom and not p.variables():
                try:
                    if float(p.n()) > 0:
                        names.add(f"a{k}")
                except (TypeError, ValueError):
                    pass
            elif atom and p.operator() is operator.pow and \
                    p.operands()[1].is_numeric() and p.operands()[1].pyobject() == QQ((1, 2)):
                names.add(f"a{k}")
        return names

    # -- translation -------------------------------------------------------

    def fraction(self, expr):
        r"""``expr`` as an element of the fraction field of
        :meth:`flat_ring` (its symbols must have been registered).

        EXAMPLES::

            sage: from sage_dynsym.algebra.translation import Translation
            sage: x, a = var('x a')
            sage: T = Translation([a*x - 1], [x])
            sage: T.fraction(x/a + 1)
            (a0 + x0)/a0
        """
        e = self._prepare(expr)
        try:
            numerator, denominator = self._trig.fraction(e, multiples=True,
                                                         numbers=exact_rational)
        except NotPolynomial as err:
            raise AnalysisError(f"{self._named(str(expr))}: {self._named(str(err))}, not "
                                "among the registered symbols", entry="translation") from err
        if self._to_flat is None:
            return self._FF(QQ(numerator.constant_coefficient())
                            / QQ(denominator.constant_coefficient()))
        return self._FF(self._to_flat(numerator)) / self._FF(self._to_flat(denominator))

    def numerator(self, expr):
        r"""The numerator of ``expr`` in :meth:`ring` and the list of the
        irreducible factors of its denominator that contain unknowns.

        EXAMPLES::

            sage: from sage_dynsym.algebra.translation import Translation
            sage: x, a = var('x a')
            sage: T = Translation([a*x - 1/x], [x])
            sage: T.numerator(a*x - 1/x)
            (a0*x0^2 - 1, [x0])
        """
        f = self.fraction(expr)
        num = self.to_ring(f.numerator())
        dens = []
        if self._ring is not None:
            den = self.to_ring(f.denominator())
            if den.degree() > 0:
                for factor, _ in den.factor():
                    if factor.degree() > 0:
                        dens.append(factor * ~factor.lc())
        return num, dens

    def to_ring(self, flat):
        r"""A polynomial of :meth:`flat_ring` as an element of :meth:`ring`
        (parameters into the coefficients).

        EXAMPLES::

            sage: from sage_dynsym.algebra.translation import Translation
            sage: x, a = var('x a')
            sage: T = Translation([a*x - 1], [x])
            sage: T.to_ring(T.flat_ring()('a0^2*x0 + a0'))
            (a0^2)*x0 + a0
        """
        if self._ring is None:
            return self._field(flat)
        flat = self._flat(flat)
        n = self._nparams
        params = self._field.gens() if n else ()
        result = self._ring(0)
        vars_ = self._ring.gens()
        for exps, c in flat.dict().items():
            coefficient = self._field(c) * prod((params[k] ** e for k, e in
                                                 enumerate(exps[:n]) if e), self._field(1))
            result += coefficient * prod((vars_[k] ** e for k, e in enumerate(exps[n:]) if e),
                                         self._ring(1))
        return result

    def to_flat(self, element):
        r"""An element of :meth:`ring` or :meth:`field` as a pair
        ``(numerator, denominator)`` of :meth:`flat_ring` polynomials.

        EXAMPLES::

            sage: from sage_dynsym.algebra.translation import Translation
            sage: x, a = var('x a')
            sage: T = Translation([a*x - 1], [x])
            sage: T.to_flat(T.ring()('x0/a0 + 1'))
            (a0 + x0, a0)
        """
        F = self._FF
        if self._flat is None:
            q = QQ(element)
            return q.numerator(), q.denominator()
        n = self._nparams
        params = [F(g) for g in self._flat.gens()[:n]]
        variables = [F(g) for g in self._flat.gens()[n:]]

        def coefficient(c):
            if self._field is QQ:
                return F(c)
            return F(_evaluate(c.numerator(), params)) / F(_evaluate(c.denominator(), params))

        parent = element.parent() if hasattr(element, 'parent') else None
        if self._ring is None or parent is self._field or parent is QQ or parent is ZZ:
            value = coefficient(self._field(element))
        else:
            value = F(0)
            for exps, c in self._ring(element).dict().items():
                value += coefficient(c) * prod((variables[k] ** e for k, e in enumerate(exps) if e),
                                               F(1))
        return self._flat(value.numerator()), self._flat(value.denominator())

    def symbolic(self, element, substitutions=None):
        r"""Back to the symbolic ring: an element of :meth:`ring`,
        :meth:`field`, :meth:`flat_ring` or its fraction field.

        INPUT:

        - ``substitutions`` -- (optional) dict mapping ring variables of
          :meth:`ring` to symbolic values (instead of what they stand for)

        EXAMPLES::

            sage: from sage_dynsym.algebra.translation import Translation
            sage: q, k = var('q k')
            sage: T = Translation([k*sin(2*q)], [q])
            sage: T.symbolic(T.equations()[0])
            2*k*cos(q)*sin(q)
            sage: c, s = T.generators_of(q)
            sage: T.symbolic(T.equations()[0], {c: 1/2, s: sqrt(3)/2})
            1/2*sqrt(3)*k
        """
        images = [SR(p) for p in self._params]
        gens = self.symbolic_generators()
        if substitutions:
            by_name = {str(k): SR(v) for k, v in substitutions.items()}
            gens = [by_name.get(f"x{k}", g) for k, g in enumerate(gens)]
        parent = element.parent() if hasattr(element, 'parent') else None
        if self._flat is not None and parent in (self._FF, self._flat):
            element = self._FF(element)
            return (polynomial_to_sr(self._flat(element.numerator()), images + gens) /
                    polynomial_to_sr(self._flat(element.denominator()), images + gens))
        num, den = self.to_flat(element)
        return polynomial_to_sr(num, images + gens) / polynomial_to_sr(den, images + gens)

    def factored(self, p):
        r"""
        An element ``p`` of :meth:`flat_ring` as a symbolic expression,
        factored (unless it has more than
        :data:`~sage_dynsym.algebra.polynomials.FACTOR_LIMIT` terms).

        EXAMPLES::

            sage: from sage_dynsym.algebra.translation import translate_expressions
            sage: a, b = var('a b')
            sage: T, (f,) = translate_expressions([a^2 - b^2])
            sage: T.factored(T.flat_ring()(f)), T.factored(T.flat_ring()(3))
            ((a + b)*(a - b), 3)
        """
        if is_constant(p) or len(p.dict()) > FACTOR_LIMIT:
            return self.symbolic(p)
        F = p.factor()
        return SR(F.unit()) * prod((self.symbolic(f) ** e for f, e in F), SR(1))


class ParameterAtoms:
    r"""
    The atoms among the parameters of ``expressions`` (``cos(alpha)``,
    ``diff(f(u), u)``, ``sqrt(g*l)``: what :class:`Translation` takes as
    independent parameters, ``unknowns`` aside) replaced by fresh symbols,
    and back: for algebra that wants symbols (polynomial rings in the
    parameters, the size of a polynomial counted in terms of symbols).

    INPUT:

    - ``expressions`` -- symbolic expressions
    - ``unknowns`` -- (default: none) symbols that are not parameters
    - ``positive`` -- (default: none) parameters declared positive

    EXAMPLES::

        sage: from sage_dynsym.algebra.translation import ParameterAtoms
        sage: lam, a, k = var('lam a k')
        sage: A = ParameterAtoms([lam^2 + k*cos(a) + pi], [lam], positive=[k])
        sage: e = A.expression(lam^2 + k*cos(a) + pi); e.has(cos(a)), e.has(pi)
        (False, False)
        sage: bool(A.restore(e) == lam^2 + k*cos(a) + pi)
        True
        sage: len(A.symbols()), len(A.positive())
        (3, 2)
        sage: A.relations([[A.expression(k*cos(a)) > 0]])
        [[k*cos(a) > 0]]
    """

    def __init__(self, expressions, unknowns=(), positive=()):
        T = Translation([], list(unknowns), extra=list(expressions))
        names = T.positive_names(positive)
        self._symbols, self._back = [], {}
        self._positive = [SR(p) for p in positive]
        for k, p in enumerate(T.parameters()):
            s = p if p.is_symbol() else SR.symbol()
            if not p.is_symbol():
                self._back[s] = p
                if f"a{k}" in names:
                    self._positive.append(s)
            self._symbols.append(s)
        self._forward = {v: k for k, v in self._back.items()}
        self._algebra = T.algebra()

    def algebra(self):
        r"""The trigonometric algebra the expressions are read in (see
        :meth:`Translation.algebra`): the atoms are its generators that are
        not symbols.

        EXAMPLES::

            sage: from sage_dynsym.algebra.translation import ParameterAtoms
            sage: lam, a, k = var('lam a k')
            sage: ParameterAtoms([lam^2 + k*cos(a)], [lam]).algebra().gens()
            (k, lam, cos(a))
        """
        return self._algebra

    def symbols(self):
        r"""The parameters, atoms replaced by their symbols.

        EXAMPLES::

            sage: from sage_dynsym.algebra.translation import ParameterAtoms
            sage: ParameterAtoms([var('b')*sqrt(2)]).symbols()[0]
            b
        """
        return list(self._symbols)

    def positive(self):
        r"""The parameters declared positive and the symbols of the atoms
        known to be positive (positive constants, square roots).

        EXAMPLES::

            sage: from sage_dynsym.algebra.translation import ParameterAtoms
            sage: A = ParameterAtoms([var('b')*sqrt(2)]); A.positive() == [A.symbols()[1]]
            True
        """
        return list(self._positive)

    def expression(self, e):
        r"""``e`` with the atoms replaced by their symbols.

        EXAMPLES: see the class documentation.
        """
        return SR(e).subs(self._forward) if self._forward else SR(e)

    def restore(self, e):
        r"""``e`` with the symbols of the atoms replaced by the atoms.

        EXAMPLES: see the class documentation.
        """
        return SR(e).subs(self._back) if self._back else SR(e)

    def relations(self, region):
        r"""A region (a list of alternatives, each a list of relations) with
        the atoms restored; ``None`` stays ``None``.

        EXAMPLES: see the class documentation.
        """
        if region is None:
            return None
        return [[self.restore_relation(r) for r in alternative] for alternative in region]

    def restore_relation(self, r):
        r"""The relation ``r`` with the atoms restored on both sides.

        EXAMPLES::

            sage: from sage_dynsym.algebra.translation import ParameterAtoms
            sage: A = ParameterAtoms([cos(var('a'))]); s = A.symbols()[0]
            sage: A.restore_relation(s == 1)
            cos(a) == 1
        """
        return r.operator()(self.restore(r.lhs()), self.restore(r.rhs()))


def translate_expressions(expressions):
    r"""
    The translation of ``expressions`` that have no unknowns (every symbol
    and atom a parameter), and the expressions as elements of the fraction
    field of its :meth:`~Translation.flat_ring`.

    OUTPUT: a pair ``(translation, fractions)``

    EXAMPLES::

        sage: from sage_dynsym.algebra.translation import translate_expressions
        sage: a, b = var('a b')
        sage: T, fractions = translate_expressions([a/b, cos(a) - 1])
        sage: fractions
        [a0/a1, a2 - 1]
        sage: [T.symbolic(f) for f in fractions]
        [a/b, cos(a) - 1]
    """
    T = Translation([], [], extra=expressions)
    return T, [T.fraction(e) for e in expressions]


def _evaluate(poly, values):
    r"""``poly`` (in the generators of its ring) at ``values``."""
    return poly(*values) if poly.parent().ngens() > 1 else poly(values[0])


def expand_angles(expr, angles):
    r"""
    Rewrite trigonometric functions of integer combinations of the
    ``angles`` (plus a part free of them) in terms of `\cos q, \sin q` of
    each angle: `\sin 2q = 2\sin q\cos q`, `\tan q = \sin q/\cos q`, ...
    Other parts of ``expr`` are left as they are.

    EXAMPLES::

        sage: from sage_dynsym.algebra.translation import expand_angles
        sage: q, r, a = var('q r a')
        sage: expand_angles(sin(2*q) + tan(q - r) + cos(a), [q, r])
        2*cos(q)*sin(q) + (cos(r)*sin(q) - cos(q)*sin(r))/(cos(q)*cos(r) + sin(q)*sin(r)) + cos(a)
        sage: expand_angles(cos(q + a), [q])
        cos(a)*cos(q) - sin(a)*sin(q)
    """
    names = {str(SR(a)) for a in angles}
    return _AngleExpansion(names).walk(expr) if names else SR(expr)


class _AngleExpansion(ExpressionWalker):
    # the walk of :func:`expand_angles`: symbolic in, symbolic out; every
    # other function is rebuilt from its walked arguments

    def __init__(self, names):
        self._names = names

    def _is_angle(self, v):
        return str(v) in self._names

    def symbol(self, e):
        return e

    number = symbol

    def atom(self, e):
        op = e.operator()
        return e if op is None else op(*[self.walk(a) for a in e.operands()])

    def trig(self, op, e):
        argument = self.walk(e.operands()[0])
        if not any(map(self._is_angle, argument.variables())):
            return op(argument)
        try:
            multiples, rest = split_angle(op, argument, self._is_angle)
        except AnalysisError:
            return op(argument)
        C, S = (SR(1), SR(0)) if rest.is_zero() else (cos(rest), sin(rest))
        C, S = angle_sum(C, S, multiples, lambda v: (cos(v), sin(v)))
        return trig_value(op, C.expand(), S.expand())
