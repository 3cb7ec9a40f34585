r"""
Nonlinear stability of relative equilibria of Lie--Poisson systems: the
energy--Casimir method

At an equilibrium `m_0` of `\dot m = J(m)\nabla H(m)` the gradient of `H`
lies in the span of the gradients of the Casimirs: `\nabla H(m_0) + \sum_i
\lambda_i \nabla C_i(m_0) = 0`. The function `F = H + \sum_i \lambda_i C_i`
is a first integral with a critical point at `m_0`; if its second variation
is definite on the tangent space of the Casimir level (the vectors `v` with
`\nabla C_i(m_0)\cdot v = 0`), `F` restricted to the level is a Lyapunov
function and `m_0` is Lyapunov stable on the level and, the Casimirs being
conserved, in the whole space (Arnold's method; Holm, Marsden, Ratiu and
Weinstein). Otherwise the first approximation decides where it can: a
root of the linearization with a positive real part makes `m_0` unstable.

EXAMPLES: Euler's rigid body rotating about its axes (moments of inertia
`1 < 2 < 3`): stable about the smallest and the largest, unstable about the
middle one::

    sage: from sage_dynsym.analysis.energy_casimir import energy_casimir_stability
    sage: M1, M2, M3 = var('M1 M2 M3')
    sage: H = (M1^2 + M2^2/2 + M3^2/3)/2; C = [M1^2 + M2^2 + M3^2]
    sage: J = matrix([[0, -M3, M2], [M3, 0, -M1], [-M2, M1, 0]])
    sage: energy_casimir_stability(H, C, J, [M1, M2, M3], {M1: 1, M2: 0, M3: 0})
    stable: energy-Casimir: H + (-1/2)*C1 has a negative definite second variation on the tangent space of the level ... Arnold's method)
    sage: energy_casimir_stability(H, C, J, [M1, M2, M3], {M1: 0, M2: 1, M3: 0}).verdict()
    'unstable'

REFERENCES:

- V. I. Arnold, Conditions for nonlinear stability of stationary plane
  curvilinear flows of an ideal fluid, Soviet Math. Dokl. 6 (1965)
  773--777.
- D. D. Holm, J. E. Marsden, T. Ratiu, A. Weinstein, Nonlinear stability of
  fluid and plasma equilibria, Physics Reports 123 (1985) 1--116.
- J. E. Marsden, T. S. Ratiu, Introduction to Mechanics and Symmetry, 2nd
  ed., Springer 1999, section 1.7.
"""
from sage.matrix.constructor import matrix
from sage.modules.free_module_element import vector
from sage.rings.polynomial.polynomial_ring_constructor import PolynomialRing
from sage.rings.qqbar import QQbar, AA
from sage.symbolic.ring import SR

from ..errors import AnalysisError, brief
from .verdict import StabilityVerdict

__all__ = ['energy_casimir_stability', 'hamiltonian_field']


def hamiltonian_field(H, poisson_matrix, variables):
    r"""
    The vector field `J(x) \nabla H` of the Hamiltonian ``H`` for the
    Poisson matrix ``poisson_matrix`` in ``variables`` (a vector of
    symbolic expressions).

    EXAMPLES: the free rigid body on `so(3)^*`, `J(M) = [M\times]`, gives
    Euler's equations `\dot M = M \times \nabla H`::

        sage: from sage_dynsym.analysis.energy_casimir import hamiltonian_field
        sage: M1, M2, M3, I1, I2, I3 = var('M1 M2 M3 I1 I2 I3')
        sage: J = matrix([[0, -M3, M2], [M3, 0, -M1], [-M2, M1, 0]])
        sage: H = (M1^2/I1 + M2^2/I2 + M3^2/I3)/2
        sage: hamiltonian_field(H, J, [M1, M2, M3])
        (-M2*M3/I2 + M2*M3/I3, M1*M3/I1 - M1*M3/I3, -M1*M2/I1 + M1*M2/I2)
    """
    return (matrix(SR, poisson_matrix) * matrix(SR, [[SR(H).diff(v)] for v in variables])
            ).column(0)


