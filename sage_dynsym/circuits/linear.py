r"""
Lagrangians of linear circuits: loop-current and node-potential methods

Both methods work branch by branch (formulas (6) and (7) of
:doc:`the method </method>`), with the branch
variables and element laws of :mod:`~sage_dynsym.circuits.elements`.

**Loop-current method.** A spanning tree is chosen that avoids the current
sources (Sage's Kruskal, preferring voltage sources, then capacitors,
resistors, inductors, ties by branch order). Every chord defines a
fundamental loop, oriented along the chord; the loop charges ``q1, q2, ...``
of the chords that are not current sources (in branch order) are the
coordinates. A current-source chord fixes its loop current to `I` (its loop
charge is `\int_0^t I`). With branch currents `i_b = \sum \pm \dot q_k` and
branch charges `Q_b = \sum \pm q_k`:

.. MATH::

    T = \tfrac12 \sum_L L\, i_b^2 + \sum_{M} M\, i_a i_b,\quad
    \Pi = \sum_C \frac{Q_b^2}{2C},\quad
    R = \tfrac12 \sum_R R\, i_b^2,\quad
    Q_k = \sum_{E \in \text{loop } k} \pm E,

`L = T - \Pi`; the Lagrange equations are Kirchhoff's voltage law around
each loop.

**Node-potential method.** One node is grounded (node ``0`` if there is one,
otherwise the highest node; in a circuit whose parts are joined only by
mutual inductances, also the highest node of every other part). The coordinates are node flux linkages
``phi<node>`` (their derivatives are node potentials). Voltage sources tie
the flux of their ``to`` node to that of their ``from`` node
(`\varphi_b = \varphi_a + \int_0^t E`), so only one node per group joined by
voltage sources is a coordinate (the ground's group has none). With branch
fluxes `\Delta_b = \varphi(\text{to}) - \varphi(\text{from})`:

.. MATH::

    T = \tfrac12 \sum_C C\, \dot\Delta_b^2,\quad
    \Pi = \tfrac12\, \Delta_L^T \mathbf{L}^{-1} \Delta_L,\quad
    R = \tfrac12 \sum_R \dot\Delta_b^2 / R,

and the current sources injecting into a node group are its generalized
force; the Lagrange equations are Kirchhoff's current law at each node.
"""
from sage.matrix.constructor import matrix
from sage.symbolic.ring import SR
from sage.symbolic.integration.integral import definite_integral

from ..errors import CircuitError
from ..symbols import velocity, t
from .elements.windings import winding_groups, winding_matrix
from .graph import node_key

__all__ = ['source_integral', 'LoopAnalysis', 'NodeAnalysis']


def _tree_rank(branch):
    # the loop method's spanning tree prefers voltage sources, then
    # capacitors, resistors, nonlinear resistors and inductors: the order of
    # the normal tree (Branch.tree_rank)
    return branch.tree_rank


def _not_current_source(branch):
    # a current source is never a tree branch of the loop method
    return branch.fixed_current() is None



def source_integral(value):
    r"""
    `\int_0^t` of a source value (a charge or a flux linkage).

    EXAMPLES::

        sage: from sage_dynsym.circuits.linear import source_integral
        sage: from sage_dynsym.symbols import t
        sage: E, w = var('E w')
        sage: source_integral(E), source_integral(E*cos(w*t))
        (E*t, E*sin(t*w)/w)
    """
    value = SR(value)
    if t not in value.variables():
        return value * t
    try:    # an antiderivative needs no assumptions on t (a definite integral may)
        prim = value.integral(t)
        return prim - prim.subs({t: 0})
    except (ValueError, TypeError, RuntimeError, NotImplementedError):
        s = SR.symbol('s')
        return definite_integral(value.subs({t: s}), s, 0, t, hold=True)


def _check_linear(circuit, method):
    for b in circuit.branches():
        if not b.is_linear():
            raise CircuitError(f"the {method} method needs a linear circuit, but "
                               f"{b.name} is nonlinear; use mixed_potential()",
                               entry=f"branches[{b.index}]")


