r"""
State equations of any solvable circuit: modified nodal analysis with a normal tree

When the Brayton--Moser split of
:mod:`~sage_dynsym.circuits.mixed_potential` is impossible (a loop of
capacitors and voltage sources, a cut-set of inductors and current sources,
resistors whose voltage and current are both unknown, as in a bridge), the
state equations are still obtained by exact elimination, in the branch
variables and orientation of :mod:`~sage_dynsym.circuits.elements`.

1. **Normal tree.** A spanning forest is grown by Kruskal's rule from the
   branches in the order voltage sources, capacitors (in the naming order
   below), resistors, nonlinear resistors, inductors, current sources. A
   voltage source that closes a loop closes a loop of voltage sources only,
   and a current source that the forest needs lies in a cut-set of current
   sources only: both are refused (no unique solution). By the minimality
   of the forest, the fundamental loop of a capacitor chord runs through
   voltage sources and capacitors only, and the fundamental cut-set of an
   inductor of the forest through inductors and current sources only.
2. **State.** The capacitors of the forest and the inductor chords: a
   maximal set of independent capacitor voltages `x_C` and inductor
   currents `x_L`. The other capacitor voltages are `u_C = P_C x_C + Q_C E`
   (their loops), the other inductor currents `i_L = P_L x_L + Q_L I`
   (their cut-sets).
3. **Resistive part.** Kirchhoff's current law on the fundamental cut-set
   of each resistive tree branch, the voltage law around the fundamental
   loop of each resistive chord and `u = -R i` form a linear system for the
   resistor voltages and currents, solved exactly (over the fraction field
   of the element values when they are rational functions, else in the
   symbolic ring), with the currents `i = f(u)` of the nonlinear resistors
   as knowns. A nonlinear resistor's voltage is then linear in those
   currents; when these dependencies have no cycle, the currents follow
   explicitly one after the other, otherwise the equations are implicit and
   refused, naming the elements.
4. **State equations.** The voltage law around the loop of each inductor
   chord and the current law on the cut-set of each capacitor of the tree:

   .. MATH::

       P_L^T \mathbf{L} P_L\, \dot x_L = \sum_{\text{loop}} \pm u_b
       - P_L^T \mathbf{L} Q_L \dot I, \qquad
       P_C^T \mathbf{C} P_C\, \dot x_C = -\sum_{\text{cut-set}} \pm i_b
       - P_C^T \mathbf{C} Q_C \dot E,

   the sums over the other branches of the loop (cut-set); `\dot E, \dot I`
   are the time derivatives of the source values (zero for constant
   sources). The matrix `B` of `B\dot x = F(x)` is the block-diagonal
   matrix of `P_L^T \mathbf{L} P_L` (mutual inductances included) and `P_C^T
   \mathbf{C} P_C`; it is what :meth:`NodalAnalysis.lhs_matrix` returns.

The state variables are named as in
:mod:`~sage_dynsym.circuits.mixed_potential`: inductor currents ``i1, ...``
(inductor chords in branch order), then capacitor voltages continuing the
numbering (capacitors of the tree in the breadth-first order of the
capacitor forest).

EXAMPLES:

Two capacitors in parallel with a voltage source charge through nothing:
the loop ``E1, C1`` leaves one state, the inductor current::

    sage: from sage_dynsym.circuits import Circuit
    sage: C = Circuit([[0, 1, 'E1'], [1, 0, 'C1'], [1, 2, 'L1'], [2, 0, 'R1']])
    sage: A = C.nodal_analysis(); A
    Modified nodal analysis of Circuit with 4 branches on 3 nodes
    sage: A.state_variables(), A.state_equations(), A.lhs_matrix()
    ([(i1, 'L1')], [-R1*i1 + E1], [L1])

A capacitor loop (two capacitors in parallel) has one voltage; an
inductor cut-set (two inductors in series) has one current::

    sage: C = Circuit([[1, 2, 'L1'], [2, 3, 'L2'], [3, 1, 'C1'], [3, 1, 'C2'], [3, 1, 'R1']])
    sage: A = C.nodal_analysis()
    sage: A.state_variables()
    [(i1, 'L2'), (u2, 'C1')]
    sage: A.lhs_matrix()
    [L1 + L2       0]
    [      0 C1 + C2]
    sage: A.state_equations()
    [u2, -i1 - u2/R1]

A voltage divider ``R1, R2`` feeding an inductor has no Brayton--Moser
split (``R2``'s voltage is fixed neither by the source alone nor its
current by the inductor); it is solved exactly::

    sage: C = Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 0, 'R2'], [2, 3, 'L1'], [3, 0, 'C1']])
    sage: C.has_mixed_potential()
    False
    sage: C.state_equations()
    [-R1*R2*i1/(R1 + R2) + E1*R2/(R1 + R2) + u2, -i1]

TESTS:

Bad input is named::

    sage: Circuit([[1, 2, 'E1'], [2, 3, 'E2'], [3, 1, 'E3'], [1, 2, 'R1']]).nodal_analysis()
    Traceback (most recent call last):
    ...
    CircuitError: branches[2]: the voltage sources E3, E1, E2 form a loop: Kirchhoff's voltage law cannot hold for arbitrary source values (no unique solution)
    sage: Circuit([[1, 2, 'I1'], [2, 3, 'R1'], [3, 2, 'C1'], [1, 3, 'I2']]).nodal_analysis()
    Traceback (most recent call last):
    ...
    CircuitError: branches[0]: the current sources I1, I2 form a cut-set: Kirchhoff's current law cannot hold for arbitrary source values (no unique solution)
    sage: Circuit([[1, 2, 'f1'], [2, 3, 'R1'], [3, 1, 'C1']]).nodal_analysis()
    Traceback (most recent call last):
    ...
    NotExplicitError: branches[0]: no explicit state equations: the voltage of the nonlinear resistor f1 depends on its own current i = f1(u) through the resistor R1 (an implicit equation)
    sage: Circuit([[1, 2, 'I1'], [2, 3, 'f1'], [3, 1, 'C1'], [3, 1, 'L1']]).nodal_analysis()
    Traceback (most recent call last):
    ...
    NotExplicitError: branches[1]: no explicit state equations: the voltage of the nonlinear resistor f1 is fixed by no capacitor, voltage source or resistor (its current is; i = f1(u) would have to be inverted)

REFERENCES:

- L. O. Chua, P.-M. Lin, *Computer-Aided Analysis of Electronic
  Circuits*, Prentice-Hall, 1975, ch. 8 (normal tree, state equations).
- C.-W. Ho, A. E. Ruehli, P. A. Brennan, *The modified nodal approach to
  network analysis*, IEEE Trans. Circuits Syst. 22 (1975) 504--509.
"""
from sage.matrix.constructor import matrix
from sage.misc.cachefunc import cached_method
from sage.matrix.special import block_diagonal_matrix
from sage.rings.rational_field import QQ
from sage.rings.real_double import RDF
from sage.rings.real_mpfr import RR
from sage.rings.polynomial.polynomial_ring_constructor import PolynomialRing
from sage.symbolic.ring import SR

