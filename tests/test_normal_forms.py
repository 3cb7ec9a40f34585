"""Birkhoff normal forms and nonlinear stability against the literature.

References of the expected values (none computed by the code under test):

- L4 of the planar circular restricted three-body problem: the frequencies
  are the roots of ``w^4 - w^2 + 27 mu (1 - mu)/4 = 0`` (Routh); the normal
  form ``H = w1 I1 - w2 I2 + (A I1^2 + 2 B I1 I2 + C I2^2)/2`` with Deprit &
  Deprit-Bartholome's (1967) A, B, C (as restated in Meyer, Hall & Offin,
  2009, section 13.4) and ``A w2^2 + 2 B w1 w2 + C w1^2 =
  (36 - 541 x + 644 x^2) / (8 (1 - 4 x)(4 - 25 x))``, ``x = w1^2 w2^2 =
  27 mu (1 - mu)/4``; mu1 (Routh), mu2 (1:2, w2^2 = 1/5), mu3 (1:3,
  w2^2 = 1/10) and mu_c (644 x^2 - 541 x + 36 = 0) in closed form; the
  verdicts of Deprit & Deprit-Bartholome (Arnold-Moser) and Markeev.
- The pendulum ``H = p^2/2 + 1 - cos q``: ``E(I) = I - I^2/16 - I^3/256``,
  checked here against the period from the complete elliptic integral
  (``omega(E) = pi / (2 K(E/2))``, mpmath).
- The transformation: the Hamiltonian composed with it, expanded
  independently, equals the normal form up to the order computed.
"""
import pytest

from sage.all import QQ, sqrt, cos, var, vector, PolynomialRing, ComplexField

from sage_dynsym import (Lagrangian, birkhoff_normal_form, nonlinear_stability,
                         exceptional_values, AnalysisError)
from sage_dynsym.analysis.normal_forms import normal_form, FormalArithmetic

x, y, dx, dy, mu = var('x y dx dy mu')
R1 = sqrt((x + mu) ** 2 + y ** 2)
R2 = sqrt((x - 1 + mu) ** 2 + y ** 2)
THREE_BODY = Lagrangian(((dx - y) ** 2 + (dy + x) ** 2) / 2 + (1 - mu) / R1 + mu / R2, [x, y])
L4 = {x: QQ(1) / 2 - mu, y: sqrt(3) / 2}


def closed_forms(m):
    m = m.n(200)
    X = 27 * m * (1 - m) / 4
    w1 = sqrt((1 + sqrt(1 - 4 * X)) / 2)
    w2 = sqrt((1 - sqrt(1 - 4 * X)) / 2)
    A = w2 ** 2 * (81 - 696 * w1 ** 2 + 124 * w1 ** 4) / (72 * (1 - 2 * w1 ** 2) ** 2 * (1 - 5 * w1 ** 2))
    B = -w1 * w2 * (43 + 64 * w1 ** 2 * w2 ** 2) / (
        6 * (4 * w1 ** 2 * w2 ** 2 - 1) * (25 * w1 ** 2 * w2 ** 2 - 4))
    C = w1 ** 2 * (81 - 696 * w2 ** 2 + 124 * w2 ** 4) / (72 * (1 - 2 * w2 ** 2) ** 2 * (1 - 5 * w2 ** 2))
    D = (36 - 541 * X + 644 * X ** 2) / (8 * (1 - 4 * X) * (4 - 25 * X))
    return w1, w2, A, B, C, D


def mu_of_x(X):
    return (1 - sqrt(1 - 16 * X / 27)) / 2


MU1 = (1 - sqrt(QQ(69)) / 9) / 2
MU2 = mu_of_x(QQ(4) / 25)                   # w2^2 = 1/5, w1^2 = 4/5
MU3 = mu_of_x(QQ(9) / 100)                  # w2^2 = 1/10, w1^2 = 9/10
MUC = mu_of_x((541 - sqrt(QQ(541 ** 2 - 4 * 644 * 36))) / (2 * 644))


