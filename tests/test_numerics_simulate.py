"""
simulate() against independent integrations of textbook equations.

Each model's motion from sage_dynsym (equations derived by the package,
compiled right-hand side, DOP853) is compared with SciPy integrating the
textbook equations written by hand here; conservative systems keep their
energy to 1e-8 relative.
"""
import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from sage.all import SR, var, sqrt, exp

from sage_dynsym import Lagrangian, load
from sage_dynsym.analysis.motion import SecondOrderEquations, FirstOrderEquations
from sage_dynsym.description import example_path
from sage_dynsym.errors import ModelError
from sage_dynsym.lie.system import LiePoissonSystem
from sage_dynsym.numerics import simulate, Trajectory

TIGHT = dict(method='DOP853', rtol=1e-12, atol=1e-13)


def reference(f, y0, t_end, points):
    times = np.linspace(0, t_end, points)
    sol = solve_ivp(f, (0, t_end), y0, t_eval=times, **TIGHT)
    assert sol.success
    return sol.y.T


def spherical_pendulum(g_over_l):
    """The textbook equations of the spherical pendulum in (psi, theta,
    dpsi, dtheta), theta from the upward vertical (the mass centre at
    (0, 0, l) in the body axes)."""
    def f(t, y):
        p, th, dp, dth = y
        return [dp, dth, -2 * dp * dth * math.cos(th) / math.sin(th),
                dp ** 2 * math.sin(th) * math.cos(th) + g_over_l * math.sin(th)]
    return f


def test_spherical_pendulum():
    L = load(example_path('spherical_pendulum.yaml')).lagrangian()
    m, l, g = 1.5, 0.8, 9.81
    psi, theta, dpsi, dtheta = var('psi theta dpsi dtheta')
    initial = {psi: 0.3, theta: 2.5, dpsi: 1.2, dtheta: -0.4}
    T = L.simulate({'m': m, 'l': l, 'g': g}, initial, 5, points=51)
    expected = reference(spherical_pendulum(g / l), [0.3, 2.5, 1.2, -0.4], 5, 51)
    for k, v in enumerate([psi, theta, dpsi, dtheta]):
        assert np.allclose(T.values(v), expected[:, k], rtol=0, atol=1e-8)
    if T.energy() is None:
        T = Trajectory(T.times(), T.states(), T.variables(), T.parameters(), energy=L.energy())
    assert T.energy_drift() < 1e-8
    assert len(T.times()) == 51 and T.times()[0] == 0 and T.times()[-1] == 5


def test_spherical_pendulum_hamiltonian():
    H = load(example_path('spherical_pendulum.yaml')).lagrangian().hamiltonian()
    m, l, g = 1.5, 0.8, 9.81
    theta = 2.5
    # p_psi = m l^2 sin^2(theta) dpsi, p_theta = m l^2 dtheta
    initial = {'psi': 0.3, 'theta': theta, 'p_psi': m * l ** 2 * math.sin(theta) ** 2 * 1.2,
               'p_theta': m * l ** 2 * -0.4}
    T = H.simulate({'m': m, 'l': l, 'g': g}, initial, 5, points=11)
    expected = reference(spherical_pendulum(g / l), [0.3, 2.5, 1.2, -0.4], 5, 11)
    assert np.allclose(T.values('theta'), expected[:, 1], rtol=0, atol=1e-8)
    assert np.allclose(T.values('psi'), expected[:, 0], rtol=0, atol=1e-8)
    assert T.energy_drift() < 1e-8


def test_double_pendulum():
    t1, t2, d1, d2 = var('theta1 theta2 dtheta1 dtheta2')
    m1, m2, l1, l2, g = var('m1 m2 l1 l2 g')
    from sage.all import cos
    L = Lagrangian((m1 + m2) / 2 * l1 ** 2 * d1 ** 2 + m2 / 2 * l2 ** 2 * d2 ** 2
                   + m2 * l1 * l2 * d1 * d2 * cos(t1 - t2)
                   + (m1 + m2) * g * l1 * cos(t1) + m2 * g * l2 * cos(t2), [t1, t2])
    values = {m1: 1.0, m2: 2.0, l1: 1.0, l2: 1.5, g: 9.81}
    initial = {t1: 1.0, t2: -0.5, d1: 0.0, d2: 0.3}
    T = L.simulate(values, initial, 10, points=101)
    M1, M2, L1, L2, G = 1.0, 2.0, 1.0, 1.5, 9.81

    def textbook(t, y):     # angles from the downward vertical
        a, b, da, db = y
        den = 2 * M1 + M2 - M2 * math.cos(2 * a - 2 * b)
        dda = (-G * (2 * M1 + M2) * math.sin(a) - M2 * G * math.sin(a - 2 * b)
               - 2 * math.sin(a - b) * M2 * (db ** 2 * L2 + da ** 2 * L1 * math.cos(a - b))
               ) / (L1 * den)
        ddb = (2 * math.sin(a - b) * (da ** 2 * L1 * (M1 + M2) + G * (M1 + M2) * math.cos(a)
                                      + db ** 2 * L2 * M2 * math.cos(a - b))) / (L2 * den)
        return [da, db, dda, ddb]
    expected = reference(textbook, [1.0, -0.5, 0.0, 0.3], 10, 101)
    for k, v in enumerate([t1, t2, d1, d2]):
        assert np.allclose(T.values(v), expected[:, k], rtol=0, atol=1e-6)
    if T.energy() is None:
        T = Trajectory(T.times(), T.states(), T.variables(), T.parameters(), energy=L.energy())
    assert T.energy_drift() < 1e-8


