"""Holonomic constraints with multipliers (Lagrange's equations of the first
kind), parameter values as Python floats, and the agreement of
``cyclic_coordinates()`` with ``routh()``.

Expected values come from outside the code under test:

- the spherical pendulum in angles, the simple pendulum and the bead on a
  uniformly rotating rod, with their constraint forces, from Newton's second
  law along the constraint normal (H. Goldstein, C. Poole, J. Safko,
  *Classical Mechanics*, 3rd ed., 2002, section 2.4): the rod
  tension of a pendulum of length l is T = m (v^2/l - g.r/l) with g = (0, 0, -g),
  i.e. T = m (l dtheta^2 + g cos theta) for the plane pendulum; the normal
  force on the bead is N = 2 m omega dr (the Coriolis force);
- the double pendulum in Cartesian coordinates from SymPy's
  ``LagrangesMethod`` with ``hol_coneqs``, numerically at random states on
  the constraint surface. SymPy's ``mass_matrix_full``/``forcing_full``
  (``lam_coeffs = -J`` as the multipliers' columns) mean
  ``M q'' - J^T lam = F``, the package's convention, so ``mu = lam`` there;
  SymPy's ``eom`` attribute, ``d/dt dL/ddq - dL/dq - lam_coeffs^T lam``, has the
  opposite sign and vanishes at ``lam = -mu`` (both checked below).
"""
import random

import pytest
import sympy
import sympy.physics.mechanics as me
from sage.all import QQ, var, sin, cos, loads, dumps, function

from sage_dynsym import Lagrangian
from sage_dynsym.analysis.linear import linearize
from sage_dynsym.analysis.stationary import stationary_motions
from sage_dynsym.errors import ModelError, AnalysisError

m, g, l, l1, l2, m1, m2, w, c, k = var('m g l l1 l2 m1 m2 omega c k')
x, y, z, dx, dy, dz = var('x y z dx dy dz')


def close(a, b, tol=1e-9):
    return abs(float(a) - float(b)) <= tol * (1 + abs(float(b)))


def sphere_lagrangian():
    return Lagrangian(m * (dx**2 + dy**2 + dz**2) / 2 - m * g * z, [x, y, z],
                      constraints=[x**2 + y**2 + z**2 - l**2])


def test_particle_on_a_sphere_matches_the_spherical_pendulum():
    L = sphere_lagrangian()
    assert L.constraints() == [x**2 + y**2 + z**2 - l**2]
    mu, = L.multipliers()
    sol = L.accelerations_and_multipliers()
    assert set(sol) == {var('ddx'), var('ddy'), var('ddz'), mu}
    # the textbook spherical pendulum, theta from the downward vertical:
    # theta'' = sin cos phi'^2 - g/l sin,  phi'' = -2 cot(theta) theta' phi'
    rng = random.Random(13)
    for _ in range(5):
        params = {m: rng.uniform(0.5, 2), g: rng.uniform(5, 12), l: rng.uniform(0.5, 2)}
        th, ph = rng.uniform(0.3, 2.8), rng.uniform(-3, 3)
        dth, dph = rng.uniform(-2, 2), rng.uniform(-2, 2)
        L_, G = params[l], params[g]
        ddth = sympy.sin(th) * sympy.cos(th) * dph**2 - G / L_ * sympy.sin(th)
        ddph = -2 * sympy.cos(th) / sympy.sin(th) * dth * dph
        # Cartesian position as a function of time, differentiated by hand
        # through theta(t), phi(t) (Sage's own diff, not the package)
        tf = var('tf')
        Th, Ph = function('Th')(tf), function('Ph')(tf)
        r = [L_ * sin(Th) * cos(Ph), L_ * sin(Th) * sin(Ph), -L_ * cos(Th)]

        def at(e):
            e = e.subs({Th.diff(tf, 2): float(ddth), Ph.diff(tf, 2): float(ddph)})
            e = e.subs({Th.diff(tf): dth, Ph.diff(tf): dph})
            return float(e.subs({Th: th, Ph: ph}))
        pos = [at(ri) for ri in r]
        vel = [at(ri.diff(tf)) for ri in r]
        acc = [at(ri.diff(tf, 2)) for ri in r]
        state = {**dict(zip([x, y, z], pos)), **dict(zip([dx, dy, dz], vel)), **params}
        for v, expected in zip([var('ddx'), var('ddy'), var('ddz')], acc):
            assert close(sol[v].subs(state), expected)
        # the tension: T = m (v^2/l - g z / l) = -2 mu l
        v2 = sum(u**2 for u in vel)
        tension = params[m] * (v2 / L_ - G * pos[2] / L_)
        assert close(-2 * params[l] * sol[mu].subs(state), tension)
        assert close(tension, params[m] * (L_ * (dth**2 + sympy.sin(th)**2 * dph**2)
                                           + G * sympy.cos(th)))


