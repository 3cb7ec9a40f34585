"""
Independent cross-check of the circuit module against Kirchhoff's laws.

Random connected multigraphs (3-8 nodes) with random R/L/C/E/I (and
nonlinear f) branches, kept complete, are solved here *directly* by a small
modified-nodal-analysis solver written only from KCL, KVL and the element
laws (numpy/scipy; it shares no code with sage_dynsym). The Brayton-Moser
state equations, the loop-method and the node-method Lagrange equations are
then checked numerically against it, and loop and node methods are checked
to give the same eigenvalues as the solver's state matrix.

Conventions (documented in sage_dynsym.circuits.elements): branch [a, b, X]
has current i along a->b and voltage u = v(b) - v(a); R: u = -R i,
L: u = -L di/dt (with mutual terms), C: i = -C du/dt, E: u = E, I: i = I,
f: i = f(u).
"""
import itertools
import sys
from pathlib import Path

import numpy as np
import pytest
from scipy.optimize import root
from scipy.linalg import eig, null_space

from sage.all import SR, Graph
from sage_dynsym.circuits import Circuit
from sage_dynsym.errors import CircuitError
from sage_dynsym.symbols import velocity, acceleration, t

sys.path.insert(0, str(Path(__file__).resolve().parent))
from reference.numerics import same_multiset  # noqa: E402


# ----------------------------------------------------------------------------
# independent solver
# ----------------------------------------------------------------------------

class MNA:
    """Kirchhoff solver: inductors act as known currents, capacitors as known
    voltages; unknowns are node potentials (node 0 grounded) and the currents
    of capacitors and voltage sources."""

    def __init__(self, branches, couplings, nnodes):
        self.br = branches              # dicts: kind, tail, head, val, name
        self.n = nnodes
        self.ind = [k for k, b in enumerate(branches) if b['kind'] == 'L']
        self.cap = [k for k, b in enumerate(branches) if b['kind'] == 'C']
        self.vsrc = [k for k, b in enumerate(branches) if b['kind'] in 'CE']
        self.Lmat = np.diag([branches[k]['val'] for k in self.ind]).astype(float)
        where = {k: a for a, k in enumerate(self.ind)}
        for ka, kb, m in couplings:
            self.Lmat[where[ka], where[kb]] += m
            self.Lmat[where[kb], where[ka]] += m

    def solve(self, iL, uC, sources=True):
        """Branch currents i and voltages u for inductor currents iL and
        capacitor voltages uC (arrays in the order of self.ind / self.cap)."""
        br, n = self.br, self.n
        given_i = dict(zip(self.ind, iL))
        given_u = dict(zip(self.cap, uC))
        nv = n - 1
        jpos = {k: nv + a for a, k in enumerate(self.vsrc)}

        def potentials(z):
            return np.concatenate([[0.0], z[:nv]])

        def currents(z):
            v = potentials(z)
            cur = np.zeros(len(br))
            for k, b in enumerate(br):
                u = v[b['head']] - v[b['tail']]
                kind = b['kind']
                if kind == 'R':
                    cur[k] = -u / b['val']
                elif kind == 'L':
                    cur[k] = given_i[k]
                elif kind == 'I':
                    cur[k] = b['val'] if sources else 0.0
                elif kind == 'f':
                    cur[k] = b['val'](u)
                else:
                    cur[k] = z[jpos[k]]
            return cur

        def residual(z):
            v = potentials(z)
            cur = currents(z)
            kcl = np.zeros(n)
            for k, b in enumerate(br):
                kcl[b['tail']] += cur[k]      # leaves the tail
                kcl[b['head']] -= cur[k]      # enters the head
            kvl = []
            for k in self.vsrc:
                b = br[k]
                target = given_u[k] if b['kind'] == 'C' else (b['val'] if sources else 0.0)
                kvl.append(v[b['head']] - v[b['tail']] - target)
            return np.concatenate([kcl[1:], kvl])

        sol = root(residual, np.zeros(nv + len(self.vsrc)), method='hybr', tol=1e-14)
        assert np.max(np.abs(residual(sol.x))) < 1e-9, "solver did not converge"
        v = potentials(sol.x)
        u = np.array([v[b['head']] - v[b['tail']] for b in br])
        return v, currents(sol.x), u

    def derivative(self, iL, uC):
        """d/dt of the state (inductor currents, capacitor voltages)."""
        _, cur, u = self.solve(iL, uC)
        diL = np.linalg.solve(self.Lmat, -u[self.ind]) if self.ind else np.zeros(0)
        duC = np.array([-cur[k] / self.br[k]['val'] for k in self.cap])
        return diL, duC

    def state_matrix(self):
        """Jacobian of the (linear, source-free) state equations."""
        nL, nC = len(self.ind), len(self.cap)
        cols = []
        for e in np.eye(nL + nC):
            _, cur, u = self.solve(e[:nL], e[nL:], sources=False)
            diL = np.linalg.solve(self.Lmat, -u[self.ind]) if nL else np.zeros(0)
            duC = np.array([-cur[k] / self.br[k]['val'] for k in self.cap])
            cols.append(np.concatenate([diL, duC]))
        return np.array(cols).T


