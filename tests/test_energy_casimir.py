"""The energy-Casimir method against the classical results.

- Euler's free rigid body: the permanent rotations about the axes of the
  largest and of the smallest moment of inertia are stable, about the middle
  one unstable (Euler 1765; Marsden & Ratiu, Introduction to Mechanics and
  Symmetry, 1999, section 15.10).
- The sleeping Lagrange top (upright, spinning about its axis): stable if
  M3^2 > 4 A m g l (the Maievski-Chetaev condition, where the energy-Casimir
  function is definite), unstable if M3^2 < 4 A m g l (two real roots of
  the linearization; Marsden & Ratiu, section 15.10, and Arnold, Kozlov,
  Neishtadt, 2006).
"""
import itertools
import random

import pytest
from sage.all import QQ, var

from sage_dynsym import load, nonlinear_stability
from sage_dynsym.lie.system import LiePoissonSystem

M1, M2, M3 = var('M1 M2 M3')


@pytest.mark.parametrize("seed", range(4))
def test_euler_rigid_body_axes(seed):
    rng = random.Random(seed)
    inertia = sorted(QQ(rng.randint(1, 40)) / rng.randint(1, 9) for _ in range(3))
    if len(set(inertia)) < 3:
        inertia = [QQ(1), QQ(2), QQ(3)]
    for order in itertools.permutations(range(3)):
        A = [inertia[k] for k in order]
        S = LiePoissonSystem('so3', (M1 ** 2 / A[0] + M2 ** 2 / A[1] + M3 ** 2 / A[2]) / 2)
        for axis, M in enumerate((M1, M2, M3)):
            rate = QQ(rng.randint(1, 5))
            at = {v: (rate if v is M else 0) for v in (M1, M2, M3)}
            middle = A[axis] not in (min(A), max(A))
            expected = 'unstable' if middle else 'stable'
            assert nonlinear_stability(S, at).verdict() == expected, (A, axis)


@pytest.mark.parametrize("M3_value, expected", [
    (3, 'stable'), (QQ(201) / 100, 'stable'), (QQ(199) / 100, 'unstable'), (1, 'unstable')])
def test_sleeping_lagrange_top(M3_value, expected):
    # A = 1, m g l = 1: the threshold is M3 = 2
    S = load('examples/heavy_top_e3.yaml')
    A, C, m, g, l = var('A C m g l')
    g1, g2, g3 = var('gamma1 gamma2 gamma3')
    at = {M1: 0, M2: 0, M3: M3_value, g1: 0, g2: 0, g3: 1,
          A: 1, C: QQ(1) / 2, m: 1, g: 1, l: 1}
    # the momentum M3 of the symmetry is an integral besides the Casimirs
    assert S.nonlinear_stability(at, integrals=[M3]).verdict() == expected