def test_sphere_reduced_to_angles_is_the_spherical_pendulum():
    th, ph, dth, dph = var('theta phi dtheta dphi')
    P = sphere_lagrangian().reduce([th, ph], {x: l * sin(th) * cos(ph),
                                              y: l * sin(th) * sin(ph), z: -l * cos(th)})
    assert P.coordinates() == [th, ph] and P.constraints() == []
    acc = P.accelerations_solved()
    expected = [sin(th) * cos(th) * dph**2 - g / l * sin(th),
                -2 * cos(th) / sin(th) * dth * dph]
    rng = random.Random(5)
    for _ in range(4):
        point = {th: rng.uniform(0.3, 2.8), ph: rng.uniform(-3, 3), dth: rng.uniform(-2, 2),
                 dph: rng.uniform(-2, 2), g: 9.81, l: rng.uniform(0.5, 2), m: 1.5}
        for a, e in zip(acc, expected):
            assert close(a.subs(point), e.subs(point))


def test_simple_pendulum_tension():
    L = Lagrangian(m * (dx**2 + dy**2) / 2 - m * g * y, [x, y],
                   constraints=[x**2 + y**2 - l**2])
    equations = L.lagrange_equations()
    mu, = L.multipliers()
    # the sign convention: E_i contain -mu df/dq_i
    assert bool(equations[0] == m * var('ddx') - 2 * mu * x)
    sol = L.accelerations_and_multipliers()
    rng = random.Random(7)
    for _ in range(5):
        th, dth = rng.uniform(-3, 3), rng.uniform(-3, 3)
        values = {m: rng.uniform(0.5, 2), g: 9.81, l: rng.uniform(0.5, 2)}
        L_ = values[l]
        state = {x: L_ * sympy.sin(th), y: -L_ * sympy.cos(th),
                 dx: L_ * sympy.cos(th) * dth, dy: L_ * sympy.sin(th) * dth, **values}
        state = {k_: float(v) for k_, v in state.items()}
        tension = values[m] * (L_ * dth**2 + 9.81 * sympy.cos(th))
        assert close(-2 * L_ * sol[mu].subs(state), tension)
        # theta'' = -g/l sin(theta), mapped: x'' = l (cos th'' - sin th'^2)
        ddth = -9.81 / L_ * sympy.sin(th)
        assert close(sol[var('ddx')].subs(state),
                     L_ * (sympy.cos(th) * ddth - sympy.sin(th) * dth**2))
        assert close(sol[var('ddy')].subs(state),
                     L_ * (sympy.sin(th) * ddth + sympy.cos(th) * dth**2))
    # accelerations_solved and the first-order system use the constrained accelerations
    assert L.accelerations_solved() == [sol[var('ddx')], sol[var('ddy')]]
    assert L.first_order_system()[1][2:] == L.accelerations_solved()


