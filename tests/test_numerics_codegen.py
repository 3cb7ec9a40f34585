"""
The generated Python runs and the generated C compiles, and both agree
with the symbolic equations at random states.

The expected values come from the symbolic equations E(q, dq, ddq) of the
package evaluated in 150-bit arithmetic: M_ij = E_i(ddq = e_j) - E_i(0)
and F = -E(0) (E is linear in ddq), or the first-order right-hand side and
matrix directly.
"""
import ctypes
import random
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from sage.all import SR, RealField, var, sin, cos

from sage_dynsym import load
from sage_dynsym.analysis.motion import FirstOrderEquations
from sage_dynsym.description import example_path
from sage_dynsym.numerics import generate_code
from sage_dynsym.numerics.compiler import compiler

sys.path.insert(0, str(Path(__file__).resolve().parent))
from reference.chains import spatial_chain  # noqa: E402
from test_numerics_rhs import build_chain  # noqa: E402

R = RealField(150)


def symbolic_blocks(record, point):
    """(M flat, F) of a second-order record at ``point`` (name -> float)."""
    base = {SR.var(k): R(v) for k, v in point.items()}
    ddq = record.accelerations()
    zero = {a: R(0) for a in ddq}

    def E(at):
        return [R(e.subs(base).subs(at)) for e in record.equations()]
    e0 = E(zero)
    columns = []
    for a in ddq:
        unit = dict(zero)
        unit[a] = R(1)
        columns.append([x - y for x, y in zip(E(unit), e0)])
    n = len(ddq)
    M = [columns[j][i] for i in range(n) for j in range(n)]
    return [float(v) for v in M], [-float(v) for v in e0]


def second_order_cases():
    yield 'spherical pendulum', load(example_path('spherical_pendulum.yaml')).lagrangian()
    yield 'spatial chain N=2', build_chain(spatial_chain(2)).lagrangian()


def run_python(code, name):
    scope = {}
    exec(code, scope)       # the test runs the generated code
    return scope[name]


def compile_c(code, tmp_path, name):
    source = tmp_path / f'{name}.c'
    source.write_text(code)
    library = tmp_path / f'{name}.so'
    subprocess.run([compiler(), '-O1', '-shared', '-fPIC', '-o', str(library), str(source), '-lm'],
                   check=True, capture_output=True)
    return ctypes.CDLL(str(library))


def pointer(values):
    array = np.ascontiguousarray(values, dtype=float)
    return array, array.ctypes.data_as(ctypes.POINTER(ctypes.c_double))


@pytest.mark.parametrize("cse", [True, False])
def test_second_order_python_and_c(tmp_path, cse):
    rng = random.Random(5)
    for number, (label, model) in enumerate(second_order_cases()):
        record = model.to_linearizer()
        q = [str(v) for v in record.coordinates()]
        dq = [str(v) for v in record.velocities()]
        params = sorted({str(v) for e in record.equations() for v in e.variables()}
                        - set(q) - set(dq) - {str(v) for v in record.accelerations()})
        python = generate_code(record, 'python', cse=cse)
        assert python.language() == 'python' and 'def mass_matrix_and_forcing' in python
        f = run_python(python, 'mass_matrix_and_forcing')
        lib = compile_c(generate_code(record, 'c', cse=cse), tmp_path, f'second{number}{cse}') \
            if compiler() else None
        n = len(q)
        for _ in range(3):
            point = {k: rng.uniform(-2, 2) for k in q + dq}
            point.update({k: rng.uniform(0.5, 2) for k in params})
            M, F = symbolic_blocks(record, point)
            args = ([point[k] for k in q], [point[k] for k in dq], [point[k] for k in params])
            got_M, got_F = f(0.0, *args)
            assert np.allclose(got_M, M, rtol=1e-12, atol=1e-12), label
            assert np.allclose(got_F, F, rtol=1e-12, atol=1e-12), label
            if lib is not None:
                arrays = [pointer(a) for a in args]
                out_M, out_F = np.zeros(n * n), np.zeros(n)
                lib.mass_matrix_and_forcing(ctypes.c_double(0.0), *[p for _, p in arrays],
                                            pointer(out_M)[1], pointer(out_F)[1])
                assert np.allclose(out_M, M, rtol=1e-12, atol=1e-12), label
                assert np.allclose(out_F, F, rtol=1e-12, atol=1e-12), label


