"""
Physical models only: coupled windings with a positive semi-definite
inductance matrix, mutual inductances that are constants, Newtonian fields
with a positive distance and a unit direction, structure constants given
once per pair, values that respect the declared signs.

The verdicts are checked against independent computations: the
eigenvalues of the inductance matrix by NumPy, the growth of the currents
of a resistive network of non-physical windings from the eigenvalues of
`-L^{-1} R` (a passive network cannot have a growing mode), the energy
`\\tfrac12 i^T L i` of physical windings, which can only decrease through
the resistors (d/dt = -sum R i^2), the Poisson matrix `J_ij = -c_ij^k x_k`
written by hand.
"""
import numpy as np
import pytest

from sage.all import SR, QQ, var, sqrt, matrix
from sage_dynsym import load, LiePoissonSystem, MechanicalSystem, RigidBody, NewtonianField
from sage_dynsym.circuits import Circuit
from sage_dynsym.description import example_path
from sage_dynsym.errors import CircuitError, DescriptionError, ModelError
from sage_dynsym.lie.description import lie_poisson_from_dict


def windings(L, M, positive=(), parameters=()):
    r"""A circuit of ``len(L)`` windings, each closed by a resistor ``R<k>``,
    coupled by the mutual inductances ``M[(j, k)]`` (values or texts)."""
    branches = []
    for k, value in enumerate(L, 1):        # loops through the common node 0
        branches.append({'from': 0, 'to': k, 'kind': 'inductor', 'name': f'L{k}', 'value': value})
        branches.append([k, 0, f'R{k}'])
    for (j, k), value in M.items():
        branches.append({'kind': 'mutual', 'between': [f'L{j}', f'L{k}'], 'value': value})
    return Circuit(branches, positive=positive, parameters=parameters)


def psd(A):
    return np.linalg.eigvalsh(np.array(A, dtype=float))[0] >= -1e-12


# -- coupled windings ------------------------------------------------------------

def test_numeric_inductance_matrices_against_numpy_eigenvalues():
    rng = np.random.default_rng(19)
    seen = {True: 0, False: 0}
    for _ in range(40):
        n = int(rng.integers(2, 4))
        B = rng.integers(-3, 4, size=(n, n))
        A = B @ B.T + np.diag(rng.integers(1, 3, size=n)) * int(rng.integers(0, 2))
        A = A + np.diag(rng.integers(-6, 1, size=n)) * int(rng.integers(0, 2))
        if np.any(np.diag(A) <= 0):
            continue            # a non-positive inductance is refused for its own reason
        M = {(j + 1, k + 1): int(A[j, k]) for j in range(n) for k in range(j + 1, n) if A[j, k]}
        if not M:
            continue
        expected = psd(A)
        try:
            windings([int(v) for v in np.diag(A)], M)
            accepted = True
        except CircuitError as err:
            assert "is not positive semi-definite" in err.message
            accepted = False
        # in every coupled group the verdict is NumPy's: a group of the coupling graph with
        # a negative eigenvalue makes the whole matrix indefinite, and conversely
        assert accepted == expected, A
        seen[expected] += 1
    assert seen[True] >= 5 and seen[False] >= 5


def test_floats_on_the_boundary_are_accepted_to_rounding():
    from sage.all import RR
    # perfect coupling M^2 = L1 L2 in floating point: 0.3^2 = 0.1 * 0.9 up to rounding
    assert RR(0.3)**2 != RR(0.1) * RR(0.9)
    windings([RR(0.1), RR(0.9)], {(1, 2): RR(0.3)})
    with pytest.raises(CircuitError, match="smallest eigenvalue is -6.0000"):
        windings([RR(0.1), RR(0.9)], {(1, 2): RR(0.30001)})
    # decimals of a description are exact: decided exactly
    with pytest.raises(CircuitError, match="smallest eigenvalue is -6.00006e-06 \\(the matrix "
                                           "is \\[1/10, 30001/100000"):
        windings([0.1, 0.9], {(1, 2): 0.30001})


def test_non_physical_windings_would_create_energy():
    # L = [[1, 2], [2, 1]] (M^2 > L1 L2), R = 1 on each winding: L i' = -R i has the mode
    # exp(t) -- the currents of a passive network would grow without bound
    L, R = np.array([[1.0, 2.0], [2.0, 1.0]]), np.eye(2)
    assert max(np.linalg.eigvals(-np.linalg.solve(L, R)).real) > 0.9
    with pytest.raises(CircuitError, match="not positive semi-definite"):
        windings([1, 1], {(1, 2): 2})
    # symbolic inductances: the values given to the simulation are checked against the
    # condition L1*L2 - M^2 >= 0 that the circuit states
    C = windings(['L1', 'L2'], {(1, 2): 'M'}, parameters=['M'], positive=['L1', 'L2'])
    L1, L2, M = var('L1 L2 M')
    assert [c.lhs() - c.rhs() for c in C.conditions()] == [L1 * L2 - M**2]
    values = {'L1': 1, 'L2': 1, 'M': 2, 'R1': 1, 'R2': 1}
    with pytest.raises(ModelError, match="break the condition L1\\*L2 - M\\^2 >= 0"):
        C.simulate(values, {'i1': 0.1, 'i2': 0}, 1)


