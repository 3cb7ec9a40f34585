"""
The package's own errors for wrong input, and the declared signs respected
everywhere.

- The public API walk: every function and class exported by ``sage_dynsym``
  and every public method of the main objects (Lagrangian, Routh function,
  Hamiltonian, mechanical system, circuit, Lie-Poisson system, linear
  system, stability verdict) is called with arguments of a wrong kind --
  ``None``, a number, a string, a dict, a list, a symbol, a circuit where a
  mechanical system is expected, a Lagrangian without cyclic coordinates
  where a Routh function is expected. Only the package's exceptions
  (``DynSymError``) may come out, never a ``TypeError``, ``AttributeError``
  or ``KeyError`` from inside; each call runs under an alarm.
- ``ModifiedRouthLyapunov`` of a Lagrangian without cyclic coordinates: the
  Routh function is the Lagrangian itself; for the pendulum the families
  are the levels of its energy, checked against energy conservation
  written here (the stationary points lie on the levels of their energies,
  the separatrix passes the lowest point at the speed `2\\omega`).
- Declared signs: a mass, a moment of inertia (and the triangle
  inequality), a rolling radius negative under the declared signs is
  refused naming the entry, in a description file and in Python; a value
  contradicting a declared sign is refused by ``simulate``,
  ``numerical_rhs``, ``subs``, ``stability_map`` and ``sweep``, naming the
  parameter, also for the Lagrangian and Hamiltonian of a model; what the
  declared signs leave open is a condition of the model, which the
  benchmark bicycle's data (Meijaard et al. 2007) satisfy.
"""
import inspect

import pytest
from sage.all import SR, var, cos, diagonal_matrix, pi

import sage_dynsym
from sage_dynsym import (DynSymError, Lagrangian, MechanicalSystem, RigidBody, load,
                         linearize, stability_map, sweep, ModifiedRouthLyapunov)
from sage_dynsym.circuits import Circuit
from sage_dynsym.description import example_path, model_from_dict
from sage_dynsym.errors import ModelError
from sage_dynsym.numerics.values import holds_to_rounding

SECONDS = 30

x, dx, k = var('x dx k')
CIRCUIT = Circuit([[1, 2, 'R1'], [2, 3, 'L1'], [3, 1, 'C1']])
NO_CYCLIC = Lagrangian(dx**2 / 2 - x**4 / 4 + k * x, [x])
WRONG = {'None': None, 'number': 42, 'string': 'text', 'dict': {'a': 1}, 'list': [1, 2],
         'symbol': SR.var('zz'), 'circuit': CIRCUIT, 'lagrangian': NO_CYCLIC}



def call(function, *args):
    """``None`` if ``function(*args)`` returned or raised a DynSymError, else a
    description of the foreign exception (or of the hang)."""
    from cysignals.alarm import alarm, cancel_alarm, AlarmInterrupt
    alarm(SECONDS)
    try:
        function(*args)
    except DynSymError:
        pass
    except AlarmInterrupt:
        return f"no answer within {SECONDS} s"
    except Exception as err:        # noqa: BLE001 -- what the test looks for
        return f"{type(err).__name__}: {str(err)[:120]}"
    finally:
        cancel_alarm()
    return None


def required_arguments(function):
    """The number of positional arguments ``function`` needs -- at least the
    first optional one, when it has one (``None`` if it cannot be
    inspected)."""
    try:
        parameters = inspect.signature(function).parameters.values()
    except (TypeError, ValueError):
        return None
    positional = [p for p in parameters if p.kind in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD)]
    return max(sum(1 for p in positional if p.default is p.empty), min(1, len(positional)))


def foreign_errors(function, label):
    """The calls of ``function`` with every wrong kind of argument (in every
    required position) that let a foreign exception out."""
    n = required_arguments(function)
    if not n:
        return []
    found = []
    for kind, value in WRONG.items():
        problem = call(function, *([value] * n))
        if problem:
            found.append(f"{label}({kind} x{n}): {problem}")
    return found


def public_callables():
    names = []
    for name in sage_dynsym.__all__:
        value = getattr(sage_dynsym, name)
        if callable(value) and not (inspect.isclass(value) and issubclass(value, Exception)):
            names.append(name)
    return names


@pytest.mark.parametrize("name", public_callables())
def test_public_functions_and_classes_raise_only_the_package_errors(name):
    problems = foreign_errors(getattr(sage_dynsym, name), name)
    assert not problems, "\n".join(problems)


