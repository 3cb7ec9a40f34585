"""
The census of relative equilibria on the symplectic leaves
(sage_dynsym.analysis.leaf_census) against results from outside the code:

- the free rigid body (Euler's top) on so(3)*, H = 1/2 sum M_i^2 / I_i, on
  the spheres |M|^2 = c^2: six relative equilibria on every sphere c != 0
  (the rotations about the principal axes), four of them stable (the
  largest and the smallest axes: Euler; Arnold, Mathematical Methods, 29),
  the only bifurcation at c = 0. Checked against a least-squares search for
  the equilibria on random spheres (SciPy) and the definiteness of the
  second variation of H - lambda |M|^2 on the tangent space of the sphere
  (NumPy), at random moments of inertia;
- a symmetric body, I_1 = I_2: the rotations about the equatorial axes form
  a circle on each sphere (M_3 = 0), reported as a family, not as points;
- the heavy Lagrange top (A = B = 1, C = 2, m g l = 1, the centre of mass
  above the fixed point, gamma the upward vertical) on (M, gamma) = c,
  (gamma, gamma) = 1: the upright sleeping top is stable for c^2 > 4 A m g l
  (Maievski), the hanging one always; the permanent rotations about the
  vertical with the axis inclined (M = W I gamma, W^2 gamma3 = m g l, so
  c = W + W^-3 with W > 1) exist for c > 4 * 3^(-3/4) (the least value of
  W + W^-3) -- two circles up to c = 2 (W -> 1: the upright top), one
  above; checked by a least-squares search;
- two parameters (a moment of inertia and the level): the bifurcation
  curves are where two moments are equal and where the sphere shrinks to
  a point; the plot draws them;
- the stability in first approximation (cells(first_approximation=True)):
  at random levels of each refined cell of Brun's problem and of the
  Lagrange top, the count of relative equilibria whose linearization on the
  leaf (written by hand here, projected on the tangent space of the leaf)
  has simple imaginary eigenvalues (NumPy), or whose second variation is
  definite there; Brun's boundaries against the discriminants of the
  characteristic polynomials at the rotations about the axes (SymPy).
"""
import numpy as np
import pytest
from scipy.optimize import least_squares

from sage.all import var, QQ
from sage_dynsym.lie import LiePoissonSystem
from sage_dynsym.analysis.census import equilibrium_census
from sage_dynsym.errors import AnalysisError

M1, M2, M3, c, a = var('M1 M2 M3 c a')


def euler_points(inertia, radius, starts=60, seed=3):
    """The equilibria of M' = M x (M / I) on |M| = radius, by least squares."""
    rng = np.random.default_rng(seed)
    inertia = np.asarray(inertia, dtype=float)

    def residual(m):
        return np.concatenate([np.cross(m, m / inertia), [m @ m - radius**2]])
    found = []
    for _ in range(starts):
        fit = least_squares(residual, rng.normal(size=3) * radius, xtol=1e-15, ftol=1e-15,
                            gtol=1e-15)
        if fit.cost < 1e-24 and not any(np.allclose(fit.x, y, atol=1e-7) for y in found):
            found.append(fit.x)
    return found


def energy_casimir_definite(inertia, m):
    """The second variation of H - l |M|^2 on the tangent plane of the sphere."""
    inertia = np.asarray(inertia, dtype=float)
    l = np.linalg.lstsq((2 * m)[:, None], m / inertia, rcond=None)[0][0]
    tangent = np.linalg.svd(m[None, :])[2][1:].T
    eig = np.linalg.eigvalsh(tangent.T @ np.diag(1 / inertia - 2 * l) @ tangent)
    return bool(all(eig > 1e-9) or all(eig < -1e-9))


@pytest.mark.parametrize("seed", [1, 2])
def test_euler_top_against_least_squares(seed):
    rng = np.random.default_rng(seed)
    inertia = sorted(QQ(int(k)) / 4 for k in rng.choice(np.arange(1, 40), 3, replace=False))
    S = LiePoissonSystem('so3', sum(m**2 / i for m, i in zip([M1, M2, M3], inertia)) / 2)
    census = equilibrium_census(S, [c], levels=[c**2])
    assert census.bifurcation_set() == [c]
    assert len(census.cells()) == 2
    for cell in census.cells():
        assert cell.families() == []
        for radius in rng.uniform(0.2, 5, size=2):
            points = euler_points([float(i) for i in inertia], radius)
            assert cell.count() == len(points) == 6
            assert cell.stable_count() == sum(energy_casimir_definite(inertia, m)
                                              for m in points) == 4
            # the middle axis is a saddle of H on the sphere: unstable
            assert cell.stable_count(first_approximation=True) == 4
    # on a sphere (a leaf of dimension 2) the linearization has one pair of roots
    # +-i w, which cannot collide: no boundary besides c = 0
    assert census.bifurcation_set(first_approximation=True) == [c]
    assert [x.stable_count(first_approximation=True)
            for x in census.cells(first_approximation=True)] == [4, 4]