def test_physical_windings_lose_energy_through_the_resistors():
    C = windings(['L1', 'L2'], {(1, 2): 'M'}, parameters=['M'], positive=['L1', 'L2'])
    values = {'L1': 1.0, 'L2': 2.0, 'M': 1.2, 'R1': 0.5, 'R2': 0.3}
    T = C.simulate(values, {'i1': 1.0, 'i2': -0.5}, 5, points=51)
    Lm = np.array([[1.0, 1.2], [1.2, 2.0]])
    i = np.array([T.values(var('i1')), T.values(var('i2'))]).T
    energy = 0.5 * np.einsum('ti,ij,tj->t', i, Lm, i)
    assert np.all(np.diff(energy) < 0) and energy[-1] < 0.5 * energy[0]


def test_symbolic_values_decided_under_the_declared_signs():
    with pytest.raises(CircuitError, match="for any value of the declared positive parameters: its "
                                           "minor -3\\*L1\\*L2"):
        windings(['L1', 'L2'], {(1, 2): '2*sqrt(L1*L2)'}, positive=['L1', 'L2'])
    assert windings(['L1', 'L2'], {(1, 2): 'sqrt(L1*L2)/2'}, positive=['L1', 'L2']).conditions() == []
    # perfect coupling is positive semi-definite (the boundary)
    assert windings(['L1', 'L2'], {(1, 2): 'sqrt(L1*L2)'}, positive=['L1', 'L2']).conditions() == []
    # undeclared signs: stated, not assumed
    C = windings(['L1', 'L2'], {(1, 2): 'k*sqrt(L1*L2)'}, parameters=['k'])
    L1, L2, k = var('L1 L2 k')
    found = [c.lhs() - c.rhs() for c in C.conditions()]
    assert found[:2] == [L1, L2] and bool((found[2] - (1 - k**2) * L1 * L2).expand() == 0)


def test_three_windings_check_every_principal_minor():
    # [[1, 1, 1], [1, 1, 1], [1, 1, 1]] is PSD (rank 1); with a 0.9 it is not
    windings([1, 1, 1], {(1, 2): 1, (1, 3): 1, (2, 3): 1})
    assert not psd([[1, 1, 1], [1, 1, 0.9], [1, 0.9, 1]])
    with pytest.raises(CircuitError, match="not positive semi-definite"):
        windings([1, 1, 1], {(1, 2): 1, (1, 3): 1, (2, 3): QQ(9) / 10})


@pytest.mark.parametrize("value", ["M*i", "M*u", "i"])
def test_a_mutual_inductance_is_a_constant(value):
    with pytest.raises(CircuitError, match="may depend on parameters and element values only"):
        windings(['L1', 'L2'], {(1, 2): value}, parameters=['M'])


def test_the_report_states_the_open_conditions(tmp_path):
    from sage_dynsym.report import report
    C = windings(['L1', 'L2'], {(1, 2): 'M'}, parameters=['M'])
    text = report(C, sections=['state_equations'])
    assert ("Conditions for the model to be physical (not decided by the declared signs): "
            "L1 >= 0, L2 >= 0, L1*L2 - M^2 >= 0") in text


def test_perfect_coupling_says_why_dP_dt_is_not_available():
    from sage_dynsym.report import report
    C = Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 0, 'L1'], [3, 4, 'L2'], [4, 3, 'R2'],
                 {'kind': 'mutual', 'between': ['L1', 'L2'], 'value': 'sqrt(L1*L2)'}])
    failed = []
    text = report(C, sections=['lyapunov', 'state_equations'], failed=failed)
    assert "dP/dt: not available (dP/dt needs the inverse of the inductance matrix, which is " \
           "singular" in text
    assert failed == [] and "section failed" not in text


# -- Newtonian fields ---------------------------------------------------------------

@pytest.mark.parametrize("r, direction, fragment", [
    (0, [1, 0, 0], "newtonian.r: the distance from the attracting centre must be positive, got 0"),
    (-2, [1, 0, 0], "must be positive, got -2"),
    ('r', [0, 0, 0], "the direction must be a unit vector, got the zero vector"),
    ('r', [2, 0, 0], "got (2, 0, 0) of length 2"),
    ('r', [0.6, 0.8000001, 0], "of length 1.00000008"),
    ('r', [1, 1, 0], "of length 1.41421356"),
    ('r', ['t', 0, 0], "a unit vector at all times"),
])
def test_newtonian_fields_that_are_not_physical(r, direction, fragment):
    nu = var('nu')
    r = SR.var(r) if isinstance(r, str) else r
    direction = [SR.var(c) if isinstance(c, str) else c for c in direction]
    with pytest.raises(ModelError, match=fragment.replace('(', '\\(').replace(')', '\\)')):
        NewtonianField(nu, r, direction)