def test_bead_on_a_rotating_rod():
    """A time-dependent constraint y cos(w t) - x sin(w t) = 0: r'' = w^2 r, and
    the normal force is the Coriolis force N = 2 m w r'."""
    t = var('t')
    L = Lagrangian(m * (dx**2 + dy**2) / 2, [x, y],
                   constraints=[y * cos(w * t) - x * sin(w * t)])
    mu, = L.multipliers()
    sol = L.accelerations_and_multipliers()
    rng = random.Random(3)
    for _ in range(5):
        r, dr, tt, W, M = (rng.uniform(0.5, 2), rng.uniform(-2, 2), rng.uniform(0, 6),
                           rng.uniform(0.5, 3), rng.uniform(0.5, 2))
        ct, st = float(sympy.cos(W * tt)), float(sympy.sin(W * tt))
        state = {x: r * ct, y: r * st, dx: dr * ct - r * W * st, dy: dr * st + r * W * ct,
                 t: tt, w: W, m: M}
        ddr = W**2 * r
        # x = r cos(w t): x'' = (r'' - w^2 r) cos - 2 w r' sin
        assert close(sol[var('ddx')].subs(state), (ddr - W**2 * r) * ct - 2 * W * dr * st)
        assert close(sol[var('ddy')].subs(state), (ddr - W**2 * r) * st + 2 * W * dr * ct)
        # the constraint force mu * grad f, grad f the unit normal (-sin, cos)
        assert close(sol[mu].subs(state), 2 * M * W * dr)


def sympy_double_pendulum():
    T = me.dynamicsymbols._t
    X1, Y1, X2, Y2 = me.dynamicsymbols('x1 y1 x2 y2')
    M1, M2, G, L1, L2 = sympy.symbols('m1 m2 g l1 l2')
    N = me.ReferenceFrame('N')
    O = me.Point('O')
    O.set_vel(N, 0)
    P1 = O.locatenew('P1', X1 * N.x + Y1 * N.y)
    P2 = O.locatenew('P2', X2 * N.x + Y2 * N.y)
    P1.set_vel(N, P1.pos_from(O).dt(N))
    P2.set_vel(N, P2.pos_from(O).dt(N))
    a, b = me.Particle('a', P1, M1), me.Particle('b', P2, M2)
    a.potential_energy, b.potential_energy = M1 * G * Y1, M2 * G * Y2
    Lag = me.Lagrangian(N, a, b)
    cons = [X1**2 + Y1**2 - L1**2, (X2 - X1)**2 + (Y2 - Y1)**2 - L2**2]
    LM = me.LagrangesMethod(Lag, [X1, Y1, X2, Y2], hol_coneqs=cons, frame=N)
    LM.form_lagranges_equations()
    q = [X1, Y1, X2, Y2]
    u = [v.diff(T) for v in q]
    return LM, q, u, (M1, M2, G, L1, L2)