def test_symmetric_body_has_a_circle_of_relative_equilibria():
    S = LiePoissonSystem('so3', (M1**2 + M2**2) / 2 + M3**2 / 6)
    cell, = equilibrium_census(S, [c], levels=[c], positive=[c]).cells()
    # M = (0, 0, +-sqrt(c)) and the circle M3 = 0 (every equatorial axis)
    assert (cell.count(), cell.stable_count(), cell.families()) == (2, 2, [1])
    assert "2 isolated, 2 stable, and a curve of relative equilibria" in str(cell)


def test_two_parameters_and_the_plot():
    S = LiePoissonSystem('so3', (M1**2 + M2**2 / a + M3**2 / 3) / 2)
    census = S.equilibrium_census([a, c], levels=[c], positive=[a, c])
    assert sorted(map(str, census.bifurcation_set())) == ['a - 1', 'a - 3', 'c']
    for cell in census.cells():
        sample = cell.sample()
        inertia = [1, float(sample[a]), 3]
        points = euler_points(inertia, np.sqrt(float(sample[c])))
        assert cell.count() == len(points) == 6
        assert cell.stable_count() == sum(energy_casimir_definite(inertia, m) for m in points)
    # one pair of roots +-i w on a sphere: no boundary of the first approximation (nor
    # a = 0, where the Hamiltonian M2^2/a is not defined)
    assert sorted(map(str, census.bifurcation_set(first_approximation=True))) == \
        ['a - 1', 'a - 3', 'c']
    G = census.plot()
    # the cells and the two curves a = 1, a = 3 (c = 0 is the edge of the window)
    assert len(G) >= len(census.cells()) + 2


def test_errors():
    S = LiePoissonSystem('so3', (M1**2 + M2**2 / a + M3**2 / 3) / 2)
    with pytest.raises(AnalysisError, match="give one level per Casimir"):
        S.equilibrium_census([a])
    with pytest.raises(AnalysisError, match="give a value to a"):
        S.equilibrium_census([c], levels=[c])
    with pytest.raises(AnalysisError, match="neither a symbol of H nor of the levels"):
        S.equilibrium_census([var('b')], levels=[c], values={a: 2})


def lagrange_top_points(level, starts=80, seed=11):
    """The relative equilibria of the Lagrange top above on the level, by least squares."""
    rng = np.random.default_rng(seed)
    inertia = np.array([1.0, 1.0, 2.0])

    def residual(x):
        m, g = np.split(x, 2)
        field = np.concatenate([np.cross(m, m / inertia) + np.cross(g, [0, 0, 1]),
                                np.cross(g, m / inertia)])
        return np.concatenate([field, [g @ g - 1, m @ g - level]])
    found = []
    for _ in range(starts):
        fit = least_squares(residual, rng.normal(size=6) * 2, xtol=1e-15, ftol=1e-15, gtol=1e-15)
        if fit.cost < 1e-24:
            found.append(fit.x)
    return found


@pytest.mark.slow       # the census takes about 10 s
def test_lagrange_top():
    g1, g2, g3 = var('gamma1 gamma2 gamma3')
    S = LiePoissonSystem('e3', (M1**2 + M2**2) / 2 + M3**2 / 4 + g3)
    census = S.equilibrium_census([c], levels=[c, 1], positive=[c])
    assert [float(v) for v in census.bifurcation_values()] == pytest.approx([4 * 3**-0.75, 2])
    expected = [(2, 1, []), (2, 1, [1]), (2, 2, [1])]      # (count, stable, families)
    assert [(x.count(), x.stable_count(), x.families()) for x in census.cells()] == expected
    for cell in census.cells():
        level = float(cell.sample()[c])
        points = lagrange_top_points(level)
        vertical = {int(np.sign(x[5])) for x in points if abs(abs(x[5]) - 1) < 1e-7}
        inclined = [x for x in points if abs(abs(x[5]) - 1) > 1e-7]
        assert len(vertical) == cell.count()
        assert bool(inclined) == bool(cell.families())
        for x in inclined:      # M = W I gamma with W^2 gamma3 = 1
            m, g = np.split(x, 2)
            w = m[2] / (2 * g[2])
            assert np.allclose(m, w * np.array([1, 1, 2]) * g) and abs(w**2 * g[2] - 1) < 1e-7
        # the upright top (gamma3 = 1, M3 = c) is stable exactly for c > 2
        assert cell.stable_count() == 1 + (level > 2)
    # the first approximation, at random levels of each refined cell, against NumPy's
    # eigenvalues on the leaf at the upright and the hanging top (M = c gamma3 e3)
    rng = np.random.default_rng(2)
    for cell in census.cells(first_approximation=True):
        lo, hi = cell.bounds()
        for level in rng.uniform(float(lo), float(hi) if hi is not None else float(lo) + 3, 3):
            stable = 0
            for up in (1, -1):
                spectrum, definite = e3_leaf(np.array([0, 0, up * level, 0, 0, up]),
                                             np.diag([1, 1, 1 / 2]),
                                             lambda g: np.array([0, 0, 1.0]), np.zeros((3, 3)))
                stable += definite or simple_and_imaginary(spectrum)
            assert cell.stable_count(first_approximation=True) == stable


