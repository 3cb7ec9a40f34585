"""kind: lie_poisson description files, their report, and the Kirchhoff
builder (issue 12).

Expected values: the example's equations are the Euler-Poisson equations
written out here (cross products; Borisov & Mamaev, Rigid Body Dynamics,
§2.1), its integral M3 is Lagrange's (Arnold, §30); Kirchhoff's equations
for a body with three planes of symmetry are typed here by hand as in Lamb,
Hydrodynamics, §127 (and worksheet 06); for a body whose centre of mass is
off the origin the Hamiltonian is checked against the kinetic energy
1/2 m |V + Omega x r|^2 + 1/2 Omega.I_c Omega (Koenig's theorem) through
the Legendre map, numerically.
"""
import random
from pathlib import Path

import numpy as np
import pytest
from sage.all import SR, var, vector, matrix, diagonal_matrix

from sage_dynsym.description import read_yaml
from sage_dynsym.errors import DynSymError
from sage_dynsym.lie import (LiePoissonSystem, kirchhoff, lie_poisson_from_dict,
                             lie_poisson_to_dict, lie_report)

ROOT = Path(__file__).resolve().parent.parent
EXAMPLE = ROOT / "examples" / "heavy_top_e3.yaml"
M = list(var('M1 M2 M3'))
G = list(var('gamma1 gamma2 gamma3'))
P = list(var('p1 p2 p3'))
A, C, m, g, l = var('A C m g l')


def test_example_file():
    S = lie_poisson_from_dict(read_yaml(str(EXAMPLE)), str(EXAMPLE))
    assert S.name() == 'heavy symmetric top'
    assert S.variables() == M + G and S.parameters() == [A, C, m, g, l]
    w = vector(SR, [M[0] / A, M[1] / A, M[2] / C])
    X = list(vector(SR, M).cross_product(w) + m * g * vector(SR, G).cross_product(
        vector(SR, [0, 0, l]))) + list(vector(SR, G).cross_product(w))
    assert all((a - b).simplify_rational().is_zero() for a, b in zip(S.equations(), X))
    assert S.polynomial_integrals(2, new_only=True) == [M[2]]


def test_report_of_the_example():
    S = lie_poisson_from_dict(read_yaml(str(EXAMPLE)), str(EXAMPLE))
    text = lie_report(S)
    assert text.startswith("== heavy symmetric top (Lie-Poisson system on e3")
    assert "equations" in text and "LaTeX: " in text
    for needle in ("dM1/dt = ", "Casimirs", "gamma1^2 + gamma2^2 + gamma3^2",
                   "Polynomial first integrals of degree <= 2", "\n  M3\n",
                   "Stationary motions", "stable (Routh-Lyapunov)"):
        assert needle in text, needle
    # the sleeping top: Maievski's condition M3^2 > 4 A m g l (gamma3 = 1)
    # (the rest points gamma = 0 come first: stable without a condition)
    assert any("4*A*g*gamma3*l*m - M3^2 < 0" in s for s in text.splitlines()
               if "stable (Routh-Lyapunov)" in s)
    short = lie_report(S, sections=['equations', 'lagrangian'], analysis=False)
    assert "Stationary" not in short and "Casimirs" not in short and "dM1/dt" in short


def test_structure_constants_and_matrix_files():
    d = {'kind': 'lie_poisson', 'name': 'rigid body', 'variables': ['L1', 'L2', 'L3'],
         'parameters': ['I1', 'I2', 'I3'],
         'algebra': {'structure_constants': [['L1', 'L2', {'L3': 1}], ['L2', 'L3', {'L1': 1}],
                                             ['L3', 'L1', {'L2': 1}]]},
         'hamiltonian': 'L1^2/(2*I1) + L2^2/(2*I2) + L3^2/(2*I3)'}
    S = lie_poisson_from_dict(d)
    L = list(var('L1 L2 L3'))
    assert S.poisson_matrix() == LiePoissonSystem('so3', L[0], variables=L).poisson_matrix()
    assert S.casimirs() == [L[0]**2 + L[1]**2 + L[2]**2]
    d['algebra'] = {'poisson_matrix': [[0, '-L3', 'L2'], ['L3', 0, '-L1'], ['-L2', 'L1', 0]]}
    assert lie_poisson_from_dict(d).equations() == S.equations()
    d2 = {'kind': 'lie_poisson', 'algebra': 'e3', 'variables': ['M', 'p'],
          'hamiltonian': 'M1^2 + p1^2'}
    assert lie_poisson_from_dict(d2).variables() == M + P


