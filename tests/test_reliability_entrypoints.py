"""
Hostile arguments to the Python entry points added after the description
files: simulate, numerical_rhs, code, stability_map, sweep,
polynomial_integrals, casimirs, LiePoissonSystem, stationary_motions, save.

Each bad input of the reliability issue is here with the package's error
it now gets (class and the fragment naming the argument and the value);
each runs under an alarm, so a hang fails the test instead of stalling
the suite, and the size limits are checked before anything is allocated
(a regression would be a MemoryError, which fails the test too). Expected
values of the accepted inputs come from the mathematics, not from the code
under test: the projection of a point onto a circle is the point scaled to
the radius, the residual of a constraint is computed by hand.
"""
import math
import sys
from pathlib import Path

import numpy as np
import pytest

from sage.all import SR, var, sqrt
from sage_dynsym import (load, LiePoissonSystem, stationary_motions, stability_map, sweep,
                         save, DynSymError)
from sage_dynsym.circuits import Circuit
from sage_dynsym.description import example_path
from sage_dynsym.errors import AnalysisError, DescriptionError, ModelError

sys.path.insert(0, str(Path(__file__).resolve().parent))
from descriptions import cartesian_pendulum  # noqa: E402

SECONDS = 60


def bounded(function):
    """The value of ``function()`` or the exception it raised, within SECONDS."""
    from cysignals.alarm import alarm, cancel_alarm, AlarmInterrupt
    alarm(SECONDS)
    try:
        return function()
    except AlarmInterrupt:
        pytest.fail(f"no answer within {SECONDS} s")
    except Exception as err:       # noqa: BLE001 -- classified by the caller
        return err
    finally:
        cancel_alarm()


@pytest.fixture(scope="module")
def top():
    return load(example_path('spherical_pendulum.yaml'))


@pytest.fixture(scope="module")
def cartesian(tmp_path_factory):
    def model(constraint="x^2 + z^2 - l^2"):
        path = tmp_path_factory.mktemp("pendulum") / "pendulum.yaml"
        path.write_text(cartesian_pendulum(constraint))
        return load(str(path))
    return model


@pytest.fixture(scope="module")
def heavy_top():
    return load(example_path('heavy_top_e3.yaml'))


VALUES = {'m': 1, 'l': 1, 'g': 9.81}
INITIAL = {'psi': 0, 'theta': 1, 'dpsi': 0.1, 'dtheta': 0}


def refused(result, error, fragment):
    assert isinstance(result, error), f"expected {error.__name__}, got {result!r}"
    assert fragment in str(result), str(result)


# -- simulate and numerical_rhs -------------------------------------------

SIMULATE = [
    ("points=2.9", dict(points=2.9), ModelError, "points: expected an integer, got 2.9 (float)"),
    ("points='7'", dict(points='7'), ModelError, "points: expected an integer, got '7' (str)"),
    ("points=True", dict(points=True), ModelError, "points: expected an integer, got True"),
    ("points=10**9", dict(points=10**9), ModelError,
     "points: 1000000000 samples are more than the limit of 1000000; raise it with max_points="),
    ("rtol=-1", dict(rtol=-1), ModelError, "rtol: the value of rtol must be greater than 0"),
    ("atol=nan", dict(atol=float('nan')), ModelError, "atol: the value of atol must be a finite"),
    ("t0='0'", dict(t0='0'), ModelError, "t0: the value of t0 must be a real number, got '0'"),
    ("method=None", dict(method=None), ModelError, "method: None is not one of"),
    ("unknown option", dict(colour=1), ModelError, "unknown option 'colour'"),
    ("max_step=-1", dict(max_step=-1), ModelError, "max_step: the value of max_step must be greater"),
    ("t_end=1e12", dict(t_end=1e12, max_evaluations=5000), AnalysisError,
     "needed more than 5000 evaluations of the right-hand side"),
    ("t_end=inf", dict(t_end=float('inf')), ModelError, "t_end: the value of t_end must be a finite"),
    ("t_end=True", dict(t_end=True), ModelError, "t_end: the value of t_end must be a real number"),
    ("project='yes'", dict(project='yes'), ModelError, "project: expected True or False"),
]


