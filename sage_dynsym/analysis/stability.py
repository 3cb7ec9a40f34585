r"""
The stability service: one exact answer for a linear system

:meth:`LinearSystem.stability <sage_dynsym.analysis.linear.LinearSystem.stability>`
is the one place where the package decides stability; reports, stability
maps, sweeps, interactive pages and stationary solutions ask it. It takes
a second-order system `M\ddot z + (D + 2G)\dot z + (K + P)z = 0` or a
first-order one `B\dot x = Jx` and returns a
:class:`~sage_dynsym.analysis.verdict.StabilityVerdict` whose
:meth:`~sage_dynsym.analysis.verdict.StabilityVerdict.cases` partition the
parameter space allowed by the declared signs (up to the boundaries, of
measure zero):

- a second-order system with a nonsingular kinetic matrix and no ignorable
  coordinate: :func:`~sage_dynsym.analysis.kelvin_chetaev.kelvin_chetaev`
  (the theorems on the structure of forces, and the first approximation
  wherever they do not decide);
- otherwise the first approximation of the first-order form `\dot x = Ax`:
  asymptotically stable where the Liénard--Chipart conditions hold, stable
  in first approximation where the roots on the imaginary axis are simple
  or semisimple and the others in the left half-plane, ``'undecided'``
  where a multiple root on the imaginary axis is not semisimple, and
  unstable in the rest (a root with a positive real part: Lyapunov's
  theorem on the first approximation) -- :mod:`~sage_dynsym.analysis.spectrum`.

**Ignorable coordinates.** A variable whose value does not enter the
linear equations (its column in `W`, resp. in `J`, is zero: a heading, the
spin angle of a wheel, the charge of a loop without a capacitor) only
drifts with the others: it adds a zero root for all parameter values,
which is never asymptotically stable and, with its rate, often not
semisimple. The verdict is then about the other variables and the rates
(stability with respect to part of the variables, Rumyantsev), and its
``reason()`` says so; ``with_respect_to=`` names the variables explicitly.

EXAMPLES: a mass on a spring with a damper, as a first-order system::

    sage: from sage_dynsym.analysis.linear import LinearSystem
    sage: x, v, m, c, k = var('x v m c k')
    sage: LinearSystem([x, v], J=[[0, 1], [-k, -c]], B=diagonal_matrix([1, m])).stability(
    ....:     positive=[m, c, k])
    asymptotically stable: every root of the characteristic polynomial has a negative real part ...

A free particle with a damper: its position is ignorable, its velocity
decays::

    sage: LinearSystem([x], M=[[m]], S=[[c]], W=[[0]]).stability(positive=[m, c]).reason()
    "every root of the characteristic polynomial has a negative real part (Liénard-Chipart conditions; Lyapunov's theorem on the first approximation); stability with respect to the rates of x (ignorable: x does not enter the linear equations through its value, it drifts)"

REFERENCES:

- A. M. Lyapunov, *The General Problem of the Stability of Motion*, 1892
  (Taylor & Francis, 1992), §§ 24--27 (the first approximation).
- V. V. Rumyantsev, A. S. Oziraner, *Stability and Stabilization of
  Motion with Respect to Part of the Variables*, Nauka, 1987.
- D. R. Merkin, *Introduction to the Theory of Stability*, Springer, 1997,
  ch. 5 and 6.
"""
from sage.matrix.constructor import matrix
from sage.symbolic.ring import SR

from ..errors import AnalysisError
from ..algebra.determinants import fraction_free_det
from ..algebra.solving import normalize
from .spectrum import spectrum_regions
from .verdict import StabilityVerdict, depends_on_parameters, verdict_from_parts

__all__ = ['REASONS', 'coefficient_conditions', 'ignorable', 'first_approximation',
           'energy_stability', 'linear_stability']

REASONS = {
    'asymptotically stable': "every root of the characteristic polynomial has a negative "
                             "real part (Liénard-Chipart conditions; Lyapunov's theorem on "
                             "the first approximation)",
    'stable in first approximation': "the roots of the characteristic polynomial on the "
                                     "imaginary axis are simple (or semisimple), the others "
                                     "have negative real parts: the linearized system is "
                                     "stable, not asymptotically; the nonlinear terms decide "
                                     "(critical case)",
    'undecided': "every root is in the closed left half-plane, but a multiple root on the "
                 "imaginary axis is not semisimple: the linearized solutions grow like t, "
                 "and the nonlinear terms decide",
    'unstable': "a root of the characteristic polynomial has a positive real part "
                "(Lyapunov's theorem on the first approximation)",
}


