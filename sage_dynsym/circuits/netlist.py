r"""
The element bookkeeping of a circuit

A :class:`Netlist` holds what a branch list declares: the element objects
(:mod:`~sage_dynsym.circuits.elements`), the mutual inductances between
them, the extra parameters and the symbols declared positive, each
checked once when it is built. A
:class:`~sage_dynsym.circuits.circuit.Circuit` keeps one and asks it for
names, symbols and substitutions.

EXAMPLES::

    sage: from sage_dynsym.circuits.netlist import Netlist
    sage: N = Netlist([[0, 1, 'E1'], [1, 0, 'L1'], [2, 0, 'L2'], [0, 2, 'f1'],
    ....:     {'kind': 'mutual', 'between': ['L1', 'L2'], 'value': 'M'}],
    ....:     parameters=['M'], positive=['L1'])
    sage: N.value_names(), N.coupling_entries, N.positive
    (['M', 'E1', 'L1', 'L2'], [4], [L1])
"""
from sage.symbolic.ring import SR

from ..errors import CircuitError, brief
from ..symbols import CIRCUIT_VARIABLES, exact_decimals
from .elements import parse_entries, is_coupling_entry
from .elements.windings import check_couplings

__all__ = ['Netlist']


class Netlist:
    r"""
    The checked elements, couplings, parameters and positive symbols of a
    branch list.

    INPUT:

    - ``entries`` -- the branch list (see
      :func:`~sage_dynsym.circuits.elements.entries.parse_entries`)
    - ``parameters`` -- extra symbols allowed in long-form values
    - ``positive`` -- parameters and element values known to be positive

    Its attributes: ``branches`` and ``couplings`` (tuples), ``parameters``
    (a tuple of names), ``positive`` (a list of symbols) and
    ``coupling_entries`` (the positions of the mutual inductances in the
    branch list, for messages).

    EXAMPLES::

        sage: from sage_dynsym.circuits.netlist import Netlist
        sage: Netlist([[1, 2, 'L1'], [2, 1, 'C1']]).branches
        (Branch(index=0, name='L1', kind='inductor', tail=1, head=2, value=L1),
         Branch(index=1, name='C1', kind='capacitor', tail=2, head=1, value=C1))

    TESTS::

        sage: Netlist([[1, 2, 'R1'], [2, 1, 'R1']])
        Traceback (most recent call last):
        ...
        CircuitError: branches[1]: duplicate element name 'R1'
        sage: Netlist([[1, 2, 'L1'], [2, 1, 'C1'], {'kind': 'mutual', 'between': ['L1', 'L1'], 'value': 'M'}], ['M'])
        Traceback (most recent call last):
        ...
        CircuitError: branches[2]: a mutual inductance couples two different inductors, once
        sage: Netlist([[1, 2, 'R1'], [2, 1, 'C1']], positive=['R2'])
        Traceback (most recent call last):
        ...
        CircuitError: positive[0]: R2 is neither a parameter nor an element value of the circuit (positive lists symbols known to be positive)
    """

    def __init__(self, entries, parameters=(), positive=()):
        if not isinstance(entries, (list, tuple)):
            raise CircuitError(f"expected a list of branches such as [1, 2, 'R1'] (and "
                               f"couplings), got {brief(entries)}", entry="branches")
        entries = list(entries)
        self.parameters = tuple(str(p) for p in parameters)
        self.branches, self.couplings = parse_entries(entries, self.parameters)
        seen = set()
        for b in self.branches:
            if b.name in seen:
                raise CircuitError(f"duplicate element name {b.name!r}",
                                   entry=f"branches[{b.index}]")
            if CIRCUIT_VARIABLES.match(b.name):
                raise CircuitError(f"the name {b.name!r} is reserved for variables "
                                   "(i, u, t, i<k>, u<k>, q<k>, phi...)",
                                   entry=f"branches[{b.index}]")
            seen.add(b.name)
        self.coupling_entries = [k for k, e in enumerate(entries) if is_coupling_entry(e)]
        check_couplings(self.branches, self.couplings, self.coupling_entries)
        symbols = set(self.value_names())
        self.positive = []
        for k, p in enumerate(positive):
            if str(p) not in symbols:
                raise CircuitError(f"{p} is neither a parameter nor an element value of the "
                                   "circuit (positive lists symbols known to be positive)",
                                   entry=f"positive[{k}]")
            self.positive.append(SR.var(str(p)))

    def value_names(self):
        r"""
        The names of the symbols a value may be given to: the parameters,
        then the elements whose name is a symbol (all but the
        characteristics of nonlinear resistors), in branch order.

        EXAMPLES: see the module documentation.
        """
        return list(self.parameters) + [b.name for b in self.branches if not b.is_function]

    def sources(self):
        r"""
        The sources: the branches whose voltage or current a source value
        fixes.

        EXAMPLES::

            sage: from sage_dynsym.circuits.netlist import Netlist
            sage: [b.name for b in Netlist([[0, 1, 'E1'], [1, 0, 'R1'], [1, 0, 'I1']]).sources()]
            ['E1', 'I1']
        """
        return [b for b in self.branches
                if b.fixed_voltage() is not None or b.fixed_current() is not None]

    def subs(self, values):
        r"""
        The branch list, parameters and positive symbols of the circuit
        with ``values`` (a dictionary ``{symbol or name: value}`` over
        :meth:`value_names`) substituted; the substituted symbols leave the
        parameters and the positive symbols.

        EXAMPLES::

            sage: from sage_dynsym.circuits.netlist import Netlist
            sage: N = Netlist([[0, 1, 'E1'], [1, 0, 'R1']], parameters=['a'], positive=['R1'])
            sage: N.subs({'R1': 2})
            ([{'from': 0, 'kind': 'voltage_source', 'name': 'E1', 'to': 1, 'value': E1},
              {'from': 1, 'kind': 'resistor', 'name': 'R1', 'to': 0, 'value': 2}],
             ['a'],
             [])

        TESTS::

            sage: N.subs({'i1': 0})
            Traceback (most recent call last):
            ...
            CircuitError: subs: i1 is not a parameter or element value of the circuit; they are: a, E1, R1
        """
        if not isinstance(values, dict):
            raise CircuitError(f"expected a dictionary {{symbol: value}}, got {values!r}",
                               entry="subs")
        symbols = self.value_names()
        substitution = {}
        for key, value in values.items():
            symbol = SR.var(key) if isinstance(key, str) else SR(key)
            if not symbol.is_symbol() or str(symbol) not in symbols:
                raise CircuitError(f"{symbol} is not a parameter or element value of the "
                                   f"circuit; they are: {', '.join(symbols)}", entry="subs")
            substitution[symbol] = SR(exact_decimals(value))
        entries = [b.subs(substitution).long_entry() for b in self.branches]
        entries += [c.subs(substitution).long_entry() for c in self.couplings]
        done = {str(x) for x in substitution}
        return (entries, [p for p in self.parameters if p not in done],
                [p for p in self.positive if str(p) not in done])