def test_double_pendulum_against_sympy_lagranges_method():
    x1, y1, x2, y2, dx1, dy1, dx2, dy2 = var('x1 y1 x2 y2 dx1 dy1 dx2 dy2')
    L = Lagrangian(m1 * (dx1**2 + dy1**2) / 2 + m2 * (dx2**2 + dy2**2) / 2
                   - m1 * g * y1 - m2 * g * y2, [x1, y1, x2, y2],
                   constraints=[x1**2 + y1**2 - l1**2, (x2 - x1)**2 + (y2 - y1)**2 - l2**2])
    assert len(L.lagrange_equations()) == 4
    mus = L.multipliers()
    sol = L.accelerations_and_multipliers()
    LM, q, u, (M1, M2, G, L1, L2) = sympy_double_pendulum()
    Mfull, Ffull = LM.mass_matrix_full, LM.forcing_full
    rng = random.Random(11)
    for _ in range(4):
        p = {m1: rng.uniform(0.5, 2), m2: rng.uniform(0.5, 2), g: 9.81,
             l1: rng.uniform(0.5, 2), l2: rng.uniform(0.5, 2)}
        a1, a2, w1, w2 = (rng.uniform(-3, 3) for _ in range(4))
        X1 = p[l1] * sympy.sin(a1)
        Y1 = -p[l1] * sympy.cos(a1)
        X2 = X1 + p[l2] * sympy.sin(a2)
        Y2 = Y1 - p[l2] * sympy.cos(a2)
        V = [p[l1] * sympy.cos(a1) * w1, p[l1] * sympy.sin(a1) * w1]
        V += [V[0] + p[l2] * sympy.cos(a2) * w2, V[1] + p[l2] * sympy.sin(a2) * w2]
        P = [X1, Y1, X2, Y2]
        ours = {**dict(zip([x1, y1, x2, y2], P)), **dict(zip([dx1, dy1, dx2, dy2], V)), **p}
        ours = {k_: float(v) for k_, v in ours.items()}
        theirs = {M1: p[m1], M2: p[m2], G: 9.81, L1: p[l1], L2: p[l2]}
        # velocities first, so that the coordinates' derivatives are replaced
        subs = {**theirs, **dict(zip(u, V))}
        Mn = Mfull.subs(subs).subs(dict(zip(q, P)))
        Fn = Ffull.subs(subs).subs(dict(zip(q, P)))
        xs = Mn.evalf().LUsolve(Fn.evalf())
        # the unknowns: u (= q'), u', lam1, lam2
        for i, v in enumerate(['ddx1', 'ddy1', 'ddx2', 'ddy2']):
            assert close(sol[var(v)].subs(ours), xs[4 + i], 1e-8)
        for j, mu in enumerate(mus):
            assert close(sol[mu].subs(ours), xs[8 + j], 1e-8)
        # SymPy's eom with lam = -mu and our accelerations vanishes
        T = me.dynamicsymbols._t
        dd = {v.diff(T, 2): float(sol[var(n)].subs(ours))
              for v, n in zip(q, ['ddx1', 'ddy1', 'ddx2', 'ddy2'])}
        lam = {lv: -float(sol[mu].subs(ours)) for lv, mu in zip(LM.lam_vec, mus)}
        residual = LM.eom.subs(dd).subs(lam).subs(subs).subs(dict(zip(q, P))).evalf()
        assert all(abs(float(r)) < 1e-8 for r in residual)


def test_constraints_in_the_record_and_value_semantics():
    L = sphere_lagrangian()
    E = L.to_linearizer()
    assert E.constraints() == L.constraints() and E.multipliers() == L.multipliers()
    assert loads(dumps(L)) == L
    assert L != Lagrangian(L.expr(), [x, y, z])
    assert hash(L) == hash(sphere_lagrangian())
    S = L.subs({l: 2})
    assert S.constraints() == [x**2 + y**2 + z**2 - 4]
    assert "subject to" in repr(L)
    # a Lagrangian already using mu1 gets another multiplier name
    mu1 = var('mu1')
    C = Lagrangian((dx**2 + dy**2) / 2 + mu1 * x, [x, y], constraints=[x - y])
    assert C.multipliers() != [mu1] and not C.expr().has(C.multipliers()[0])


def test_analysis_refuses_multipliers():
    L = sphere_lagrangian()
    with pytest.raises(AnalysisError, match="constraints"):
        linearize(L, {x: 0, y: 0, z: -l})
    with pytest.raises(AnalysisError, match="constraints"):
        stationary_motions(L)
    with pytest.raises(ModelError, match="constraints"):
        L.hamiltonian()


def test_constraint_errors():
    with pytest.raises(ModelError, match=r"constraints\[1\].*does not depend on the coordinates"):
        Lagrangian(dx**2 + dy**2, [x, y], constraints=[x - y, l - 1])
    with pytest.raises(ModelError, match=r"^constraints: .*redundant"):
        Lagrangian(dx**2 + dy**2 + dz**2, [x, y, z],
                   constraints=[x**2 + y**2 + z**2 - l**2, 3 * (x**2 + y**2 + z**2 - l**2)])
    with pytest.raises(ModelError, match=r"redundant"):
        Lagrangian(dx**2 + dy**2, [x, y], constraints=[x, y, x + y])
    with pytest.raises(ModelError, match=r"constraints\[0\].*velocity dx"):
        Lagrangian(dx**2 + dy**2, [x, y], constraints=[x * dx - y])
    # independent constraints are accepted, also with trigonometric functions
    Lagrangian(dx**2 + dy**2 + dz**2, [x, y, z], constraints=[sin(x) - y, z - cos(x)])


