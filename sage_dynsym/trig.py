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
    -cos(a)*sin(a)^2 + cos(a)
"""
from sage.rings.polynomial.polynomial_ring_constructor import PolynomialRing
from sage.rings.rational_field import QQ
from sage.symbolic.ring import SR


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
        self._ideal = self.ring.ideal([c ** 2 + s ** 2 - 1 for c, s in self._pairs.values()])
        self.zero = self.ring.zero()

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

    def to_symbolic(self, element):
        reduced = self._ideal.reduce(element) if self._pairs else element
        return SR(reduced).subs(self._backward) if self._backward else SR(reduced)
