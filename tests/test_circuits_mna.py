"""
State equations of any solvable circuit (modified nodal analysis with a
normal tree), checked against an independent descriptor-system analysis.

The reference below is written here from Kirchhoff's laws and the element
laws only (numpy/scipy; no code shared with sage_dynsym): unknowns are the
node potentials and the branch currents, the equations KCL at every node
but one per connected part, one grounded node per part and one law per
element, giving a pencil ``E x' + A x + b = 0``. Its finite generalized
eigenvalues are the natural frequencies of the circuit, its pencil is
singular exactly when the circuit has no unique solution (a loop of voltage
sources, a cut-set of current sources), and ``A x + b = 0`` is the DC
operating point.

Conventions (sage_dynsym.circuits.elements): branch [a, b, X] has current
i along a->b and voltage u = v(b) - v(a); R: u = -R i, L: u = -L di/dt
(with mutual terms), C: i = -C du/dt, E: u = E, I: i = I.
"""
import sys
from pathlib import Path

import numpy as np
import pytest
from scipy.linalg import eig

from sage.all import SR, QQ, matrix, function
from sage_dynsym.circuits import Circuit
from sage_dynsym.errors import CircuitError

sys.path.insert(0, str(Path(__file__).resolve().parent))
from reference.numerics import same_multiset  # noqa: E402


# ----------------------------------------------------------------------------
# independent reference: descriptor system from Kirchhoff's laws
# ----------------------------------------------------------------------------

def _parts(nnodes, br):
    parent = list(range(nnodes))

    def find(v):
        while parent[v] != v:
            v = parent[v]
        return v
    for b in br:
        parent[find(b['tail'])] = find(b['head'])
    return [find(v) for v in range(nnodes)]


def descriptor(nnodes, br, couplings, sources=None):
    """E, A, b of E x' + A x + b = 0, x = (potentials, branch currents)."""
    m = len(br)
    size = nnodes + m
    E, A, b = np.zeros((size, size)), np.zeros((size, size)), np.zeros(size)
    root = _parts(nnodes, br)
    grounds = sorted(set(root))
    row = 0
    for v in range(nnodes):                        # KCL, ground rows instead
        if v in grounds:
            A[row, v] = 1
        else:
            for k, x in enumerate(br):
                if x['tail'] == v:
                    A[row, nnodes + k] += 1
                if x['head'] == v:
                    A[row, nnodes + k] -= 1
        row += 1
    mutual = {}
    for ka, kb, M in couplings:
        mutual.setdefault(ka, []).append((kb, M))
        mutual.setdefault(kb, []).append((ka, M))
    for k, x in enumerate(br):
        h, tl, i = x['head'], x['tail'], nnodes + k
        kind, val = x['kind'], x['val']
        src = (sources or {}).get(x['name'], 0.0)
        if kind == 'R':
            A[row, h], A[row, tl], A[row, i] = 1, -1, val
        elif kind == 'L':
            A[row, h], A[row, tl] = 1, -1
            E[row, i] = val
            for kb, M in mutual.get(k, []):
                E[row, nnodes + kb] += M
        elif kind == 'C':
            A[row, i] = 1
            E[row, h], E[row, tl] = val, -val
        elif kind == 'E':
            A[row, h], A[row, tl] = 1, -1
            b[row] = -src
        elif kind == 'I':
            A[row, i] = 1
            b[row] = -src
        row += 1
    return E, A, b


def is_singular_pencil(E, A, rng):
    for _ in range(3):
        s = complex(rng.normal(), rng.normal())
        sv = np.linalg.svd(s * E + A, compute_uv=False)
        if sv[-1] > 1e-10 * sv[0]:
            return False
    return True


def nonsingular(M):
    sv = np.linalg.svd(M, compute_uv=False)
    return sv[-1] > 1e-10 * sv[0]


def natural_frequencies(E, A):
    alpha, beta = eig(-A, E, homogeneous_eigvals=True)[0]
    finite = np.abs(beta) > 1e-9 * np.abs(alpha)
    return alpha[finite] / beta[finite]


# ----------------------------------------------------------------------------
# random circuits
# ----------------------------------------------------------------------------

KINDS = ['R', 'L', 'C', 'E', 'I']