def coefficient_conditions(poly, var):
    r"""
    The Liénard--Chipart conditions of the polynomial ``poly`` in ``var``
    stated in its coefficients: for a polynomial whose conditions would be
    too large expanded (a report shows them this way, each coefficient
    given apart).

    OUTPUT: ``None`` for a polynomial without odd coefficients (no
    dissipation: these conditions never hold), else a triple ``(zeros,
    conditions, coefficients)``: the multiplicity of the root `0` (left
    out), the conditions (each ``> 0``) in symbols ``a_k``, and the dict
    ``{a_k: coefficient of var^(k + zeros)}``

    EXAMPLES::

        sage: from sage_dynsym.analysis.stability import coefficient_conditions
        sage: lam, m, c, k = var('lam m c k')
        sage: zeros, conditions, a = coefficient_conditions(lam*(m*lam^2 + c*lam + k), lam)
        sage: zeros, conditions, a
        (1, [a_2, a_0, a_1], {a_0: k, a_1: c, a_2: m})
        sage: coefficient_conditions(m*lam^2 + k, lam) is None
        True
    """
    from .hurwitz import lienard_chipart_conditions
    coefficients = SR(poly).expand().coefficients(var, sparse=False)
    zeros = next(k for k, a in enumerate(coefficients) if not SR(a).is_zero())
    coefficients = coefficients[zeros:]
    if all(SR(a).is_zero() for a in coefficients[1::2]):
        return None
    a = [SR.var(f"a_{k}") for k in range(len(coefficients))]
    generic = sum(a_k * var ** k for k, a_k in enumerate(a))
    return zeros, lienard_chipart_conditions(generic, var), dict(zip(a, coefficients))


def _zero_column(X, j):
    return all(normalize(SR(X[i, j])).is_zero() for i in range(X.nrows()))


def ignorable(system, with_respect_to=None):
    r"""
    The variables of the linear ``system`` left out of the stability
    question: those not in ``with_respect_to`` if given (each must be
    ignorable), else every variable whose value does not enter the
    equations (a zero column of `W`, resp. of `J`).

    EXAMPLES::

        sage: from sage_dynsym.analysis.linear import LinearSystem
        sage: from sage_dynsym.analysis.stability import ignorable
        sage: psi, th, k = var('psi theta k')
        sage: Ls = LinearSystem([psi, th], M=identity_matrix(2), S=zero_matrix(2),
        ....:                   W=matrix([[0, 0], [0, k]]))
        sage: ignorable(Ls), ignorable(Ls, with_respect_to=[psi, th])
        ([psi], [])
        sage: ignorable(Ls, with_respect_to=[psi])
        Traceback (most recent call last):
        ...
        AnalysisError: stability: theta enters the linear equations through its value (its column of W is not zero): it cannot be left out; with_respect_to= must list it (e.g. with_respect_to=[psi, theta])
    """
    X = system.W() if system.order() == 2 else system.characteristic_matrix(0)
    name = 'W' if system.order() == 2 else 'J'
    variables = system.variables()
    if with_respect_to is None:
        return [v for j, v in enumerate(variables) if _zero_column(X, j)]
    kept = [SR(v) for v in with_respect_to]
    unknown = [v for v in kept if v not in variables]
    if unknown:
        raise AnalysisError(f"{', '.join(map(str, unknown))} not among the variables "
                            f"{variables} (with_respect_to=)", entry="stability")
    dropped = [v for v in variables if v not in kept]
    for v in dropped:
        if not _zero_column(X, variables.index(v)):
            raise AnalysisError(f"{v} enters the linear equations through its value (its "
                                f"column of {name} is not zero): it cannot be left out; "
                                f"with_respect_to= must list it (e.g. with_respect_to="
                                f"[{', '.join(map(str, kept + [v]))}])", entry="stability")
    return dropped


