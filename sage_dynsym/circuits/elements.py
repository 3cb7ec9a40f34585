r"""
Circuit elements and branch entries

A circuit is a list of *elementary branches*, each joining two nodes and
holding exactly one element, plus optional couplings (mutual inductances)
between inductors. This module turns user entries -- short form
``[from, to, name]`` or long form ``{from: .., to: .., kind: .., ...}`` --
into :class:`Branch` and :class:`Coupling` records.

**Orientation convention** (the same for every element). A branch entered
as ``[a, b, X]`` is oriented from node ``a`` to node ``b``:

- its current `i_b` counts positive from ``a`` to ``b`` through the element;
- its voltage is the potential *rise* along the orientation,
  `u_b = \varphi(b) - \varphi(a)`.

With these branch variables the element laws read

============================  ==========================================================================
kind (short-form prefix)      law
============================  ==========================================================================
resistor (``R``)              `u_b = -R\, i_b`
inductor (``L``)              `u_b = -L(i_b)\, di_b/dt`
capacitor (``C``)             `i_b = -C(u_b)\, du_b/dt`
voltage_source (``E``)        `u_b = E`  (the source raises the potential from ``a`` to ``b`` by `E`)
current_source (``I``)        `i_b = I`  (the source drives `I` from ``a`` to ``b``)
nonlinear_resistor (``f``)    `i_b = f(u_b)`
============================  ==========================================================================

i.e. passive elements obey the usual laws for the voltage *drop*
`\varphi(a) - \varphi(b) = -u_b` in the direction of the current, while
sources and the characteristic `f` are written directly in `(u_b, i_b)`.
This is the convention under which Example 2 of
:doc:`the method </method>` is reproduced exactly (there the source
``I0`` is entered as ``[5, 2, I0]``).

A mutual inductance couples two inductors ``L1, L2`` (long form only,
``{kind: mutual, between: [L1, L2], value: M12}``): then
`u_1 = -(L_1\, di_1/dt + M_{12}\, di_2/dt)` and symmetrically.

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
from collections import namedtuple

from sage.symbolic.ring import SR
from sage.rings.integer import Integer

from ..errors import CircuitError, ExpressionError, brief
from ..symbols import CIRCUIT_VARIABLES
from ..io.expressions import ExpressionParser
from ..symbols import check_names, check_name, MAX_NAME_LENGTH

#: element kinds, keyed by the first letter of a short-form name
PREFIXES = {'R': 'resistor', 'L': 'inductor', 'C': 'capacitor',
            'E': 'voltage_source', 'I': 'current_source',
            'f': 'nonlinear_resistor'}
KIND_PREFIX = {kind: prefix for prefix, kind in PREFIXES.items()}
BRANCH_KINDS = tuple(PREFIXES.values())
#: the symbol standing for an element's own variable inside its value
OWN_VARIABLE = {'inductor': 'i', 'capacitor': 'u', 'nonlinear_resistor': 'u'}

#: Largest node number.
MAX_NODE = 10**9

#: what to do instead of a zero element value
_ZERO_VALUE = {
    'resistor': "a resistance of 0 is a short circuit: join its two nodes into one instead",
    'inductor': "an inductance of 0 is a short circuit: join its two nodes into one instead",
    'capacitor': "a capacitance of 0 is an open circuit: remove the branch instead",
}

LONG_KEYS = {'from', 'to', 'kind', 'name', 'value'}
MUTUAL_KEYS = {'kind', 'name', 'between', 'value'}

Branch = namedtuple('Branch', 'index name kind tail head value')
Branch.__doc__ = r"""
One elementary branch: position ``index`` of its entry in the branch list, element
``name`` (also its symbol), ``kind`` (see :data:`BRANCH_KINDS`), oriented
from node ``tail`` to node ``head``; ``value`` is the element's symbolic
value (for a nonlinear resistor: ``None`` for the unknown function
``function(name)``, or its characteristic as an expression in ``u``).

