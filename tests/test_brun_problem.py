"""
Brun's problem (a rigid body with a fixed point in the quadratic potential
eps (gamma, I gamma)/2; worksheets/17_brun_problem.ipynb) against
independent computations:

- Brun's integral F = (M, M) - eps det(I) (gamma, I^-1 gamma) commutes with
  H for symbolic inertia and eps, by the e(3) bracket written here in SymPy
  (Brun 1893; Bogoyavlensky, Math. USSR Izv. 25 (1985) 207-257); the
  package's new quadratic integral is a combination of F, H and (gamma, gamma).
- The uniform rotations about the principal axes: the package's stability
  regions against the roots of the linearization (NumPy) at many values of
  the area constant c, and the bifurcation value sqrt(eps) I3 of the axis of
  the largest moment found as the root of the largest real part (SciPy).
- The relative equilibria on a level (gamma, gamma) = 1, (M, gamma) = c: by
  least squares from many random starts (SciPy), six isolated points, plus
  Brun's rotations M = +-sqrt(eps) I gamma exactly where sqrt(eps) I1 < |c|
  < sqrt(eps) I3; against the package's stationary solutions on the level.
- The census over the area constant c (equilibrium_census with levels
  [c, 1]): its bifurcation values are sqrt(eps) I_k (the worksheet's table);
  at random levels inside each cell, the least-squares search finds as many
  rotations about the axes as the cell counts, Brun's rotations exactly in
  the cells with a curve of relative equilibria, as many axes with a
  definite second variation of H - lambda.C on the tangent space of the leaf
  (NumPy, with the multipliers by least squares) as the cell's stable count,
  and as many without a growing mode of the linearization (NumPy) as its
  count stable in first approximation.
"""
import numpy as np
import pytest
import sympy as sp
from scipy.optimize import brentq, least_squares

from conftest import slow_except
from sage.all import var, vector, diagonal_matrix, QQ, SR
from sage_dynsym.lie import LiePoissonSystem

INERTIA = (1, 2, 3)
EPS = 1


def e3_bracket(f, g, M, G):
    """{f, g} on e(3)*: {M_i, M_j} = eps_ijk M_k, {M_i, G_j} = eps_ijk G_k (SymPy)."""
    grad = lambda h, xs: sp.Matrix([sp.diff(h, x) for x in xs])
    Mv, Gv = sp.Matrix(M), sp.Matrix(G)
    fM, fG, gM, gG = grad(f, M), grad(f, G), grad(g, M), grad(g, G)
    return sp.expand(Mv.dot(fM.cross(gM)) + Gv.dot(fM.cross(gG) + fG.cross(gM)))


def test_brun_integral_for_symbolic_inertia():
    M, G = sp.symbols('M1:4'), sp.symbols('g1:4')
    I, eps = sp.symbols('I1:4', positive=True), sp.Symbol('epsilon')
    H = sum(m**2 / (2 * i) for m, i in zip(M, I)) + eps * sum(i * g**2 for i, g in zip(I, G)) / 2
    F = sum(m**2 for m in M) - eps * I[0] * I[1] * I[2] * sum(g**2 / i for i, g in zip(I, G))
    assert sp.simplify(e3_bracket(F, H, M, G)) == 0
    # and it is not a function of H and the Casimirs: {F, M1} != 0 while {H, M1} is not it
    assert sp.simplify(e3_bracket(F, M[0], M, G)) != 0


def field(M, G):
    """The Euler-Poisson vector field of Brun's H (NumPy)."""
    I = np.array(INERTIA, dtype=float)
    return np.concatenate([np.cross(M, M / I) + EPS * np.cross(G, I * G), np.cross(G, M / I)])


def max_real_part(x, h=1e-6):
    J = np.empty((6, 6))
    for j in range(6):
        d = np.zeros(6); d[j] = h
        J[:, j] = (field(*np.split(x + d, 2)) - field(*np.split(x - d, 2))) / (2 * h)
    return max(np.linalg.eigvals(J).real)


def axis_point(k, c, sign=1):
    e = np.zeros(3); e[k] = sign
    return np.concatenate([c * e * sign, e])     # (M, gamma) = c