from ..errors import CircuitError, brief
from ..symbols import t
from .elements.kinds import ELEMENTS, state_symbols
from .elements.windings import winding_matrix
from .graph import UnionFind, capacitor_order

__all__ = ['TREE_ORDER', 'NOT_EXPLICIT', 'NotExplicitError', 'coefficient_ring', 'NodalAnalysis']

#: the order in which the normal tree takes the branches (by kind; see
#: :attr:`~sage_dynsym.circuits.elements.kinds.Branch.tree_rank`)
TREE_ORDER = tuple(sorted(ELEMENTS, key=lambda kind: ELEMENTS[kind].tree_rank))

#: how the errors of implicit (not explicitly solvable) circuits begin
NOT_EXPLICIT = "no explicit state equations"


class NotExplicitError(CircuitError):
    r"""
    The state equations of a circuit exist but are implicit: the
    relations of its nonlinear resistors cannot be solved explicitly.

    EXAMPLES::

        sage: from sage_dynsym.circuits import Circuit
        sage: from sage_dynsym.circuits.nodal import NotExplicitError
        sage: try:
        ....:     Circuit([[1, 2, 'f1'], [2, 3, 'R1'], [3, 1, 'C1']]).nodal_analysis()
        ....: except NotExplicitError as err:
        ....:     print(err.entry)
        branches[0]
    """