def valid_calls():
    """For public functions and classes, arguments of a call that works: each
    argument in turn is replaced by a wrong kind of value."""
    from sage.all import sin, identity_matrix, zero_matrix
    from sage_dynsym.analysis.motion import FirstOrderEquations
    y, dy, phi, dphi, r, dr, a, b, lam, l, g, m, psi, theta = var(
        'y dy phi dphi r dr a b lam l g m psi theta')
    L = Lagrangian(dx**2 / 2 - x**2 / 2, [x])
    kepler = Lagrangian((dr**2 + r**2 * dphi**2) / 2 + 1 / r, [r, phi])
    I2, Z2, K2 = identity_matrix(2), zero_matrix(2), diagonal_matrix([a, b])
    E = sage_dynsym.lie_algebra('so3')
    M1, M2, M3 = E.variables()
    top = RigidBody('top', rotations=[(3, psi), (1, theta), (3, phi)], mass=m,
                    mass_center=[0, 0, l], inertia=diagonal_matrix([a, a, b]))
    heavy = MechanicalSystem([top], [psi, theta, phi],
                             force_function=sage_dynsym.UniformGravity([0, 0, -g]))
    decay = FirstOrderEquations([-k * x], [x])
    rolling = sage_dynsym.NonholonomicLagrangian((dx**2 + dy**2) / 2, [x, y],
                                                 nonholonomic=[dx - dy])
    poly = lam**2 + a * lam + 1
    return {
        'Lagrangian': (dx**2 / 2 - x**2 / 2, [x]), 'RouthFunction': (kepler, [phi]),
        'Hamiltonian': (L,), 'equations_cse': ([sin(x)**2 + sin(x)],),
        'CompactEquations': ([], [x]), 'NonholonomicLagrangian': ((dx**2 + dy**2) / 2, [x, y]),
        'ReducedEquations': (rolling, [dy]), 'RigidBody': ('b',),
        'UniformGravity': ([0, 0, -g],), 'NewtonianField': (k, r, [1, 0, 0]),
        'RollingDisk': ('wheel', r, 2),
        'MechanicalSystem': ([RigidBody('b', joint=[x, 0, 0], mass=1)], [x]),
        'load': (example_path('spherical_pendulum.yaml'),),
        'Circuit': ([[1, 2, 'R1'], [2, 1, 'C1']],), 'NodalAnalysis': (CIRCUIT,),
        'stationary_solutions': ([x**2], [x]), 'stationary_motions': (kepler.routh([phi]),),
        'ModifiedRouthLyapunov': (kepler.routh([phi]),), 'linearize': (L, {x: 0}),
        'LinearSystem': ([x], [[1]], [[0]], [[1]]),
        'hurwitz_matrix': (poly, lam), 'hurwitz_determinants': (poly, lam),
        'hurwitz_conditions': (poly, lam), 'lienard_chipart_conditions': (poly, lam),
        'real_negative_roots_conditions': (poly, lam),
        'conservative_stability_conditions': (lam**2 + a, lam),
        'sylvester_conditions': (K2,), 'definiteness_conditions': (K2,),
        'restrict_to_subspace': (x**2 + y**2, [x + y], [x, y]),
        'simultaneous_reduction': (I2, K2), 'kelvin_chetaev': (I2, Z2, Z2, K2),
        'equilibrium_family': ([x**2 - 1], [x], []), 'solve_exactly': ([x**2 - 1], [x]),
        'exists': ([x], [x**2 - a > 0]), 'small_damping_limit': (I2, I2, Z2, K2),
        'spectrum_regions': (lam**2 + a, lam), 'trig_rational_simplify': (sin(x)**2,),
        'LiePoissonSystem': ('so3', M1**2), 'lie_algebra': ('so3',),
        'poisson_structure': ('so3',), 'casimirs': (E,),
        'polynomial_integrals': (E, M1**2 + M2**2 + M3**2, 2),
        'euler_poisson': (heavy,), 'kirchhoff': (top,),
        'numerical_rhs': (decay, {k: 1}), 'simulate': (decay, {k: 1}, {x: 1}, 1),
        'generate_code': (decay,), 'Event': (x,), 'OperatingPoint': ('p', {x: 0}),
    }


VALID = valid_calls()


