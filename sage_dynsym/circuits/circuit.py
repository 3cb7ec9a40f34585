r"""
Electrical circuits

A :class:`Circuit` is an immutable graph of elementary branches (see
:mod:`~sage_dynsym.circuits.elements` for the entry forms and the
orientation convention). A linear circuit gives Lagrangians by the
loop-current and node-potential methods (:mod:`~sage_dynsym.circuits.linear`);
a complete, possibly nonlinear circuit gives the Brayton--Moser mixed
potential and the state equations (:mod:`~sage_dynsym.circuits.mixed_potential`);
any other circuit with a unique solution gets its state equations by
modified nodal analysis (:mod:`~sage_dynsym.circuits.nodal`).

EXAMPLES:

A series RLC circuit driven by a voltage source::

    sage: from sage_dynsym.circuits import Circuit
    sage: C = Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 3, 'L1'], [3, 0, 'C1']], name="RLC")
    sage: C
    Circuit 'RLC' with 4 branches on 4 nodes
    sage: L = C.lagrangian(method="loop"); L
    Lagrangian of RLC (loop method) in coordinates (q1) : 1/2*L1*dq1^2 - 1/2*q1^2/C1
    sage: L.lagrange_equations()
    [L1*ddq1 + R1*dq1 - E1 + q1/C1]
    sage: C.state_variables()
    [(i1, 'L1'), (u2, 'C1')]
    sage: C.state_equations()
    [-R1*i1 + E1 + u2, -i1]
    sage: C.brayton_moser().mixed_potential()
    -1/2*R1*i1^2 + (E1 + u2)*i1

Here `u_2 = \varphi(0) - \varphi(3)` is the rise across ``C1`` from node 3
to node 0, so `L_1\, di_1/dt = E_1 + u_2 - R_1 i_1` is Kirchhoff's voltage
law around the loop (the loop charge ``q1`` charges ``C1`` to `u_2 =
-q_1/C_1`).

The node-potential method gives Kirchhoff's current law instead::

    sage: Ln = C.lagrangian(method="node"); Ln.coordinates()
    [phi2, phi3]
    sage: Ln.lagrange_equations()
    [-(E1 - dphi2)/R1 + (phi2 - phi3)/L1, C1*ddphi3 - (phi2 - phi3)/L1]
"""

from sage.misc.cachefunc import cached_method
from sage.symbolic.ring import SR

from ..errors import CircuitError
from ..dynamics.model import Model
from ..numerics.methods import NumericalMethods
from ..numerics.values import check_model_values
from .elements.windings import inductance_conditions
from .format import read_circuit, circuit_mapping, circuit_results, result_symbols
from .forms import circuit_forms
from .free_system import free_linear_system
from .graph import CircuitGraph
from .netlist import Netlist
from .report import report_title, report_sections
from .state import StateEquations

__all__ = ['Circuit']


