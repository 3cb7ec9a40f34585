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
from sage.structure.sage_object import SageObject
from sage.symbolic.ring import SR

from ..errors import CircuitError
from ..symbols import CIRCUIT_VARIABLES, sage_numbers
from ..dynamics.model import Model
from ..numerics.energy import quadratic_energy
from ..numerics.methods import NumericalMethods
from .elements import parse_entries
from .forms import circuit_forms
from .free_system import free_linear_system
from .graph import CircuitGraph
from .inductance import inductance_conditions
from .report import report_title, report_sections

class Circuit(NumericalMethods, Model):
    r"""
    An electrical circuit given as a list of branches.

    INPUT:

    - ``branches`` -- list of entries ``[from, to, name]`` (the element kind
      follows the first letter of ``name``: ``R`` resistor, ``L`` inductor,
      ``C`` capacitor, ``E`` voltage source, ``I`` current source, ``f``
      nonlinear resistor `i = f(u)`), or long-form dicts
      ``{from, to, kind, name, value}`` and ``{kind: mutual, between:
      [L1, L2], value: M}`` (see :func:`~sage_dynsym.circuits.elements.parse_entries`)
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
        entries = list(branches)
        self._parameters = tuple(str(p) for p in parameters)
        self._branches, self._couplings = parse_entries(entries, self._parameters)
        seen = set()
        for b in self._branches:
            if b.name in seen:
                raise CircuitError(f"duplicate element name {b.name!r}",
                                   entry=f"branches[{b.index}]")
            if CIRCUIT_VARIABLES.match(b.name):
                raise CircuitError(f"the name {b.name!r} is reserved for variables "
                                   "(i, u, t, i<k>, u<k>, q<k>, phi...)",
                                   entry=f"branches[{b.index}]")
            seen.add(b.name)
        kind = {b.name: b.kind for b in self._branches}
        pairs = set()
        mutual_entries = [k for k, e in enumerate(entries)
                          if isinstance(e, dict) and e.get('kind') == 'mutual']
        for k, c in zip(mutual_entries, self._couplings):
            for x in (c.first, c.second):
                if kind.get(x) != 'inductor':
                    raise CircuitError(f"a mutual inductance couples two inductors; {x} "
                                       "is not an inductor", entry=f"branches[{k}]")
            pair = frozenset((c.first, c.second))
            if len(pair) != 2 or pair in pairs:
                raise CircuitError("a mutual inductance couples two different inductors, "
                                   "once", entry=f"branches[{k}]")
            pairs.add(pair)
        self._name = name
        symbols = set(self._parameters) | {b.name for b in self._branches
                                           if b.kind != 'nonlinear_resistor'}
        self._positive = []
        for k, p in enumerate(positive):
            if str(p) not in symbols:
                raise CircuitError(f"{p} is neither a parameter nor an element value of the "
                                   "circuit (positive lists symbols known to be positive)",
                                   entry=f"positive[{k}]")
            self._positive.append(SR.var(str(p)))
        where = {b.name: p for p, b in enumerate(self._branches)}
        self._cgraph = CircuitGraph(self._branches, links=[
            (where[c.first], where[c.second]) for c in self._couplings])
        self._conditions = inductance_conditions(self, mutual_entries)

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


    def equations(self):
        r"""
        The equations of motion: the right-hand sides of the state
        equations (:meth:`state_equations`; raises
        :class:`~sage_dynsym.errors.CircuitError` for a circuit without
        unique or explicit solution).

        EXAMPLES::

            sage: from sage_dynsym import load
            sage: from sage_dynsym.description import example_path
            sage: load(example_path('nonlinear_circuit.yaml')).equations()[0]
            -u3 + u4 + u6
        """
        return self.state_equations()

    def _is_linear(self):
        return not self.elements('nonlinear_resistor')

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
        if self._is_linear():
            functions['lagrangian'] = lambda: self.lagrangian(method="loop")
            functions['node_lagrangian'] = lambda: self.lagrangian(method="node")
        return functions

    @classmethod
    def from_dict(cls, data, source=None):
        r"""
        The circuit of a description mapping (``kind: circuit``); ``source``
        names the file in errors. The format is read by
        :func:`~sage_dynsym.circuits.description.circuit_from_dict`.

        EXAMPLES::

            sage: from sage_dynsym import Circuit
            sage: Circuit.from_dict({'kind': 'circuit', 'branches': [[1, 2, 'L1'], [2, 1, 'C1']]})
            Circuit with 2 branches on 2 nodes
        """
        # the format module builds on this class: imported when first used
        from .description import circuit_from_dict
        return circuit_from_dict(data, source)

    def to_dict(self):
        r"""
        The description mapping of the circuit (short form wherever the
        element's value is its own symbol), the inverse of
        :func:`~sage_dynsym.circuits.description.circuit_from_dict`.

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
        from .elements import PREFIXES
        out = {'kind': 'circuit'}
        if self.name():
            out['name'] = self.name()
        if self.parameters():
            out['parameters'] = list(self.parameters())
        if self._positive:
            out['positive'] = [str(p) for p in self._positive]
        branches = []
        for b in self.branches():
            short = PREFIXES.get(b.name[0]) == b.kind and (
                b.value is None if b.kind == 'nonlinear_resistor'
                else b.value.is_symbol() and str(b.value) == b.name)
            if short:
                branches.append([b.tail, b.head, b.name])
            else:
                entry = {'from': b.tail, 'to': b.head, 'kind': b.kind, 'name': b.name}
                if b.value is not None:
                    entry['value'] = str(b.value)
                branches.append(entry)
        for c in self.couplings():
            branches.append({'kind': 'mutual', 'between': [c.first, c.second],
                             'value': str(c.value)})
        out['branches'] = branches
        return out

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
        from sage.misc.latex import latex
        results = {}
        try:
            equations = self.state_equations()
        except CircuitError:
            pass
        else:
            results['state_variables'] = [str(v) for v, _ in self.state_variables()]
            results['state_equations'] = [str(e) for e in equations]
            results['state_equations_latex'] = [str(latex(e)) for e in equations]
            if self.has_mixed_potential():
                results['mixed_potential_text'] = str(self.mixed_potential())
                results['mixed_potential_latex'] = str(latex(self.mixed_potential()))
        if self._is_linear():
            try:
                L = self.lagrangian(method="loop")
            except CircuitError:
                pass
            else:
                results['lagrangian'] = str(L.expr())
                results['lagrangian_latex'] = str(latex(L.expr()))
                results['lagrange_equations'] = [str(e) for e in L.lagrange_equations()]
        return results

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
        from ..errors import DescriptionError, brief
        from ..symbols import velocity, acceleration, momentum
        q = [str(v) for v in self.lagrangian().coordinates()] if 'lagrangian' in results else []
        states = results.get('state_variables', [])
        expected = [str(v) for v, _ in self.state_variables()] if states else []
        if states != expected:
            raise DescriptionError(f"expected the state variables {expected} of the circuit, "
                                   f"got {brief(states)}", entry='results.state_variables')
        symbols = list(self.parameters()) + states
        symbols += [b.name for b in self.branches() if b.kind != 'nonlinear_resistor']
        symbols += q + [str(velocity(v)) for v in q] + [str(acceleration(v)) for v in q]
        symbols += [str(momentum(v)) for v in q]
        return symbols, self.elements('nonlinear_resistor')

    def _graph(self):
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
        The branches, a tuple of :class:`~sage_dynsym.circuits.elements.Branch`.

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
        :class:`~sage_dynsym.circuits.elements.Coupling`.

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
        :mod:`~sage_dynsym.circuits.inductance`); ``[]`` when there is none.
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

    def _check_source_loops(self):
        # voltage sources alone must not form a loop (KVL would fix a sum of sources)
        sources = [p for p, b in enumerate(self._branches) if b.kind == 'voltage_source']
        try:
            self._cgraph.components(sources)
        except ValueError as err:
            loop = self._cgraph.cycle_through(sources[:sources.index(err.args[0])],
                                              err.args[0])
            raise CircuitError(f"the voltage sources {', '.join(loop)} form a loop: "
                               "Kirchhoff's voltage law cannot hold for arbitrary "
                               "source values") from None

    def subs(self, values):
        r"""
        The circuit with parameter and element values substituted.

        INPUT:

        - ``values`` -- a dictionary ``{symbol: value}``, keys symbols or
          names of parameters or elements (an element's name is its value's
          symbol); values exact or floating-point numbers, or expressions

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
            [                L1                  0]
            [                 0 0.500000000000000], []
            )

        TESTS::

            sage: C.subs({'i1': 0})
            Traceback (most recent call last):
            ...
            CircuitError: subs: i1 is not a parameter or element value of the circuit; they are: E1, R1, L1, C1
            sage: C.subs({'R1': 0})
            Traceback (most recent call last):
            ...
            CircuitError: branches[1].value: a resistance of 0 is a short circuit: join its two nodes into one instead
        """
        if not isinstance(values, dict):
            raise CircuitError(f"expected a dictionary {{symbol: value}}, got {values!r}",
                               entry="subs")
        symbols = list(self._parameters) + [b.name for b in self._branches
                                            if b.kind != 'nonlinear_resistor']
        substitution = {}
        for key, value in values.items():
            symbol = SR.var(key) if isinstance(key, str) else SR(key)
            if not symbol.is_symbol() or str(symbol) not in symbols:
                raise CircuitError(f"{symbol} is not a parameter or element value of the "
                                   f"circuit; they are: {', '.join(symbols)}", entry="subs")
            substitution[symbol] = SR(sage_numbers(value))
        entries = []
        for b in self._branches:
            entry = {'from': b.tail, 'to': b.head, 'kind': b.kind, 'name': b.name}
            if b.value is not None:
                entry['value'] = SR(b.value).subs(substitution)
            entries.append(entry)
        entries += [{'kind': 'mutual', 'between': [c.first, c.second],
                     'value': SR(c.value).subs(substitution)} for c in self._couplings]
        done = {str(x) for x in substitution}
        return Circuit(entries, name=self._name,
                       parameters=[p for p in self._parameters if p not in done],
                       positive=[p for p in self._positive if str(p) not in done])

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
                          name=f"{self._name or 'circuit'} ({method} method)")

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

    def has_mixed_potential(self):
        r"""
        Whether the circuit is complete (has the Brayton--Moser split);
        then :meth:`state_equations` come from the mixed potential, else
        from :meth:`nodal_analysis`.

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: Circuit([[1, 2, 'L1'], [2, 1, 'C1']]).has_mixed_potential()
            True
            sage: Circuit([[1, 2, 'L1'], [2, 1, 'C1'], [2, 1, 'C2']]).has_mixed_potential()
            False
        """
        try:
            self.brayton_moser()
        except CircuitError:
            return False
        return True

    def _state_form(self):
        # the mixed potential for a complete circuit, else nodal analysis
        try:
            return self.brayton_moser()
        except CircuitError as split:
            try:
                return self.nodal_analysis()
            except CircuitError as err:
                from .nodal import NOT_EXPLICIT
                if not err.message.startswith(NOT_EXPLICIT):
                    raise
                raise CircuitError(f"{split.message}; {err.message}",
                                   entry=split.entry or err.entry) from None

    def state_variables(self):
        r"""
        The state variables, pairs ``(symbol, element name)``: inductor
        currents ``i1, ..., ir`` first, then capacitor voltages. A loop of
        capacitors (and voltage sources) or a cut-set of inductors (and
        current sources) leaves out one of its elements: the state is a
        maximal set of independent capacitor voltages and inductor currents
        (see :mod:`~sage_dynsym.circuits.nodal`).

        EXAMPLES: a loop of an inductor, a resistor and a capacitor::

            sage: from sage_dynsym.circuits import Circuit
            sage: C = Circuit([[1, 2, 'L1'], [2, 3, 'R1'], [3, 1, 'C1']], name='RLC')
            sage: C.state_variables()
            [(i1, 'L1'), (u2, 'C1')]

        Two capacitors in parallel have one voltage::

            sage: Circuit([[1, 2, 'L1'], [2, 1, 'C1'], [2, 1, 'C2']]).state_variables()
            [(i1, 'L1'), (u2, 'C1')]
        """
        return self._state_form().state_variables()

    def state_equations(self):
        r"""
        The right-hand sides `F` of `B\dot x = F(x)`, `B` the
        :meth:`lhs_matrix`, in the order of :meth:`state_variables`. For a
        complete circuit these are `\partial P/\partial i_k` and
        `-\partial P/\partial u_l` of the mixed potential (the equations
        `L_k\, di_k/dt = \partial P/\partial i_k`, `C_l\, du_l/dt =
        -\partial P/\partial u_l`); otherwise they come from
        :meth:`nodal_analysis`.

        Raises :class:`~sage_dynsym.errors.CircuitError` for a circuit
        without unique solution (a loop of voltage sources, a cut-set of
        current sources) and for nonlinear resistors whose relations cannot
        be solved explicitly, naming the elements.

        EXAMPLES: a loop of an inductor, a resistor and a capacitor::

            sage: from sage_dynsym.circuits import Circuit
            sage: C = Circuit([[1, 2, 'L1'], [2, 3, 'R1'], [3, 1, 'C1']], name='RLC')
            sage: C.state_equations()     # L1 di1/dt = u2 - R1 i1, C1 du2/dt = -i1
            [-R1*i1 + u2, -i1]

        Two capacitors in parallel::

            sage: C = Circuit([[1, 2, 'L1'], [2, 1, 'C1'], [2, 1, 'C2']])
            sage: C.state_equations(), C.lhs_matrix()
            (
                        [     L1       0]
            [u2, -i1], [      0 C1 + C2]
            )

        TESTS::

            sage: Circuit([[1, 2, 'E1'], [2, 1, 'E2'], [1, 2, 'C1']]).state_equations()
            Traceback (most recent call last):
            ...
            CircuitError: branches[1]: the voltage sources E2, E1 form a loop: ...
            sage: Circuit([[1, 2, 'f1'], [2, 3, 'R1'], [3, 1, 'C1']]).state_equations()
            Traceback (most recent call last):
            ...
            CircuitError: branches[0]: no Brayton-Moser split: ...; no explicit state equations: ...
        """
        return self._state_form().state_equations()

    def source_values_off(self):
        r"""
        The substitution that switches the sources off: the symbol of each
        voltage and current source to 0.

        EXAMPLES::

            sage: from sage_dynsym import Circuit
            sage: Circuit([[0, 1, 'E1'], [1, 0, 'R1'], [1, 0, 'I1']]).source_values_off()
            {E1: 0, I1: 0}
        """
        return {SR.var(b.name): 0 for b in self._branches
                if b.kind in ('voltage_source', 'current_source')}

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

    def state_equation_labels(self, latex=False):
        r"""
        The left-hand sides of `B\dot x =` :meth:`state_equations`, row by
        row, as text (``latex=True``: LaTeX), e.g. ``C1 du2/dt`` or, for a
        state reduced by a capacitor loop, ``(C1 + C2) du2/dt``.

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: C = Circuit([[1, 2, 'C1'], [2, 3, 'C2'], [3, 1, 'E1'], [1, 3, 'L1'], [2, 3, 'R1']])
            sage: C.state_equation_labels()
            ['L1 di1/dt', '(C1 + C2) du2/dt']
            sage: C.state_equation_labels(latex=True)[1]
            '\\left(C_{1} + C_{2}\\right) \\frac{d u_{2}}{dt}'
        """
        from sage.misc.latex import latex as to_latex
        B = self.lhs_matrix()
        x = [v for v, _ in self.state_variables()]
        labels = []
        for i in range(B.nrows()):
            terms = []
            for b, v in zip(B.row(i), x):
                if b.is_zero():
                    continue
                b = SR(b)
                simple = b.is_symbol() or b.is_numeric()
                if latex:
                    factor = "" if b == 1 else (to_latex(b) if simple
                                                else f"\\left({to_latex(b)}\\right)")
                    terms.append(f"{factor} \\frac{{d {to_latex(v)}}}{{dt}}".strip())
                else:
                    factor = "" if b == 1 else (f"{b} " if simple else f"({b}) ")
                    terms.append(f"{factor}d{v}/dt")
            labels.append(" + ".join(terms))
        return labels

    def lhs_matrix(self):
        r"""
        The matrix `B` of `B\dot x = F(x)`, `F` the :meth:`state_equations`,
        rows and columns in the order of :meth:`state_variables`: the
        inductance matrix (mutual inductances included) and the
        capacitances, block-diagonal; for a reduced state (capacitor loops,
        inductor cut-sets) the effective matrices of
        :meth:`~sage_dynsym.circuits.nodal.NodalAnalysis.lhs_matrix`.

        EXAMPLES: a transformer with galvanically isolated sides::

            sage: from sage_dynsym.circuits import Circuit
            sage: C = Circuit([[0, 1, 'E1'], [1, 0, 'L1'], [2, 3, 'L2'], [3, 2, 'R2'],
            ....:              {'kind': 'mutual', 'between': ['L1', 'L2'], 'value': 'M'}],
            ....:             parameters=['M'])
            sage: C.lhs_matrix(), C.state_equations()
            (
            [L1  M]
            [ M L2], [E1, -R2*i2]
            )
        """
        form = self._state_form()
        if hasattr(form, 'lhs_matrix'):
            return form.lhs_matrix()
        from sage.matrix.special import block_diagonal_matrix
        from sage.matrix.constructor import matrix
        from sage.symbolic.ring import SR
        B = block_diagonal_matrix([form.inductance_matrix(),
                                   matrix.diagonal(SR, form.capacitances())], subdivide=False)
        B.set_immutable()
        return B

    def _conserved_energy(self):
        r"""
        The stored energy `\tfrac12 x^T B x` (`B` the :meth:`lhs_matrix`:
        inductances with their mutual terms, capacitances) when the state
        equations are lossless and linear (see
        :func:`~sage_dynsym.numerics.energy.quadratic_energy`), else
        ``None``; what ``simulate(...).energy_drift()`` measures.

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: Circuit([[1, 2, 'L1'], [2, 1, 'C1']])._conserved_energy()
            1/2*L1*i1^2 + 1/2*C1*u2^2
            sage: Circuit([[1, 2, 'L1'], [2, 3, 'R1'], [3, 1, 'C1']])._conserved_energy() is None
            True
        """
        return quadratic_energy(self.equations_record())

    def equations_record(self):
        r"""
        The state equations as the neutral record of the analysis:
        :class:`~sage_dynsym.analysis.motion.FirstOrderEquations` with the
        right-hand sides, the state variables and `B` (:meth:`lhs_matrix`).
        This is what :func:`~sage_dynsym.analysis.linear.linearize` uses.

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: from sage_dynsym.analysis.linear import linearize
            sage: C = Circuit([[1, 2, 'L1'], [2, 3, 'R1'], [3, 1, 'C1']])
            sage: F = C.equations_record(); F
            First-order equations B x' = F(x) in (i1, u2)
            sage: linearize(C, {var('i1'): 0, var('u2'): 0}).jacobian()
            [-R1/L1   1/L1]
            [ -1/C1      0]
        """
        from ..analysis.motion import FirstOrderEquations
        return FirstOrderEquations(self.state_equations(),
                                   [x for x, _ in self.state_variables()],
                                   lhs_matrix=self.lhs_matrix())