def energy_casimir_stability(H, casimirs, poisson_matrix, variables, at, integrals=(),
                             positive=()):
    r"""
    The stability of the equilibrium ``at`` of the Lie--Poisson system
    `\dot m = J(m)\nabla H(m)` by the energy--Casimir method, then the first
    approximation (see the module documentation).

    With first integrals besides the Casimirs (``integrals``: a momentum of
    a symmetry, say), the multipliers `\lambda` of `F = H + \sum\lambda_i
    I_i` are not unique: `\nabla F(m_0) = 0` leaves a family, and the method
    looks in it for one that makes the second variation definite on the
    tangent space of the common level (exactly, for a family of dimension
    one: between the real roots of the leading minors; the
    energy--Casimir--momentum method).

    INPUT:

    - ``H`` -- the Hamiltonian (symbolic)
    - ``casimirs`` -- the Casimir functions
    - ``poisson_matrix`` -- `J(m)`
    - ``variables`` -- the variables `m`
    - ``at`` -- dict variable -> exact value (every variable, and every
      parameter of ``H``)
    - ``integrals`` -- (optional) first integrals that are not Casimirs
    - ``positive`` -- symbols declared positive (recorded)

    OUTPUT: a :class:`~sage_dynsym.analysis.verdict.StabilityVerdict`:
    ``'stable'`` (energy--Casimir), ``'unstable'`` (first approximation) or
    ``'undecided'`` (no definite second variation found and no root with a
    positive real part)

    EXAMPLES: see the module documentation, and the rotation about the
    largest axis::

        sage: from sage_dynsym.analysis.energy_casimir import energy_casimir_stability
        sage: M1, M2, M3 = var('M1 M2 M3')
        sage: H = (M1^2 + M2^2/2 + M3^2/3)/2; C = [M1^2 + M2^2 + M3^2]
        sage: J = matrix([[0, -M3, M2], [M3, 0, -M1], [-M2, M1, 0]])
        sage: energy_casimir_stability(H, C, J, [M1, M2, M3], {M3: 1, M1: 0, M2: 0}).method()
        'energy-Casimir'

    TESTS::

        sage: energy_casimir_stability(H, C, J, [M1, M2, M3], {M1: 1, M2: 1, M3: 0})
        Traceback (most recent call last):
        ...
        AnalysisError: at: {M1: 1, M2: 1, M3: 0} is not an equilibrium: ...
        sage: energy_casimir_stability(H, C, J, [M1, M2, M3], [1, 0, 0])
        Traceback (most recent call last):
        ...
        AnalysisError: at: expected a dict {variable: value}, got [1, 0, 0]
    """
    if not isinstance(at, dict):
        raise AnalysisError(f"expected a dict {{variable: value}}, got {brief(at)}",
                            entry="at")
    try:
        values = {SR(k): SR(v) for k, v in at.items()}
    except (TypeError, ValueError) as err:
        raise AnalysisError(f"the keys and values of {brief(at)} must be symbols and "
                            f"numbers: {err}", entry="at") from err
    variables = [SR(v) for v in variables]
    missing = [v for v in variables if v not in values]
    free = sorted({str(s) for s in SR(H).variables()} - {str(v) for v in variables}
                  - {str(k) for k in values})
    if missing or free:
        raise AnalysisError(f"give the value of every variable and parameter (missing "
                            f"{[str(v) for v in missing] + free})", entry="at")
    functions = list(casimirs) + list(integrals)

    def at_point(expr):
        return QQbar(SR(expr).subs(values))

    def hessian(f):
        return matrix(QQbar, [[at_point(SR(f).diff(a).diff(b)) for b in variables]
                              for a in variables])
    field = hamiltonian_field(H, poisson_matrix, variables)
    try:
        value = [at_point(f) for f in field]
        gradient = matrix(QQbar, [[at_point(SR(H).diff(v)) for v in variables]])
        G = matrix(QQbar, len(functions), len(variables),
                   [[at_point(SR(c).diff(v)) for v in variables] for c in functions])
    except (TypeError, ValueError) as err:
        raise AnalysisError(f"the values {at} are not exact numbers: {err}", entry="at") from err
    if any(f != 0 for f in value):
        raise AnalysisError(f"{at} is not an equilibrium: J grad H = {value}", entry="at")
    try:
        particular = G.solve_left(-gradient).row(0) if functions else vector(QQbar, [])
    except ValueError as err:
        raise AnalysisError(f"grad H is not in the span of the gradients of the Casimirs and "
                            f"integrals at {at} (a singular point of the Poisson structure?)",
                            entry="at") from err
    family = G.left_kernel().basis_matrix().rows() if functions else []
    tangent = G.right_kernel_matrix() if functions else matrix.identity(QQbar, len(variables))
    base = hessian(H) + sum((m * hessian(f) for m, f in zip(particular, functions)),
                            matrix(QQbar, len(variables)))
    Q0 = tangent * base * tangent.transpose()
    found = _definite(Q0), particular
    if not found[0] and len(family) == 1:
        direction = sum((m * hessian(f) for m, f in zip(family[0], functions)),
                        matrix(QQbar, len(variables)))
        t = _definite_along(Q0, tangent * direction * tangent.transpose())
        if t is not None:
            multipliers = particular + t[1] * family[0]
            found = t[0], multipliers
    sign, multipliers = found
    name = "H" + "".join(f" + ({m})*{'C' if k < len(casimirs) else 'I'}"
                         f"{k + 1 if k < len(casimirs) else k + 1 - len(casimirs)}"
                         for k, m in enumerate(multipliers))
    if sign:
        return StabilityVerdict(
            'stable', f"energy-Casimir: {name} has a {'positive' if sign > 0 else 'negative'} "
            "definite second variation on the tangent space of the level of the Casimirs "
            "and integrals (a Lyapunov function on the level; Arnold's method)",
            method='energy-Casimir', positive=positive)
    A = matrix(QQbar, [[at_point(SR(f).diff(v)) for v in variables] for f in field])
    if any(r.real() > 0 for r in A.charpoly().roots(QQbar, multiplicities=False)):
        return StabilityVerdict(
            'unstable', "a root of the linearization has a positive real part (Lyapunov's "
            "theorem on the first approximation)", method='first approximation',
            positive=positive)
    return StabilityVerdict(
        'undecided', f"the second variation of {name} on the level of the Casimirs and "
        "integrals is not definite (for the multipliers searched) and no root of the "
        "linearization has a positive real part: the energy-Casimir method and the first "
        "approximation do not decide", method='energy-Casimir', positive=positive)


