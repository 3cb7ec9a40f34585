r"""
Branch entries: from the entries of a branch list to element objects

A branch list holds short-form entries ``[from, to, name]`` (the kind
follows the first letter of ``name``, :attr:`~.kinds.Branch.prefix`),
long-form entries ``{from, to, kind, name, value}`` and mutual
inductances ``{kind: mutual, between: [L1, L2], value: M}``.
:func:`parse_entries` turns them into the element objects of
:mod:`~sage_dynsym.circuits.elements.kinds` and the
:class:`~sage_dynsym.circuits.elements.windings.Coupling` records, each
checked by its kind (:meth:`~.kinds.Branch.check`).

EXAMPLES::

    sage: from sage_dynsym.circuits.elements import parse_entries
    sage: branches, couplings = parse_entries([[1, 2, 'L1'], [2, 1, 'f1'],
    ....:     {'from': 1, 'to': 2, 'kind': 'capacitor', 'value': 'C0*(1 + u^2)', 'name': 'C1'},
    ....:     {'kind': 'mutual', 'between': ['L1', 'L1b'], 'value': 'M'},
    ....:     [2, 1, 'L1b']], parameters=['C0', 'M'])
    sage: branches[0]
    Branch(index=0, name='L1', kind='inductor', tail=1, head=2, value=L1)
    sage: branches[2].value
    (u^2 + 1)*C0
    sage: couplings
    (Coupling(first='L1', second='L1b', value=M),)
"""
from sage.rings.integer import Integer
from sage.symbolic.ring import SR

from ...errors import CircuitError, ExpressionError, brief
from ...io.expressions import ExpressionParser
from ...symbols import CIRCUIT_VARIABLES, MAX_NAME_LENGTH, check_name, check_names
from .kinds import CURRENT, VOLTAGE, ELEMENTS, Branch
from .windings import Coupling

__all__ = ['MAX_NODE', 'LONG_KEYS', 'MUTUAL_KEYS', 'is_coupling_entry', 'parse_entries']

#: Largest node number.
MAX_NODE = 10**9

#: The keys of a long-form branch entry.
LONG_KEYS = {'from', 'to', 'kind', 'name', 'value'}
#: The keys of a mutual inductance entry.
MUTUAL_KEYS = {'kind', 'name', 'between', 'value'}


def _check_node(node, entry):
    r"""
    A node: a number `0 \le n \le` :data:`MAX_NODE` or a name (an
    identifier of at most :data:`~sage_dynsym.symbols.MAX_NAME_LENGTH`
    characters); the node potential of the node method is ``phi<n>``.

    TESTS::

        sage: from sage_dynsym.circuits.elements.entries import _check_node
        sage: _check_node(3, 'b'), _check_node('out', 'b')
        (3, 'out')
        sage: _check_node(-1, 'branches[0]')
        Traceback (most recent call last):
        ...
        CircuitError: branches[0]: a node number is an integer from 0 to 1000000000, got -1
        sage: _check_node(float(1.5), 'branches[0]')
        Traceback (most recent call last):
        ...
        CircuitError: branches[0]: a node must be an integer or a name, got 1.5
    """
    if isinstance(node, bool) or not isinstance(node, (int, Integer, str)):
        raise CircuitError(f"a node must be an integer or a name, got {brief(node)}",
                           entry=entry)
    if isinstance(node, str):
        if not node.isidentifier() or len(node) > MAX_NAME_LENGTH:
            raise CircuitError("a node name must be an identifier of at most "
                               f"{MAX_NAME_LENGTH} characters, got {brief(node)}", entry=entry)
        return node
    if not 0 <= node <= MAX_NODE:
        raise CircuitError(f"a node number is an integer from 0 to {MAX_NODE}, got "
                           f"{brief(node)}", entry=entry)
    return int(node)


def _check_name(name, entry):
    if not isinstance(name, str) or not name.isidentifier():
        raise CircuitError(f"an element name must be an identifier such as "
                           f"'L1', got {brief(name)}", entry=entry)
    return check_name(name, entry, CircuitError)


def _kind_of_name(name, entry):
    # read from ELEMENTS each time: a kind added to it is known at once
    element = next((cls for cls in ELEMENTS.values() if cls.prefix == name[0]), None)
    if element is None:
        if name[0] == 'M':
            raise CircuitError(
                f"unknown element prefix 'M' in {name!r}: a mutual inductance "
                "needs the long form {kind: mutual, between: [L1, L2], value: M}",
                entry=entry)
        known = ", ".join(f"{cls.prefix} ({cls.kind_name.replace('_', ' ')})"
                          for cls in ELEMENTS.values())
        known = " or ".join(known.rsplit(", ", 1))
        raise CircuitError(
            f"unknown element prefix {name[0]!r} in {name!r}; expected a name "
            f"starting with {known}, or the long form {{from: .., to: .., kind: .., "
            "value: ..}", entry=entry)
    return element


