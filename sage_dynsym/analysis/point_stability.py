r"""
The stability of a stationary solution at one point, at numerical values
of the parameters, decided exactly

At a point of real algebraic numbers (a
:class:`~sage_dynsym.analysis.charts.ConfigurationPoint`) the verdict is
exact: ``'stable'`` where `W` (or `\pm K`) has a nondegenerate minimum
(Routh's theorem), ``'unstable'`` where the characteristic polynomial has
a root with a positive real part, ``'stable in first approximation'``
where all its roots are simple and on the imaginary axis, ``'undecided'``
otherwise (or at a singular point of the chart). For a gyroscopic system
`M\ddot x + G\dot x + Kx = 0` the characteristic polynomial is
`q(\lambda^2)` and the roots of `q` are counted by a Sturm sequence in
interval arithmetic (exact algebraic numbers as the fallback). Used by the
census (:mod:`~sage_dynsym.analysis.census`) at its sample points and by
the listings of stationary solutions in a chart.

EXAMPLES: see :func:`point_verdict`.

REFERENCES:

- E. J. Routh, *A Treatise on the Stability of a Given State of Motion*,
  Macmillan, 1877.
- D. R. Merkin, *Introduction to the Theory of Stability*, Springer, 1997,
  ch. 6 (gyroscopic systems; Kelvin--Chetaev).
"""
from sage.matrix.constructor import matrix
from sage.rings.polynomial.polynomial_ring_constructor import PolynomialRing
from sage.rings.qqbar import AA, QQbar
from sage.rings.real_mpfi import RealIntervalField
from sage.symbolic.ring import SR

from .charts import algebraic_value

__all__ = ['point_verdict', 'is_gyroscopic', 'spectrum_verdict']


def _is_positive_definite(K):
    return all(K.matrix_from_rows_and_columns(range(k), range(k)).det() > 0
               for k in range(1, K.nrows() + 1))


def point_verdict(point, problem, gyroscopic=None):
    r"""
    The stability of a stationary solution at a point of the configuration
    space, at numerical values of the parameters, decided exactly (real
    algebraic numbers): ``'stable'`` where the function is definite of a
    sign that gives stability (Routh; Lyapunov), else from the first
    approximation as in the module documentation.

    INPUT:

    - ``point`` -- a :class:`~sage_dynsym.analysis.charts.ConfigurationPoint`
    - ``problem`` -- the :class:`~sage_dynsym.analysis.stationary.StationaryProblem`,
      without constraint integrals (the Hessian is not restricted)
    - ``gyroscopic`` -- (optional) :func:`is_gyroscopic` of ``problem``,
      when known (it is decided once per problem)

    OUTPUT: one of ``'stable'``, ``'unstable'``, ``'stable in first
    approximation'``, ``'undecided'``

    EXAMPLES: the real root of `x^5 - x - 1` (not solvable by radicals) is
    a minimum of `x^6/6 - x^2/2 - x`::

        sage: from sage_dynsym.analysis.point_stability import point_verdict
        sage: from sage_dynsym.analysis.stationary import stationary_solutions
        sage: x = var('x')
        sage: sols = stationary_solutions([x^6/6 - x^2/2 - x], [x])
        sage: [point_verdict(p, sols.stationary_problem()) for p in sols.configuration_points()]
        ['stable']
    """
    if gyroscopic is None:
        gyroscopic = is_gyroscopic(problem)
    if point.is_singular():
        return 'undecided'
    K = problem.hessian().apply_map(lambda e: algebraic_value(point.value(e), e))
    M = problem.kinetic
    M = None if M is None else M.apply_map(lambda e: algebraic_value(point.value(e), e))
    if _is_positive_definite(K) and (M is None or _is_positive_definite(M)):
        return 'stable'
    if 'negative' in problem.signs and M is None and _is_positive_definite(-K):
        return 'stable'
    linear = problem.linear_system(point.value)
    if linear is None:
        return 'undecided'
    z = PolynomialRing(AA, 'z').gen()

    def exact(A):
        return A.apply_map(lambda e: algebraic_value(e, 'the first approximation'))
    if linear.order() == 2:
        Mx, Sx, Wx = exact(linear.M()), exact(linear.S()), exact(linear.W())
        if gyroscopic and _is_positive_definite(Mx):
            return _gyroscopic_verdict(Mx, Sx, Wx)
        poly = (Mx * z**2 + Sx * z + Wx).det()
    else:
        J = exact(linear.jacobian())
        poly = (z * matrix.identity(AA, J.nrows()) - J).det()
    return spectrum_verdict(poly)