def _inexact(expr):
    # a floating-point number anywhere in expr
    expr = SR(expr)
    if expr.is_numeric():
        value = expr.pyobject()
        return isinstance(value, float) or not getattr(value.parent(), 'is_exact',
                                                       lambda: True)()
    return any(_inexact(op) for op in expr.operands())


def coefficient_ring(values):
    r"""
    The ring in which a linear system with coefficients ``values`` (and
    `\pm 1`) is solved exactly: the fraction field of the rational
    polynomials in their symbols when they are rational functions, ``RDF``
    when they are floating-point numbers, else the symbolic ring.

    EXAMPLES::

        sage: from sage_dynsym.circuits.nodal import coefficient_ring
        sage: R1, R2 = var('R1 R2')
        sage: coefficient_ring([R1, R1*R2/(R1 + R2)])
        Fraction Field of Multivariate Polynomial Ring in R1, R2 over Rational Field
        sage: coefficient_ring([SR(2), SR(3)/4]), coefficient_ring([SR(0.5)])
        (Rational Field, Real Double Field)
        sage: coefficient_ring([sqrt(R1)]), coefficient_ring([0.5*R1]), coefficient_ring([pi])
        (Symbolic Ring, Symbolic Ring, Symbolic Ring)
    """
    values = [SR(v) for v in values]
    names = sorted({str(x) for v in values for x in v.variables()})
    if any(_inexact(v) for v in values):
        return SR if names else RDF
    ring = PolynomialRing(QQ, names).fraction_field() if names else QQ
    try:
        for v in values:
            ring(v)
    except (TypeError, ValueError):
        return SR
    return ring