def random_circuit(rng, weights=(4, 3, 3, 1, 1), mutual=0.5):
    nnodes = int(rng.integers(3, 9))
    pairs = [(int(rng.integers(0, v)), v) for v in range(1, nnodes)]
    pairs += [tuple(int(x) for x in rng.choice(nnodes, 2, replace=False))
              for _ in range(int(rng.integers(1, nnodes + 1)))]
    p = np.array(weights, dtype=float) / sum(weights)
    count = {k: 0 for k in KINDS}
    br, entries, values = [], [], {}
    for a, c in pairs:
        if rng.random() < 0.5:
            a, c = c, a
        kind = str(rng.choice(KINDS, p=p))
        count[kind] += 1
        name = f"{kind}{count[kind]}"
        val = QQ(int(rng.integers(500, 2000))) / 1000
        br.append({'kind': kind, 'tail': a, 'head': c, 'name': name, 'val': float(val)})
        entries.append([a, c, name])
        if kind in 'RLC':
            values[SR.var(name)] = val
    inductors = [k for k, x in enumerate(br) if x['kind'] == 'L']
    couplings, parameters = [], []
    if len(inductors) >= 2 and rng.random() < mutual:
        ka, kb = (int(x) for x in rng.choice(inductors, 2, replace=False))
        k = QQ(int(rng.integers(-600, 600))) / 1000
        M = k * (values[SR.var(br[ka]['name'])] * values[SR.var(br[kb]['name'])])
        # a rational M with |M| < 0.6 sqrt(La Lb): the inductance matrix stays definite
        M = QQ(round(float(M) * 1000)) / 1000
        couplings.append((ka, kb, float(M)))
        entries.append({'kind': 'mutual', 'between': [br[ka]['name'], br[kb]['name']],
                        'value': 'M1'})
        parameters.append('M1')
        values[SR.var('M1')] = M
    return nnodes, br, couplings, entries, parameters, values


def package_matrices(C, values, sources=None):
    """B, J, F(0) of the package's state equations at numeric values."""
    xs = [x for x, _ in C.state_variables()]
    point = dict(values)
    for b in C.branches():
        if b.kind in ('voltage_source', 'current_source'):
            point[SR.var(b.name)] = (sources or {}).get(b.name, 0)
    F = [SR(f).subs(point) for f in C.state_equations()]
    B = np.array([[float(e) for e in row] for row in
                  matrix(SR, C.lhs_matrix()).subs(point).rows()]) if xs else \
        np.zeros((0, 0))
    J = np.array([[float(f.diff(x)) for x in xs] for f in F]).reshape(len(xs), len(xs))
    F0 = np.array([float(f.subs({x: 0 for x in xs})) for f in F])
    return xs, B, J, F0


@pytest.mark.parametrize("seed", range(24))
def test_natural_frequencies_and_dc_point_match_nodal_analysis(seed):
    rng = np.random.default_rng(7100 + seed)
    nnodes, br, couplings, entries, parameters, values = random_circuit(rng)
    C = Circuit(entries, parameters=parameters)
    E, A, _ = descriptor(nnodes, br, couplings)
    if is_singular_pencil(E, A, rng):
        with pytest.raises(CircuitError):
            C.state_equations()
        return
    xs, B, J, _ = package_matrices(C, values)
    reference = natural_frequencies(E, A)
    ours = np.linalg.eigvals(np.linalg.solve(B, J)) if xs else []
    assert same_multiset(ours, reference), (entries, ours, reference)
    # DC operating point, where it is unique
    sources = {x['name']: float(rng.integers(-20, 20)) / 4 for x in br if x['kind'] in 'EI'}
    _, _, b = descriptor(nnodes, br, couplings, sources)
    unique = nonsingular(A)
    _, _, J, F0 = package_matrices(C, values, {k: QQ(v) for k, v in sources.items()})
    if not xs:
        return
    assert unique == nonsingular(J)
    if unique:
        z = np.linalg.solve(A, -b)
        x = np.linalg.solve(J, -F0)
        where = {name: k for k, name in enumerate(x_['name'] for x_ in br)}
        for value, (_, name) in zip(x, C.state_variables()):
            k = where[name]
            if br[k]['kind'] == 'L':
                expected = z[nnodes + k]
            else:
                expected = z[br[k]['head']] - z[br[k]['tail']]
            assert value == pytest.approx(expected, rel=1e-8, abs=1e-8), (entries, name)


