"""Stability maps (sage_dynsym.scale.maps) without Dask, against references
from outside the code under test: closed-form roots of a damped oscillator,
Lienard-Chipart conditions derived by hand, the package's symbolic
lienard_chipart_conditions evaluated point by point with Sage, and
numpy.linalg.eigvals of matrices evaluated by Sage.

The numerical verdict is "asymptotically stable" when the largest real part
of the roots is below -1e-9 times their largest modulus; the exact verdict
differs only where the exact largest real part is within that margin of 0.
The band stated and tested: every grid point farther than ONE grid step from
the exact boundary (no grid neighbour, diagonals included, with the other
exact verdict) agrees.
"""
import numpy as np
import pytest
from sage.all import SR, var, matrix, identity_matrix, diagonal_matrix, function, diff, \
    fast_callable, RDF

from sage_dynsym import load
from scale_helpers import example_path
from sage_dynsym.analysis import linearize, LinearSystem, lienard_chipart_conditions
from sage_dynsym.errors import AnalysisError
from sage_dynsym import linearize
from sage_dynsym.scale import stability_map


def near_boundary(exact):
    """Points with a grid neighbour (8-neighbourhood in 2-D) of the other verdict."""
    padded = np.pad(exact, 1, mode='edge')
    n0, n1 = exact.shape
    near = np.zeros_like(exact)
    for di in (-1, 0, 1):
        for dj in (-1, 0, 1):
            near |= padded[1 + di:1 + di + n0, 1 + dj:1 + dj + n1] != exact
    return near


def check_band(S, exact):
    """The map agrees with ``exact`` at every point away from the boundary,
    and the band is thin."""
    wrong = (S.stable() != exact) & np.isfinite(S.max_real_part())
    assert not (wrong & ~near_boundary(exact)).any()
    assert near_boundary(exact).mean() < 0.1


# ---------------------------------------------------------------------------
# damped oscillator m x'' + c x' + k x = 0: closed form
# ---------------------------------------------------------------------------

x, y, m, c, k = var('x y m c k')
OSC_FIRST = linearize([y, -(c * y + k * x) / m], {x: 0, y: 0}, [x, y])
OSC_SECOND = LinearSystem([x], M=[[m]], S=[[c]], W=[[k]])
GRID = {c: (-1, 2, 61), k: (-1, 2, 61)}


def oscillator_abscissa(C, K, mass):
    disc = C * C - 4 * mass * K
    return np.where(disc > 0, (-C + np.sqrt(np.abs(disc))) / (2 * mass), -C / (2 * mass))


@pytest.mark.parametrize("system", [OSC_FIRST, OSC_SECOND], ids=["first-order", "second-order"])
@pytest.mark.parametrize("method", ["polynomial", "eigvals"])
def test_oscillator_against_closed_form(system, method):
    S = stability_map(system, GRID, fixed={m: 2}, client=False, method=method)
    assert S.method() == method
    C, K = np.meshgrid(S.axes()[c], S.axes()[k], indexing='ij')
    np.testing.assert_allclose(S.max_real_part(), oscillator_abscissa(C, K, 2.0), atol=1e-7)
    exact = (C > 0) & (K > 0)           # Lienard-Chipart for m > 0, by hand
    check_band(S, exact)
    wrong = S.stable() != exact         # and the disagreements are on the lines c = 0, k = 0
    step = 3 / 60
    assert (np.minimum(np.abs(C), np.abs(K))[wrong] <= step + 1e-12).all()
    assert S.agreement([c > 0, k > 0], band=1) == 1.0
    assert S.agreement([c, k], band=1) == 1.0         # expressions mean > 0


def test_oscillator_exact_conditions_from_the_package():
    S = stability_map(OSC_FIRST, GRID, fixed={m: 2}, client=False, conditions='lienard-chipart')
    assert S.conditions() is not None
    C, K = np.meshgrid(S.axes()[c], S.axes()[k], indexing='ij')
    assert (S.exact() == ((C > 0) & (K > 0))).all()
    assert S.agreement(band=1) == 1.0


# ---------------------------------------------------------------------------
# a tunnel-diode circuit (the cubic diode of Example 4): conditions by hand
# ---------------------------------------------------------------------------

i, u, E, R, L, Cap, g, s = var('i u E R L C g s')
DIODE = g * u * (u - 3 * s) ** 2
DIODE_RHS = [E - R * i - u, i - DIODE]
# equilibrium on the falling branch u = 2s: i = f(2s) = 2 g s^3, E = R i + u
DIODE_AT = {i: 2 * g * s ** 3, u: 2 * s}


