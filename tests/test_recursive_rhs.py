"""
The recursive right-hand side (numerics/recursive.py) of trees of rigid bodies.

Random trees -- branching, with joint offsets, sliding joints (joint
points depending on coordinates), rotation angles that are coordinates,
constants or functions of t, full inertia tensors, uniform gravity,
loads -- are checked at random states against

- an independent implementation written here: the kinematics in the
  inertial axes as truncated Taylor series along the motion (positions of
  the mass centres and rotation matrices composed from elementary rotations),
  the velocities, accelerations and partial velocities read off the series,
  and Kane's equations with the centroidal Newton--Euler equations; NumPy
  solves for the accelerations;
- the accelerations solved from the package's symbolic Lagrange equations
  in 150-bit arithmetic (linear in the accelerations).

Both solvers (articulated-body algorithm, and mass matrix + L^T D L) must
agree to 1e-10 relative. With holonomic constraints and constraints on the
velocities, the reference's mass matrix and forcing are completed by the
constraint rows and their right-hand sides differentiated here with SymPy. The rest of the model format (dissipation,
generalized forces, force functions given as expressions or Newtonian
fields, prescribed joint velocities, constraints) is checked against the
symbolic equations.
"""
import math
import random
import sys
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest
import sympy

from sage.all import SR, sin, cos, dumps, loads

sys.path.insert(0, str(Path(__file__).resolve().parent))
from reference.chains import physical_inertia  # noqa: E402
from sage_chains import sage_chain_parts, assemble, exact_accelerations  # noqa: E402
from sage_dynsym import MechanicalSystem, RigidBody, UniformGravity, NewtonianField  # noqa: E402
from sage_dynsym.mechanics.recursive_numerics import body_tree, numerical_form  # noqa: E402
from sage_dynsym.numerics.compiler import compiler  # noqa: E402
from sage_dynsym.numerics.recursive import RecursiveForm  # noqa: E402
from sage_dynsym.numerics.rhs import RightHandSide  # noqa: E402

BACKEND = 'c' if compiler() else 'python'


# ----------------------------------------------------------------------
# random trees (plain data, the fields of reference/sympy_chain.py)

def random_tree(seed, n_bodies):
    """
    A random tree: body k hangs from a random earlier body or the inertial
    frame; 0-3 elementary rotations about random axes (never twice the same
    axis in a row), each angle a coordinate, or a constant, or a function of
    t; a random joint offset, one component sliding along a coordinate for
    some bodies; a random mass centre, mass and full inertia tensor.
    """
    rng = random.Random(seed)
    bodies, coords = [], []
    for k in range(1, n_bodies + 1):
        rotations, last = [], None
        for i in range(rng.randint(0 if k > 1 else 1, 3)):
            axis = rng.choice([a for a in (1, 2, 3) if a != last])
            last = axis
            kind = rng.random()
            if kind < 0.7:
                angle = f"q{k}_{i}"
                coords.append(angle)
            elif kind < 0.85:
                angle = "3/7"
            else:
                angle = "w*t + 1/5"
            rotations.append((axis, angle))
        joint = [Fraction(rng.randint(-8, 8), 4) for _ in range(3)]
        if not any(a.startswith('q') for _, a in rotations) or rng.random() < 0.3:
            name = f"s{k}"
            coords.append(name)
            joint[rng.randrange(3)] = f"{name} + {Fraction(rng.randint(-4, 4), 4)}"
        center = [Fraction(rng.randint(-6, 6), 4) for _ in range(3)]
        mass = Fraction(rng.randint(4, 12), 4)
        bodies.append(dict(parent=0 if k == 1 else rng.randint(0, k - 1), rotations=rotations,
                           joint=joint, mass_center=center, mass=mass,
                           inertia=physical_inertia(rng, mass, center)))
    gravity = [Fraction(rng.randint(-12, 12), 4) for _ in range(3)]
    return dict(bodies=bodies, coordinates=coords, parameters=['w'], gravity=gravity,
                values={'w': 0.7})


# ----------------------------------------------------------------------
# the independent reference: Taylor series along the motion + Kane

