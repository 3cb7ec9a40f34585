r"""
Brayton--Moser mixed potential of a complete circuit

For a *complete* circuit the state equations are

.. MATH::

    L_k(i_k)\, \frac{di_k}{dt} = \frac{\partial P}{\partial i_k}, \qquad
    C_l(u_l)\, \frac{du_l}{dt} = -\frac{\partial P}{\partial u_l},
    \qquad P(i, u) = F(i) - G(u) + (i, \gamma u)

(with mutual inductances the left-hand sides are the rows of
`\mathbf{L}\, di/dt`). The construction, in the branch variables of
:mod:`~sage_dynsym.circuits.elements`:

1. `T_C`: the capacitors and voltage sources; they must form a forest
   (otherwise a loop of capacitors and voltage sources: not complete).
2. `\Omega_u`: capacitors, voltage sources, and the resistors, nonlinear
   resistors and current sources whose two nodes are joined by `T_C` (their
   voltage is fixed by the capacitor voltages and the sources).
   `\Omega_i`: all other branches -- inductors, and resistors and current
   sources whose current must then be fixed by the inductor and
   current-source currents. This is checked: `T_C` plus the resistors of
   `\Omega_i` must be a spanning tree `K` of the graph. If it has a loop,
   those resistors are determined neither way and the split is impossible;
   if it is not connected, inductors and current sources form a cut-set
   (not complete). A nonlinear resistor `i = f(u)` must lie in `\Omega_u`.
3. The loop `\Lambda_p` of inductor `p` is its fundamental loop in `K`,
   oriented along the inductor; it closes through `T_C` and resistors of
   `\Omega_i`. Currents of `\Omega_i` resistors follow from these loops,
   voltages of `\Omega_u` branches from `T_C`.
4. `F(i) = \sum_{\rho \in \Omega_i} \int u_\rho\, di_\rho` (resistors:
   `-R i_\rho^2/2`); `G(u) = \sum_{\mu \in \Omega_u} \int_0^{u_\mu}
   i_\mu\, du_\mu` over resistors (`-u_\mu^2/(2R)`), nonlinear resistors
   (`\int_0^{u_\mu} f(s)\,ds`) and current sources (`I u_\mu`); a current
   source in `\Omega_i` adds `-I \sum \pm u_\sigma` over the capacitors on
   its own fundamental loop; `(i, \gamma u) = \sum_p i_p
   \sum_{\sigma \in \Lambda_p \cap T_C} \pm u_\sigma`, the sign ``+`` when
   the loop runs along `\sigma`'s orientation (`u_\sigma = E` for a
   voltage source).

Why this gives the state equations: Tellegen's theorem applied to the
actual branch voltages and the unit current around `\Lambda_k` gives
`-u_{L_k} = \partial P / \partial i_k`; applied to the actual currents and
the unit voltage of capacitor `l` it gives `i_{C_l} = \partial P /
\partial u_l`; with `u_L = -L\, di/dt` and `i_C = -C\, du/dt` these are (8).

**Naming of the state variables.** Inductor currents are ``i1, ..., ir``
in the order of the branch list; capacitor voltages continue the numbering,
``u(r+1), ..., u(r+m)``, in breadth-first order of the capacitor forest,
each tree of it started at its highest node (trees taken from the highest
such node down) and neighbours visited in increasing node order. For
Example 2 this gives ``i1, i2`` for ``L1, L2`` and ``u3, u4, u5, u6`` for
``C3, C2, C4, C1``, exactly the names used in :doc:`the method </method>`.

EXAMPLES:

Example 2 of :doc:`the method </method>`, read from its description file::

    sage: import os, yaml, sage_dynsym
    sage: from sage_dynsym.circuits import circuit_from_dict
    sage: path = os.path.join(os.path.dirname(sage_dynsym.__file__), os.pardir,
    ....:                     'examples', 'nonlinear_circuit.yaml')
    sage: with open(path) as f:
    ....:     C = circuit_from_dict(yaml.safe_load(f), source=path)
    sage: C
    Circuit 'nonlinear circuit of Example 2' with 13 branches on 5 nodes
    sage: BM = C.brayton_moser()
    sage: BM.state_variables()
    [(i1, 'L1'), (i2, 'L2'), (u3, 'C3'), (u4, 'C2'), (u5, 'C4'), (u6, 'C1')]

The split, with `\Omega_i = \{\{1,2\} L_1, \{3,4\} L_2\}`, and the loops
`\Lambda_1, \Lambda_2` (each step is ``(node, next node, element)``)::

    sage: BM.omega_i()
    [(1, 2, 'L1'), (3, 4, 'L2')]
    sage: BM.omega_u()
    [(2, 3, 'f1'), (2, 3, 'C1'), (4, 5, 'I02'), (4, 5, 'C4'), (4, 5, 'f4'),
     (3, 5, 'C2'), (3, 5, 'f2'), (5, 2, 'I0'), (1, 5, 'C3'), (1, 5, 'f3'), (1, 5, 'I01')]
    sage: BM.loops()
    [[(1, 2, 'L1'), (2, 3, 'C1'), (3, 5, 'C2'), (5, 1, 'C3')],
     [(3, 4, 'L2'), (4, 5, 'C4'), (5, 3, 'C2')]]

`F`, `G`, `(i, \gamma u)` and `P`::

    sage: BM.current_potential()
    0
    sage: G = BM.voltage_potential(); G
    I01*u3 - I0*(u4 + u6) + I02*u5 + integrate(f1(s), s, 0, u6)
     + integrate(f2(s), s, 0, u4) + integrate(f3(s), s, 0, u3) + integrate(f4(s), s, 0, u5)
    sage: J = BM.coupling_term(); J
    -i1*(u3 - u4 - u6) - i2*(u4 - u5)
    sage: bool(J == var('i1')*(var('u4') + var('u6') - var('u3')) + var('i2')*(var('u5') - var('u4')))
    True
    sage: BM.gamma_matrix()
    [-1  1  0  1]
    [ 0 -1  1  0]
    sage: P = C.mixed_potential(); bool(P == -G + J)
    True

The six state equations (11), in the order of the state variables::

    sage: for (x, name), rhs in zip(C.state_variables(), C.state_equations()):
    ....:     print(f"{name} d{x}/dt = {rhs}")
    L1 di1/dt = -u3 + u4 + u6
    L2 di2/dt = -u4 + u5
    C3 du3/dt = I01 + i1 + f3(u3)
    C2 du4/dt = -I0 - i1 + i2 + f2(u4)
    C4 du5/dt = I02 - i2 + f4(u5)
    C1 du6/dt = -I0 - i1 + f1(u6)

The time derivative of `P` along them (Lyapunov-function analogue)::

    sage: BM.time_derivative()
    -(I0 + i1 - i2 - f2(u4))^2/C2 - (I0 + i1 - f1(u6))^2/C1
     - (I01 + i1 + f3(u3))^2/C3 - (I02 - i2 + f4(u5))^2/C4
     + (u3 - u4 - u6)^2/L1 + (u4 - u5)^2/L2

Nonlinear inductances and capacitances (depending on their own variable)
only change the left-hand sides::

    sage: from sage_dynsym.circuits import Circuit
    sage: C2 = Circuit([{'from': 1, 'to': 2, 'kind': 'inductor', 'name': 'L1',
    ....:                'value': 'L0/(1 + i^2)'}, [2, 1, 'C1'], [2, 1, 'f1']], parameters=['L0'])
    sage: C2.brayton_moser().inductance_matrix(), C2.state_equations()
    ([L0/(i1^2 + 1)], [u2, -i1 + f1(u2)])

REFERENCES:

- R. K. Brayton, J. K. Moser, *A theory of nonlinear networks I*,
  Quart. Appl. Math. 22 (1964) 1--33.
"""
from sage.symbolic.ring import SR
from sage.matrix.constructor import matrix

