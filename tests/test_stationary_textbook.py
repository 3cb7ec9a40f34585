"""Stationary solutions and their stability on textbook problems (issue 9).

Every expected value comes from the textbook result cited at the test, or
from an independent numerical computation: numpy eigenvalues of Jacobians
and linearizations written out here by hand, finite-difference second
derivatives of effective / amended potentials, substitution into the
equations of motion. Verdicts that depend on parameters are checked by
evaluating the case regions (region_holds) at numerical parameter values.
"""
import math
import random

import numpy as np
import pytest
from sage.all import SR, QQ, var, sin, cos

from sage_dynsym import Lagrangian, load
from sage_dynsym.algebra.conditions import region_holds, holds
from sage_dynsym.analysis.stationary import stationary_solutions, stationary_motions


def cases_at(verdict, vals):
    """The (verdict, method) pairs whose region holds at ``vals``."""
    cases = verdict.cases() if verdict.verdict() == 'depends on the parameters' else [verdict]
    return [(c.verdict(), c.method()) for c in cases if region_holds(c.region(), vals)]


STABLE_RL = [('stable', 'Routh-Lyapunov')]
UNSTABLE_FA = [('unstable', 'first approximation')]


# ---------------------------------------------------------------------------
# Euler top: Arnold, Mathematical Methods of Classical Mechanics, §28-29;
# Merkin, Introduction to the Theory of Stability, ch. 5. Rotations about
# the largest and smallest principal axes are stable, about the middle one
# unstable.
# ---------------------------------------------------------------------------

M1, M2, M3, A1, A2, A3 = var('M1 M2 M3 A1 A2 A3')
MS, AS = [M1, M2, M3], [A1, A2, A3]


def euler(A):
    a1, a2, a3 = A
    X = [(a2 - a3) / (a2 * a3) * M2 * M3, (a3 - a1) / (a3 * a1) * M3 * M1,
         (a1 - a2) / (a1 * a2) * M1 * M2]
    H = (M1**2 / a1 + M2**2 / a2 + M3**2 / a3) / 2
    return X, H, M1**2 + M2**2 + M3**2


def euler_jacobian_eigenvalues(vals):
    """numpy eigenvalues of the Jacobian of the Euler equations at the
    point vals (Jacobian by Sage differentiation)."""
    X, _, _ = euler(AS)
    J = [[float(SR(e).diff(v).subs(vals)) for v in MS] for e in X]
    return np.linalg.eigvals(np.array(J))


def rotation_kind(vals, axis):
    """'middle' or 'extreme' from the numerical moments of inertia."""
    order = sorted(AS, key=lambda s: vals[s])
    return 'middle' if str(order[1]) == str(AS[axis]) else 'extreme'


def axis_of(s):
    """The index of the component a line of rotations leaves free."""
    return [k for k, M in enumerate(MS) if str(s.point()[M]) == str(M)][0]


@pytest.mark.slow
def test_euler_top_rest_point_and_three_lines_of_rotations():
    X, H, V = euler(AS)
    sols = stationary_solutions([H, V], MS, equations=X, positive=AS)
    assert sorted(s.dimension() for s in sols) == [0, 1, 1, 1]
    rest = [s for s in sols if s.dimension() == 0][0]
    assert rest.point() == {M1: 0, M2: 0, M3: 0}
    assert rest.stability().verdict() == 'stable'
    assert rest.stability().method() == 'Routh-Lyapunov'
    lines = sorted((s for s in sols if s.dimension() == 1), key=axis_of)
    for axis, s in enumerate(lines):
        # the line of the axis: M_axis free, the other components zero
        assert s.point() == {M: (M if k == axis else 0) for k, M in enumerate(MS)}
        # it annuls the Euler equations (by substitution)
        assert all(SR(e).subs(s.point()).simplify_rational() == 0 for e in X)

    rng = random.Random(29)
    seen = set()
    for _ in range(12):
        while True:
            vals = {A: QQ(rng.randint(2, 40)) / 8 for A in AS}
            if len(set(vals.values())) == 3:
                break
        for axis, s in enumerate(lines):
            at = dict(vals)
            at.update({M: (QQ(rng.choice([-3, -1, 2, 5])) / 2 if k == axis else 0)
                       for k, M in enumerate(MS)})
            kind = rotation_kind(vals, axis)
            seen.add(kind)
            got = cases_at(s.stability(), at)
            ev = euler_jacobian_eigenvalues(at)
            if kind == 'middle':
                assert got == UNSTABLE_FA, (vals, axis, got)
                assert np.max(ev.real) > 1e-6          # a root with Re > 0
            else:
                assert got == STABLE_RL, (vals, axis, got)
                assert np.max(np.abs(ev.real)) < 1e-9  # a centre
    assert seen == {'middle', 'extreme'}