def test_random_circuits_cover_reduced_states_and_bad_input():
    # the random family above exercises capacitor loops, inductor cut-sets,
    # circuits without Brayton-Moser split and circuits without solution
    seen = {'reduced': 0, 'no split': 0, 'no solution': 0}
    for seed in range(24):
        rng = np.random.default_rng(7100 + seed)
        nnodes, br, couplings, entries, parameters, values = random_circuit(rng)
        C = Circuit(entries, parameters=parameters)
        E, A, _ = descriptor(nnodes, br, couplings)
        if is_singular_pencil(E, A, rng):
            seen['no solution'] += 1
            continue
        states = len(C.state_variables())
        if states < sum(x['kind'] in 'LC' for x in br):
            seen['reduced'] += 1
        if not C.has_mixed_potential():
            seen['no split'] += 1
    assert seen['reduced'] >= 3 and seen['no split'] >= 3 and seen['no solution'] >= 1, seen


@pytest.mark.parametrize("seed", range(4))
def test_subs_with_floats_gives_the_same_frequencies(seed):
    rng = np.random.default_rng(7200 + seed)
    while True:
        nnodes, br, couplings, entries, parameters, values = random_circuit(rng)
        E, A, _ = descriptor(nnodes, br, couplings)
        if not is_singular_pencil(E, A, rng):
            break
    C = Circuit(entries, parameters=parameters)
    numeric = C.subs({k: float(v) for k, v in values.items()})
    xs, B, J, _ = package_matrices(numeric, {})
    if xs:
        assert same_multiset(np.linalg.eigvals(np.linalg.solve(B, J)),
                             natural_frequencies(E, A))


def test_complete_circuits_keep_the_mixed_potential_and_agree_with_nodal_analysis():
    rng = np.random.default_rng(7300)
    checked = 0
    for _ in range(60):
        nnodes, br, couplings, entries, parameters, values = random_circuit(rng)
        C = Circuit(entries, parameters=parameters)
        if not C.has_mixed_potential():
            continue
        A = C.nodal_analysis()
        assert A.state_variables() == C.state_variables()
        for f, g in zip(A.state_equations(), C.state_equations()):
            assert bool((f - g).simplify_rational() == 0), (entries, f, g)
        assert (A.lhs_matrix() - C.lhs_matrix()).is_zero()
        checked += 1
    assert checked >= 5


# ----------------------------------------------------------------------------
# transformer with galvanically isolated sides
# ----------------------------------------------------------------------------

def test_transformer_with_isolated_sides():
    entries = [[0, 1, 'E1'], [1, 2, 'R1'], [2, 0, 'L1'], [3, 4, 'L2'], [4, 3, 'R2'],
               [4, 3, 'C2'], {'kind': 'mutual', 'between': ['L1', 'L2'], 'value': 'M'}]
    C = Circuit(entries, parameters=['M'])
    assert [n for _, n in C.state_variables()] == ['L1', 'L2', 'C2']
    values = {SR.var('R1'): 1, SR.var('L1'): 2, SR.var('L2'): QQ(3) / 2,
              SR.var('R2'): QQ(1) / 3, SR.var('C2'): QQ(1) / 2, SR.var('M'): 1}
    br = [{'kind': k[0], 'tail': a, 'head': b, 'name': k, 'val': float(values.get(SR.var(k), 0))}
          for a, b, k in entries[:-1]]
    nodes = {0: 0, 1: 1, 2: 2, 3: 3, 4: 4}
    E, A, _ = descriptor(len(nodes), br, [(2, 3, 1.0)])
    xs, B, J, _ = package_matrices(C, values)
    assert same_multiset(np.linalg.eigvals(np.linalg.solve(B, J)), natural_frequencies(E, A))
    # the secondary is driven only through M: L1 i1' + M i2' = ..., M i1' + L2 i2' = ...
    assert C.lhs_matrix()[0, 1] == SR.var('M')
    # both Lagrangians: one grounded node per part (node 1 follows E1), three loops
    assert len(C.lagrangian(method="node").coordinates()) == 2
    assert len(C.lagrangian(method="loop").coordinates()) == 3
    # parts joined neither by a branch nor by a coupling are still refused
    with pytest.raises(CircuitError, match="disconnected"):
        Circuit(entries[:-1])


# ----------------------------------------------------------------------------
# nonlinear resistors, bad input
# ----------------------------------------------------------------------------