from ..errors import CircuitError
from .elements.kinds import state_symbols
from .elements.windings import winding_matrix
from .graph import capacitor_order

__all__ = ['MixedPotential']


class MixedPotential:
    r"""
    The Brayton--Moser data of a complete circuit (see the module
    documentation for the construction and the conventions).

    Built by :meth:`~sage_dynsym.circuits.circuit.Circuit.brayton_moser`.

    EXAMPLES::

        sage: from sage_dynsym.circuits import Circuit
        sage: C = Circuit([[0, 1, 'E1'], [1, 2, 'L1'], [2, 0, 'C1'], [2, 0, 'R2']])
        sage: BM = C.brayton_moser(); BM
        Brayton-Moser mixed potential of Circuit with 4 branches on 3 nodes
        sage: BM.omega_i(), BM.tree()
        ([(1, 2, 'L1')], [(0, 1, 'E1'), (2, 0, 'C1')])
        sage: BM.voltage_potential(), BM.coupling_term()
        (-1/2*u2^2/R2, (E1 + u2)*i1)
        sage: BM.state_equations()
        [E1 + u2, -i1 - u2/R2]

    TESTS::

        sage: Circuit([[1, 2, 'C1'], [2, 3, 'C2'], [3, 1, 'E1'], [1, 3, 'L1']]).brayton_moser()
        Traceback (most recent call last):
        ...
        CircuitError: the circuit is not complete: the capacitors and voltage sources E1, C1, C2 form a loop; the capacitor voltages are not independent
        sage: Circuit([[1, 2, 'L1'], [2, 3, 'I1'], [3, 1, 'C1'], [3, 1, 'R1']]).brayton_moser()
        Traceback (most recent call last):
        ...
        CircuitError: the circuit is not complete: the inductors and current sources L1, I1 form a cut-set; the inductor currents are not independent
        sage: Circuit([[1, 2, 'I1'], [2, 3, 'f1'], [3, 1, 'C1'], [3, 1, 'L1']]).brayton_moser()
        Traceback (most recent call last):
        ...
        CircuitError: branches[1]: no Brayton-Moser split: the nonlinear resistor f1 is voltage-controlled ...
        sage: Circuit([[1, 2, 'L1'], [2, 3, 'R1'], [3, 1, 'R2'], [2, 1, 'C1']]).brayton_moser()
        Traceback (most recent call last):
        ...
        CircuitError: branches[2]: no Brayton-Moser split: the resistors R2, R1 lie in a loop R2, C1, R1 ...
    """

    def __init__(self, circuit):
        self._circuit = circuit
        cg = circuit.circuit_graph()
        self._branches = br = cg.branches
        self._pos = pos_of = {b.name: p for p, b in enumerate(br)}
        tc = [p for p, b in enumerate(br) if b.sets_voltage]
        try:
            forest = cg.components(tc)
        except ValueError as err:
            loop = cg.cycle_through(tc[:tc.index(err.args[0])], err.args[0])
            raise CircuitError("the circuit is not complete: the capacitors and "
                               f"voltage sources {', '.join(loop)} form a loop; "
                               "the capacitor voltages are not independent") from err
        self._tc = frozenset(tc)
        omega_u, omega_i, tree = [], [], list(tc)
        for p, b in enumerate(br):
            fixed_voltage = forest.find(b.tail) == forest.find(b.head)
            if b.sets_voltage or (b.voltage_controlled and fixed_voltage):
                omega_u.append(p)
            elif not (b.sets_current or b.current_controlled):
                raise CircuitError(
                    f"no Brayton-Moser split: the nonlinear resistor {b.name} is "
                    "voltage-controlled (i = f(u)) but its voltage is not fixed by "
                    "the capacitor voltages and voltage sources",
                    entry=f"branches[{b.index}]")
            else:
                omega_i.append(p)
                if b.current_controlled:    # a resistor: its current from the loops
                    tree.append(p)
        self._omega_u, self._omega_i = omega_u, omega_i
        try:
            kforest = cg.components(tree)
        except ValueError as err:
            loop = cg.cycle_through(tree[:tree.index(err.args[0])], err.args[0])
            res = [n for n in loop if br[pos_of[n]].current_controlled]
            raise CircuitError(
                f"no Brayton-Moser split: the resistors {', '.join(res)} lie in a loop "
                f"{', '.join(loop)} of resistors, capacitors and voltage sources; their "
                "voltages are not fixed by the capacitors and their currents are not "
                "fixed by the inductors",
                entry=f"branches[{br[err.args[0]].index}]") from err
        parts = cg.graph.connected_components(sort=False)
        if len(tree) != len(cg.nodes) - len(parts):
            # a part of the graph that K does not span: its piece around its
            # first node is cut off by inductors and current sources
            part = next(c for c in parts if len({kforest.find(v) for v in c}) > 1)
            root = kforest.find(part[0])
            cut = [b.name for b in br
                   if (kforest.find(b.tail) == root) != (kforest.find(b.head) == root)]
            raise CircuitError("the circuit is not complete: the inductors and current "
                               f"sources {', '.join(cut)} form a cut-set; the inductor "
                               "currents are not independent")
        self._tree = cg.rooted(tree)
        self._name_states(cg)
        self._build()

    def _name_states(self, cg):
        br = self._branches
        inductors = [p for p, b in enumerate(br) if b.is_inductive()]
        capacitors = capacitor_order(cg)     # a forest here: the circuit is complete
        self._inductors, self._capacitors = inductors, capacitors
        self._symbol = state_symbols(br, inductors + capacitors)

    def _voltage(self, p):
        # voltage of a branch of T_C: a state variable or a source value
        return self._branches[p].known_voltage(self._symbol.get(p))

    def _current(self, p):
        # current of an inductor or current source of Omega_i
        return self._branches[p].known_current(self._symbol.get(p))

    def _build(self):
        br, tree, tc, pos_of = self._branches, self._tree, self._tc, self._pos
        used = {str(v) for b in br if b.value is not None for v in b.value.variables()}
        used |= {str(x) for x in self._symbol.values()}
        s = SR.var('s_' if 's' in used else 's')
        self._loops = {p: tree.loop(br[p]) for p in self._omega_i if br[p].sets_current}
        alpha = {}          # currents of the Omega_i resistors, from the loops
        for p, loop in self._loops.items():
            for sigma, sign in loop[1:]:
                if sigma.current_controlled:
                    q = pos_of[sigma.name]
                    alpha[q] = alpha.get(q, 0) + sign * self._current(p)
        F = SR(0)
        for q in self._omega_i:
            term = br[q].current_potential(alpha.get(q, 0))
            if term is not None:
                F += term
        G = SR(0)
        for p in self._omega_u:
            b = br[p]
            if not b.voltage_controlled:
                continue
            beta = -sum(sign * self._voltage(pos_of[sigma.name])
                        for sigma, sign in tree.loop(b)[1:])
            G += b.voltage_potential(beta, s)
        J = SR(0)
        for p, loop in self._loops.items():
            I = br[p].fixed_current()
            if I is None:       # an inductor
                J += self._symbol[p] * sum(sign * self._voltage(pos_of[sigma.name])
                                           for sigma, sign in loop[1:]
                                           if pos_of[sigma.name] in tc)
            else:   # a current source of Omega_i; constant terms dropped
                G -= I * sum(sign * self._symbol[pos_of[sigma.name]]
                             for sigma, sign in loop[1:] if sigma.is_capacitive())
        self._F, self._G, self._J = F, G, J
        self._P = F - G + J

    def _repr_(self):
        return f"Brayton-Moser mixed potential of {self._circuit!r}"

    __repr__ = _repr_

    def _latex_(self):
        r"""
        The state equations (8) as an aligned system.

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: BM = Circuit([[0, 1, 'E1'], [1, 2, 'L1'], [2, 0, 'C1'], [2, 0, 'f1']]).brayton_moser()
            sage: latex(BM)
            \begin{aligned}
            L_{1} \dot{i_{1}} &= E_{1} + u_{2} \\
            C_{1} \dot{u_{2}} &= -i_{1} + f_{1}\left(u_{2}\right)
            \end{aligned}
        """
        from sage.misc.latex import latex
        xs = [x for x, _ in self.state_variables()]
        r = len(self._inductors)
        Lm = self.inductance_matrix()
        lhs = [" + ".join(f"{latex(Lm[k, j])} \\dot{{{latex(xs[j])}}}"
                          for j in range(r) if not Lm[k, j].is_zero()) for k in range(r)]
        lhs += [f"{latex(c)} \\dot{{{latex(x)}}}" for c, x in zip(self.capacitances(), xs[r:])]
        rows = [f"{a} &= {latex(b)}" for a, b in zip(lhs, self.state_equations())]
        return "\\begin{aligned}\n" + " \\\\\n".join(rows) + "\n\\end{aligned}"

    def _states(self):
        return self._inductors + self._capacitors

    def state_variables(self):
        r"""
        The state variables as pairs ``(symbol, element name)``: inductor
        currents first, then capacitor voltages (naming rule in the module
        documentation).

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: BM = Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 3, 'L1'], [3, 0, 'C1'],
            ....:              [3, 0, 'f1'], [0, 3, 'I1']]).brayton_moser()
            sage: BM.state_variables()
            [(i1, 'L1'), (u2, 'C1')]
        """
        br = self._branches
        return [(self._symbol[p], br[p].name) for p in self._states()]

    def _triples(self, positions):
        br = self._branches
        return [(br[p].tail, br[p].head, br[p].name) for p in positions]

    def omega_i(self):
        r"""
        The branches of `\Omega_i` (current fixed by the inductor and
        current-source currents) as triples ``(from, to, name)``.

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: BM = Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 3, 'L1'], [3, 0, 'C1'],
            ....:              [3, 0, 'f1'], [0, 3, 'I1']]).brayton_moser()
            sage: BM.omega_i()
            [(1, 2, 'R1'), (2, 3, 'L1')]
        """
        return self._triples(self._omega_i)

    def omega_u(self):
        r"""
        The branches of `\Omega_u` (voltage fixed by the capacitor voltages
        and voltage sources) as triples ``(from, to, name)``.

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: BM = Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 3, 'L1'], [3, 0, 'C1'],
            ....:              [3, 0, 'f1'], [0, 3, 'I1']]).brayton_moser()
            sage: BM.omega_u()
            [(0, 1, 'E1'), (3, 0, 'C1'), (3, 0, 'f1'), (0, 3, 'I1')]
        """
        return self._triples(self._omega_u)

    def tree(self):
        r"""
        The spanning tree `K` (capacitors, voltage sources and the resistors
        of `\Omega_i`) as triples ``(from, to, name)``.

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: BM = Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 3, 'L1'], [3, 0, 'C1'],
            ....:              [3, 0, 'f1'], [0, 3, 'I1']]).brayton_moser()
            sage: BM.tree()
            [(0, 1, 'E1'), (1, 2, 'R1'), (3, 0, 'C1')]
        """
        return self._triples(sorted(self._tree.positions))

    def loops(self):
        r"""
        The loops `\Lambda_p`, one per inductor (in the order of the state
        variables), each a list of triples ``(node, next node, name)`` in the
        order they are walked, starting with the inductor along its
        orientation.

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: BM = Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 3, 'L1'], [3, 0, 'C1'],
            ....:              [3, 0, 'f1'], [0, 3, 'I1']]).brayton_moser()
            sage: BM.loops()
            [[(2, 3, 'L1'), (3, 0, 'C1'), (0, 1, 'E1'), (1, 2, 'R1')]]
        """
        return [[(b.tail, b.head, b.name) if sign > 0 else (b.head, b.tail, b.name)
                 for b, sign in self._loops[p]] for p in self._inductors]

    def current_potential(self):
        r"""The current potential `F(i)`.

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: BM = Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 3, 'L1'], [3, 0, 'C1'],
            ....:              [3, 0, 'f1'], [0, 3, 'I1']]).brayton_moser()
            sage: BM.current_potential()
            -1/2*R1*i1^2
        """
        return self._F

    def voltage_potential(self):
        r"""The voltage potential `G(u)`.

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: BM = Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 3, 'L1'], [3, 0, 'C1'],
            ....:              [3, 0, 'f1'], [0, 3, 'I1']]).brayton_moser()
            sage: BM.voltage_potential()
            -I1*u2 + integrate(f1(s), s, 0, u2)
        """
        return self._G

    def coupling_term(self):
        r"""The bilinear term `(i, \gamma u)`, voltage sources included.

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: BM = Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 3, 'L1'], [3, 0, 'C1'],
            ....:              [3, 0, 'f1'], [0, 3, 'I1']]).brayton_moser()
            sage: BM.coupling_term()
            (E1 + u2)*i1
        """
        return self._J

    def gamma_matrix(self):
        r"""
        The matrix `\gamma` (rows: inductor currents, columns: capacitor
        voltages, in the order of :meth:`state_variables`).

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: BM = Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 3, 'L1'], [3, 0, 'C1'],
            ....:              [3, 0, 'f1'], [0, 3, 'I1']]).brayton_moser()
            sage: BM.gamma_matrix()
            [1]
        """
        rows = []
        for p in self._inductors:
            row = {q: 0 for q in self._capacitors}
            for sigma, sign in self._loops[p][1:]:
                if sigma.is_capacitive():
                    row[self._pos[sigma.name]] += sign
            rows.append([row[q] for q in self._capacitors])
        return matrix(SR, len(self._inductors), len(self._capacitors), rows)

    def mixed_potential(self):
        r"""The mixed potential `P(i, u) = F(i) - G(u) + (i, \gamma u)`.

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: BM = Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 3, 'L1'], [3, 0, 'C1'],
            ....:              [3, 0, 'f1'], [0, 3, 'I1']]).brayton_moser()
            sage: BM.mixed_potential()
            -1/2*R1*i1^2 + (E1 + u2)*i1 + I1*u2 - integrate(f1(s), s, 0, u2)
        """
        return self._P

    def inductance_matrix(self):
        r"""
        The inductance matrix `\mathbf{L}(i)` of the inductors (mutual
        inductances off the diagonal), in the order of the state variables.

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: BM = Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 3, 'L1'], [3, 0, 'C1'],
            ....:              [3, 0, 'f1'], [0, 3, 'I1']]).brayton_moser()
            sage: BM.inductance_matrix()
            [L1]
        """
        br, ind = self._branches, self._inductors
        return winding_matrix([br[p] for p in ind], self._circuit.couplings(),
                              currents=[self._symbol[p] for p in ind])

    def capacitances(self):
        r"""The capacitances `C_l(u_l)`, in the order of the state variables.

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: BM = Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 3, 'L1'], [3, 0, 'C1'],
            ....:              [3, 0, 'f1'], [0, 3, 'I1']]).brayton_moser()
            sage: BM.capacitances()
            [C1]
        """
        br = self._branches
        return [br[p].value_at(self._symbol[p]) for p in self._capacitors]

    def lhs_matrix(self):
        r"""
        The matrix `B` of `B\dot x =` :meth:`state_equations`: the
        :meth:`inductance_matrix` and the :meth:`capacitances`,
        block-diagonal, rows and columns in the order of
        :meth:`state_variables`.

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: BM = Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 3, 'L1'], [3, 0, 'C1'],
            ....:              [3, 0, 'f1'], [0, 3, 'I1']]).brayton_moser()
            sage: BM.lhs_matrix()
            [L1  0]
            [ 0 C1]
        """
        from sage.matrix.special import block_diagonal_matrix
        B = block_diagonal_matrix([self.inductance_matrix(),
                                   matrix.diagonal(SR, self.capacitances())], subdivide=False)
        B.set_immutable()
        return B

    def state_equations(self):
        r"""
        The right-hand sides of (8): `\partial P/\partial i_k` for the
        inductors, then `-\partial P/\partial u_l` for the capacitors, in
        the order of :meth:`state_variables`.

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: BM = Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 3, 'L1'], [3, 0, 'C1'],
            ....:              [3, 0, 'f1'], [0, 3, 'I1']]).brayton_moser()
            sage: BM.state_equations()
            [-R1*i1 + E1 + u2, -I1 - i1 + f1(u2)]
        """
        P = self._P
        return ([P.diff(self._symbol[p]) for p in self._inductors]
                + [-P.diff(self._symbol[p]) for p in self._capacitors])

    def time_derivative(self):
        r"""
        The total time derivative of `P` along the state equations,
        `dP/dt = P_i^T \mathbf{L}^{-1} P_i - \sum_l (\partial P/\partial u_l)^2 / C_l`.

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: BM = Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 3, 'L1'], [3, 0, 'C1'],
            ....:              [3, 0, 'f1'], [0, 3, 'I1']]).brayton_moser()
            sage: BM.time_derivative()
            -(I1 + i1 - f1(u2))^2/C1 + (R1*i1 - E1 - u2)^2/L1

        TESTS: perfectly coupled windings::

            sage: C = Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 0, 'L1'], [3, 4, 'L2'], [4, 3, 'R2'],
            ....:              {'kind': 'mutual', 'between': ['L1', 'L2'], 'value': 'sqrt(L1*L2)'}])
            sage: C.brayton_moser().time_derivative()
            Traceback (most recent call last):
            ...
            CircuitError: dP/dt needs the inverse of the inductance matrix, which is singular: some windings are perfectly coupled (M^2 = L1*L2), so their currents are not independent states
        """
        eqs = self.state_equations()
        r = len(self._inductors)
        Pi, Pu = eqs[:r], eqs[r:]
        if self._circuit.couplings():
            vec = matrix(SR, r, 1, Pi)
            L = self.inductance_matrix()
            if SR(L.det()).simplify_full().is_zero():
                raise CircuitError("dP/dt needs the inverse of the inductance matrix, which is "
                                   "singular: some windings are perfectly coupled (M^2 = "
                                   "L1*L2), so their currents are not independent states")
            di = (vec.transpose() * L.inverse() * vec)[0, 0]
        else:
            di = sum(x ** 2 / L for x, L in zip(Pi, self.inductance_matrix().diagonal()))
        return di - sum(x ** 2 / Cl for x, Cl in zip(Pu, self.capacitances()))
