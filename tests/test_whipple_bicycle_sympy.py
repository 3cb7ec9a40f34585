"""The nonlinear Whipple bicycle of examples/whipple_bicycle.yaml against an
independent model in sympy.physics.mechanics: the same bodies and
coordinates written with SymPy frames and points, the wheels' contact points
from their axles by vector algebra, Kane's generalized inertia forces from the
partial velocities; the accelerations with the holonomic front contact and the
four no-slip constraints are compared at random states that satisfy the
constraints (the package's compiled right-hand side, with its augmented
system).

Building the SymPy model takes about a minute: the cross-check is marked slow
(``make test-slow``; the linearized bicycle is checked against the benchmark
in test_whipple_bicycle.py).
"""
import random

import numpy as np
import pytest

pytestmark = pytest.mark.slow

#: Table 1 of Meijaard et al. (2007)
VALUES = dict(w=1.02, c=0.08, lam=0.1 * np.pi, g=9.81, rR=0.3, mR=2, IRxx=0.0603, IRyy=0.12,
              xB=0.3, zB=-0.9, mB=85, IBxx=9.2, IByy=11, IBzz=2.8, IBxz=2.4, xH=0.9, zH=-0.7,
              mH=4, IHxx=0.05892, IHyy=0.06, IHzz=0.00708, IHxz=-0.00756, rF=0.35, mF=3,
              IFxx=0.1405, IFyy=0.28)
COORDINATES = ['x', 'y', 'yaw', 'lean', 'pitch', 'steer', 'thetaR', 'thetaF']


def sympy_bicycle():
    r"""Functions of (q, u) for the SymPy model: the generalized mass matrix
    and forcing (u = q'), the height of the front contact point, its gradient,
    and the four no-slip velocities."""
    import sympy as sm
    import sympy.physics.mechanics as me
    q = me.dynamicsymbols(' '.join(COORDINATES))
    u = me.dynamicsymbols(' '.join('u' + n for n in COORDINATES))
    x, y, yaw, lean, pitch, steer, thR, thF = q
    p = {k: sm.Float(v) for k, v in VALUES.items()}
    N = me.ReferenceFrame('N')                      # z up
    A0 = N.orientnew('A0', 'Axis', [sm.pi, N.x])    # x forward, y right, z down
    Y = A0.orientnew('Y', 'Axis', [yaw, A0.z])
    Lf = Y.orientnew('Lf', 'Axis', [lean, Y.x])
    Rf = Lf.orientnew('Rf', 'Axis', [pitch, Lf.y])
    RW = Rf.orientnew('RW', 'Axis', [thR, Rf.y])
    F1 = Rf.orientnew('F1', 'Axis', [p['lam'], Rf.y])
    F2 = F1.orientnew('F2', 'Axis', [steer, F1.z])
    H = F2.orientnew('H', 'Axis', [-p['lam'], F2.y])
    FW = H.orientnew('FW', 'Axis', [thF, H.y])
    P0 = me.Point('P0')
    P0.set_vel(N, x.diff() * N.x + y.diff() * N.y)
    Rc = P0.locatenew('Rc', -p['rR'] * Lf.z)
    Rc.v2pt_theory(P0, N, Lf)
    Bc = Rc.locatenew('Bc', p['xB'] * Rf.x + (p['zB'] + p['rR']) * Rf.z)
    Bc.v2pt_theory(Rc, N, Rf)
    Fj = Rc.locatenew('Fj', (p['w'] + p['c']) * Rf.x + p['rR'] * Rf.z)
    Fj.v2pt_theory(Rc, N, Rf)
    Hc = Fj.locatenew('Hc', (p['xH'] - p['w'] - p['c']) * H.x + p['zH'] * H.z)
    Hc.v2pt_theory(Fj, N, H)
    Fc = Fj.locatenew('Fc', -p['c'] * H.x - p['rF'] * H.z)
    Fc.v2pt_theory(Fj, N, H)
    bodies = [(Rc, RW, p['mR'], me.inertia(RW, p['IRxx'], p['IRyy'], p['IRxx'])),
              (Bc, Rf, p['mB'], me.inertia(Rf, p['IBxx'], p['IByy'], p['IBzz'], 0, 0, p['IBxz'])),
              (Hc, H, p['mH'], me.inertia(H, p['IHxx'], p['IHyy'], p['IHzz'], 0, 0, p['IHxz'])),
              (Fc, FW, p['mF'], me.inertia(FW, p['IFxx'], p['IFyy'], p['IFxx']))]
    t = me.dynamicsymbols._t
    qd = {qi.diff(): ui for qi, ui in zip(q, u)}
    qdd = {qi.diff(t, 2): ui.diff() for qi, ui in zip(q, u)}
    ud = [ui.diff() for ui in u]
    parts = []
    for point, frame, m, inertia in bodies:
        v = me.msubs(point.vel(N).to_matrix(N), qd)
        w = me.msubs(frame.ang_vel_in(N).to_matrix(frame), qd)
        a = me.msubs(me.msubs(point.vel(N).dt(N).to_matrix(N), qdd), qd)
        al = me.msubs(me.msubs(frame.ang_vel_in(N).dt(frame).to_matrix(frame), qdd), qd)
        f = sm.lambdify(list(q) + list(u) + ud, [v.jacobian(u), w.jacobian(u), a, al],
                        'numpy', cse=True)
        parts.append((float(m), f, np.array(inertia.to_matrix(frame), dtype=float)))

    def contact(center, wheel, r):
        # the lowest point of the rim: along (a x z) x a from the centre
        a = wheel.y
        down = (a.cross(N.z)).cross(a)
        arm = -r * down / sm.sqrt(down.dot(down))
        return center.pos_from(P0) + arm, center.vel(N) + wheel.ang_vel_in(N).cross(arm)

    _, slip_R = contact(Rc, RW, p['rR'])
    position_F, slip_F = contact(Fc, FW, p['rF'])
    height = position_F.dot(N.z)
    slips = [me.msubs(e, qd) for e in (slip_R.dot(N.x), slip_R.dot(N.y),
                                        slip_F.dot(N.x), slip_F.dot(N.y))]
    height_f = sm.lambdify(list(q), height, 'numpy')
    gradient_f = sm.lambdify(list(q), [height.diff(qi) for qi in q], 'numpy')
    slips_f = sm.lambdify(list(q) + list(u), slips, 'numpy', cse=True)

    def mass_and_forcing(qv, uv):
        n = len(q)
        M, F = np.zeros((n, n)), np.zeros(n)
        for m, f, I in parts:
            Jv, Jw, a0, al0 = (np.array(z, dtype=float) for z in f(*qv, *uv, *np.zeros(n)))
            a0, al0 = a0.ravel(), al0.ravel()
            w = Jw @ uv
            M += m * Jv.T @ Jv + Jw.T @ I @ Jw
            F -= Jv.T @ (m * a0) + Jw.T @ (I @ al0 + np.cross(w, I @ w))
            F += Jv.T @ np.array([0, 0, -m * VALUES['g']])
        return M, F

    return mass_and_forcing, height_f, gradient_f, slips_f