def test_first_order_with_lhs_matrix_python_and_c(tmp_path):
    # a nonlinear circuit-like system B(x) x' = F(x, t) with clashing names
    x, p, F, t = var('x p F t')
    a, b = var('a b')
    rhs = [-p * sin(x) + a * cos(t), x * p - b * F]
    B = [[1 + x ** 2, a], [0, 2 + cos(F)]]
    E = FirstOrderEquations([rhs[0], rhs[1], -F], [x, p, F],
                            lhs_matrix=[[B[0][0], B[0][1], 0], [B[1][0], B[1][1], 0],
                                        [0, 0, 1]])
    code = generate_code(E, 'python')
    f = run_python(code, 'rhs_and_lhs_matrix')
    lib = compile_c(generate_code(E, 'c'), tmp_path, 'first') if compiler() else None
    rng = random.Random(2)
    for _ in range(5):
        state = [rng.uniform(-2, 2) for _ in range(3)]
        par = [rng.uniform(0.5, 2) for _ in range(2)]   # (a, b) sorted by name
        when = rng.uniform(0, 3)
        at = {x: state[0], p: state[1], F: state[2], a: par[0], b: par[1], t: when}
        want_F = [float(e.subs(at)) for e in E.rhs()]
        want_B = [float(e.subs(at)) for e in E.lhs_matrix().list()]
        got_F, got_B = f(when, state, par)
        assert np.allclose(got_F, want_F, rtol=1e-13, atol=1e-13)
        assert np.allclose(got_B, want_B, rtol=1e-13, atol=1e-13)
        if lib is not None:
            out_F, out_B = np.zeros(3), np.zeros(9)
            s, pp = pointer(state), pointer(par)
            lib.rhs_and_lhs_matrix(ctypes.c_double(when), s[1], pp[1], pointer(out_F)[1],
                                   pointer(out_B)[1])
            assert np.allclose(out_F, want_F, rtol=1e-13, atol=1e-13)
            assert np.allclose(out_B, want_B, rtol=1e-13, atol=1e-13)


def test_generated_code_is_readable():
    L = load(example_path('spherical_pendulum.yaml')).lagrangian()
    code = generate_code(L.to_linearizer(), 'python')
    assert 'psi, theta = q' in code and 'dpsi, dtheta = dq' in code and 'g, l, m = p' in code
    assert 'math.sin(theta)' in code
    c = generate_code(L.to_linearizer(), 'c')
    assert 'const double theta = q[1];' in c and '#include <math.h>' in c


def test_constraint_blocks(tmp_path):
    """Cartesian pendulum: J = (2x, 2y) and gamma = -2(dx^2 + dy^2) by hand
    (the second derivative of x^2 + y^2 - l^2 vanishes)."""
    from sage_dynsym.analysis.motion import SecondOrderEquations
    x, y, dx, dy, ddx, ddy, mu, m, g, l = var('x y dx dy ddx ddy mu m g l')
    f = x ** 2 + y ** 2 - l ** 2
    E = SecondOrderEquations([m * ddx - 2 * mu * x, m * ddy + m * g - 2 * mu * y],
                             [x, y], [dx, dy], [ddx, ddy], constraints=[f], multipliers=[mu])
    code = generate_code(E, 'python')
    M, F, J, gamma = run_python(code, 'mass_matrix_and_forcing')(0.0, [0.3, -0.8], [1.5, -2.0],
                                                                   [9.81, 1.0, 2.0])
    assert np.allclose(M, [2, 0, 0, 2]) and np.allclose(F, [0, -2 * 9.81])
    assert np.allclose(J, [0.6, -1.6]) and np.allclose(gamma, [-2 * (1.5 ** 2 + 2.0 ** 2)])
    if compiler():
        lib = compile_c(generate_code(E, 'c'), tmp_path, 'constrained')
        outs = [np.zeros(4), np.zeros(2), np.zeros(2), np.zeros(1)]
        args = [pointer(a) for a in ([0.3, -0.8], [1.5, -2.0], [9.81, 1.0, 2.0])]
        lib.mass_matrix_and_forcing(ctypes.c_double(0.0), *[p for _, p in args],
                                    *[pointer(o)[1] for o in outs])
        assert np.allclose(outs[2], J) and np.allclose(outs[3], gamma)
