"""
Modelling breadth of mechanical systems: several force-function terms,
loads on bodies, holonomic constraints, parameter values.

Every model is built twice: with sage_dynsym, and independently in this file
with ``sympy.physics.mechanics`` (``LagrangesMethod``, loads as
``(point, force)`` / ``(frame, torque)`` pairs of its ``forcelist``,
constraints as ``hol_coneqs``). Equations, accelerations and constraint
forces are compared numerically at random states (fixed seeds). The
textbook forms are written out too:

- the pendulum on a cart held by a spring and a damper (Meirovitch,
  *Methods of Analytical Dynamics*, the cart-pendulum of the Lagrange
  equations chapter; Ginsberg, *Advanced Engineering Dynamics*):
  `(M+m)\\ddot y + m l(\\ddot\\theta\\cos\\theta - \\dot\\theta^2\\sin\\theta)
  + c\\dot y + k y = 0`, `m l^2\\ddot\\theta + m l \\ddot y\\cos\\theta
  + m g l\\sin\\theta = 0`;
- the rod pendulum driven by a horizontal force `F` at its tip:
  `\\tfrac13 m l^2\\ddot\\theta + \\tfrac12 m g l\\sin\\theta = F l\\cos\\theta`;
- the simple (and spherical) pendulum in Cartesian coordinates: rod tension
  `T = m(|v|^2/l + g\\cdot r/l)`, i.e. `m(l\\dot\\theta^2 + g\\cos\\theta)` in
  the plane (any mechanics text, e.g. Goldstein, *Classical Mechanics*,
  ch. 1-2);
- the double pendulum (Goldstein, ch. 1; Marion & Thornton) in angles, and
  the rod tensions from Newton's law for each mass.

SymPy's equations are `d/dt dL/d(dq) - dL/dq - Q` (``forcelist``), the same
sign as sage_dynsym's `E_i = d/dt dL/d(dq_i) - dL/dq_i + dR/d(dq_i) - Q_i`.
"""
import random

import pytest
import sympy
from sympy.physics import mechanics as me

from sage.all import SR, QQ, RDF, matrix, vector, diagonal_matrix
from sage_dynsym import MechanicalSystem, RigidBody, UniformGravity, load, save
from sage_dynsym.description import example_path
from sage_dynsym.mechanics.loads import Load
from sage_dynsym.symbols import velocity, acceleration

T = me.dynamicsymbols._t
TOL = 1e-9


def sage_at(expr, values):
    return complex(SR(expr).subs(values)).real


def sympy_values(coordinates, state):
    """SymPy substitutions for q, dq, ddq (derivatives first)."""
    out = {}
    for q, (x, v, a) in zip(coordinates, state):
        out[q.diff(T, 2)] = a
        out[q.diff(T)] = v
        out[q] = x
    return out


def sage_values(coordinates, state):
    out = {}
    for q, (x, v, a) in zip(coordinates, state):
        out[q], out[velocity(q)], out[acceleration(q)] = x, v, a
    return out


def close(a, b, scale=1.0):
    return abs(a - b) <= TOL * max(1.0, abs(a), abs(b), scale)


# ---------------------------------------------------------------------------
# (a) pendulum on a cart with a spring and a damper: gravity + spring in one
# file (the bundled example cart_pendulum_spring_damper.yaml)
# ---------------------------------------------------------------------------

def sympy_cart(values):
    y, th = me.dynamicsymbols('y theta')
    M, m, l, g, k, c = sympy.symbols('M m l g k c')
    N = me.ReferenceFrame('N')
    O = me.Point('O')
    O.set_vel(N, 0)
    cart = O.locatenew('C', y * N.y)
    cart.set_vel(N, y.diff(T) * N.y)
    bob = cart.locatenew('B', l * sympy.sin(th) * N.y - l * sympy.cos(th) * N.z)
    bob.set_vel(N, bob.pos_from(O).dt(N))
    pc, pb = me.Particle('pc', cart, M), me.Particle('pb', bob, m)
    pc.potential_energy = k * y ** 2 / 2
    pb.potential_energy = m * g * bob.pos_from(O).dot(N.z)
    L = me.Lagrangian(N, pc, pb)
    LM = me.LagrangesMethod(L, [y, th], forcelist=[(cart, -c * y.diff(T) * N.y)], frame=N)
    eom = LM.form_lagranges_equations()
    params = dict(zip((M, m, l, g, k, c), values))
    return [y, th], [e.subs(params) for e in eom]


