"""
Compact equations of large systems (issue 14): the recursive (Newton-Euler)
assembly of ``MechanicalSystem.lagrangian(christoffel='recursive')`` and the
common-subexpression form ``equations_cse``.

Expected values come from SymPy's ``KanesMethod`` / ``LagrangesMethod``
(``tests/reference/sympy_chain.py``, independent of sage_dynsym) and from
the other ways sage_dynsym assembles the same equations; the random chains
of ``tests/test_mechanics_crosscheck.py`` are compared there for the
'polynomial' and 'symbolic' forms, here for the 'recursive' one.
"""
import functools
import random
import re
import sys
from pathlib import Path

import pytest
import sympy

sys.path.insert(0, str(Path(__file__).resolve().parent))
from reference.chains import random_chain, random_point, spatial_chain  # noqa: E402
from reference.sympy_chain import SympyChain  # noqa: E402
from sage_chains import sage_chain as _sage_system  # noqa: E402

from sage.all import SR, fast_callable, RDF  # noqa: E402
from sage_dynsym.dynamics.compact import equations_cse  # noqa: E402
from sage_dynsym.symbols import check_mechanical_names  # noqa: E402
from sage_dynsym.errors import ModelError  # noqa: E402
from conftest import slow_except  # noqa: E402


def _rheonomic():
    # a turntable turning at the rate w carries a pendulum whose joint
    # oscillates along the table's axis: time in rotations and in a joint
    spd = [[3, 0, 0], [0, 2, 0], [0, 0, 2]]
    return dict(bodies=[dict(parent=0, rotations=[(3, 'w*t'), (1, 'a')], joint=[0, 0, 0],
                             mass_center=[0, 1, 1], mass=2, inertia=spd),
                        dict(parent=1, rotations=[(2, 'b')], joint=[0, 0, '1 + h*sin(t)'],
                             mass_center=[1, 0, 0], mass=1, inertia=spd)],
                coordinates=['a', 'b'], parameters=['w', 'h'], gravity=[0, 0, -10],
                values=dict(w=0.7, h=0.3))


def _cases():
    cases = {f'spatial{n}': spatial_chain(n) for n in (1, 2, 3)}
    cases['rheonomic'] = _rheonomic()
    seed = 0
    for opts in ({}, {}, {'symbolic': True}, {'massless_carrier': True}, {}):
        while True:
            seed += 1
            desc = random_chain(5000 + seed, n_bodies=2 + seed % 2, **opts)
            if 1 <= len(desc['coordinates']) <= 4:
                break
        cases[f"random-seed{5000 + seed}" + "".join(f"-{o}" for o in opts)] = desc
    return cases


CASES = _cases()


def _point(desc, seed):
    rng = random.Random(seed)
    point = random_point(desc, rng, desc['values'])
    point['t'] = rng.uniform(0, 2)
    return point


def _sage_values(exprs, point):
    order = sorted(point)
    return [float(fast_callable(SR(e), vars=[SR.var(s) for s in order], domain=RDF)(
        *[point[s] for s in order])) for e in exprs]


@functools.lru_cache(maxsize=None)
def _kane(name):
    desc = CASES[name]
    chain = SympyChain(desc['bodies'], desc['coordinates'], desc['gravity'], desc['parameters'])
    return chain.kane_equations()


def _sympy_values(exprs, point):
    order = sorted(point)
    f = sympy.lambdify([sympy.Symbol(s) for s in order], exprs, modules='math')
    return [float(v) for v in f(*[point[s] for s in order])]


def _assert_close(a, b, what):
    scale = max(1.0, max(abs(x) for x in b))
    assert max(abs(x - y) for x, y in zip(a, b)) <= 1e-9 * scale, f"{what}: {a} != {b}"


def _size(exprs):
    return sum(len(str(e).replace(' ', '')) for e in exprs)


@pytest.mark.parametrize('name', slow_except(list(CASES), list(CASES)[:2]))
def test_recursive_equations_agree_with_kane(name):
    """fr + frstar of SymPy's KanesMethod is minus the Lagrange equations."""
    desc = CASES[name]
    E = _sage_system(desc).lagrangian('recursive').lagrange_equations()
    K = _kane(name)
    for seed in range(3):
        point = _point(desc, seed)
        _assert_close(_sage_values(E, point), [-v for v in _sympy_values(K, point)], name)


@pytest.mark.parametrize('name', ['spatial2', 'rheonomic'] + [
    name for name in CASES if name.endswith('massless_carrier')])