@pytest.mark.parametrize("name, options, error, fragment", SIMULATE, ids=[c[0] for c in SIMULATE])
def test_simulate_arguments(top, name, options, error, fragment):
    options = dict(options)
    t_end = options.pop('t_end', 1)
    refused(bounded(lambda: top.simulate(VALUES, INITIAL, t_end, **options)), error, fragment)


def test_simulate_declared_signs_and_values(top):
    refused(bounded(lambda: top.simulate({'m': -1, 'l': 1, 'g': 9.81}, INITIAL, 1)), ModelError,
            "values: m is declared positive, got -1")
    refused(bounded(lambda: top.numerical_rhs({'m': 1, 'l': 0, 'g': 9.81})), ModelError,
            "values: l is declared positive, got 0")
    refused(bounded(lambda: top.simulate({'m': '1', 'l': 1, 'g': 9.81}, INITIAL, 1)), ModelError,
            "the value of m must be a real number, got '1' (str)")
    refused(bounded(lambda: top.simulate(VALUES, {'psi': 'a', 'theta': 1, 'dpsi': 0, 'dtheta': 0},
                                         1)), ModelError, "the value of psi must be a real number")


RHS_CALLS = [
    ("t='a'", ('a', [0, 1, 0.1, 0]), "the value of t must be a real number, got 'a'"),
    ("t=nan", (float('nan'), [0, 1, 0.1, 0]), "the value of t must be a finite real number"),
    ("strings", (0, ['a', 'b', 'c', 'd']), "the state must be 4 real numbers"),
    ("numeric strings", (0, ['1', '2', '3', '4']), "the state must be 4 real numbers"),
    ("booleans", (0, [True, False, True, False]), "the state must be 4 real numbers"),
    ("None", (0, None), "the state must be 4 real numbers, got None"),
    ("a number", (0, 5), "the state must be 4 real numbers, got 5"),
    ("too short", (0, [1.0, 2.0]), "the state must have 4 entries, got 2"),
    ("a matrix", (0, [[1, 2], [3, 4]]), "the state must have 4 entries, got shape (2, 2)"),
    ("nan", (0, [0, float('nan'), 0, 0]), "the state must be 4 finite real numbers"),
    ("complex", (0, [1j, 0, 0, 0]), "the state must be 4 real numbers"),
]


@pytest.mark.parametrize("name, arguments, fragment", RHS_CALLS, ids=[c[0] for c in RHS_CALLS])
def test_numerical_rhs_calls(top, name, arguments, fragment):
    f = top.numerical_rhs(VALUES)
    refused(bounded(lambda: f(*arguments)), ModelError, "numerical_rhs: " + fragment)


def test_numerical_rhs_accepts_sage_numbers(top):
    from sage.all import pi, QQ
    f = top.numerical_rhs(VALUES)
    x = [0, float(pi) / 3, 0.1, 0]
    assert np.array_equal(f(QQ(0), [0, pi / 3, QQ(1) / 10, 0]), f(0.0, np.array(x)))


# -- constraints ------------------------------------------------------------

def test_initial_state_off_the_constraints_is_refused_with_its_residuals(cartesian):
    S = cartesian()
    # on the circle x^2 + z^2 = l^2 = 1: f = 2^2 + 0 - 1 = 3; velocity 2 x dx + 2 z dz = 0
    err = bounded(lambda: S.simulate({'m': 1, 'l': 1, 'g': 1}, {'x': 2, 'z': 0, 'dx': 0, 'dz': 1},
                                     1, points=3))
    refused(err, ModelError, "initial: the initial state is off the constraints: residuals f = [3] "
                             "(positions), J dq + df/dt = [0] (velocities)")
    # a velocity across the circle: 2 x dx = 2 at x = 1
    err = bounded(lambda: S.simulate({'m': 1, 'l': 1, 'g': 1}, {'x': 1, 'z': 0, 'dx': 1, 'dz': 0},
                                     1, points=3))
    refused(err, ModelError, "residuals f = [0] (positions), J dq + df/dt = [2] (velocities)")


