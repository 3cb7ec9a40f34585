"""
Cross-check of the mechanics core against an independent SymPy model.

Every case is a plain-data chain of rigid bodies (``reference.chains``). The
same description is built twice: with sage_dynsym (``RigidBody``,
``MechanicalSystem``, ``UniformGravity``) and with
``sympy.physics.mechanics`` (``reference.sympy_chain``: orient_axis,
v2pt_theory, RigidBody with the central inertia, ``LagrangesMethod``). The
Lagrangians and the Lagrange equations are compared numerically at random
states (q, dq, ddq). Both sides use ``E_i = d/dt dL/d(dq_i) - dL/dq_i``.

SymPy's ``LagrangesMethod`` needs minutes for chains with 6+ angles, so the
random cases are the first seeds whose chain has at most
``MAX_COORDINATES`` angles (the rotation sequences themselves stay random,
length 0..3).
"""
import functools
import math
import sys
import zlib
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest
import sympy

sys.path.insert(0, str(Path(__file__).resolve().parent))
from reference.chains import random_chain  # noqa: E402
from reference.sympy_chain import SympyChain  # noqa: E402
from sage_chains import sage_chain as sage_system  # noqa: E402

from sage.all import SR, fast_callable, RDF  # noqa: E402
from sage_dynsym.symbols import velocity
from sage_dynsym.symbols import acceleration  # noqa: E402
from conftest import slow_except  # noqa: E402

MAX_COORDINATES = 4
N_RANDOM = 20
STATES_PER_CASE = 3


# ---------------------------------------------------------------------------
# The same plain data, given to sage_dynsym
# ---------------------------------------------------------------------------

def sympy_chain(desc):
    return SympyChain(desc['bodies'], desc['coordinates'], desc['gravity'],
                      desc['parameters'])


# ---------------------------------------------------------------------------
# The cases
# ---------------------------------------------------------------------------

def _random_cases():
    # 5 cases each of 1, 2, 3 and 4 bodies; the massless carriers carry
    # another body.
    cases, seed = {}, 0
    special = {2: dict(symbolic=True), 7: dict(symbolic=True),
               9: dict(massless_carrier=True), 14: dict(massless_carrier=True)}
    while len(cases) < N_RANDOM:
        index = len(cases)
        opts = special.get(index, {})
        n_bodies = 1 + index % 4
        if opts.get('massless_carrier'):
            n_bodies = max(n_bodies, 2)
        desc = random_chain(1000 + seed, n_bodies=n_bodies, **opts)
        seed += 1
        if 1 <= len(desc['coordinates']) <= MAX_COORDINATES:
            tag = "".join(f"-{o}" for o in opts)
            cases[f"random{index:02d}-seed{999 + seed}-{n_bodies}bodies{tag}"] = desc
    return cases


def _spherical_pendulum():
    return dict(bodies=[dict(parent=0, rotations=[(3, 'psi'), (1, 'theta')],
                             joint=[0, 0, 0], mass_center=[0, 0, 'l'], mass='m',
                             inertia=[['m*l**2', 0, 0], [0, 'm*l**2', 0], [0, 0, 0]])],
                coordinates=['psi', 'theta'], parameters=['m', 'l', 'g'],
                gravity=[0, 0, '-g'], values=dict(m=1.3, l=0.7, g=9.81))


def _two_roots_and_slider():
    # Body 2 hangs from the inertial frame too (parent 0 is allowed for any
    # body); body 3 slides along body 1's z axis (joint depends on z: the
    # relative velocity is its time derivative); body 3 has no rotation.
    # principal moments about 1.93, 2.71, 3.36: a physical tensor (triangle inequality)
    spd = [[3, Fraction(1, 3), 0], [Fraction(1, 3), 3, Fraction(-1, 4)], [0, Fraction(-1, 4), 2]]
    return dict(bodies=[dict(parent=0, rotations=[(1, 'a')], joint=[0, 0, 0],
                             mass_center=[Fraction(1, 2), 0, 1], mass=2, inertia=spd),
                        dict(parent=0, rotations=[(2, 'b'), (3, 'c')], joint=[1, 2, 3],
                             mass_center=[0, Fraction(-1, 3), Fraction(1, 2)], mass=1,
                             inertia=spd),
                        dict(parent=1, rotations=[], joint=[0, 0, 'z'],
                             mass_center=[Fraction(1, 5), Fraction(1, 7), 0], mass=3,
                             inertia=spd)],
                coordinates=['a', 'b', 'c', 'z'], parameters=[],
                gravity=[0, 0, -10], values={})


CASES = {'spherical_pendulum': _spherical_pendulum(),
         'two_roots_and_slider': _two_roots_and_slider(),
         **_random_cases()}
#: what `make test` cross-checks; the other random cases run in `make test-slow`
FAST_CASES = {'spherical_pendulum', 'two_roots_and_slider', *list(CASES)[2:4]}


def test_case_set_covers_the_issue():
    """The random cases contain what issue 2 asks for."""
    random_descs = [d for name, d in CASES.items() if name.startswith('random')]
    n_bodies = {len(d['bodies']) for d in random_descs}
    lengths = {len(b['rotations']) for d in random_descs for b in d['bodies']}
    axes_sequences = {tuple(a for a, _ in b['rotations']) for d in random_descs for b in d['bodies']}
    assert n_bodies == {1, 2, 3, 4}
    assert lengths == {0, 1, 2, 3}
    assert len(axes_sequences) >= 8
    assert any(d['parameters'] for d in random_descs)
    assert any(d['bodies'][0]['mass'] == 0 and len(d['bodies']) > 1 for d in random_descs)
    assert any(b['parent'] not in (0, k - 1) for d in random_descs
               for k, b in enumerate(d['bodies'], start=1))   # a real tree, not only a path