def _reduced(system, dropped, positive):
    r"""``(polynomial, lam, A)``: the characteristic polynomial of the
    system without the values of ``dropped`` (fraction-free, the factor
    `\lambda` of each dropped variable divided out: its column of the
    characteristic matrix is `\lambda` times that of `M\lambda + S`, resp.
    of `B`) and the matrix of the reduced first-order form (``None`` when
    `M`, resp. `B`, is singular: a descriptor system, whose finite roots
    are those of the polynomial)."""
    lam = SR.symbol('lambda_stability')
    variables = system.variables()
    keep = [j for j, v in enumerate(variables) if v not in dropped]
    n = len(variables)
    chi_matrix = system.characteristic_matrix(lam)
    lead = system.M() if system.order() == 2 else system.lhs_matrix()
    for j, v in enumerate(variables):
        if v in dropped:
            chi_matrix[:, j] = lead[:, j] * lam + system.S()[:, j] \
                if system.order() == 2 else lead[:, j]
    # state (z, z') of the second-order form: the dropped values go
    rows = keep + list(range(n, 2 * n)) if system.order() == 2 else keep
    A = None if normalize(fraction_free_det(lead)).is_zero() else \
        system.jacobian().matrix_from_rows_and_columns(rows, rows)
    return fraction_free_det(chi_matrix, positive=positive).expand(), lam, A


def first_approximation(system, positive=(), dropped=()):
    r"""
    The verdict of the first approximation for the linear ``system``
    without the values of the variables ``dropped`` (see the module
    documentation): a partition of the parameter space into
    asymptotically stable, stable in first approximation, undecided and
    unstable parts.

    EXAMPLES: a series RLC circuit, `L i' = -R i - u`, `C u' = i`::

        sage: from sage_dynsym.analysis.linear import LinearSystem
        sage: from sage_dynsym.analysis.stability import first_approximation
        sage: i, u, L, R, C = var('i u L R C')
        sage: Ls = LinearSystem([i, u], J=[[-R, -1], [1, 0]], B=diagonal_matrix([L, C]))
        sage: first_approximation(Ls, positive=[L, C]).cases()
        [asymptotically stable where [R > 0]: ..., unstable where [R < 0]: ...]
    """
    positive = list(positive)
    chi, lam, A = _reduced(system, list(dropped), positive)
    if not chi.has(lam):
        raise AnalysisError("no dynamics left: every variable was left out",
                            entry="stability")
    spectrum = spectrum_regions(chi, lam, positive, matrix=A)
    parts = [('asymptotically stable', spectrum.asymptotic()),
             ('stable in first approximation', spectrum.marginal()),
             ('undecided', spectrum.undecided())]
    return verdict_from_parts(parts, REASONS, spectrum.boundaries(), positive,
                              method='first approximation')


def energy_stability(system, positive=(), seed=0):
    r"""
    The energy theorem for a first-order system `B\dot x = Jx` with `B`
    symmetric positive definite and `J + J^T` negative semidefinite for
    all values allowed by the declared signs (a passive circuit: `B` the
    inductances and capacitances, `J + J^T` the resistances): `V = x^T B
    x/2` has `\dot V = x^T (J + J^T) x/2 \le 0`, so the system is stable;
    it is asymptotically stable iff no solution but zero keeps `\dot V =
    0` (LaSalle), i.e. iff the pair `(J + J^T, B^{-1}J)` is observable --
    decided here when a maximal minor of the observability matrix has a
    sign fixed by the declared signs.

    OUTPUT: a :class:`~sage_dynsym.analysis.verdict.StabilityVerdict`
    (``'asymptotically stable'`` or ``'stable'``, everywhere), or ``None``
    when the theorem does not apply

    EXAMPLES: a series RLC circuit, and without its resistor::

        sage: from sage_dynsym.analysis.linear import LinearSystem
        sage: from sage_dynsym.analysis.stability import energy_stability
        sage: i, u, L, R, C = var('i u L R C')
        sage: energy_stability(LinearSystem([i, u], J=[[-R, -1], [1, 0]],
        ....:                  B=diagonal_matrix([L, C])), positive=[L, R, C]).verdict()
        'asymptotically stable'
        sage: energy_stability(LinearSystem([i, u], J=[[0, -1], [1, 0]],
        ....:                  B=diagonal_matrix([L, C])), positive=[L, C]).verdict()
        'stable'
        sage: energy_stability(LinearSystem([i, u], J=[[-R, -1], [1, 0]],
        ....:                  B=diagonal_matrix([L, C])), positive=[L, C]) is None
        True

    REFERENCES:

    - J. P. LaSalle, Some extensions of Liapunov's second method, *IRE
      Trans. Circuit Theory* 7 (1960) 520--527.
    """
    from .quadratic_forms import definiteness_conditions, semidefiniteness_conditions
    B = system.lhs_matrix()
    if system.order() != 1 or B != B.transpose():
        return None
    J = -system.characteristic_matrix(0)
    N = J + J.transpose()
    if definiteness_conditions(B, positive=positive) != [] or \
            semidefiniteness_conditions(-N, positive=positive) != []:
        return None
    why = ("the energy x^T B x/2 (B > 0) is a Lyapunov function: its derivative x^T (J + J^T) "
           "x/2 is negative semidefinite (Lyapunov's theorem")
    if _observable(N, system.jacobian(), positive, seed):
        return StabilityVerdict('asymptotically stable', why + "); only the zero solution keeps "
                                "it constant: (J + J^T, A) is observable (LaSalle)",
                                method='energy', region=[[]], positive=positive)
    if N.is_zero():
        return StabilityVerdict('stable', why + "; the energy is conserved)",
                                method='energy', region=[[]], positive=positive)
    return None


