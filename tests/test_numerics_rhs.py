"""
numerical_rhs equals the right-hand side of the symbolic equations.

For the chains of ``tests/reference/chains.py`` the package derives the
Lagrange equations E(q, dq, ddq) = 0; at random states the accelerations
are found here independently of the numerics: E is evaluated in 150-bit
arithmetic at ddq = 0 and at the unit vectors (it is linear in ddq), and
the linear system is solved in that precision. The compiled (C) and the
Python right-hand sides must agree with it to 1e-12.
"""
import random
import sys
from pathlib import Path

import numpy as np
import pytest

from sage.all import SR, RealField, matrix, vector

sys.path.insert(0, str(Path(__file__).resolve().parent))
from reference.chains import spatial_chain, random_chain  # noqa: E402

from sage_chains import sage_chain as build_chain, exact_accelerations  # noqa: E402
from sage_dynsym.numerics import numerical_rhs  # noqa: E402
from sage_dynsym.numerics.compiler import compiler  # noqa: E402

R = RealField(150)


CASES = [('spatial', n) for n in (1, 2, 3)] + [('random', seed) for seed in (3, 5, 7)]


@pytest.mark.parametrize("kind,n", CASES)
def test_rhs_equals_symbolic_solution(kind, n):
    if kind == 'spatial':
        desc = spatial_chain(n)
        rng = random.Random(100 + n)
        values = {p: rng.uniform(0.5, 2) for p in desc['parameters']}
    else:
        desc = random_chain(n, n_bodies=2, max_rotations=2, symbolic=True)
        rng = random.Random(n)
        values = desc['values']
    record = build_chain(desc).lagrangian().to_linearizer()
    backends = ['python'] + (['c'] if compiler() else [])
    rhs = {b: numerical_rhs(record, values, backend=b) for b in backends}
    names = [str(v) for v in rhs['python'].variables()]
    for _ in range(3):
        state = [rng.uniform(-3, 3) for _ in names]
        point = dict(zip(names, state), **values)
        expected = exact_accelerations(record, point)
        nq = len(record.coordinates())
        for b, f in rhs.items():
            got = f(0.0, np.array(state))
            assert np.allclose(got[:nq], state[nq:], rtol=0, atol=0)
            scale = max(1.0, float(np.max(np.abs(expected))))
            error = float(np.max(np.abs(expected - got[nq:]))) / scale
            assert error < 1e-12, (b, error)


def test_compiled_and_python_backends_report_singular_matrices():
    from sage.all import var
    from sage_dynsym.analysis.motion import SecondOrderEquations
    from sage_dynsym.errors import AnalysisError
    x, dx, ddx = var('x dx ddx')
    E = SecondOrderEquations([x * ddx + 1], [x], [dx], [ddx])
    for b in ['python'] + (['c'] if compiler() else []):
        with pytest.raises(AnalysisError, match='singular'):
            numerical_rhs(E, {}, backend=b)(0, [0.0, 1.0])


@pytest.mark.parametrize("example", ['coupled_inductors.yaml', 'nonlinear_circuit.yaml',
                                     'heavy_top_e3.yaml'])
def test_first_order_rhs_solves_the_lhs_matrix(example):
    """x' = B^{-1} F(x) for circuits (mutual inductance: B not diagonal;
    nonlinear resistors defined through values) and a Lie-Poisson system,
    with B and F evaluated in 150 bits and solved there."""
    from sage.all import function
    from sage_dynsym import load
    from sage_dynsym.description import example_path
    record = load(example_path(example)).to_linearizer()
    x = record.variables()
    rng = random.Random(len(example))
    params = sorted({str(v) for e in record.rhs() + record.lhs_matrix().list()
                     for v in SR(e).variables()} - {str(v) for v in x})
    values = {p: rng.uniform(0.5, 2) for p in params}
    # the nonlinear resistors' characteristics i = a u^3 - u (a = 0.3)
    characteristics = {f'f{k}': (lambda u: 3 * u ** 3 / 10 - u) for k in range(1, 5)}
    f = numerical_rhs(record, dict(values, **characteristics))
    for _ in range(3):
        state = [rng.uniform(-2, 2) for _ in x]
        at = {SR.var(k): R(v) for k, v in values.items()}
        at.update({v: R(s) for v, s in zip(x, state)})
        F = [SR(e) for e in record.rhs()]
        for k in range(1, 5):
            F = [e.substitute_function(function(f'f{k}'), characteristics[f'f{k}'](SR.var('w'))
                                       .function(SR.var('w'))) for e in F]
        B = matrix(R, [[R(SR(e).subs(at)) for e in row] for row in record.lhs_matrix().rows()])
        expected = B.solve_right(vector(R, [R(e.subs(at)) for e in F]))
        got = f(0.0, state)
        scale = max(1.0, max(abs(float(v)) for v in expected))
        assert max(abs(float(e) - g) for e, g in zip(expected, got)) / scale < 1e-12