EXAMPLES::

    sage: from sage_dynsym.circuits.elements import parse_entries
    sage: branches, _ = parse_entries([[1, 2, 'L1'], [2, 1, 'C1']])
    sage: b = branches[0]; b
    Branch(index=0, name='L1', kind='inductor', tail=1, head=2, value=L1)
    sage: b.kind, b.tail, b.head
    ('inductor', 1, 2)
"""
Coupling = namedtuple('Coupling', 'first second value')
Coupling.__doc__ = r"""
A mutual inductance ``value`` between inductors ``first`` and ``second``.

EXAMPLES::

    sage: from sage_dynsym.circuits.elements import parse_entries
    sage: _, (c,) = parse_entries([[1, 2, 'L1'], [2, 1, 'L2'],
    ....:     {'kind': 'mutual', 'between': ['L1', 'L2'], 'value': 'M'}], ['M'])
    sage: c, c.value
    (Coupling(first='L1', second='L2', value=M), M)
"""


def own_variable(kind):
    r"""
    Return the placeholder symbol for the element's own variable in a
    value expression (``i`` for inductors, ``u`` for capacitors and
    nonlinear resistors), or ``None``.

    EXAMPLES::

        sage: from sage_dynsym.circuits.elements import own_variable
        sage: own_variable('capacitor'), own_variable('resistor')
        (u, None)
    """
    name = OWN_VARIABLE.get(kind)
    return SR.var(name) if name else None


def _check_node(node, entry):
    r"""
    A node: a number `0 \le n \le` :data:`MAX_NODE` or a name (an
    identifier of at most :data:`~sage_dynsym.symbols.MAX_NAME_LENGTH`
    characters); the node potential of the node method is ``phi<n>``.

    TESTS::

        sage: from sage_dynsym.circuits.elements import _check_node
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


def check_value(kind, value, entry):
    r"""
    Check the physical sense of an element value: real (no ``I``); a
    *numeric* resistance, inductance or capacitance positive (a zero one is
    refused with what to do instead). Symbolic values are not assumed to
    have any sign.

    EXAMPLES::

        sage: from sage_dynsym.circuits.elements import check_value
        sage: check_value('resistor', SR(2), 'b'); check_value('resistor', var('R0'), 'b')
        sage: check_value('resistor', SR(0), 'branches[1]')
        Traceback (most recent call last):
        ...
        CircuitError: branches[1].value: a resistance of 0 is a short circuit: join its two nodes into one instead
        sage: check_value('capacitor', SR(0), 'branches[1]')
        Traceback (most recent call last):
        ...
        CircuitError: branches[1].value: a capacitance of 0 is an open circuit: remove the branch instead
        sage: check_value('inductor', SR(-1), 'branches[1]')
        Traceback (most recent call last):
        ...
        CircuitError: branches[1].value: the inductance must be positive, got -1
        sage: check_value('resistor', SR(-1), 'branches[1]')
        Traceback (most recent call last):
        ...
        CircuitError: branches[1].value: the resistance must be positive, got -1; an active element is a nonlinear resistor (kind: nonlinear_resistor) with its characteristic
        sage: check_value('voltage_source', I*var('E0'), 'branches[1]')
        Traceback (most recent call last):
        ...
        CircuitError: branches[1].value: the value must be real, got I*E0
    """
    if value is None:
        return
    value = SR(value)
    if value.has(SR.I()) or (value.is_numeric() and not value.is_real()):
        raise CircuitError(f"the value must be real, got {brief(value)}", entry=f"{entry}.value")
    if kind not in _ZERO_VALUE or value.variables():
        return
    if value.is_zero():
        raise CircuitError(_ZERO_VALUE[kind], entry=f"{entry}.value")
    try:
        negative = bool(value < 0)
    except (TypeError, ValueError):
        return
    if negative:
        what = {'resistor': 'resistance', 'inductor': 'inductance',
                'capacitor': 'capacitance'}[kind]
        hint = ("; an active element is a nonlinear resistor (kind: nonlinear_resistor) with "
                "its characteristic" if kind == 'resistor' else "")
        raise CircuitError(f"the {what} must be positive, got {brief(value)}{hint}",
                           entry=f"{entry}.value")