# ---------------------------------------------------------------------------
# Numerical comparison
# ---------------------------------------------------------------------------

@functools.lru_cache(maxsize=None)
def _sympy_results(name):
    desc = CASES[name]
    chain = sympy_chain(desc)
    return chain.to_plain(chain.lagrangian), chain.lagrange_equations()


@functools.lru_cache(maxsize=None)
def _sage_results(name, christoffel='auto'):
    L = sage_system(CASES[name]).lagrangian(christoffel)
    return L, L.expr(), L.lagrange_equations()


def _names(desc):
    q = list(desc['coordinates'])
    return q, ['d' + c for c in q], ['dd' + c for c in q], list(desc['parameters'])


def _states(name, desc):
    rng = np.random.default_rng(zlib.crc32(name.encode()))
    q, dq, ddq, params = _names(desc)
    for _ in range(STATES_PER_CASE):
        state = {n: rng.uniform(-math.pi, math.pi) for n in q}
        state.update({n: rng.uniform(-2, 2) for n in dq + ddq})
        state.update(desc['values'])
        yield state


def _sympy_numeric(exprs, order):
    f = sympy.lambdify([sympy.Symbol(n) for n in order], exprs, modules='math')
    return lambda state: np.array(f(*[state[n] for n in order]), dtype=float)


def _sage_numeric(exprs, order):
    fs = [fast_callable(SR(e), vars=[SR.var(n) for n in order], domain=RDF) for e in exprs]
    return lambda state: np.array([float(f(*[state[n] for n in order])) for f in fs])


def _assert_close(a, b, what):
    scale = max(1.0, float(np.max(np.abs(b))))
    assert np.allclose(a, b, rtol=1e-9, atol=1e-9 * scale), (
        f"{what}: sage_dynsym {a} != SymPy {b} (difference {a - b})")


@pytest.mark.parametrize('name', slow_except(list(CASES), FAST_CASES))
def test_symbols_follow_the_conventions(name):
    desc = CASES[name]
    L, _, _ = _sage_results(name)
    q, dq, ddq, _ = _names(desc)
    assert [str(x) for x in L.coordinates()] == q
    assert [str(x) for x in L.velocities()] == dq == [str(velocity(SR.var(c))) for c in q]
    assert [str(x) for x in L.accelerations()] == ddq == [str(acceleration(SR.var(c))) for c in q]


@pytest.mark.parametrize('name', slow_except(list(CASES), FAST_CASES))
def test_lagrangian_agrees_with_sympy(name):
    desc = CASES[name]
    q, dq, _, params = _names(desc)
    order = q + dq + params
    L_sympy, _ = _sympy_results(name)
    _, L_sage, _ = _sage_results(name)
    f_sympy, f_sage = _sympy_numeric([L_sympy], order), _sage_numeric([L_sage], order)
    for state in _states(name, desc):
        _assert_close(f_sage(state), f_sympy(state), f"{name}: Lagrangian at {state}")


@pytest.mark.parametrize('christoffel', ['polynomial', 'symbolic', 'recursive'])
@pytest.mark.parametrize('name', slow_except(list(CASES), FAST_CASES))
def test_lagrange_equations_agree_with_sympy(name, christoffel):
    """The three ways of forming the equations (the automatic choice takes
    the polynomial one for chains this small)."""
    desc = CASES[name]
    q, dq, ddq, params = _names(desc)
    order = q + dq + ddq + params
    _, E_sympy = _sympy_results(name)
    _, _, E_sage = _sage_results(name, christoffel)
    assert len(E_sage) == len(E_sympy) == len(q)
    f_sympy, f_sage = _sympy_numeric(E_sympy, order), _sage_numeric(E_sage, order)
    for state in _states(name, desc):
        _assert_close(f_sage(state), f_sympy(state), f"{name}: Lagrange equations at {state}")


def test_reference_reproduces_example_1():
    """The SymPy reference itself gives equations (9) of doc/method.rst (times m l)."""
    _, (E_psi, E_theta) = _sympy_results('spherical_pendulum')
    psi, theta, dpsi, dtheta, ddpsi, ddtheta, m, l, g = sympy.symbols(
        'psi theta dpsi dtheta ddpsi ddtheta m l g')
    eq9_theta = l * ddtheta - l * sympy.cos(theta) * sympy.sin(theta) * dpsi**2 - g * sympy.sin(theta)
    eq9_psi = ddpsi + 2 * sympy.cot(theta) * dtheta * dpsi
    assert sympy.simplify(E_theta - m * l * eq9_theta) == 0
    assert sympy.simplify(E_psi - m * l**2 * sympy.sin(theta)**2 * eq9_psi) == 0


def test_reference_does_not_use_sage_dynsym():
    """The reference package stays independent of the code under test."""
    for path in (Path(__file__).resolve().parent / 'reference').glob('*.py'):
        for line in path.read_text().splitlines():
            words = line.split()
            assert not (words[:1] in (['import'], ['from']) and 'sage_dynsym' in line), (
                f"{path.name} imports sage_dynsym: {line}")
            assert not (words[:1] in (['import'], ['from']) and words[1].startswith('sage')), (
                f"{path.name} imports Sage: {line}")