def diode_system():
    rhs = [f.subs(E=2 * R * g * s ** 3 + 2 * s) for f in DIODE_RHS]
    return linearize(rhs, DIODE_AT, [i, u], lhs_matrix=[L, Cap])


def test_tunnel_diode_against_hand_conditions():
    # C L lam^2 + (C R - 3 L g s^2) lam + (1 - 3 R g s^2): with L = C = s = 1
    # stable iff R - 3 g > 0 and 1 - 3 R g > 0
    S = stability_map(diode_system(), {R: (0, 5, 101), g: (0, 0.6, 61)},
                      fixed={L: 1, Cap: 1, s: 1}, client=False)
    RR, GG = np.meshgrid(S.axes()[R], S.axes()[g], indexing='ij')
    exact = (RR - 3 * GG > 0) & (1 - 3 * RR * GG > 0)
    check_band(S, exact)
    lam = var('lam')
    poly = diode_system().characteristic_polynomial(lam)
    assert S.agreement(lienard_chipart_conditions(poly, lam), band=1) == 1.0
    assert 0.1 < S.stable().mean() < 0.9


def test_tunnel_diode_roots_against_numpy_eigvals():
    S = stability_map(diode_system(), {R: (0, 5, 26), g: (0, 0.6, 13)},
                      fixed={L: 2, Cap: 0.5, s: 1}, client=False)
    A = diode_system().jacobian().subs({L: 2, Cap: 0.5, s: 1})
    rng = np.random.default_rng(1)
    for a, b in zip(rng.integers(0, 26, 20), rng.integers(0, 13, 20)):
        point = {R: float(S.axes()[R][a]), g: float(S.axes()[g][b])}
        w = np.linalg.eigvals(A.subs(point).change_ring(RDF).numpy())
        # near a double root both are accurate to about sqrt(eps) only
        assert abs(S.max_real_part()[a, b] - w.real.max()) <= 1e-7 * max(1, abs(w).max())


# ---------------------------------------------------------------------------
# a sixth-order system: the RLC ladder of the examples
# ---------------------------------------------------------------------------

LADDER_FIXED = {'R3': 1, 'R4': 2, 'L1': 1, 'L2': 0.5, 'L3': 1, 'C1': 1, 'C2': 2, 'C3': 1}


@pytest.fixture(scope="module")
def ladder():
    return linearize(load(example_path("rlc_ladder.yaml")), sources=False)


def test_ladder_is_sixth_order(ladder):
    assert ladder.order() == 1 and len(ladder.variables()) == 6


@pytest.mark.parametrize("method", ["polynomial", "eigvals"])
def test_ladder_against_lienard_chipart_evaluated_by_sage(ladder, method):
    R1, R2 = SR.var('R1'), SR.var('R2')
    S = stability_map(ladder, {'R1': (-1, 2, 41), 'R2': (-1, 2, 41)}, fixed=LADDER_FIXED,
                      client=False, method=method)
    lam = var('lam')
    values = {SR.var(n): v for n, v in LADDER_FIXED.items()}
    poly = ladder.characteristic_polynomial(lam)
    conditions = [fast_callable(cond.subs(values), vars=[R1, R2], domain=RDF)
                  for cond in lienard_chipart_conditions(poly, lam)]
    X, Y = S.axes()[R1], S.axes()[R2]
    exact = np.array([[all(f(a, b) > 0 for f in conditions) for b in Y] for a in X])
    check_band(S, exact)
    assert 0.1 < exact.mean() < 0.9


def test_ladder_roots_against_numpy_eigvals(ladder):
    R1, R2 = SR.var('R1'), SR.var('R2')
    S = stability_map(ladder, {R1: (-1, 2, 41), R2: (-1, 2, 41)}, fixed=LADDER_FIXED,
                      client=False)
    T = stability_map(ladder, {R1: (-1, 2, 41), R2: (-1, 2, 41)}, fixed=LADDER_FIXED,
                      client=False, method='eigvals')
    A = ladder.jacobian().subs({SR.var(n): v for n, v in LADDER_FIXED.items()})
    rng = np.random.default_rng(2)
    for a, b in zip(rng.integers(0, 41, 25), rng.integers(0, 41, 25)):
        point = {R1: float(S.axes()[R1][a]), R2: float(S.axes()[R2][b])}
        w = np.linalg.eigvals(A.subs(point).change_ring(RDF).numpy())
        for M in (S, T):
            assert abs(M.max_real_part()[a, b] - w.real.max()) <= 1e-7 * abs(w).max()


# ---------------------------------------------------------------------------
# other shapes of systems
# ---------------------------------------------------------------------------

