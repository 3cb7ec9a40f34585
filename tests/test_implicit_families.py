"""
Implicit families of solutions with parameters: where they are real is
decided (a parametrization by other free unknowns, or quantifier
elimination), or said to be undecided -- never an exception -- and their
stability is a verdict with cases. Expected values from outside: the real
roots of the fibres with NumPy, the equations evaluated with NumPy, and for
Brun's problem the stationary points at rational values solved exactly by
Sage over the real algebraic numbers in a formulation written here.

Brun's problem (1893): a rigid body with a fixed point in a quadratic
potential, on e(3)* with the Casimirs gamma.gamma and M.gamma,

    H = 1/2 (M, A M) + epsilon/2 (gamma, I gamma),   A = I^{-1},

integrable with the integral F = (M, M) - epsilon det(I) (gamma, A gamma)
(A. V. Borisov, I. S. Mamaev, Rigid Body Dynamics, De Gruyter 2019, the
Brun case, equivalent to Clebsch's case of Kirchhoff's equations with
epsilon = theta a1 a2 a3). Its uniform rotations off the principal axes
form the 3-parameter family gamma_i = s M_i / (I_i sqrt(epsilon)), s = +-1,
real exactly where epsilon > 0 (by hand: grad K = 0 for K = H + l1 gamma.gamma
+ l2 M.gamma gives M_i/I_i + l2 gamma_i = 0 and epsilon I_i gamma_i +
2 l1 gamma_i + l2 M_i = 0, so epsilon I_i^2 = l2^2 I_i^2 with l1 = 0).
"""
import numpy as np
import pytest

from sage.all import SR, QQ, AA, PolynomialRing, var, vector
import sage_dynsym.algebra.solving as solving
from sage_dynsym.algebra.conditions import holds
from sage_dynsym.algebra.solving import solve_exactly
from sage_dynsym.analysis.stationary import stationary_solutions

x, y, z, a = var('x y z a')


def real_root_exists(coefficients):
    roots = np.roots(coefficients)
    return bool(np.any(np.abs(roots.imag) < 1e-9))


@pytest.mark.parametrize("equation, fibre", [
    # y^4 = a - x^4 over x
    (y**4 + x**4 - a, lambda av, xv: [1, 0, 0, 0, xv**4 - av]),
    # a quadratic in u = y^3: real iff x^2 - 4 (x^4 - a) >= 0
    (y**6 + x * y**3 + x**4 - a, lambda av, xv: [1, 0, 0, xv, 0, 0, xv**4 - av]),
])
def test_reality_of_a_family_by_quantifier_elimination(equation, fibre):
    s, = solve_exactly([equation], [x, y])
    assert s.dimension() == 1 and s.is_reality_decided()
    assert s.free_unknowns() == [x]
    rng = np.random.default_rng(7)
    inside = outside = 0
    for _ in range(40):
        av, xv = rng.uniform(-2, 2), rng.uniform(-1.5, 1.5)
        claimed = all(holds(c, {a: av, x: xv}) for c in s.conditions())
        assert claimed == real_root_exists(fibre(av, xv))
        inside, outside = inside + claimed, outside + (not claimed)
    assert inside and outside            # both sides were sampled


def test_reality_of_a_family_by_a_rational_parametrization():
    # over x the fibre is a cubic; over y every unknown is rational:
    # x = (y^3 + 1)/(a y), z = 1/y, real wherever a y != 0
    s, = solve_exactly([y**3 - a * x * y + 1, z * y - 1], [x, y, z])
    assert s.is_explicit() and s.free_unknowns() == [y]
    assert {str(c) for c in s.conditions()} == {'a != 0', 'y != 0'}
    rng = np.random.default_rng(3)
    for _ in range(10):
        av, yv = rng.uniform(-3, 3), rng.uniform(-3, 3)
        xv, zv = (float(SR(s.values()[u]).subs({a: av, y: yv})) for u in (x, z))
        assert abs(yv**3 - av * xv * yv + 1) < 1e-9 and abs(zv * yv - 1) < 1e-12


def test_implicit_stationary_family_multipliers_and_reality():
    # K = H + l z with H = (x^4 + y^4 - a)^2/4 + z^2/2 + x z: the family
    # x^4 + y^4 = a, z = 0, l = -x (by hand), real where x^4 <= a
    H = (x**4 + y**4 - a)**2 / 4 + z**2 / 2 + x * z
    family, = [s for s in stationary_solutions([H, z], [x, y, z]) if not s.is_explicit()]
    assert family.is_reality_decided() and family.dimension() == 1
    lam, = family.multipliers()
    rng = np.random.default_rng(5)
    inside = outside = 0
    for _ in range(30):
        av, xv = rng.uniform(-1, 2), rng.uniform(-1.3, 1.3)
        claimed = all(holds(c, {a: av, x: xv}) for c in family.conditions())
        ys = [r.real for r in np.roots([1, 0, 0, 0, xv**4 - av]) if abs(r.imag) < 1e-9]
        assert claimed == bool(ys)
        inside, outside = inside + claimed, outside + (not claimed)
        for yv in ys:
            zv = float(SR(family.point()[z]).subs({a: av, x: xv}))
            lv = float(SR(family.multipliers()[lam]).subs({a: av, x: xv, z: zv}))
            w = xv**4 + yv**4 - av
            grad = [w * xv**3 + zv, w * yv**3, zv + xv + lv]      # dK, by hand
            assert np.allclose(grad, 0, atol=1e-9)
    assert inside and outside


