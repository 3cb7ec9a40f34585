r"""
Lyapunov stability of an equilibrium of a Hamiltonian system from its
Birkhoff normal form

The decision of :func:`~sage_dynsym.dynamics.nonlinear_stability.nonlinear_stability`,
on neutral data: the Hamiltonian's Taylor polynomial at the equilibrium
(canonical pairs `q_1..q_n, p_1..p_n`) and a function that computes its
normal form to a given order. In order: the first approximation (a root
with a positive real part: unstable), a definite quadratic part (a
definite first integral: stable, Lagrange--Dirichlet), and with roots
simple on the imaginary axis, in two degrees of freedom, Markeev's
resonance criteria (orders 3 and 4) and the Arnold--Moser theorem; in more
degrees of freedom, formal stability only (said so: 'stable in first
approximation').

EXAMPLES: the restricted three-body problem's L4, through the model-level
call (see :mod:`~sage_dynsym.dynamics.nonlinear_stability`)::

    sage: from sage_dynsym import load, nonlinear_stability
    sage: L = load('examples/restricted_three_body.yaml').lagrangian()
    sage: x, y, mu = var('x y mu')
    sage: nonlinear_stability(L, {x: 1/2 - 1/100, y: sqrt(3)/2, mu: 1/100}).verdict()
    'stable'

REFERENCES:

- V. I. Arnold, V. V. Kozlov, A. I. Neishtadt, *Mathematical Aspects of
  Classical and Celestial Mechanics*, Springer, 2006, § 7.
- A. P. Markeev, *Libration Points in Celestial Mechanics and
  Cosmodynamics*, Nauka, 1978.
"""
from sage.matrix.constructor import matrix
from sage.rings.complex_mpfr import ComplexField
from sage.rings.polynomial.polynomial_ring_constructor import PolynomialRing as PR
from sage.rings.qqbar import QQbar
from sage.rings.rational_field import QQ
from sage.rings.real_mpfi import RealIntervalField

from ..errors import AnalysisError
from .normal_forms import symplectic_unit
from .verdict import StabilityVerdict, depends_on_parameters

__all__ = ['normal_form_stability', 'stability_over_parameter']