def _short(entry_data, index, entry):
    if len(entry_data) != 3:
        raise CircuitError("a short-form branch is [from_node, to_node, "
                           f"element_name], got {list(entry_data)!r}", entry=entry)
    tail, head, name = entry_data
    name = _check_name(name, entry)
    element = _kind_of_name(name, entry)
    return Branch(index, name, element.kind_name, _check_node(tail, entry),
                  _check_node(head, entry), element.default_value(name))


def _value(raw, parser, entry):
    if raw is None:
        return None
    if isinstance(raw, (str, int, float)):
        try:
            return parser.parse(raw, entry=f"{entry}.value")
        except ExpressionError as err:
            raise CircuitError(err.message, entry=err.entry) from err
    try:
        return SR(raw)
    except (TypeError, ValueError) as cause:
        raise CircuitError(f"expected an expression, got {raw!r}",
                           entry=f"{entry}.value") from cause


def _long(data, index, entry, parser):
    if data.get('kind') == Coupling.kind_name:
        return _mutual(data, entry, parser)
    unknown = set(data) - LONG_KEYS
    if unknown:
        raise CircuitError(f"unknown key(s) {sorted(map(str, unknown))}; a "
                           f"long-form branch has keys {sorted(LONG_KEYS)}",
                           entry=entry)
    for key in ('from', 'to', 'kind'):
        if key not in data:
            raise CircuitError(f"missing key {key!r}", entry=entry)
    kind = data['kind']
    element = ELEMENTS.get(kind) if isinstance(kind, str) else None
    if element is None:
        raise CircuitError(f"unknown kind {kind!r}; expected one of "
                           f"{', '.join(list(ELEMENTS) + [Coupling.kind_name])}",
                           entry=f"{entry}.kind")
    raw = data.get('value')
    name = data.get('name')
    if name is None:
        if isinstance(raw, str) and raw.isidentifier():
            name = raw
        elif raw is None:
            raise CircuitError("give the element a 'name' or a 'value'", entry=entry)
        else:
            name = f"{element.prefix}_{index}"
    name = _check_name(name, f"{entry}.name")
    value = element.default_value(name) if raw is None else _value(raw, parser, entry)
    element.check(value, entry)
    return Branch(index, name, kind, _check_node(data['from'], entry),
                  _check_node(data['to'], entry), value)


def _mutual(data, entry, parser):
    unknown = set(data) - MUTUAL_KEYS
    if unknown:
        raise CircuitError(f"unknown key(s) {sorted(map(str, unknown))}; a "
                           f"mutual inductance has keys {sorted(MUTUAL_KEYS)}",
                           entry=entry)
    between = data.get('between')
    if (not isinstance(between, (list, tuple)) or len(between) != 2
            or not all(isinstance(x, str) for x in between)):
        raise CircuitError("'between' must list two inductor names, e.g. "
                           f"[L1, L2], got {between!r}", entry=f"{entry}.between")
    if 'value' not in data and 'name' not in data:
        raise CircuitError("a mutual inductance needs a 'value'", entry=entry)
    value = _value(data.get('value', data.get('name')), parser, entry)
    Coupling.check(value, entry)
    return Coupling(between[0], between[1], value)


def is_coupling_entry(item):
    r"""
    Whether the branch-list entry ``item`` is a mutual inductance
    (``{kind: mutual, ...}``).

    EXAMPLES::

        sage: from sage_dynsym.circuits.elements import is_coupling_entry
        sage: is_coupling_entry({'kind': 'mutual', 'between': ['L1', 'L2'], 'value': 'M'})
        True
        sage: is_coupling_entry([1, 2, 'L1']), is_coupling_entry({'kind': 'inductor'})
        (False, False)
    """
    return isinstance(item, dict) and item.get('kind') == Coupling.kind_name