@pytest.mark.parametrize("name", sorted(VALID))
def test_each_argument_of_a_wrong_kind_raises_only_the_package_errors(name):
    function, args = getattr(sage_dynsym, name), VALID[name]
    assert call(function, *args) is None            # the call itself works
    problems = []
    for i in range(len(args)):
        for kind, value in WRONG.items():
            problem = call(function, *(args[:i] + (value,) + args[i + 1:]))
            if problem:
                problems.append(f"{name}(argument {i} = {kind}): {problem}")
    assert not problems, "\n".join(problems)


def main_objects():
    S = load(example_path('spherical_pendulum.yaml'))
    L = S.lagrangian()
    m, c = var('m c')                       # a damped oscillator
    lin = linearize(Lagrangian(m * dx**2 / 2 - k * x**2 / 2, [x], dissipation=c * dx**2 / 2),
                    {x: 0})
    return {'Lagrangian': L, 'RouthFunction': L.routh([SR.var('psi')]),
            'Hamiltonian': L.hamiltonian(), 'MechanicalSystem': S,
            'Circuit': load(example_path('rlc_ladder.yaml')),
            'LiePoissonSystem': load(example_path('heavy_top_e3.yaml')),
            'LinearSystem': lin, 'StabilityVerdict': lin.kelvin_chetaev(positive=[m, c, k])}


@pytest.fixture(scope="module")
def objects():
    return main_objects()


@pytest.mark.parametrize("kind", ['Lagrangian', 'RouthFunction', 'Hamiltonian',
                                  'MechanicalSystem', 'Circuit', 'LiePoissonSystem',
                                  'LinearSystem', 'StabilityVerdict'])
def test_methods_raise_only_the_package_errors(objects, kind):
    obj = objects[kind]
    problems = []
    for name in sorted(dir(obj)):
        method = getattr(obj, name, None) if not name.startswith('_') else None
        if callable(method) and not inspect.isclass(method) and \
                str(getattr(method, '__module__', '')).startswith('sage_dynsym'):
            problems += foreign_errors(method, f"{kind}.{name}")
    assert not problems, "\n".join(problems)


def test_a_wrong_kind_of_model_is_named_with_the_call_that_works():
    from sage_dynsym import euler_poisson, numerical_rhs
    with pytest.raises(ModelError, match=r"system: expected a mechanical system, got Circuit"):
        euler_poisson(CIRCUIT)
    with pytest.raises(ModelError, match=r"equations: .*model.numerical_rhs\(values\)"):
        numerical_rhs(NO_CYCLIC, {})
    with pytest.raises(ModelError, match=r"lagrangian: expected a Lagrangian, got Circuit"):
        sage_dynsym.Hamiltonian(CIRCUIT)
    with pytest.raises(DynSymError, match=r"model: expected a model"):
        sage_dynsym.save('model.yaml', CIRCUIT)


# -- ModifiedRouthLyapunov of a Lagrangian without cyclic coordinates ---------

def test_modified_routh_lyapunov_of_a_pendulum_gives_its_energy_levels():
    theta, dtheta, w = var('theta dtheta omega')
    L = Lagrangian(dtheta**2 / 2 + w**2 * cos(theta), [theta])
    families = ModifiedRouthLyapunov(L).invariant_manifolds()
    assert len(families) == 2                       # the two directions of motion
    C = SR.var('_C')
    for family in families:
        assert family.lhs() == dtheta
        speed = family.rhs()
        # energy conservation, written here: E = dtheta^2/2 - w^2 cos(theta)
        # is constant along each family
        assert (speed**2 / 2 - w**2 * cos(theta)).diff(theta).simplify_full() == 0
        # E = -w^2 C; the lower equilibrium (E = -w^2) lies on C = 1, the
        # upper one (E = w^2) on the separatrix C = -1, which passes the
        # lowest point at the speed 2 w
        assert speed.subs({C: 1, theta: 0}) == 0
        assert speed.subs({C: -1, theta: pi}).simplify_full() == 0
        assert abs(abs(float(speed.subs({C: -1, theta: 0, w: 3}))) - 6) < 1e-12


def test_modified_routh_lyapunov_refuses_what_is_not_a_characteristic_function():
    with pytest.raises(DynSymError, match="expected a Routh function"):
        ModifiedRouthLyapunov(CIRCUIT)


# -- declared signs: the data of a mechanical system --------------------------