def test_cart_pendulum_spring_damper(tmp_path):
    S = load(example_path('cart_pendulum_spring_damper.yaml'))
    # the two force-function terms add up
    y, th, M, m, l, g, k, c = [SR.var(n) for n in 'y theta M m l g k c'.split()]
    assert bool(S.force_function() == m * g * l * SR(th).cos() - k * y ** 2 / 2)
    E = S.equations()
    dy, dth, ddy, ddth = velocity(y), velocity(th), acceleration(y), acceleration(th)
    textbook = [(M + m) * ddy + m * l * (ddth * th.cos() - dth ** 2 * th.sin()) + c * dy + k * y,
                m * l ** 2 * ddth + m * l * ddy * th.cos() + m * g * l * th.sin()]
    rng = random.Random(1301)
    params = [rng.uniform(0.5, 2.0) for _ in range(6)]
    coords, eom = sympy_cart(params)
    pvals = dict(zip((M, m, l, g, k, c), params))
    for _ in range(5):
        state = [(rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-2, 2)) for _ in range(2)]
        sv = {**sage_values([y, th], state), **pvals}
        yv = sympy_values(coords, state)
        for i in range(2):
            mine = sage_at(E[i], sv)
            assert close(mine, float(eom[i].subs(yv)))
            assert close(mine, sage_at(textbook[i], sv))
    # round trip through save / load keeps the list of terms
    out = tmp_path / "saved.yaml"
    save(S, str(out))
    S2 = load(str(out))
    assert S2.to_dict()['force_function'] == S.to_dict()['force_function']
    assert len(S2.force_terms()) == 2
    assert S2.lagrangian() == S.lagrangian()


def test_cart_pendulum_example_file():
    import os
    path = os.path.join(os.path.dirname(__file__), "..", "examples",
                        "cart_pendulum_spring_damper.yaml")
    if not os.path.exists(path):
        pytest.skip("example file not bundled")
    S = load(path)
    assert len(S.force_terms()) == 2 and not S.dissipation().is_zero()


# ---------------------------------------------------------------------------
# (b) rod pendulum driven by a horizontal force at its tip
# ---------------------------------------------------------------------------

def test_rod_pendulum_tip_force():
    th, m, l, g, F0, w, t = [SR.var(n) for n in 'theta m l g F0 w t'.split()]
    rod = RigidBody('rod', rotations=[(1, th)], mass_center=[0, 0, -l / 2], mass=m,
                    inertia=diagonal_matrix([m * l ** 2 / 3, m * l ** 2 / 3, 0]))
    push = Load('rod', point=[0, 0, -l], force=[0, F0 * (w * t).cos(), 0], axes=0)
    S = MechanicalSystem([rod], [th], parameters=[m, l, g, F0, w],
                         force_function=UniformGravity([0, 0, -g]), loads=[push])
    F = F0 * (w * t).cos()
    assert bool(S.generalized_forces()[0] == F * l * th.cos())
    E = S.equations()[0]
    textbook = m * l ** 2 / 3 * acceleration(th) + m * g * l / 2 * th.sin() - F * l * th.cos()

    # SymPy: the uniform rod, the force applied at the tip point
    q = me.dynamicsymbols('theta')
    ms, ls, gs, F0s, ws = sympy.symbols('m l g F0 w')
    N = me.ReferenceFrame('N')
    A = N.orientnew('A', 'Axis', [q, N.x])
    O = me.Point('O')
    O.set_vel(N, 0)
    C = O.locatenew('C', -ls / 2 * A.z)
    C.v2pt_theory(O, N, A)
    P = O.locatenew('P', -ls * A.z)
    P.v2pt_theory(O, N, A)
    body = me.RigidBody('rod', C, A, ms, (me.inertia(A, ms * ls ** 2 / 12, ms * ls ** 2 / 12, 0), C))
    body.potential_energy = ms * gs * C.pos_from(O).dot(N.z)
    LM = me.LagrangesMethod(me.Lagrangian(N, body), [q],
                            forcelist=[(P, F0s * sympy.cos(ws * T) * N.y)], frame=N)
    eom = LM.form_lagranges_equations()[0]
    rng = random.Random(1302)
    for _ in range(6):
        p = [rng.uniform(0.5, 2.0) for _ in range(5)]
        tv = rng.uniform(0, 3)
        state = [(rng.uniform(-3, 3), rng.uniform(-2, 2), rng.uniform(-2, 2))]
        sv = {**sage_values([th], state), **dict(zip((m, l, g, F0, w), p)), t: tv}
        yv = sympy_values([q], state)
        yv.update(dict(zip((ms, ls, gs, F0s, ws), p)))
        mine = sage_at(E, sv)
        assert close(mine, float(eom.subs(yv).subs(T, tv)))
        assert close(mine, sage_at(textbook, sv))


