"""
The Newtonian force function (2) against the exact potential of point masses.

Each body is a cloud of point masses; its mass, mass centre and inertia
tensor about its joint point are computed here from the points. The exact
force function is ``nu * sum m_i / |R_i|`` (``R_i`` from the attracting
centre to the point), with the positions obtained by composing elementary
rotation matrices in NumPy. Formula (2) is exact to second order in
size/distance, so its relative error must fall like ``(size/distance)^3``:
doubling the distance divides it by about 8 (a wrong term of order k <= 2
would give a ratio of at least 1/4).
"""
import math
import sys
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))
from reference.sympy_chain import SympyChain  # noqa: E402

from sage.all import SR, fast_callable, RDF  # noqa: E402
from sage_dynsym import MechanicalSystem, RigidBody, NewtonianField  # noqa: E402

DISTANCES = (300.0, 600.0)   # far enough that the third-order term dominates the fourth
ORIENTATIONS = 4


def elementary_rotation(axis, angle):
    """Components in the old axes of a vector given in the axes turned by
    ``angle`` about ``axis`` (1, 2, 3 = x, y, z)."""
    c, s = math.cos(angle), math.sin(angle)
    return {1: np.array([[1, 0, 0], [0, c, -s], [0, s, c]]),
            2: np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]]),
            3: np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])}[axis]


def orientation(rotations, values):
    """Matrix taking body components to parent components (rotations about new axes)."""
    A = np.eye(3)
    for axis, name in rotations:
        A = A @ elementary_rotation(axis, values[name])
    return A


class PointCloud:
    """A rigid body made of point masses given in its own axes, relative to O_k."""

    def __init__(self, rng, n_points=7, size=2):
        self.masses = [Fraction(rng.integers(1, 9), 4) for _ in range(n_points)]
        self.points = [[Fraction(int(rng.integers(-4 * size, 4 * size + 1)), 4) for _ in range(3)]
                       for _ in range(n_points)]
        self.mass = sum(self.masses)
        self.mass_center = [sum(m * p[i] for m, p in zip(self.masses, self.points)) / self.mass
                            for i in range(3)]
        # Inertia about O_k: sum m (|rho|^2 E - rho rho^T).
        self.inertia = [[sum(m * ((sum(x * x for x in p) if i == j else 0) - p[i] * p[j])
                             for m, p in zip(self.masses, self.points))
                         for j in range(3)] for i in range(3)]

    def numeric_points(self):
        return np.array([[float(x) for x in p] for p in self.points])


def _sage(x):
    return SR(x.numerator) / SR(x.denominator) if isinstance(x, Fraction) else SR(x)


def _exact_force_function(clouds, chain, values, nu, r, e):
    """nu * sum m_i / |R_i| with R_i = r e + (position of the point from O_1)."""
    frames, origins = [np.eye(3)], [np.zeros(3)]   # index 0: the inertial frame at O_1
    U = 0.0
    for cloud, body in zip(clouds, chain):
        parent = body['parent']
        joint = np.array([float(x) for x in body['joint']]) if parent else np.zeros(3)
        origin = origins[parent] + frames[parent] @ joint
        frame = frames[parent] @ orientation(body['rotations'], values)
        frames.append(frame)
        origins.append(origin)
        R = r * e + origin + cloud.numeric_points() @ frame.T
        U += nu * sum(float(m) / np.linalg.norm(Ri) for m, Ri in zip(cloud.masses, R))
    return U


def _system(clouds, chain, coordinates):
    nu, r, e1, e2, e3 = SR.var('nu r e1 e2 e3')
    bodies = [RigidBody(f'cloud{k}', parent=b['parent'],
                        rotations=[(axis, SR.var(name)) for axis, name in b['rotations']],
                        joint=[_sage(x) for x in b['joint']],
                        mass_center=[_sage(x) for x in c.mass_center], mass=_sage(c.mass),
                        inertia=[[_sage(x) for x in row] for row in c.inertia])
              for k, (c, b) in enumerate(zip(clouds, chain), start=1)]
    return MechanicalSystem(bodies, coordinates=[SR.var(q) for q in coordinates],
                            parameters=[nu, r, e1, e2, e3],
                            force_function=NewtonianField(nu, r, [e1, e2, e3]))


CHAINS = {
    'one body': ([dict(parent=0, rotations=[(3, 'a'), (1, 'b'), (3, 'c')], joint=[0, 0, 0])],
                 ['a', 'b', 'c']),
    'two bodies': ([dict(parent=0, rotations=[(3, 'a'), (2, 'b')], joint=[0, 0, 0]),
                    dict(parent=1, rotations=[(1, 'd'), (3, 'f')],
                         joint=[Fraction(3, 2), Fraction(-1, 2), 1])],
                   ['a', 'b', 'd', 'f']),
}


@pytest.mark.parametrize('name', list(CHAINS))
def test_force_function_error_is_third_order(name):
    chain, coordinates = CHAINS[name]
    rng = np.random.default_rng(2024 + len(chain))
    clouds = [PointCloud(rng) for _ in chain]
    U = _system(clouds, chain, coordinates).force_function()
    order = coordinates + ['nu', 'r', 'e1', 'e2', 'e3']
    U_formula = fast_callable(SR(U), vars=[SR.var(n) for n in order], domain=RDF)
    nu = 3.5
    for _ in range(ORIENTATIONS):
        values = {q: rng.uniform(-math.pi, math.pi) for q in coordinates}
        e = rng.normal(size=3)
        e /= np.linalg.norm(e)
        errors = []
        for r in DISTANCES:
            exact = _exact_force_function(clouds, chain, values, nu, r, e)
            approx = float(U_formula(*[values[q] for q in coordinates], nu, r, *e))
            errors.append(abs(approx - exact) / abs(exact))
        ratio = errors[1] / errors[0]
        assert errors[0] < 1e-4, f"{name}: relative error {errors[0]} at r = {DISTANCES[0]}"
        assert ratio > 1 / 12 and ratio < 1 / 5, (
            f"{name}: relative errors {errors} at r = {DISTANCES}, ratio {ratio} "
            f"(expected about 1/8) at {values}, e = {e}")


def test_numpy_rotations_match_sympy():
    """The NumPy orientation used above is the one of the SymPy reference
    (orient_axis about the new axes), hence the package's convention (doc/method.rst)."""
    chain, coordinates = CHAINS['two bodies']
    bodies = [dict(b, mass_center=[0, 0, 0], mass=1, inertia=np.eye(3).tolist()) for b in chain]
    ref = SympyChain(bodies, coordinates)
    values = dict(zip(coordinates, (0.3, -1.1, 2.0, 0.7)))
    subs = {q: values[q.func.__name__] for q in ref.coordinates}
    for k in (1, 2):
        dcm = np.array(ref.inertial_frame.dcm(ref.frames[k]).subs(subs), dtype=float)
        A = orientation(chain[0]['rotations'], values)
        if k == 2:
            A = A @ orientation(chain[1]['rotations'], values)
        assert np.allclose(dcm, A, atol=1e-14)
