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

Models that are not polynomial in this sense (other functions of the angles,
parameters in denominators) use :class:`SymbolicBackend`.

EXAMPLES::

    sage: from sage_dynsym.trig import TrigPolynomialRing
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
from itertools import chain
from operator import itemgetter

from sage.arith.misc import factorial
from sage.rings.polynomial.polynomial_ring_constructor import PolynomialRing
from sage.rings.rational_field import QQ
from sage.symbolic.ring import SR


_ZERO, _ONE = SR(0), SR(1)


class NotPolynomial(ValueError):
    r"""
    Raised when an expression cannot be written in a
    :class:`TrigPolynomialRing`; callers then work in the symbolic ring.
    """


class SymbolicBackend:
    r"""
    Arithmetic of kinematic quantities in the symbolic ring (the general
    case: any expression is allowed).

    EXAMPLES::

        sage: from sage_dynsym.trig import SymbolicBackend
        sage: B = SymbolicBackend(); x, dx = var('x dx')
        sage: B.diff(B.convert(x*dx), dx), B.at_zero(x*dx + x, [dx]), B.trig(x)
        (x, x, (cos(x), sin(x)))
    """
    zero = SR(0)

    def convert(self, expr):
        return SR(expr)

    def trig(self, angle):
        return SR(angle).cos(), SR(angle).sin()

    def diff(self, element, symbol):
        return element.diff(symbol)

    def at_zero(self, element, symbols):
        return element.subs({v: 0 for v in symbols})

    def to_symbolic(self, element):
        return element