def test_projection_on_request_is_the_nearest_point_and_is_reported(cartesian):
    S = cartesian()
    q = np.array([1.2, -1.6])           # |q| = 2: the nearest point of the unit circle is q/2
    with pytest.warns(UserWarning, match="projected onto the constraints"):
        T = S.simulate({'m': 1, 'l': 1, 'g': 1}, {'x': q[0], 'z': q[1], 'dx': 0, 'dz': 0}, 1,
                       points=3, project=True)
    x0, z0 = T.values(var('x'))[0], T.values(var('z'))[0]
    assert abs(x0 - 0.6) < 1e-12 and abs(z0 + 0.8) < 1e-12
    assert max(abs(x**2 + z**2 - 1) for x, z in zip(T.values(var('x')), T.values(var('z')))) < 1e-9


def test_rounding_residuals_are_on_the_constraints(cartesian):
    S = cartesian()
    a = 0.3
    T = S.simulate({'m': 1, 'l': 1, 'g': 1}, {'x': math.sin(a), 'z': -math.cos(a),
                                               'dx': math.cos(a), 'dz': math.sin(a)}, 1, points=3)
    assert abs(T.values(var('x'))[0] - math.sin(a)) < 1e-15


@pytest.mark.parametrize("constraint, fragment", [
    ("x^2 + z^2 + l^2", "no regular real point"),          # empty over the reals
    ("(x^2 + z^2 - l^2)^2", "the Jacobian of the constraints has rank 0 < 1"),   # singular
])
def test_constraints_without_a_regular_real_point_are_refused_before_integrating(
        cartesian, constraint, fragment):
    S = cartesian(constraint)
    err = bounded(lambda: S.simulate({'m': 1, 'l': 1, 'g': 1}, {'x': 1, 'z': 0, 'dx': 0, 'dz': 0},
                                     1, points=3, project=True))
    refused(err, AnalysisError, fragment)
    assert "LinAlgError" not in repr(err)


# -- generated code ---------------------------------------------------------

def test_code_language_and_flags(top):
    refused(bounded(lambda: top.code('fortran')), AnalysisError,
            "language must be 'python' or 'c', got 'fortran'")


# -- Lie-Poisson systems ------------------------------------------------------

INTEGRALS = [
    ("degree=inf", lambda S: S.polynomial_integrals(float('inf')), "expected an integer, got inf"),
    ("degree=2.9", lambda S: S.polynomial_integrals(2.9), "expected an integer, got 2.9"),
    ("degree='2'", lambda S: S.polynomial_integrals('2'), "expected an integer, got '2' (str)"),
    ("degree=True", lambda S: S.casimirs(degree=True), "expected an integer, got True (bool)"),
    ("degree=0", lambda S: S.casimirs(degree=0), "expected at least 1, got 0"),
    ("degree=50", lambda S: S.polynomial_integrals(50),
     "polynomial_integrals: 50 is more than the limit of 12; raise it with max_degree="),
    ("degree=10**6", lambda S: S.casimirs(degree=10**6),
     "casimirs: 1000000 is more than the limit of 12"),
    ("basis", lambda S: S.casimirs(degree=12, max_degree=20),
     "degree 12 in 6 variables has 18563 monomials, more than the limit of 3000"),
    ("new_only='yes'", lambda S: S.polynomial_integrals(1, new_only='yes'),
     "new_only: expected True or False, got 'yes'"),
    ("max_basis=-1", lambda S: S.casimirs(max_basis=-1), "max_basis: expected at least 1"),
]


@pytest.mark.parametrize("name, call, fragment", INTEGRALS, ids=[c[0] for c in INTEGRALS])
def test_integral_searches(heavy_top, name, call, fragment):
    refused(bounded(lambda: call(heavy_top)), AnalysisError, fragment)


def test_basis_size_is_the_number_of_monomials():
    from itertools import combinations_with_replacement
    from sage_dynsym.lie.integrals import basis_size
    for n, d in [(3, 4), (6, 2), (10, 3)]:
        monomials = sum(1 for k in range(1, d + 1)
                        for _ in combinations_with_replacement(range(n), k))
        assert basis_size(n, d) == monomials