def test_gyroscopic_second_order_against_numpy():
    # z'' + (d I + 2 G) z' + K z = 0, K = diag(-1, -2): gyroscopic stabilization
    # for d = 0 is destroyed by dissipation; compare with the companion matrix
    xs = var('z1 z2')
    d, gg = var('d gg')
    Ls = LinearSystem(list(xs), M=identity_matrix(2), S=matrix([[d, -gg], [gg, d]]),
                      W=diagonal_matrix([-1, -2]))
    S = stability_map(Ls, {d: (-0.5, 0.5, 11), gg: (0, 6, 13)}, client=False)
    for a, dv in enumerate(S.axes()[d]):
        for b, gv in enumerate(S.axes()[gg]):
            A = np.block([[np.zeros((2, 2)), np.eye(2)],
                          [np.diag([1.0, 2.0]), -np.array([[dv, -gv], [gv, dv]])]])
            w = np.linalg.eigvals(A)
            assert abs(S.max_real_part()[a, b] - w.real.max()) <= 1e-7 * abs(w).max()
    lam = var('lam')
    conds = lienard_chipart_conditions(Ls.characteristic_polynomial(lam), lam)
    assert S.agreement(conds, band=1) == 1.0


@pytest.mark.parametrize("method", ["polynomial", "eigvals"])
def test_singular_lhs_matrix(method):
    # x' = -a x + y, 0 = x - b y: x' = (1/b - a) x
    a, b = var('a b')
    Ls = LinearSystem([x, y], J=[[-a, 1], [1, -b]], B=[[1, 0], [0, 0]])
    S = stability_map(Ls, {a: (0.5, 2, 16), b: (0.5, 2, 16)}, client=False, method=method)
    A, B = np.meshgrid(S.axes()[a], S.axes()[b], indexing='ij')
    np.testing.assert_allclose(S.max_real_part(), 1 / B - A, atol=1e-12)


def test_unspecified_function_given_in_fixed():
    a = var('a')
    f = function('f')
    Ls = linearize([-(f(x) - f(0)) + a * x], {x: 0}, [x])
    fprime = diff(f(x), x).subs(x=0)
    S = stability_map(Ls, {a: (0, 2, 5)}, fixed={fprime: 1}, client=False)
    np.testing.assert_allclose(S.max_real_part(), [-1, -0.5, 0, 0.5, 1], atol=1e-15)
    with pytest.raises(AnalysisError, match=r"D\[0\]\(f\)\(0\) has no numerical value"):
        stability_map(Ls, {a: (0, 2, 5)}, client=False)


@pytest.mark.parametrize("method", ["polynomial", "eigvals"])
def test_chunking_does_not_change_anything(ladder, method):
    args = (ladder, {'R1': (-1, 2, 23), 'R2': (-1, 2, 19)})
    S = stability_map(*args, fixed=LADDER_FIXED, client=False, method=method)
    for size in (1, 2, 3, 6, 7, 100):       # short arrays take other NumPy loops
        T = stability_map(*args, fixed=LADDER_FIXED, client=False, method=method,
                          chunk_size=size)
        assert np.array_equal(S.max_real_part(), T.max_real_part())
        assert np.array_equal(S.stable(), T.stable())


def test_random_samples():
    args = (OSC_FIRST, {c: (-1, 2), k: (-1, 2)})
    S = stability_map(*args, fixed={m: 1}, samples=3000, seed=3, client=False)
    T = stability_map(*args, fixed={m: 1}, samples=3000, seed=3, client=False, chunk_size=100)
    U = stability_map(*args, fixed={m: 1}, samples=3000, seed=4, client=False)
    assert not S.is_grid() and S.max_real_part().shape == (3000,)
    assert np.array_equal(S.max_real_part(), T.max_real_part())
    assert not np.array_equal(S.axes()[c], U.axes()[c])
    C, K = S.axes()[c], S.axes()[k]
    assert C.min() >= -1 and C.max() <= 2 and K.min() >= -1 and K.max() <= 2
    np.testing.assert_allclose(S.max_real_part(), oscillator_abscissa(C, K, 1.0), atol=1e-7)
    assert S.agreement([c > 0, k > 0]) == 1.0    # no sample exactly on the boundary


def test_plot_and_save(tmp_path):
    S = stability_map(OSC_FIRST, GRID, fixed={m: 1}, client=False, conditions=[c > 0, k > 0])
    path = tmp_path / "map.png"
    S.plot(title="oscillator").save(str(path))
    assert path.stat().st_size > 1000
    S.save(tmp_path / "map.npz")
    data = np.load(tmp_path / "map.npz")
    assert list(data['parameters']) == ['c', 'k']
    assert np.array_equal(data['stable'], S.stable())
    assert np.array_equal(data['axis_0'], S.axes()[c])
    assert list(data['fixed_names']) == ['m'] and list(data['fixed_values']) == [1.0]