# ----------------------------------------------------------------------------
# random complete circuits
# ----------------------------------------------------------------------------

def _union_find(nnodes, edges):
    """The number of connected components of the graph, and whether its
    edges close a loop."""
    parent = list(range(nnodes))

    def find(x):
        while parent[x] != x:
            x = parent[x]
        return x
    loop = False
    for a, b in edges:
        ra, rb = find(a), find(b)
        loop = loop or ra == rb
        parent[ra] = rb
    return len({find(x) for x in range(nnodes)}), loop


def random_circuit(rng, weights, mutual=False, nonlinear=False):
    """A random complete circuit: (branch dicts, couplings, node count,
    entries for Circuit, numeric values for the symbols)."""
    kinds, p = zip(*weights.items())
    p = np.array(p, dtype=float) / sum(p)
    while True:
        n = int(rng.integers(3, 9))
        pairs = [(int(rng.integers(0, k)), k) for k in range(1, n)]
        for _ in range(int(rng.integers(1, n + 3))):
            a, b = rng.choice(n, 2, replace=False)
            pairs.append((int(a), int(b)))
        pairs = [(b, a) if rng.random() < 0.5 else (a, b) for a, b in pairs]
        rng.shuffle(pairs)
        ks = list(rng.choice(kinds, len(pairs), p=p))
        ce = [e for e, k in zip(pairs, ks) if k in 'CE']
        rest = [e for e, k in zip(pairs, ks) if k not in 'LI']
        if _union_find(n, ce)[1] or _union_find(n, rest)[0] != 1:
            continue            # not complete: C/E loop or L/I cut-set
        if not any(k in 'LC' for k in ks):
            continue
        break
    branches, entries, values, count = [], [], {}, {}
    for (a, b), k in zip(pairs, ks):
        count[k] = count.get(k, 0) + 1
        name = f"{k}{count[k]}"
        if k == 'f':
            c1, c3 = rng.integers(-3, 4), rng.integers(1, 4)
            val = (lambda u, c1=c1, c3=c3: c1 / 2 * u + c3 / 5 * u ** 3)
            entries.append({'from': a, 'to': b, 'kind': 'nonlinear_resistor',
                            'name': name, 'value': f"{c1}/2*u + {c3}/5*u^3"})
        else:
            val = float(rng.uniform(0.5, 2.0)) if k in 'RLC' else float(rng.uniform(-1, 1))
            entries.append([a, b, name])
            values[SR.var(name)] = val
        branches.append({'kind': k, 'tail': a, 'head': b, 'val': val, 'name': name})
    couplings = []
    ind = [j for j, b in enumerate(branches) if b['kind'] == 'L']
    if mutual and len(ind) >= 2 and rng.random() < 0.7:
        ka, kb = ind[0], ind[1]
        m = 0.4 * np.sqrt(branches[ka]['val'] * branches[kb]['val'])
        couplings.append((ka, kb, m))
        entries.append({'kind': 'mutual', 'between': [branches[ka]['name'], branches[kb]['name']],
                        'value': 'M12'})
        values[SR.var('M12')] = m
    return branches, couplings, n, entries, values