def _quadratic(rows, weights, n):
    # n x n matrix sum_b weight_b * row_b row_b^T, each row a sparse
    # {coordinate index: sign}
    M = matrix(SR, n, n, sparse=True)
    for row, w in zip(rows, weights):
        for k, sk in row.items():
            for l, sl in row.items():
                M[k, l] += sk * sl * w
    return M.dense_matrix()


def _energy(terms, role, variables):
    # sum of w_b x_b^2 / 2 over the branches whose term has this role
    return SR(sum(term[1] * x ** 2 / 2 for term, x in zip(terms, variables)
                  if term is not None and term[0] == role))


class _BranchAnalysis:
    r"""
    What the loop and the node descriptions of a linear circuit share: the
    coordinates, the branch-to-coordinate incidence ``rows`` (one dict
    ``{coordinate index: sign}`` per branch), each branch's term ``terms``
    (``(role, weight)`` or ``None``, see
    :meth:`~sage_dynsym.circuits.elements.kinds.Branch.loop_term`), the
    energies ``T, Pi, R`` and the generalized ``forces``, assembled branch
    by branch by the subclasses.
    """

    def __init__(self, coordinates, rows, terms, T, Pi, R, forces):
        self._coordinates, self._rows, self._terms = coordinates, rows, terms
        self._T, self._Pi, self._R, self._forces = T, Pi, R, forces

    def coordinates(self):
        r"""The coordinates: loop charges ``q1, q2, ...`` (loop method) or
        node flux linkages ``phi<node>`` (node method, one per node group,
        ground excluded).

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: C = Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 3, 'L1'], [3, 0, 'C1'],
            ....:              [3, 0, 'R2'], [0, 3, 'I1']])
            sage: C.loop_analysis().coordinates(), C.node_analysis().coordinates()
            ([q1, q2], [phi2, phi3])
        """
        return list(self._coordinates)

    def _matrix(self, role):
        sel = [p for p, term in enumerate(self._terms) if term is not None and term[0] == role]
        return _quadratic([self._rows[p] for p in sel], [self._terms[p][1] for p in sel],
                          len(self._coordinates))

    def source_vector(self):
        r"""The generalized forces of the sources: loop electromotive forces
        `Q_k = \sum \pm E` (loop method), or the source currents injected
        into each node group (node method).

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: C = Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 3, 'L1'], [3, 0, 'C1'],
            ....:              [3, 0, 'R2'], [0, 3, 'I1']])
            sage: C.loop_analysis().source_vector(), C.node_analysis().source_vector()
            ([E1, 0], [0, I1])
        """
        return list(self._forces)

    def kinetic_energy(self):
        r"""The kinetic energy `T`: magnetic (loop method) or electric
        (node method).

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: C = Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 3, 'L1'], [3, 0, 'C1'],
            ....:              [3, 0, 'R2'], [0, 3, 'I1']])
            sage: C.loop_analysis().kinetic_energy(), C.node_analysis().kinetic_energy()
            (1/2*L1*dq1^2, 1/2*C1*dphi3^2)
        """
        return self._T

    def potential_energy(self):
        r"""The potential energy `\Pi`: electric (loop method) or magnetic
        (node method).

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: C = Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 3, 'L1'], [3, 0, 'C1'],
            ....:              [3, 0, 'R2'], [0, 3, 'I1']])
            sage: C.loop_analysis().potential_energy(), C.node_analysis().potential_energy()
            (1/2*(I1*t + q1 - q2)^2/C1, 1/2*(phi2 - phi3)^2/L1)
        """
        return self._Pi

    def dissipation(self):
        r"""The Rayleigh function `R`.

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: C = Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 3, 'L1'], [3, 0, 'C1'],
            ....:              [3, 0, 'R2'], [0, 3, 'I1']])
            sage: C.loop_analysis().dissipation(), C.node_analysis().dissipation()
            (1/2*R1*dq1^2 + 1/2*R2*dq2^2, 1/2*(E1 - dphi2)^2/R1 + 1/2*dphi3^2/R2)
        """
        return self._R