def _observable(N, A, positive, seed):
    r"""Whether ``(N, A)`` is observable for all values allowed by the
    declared signs: ``n`` rows of `N, NA, NA^2, \dots`, independent at a
    random point, whose determinant has a sign fixed by the declarations."""
    import random
    from sage.rings.rational_field import QQ
    from ..algebra.translation import Translation
    from ..algebra.polynomials import positive_polynomial
    n = A.nrows()
    rows, power = [], N
    for _ in range(n):
        rows += list(power.rows())
        power = (power * A).apply_map(lambda e: SR(e).normalize())
    O = matrix(SR, rows)
    symbols = sorted({v for e in O.list() for v in SR(e).variables()}, key=str)
    rng = random.Random(seed)
    point = {v: QQ(rng.randint(100, 300)) / 100 for v in symbols}
    try:
        numeric = O.subs(point).change_ring(QQ)
    except (TypeError, ValueError, ZeroDivisionError):
        return False
    chosen = []
    for k in range(O.nrows()):
        if numeric.matrix_from_rows(chosen + [k]).rank() == len(chosen) + 1:
            chosen.append(k)
    if len(chosen) < n:
        return False
    det = fraction_free_det(O.matrix_from_rows(chosen), positive=positive)
    T = Translation([], [], extra=[det])
    if T.flat_ring() is None:
        return not SR(det).is_zero()
    f = T.flat_ring()(T.fraction(det))
    names = set(T.positive_names(positive))
    return positive_polynomial(f, names) or positive_polynomial(-f, names)


def _about(dropped, variables):
    rates = ', '.join(map(str, dropped))
    others = [v for v in variables if v not in dropped]
    return (f"; stability with respect to {', '.join(map(str, others)) + ' and ' if others else ''}"
            f"the rates of {rates} (ignorable: {rates} does not enter the linear equations "
            "through its value, it drifts)")


def linear_stability(system, positive=(), with_respect_to=None):
    r"""
    The stability of the zero solution of the linear ``system`` (a
    :class:`~sage_dynsym.analysis.linear.LinearSystem`): see the module
    documentation and :meth:`LinearSystem.stability
    <sage_dynsym.analysis.linear.LinearSystem.stability>`.

    EXAMPLES: gyroscopic stabilization, from the equations as written
    (`\ddot x - g\dot y - a x = 0`, `\ddot y + g\dot x - b y = 0`)::

        sage: from sage_dynsym.analysis.linear import LinearSystem
        sage: from sage_dynsym.analysis.stability import linear_stability
        sage: x, y, a, b, g = var('x y a b g')
        sage: Ls = LinearSystem.from_equations(identity_matrix(2), matrix([[0, -g], [g, 0]]),
        ....:                                  diagonal_matrix([-a, -b]), variables=[x, y])
        sage: v = linear_stability(Ls, positive=[a, b, g])
        sage: v.at({a: 1, b: 1, g: 3}), v.at({a: 1, b: 1, g: 1})
        ('stable in first approximation', 'unstable')

    A mass of unknown sign: where `m < 0` (not a mechanical system) the
    first approximation covers the rest of the space::

        sage: m, c, k = var('m c k')
        sage: [(case.verdict(), case.region()) for case in
        ....:  LinearSystem([x], M=[[m]], S=[[c]], W=[[k]]).stability().cases()]
        [('asymptotically stable', [[m > 0, c > 0, k > 0]]),
         ('unstable', [[m > 0, c < 0], [m > 0, k < 0]]),
         ('asymptotically stable', [[k < 0, c < 0, m < 0]]),
         ('unstable', [[k > 0, m < 0], [c > 0, m < 0]])]

    TESTS: a kinetic matrix singular everywhere (a coordinate of first
    order, `\dot x + ax = 0`): the finite roots decide::

        sage: linear_stability(LinearSystem([x], M=[[0]], S=[[1]], W=[[a]])).cases()
        [asymptotically stable where [a > 0]: ..., unstable where [a < 0]: ...]
    """
    from ..algebra.number_fields import AlgebraicConstants
    positive = list(positive)
    constants = AlgebraicConstants(_entries(system))
    if constants.is_trivial():
        return _decide(system, positive, with_respect_to)
    # irrational constants (cos(pi/10)): in a number field, its generator a
    # positive symbol, put back at the end
    forward = constants.forward
    LinearSystem = type(system)     # not imported: linear.py asks this module
    if system.order() == 2:
        mapped = LinearSystem(system.variables(), M=system.M().apply_map(forward),
                              S=system.S().apply_map(forward), W=system.W().apply_map(forward))
    else:
        mapped = LinearSystem(system.variables(), J=(-system.characteristic_matrix(0))
                              .apply_map(forward), B=system.lhs_matrix().apply_map(forward))
    verdict = _decide(mapped, positive + [constants.symbol()], with_respect_to)
    return _rebuilt(verdict, positive, expression=constants.back)


