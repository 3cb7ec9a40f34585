"""Linearization, force structure and Kelvin-Chetaev verdicts, checked
against numerically computed eigenvalues (numpy) at random parameter
points inside and outside the returned regions."""
import random

import numpy as np
import pytest
from sage.all import SR, QQ, RDF, matrix, identity_matrix, zero_matrix, diagonal_matrix, var, sin, cos, pi

from sage_dynsym import Lagrangian
from sage_dynsym.analysis import linearize, kelvin_chetaev, LinearSystem
from sage_dynsym.analysis.hurwitz import lienard_chipart_conditions
from sage_dynsym.errors import AnalysisError


def holds(conditions, point):
    return all(float(SR(c).subs(point)) > 0 for c in conditions)


def eigenvalues(lin, point):
    A = lin.jacobian().subs(point).change_ring(RDF)
    return np.linalg.eigvals(A.numpy())


def test_force_structure_split_against_definition():
    # x'' + (d + 2g J) x' + (k + p J) x with J the rotation by 90 degrees
    x, y, dx, dy = var('x y dx dy')
    d1, d2, g, k1, k2, p = var('d1 d2 g k1 k2 p')
    Ls = LinearSystem([x, y], M=identity_matrix(2), S=matrix([[d1, 2 * g], [-2 * g, d2]]),
                      W=matrix([[k1, p], [-p, k2]]))
    assert Ls.D() == diagonal_matrix([d1, d2])
    assert Ls.G() == matrix([[0, g], [-g, 0]])
    assert Ls.K() == diagonal_matrix([k1, k2])
    assert Ls.P() == matrix([[0, p], [-p, 0]])
    assert (Ls.D() + 2 * Ls.G() - Ls.S()).is_zero()


def test_linearize_lagrangian_matches_numeric_jacobian():
    # pendulum on a rotating hoop (Merkin): equilibria theta = 0 and
    # cos(theta) = g/(a Omega^2)
    th, dth, m, a, g, Om, c = var('theta dtheta m a g Omega c')
    L = Lagrangian(m * a**2 / 2 * (dth**2 + Om**2 * sin(th)**2) + m * g * a * cos(th), [th],
                   dissipation=c * dth**2 / 2)
    lin = linearize(L, {th: 0})
    params = [m, a, g, Om, c]
    v = lin.kelvin_chetaev(positive=[m, a, g, c])
    rng = random.Random(1)
    for _ in range(40):
        pt = {s: QQ(rng.uniform(0.2, 3)) for s in params}
        ev = eigenvalues(lin, pt)
        stable = bool(np.all(ev.real < 0))
        # lower position: asymptotically stable iff g > a Omega^2
        assert stable == (float(pt[g] - pt[a] * pt[Om]**2) > 0)
        assert v.at(pt) == ('asymptotically stable' if stable else 'unstable')


def test_gyroscopic_stabilization_against_eigenvalues():
    # Merkin ch. 6: x'' - 2g y' - a x = 0, y'' + 2g x' - b y = 0
    a, b, g = var('a b g')
    M = identity_matrix(SR, 2)
    G = matrix([[0, -g], [g, 0]])
    K = diagonal_matrix([-a, -b])
    v = kelvin_chetaev(M, zero_matrix(SR, 2), G, K, positive=[a, b])
    assert v.verdict() == 'depends on the parameters'
    assert [c.verdict() for c in v.cases()] == ['stable in first approximation', 'unstable']
    lin = LinearSystem([var('x'), var('y')], M=M, S=2 * G, W=K)
    rng = random.Random(2)
    seen = set()
    for _ in range(60):
        pt = {a: QQ(rng.uniform(0.1, 2)), b: QQ(rng.uniform(0.1, 2)), g: QQ(rng.uniform(0, 3))}
        ev = eigenvalues(lin, pt)
        marginal = bool(np.all(np.abs(ev.real) < 1e-7))
        inside = v.at(pt) == 'stable in first approximation'
        assert inside == marginal
        assert v.at(pt) == ('stable in first approximation' if marginal else 'unstable')
        # the classical form: 2 g > sqrt(a) + sqrt(b)
        assert inside == (2 * float(pt[g]) > float(pt[a])**0.5 + float(pt[b])**0.5)
        seen.add(inside)
    assert seen == {True, False}
    # complete dissipation destroys it: a root with positive real part
    c = var('c')
    vd = kelvin_chetaev(M, c * M, G, K, positive=[a, b, c])
    assert vd.verdict() == 'unstable'
    assert '4th theorem' in vd.reason()
    lind = LinearSystem([var('x'), var('y')], M=M, S=c * M + 2 * G, W=K)
    for _ in range(20):
        pt = {a: QQ(rng.uniform(0.1, 2)), b: QQ(rng.uniform(0.1, 2)), g: QQ(rng.uniform(1, 5)),
              c: QQ(rng.uniform(0.01, 1))}
        assert np.max(eigenvalues(lind, pt).real) > 0