# ---------------------------------------------------------------------------
# (c) loads in body axes, torques, loads between two bodies
# ---------------------------------------------------------------------------

def test_body_axes_loads_and_torques_vs_sympy():
    """A body turned by (3, psi), (1, theta) carrying a second body turned by
    (2, phi): a follower force in the axes of body 2 at a point of it, a dead
    force in the inertial axes, a torque in the axes of body 1 on body 2 and
    a torque in body 2's axes."""
    psi, th, phi, a, b, h, m = [SR.var(n) for n in 'psi theta phi a b h m'.split()]
    F1, F2, F3, G1, G2, G3, M1, M2, M3, N1, N2, N3 = [SR.var(n) for n in
                                                      'F1 F2 F3 G1 G2 G3 M1 M2 M3 N1 N2 N3'.split()]
    b1 = RigidBody('carrier', rotations=[(3, psi), (1, th)], mass_center=[0, 0, h], mass=m,
                   inertia=diagonal_matrix([2 * m * h ** 2, 2 * m * h ** 2, m * h ** 2]))
    b2 = RigidBody('arm', parent='carrier', joint=[0, 0, h], rotations=[(2, phi)],
                   mass_center=[a, 0, 0], mass=m,
                   inertia=diagonal_matrix([m * a ** 2, 2 * m * a ** 2, 2 * m * a ** 2]))
    loads = [Load('arm', point=[a, b, 0], force=[F1, F2, F3], axes='arm'),
             {'body': 'arm', 'point': [0, b, h], 'force': [G1, G2, G3], 'axes': 0},
             Load('arm', torque=[M1, M2, M3], axes='carrier'),
             Load(2, torque=[N1, N2, N3], axes=2)]
    S = MechanicalSystem([b1, b2], [psi, th, phi], loads=loads)
    Q = S.generalized_forces()

    # SymPy: generalized active forces from the same loads (Kane's partial
    # velocities), compared with sage_dynsym's virtual power
    qs = me.dynamicsymbols('psi theta phi')
    sym = dict(zip('a b h F1 F2 F3 G1 G2 G3 M1 M2 M3 N1 N2 N3'.split(),
                   sympy.symbols('a b h F1 F2 F3 G1 G2 G3 M1 M2 M3 N1 N2 N3')))
    N = me.ReferenceFrame('N')
    A1 = N.orientnew('A1', 'Axis', [qs[0], N.z])
    B1 = A1.orientnew('B1', 'Axis', [qs[1], A1.x])
    B2 = B1.orientnew('B2', 'Axis', [qs[2], B1.y])
    O = me.Point('O')
    O.set_vel(N, 0)
    O2 = O.locatenew('O2', sym['h'] * B1.z)
    O2.v2pt_theory(O, N, B1)
    P = O2.locatenew('P', sym['a'] * B2.x + sym['b'] * B2.y)
    P.v2pt_theory(O2, N, B2)
    R = O2.locatenew('R', sym['b'] * B2.y + sym['h'] * B2.z)
    R.v2pt_theory(O2, N, B2)
    forces = [(P, sym['F1'] * B2.x + sym['F2'] * B2.y + sym['F3'] * B2.z),
              (R, sym['G1'] * N.x + sym['G2'] * N.y + sym['G3'] * N.z),
              (B2, sym['M1'] * B1.x + sym['M2'] * B1.y + sym['M3'] * B1.z),
              (B2, sym['N1'] * B2.x + sym['N2'] * B2.y + sym['N3'] * B2.z)]
    qd = [q.diff(T) for q in qs]
    reference = []
    for u in qd:
        total = 0
        for where, vec in forces:
            if isinstance(where, me.Point):
                partial = where.vel(N).diff(u, N)
            else:
                partial = where.ang_vel_in(N).diff(u, N)
            total += vec.dot(partial)
        reference.append(total)
    rng = random.Random(1303)
    for _ in range(4):
        xs = [rng.uniform(-3, 3) for _ in range(3)]
        pv = {n: rng.uniform(-2, 2) for n in sym}
        sv = {SR.var(n): v for n, v in pv.items()}
        sv.update(dict(zip([psi, th, phi], xs)))
        yv = {sym[n]: v for n, v in pv.items()}
        yv.update(dict(zip(qs, xs)))
        for i in range(3):
            assert close(sage_at(Q[i], sv), float(sympy.sympify(reference[i]).subs(yv)))