def test_free_rigid_body_lie_poisson():
    M1, M2, M3, A1, A2, A3 = var('M1 M2 M3 A1 A2 A3')
    S = LiePoissonSystem('so3', (M1 ** 2 / A1 + M2 ** 2 / A2 + M3 ** 2 / A3) / 2)
    I1, I2, I3 = 1.0, 2.0, 3.5
    T = S.simulate({A1: I1, A2: I2, A3: I3}, {M1: 0.2, M2: 1.0, M3: 0.3}, 20, points=201)

    def euler(t, M):        # dM/dt = M x omega, omega_i = M_i / I_i
        w = [M[0] / I1, M[1] / I2, M[2] / I3]
        return [M[1] * w[2] - M[2] * w[1], M[2] * w[0] - M[0] * w[2],
                M[0] * w[1] - M[1] * w[0]]
    expected = reference(euler, [0.2, 1.0, 0.3], 20, 201)
    for k, v in enumerate([M1, M2, M3]):
        assert np.allclose(T.values(v), expected[:, k], rtol=0, atol=1e-8)
    assert T.energy_drift() < 1e-8
    casimir = T.values(M1 ** 2 + M2 ** 2 + M3 ** 2)
    assert max(abs(c - casimir[0]) for c in casimir) < 1e-9


def test_rlc_with_lhs_matrix_and_stiff_method():
    # L di/dt = -u - R i, C du/dt = i: underdamped, exact solution by hand
    i, u, Lc, C, R = var('i u L C R')
    E = FirstOrderEquations([-u - R * i, i], [i, u], lhs_matrix=[Lc, C])
    Lv, Cv, Rv = 0.5, 0.02, 1.0
    alpha, w = Rv / (2 * Lv), math.sqrt(1 / (Lv * Cv) - (Rv / (2 * Lv)) ** 2)
    for method in ('auto', 'stiff', 'LSODA'):
        T = simulate(E, {Lc: Lv, C: Cv, R: Rv}, {i: 0, u: 1}, 2, points=21, method=method)
        # u(0) = 1, du/dt(0) = i(0)/C = 0
        exact = [math.exp(-alpha * s) * (math.cos(w * s) + alpha / w * math.sin(w * s))
                 for s in T.times()]
        tolerance = 1e-8 if method == 'auto' else 1e-5
        assert np.allclose(T.values(u), exact, rtol=0, atol=tolerance)
    with pytest.raises(ModelError, match='energy integral'):
        T.energy_drift()


def cartesian_pendulum():
    x, y, dx, dy, ddx, ddy, mu, m, g, l = var('x y dx dy ddx ddy mu m g l')
    f = x ** 2 + y ** 2 - l ** 2
    # E_i = m ddq_i + dV/dq_i - mu df/dq_i, V = m g y
    E = [m * ddx - mu * f.diff(x), m * ddy + m * g - mu * f.diff(y)]
    record = SecondOrderEquations(E, [x, y], [dx, dy], [ddx, ddy], constraints=[f],
                                  multipliers=[mu])
    return record, (x, y, dx, dy, m, g, l)


def test_cartesian_pendulum_keeps_its_constraint():
    record, (x, y, dx, dy, m, g, l) = cartesian_pendulum()
    G, Lv, th0 = 9.81, 1.3, 2.0
    initial = {x: Lv * math.sin(th0), y: -Lv * math.cos(th0), dx: 0, dy: 0}
    T = simulate(record, {m: 2.0, g: G, l: Lv}, initial, 10, points=201,
                 energy=m * (dx ** 2 + dy ** 2) / 2 + m * g * y)
    residual = T.values(x ** 2 + y ** 2 - l ** 2)
    assert max(abs(r) for r in residual) < 1e-12
    velocity_residual = T.values(x * dx + y * dy)
    assert max(abs(r) for r in velocity_residual) < 1e-10
    assert T.energy_drift() < 1e-8
    # the textbook pendulum theta'' = -g/l sin(theta), x = l sin(theta), y = -l cos(theta)
    expected = reference(lambda t, s: [s[1], -G / Lv * math.sin(s[0])], [th0, 0.0], 10, 201)
    assert np.allclose(T.values(x), Lv * np.sin(expected[:, 0]), rtol=0, atol=1e-7)
    assert np.allclose(T.values(y), -Lv * np.cos(expected[:, 0]), rtol=0, atol=1e-7)