def test_reduce_errors():
    L = sphere_lagrangian()
    th, ph = var('theta phi')
    with pytest.raises(ModelError, match="parametrization: the constraint constraints"):
        L.reduce([th, ph], {x: l * sin(th), y: l * sin(ph), z: l})
    with pytest.raises(ModelError, match="independent"):
        L.reduce([th], {x: th, y: 0, z: 0})


def test_reduce_keeps_forces_by_virtual_work():
    """A pendulum with a horizontal force F at the bob and a damper on x:
    the generalized force on theta is F l cos(theta) (virtual work), and the
    damping c dx^2/2 becomes c l^2 cos^2 dtheta^2/2."""
    F, th, dth = var('F theta dtheta')
    L = Lagrangian(m * (dx**2 + dy**2) / 2 - m * g * y, [x, y], forces=[F, 0],
                   dissipation=c * dx**2 / 2, constraints=[x**2 + y**2 - l**2])
    P = L.reduce([th], {x: l * sin(th), y: -l * cos(th)})
    assert bool(P.generalized_forces()[0] == F * l * cos(th))
    assert bool((P.dissipation() - c * l**2 * cos(th)**2 * dth**2 / 2).simplify_full() == 0)
    expected = (m * l**2 * var('ddtheta') + m * g * l * sin(th) - F * l * cos(th)
                + c * l**2 * cos(th)**2 * dth)
    assert bool((P.lagrange_equations()[0] - expected).simplify_full() == 0)


def damped_cart():
    th, dth, M = var('theta dtheta M')
    return Lagrangian((M + m) * dx**2 / 2 + m * l * cos(th) * dx * dth + m * l**2 * dth**2 / 2
                      + m * g * l * cos(th), [x, th], dissipation=c * dx**2 / 2)


def test_float_parameter_values():
    th, dth, M = var('theta dtheta M')
    L = damped_cart()
    values = {M: 2.0, m: 0.5, l: 1.5, g: 9.81, c: 0.25}
    exact = {M: 2, m: QQ(1) / 2, l: QQ(3) / 2, g: QQ(981) / 100, c: QQ(1) / 4}
    F, E = L.subs(values), L.subs(exact)
    state, rhs = F.first_order_system()
    _, rhs_exact = E.first_order_system()
    point = {x: 0.3, th: 0.7, dx: -0.4, dth: 1.1}
    for a, b in zip(rhs, rhs_exact):
        assert close(a.subs(point), b.subs(point))
    assert all(close(a.subs(point), b.subs(point))
               for a, b in zip(F.accelerations_solved(), E.accelerations_solved()))
    p = var('p_x')
    H, HE = F.hamiltonian(), E.hamiltonian()
    hp = {x: 0.3, th: 0.7, p: -0.4, var('p_theta'): 1.1}
    assert close(H.expr().subs(hp), HE.expr().subs(hp))
    # undamped: the Routh function with float parameter values
    U = Lagrangian(L.expr(), [x, th])
    R, RE = U.subs(values).routh([x]), U.subs(exact).routh([x])
    rp = {th: 0.7, dth: 1.1, p: 0.9}
    assert close(R.expr().subs(rp), RE.expr().subs(rp))
    assert all(close(a.subs(rp).subs({var('ddtheta'): 0.2}), b.subs(rp).subs({var('ddtheta'): 0.2}))
               for a, b in zip(R.equations(), RE.equations()))
    # Python floats inside expressions are made Sage numbers too
    G = L.subs({c: 0.5 * k})
    assert G.first_order_system()