def test_follower_force_and_torque_textbook():
    """A follower force perpendicular to a rod at its tip has the moment F l at
    every angle; a torque M about the pivot axis is the generalized force M."""
    th, l, F, M = [SR.var(n) for n in 'theta l F M'.split()]
    rod = RigidBody('rod', rotations=[(1, th)], mass_center=[0, 0, -l / 2], mass=1)
    S = MechanicalSystem([rod], [th], loads=[Load('rod', point=[0, 0, -l], force=[0, F, 0],
                                                   axes='rod'),
                                              Load('rod', torque=[M, 0, 0], axes=0)])
    assert bool(S.generalized_forces()[0] == F * l + M)


def test_interaction_force_is_two_opposite_loads():
    """A spring between two bodies given as two opposite loads gives the same
    equations as its potential -k |r_b - r_a - d|^2 / 2 in the force function."""
    xa, xb, za, zb, k, d, m = [SR.var(n) for n in 'xa xb za zb k d m'.split()]
    bodies = [RigidBody('a', joint=[xa, 0, za], mass=m), RigidBody('b', joint=[xb, 0, zb], mass=m)]
    stretch = [xb - xa - d, 0, zb - za]
    on_b = Load('b', force=[-k * c for c in stretch])
    on_a = Load('a', force=[k * c for c in stretch])
    S1 = MechanicalSystem(bodies, [xa, za, xb, zb], loads=[on_b, on_a])
    S2 = MechanicalSystem(bodies, [xa, za, xb, zb],
                          force_function=-k * sum(c ** 2 for c in stretch) / 2)
    for e1, e2 in zip(S1.equations(), S2.equations()):
        assert bool((e1 - e2).expand() == 0)


# ---------------------------------------------------------------------------
# (d) constraints: Cartesian models with multipliers vs reduced models
# ---------------------------------------------------------------------------

def _solve_numeric(L, values):
    sol = L.accelerations_and_multipliers()
    return {key: sage_at(value, values) for key, value in sol.items()}


def _sympy_constrained(coords, L_sym, coneqs, values, state):
    """Accelerations and multipliers of SymPy's LagrangesMethod, solved
    numerically: mass_matrix_full * [qd, qdd, lam] = forcing_full."""
    LM = me.LagrangesMethod(L_sym, coords, hol_coneqs=coneqs)
    LM.form_lagranges_equations()
    sub = {}
    for q, (x, v) in zip(coords, state):
        sub[q.diff(T)] = v
        sub[q] = x
    Mf = LM.mass_matrix_full.subs(values).subs(sub)
    Ff = LM.forcing_full.subs(values).subs(sub)
    x = sympy.Matrix(Mf).evalf().LUsolve(sympy.Matrix(Ff).evalf())
    n = len(coords)
    return [float(v) for v in x[n:2 * n]], [float(v) for v in x[2 * n:]]