PENDULUM = """\
kind: mechanical
name: pendulum
parameters: [m, l, g]
positive: [m, l, g]
coordinates: [theta]
force_function:
  uniform_gravity: [0, 0, -g]
bodies:
  - name: bob
    rotations: [[1, theta]]
    mass_center: [0, 0, -l]
    mass: {mass}
    inertia: {inertia}
"""


def pendulum_file(tmp_path, mass='m', inertia='[[m*l^2, 0, 0], [0, m*l^2, 0], [0, 0, 0]]'):
    path = tmp_path / "pendulum.yaml"
    path.write_text(PENDULUM.format(mass=mass, inertia=inertia))
    return str(path)


def test_a_symbolic_negative_mass_in_a_file_is_refused(tmp_path):
    load(pendulum_file(tmp_path))                   # the model itself is accepted
    with pytest.raises(ModelError) as info:
        load(pendulum_file(tmp_path, mass='-m'))
    message = str(info.value)
    assert "pendulum.yaml: bodies[0].mass:" in message and "-m is negative" in message
    with pytest.raises(ModelError, match=r"bodies\[0\]\.mass: .* -l\^2\*m is negative"):
        load(pendulum_file(tmp_path, mass='-m*l^2'))


def test_a_symbolic_negative_moment_of_inertia_in_a_file_is_refused(tmp_path):
    with pytest.raises(ModelError, match=r"pendulum.yaml: bodies\[0\]\.inertia: .*-l\^2\*m"):
        load(pendulum_file(tmp_path, inertia='[[-m*l^2, 0, 0], [0, m*l^2, 0], [0, 0, 0]]'))


def test_a_symbolic_negative_mass_in_python_is_refused():
    z, m, A, B, C = var('z m A B C')
    with pytest.raises(ModelError, match=r"bodies\[0\]\.mass: the mass of body 'p' must be "
                                         r"non-negative, but -m is negative"):
        MechanicalSystem([RigidBody('p', joint=[0, 0, z], mass=-m)], [z], positive=[m])
    # not negative: a mass never positive and not zero
    with pytest.raises(ModelError, match=r"-m\^2 is never positive"):
        MechanicalSystem([RigidBody('p', joint=[0, 0, z], mass=-m**2)], [z])
    # the triangle inequality C <= A + B broken for every positive A, B, C
    with pytest.raises(ModelError, match=r"bodies\[1\]\.inertia: the triangle inequality"):
        MechanicalSystem([RigidBody('a', joint=[0, 0, z], mass=m),
                          RigidBody('b', parent='a', mass=m,
                                    inertia=diagonal_matrix([A, B, A + B + C]))],
                         [z], positive=[m, A, B, C])


def test_a_symbolic_negative_rolling_radius_is_refused():
    data = {'kind': 'mechanical', 'parameters': ['m', 'r', 'A', 'C'], 'positive': ['r'],
            'coordinates': ['x', 'y', 'psi', 'theta', 'phi'],
            'bodies': [{'name': 'frame', 'joint': ['x', 'y', 0],
                        'rotations': [[3, 'psi'], [1, 'theta']]},
                       {'name': 'disk', 'parent': 'frame', 'joint': [0, 0, '-r'],
                        'rotations': [[2, 'phi']], 'mass': 'm',
                        'inertia': [['A', 0, 0], [0, 'C', 0], [0, 0, 'A']]}],
            'rolling': [{'body': 'disk', 'radius': '-r', 'axle': 2}]}
    with pytest.raises(ModelError, match=r"rolling\[0\]\.radius: the radius must be positive, "
                                         r"but -r is never positive"):
        model_from_dict(data)
    # with r undeclared, its sign is a condition of the model
    data['positive'] = []
    assert '-r > 0' in [str(c) for c in model_from_dict(data).conditions()]


def test_what_the_declared_signs_leave_open_is_a_condition_checked_at_values():
    z, a, b = var('z a b')
    S = MechanicalSystem([RigidBody('p', joint=[0, 0, z], mass=a - b)], [z])
    assert [str(c) for c in S.conditions()] == ['a - b >= 0']
    with pytest.raises(ModelError, match=r"values: the values break the condition a - b >= 0"):
        S.simulate({a: 1, b: 2}, {z: 0, 'dz': 1}, 1)
    T = S.simulate({a: 2, b: 1}, {z: 0, 'dz': 1}, 1, points=3)
    assert abs(T.values(z)[-1] - 1) < 1e-9          # free motion: z = t