class Taylor:
    """A truncated power series c0 + c1 s + c2 s^2 of a motion parameter s."""
    __slots__ = ('c',)

    def __init__(self, c0, c1=0.0, c2=0.0):
        self.c = (float(c0), float(c1), float(c2))

    @staticmethod
    def lift(x):
        return x if isinstance(x, Taylor) else Taylor(x)

    def __add__(self, other):
        o = Taylor.lift(other).c
        return Taylor(*(a + b for a, b in zip(self.c, o)))
    __radd__ = __add__

    def __neg__(self):
        return Taylor(*(-a for a in self.c))

    def __sub__(self, other):
        return self + (-Taylor.lift(other))

    def __rsub__(self, other):
        return Taylor.lift(other) - self

    def __mul__(self, other):
        a, b = self.c, Taylor.lift(other).c
        return Taylor(a[0] * b[0], a[0] * b[1] + a[1] * b[0],
                      a[0] * b[2] + a[1] * b[1] + a[2] * b[0])
    __rmul__ = __mul__

    def inverse(self):
        b0, b1, b2 = self.c
        return Taylor(1 / b0, -b1 / b0 ** 2, (b1 * b1 - b0 * b2) / b0 ** 3)

    def __truediv__(self, other):
        return self * Taylor.lift(other).inverse()

    def __rtruediv__(self, other):
        return Taylor.lift(other) * self.inverse()

    def __pow__(self, n):
        assert int(n) == n and n >= 0
        out = Taylor(1.0)
        for _ in range(int(n)):
            out = out * self
        return out


def t_sin(x):
    x = Taylor.lift(x)
    s, c = math.sin(x.c[0]), math.cos(x.c[0])
    return Taylor(s, c * x.c[1], c * x.c[2] - s * x.c[1] ** 2 / 2)


def t_cos(x):
    x = Taylor.lift(x)
    s, c = math.sin(x.c[0]), math.cos(x.c[0])
    return Taylor(c, -s * x.c[1], -s * x.c[2] - c * x.c[1] ** 2 / 2)


def _function(text, names):
    symbols = [sympy.Symbol(n) for n in names]
    expr = sympy.sympify(str(text), locals={n: s for n, s in zip(names, symbols)})
    return sympy.lambdify(symbols, expr, modules=[{'sin': t_sin, 'cos': t_cos, 'pi': math.pi}])


def _elementary(axis, angle):
    c, s = t_cos(angle), t_sin(angle)
    if axis == 1:
        return [[1, 0, 0], [0, c, -s], [0, s, c]]
    if axis == 2:
        return [[c, 0, s], [0, 1, 0], [-s, 0, c]]
    return [[c, -s, 0], [s, c, 0], [0, 0, 1]]


def _mat(A, B):
    return [[sum((A[i][k] * B[k][j] for k in range(3)), Taylor(0)) for j in range(3)]
            for i in range(3)]


def _apply(A, v):
    return [sum((A[i][k] * v[k] for k in range(3)), Taylor(0)) for i in range(3)]


def _vee(M):
    S = (M - M.T) / 2
    return np.array([S[2, 1], S[0, 2], S[1, 0]])