@pytest.mark.parametrize("m", [QQ(1) / 100, QQ(1) / 50, QQ(3) / 100])
def test_l4_frequencies_and_coefficients_against_deprit(m):
    nf = birkhoff_normal_form(THREE_BODY, {**L4, mu: m}, prec=200)
    w1, w2, A, B, C, D = closed_forms(m)
    f1, f2 = nf.frequencies()
    assert abs(f1 - w1) < 1e-50 and abs(f2 + w2) < 1e-50       # signs: + for w1, - for w2
    c = nf.coefficients()
    assert abs(c[(2, 0)] - A / 2) < 1e-40
    assert abs(c[(1, 1)] - B) < 1e-40
    assert abs(c[(0, 2)] - C / 2) < 1e-40
    # A w2^2 + 2 B w1 w2 + C w1^2 = 2 D with this normalization of the quartic terms
    assert abs(nf.arnold_determinant() - D / 2) < 1e-40


def test_l4_frequencies_satisfy_the_characteristic_equation():
    m = QQ(1) / 37
    for w in birkhoff_normal_form(THREE_BODY, {**L4, mu: m}, prec=150).frequencies():
        assert abs(w ** 4 - w ** 2 + 27 * m * (1 - m) / 4) < 1e-40


@pytest.mark.slow
def test_l4_exceptional_values():
    found = exceptional_values(THREE_BODY, L4, mu, (0, QQ(1) / 2))
    assert abs(found['first approximation'][0] - MU1.n(100)) < 1e-12
    assert abs(found['resonance 1:2'][0] - MU2.n(100)) < 1e-12
    assert abs(found['resonance 1:3'][0] - MU3.n(100)) < 1e-12
    assert len(found['Arnold determinant']) == 1
    assert abs(found['Arnold determinant'][0] - MUC.n(100)) < 1e-12
    # the published decimals
    assert abs(found['Arnold determinant'][0] - 0.0109136676) < 1e-10
    assert abs(found['resonance 1:2'][0] - 0.0242938971) < 1e-10
    assert abs(found['resonance 1:3'][0] - 0.0135160160) < 1e-10


@pytest.mark.parametrize("m", [QQ(1) / 200, QQ(12) / 1000, QQ(2) / 100, QQ(3) / 100,
                               QQ(38) / 1000])
def test_l4_stable_off_the_exceptional_values(m):
    v = nonlinear_stability(THREE_BODY, {**L4, mu: m}, prec=160)
    assert v.verdict() == 'stable' and 'Arnold-Moser' in v.reason()


def test_l4_unstable_at_the_resonances_and_beyond_routh():
    v2 = nonlinear_stability(THREE_BODY, {**L4, mu: MU2})
    assert v2.verdict() == 'unstable' and 'resonance 1:2' in v2.reason()
    v3 = nonlinear_stability(THREE_BODY, {**L4, mu: MU3})
    assert v3.verdict() == 'unstable' and 'resonance 1:3' in v3.reason()
    assert nonlinear_stability(THREE_BODY, {**L4, mu: QQ(1) / 20}).verdict() == 'unstable'


def test_l4_undecided_at_mu_c_at_order_4():
    v = nonlinear_stability(THREE_BODY, {**L4, mu: MUC}, order=4)
    assert v.verdict() == 'undecided' and 'order' in v.reason()