def num(expr, values):
    return float(SR(expr).subs(values))


# ----------------------------------------------------------------------------
# Brayton-Moser state equations
# ----------------------------------------------------------------------------

def test_mixed_potential_state_equations_match_kirchhoff():
    rng = np.random.default_rng(20261121)
    checked = 0
    attempts = 0
    while checked < 25:
        attempts += 1
        br, cp, n, entries, values = random_circuit(
            rng, {'R': 3, 'L': 2, 'C': 2, 'E': 1, 'I': 1, 'f': 1}, mutual=True)
        C = Circuit(entries, parameters=['M12'])
        try:
            BM = C.brayton_moser()
        except CircuitError:
            continue            # the split does not exist for this one
        checked += 1
        solver = MNA(br, cp, n)
        index = {b['name']: k for k, b in enumerate(br)}
        states = BM.state_variables()
        rhs = BM.state_equations()
        P = BM.mixed_potential()
        dP = BM.time_derivative()
        Lsym = BM.inductance_matrix()
        for _ in range(2):
            iL = rng.normal(size=len(solver.ind))
            uC = rng.normal(size=len(solver.cap))
            point = dict(values)
            for (x, name) in states:
                k = index[name]
                point[x] = iL[solver.ind.index(k)] if br[k]['kind'] == 'L' else uC[solver.cap.index(k)]
            diL, duC = solver.derivative(iL, uC)
            ddt = {}
            for a, k in enumerate(solver.ind):
                ddt[br[k]['name']] = diL[a]
            for a, k in enumerate(solver.cap):
                ddt[br[k]['name']] = duC[a]
            r = len(solver.ind)
            # L di/dt = dP/di (rows of the inductance matrix), C du/dt = -dP/du
            Lnum = np.array([[num(Lsym[a, b], point) for b in range(r)] for a in range(r)])
            di_order = np.array([ddt[name] for _, name in states[:r]])
            lhs_i = Lnum @ di_order if r else []
            for a, (x, name) in enumerate(states):
                got = num(rhs[a], point)
                if a < r:
                    expected = lhs_i[a]
                else:
                    expected = br[index[name]]['val'] * ddt[name]
                assert got == pytest.approx(expected, abs=1e-8), (entries, name)
            # dP/dt along the motion, by a central difference of P
            h = 1e-6
            shifted = [dict(point), dict(point)]
            for x, name in states:
                shifted[0][x] = point[x] + h * ddt[name]
                shifted[1][x] = point[x] - h * ddt[name]
            fd = (num(P, shifted[0]) - num(P, shifted[1])) / (2 * h)
            assert num(dP, point) == pytest.approx(fd, rel=1e-5, abs=1e-6)
    assert attempts < 400


# ----------------------------------------------------------------------------
# loop and node Lagrangians
# ----------------------------------------------------------------------------

def _eval_equations(L, q, dq, ddq, t0, values):
    point = dict(values)
    point[t] = t0
    for x, a, b, c in zip(L.coordinates(), q, dq, ddq):
        point[x], point[velocity(x)], point[acceleration(x)] = a, b, c
    return [num(e, point) for e in L.lagrange_equations()]


def _incidence(br, n):
    A = np.zeros((n, len(br)))
    for k, b in enumerate(br):
        A[b['tail'], k] += 1
        A[b['head'], k] -= 1
    return A


LINEAR = {'R': 3, 'L': 2, 'C': 2, 'E': 1, 'I': 1}