class LoopAnalysis(_BranchAnalysis):
    r"""
    Loop-current description of a linear circuit (see the module
    documentation). Built by
    :meth:`~sage_dynsym.circuits.circuit.Circuit.loop_analysis`.

    EXAMPLES: a series RLC circuit has one loop::

        sage: from sage_dynsym.circuits import Circuit
        sage: A = Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 3, 'L1'], [3, 0, 'C1']]).loop_analysis()
        sage: A.loops()
        [[(2, 3, 'L1'), (3, 0, 'C1'), (0, 1, 'E1'), (1, 2, 'R1')]]
        sage: A.kinetic_energy(), A.potential_energy(), A.dissipation(), A.source_vector()
        (1/2*L1*dq1^2, 1/2*q1^2/C1, 1/2*R1*dq1^2, [E1])
    """

    def __init__(self, circuit):
        _check_linear(circuit, "loop-current")
        cg = circuit.circuit_graph()
        br = cg.branches
        tree = cg.spanning_tree(rank=_tree_rank, keep=_not_current_source)
        if tree is None:
            raise CircuitError("the current sources form a cut-set: Kirchhoff's "
                               "current law cannot hold for arbitrary source values")
        cg.check_source_loops()
        rooted = cg.rooted(tree)
        chords = [p for p in range(len(br)) if p not in tree]
        coords = [p for p in chords if br[p].fixed_current() is None]
        coordinates = [SR.var(f"q{k + 1}") for k in range(len(coords))]
        index = {p: k for k, p in enumerate(coords)}
        pos_of = {b.name: p for p, b in enumerate(br)}
        rows = [dict() for _ in br]        # branch -> {loop: sign}
        current = [SR(0)] * len(br)
        charge = [SR(0)] * len(br)
        self._loops = []
        for c in chords:
            loop = rooted.loop(br[c])
            if c in index:
                self._loops.append(loop)
                x, X = velocity(coordinates[index[c]]), coordinates[index[c]]
            else:
                x, X = br[c].fixed_current(), source_integral(br[c].fixed_current())
            for b, sign in loop:
                p = pos_of[b.name]
                current[p] += sign * x
                charge[p] += sign * X
                if c in index:
                    rows[p][index[c]] = sign
        terms = [b.loop_term() for b in br]
        T = _energy(terms, 'kinetic', current)
        for cp in circuit.couplings():
            T += cp.value * current[pos_of[cp.first]] * current[pos_of[cp.second]]
        forces = [SR(0)] * len(coords)
        for p, b in enumerate(br):
            if b.fixed_voltage() is not None:
                for k, sign in rows[p].items():
                    forces[k] += sign * b.fixed_voltage()
        super().__init__(coordinates, rows, terms, SR(T), _energy(terms, 'potential', charge),
                         _energy(terms, 'dissipation', current), forces)
        self._circuit = circuit
        self._pos_of = pos_of

    def loops(self):
        r"""
        The loops of the coordinates, each a list of triples
        ``(node, next node, name)`` in walking order, starting with the chord.

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: A = Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 3, 'L1'], [3, 0, 'C1'],
            ....:              [3, 0, 'R2'], [0, 3, 'I1']]).loop_analysis()
            sage: A.loops()
            [[(2, 3, 'L1'), (3, 0, 'C1'), (0, 1, 'E1'), (1, 2, 'R1')], [(3, 0, 'R2'), (0, 3, 'C1')]]
        """
        return [[(b.tail, b.head, b.name) if s > 0 else (b.head, b.tail, b.name)
                 for b, s in loop] for loop in self._loops]

    def inductance_matrix(self):
        r"""The loop inductance matrix `L_{ij}` (mutual inductances included).

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: A = Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 3, 'L1'], [3, 0, 'C1'],
            ....:              [3, 0, 'R2'], [0, 3, 'I1']]).loop_analysis()
            sage: A.inductance_matrix()
            [L1  0]
            [ 0  0]
        """
        M = self._matrix('kinetic')
        for cp in self._circuit.couplings():
            ra, rb = self._rows[self._pos_of[cp.first]], self._rows[self._pos_of[cp.second]]
            for k, sk in ra.items():
                for l, sl in rb.items():
                    M[k, l] += sk * sl * cp.value
                    M[l, k] += sk * sl * cp.value
        return M

    def elastance_matrix(self):
        r"""The loop elastance matrix `(1/C)_{ij}`.

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: A = Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 3, 'L1'], [3, 0, 'C1'],
            ....:              [3, 0, 'R2'], [0, 3, 'I1']]).loop_analysis()
            sage: A.elastance_matrix()
            [ 1/C1 -1/C1]
            [-1/C1  1/C1]
        """
        return self._matrix('potential')

    def resistance_matrix(self):
        r"""The loop resistance matrix `R_{ij}`.

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: A = Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 3, 'L1'], [3, 0, 'C1'],
            ....:              [3, 0, 'R2'], [0, 3, 'I1']]).loop_analysis()
            sage: A.resistance_matrix()
            [R1  0]
            [ 0 R2]
        """
        return self._matrix('dissipation')