# ---------------------------------------------------------------------------
# bad input
# ---------------------------------------------------------------------------

@pytest.mark.parametrize("parameters, fixed, message", [
    ({c: (0, 1, 5), var('z'): (0, 1, 5)}, {m: 1}, "unknown parameter z"),
    ({'cc': (0, 1, 5)}, {m: 1}, "unknown parameter cc"),
    ({c: (0, 1, 5)}, {m: 1}, "no value for k"),
    ({c: (0, 1, 5), k: (0, 1, 5)}, {}, "no value for m"),
    ({c: (0, 1, 5), k: (0, 1, 5)}, {'mass': 1}, "unknown symbol in fixed= mass"),
    ({c: (0, 1, 5), k: (0, 1, 5)}, {m: 'one'}, r"fixed\[m\]: expected a real number"),
    ({c: (0, 1, 5), k: (0, 1, 5)}, {m: 1, c: 2}, "c is both a parameter and fixed"),
    ({c: (0, 1, 0), k: (0, 1, 5)}, {m: 1}, r"parameters\[c\]: empty range"),
    ({c: (1, 0, 5), k: (0, 1, 5)}, {m: 1}, r"parameters\[c\]: empty range"),
    ({c: (1, 1, 5), k: (0, 1, 5)}, {m: 1}, r"parameters\[c\]: empty range"),
    ({c: (0, 1), k: (0, 1, 5)}, {m: 1}, r"parameters\[c\]: expected \(low, high, n\)"),
    ({}, {m: 1}, "no parameters"),
])
def test_bad_input(parameters, fixed, message):
    with pytest.raises(AnalysisError, match=message):
        stability_map(OSC_FIRST, parameters, fixed=fixed, client=False)


def test_bad_options():
    with pytest.raises(AnalysisError, match="method must be"):
        stability_map(OSC_FIRST, GRID, fixed={m: 1}, client=False, method='qr')
    with pytest.raises(AnalysisError, match="expected a positive number of random points"):
        stability_map(OSC_FIRST, GRID, fixed={m: 1}, client=False, samples=-3)
    with pytest.raises(AnalysisError, match="expected a linear system"):
        stability_map(x + y, GRID, fixed={m: 1}, client=False)
    with pytest.raises(AnalysisError, match="client must be"):
        stability_map(OSC_FIRST, GRID, fixed={m: 1}, client=3)
    S = stability_map(OSC_FIRST, GRID, fixed={m: 1}, client=False)
    with pytest.raises(AnalysisError, match="no value for z"):
        S.exact([c * var("z") > 0])
    with pytest.raises(AnalysisError, match="no conditions"):
        S.agreement()


def test_large_system_uses_eigvals():
    # a chain of 9 masses (order 18 > 16): the map falls back on the matrices
    n = 9
    cc, kk = var('cc kk')
    T = matrix.identity(n) * 2 - matrix(n, n, lambda i, j: 1 if abs(i - j) == 1 else 0)
    Ls = LinearSystem(list(var(' '.join(f'q{i}' for i in range(n)))), M=identity_matrix(n),
                      S=cc * T, W=kk * T)
    S = stability_map(Ls, {cc: (-0.5, 1, 4), kk: (-0.5, 1, 4)}, client=False)
    assert S.method() == 'eigvals' and "order 18 > 16" in S.note()
    Tn = np.array(T, dtype=float)
    for a, cv in enumerate(S.axes()[cc]):
        for b, kv in enumerate(S.axes()[kk]):
            A = np.block([[np.zeros((n, n)), np.eye(n)], [-kv * Tn, -cv * Tn]])
            w = np.linalg.eigvals(A)
            assert abs(S.max_real_part()[a, b] - w.real.max()) <= 1e-7 * max(1, abs(w).max())
    with pytest.raises(AnalysisError, match="order 18 > 16"):
        stability_map(Ls, {cc: (-0.5, 1, 4), kk: (-0.5, 1, 4)}, client=False, method='polynomial')


def test_bad_numbers_of_the_computation():
    with pytest.raises(AnalysisError, match="chunk_size must be a positive integer, got 0"):
        stability_map(OSC_FIRST, GRID, fixed={m: 1}, client=False, chunk_size=0)
    with pytest.raises(AnalysisError, match="tol must be a non-negative number"):
        stability_map(OSC_FIRST, GRID, fixed={m: 1}, client=False, tol=-1)
    with pytest.raises(AnalysisError, match="no parameters: expected a dict"):
        stability_map(OSC_FIRST, [(c, 0, 1, 3)], fixed={m: 1}, client=False)
