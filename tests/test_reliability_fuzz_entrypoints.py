"""
Property-based fuzzing (hypothesis) of the Python entry points added after
the description files: simulate, numerical_rhs, code, stability_map, sweep,
polynomial_integrals, casimirs, LiePoissonSystem, loads, constraints,
force-function lists and mutual inductances. Whatever the arguments --
numbers of every type and size, ``nan``, infinities, booleans, strings,
``None``, lists, symbols -- the only exceptions are the package's own
(``DynSymError``), nothing hangs (each example runs under an alarm), and
what is accepted is what was asked for: as many samples as ``points``, a
state of the right length, coupled windings whose inductance matrix has no
negative eigenvalue (NumPy's, computed here).

Runs are deterministic (``derandomize``): ``make test`` draws a fifth of the
examples, ``make test-slow`` all of them (``conftest.fuzz_settings``). They
are small: the limits of the calls that could run long (``max_evaluations``,
``max_points``) are set low, since the property is about the arguments, not
about the work.
"""
import string

import numpy as np
import pytest
from hypothesis import given, strategies as st
from conftest import fuzz_settings
from fuzzing import within

from sage.all import SR, var, QQ
from sage_dynsym import (DynSymError, Lagrangian, LiePoissonSystem, MechanicalSystem, RigidBody,
                         UniformGravity, NewtonianField, stability_map, sweep)
from sage_dynsym.circuits import Circuit
from sage_dynsym.numerics.trajectory import Trajectory


# a fifth of the examples in `make test`, all of them in `make test-slow` (CI)
pytestmark = pytest.mark.fuzz

SECONDS = 30


bounded = within(SECONDS)


x, dx, k, c = var('x dx k c')
SYMBOLS = [x, k, SR.var('zz')]
anything = st.one_of(
    st.integers(-3, 12), st.integers(-10**30, 10**30), st.floats(allow_nan=True, allow_infinity=True),
    st.floats(-10, 10), st.booleans(), st.none(), st.text(string.printable, max_size=6),
    st.fractions(max_denominator=7), st.complex_numbers(max_magnitude=5), st.just(QQ(1) / 3),
    st.lists(st.floats(-2, 2), max_size=3), st.sampled_from(SYMBOLS), st.just({}))
small_numbers = st.one_of(st.integers(-3, 3), st.floats(-3, 3), st.fractions(max_denominator=5))
numbers = st.one_of(small_numbers, small_numbers, anything)


def perturbed(valid, hostile=anything):
    r"""Keyword arguments: drawn from the strategies of the dict ``valid``,
    then none, one or two of them replaced by a ``hostile`` value -- so that
    most examples get past the first check and reach the next ones."""
    @st.composite
    def draw(draw):
        kwargs = draw(st.fixed_dictionaries(valid))
        for key in draw(st.lists(st.sampled_from(sorted(valid)), max_size=2, unique=True)):
            kwargs[key] = draw(hostile)
        return kwargs
    return draw()


def ranges_from(low, width, points):
    return st.builds(lambda a, w, n: (a, a + w, n), low, width, points)


@pytest.fixture(scope="module")
def oscillator():
    L = Lagrangian(dx**2 / 2 - k * x**2 / 2, [x], dissipation=c * dx**2 / 2)
    L.numerical_rhs({'k': 1, 'c': 0})          # compiled once for all the examples
    return L


@fuzz_settings(150)
@given(kwargs=perturbed({
    'points': st.integers(2, 40), 't_end': st.floats(0.1, 3), 't0': st.floats(-1, 0),
    'rtol': st.sampled_from([1e-6, 1e-10]), 'atol': st.sampled_from([1e-8, 0.0]),
    'method': st.sampled_from(['auto', 'stiff', 'RK45', 'LSODA']), 'k_value': st.floats(0.1, 4),
    'initial': st.fixed_dictionaries({'x': st.floats(-2, 2), 'dx': st.floats(-2, 2)}),
    'project': st.booleans(), 'max_step': st.floats(0.01, 1)}))
def test_simulate(oscillator, kwargs):
    kwargs = dict(kwargs)
    values, initial, t_end = {'k': kwargs.pop('k_value'), 'c': 0.1}, kwargs.pop('initial'), \
        kwargs.pop('t_end')
    result = bounded(lambda: oscillator.simulate(values, initial, t_end, max_evaluations=3000,
                                                 max_points=1000, **kwargs))
    if isinstance(result, Trajectory):
        points = kwargs['points']
        assert isinstance(points, int) and not isinstance(points, bool)
        assert len(result.times()) == points


