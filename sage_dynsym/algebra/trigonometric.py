r"""
Arithmetic backends for kinematics: symbolic, or polynomial in sines and cosines

Kinetic energies of rigid-body chains are polynomials in `\sin\theta`,
`\cos\theta` of the rotation angles, the velocities and the parameters, but
straightforward symbolic kinematics produces them in a redundant form
(`\sin^2+\cos^2` pairs that never cancel syntactically, nested rotations).
:class:`TrigPolynomialRing` maps every `\cos\theta, \sin\theta` to
polynomial variables `c, s` of a Singular polynomial ring and reduces modulo
the ideal `(c^2 + s^2 - 1)` (whose generators are already a Gröbner basis)
when converting back: fast arithmetic and a canonical result (equal
functions give equal expressions, no power of a cosine above one).

Every angle gets its pair, whatever it is: a coordinate, a known function
of time (a frame turning as `\omega t`), a parameter or a constant. Other
non-polynomial parts that do not depend on coordinates, velocities or time
(`\pi`, `\sqrt 3`, `1/m`) are generators too ("atoms"). Models that are
still not polynomial (e.g. `\sqrt{x}` of a coordinate) use
:class:`SymbolicBackend`. :func:`trig_rational_simplify` applies the same
reduction to symbolic rational expressions (Routh functions, Hamiltonians).

The Sage parent of the reduced polynomials, with elements, coercions and
the category checks, is :class:`~sage_dynsym.algebra.trig_algebra.TrigAlgebra`
(``TrigAlgebra(R)`` for a ring ``R`` of this module); the ring here is the
arithmetic on representatives that a backend needs (one reduction at the
end instead of one per product). Expressions are read by the walk of
:mod:`~sage_dynsym.algebra.expression_walk`.

EXAMPLES::

    sage: from sage_dynsym.algebra.trigonometric import TrigPolynomialRing
    sage: a, b, m = var('a b m')
    sage: R = TrigPolynomialRing([a, b], [m])
    sage: (ca, sa), (cb, sb) = R.trig(a), R.trig(b)
    sage: M = R.convert(m)
    sage: R.to_symbolic(M*ca^2 + M*sa^2*cb^2 + M*sa^2*sb^2)
    m
    sage: R.to_symbolic(ca^3)
    -(sin(a)^2 - 1)*cos(a)
"""
from collections import Counter
import re
from itertools import chain
from operator import itemgetter

from sage.arith.functions import lcm
from sage.arith.misc import factorial, gcd
from sage.functions.trig import cos, sin
from sage.rings.integer import Integer
from sage.rings.polynomial.polynomial_ring_constructor import PolynomialRing
from sage.rings.rational import Rational
from sage.rings.rational_field import QQ
from sage.symbolic.ring import SR

from sage.structure.unique_representation import UniqueRepresentation

from ..arguments import expression_argument
from ..errors import AnalysisError
from .expression_walk import ExpressionWalker, ExpressionScan, split_angle, angle_sum, trig_value

__all__ = ['NotPolynomial', 'NotAlgebraic', 'circle_reduce', 'symbolic_trig', 'SymbolicBackend',
           'TrigPolynomialRing', 'RingCalculus', 'trig_rational_simplify']

_ZERO, _ONE = SR(0), SR(1)
#: The names Singular takes for variables.
_VARIABLE_NAME = re.compile(r'[A-Za-z][A-Za-z0-9_]*$')


class NotPolynomial(AnalysisError):
    r"""
    Raised when an expression cannot be written in a
    :class:`TrigPolynomialRing`; callers then work in the symbolic ring.
    An :class:`~sage_dynsym.errors.AnalysisError` (so also a ``ValueError``).

    EXAMPLES::

        sage: from sage_dynsym.algebra.trigonometric import TrigPolynomialRing, NotPolynomial
        sage: a = var('a')
        sage: try:
        ....:     TrigPolynomialRing([a], []).convert(sqrt(a))
        ....: except NotPolynomial as error:
        ....:     print(error)
        sqrt(a) is not polynomial in the rotation variables and parameters
        sage: from sage_dynsym.errors import AnalysisError
        sage: issubclass(NotPolynomial, AnalysisError), issubclass(NotPolynomial, ValueError)
        (True, True)
    """


class NotAlgebraic(AnalysisError):
    r"""
    An expression that is not polynomial (or rational) in the unknowns of a
    polynomial system, after trigonometric functions of the unknowns are
    replaced by their pairs `(c, s)` (see
    :meth:`TrigPolynomialRing.for_unknowns`); the message names the
    subexpression.

    EXAMPLES::

        sage: from sage_dynsym.algebra.trigonometric import NotAlgebraic
        sage: print(NotAlgebraic("log(x)"))
        log(x)
    """


def _is_rational(number):
    return isinstance(number.pyobject(), (Integer, Rational))


def _unsigned_angle(angle):
    r"""
    ``-angle`` if it is written with a leading minus sign and its negative
    is not, else ``angle``: `\cos(-a) = \cos a` and `\sin(-a) = -\sin a`
    then share the pair of `a` (Sage keeps ``cos(-a)`` as it is).

    EXAMPLES::

        sage: from sage_dynsym.algebra.trigonometric import _unsigned_angle
        sage: a, b = var('a b')
        sage: _unsigned_angle(-a), _unsigned_angle(b - a), _unsigned_angle(a - b)
        (a, a - b, a - b)
    """
    angle = SR(angle)
    if str(angle).startswith('-') and not str(-angle).startswith('-'):
        return -angle
    return angle


class _Scan(ExpressionScan):
    r"""
    What a polynomial ring needs to hold expressions: the arguments of their
    sines and cosines in ``angles``, their non-polynomial parts (constants
    such as `\pi` or `\sqrt 2`, powers of parameters with fractional or
    negative exponents, other functions) in ``atoms`` (dicts used as
    ordered sets) and their symbols in the set ``symbols``. With
    ``fractions``, negative integer powers are allowed (rational functions).

    A non-polynomial part containing a symbol of ``dynamic`` (coordinates,
    velocities, time: it would not be differentiated) raises
    :class:`NotPolynomial`, as does an inexact number with ``fractions``
    (otherwise the ring's conversion takes its rational value, as kinematic
    data always did).

    EXAMPLES::

        sage: from sage_dynsym.algebra.trigonometric import _Scan
        sage: x, m = var('x m'); S = _Scan([x], fractions=False)
        sage: S.walk(x/m + cos(-x)*pi); S.angles, S.atoms, sorted(S.symbols, key=str)
        ({x: None}, {1/m: None, pi: None}, [x])
    """

    def __init__(self, dynamic, fractions):
        self.dynamic, self.fractions = dynamic, fractions
        self.angles, self.atoms, self.symbols = {}, {}, set()

    def operands(self, e):
        # right to left: the order of the generators (and so the printed
        # forms) the rings have always had
        return reversed(e.operands())

    def symbol(self, e):
        self.symbols.add(e)

    def number(self, e):
        if self.fractions and not _is_rational(e):
            raise NotPolynomial(f"{e} is not a rational number")

    def atom(self, e):
        if any(e.has(v) for v in self.dynamic):
            raise NotPolynomial(f"{e} is not polynomial in the rotation variables and "
                                "parameters")
        self.atoms.setdefault(e)

    def trig(self, op, e):
        if op is cos or op is sin:
            self.angles.setdefault(_unsigned_angle(e.operands()[0]))
        else:
            self.atom(e)

    def takes_power(self, k):
        return self.fractions or k > 0