class Circuit(StateEquations, NumericalMethods, Model):
    r"""
    An electrical circuit given as a list of branches.

    INPUT:

    - ``branches`` -- list of entries ``[from, to, name]`` (the element kind
      follows the first letter of ``name``: ``R`` resistor, ``L`` inductor,
      ``C`` capacitor, ``E`` voltage source, ``I`` current source, ``f``
      nonlinear resistor `i = f(u)`), or long-form dicts
      ``{from, to, kind, name, value}`` and ``{kind: mutual, between:
      [L1, L2], value: M}`` (see :func:`~sage_dynsym.circuits.elements.entries.parse_entries`)
    - ``name`` -- (optional) a title
    - ``parameters`` -- (optional) extra symbols allowed in long-form values
    - ``positive`` -- (optional) parameters and element values known to be
      positive (:meth:`positive_parameters`); the analysis assumes no
      other sign

    The element name is its symbol (``L1`` is ``var('L1')``); a nonlinear
    resistor ``f1`` without a value is ``function('f1')`` of its branch
    voltage. In a long-form value, ``i`` stands for an inductor's own
    current and ``u`` for a capacitor's (or nonlinear resistor's) own voltage.

    EXAMPLES::

        sage: from sage_dynsym.circuits import Circuit
        sage: C = Circuit([[1, 2, 'L1'], {'from': 2, 'to': 1, 'kind': 'capacitor',
        ....:              'value': 'C0*(1 + u^2)', 'name': 'C1'}], parameters=['C0'])
        sage: C.branches()[1]
        Branch(index=1, name='C1', kind='capacitor', tail=2, head=1, value=(u^2 + 1)*C0)
        sage: C.brayton_moser().capacitances()
        [(u2^2 + 1)*C0]

    TESTS::

        sage: TestSuite(C).run()
        sage: Circuit([[1, 2, 'R1'], [2, 1, 'R1']])
        Traceback (most recent call last):
        ...
        CircuitError: branches[1]: duplicate element name 'R1'
        sage: Circuit([[1, 2, 'L1'], [2, 1, 'C1'], {'kind': 'mutual', 'between': ['L1', 'C1'], 'value': 'M'}])
        Traceback (most recent call last):
        ...
        CircuitError: branches[2]: a mutual inductance couples two inductors; C1 is not an inductor
        sage: Circuit([{'from': 1, 'to': 2, 'kind': 'resistor', 'name': 'q1'}, [2, 1, 'C1']])
        Traceback (most recent call last):
        ...
        CircuitError: branches[0]: the name 'q1' is reserved for variables ...
    """

    def __init__(self, branches, name=None, parameters=(), positive=()):
        self._netlist = netlist = Netlist(branches, parameters, positive)
        self._name = name
        self._parameters, self._positive = netlist.parameters, netlist.positive
        self._branches, self._couplings = netlist.branches, netlist.couplings
        where = {b.name: p for p, b in enumerate(self._branches)}
        self._cgraph = CircuitGraph(self._branches, links=[
            (where[c.first], where[c.second]) for c in self._couplings])
        self._conditions = inductance_conditions(self, netlist.coupling_entries)

    def _repr_(self):
        title = f" {self._name!r}" if self._name else ""
        extra = f" and {len(self._couplings)} mutual inductances" if self._couplings else ""
        return (f"Circuit{title} with {len(self._branches)} branches on "
                f"{len(self._cgraph.nodes)} nodes{extra}")

    def __eq__(self, other):
        return (isinstance(other, Circuit) and self._branches == other._branches
                and self._couplings == other._couplings
                and self._positive == other._positive)

    def __hash__(self):
        return hash((self._branches, self._couplings))

    # ------------------------------------------------------------------
    # the model interface

    kind = 'circuit'

    def characteristic_functions(self):
        r"""
        The characteristic functions of the circuit: the mixed potential,
        and for a linear circuit its loop and node Lagrangians (builders of
        no argument).

        EXAMPLES::

            sage: from sage_dynsym import load
            sage: from sage_dynsym.description import example_path
            sage: sorted(load(example_path('rlc_ladder.yaml')).characteristic_functions())
            ['lagrangian', 'mixed_potential', 'node_lagrangian']
        """
        functions = {'mixed_potential': self.mixed_potential}
        if all(b.is_linear() for b in self._branches):
            functions['lagrangian'] = lambda: self.lagrangian(method="loop")
            functions['node_lagrangian'] = lambda: self.lagrangian(method="node")
        return functions

    @classmethod
    def from_dict(cls, data, source=None):
        r"""
        The circuit of a description mapping (``kind: circuit``); ``source``
        names the file in errors. The format is read by
        :func:`~sage_dynsym.circuits.format.read_circuit`.

        EXAMPLES::

            sage: from sage_dynsym import Circuit
            sage: Circuit.from_dict({'kind': 'circuit', 'branches': [[1, 2, 'L1'], [2, 1, 'C1']]})
            Circuit with 2 branches on 2 nodes
        """
        return read_circuit(cls, data, source)

    def to_dict(self):
        r"""
        The description mapping of the circuit (short form wherever the
        element's value is its own symbol), the inverse of
        :meth:`from_dict`.

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: Circuit([[1, 2, 'L1'], [2, 1, 'L2'], [1, 2, 'f1'],
            ....:     {'kind': 'mutual', 'between': ['L1', 'L2'], 'value': 'M'}],
            ....:     parameters=['M']).to_dict()
            {'branches': [[1, 2, 'L1'],
                          [2, 1, 'L2'],
                          [1, 2, 'f1'],
                          {'between': ['L1', 'L2'], 'kind': 'mutual', 'value': 'M'}],
             'kind': 'circuit',
             'parameters': ['M']}
        """
        return circuit_mapping(self)

    def results(self):
        r"""
        The ``results:`` section of a saved description: the state
        equations (where the circuit has them), the mixed potential (of a
        complete circuit) and
        the loop Lagrangian of a linear circuit, as text and LaTeX.

        EXAMPLES::

            sage: from sage_dynsym import load
            sage: from sage_dynsym.description import example_path
            sage: sorted(load(example_path('nonlinear_circuit.yaml')).results())
            ['mixed_potential_latex', 'mixed_potential_text', 'state_equations',
             'state_equations_latex', 'state_variables']
        """
        return circuit_results(self)

    def result_symbols(self, results):
        r"""
        The names a ``results:`` section of this circuit may use: the
        parameters, element values, state variables, and the loop
        coordinates with their derivatives; the characteristics of nonlinear
        resistors as functions. The section's state variables must be the
        circuit's.

        EXAMPLES::

            sage: from sage_dynsym import load
            sage: from sage_dynsym.description import example_path
            sage: C = load(example_path('nonlinear_circuit.yaml'))
            sage: symbols, functions = C.result_symbols({})
            sage: 'L1' in symbols, functions
            (True, ['f1', 'f4', 'f2', 'f3'])
        """
        return result_symbols(self, results)

    def circuit_graph(self):
        r"""
        The :class:`~sage_dynsym.circuits.graph.CircuitGraph` of the
        branches (spanning trees, fundamental loops, cut-sets): what the
        loop, node, nodal and Brayton--Moser analyses share.

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: CG = Circuit([[1, 2, 'R1'], [2, 3, 'C1'], [3, 1, 'L1']]).circuit_graph(); CG
            Circuit graph with 3 branches on 3 nodes
            sage: CG.nodes, [b.name for b in CG.branches]
            ((1, 2, 3), ['R1', 'C1', 'L1'])
        """
        return self._cgraph

    def name(self):
        r"""The title of the circuit (or ``None``).

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: Circuit([[1, 2, 'L1'], [2, 1, 'C1']], name='LC').name()
            'LC'
            sage: Circuit([[1, 2, 'L1'], [2, 1, 'C1']]).name() is None
            True
        """
        return self._name

    def parameters(self):
        r"""The extra symbols declared for long-form values.

        EXAMPLES: a transformer, whose mutual inductance ``M`` is a parameter::

            sage: from sage_dynsym.circuits import Circuit
            sage: C = Circuit([[0, 1, 'E1'], [1, 0, 'L1'], [2, 0, 'L2'], [0, 2, 'R2'],
            ....:              {'kind': 'mutual', 'between': ['L1', 'L2'], 'value': 'M'}],
            ....:             parameters=['M'])
            sage: C.parameters()
            ('M',)
        """
        return self._parameters

    def branches(self):
        r"""
        The branches, a tuple of :class:`~sage_dynsym.circuits.elements.kinds.Branch`.

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: Circuit([[1, 2, 'L1'], [2, 1, 'C1']]).branches()
            (Branch(index=0, name='L1', kind='inductor', tail=1, head=2, value=L1),
             Branch(index=1, name='C1', kind='capacitor', tail=2, head=1, value=C1))
        """
        return self._branches

    def couplings(self):
        r"""
        The mutual inductances, a tuple of
        :class:`~sage_dynsym.circuits.elements.windings.Coupling`.

        EXAMPLES: a transformer::

            sage: from sage_dynsym.circuits import Circuit
            sage: C = Circuit([[0, 1, 'E1'], [1, 0, 'L1'], [2, 0, 'L2'], [0, 2, 'R2'],
            ....:              {'kind': 'mutual', 'between': ['L1', 'L2'], 'value': 'M'}],
            ....:             parameters=['M'])
            sage: C.couplings()
            (Coupling(first='L1', second='L2', value=M),)
        """
        return self._couplings

    def conditions(self):
        r"""
        The conditions on the parameters for the circuit to be physical that
        its declared signs leave open: the principal minors of the
        inductance matrix of each group of coupled windings `\ge 0` (see
        :mod:`~sage_dynsym.circuits.elements.windings`); ``[]`` when there is none.
        Values given to :meth:`simulate` and :meth:`numerical_rhs` must
        satisfy them.

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: C = Circuit([[0, 1, 'E1'], [1, 0, 'L1'], [2, 0, 'L2'], [0, 2, 'R2'],
            ....:              {'kind': 'mutual', 'between': ['L1', 'L2'], 'value': 'M'}],
            ....:             parameters=['M'], positive=['L1', 'L2'])
            sage: C.conditions()
            [L1*L2 - M^2 >= 0]
        """
        return list(self._conditions)

    def nodes(self):
        r"""
        The nodes, sorted.

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: Circuit([[3, 1, 'R1'], [1, 2, 'C1'], [2, 3, 'L1']]).nodes()
            [1, 2, 3]
        """
        return list(self._cgraph.nodes)

    def graph(self):
        r"""
        The circuit graph: an immutable Sage ``Graph`` with multiple edges,
        each edge labelled by its branch's position.

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: Circuit([[1, 2, 'R1'], [1, 2, 'C1']]).graph().edges(sort=True)
            [(1, 2, 0), (1, 2, 1)]
        """
        return self._cgraph.graph

    def elements(self, kind=None):
        r"""
        The element names, optionally only those of one ``kind``.

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: Circuit([[1, 2, 'R1'], [1, 2, 'C1'], [2, 1, 'R2']]).elements('resistor')
            ['R1', 'R2']
        """
        return [b.name for b in self._branches if kind is None or b.kind == kind]

    def subs(self, values):
        r"""
        The circuit with parameter and element values substituted.

        INPUT:

        - ``values`` -- a dictionary ``{symbol: value}``, keys symbols or
          names of parameters or elements (an element's name is its value's
          symbol); values exact numbers, expressions, or floats, each the
          exact decimal it prints as (``0.5`` is `1/2`)

        OUTPUT: a :class:`Circuit`; the substituted symbols leave
        :meth:`parameters` and :meth:`positive_parameters`

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: C = Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 3, 'L1'], [3, 0, 'C1']],
            ....:             positive=['R1'])
            sage: C2 = C.subs({'R1': 2, var('C1'): 0.5}); C2.state_equations()
            [E1 - 2*i1 + u2, -i1]
            sage: C2.lhs_matrix(), C2.positive_parameters()
            (
            [ L1   0]
            [  0 1/2], []
            )

        TESTS::

            sage: C.subs({'i1': 0})
            Traceback (most recent call last):
            ...
            CircuitError: subs: i1 is not a parameter or element value of the circuit; they are: E1, R1, L1, C1
            sage: C.subs({'R1': -2})
            Traceback (most recent call last):
            ...
            ModelError: subs: R1 is declared positive, got -2
            sage: Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 0, 'C1']]).subs({'R1': 0})
            Traceback (most recent call last):
            ...
            CircuitError: branches[1].value: a resistance of 0 is a short circuit: join its two nodes into one instead
        """
        check_model_values(self, values, entry="subs")
        entries, parameters, positive = self._netlist.subs(values)
        return Circuit(entries, name=self._name, parameters=parameters, positive=positive)

    @cached_method
    def loop_analysis(self):
        r"""
        The loop-current description (loops, matrices, energies); see
        :class:`~sage_dynsym.circuits.linear.LoopAnalysis`.

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: A = Circuit([[0, 1, 'E1'], [1, 0, 'L1'], [1, 2, 'R1'], [2, 0, 'C1']]).loop_analysis()
            sage: A.loops()
            [[(1, 0, 'L1'), (0, 1, 'E1')], [(1, 2, 'R1'), (2, 0, 'C1'), (0, 1, 'E1')]]
            sage: A.inductance_matrix(), A.elastance_matrix(), A.resistance_matrix()
            (
            [L1  0]  [   0    0]  [ 0  0]
            [ 0  0], [   0 1/C1], [ 0 R1]
            )
            sage: A.source_vector()
            [E1, E1]
        """
        from .linear import LoopAnalysis
        return LoopAnalysis(self)

    @cached_method
    def node_analysis(self, ground=None):
        r"""
        The node-potential description; see
        :class:`~sage_dynsym.circuits.linear.NodeAnalysis`.

        INPUT:

        - ``ground`` -- (default: node ``0`` if present, else the highest node)

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: A = Circuit([[0, 1, 'I1'], [1, 0, 'L1'], [1, 2, 'R1'], [2, 0, 'C1']]).node_analysis()
            sage: A.coordinates(), A.source_vector()
            ([phi1, phi2], [I1, 0])
            sage: A.capacitance_matrix(), A.inverse_inductance_matrix(), A.conductance_matrix()
            (
            [ 0  0]  [1/L1    0]  [ 1/R1 -1/R1]
            [ 0 C1], [   0    0], [-1/R1  1/R1]
            )
        """
        from .linear import NodeAnalysis
        return NodeAnalysis(self, ground)

    def lagrangian(self, method="loop", ground=None):
        r"""
        The Lagrangian `L = T - \Pi` of a linear circuit, with its Rayleigh
        function and generalized forces.

        INPUT:

        - ``method`` -- ``"loop"`` (loop charges ``q1, q2, ...``) or
          ``"node"`` (node flux linkages ``phi<node>``)
        - ``ground`` -- (node method) the grounded node

        OUTPUT: a :class:`~sage_dynsym.dynamics.lagrangian.Lagrangian`

        EXAMPLES:

        Two coupled inductors (a transformer) with a resistive load::

            sage: from sage_dynsym.circuits import Circuit
            sage: C = Circuit([[0, 1, 'E1'], [1, 0, 'L1'], [2, 0, 'L2'], [0, 2, 'R2'],
            ....:              {'kind': 'mutual', 'between': ['L1', 'L2'], 'value': 'M'}],
            ....:             parameters=['M'])
            sage: L = C.lagrangian(); L
            Lagrangian of circuit (loop method) in coordinates (q1, q2) : 1/2*L1*dq1^2 + M*dq1*dq2 + 1/2*L2*dq2^2
            sage: L.lagrange_equations()
            [L1*ddq1 + M*ddq2 - E1, M*ddq1 + L2*ddq2 + R2*dq2]

        The Lagrangian carries the declared signs of the element values; those
        of the sources, inputs that the analysis switches off, stay with the
        circuit::

            sage: C = Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 0, 'C1']], positive=['E1', 'R1'])
            sage: L = C.lagrangian(); L.positive_parameters()
            [R1]
            sage: L.subs(C.source_values_off()).numerical_rhs({'R1': -1, 'C1': 1})
            Traceback (most recent call last):
            ...
            ModelError: values: R1 is declared positive, got -1

        TESTS::

            sage: Circuit([[1, 2, 'f1'], [2, 1, 'C1']]).lagrangian()
            Traceback (most recent call last):
            ...
            CircuitError: branches[0]: the loop-current method needs a linear circuit, but f1 is nonlinear; use mixed_potential()
            sage: Circuit([[1, 2, 'R1'], [2, 1, 'C1']]).lagrangian(method="mesh")
            Traceback (most recent call last):
            ...
            CircuitError: unknown method 'mesh'; expected "loop" or "node"
        """
        from ..dynamics.lagrangian import Lagrangian
        if method == "loop":
            A = self.loop_analysis()
        elif method == "node":
            A = self.node_analysis(ground)
        else:
            raise CircuitError(f"unknown method {method!r}; expected \"loop\" or \"node\"")
        return Lagrangian(A.kinetic_energy() - A.potential_energy(), A.coordinates(),
                          dissipation=A.dissipation(), forces=A.source_vector(),
                          name=f"{self._name or 'circuit'} ({method} method)",
                          # the sources are inputs, switched off for the free
                          # circuit: their declared signs stay with the circuit
                          positive=[p for p in self.positive_parameters()
                                    if p not in self.source_values_off()])

    @cached_method
    def brayton_moser(self):
        r"""
        The Brayton--Moser data of a complete circuit: split, loops, `F`,
        `G`, `(i, \gamma u)`, mixed potential, state equations; see
        :class:`~sage_dynsym.circuits.mixed_potential.MixedPotential`.
        """
        from .mixed_potential import MixedPotential
        return MixedPotential(self)

    def mixed_potential(self):
        r"""
        The mixed potential `P(i, u) = F(i) - G(u) + (i, \gamma u)` of a
        complete circuit (see :meth:`brayton_moser`).

        EXAMPLES: a loop of an inductor, a resistor and a capacitor::

            sage: from sage_dynsym.circuits import Circuit
            sage: C = Circuit([[1, 2, 'L1'], [2, 3, 'R1'], [3, 1, 'C1']], name='RLC')
            sage: C.mixed_potential()
            -1/2*R1*i1^2 + i1*u2
        """
        return self.brayton_moser().mixed_potential()

    @cached_method
    def nodal_analysis(self):
        r"""
        The state equations by modified nodal analysis with a normal tree,
        for any solvable circuit (capacitor loops and inductor cut-sets
        reduce the state); see
        :class:`~sage_dynsym.circuits.nodal.NodalAnalysis`.

        EXAMPLES: a resistive bridge has no Brayton--Moser split::

            sage: from sage_dynsym.circuits import Circuit
            sage: C = Circuit([[1, 2, 'L1'], [2, 3, 'R1'], [3, 1, 'R2'], [2, 1, 'C1']])
            sage: C.nodal_analysis()
            Modified nodal analysis of Circuit with 4 branches on 3 nodes
        """
        from .nodal import NodalAnalysis
        return NodalAnalysis(self)

    def source_values_off(self):
        r"""
        The substitution that switches the sources off: the symbol of each
        voltage and current source to 0.

        EXAMPLES::

            sage: from sage_dynsym import Circuit
            sage: Circuit([[0, 1, 'E1'], [1, 0, 'R1'], [1, 0, 'I1']]).source_values_off()
            {E1: 0, I1: 0}
        """
        return {SR.var(b.name): 0 for b in self._netlist.sources()}

    def equation_forms(self):
        r"""
        The forms of the circuit's equations: Brayton--Moser, Lagrange
        (loop and node), Hamilton (loop); see :mod:`~sage_dynsym.circuits.forms`.

        EXAMPLES::

            sage: from sage_dynsym import Circuit
            sage: C = Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 0, 'C1']])
            sage: C.equation_forms()['Lagrange (node)']().equations
            [('0', C1*ddphi2 - (E1 - dphi2)/R1)]
        """
        return circuit_forms(self)

    def free_linear_system(self, at=None):
        r"""
        The state equations with the sources off, linearized around the
        zero state (``at``: other state values): what
        :func:`~sage_dynsym.scale.maps.stability_map` maps (see
        :mod:`~sage_dynsym.circuits.free_system`).

        EXAMPLES::

            sage: from sage_dynsym import Circuit
            sage: C = Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 0, 'C1']])
            sage: S = C.free_linear_system(); S.variables(), S.jacobian()
            ([u1], [-1/(C1*R1)])
        """
        return free_linear_system(self, at)

    def report_title(self):
        r"""The heading of the circuit's report (see :mod:`~sage_dynsym.circuits.report`).

        EXAMPLES::

            sage: from sage_dynsym import Circuit
            sage: Circuit([[1, 2, 'L1'], [2, 1, 'C1']], name='LC').report_title()
            '== LC (circuit: 2 branches on 2 nodes) =='
        """
        return report_title(self)

    def report_sections(self):
        r"""The sections of the circuit's report (see :mod:`~sage_dynsym.circuits.report`).

        EXAMPLES::

            sage: from sage_dynsym import Circuit
            sage: [s.name for s in Circuit([[1, 2, 'L1'], [2, 1, 'C1']]).report_sections()][:3]
            ['Conditions', 'State equations', 'Mixed potential']
        """
        return report_sections(self)