@fuzz_settings(200)
@given(t=numbers, state=st.one_of(st.lists(numbers, max_size=3), anything,
                                  st.lists(st.floats(-5, 5), min_size=2, max_size=2)))
def test_numerical_rhs_calls(oscillator, t, state):
    f = oscillator.numerical_rhs({'k': 2, 'c': 0})
    result = bounded(lambda: f(t, state))
    if not isinstance(result, DynSymError):
        assert isinstance(result, np.ndarray) and result.shape == (2,)
        assert np.isfinite(result).all()


@fuzz_settings(80)
@given(values=st.dictionaries(st.one_of(st.sampled_from(['k', 'c', 'x', 'zz', 'not a name']),
                                        st.sampled_from(SYMBOLS)), numbers, max_size=4),
       backend=st.one_of(st.sampled_from(['auto', 'python', 'c']), anything),
       language=st.one_of(st.sampled_from(['python', 'c']), anything))
def test_numerical_rhs_values_and_code(oscillator, values, backend, language):
    bounded(lambda: oscillator.numerical_rhs(values, backend=backend))
    result = bounded(lambda: oscillator.code(language))
    if not isinstance(result, DynSymError):
        assert language in ('python', 'c')


def ranges():
    return st.one_of(ranges_from(st.floats(-2, 1), st.floats(0.1, 2), st.integers(1, 12)),
                     ranges_from(st.floats(-2, 1), st.floats(0.1, 2), st.integers(1, 12)),
                     ranges_from(st.integers(-2, 1), st.integers(1, 2), st.integers(1, 12)),
                     st.builds(lambda a, w: (a, a + w), st.floats(-2, 1), st.floats(0.1, 2)))


@fuzz_settings(120)
@given(kwargs=perturbed({
    'a_range': ranges(), 'b_range': ranges(),
    'samples': st.one_of(st.none(), st.none(), st.integers(1, 300)), 'seed': st.integers(0, 9),
    'fixed': st.just({}), 'method': st.sampled_from(['auto', 'polynomial', 'eigvals']),
    'max_points': st.just(2000)}))
def test_stability_map(kwargs):
    u, v, a, b = var('u v a b')
    kwargs = dict(kwargs)
    parameters = {a: kwargs.pop('a_range'), b: kwargs.pop('b_range')}
    result = bounded(lambda: stability_map([v, -a * u - b * v], parameters, at={u: 0, v: 0},
                                           variables=[u, v], client=False, **kwargs))
    if not isinstance(result, DynSymError):
        assert result.max_real_part().size <= 2000
        # the damped oscillator u'' + b u' + a u = 0 is asymptotically stable iff a, b > 0
        A, B = (result.axes()[a], result.axes()[b]) if kwargs['samples'] is not None else \
            np.meshgrid(result.axes()[a], result.axes()[b], indexing='ij')
        clear = (np.minimum(A, B) > 1e-6) | (np.minimum(A, B) < -1e-6)
        assert np.array_equal(result.stable()[clear], ((A > 0) & (B > 0))[clear])


@fuzz_settings(120)
@given(kwargs=perturbed({
    'a_range': ranges(), 'b_range': ranges(),
    'samples': st.one_of(st.none(), st.none(), st.integers(1, 300)), 'seed': st.integers(0, 9),
    'fixed': st.sampled_from([{}, {'c': 2}]), 'vectorized': st.booleans(),
    'max_points': st.just(2000)}))
def test_sweep(kwargs):
    def function(a, b, c=1):
        return a * b + c
    kwargs = dict(kwargs)
    parameters = {'a': kwargs.pop('a_range'), 'b': kwargs.pop('b_range')}
    result = bounded(lambda: sweep(function, parameters, client=False, **kwargs))
    if not isinstance(result, DynSymError):
        assert result.values().size <= 2000


@pytest.fixture(scope="module")
def rigid_body():
    M1, M2, M3, A = var('M1 M2 M3 A')
    return LiePoissonSystem('so3', (M1**2 + M2**2) / (2 * A) + M3**2, positive=[A])


@fuzz_settings(80)
@given(degree=st.one_of(st.integers(1, 3), st.integers(1, 3), numbers),
       new_only=st.one_of(st.booleans(), st.booleans(), anything),
       conditions=st.one_of(st.booleans(), st.booleans(), anything),
       max_basis=st.one_of(st.just(3000), st.just(3000), st.integers(-2, 50), anything))