def test_particle_on_sphere():
    x, y, z, m, g, l = [SR.var(n) for n in 'x y z m g l'.split()]
    S = MechanicalSystem([RigidBody('bob', joint=[x, y, z], mass=m)], [x, y, z],
                         parameters=[m, g, l], force_function=UniformGravity([0, 0, -g]),
                         constraints=[x ** 2 + y ** 2 + z ** 2 == l ** 2])
    L = S.lagrangian()
    assert L.constraints() == [x ** 2 + y ** 2 + z ** 2 - l ** 2]
    mu, = L.multipliers()
    # the reduced model: the spherical pendulum in angles (Example 1)
    psi, th = SR.var('psi theta')
    bob = RigidBody('bob', rotations=[(3, psi), (1, th)], mass_center=[0, 0, l], mass=m,
                    inertia=diagonal_matrix([m * l ** 2, m * l ** 2, 0]))
    reduced = MechanicalSystem([bob], [psi, th], force_function=UniformGravity([0, 0, -g]))
    Lr = reduced.lagrangian()
    angles = Lr.accelerations_solved()
    r = vector([l * psi.sin() * th.sin(), -l * psi.cos() * th.sin(), l * th.cos()])
    rates = [velocity(psi), velocity(th)]
    v = vector([sum(c.diff(q) * dq for q, dq in zip([psi, th], rates)) for c in r])
    a = vector([sum(c.diff(dq) * acc for dq, acc in zip(rates, angles))
                + sum(c.diff(q) * dq for q, dq in zip([psi, th], rates)) for c in v])
    # SymPy with the constraint
    qs = me.dynamicsymbols('x y z')
    ms, gs, ls = sympy.symbols('m g l')
    Ns = me.ReferenceFrame('N')
    O = me.Point('O')
    O.set_vel(Ns, 0)
    P = O.locatenew('P', qs[0] * Ns.x + qs[1] * Ns.y + qs[2] * Ns.z)
    P.set_vel(Ns, P.pos_from(O).dt(Ns))
    particle = me.Particle('p', P, ms)
    particle.potential_energy = ms * gs * qs[2]
    L_sym = me.Lagrangian(Ns, particle)
    con = [qs[0] ** 2 + qs[1] ** 2 + qs[2] ** 2 - ls ** 2]
    rng = random.Random(1304)
    signs = set()
    for _ in range(4):
        pm, pg, pl = [rng.uniform(0.5, 2.0) for _ in range(3)]
        angle_state = {psi: rng.uniform(-3, 3), th: rng.uniform(0.3, 2.8),
                       rates[0]: rng.uniform(-2, 2), rates[1]: rng.uniform(-2, 2),
                       m: pm, g: pg, l: pl}
        pos = [sage_at(c, angle_state) for c in r]
        vel = [sage_at(c, angle_state) for c in v]
        acc = [sage_at(c, angle_state) for c in a]
        values = {m: pm, g: pg, l: pl}
        for q, p0, v0 in zip([x, y, z], pos, vel):
            values[q], values[velocity(q)] = p0, v0
        sol = _solve_numeric(L, values)
        for q, expected in zip([x, y, z], acc):
            assert close(sol[acceleration(q)], expected)
        # the tension T = m (|v|^2 / l + g . r / l) (g = (0, 0, -g))
        speed2 = sum(c ** 2 for c in vel)
        tension = pm * (speed2 / pl - pg * pos[2] / pl)
        # constraint force J^T mu = 2 mu r = -T r / l
        assert close(-2 * sol[mu] * pl, tension)
        acc_sym, lam = _sympy_constrained(qs, L_sym, con, {ms: pm, gs: pg, ls: pl},
                                          list(zip(pos, vel)))
        for mine, theirs in zip([sol[acceleration(q)] for q in (x, y, z)], acc_sym):
            assert close(mine, theirs)
        assert close(abs(lam[0]), abs(sol[mu]))
        signs.add((lam[0] > 0) == (sol[mu] > 0))
    assert len(signs) == 1   # one sign convention throughout