def test_odd_degree_of_instability_cannot_be_stabilized():
    a, b, g, c = var('a b g c')
    M = identity_matrix(SR, 2)
    G = matrix([[0, -g], [g, 0]])
    K = diagonal_matrix([-a, b])
    assert kelvin_chetaev(M, zero_matrix(SR, 2), G, K, positive=[a, b]).verdict() == 'unstable'
    lin = LinearSystem([var('x'), var('y')], M=M, S=2 * G, W=K)
    rng = random.Random(4)
    for _ in range(30):
        pt = {a: QQ(rng.uniform(0.1, 2)), b: QQ(rng.uniform(0.1, 2)), g: QQ(rng.uniform(0, 5))}
        assert np.max(eigenvalues(lin, pt).real) > 1e-9


@pytest.mark.slow
def test_first_order_circuit_like_system_against_eigenvalues():
    # B x' = F(x): an RLC loop with a tunnel-diode-like element i = f(u)
    i, u, L, C, r, s = var('i u L C r s')
    rhs = [-u - r * i, i - u * (u - s) * (u - 2 * s)]  # f(u) = u(u-s)(u-2s)
    lin = linearize(rhs, {i: 0, u: 0}, [i, u], lhs_matrix=[L, C])
    lam = var('lam')
    conds = lienard_chipart_conditions(lin.characteristic_polynomial(lam), lam, positive=[L, C])
    rng = random.Random(5)
    seen = set()
    for _ in range(60):
        pt = {L: QQ(rng.uniform(0.1, 2)), C: QQ(rng.uniform(0.1, 2)),
              r: QQ(rng.uniform(-1, 2)), s: QQ(rng.uniform(0.1, 2))}
        ev = eigenvalues(lin, pt)
        truth = bool(np.all(ev.real < 0))
        assert holds(conds, pt) == truth
        seen.add(truth)
    assert seen == {True, False}


def test_characteristic_polynomial_is_fraction_free_and_correct():
    x, y, m, k, c = var('x y m k c')
    lin = linearize([y, -(k / m) * x - (c / m) * y], {x: 0, y: 0}, [x, y])
    lam = var('lam')
    # det(lam I - J) = lam^2 + c/m lam + k/m; the fraction-free polynomial is
    # a positive multiple of it: m^2 det, or m det once m is declared positive
    det = lam**2 + c / m * lam + k / m
    p = lin.characteristic_polynomial(lam)
    assert (p - m**2 * det).simplify_rational() == 0
    p = lin.characteristic_polynomial(lam, positive=[m])
    assert (p - m * det).simplify_rational() == 0


def test_integrals_of_linear_equations():
    x, y, m, k = var('x y m k')
    lin = LinearSystem([x, y], M=diagonal_matrix([m, m]), S=zero_matrix(SR, 2),
                       W=matrix([[k, -k], [-k, k]]))
    (I,) = lin.linear_integrals()
    A = lin.jacobian()
    # d/dt of the integral along x' = A x vanishes
    xs = [x, y, var('dx'), var('dy')]
    grad = matrix(SR, [[I.diff(v) for v in xs]])
    assert (grad * A).is_zero()
    for Q in lin.quadratic_integrals():
        H = matrix(SR, [[Q.diff(a).diff(b) for b in xs] for a in xs])
        assert (A.transpose() * H + H * A).simplify_rational().is_zero()


def test_bad_points():
    x, y = var('x y')
    with pytest.raises(AnalysisError, match="not an equilibrium"):
        linearize([y, -sin(x)], {x: 1, y: 0}, [x, y])
    th, dth = var('theta dtheta')
    L = Lagrangian(dth**2 / 2 + cos(th), [th])
    with pytest.raises(AnalysisError, match="not an equilibrium"):
        linearize(L, {th: pi / 3})
    with pytest.raises(AnalysisError, match="no value given"):
        linearize(L, {})
    with pytest.raises(AnalysisError):
        linearize([y], {x: 0, y: 0}, [x, y])


def test_hamiltonian_linearization_matches_lagrangian():
    th, dth, m, l, g = var('theta dtheta m l g')
    L = Lagrangian(m * l**2 * dth**2 / 2 + m * g * l * cos(th), [th])
    H = L.hamiltonian()
    (p,) = H.momenta()
    lin_h = linearize(H, {th: 0, p: 0})
    lin_l = linearize(L, {th: 0})
    lam = var('lam')
    ph = lin_h.characteristic_polynomial(lam)
    pl = lin_l.characteristic_polynomial(lam)
    # same roots: the polynomials are proportional
    assert (ph * pl.coefficient(lam, 2) - pl * ph.coefficient(lam, 2)).expand() == 0
    with pytest.raises(AnalysisError, match="not an equilibrium"):
        linearize(H, {th: 0, p: 1})