def test_integral_searches(rigid_body, degree, new_only, conditions, max_basis):
    result = bounded(lambda: rigid_body.polynomial_integrals(degree, new_only=new_only,
                                                             conditions=conditions,
                                                             max_basis=max_basis))
    if not isinstance(result, DynSymError):
        assert isinstance(degree, int) and 1 <= degree <= 12
    bounded(lambda: rigid_body.casimirs(degree=degree, max_basis=max_basis))


names = st.sampled_from(['x', 'y', 'z', 'M1', 'a', 'b', 'not a name', '', 'lambda', 't'])
entries = st.one_of(st.sampled_from(['x', 'y', 'z', 'a', 'x*y', 'a*z', 'x^2', '1/x', 'sin(y)']),
                    numbers)


hostile_algebras = st.one_of(
    st.sampled_from(['so5', '', 'SO3', 'e3 ']),
    st.lists(st.lists(entries, min_size=3, max_size=3), min_size=3, max_size=3),
    st.dictionaries(st.tuples(names, names), st.dictionaries(names, numbers, max_size=2),
                    max_size=4),
    anything)
xs, ys, zs, a_ = var('x y z a')
#: valid (algebra, variables, hamiltonians) of small systems
SYSTEMS = [
    ('so3', None, ['M1^2 + M2^2 + a*M3^2', 'M1*M2*M3']),
    ('e3', None, ['M1^2 + M2^2 + M3^2 + a*gamma3', 'M1*gamma1']),
    ({(xs, ys): {ys: 1}}, [xs, ys], ['x*y', 'x^2 + a*y']),
    ([[0, zs, -ys], [-zs, 0, xs], [ys, -xs, 0]], ['x', 'y', 'z'], ['x^2 + a*y^2 + z^2']),
]


@st.composite
def lie_arguments(draw):
    algebra, variables, hamiltonians = draw(st.sampled_from(SYSTEMS))
    kwargs = {'algebra': algebra, 'variables': variables,
              'hamiltonian': SR(draw(st.sampled_from(hamiltonians))),
              'parameters': draw(st.sampled_from([None, ['a'], [a_]])),
              'positive': draw(st.sampled_from([(), ['a'], [a_]]))}
    hostile = {'algebra': hostile_algebras, 'variables': st.one_of(st.lists(names, max_size=4),
                                                                   anything),
               'hamiltonian': st.one_of(entries, anything), 'parameters': st.one_of(
                   st.lists(names, max_size=2), anything),
               'positive': st.one_of(st.lists(names, max_size=2), anything)}
    for key in draw(st.lists(st.sampled_from(sorted(hostile)), max_size=2, unique=True)):
        kwargs[key] = draw(hostile[key])
    return kwargs


@fuzz_settings(120)
@given(kwargs=lie_arguments())
def test_lie_poisson_systems(kwargs):
    kwargs = dict(kwargs)
    algebra, hamiltonian = kwargs.pop('algebra'), kwargs.pop('hamiltonian')
    S = bounded(lambda: LiePoissonSystem(algebra, hamiltonian, **kwargs))
    if not isinstance(S, DynSymError):
        casimirs = bounded(lambda: S.casimirs(degree=2))
        if isinstance(casimirs, list):      # each is a Casimir: {C, x_i} = 0 for every i
            assert all(S.poisson_bracket(C, v).is_zero() for C in casimirs
                       for v in S.variables())


EXPRESSIONS = ['x', 'g', 't', 'dx', 'x^2 + y^2 - 1', 'x - y', 'x^2 + y^2 + 1', '-k*x^2/2',
               '-k*dx^2', 'x*y', 'gamma3']
vectors = st.one_of(st.lists(st.one_of(small_numbers, st.sampled_from(['x', 'g', 't', 'dx'])),
                             min_size=3, max_size=3), anything)


good_vectors = st.lists(st.one_of(small_numbers, st.sampled_from(['x', 'g'])), min_size=3,
                        max_size=3)