def normal_form_stability(H, compute_normal_form, order=4, positive=(), prec=256,
                          degenerate=()):
    r"""
    The stability verdict of the equilibrium at the origin of the
    Hamiltonian whose Taylor polynomial (of degree at least 2, exact
    coefficients) is ``H``.

    INPUT:

    - ``H`` -- a polynomial in `q_1..q_n, p_1..p_n` with exact
      coefficients (numbers, no parameter)
    - ``compute_normal_form`` -- a function ``order -> BirkhoffNormalForm``
      of the same Hamiltonian
    - ``order``, ``positive``, ``prec`` -- as for
      :func:`~sage_dynsym.dynamics.nonlinear_stability.nonlinear_stability`
    - ``degenerate`` -- (optional) degrees of Arnold's determinant known to
      vanish at the point (``H`` then being a numerical approximation of a
      point where it does: its small value there decides nothing)

    OUTPUT: a :class:`~sage_dynsym.analysis.verdict.StabilityVerdict`

    EXAMPLES: a minimum of the energy is stable whatever its resonances (a
    1:2 resonance here)::

        sage: from sage_dynsym.analysis.normal_form_stability import normal_form_stability
        sage: R = PolynomialRing(QQ, 'q1, q2, p1, p2'); q1, q2, p1, p2 = R.gens()
        sage: H = (p1^2 + q1^2)/2 + (p2^2 + 4*q2^2)/2 + q1^2*q2
        sage: normal_form_stability(H, None).verdict()
        'stable'
        sage: normal_form_stability(H - 3*q1^2, None).reason()
        "a root of the linearization has a positive real part (Lyapunov's theorem on the first approximation)"
    """
    S, chi = _exact_linearization(H)
    n = S.nrows() // 2
    CC = ComplexField(prec)
    eps = QQ(2) ** (-prec // 2)
    roots = chi.change_ring(CC).roots(multiplicities=False)

    def verdict(kind, reason, method):
        return StabilityVerdict(kind, reason, method=method, positive=positive)
    if any(r.real() > eps for r in roots):
        return verdict('unstable', "a root of the linearization has a positive real part "
                       "(Lyapunov's theorem on the first approximation)", 'first approximation')
    # Sylvester's criterion, exactly (each minor compared with 0 in QQbar)
    minors = [S.matrix_from_rows_and_columns(range(k), range(k)).det()
              for k in range(1, 2 * n + 1)]
    signs = [_sign(m) for m in minors]
    if all(x > 0 for x in signs) or all((-1) ** (k + 1) * x > 0 for k, x in enumerate(signs)):
        return verdict('stable', "the energy has a strict minimum at the equilibrium "
                       "(Lagrange-Dirichlet): a definite first integral, whatever the "
                       "resonances" if signs[0] > 0 else "the energy is negative definite at "
                       "the equilibrium: a definite first integral", 'energy')
    # a multiple root: the resultant of chi and chi' (a Sylvester determinant:
    # chi.discriminant() asks PARI first, which refuses a polynomial over
    # QQbar; the caught error went through an abort that pytest's fault
    # handler printed as 'Fatal Python error: Aborted')
    if _sign(chi[0]) == 0 or _sign(chi.sylvester_matrix(chi.derivative()).det()) == 0:
        return verdict('undecided', "multiple or zero roots of the linearization: a critical "
                       "case the normal forms of this package do not treat", 'normal form')
    order = max(order, 4) if n == 2 else order
    nf = compute_normal_form(order)
    resonances = _exact_resonances(chi, nf, order, eps)
    if n != 2:
        return verdict('stable in first approximation', "the normal form of order "
                       f"{order} has {'the resonances ' + str(resonances) if resonances else 'no resonance'}"
                       "; in more than two degrees of freedom it gives formal stability only, "
                       "not Lyapunov stability", 'normal form')
    return _two_degrees(nf, resonances, order, verdict, degenerate)


def _exact_linearization(H):
    r"""The Hessian at the point over ``QQbar`` and the characteristic
    polynomial of `JS` (``H`` with symbolic coefficients, constants)."""
    n = len(H.parent().gens()) // 2
    X = H.parent().gens()
    H2 = H.parent()({e: c for e, c in H.dict().items() if sum(e) == 2})
    S = matrix(QQbar, 2 * n, 2 * n, lambda i, j: QQbar(
        H2.derivative(X[i]).derivative(X[j]).constant_coefficient()))
    return S, (symplectic_unit(n).change_ring(QQbar) * S).charpoly('x')


def _sign(a):
    r"""The sign of the real algebraic number ``a`` (or of the real part):
    by intervals of growing precision, exactly only when they do not
    separate it from 0 (exactification is costly)."""
    for bits in (128, 512):
        box = RealIntervalField(bits)(QQbar(a).real())
        if not box.contains_zero():
            return 1 if box > 0 else -1
    a = QQbar(a).real()
    return 0 if a == 0 else (1 if a > 0 else -1)


def _exact_resonances(chi, nf, order, eps):
    r"""The resonances `k\cdot w = 0`, `|k| \le` ``order`` (``k1 > 0``,
    primitive), by order: candidates from the numeric frequencies,
    confirmed exactly in two degrees of freedom (the roots `s = \lambda^2`
    of `\chi` related by `s_1 = (k_2/k_1)^2 s_2`: a resultant that vanishes)."""
    w = nf.frequencies()
    found = []
    for k, value in nf.resonances(order, tolerance=eps):
        if len(w) == 2:
            s = PR(chi.base_ring(), 's').gen()
            p = sum(chi[2 * j] * s ** j for j in range(3))
            r = QQ(abs(k[1])) / QQ(abs(k[0])) if abs(w[0]) > abs(w[1]) else \
                QQ(abs(k[0])) / QQ(abs(k[1]))
            if _sign(p.sylvester_matrix(p(r ** 2 * s)).det()) != 0:   # not PARI: see above
                raise AnalysisError(f"the frequencies {w} are within {eps} of the resonance "
                                    f"k = {k} without being resonant: increase prec",
                                    entry="prec")
        found.append(k)
    return sorted(found, key=lambda k: sum(map(abs, k)))


def _two_degrees(nf, resonances, order, verdict, degenerate=()):
    eps = QQ(2) ** (-nf.arithmetic().prec // 2) if nf.arithmetic().is_numeric() else 0
    for k in resonances:
        size = sum(map(abs, k))
        name = f"resonance {min(map(abs, k))}:{max(map(abs, k))} (k = {k})"
        if size == 3:
            a = nf.resonant_amplitude(3)
            if a > eps:
                return verdict('unstable', f"{name} with a nonzero resonant term of degree 3 "
                               f"(amplitude {a.n(20)}): unstable (Markeev)", 'Markeev')
            return verdict('undecided', f"{name} whose resonant term of degree 3 vanishes: "
                           "not decided at this order", 'Markeev')
        if size == 4:
            k1, k2 = map(abs, k)
            form = nf.form_values(4)
            h4 = abs(form.get((2, 0), 0) * k1 ** 2 + form.get((1, 1), 0) * k1 * k2
                     + form.get((0, 2), 0) * k2 ** 2)
            a = nf.resonant_amplitude(4) * QQ(k1 ** k1 * k2 ** k2).sqrt()
            if abs(h4 - a) <= eps:
                return verdict('undecided', f"{name}: the terms in the actions and the "
                               "resonant term balance (Markeev's boundary case)", 'Markeev')
            if h4 > a:
                return verdict('stable', f"{name}: the terms of degree 4 in the actions "
                               f"dominate the resonant term ({h4.n(20)} > {a.n(20)}): stable "
                               "(Markeev)", 'Markeev')
            return verdict('unstable', f"{name}: the resonant term of degree 4 dominates "
                           f"({a.n(20)} > {h4.n(20)}): unstable (Markeev)", 'Markeev')
    low = []
    for degree in range(4, order + 1, 2):
        low = [k for k in resonances if sum(map(abs, k)) <= degree]
        if low:
            break
        D = nf.arnold_determinant(degree)
        if degree not in degenerate and abs(D) > eps:
            return verdict('stable', f"Arnold-Moser theorem: no resonance up to order "
                           f"{degree} and Arnold's determinant of degree {degree} "
                           f"D = {D.real().n(30)} is not zero", 'Arnold-Moser')
    if low:
        return verdict('undecided', f"Arnold's determinant vanishes below order {degree}, "
                       f"where the resonances {low} intervene: not decided", 'Arnold-Moser')
    return verdict('undecided', f"Arnold's determinant vanishes up to order {order}: "
                   f"compute the normal form to order {order + 2} (order={order + 2})",
                   'Arnold-Moser')


def stability_over_parameter(parameter, interval, exceptional, verdict_at, positive=()):
    r"""
    The verdict over an interval of one parameter, case by case: the open
    intervals between the exceptional values (where the verdict of
    :func:`normal_form_stability` cannot change: no root crosses the
    imaginary axis, no resonance of the orders considered, Arnold's
    determinant keeps its sign), each decided at an exact rational sample,
    and the exceptional values themselves.

    INPUT:

    - ``parameter`` -- the symbol
    - ``interval`` -- a pair ``(a, b)`` (open)
    - ``exceptional`` -- dict kind -> list of values in ``(a, b)``: real
      algebraic numbers (exact) or real numbers (approximations, e.g. the
      zeros of Arnold's determinant)
    - ``verdict_at`` -- a function ``(value, kinds) -> StabilityVerdict``:
      the verdict at one value (``kinds``: the exceptional kinds of the
      value, empty at a sample)
    - ``positive`` -- symbols declared positive

    OUTPUT: a :class:`~sage_dynsym.analysis.verdict.StabilityVerdict`,
    ``'depends on the parameters'`` with one case per interval and per
    exceptional value (their regions partition the interval), and the
    exceptional values as its :meth:`~sage_dynsym.analysis.verdict.StabilityVerdict.boundaries`

    EXAMPLES: a made-up verdict, unstable at `a = 1/2` only::

        sage: from sage_dynsym.analysis.normal_form_stability import stability_over_parameter
        sage: from sage_dynsym.analysis.verdict import StabilityVerdict
        sage: a = var('a')
        sage: def at(value, kinds):
        ....:     kind = 'unstable' if kinds else 'stable'
        ....:     return StabilityVerdict(kind, f'at {value}')
        sage: v = stability_over_parameter(a, (0, 1), {'resonance 1:2': [AA(1/2)]}, at)
        sage: [(c.verdict(), c.region()) for c in v.cases()]
        [('stable', [[a > 0, a < (1/2)]]), ('unstable', [[a == (1/2)]]),
         ('stable', [[a > (1/2), a < 1]])]
        sage: v.boundaries(), v.at({a: 1/2}), v.at({a: 1/3})
        ({'resonance 1:2': [a == (1/2)]}, 'unstable', 'stable')
    """
    from sage.rings.qqbar import AA
    from sage.rings.real_mpfi import RIF
    from sage.symbolic.ring import SR
    a, b = AA(interval[0]), AA(interval[1])
    points = {}
    for kind, values in exceptional.items():
        for value in values:
            key = next((v for v in points if v == value), value)
            points.setdefault(key, []).append(kind)
    cuts = sorted(points, key=lambda v: RIF(v).center())

    def expression(value):
        if value in AA:
            exact = AA(value).radical_expression()
            return exact if exact in SR and not isinstance(exact, type(AA(0))) else SR(value)
        return SR(value)
    cases = []
    ends = [a] + cuts + [b]
    for k, (lo, hi) in enumerate(zip(ends, ends[1:])):
        width = (RIF(hi) - RIF(lo)) / 4
        sample = RIF(RIF(lo) + width, RIF(hi) - width).simplest_rational()
        v = verdict_at(sample, [])
        cases.append(StabilityVerdict(
            v.verdict(), f"{v.reason()} (decided at {parameter} = {sample})",
            method=v.method(), positive=positive,
            region=[[SR(parameter) > expression(lo), SR(parameter) < expression(hi)]]))
        if k < len(cuts):
            v = verdict_at(hi, points[hi])
            cases.append(StabilityVerdict(
                v.verdict(), f"{', '.join(points[hi])}: {v.reason()}", method=v.method(),
                region=[[SR(parameter) == expression(hi)]], positive=positive))
    boundaries = {}
    for value in cuts:
        for kind in points[value]:
            boundaries.setdefault(kind, []).append(SR(parameter) == expression(value))
    return depends_on_parameters(cases, boundaries, positive)