class Reference:
    """Kane's equations of a plain-data tree, numerically (see the module doc)."""

    def __init__(self, desc, values, loads=()):
        self.desc, self.values, self.loads = desc, values, loads
        self.names = desc['coordinates'] + list(values) + ['t']
        self.bodies = []
        for body in desc['bodies']:
            self.bodies.append(dict(
                parent=body['parent'],
                rotations=[(axis, _function(angle, self.names))
                           for axis, angle in body['rotations']],
                joint=[_function(c, self.names) for c in body['joint']],
                c=np.array([float(x) for x in body['mass_center']]),
                m=float(body['mass']),
                I_O=np.array([[float(x) for x in row] for row in body['inertia']])))
        self.g = np.array([float(x) for x in desc['gravity']])

    def _frames(self, q, t):
        args = list(q) + [Taylor(v) for v in self.values.values()] + [t]
        R, O = [[[Taylor(float(i == j)) for j in range(3)] for i in range(3)]], [[Taylor(0)] * 3]
        for body in self.bodies:
            Rp, Op = R[body['parent']], O[body['parent']]
            r = [f(*args) for f in body['joint']]
            Ok = [a + b for a, b in zip(Op, _apply(Rp, r))]
            Rk = Rp
            for axis, angle in body['rotations']:
                Rk = _mat(Rk, _elementary(axis, angle(*args)))
            R.append(Rk)
            O.append(Ok)
        return R[1:], O[1:]

    def _series(self, q, dq, t, dt):
        qs = [Taylor(a, b) for a, b in zip(q, dq)]
        R, O = self._frames(qs, Taylor(t, dt))
        out = []
        for body, Rk, Ok in zip(self.bodies, R, O):
            C = [a + b for a, b in zip(Ok, _apply(Rk, list(body['c'])))]
            out.append(([np.array([[Taylor.lift(x).c[o] for x in row] for row in Rk])
                         for o in range(3)],
                        [np.array([Taylor.lift(x).c[o] for x in C]) for o in range(3)],
                        [np.array([Taylor.lift(x).c[o] for x in Ok]) for o in range(3)]))
        return out

    def accelerations(self, q, dq, t):
        M, F = self.mass_and_forcing(q, dq, t)
        return np.linalg.solve(M, F)

    def constrained_accelerations(self, q, dq, t, G, gamma):
        """ddq of M ddq - G^T lam = F, G ddq = gamma (constraint forces G^T lam)."""
        M, F = self.mass_and_forcing(q, dq, t)
        n, m = len(q), len(gamma)
        K = np.block([[M, -np.asarray(G).T], [np.asarray(G), np.zeros((m, m))]])
        return np.linalg.solve(K, np.concatenate([F, gamma]))[:n]

    def mass_and_forcing(self, q, dq, t):
        n = len(q)
        motion = self._series(q, dq, t, 1.0)
        partial = [self._series(q, [float(i == j) for j in range(n)], t, 0.0) for i in range(n)]
        M, E0 = np.zeros((n, n)), np.zeros(n)
        for b, body in enumerate(self.bodies):
            (R0, R1, R2), (C0, C1, C2), _ = motion[b]
            m, c = body['m'], body['c']
            I_C = body['I_O'] - m * (c @ c * np.eye(3) - np.outer(c, c))
            w = _vee(R0.T @ R1)
            alpha = _vee(2 * R0.T @ R2)
            a_c = 2 * C2
            force = m * a_c - m * self.g
            torque = I_C @ alpha + np.cross(w, I_C @ w)
            Jc = [partial[i][b][1][1] for i in range(n)]
            Jw = [_vee(R0.T @ partial[i][b][0][1]) for i in range(n)]
            for i in range(n):
                E0[i] += force @ Jc[i] + torque @ Jw[i]
                for j in range(n):
                    M[i, j] += m * Jc[i] @ Jc[j] + Jw[i] @ I_C @ Jw[j]
        for body_index, point, force, torque in self.loads:
            for i in range(n):
                R0, R1 = partial[i][body_index - 1][0][0], partial[i][body_index - 1][0][1]
                O1 = partial[i][body_index - 1][2][1]
                if force is not None:
                    E0[i] -= np.array(force) @ (O1 + R1 @ np.array(point))
                if torque is not None:
                    E0[i] -= np.array(torque) @ (R0 @ _vee(R0.T @ R1))
        return M, -E0


# ----------------------------------------------------------------------

def _system(desc, **extra):
    bodies, coordinates, parameters, gravity = sage_chain_parts(desc)
    rigid = [RigidBody(b['name'], **{k: v for k, v in b.items() if k != 'name'})
             for b in bodies]
    return MechanicalSystem(rigid, coordinates=coordinates, parameters=parameters,
                            force_function=UniformGravity(gravity), **extra)


def _relative(got, expected):
    scale = max(1.0, float(np.max(np.abs(expected))))
    return float(np.max(np.abs(np.asarray(got, dtype=float) - expected))) / scale


TREES = [(seed, n) for seed, n in zip(range(8), (3, 4, 5, 4, 6, 3, 5, 4))]


