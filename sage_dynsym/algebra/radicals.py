r"""
Roots in radicals of a polynomial of degree one to four in one unknown

The coefficients are any symbolic expressions free of the unknown (other
parameters, functions of the coordinates); the roots come from the formulas
`-a_0/a_1` and `(-a_1 \pm \sqrt{a_1^2 - 4 a_2 a_0})/(2 a_2)`, with the
square factors of the discriminant taken out of the root and the rational
parts in Sage's normal form; of degree three from Cardano's formula, of
degree four from Ferrari's (a resolvent cubic), and a biquadratic
`a x^4 + b x^2 + c` as the square roots of the roots of its quadratic,
denested when `c/a` is a square: `\sqrt{u \pm \sqrt v} = \sqrt{(u + w)/2}
\pm \sqrt{(u - w)/2}` with `w^2 = u^2 - v` -- polynomial arithmetic, no equation solver
(Maxima's ``solve`` is kept for equations that are not algebraic:
:func:`~sage_dynsym.algebra.solving.solve_transcendental`).

EXAMPLES::

    sage: from sage_dynsym.algebra.radicals import roots_in_radicals
    sage: p, k, l = var('p k l')
    sage: roots_in_radicals(4*p^2*l^2 - 28*p*k*l + 41*k^2, p)
    [-sqrt(2)*k/l + 7/2*k/l, sqrt(2)*k/l + 7/2*k/l]
"""
from sage.misc.functional import sqrt
from sage.rings.rational_field import QQ
from sage.symbolic.ring import SR

from ..errors import AnalysisError

__all__ = ['roots_in_radicals', 'real_algebraic_roots']


def roots_in_radicals(f, x, entry="roots_in_radicals"):
    r"""
    The roots in ``x`` of ``f``, a polynomial of degree one or two in ``x``.

    INPUT:

    - ``f`` -- a symbolic expression, polynomial in ``x``
    - ``x`` -- the unknown
    - ``entry`` -- (optional) the entry point named in errors

    OUTPUT: a list of symbolic expressions, one root of a linear ``f``, the
    two roots of a quadratic one (equal or complex ones included), the one
    written with `-\sqrt{\ }` first, as Maxima's ``solve`` lists them; the
    three roots of a cubic, the four of a quartic (complex cube and square
    roots taken on their principal branches). A polynomial of degree five
    or more, or an ``f`` that is not polynomial in ``x``, is an
    :class:`~sage_dynsym.errors.AnalysisError`: no root is ever left out
    silently.

    EXAMPLES::

        sage: from sage_dynsym.algebra.radicals import roots_in_radicals
        sage: p, k, l, q = var('p k l q')
        sage: roots_in_radicals(p*l - k, p)
        [k/l]
        sage: roots_in_radicals(p^2 - 2*k*p - l^2, p)    # the root of 4 (k^2 + l^2)
        [k - sqrt(k^2 + l^2), k + sqrt(k^2 + l^2)]
        sage: roots_in_radicals(p^2 - k^2*l^2, p)        # a square comes out of the root
        [-k*l, k*l]
        sage: roots_in_radicals(p^2 - 2*k*p/l + 1/l^2, p)   # a square denominator too
        [k/l - sqrt(k^2 - 1)/l, k/l + sqrt(k^2 - 1)/l]

    A biquadratic, denested: the gyroscopic stabilization threshold
    `g = \sqrt a + \sqrt b` of `g^4 - 2(a + b)g^2 + (a - b)^2`::

        sage: a, b, g = var('a b g')
        sage: roots_in_radicals(g^4 - 2*(a + b)*g^2 + (a - b)^2, g)
        [-sqrt(a) - sqrt(b), sqrt(a) + sqrt(b), -sqrt(a) + sqrt(b), sqrt(a) - sqrt(b)]

    A cubic and a quartic: the roots of `x^3 - 2` and `x^4 - x - 1`::

        sage: [r.n(digits=12) for r in roots_in_radicals(p^3 - 2, p)]
        [1.25992104989, -0.629960524947 + 1.09112363597*I, -0.629960524947 - 1.09112363597*I]
        sage: sorted(CC(r.n(digits=30)) for r in roots_in_radicals(p^4 - p - 1, p)
        ....:        if abs(CC(r).imag()) < 1e-12)
        [-0.724491959000516, 1.22074408460576]

    The formulas hold::

        sage: all(bool((p^2*cos(q) - 2*p + sin(q)).subs(p=r) == 0)
        ....:     for r in roots_in_radicals(p^2*cos(q) - 2*p + sin(q), p))
        True

    TESTS::

        sage: roots_in_radicals(p^5 - k, p)
        Traceback (most recent call last):
        ...
        AnalysisError: roots_in_radicals: p^5 - k has degree 5 in p: roots in radicals are given up to degree four (with values for the other parameters, exact real algebraic roots of any degree: real_algebraic_roots)
        sage: roots_in_radicals(exp(p) - k, p)
        Traceback (most recent call last):
        ...
        AnalysisError: roots_in_radicals: -k + e^p is not a polynomial in p
        sage: roots_in_radicals(k, p)
        Traceback (most recent call last):
        ...
        AnalysisError: roots_in_radicals: k does not depend on p
    """
    f, x = SR(f), SR(x)
    if not f.has(x):
        raise AnalysisError(f"{f} does not depend on {x}", entry=entry)
    if not f.is_polynomial(x):
        raise AnalysisError(f"{f} is not a polynomial in {x}", entry=entry)
    degree = f.degree(x)
    if degree > 4:
        raise AnalysisError(f"{f} has degree {degree} in {x}: roots in radicals are given up "
                            "to degree four (with values for the other parameters, exact real "
                            "algebraic roots of any degree: real_algebraic_roots)", entry=entry)
    a = [f.coefficient(x, k) for k in range(degree + 1)]
    if degree == 1:
        return [(-a[0] / a[1]).normalize()]
    if degree == 3:
        return _cubic(a)
    if degree == 4:
        return _quartic(a, x)
    square, content, rest = _square_part(a[1]**2 - 4 * a[2] * a[0])
    middle = (-a[1] / (2 * a[2])).normalize()
    half_width = (square / (2 * a[2])).normalize() * sqrt(content)
    if str(half_width).startswith('-'):
        half_width = -half_width    # both roots are listed: written with - first, then +
    return [middle + e * half_width * sqrt(rest) for e in (-1, 1)]