def _lagrangian_case(seed, method):
    """A random linear circuit with a mutual inductance: the random
    generator, its branches and number of nodes, its entries and values, the
    circuit, its Lagrangian by ``method``, the reference solver and a time
    ``t0``."""
    rng = np.random.default_rng(seed)
    br, cp, n, entries, values = random_circuit(rng, LINEAR, mutual=True)
    C = Circuit(entries, parameters=['M12'])
    return (rng, br, n, entries, values, C, C.lagrangian(method=method), MNA(br, cp, n),
            float(rng.uniform(0.1, 2)))


@pytest.mark.parametrize("seed", range(12))
def test_loop_lagrangian_matches_kirchhoff(seed):
    rng, br, n, entries, values, C, L, solver, t0 = _lagrangian_case(1000 + seed, "loop")
    chords = [loop[0][2] for loop in C.loop_analysis().loops()]
    index = {b['name']: k for k, b in enumerate(br)}
    # branch charges: any KCL-consistent vector with the current sources' charges I*t0
    Z = null_space(_incidence(br, n))
    isrc = [k for k, b in enumerate(br) if b['kind'] == 'I']
    coef = rng.normal(size=Z.shape[1])
    if isrc:
        target = np.array([br[k]['val'] * t0 for k in isrc])
        fix, *_ = np.linalg.lstsq(Z[isrc], target - Z[isrc] @ coef, rcond=None)
        coef = coef + fix
    Q = Z @ coef
    if isrc:
        assert np.allclose(Q[isrc], [br[k]['val'] * t0 for k in isrc])
    uC = np.array([-Q[k] / br[k]['val'] for k in solver.cap])   # u = -Q/C
    iL = rng.normal(size=len(solver.ind))
    _, cur, _ = solver.solve(iL, uC)
    diL, duC = solver.derivative(iL, uC)
    _, dcur, _ = solver.solve(diL, duC, sources=False)   # linear: d/dt of every current
    q = [Q[index[c]] for c in chords]
    dq = [cur[index[c]] for c in chords]
    ddq = [dcur[index[c]] for c in chords]
    res = _eval_equations(L, q, dq, ddq, t0, values)
    assert np.allclose(res, 0, atol=1e-8), (entries, res)


@pytest.mark.parametrize("seed", range(12))
def test_node_lagrangian_matches_kirchhoff(seed):
    rng, br, n, entries, values, C, L, solver, t0 = _lagrangian_case(2000 + seed, "node")
    A = C.node_analysis()
    assert A.ground() == 0
    # node fluxes: ground 0 and phi(head) - phi(tail) = E*t0 on voltage sources
    rows, rhs = [np.eye(n)[0]], [0.0]
    for b in br:
        if b['kind'] == 'E':
            rows.append(np.eye(n)[b['head']] - np.eye(n)[b['tail']])
            rhs.append(b['val'] * t0)
    Acon, bcon = np.array(rows), np.array(rhs)
    phi = rng.normal(size=n)
    fix, *_ = np.linalg.lstsq(Acon, bcon - Acon @ phi, rcond=None)
    phi = phi + fix
    delta = np.array([phi[br[k]['head']] - phi[br[k]['tail']] for k in solver.ind])
    iL = np.linalg.solve(solver.Lmat, -delta) if solver.ind else np.zeros(0)   # L i = -flux
    uC = rng.normal(size=len(solver.cap))
    v, _, _ = solver.solve(iL, uC)
    diL, duC = solver.derivative(iL, uC)
    dv, _, _ = solver.solve(diL, duC, sources=False)
    nodes = A.nodes()
    res = _eval_equations(L, [phi[v_] for v_ in nodes], [v[v_] for v_ in nodes],
                          [dv[v_] for v_ in nodes], t0, values)
    assert np.allclose(res, 0, atol=1e-8), (entries, res)