@pytest.mark.parametrize("moments", [(1, 2, 3), (3, 1, 2), (QQ(5) / 2, 4, QQ(1) / 3)])
def test_euler_top_numerical_moments(moments):
    X, H, V = euler(moments)
    sols = stationary_solutions([H, V], MS, equations=X)
    lines = [s for s in sols if s.dimension() == 1]
    assert len(lines) == 3 and len(sols) == 4
    middle = sorted(range(3), key=lambda k: moments[k])[1]
    for s in lines:
        axis = axis_of(s)
        v = s.stability()
        at = {M: (1 if k == axis else 0) for k, M in enumerate(MS)}
        expected = UNSTABLE_FA if axis == middle else STABLE_RL
        assert cases_at(v, at) == expected, (moments, axis, v)


# ---------------------------------------------------------------------------
# Double pendulum (Merkin, ch. 3; Landau & Lifshitz, Mechanics, §5 problem 1):
# four equilibria, only the lowest stable.
# ---------------------------------------------------------------------------

t1, t2, d1, d2, m1, m2, l1, l2, g = var('theta1 theta2 dtheta1 dtheta2 m1 m2 l1 l2 g')
DP = [m1, m2, l1, l2, g]


def double_pendulum():
    return Lagrangian((m1 + m2) / 2 * l1**2 * d1**2 + m2 / 2 * l2**2 * d2**2
                      + m2 * l1 * l2 * d1 * d2 * cos(t1 - t2)
                      + (m1 + m2) * g * l1 * cos(t1) + m2 * g * l2 * cos(t2), [t1, t2])


def double_pendulum_squared_frequencies(vals, a1, a2):
    """Eigenvalues of M^{-1} K at the equilibrium (a1, a2), M and K written
    out by hand: M = [[(m1+m2) l1^2, m2 l1 l2 cos(a1-a2)], [., m2 l2^2]],
    K = diag((m1+m2) g l1 cos a1, m2 g l2 cos a2)."""
    v = {k: float(x) for k, x in vals.items()}
    c12 = math.cos(a1 - a2)
    M = np.array([[(v[m1] + v[m2]) * v[l1]**2, v[m2] * v[l1] * v[l2] * c12],
                  [v[m2] * v[l1] * v[l2] * c12, v[m2] * v[l2]**2]])
    K = np.diag([(v[m1] + v[m2]) * v[g] * v[l1] * math.cos(a1),
                 v[m2] * v[g] * v[l2] * math.cos(a2)])
    return np.linalg.eigvals(np.linalg.solve(M, K)).real, M, K


def numeric(A, vals):
    return np.array([[float(SR(e).subs(vals)) for e in row] for row in A.rows()])


def test_double_pendulum_four_equilibria_only_the_lowest_stable():
    L = double_pendulum()
    sols = stationary_motions(L, positive=DP)
    points = sorted((str(s.point()[t1]), str(s.point()[t2])) for s in sols)
    assert points == [('0', '0'), ('0', 'pi'), ('pi', '0'), ('pi', 'pi')]
    assert all(s.dimension() == 0 and s.conditions() == [] for s in sols)
    verdicts = [s.stability() for s in sols]
    rng = random.Random(5)
    for _ in range(8):
        vals = {p: QQ(rng.randint(2, 30)) / 8 for p in DP}
        for s, v in zip(sols, verdicts):
            a1, a2 = float(s.point()[t1]), float(s.point()[t2])
            mu, M, K = double_pendulum_squared_frequencies(vals, a1, a2)
            lowest = a1 == 0 and a2 == 0
            # reference: all squared frequencies positive iff the lowest one
            assert (min(mu) > 0) == lowest
            # the package's linearization has the same matrices
            lin = s.linear_system()
            assert np.allclose(numeric(lin.M(), vals), M)
            assert np.allclose(numeric(lin.K(), vals), K)
            assert cases_at(v, vals) == (STABLE_RL if lowest else UNSTABLE_FA), (s, vals, v)


