"""Polynomial first integrals of the heavy rigid body and of Kirchhoff's
equations found by undetermined coefficients (issue 12, must-show 2 and
the rank-drop conditions).

Expected values (outside the code under test):
- the Euler-Poisson equations are written out here by hand (cross products,
  Borisov & Mamaev, Rigid Body Dynamics, §2.1: dM/dt = M x w + mu gamma x r,
  dgamma/dt = gamma x w, gamma the upward vertical), and every integral is
  checked against them by differentiation;
- Euler's case (no gravity): the energy and M^2 (Arnold, Mathematical
  Methods of Classical Mechanics, §28);
- Lagrange's case (A = B, centre of mass on the axis): M3 (Arnold, §30);
- Kovalevskaya's case (A = B = 2C, centre of mass (x0, 0, 0)): the integral
  (p^2 - q^2 - c gamma1)^2 + (2pq - c gamma2)^2, c = m g x0 / C, p = M1/(2C),
  q = M2/(2C) (S. Kovalevskaya, Acta Math. 12 (1889) 177-232; Golubev,
  Lectures on the Integration of the Equations of Motion of a Heavy Rigid
  Body, ch. 4); no integral of degree <= 3 beyond the classical ones;
- a generic body: only the algebra of H, gamma^2, M.gamma up to degree 4
  (Kozlov / Ziglin non-integrability; here the finite-degree statement);
- linear integrals of the heavy top with the centre of mass on the third
  axis: exactly the Lagrange case A1 = A2 and, without gravity, the
  symmetric Euler tops (Borisov & Mamaev, §2.1); Kirchhoff's equations
  with H = (sum a_i M_i^2 + b_i p_i^2)/2: a new quadratic integral exactly on
  Clebsch's condition (b2 - b3)/a1 + (b3 - b1)/a2 + (b1 - b2)/a3 = 0
  (Clebsch, Math. Ann. 3 (1871); Borisov & Mamaev, §2.5), besides the
  symmetric bodies (a linear integral).
"""
import pytest
from sage.all import SR, QQ, var, vector, matrix, PolynomialRing

from sage_dynsym.lie import LiePoissonSystem

M = list(var('M1 M2 M3'))
G = list(var('gamma1 gamma2 gamma3'))
A1, A2, A3, A, C, mu, c = var('A1 A2 A3 A C mu c')
x0, y0, z0 = var('x0 y0 z0')


def euler_poisson_by_hand(inertia, r, mu_):
    Mv, gv = vector(SR, M), vector(SR, G)
    w = vector(SR, [M[i] / inertia[i] for i in range(3)])
    dM = Mv.cross_product(w) + mu_ * gv.cross_product(vector(SR, r))
    dg = gv.cross_product(w)
    return list(dM) + list(dg)


def conserved(F, X):
    return sum(SR(F).diff(x) * e for x, e in zip(M + G, X)).expand().is_zero()


def in_span(f, basis, variables=M + G):
    """f is a combination of basis over Q(parameters) (rank test)."""
    names = [str(v) for v in variables]
    params = sorted({str(a) for e in [f] + basis for a in SR(e).variables()} - set(names))
    K = PolynomialRing(QQ, params).fraction_field() if params else QQ
    R = PolynomialRing(K, names)
    polys = [R(SR(e)) for e in basis + [f]]
    monos = sorted({m for p in polys for m in p.monomials()})
    rows = [[p.monomial_coefficient(m) for m in monos] for p in polys]
    return matrix(K, rows[:-1]).rank() == matrix(K, rows).rank()


def classical(H):
    Mg = sum(a * b for a, b in zip(M, G))
    g2 = sum(b**2 for b in G)
    return [H, Mg, g2, H**2, H * Mg, H * g2, Mg**2, Mg * g2, g2**2]


def test_euler_case():
    inertia = [A1, A2, A3]
    H = sum(M[i]**2 / (2 * inertia[i]) for i in range(3))
    S = LiePoissonSystem('e3', H)
    X = euler_poisson_by_hand(inertia, [0, 0, 0], 0)
    basis = S.polynomial_integrals(2)
    assert all(conserved(F, X) for F in basis)
    M2 = sum(m**2 for m in M)
    assert len(basis) == 4          # H, M^2, gamma^2, M.gamma
    assert in_span(H, basis) and in_span(M2, basis)
    new = S.polynomial_integrals(2, new_only=True)
    assert len(new) == 1 and in_span(M2, new + classical(H)[:3])
    # on so(3) the same: the energy and the squared angular momentum
    T = LiePoissonSystem('so3', H)
    assert T.polynomial_integrals(2) and in_span(M2, T.polynomial_integrals(2), M)
    assert len(T.polynomial_integrals(2)) == 2


def test_lagrange_case():
    H = (M[0]**2 + M[1]**2) / (2 * A) + M[2]**2 / (2 * C) + mu * z0 * G[2]
    X = euler_poisson_by_hand([A, A, C], [0, 0, z0], mu)
    S = LiePoissonSystem('e3', H)
    linear = S.polynomial_integrals(1)
    assert len(linear) == 1 and in_span(M[2], linear)
    assert conserved(linear[0], X)
    assert S.polynomial_integrals(2, new_only=True) == [M[2]]


