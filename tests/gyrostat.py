"""
The gyrostat satellite on a circular orbit, shared by tests/test_census.py
and bench/bench_census.py: the model built with sage_dynsym, and the
independent route to its equilibria -- the critical orientations on SO(3)
found numerically from the torque written from the physics (the amended
potential and its torque are derived in the docstring of
tests/test_census.py).
"""
import numpy as np
from scipy.optimize import root
from scipy.spatial.transform import Rotation

from sage.all import SR, QQ, var, diagonal_matrix, zero_matrix, cos, sin
from sage_dynsym import RigidBody, MechanicalSystem, NewtonianField, Lagrangian
from sage_dynsym.mechanics.charts import model_chart


# -- the independent route: critical points on SO(3) by numerical search ----------

def critical_orientations(torque, starts=300, seed=7):
    """Distinct rotation matrices where ``torque(R)`` vanishes, and how
    many are minima (the Hessian d tau / d eps positive definite)."""
    rng = np.random.default_rng(seed)
    found = []
    for R0 in Rotation.random(starts, random_state=rng).as_matrix():
        sol = root(lambda w: torque(R0 @ Rotation.from_rotvec(w).as_matrix()), np.zeros(3),
                   tol=1e-13)
        R = R0 @ Rotation.from_rotvec(sol.x).as_matrix()
        if np.linalg.norm(torque(R)) < 1e-9 and all(np.linalg.norm(R - S) > 1e-6 for S in found):
            found.append(R)
    minima = 0
    for R in found:
        eps = 1e-6
        H = np.array([(torque(R @ Rotation.from_rotvec(eps * e).as_matrix())
                       - torque(R @ Rotation.from_rotvec(-eps * e).as_matrix())) / (2 * eps)
                      for e in np.eye(3)])
        minima += bool(np.all(np.linalg.eigvalsh((H + H.T) / 2) > 1e-7))
    return found, minima


def gyrostat_torque(Is, It, h, w0=1.0):
    """The torque of the amended potential W (see tests/test_census.py) on
    the body turned to ``R``, with inertia ``Is`` of the carrier, ``It`` of
    carrier and rotor, gyrostatic moment ``h`` and orbital rate ``w0``."""
    def torque(R):
        gamma, n = R[0, :], R[2, :]
        return (3 * w0**2 * np.cross(It @ gamma, gamma) - w0**2 * np.cross(Is @ n, n)
                - h * w0 * np.cross([0, 0, 1.0], n))
    return torque


# -- the model built with sage_dynsym, as in worksheets/05_gyrostat_satellite.ipynb, with three angles ------

w0, A, B, C, J, r, t, chi = var('w0 A B C J r t chi')
VALUES = {A: 1, B: 2, C: QQ(5) / 2, w0: 1, J: 1, r: 1}
INERTIA = (np.diag([1.0, 2.0, 2.5]), np.diag([1.0, 2.0, 3.5]))


def gyrostat(sequence):
    """The Routh function of the gyrostat satellite (the rotor angle ``chi``
    ignorable) in the Euler angles ``sequence`` (pairs ``(axis, name)``),
    and the chart of the satellite's orientation those angles are."""
    angles = [SR.var(n) for _, n in sequence]
    orbit = RigidBody('orbital frame', rotations=[(3, w0 * t)], mass=0, inertia=zero_matrix(3))
    sat = RigidBody('satellite', parent=1, rotations=[(a, q) for (a, _), q in zip(sequence, angles)],
                    mass=1, inertia=diagonal_matrix([A, B, C]))
    rotor = RigidBody('rotor', parent=2, rotations=[(3, chi)], mass=0,
                      inertia=diagonal_matrix([0, 0, J]))
    S = MechanicalSystem([orbit, sat, rotor], angles + [chi],
                         force_function=NewtonianField(w0**2 * r**3, r, [cos(w0 * t), sin(w0 * t), 0]))
    L = Lagrangian(S.lagrangian().expr().simplify_trig().expand(), angles + [chi])
    R = L.routh([chi])
    # the model knows its chart: the satellite turned by three angles
    return R, model_chart(S, angles)