def test_inconsistent_initial_state_is_projected():
    record, (x, y, dx, dy, m, g, l) = cartesian_pendulum()
    state = {x: 1.1, y: 0.1, dx: 0.2, dy: 0.5}
    # an initial state off the constraints is refused unless the projection is asked for
    with pytest.raises(ModelError, match='off the constraints'):
        simulate(record, {m: 1, g: 1, l: 1}, state, 1, points=3)
    with pytest.warns(UserWarning, match='projected onto the constraints'):
        T = simulate(record, {m: 1, g: 1, l: 1}, state, 1, points=3, project=True)
    assert abs(T.values(x ** 2 + y ** 2)[0] - 1) < 1e-12
    assert abs(T.values(x * dx + y * dy)[0]) < 1e-12


def test_errors_name_what_is_missing():
    x, dx, ddx, k, c = var('x dx ddx k c')
    E = SecondOrderEquations([ddx + k * x + c * dx], [x], [dx], [ddx])
    with pytest.raises(ModelError, match='missing values of the parameters c, k'):
        simulate(E, {}, {x: 1, dx: 0}, 1)
    with pytest.raises(ModelError, match='missing initial values of dx'):
        simulate(E, {k: 1, c: 0}, {x: 1}, 1)
    with pytest.raises(ModelError, match='z is not a state variable'):
        simulate(E, {k: 1, c: 0}, {x: 1, dx: 0, 'z': 0}, 1)
    with pytest.raises(ModelError, match='real number'):
        simulate(E, {k: 1, c: 0}, {x: SR.var('a'), dx: 0}, 1)
    # Sage numbers and names are accepted
    T = simulate(E, {'k': sqrt(2), c: 0}, {'x': exp(0), dx: 1 / SR(2)}, 1, points=2, t0=SR(1) / 2)
    assert list(T.times()) == [0.5, 1.0]


def test_interrupt_propagates():
    from sage_dynsym.numerics import numerical_rhs
    from sage_dynsym.numerics.rhs import RightHandSide
    x, dx, ddx = var('x dx ddx')
    f = numerical_rhs(SecondOrderEquations([ddx + x], [x], [dx], [ddx]), {})
    calls = []

    class Interrupted(RightHandSide):
        def __init__(self):
            self.__dict__.update(f.__dict__)

        def __call__(self, t, y):
            calls.append(t)
            if len(calls) > 50:
                raise KeyboardInterrupt
            return f(t, y)
    with pytest.raises(KeyboardInterrupt):
        simulate(Interrupted(), {}, {x: 1, dx: 0}, 100)


def test_rlc_ladder_circuit_against_hand_written_kirchhoff():
    """The ladder of examples/rlc_ladder.yaml driven from rest; by hand: node
    potentials v3, v5, v7 of the capacitors' top nodes and the inductor
    currents (left to right). The package's variables may be oriented the
    other way: each must agree up to its sign."""
    C = load(example_path('rlc_ladder.yaml'))
    record = C.to_linearizer()
    p = dict(E1=1.0, R1=0.5, R2=0.3, R3=0.2, R4=2.0, L1=0.4, L2=0.3, L3=0.5,
             C1=0.2, C2=0.3, C3=0.25)
    names = [str(v) for v in record.variables()]
    element = {str(v): str(record.lhs_matrix()[k, k]) for k, v in enumerate(names)}
    T = simulate(record, p, {v: 0 for v in names}, 6, points=61)

    def kirchhoff(t, y):
        i1, i2, i3, v3, v5, v7 = y
        return [(p['E1'] - p['R1'] * i1 - v3) / p['L1'], (v3 - p['R2'] * i2 - v5) / p['L2'],
                (v5 - p['R3'] * i3 - v7) / p['L3'], (i1 - i2) / p['C1'], (i2 - i3) / p['C2'],
                (i3 - v7 / p['R4']) / p['C3']]
    expected = reference(kirchhoff, [0.0] * 6, 6, 61)
    column = dict(L1=0, L2=1, L3=2, C1=3, C2=4, C3=5)
    for v in names:
        want = expected[:, column[element[v]]]
        got = np.array(T.values(v))
        assert max(abs(want).max(), 1e-3) > 1e-3
        assert (np.allclose(got, want, rtol=0, atol=1e-8)
                or np.allclose(got, -want, rtol=0, atol=1e-8)), v