def kovalevskaya():
    H = (M[0]**2 + M[1]**2) / (4 * C) + M[2]**2 / (2 * C) + mu * x0 * G[0]
    X = euler_poisson_by_hand([2 * C, 2 * C, C], [x0, 0, 0], mu)
    cc = mu * x0 / C
    p, q = M[0] / (2 * C), M[1] / (2 * C)
    K = (p**2 - q**2 - cc * G[0])**2 + (2 * p * q - cc * G[1])**2
    return H, X, K


def test_kovalevskaya_case():
    H, X, K = kovalevskaya()
    assert conserved(K, X)             # the textbook formula, on the hand-written equations
    S = LiePoissonSystem('e3', H)
    assert S.polynomial_integrals(3, new_only=True) == []
    new = S.polynomial_integrals(4, new_only=True)
    assert len(new) == 1 and conserved(new[0], X)
    assert in_span(K, new + classical(H))
    assert not in_span(K, classical(H))


@pytest.mark.slow
def test_generic_body_has_only_the_classical_integrals():
    H = sum(M[i]**2 / (2 * a) for i, a in enumerate([A1, A2, A3])) + \
        mu * (x0 * G[0] + y0 * G[1] + z0 * G[2])
    X = euler_poisson_by_hand([A1, A2, A3], [x0, y0, z0], mu)
    S = LiePoissonSystem('e3', H)
    assert S.polynomial_integrals(4, new_only=True) == []
    basis = S.polynomial_integrals(4)
    assert len(basis) == 9 and all(conserved(F, X) for F in basis)
    assert all(in_span(F, basis) for F in classical(H))
    # and a numerical generic body
    Hn = M[0]**2 / 4 + M[1]**2 / 6 + M[2]**2 / 10 + G[0] + 2 * G[1] + 3 * G[2]
    assert LiePoissonSystem('e3', Hn).polynomial_integrals(4, new_only=True) == []


def test_products_count_in_the_space():
    _, _, K = kovalevskaya()
    H, X, _ = kovalevskaya()
    S = LiePoissonSystem('e3', H)
    basis = S.polynomial_integrals(4)
    assert len(basis) == 10
    assert in_span(H**2, basis) and in_span(K, basis)


def ideal(gens):
    params = sorted({str(a) for g in gens for a in SR(g).variables()})
    R = PolynomialRing(QQ, params)
    return R.ideal([R(SR(g)) for g in gens])


def jump_ideals(jumps):
    return {tuple(sorted(str(g) for g in ideal([e.lhs() for e in j.conditions()])
                         .groebner_basis())): j.dimension() for j in jumps}


def test_conditions_for_linear_integrals_of_the_heavy_top():
    H = M[0]**2 / (2 * A1) + M[1]**2 / (2 * A2) + M[2]**2 / (2 * A3) + c * G[2]
    basis, jumps = LiePoissonSystem('e3', H).polynomial_integrals(1, conditions=True)
    assert basis == []
    expected = {(A1 - A2,): 1, (A1 - A3, c): 1, (A2 - A3, c): 1,
                (A1 - A2, A2 - A3, c): 3}
    found = jump_ideals(jumps)
    want = {tuple(sorted(str(g) for g in ideal(list(k)).groebner_basis())): d
            for k, d in expected.items()}
    # the same varieties (ideals compared by their reduced Groebner bases)
    assert sorted(found.values()) == sorted(want.values())
    assert len(found) == len(want)
    for j in jumps:
        I = ideal([e.lhs() for e in j.conditions()])
        assert any(I == ideal(list(k)) and d == j.dimension() for k, d in expected.items())
    lagrange = next(j for j in jumps if len(j.conditions()) == 1)
    assert lagrange.integrals() == [M[2]]


@pytest.mark.slow
def test_conditions_find_clebsch_case():
    P = list(var('p1 p2 p3'))
    a = list(var('a1 a2 a3'))
    b = list(var('b1 b2 b3'))
    H = sum(a[i] * M[i]**2 + b[i] * P[i]**2 for i in range(3)) / 2
    S = LiePoissonSystem('e3', H, variables=M + P)
    basis, jumps = S.polynomial_integrals(2, conditions=True)
    assert len(basis) == 3                       # H, p^2, M.p
    clebsch = a[1] * a[2] * (b[1] - b[2]) + a[0] * a[2] * (b[2] - b[0]) + \
        a[0] * a[1] * (b[0] - b[1])
    top = [j for j in jumps if len(j.conditions()) == 1]
    assert len(top) == 1 and top[0].dimension() == 4
    assert ideal([top[0].conditions()[0].lhs()]) == ideal([clebsch])
    # the symmetric bodies a_i = a_j, b_i = b_j: a linear integral
    symmetric = [j for j in jumps if j.dimension() == 5 and
                 all(not e.lhs().is_symbol() for e in j.conditions())]
    assert len(symmetric) == 3
    # the integral on the Clebsch family is conserved along Kirchhoff's equations
    X = S.equations()
    sub = top[0].substitution()
    for F in top[0].integrals():
        dF = sum(SR(F).diff(x) * SR(e).subs(sub) for x, e in zip(M + P, X))
        assert dF.simplify_rational().is_zero()