def test_l4_cases_over_the_mass_ratio():
    # Deprit's diagram over 0 < mu < 1/2: the cases change exactly at the
    # literature's mu_c, mu3, mu2, mu1; stable between them (Arnold-Moser),
    # unstable at the resonances (Markeev) and beyond mu1 (Routh)
    v = nonlinear_stability(THREE_BODY, L4, interval=(0, QQ(1) / 2))
    cuts = sorted({float(c.region()[0][0].rhs()) for c in v.cases()} - {0.0})
    for found, expected in zip(cuts, [MUC, MU3, MU2, MU1]):
        assert abs(found - expected.n(100)) < 1e-10
    assert len(cuts) == 4
    expected = {QQ(1) / 200: 'stable', QQ(12) / 1000: 'stable', QQ(2) / 100: 'stable',
                QQ(3) / 100: 'stable', QQ(1) / 10: 'unstable', QQ(4) / 10: 'unstable'}
    for m, verdict in expected.items():
        assert v.at({mu: m}) == verdict, m
    at_points = {c.region()[0][0].rhs().n(60): c for c in v.cases()
                 if c.region()[0][0].operator().__name__ == 'eq'}
    by_value = sorted(at_points.items())
    assert [c.verdict() for _, c in by_value] == ['undecided', 'unstable', 'unstable',
                                                  'undecided']
    assert 'resonance 1:3' in by_value[1][1].reason()
    assert 'resonance 1:2' in by_value[2][1].reason()
    assert set(v.boundaries()) == {'Arnold determinant', 'resonance 1:2', 'resonance 1:3',
                                   'first approximation'}


def test_l4_exact_normal_form_with_the_mass_ratio_free():
    # the whole normal form in QQ(mu)[sqrt 3, lambda1, lambda2]/P: Arnold's
    # determinant is Deprit's closed form identically in mu, and its norm
    # vanishes exactly on Deprit's 644 x^2 - 541 x + 36 = 0
    from sage.all import PolynomialRing, AA
    from sage_dynsym.analysis.parametric_normal_forms import arnold_polynomial
    nf = birkhoff_normal_form(THREE_BODY, L4, order=4, sample={mu: QQ(1) / 100})
    D, N = arnold_polynomial(nf)
    A = nf.arithmetic()
    m = A.K.base_ring().gen()
    X = 27 * m * (1 - m) / 4
    # D/2 with the normalization of the quartic terms of the numeric test above
    closed = A.K((36 - 541 * X + 644 * X ** 2) / (8 * (1 - 4 * X) * (4 - 25 * X)))
    assert A.reduce(D - closed / 2) == 0
    t = PolynomialRing(QQ, 't').gen()
    deprit = (644 * (27 * t * (1 - t) / 4) ** 2 - 541 * (27 * t * (1 - t) / 4) + 36).monic()
    assert N.radical().change_ring(QQ) == deprit.change_variable_name('mu')
    zeros = exceptional_values(THREE_BODY, L4, mu, (0, QQ(1) / 2))['Arnold determinant']
    assert len(zeros) == 1 and zeros[0].parent() is AA and deprit(zeros[0]) == 0


def test_a_free_parameter_needs_an_interval():
    with pytest.raises(AnalysisError, match="interval"):
        nonlinear_stability(THREE_BODY, L4)


@pytest.mark.slow
def test_l4_order_6_decides_at_mu_c():
    # Meyer & Schmidt (1986): stable at mu_c
    v = nonlinear_stability(THREE_BODY, {**L4, mu: MUC}, order=6)
    assert v.verdict() == 'stable' and 'degree 6' in v.reason()


def test_pendulum_normal_form_against_the_elliptic_period():
    import mpmath
    q, dq = var('q dq')
    nf = birkhoff_normal_form(Lagrangian(dq ** 2 / 2 + cos(q), [q]),
                              {q: 0}, order=6, exact=True)
    c = nf.coefficients(exact=True)
    assert (QQ(c[(1,)]), QQ(c[(2,)]), QQ(c[(3,)])) == (1, QQ(-1) / 16, QQ(-1) / 256)
    # omega(E) = dE/dI from the normal form against pi/(2 K(E/2)), to O(E^3)
    for E in [1e-2, 2e-2]:
        I = mpmath.findroot(lambda s: s - s ** 2 / 16 - s ** 3 / 256 - E, E)
        omega_nf = 1 - I / 8 - 3 * I ** 2 / 256
        omega = mpmath.pi / (2 * mpmath.ellipk(E / 2))
        assert abs(omega_nf - omega) < 5 * E ** 3