@fuzz_settings(80)
@given(kwargs=perturbed({
    'loads': st.lists(st.fixed_dictionaries(
        {'body': st.sampled_from(['b', 1]), 'force': good_vectors},
        optional={'point': good_vectors, 'torque': good_vectors, 'axes': st.sampled_from([0, 'b'])}),
        max_size=2),
    'constraints': st.sampled_from([[], ['x^2 + y^2 - 1'], ['x - y']]),
    'terms': st.lists(st.one_of(
        st.builds(lambda v: ('uniform', v), good_vectors),
        st.builds(lambda nu, r, e: ('newtonian', nu, r, e), st.sampled_from([1, 'g']),
                  st.sampled_from([2, 'g']), st.sampled_from([[1, 0, 0], [0.6, 0.8, 0]])),
        st.sampled_from(['-k*x^2/2', 'x*y'])), max_size=3)},
    hostile=st.one_of(anything, st.lists(st.one_of(
        st.fixed_dictionaries({'body': st.one_of(st.sampled_from(['b', 1, 2, 0]), anything),
                               'force': vectors},
                              optional={'point': vectors, 'torque': vectors,
                                        'axes': st.one_of(st.sampled_from([0, 'b']), anything)}),
        st.sampled_from(['x^2 + y^2 - 1', 'x - y', 'dx', 'g', 'x', 'x^2 + y^2 + 1', '-k*dx^2']),
        st.builds(lambda v: ('uniform', v), vectors),
        st.builds(lambda nu, r, e: ('newtonian', nu, r, e), numbers, numbers, vectors),
        numbers, anything), max_size=3))))
def test_loads_constraints_and_force_function_lists(kwargs):
    loads, constraints, terms = kwargs['loads'], kwargs['constraints'], kwargs['terms']
    xx, y, g, kk = var('x y g k')

    def parse(item):
        # the test's own expressions are symbolic; any other text goes in as it is
        return SR(item) if isinstance(item, str) and item in EXPRESSIONS else item

    def field(term):
        if isinstance(term, tuple) and term[0] == 'uniform':
            vector = term[1]
            return UniformGravity([parse(v) for v in vector] if isinstance(vector, list) else vector)
        if isinstance(term, tuple):
            e = term[3]
            return NewtonianField(term[1], term[2], [parse(v) for v in e] if isinstance(e, list)
                                  else e)
        return parse(term)

    def build():
        force = [field(t) for t in terms] if isinstance(terms, list) else terms
        cons = [parse(f) for f in constraints] if isinstance(constraints, list) else constraints
        return MechanicalSystem([RigidBody('b', joint=[xx, y, 0], mass=1)], [xx, y],
                                parameters=[g, kk], force_function=force, loads=loads,
                                constraints=cons)
    S = bounded(build)
    if not isinstance(S, DynSymError):
        bounded(lambda: S.lagrangian().lagrange_equations())


@fuzz_settings(150)
@given(values=st.lists(st.one_of(st.integers(-4, 4), st.fractions(max_denominator=4),
                                  st.floats(-4, 4), st.sampled_from(['M', 'M*i', 'u', 'L1', 'k*L1',
                                                                     'sqrt(L1*L2)', '2*L2'])),
                        min_size=3, max_size=3),
       inductances=st.lists(st.one_of(st.integers(-1, 4), st.floats(0.1, 4),
                                      st.sampled_from(['L0', 'L0*(1 + i^2)'])),
                            min_size=3, max_size=3),
       between=st.one_of(st.just(None), st.lists(st.sampled_from(['L1', 'L2', 'L3', 'R1', 'X']),
                                                 min_size=0, max_size=3)),
       positive=st.lists(st.sampled_from(['L1', 'L2', 'L3', 'M']), max_size=3, unique=True))
def test_mutual_inductances(values, inductances, between, positive):
    branches = []
    for n, value in enumerate(inductances, 1):
        branches.append({'from': 0, 'to': n, 'kind': 'inductor', 'name': f'L{n}', 'value': value})
        branches.append([n, 0, f'R{n}'])
    pairs = [('L1', 'L2'), ('L1', 'L3'), ('L2', 'L3')]
    if between is not None:
        pairs[0] = between
    for pair, value in zip(pairs, values):
        branches.append({'kind': 'mutual', 'between': list(pair), 'value': value})
    C = bounded(lambda: Circuit(branches, parameters=['M', 'k', 'L0'], positive=positive))
    if isinstance(C, DynSymError):
        return
    numeric = all(not isinstance(v, str) for v in values + inductances)
    if numeric:
        L = np.diag([float(v) for v in inductances])
        for (a, b), value in zip(pairs, values):
            j, m = int(a[1]) - 1, int(b[1]) - 1
            L[j, m] = L[m, j] = float(value)
        assert np.linalg.eigvalsh(L)[0] >= -1e-9, L