def test_newtonian_fields_that_are():
    nu, r, a, e1, e2, e3 = var('nu r a e1 e2 e3')
    assert NewtonianField(nu, r, [sqrt(2) / 2, -sqrt(2) / 2, 0]).conditions() == [r > 0]
    assert NewtonianField(nu, 1, [0.6, 0.8, 0.0]).conditions() == []
    assert NewtonianField(nu, 1, [var('t').cos(), var('t').sin(), 0]).conditions() == []
    assert NewtonianField(nu, 1, [a.cos(), 0, a.sin()]).conditions() == []
    # symbolic direction cosines: a condition the values must satisfy
    phi = var('phi')
    S = MechanicalSystem([RigidBody('b', rotations=[(3, phi)], mass=1,
                                    inertia=matrix([[1, 0, 0], [0, 2, 0], [0, 0, 3]]))], [phi],
                         force_function=NewtonianField(nu, r, [e1, e2, e3]))
    assert S.conditions() == [e1**2 + e2**2 + e3**2 == 1, r > 0]
    good = {'nu': 1, 'r': 10, 'e1': 0.6, 'e2': 0.8, 'e3': 0}
    S.numerical_rhs(good)
    with pytest.raises(ModelError, match="break the condition e1\\^2 \\+ e2\\^2 \\+ e3\\^2 == 1"):
        S.numerical_rhs(dict(good, e2=1))
    with pytest.raises(ModelError, match="break the condition r > 0"):
        S.simulate(dict(good, r=0), {'phi': 0, 'dphi': 0}, 1)


def test_newtonian_field_in_a_file_names_the_entry(tmp_path):
    path = tmp_path / "field.yaml"
    path.write_text("kind: mechanical\nparameters: [m, nu]\ncoordinates: [phi]\n"
                    "force_function:\n  newtonian: {nu: nu, r: 0, direction: [1, 0, 0]}\n"
                    "bodies:\n  - {name: b, parent: 0, rotations: [[3, phi]], mass: m}\n")
    with pytest.raises(ModelError, match=f"{path}: force_function.newtonian.r: the distance"):
        load(str(path))


# -- structure constants ------------------------------------------------------------------

def test_structure_constants_are_given_once_per_pair():
    x, y, z = var('x y z')
    S = LiePoissonSystem({(x, y): {z: 1}, (y, z): {x: 1}, (z, x): {y: 1}}, x**2, variables=[x, y, z])
    # J_ij = -c_ij^k x_k: J_xy = -z, J_yz = -x, J_zx = -y (so(3) with this sign convention)
    J = S.poisson_matrix()
    assert (J[0, 1], J[1, 2], J[2, 0], J[1, 0]) == (-z, -x, -y, z)
    with pytest.raises(ModelError, match="the bracket \\[y, x\\] is given after \\[x, y\\]"):
        LiePoissonSystem({(x, y): {z: 1}, (y, x): {z: -1}}, x, variables=[x, y, z])
    with pytest.raises(ModelError, match="the bracket \\[x, y\\] is given twice"):
        LiePoissonSystem({(x, y): {z: 1}, (0, 1): {z: 2}}, x, variables=[x, y, z])
    with pytest.raises(ModelError, match="not skew-symmetric: \\[x, y\\] = z but \\[y, x\\] = z"):
        LiePoissonSystem({(x, y): {z: 1}, (y, x): {z: 1}}, x, variables=[x, y, z])


@pytest.mark.parametrize("brackets, fragment", [
    ([['x', 'y', {'y': 1}], ['x', 'y', {'y': 2}]], "structure_constants[1]: the bracket of x and y "
                                                   "is already given in structure_constants[0]"),
    ([['x', 'y', {'y': 1}], ['y', 'x', {'y': -1}]], "structure_constants[1]: the bracket of y and x "
                                                    "is already given"),
])
def test_structure_constants_in_files(brackets, fragment):
    data = {'kind': 'lie_poisson', 'variables': ['x', 'y'], 'hamiltonian': 'x*y',
            'algebra': {'structure_constants': brackets}}
    with pytest.raises(DescriptionError) as err:
        lie_poisson_from_dict(data, 'b.yaml')
    assert fragment in str(err.value)


# -- declared signs -------------------------------------------------------------------------

def test_lie_poisson_values_respect_the_declared_signs():
    S = load(example_path('heavy_top_e3.yaml'))
    values = {'A': 1, 'C': 2, 'm': 1, 'g': 9.81, 'l': 0.1}
    S.numerical_rhs(values)
    with pytest.raises(ModelError, match="values: C is declared positive, got -2"):
        S.numerical_rhs(dict(values, C=-2))
    state = {'M1': 0, 'M2': 0, 'M3': 1, 'gamma1': 0, 'gamma2': 0, 'gamma3': 1}
    with pytest.raises(ModelError, match="values: l is declared positive, got 0"):
        S.simulate(dict(values, l=0), state, 1)


def test_circuit_values_respect_the_declared_signs():
    C = Circuit([[1, 2, 'L1'], [2, 3, 'R1'], [3, 1, 'C1']], positive=['R1'])
    with pytest.raises(ModelError, match="values: R1 is declared positive, got -0.5"):
        C.numerical_rhs({'L1': 1, 'R1': -0.5, 'C1': 1})