# -- Brun's problem: the stability in first approximation ------------------------------
#
# H = (M, A M)/2 + (gamma, B gamma)/2 with A = diag(1, 1/2, 1/3), B = diag(1, 2, 3), on the
# levels (M, gamma) = c, (gamma, gamma) = 1: M' = M x AM + gamma x B gamma, gamma' = gamma x AM.
# The linearization is computed here by hand, restricted to the tangent space of the leaf
# (the kernel of the gradients of the Casimirs) and its eigenvalues taken by NumPy.

BRUN_A, BRUN_B = np.diag([1, 1 / 2, 1 / 3]), np.diag([1.0, 2.0, 3.0])


def cross_matrix(v):
    """S(v) with S(v) u = v x u."""
    return np.array([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])


def brun_field(x):
    m, g = np.split(x, 2)
    return np.concatenate([np.cross(m, BRUN_A @ m) + np.cross(g, BRUN_B @ g),
                           np.cross(g, BRUN_A @ m)])


def e3_leaf(x, inertia, potential_gradient, potential_hessian):
    """For H = (M, A M)/2 + U(gamma) on e(3)*: the eigenvalues of the linearization of
    M' = M x AM + gamma x grad U, gamma' = gamma x AM on the leaf through the relative
    equilibrium x, and whether the second variation of H - l1 (M, gamma) - l2 (gamma, gamma)
    is definite on the tangent space of the leaf (the energy-Casimir method)."""
    m, g = np.split(x, 2)
    am, du = inertia @ m, potential_gradient(g)
    jacobian = np.block([[-cross_matrix(am) + cross_matrix(m) @ inertia,
                          -cross_matrix(du) + cross_matrix(g) @ potential_hessian],
                         [cross_matrix(g) @ inertia, -cross_matrix(am)]])
    gradients = np.array([np.concatenate([g, m]), np.concatenate([np.zeros(3), 2 * g])])
    tangent = np.linalg.svd(gradients)[2][2:].T         # orthonormal basis of the kernel
    # the linearization maps into the tangent space at a relative equilibrium
    assert np.allclose(gradients @ jacobian, 0, atol=1e-9)
    l1, l2 = np.linalg.lstsq(gradients.T, np.concatenate([am, du]), rcond=None)[0]
    second = np.block([[inertia, -l1 * np.eye(3)],
                       [-l1 * np.eye(3), potential_hessian - 2 * l2 * np.eye(3)]])
    eig = np.linalg.eigvalsh(tangent.T @ second @ tangent)
    return (np.linalg.eigvals(tangent.T @ jacobian @ tangent),
            bool(all(eig > 1e-9) or all(eig < -1e-9)))


def brun_leaf(x):
    return e3_leaf(x, BRUN_A, lambda g: BRUN_B @ g, BRUN_B)


def simple_and_imaginary(roots, tol=1e-7):
    gaps = [abs(a - b) for i, a in enumerate(roots) for b in roots[i + 1:]]
    return bool(np.all(np.abs(roots.real) < tol) and min(gaps) > 1e-4)


