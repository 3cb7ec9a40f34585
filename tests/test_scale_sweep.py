"""Parameter sweeps (sage_dynsym.scale.sweeps) in this process (client=False;
the Dask runs are in test_scale_dask.py): values against NumPy and against
an independent numerical integration (SciPy), the model calling convention
with a stand-in object, chunking and random points, failures."""
import numpy as np
import pytest
from scipy.integrate import solve_ivp
from sage.all import var

import scale_helpers
from sage_dynsym.errors import AnalysisError
from sage_dynsym.scale import sweep


def test_grid_of_a_function_against_numpy():
    W = sweep(scale_helpers.product, {'a': (0, 2, 5), 'b': (-1, 1, 3)}, fixed={'c': 2.0},
              client=False)
    assert W.parameters() == ['a', 'b'] and W.values().shape == (5, 3)
    np.testing.assert_array_equal(W.values(),
                                  2.0 * np.outer(np.linspace(0, 2, 5), np.linspace(-1, 1, 3)))
    np.testing.assert_array_equal(W.axes()['a'], np.linspace(0, 2, 5))


def test_explicit_axes_and_symbols():
    a, b = var('a b')
    W = sweep(lambda a, b: a - b, {a: np.array([0.0, 10.0]), b: (0, 1, 2)}, client=False)
    assert W.parameters() == [a, b]
    np.testing.assert_array_equal(W.values(), [[0, -1], [10, 9]])


def test_model_against_scipy_integration():
    # the stand-in's simulate has the calling convention of the package's
    # simulations; the reference integrates m x'' + c x' + k x = 0 with SciPy
    c, k = var('c k')
    W = sweep(scale_helpers.OscillatorModel(), {c: (0, 2, 5), k: (0.5, 3, 4)},
              simulate=dict(initial=1.0, t_end=3.0), reduce=scale_helpers.last_value,
              client=False)
    for i, cv in enumerate(np.linspace(0, 2, 5)):
        for j, kv in enumerate(np.linspace(0.5, 3, 4)):
            sol = solve_ivp(lambda t, z: [z[1], -cv * z[1] - kv * z[0]], (0, 3), [1.0, 0.0],
                            rtol=1e-11, atol=1e-12)
            assert abs(W.values()[i, j] - sol.y[0, -1]) < 1e-8


def test_model_values_include_fixed_and_trajectories_are_kept():
    m, c, k = var('m c k')
    W = sweep(scale_helpers.OscillatorModel(), {c: (0, 1, 2)}, fixed={k: 4.0, m: 1.0},
              simulate=dict(initial=2.0, t_end=np.pi / 2, points=2), client=False)
    assert W.values().dtype == object
    trajectory = W.values()[0]          # c = 0: x = 2 cos(2 t), at t = pi/2: -2
    assert abs(trajectory.values('x')[-1] + 2.0) < 1e-12


def test_vectorized_equals_per_point_and_chunking_does_not_matter():
    grid = {'a': (-1, 1, 33), 'b': (0, 3, 17)}
    f = lambda a, b: np.sin(a) * np.exp(-b)     # noqa: E731
    W = sweep(f, grid, client=False)
    V = sweep(f, grid, vectorized=True, client=False)
    U = sweep(f, grid, vectorized=True, client=False, chunk_size=10)
    assert np.array_equal(W.values(), V.values()) and np.array_equal(V.values(), U.values())


def test_random_samples():
    grid = {'a': (-1, 1), 'b': (2, 3)}
    W = sweep(lambda a, b: a + b, grid, samples=1000, seed=5, client=False)
    V = sweep(lambda a, b: a + b, grid, samples=1000, seed=5, client=False, chunk_size=7)
    U = sweep(lambda a, b: a + b, grid, samples=1000, seed=6, client=False)
    assert W.values().shape == (1000,)
    assert np.array_equal(W.values(), V.values()) and not np.array_equal(W.values(), U.values())
    A, B = W.axes()['a'], W.axes()['b']
    assert -1 <= A.min() and A.max() <= 1 and 2 <= B.min() and B.max() <= 3
    np.testing.assert_array_equal(W.values(), A + B)


def test_results_of_other_shapes():
    W = sweep(lambda a: np.array([[a, 1], [2, a]]), {'a': (0, 1, 3)}, client=False)
    assert W.values().shape == (3, 2, 2)
    W = sweep(lambda a: {'a': a}, {'a': (0, 1, 2)}, client=False)
    assert W.values().dtype == object and W.values()[1] == {'a': 1.0}


def test_failures():
    with pytest.raises(AnalysisError, match=r"raised ZeroDivisionError at \{'a': 0.0, 'b': 0.0\}"
                                            r": float division by zero \(and 2 other points\)"):
        sweep(lambda a, b: 1 / (a * b), {'a': (0, 1, 2), 'b': (0, 1, 2)}, client=False)
    W = sweep(lambda a, b: 1 / (a * b), {'a': (0, 1, 2), 'b': (0, 1, 2)}, client=False,
              on_error='nan')
    assert np.isnan(W.values()).sum() == 3 and W.values()[1, 1] == 1.0


@pytest.mark.parametrize("function, parameters, options, message", [
    (42, {'a': (0, 1, 3)}, {}, "expected a function of the parameters or a model"),
    (len, {'a b': (0, 1, 3)}, {}, "'a b' is not a valid keyword name"),
    (len, {'a': (0, 1, 3)}, {'fixed': {'a': 1}}, "a is both a parameter and fixed"),
    (len, {'a': (0, 1, 3)}, {'simulate': {}}, "simulate= and reduce= are for a model"),
    (len, {'a': (0, 1, 3)}, {'on_error': 'ignore'}, "on_error must be"),
    (len, {'a': (1, 0, 3)}, {}, r"parameters\[a\]: empty range"),
    (lambda a: a[:1], {'a': (0, 1, 3)}, {'vectorized': True}, "returned shape \\(1,\\) for 3"),
])
def test_bad_input(function, parameters, options, message):
    with pytest.raises(AnalysisError, match=message):
        sweep(function, parameters, client=False, **options)


def test_lagrangian_and_circuit_are_swept_as_they_are():
    # a mass on a spring: x(t) = cos(sqrt(k/m) t); an RL loop:
    # L di/dt = -R i, i(t) = exp(-R t / L)
    from sage_dynsym import Lagrangian
    from sage_dynsym.circuits import Circuit
    x, dx, m, k = var('x dx m k')
    L = Lagrangian(m * dx**2 / 2 - k * x**2 / 2, [x])
    W = sweep(L, {'k': (1, 4, 4)}, fixed={'m': 2}, client=False,
              simulate=dict(initial={x: 1, dx: 0}, t_end=1.5),
              reduce=lambda T: T.values(x)[-1])
    np.testing.assert_allclose(W.values(), np.cos(np.sqrt(np.linspace(1, 4, 4) / 2) * 1.5),
                               rtol=1e-8)
    C = Circuit([[1, 2, 'L1'], [2, 1, 'R1']])
    i1 = C.state_variables()[0][0]
    W = sweep(C, {'R1': (0.5, 2, 4)}, fixed={'L1': 0.5}, client=False,
              simulate=dict(initial={i1: 1}, t_end=1.0), reduce=lambda T: T.values(i1)[-1])
    np.testing.assert_allclose(W.values(), np.exp(-np.linspace(0.5, 2, 4) / 0.5), rtol=1e-8)