def _entries(system):
    if system.order() == 2:
        return system.M().list() + system.S().list() + system.W().list()
    return system.characteristic_matrix(0).list() + system.lhs_matrix().list()


def _decide(system, positive, with_respect_to):
    from .kelvin_chetaev import kelvin_chetaev
    dropped = ignorable(system, with_respect_to)
    if system.order() == 2 and not dropped and \
            not normalize(fraction_free_det(system.M())).is_zero():
        verdict = kelvin_chetaev(system.M(), system.D(), system.G(), system.K(), system.P(),
                                 positive=positive)
        return _outside_kinetic(verdict, system, positive)
    if not dropped:
        return energy_stability(system, positive) or first_approximation(system, positive)
    about = _about(dropped, system.variables())
    return _rebuilt(first_approximation(system, positive, dropped), positive,
                    reason=lambda r: r + about)


def _outside_kinetic(verdict, system, positive):
    r"""``verdict`` (of the theorems on the structure of forces, which hold
    where `M > 0`) with the cases of the first approximation where the
    declared signs leave `M` not positive definite: together they cover
    the whole space."""
    from .quadratic_forms import definiteness_conditions
    from ..algebra.regions import negation, intersection, prune_empty
    kinetic = definiteness_conditions(system.M(), positive=positive)
    outside = negation([kinetic], positive) if kinetic else None
    if not outside:
        return verdict
    cases = verdict.cases()
    for case in first_approximation(system, positive).cases():
        if case.region() is None:
            continue
        region = prune_empty(intersection(case.region(), outside, positive), positive)
        if region:
            cases.append(StabilityVerdict(
                case.verdict(), case.reason() + "; there M is not positive definite (not a "
                "mechanical system): the first approximation alone decides",
                method=case.method(), region=region, boundaries=case.boundaries(),
                positive=positive))
    if len(cases) == 1:
        return cases[0]
    return depends_on_parameters(cases, verdict.boundaries(), positive)


def _rebuilt(verdict, positive, reason=None, expression=None):
    r"""``verdict`` with each case's reason and relations mapped."""
    def relation(r):
        return r.operator()(expression(r.lhs()), expression(r.rhs())) if expression else r

    def region(alternatives):
        return None if alternatives is None else [[relation(r) for r in alt]
                                                  for alt in alternatives]

    def boundaries(found):
        return {kind: [relation(r) for r in rs] for kind, rs in found.items()}

    cases = [StabilityVerdict(c.verdict(), reason(c.reason()) if reason else c.reason(),
                              conditions=[expression(e) if expression else e
                                          for e in c.conditions()],
                              method=c.method(), region=region(c.region()),
                              boundaries=boundaries(c.boundaries()), positive=positive)
             for c in verdict.cases()]
    if len(cases) == 1:
        return cases[0]
    return StabilityVerdict(verdict.verdict(), verdict.reason(), cases=cases,
                            boundaries=boundaries(verdict.boundaries()), positive=positive)