def _pencil_eigenvalues(L, values):
    q = L.coordinates()
    dq, ddq = [velocity(x) for x in q], [acceleration(x) for x in q]
    eqs = L.lagrange_equations()
    zero = {x: 0 for x in q + dq + ddq}
    zero[t] = 0

    def jac(vars_):
        return np.array([[num(e.diff(x).subs(zero), values) for x in vars_] for e in eqs])
    M, D, K = jac(ddq), jac(dq), jac(q)
    r = len(q)
    Acomp = np.block([[np.zeros((r, r)), np.eye(r)], [-K, -D]])
    Bcomp = np.block([[np.eye(r), np.zeros((r, r))], [np.zeros((r, r)), M]])
    lam = eig(Acomp, Bcomp, right=False)
    return [x for x in lam if np.isfinite(x) and 1e-7 < abs(x) < 1e7]


@pytest.mark.parametrize("seed", range(10))
def test_loop_and_node_methods_same_eigenvalues(seed):
    rng = np.random.default_rng(3000 + seed)
    br, cp, n, entries, values = random_circuit(rng, {'R': 3, 'L': 2, 'C': 2},
                                                mutual=True)
    C = Circuit(entries, parameters=['M12'])
    loop = _pencil_eigenvalues(C.lagrangian(method="loop"), values)
    node = _pencil_eigenvalues(C.lagrangian(method="node"), values)
    physical = [x for x in np.linalg.eigvals(MNA(br, cp, n).state_matrix()) if abs(x) > 1e-7]
    assert same_multiset(loop, node, rel=1e-6), (entries, loop, node)
    assert same_multiset(loop, physical, rel=1e-6), (entries, loop, physical)


# ----------------------------------------------------------------------------
# a non-planar circuit (K_{3,3}) goes through every method
# ----------------------------------------------------------------------------

def test_non_planar_circuit():
    left, right = [0, 1, 2], [3, 4, 5]
    kinds = itertools.cycle('RLCRRLRCR')
    entries, br, values, count = [], [], {}, {}
    for a, b in itertools.product(left, right):
        k = next(kinds)
        count[k] = count.get(k, 0) + 1
        name = f"{k}{count[k]}"
        val = 1.0 + 0.1 * len(br)
        entries.append([a, b, name])
        br.append({'kind': k, 'tail': a, 'head': b, 'val': val, 'name': name})
        values[SR.var(name)] = val
    C = Circuit(entries)
    assert not C.graph().is_planar()
    assert len(C.loop_analysis().loops()) == 9 - 6 + 1
    loop = _pencil_eigenvalues(C.lagrangian(method="loop"), values)
    node = _pencil_eigenvalues(C.lagrangian(method="node"), values)
    solver = MNA(br, [], 6)
    physical = [x for x in np.linalg.eigvals(solver.state_matrix()) if abs(x) > 1e-7]
    assert same_multiset(loop, node, rel=1e-6) and same_multiset(loop, physical, rel=1e-6)
    # the Brayton-Moser route, when the split exists, agrees with Kirchhoff too
    try:
        BM = C.brayton_moser()
    except CircuitError:
        return
    iL, uC = np.ones(len(solver.ind)), np.linspace(-1, 1, len(solver.cap))
    diL, duC = solver.derivative(iL, uC)
    point = dict(values)
    names = {b['name']: k for k, b in enumerate(br)}
    for x, name in BM.state_variables():
        k = names[name]
        point[x] = iL[solver.ind.index(k)] if br[k]['kind'] == 'L' else uC[solver.cap.index(k)]
    for (x, name), rhs in zip(BM.state_variables(), BM.state_equations()):
        k = names[name]
        d = diL[solver.ind.index(k)] if br[k]['kind'] == 'L' else duC[solver.cap.index(k)]
        assert num(rhs, point) == pytest.approx(br[k]['val'] * d, abs=1e-9)


def test_cycle_basis_size_matches_sage():
    rng = np.random.default_rng(7)
    for _ in range(10):
        br, cp, n, entries, values = random_circuit(rng, {'R': 1, 'L': 1, 'C': 1})
        C = Circuit(entries)
        G = Graph([(b['tail'], b['head'], k) for k, b in enumerate(br)], multiedges=True)
        assert len(C.loop_analysis().loops()) == len(G.cycle_basis(output='edge'))