# ---------------------------------------------------------------------------
# Bead on a hoop of radius R turning at the rate w about its vertical
# diameter (Goldstein, Classical Mechanics, 3rd ed., §2.6; Arnold, §25;
# Strogatz, Nonlinear Dynamics and Chaos, §3.5): equilibria theta = 0, pi and
# +-arccos(g/(R w^2)) when R w^2 > g; the bottom is stable below the
# bifurcation, unstable above, the new ones are stable.
# ---------------------------------------------------------------------------

th, dth, m, R, w = var('theta dtheta m R w')
HOOP = [m, R, w, g]


def effective_potential_second_derivative(vals, theta0):
    """U_eff'' by central differences, U_eff = -m R^2 w^2 sin^2/2 - m g R cos."""
    v = {k: float(x) for k, x in vals.items()}

    def U(t):
        return -v[m] * v[R]**2 * v[w]**2 * math.sin(t)**2 / 2 - v[m] * v[g] * v[R] * math.cos(t)
    h = 1e-4
    return (U(theta0 + h) - 2 * U(theta0) + U(theta0 - h)) / h**2


def hoop_samples():
    # R w^2 / g = 1/2 and 2 (e.g. Strogatz's gamma = R w^2 / g), then random
    yield {m: QQ(1), R: QQ(2), w: QQ(1), g: QQ(4)}
    yield {m: QQ(3), R: QQ(2), w: QQ(2), g: QQ(4)}
    rng = random.Random(25)
    n = 0
    while n < 8:
        vals = {p: QQ(rng.randint(2, 40)) / 8 for p in HOOP}
        if abs(vals[R] * vals[w]**2 / vals[g] - 1) > 0.1:
            n += 1
            yield vals


def test_bead_on_rotating_hoop():
    L = Lagrangian(m * R**2 * (dth**2 + w**2 * sin(th)**2) / 2 + m * g * R * cos(th), [th])
    sols = stationary_motions(L, positive=HOOP)
    assert len(sols) == 4
    verdicts = [s.stability() for s in sols]
    for vals in hoop_samples():
        above = vals[R] * vals[w]**2 > vals[g]
        exist = 0
        for s, v in zip(sols, verdicts):
            ok = all(holds(c, vals) for c in s.conditions())
            if not ok:
                continue
            exist += 1
            theta0 = float(SR(s.point()[th]).subs(vals))
            # the computed equilibrium annuls the equation of motion at rest
            fv = {k: float(x) for k, x in vals.items()}
            residual = math.sin(theta0) * (fv[R] * fv[w]**2 * math.cos(theta0) - fv[g])
            assert abs(residual) < 1e-9
            U2 = effective_potential_second_derivative(vals, theta0)
            expected = STABLE_RL if U2 > 0 else UNSTABLE_FA
            assert cases_at(v, vals) == expected, (s, vals, U2, v)
            if abs(theta0) > 1e-9 and abs(abs(theta0) - math.pi) > 1e-9:
                # off-axis: cos(theta) = g / (R w^2), only above the bifurcation
                assert above
                assert math.cos(theta0) == pytest.approx(fv[g] / (fv[R] * fv[w]**2))
                assert U2 > 0
            elif abs(theta0) < 1e-9:
                assert (U2 > 0) == (not above)
        assert exist == (4 if above else 2)


# ---------------------------------------------------------------------------
# Spherical pendulum, conical motions (Goldstein, §3.x, the conical
# pendulum: psi-dot^2 = g / (l |cos theta|), theta from the upward vertical
# here, p_psi = m l^2 sin^2(theta) psi-dot): p_psi^2 = -g l^3 m^2
# sin^4(theta)/cos(theta), real iff cos(theta) < 0; stable (Routh's theorem:
# the amended potential W = m g l cos(theta) + p^2/(2 m l^2 sin^2 theta) has
# a minimum).
# ---------------------------------------------------------------------------