def test_nonlinear_resistor_explicit_and_implicit():
    # f1 across a capacitor loop: its voltage is the state u2, explicit;
    # KCL at node 2 by hand: (C1 + C2) du2/dt = -i1 - u2/R1 + f1(u2)
    C = Circuit([[1, 2, 'L1'], [2, 1, 'C1'], [2, 1, 'C2'], [2, 1, 'f1'], [1, 2, 'R1']])
    u2, i1, R1 = SR.var('u2'), SR.var('i1'), SR.var('R1')
    assert [n for _, n in C.state_variables()] == ['L1', 'C1']
    assert bool(C.state_equations()[1] == -i1 - u2 / R1 + function('f1')(u2))
    assert C.lhs_matrix()[1, 1] == SR.var('C1') + SR.var('C2')
    # f1 in series with a resistor: i = f1(u_C - R i) is implicit
    with pytest.raises(CircuitError, match=r"f1 .*through the resistor R1"):
        Circuit([[1, 2, 'f1'], [2, 3, 'R1'], [3, 1, 'C1']]).state_equations()


@pytest.mark.parametrize("entries, message", [
    ([[1, 2, 'E1'], [2, 1, 'E2'], [1, 2, 'C1']], r"voltage sources E2, E1 form a loop"),
    ([[1, 2, 'E1'], [2, 3, 'E2'], [3, 1, 'E3'], [1, 3, 'L1']], r"voltage sources .*E3.* form a loop"),
    ([[1, 2, 'I1'], [2, 3, 'R1'], [3, 2, 'C1'], [1, 3, 'I2']], r"current sources I1, I2 form a cut-set"),
    ([[1, 2, 'R1'], [2, 1, 'C1'], [2, 3, 'I1'], [3, 4, 'R2'], [4, 3, 'L1']],
     r"current sources I1 form a cut-set"),
])
def test_no_unique_solution_is_named(entries, message):
    with pytest.raises(CircuitError, match=message):
        Circuit(entries).state_equations()


def test_linearize_and_positive():
    from sage_dynsym.analysis.linear import linearize
    C = Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 0, 'R2'], [2, 3, 'L1'], [3, 0, 'C1'],
                 [3, 0, 'C2']], positive=['R1', 'C1'])
    assert C.positive_parameters() == [SR.var('R1'), SR.var('C1')]
    rec = C.to_linearizer()
    assert rec.variables() == [x for x, _ in C.state_variables()]
    assert (rec.lhs_matrix() - C.lhs_matrix()).is_zero()
    i1, u2, E1 = SR.var('i1'), SR.var('u2'), SR.var('E1')
    lin = linearize(C.subs({E1: 0}), {i1: 0, u2: 0})
    assert lin.jacobian().nrows() == 2


@pytest.mark.slow       # eight nonlinear circuits solved by SciPy: `make test-slow` (CI)
def test_nonlinear_circuits_without_split_match_kirchhoff():
    # circuits with nonlinear resistors i = c1/2 u + c3/5 u^3 and no
    # Brayton-Moser split, against the Kirchhoff solver (scipy root finding)
    # of test_circuits_crosscheck, which shares no code with sage_dynsym
    from test_circuits_crosscheck import MNA, random_circuit as complete_circuit, num
    rng = np.random.default_rng(7400)
    checked = implicit = 0
    for _ in range(300):
        if checked >= 8:
            break
        br, cp, n, entries, values = complete_circuit(
            rng, {'R': 3, 'L': 2, 'C': 2, 'E': 1, 'I': 1, 'f': 2}, mutual=True)
        if not any(b['kind'] == 'f' for b in br):
            continue
        C = Circuit(entries, parameters=['M12'])
        if C.has_mixed_potential():
            continue
        try:
            rhs = C.state_equations()
        except CircuitError as err:
            assert "no explicit state equations" in str(err) and " f" in str(err)
            implicit += 1
            continue
        solver = MNA(br, cp, n)
        index = {b['name']: k for k, b in enumerate(br)}
        states = C.state_variables()
        assert len(states) == len(solver.ind) + len(solver.cap)
        iL, uC = rng.normal(size=len(solver.ind)), rng.normal(size=len(solver.cap))
        point = dict(values)
        for x, name in states:
            k = index[name]
            point[x] = iL[solver.ind.index(k)] if br[k]['kind'] == 'L' \
                else uC[solver.cap.index(k)]
        diL, duC = solver.derivative(iL, uC)
        rate = {br[k]['name']: d for k, d in zip(solver.ind + solver.cap,
                                                  list(diL) + list(duC))}
        B = C.lhs_matrix()
        for a, (x, name) in enumerate(states):
            expected = sum(num(B[a, c], point) * rate[other]
                           for c, (_, other) in enumerate(states))
            assert num(rhs[a], point) == pytest.approx(expected, abs=1e-8), (entries, name)
        checked += 1
    assert checked >= 8 and implicit >= 1, (checked, implicit)


