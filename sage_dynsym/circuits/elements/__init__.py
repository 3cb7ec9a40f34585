r"""
Circuit elements and branch entries

A circuit is a list of *elementary branches*, each joining two nodes and
holding exactly one element, plus optional couplings (mutual inductances)
between inductors. Each element kind is a class
(:mod:`~sage_dynsym.circuits.elements.kinds`) that knows its law and what
it contributes to every analysis; coupled windings live in
:mod:`~sage_dynsym.circuits.elements.windings`; the entries of a branch
list -- short form ``[from, to, name]`` or long form ``{from: .., to: ..,
kind: .., ...}`` -- are read by
:mod:`~sage_dynsym.circuits.elements.entries`. Only this package names
the kinds; the analyses ask the element objects.

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

    sage: from sage_dynsym.circuits.elements import parse_entries, Inductor
    sage: branches, couplings = parse_entries([[1, 2, 'L1'], [2, 1, 'f1'],
    ....:     {'from': 1, 'to': 2, 'kind': 'capacitor', 'value': 'C0*(1 + u^2)', 'name': 'C1'},
    ....:     {'kind': 'mutual', 'between': ['L1', 'L1b'], 'value': 'M'},
    ....:     [2, 1, 'L1b']], parameters=['C0', 'M'])
    sage: branches[0], isinstance(branches[0], Inductor)
    (Branch(index=0, name='L1', kind='inductor', tail=1, head=2, value=L1), True)
    sage: branches[2].value
    (u^2 + 1)*C0
    sage: couplings
    (Coupling(first='L1', second='L1b', value=M),)
"""
from ...errors import CircuitError
from .kinds import (Branch, Resistor, Inductor, Capacitor, VoltageSource, CurrentSource,
                    NonlinearResistor, ELEMENTS, CURRENT, VOLTAGE)
from .windings import Coupling
from .entries import parse_entries, is_coupling_entry, MAX_NODE, LONG_KEYS, MUTUAL_KEYS

#: element kinds, keyed by the first letter of a short-form name
PREFIXES = {cls.prefix: kind for kind, cls in ELEMENTS.items()}
#: the short-form prefix of each element kind
KIND_PREFIX = {kind: prefix for prefix, kind in PREFIXES.items()}
#: the element kinds of a branch
BRANCH_KINDS = tuple(ELEMENTS)
#: the symbol standing for an element's own variable inside its value
OWN_VARIABLE = {kind: cls.own for kind, cls in ELEMENTS.items() if cls.own}


def element_class(kind):
    r"""
    The class of the element kind ``kind`` (its name in a long-form entry,
    e.g. ``'capacitor'``, or ``'mutual'`` for a mutual inductance).

    EXAMPLES::

        sage: from sage_dynsym.circuits.elements import element_class
        sage: element_class('capacitor'), element_class('mutual')
        (<class 'sage_dynsym.circuits.elements.kinds.Capacitor'>,
         <class 'sage_dynsym.circuits.elements.windings.Coupling'>)

    TESTS::

        sage: element_class('diode')
        Traceback (most recent call last):
        ...
        CircuitError: unknown kind 'diode'; expected one of resistor, inductor, capacitor, voltage_source, current_source, nonlinear_resistor, mutual
    """
    if kind == Coupling.kind_name:
        return Coupling
    element = ELEMENTS.get(kind) if isinstance(kind, str) else None
    if element is None:
        raise CircuitError(f"unknown kind {kind!r}; expected one of "
                           f"{', '.join(list(ELEMENTS) + [Coupling.kind_name])}")
    return element


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
    return element_class(kind).own_variable()


def check_value(kind, value, entry):
    r"""
    Check the physical sense of a value of an element of kind ``kind``
    (see :meth:`Branch.check <.kinds.Branch.check>` and
    :meth:`Coupling.check <.windings.Coupling.check>`).

    EXAMPLES::

        sage: from sage_dynsym.circuits.elements import check_value
        sage: check_value('resistor', SR(2), 'b'); check_value('resistor', var('R0'), 'b')
        sage: check_value('inductor', SR(-1), 'branches[1]')
        Traceback (most recent call last):
        ...
        CircuitError: branches[1].value: the inductance must be positive, got -1
        sage: check_value('voltage_source', I*var('E0'), 'branches[1]')
        Traceback (most recent call last):
        ...
        CircuitError: branches[1].value: the value must be real, got I*E0
    """
    if value is not None:
        element_class(kind).check(value, entry)


__all__ = ['Branch', 'Resistor', 'Inductor', 'Capacitor', 'VoltageSource', 'CurrentSource',
           'NonlinearResistor', 'Coupling', 'ELEMENTS', 'CURRENT', 'VOLTAGE', 'PREFIXES',
           'KIND_PREFIX', 'BRANCH_KINDS', 'OWN_VARIABLE', 'MAX_NODE', 'LONG_KEYS',
           'MUTUAL_KEYS', 'parse_entries', 'is_coupling_entry', 'element_class',
           'own_variable', 'check_value']