def test_simple_pendulum_tension_textbook():
    x, z, m, g, l = [SR.var(n) for n in 'x z m g l'.split()]
    S = MechanicalSystem([RigidBody('bob', joint=[x, 0, z], mass=m)], [x, z],
                         force_function=UniformGravity([0, 0, -g]),
                         constraints=[x ** 2 + z ** 2 - l ** 2])
    L = S.lagrangian()
    mu, = L.multipliers()
    rng = random.Random(1305)
    for _ in range(5):
        pm, pg, pl = [rng.uniform(0.5, 2.0) for _ in range(3)]
        q, dq = rng.uniform(-3, 3), rng.uniform(-2, 2)
        import math
        values = {m: pm, g: pg, l: pl, x: pl * math.sin(q), z: -pl * math.cos(q),
                  velocity(x): pl * math.cos(q) * dq, velocity(z): pl * math.sin(q) * dq}
        sol = _solve_numeric(L, values)
        assert close(-2 * sol[mu] * pl, pm * (pl * dq ** 2 + pg * math.cos(q)))
        # the motion is the pendulum's: l ddq = -g sin q
        ddq = -pg / pl * math.sin(q)
        assert close(sol[acceleration(x)], pl * (math.cos(q) * ddq - math.sin(q) * dq ** 2))