class TrigPolynomialRing:
    r"""
    Kinematic quantities as polynomials over `\mathbb{Q}` in the parameters,
    velocities and the cosines and sines of the rotation angles, reduced
    modulo `\cos^2+\sin^2 = 1` when converted back: Singular's arithmetic
    and a canonical, compact result.

    INPUT:

    - ``angles`` -- the rotation angles (symbolic expressions)
    - ``symbols`` -- every other symbolic variable that may appear

    Converting an expression that is not polynomial in these raises
    :class:`NotPolynomial`.

    EXAMPLES::

        sage: from sage_dynsym.trig import TrigPolynomialRing
        sage: a, l, da = var('a l da')
        sage: R = TrigPolynomialRing([a], [l, da])
        sage: c, s = R.trig(a)
        sage: R.to_symbolic(R.convert(l^2)*(c^2 + s^2))
        l^2
        sage: R.convert(1/a)
        Traceback (most recent call last):
        ...
        NotPolynomial: 1/a is not polynomial in the rotation variables and parameters
    """

    def __init__(self, angles, symbols):
        self._angles = []
        for angle in angles:
            angle = SR(angle)
            if not angle.is_constant() and angle not in self._angles:
                self._angles.append(angle)
        k = len(self._angles)
        self._cos_names = [f'dynsymcos{i}' for i in range(k)]
        self._sin_names = [f'dynsymsin{i}' for i in range(k)]
        others = sorted({str(v) for v in symbols}, key=str)
        self.ring = PolynomialRing(QQ, self._cos_names + self._sin_names + others,
                                   order='degrevlex')
        gens = self.ring.gens()
        self._pairs = {angle: (gens[i], gens[k + i]) for i, angle in enumerate(self._angles)}
        self._forward = {}
        for angle, (i, _) in zip(self._angles, enumerate(self._angles)):
            self._forward[angle.cos()] = SR.var(self._cos_names[i])
            self._forward[angle.sin()] = SR.var(self._sin_names[i])
        self._backward = {SR.var(n): a.cos() for n, a in zip(self._cos_names, self._angles)}
        self._backward.update({SR.var(n): a.sin() for n, a in zip(self._sin_names, self._angles)})
        self.zero = self.ring.zero()
        # the symbolic value of every generator, for the conversion back
        self._values = [self._backward.get(SR.var(name), SR.var(name))
                        for name in self.ring.variable_names()]

    def angles(self):
        r"""
        The angles whose cosine and sine are generators of the ring.

        EXAMPLES::

            sage: from sage_dynsym.trig import TrigPolynomialRing
            sage: TrigPolynomialRing([var('a'), 1, var('a')], []).angles()
            [a]
        """
        return list(self._angles)

    def convert(self, expr):
        expr = SR(expr)
        try:
            return self.ring(expr.subs(self._forward) if self._forward else expr)
        except (TypeError, ValueError, NotImplementedError):
            raise NotPolynomial(f"{expr} is not polynomial in the rotation variables "
                                "and parameters") from None

    def trig(self, angle):
        angle = SR(angle)
        if angle in self._pairs:
            return self._pairs[angle]
        return self.convert(angle.cos()), self.convert(angle.sin())

    def diff(self, element, symbol):
        return element.derivative(self.ring(str(symbol)))

    def at_zero(self, element, symbols):
        return element.subs({self.ring(str(v)): 0 for v in symbols})

    def reduce(self, element):
        r"""
        The normal form of ``element`` modulo `\cos^2+\sin^2 = 1`: no
        monomial divisible by the square of a cosine.

        EXAMPLES::

            sage: from sage_dynsym.trig import TrigPolynomialRing
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
        # Singular's normal form (and its division) is quadratic in the length
        # of the polynomial: minutes for the 50,000-term entries of a 6-link
        # chain. Here each angle costs a few linear passes: the Taylor
        # coefficients p_k of element = sum_k c^k p_k, then c^2 = 1 - s^2.
        for c, s in self._pairs.values():
            degree = element.degree(c)
            if degree < 2:
                continue
            parts, derivative = [], element
            for k in range(degree + 1):
                parts.append(derivative.subs({c: 0}) / factorial(k))
                derivative = derivative.derivative(c)
            one_minus_s2 = 1 - s ** 2
            even = odd = self.zero
            for k in reversed(range(degree + 1)):
                if k % 2:
                    odd = odd * one_minus_s2 + parts[k]
                else:
                    even = even * one_minus_s2 + parts[k]
            element = even + c * odd
        return element

    def to_symbolic(self, element, reduced=False):
        r"""
        The symbolic expression of ``element`` after reduction modulo
        `\cos^2+\sin^2 = 1` (skipped if ``reduced`` says it is already
        reduced, see :meth:`reduce`), in *recursive* form: the variable occurring
        in most terms is factored out, then recursively in each group
        (a multivariate Horner scheme). Typically half the size of the
        expanded form and smaller than nested kinematic expressions.

        EXAMPLES::

            sage: from sage_dynsym.trig import TrigPolynomialRing
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

    def calculus(self, coordinates):
        r"""
        The :class:`RingCalculus` of this ring for the given coordinates.

        EXAMPLES::

            sage: from sage_dynsym.trig import TrigPolynomialRing
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
    :class:`~sage_dynsym.natural_equations.SymbolicCalculus`. Elements must
    be reduced (:meth:`TrigPolynomialRing.reduce`); derivatives stay reduced.

    Raises :class:`NotPolynomial` if an angle's derivative is not polynomial.

    EXAMPLES::

        sage: from sage_dynsym.trig import TrigPolynomialRing
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
        from .expressions import t
        self.ring = ring
        self.zero = ring.zero
        P = ring.ring
        names = set(P.variable_names())
        self._direct = [P(str(q)) if str(q) in names else None for q in coordinates]
        self._time = P(str(t)) if str(t) in names else None
        # per angle: its ring pair and the ring derivatives of the angle
        self._chains = []
        for angle in ring.angles():
            c, s = ring.trig(angle)
            by_coordinate = {k: ring.convert(angle.diff(q)) for k, q in enumerate(coordinates)
                             if angle.has(q)}
            rate = ring.convert(angle.diff(t)) if angle.has(t) else None
            self._chains.append((c, s, by_coordinate, rate))

    def convert(self, expr):
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
        if k is None:
            direct = element.derivative(self._time) if self._time is not None else self.zero
            return direct + self._through_angles(element, lambda by, rate: rate)
        direct = element.derivative(self._direct[k]) if self._direct[k] is not None else self.zero
        return direct + self._through_angles(element, lambda by, rate: by.get(k))

    def _uses(self, element):
        return set(element.variables())

    def dependencies(self, element):
        used = self._uses(element)
        found = {k for k, v in enumerate(self._direct) if v is not None and v in used}
        for c, s, by_coordinate, _ in self._chains:
            if c in used or s in used:
                found.update(by_coordinate)
        return found

    def depends_on_time(self, element):
        used = self._uses(element)
        return (self._time is not None and self._time in used) or any(
            rate is not None and (c in used or s in used) for c, s, _, rate in self._chains)

    def is_zero(self, element):
        return element.is_zero()

    def symbolic(self, element):
        return self.ring.to_symbolic(element, reduced=True)