@pytest.fixture(scope="module")
def brun():
    M1, M2, M3, g1, g2, g3 = var('M1 M2 M3 gamma1 gamma2 gamma3')
    M, g = vector([M1, M2, M3]), vector([g1, g2, g3])
    I = diagonal_matrix(QQ, list(INERTIA))
    H = (M * I.inverse() * M) / 2 + EPS * (g * I * g) / 2
    return LiePoissonSystem('e3', H), list(M), list(g), H


def test_package_integral_is_brun_integral(brun):
    S, M, g, H = brun
    new, = S.polynomial_integrals(2, new_only=True)
    Ms, Gs = sp.symbols('M1:4'), sp.symbols('g1:4')
    to_sympy = lambda e: sp.sympify(str(SR(e)).replace('gamma', 'g'))
    F = sum(m**2 for m in Ms) - EPS * 6 * sum(gg**2 / i for i, gg in zip(INERTIA, Gs))
    a, b, c, d = sp.symbols('a b c d')
    residual = sp.Poly(sp.expand(F - a * to_sympy(new) - b * to_sympy(H)
                                 - c * sum(gg**2 for gg in Gs) - d), *Ms, *Gs)
    assert sp.solve(residual.coeffs(), [a, b, c, d])     # a combination exists


def test_rotations_about_the_axes_against_the_linearization(brun):
    S, M, g, H = brun
    sols = S.stationary_solutions(S.polynomial_integrals(2, new_only=True),
                                  levels=[None, 1, None])
    # (the rest points M = 0 on the axes, where the integral is critical and
    # its multiplier free, are listed as points besides)
    axes = [s for s in sols if s.is_explicit() and s.dimension() == 1]
    assert len(axes) == 6
    for s in axes:
        point = s.point()
        k, = [i for i in range(3) if point[g[i]] != 0]
        sign = int(point[g[k]])
        regions = s.stability_region()
        for c in np.linspace(-6, 6, 25):
            if min(abs(abs(c) - np.array([0, 1, 2, 3]))) < 1e-6:
                continue        # the bifurcation values
            stable = any(all(bool(r.subs({M[k]: QQ(c) * sign})) for r in region)
                         for region in regions)
            growth = max_real_part(axis_point(k, c, sign))
            if stable:          # a stable rotation has no growing mode
                assert growth < 1e-7, (k, c)
            else:               # here none is proved stable: they are unstable
                assert growth > 1e-4, (k, c, growth)
    # the axis of the largest moment becomes stable at |c| = sqrt(eps) I3 = 3
    root = brentq(lambda c: max_real_part(axis_point(2, c)) - 1e-3, 2.5, 3.5)
    assert abs(root - np.sqrt(EPS) * INERTIA[2]) < 1e-3


def stationary_on_level(c, starts=120, seed=5):
    """The relative equilibria on (gamma, gamma) = 1, (M, gamma) = c, by least squares."""
    rng = np.random.default_rng(seed)

    def residual(x):
        M, G = np.split(x, 2)
        return np.concatenate([field(M, G), [G @ G - 1, M @ G - c]])
    found = []
    for _ in range(starts):
        fit = least_squares(residual, rng.normal(size=6) * (1 + abs(c)), xtol=1e-15, ftol=1e-15,
                            gtol=1e-15)
        if fit.cost < 1e-24:
            found.append(fit.x)
    return found


# a level with Brun's rotations and one without in `make test`, all four in `make test-slow`
@pytest.mark.parametrize("c", slow_except([0.5, 1.5, 2.5, 4.0], [1.5, 4.0]))
def test_relative_equilibria_on_a_level_by_least_squares(c):
    I = np.array(INERTIA, dtype=float)
    points = stationary_on_level(c)
    axes = {(k, int(np.sign(x[3 + k]))) for x in points for k in range(3)
            if abs(abs(x[3 + k]) - 1) < 1e-7}
    assert len(axes) == 6       # the six isolated rotations, found from random starts
    others = [x for x in points if not any(abs(abs(x[3 + k]) - 1) < 1e-7 for k in range(3))]
    # Brun's rotations exactly for sqrt(eps) I1 < |c| < sqrt(eps) I3, with M = sign(c) sqrt(eps) I gamma
    assert bool(others) == (np.sqrt(EPS) * I[0] < abs(c) < np.sqrt(EPS) * I[2])
    for x in others:
        M, G = np.split(x, 2)
        assert np.allclose(M, np.sign(c) * np.sqrt(EPS) * I * G, atol=1e-7)
        assert abs(G @ (I * G) - abs(c) / np.sqrt(EPS)) < 1e-7