def spherical_pendulum():
    L = load('examples/spherical_pendulum.yaml').lagrangian()
    psi, theta = L.coordinates()
    Rf = L.routh([psi])
    return Rf, theta, Rf.momenta()[0]


ml, ll = var('m l')
SPH = [ml, ll, g]


def amended_second_derivative(fv, p, theta0):
    def W(t):
        return fv['m'] * fv['g'] * fv['l'] * math.cos(t) + \
            p**2 / (2 * fv['m'] * fv['l']**2 * math.sin(t)**2)
    h = 1e-4
    return (W(theta0 + h) - 2 * W(theta0) + W(theta0 - h)) / h**2


def spherical_samples(seed, n):
    rng = random.Random(seed)
    for _ in range(n):
        vals = {p: QQ(rng.randint(2, 30)) / 8 for p in SPH}
        theta0 = QQ(rng.randint(5, 95)) / 100 * 3      # in (0.15, 2.85)
        yield vals, theta0


def test_spherical_pendulum_conical_motions_solved_for_the_momentum():
    Rf, theta, p = spherical_pendulum()
    sols = stationary_motions(Rf, solve_for=[p], positive=SPH)
    assert len(sols) == 2
    verdicts = [s.stability() for s in sols]
    signs = set()
    for vals, theta0 in spherical_samples(3, 12):
        at = dict(vals)
        at[theta] = theta0
        fv = {str(k): float(v) for k, v in vals.items()}
        below = math.cos(theta0) < 0
        for s, v in zip(sols, verdicts):
            assert all(holds(c, at) for c in s.conditions()) == below
            if not below:
                continue
            p0 = float(SR(s.point()[p]).subs(at))
            signs.add(p0 > 0)
            ref = -fv['g'] * fv['l']**3 * fv['m']**2 * math.sin(theta0)**4 / math.cos(theta0)
            assert p0**2 == pytest.approx(ref, rel=1e-9)
            # psi-dot^2 = g / (l |cos theta|) (Goldstein's conical pendulum)
            psidot = p0 / (fv['m'] * fv['l']**2 * math.sin(theta0)**2)
            assert psidot**2 == pytest.approx(fv['g'] / (fv['l'] * abs(math.cos(theta0))))
            assert amended_second_derivative(fv, p0, float(theta0)) > 0
            assert cases_at(v, at) == STABLE_RL
    assert signs == {True, False}     # both senses of rotation


def test_spherical_pendulum_default_unknowns():
    # theta the unknown, the momentum a parameter: the conical motions form
    # one component, given by its equations
    Rf, theta, p = spherical_pendulum()
    sols = stationary_motions(Rf, positive=SPH)
    assert len(sols) == 1
    s = sols[0]
    eqs = s.equations() + sols.equations()
    # (1) at a textbook conical motion every equation vanishes
    for vals, theta0 in spherical_samples(4, 8):
        if math.cos(theta0) >= 0:
            continue
        fv = {str(k): float(v) for k, v in vals.items()}
        p0 = math.sqrt(-fv['g'] * fv['l']**3 * fv['m']**2 * math.sin(theta0)**4
                       / math.cos(theta0))
        at = {k: float(v) for k, v in vals.items()}
        at.update({theta: float(theta0), p: p0})
        scale = fv['g'] * fv['l']**3 * fv['m']**2 + p0**2
        assert all(abs(float(SR(e).subs(at))) < 1e-9 * scale for e in eqs), eqs
    # (2) conversely, for a given momentum the real points of the component
    # are the textbook conical motion: one root cos(theta) in (-1, 0)
    c = var('c')
    first = SR(s.equations()[0]).subs({cos(theta): c})
    assert not first.has(theta)
    rng = random.Random(44)
    for _ in range(6):
        vals = {q: QQ(rng.randint(2, 30)) / 8 for q in SPH}
        vals[p] = QQ(rng.randint(1, 40)) / 8
        poly = first.subs(vals).polynomial(QQ)
        roots = [r for r in np.roots([float(k) for k in reversed(poly.list())])
                 if abs(r.imag) < 1e-12 and -1 < r.real < 1]
        assert len(roots) == 1 and roots[0].real < 0
        c0 = roots[0].real
        fv = {str(k): float(v) for k, v in vals.items()}
        ref = -fv['g'] * fv['l']**3 * fv['m']**2 * (1 - c0**2)**2 / c0
        assert fv['p_psi']**2 == pytest.approx(ref, rel=1e-9)