@pytest.mark.parametrize("seed,n_bodies", TREES)
def test_recursive_rhs_equals_independent_kane(seed, n_bodies):
    desc = random_tree(seed, n_bodies)
    S = assemble(*sage_chain_parts(desc))
    tree = body_tree(S)
    reference = Reference(desc, desc['values'])
    rng = random.Random(seed)
    rhs = [RightHandSide(RecursiveForm(tree, solver=s), desc['values'], BACKEND)
           for s in ('articulated', 'ltdl')]
    assert [f.form().solver() for f in rhs] == ['articulated', 'ltdl']
    n = len(desc['coordinates'])
    for _ in range(3):
        q = [rng.uniform(-2, 2) for _ in range(n)]
        dq = [rng.uniform(-1, 1) for _ in range(n)]
        t = rng.uniform(0, 2)
        expected = reference.accelerations(q, dq, t)
        for f in rhs:
            got = f(t, np.array(q + dq))
            assert np.array_equal(got[:n], dq)
            assert _relative(got[n:], expected) < 1e-10, (f.form().solver(), got, expected)


@pytest.mark.parametrize("seed,n_bodies", TREES[:3])
def test_recursive_rhs_equals_symbolic_equations(seed, n_bodies):
    desc = random_tree(seed, n_bodies)
    S = assemble(*sage_chain_parts(desc))
    record = S.lagrangian().equations_record()
    f = S.numerical_rhs(desc['values'])
    assert f.form().solver() == 'articulated'
    rng = random.Random(seed + 100)
    n = len(desc['coordinates'])
    for _ in range(2):
        state = [rng.uniform(-2, 2) for _ in range(n)] + [rng.uniform(-1, 1) for _ in range(n)]
        t = rng.uniform(0, 2)
        point = dict(zip([str(v) for v in f.variables()], state), t=t, **desc['values'])
        assert _relative(f(t, np.array(state))[n:], exact_accelerations(record, point)) < 1e-10


def test_loads_against_independent_kane():
    """Forces at body points (inertial axes) and torques (inertial axes)."""
    desc = random_tree(11, 4)
    loads = [(2, [0.5, -0.25, 1.0], [1.5, -0.5, 2.0], None),
             (4, [0.0, 0.75, -0.5], [0.25, 1.0, -1.0], [0.5, 0.3, -0.2]),
             (1, [0, 0, 0], None, [0.0, -1.0, 0.4])]
    S = _system(desc, loads=[{'body': f'body{k}', 'point': p, 'force': F, 'torque': T}
                             for k, p, F, T in loads])
    reference = Reference(desc, desc['values'], loads)
    rng = random.Random(5)
    n = len(desc['coordinates'])
    for solver in ('articulated', 'ltdl'):
        f = RightHandSide(RecursiveForm(body_tree(S), solver=solver), desc['values'], BACKEND)
        q = [rng.uniform(-2, 2) for _ in range(n)]
        dq = [rng.uniform(-1, 1) for _ in range(n)]
        got = f(0.4, np.array(q + dq))[n:]
        assert _relative(got, reference.accelerations(q, dq, 0.4)) < 1e-10


def _against_equations(S, values, seed=1, solvers=('articulated', 'ltdl'), t=0.3):
    """The recursive right-hand sides of S against its symbolic equations
    (Gaussian elimination of the equations' mass matrix and forcing)."""
    rng = random.Random(seed)
    equations = RightHandSide(numerical_form(S, 'equations'), values, BACKEND)
    n = len(S.coordinates())
    for solver in solvers:
        f = RightHandSide(RecursiveForm(body_tree(S), solver=solver), values, BACKEND)
        for _ in range(2):
            x = np.array([rng.uniform(-1.5, 1.5) for _ in range(2 * n)])
            assert _relative(f(t, x), equations(t, x)) < 1e-10, solver


def test_dissipation_forces_and_force_functions():
    desc = random_tree(21, 3)
    q = [SR.var(c) for c in desc['coordinates']]
    dq = [SR.var('d' + c) for c in desc['coordinates']]
    k, c = SR.var('k'), SR.var('c')
    R = c * sum(v ** 2 for v in dq) / 2 + dq[0] * dq[-1] * q[0] ** 2 / 3
    forces = [SR(0)] * len(q)
    forces[1] = SR.var('F0') * sin(SR.var('t')) - dq[1] * q[0]
    bodies, coordinates, parameters, gravity = sage_chain_parts(desc)
    rigid = [RigidBody(b['name'], **{key: v for key, v in b.items() if key != 'name'})
             for b in bodies]
    nu, r = SR.var('nu'), SR.var('r')
    S = MechanicalSystem(rigid, coordinates, dissipation=R, forces=forces,
                         force_function=[UniformGravity(gravity), -k * q[0] ** 2 / 2
                                         + q[1] * q[-1], NewtonianField(nu, r, [0, 0.6, 0.8])])
    values = dict(desc['values'], k=3, c=0.4, F0=1.5, nu=2.0, r=5.0)
    _against_equations(S, values)