def test_lie_poisson_system_arguments():
    M1 = var('M1')
    refused(bounded(lambda: LiePoissonSystem('so3', M1**2, positive=['not a name'])), ModelError,
            "positive: expected symbols or their names, got 'not a name'")
    refused(bounded(lambda: LiePoissonSystem('so3', M1**2, parameters=['a b'])), ModelError,
            "parameters: expected symbols or their names, got 'a b'")
    refused(bounded(lambda: LiePoissonSystem('so3', M1**2, positive=M1)), ModelError,
            "positive: expected a list of symbols or names")


# -- stationary motions: never a false answer -----------------------------------

def test_solve_for_a_symbol_that_is_not_an_unknown(top):
    R = top.lagrangian().routh([var('psi')])
    err = bounded(lambda: stationary_motions(R, solve_for=[var('zz')]))
    refused(err, AnalysisError, "solve_for: zz is not an unknown of the model; the unknowns are "
                                "theta, g, l, m, p_psi")
    refused(bounded(lambda: stationary_motions(R, solve_for=['not a name'])), AnalysisError,
            "'not a name' is not an unknown of the model")
    refused(bounded(lambda: stationary_motions(R, positive=['not a name'])), AnalysisError,
            "positive: expected symbols or their names")


def test_an_equation_free_of_the_unknowns_is_not_called_inconsistent():
    from sage_dynsym import Lagrangian
    x, y, dx, dy, k = var('x y dx dy k')
    L = Lagrangian((dx**2 + dy**2) / 2 - (x**2 + k * y**2) / 2, [x, y])
    # solving for x alone: the equation k*y = 0 involves no unknown
    err = bounded(lambda: stationary_motions(L, solve_for=[x]))
    refused(err, AnalysisError, "the equation k*y == 0 does not involve the unknowns x")
    # with both coordinates the family of equilibria is found, not "inconsistent"
    sols = stationary_motions(L, solve_for=[x, y])
    assert not sols.is_empty()


# -- maps and sweeps ------------------------------------------------------------

MAPS = [
    ("10^5 x 10^5", lambda a, b: {a: (0, 1, 10**5), b: (0, 1, 10**5)}, {},
     "parameters: 10000000000 points are more than the limit of 10000000"),
    ("samples 10^10", lambda a, b: {a: (0, 1), b: (0, 1)}, dict(samples=10**10),
     "samples: 10000000000 points are more than the limit of 10000000"),
    ("n=True", lambda a, b: {a: (0, 1, True), b: (0, 1, 2)}, {}, "and an integer n, got (0, 1, True)"),
    ("n=2.0", lambda a, b: {a: (0, 1, 2.0), b: (0, 1, 2)}, {}, "and an integer n, got (0, 1, 2.0)"),
    ("low='0'", lambda a, b: {a: ('0', 1, 3), b: (0, 1, 2)}, {}, "with real numbers low, high"),
    ("overflowing range", lambda a, b: {a: (-1e308, 1e308, 5), b: (0, 1, 2)}, {},
     "too wide for floating point"),
    ("seed=-1", lambda a, b: {a: (0, 1), b: (0, 1)}, dict(samples=5, seed=-1), "seed: expected at least 0"),
    ("seed=1.5", lambda a, b: {a: (0, 1), b: (0, 1)}, dict(samples=5, seed=1.5), "seed: expected an integer"),
    ("max_points=0", lambda a, b: {a: (0, 1, 2), b: (0, 1, 2)}, dict(max_points=0),
     "max_points: expected at least 1"),
    ("chunk_size=2.5", lambda a, b: {a: (0, 1, 2), b: (0, 1, 2)}, dict(chunk_size=2.5),
     "chunk_size must be a positive integer"),
    ("workers=10^5", lambda a, b: {a: (0, 1, 2), b: (0, 1, 2)}, dict(workers=10**5, client=None),
     "workers: 100000 is more than the limit of 256"),
]