def test_accelerations_at_random_states():
    from scipy.optimize import brentq
    from sage.all import SR, QQ, pi
    from sage_dynsym import load
    from sage_dynsym.description import example_path
    mass_and_forcing, height, gradient, slips = sympy_bicycle()
    S = load(example_path('whipple_bicycle.yaml'))
    from fractions import Fraction
    exact = {k: (pi / 10 if k == 'lam' else QQ(Fraction(str(v)))) for k, v in VALUES.items()}
    rhs = S.numerical_rhs({SR.var(k): x for k, x in exact.items()})

    def constraint_rows(qv):
        # the velocity-level constraints: the front contact height differentiated, no slip
        rows = [np.array(gradient(*qv), dtype=float)]
        for j in range(4):
            rows.append(np.array([slips(*qv, *np.eye(8)[k])[j] for k in range(8)], dtype=float))
        return np.array(rows)

    def phi(qv, uv):
        return np.concatenate([[np.dot(gradient(*qv), uv)], np.array(slips(*qv, *uv), float)])

    rng = random.Random(2007)
    for _ in range(3):
        qv = np.array([rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-3, 3),
                       rng.uniform(-0.4, 0.4), 0.0, rng.uniform(-0.6, 0.6),
                       rng.uniform(-3, 3), rng.uniform(-3, 3)])
        qv[4] = brentq(lambda pitch: height(*np.concatenate([qv[:4], [pitch], qv[5:]])), -0.5, 0.5)
        G = constraint_rows(qv)
        free, dependent = [3, 5, 6], [0, 1, 2, 4, 7]
        uv = np.zeros(8)
        uv[free] = [rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-10, 10)]
        uv[dependent] = np.linalg.solve(G[:, dependent], -G[:, free] @ uv[free])
        assert np.max(np.abs(phi(qv, uv))) < 1e-10
        # G ddq + gamma = 0 with gamma = d/dt(G) u (a central difference along u)
        h = 1e-6
        gamma = (phi(qv + h * uv, uv) - phi(qv - h * uv, uv)) / (2 * h)
        M, F = mass_and_forcing(qv, uv)
        K = np.block([[M, -G.T], [G, np.zeros((5, 5))]])
        theirs = np.linalg.solve(K, np.concatenate([F, -gamma]))[:8]
        ours = rhs(0, np.concatenate([qv, uv]))[8:]
        assert np.max(np.abs(ours - theirs)) < 1e-6 * max(1, np.max(np.abs(theirs))), (ours, theirs)