def test_recursive_equations_equal_the_polynomial_ones(name):
    desc = CASES[name]
    S = _sage_system(desc)
    R = S.lagrangian('recursive')
    E, P = R.lagrange_equations(), S.lagrangian('polynomial').lagrange_equations()
    for seed in range(3):
        point = _point(desc, seed)
        _assert_close(_sage_values(E, point), _sage_values(P, point), name)
    # the decomposition of the recursive Lagrangian is that of the system
    A, A1, A0 = S.decomposition()
    point = _point(desc, 7)
    rA, rA1, rA0 = R.decomposition()
    _assert_close(_sage_values(rA.list() + list(rA1) + [rA0], point),
                  _sage_values(A.list() + list(A1) + [A0], point), name + ' decomposition')


def test_kane_reference_agrees_with_lagrange_reference():
    """The two SymPy builders of the reference, on their own."""
    desc = CASES['rheonomic']
    chain = SympyChain(desc['bodies'], desc['coordinates'], desc['gravity'], desc['parameters'])
    L, K = chain.lagrange_equations(), chain.kane_equations()
    point = _point(desc, 3)
    _assert_close(_sympy_values(L, point), [-v for v in _sympy_values(K, point)], 'references')


@pytest.mark.slow
def test_auto_takes_the_recursive_form_for_long_chains():
    """The 5-link chain of bench/bench_chain.py: 'auto' gives the recursive
    equations, shorter than the 'symbolic' ones 'auto' gave before."""
    S = _sage_system(spatial_chain(5))
    E = S.lagrangian().lagrange_equations()
    R = S.lagrangian('recursive').lagrange_equations()
    assert all(a.is_trivially_equal(b) for a, b in zip(E, R))
    assert _size(E) < _size(S.lagrangian('symbolic').lagrange_equations())


@pytest.mark.parametrize('n', [1, 2, 3])
def test_small_chains_keep_their_form(n):
    """Below the switch, 'auto' keeps the compact polynomial form, no
    longer than the recursive one."""
    S = _sage_system(spatial_chain(n))
    E = S.lagrangian().lagrange_equations()
    assert all(a.is_trivially_equal(b)
               for a, b in zip(E, S.lagrangian('polynomial').lagrange_equations()))
    assert _size(E) <= _size(S.lagrangian('recursive').lagrange_equations())


@pytest.mark.parametrize('n', slow_except([1, 2, 3, 5], [1, 2]))
def test_equations_cse_round_trip(n):
    desc = spatial_chain(n)
    E = _sage_system(desc).lagrangian().lagrange_equations()
    C = equations_cse(E, reserved_names=['x1_'])
    # expanding the subexpressions gives the same expressions back: the
    # same structure, or (long chains: the recursive form holds products of
    # sums, which a substitution evaluates again) the same values at random
    # points
    rng = random.Random(n)
    symbols = sorted(SR(sum(E)).variables(), key=str)
    point = [rng.uniform(-2, 2) for _ in symbols]
    for a, b in zip(C.expand(), E):
        if not a.is_trivially_equal(b):
            va, vb = (fast_callable(e, vars=symbols, domain=RDF)(*point) for e in (a, b))
            assert abs(va - vb) <= 1e-9 * (1 + abs(vb)), (va, vb)
    symbols = [s for s, _ in C.subexpressions()]
    names = [str(s) for s in symbols]
    assert 'x1_' not in names and len(set(names)) == len(names)
    # every subexpression uses only earlier ones; the names are reserved
    for k, (s, e) in enumerate(C.subexpressions()):
        assert not set(e.variables()) & set(symbols[k:])
    with pytest.raises(ModelError):
        check_mechanical_names(desc['coordinates'], names[:1])
    assert all(not re.fullmatch(r'x\d+_', v) for v in desc['coordinates'] + desc['parameters'])
    assert _size([e for _, e in C.subexpressions()] + C.equations()) < _size(E)
    if n <= 3:   # (compiling the 5-link equations takes half a minute)
        point = _point(desc, 11)
        _assert_close(_sage_values(C.expand(), point), _sage_values(E, point), 'cse')


def test_equations_cse_skips_names_in_use():
    x, y, x1_ = SR.var('x y x1_')
    E = [SR.var('x2_') * (x + y) ** 2 + x1_, (x + y) ** 3]
    C = equations_cse(E, reserved_names=['x3_'])
    assert [str(s) for s, _ in C.subexpressions()] == ['x4_']
    assert all(a.is_trivially_equal(b) for a, b in zip(C.expand(), E))