@pytest.mark.parametrize("name, ranges, options, fragment", MAPS, ids=[c[0] for c in MAPS])
def test_stability_map_arguments(name, ranges, options, fragment):
    x, y, a, b = var('x y a b')
    options = dict(options)
    options.setdefault('client', False)
    err = bounded(lambda: stability_map([y, -a * x - b * y], ranges(a, b), at={x: 0, y: 0},
                                        variables=[x, y], **options))
    refused(err, AnalysisError, fragment)


@pytest.mark.parametrize("name, ranges, options, fragment", MAPS[:8], ids=[c[0] for c in MAPS[:8]])
def test_sweep_arguments(name, ranges, options, fragment):
    err = bounded(lambda: sweep(lambda a, b: a * b, ranges('a', 'b'), client=False, **options))
    refused(err, AnalysisError, fragment)


def test_maps_and_sweeps_of_models_respect_declared_signs():
    C = Circuit([[1, 2, 'L1'], [2, 3, 'R1'], [3, 1, 'C1']], positive=['L1', 'R1', 'C1'])
    refused(bounded(lambda: stability_map(C, {'R1': (0.5, 1, 3)}, fixed={'L1': -1, 'C1': 1},
                                          client=False)),
            ModelError, "fixed: L1 is declared positive, got -1")
    refused(bounded(lambda: stability_map(C, {'R1': (-1, 1, 3)}, fixed={'L1': 1, 'C1': 1},
                                          client=False)),
            AnalysisError, "R1 is declared positive: its values must be positive")
    refused(bounded(lambda: stability_map(C, {'R1': (0.5, 1, 3)}, fixed={'L1': 1, 'C1': 1},
                                          at={'zz': 1}, client=False)),
            AnalysisError, "at: zz is not a state variable of the model; the state variables are "
                           "i1, u2")
    run = dict(initial={'i1': 1, 'u2': 0}, t_end=1, points=2)
    refused(bounded(lambda: sweep(C, {'R1': (0.5, 1, 2)}, fixed={'L1': 0, 'C1': 1},
                                  simulate=run, client=False)),
            ModelError, "fixed: L1 is declared positive, got 0")
    refused(bounded(lambda: sweep(C, {'R1': (0, 1, 2)}, fixed={'L1': 1, 'C1': 1},
                                  simulate=run, client=False)),
            AnalysisError, "R1 is declared positive: its values must be positive")
    # positive values pass: the series RLC loop, L i' = u - R i, C u' = -i (the state
    # equations of the circuit), integrated here independently
    from scipy.integrate import solve_ivp
    W = sweep(C, {'R1': (0.5, 1, 2)}, fixed={'L1': 1, 'C1': 1}, simulate=run, client=False,
              reduce=lambda T: T.values(var('i1'))[-1])
    for R, found in zip((0.5, 1.0), W.values()):
        exact = solve_ivp(lambda t, s: [s[1] - R * s[0], -s[0]], (0, 1), [1, 0], rtol=1e-11,
                          atol=1e-13).y[0, -1]
        assert abs(found - exact) < 1e-8


def test_map_of_a_mechanical_model_names_its_coordinates(top):
    err = bounded(lambda: stability_map(top, {'l': (0.5, 1, 3)}, fixed={'m': 1, 'g': 1},
                                        at={'zz': 1}, client=False))
    refused(err, AnalysisError, "at: zz is not a coordinate of the model; the coordinates are "
                                "psi, theta")


# -- save -----------------------------------------------------------------------------

@pytest.mark.parametrize("path, fragment", [
    ("a\x00b.yaml", "cannot write the file: embedded null byte"),
    (42, "expected a file name, got 42"),
    ("", "expected a file name"),
    ("/no/such/dir/x.yaml", "cannot write the file: No such file or directory"),
])
def test_save_to_names_that_are_not_files(top, path, fragment):
    refused(bounded(lambda: save(top, path)), DescriptionError, fragment)


def test_every_error_here_is_the_packages():
    # the classes used above are the package's own, derived from DynSymError
    for error in (ModelError, AnalysisError, DescriptionError):
        assert issubclass(error, DynSymError)