def test_double_pendulum_cartesian():
    import math
    x1, z1, x2, z2, m1, m2, l1, l2, g = [SR.var(n) for n in 'x1 z1 x2 z2 m1 m2 l1 l2 g'.split()]
    S = MechanicalSystem([RigidBody('b1', joint=[x1, 0, z1], mass=m1),
                          RigidBody('b2', joint=[x2, 0, z2], mass=m2)], [x1, z1, x2, z2],
                         parameters=[m1, m2, l1, l2, g],
                         force_function=UniformGravity([0, 0, -g]),
                         constraints=[x1 ** 2 + z1 ** 2 - l1 ** 2,
                                      (x2 - x1) ** 2 + (z2 - z1) ** 2 - l2 ** 2])
    L = S.lagrangian()
    mu1, mu2 = L.multipliers()
    qs = me.dynamicsymbols('x1 z1 x2 z2')
    ms1, ms2, ls1, ls2, gs = sympy.symbols('m1 m2 l1 l2 g')
    Ns = me.ReferenceFrame('N')
    O = me.Point('O')
    O.set_vel(Ns, 0)
    P1 = O.locatenew('P1', qs[0] * Ns.x + qs[1] * Ns.z)
    P1.set_vel(Ns, P1.pos_from(O).dt(Ns))
    P2 = O.locatenew('P2', qs[2] * Ns.x + qs[3] * Ns.z)
    P2.set_vel(Ns, P2.pos_from(O).dt(Ns))
    pa, pb = me.Particle('pa', P1, ms1), me.Particle('pb', P2, ms2)
    pa.potential_energy = ms1 * gs * qs[1]
    pb.potential_energy = ms2 * gs * qs[3]
    L_sym = me.Lagrangian(Ns, pa, pb)
    con = [qs[0] ** 2 + qs[1] ** 2 - ls1 ** 2, (qs[2] - qs[0]) ** 2 + (qs[3] - qs[1]) ** 2 - ls2 ** 2]
    rng = random.Random(1306)
    for _ in range(3):
        pm1, pm2, pl1, pl2, pg = [rng.uniform(0.5, 2.0) for _ in range(5)]
        t1, t2 = rng.uniform(-3, 3), rng.uniform(-3, 3)
        w1, w2 = rng.uniform(-2, 2), rng.uniform(-2, 2)
        # the reduced model (angles from the downward vertical), textbook form:
        # (m1+m2) l1 a1 + m2 l2 a2 cos(t1-t2) + m2 l2 w2^2 sin(t1-t2) + (m1+m2) g sin t1 = 0
        # l2 a2 + l1 a1 cos(t1-t2) - l1 w1^2 sin(t1-t2) + g sin t2 = 0
        s, c = math.sin(t1 - t2), math.cos(t1 - t2)
        A = matrix(RDF, [[(pm1 + pm2) * pl1, pm2 * pl2 * c], [pl1 * c, pl2]])
        rhs = vector(RDF, [-pm2 * pl2 * w2 ** 2 * s - (pm1 + pm2) * pg * math.sin(t1),
                           pl1 * w1 ** 2 * s - pg * math.sin(t2)])
        a1, a2 = A.solve_right(rhs)
        r1 = [pl1 * math.sin(t1), -pl1 * math.cos(t1)]
        e2 = [math.sin(t2), -math.cos(t2)]
        r2 = [r1[0] + pl2 * e2[0], r1[1] + pl2 * e2[1]]
        v1 = [pl1 * math.cos(t1) * w1, pl1 * math.sin(t1) * w1]
        v2 = [v1[0] + pl2 * math.cos(t2) * w2, v1[1] + pl2 * math.sin(t2) * w2]
        acc1 = [pl1 * (math.cos(t1) * a1 - math.sin(t1) * w1 ** 2),
                pl1 * (math.sin(t1) * a1 + math.cos(t1) * w1 ** 2)]
        acc2 = [acc1[0] + pl2 * (math.cos(t2) * a2 - math.sin(t2) * w2 ** 2),
                acc1[1] + pl2 * (math.sin(t2) * a2 + math.cos(t2) * w2 ** 2)]
        values = {m1: pm1, m2: pm2, l1: pl1, l2: pl2, g: pg}
        for q, p0, v0 in zip([x1, z1, x2, z2], r1 + r2, v1 + v2):
            values[q], values[velocity(q)] = p0, v0
        sol = _solve_numeric(L, values)
        for q, expected in zip([x1, z1, x2, z2], acc1 + acc2):
            assert close(sol[acceleration(q)], expected)
        # tensions by Newton's law: on mass 2, m2 a2 = m2 g - T2 e2; on mass 1,
        # m1 a1 = m1 g - T1 e1 + T2 e2 (e1, e2 the rod directions, downwards)
        e1 = [r1[0] / pl1, r1[1] / pl1]
        T2 = -(pm2 * acc2[0] * e2[0] + (pm2 * acc2[1] + pm2 * pg) * e2[1])
        T1 = -((pm1 * acc1[0] - T2 * e2[0]) * e1[0]
               + (pm1 * acc1[1] + pm1 * pg - T2 * e2[1]) * e1[1])
        assert close(-2 * sol[mu1] * pl1, T1)
        assert close(-2 * sol[mu2] * pl2, T2)
        acc_sym, lam = _sympy_constrained(qs, L_sym, con,
                                          {ms1: pm1, ms2: pm2, ls1: pl1, ls2: pl2, gs: pg},
                                          list(zip(r1 + r2, v1 + v2)))
        for q, theirs in zip([x1, z1, x2, z2], acc_sym):
            assert close(sol[acceleration(q)], theirs)
        assert close(abs(lam[0]), abs(sol[mu1])) and close(abs(lam[1]), abs(sol[mu2]))


def test_constraints_round_trip(tmp_path):
    x, z, m, g, l = [SR.var(n) for n in 'x z m g l'.split()]
    S = MechanicalSystem([RigidBody('bob', joint=[x, 0, z], mass=m)], [x, z],
                         parameters=[m, g, l], force_function=UniformGravity([0, 0, -g]),
                         constraints=[x ** 2 + z ** 2 - l ** 2], name='pendulum')
    path = tmp_path / "pendulum.yaml"
    save(S, str(path))
    S2, results = load(str(path), results=True)
    assert S2.constraints() == S.constraints()
    assert results['lagrange_equations'] == S.lagrangian().lagrange_equations()