@pytest.mark.parametrize("case", ["damper", "force", "force_depends", "dissipation_depends",
                                  "constraint", "free"])
def test_cyclic_coordinates_agree_with_routh(case):
    th, dth, M = var('theta dtheta M')
    base = damped_cart().expr()
    z_, dz_ = var('z dz')
    expr = base + M * dz_**2 / 2
    options = {
        "damper": dict(dissipation=c * dx**2 / 2),
        "force": dict(forces=[k, 0, 0]),
        "force_depends": dict(forces=[0, k * x, 0]),
        "dissipation_depends": dict(dissipation=c * x**2 * dth**2 / 2),
        "constraint": dict(constraints=[z_ - x]),
        "free": dict(),
    }[case]
    L = Lagrangian(expr, [x, th, z_], **options)
    cyclic = L.cyclic_coordinates()
    expected = {"damper": [z_], "force": [z_], "force_depends": [z_],
                "dissipation_depends": [z_], "constraint": [], "free": [x, z_]}[case]
    assert cyclic == expected
    for q in [x, z_]:
        if q in cyclic:
            L.routh([q])
        else:
            with pytest.raises(ModelError, match="not cyclic"):
                L.routh([q])


def test_double_pendulum_motion_equals_the_reduced_model():
    """The Cartesian double pendulum reduced to its two angles (by the
    package's ``reduce``) moves as the constrained model: its angular
    accelerations, mapped to Cartesian ones by hand, equal the accelerations
    solved with the multipliers."""
    x1, y1, x2, y2, dx1, dy1, dx2, dy2 = var('x1 y1 x2 y2 dx1 dy1 dx2 dy2')
    a1, a2, da1, da2 = var('a1 a2 da1 da2')
    L = Lagrangian(m1 * (dx1**2 + dy1**2) / 2 + m2 * (dx2**2 + dy2**2) / 2
                   - m1 * g * y1 - m2 * g * y2, [x1, y1, x2, y2],
                   constraints=[x1**2 + y1**2 - l1**2, (x2 - x1)**2 + (y2 - y1)**2 - l2**2])
    P = L.reduce([a1, a2], {x1: l1 * sin(a1), y1: -l1 * cos(a1),
                            x2: l1 * sin(a1) + l2 * sin(a2),
                            y2: -l1 * cos(a1) - l2 * cos(a2)})
    reduced = P.accelerations_solved()
    sol = L.accelerations_and_multipliers()
    rng = random.Random(17)
    for _ in range(4):
        p = {m1: rng.uniform(0.5, 2), m2: rng.uniform(0.5, 2), g: 9.81,
             l1: rng.uniform(0.5, 2), l2: rng.uniform(0.5, 2)}
        A1, A2, W1, W2 = (rng.uniform(-3, 3) for _ in range(4))
        angles = {a1: A1, a2: A2, da1: W1, da2: W2, **p}
        dd1, dd2 = (float(r.subs(angles)) for r in reduced)
        s1, c1, s2, c2 = (float(f) for f in (sin(A1), cos(A1), sin(A2), cos(A2)))
        L1, L2 = p[l1], p[l2]
        cart = {x1: L1 * s1, y1: -L1 * c1, x2: L1 * s1 + L2 * s2, y2: -L1 * c1 - L2 * c2,
                dx1: L1 * c1 * W1, dy1: L1 * s1 * W1,
                dx2: L1 * c1 * W1 + L2 * c2 * W2, dy2: L1 * s1 * W1 + L2 * s2 * W2, **p}
        ddx1 = L1 * (c1 * dd1 - s1 * W1**2)
        ddy1 = L1 * (s1 * dd1 + c1 * W1**2)
        expected = {'ddx1': ddx1, 'ddy1': ddy1,
                    'ddx2': ddx1 + L2 * (c2 * dd2 - s2 * W2**2),
                    'ddy2': ddy1 + L2 * (s2 * dd2 + c2 * W2**2)}
        for name, value in expected.items():
            assert close(sol[var(name)].subs(cart), value, 1e-8)