def test_prescribed_joint_velocities():
    """A screw joint (v = p * dphi along the axis, the joint point fixed:
    not the derivative of the joint point) and a velocity field that is not
    integrable: Lagrange's equations of the kinetic energy, not Kane's."""
    phi, x, y, p, m = (SR.var(s) for s in 'phi x y p m'.split())
    dphi, dx, dy = SR.var('dphi'), SR.var('dx'), SR.var('dy')
    nut = RigidBody('nut', rotations=[(3, phi)], velocity=[0, 0, p * dphi], mass=m,
                    mass_center=[0.3, 0, 0.1], inertia=[[2.5, 0.1, 0], [0.1, 3, 0.2], [0, 0.2, 2]])
    skate = RigidBody('skate', parent='nut', joint=[x, y, 0],
                      velocity=[dx, dy + x * dx * cos(phi), 0], rotations=[(1, x)],
                      mass=2, mass_center=[0, 0.5, 0.2],
                      inertia=[[1, 0, 0.1], [0, 2, 0], [0.1, 0, 1.5]])
    S = MechanicalSystem([nut, skate], [phi, x, y], force_function=UniformGravity([0, -1, -9.8]))
    _against_equations(S, {'p': 0.4, 'm': 1.5})


def test_constraints_take_the_factorized_mass_matrix():
    """A four-bar-like loop: two pendulums whose tips are tied together."""
    a, b = SR.var('a'), SR.var('b')
    left = RigidBody('left', rotations=[(1, a)], mass=1, mass_center=[0, 0, -1],
                     inertia=[[1.2, 0, 0], [0, 1.1, 0], [0, 0, 0.1]])
    right = RigidBody('right', joint=[0, 1, 0], rotations=[(1, b)], mass=2,
                      mass_center=[0, 0, -1], inertia=[[2.3, 0, 0], [0, 2.2, 0], [0, 0, 0.2]])
    constraint = (sin(a) - 1 - sin(b)) ** 2 + (cos(a) - cos(b)) ** 2 - 1
    S = MechanicalSystem([left, right], [a, b], force_function=UniformGravity([0, 0, -9.8]),
                         constraints=[constraint])
    form = numerical_form(S)
    assert form.solver() == 'auto'
    _against_equations(S, {}, solvers=('ltdl',))
    assert form.graph() and form.solver() == 'ltdl'


def test_models_outside_the_recursive_form_take_the_equations():
    x, m = SR.var('x'), SR.var('m')
    S = MechanicalSystem([RigidBody('b', joint=[x, 0, 0], mass=m * (1 + x ** 2))], [x])
    f = S.numerical_rhs({'m': 2})
    assert type(f.form()).__name__ == 'NumericalForm'
    # d/dt (m (1 + x^2) dx) - m x dx^2 = 0: m (1 + x^2) ddx + m x dx^2 = 0
    assert f(0, [1.0, 2.0])[1] == pytest.approx(-1 * 4 / 2)


def test_simulation_keeps_the_energy_computed_only_on_demand():
    desc = random_tree(3, 3)
    for body in desc['bodies']:       # no explicit time: the energy is conserved
        body['rotations'] = [(axis, '1/5' if 't' in angle else angle)
                             for axis, angle in body['rotations']]
    S = assemble(*sage_chain_parts(desc))
    n = len(desc['coordinates'])
    initial = {v: 0.1 * (i % 3) for i, v in enumerate(S.coordinates() + S.velocities())}
    T = S.simulate({}, initial, 1.0, points=5)
    assert T.states().shape == (5, 2 * n)
    assert loads(dumps(S)).coordinates() == S.coordinates()     # no compiled code pickled
    assert not S.lagrangian.cache           # no symbolic equations, no energy yet
    assert T.energy_drift() < 1e-8
    assert S.lagrangian.cache


