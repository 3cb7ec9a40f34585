"""Benchmark: the census of equilibria of the gyrostat satellite.

The gyrostat satellite on a circular orbit (principal moments 1, 2, 5/2,
a rotor of axial moment 1 along the third axis, orbital rate 1) in the
Euler angles z, x, y, with the angles z, y, x as the regular chart on
their singular set. ``equilibrium_census`` over the gyrostatic moment h > 0
is timed stage by stage (the discriminant by elimination, the exact solve
at each sample point), and compared in the same run with the reference
route: a direct numerical search of the critical points of the amended
potential on SO(3) (SciPy, rotation vectors, 300 random starts) at the
same sample points. The table gives, per cell, both counts and both times.

Target: the whole census within minutes on 2 cores.

Usage: python bench/bench_census.py [--quick] [--executor process]
"""
import argparse
import time

import numpy as np
from scipy.optimize import root
from scipy.spatial.transform import Rotation

from sage.all import SR, QQ, var, cos, sin, diagonal_matrix, zero_matrix
from sage_dynsym import RigidBody, MechanicalSystem, NewtonianField, Lagrangian, euler_angles
from sage_dynsym.analysis.census import equilibrium_census, discriminant_polynomials, \
    equilibria_at, _amended_potential

w0, A, B, C, J, r, t, chi = var('w0 A B C J r t chi')
VALUES = {A: 1, B: 2, C: QQ(5) / 2, w0: 1, J: 1, r: 1}


def gyrostat(sequence):
    angles = [SR.var(n) for _, n in sequence]
    orbit = RigidBody('orbital frame', rotations=[(3, w0 * t)], mass=0, inertia=zero_matrix(3))
    sat = RigidBody('satellite', parent=1, rotations=[(a, q) for (a, _), q in zip(sequence, angles)],
                    mass=1, inertia=diagonal_matrix([A, B, C]))
    rotor = RigidBody('rotor', parent=2, rotations=[(3, chi)], mass=0,
                      inertia=diagonal_matrix([0, 0, J]))
    S = MechanicalSystem([orbit, sat, rotor], angles + [chi],
                         force_function=NewtonianField(w0**2 * r**3, r, [cos(w0 * t), sin(w0 * t), 0]))
    L = Lagrangian(S.lagrangian().expr().simplify_trig().expand(), angles + [chi])
    return L.routh([chi]), euler_angles(list(zip([a for a, _ in sequence], angles)))


def direct(h, starts=300):
    """Critical points and minima of W on SO(3), numerically (the reference)."""
    Is, It = np.diag([1.0, 2.0, 2.5]), np.diag([1.0, 2.0, 3.5])

    def torque(R):
        g, n = R[0, :], R[2, :]
        return 3 * np.cross(It @ g, g) - np.cross(Is @ n, n) - h * np.cross([0, 0, 1.0], n)
    found = []
    for R0 in Rotation.random(starts, random_state=np.random.default_rng(5)).as_matrix():
        sol = root(lambda w: torque(R0 @ Rotation.from_rotvec(w).as_matrix()), np.zeros(3), tol=1e-13)
        R = R0 @ Rotation.from_rotvec(sol.x).as_matrix()
        if np.linalg.norm(torque(R)) < 1e-9 and all(np.linalg.norm(R - S) > 1e-6 for S in found):
            found.append(R)
    minima = 0
    for R in found:
        H = np.array([(torque(R @ Rotation.from_rotvec(1e-6 * e).as_matrix())
                       - torque(R @ Rotation.from_rotvec(-1e-6 * e).as_matrix())) / 2e-6
                      for e in np.eye(3)])
        minima += bool(np.all(np.linalg.eigvalsh((H + H.T) / 2) > 1e-7))
    return len(found), minima


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--quick', action='store_true', help='one sample point only')
    parser.add_argument('--executor', choices=['none', 'process'], default='none',
                        help='solve the sample points in 2 worker processes')
    args = parser.parse_args()
    first, second = gyrostat([(3, 'alpha'), (1, 'beta'), (2, 'gamma')]), \
        gyrostat([(3, 'alpha'), (2, 'beta'), (1, 'gamma')])
    h = first[0].momenta()[0]
    start = time.time()
    q, W = _amended_potential(first[0])
    polys = discriminant_polynomials(SR(W).subs(VALUES), q, [h])
    print(f"discriminant (elimination, Singular): {time.time() - start:.2f} s, "
          f"{len(polys)} factors: {polys}")
    if args.quick:
        for value in (0, QQ(1) / 3):
            start = time.time()
            found = equilibria_at(first[0], {**VALUES, h: value}, first[1],
                                  (second[0].subs(VALUES), second[1]))
            exact_time = time.time() - start
            start = time.time()
            ref = direct(float(value))
            print(f"h = {value}: exact {len(found)} equilibria, "
                  f"{sum(v == 'stable' for _, v in found)} stable in {exact_time:.2f} s; "
                  f"direct numerical {ref[0]}, {ref[1]} in {time.time() - start:.2f} s")
        return
    executor = None
    if args.executor == 'process':
        from concurrent.futures import ProcessPoolExecutor
        executor = ProcessPoolExecutor(max_workers=2)
    start = time.time()
    census = equilibrium_census(first[0], [h], positive=[h], values=VALUES, chart=first[1],
                                regular=second, executor=executor)
    total = time.time() - start
    print(census)
    print(f"census: {total:.1f} s for {len(census.cells())} cells")
    print(f"{'sample h':>10} {'exact':>10} {'direct':>10} {'direct s':>9}")
    agree = 0
    for cell in census.cells():
        value = cell.sample()[h]
        start = time.time()
        ref = direct(float(value))
        agree += ref == (cell.count(), cell.stable_count())
        print(f"{str(value):>10} {cell.count():>5}/{cell.stable_count():<4} "
              f"{ref[0]:>5}/{ref[1]:<4} {time.time() - start:9.2f}")
    print(f"agreement: {agree} of {len(census.cells())} cells")
    if executor is not None:
        executor.shutdown()


if __name__ == '__main__':
    main()