@pytest.mark.parametrize('change, message', [
    ({'algebra': 'so5'}, "algebra: unknown Lie algebra 'so5'"),
    ({'hamiltonian': 'M1^2 + q'}, "hamiltonian: undeclared symbol 'q'"),
    ({'variables': ['a', 'b', 'c']}, "variables: e3 has 6 coordinates"),
    ({'colour': 'red'}, "unknown key 'colour'"),
    ({'parameters': 'A'}, "parameters: expected a list of symbol names"),
    ({'positive': ['B']}, "positive[0]: 'B' is not a declared parameter"),
    ({'variables': ['M1', 'M2', 'M3', 'lambda1', 'g2', 'g3']}, "variables[3]: the name 'lambda1' is reserved"),
    ({'algebra': {'poisson_matrix': [[0, 1], [-1, 0]]}}, "algebra.poisson_matrix: expected a 6x6 matrix"),
    ({'algebra': {'structure_constants': [['M1', 'M2']]}},
     "algebra.structure_constants[0]: expected a bracket"),
    ({'algebra': {'lie': 1}}, "algebra: unknown key 'lie'"),
])
def test_bad_descriptions(change, message):
    d = read_yaml(str(EXAMPLE))
    d.update(change)
    with pytest.raises(DynSymError) as err:
        lie_poisson_from_dict(d, 'top.yaml')
    assert str(err.value).startswith('top.yaml: ') and message in str(err.value), str(err.value)


def test_jacobi_breaking_matrix_in_a_file():
    d = {'kind': 'lie_poisson', 'variables': ['x', 'y', 'z'], 'hamiltonian': 'x',
         'algebra': {'poisson_matrix': [[0, 'x', 0], ['-x', 0, 'y'], [0, '-y', 0]]}}
    with pytest.raises(DynSymError, match="bad.yaml: algebra: the matrix breaks the Jacobi"):
        lie_poisson_from_dict(d, 'bad.yaml')


def test_kirchhoff_three_planes_of_symmetry():
    I = list(var('I1 I2 I3'))
    J = list(var('J1 J2 J3'))
    K = list(var('K1 K2 K3'))
    mass = var('mass')
    S = kirchhoff(inertia=diagonal_matrix(I), mass=mass,
                  added_masses=diagonal_matrix(J + K))
    a = [1 / (I[i] + J[i]) for i in range(3)]
    b = [1 / (mass + K[i]) for i in range(3)]
    Mv, Pv = vector(SR, M), vector(SR, P)
    w = vector(SR, [a[i] * M[i] for i in range(3)])
    v = vector(SR, [b[i] * P[i] for i in range(3)])
    X = list(Mv.cross_product(w) + Pv.cross_product(v)) + list(Pv.cross_product(w))
    assert all((e - f).simplify_rational().is_zero() for e, f in zip(S.equations(), X))
    assert S.casimirs() == [M[0] * P[0] + M[1] * P[1] + M[2] * P[2], P[0]**2 + P[1]**2 + P[2]**2]


def test_kirchhoff_with_an_offset_centre_of_mass_matches_the_energy():
    I = list(var('I1 I2 I3'))
    mass, r1, r3 = var('mass r1 r3')
    fluid = matrix(SR, 6, 6)
    for i, s in enumerate(var('f1 f2 f3 f4 f5 f6')):
        fluid[i, i] = s
    fluid[0, 4] = fluid[4, 0] = var('f15')
    S = kirchhoff(inertia=diagonal_matrix(I), mass=mass, mass_center=[r1, 0, r3],
                  added_masses=fluid)
    rng = random.Random(9)
    for _ in range(3):
        vals = {s: rng.uniform(2, 4) for s in I + [var('f%d' % k) for k in range(1, 7)]}
        vals.update({mass: rng.uniform(1, 2), r1: rng.uniform(-0.3, 0.3),
                     r3: rng.uniform(-0.3, 0.3), var('f15'): rng.uniform(-0.2, 0.2)})
        Om = np.array([rng.uniform(-1, 1) for _ in range(3)])
        V = np.array([rng.uniform(-1, 1) for _ in range(3)])
        r = np.array([float(vals[r1]), 0.0, float(vals[r3])])
        Ic = np.diag([float(vals[s]) for s in I]) - float(vals[mass]) * (
            np.dot(r, r) * np.eye(3) - np.outer(r, r))
        F = np.array([[float(SR(fluid[i, j]).subs(vals)) for j in range(6)] for i in range(6)])
        u = np.concatenate([Om, V])

        def T(u):
            Om, V = u[:3], u[3:]
            vel = V + np.cross(Om, r)
            return 0.5 * float(vals[mass]) * vel.dot(vel) + 0.5 * Om.dot(Ic.dot(Om)) + \
                0.5 * u.dot(F.dot(u))
        h = 1e-6
        grad = np.array([(T(u + h * e) - T(u - h * e)) / (2 * h) for e in np.eye(6)])
        point = dict(zip(M + P, grad))
        H = float(S.hamiltonian().subs(point).subs(vals))
        assert abs(H - T(u)) < 1e-6
        # the inverse Legendre map: dH/d(M, p) = (Omega, V)
        back = [float(S.hamiltonian().diff(x).subs(point).subs(vals)) for x in M + P]
        assert np.allclose(back, u, atol=1e-6)


def test_round_trip_and_subs():
    S = lie_poisson_from_dict(read_yaml(str(EXAMPLE)), str(EXAMPLE))
    d = lie_poisson_to_dict(S)
    T = lie_poisson_from_dict(d)
    assert T.equations() == S.equations() and T.positive_parameters() == [A, C, m, g, l]
    fast = S.subs({m: 1, g: 10})
    assert fast.parameters() == [A, C, l] and fast.hamiltonian() == S.hamiltonian().subs(m=1, g=10)
    with pytest.raises(DynSymError, match="M1 is not a parameter"):
        S.subs({M[0]: 1})