def spectrum_verdict(poly):
    r"""
    The verdict of the first approximation from its characteristic
    polynomial (exact coefficients): ``'unstable'`` for a root with a
    positive real part, ``'stable in first approximation'`` when all roots
    are simple and on the imaginary axis, ``'undecided'`` otherwise.

    EXAMPLES::

        sage: from sage_dynsym.analysis.point_stability import spectrum_verdict
        sage: z = polygen(AA, 'z')
        sage: [spectrum_verdict(p) for p in (z^2 + 1, z^2 - 1, z^2, (z^2 + 1)^2)]
        ['stable in first approximation', 'unstable', 'undecided', 'undecided']
    """
    roots = poly.roots(QQbar)
    if any(r.real() > 0 for r, _ in roots):
        return 'unstable'
    if all(r.real() == 0 and m == 1 for r, m in roots):
        return 'stable in first approximation'
    return 'undecided'


def is_gyroscopic(problem):
    r"""
    Whether the first approximation of ``problem`` has a skew velocity
    matrix and a symmetric positional one at every point, decided on the
    symbolic matrices (at a point, equal algebraic numbers given by
    different expressions would need their minimal polynomials).

    EXAMPLES: a spinning particle in a rotating plane::

        sage: from sage_dynsym import Lagrangian
        sage: from sage_dynsym.analysis.point_stability import is_gyroscopic
        sage: from sage_dynsym.analysis.stationary import stationary_motions
        sage: x, y, dx, dy, w = var('x y dx dy w')
        sage: L = Lagrangian((dx^2 + dy^2)/2 + w*(x*dy - y*dx) - (x^2 + 3*y^2)/2, [x, y])
        sage: is_gyroscopic(stationary_motions(L).stationary_problem())
        True
    """
    linear = problem.linear_system(lambda e: e)
    if linear is None or linear.order() != 2:
        return False
    S, W = linear.S(), linear.W()
    return all(SR(e).simplify_full().is_zero()
               for e in (S + S.transpose()).list() + (W - W.transpose()).list())


def _gyroscopic_verdict(M, G, K):
    r"""
    The stability of `M\ddot x + G\dot x + Kx = 0` with `G` skew and `M`
    positive definite (and `K` not positive definite): an odd number of
    negative eigenvalues of `K` (`\det K < 0`) gives instability whatever
    the gyroscopic forces (Kelvin--Chetaev); otherwise the characteristic
    polynomial is `q(\lambda^2)`, and the roots are simple and on the
    imaginary axis iff those of `q` are real, negative and simple.
    """
    n = K.nrows()
    if K.det() < 0:
        return 'unstable'
    for prec in (128, 512):
        counts = _sturm_counts(M, G, K, prec)
        if counts is not None:
            break
    else:
        counts = _exact_counts(M, G, K)
    if counts is None:
        return 'undecided'
    negative, positive = counts
    if negative == n:
        return 'stable in first approximation'
    # fewer distinct real roots than the degree (q squarefree), or a positive
    # one: a root mu not real and negative, so lambda with Re > 0
    if negative + positive < n or positive:
        return 'unstable'
    return 'undecided'


def _sturm_counts(M, G, K, prec):
    r"""
    The numbers of distinct negative and positive real roots of `q`, where
    `\det(M z^2 + G z + K) = q(z^2)`, by a Sturm sequence in interval
    arithmetic of precision ``prec``: exact when every leading coefficient
    of the sequence and `q(0)` have a certain sign and `q` is squarefree;
    ``None`` otherwise.
    """
    F = RealIntervalField(prec)
    z = PolynomialRing(F, 'z').gen()
    p = (M.change_ring(F) * z**2 + G.change_ring(F) * z + K.change_ring(F)).det()
    n = K.nrows()
    q = PolynomialRing(F, 'mu')([p[2 * k] for k in range(n + 1)])
    sequence = [q, q.derivative()]
    while sequence[-1].degree() > 0:
        r = -(sequence[-2] % sequence[-1])
        if r.degree() < 0 or r.leading_coefficient().contains_zero():
            return None     # its degree is not certain (or q is not squarefree)
        sequence.append(r)
    if any(f.leading_coefficient().contains_zero() or f[0].contains_zero() for f in sequence):
        return None

    def changes(signs):
        signs = [x for x in signs if x != 0]
        return sum(1 for a, b in zip(signs, signs[1:]) if a != b)

    def sign(x):
        return 1 if x > 0 else -1
    at_minus = changes([sign(f.leading_coefficient()) * (-1) ** f.degree() for f in sequence])
    at_plus = changes([sign(f.leading_coefficient()) for f in sequence])
    at_zero = changes([sign(f[0]) for f in sequence])
    return at_minus - at_zero, at_zero - at_plus


def _exact_counts(M, G, K):
    r"""The numbers of distinct negative and positive real roots of `q`
    (see :func:`_sturm_counts`), exactly; ``None`` when `q` has a multiple
    root (a critical case)."""
    z = PolynomialRing(AA, 'z').gen()
    p = (M * z**2 + G * z + K).det()
    n = K.nrows()
    q = PolynomialRing(AA, 'mu')([p[2 * k] for k in range(n + 1)])
    roots = q.roots(AA)
    if any(m > 1 for _, m in roots) or sum(m for _, m in roots) < n and \
            not q.is_squarefree():
        return None
    return sum(1 for r, _ in roots if r < 0), sum(1 for r, _ in roots if r > 0)