class NodalAnalysis:
    r"""
    The state equations of a circuit by modified nodal analysis (see the
    module documentation). Built by
    :meth:`~sage_dynsym.circuits.circuit.Circuit.nodal_analysis`.

    EXAMPLES::

        sage: from sage_dynsym.circuits import Circuit
        sage: A = Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 3, 'L1'], [3, 0, 'C1']]).nodal_analysis()
        sage: A.tree()
        [(0, 1, 'E1'), (1, 2, 'R1'), (3, 0, 'C1')]
        sage: A.state_equations()
        [-R1*i1 + E1 + u2, -i1]
    """

    def __init__(self, circuit):
        if not callable(getattr(circuit, 'circuit_graph', None)):
            raise CircuitError(f"expected a circuit, got {brief(circuit)}; the call is "
                               "Circuit(branches).nodal_analysis()", entry="circuit")
        self._circuit = circuit
        cg = circuit.circuit_graph()
        self._branches = br = cg.branches
        caps = capacitor_order(cg)
        tie = {p: k for k, p in enumerate(caps)}
        order = sorted(range(len(br)), key=lambda p: (br[p].tree_rank, tie.get(p, p)))
        uf, tree = UnionFind(cg.nodes), []
        for p in order:
            b = br[p]
            if uf.union(b.tail, b.head):
                if b.fixed_current() is not None:
                    self._source_cut_set(cg, p)
                tree.append(p)
            elif b.fixed_voltage() is not None:
                loop = cg.cycle_through(tree, p)
                raise CircuitError(f"the voltage sources {', '.join(loop)} form a loop: "
                                   "Kirchhoff's voltage law cannot hold for arbitrary "
                                   "source values (no unique solution)",
                                   entry=f"branches[{b.index}]")
        self._tree = frozenset(tree)
        rooted = cg.rooted(tree)
        pos_of = {b.name: p for p, b in enumerate(br)}
        self._chords = [p for p in range(len(br)) if p not in self._tree]
        # loops[k]: the tree branches of the loop of chord k, with their signs;
        # cut[b]: the chords whose loops run through tree branch b
        self._loops, self._cut = {}, {p: [] for p in tree}
        for k in self._chords:
            self._loops[k] = [(pos_of[b.name], s) for b, s in rooted.loop(br[k])[1:]]
            for p, s in self._loops[k]:
                self._cut[p].append((k, s))
        self._inductors = [p for p in self._chords if br[p].is_inductive()]
        self._capacitors = [p for p in caps if p in self._tree]
        self._symbol = state_symbols(br, self._inductors + self._capacitors)
        self._solve()

    def _source_cut_set(self, cg, p):
        # p: a current source the tree needs; the part of the other branches'
        # graph at its tail is cut from the rest by current sources only
        br = self._branches
        uf = UnionFind(cg.nodes)
        for b in br:
            if b.fixed_current() is None:
                uf.union(b.tail, b.head)
        side = uf.find(br[p].tail)
        cut = [b for b in br if (uf.find(b.tail) == side) != (uf.find(b.head) == side)]
        raise CircuitError(f"the current sources {', '.join(b.name for b in cut)} form a "
                           "cut-set: Kirchhoff's current law cannot hold for arbitrary "
                           "source values (no unique solution)",
                           entry=f"branches[{cut[0].index}]")

    # ------------------------------------------------------------------
    # the resistive part

    def _known(self, p, what):
        # a known branch quantity: a state variable or a source value
        b = self._branches[p]
        known = (b.known_voltage if what == 'u' else b.known_current)(self._symbol.get(p))
        if known is None:
            raise AssertionError(f"{b.name}: {what} is not known")    # excluded by the tree
        return SR(known)

    def _solve(self):
        br = self._branches
        res = [p for p, b in enumerate(br) if b.resistive]
        # the currents of the linear resistors are unknowns, those of the
        # nonlinear ones known functions of their voltages
        linear = [p for p in res if br[p].resistance() is not None]
        unknowns = [('u', p) for p in res] + [('i', p) for p in linear]
        where = {x: k for k, x in enumerate(unknowns)}
        columns, rows = {}, []          # known quantity -> column; rows (A part, K part)

        def term(row, what, p, coefficient):
            key = (what, p)
            if key in where:
                row[0][where[key]] = row[0].get(where[key], 0) + coefficient
            else:
                if key not in columns:
                    columns[key] = len(columns)
                row[1][columns[key]] = row[1].get(columns[key], 0) + coefficient

        for p in res:
            row = ({}, {})
            if p in self._tree:        # current law on the cut-set of p
                term(row, 'i', p, 1)
                for k, s in self._cut[p]:
                    term(row, 'i', k, -s)
            else:                      # voltage law around the loop of p
                term(row, 'u', p, 1)
                for q, s in self._loops[p]:
                    term(row, 'u', q, s)
            rows.append(row)
            if p in linear:
                row = ({}, {})
                term(row, 'u', p, 1)
                term(row, 'i', p, br[p].resistance())
                rows.append(row)
        n = len(unknowns)
        ring = coefficient_ring([br[p].resistance() for p in linear])
        A = matrix(ring, n, n, {(j, k): c for j, (a, _) in enumerate(rows)
                                for k, c in a.items()})
        K = matrix(ring, n, len(columns), {(j, k): -c for j, (_, a) in enumerate(rows)
                                           for k, c in a.items()})
        if n and A.rank() < n:
            self._singular(A, unknowns)
        X = A.solve_right(K) if n else K
        value = {key: None if key[0] == 'i' and key[1] in res
                 else self._known(key[1], key[0]) for key in columns}
        keys = list(columns)
        row_of = {x: X.row(where[x]) for x in unknowns}

        # floating-point results as Sage reals (a Python float inside SR breaks
        # matrix algebra)
        to_sr = (lambda c: SR(RR(c))) if ring is RDF else SR

        def combination(x):
            v = row_of[x]
            return sum((to_sr(v[columns[key]]) * value[key] for key in keys
                        if v[columns[key]] != 0), SR(0))

        nonlinear = [p for p in res if p not in linear]
        depends = {p: [g for g in nonlinear if ('i', g) in columns and
                       row_of[('u', p)][columns[('i', g)]] != 0] for p in nonlinear}
        for p in self._explicit_order(nonlinear, depends):
            value[('i', p)] = br[p].current(combination(('u', p)))
        self._voltage = {p: combination(('u', p)) for p in res}
        self._current = {p: combination(('i', p)) if p in linear
                         else value.get(('i', p)) for p in res}

    def _singular(self, A, unknowns):
        br = self._branches
        kernel = A.right_kernel_matrix()
        free = sorted({unknowns[k][1] for v in kernel.rows() for k, c in enumerate(v)
                       if c != 0})
        nonlinear = [p for p in free if br[p].resistance() is None]
        if nonlinear:
            p = nonlinear[0]
            raise NotExplicitError(f"{NOT_EXPLICIT}: the voltage of the nonlinear resistor "
                               f"{br[p].name} is fixed by no capacitor, voltage source or "
                               f"resistor (its current is; i = {br[p].name}(u) would have "
                               "to be inverted)", entry=f"branches[{br[p].index}]")
        names = ', '.join(br[p].name for p in free)
        raise CircuitError(f"the voltages and currents of the resistors {names} are not "
                           "unique for these element values (no unique solution)",
                           entry=f"branches[{br[free[0]].index}]")

    def _explicit_order(self, nonlinear, depends):
        # the nonlinear resistors in an order where each voltage depends only
        # on the currents of earlier ones; a cycle makes the equations implicit
        done, order, state = set(), [], {}

        def visit(p, path):
            if p in done:
                return
            if state.get(p) == 'open':
                self._implicit(path[path.index(p):-1])
            state[p] = 'open'
            for g in depends[p]:
                visit(g, path + [g])
            state[p] = 'closed'
            done.add(p)
            order.append(p)

        for p in nonlinear:
            visit(p, [p])
        return order

    def _implicit(self, cycle):
        br = self._branches
        involved = []
        for p in cycle:
            near = self._cut[p] if p in self._tree else self._loops[p]
            involved += [br[q].name for q, _ in near
                         if br[q].resistance() is not None and br[q].name not in involved]
        f = ', '.join(br[p].name for p in cycle)
        what = (f"the voltage of the nonlinear resistor {f} depends on its own current "
                f"i = {f}(u)" if len(cycle) == 1 else
                f"the voltages of the nonlinear resistors {f} depend on each other's "
                "currents i = f(u)")
        through = (f" through the resistor{'s' if len(involved) > 1 else ''} "
                   f"{', '.join(involved)}" if involved else "")
        raise NotExplicitError(f"{NOT_EXPLICIT}: {what}{through} (an implicit equation)",
                           entry=f"branches[{br[cycle[0]].index}]")

    # ------------------------------------------------------------------
    # branch quantities

    def _tree_voltage(self, p):
        return self._voltage[p] if p in self._voltage else self._known(p, 'u')

    def _chord_current(self, p):
        return self._current[p] if p in self._current else self._known(p, 'i')

    def _repr_(self):
        return f"Modified nodal analysis of {self._circuit!r}"

    __repr__ = _repr_

    def _triples(self, positions):
        br = self._branches
        return [(br[p].tail, br[p].head, br[p].name) for p in positions]

    def tree(self):
        r"""
        The normal tree (a forest when the circuit has parts joined only by
        mutual inductances) as triples ``(from, to, name)``, in branch order.

        EXAMPLES: the capacitor ``C2`` closes a loop with ``C1`` and is left
        out::

            sage: from sage_dynsym.circuits import Circuit
            sage: C = Circuit([[1, 2, 'L1'], [2, 1, 'C1'], [2, 1, 'C2'], [2, 1, 'R1']])
            sage: C.nodal_analysis().tree()
            [(2, 1, 'C1')]
        """
        return self._triples(sorted(self._tree))

    def state_variables(self):
        r"""
        The state variables, pairs ``(symbol, element name)``: the currents
        of the inductor chords, then the voltages of the capacitors of the
        tree (naming rule in the module documentation).

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: C = Circuit([[1, 2, 'L1'], [2, 1, 'C1'], [2, 1, 'C2'], [2, 1, 'R1']])
            sage: C.nodal_analysis().state_variables()
            [(i1, 'L1'), (u2, 'C1')]
        """
        br = self._branches
        return [(self._symbol[p], br[p].name) for p in self._inductors + self._capacitors]

    def _inductor_currents(self):
        # every inductor's current in the state and the current sources
        br = self._branches
        current = {p: self._symbol[p] for p in self._inductors}
        for p, b in enumerate(br):
            if b.is_inductive() and p in self._tree:
                current[p] = sum((s * self._chord_current(k) for k, s in self._cut[p]), SR(0))
        return current

    def _capacitor_voltages(self):
        br = self._branches
        voltage = {p: self._symbol[p] for p in self._capacitors}
        for p, b in enumerate(br):
            if b.is_capacitive() and p not in self._tree:
                voltage[p] = -sum((s * self._tree_voltage(q) for q, s in self._loops[p]),
                                  SR(0))
        return voltage

    def _inductor_blocks(self):
        # (P_L^T L P_L, P_L^T L Q_L, the chord current sources)
        br = self._branches
        inductors = [p for p, b in enumerate(br) if b.is_inductive()]
        index = {p: a for a, p in enumerate(inductors)}
        current = self._inductor_currents()
        L = winding_matrix([br[p] for p in inductors], self._circuit.couplings(),
                           currents=[current[p] for p in inductors])
        sources = [k for k in self._chords if br[k].fixed_current() is not None
                   and any(br[q].is_inductive() for q, _ in self._loops[k])]
        P = matrix(SR, len(inductors), len(self._inductors))
        Q = matrix(SR, len(inductors), len(sources))
        for j, k in enumerate(self._inductors):
            P[index[k], j] = 1
            for q, s in self._loops[k]:
                if br[q].is_inductive():
                    P[index[q], j] += s
        for j, k in enumerate(sources):
            for q, s in self._loops[k]:
                if br[q].is_inductive():
                    Q[index[q], j] += s
        return P.transpose() * L * P, P.transpose() * L * Q, sources

    def _capacitor_blocks(self):
        # (P_C^T C P_C, P_C^T C Q_C, the tree voltage sources)
        br = self._branches
        capacitors = [p for p, b in enumerate(br) if b.is_capacitive()]
        index = {p: a for a, p in enumerate(capacitors)}
        voltage = self._capacitor_voltages()
        Cd = matrix.diagonal(SR, [br[p].value_at(voltage[p]) for p in capacitors])
        sources = sorted({q for k in self._chords if br[k].is_capacitive()
                          for q, _ in self._loops[k] if br[q].fixed_voltage() is not None})
        column = {q: j for j, q in enumerate(self._capacitors)}
        scol = {q: j for j, q in enumerate(sources)}
        P = matrix(SR, len(capacitors), len(self._capacitors))
        Q = matrix(SR, len(capacitors), len(sources))
        for q in self._capacitors:
            P[index[q], column[q]] = 1
        for k in self._chords:
            if br[k].is_capacitive():
                for q, s in self._loops[k]:
                    if q in column:
                        P[index[k], column[q]] -= s
                    else:
                        Q[index[k], scol[q]] -= s
        return P.transpose() * Cd * P, P.transpose() * Cd * Q, sources

    @cached_method
    def _lhs(self):
        BL = self._inductor_blocks()[0]
        BC = self._capacitor_blocks()[0]
        B = block_diagonal_matrix([BL, BC], subdivide=False).apply_map(
            lambda e: SR(e).expand())
        B.set_immutable()
        return B

    def lhs_matrix(self):
        r"""
        The matrix `B` of `B\dot x = F(x)`: the effective inductance matrix
        `P_L^T \mathbf{L} P_L` of the inductor chords (mutual inductances
        included) and the effective capacitance matrix `P_C^T \mathbf{C}
        P_C` of the tree capacitors, block-diagonal, rows and columns in the
        order of :meth:`state_variables`.

        EXAMPLES: two coupled inductors in series carry one current::

            sage: from sage_dynsym.circuits import Circuit
            sage: C = Circuit([[1, 2, 'L1'], [2, 3, 'L2'], [3, 1, 'R1'],
            ....:     {'kind': 'mutual', 'between': ['L1', 'L2'], 'value': 'M'}], parameters=['M'])
            sage: C.nodal_analysis().lhs_matrix()
            [L1 + L2 + 2*M]
        """
        return self._lhs()

    def state_equations(self):
        r"""
        The right-hand sides `F` of `B\dot x = F(x)` (see
        :meth:`lhs_matrix`), in the order of :meth:`state_variables`: the
        voltage law around the loop of each inductor chord, the current law
        on the cut-set of each capacitor of the tree.

        EXAMPLES: two capacitors in series across a time-dependent voltage
        source; the source drives the current `C_1\, dE/dt` through
        them::

            sage: from sage_dynsym.circuits import Circuit
            sage: C = Circuit([{'from': 0, 'to': 1, 'kind': 'voltage_source', 'name': 'E1',
            ....:               'value': 'E0*sin(w*t)'}, [1, 2, 'C1'], [2, 0, 'C2'],
            ....:              [2, 0, 'R1']], parameters=['E0', 'w'])
            sage: A = C.nodal_analysis(); A.state_variables()
            [(u1, 'C2')]
            sage: A.state_equations(), A.lhs_matrix()
            ([-C1*E0*w*cos(t*w) - u1/R1], [C1 + C2])
        """
        return list(self._rhs())

    @cached_method
    def _rhs(self):
        br = self._branches
        _, LQ, isources = self._inductor_blocks()
        _, CQ, esources = self._capacitor_blocks()
        rate = lambda ps: matrix(SR, len(ps), 1, [SR(br[q].value).diff(t) for q in ps])
        rhs = []
        for j, k in enumerate(self._inductors):
            F = sum((s * self._tree_voltage(q) for q, s in self._loops[k]
                     if not br[q].is_inductive()), SR(0))
            if isources:
                F -= (LQ * rate(isources))[j, 0]
            rhs.append(F)
        column = {q: j for j, q in enumerate(self._capacitors)}
        currents = [SR(0)] * len(self._capacitors)
        for k in self._chords:
            if not br[k].is_capacitive():
                for q, s in self._loops[k]:
                    if q in column:
                        currents[column[q]] -= s * self._chord_current(k)
        if esources:
            drive = CQ * rate(esources)
            currents = [c - drive[j, 0] for j, c in enumerate(currents)]
        states = [x for x, _ in self.state_variables()]
        return [_collect(e, states) for e in rhs + currents]


def _collect(expr, states):
    r"""
    ``expr`` written as `\sum_k c_k x_k + r` with each coefficient and the
    rest in lowest terms, when it is linear in the states ``x_k``;
    unchanged otherwise.

    EXAMPLES::

        sage: from sage_dynsym.circuits.nodal import _collect
        sage: x, E, R1, R2 = var('x E R1 R2')
        sage: _collect(E - E*R1/(R1 + R2) + x - R1*x/(R1 + R2), [x])
        E*R2/(R1 + R2) + R2*x/(R1 + R2)
        sage: _collect(sin(x) + 1, [x])
        sin(x) + 1
    """
    coefficients = [expr.diff(x) for x in states]
    if any(c.has(x) for c in coefficients for x in states):
        return expr
    rest = expr.subs({x: 0 for x in states})
    return sum((c.simplify_rational() * x for c, x in zip(coefficients, states)
                if not c.is_zero()), rest.simplify_rational())