def test_lossless_lc_circuit_keeps_its_energy():
    """Two LC meshes sharing C2 (built with Circuit): the magnetic plus electric
    energy is conserved; a single mesh oscillates at 1/sqrt(LC) by hand."""
    from sage_dynsym.circuits import Circuit
    from sage_dynsym.numerics.energy import quadratic_energy
    record = Circuit([[0, 1, 'L1'], [1, 2, 'C1'], [2, 0, 'L2'], [2, 0, 'C2']]).to_linearizer()
    energy = quadratic_energy(record)
    assert energy is not None
    values = dict(L1=0.5, L2=0.2, C1=0.3, C2=0.1)
    names = [str(v) for v in record.variables()]
    initial = {v: 0.0 for v in names}
    initial[names[-1]] = 1.0
    T = simulate(record, values, initial, 20, points=201, energy=energy)
    assert T.energy_drift() < 1e-8

    single = Circuit([[0, 1, 'L1'], [1, 0, 'C1']]).to_linearizer()
    names = [str(v) for v in single.variables()]
    element = {str(v): str(single.lhs_matrix()[k, k]) for k, v in enumerate(names)}
    u = next(v for v in names if element[v] == 'C1')
    T = simulate(single, {'L1': 0.5, 'C1': 0.2}, {v: (1.0 if v == u else 0.0) for v in names},
                 5, points=51)
    assert np.allclose(T.values(u), np.cos(T.times() / math.sqrt(0.5 * 0.2)), rtol=0, atol=1e-8)


def test_explicit_time_forced_oscillator():
    # x'' + x = cos(2 t) from rest: x = (cos t - cos 2t)/3 by hand
    from sage.all import cos
    from sage_dynsym.symbols import t
    x, dx, ddx = var('x dx ddx')
    E = SecondOrderEquations([ddx + x - cos(2 * t)], [x], [dx], [ddx])
    for backend in ('python', 'c'):
        T = simulate(E, {}, {x: 0, dx: 0}, 6, points=31, backend=backend)
        want = (np.cos(T.times()) - np.cos(2 * T.times())) / 3
        assert np.allclose(T.values(x), want, rtol=0, atol=1e-9)


def test_rheonomic_constraint_bead_on_rotating_rod():
    """A bead on a rod turning at the rate w in a plane without gravity:
    r'' = w^2 r, so r = r0 cosh(w t) from rest on the rod (by hand). The
    constraint -x sin(wt) + y cos(wt) = 0 depends on time (its J_t and f_tt
    enter gamma, f_t the velocity projection)."""
    from sage.all import sin, cos
    from sage_dynsym.symbols import t
    x, y, dx, dy, ddx, ddy, mu, w = var('x y dx dy ddx ddy mu w')
    f = -x * sin(w * t) + y * cos(w * t)
    E = [ddx - mu * f.diff(x), ddy - mu * f.diff(y)]
    record = SecondOrderEquations(E, [x, y], [dx, dy], [ddx, ddy], constraints=[f],
                                  multipliers=[mu])
    W, r0 = 0.7, 0.5
    # at t = 0 the rod is the x axis; the bead turns with it: dy = w r0
    T = simulate(record, {w: W}, {x: r0, y: 0, dx: 0, dy: W * r0}, 3, points=31)
    r = np.hypot(T.values(x), T.values(y))
    assert np.allclose(r, r0 * np.cosh(W * T.times()), rtol=1e-9, atol=0)
    angle = np.unwrap(np.arctan2(T.values(y), T.values(x)))
    assert np.allclose(angle, W * T.times(), rtol=0, atol=1e-10)


def test_constrained_lagrangian_end_to_end():
    """Lagrangian(..., constraints=...) -> record -> simulate: the Cartesian
    pendulum follows the textbook theta'' = -g/l sin(theta)."""
    x, y, dx, dy, m, g, l = var('x y dx dy m g l')
    L = Lagrangian(m * (dx ** 2 + dy ** 2) / 2 - m * g * y, [x, y],
                   constraints=[x ** 2 + y ** 2 - l ** 2])
    G, Lv, th0 = 9.81, 0.9, 1.0
    initial = {x: Lv * math.sin(th0), y: -Lv * math.cos(th0), dx: 0, dy: 0}
    T = L.simulate({m: 1.5, g: G, l: Lv}, initial, 5, points=51)
    expected = reference(lambda t, s: [s[1], -G / Lv * math.sin(s[0])], [th0, 0.0], 5, 51)
    assert np.allclose(T.values(x), Lv * np.sin(expected[:, 0]), rtol=0, atol=1e-8)
    assert max(abs(r) for r in T.values(x ** 2 + y ** 2 - l ** 2)) < 1e-12