def parse_entries(entries, parameters=(), entry_prefix="branches"):
    r"""
    Turn branch entries into branches and couplings.

    INPUT:

    - ``entries`` -- a list; each item is ``[from, to, name]`` (kind from
      the first letter of ``name``), a dict in long form
      ``{from, to, kind, name, value}`` (``value`` an expression string or
      a symbolic expression; ``name`` defaults to the value when it is a
      plain symbol), or ``{kind: mutual, between: [L1, L2], value: M}``
    - ``parameters`` -- extra symbols allowed in value expressions (element
      names are always allowed, and ``i``/``u`` for the element's own
      current/voltage in inductors/capacitors/nonlinear resistors)
    - ``entry_prefix`` -- name used in error messages

    OUTPUT: a pair (tuple of :class:`~.kinds.Branch`, tuple of
    :class:`~.windings.Coupling`), each branch an instance of the class of
    its kind

    EXAMPLES::

        sage: from sage_dynsym.circuits.elements import parse_entries
        sage: parse_entries([[1, 2, 'R1'], {'from': 2, 'to': 1, 'kind': 'nonlinear_resistor',
        ....:                'name': 'f1', 'value': 'g*u^3 - u'}], parameters=['g'])
        ((Branch(index=0, name='R1', kind='resistor', tail=1, head=2, value=R1),
          Branch(index=1, name='f1', kind='nonlinear_resistor', tail=2, head=1, value=g*u^3 - u)),
         ())

    TESTS::

        sage: parse_entries([[1, 2, 'X1']])
        Traceback (most recent call last):
        ...
        CircuitError: branches[0]: unknown element prefix 'X' in 'X1'; expected a name starting with R (resistor), L (inductor), C (capacitor), E (voltage source), I (current source) or f (nonlinear resistor), or the long form {from: .., to: .., kind: .., value: ..}
        sage: parse_entries([[1, 2, 'R1'], [2, 3]])
        Traceback (most recent call last):
        ...
        CircuitError: branches[1]: a short-form branch is [from_node, to_node, element_name], got [2, 3]
        sage: parse_entries([{'from': 1, 'to': 2, 'kind': 'resistor', 'value': 'R*x'}], ['R'])
        Traceback (most recent call last):
        ...
        CircuitError: branches[0].value: undeclared symbol 'x' in 'R*x'; ...
        sage: parse_entries([{'from': 1, 'to': 2, 'kind': 'inductor', 'value': 'L0', 'colour': 1}])
        Traceback (most recent call last):
        ...
        CircuitError: branches[0]: unknown key(s) ['colour']; ...
        sage: parse_entries([{'from': 1, 'to': 2, 'kind': 'diode', 'value': 'D1'}])
        Traceback (most recent call last):
        ...
        CircuitError: branches[0].kind: unknown kind 'diode'; expected one of resistor, inductor, capacitor, voltage_source, current_source, nonlinear_resistor, mutual
        sage: parse_entries([[1, 2, 'L1'], [2, 1, 'L2'],
        ....:                {'kind': 'mutual', 'between': ['L1', 'L2'], 'value': 'M*i'}], ['M'])
        Traceback (most recent call last):
        ...
        CircuitError: branches[2].value: a mutual inductance may depend on parameters and element values only, got M*i
    """
    entries = list(entries)
    _check_declared(entries, parameters, entry_prefix)
    names = set(str(p) for p in parameters)
    for item in entries:    # element names are symbols usable in values
        if isinstance(item, (list, tuple)) and len(item) == 3 and isinstance(item[2], str) \
                and item[2].isidentifier():
            names.add(item[2])
        elif isinstance(item, dict):
            for key in ('name', 'value'):
                if isinstance(item.get(key), str) and item[key].isidentifier():
                    names.add(item[key])
    own = {CURRENT, VOLTAGE}
    parser = ExpressionParser(sorted((names - own) | own))
    branches, couplings = [], []
    for k, item in enumerate(entries):
        entry = f"{entry_prefix}[{k}]"
        if isinstance(item, dict):
            result = _long(item, k, entry, parser)
        elif isinstance(item, (list, tuple)):
            result = _short(item, k, entry)
        else:
            raise CircuitError("a branch is [from, to, name] or a mapping "
                               f"{{from, to, kind, value}}, got {item!r}", entry=entry)
        (couplings if isinstance(result, Coupling) else branches).append(result)
    return tuple(branches), tuple(couplings)


def _check_declared(entries, parameters, entry_prefix):
    # parameters and element names against the reserved names and each
    # other; element names of the circuit's own variables (i1, q1, phi2)
    # are left to Circuit, which says so in its words
    declared = [(check_name(str(p), f"parameters[{i}]", CircuitError), 'parameter',
                 f"parameters[{i}]") for i, p in enumerate(parameters)]
    for k, item in enumerate(entries):
        name = None
        if isinstance(item, (list, tuple)) and len(item) == 3:
            name = item[2]
        elif isinstance(item, dict) and not is_coupling_entry(item):
            name = item.get('name')
            if name is None and isinstance(item.get('value'), str) and \
                    item['value'].isidentifier():
                name = item['value']
        if isinstance(name, str) and name.isidentifier() and not CIRCUIT_VARIABLES.match(name):
            declared.append((name, 'element', f"{entry_prefix}[{k}]"))
    elements = set()
    for name, use, entry in declared:
        if use == 'element':
            if name in elements:
                raise CircuitError(f"duplicate element name {name!r}", entry=entry)
            elements.add(name)
    check_names(declared, 'circuit', CircuitError)