def test_transformation_reproduces_the_normal_form():
    nf = birkhoff_normal_form(THREE_BODY, {**L4, mu: QQ(1) / 100}, order=4, prec=120)
    # the data of the normal form (its correctness is that of the coefficients above)
    from sage_dynsym.dynamics.nonlinear_stability import taylor_polynomial
    CC = ComplexField(120)
    taylor = taylor_polynomial(THREE_BODY, {**L4, mu: QQ(1) / 100}, 4)
    Hc = taylor.map_coefficients(CC, new_base_ring=CC)
    T, phi = nf.transformation()
    z = T * vector(phi)
    composed = Hc(*z)
    difference = composed - nf.hamiltonian()
    low = [abs(c) for e, c in difference.dict().items() if 2 <= sum(e) <= 4]
    assert max(low) < 1e-25
    # and the normal form really is normal: only xi_k eta_k products
    assert not nf.resonant_terms()


def test_exact_and_numeric_arithmetic_agree():
    R = PolynomialRing(QQ, 'q1, q2, p1, p2')
    q1, q2, p1, p2 = R.gens()
    H = (q1 ** 2 + p1 ** 2) - 3 * (q2 ** 2 + p2 ** 2) / 5 + q1 * q2 * p2 + q1 ** 3 + q2 ** 2 * q1 ** 2
    exact = normal_form(FormalArithmetic(H.change_ring(PolynomialRing(QQ, 'a')), 2, {'a': 0}), 4)
    numeric = normal_form(FormalArithmetic.numeric(H, 2, prec=120), 4)
    for m, c in exact.coefficients().items():
        assert abs(c.center() - numeric.coefficients()[m]) < 1e-25


def test_definite_energy_is_stable_whatever_the_resonances():
    q1, q2, dq1, dq2 = var('q1 q2 dq1 dq2')
    # frequencies 1 and 2 (resonance 1:2), the energy a strict minimum
    L = Lagrangian((dq1 ** 2 + dq2 ** 2) / 2 - q1 ** 2 / 2 - 2 * q2 ** 2 - q1 ** 2 * q2, [q1, q2])
    assert nonlinear_stability(L, {q1: 0, q2: 0}).verdict() == 'stable'


def test_bad_input():
    with pytest.raises(AnalysisError, match="not an equilibrium"):
        birkhoff_normal_form(THREE_BODY, {x: 0, y: 0, mu: QQ(1) / 100})
    with pytest.raises(AnalysisError, match="sample"):
        birkhoff_normal_form(THREE_BODY, L4)
    with pytest.raises(AnalysisError, match="simple roots on the imaginary axis"):
        birkhoff_normal_form(THREE_BODY, {**L4, mu: QQ(1) / 10})
    with pytest.raises(AnalysisError, match="give a value"):
        nonlinear_stability(THREE_BODY, L4)


def test_routh_function_and_hamiltonian_models():
    # Kepler's circular orbit as an equilibrium of the Routh function
    # (m = mu = p_phi = 1): r0 = 1, radial frequency 1 (the orbit's)
    r, phi, dr, dphi = var('r phi dr dphi')
    kepler = Lagrangian((dr ** 2 + r ** 2 * dphi ** 2) / 2 + 1 / r, [r, phi])
    routh = kepler.routh([phi])
    at = {r: 1, var('p_phi'): 1}
    nf = birkhoff_normal_form(routh, at, order=4, prec=100)
    assert abs(nf.frequencies()[0] - 1) < 1e-25
    assert nonlinear_stability(routh, at).verdict() == 'stable'
    # a Hamiltonian given directly: the pendulum's
    q, dq = var('q dq')
    H = Lagrangian(dq ** 2 / 2 + cos(q), [q]).hamiltonian()
    assert abs(birkhoff_normal_form(H, {q: 0}, prec=80).coefficients()[(2,)] + QQ(1) / 16) < 1e-20