# ---------------------------------------------------------------------------
# parameter values
# ---------------------------------------------------------------------------

def test_subs_exact_and_float():
    S = load(example_path('cart_pendulum_spring_damper.yaml'))
    M, m, l, g, k, c = [SR.var(n) for n in 'M m l g k c'.split()]
    S1 = S.subs({M: 2, 'm': QQ(1) / 2, l: 1, g: 9.81, k: 3.0, c: 0.5})
    assert S1.parameters() == [] and S1.positive_parameters() == []
    # downstream with floats: the first-order system and its numerical values
    state, rhs = S1.lagrangian().first_order_system()
    S2 = S.subs({M: 2, m: QQ(1) / 2, l: 1, g: QQ(981) / 100, k: 3, c: QQ(1) / 2})
    exact = S2.lagrangian().first_order_system()[1]
    rng = random.Random(1307)
    for _ in range(3):
        point = {v: rng.uniform(-1, 1) for v in state}
        for a, b in zip(rhs, exact):
            assert close(sage_at(a, point), sage_at(b, point))
    # loads, dissipation and the parameters list follow
    F = SR.var('F')
    th = SR.var('theta')
    rod = RigidBody('rod', rotations=[(1, th)], mass_center=[0, 0, -l / 2], mass=m)
    S3 = MechanicalSystem([rod], [th], parameters=[m, l, F, c], positive=[m, l],
                          loads=[Load('rod', point=[0, 0, -l], force=[0, F, 0])],
                          dissipation=c * velocity(th) ** 2)
    S4 = S3.subs({F: 2, l: 0.5, c: 1})
    assert S4.parameters() == [m] and S4.positive_parameters() == [m]
    assert bool(S4.dissipation() == velocity(th) ** 2)
    assert bool(S4.generalized_forces()[0] == 2 * 0.5 * th.cos())


def test_velocity_dependent_load_is_a_drag():
    """A linear drag -c v_P at the tip of a rod on a cart, as a load whose
    force depends on the velocities, equals the Rayleigh function
    c |v_P|^2 / 2 (the partial velocities, not the derivative of the power)."""
    y, th, l, c = [SR.var(n) for n in 'y theta l c'.split()]
    dy, dth = velocity(y), velocity(th)
    tip_velocity = [0, dy + l * th.cos() * dth, l * th.sin() * dth]
    cart = RigidBody('cart', joint=[0, y, 0], mass=1)
    rod = RigidBody('rod', parent='cart', rotations=[(1, th)], mass_center=[0, 0, -l / 2], mass=1)
    S1 = MechanicalSystem([cart, rod], [y, th],
                          loads=[Load('rod', point=[0, 0, -l], force=[-c * u for u in tip_velocity])])
    S2 = MechanicalSystem([cart, rod], [y, th],
                          dissipation=c * sum(u ** 2 for u in tip_velocity) / 2)
    for e1, e2 in zip(S1.equations(), S2.equations()):
        assert bool((e1 - e2).expand().simplify_trig() == 0)


def test_loads_round_trip(tmp_path):
    th, phi, l, F, M = [SR.var(n) for n in 'theta phi l F M'.split()]
    arm = RigidBody('arm', rotations=[(3, phi)], mass=1, mass_center=[l, 0, 0])
    rod = RigidBody('rod', parent='arm', joint=[l, 0, 0], rotations=[(1, th)],
                    mass_center=[0, 0, -l / 2], mass=1)
    S = MechanicalSystem([arm, rod], [phi, th], parameters=[l, F, M], name='loaded',
                         loads=[Load('rod', point=[0, 0, -l], force=[F, 0, 0], axes='arm'),
                                Load(1, torque=[0, 0, M])])
    assert [load.body() for load in S.loads()] == ['rod', 'arm']
    path = tmp_path / "loaded.yaml"
    save(S, str(path))
    S2, results = load(str(path), results=True)
    assert S2.to_dict()['loads'] == S.to_dict()['loads']
    assert S2.generalized_forces() == S.generalized_forces()
    assert results['lagrange_equations'] == S.lagrangian().lagrange_equations()