def test_the_benchmark_bicycle_satisfies_the_conditions_of_its_inertias():
    S = load(example_path('whipple_bicycle.yaml'))
    conditions = S.conditions()
    # Meijaard, Papadopoulos, Ruina, Schwab, Proc. R. Soc. A 463 (2007),
    # Table 1: the benchmark's moments of inertia (kg m^2)
    benchmark = {'IRxx': 0.0603, 'IRyy': 0.12, 'IBxx': 9.2, 'IByy': 11, 'IBzz': 2.8,
                 'IBxz': 2.4, 'IHxx': 0.05892, 'IHyy': 0.06, 'IHzz': 0.00708,
                 'IHxz': -0.00756, 'IFxx': 0.1405, 'IFyy': 0.28}
    assert conditions and all(holds_to_rounding(c, benchmark)[0] for c in conditions)
    # a product of inertia too large for the rear frame's tensor
    broken = dict(benchmark, IBxz=6)
    assert not all(holds_to_rounding(c, broken)[0] for c in conditions)


# -- declared signs: the values given to the numerics and to subs ------------

VALUES = {'m': 1, 'l': 1, 'g': 9.81}
INITIAL = {'psi': 0, 'theta': 1, 'dpsi': 0, 'dtheta': 0}


@pytest.fixture(scope="module")
def spherical():
    return load(example_path('spherical_pendulum.yaml'))


def test_the_lagrangian_of_a_model_refuses_values_against_its_signs(spherical):
    L = spherical.lagrangian()
    with pytest.raises(ModelError, match=r"values: m is declared positive, got -1"):
        L.simulate(dict(VALUES, m=-1), INITIAL, 1)
    with pytest.raises(ModelError, match=r"values: l is declared positive, got -2"):
        L.numerical_rhs(dict(VALUES, l=-2))
    with pytest.raises(ModelError, match=r"values: g is declared positive, got -9.81"):
        L.hamiltonian().numerical_rhs(dict(VALUES, g=-9.81))
    with pytest.raises(ModelError, match=r"subs: g is declared positive"):
        L.subs(g=-1)
    with pytest.raises(ModelError, match=r"subs: m is declared positive"):
        L.routh([SR.var('psi')]).subs({'m': -3})
    # the motion with the declared signs is that of the model
    T = L.simulate(VALUES, INITIAL, 1, points=3)
    U = spherical.simulate(VALUES, INITIAL, 1, points=3)
    assert abs(T.values('theta') - U.values('theta')).max() < 1e-8


def test_subs_of_models_refuses_values_against_their_signs(spherical):
    with pytest.raises(ModelError, match=r"subs: g is declared positive, got -981/100"):
        spherical.subs({'g': -9.81})
    C = Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 3, 'L1'], [3, 0, 'C1']], positive=['R1'])
    with pytest.raises(ModelError, match=r"subs: R1 is declared positive, got -2"):
        C.subs({'R1': -2})
    top = load(example_path('heavy_top_e3.yaml'))
    name = str(top.positive_parameters()[0])
    with pytest.raises(ModelError, match=rf"subs: {name} is declared positive, got -1"):
        top.subs({name: -1})


def test_maps_and_sweeps_refuse_values_against_the_signs():
    cart = load(example_path('cart_pendulum_spring_damper.yaml'))
    L = cart.lagrangian()
    fixed = dict(M=1, m=1, l=1, g=9.81, k=1)
    at = {'y': 0, 'theta': 0}
    with pytest.raises(ModelError, match=r"fixed: m is declared positive, got -1"):
        stability_map(L, {'c': (0.1, 1, 3)}, fixed=dict(fixed, m=-1), at=at, client=False)
    with pytest.raises(DynSymError, match=r"parameters\[c\]: c is declared positive"):
        stability_map(L, {'c': (-1, 1, 3)}, fixed=fixed, at=at, client=False)
    # a Sage number counts as a number
    with pytest.raises(ModelError, match=r"fixed: k is declared positive, got -1"):
        stability_map(cart, {'c': (0.1, 1, 3)}, fixed=dict(fixed, k=SR(-1)), client=False)
    run = dict(initial={'y': 0, 'theta': 0.1, 'dy': 0, 'dtheta': 0}, t_end=1)
    with pytest.raises(ModelError, match=r"fixed: g is declared positive, got -1"):
        sweep(L, {'c': (0.1, 1, 2)}, fixed=dict(fixed, g=-1), simulate=run, client=False)