@pytest.mark.slow       # the stationary solutions on three levels (a few seconds each)
def test_package_on_levels_against_least_squares(brun):
    S, M, g, H = brun
    for c in (QQ(1) / 2, QQ(3) / 2, 4):
        sols = S.stationary_solutions(levels=[c, 1])
        points = [np.array([float(s.point()[v]) for v in M + g])
                  for s in sols if s.dimension() == 0]
        # no point of Brun's curve (M = sign(c) sqrt(eps) I gamma) is listed on
        # its own: the ends of the curve's branches (written with square
        # roots) belong to the branches
        I = np.array(INERTIA, dtype=float)

        def on_curve(x):
            return np.allclose(x[:3], np.sign(float(c)) * np.sqrt(EPS) * I * x[3:], atol=1e-9)
        assert not any(on_curve(x) for x in points)
        isolated = sorted(tuple(x) for x in points)
        numeric = sorted({tuple(np.round(x, 6) + 0.0) for x in stationary_on_level(float(c))
                          if any(abs(abs(x[3 + k]) - 1) < 1e-7 for k in range(3))})
        assert np.allclose(isolated, numeric, atol=1e-6)
        # the families of the package are curves (Brun's rotations)
        assert all(s.dimension() == 1 for s in sols if s.dimension() > 0)


def energy_casimir_definite(x):
    """Whether H - l1 (M, gamma) - l2 (gamma, gamma) has a definite second
    variation on the tangent space of the leaf at x (NumPy)."""
    I = np.array(INERTIA, dtype=float)
    M, G = np.split(x, 2)
    grad_H = np.concatenate([M / I, EPS * I * G])
    grads = np.array([np.concatenate([G, M]), np.concatenate([np.zeros(3), 2 * G])])
    lam = np.linalg.lstsq(grads.T, grad_H, rcond=None)[0]
    assert np.allclose(grads.T @ lam, grad_H, atol=1e-9)       # a relative equilibrium
    hess = np.diag(np.concatenate([1 / I, EPS * I]))
    hess -= lam[0] * np.block([[np.zeros((3, 3)), np.eye(3)], [np.eye(3), np.zeros((3, 3))]])
    hess -= lam[1] * np.diag([0, 0, 0, 2, 2, 2])
    tangent = np.linalg.svd(grads)[2][2:].T                    # the null space of the gradients
    eig = np.linalg.eigvalsh(tangent.T @ hess @ tangent)
    return bool(all(eig > 1e-9) or all(eig < -1e-9))


@pytest.mark.slow       # the census (about 6 s) and a least-squares search on 8 levels
def test_census_over_the_area_constant(brun):
    S = brun[0]
    c = var('c')
    census = S.equilibrium_census([c], levels=[c, 1], positive=[c])
    # the bifurcation values of the worksheet's table: |c| = sqrt(eps) I_k
    assert [float(v) for v in census.bifurcation_values()] == \
        pytest.approx([np.sqrt(EPS) * i for i in INERTIA])
    rng = np.random.default_rng(17)
    for cell in census.cells():
        lo, hi = cell.bounds()
        hi = float(lo) + 3 if hi is None else float(hi)
        for level in rng.uniform(float(lo) + 0.05, hi - 0.05, size=2):
            points = stationary_on_level(level)
            axes = {}
            for x in points:
                for k in range(3):
                    if abs(abs(x[3 + k]) - 1) < 1e-7:
                        axes[(k, int(np.sign(x[3 + k])))] = x
            others = [x for x in points if not any(abs(abs(x[3 + k]) - 1) < 1e-7
                                                   for k in range(3))]
            assert cell.count() == len(axes), (cell, level)
            assert cell.families() == ([1] if others else []), (cell, level)
            assert cell.stable_count() == sum(energy_casimir_definite(x) for x in axes.values())
            assert cell.stable_count(first_approximation=True) == \
                sum(max_real_part(x) < 1e-7 for x in axes.values()), (cell, level)