def _square_part(discriminant):
    r"""``(s, c, r)`` with ``discriminant = s^2 c r``: ``s`` the factors of
    even multiplicity (negative ones too: denominators), halved; ``c`` the
    positive rational content of the others when it is a square (else 1),
    ``r`` the rest, expanded."""
    square, odd, other = SR(1), SR(1), SR(1)
    for factor, m in SR(discriminant).factor_list():
        m = QQ(m)
        if m.is_integer():
            m = int(m)          # not in QQ, where // is exact division
            square, odd = square * factor**(m // 2), odd * factor**(m % 2)
        else:
            other *= factor**m
    odd = odd.expand()
    content = _content(odd)
    if not content.is_square():             # its root would only split the radical
        content = QQ(1)
    return square, content, (odd / content).expand() * other


def _content(f):
    r"""The positive rational gcd of the numerical coefficients of the terms
    of the sum ``f`` (1 when there is none to take)."""
    from sage.arith.misc import gcd
    from sage.symbolic.operators import add_vararg, mul_vararg
    coefficients = []
    for term in (f.operands() if f.operator() is add_vararg else [f]):
        if term.is_numeric():
            coefficients.append(term)
        elif term.operator() is mul_vararg:
            numeric = [o for o in term.operands() if o.is_numeric()]
            coefficients.append(numeric[0] if numeric else 1)
        else:
            coefficients.append(1)
    try:
        return abs(gcd([QQ(c) for c in coefficients])) or QQ(1)
    except (TypeError, ValueError):
        return QQ(1)


def _quadratic_roots(a2, a1, a0):
    return roots_in_radicals(SR.symbol('_radicals_x')**2 * a2 + SR.symbol('_radicals_x') * a1
                             + a0, SR.symbol('_radicals_x'))


def _cubic(a):
    r"""The roots of `a_3x^3 + a_2x^2 + a_1x + a_0` (Cardano): `x = u + v -
    a_2/(3a_3)` with `u^3` a root of the resolvent quadratic and `v =
    -p/(3u)`, `u` over the three cube roots."""
    from sage.symbolic.constants import I
    b, c, d = (SR(a[k] / a[3]).normalize() for k in (2, 1, 0))
    p = (c - b**2 / 3).normalize()
    q = (2 * b**3 / 27 - b * c / 3 + d).normalize()
    shift = -b / 3
    if p.is_zero():
        u = (-q)**(QQ(1) / 3)
        roots = [u, u * (-1 + I * sqrt(3)) / 2, u * (-1 - I * sqrt(3)) / 2]
        return [(shift + r) for r in roots]
    u3 = _quadratic_roots(1, q, -p**3 / 27)[1]
    u = u3**(QQ(1) / 3)
    omega = (-1 + I * sqrt(3)) / 2
    return [shift + w * u - p / (3 * w * u) for w in (1, omega, omega**2)]


def _quartic(a, x):
    r"""The roots of `a_4x^4 + \dots + a_0` (Ferrari): the depressed quartic
    `y^4 + py^2 + qy + r`, `x = y - a_3/(4a_4)`; a biquadratic (`q = 0`)
    by its quadratic in `y^2`, denested when `r` is a square."""
    b, c, d, e = (SR(a[k] / a[4]).normalize() for k in (3, 2, 1, 0))
    p = (c - 3 * b**2 / 8).normalize()
    q = (b**3 / 8 - b * c / 2 + d).normalize()
    r = (-3 * b**4 / 256 + b**2 * c / 16 - b * d / 4 + e).normalize()
    shift = (-b / 4).normalize()
    if q.is_zero():
        roots = _biquadratic(p, r)
    else:
        # a root m != 0 of the resolvent 8m^3 + 8pm^2 + (2p^2 - 8r)m - q^2
        m = _cubic([-q**2, 2 * p**2 - 8 * r, 8 * p, 8])[0]
        s2m = sqrt(2 * m)
        roots = [(e1 * s2m + e2 * sqrt(-(2 * p + 2 * m + e1 * sqrt(2) * q / sqrt(m)))) / 2
                 for e1 in (1, -1) for e2 in (1, -1)]
    return [shift + y for y in roots]


def _biquadratic(p, r):
    r"""The roots of `y^4 + py^2 + r`: `\pm\sqrt{z}` for the roots `z` of
    `z^2 + pz + r`, denested (`\pm(\sqrt s \pm \sqrt t)` with `s + t = -p`,
    `4st = p^2 - 4(p^2/4 - r)`) when `r` is a square `w^2`."""
    w = _square_root(r)
    if w is not None:
        s, t = ((-p + 2 * w) / 4).normalize(), ((-p - 2 * w) / 4).normalize()
        # (sqrt s +- sqrt t)^2 = s + t +- 2 sqrt(st) are the roots z
        ss, st = _simple_sqrt(s), _simple_sqrt(t)
        return [-(ss + st), ss + st, -(ss - st), ss - st]
    return [e * sqrt(z) for z in _quadratic_roots(1, p, r) for e in (-1, 1)]


def _simple_sqrt(e):
    root = _square_root(e)
    return root if root is not None else sqrt(e)


def _square_root(e):
    r"""A square root of ``e`` without a radical (``None`` when ``e`` is not
    the square of a rational function)."""
    square, content, rest = _square_part(e)
    rest = SR(rest)
    if rest.is_numeric() and rest.is_zero():
        return SR(0)
    if not (rest.is_numeric() and rest == 1):
        return None
    root = QQ(content).sqrt() if QQ(content).is_square() else None
    return None if root is None else (square * root).normalize()


def real_algebraic_roots(f, x, entry="real_algebraic_roots"):
    r"""
    The real roots of ``f``, a polynomial in ``x`` whose coefficients are
    numbers (rationals, radicals, trigonometric values of rational
    multiples of `\pi`), as exact real algebraic numbers (Sage's `AA`),
    of any degree, in increasing order without repetitions.

    INPUT:

    - ``f`` -- a symbolic expression, polynomial in ``x`` with numerical
      coefficients
    - ``x`` -- the unknown
    - ``entry`` -- (optional) the entry point named in errors

    OUTPUT: a list of elements of ``AA`` (printed to any precision with
    ``n(digits=...)``)

    EXAMPLES::

        sage: from sage_dynsym.algebra.radicals import real_algebraic_roots
        sage: x = var('x')
        sage: r = real_algebraic_roots(x^5 - x - 1, x); r
        [1.167303978261419?]
        sage: r[0].n(digits=30)
        1.16730397826141868425604589985
        sage: real_algebraic_roots(x^2 - cos(pi/10), x)
        [-0.9752212653009334?, 0.9752212653009334?]

    TESTS::

        sage: real_algebraic_roots(x^2 - var('k'), x)
        Traceback (most recent call last):
        ...
        AnalysisError: real_algebraic_roots: the coefficient -k of x^2 - k is not a number: give values to its parameters
    """
    from sage.rings.qqbar import AA
    from sage.rings.polynomial.polynomial_ring_constructor import PolynomialRing
    f, x = SR(f).expand(), SR(x)
    if not f.is_polynomial(x):
        raise AnalysisError(f"{f} is not a polynomial in {x}", entry=entry)
    coefficients = []
    for k in range(f.degree(x) + 1):
        c = f.coefficient(x, k)
        try:
            coefficients.append(AA(c))
        except (TypeError, ValueError, NotImplementedError) as err:
            raise AnalysisError(f"the coefficient {c} of {f} is not a number: give values "
                                "to its parameters", entry=entry) from err
    return sorted(PolynomialRing(AA, 'x')(coefficients).roots(multiplicities=False))