def _minors(Q):
    n = Q.nrows()
    return [Q.matrix_from_rows_and_columns(range(k), range(k)).det() for k in range(1, n + 1)]


def _definite(Q):
    r"""``1``/``-1`` if the symmetric matrix ``Q`` (over ``QQbar``, real) is
    positive/negative definite, else ``0`` (Sylvester's criterion, exact)."""
    if Q.nrows() == 0:
        return 1
    minors = [AA(m.real()) for m in _minors(Q)]
    if all(m > 0 for m in minors):
        return 1
    if all((-1) ** (k + 1) * m > 0 for k, m in enumerate(minors)):
        return -1
    return 0


def _definite_along(Q0, Q1):
    r"""A pair ``(sign, t)`` with `Q_0 + t Q_1` definite of that sign, or
    ``None``: the leading minors are polynomials in `t`; the signs are
    constant between their real roots, so a point of each interval (and
    beyond the extreme roots) decides."""
    t = PolynomialRing(AA, 't').gen()
    Q = (Q0.apply_map(lambda x: AA(x.real())) + t * Q1.apply_map(lambda x: AA(x.real())))
    minors = _minors(Q)
    roots = sorted({r for m in minors if m != 0 for r in m.roots(AA, multiplicities=False)})
    samples = [AA(0)] if not roots else \
        [roots[0] - 1] + [(a + b) / 2 for a, b in zip(roots, roots[1:])] + [roots[-1] + 1]
    for point in samples:
        signs = [m(point) for m in minors]
        if all(x > 0 for x in signs):
            return 1, point
        if all((-1) ** (k + 1) * x > 0 for k, x in enumerate(signs)):
            return -1, point
    return None
