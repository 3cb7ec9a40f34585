r"""
Fraction-free determinants with the sign of the determinant

The characteristic polynomials of the analysis are determinants of
matrices whose entries are rational in the parameters. Clearing the
denominators row by row and multiplying their product back in gives a
polynomial with the zeros *and the sign* of the determinant, without
assuming any denominator positive.

EXAMPLES::

    sage: from sage_dynsym.algebra.determinants import fraction_free_det
    sage: m, k, lam = var('m k lam')
    sage: fraction_free_det(matrix([[lam, -1], [k/m, lam]]))
    lam^2*m^2 + k*m
"""
from sage.matrix.constructor import matrix
from sage.rings.rational_field import QQ
from sage.symbolic.ring import SR

from ..errors import AnalysisError
from .polynomials import parameter_ring, to_ring, positive_polynomial
from .translation import Translation

__all__ = ['fraction_free_det']


def fraction_free_det(A, as_polynomial=False, positive=()):
    r"""
    A polynomial with the sign (and the zeros) of ``det(A)``.

    Each row is multiplied by the least common multiple `d_i` of its
    denominators and the determinant is taken over a polynomial ring
    (Singular); then `\det A = N/D` with `N = \det(\mathrm{diag}(d) A)`,
    `D = \prod d_i`, and the result is `N D` with common factors cancelled:
    no denominator is assumed positive unless its factors are declared in
    ``positive``. Non-polynomial parts of the entries (unspecified
    functions and their derivatives, ``cos(alpha)``) are atoms.

    OUTPUT: a symbolic expression, or with ``as_polynomial`` an element of a
    polynomial ring over `\QQ` in the symbols (sorted by name)

    EXAMPLES::

        sage: from sage_dynsym.algebra.determinants import fraction_free_det
        sage: a, g, lam = var('a g lam'); f = function('f')
        sage: fraction_free_det(matrix([[lam, 1], [-a/g, lam]]))
        g^2*lam^2 + a*g
        sage: fraction_free_det(matrix([[lam, 1], [-a/g, lam]]), positive=[g])
        g*lam^2 + a
        sage: fraction_free_det(matrix([[lam - diff(f(a), a)]]))
        lam - diff(f(a), a)
    """
    T = Translation([], [], extra=A.list())
    R = T.flat_ring()
    if R is None:
        det = SR(matrix(QQ, [[QQ(e) for e in row] for row in A.rows()]).det())
        return to_ring(det, QQ) if as_polynomial else det
    rows, D = [], R(1)
    for row in A.rows():
        fractions = [T.fraction(e) for e in row]
        d = R(1)
        for f in fractions:
            d = d.lcm(R(f.denominator()))
        D *= d
        rows.append([R(f * d) for f in fractions])
    N = matrix(R, rows).det()
    if not D.is_constant() and not N.is_zero():
        g = N.gcd(D)
        N, D = N // g, D // g
    names = T.positive_names(positive)
    if D.is_constant():
        scale = R(QQ(D.constant_coefficient()).sign())
    else:
        F = D.factor()
        scale = R(QQ(F.unit()).sign())
        for factor, e in F:
            if e % 2 and not positive_polynomial(factor, names):
                scale *= factor
    det = T.symbolic(N * scale)
    if not as_polynomial:
        return det
    if any(not p.is_symbol() for p in T.parameters()):
        raise AnalysisError("the characteristic matrix is not rational in its "
                            "symbols; use as_polynomial=False", entry="linearize")
    return to_ring(det, parameter_ring(det.variables()), "characteristic polynomial")
