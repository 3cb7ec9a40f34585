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

A relative equilibrium of a Lie--Poisson system on its symplectic leaf
(:func:`relative_equilibrium_verdict`, for the census of
:mod:`~sage_dynsym.analysis.leaf_census`) is decided in the number field
of the point, with signs certified by interval refinement of its
embedding: a verdict at a point of degree 18 (the asymmetric heavy top)
takes a fraction of a second, where arithmetic with algebraic numbers
(``QQbar``) takes many minutes.

EXAMPLES: see :func:`point_verdict`.

REFERENCES:

- E. J. Routh, *A Treatise on the Stability of a Given State of Motion*,
  Macmillan, 1877.
- D. R. Merkin, *Introduction to the Theory of Stability*, Springer, 1997,
  ch. 6 (gyroscopic systems; Kelvin--Chetaev).
"""
from sage.matrix.constructor import matrix
from sage.rings.polynomial.polynomial_ring_constructor import PolynomialRing
from sage.rings.qqbar import AA, QQbar, number_field_elements_from_algebraics
from sage.rings.rational_field import QQ
from sage.rings.real_mpfi import RealIntervalField
from sage.symbolic.ring import SR

from .charts import algebraic_value
from .energy_casimir import energy_casimir_stability, hamiltonian_field

__all__ = ['point_verdict', 'is_gyroscopic', 'spectrum_verdict', 'relative_equilibrium_verdict']


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
    # a remainder whose leading coefficient may be zero has no certain
    # degree (or q is not squarefree)
    sequence = _sturm_sequence(q, lambda c: c.contains_zero())
    if sequence is None or any(f.leading_coefficient().contains_zero() or f[0].contains_zero()
                               for f in sequence):
        return None
    return _sturm_root_counts(sequence, lambda x: 1 if x > 0 else -1)


def _sturm_sequence(f, uncertain=lambda c: False):
    r"""The Sturm sequence of the squarefree polynomial ``f`` (``f``, its
    derivative, then minus the remainders), or ``None`` when a remainder is
    zero or its leading coefficient is ``uncertain`` (an interval that
    contains zero)."""
    sequence = [f, f.derivative()]
    while sequence[-1].degree() > 0:
        r = -(sequence[-2] % sequence[-1])
        if r.degree() < 0 or uncertain(r.leading_coefficient()):
            return None
        sequence.append(r)
    return sequence


def _sturm_root_counts(sequence, sign):
    r"""The numbers of distinct negative and positive real roots of the
    first polynomial of the Sturm ``sequence`` (its value at `0` nonzero),
    from the sign variations at `-\infty`, `0`, `+\infty`; ``sign`` gives
    the sign (`-1, 0, 1`) of a coefficient."""
    def changes(signs):
        signs = [x for x in signs if x != 0]
        return sum(1 for a, b in zip(signs, signs[1:]) if a != b)
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


def relative_equilibrium_verdict(H, casimirs, poisson_matrix, variables, values):
    r"""
    The stability of a relative equilibrium of the Lie--Poisson system
    `\dot x = J(x)\nabla H` on its symplectic leaf (the level of the
    Casimirs through it), at a point of real algebraic numbers, decided
    exactly: ``'stable'`` by the energy--Casimir method (the second
    variation of `H + \lambda\cdot C` definite on the tangent space of the
    leaf), ``'unstable'`` for a root of the linearization with a positive
    real part, ``'stable in first approximation'`` when the linearization
    on the leaf (its characteristic polynomial without the `k` zero roots
    transversal to the leaf) has simple roots on the imaginary axis,
    ``'undecided'`` otherwise or at a singular point of the leaf.

    The coordinates of the point are written in one number field `K =
    \QQ(\alpha)` with a real embedding (Sage's
    ``number_field_elements_from_algebraics``, the field of the point), and
    everything is computed in `K`: the gradients and Hessians (`H`, the
    Casimirs and `J` are polynomials with rational coefficients), the
    multipliers, the tangent space, the leading minors of the second
    variation on it (Sylvester), the characteristic polynomial. An element
    of `K` is zero exactly when its polynomial in `\alpha` is; the sign of
    a nonzero one is that of its value on an isolating interval of
    `\alpha`, refined until the interval excludes zero (certified interval
    arithmetic), so every sign is exact -- never a rounded guess. On a leaf
    the linearization is Hamiltonian: its characteristic polynomial is
    `q(z^2)`, and its roots are simple and imaginary iff those of `q` are
    simple, real and negative, a root `z` with `\operatorname{Re} z > 0`
    exists iff `q` has a root outside `(-\infty, 0]`; the real roots of the
    squarefree part of `q` are counted by a Sturm sequence over `K`.

    Where a function is not a polynomial over `\QQ` (irrational parameter
    values), at a singular point of the leaf or where the characteristic
    polynomial on the leaf is not even, the verdict is computed with
    algebraic numbers (:func:`~sage_dynsym.analysis.energy_casimir.energy_casimir_stability`,
    :func:`spectrum_verdict`): exact, but slow for points of high degree.

    INPUT:

    - ``H`` -- the Hamiltonian (no parameter left)
    - ``casimirs`` -- the Casimirs `C_1, \dots, C_k` of `J`
    - ``poisson_matrix`` -- `J(x)`
    - ``variables`` -- the variables `x`
    - ``values`` -- the values of the variables at the relative
      equilibrium: exact real algebraic numbers (or expressions of them)

    OUTPUT: one of ``'stable'``, ``'unstable'``, ``'stable in first
    approximation'``, ``'undecided'``

    EXAMPLES: the free rigid body, `I = (1, 2, 3)`, rotating about its
    axes on the sphere `|M| = 1`: stable about the smallest and the largest
    (Euler; Arnold, *Mathematical Methods*, §29)::

        sage: from sage_dynsym.analysis.point_stability import relative_equilibrium_verdict
        sage: M1, M2, M3 = var('M1 M2 M3')
        sage: J = matrix([[0, -M3, M2], [M3, 0, -M1], [-M2, M1, 0]])
        sage: H = M1^2/2 + M2^2/4 + M3^2/6
        sage: [relative_equilibrium_verdict(H, [M1^2 + M2^2 + M3^2], J, [M1, M2, M3], e)
        ....:  for e in ([1, 0, 0], [0, 1, 0], [0, 0, 1])]
        ['stable', 'unstable', 'stable']

    The same body on the sphere `|M| = \sqrt[3]{2}` (a point of degree 3)::

        sage: r = AA(2)^(1/3)
        sage: relative_equilibrium_verdict(H, [M1^2 + M2^2 + M3^2], J, [M1, M2, M3], [0, r, 0])
        'unstable'

    The heavy top with the centre of mass at `(1, 1, 1)` and `I = (1, 2,
    3)` on the leaf `(M, \gamma) = 1`, `|\gamma| = 1`: two relative
    equilibria (permanent rotations), real algebraic numbers of degree 18,
    one stable (the energy--Casimir method) and one unstable::

        sage: from sage_dynsym.analysis.stationary import stationary_solutions
        sage: from sage_dynsym.analysis.charts import configuration_points
        sage: g1, g2, g3 = var('gamma1 gamma2 gamma3')
        sage: x = [M1, M2, M3, g1, g2, g3]
        sage: H = M1^2/2 + M2^2/4 + M3^2/6 + g1 + g2 + g3
        sage: C = [M1*g1 + M2*g2 + M3*g3, g1^2 + g2^2 + g3^2]
        sage: S = matrix([[0, -M3, M2], [M3, 0, -M1], [-M2, M1, 0]])
        sage: G = matrix([[0, -g3, g2], [g3, 0, -g1], [-g2, g1, 0]])
        sage: J = block_matrix([[S, G], [G, 0]])
        sage: field = (J * vector([H.diff(v) for v in x])).list()
        sage: sols = stationary_solutions([H] + C, x, equations=field, levels=[1, 1])
        sage: points = configuration_points(sols)
        sage: sorted(relative_equilibrium_verdict(H, C, J, x, [p.value(v) for v in x])
        ....:        for p in points)
        ['stable', 'unstable']

    TESTS: Brun's problem, `H = \frac12 (M, I^{-1} M) + \frac12 (\gamma,
    I\gamma)`, `I = (1, 2, 3)`, at the rotations about the axes on the
    levels `(M, \gamma) = c`, `|\gamma| = 1`: about the first axis stable
    for `c < 1` (energy--Casimir), stable in first approximation for `c >
    1`; about the third axis for `2 < c < 3` a root with a positive real
    part; for `c > 3` stable (energy--Casimir) with double roots on the
    leaf; at `c = 1` a zero root (degenerate)::

        sage: H = (M1^2 + M2^2/2 + M3^2/3)/2 + (g1^2 + 2*g2^2 + 3*g3^2)/2
        sage: def at(k, c):
        ....:     e = [int(i == k) for i in range(3)]
        ....:     return relative_equilibrium_verdict(H, C, J, x, [c*a for a in e] + e)
        sage: [at(0, 1/2), at(0, 3/2), at(2, 5/2), at(2, 4), at(0, 1)]
        ['stable', 'stable in first approximation', 'unstable', 'stable', 'undecided']

    A function that is not a polynomial over `\QQ` (the algebraic-number
    route)::

        sage: M1, M2, M3 = var('M1 M2 M3')
        sage: S3 = matrix([[0, -M3, M2], [M3, 0, -M1], [-M2, M1, 0]])
        sage: relative_equilibrium_verdict(M1^2/2 + M2^2/4 + sqrt(2)*M3^2, [M1^2 + M2^2 + M3^2],
        ....:                              S3, [M1, M2, M3], [0, 1, 0])
        'stable'
    """
    x = [SR(v) for v in variables]
    point = [algebraic_value(SR(v), str(u)) for v, u in zip(values, x)]
    try:
        R = PolynomialRing(QQ, [str(v) for v in x])
        Hp, Cp = R(SR(H)), [R(SR(C)) for C in casimirs]
        Jp = matrix(R, [[R(SR(e)) for e in row] for row in matrix(SR, poisson_matrix).rows()])
    except (TypeError, ValueError):
        return _algebraic_leaf_verdict(H, casimirs, poisson_matrix, x, point)
    K, at, to_algebraic = number_field_elements_from_algebraics(point, embedded=True,
                                                                minimal=False)

    def value(f):
        return K(f(*at))

    def hessian(f):
        return matrix(K, [[value(f.derivative(a).derivative(b)) for b in R.gens()]
                          for a in R.gens()])
    G = matrix(K, len(Cp), len(x), [[value(C.derivative(v)) for v in R.gens()] for C in Cp])
    if G.rank() < len(Cp):
        return _algebraic_leaf_verdict(H, casimirs, poisson_matrix, x, point)
    gradient = matrix(K, [[value(Hp.derivative(v)) for v in R.gens()]])
    try:
        multipliers = G.solve_left(-gradient).row(0) if Cp else []
    except ValueError:      # grad H not in the span: not a relative equilibrium of J
        return _algebraic_leaf_verdict(H, casimirs, poisson_matrix, x, point)
    second = hessian(Hp) + sum((m * hessian(C) for m, C in zip(multipliers, Cp)),
                               matrix(K, len(x)))
    tangent = G.right_kernel_matrix() if Cp else matrix.identity(K, len(x))
    Q = tangent * second * tangent.transpose()
    if _is_positive_definite(Q) or _is_positive_definite(-Q):
        return 'stable'
    field = Jp * matrix(R, [[Hp.derivative(v)] for v in R.gens()])
    A = matrix(K, [[value(f.derivative(v)) for v in R.gens()] for f in field.column(0)])
    poly = A.charpoly('z')
    leaf, rest = poly.quo_rem(poly.parent().gen() ** len(Cp))
    if rest != 0:       # no k zero roots: the field does not map into the leaf
        verdict = _number_field_spectrum_verdict(poly, to_algebraic)
        return 'unstable' if verdict == 'unstable' else 'undecided'
    return _number_field_spectrum_verdict(leaf, to_algebraic)


def _algebraic_leaf_verdict(H, casimirs, poisson_matrix, x, point):
    r"""The verdict of :func:`relative_equilibrium_verdict` with algebraic
    numbers (``QQbar``): the energy--Casimir method, then the first
    approximation on the leaf."""
    at = {v: SR(p) for v, p in zip(x, point)}
    verdict = energy_casimir_stability(H, casimirs, poisson_matrix, x, at).verdict()
    if verdict != 'undecided':
        return verdict
    field = hamiltonian_field(H, poisson_matrix, x)
    A = matrix(QQbar, [[QQbar(SR(f).diff(v).subs(at)) for v in x] for f in field])
    G = matrix(QQbar, [[QQbar(SR(C).diff(v).subs(at)) for v in x] for C in casimirs])
    if G.rank() < len(casimirs):
        return 'undecided'      # a singular point of the leaf
    # the field maps into the tangent space of the leaf: the k transversal
    # roots of its linearization are zeros
    z = PolynomialRing(QQbar, 'z').gen()
    leaf, rest = A.charpoly('z').quo_rem(z ** len(casimirs))
    return spectrum_verdict(leaf) if rest == 0 else 'undecided'


def _sign(a):
    r"""The sign of an element of a number field with a real embedding
    (or of `\QQ`): zero exactly, otherwise by the embedding's interval
    refinement (Sage's comparison of embedded number field elements)."""
    return 0 if a == 0 else (1 if a > 0 else -1)


def _number_field_spectrum_verdict(poly, to_algebraic):
    r"""
    :func:`spectrum_verdict` for a polynomial over a number field `K` with
    a real embedding: for an even polynomial `q(z^2)` by the real roots of
    `q` (the squarefree part, a Sturm sequence over `K`, certified signs);
    otherwise with its coefficients as algebraic numbers (``to_algebraic``,
    the embedding of `K`).

    EXAMPLES::

        sage: from sage_dynsym.analysis.point_stability import _number_field_spectrum_verdict
        sage: K.<a> = NumberField(x^2 - 2, embedding=1.4)
        sage: z = polygen(K, 'z')
        sage: f = K.hom([AA(2).sqrt()])
        sage: [_number_field_spectrum_verdict(p, f) for p in ((z^2 + a)*(z^2 + 1), (z^2 + a)^2,
        ....:      z^2*(z^2 + a), (z^2 - a)*(z^2 + 1), z^4 + z^2 + a, z^3 + a*z + 1)]
        ['stable in first approximation', 'undecided', 'undecided', 'unstable', 'unstable',
         'unstable']
    """
    coefficients = poly.list()
    if any(c != 0 for c in coefficients[1::2]):
        return spectrum_verdict(PolynomialRing(QQbar, 'z')([QQbar(to_algebraic(c))
                                                            for c in coefficients]))
    w = PolynomialRing(poly.base_ring(), 'w').gen()
    q = w.parent()(coefficients[::2])
    free = q // q.gcd(q.derivative())
    zero = free[0] == 0
    if zero:
        free = free // w
    if free.degree() > 0:
        negative, positive = _sturm_root_counts(_sturm_sequence(free), _sign)
    else:
        negative = positive = 0
    if negative + positive < free.degree() or positive:
        return 'unstable'       # a root of q not in (-oo, 0]: z = +-sqrt of it, one Re > 0
    if zero or free.degree() + zero < q.degree():
        return 'undecided'      # a zero root, or a multiple one
    return 'stable in first approximation'