def test_undecided_reality_is_no_exception(monkeypatch):
    monkeypatch.setattr(solving, 'FAMILY_QE_VARIABLES', 0)
    H = (y**4 + x**4 - a)**2 / 4
    family, = [s for s in stationary_solutions([H], [x, y]) if s.dimension() == 1]
    assert not family.is_reality_decided()
    assert family.conditions() == []
    assert "where it is real not decided" in repr(family)
    assert any("where it is real: not decided" in line
               for line in stationary_solutions([H], [x, y]).report_lines())
    assert isinstance(family.stability_region(), list)
    v = family.stability()
    assert "not decided" in v.reason()
    assert [c.verdict() for c in v.cases() or [v]]


# --- Brun's problem ------------------------------------------------------------

M = list(var('M1 M2 M3'))
G = list(var('g1 g2 g3'))
I = list(var('I1 I2 I3'))
epsilon = var('epsilon')


def brun(with_integral=False):
    H = sum(M[i]**2 / I[i] for i in range(3)) / 2 + epsilon / 2 * sum(
        I[i] * G[i]**2 for i in range(3))
    Mv, gv = vector(SR, M), vector(SR, G)
    w = vector(SR, [H.diff(v) for v in M])
    u = vector(SR, [H.diff(v) for v in G])
    X = list(Mv.cross_product(w) + gv.cross_product(u)) + list(gv.cross_product(w))
    F = Mv * Mv - epsilon * I[0] * I[1] * I[2] * sum(G[i]**2 / I[i] for i in range(3))
    assert sum(F.diff(v) * e for v, e in zip(M + G, X)).simplify_full() == 0
    integrals = [H, F, gv * gv, Mv * gv] if with_integral else [H, gv * gv, Mv * gv]
    return stationary_solutions(integrals, M + G, equations=X)


def gradient_K(iv, ev, m, g, l1, l2):
    """dK/dM and dK/dgamma for K = H + l1 gamma.gamma + l2 M.gamma (by hand)."""
    return np.concatenate([m / iv + l2 * g, ev * iv * g + 2 * l1 * g + l2 * m])


def real_stationary_points(iv, ev, m):
    """The real (gamma, l1, l2) with grad K = 0 at the given M, exactly:
    Sage over AA, from the gradient written by hand."""
    R = PolynomialRing(QQ, 'g1, g2, g3, l1, l2')
    g, l1, l2 = R.gens()[:3], R.gen(3), R.gen(4)
    eqs = [QQ(m[i]) / QQ(iv[i]) + l2 * g[i] for i in range(3)] + \
        [QQ(ev) * QQ(iv[i]) * g[i] + 2 * l1 * g[i] + l2 * QQ(m[i]) for i in range(3)]
    return [[float(p[g[i]]) for i in range(3)] for p in R.ideal(eqs).variety(AA)]


@pytest.fixture(scope='module')
def brun_families():
    return [s for s in brun() if s.dimension() == 3]


@pytest.mark.slow
def test_brun_uniform_rotations_are_real_exactly_for_positive_epsilon(brun_families):
    assert len(brun_families) == 2
    assert all(s.is_reality_decided() for s in brun_families)
    rng = np.random.default_rng(5)
    signs = set()
    for _ in range(6):
        iv = [int(k) for k in rng.choice(range(1, 7), size=3, replace=False)]   # triaxial
        ev = int(rng.integers(1, 4) * rng.choice([-1, 1]))
        m = [int(k) for k in rng.integers(1, 4, size=3)]
        values = dict(zip(I + [epsilon] + M, iv + [ev] + m))
        claimed = [all(bool(SR(c).subs(values).subs(
            {v: SR(s.point()[v]).subs(values) for v in G})) for c in s.conditions())
            for s in brun_families]
        found = real_stationary_points(iv, ev, m)
        # exactly the two branches for epsilon > 0, no real point below
        assert len(found) == (2 if ev > 0 else 0)
        assert claimed == [ev > 0] * 2
        signs.add(ev > 0)
        for s in brun_families if ev > 0 else []:
            gv = np.array([float(SR(s.point()[v]).subs(values)) for v in G])
            mult = s.multipliers()
            l1, l2 = (float(SR(mult[k]).subs(values)) for k in sorted(mult, key=str))
            assert np.allclose(gradient_K(np.array(iv, float), ev, np.array(m, float),
                                          gv, l1, l2), 0, atol=1e-9)
            assert any(np.allclose(gv, p) for p in found)
    assert signs == {True, False}


