r"""
Trigonometric normal form of expressions polynomial in sines and cosines

Kinetic energies of rigid-body chains are polynomials in `\sin q_i`,
`\cos q_i`, the velocities and the parameters, but straightforward
kinematics produces them in a redundant form (`\sin^2+\cos^2` pairs that do
not cancel syntactically). :func:`trig_normal_form` maps every
`\sin q_i, \cos q_i` to polynomial variables `s_i, c_i`, reduces modulo the
ideal `(c_i^2 + s_i^2 - 1)` with Singular (these generators are already a
Gröbner basis), and maps back: the result is canonical (equal functions
give equal expressions) and contains no power of a cosine above one.

Expressions that are not of this form (other functions of the angles,
non-polynomial dependence) are returned unchanged.

EXAMPLES::

    sage: from sage_dynsym.trig import trig_normal_form
    sage: a, b, m = var('a b m')
    sage: trig_normal_form(m*cos(a)^2 + m*sin(a)^2*cos(b)^2 + m*sin(a)^2*sin(b)^2, [a, b])
    m
    sage: trig_normal_form(cos(a)^3, [a])
    -cos(a)*sin(a)^2 + cos(a)
    sage: trig_normal_form(sin(2*a) + cos(a)^2, [a])   # sin(2a) is left as it is
    cos(a)^2 + sin(2*a)
"""
from sage.rings.polynomial.polynomial_ring_constructor import PolynomialRing
from sage.rings.rational_field import QQ
from sage.symbolic.ring import SR


def trig_normal_form(expr, angles):
    r"""
    The normal form of ``expr`` modulo `\cos^2 q + \sin^2 q = 1` for each
    ``q`` in ``angles`` (see the module documentation).

    INPUT:

    - ``expr`` -- a symbolic expression
    - ``angles`` -- list of symbolic variables appearing as arguments of
      ``sin`` and ``cos``

    OUTPUT: a symbolic expression, equal to ``expr`` as a function

    EXAMPLES::

        sage: from sage_dynsym.trig import trig_normal_form
        sage: x, l = var('x l')
        sage: trig_normal_form((l*sin(x))^2 + (l*cos(x))^2 + 1/x, [x])   # not polynomial in x
        l^2*cos(x)^2 + l^2*sin(x)^2 + 1/x
        sage: trig_normal_form(SR(0), [x])
        0
    """
    expr = SR(expr)
    angles = [q for q in angles if expr.has(q)]
    if not angles or expr.is_zero():
        return expr
    cosines = [SR.var(f'trigcos{i}') for i in range(len(angles))]
    sines = [SR.var(f'trigsin{i}') for i in range(len(angles))]
    forward = {}
    for q, c, s in zip(angles, cosines, sines):
        forward[q.cos()] = c
        forward[q.sin()] = s
    replaced = expr.subs(forward)
    if any(replaced.has(q) for q in angles):
        return expr
    others = sorted(set(replaced.variables()) - set(cosines) - set(sines), key=str)
    # cosines before sines: the leading term of c^2 + s^2 - 1 is c^2
    names = [str(c) for c in cosines] + [str(s) for s in sines] + [str(v) for v in others]
    ring = PolynomialRing(QQ, names, order='degrevlex')
    try:
        polynomial = ring(replaced)
    except (TypeError, ValueError):
        return expr
    relations = [ring(str(c)) ** 2 + ring(str(s)) ** 2 - 1 for c, s in zip(cosines, sines)]
    reduced = ring.ideal(relations).reduce(polynomial)
    backward = dict(zip(cosines, [q.cos() for q in angles]))
    backward.update(zip(sines, [q.sin() for q in angles]))
    return SR(reduced).subs(backward)