@pytest.mark.parametrize("seed", range(12))
def test_ramp_sources_drive_loops_and_cut_sets_through_their_derivatives(seed):
    # sources E_k(t) = e_k t, I_k(t) = e_k t: the descriptor system has the
    # solution z0 + z1 t with A z1 = -b1, E z1 + A z0 = 0 (A nonsingular);
    # the state part x(t) = x0 + x1 t must satisfy B x1 = F(x(t), t) at every
    # t -- a capacitor loop through a voltage source feels dE/dt, an inductor
    # cut-set with a current source dI/dt
    from sage_dynsym.symbols import t
    rng = np.random.default_rng(7500 + seed)
    while True:
        nnodes, br, couplings, entries, parameters, values = random_circuit(rng, (2, 3, 4, 3, 3))
        E, A, _ = descriptor(nnodes, br, couplings)
        parts = lambda kinds: len(set(_parts(nnodes, [x for x in br if x['kind'] in kinds])))
        voltage_sources = sum(x['kind'] == 'E' for x in br)
        # a capacitor loop through a voltage source, a cut-set of inductors
        # with a current source
        loop_or_cut = (parts('CE') > parts('C') - voltage_sources
                       or parts('RCEf') > parts('RCEfI'))
        if loop_or_cut and not is_singular_pencil(E, A, rng) and nonsingular(A):
            break
    slopes = {x['name']: QQ(int(rng.integers(-8, 9))) / 4 for x in br if x['kind'] in 'EI'}
    ramped = []
    for entry in entries:
        if isinstance(entry, list) and entry[2][0] in 'EI':
            kind = 'voltage_source' if entry[2][0] == 'E' else 'current_source'
            ramped.append({'from': entry[0], 'to': entry[1], 'kind': kind, 'name': entry[2],
                           'value': f"{slopes[entry[2]]}*t"})
        else:
            ramped.append(entry)
    C = Circuit(ramped, parameters=parameters)
    _, _, b1 = descriptor(nnodes, br, couplings, {k: float(v) for k, v in slopes.items()})
    z1 = np.linalg.solve(A, -b1)
    z0 = np.linalg.solve(A, -E @ z1)
    where = {x['name']: k for k, x in enumerate(br)}

    def state(z, name):
        k = where[name]
        return z[nnodes + k] if br[k]['kind'] == 'L' else z[br[k]['head']] - z[br[k]['tail']]

    states = C.state_variables()
    x0 = np.array([state(z0, name) for _, name in states])
    x1 = np.array([state(z1, name) for _, name in states])
    B = np.array([[float(SR(e).subs(values)) for e in row] for row in C.lhs_matrix().rows()])
    for time in (0, 1):
        point = dict(values)
        point[t] = time
        point.update({x: v for (x, _), v in zip(states, x0 + time * x1)})
        F = np.array([float(SR(f).subs(point)) for f in C.state_equations()])
        assert np.allclose(B @ x1 if len(states) else F, F, rtol=1e-8, atol=1e-8), (ramped, time)


def test_positive_key_of_circuit_descriptions():
    from sage_dynsym.circuits import circuit_from_dict
    data = {'kind': 'circuit', 'branches': [[1, 2, 'L1'], [2, 1, 'C1'],
            {'from': 2, 'to': 1, 'kind': 'resistor', 'name': 'R1', 'value': 'R0/2'}],
            'parameters': ['R0'], 'positive': ['R0', 'C1']}
    C = circuit_from_dict(data)
    assert C.positive_parameters() == [SR.var('R0'), SR.var('C1')]
    assert C.to_dict()['positive'] == ['R0', 'C1'] and circuit_from_dict(C.to_dict()) == C
    assert C.subs({'R0': 4}).positive_parameters() == [SR.var('C1')]
    for bad in (['R9'], ['f1'], 'R0'):
        with pytest.raises(Exception, match="positive"):
            circuit_from_dict(dict(data, positive=bad), source='c.yaml')