def euler_poisson_jacobian(iv, ev, m, g):
    """The Jacobian of dM/dt = M x w + gamma x u, dgamma/dt = gamma x w
    (w = M/I, u = epsilon I gamma), by central differences."""
    def rhs(z):
        mm, gg = z[:3], z[3:]
        return np.concatenate([np.cross(mm, mm / iv) + np.cross(gg, ev * iv * gg),
                               np.cross(gg, mm / iv)])
    z0, h = np.concatenate([m, g]), 1.0      # exact for a quadratic right-hand side
    return np.array([(rhs(z0 + h * e) - rhs(z0 - h * e)) / (2 * h) for e in np.eye(6)]).T


@pytest.mark.slow
def test_brun_families_stability_has_cases_checked_by_eigenvalues(brun_families):
    # the square root of epsilon in the family does not stop the first
    # approximation; its 'unstable' case is where the numerical Jacobian
    # has a root with positive real part, the rest (roots on the imaginary
    # axis) is undecided
    rng = np.random.default_rng(11)
    for s in brun_families:
        v = s.stability()
        assert v.verdict() == 'depends on the parameters'
        unstable, = [c for c in v.cases() if c.verdict() == 'unstable']
        seen = set()
        for _ in range(12):
            # for positive moments of inertia the 'unstable' region is empty
            # (the polynomial is a sum of I_j I_k (I_i - I_j - I_k)^2 M_i^2):
            # signs are drawn too, to test the case
            iv = [int(k) * int(rng.choice([-1, 1]))
                  for k in rng.choice(range(1, 9), size=3, replace=False)]
            ev = int(rng.integers(1, 4))
            m = [int(k) * int(rng.choice([-1, 1])) for k in rng.integers(1, 5, size=3)]
            values = dict(zip(I + [epsilon] + M, iv + [ev] + m))
            gv = np.array([float(SR(s.point()[x]).subs(values)) for x in G])
            at = {**values, **dict(zip(G, gv))}
            claimed = any(all(holds(c, at) for c in alt) for alt in unstable.region())
            roots = np.linalg.eigvals(euler_poisson_jacobian(
                np.array(iv, float), ev, np.array(m, float), gv))
            # zero roots of the Casimirs and the family split by rounding only
            assert claimed == bool(roots.real.max() > 1e-4)
            seen.add(claimed)
        assert seen == {True, False}


def brun_integral_points(iv, ev, m, g1v):
    """The real (g2, g3) with grad K = 0 for K = H + l1 F + l2 gamma.gamma
    + l3 M.gamma at the given M and gamma_1, exactly (Sage over AA, the
    gradient written by hand)."""
    R = PolynomialRing(QQ, 'g2, g3, l1, l2, l3')
    g2, g3, l1, l2, l3 = R.gens()
    g = [QQ(g1v), g2, g3]
    iv, m, ev = [QQ(k) for k in iv], [QQ(k) for k in m], QQ(ev)
    det = iv[0] * iv[1] * iv[2]
    eqs = [m[i] / iv[i] + 2 * l1 * m[i] + l3 * g[i] for i in range(3)] + \
        [ev * iv[i] * g[i] - 2 * l1 * ev * det * g[i] / iv[i] + 2 * l2 * g[i] + l3 * m[i]
         for i in range(3)]
    J = R.ideal(eqs)
    assert J.dimension() == 0
    return [[float(p[g2]), float(p[g3])] for p in J.variety(AA)]


@pytest.mark.slow
def test_brun_with_its_integral_4_parameter_family():
    # with Brun's integral F the stationary set has 4-parameter families,
    # given over (M, gamma_1) with a square root: real exactly where its
    # radicand is positive, as the exact solution at rational values says
    families = [s for s in brun(with_integral=True) if s.dimension() == 4]
    assert len(families) == 2 and all(s.is_reality_decided() for s in families)
    # (the radicand, a quadratic in epsilon g1^2, is negative somewhere only
    # when I1 is the largest or the smallest moment of inertia)
    rng = np.random.default_rng(17)
    seen = set()
    for _ in range(14):
        iv = [int(k) for k in rng.choice(range(1, 7), size=3, replace=False)]
        ev = int(rng.integers(1, 4) * rng.choice([-1, 1]))
        m = [int(k) * int(rng.choice([-1, 1])) for k in rng.integers(1, 4, size=3)]
        g1v = int(rng.integers(1, 3) * rng.choice([-1, 1]))
        values = dict(zip(I + [epsilon] + M + [G[0]], iv + [ev] + m + [g1v]))
        claimed = [all(bool(SR(c).subs(values)) for c in s.conditions()) for s in families]
        assert claimed[0] == claimed[1]
        found = brun_integral_points(iv, ev, m, g1v)
        assert len(found) == (2 if claimed[0] else 0)
        seen.add(claimed[0])
        for s in families if claimed[0] else []:
            point = [float(SR(s.point()[v]).subs(values)) for v in G[1:]]
            assert sum(np.allclose(point, p) for p in found) == 1
    assert seen == {True, False}