# ---------------------------------------------------------------------------
# A curve of equilibria: V = (x^2 + y^2 - 1)^2 (a "Mexican hat"): grad V =
# 4 (x^2 + y^2 - 1) (x, y) vanishes on the unit circle and at the origin.
# ---------------------------------------------------------------------------

x, y, dx, dy, px, py = var('x y dx dy px py')
HAT = (x**2 + y**2 - 1)**2


def circle_points():
    for t in (QQ(1) / 3, QQ(2), QQ(-3) / 4):
        yield {x: (1 - t**2) / (1 + t**2), y: 2 * t / (1 + t**2)}


def hat_hessian(pt):
    # by hand: d^2 V = 4 (x^2 + y^2 - 1) I + 8 (x, y)^T (x, y)
    r = float(pt[x]**2 + pt[y]**2 - 1)
    X, Y = float(pt[x]), float(pt[y])
    return 4 * r * np.eye(2) + 8 * np.array([[X * X, X * Y], [X * Y, Y * Y]])


def test_mexican_hat_circle_and_origin():
    sols = stationary_solutions([HAT], [x, y])
    assert sorted(s.dimension() for s in sols) == [0, 1]
    origin = [s for s in sols if s.dimension() == 0][0]
    circle = [s for s in sols if s.dimension() == 1][0]
    assert origin.point() == {x: 0, y: 0}
    for pt in circle_points():
        assert all(SR(e).subs(pt) == 0 for e in circle.equations())
        assert all(SR(v).subs(pt) == pt[u] for u, v in circle.point().items())
        # numpy: the Hessian on the circle is only semi-definite (one zero
        # eigenvalue), so no Routh-Lyapunov stability may be claimed there
        ev = np.linalg.eigvalsh(hat_hessian(pt))
        assert abs(min(ev)) < 1e-12
        v = circle.stability()
        assert ('stable', 'Routh-Lyapunov') not in cases_at(v, pt)
    # off the circle the equation does not vanish: it is the circle
    assert SR(circle.equations()[0]).subs({x: QQ(1) / 2, y: 0}) != 0
    # the origin is a maximum of V (Hessian -4 I): a maximum of an integral
    # is stable for any flow preserving it; as a potential it is unstable
    assert cases_at(origin.stability(), {}) == STABLE_RL
    eq = stationary_motions(Lagrangian((dx**2 + dy**2) / 2 - HAT, [x, y]))
    rest = [s for s in eq if s.dimension() == 0][0]
    assert rest.point() == {x: 0, y: 0}
    assert np.max(np.linalg.eigvalsh(hat_hessian({x: 0, y: 0}))) < 0
    assert cases_at(rest.stability(), {}) == UNSTABLE_FA


def test_mexican_hat_circle_is_degenerate():
    # doc/method.rst (stationary solutions): a singular Hessian on the solutions means an invariant
    # manifold; numpy: the Hessian has a zero eigenvalue on the circle
    circle = [s for s in stationary_solutions([HAT], [x, y]) if s.dimension() == 1][0]
    assert circle.is_degenerate()


def test_mexican_hat_with_its_equations_of_motion():
    # x' = px, y' = py, p' = -grad V conserve H = |p|^2/2 + V; the
    # stationary set of H is p = 0 with grad V = 0, which annuls the
    # right-hand sides (by substitution on the circle)
    H = (px**2 + py**2) / 2 + HAT
    X = [px, py, -HAT.diff(x), -HAT.diff(y)]
    sols = stationary_solutions([H], [x, y, px, py], equations=X)
    assert sorted(s.dimension() for s in sols) == [0, 1]