def _kind_of_name(name, entry):
    kind = PREFIXES.get(name[0])
    if kind is None:
        if name[0] == 'M':
            raise CircuitError(
                f"unknown element prefix 'M' in {name!r}: a mutual inductance "
                "needs the long form {kind: mutual, between: [L1, L2], value: M}",
                entry=entry)
        raise CircuitError(
            f"unknown element prefix {name[0]!r} in {name!r}; expected a name "
            "starting with R (resistor), L (inductor), C (capacitor), "
            "E (voltage source), I (current source) or f (nonlinear resistor), "
            "or the long form {from: .., to: .., kind: .., value: ..}",
            entry=entry)
    return kind


def _short(entry_data, index, entry):
    if len(entry_data) != 3:
        raise CircuitError("a short-form branch is [from_node, to_node, "
                           f"element_name], got {list(entry_data)!r}", entry=entry)
    tail, head, name = entry_data
    name = _check_name(name, entry)
    kind = _kind_of_name(name, entry)
    value = None if kind == 'nonlinear_resistor' else SR.var(name)
    return Branch(index, name, kind, _check_node(tail, entry),
                  _check_node(head, entry), value)


def _value(raw, parser, entry):
    if raw is None:
        return None
    if isinstance(raw, (str, int, float)):
        try:
            return parser.parse(raw, entry=f"{entry}.value")
        except ExpressionError as err:
            raise CircuitError(err.message, entry=err.entry) from None
    try:
        return SR(raw)
    except (TypeError, ValueError):
        raise CircuitError(f"expected an expression, got {raw!r}",
                           entry=f"{entry}.value") from None


def _long(data, index, entry, parser):
    kind = data.get('kind')
    if kind == 'mutual':
        return _mutual(data, entry, parser)
    unknown = set(data) - LONG_KEYS
    if unknown:
        raise CircuitError(f"unknown key(s) {sorted(map(str, unknown))}; a "
                           f"long-form branch has keys {sorted(LONG_KEYS)}",
                           entry=entry)
    for key in ('from', 'to', 'kind'):
        if key not in data:
            raise CircuitError(f"missing key {key!r}", entry=entry)
    if kind not in BRANCH_KINDS:
        raise CircuitError(f"unknown kind {kind!r}; expected one of "
                           f"{', '.join(BRANCH_KINDS + ('mutual',))}",
                           entry=f"{entry}.kind")
    raw = data.get('value')
    name = data.get('name')
    if name is None:
        if isinstance(raw, str) and raw.isidentifier():
            name = raw
        elif raw is None:
            raise CircuitError("give the element a 'name' or a 'value'", entry=entry)
        else:
            name = f"{KIND_PREFIX[kind]}_{index}"
    name = _check_name(name, f"{entry}.name")
    if raw is None and kind != 'nonlinear_resistor':
        value = SR.var(name)
    else:
        value = _value(raw, parser, entry)
    own = OWN_VARIABLE.get(kind)
    allowed = {own} if own else set()
    extra = {str(v) for v in (value.variables() if value is not None else ())}
    extra &= {'i', 'u'} - allowed
    if extra:
        raise CircuitError(f"the value of a {kind} cannot depend on "
                           f"{', '.join(sorted(extra))}", entry=f"{entry}.value")
    check_value(kind, value, entry)
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
    raw = data.get('value', data.get('name'))
    value = _value(raw, parser, entry)
    check_value('mutual', value, entry)
    # a constant of the windings: a current or a voltage in it would make
    # the inductance matrix depend on the state
    state = sorted({str(v) for v in SR(value).variables()} & {'i', 'u'})
    if state:
        raise CircuitError(f"a mutual inductance may depend on parameters and element values "
                           f"only, got {brief(value)}", entry=f"{entry}.value")
    return Coupling(between[0], between[1], value)


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

    OUTPUT: a pair (tuple of :class:`Branch`, tuple of :class:`Coupling`)

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
        CircuitError: branches[0]: unknown element prefix 'X' in 'X1'; ...
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
    names -= {'i', 'u'}
    parser = ExpressionParser(sorted(names | {'i', 'u'}))
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
        elif isinstance(item, dict) and item.get('kind') != 'mutual':
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