class _UnknownScan(_Scan):
    r"""
    The scan of :meth:`TrigPolynomialRing.for_unknowns`: a symbol named in
    ``unknowns`` is an *angle* where it occurs in a trigonometric function
    (of an integer combination of angles plus a rest free of them: the
    cosine and sine of the rest are atoms) and a plain generator elsewhere
    (``plain``, by name); every other symbol is a parameter; a part free of
    the unknowns that is not polynomial is an atom. An unknown anywhere
    else raises :class:`NotAlgebraic`; every number goes through
    ``numbers`` (which refuses what it cannot make a rational).

    EXAMPLES::

        sage: from sage_dynsym.algebra.trigonometric import _UnknownScan
        sage: x, q, a = var('x q a')
        sage: S = _UnknownScan({'x', 'q'}, QQ); S.walk(a*x + cos(2*q + a))
        sage: S.angles, S.plain, sorted(S.symbols, key=str), S.atoms
        ({q: None}, {'x'}, [a, x], {cos(a): None, sin(a): None})
    """

    def __init__(self, unknowns, numbers):
        super().__init__((), fractions=True)
        self.unknowns, self.numbers, self.plain = unknowns, numbers, set()

    def is_unknown(self, v):
        return str(v) in self.unknowns

    def symbol(self, e):
        self.symbols.add(e)
        if self.is_unknown(e):
            self.plain.add(str(e))

    def number(self, e):
        self.numbers(e)

    def atom(self, e):
        if any(map(self.is_unknown, e.variables())):
            raise NotAlgebraic(str(e))
        self.atoms.setdefault(e)

    def trig(self, op, e):
        if not any(map(self.is_unknown, e.variables())):
            return self.atom(e)
        multiples, rest = split_angle(op, e.operands()[0], self.is_unknown, NotAlgebraic)
        for v, _ in multiples:
            self.angles.setdefault(v)
        if not rest.is_zero():
            self.atom(cos(rest))
            self.atom(sin(rest))