class NodeAnalysis(_BranchAnalysis):
    r"""
    Node-potential description of a linear circuit (see the module
    documentation). Built by
    :meth:`~sage_dynsym.circuits.circuit.Circuit.node_analysis`.

    EXAMPLES: a series RLC circuit, node 0 grounded (node 1 is fixed by the
    source)::

        sage: from sage_dynsym.circuits import Circuit
        sage: A = Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 3, 'L1'], [3, 0, 'C1']]).node_analysis()
        sage: A.ground(), A.coordinates()
        (0, [phi2, phi3])
        sage: A.kinetic_energy(), A.potential_energy(), A.dissipation()
        (1/2*C1*dphi3^2, 1/2*(phi2 - phi3)^2/L1, 1/2*(E1 - dphi2)^2/R1)

    A transformer with galvanically isolated sides: node 4 grounds the
    secondary::

        sage: C = Circuit([[0, 1, 'E1'], [1, 0, 'L1'], [3, 4, 'L2'], [4, 3, 'R2'],
        ....:              {'kind': 'mutual', 'between': ['L1', 'L2'], 'value': 'M'}],
        ....:             parameters=['M'])
        sage: C.node_analysis().coordinates()
        [phi3]
    """

    def __init__(self, circuit, ground=None):
        _check_linear(circuit, "node-potential")
        cg = circuit.circuit_graph()
        br, nodes = cg.branches, cg.nodes
        if ground is None:
            ground = 0 if 0 in nodes else nodes[-1]
        if ground not in nodes:
            raise CircuitError(f"the ground node {ground!r} is not a node of the circuit")
        cg.check_source_loops()
        adjacency = {v: [] for v in nodes}
        for b in br:
            E = b.fixed_voltage()
            if E is not None:
                adjacency[b.tail].append((b.head, E))
                adjacency[b.head].append((b.tail, -E))
        # one grounded node per part of the graph (parts joined only by mutual
        # inductances): the given one, and each other part's highest node
        grounds = [ground] + [max(part, key=node_key) for part in
                              cg.graph.connected_components(sort=False) if ground not in part]
        # flux of every node = coordinate of its group's representative + offset
        rep, offset = {}, {}
        for root in grounds + [v for v in nodes if v not in grounds]:
            if root in rep:
                continue
            rep[root], offset[root] = root, SR(0)
            queue = [root]
            for v in queue:
                for w, e in adjacency[v]:
                    if w not in rep:
                        rep[w], offset[w] = root, offset[v] + e
                        queue.append(w)
        reps = [v for v in nodes if rep[v] == v and v not in grounds]
        coordinates = [SR.var(f"phi{v}" if not isinstance(v, str) else f"phi_{v}")
                       for v in reps]
        index = {v: k for k, v in enumerate(reps)}
        flux = {}
        dflux = {}
        for v in nodes:
            base = coordinates[index[rep[v]]] if rep[v] in index else SR(0)
            flux[v] = base + source_integral(offset[v])
            dflux[v] = (velocity(base) if rep[v] in index else SR(0)) + offset[v]
        rows = []
        for b in br:
            row = {}
            for v, sign in ((b.head, 1), (b.tail, -1)):
                if rep[v] in index:
                    k = index[rep[v]]
                    row[k] = row.get(k, 0) + sign
            rows.append({k: s for k, s in row.items() if s})
        delta = [flux[b.head] - flux[b.tail] for b in br]
        ddelta = [dflux[b.head] - dflux[b.tail] for b in br]
        terms = [b.node_term() for b in br]
        # the potential energy of the windings: the inverse inductance
        # matrix of each group of coupled inductors
        self._gamma_blocks = self._inverse_inductance(circuit, br)
        Pi = SR(0)
        for block, G in self._gamma_blocks:
            d = [delta[p] for p in block]
            Pi += sum(G[a, b] * d[a] * d[b] for a in range(len(d)) for b in range(len(d))) / 2
        forces = [SR(0)] * len(reps)
        for b in br:
            if b.fixed_current() is not None:
                for v, sign in ((b.head, 1), (b.tail, -1)):
                    if rep[v] in index:
                        forces[index[rep[v]]] += sign * b.fixed_current()
        super().__init__(coordinates, rows, terms, _energy(terms, 'kinetic', ddelta), Pi,
                         _energy(terms, 'dissipation', ddelta), forces)
        self._ground = ground
        self._reps = reps

    @staticmethod
    def _inverse_inductance(circuit, br):
        # inverse inductance matrix, block by block of mutually coupled
        # inductors (an uncoupled one: its node term 1/L)
        pos_of = {b.name: p for p, b in enumerate(br)}
        blocks = []
        for group in winding_groups([b for b in br if b.is_inductive()],
                                    circuit.couplings()):
            block = [pos_of[b.name] for b in group]
            if len(group) == 1:
                blocks.append((block, matrix(SR, [[group[0].node_term()[1]]])))
            else:
                Lm = winding_matrix(group, circuit.couplings())
                blocks.append((block, Lm.inverse().simplify_rational()))
        return blocks

    def ground(self):
        r"""The grounded node.

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: A = Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 3, 'L1'], [3, 0, 'C1'],
            ....:              [3, 0, 'R2'], [0, 3, 'I1']]).node_analysis()
            sage: A.ground()
            0
        """
        return self._ground

    def nodes(self):
        r"""The nodes whose flux linkages are the coordinates, in the same order.

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: A = Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 3, 'L1'], [3, 0, 'C1'],
            ....:              [3, 0, 'R2'], [0, 3, 'I1']]).node_analysis()
            sage: A.nodes()
            [2, 3]
        """
        return list(self._reps)

    def capacitance_matrix(self):
        r"""The node capacitance matrix `C_{ij}`.

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: A = Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 3, 'L1'], [3, 0, 'C1'],
            ....:              [3, 0, 'R2'], [0, 3, 'I1']]).node_analysis()
            sage: A.capacitance_matrix()
            [ 0  0]
            [ 0 C1]
        """
        return self._matrix('kinetic')

    def conductance_matrix(self):
        r"""The node conductance matrix `(1/R)_{ij}`.

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: A = Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 3, 'L1'], [3, 0, 'C1'],
            ....:              [3, 0, 'R2'], [0, 3, 'I1']]).node_analysis()
            sage: A.conductance_matrix()
            [1/R1    0]
            [   0 1/R2]
        """
        return self._matrix('dissipation')

    def inverse_inductance_matrix(self):
        r"""The node inverse-inductance matrix `(1/L)_{ij}` (mutual inductances included).

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: A = Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 3, 'L1'], [3, 0, 'C1'],
            ....:              [3, 0, 'R2'], [0, 3, 'I1']]).node_analysis()
            sage: A.inverse_inductance_matrix()
            [ 1/L1 -1/L1]
            [-1/L1  1/L1]
        """
        n = len(self._coordinates)
        M = matrix(SR, n, n)
        for block, G in self._gamma_blocks:
            for a, pa in enumerate(block):
                for b, pb in enumerate(block):
                    for k, sk in self._rows[pa].items():
                        for l, sl in self._rows[pb].items():
                            M[k, l] += sk * sl * G[a, b]
        return M