def brun_isolated_points(level, starts=150, seed=7):
    """The relative equilibria on the level by least squares, without Brun's rotations
    (the curve M = I gamma, I = diag(1, 2, 3), on the levels 1 < c < 3)."""
    rng = np.random.default_rng(seed)

    def residual(x):
        m, g = np.split(x, 2)
        return np.concatenate([brun_field(x), [g @ g - 1, m @ g - level]])
    found = []
    for _ in range(starts):
        fit = least_squares(residual, rng.normal(size=6) * 2, xtol=1e-15, ftol=1e-15,
                            gtol=1e-15)
        m, g = np.split(fit.x, 2)
        on_curve = np.allclose(m, BRUN_B @ g, atol=1e-7)
        if fit.cost < 1e-24 and not on_curve and \
                not any(np.allclose(fit.x, y, atol=1e-6) for y in found):
            found.append(fit.x)
    return found


@pytest.fixture(scope="module")
def brun_census():
    g1, g2, g3 = var('gamma1 gamma2 gamma3')
    H = (M1**2 + M2**2 / 2 + M3**2 / 3) / 2 + (g1**2 + 2 * g2**2 + 3 * g3**2) / 2
    S = LiePoissonSystem('e3', H)
    return S.equilibrium_census([c], levels=[c, 1], positive=[c])


@pytest.mark.slow       # the census, its refinement and the searches take about 40 s
def test_brun_first_approximation_against_numpy(brun_census):
    census = brun_census
    rng = np.random.default_rng(5)
    cells = census.cells(first_approximation=True)
    assert len(cells) == len(census.bifurcation_values(first_approximation=True)) + 1
    for cell in cells:
        lo, hi = cell.bounds()
        top = float(hi) if hi is not None else float(lo) + 3
        for level in rng.uniform(float(lo), top, size=3):
            points = brun_isolated_points(level)
            assert len(points) == cell.count()
            definite = [brun_leaf(x)[1] for x in points]
            linear = [simple_and_imaginary(brun_leaf(x)[0]) for x in points]
            assert cell.stable_count() == sum(definite)
            # stable (energy-Casimir) or stable in first approximation; for c > 3 the
            # rotations about the third axis are stable with double roots on the leaf
            assert cell.stable_count(first_approximation=True) == \
                sum(d or s for d, s in zip(definite, linear))


def test_brun_discriminants_against_sympy():
    """The boundaries of the first approximation of the rotations about the axes
    (gamma = e_k, M = c e_k), from SymPy's characteristic polynomial of the
    linearization at them: q(w) with p(z) = z^2 q(z^2); they are in the set
    computed with the parameters symbolic."""
    import sympy as sp
    from sage.all import SR, block_matrix, matrix
    from sage_dynsym.analysis.leaf_census import leaf_first_approximation_polynomials
    sc, z, w = sp.symbols('c z w')
    m, g = sp.Matrix(sp.symbols('m1:4')), sp.Matrix(sp.symbols('n1:4'))
    field = (m.cross(sp.diag(1, sp.Rational(1, 2), sp.Rational(1, 3)) * m)
             + g.cross(sp.diag(1, 2, 3) * g)).col_join(
                 g.cross(sp.diag(1, sp.Rational(1, 2), sp.Rational(1, 3)) * m))
    jacobian = field.jacobian(list(m) + list(g))
    expected = set()
    for k in range(3):
        axis = [int(i == k) for i in range(3)]
        at = dict(zip(list(m) + list(g), [sc * v for v in axis] + axis))
        p = sp.cancel(jacobian.subs(at).charpoly(z).as_expr() / z**2)
        q = sp.Poly(sp.expand(p).subs(z**2, w), w)
        for f in (q.eval(0), q.discriminant()):
            expected |= {str(sp.Poly(a, sc).monic().as_expr()) for a, _ in sp.factor_list(f)[1]}
    g1, g2, g3 = var('g1 g2 g3')
    H = (M1**2 + M2**2 / 2 + M3**2 / 3) / 2 + (g1**2 + 2 * g2**2 + 3 * g3**2) / 2
    J = block_matrix([[matrix([[0, -M3, M2], [M3, 0, -M1], [-M2, M1, 0]]),
                       matrix([[0, -g3, g2], [g3, 0, -g1], [-g2, g1, 0]])],
                      [matrix([[0, -g3, g2], [g3, 0, -g1], [-g2, g1, 0]]), 0]])
    found = leaf_first_approximation_polynomials(
        H, [M1 * g1 + M2 * g2 + M3 * g3, g1**2 + g2**2 + g3**2], J,
        [M1, M2, M3, g1, g2, g3], [c, 1], [c])
    found = {str(sp.Poly(sp.sympify(str(f)).subs(sp.Symbol('c'), sc), sc).monic().as_expr())
             for f in found}
    # the axes are all the isolated relative equilibria of Brun's problem
    assert found == expected
    assert expected >= {'c**4 + 14*c**2 + 1', 'c**4 - 4*c**2 + 16'}