class _Fraction(ExpressionWalker):
    r"""
    An expression as a pair ``(numerator, denominator)`` of elements of the
    polynomial ring of ``generators`` (a dict: the symbolic value of each
    generator, and of the cosines and sines of the negative angles, to its
    ring element). Numbers are rational (``exact``: ``True`` for only
    integers and rationals, ``False`` for the rational value of an inexact
    number, or a function giving the rational of a number); numerator
    and denominator of a part get at most ``limit`` terms. With ``pairs``
    (a dict: angles that are symbols to their pairs ``(c, s)``), a
    trigonometric function of integer multiples of them plus a generator
    angle is expanded by the addition formulas. Anything else raises
    :class:`NotPolynomial`.

    EXAMPLES::

        sage: from sage_dynsym.algebra.trigonometric import _Fraction
        sage: R.<c, s, m> = QQ[]; a, M = var('a M')
        sage: _Fraction(R, {cos(a): c, M: m}, exact=True).walk(M/cos(a) + cos(a)/M^2)
        (m^3 + c^2, c*m^2)
        sage: _Fraction(R, {}, exact=True, pairs={a: (c, s)}).walk(tan(2*a))
        (2*c*s, c^2 - s^2)
    """

    def __init__(self, ring, generators, exact, limit=None, pairs=None):
        self.ring, self.generators, self.exact, self.limit = ring, generators, exact, limit
        self.pairs = pairs or {}
        self.one, self.zero = ring.one(), ring.zero()

    def trig(self, op, e):
        if not self.pairs:
            return self.atom(e)
        multiples, rest = split_angle(op, e.operands()[0], self.pairs.__contains__,
                                      NotPolynomial)
        C, S = (self.one, self.zero) if rest.is_zero() else (self.generators.get(rest.cos()),
                                                             self.generators.get(rest.sin()))
        if not multiples or C is None or S is None:
            return self.atom(e)
        C, S = angle_sum(C, S, multiples, self.pairs.get)
        return trig_value(op, (C, self.one), (S, self.one), one=(self.one, self.one),
                          divide=lambda x, y: (x[0] * y[1], x[1] * y[0]))

    def checked(self, n, d):
        if self.limit is not None and n.number_of_terms() + d.number_of_terms() > self.limit:
            raise NotPolynomial(f"the fraction has more than {self.limit} terms")
        return n, d

    def known(self, e):
        element = self.generators.get(e)
        return None if element is None else (element, self.one)

    def number(self, e):
        if callable(self.exact):
            return self.ring(self.exact(e)), self.one
        if self.exact:
            if _is_rational(e):
                return self.ring(e.pyobject()), self.one
        else:
            try:
                return self.ring(QQ(e.pyobject())), self.one
            except (TypeError, ValueError):
                pass
        return self.atom(e)

    def atom(self, e):
        raise NotPolynomial(f"{e} is not a rational function of the generators")

    symbol = atom

    def add(self, values):
        # terms over the same denominator are added first
        groups = {}
        for n, d in values:
            groups[d] = groups.get(d, self.zero) + n
        denominator = self.one
        for d in groups:
            denominator = denominator.lcm(d)
        return self.checked(sum((n * (denominator // d) for d, n in groups.items()), self.zero),
                            denominator)

    def mul(self, values):
        n, d = self.one, self.one
        for xn, xd in values:
            n, d = self.checked(n * xn, d * xd)
        return n, d

    def power(self, value, k):
        n, d = value
        return self.checked(*((n ** k, d ** k) if k >= 0 else (d ** -k, n ** -k)))


# Fractions whose numerator and denominator have at most this many terms
# together are also tried in factored form (Singular's factorization is fast
# there; the recursive form of a fraction's numerator may hide a factor).
_FACTOR_TERMS = 40
# Beyond this many terms only the first normal form is written (see
# TrigPolynomialRing.simplest_fraction).
_SHAPE_TERMS = 300
# trig_rational_simplify gives up on fractions with more terms: the
# greatest common divisors of nested denominators would take minutes.
_FRACTION_TERMS = 2000


def _content(element):
    r"""
    The rational `c` such that ``element / c`` has coprime integer
    coefficients and a positive leading coefficient.
    """
    coefficients = element.coefficients()
    if not coefficients:
        return QQ.one()
    numerators = gcd([c.numerator() for c in coefficients])
    denominators = lcm([c.denominator() for c in coefficients])
    content = QQ((numerators, denominators))
    return content if element.lc() > 0 else -content


def circle_reduce(element, pairs, zero):
    r"""
    ``element`` with `c^2` replaced by `1 - s^2` for every pair ``(c, s)``:
    a linear-time normal form modulo the ideal `(c^2 + s^2 - 1)`.

    INPUT:

    - ``element`` -- a polynomial
    - ``pairs`` -- pairs ``(c, s)`` of generators of its ring, the cosine
      and the sine of one angle
    - ``zero`` -- the zero of the ring

    OUTPUT: a polynomial of degree at most one in each ``c``

    EXAMPLES::

        sage: from sage_dynsym.algebra.trigonometric import circle_reduce
        sage: R.<c, s, m> = QQ[]
        sage: circle_reduce(m*c^2 + m*s^2 + c^3, [(c, s)], R.zero())
        -c*s^2 + c + m
    """
    # Singular's normal form (and its division) is quadratic in the length
    # of the polynomial: minutes for the 50,000-term entries of a 6-link
    # chain. Here each angle costs a few linear passes: the Taylor
    # coefficients p_k of element = sum_k c^k p_k, then c^2 = 1 - s^2.
    for c, s in pairs:
        degree = element.degree(c)
        if degree < 2:
            continue
        parts, derivative = [], element
        for k in range(degree + 1):
            parts.append(derivative.subs({c: 0}) / factorial(k))
            derivative = derivative.derivative(c)
        one_minus_s2 = 1 - s ** 2
        even = odd = zero
        for k in reversed(range(degree + 1)):
            if k % 2:
                odd = odd * one_minus_s2 + parts[k]
            else:
                even = even * one_minus_s2 + parts[k]
        element = even + c * odd
    return element


def symbolic_trig(angle):
    r"""
    The pair `(\cos, \sin)` of ``angle`` in the symbolic ring.

    EXAMPLES::

        sage: from sage_dynsym.algebra.trigonometric import symbolic_trig
        sage: symbolic_trig(var('a'))
        (cos(a), sin(a))
    """
    return SR(angle).cos(), SR(angle).sin()


class SymbolicBackend:
    r"""
    Arithmetic of kinematic quantities in the symbolic ring (the general
    case: any expression is allowed).

    EXAMPLES::

        sage: from sage_dynsym.algebra.trigonometric import SymbolicBackend
        sage: B = SymbolicBackend(); x, dx = var('x dx')
        sage: B.diff(B.convert(x*dx), dx), B.at_zero(x*dx + x, [dx]), B.trig(x)
        (x, x, (cos(x), sin(x)))
    """
    zero = SR(0)

    def convert(self, expr):
        r"""``expr`` as an element of the backend: a symbolic expression.

        EXAMPLES::

            sage: from sage_dynsym.algebra.trigonometric import SymbolicBackend
            sage: B = SymbolicBackend(); a, l, da = var('a l da')
            sage: B.convert(1).parent()
            Symbolic Ring
        """
        return SR(expr)

    @staticmethod
    def trig(angle):
        r"""The pair `(\cos, \sin)` of ``angle`` (see :func:`symbolic_trig`).

        EXAMPLES::

            sage: from sage_dynsym.algebra.trigonometric import SymbolicBackend
            sage: B = SymbolicBackend(); a, l, da = var('a l da')
            sage: B.trig(a)
            (cos(a), sin(a))
        """
        return symbolic_trig(angle)

    def diff(self, element, symbol):
        r"""The derivative of ``element`` with respect to ``symbol``.

        EXAMPLES::

            sage: from sage_dynsym.algebra.trigonometric import SymbolicBackend
            sage: B = SymbolicBackend(); a, l, da = var('a l da')
            sage: B.diff(l^2*da^2/2, da)
            da*l^2
        """
        return element.diff(symbol)

    def at_zero(self, element, symbols):
        r"""``element`` with every one of ``symbols`` set to zero.

        EXAMPLES::

            sage: from sage_dynsym.algebra.trigonometric import SymbolicBackend
            sage: B = SymbolicBackend(); a, l, da = var('a l da')
            sage: B.at_zero(l*da + l^2, [da])
            l^2
        """
        return element.subs({v: 0 for v in symbols})

    def to_symbolic(self, element):
        r"""``element`` as a symbolic expression (itself).

        EXAMPLES::

            sage: from sage_dynsym.algebra.trigonometric import SymbolicBackend
            sage: B = SymbolicBackend(); a, l, da = var('a l da')
            sage: B.to_symbolic(l*cos(a))
            l*cos(a)
        """
        return element


class _Structural:
    r"""
    A symbolic expression as the key of a cached parent: equal when printed
    alike. Two symbolic expressions compare by ``bool(a == b)``, which may
    try to prove an identity by evaluating them at random points, a long
    computation for nested constants such as `\sin(\sin(\sin k))`.

    EXAMPLES::

        sage: from sage_dynsym.algebra.trigonometric import _Structural
        sage: k = var('k')
        sage: _Structural(sin(sin(k))) == _Structural(sin(sin(k))), _Structural(k) == _Structural(2*k)
        (True, False)
        sage: loads(dumps(_Structural(k))).value
        k
    """
    __slots__ = ('value', '_text')

    def __init__(self, value):
        self.value = SR(value)
        self._text = repr(self.value)

    def __eq__(self, other):
        return isinstance(other, _Structural) and self._text == other._text

    def __hash__(self):
        return hash(self._text)

    def __reduce__(self):
        return _Structural, (self.value,)


def _structural_value(x):
    r"""The expression of ``x`` (a :class:`_Structural` key or an expression)."""
    return x.value if isinstance(x, _Structural) else x


class TrigPolynomialRing(UniqueRepresentation):
    r"""
    Kinematic quantities as polynomials over `\mathbb{Q}` in the parameters,
    velocities and the cosines and sines of the rotation angles, reduced
    modulo `\cos^2+\sin^2 = 1` when converted back: Singular's arithmetic
    and a canonical, compact result.

    INPUT:

    - ``angles`` -- the rotation angles (symbolic expressions)
    - ``symbols`` -- every other symbolic variable that may appear

    Converting an expression that is not polynomial in these raises
    :class:`NotPolynomial`. Rings with the same generators are one object
    (``UniqueRepresentation``); their Sage parent is
    :class:`~sage_dynsym.algebra.trig_algebra.TrigAlgebra`.

    EXAMPLES::

        sage: from sage_dynsym.algebra.trigonometric import TrigPolynomialRing
        sage: a, l, da = var('a l da')
        sage: R = TrigPolynomialRing([a], [l, da])
        sage: c, s = R.trig(a)
        sage: R.to_symbolic(R.convert(l^2)*(c^2 + s^2))
        l^2
        sage: R.convert(1/a)
        Traceback (most recent call last):
        ...
        NotPolynomial: 1/a is not polynomial in the rotation variables and parameters
        sage: R is TrigPolynomialRing([a, -a], [da, l, l])
        True
        sage: from sage_dynsym.algebra.trig_algebra import TrigAlgebra
        sage: TrigAlgebra(R)(l^2*cos(a)^2 + l^2*sin(a)^2)
        l^2
    """

    @staticmethod
    def __classcall__(cls, angles, symbols, atoms=()):
        # the normal form of the arguments (angles sorted, as the symbols):
        # equal rings are one object (UniqueRepresentation), and the parent
        # TrigAlgebra is keyed by it
        unique = {}
        for angle in map(_structural_value, angles):
            angle = _unsigned_angle(angle)
            # no pair for a constant angle whose sine and cosine evaluate
            # (pi/6: sqrt(3) is an atom)
            if str(angle) not in unique and (angle.cos().operator() is cos
                                             or angle.sin().operator() is sin):
                unique[str(angle)] = angle
        return super().__classcall__(cls, tuple(_Structural(unique[k]) for k in sorted(unique)),
                                     tuple(sorted({str(v) for v in symbols}, key=str)),
                                     tuple(_Structural(a) for a in map(_structural_value, atoms)))

    def __init__(self, angles, symbols, atoms=()):
        self._angles = [a.value for a in angles]
        self._symbols = list(symbols)
        self._atoms = [a.value for a in atoms]
        k = len(self._angles)
        # a symbol is a variable of its own name where Singular takes that
        # name (``_C`` it does not)
        names = ([f'dynsymcos{i}' for i in range(k)] + [f'dynsymsin{i}' for i in range(k)]
                 + [n if _VARIABLE_NAME.match(n) else f'dynsymsymbol{i}'
                    for i, n in enumerate(self._symbols)]
                 + [f'dynsymatom{i}' for i in range(len(self._atoms))])
        # always multivariate (one variable would give a univariate ring)
        self.ring = PolynomialRing(QQ, names, len(names), order='degrevlex')
        gens = self.ring.gens()
        self._pairs = {angle: (gens[i], gens[k + i]) for i, angle in enumerate(self._angles)}
        self.zero = self.ring.zero()
        # the symbolic value of every generator, for the conversion back
        self._values = ([a.cos() for a in self._angles] + [a.sin() for a in self._angles]
                        + [SR.var(name) for name in self._symbols] + self._atoms)
        # the ring element of every symbol, atom, cosine and sine (the walk)
        self._elements = {value: gen for value, gen in zip(self._values, gens)}
        self._symbol_gens = dict(zip(self._symbols, gens[2 * k:]))
        for angle, (c, s) in self._pairs.items():
            self._elements[(-angle).cos()], self._elements[(-angle).sin()] = c, -s

    @classmethod
    def for_expressions(cls, expressions, dynamic=(), fractions=False):
        r"""
        The ring holding ``expressions``: a pair for every argument of a
        sine or cosine in them, a generator for every symbol and for every
        other non-polynomial part ("atom": `\pi`, `\sqrt 2`, `1/m`,
        `e^{k}`, ...), treated as an independent variable.

        INPUT:

        - ``expressions`` -- symbolic expressions
        - ``dynamic`` -- (default: none) symbols that must not occur in an
          atom (coordinates, velocities, time), since derivatives with
          respect to them treat atoms as constants
        - ``fractions`` -- (default: ``False``) whether negative integer
          powers are allowed (for :meth:`fraction`) instead of being atoms

        Raises :class:`NotPolynomial` if an atom contains a ``dynamic``
        symbol, or with ``fractions`` if a number is inexact.

        EXAMPLES::

            sage: from sage_dynsym.algebra.trigonometric import TrigPolynomialRing
            sage: x, w, t, a, m = var('x w t a m')
            sage: R = TrigPolynomialRing.for_expressions([a*cos(w*t)*x + sqrt(2)/m], [x, t])
            sage: R.angles(), R.atoms()
            ([t*w], [1/m, sqrt(2)])
            sage: c, s = R.trig(w*t)
            sage: R.to_symbolic(R.convert(x^2*cos(w*t)^2 + x^2*sin(w*t)^2 + sqrt(2)))
            x^2 + sqrt(2)

        TESTS::

            sage: TrigPolynomialRing.for_expressions([sqrt(x)], [x])
            Traceback (most recent call last):
            ...
            NotPolynomial: sqrt(x) is not polynomial in the rotation variables and parameters
        """
        found = _Scan(dynamic, fractions)
        for expr in expressions:
            found.walk(expr)
        for angle in list(found.angles):
            # the derivatives of an angle are converted as well
            for v in SR(angle).variables():
                found.walk(SR(angle).diff(v))
            found.symbols.update(SR(angle).variables())
        return cls(found.angles, found.symbols, found.atoms)

    @classmethod
    def for_unknowns(cls, expressions, unknowns, numbers=QQ):
        r"""
        The ring of a polynomial system in ``unknowns``: an unknown that
        occurs in trigonometric functions is an angle (its pair `(c, s)`;
        multiple angles and sums are expanded by :meth:`fraction` with
        ``multiples=True``), any other unknown and every other symbol a
        generator, and every part free of the unknowns that is not
        polynomial an atom (`\cos\alpha` of a parameter, `\sqrt 2`,
        `D[0](f)(u)`, and the cosine and sine of the part of an angle's
        argument free of the unknowns), sorted by name.

        INPUT:

        - ``expressions`` -- symbolic expressions
        - ``unknowns`` -- symbols
        - ``numbers`` -- (default: `\QQ`) the function giving the rational
          number of a numeric constant (it raises on what it refuses)

        Raises :class:`NotAlgebraic` if an unknown occurs otherwise than in
        a rational function of the generators, or both inside and outside
        trigonometric functions.

        EXAMPLES::

            sage: from sage_dynsym.algebra.trigonometric import TrigPolynomialRing
            sage: q, x, g, a = var('q x g a')
            sage: R = TrigPolynomialRing.for_unknowns([g*sin(2*q) - x*cos(q + a)], [q, x])
            sage: R.angles(), R.symbols(), R.atoms()
            ([q], ['g', 'x'], [cos(a), sin(a)])
            sage: R is TrigPolynomialRing([q], [g, x], [cos(a), sin(a)])
            True
            sage: [R.to_symbolic(p) for p in R.fraction(sin(2*q)/x, multiples=True)]
            [2*cos(q)*sin(q), x]

        TESTS::

            sage: TrigPolynomialRing.for_unknowns([exp(q)], [q])
            Traceback (most recent call last):
            ...
            NotAlgebraic: e^q
            sage: TrigPolynomialRing.for_unknowns([q*sin(q)], [q])
            Traceback (most recent call last):
            ...
            NotAlgebraic: q occurs both inside and outside trigonometric functions
        """
        found = _UnknownScan({str(u) for u in unknowns}, numbers)
        for expr in expressions:
            found.walk(expr)
        angles = [u for u in unknowns if u in found.angles]
        for u in angles:
            if str(u) in found.plain:
                raise NotAlgebraic(f"{u} occurs both inside and outside trigonometric functions")
        # an unknown that is not an angle is a generator even where absent
        plain = [u for u in unknowns if u not in found.angles]
        return cls(angles, found.symbols.union(plain), sorted(found.atoms, key=str))

    def angles(self):
        r"""
        The angles whose cosine and sine are generators of the ring.

        EXAMPLES::

            sage: from sage_dynsym.algebra.trigonometric import TrigPolynomialRing
            sage: TrigPolynomialRing([var('a'), pi/2, var('a'), 1], []).angles()
            [1, a]

        They are sorted by their printed form: the same angles give the same
        ring (and :class:`~sage_dynsym.algebra.trig_algebra.TrigAlgebra`)
        whatever the order they are met in::

            sage: a, b = var('a b')
            sage: TrigPolynomialRing([b, a], []) is TrigPolynomialRing([a, -b], [])
            True

        (`\cos(\pi/2)` and `\sin(\pi/2)` are numbers, so `\pi/2` has no pair.)
        """
        return list(self._angles)

    def symbols(self):
        r"""
        The names of the symbols that are generators of the ring (sorted).

        EXAMPLES::

            sage: from sage_dynsym.algebra.trigonometric import TrigPolynomialRing
            sage: TrigPolynomialRing([var('a')], [var('m'), var('l'), var('m')]).symbols()
            ['l', 'm']
        """
        return list(self._symbols)

    def atoms(self):
        r"""
        The non-polynomial parts held as generators of the ring (see
        :meth:`for_expressions`).

        EXAMPLES::

            sage: from sage_dynsym.algebra.trigonometric import TrigPolynomialRing
            sage: TrigPolynomialRing([], [], [pi]).atoms()
            [pi]
        """
        return list(self._atoms)

    def _walk(self, exact, limit=None, multiples=False):
        # exact: True, False, or the function giving the rational of a number
        # multiples: the angles that are symbols, for the addition formulas
        pairs = {a: p for a, p in self._pairs.items() if a.is_symbol()} if multiples else None
        return _Fraction(self.ring, self._elements, exact, limit, pairs)

    def convert(self, expr, multiples=False):
        r"""The ring element of the symbolic expression ``expr``; raises
        :class:`NotPolynomial` if it is not polynomial in the generators.
        With ``multiples``, sines and cosines of integer multiples of the
        angles that are symbols, and of their sums, are expanded (else each
        argument must be an angle of the ring).

        EXAMPLES::

            sage: from sage_dynsym.algebra.trigonometric import TrigPolynomialRing
            sage: a, l, da = var('a l da')
            sage: R = TrigPolynomialRing([a], [l, da]); c, s = R.trig(a)
            sage: R.convert(l*da*cos(a))
            dynsymcos0*da*l
            sage: R.convert(sin(2*a), multiples=True)
            2*dynsymcos0*dynsymsin0
            sage: R.convert(sin(2*a))
            Traceback (most recent call last):
            ...
            NotPolynomial: sin(2*a) is not polynomial in the rotation variables and parameters
        """
        expr = SR(expr)
        try:
            numerator, denominator = self._walk(False, multiples=multiples).walk(expr)
        except NotPolynomial as error:
            raise NotPolynomial(f"{expr} is not polynomial in the rotation variables "
                                "and parameters") from error
        if not denominator.is_constant():
            raise NotPolynomial(f"{expr} is not polynomial in the rotation variables "
                                "and parameters")
        return numerator / denominator.constant_coefficient()

    def trig(self, angle):
        r"""The pair `(\cos, \sin)` of ``angle`` as ring elements: the
        generators of an angle of the ring, else converted values.

        EXAMPLES::

            sage: from sage_dynsym.algebra.trigonometric import TrigPolynomialRing
            sage: a, l, da = var('a l da')
            sage: R = TrigPolynomialRing([a], [l, da]); c, s = R.trig(a)
            sage: R.trig(a), R.trig(pi/2)
            ((dynsymcos0, dynsymsin0), (0, 1))

        A negative angle shares the pair of its negative (a rotation back
        by `-a`)::

            sage: R.trig(-a)
            (dynsymcos0, -dynsymsin0)
            sage: from sage_dynsym.algebra.trigonometric import trig_rational_simplify
            sage: trig_rational_simplify(cos(-a)*cos(a) - sin(-a)*sin(a))
            1
        """
        angle = SR(angle)
        if angle in self._pairs:
            return self._pairs[angle]
        if -angle in self._pairs:
            c, s = self._pairs[-angle]
            return c, -s
        return self.convert(angle.cos()), self.convert(angle.sin())

    def generator(self, symbol, *default):
        r"""The ring variable of ``symbol`` (one of :meth:`symbols`); the
        ``default`` if given and ``symbol`` is not one of them.

        EXAMPLES::

            sage: from sage_dynsym.algebra.trigonometric import TrigPolynomialRing
            sage: a, l, C = var('a l _C'); R = TrigPolynomialRing([a], [l, C])
            sage: R.generator(l), R.generator(C), R.generator(a, None)
            (l, dynsymsymbol0, None)
            sage: R.to_symbolic(R.convert(C*l))
            _C*l
        """
        gen = self._symbol_gens.get(str(symbol), *default)
        if gen is None and not default:
            raise KeyError(symbol)
        return gen

    def diff(self, element, symbol):
        r"""The derivative of ``element`` with respect to ``symbol`` (a
        generator of the ring, such as a velocity).

        EXAMPLES::

            sage: from sage_dynsym.algebra.trigonometric import TrigPolynomialRing
            sage: a, l, da = var('a l da')
            sage: R = TrigPolynomialRing([a], [l, da]); c, s = R.trig(a)
            sage: R.to_symbolic(R.diff(R.convert(l^2*da^2/2)*c, da))
            da*l^2*cos(a)
        """
        return element.derivative(self.generator(symbol))

    def at_zero(self, element, symbols):
        r"""``element`` with every one of ``symbols`` (generators) set to zero.

        EXAMPLES::

            sage: from sage_dynsym.algebra.trigonometric import TrigPolynomialRing
            sage: a, l, da = var('a l da')
            sage: R = TrigPolynomialRing([a], [l, da]); c, s = R.trig(a)
            sage: R.to_symbolic(R.at_zero(R.convert(l*da + l^2)*c, [da]))
            l^2*cos(a)
        """
        return element.subs({self.generator(v): 0 for v in symbols})

    def reduce(self, element):
        r"""
        The normal form of ``element`` modulo `\cos^2+\sin^2 = 1`: no
        monomial divisible by the square of a cosine.

        EXAMPLES::

            sage: from sage_dynsym.algebra.trigonometric import TrigPolynomialRing
            sage: R = TrigPolynomialRing([var('a')], [])
            sage: c, s = R.trig(var('a'))
            sage: R.reduce(c^3)
            -dynsymcos0*dynsymsin0^2 + dynsymcos0

        TESTS:

        The result is Singular's normal form modulo the ideal::

            sage: R = TrigPolynomialRing(var('a b'), [var('m')])
            sage: I = R.ring.ideal([c^2 + s^2 - 1 for c, s in map(R.trig, var('a b'))])
            sage: for _ in range(20):
            ....:     f = R.ring.random_element(degree=7, terms=30)
            ....:     assert R.reduce(f) == I.reduce(f), f
        """
        return circle_reduce(element, self._pairs.values(), self.zero)

    def to_symbolic(self, element, reduced=False):
        r"""
        The symbolic expression of ``element`` after reduction modulo
        `\cos^2+\sin^2 = 1` (skipped if ``reduced`` says it is already
        reduced, see :meth:`reduce`), in *recursive* form: the variable occurring
        in most terms is factored out, then recursively in each group
        (a multivariate Horner scheme). Typically half the size of the
        expanded form and smaller than nested kinematic expressions.

        EXAMPLES::

            sage: from sage_dynsym.algebra.trigonometric import TrigPolynomialRing
            sage: a, m, l = var('a m l')
            sage: R = TrigPolynomialRing([a], [m, l])
            sage: c, s = R.trig(a)
            sage: M, L = R.convert(m), R.convert(l)
            sage: R.to_symbolic(M*L^2*c^2 + M*L*s + M*c^2)
            -((l^2 + 1)*sin(a)^2 - l^2 - l*sin(a) - 1)*m
        """
        if not reduced:
            element = self.reduce(element)
        terms = [(dict(exponents.sparse_iter()), SR(coefficient))
                 for exponents, coefficient in element.dict().items()]
        return self._recursive(terms, frozenset(), {}) if terms else SR(0)

    def _recursive(self, terms, factored, powers):
        # ``factored``: variables already taken out by the callers (they stay
        # in the exponent dictionaries: copying those costs more than skipping)
        def power(index, e):
            try:
                return powers[index, e]
            except KeyError:
                value = powers[index, e] = self._values[index] ** e
                return value

        def monomial(exponents, coefficient):
            return _ONE.mul(coefficient, *[power(i, e) for i, e in exponents.items()
                                           if i not in factored])

        if len(terms) == 1:
            return monomial(*terms[0])
        counts = Counter(chain.from_iterable(map(itemgetter(0), terms)))
        for index in factored:
            del counts[index]
        variable, top = max(counts.items(), key=itemgetter(1), default=(None, 1))
        if top == 1:
            return _ZERO.add(*[monomial(*term) for term in terms])
        groups = {}
        for term in terms:
            groups.setdefault(term[0].get(variable, 0), []).append(term)
        inner = factored | {variable}
        parts = [self._recursive(group, inner, powers) * power(variable, e) if e
                 else self._recursive(group, factored, powers)
                 for e, group in groups.items()]
        return parts[0] if len(parts) == 1 else _ZERO.add(*parts)

    def fraction(self, expr, limit=None, multiples=False, numbers=None):
        r"""
        ``expr``, a rational function of the generators of the ring (see
        :meth:`for_expressions` with ``fractions=True``), as a pair
        ``(numerator, denominator)`` of ring elements.

        Raises :class:`NotPolynomial` if ``expr`` is not such a function, or
        if numerator or denominator of a part get more than ``limit`` terms
        (common denominators of nested fractions grow fast, and their
        greatest common divisors take minutes). ``multiples``: as in
        :meth:`convert`. ``numbers``: (default: integers and rationals only)
        the function giving the rational number of a numeric constant.

        EXAMPLES::

            sage: from sage_dynsym.algebra.trigonometric import TrigPolynomialRing
            sage: a, m = var('a m')
            sage: e = m/sin(a) + cos(a)/(m*sin(a))
            sage: R = TrigPolynomialRing.for_expressions([e], fractions=True)
            sage: [R.to_symbolic(p) for p in R.fraction(e)]
            [m^2 + cos(a), m*sin(a)]
            sage: [R.to_symbolic(p) for p in R.fraction(tan(a - 2*a), multiples=True)]
            [-sin(a), cos(a)]
        """
        return self._walk(numbers or True, limit, multiples).walk(SR(expr))

    def simplest_fraction(self, numerator, denominator=1, printed=False):
        r"""
        The shortest symbolic form found for ``numerator/denominator`` (ring
        elements) modulo `\cos^2+\sin^2 = 1`.

        Both are first reduced with `\cos^2 = 1 - \sin^2` (a normal form:
        zero is recognised), their greatest common divisor is cancelled and
        they are written in recursive (Horner) form, see
        :meth:`to_symbolic`. Before that, angle by angle, the reduction
        `\sin^2 = 1 - \cos^2` is tried instead and kept when it gives
        fewer terms (or as many, of lower degrees), or with ``printed``, a
        shorter printed form (slower: every candidate is written); finally,
        for a small fraction with a denominator, the factored form is tried.
        Fractions with more than 300 terms only get the first form.

        EXAMPLES::

            sage: from sage_dynsym.algebra.trigonometric import TrigPolynomialRing
            sage: a, b, m = var('a b m')
            sage: R = TrigPolynomialRing([a, b], [m])
            sage: (c, s), (cb, sb) = R.trig(a), R.trig(b)
            sage: M = R.convert(m)
            sage: R.simplest_fraction(M*c^2 + M*s^2, M^2), R.simplest_fraction(s^2, 1 - c)
            (1/m, cos(a) + 1)
            sage: R.simplest_fraction(M*s^2 - M + M*c^2, M)
            0
            sage: R.to_symbolic(M*c^2*sb^2 + M*c)
            -((sin(a)^2 - 1)*sin(b)^2 - cos(a))*m
            sage: R.simplest_fraction(M*c^2*sb^2 + M*c)
            m*cos(a)^2*sin(b)^2 + m*cos(a)
        """
        numerator, denominator = self.ring(numerator), self.ring(denominator)
        pairs = list(self._pairs.values())

        def form(flips):
            rule = [(s, c) if flip else (c, s) for (c, s), flip in zip(pairs, flips)]
            n = circle_reduce(numerator, rule, self.zero)
            d = circle_reduce(denominator, rule, self.zero)
            if not (n.is_zero() or d.is_constant()):
                g = n.gcd(d)
                n, d = n // g, d // g
            return n, d

        def written(n, d):
            # integer, coprime coefficients; the denominator's leading one positive
            cn, cd = _content(n), _content(d)
            n, d = n / cn, d / cd
            expr = SR(cn / cd) * self.to_symbolic(n, reduced=True)
            return expr if d.is_one() else expr / self.to_symbolic(d, reduced=True)

        def cost(n, d):
            if printed:
                return len(str(written(n, d)))
            # fewer terms, then lower degrees: a proxy for the printed length
            return (n.number_of_terms() + d.number_of_terms(),
                    sum(map(sum, chain(n.exponents(), d.exponents()))))

        flips = [False] * len(pairs)
        n, d = form(flips)
        if n.is_zero():
            return SR(0)
        small = numerator.number_of_terms() + denominator.number_of_terms() <= _SHAPE_TERMS
        if small:
            best = cost(n, d)
            for i, (c, s) in enumerate(pairs):
                if n.degree(s) < 2 and d.degree(s) < 2:
                    continue   # no sin^2: the other reduction would change nothing
                flips[i] = True
                trial = form(flips)
                if cost(*trial) < best:
                    (n, d), best = trial, cost(*trial)
                else:
                    flips[i] = False
        expr = written(n, d)
        # (polynomials: the recursive form already shows the common factors)
        if (small and not d.is_constant()
                and n.number_of_terms() + d.number_of_terms() <= _FACTOR_TERMS):
            factor = SR(_content(n) / _content(d))
            factored = factor * self._factored(n / _content(n)) / self._factored(d / _content(d))
            if len(str(factored)) < len(str(expr)):
                return factored
        return expr

    def _factored(self, element):
        if element.is_constant():
            return SR(element.constant_coefficient())
        F = element.factor()
        return SR(F.unit()) * _ONE.mul(*[self.to_symbolic(f, reduced=True) ** e for f, e in F])

    def calculus(self, coordinates):
        r"""
        The :class:`RingCalculus` of this ring for the given coordinates.

        EXAMPLES::

            sage: from sage_dynsym.algebra.trigonometric import TrigPolynomialRing
            sage: a, l = var('a l')
            sage: C = TrigPolynomialRing([a], [l]).calculus([a])
            sage: c, s = C.ring.trig(a)
            sage: C.symbolic(C.derivative(c^2*C.convert(l), 0))
            -2*l*cos(a)*sin(a)
        """
        return RingCalculus(self, coordinates)


class RingCalculus:
    r"""
    Derivatives in a :class:`TrigPolynomialRing` with respect to the
    coordinates and time: the chain rule through every angle,
    `\partial_q \cos\theta = -\sin\theta\, \partial_q\theta`,
    `\partial_q \sin\theta = \cos\theta\, \partial_q\theta`, plus
    the direct dependence of coordinates used as polynomial variables (e.g. a
    sliding coordinate). The interface is that of
    :class:`~sage_dynsym.dynamics.natural_equations.SymbolicCalculus`. Elements must
    be reduced (:meth:`TrigPolynomialRing.reduce`); derivatives stay reduced.

    Raises :class:`NotPolynomial` if an angle's derivative is not polynomial.

    EXAMPLES::

        sage: from sage_dynsym.algebra.trigonometric import TrigPolynomialRing
        sage: x, z, w, t = var('x z w t')
        sage: R = TrigPolynomialRing([x + w*t], [z, w, t])
        sage: C = R.calculus([x, z])
        sage: c, s = R.trig(x + w*t)
        sage: p = c * R.convert(z^2)
        sage: sorted(C.dependencies(p)), C.depends_on_time(p)
        ([0, 1], True)
        sage: C.symbolic(C.derivative(p, 0)), C.symbolic(C.derivative(p, None))
        (-z^2*sin(t*w + x), -w*z^2*sin(t*w + x))
    """

    def __init__(self, ring, coordinates):
        from ..symbols import t
        self.ring = ring
        self.zero = ring.zero
        self._direct = [ring.generator(q, None) for q in coordinates]
        self._time = ring.generator(t, None)
        # per angle: its ring pair and the ring derivatives of the angle
        self._chains = []
        for angle in ring.angles():
            c, s = ring.trig(angle)
            by_coordinate = {k: ring.convert(angle.diff(q)) for k, q in enumerate(coordinates)
                             if angle.has(q)}
            rate = ring.convert(angle.diff(t)) if angle.has(t) else None
            self._chains.append((c, s, by_coordinate, rate))

    def convert(self, expr):
        r"""The ring element of the symbolic expression ``expr``.

        EXAMPLES: `z^2\cos(x + \omega t)` with the coordinates `x, z`::

            sage: from sage_dynsym.algebra.trigonometric import TrigPolynomialRing
            sage: x, z, w, t = var('x z w t')
            sage: R = TrigPolynomialRing([x + w*t], [z, w, t]); C = R.calculus([x, z])
            sage: c, s = R.trig(x + w*t); p = c*C.convert(z^2)
            sage: C.convert(z^2)
            z^2
        """
        return self.ring.convert(expr)

    def _through_angles(self, element, select):
        # element = p0 + c p1 is reduced (no c^2); its derivative
        # -s p1 + c dp0/ds + c^2 dp1/ds is kept reduced with c^2 = 1 - s^2,
        # so that no Groebner reduction is ever needed afterwards
        result = self.zero
        for c, s, by_coordinate, rate in self._chains:
            factor = select(by_coordinate, rate)
            if factor is not None:
                p1 = element.derivative(c)
                p0 = element - c * p1
                result += factor * (-s * p1 + c * p0.derivative(s)
                                    + (1 - s ** 2) * p1.derivative(s))
        return result

    def derivative(self, element, k):
        r"""
        The derivative of ``element`` with respect to the coordinate of
        index ``k``, or with respect to time (explicit dependence) for
        ``k = None``.

        EXAMPLES: `z^2\cos(x + \omega t)` with the coordinates `x, z`::

            sage: from sage_dynsym.algebra.trigonometric import TrigPolynomialRing
            sage: x, z, w, t = var('x z w t')
            sage: R = TrigPolynomialRing([x + w*t], [z, w, t]); C = R.calculus([x, z])
            sage: c, s = R.trig(x + w*t); p = c*C.convert(z^2)
            sage: [C.symbolic(C.derivative(p, k)) for k in (0, 1, None)]
            [-z^2*sin(t*w + x), 2*z*cos(t*w + x), -w*z^2*sin(t*w + x)]
        """
        if k is None:
            direct = element.derivative(self._time) if self._time is not None else self.zero
            return direct + self._through_angles(element, lambda by, rate: rate)
        direct = element.derivative(self._direct[k]) if self._direct[k] is not None else self.zero
        return direct + self._through_angles(element, lambda by, rate: by.get(k))

    def _uses(self, element):
        return set(element.variables())

    def dependencies(self, element):
        r"""The set of the indices of the coordinates ``element`` depends on.

        EXAMPLES: `z^2\cos(x + \omega t)` with the coordinates `x, z`::

            sage: from sage_dynsym.algebra.trigonometric import TrigPolynomialRing
            sage: x, z, w, t = var('x z w t')
            sage: R = TrigPolynomialRing([x + w*t], [z, w, t]); C = R.calculus([x, z])
            sage: c, s = R.trig(x + w*t); p = c*C.convert(z^2)
            sage: C.dependencies(p), C.dependencies(C.convert(z)), C.dependencies(C.convert(w))
            ({0, 1}, {1}, set())
        """
        used = self._uses(element)
        found = {k for k, v in enumerate(self._direct) if v is not None and v in used}
        for c, s, by_coordinate, _ in self._chains:
            if c in used or s in used:
                found.update(by_coordinate)
        return found

    def depends_on_time(self, element):
        r"""Whether ``element`` depends explicitly on time.

        EXAMPLES: `z^2\cos(x + \omega t)` with the coordinates `x, z`::

            sage: from sage_dynsym.algebra.trigonometric import TrigPolynomialRing
            sage: x, z, w, t = var('x z w t')
            sage: R = TrigPolynomialRing([x + w*t], [z, w, t]); C = R.calculus([x, z])
            sage: c, s = R.trig(x + w*t); p = c*C.convert(z^2)
            sage: C.depends_on_time(p), C.depends_on_time(C.convert(z))
            (True, False)
        """
        used = self._uses(element)
        return (self._time is not None and self._time in used) or any(
            rate is not None and (c in used or s in used) for c, s, _, rate in self._chains)

    def is_zero(self, element):
        r"""Whether ``element`` is zero (a reduced element: exactly).

        EXAMPLES: `z^2\cos(x + \omega t)` with the coordinates `x, z`::

            sage: from sage_dynsym.algebra.trigonometric import TrigPolynomialRing
            sage: x, z, w, t = var('x z w t')
            sage: R = TrigPolynomialRing([x + w*t], [z, w, t]); C = R.calculus([x, z])
            sage: c, s = R.trig(x + w*t); p = c*C.convert(z^2)
            sage: C.is_zero(C.derivative(C.convert(w), 0)), C.is_zero(p)
            (True, False)
        """
        return element.is_zero()

    def symbolic(self, element):
        r"""The reduced ``element`` as a symbolic expression.

        EXAMPLES: `z^2\cos(x + \omega t)` with the coordinates `x, z`::

            sage: from sage_dynsym.algebra.trigonometric import TrigPolynomialRing
            sage: x, z, w, t = var('x z w t')
            sage: R = TrigPolynomialRing([x + w*t], [z, w, t]); C = R.calculus([x, z])
            sage: c, s = R.trig(x + w*t); p = c*C.convert(z^2)
            sage: C.symbolic(p)
            z^2*cos(t*w + x)
        """
        return self.ring.to_symbolic(element, reduced=True)


def trig_rational_simplify(expr, strict=False):
    r"""
    Simplify a rational function of sines, cosines and other symbols
    modulo `\cos^2 + \sin^2 = 1`, whatever the angles: coordinates,
    known functions of time (`\omega t`), parameters or constants.

    The sines and cosines are polynomial variables (one pair per
    argument); any other non-rational part (`\sqrt 2`, `\pi`,
    `e^{x}`, ...) is an independent variable, after simplifying its own
    arguments. See :meth:`TrigPolynomialRing.simplest_fraction`: the result
    is the shortest of several normal forms, or ``expr`` itself if that is
    shorter; it is zero if ``expr`` is zero modulo the identity. No Maxima.

    Expressions that are not rational in the generators (inexact numbers),
    or whose common denominator gets more than 2000 terms, are returned
    unchanged; with ``strict=True`` they raise :class:`NotPolynomial`
    instead (for callers that need the zero test).

    EXAMPLES::

        sage: from sage_dynsym.algebra.trigonometric import trig_rational_simplify
        sage: w, t, x, m = var('w t x m')
        sage: trig_rational_simplify(cos(w*t)^4 + 2*cos(w*t)^2*sin(w*t)^2 + sin(w*t)^4)
        1
        sage: trig_rational_simplify(m*x^2*sin(x)^2/(1 - cos(x)^2)
        ....:                        + sqrt(2)*cos(x)^2 + sqrt(2)*sin(x)^2)
        m*x^2 + sqrt(2)
        sage: trig_rational_simplify((m*cos(x)^2 - m)/(sin(x)*cos(x)))
        -m*sin(x)/cos(x)
        sage: trig_rational_simplify(sqrt(cos(x)^2 + sin(x)^2 + m) + exp(cos(w*t)^2 + sin(w*t)^2))
        sqrt(m + 1) + e

    TESTS::

        sage: trig_rational_simplify(SR(0)), trig_rational_simplify(0.5*sin(x)^2 + 0.5*cos(x)^2)
        (0, 0.500000000000000*cos(x)^2 + 0.500000000000000*sin(x)^2)
        sage: trig_rational_simplify(0.5*sin(x)^2, strict=True)
        Traceback (most recent call last):
        ...
        NotPolynomial: 0.500000000000000 is not a rational number
        sage: y, z = var('y z')
        sage: e = sum(1/(x + k*y + k^2*z + 1) for k in range(30))
        sage: trig_rational_simplify(e) is e
        True
        sage: trig_rational_simplify(e, strict=True)
        Traceback (most recent call last):
        ...
        NotPolynomial: the fraction has more than 2000 terms
        sage: trig_rational_simplify('sin(x)^2')
        Traceback (most recent call last):
        ...
        AnalysisError: expr: expected a symbolic expression, got 'sin(x)^2' (str)
    """
    expr = expression_argument(expr, "expr", AnalysisError)
    original = expr
    try:
        ring = TrigPolynomialRing.for_expressions([expr], fractions=True)
        inner = {}
        for atom in ring.atoms():
            # the arguments of sqrt(...), exp(...), ... are simplified too
            if atom.operator() is not None:
                rebuilt = atom.operator()(*[trig_rational_simplify(x) for x in atom.operands()])
                if not (rebuilt - atom).is_trivial_zero():
                    inner[atom] = rebuilt
        if inner:
            expr = expr.subs(inner)
            ring = TrigPolynomialRing.for_expressions([expr], fractions=True)
        simplest = ring.simplest_fraction(*ring.fraction(expr, limit=_FRACTION_TERMS),
                                          printed=True)
    except NotPolynomial:
        if strict:
            raise
        return original
    return simplest if len(str(simplest)) <= len(str(original)) else original