def _constraint_rows(desc, holonomic, nonholonomic, q, dq, t):
    """Independently of the package (SymPy): the rows G and the right-hand
    sides gamma of G ddq = gamma, from d^2 f/dt^2 = 0 of holonomic
    constraints f(q, t) and d g/dt = 0 of velocity constraints g(q, dq, t)."""
    names = desc['coordinates']
    Q = sympy.symbols(names)
    D = sympy.symbols(['d' + c for c in names])
    T = sympy.Symbol('t')
    point = dict(zip(Q, q)) | dict(zip(D, dq)) | {T: t} | {
        sympy.Symbol(k): v for k, v in desc['values'].items()}

    def dt(e):      # d/dt along the motion at zero accelerations
        return sum(e.diff(a) * b for a, b in zip(Q, D)) + e.diff(T)
    rows, gamma = [], []
    for text in holonomic:
        f = sympy.sympify(text, locals={str(s): s for s in Q + [T]})
        velocity = dt(f)
        rows.append([float(velocity.diff(b).subs(point)) for b in D])
        gamma.append(-float(dt(velocity).subs(point)))
    for text in nonholonomic:
        g = sympy.sympify(text, locals={str(s): s for s in Q + D + [T]})
        rows.append([float(g.diff(b).subs(point)) for b in D])
        gamma.append(-float(dt(g).subs(point)))
    return np.array(rows), np.array(gamma)


@pytest.mark.parametrize("seed,n_bodies", [(30, 3), (31, 4)])
def test_velocity_constraints_against_independent_kane(seed, n_bodies):
    """Constraints on the velocities (not integrable, depending on q and t)
    with a holonomic one: the rows are appended to the factorized mass
    matrix (the multipliers eliminated in the generated code)."""
    desc = random_tree(seed, n_bodies)
    c = desc['coordinates']
    holonomic = [f"{c[0]} + {c[1]}**2/3 - sin({c[-1]})/2"]
    nonholonomic = [f"cos({c[0]})*d{c[1]} - {c[1]}*sin({c[0]})*d{c[0]} + d{c[-1]}/3 "
                    f"+ sin(t)/10",
                    f"d{c[2]} - {c[0]}*d{c[-1]} + w*{c[1]}"]
    S = _system(desc, constraints=[SR(f) for f in holonomic],
                nonholonomic=[SR(g) for g in nonholonomic])
    form = numerical_form(S)
    assert type(form).__name__ == 'RecursiveForm'
    f = S.numerical_rhs(desc['values'])
    assert f.form() is form and form.solver() == 'ltdl'
    reference = Reference(desc, desc['values'])
    rng = random.Random(seed)
    n = len(c)
    for _ in range(2):
        q = [rng.uniform(-1.5, 1.5) for _ in range(n)]
        dq = [rng.uniform(-1, 1) for _ in range(n)]
        t = rng.uniform(0, 2)
        G, gamma = _constraint_rows(desc, holonomic, nonholonomic, q, dq, t)
        expected = reference.constrained_accelerations(q, dq, t, G, gamma)
        assert _relative(f(t, np.array(q + dq))[n:], expected) < 1e-10


def test_whipple_bicycle_takes_the_recursive_form():
    """Rolling wheels (a holonomic contact condition and no-slip conditions
    on the velocities): the recursive form by default, the same
    accelerations as the Lagrange equations with multipliers (SymPy's
    bicycle checks the default in tests/test_whipple_bicycle_sympy.py)."""
    from sage_dynsym import load
    from sage_dynsym.description import example_path
    S = load(example_path('whipple_bicycle.yaml'))
    assert type(numerical_form(S)).__name__ == 'RecursiveForm'
    values = dict(w=1.02, c=0.08, lam=math.pi / 10, g=9.81, rR=0.3, mR=2, IRxx=0.0603,
                  IRyy=0.12, xB=0.3, zB=-0.9, mB=85, IBxx=9.2, IByy=11, IBzz=2.8, IBxz=2.4,
                  xH=0.9, zH=-0.7, mH=4, IHxx=0.05892, IHyy=0.06, IHzz=0.00708, IHxz=-0.00756,
                  rF=0.35, mF=3, IFxx=0.1405, IFyy=0.28, v=5)
    _against_equations(S, values, solvers=('ltdl',))
