r"""
The kinds of circuit elements

Every elementary branch is an instance of the class of its element's kind
(all subclasses of :class:`Branch`): :class:`Resistor`, :class:`Inductor`,
:class:`Capacitor`, :class:`VoltageSource`, :class:`CurrentSource`,
:class:`NonlinearResistor`. The class holds everything the analyses ask of
an element -- its short-form prefix, its value checks, its state variable,
its term in the loop and node Lagrangians, in the mixed potential and its
place in modified nodal analysis -- so that they never test a kind's name.
The laws are those of the orientation convention of
:mod:`~sage_dynsym.circuits.elements`. A new kind is one more subclass and
its entry in :data:`ELEMENTS` (see the section *Adding an element kind* of
:doc:`the circuits guide </guide_circuits>`).

What the classes answer, by analysis:

==========================  =====================================================
analysis                    attributes and methods
==========================  =====================================================
description entries         :attr:`~Branch.prefix`, :meth:`~Branch.check`,
                            :meth:`~Branch.default_value`, :meth:`~Branch.entry`
state                       :attr:`~Branch.state`, :meth:`~Branch.state_symbol`,
                            :meth:`~Branch.value_at`, :meth:`~Branch.known_voltage`,
                            :meth:`~Branch.known_current`
sources                     :meth:`~Branch.fixed_voltage`,
                            :meth:`~Branch.fixed_current`
loop and node Lagrangians   :meth:`~Branch.is_linear`, :meth:`~Branch.loop_term`,
                            :meth:`~Branch.node_term`
mixed potential             :attr:`~Branch.sets_voltage`, :attr:`~Branch.sets_current`,
                            :attr:`~Branch.voltage_controlled`,
                            :attr:`~Branch.current_controlled`,
                            :meth:`~Branch.current_potential`,
                            :meth:`~Branch.voltage_potential`
modified nodal analysis     :attr:`~Branch.tree_rank`, :attr:`~Branch.resistive`,
                            :meth:`~Branch.resistance`, :meth:`~Branch.current`
==========================  =====================================================

EXAMPLES::

    sage: from sage_dynsym.circuits.elements import Branch
    sage: L = Branch(0, 'L1', 'inductor', 1, 2, var('L1')); L
    Branch(index=0, name='L1', kind='inductor', tail=1, head=2, value=L1)
    sage: type(L).__name__, L.prefix, L.state_symbol(1)
    ('Inductor', 'L', i1)
    sage: L.loop_term(), L.node_term()
    (('kinetic', L1), ('potential', 1/L1))
"""
from collections import namedtuple

from sage.symbolic.function_factory import function as symbolic_function
from sage.symbolic.integration.integral import definite_integral
from sage.symbolic.ring import SR

from ...errors import CircuitError, brief

__all__ = ['CURRENT', 'VOLTAGE', 'check_real', 'Branch', 'Resistor', 'Inductor', 'Capacitor',
           'VoltageSource', 'CurrentSource', 'NonlinearResistor', 'state_symbols', 'ELEMENTS']

#: The letter of a current: an inductor's state variable ``i<k>``, the own
#: current ``i`` in an inductance.
CURRENT = 'i'
#: The letter of a voltage: a capacitor's state variable ``u<k>``, the own
#: voltage ``u`` in a capacitance or a characteristic.
VOLTAGE = 'u'


def check_real(value, entry):
    r"""
    Refuse a complex value (one with ``I``) of the entry ``entry``.

    EXAMPLES::

        sage: from sage_dynsym.circuits.elements.kinds import check_real
        sage: check_real(SR(2), 'b')
        sage: check_real(I*var('E0'), 'branches[1]')
        Traceback (most recent call last):
        ...
        CircuitError: branches[1].value: the value must be real, got I*E0
    """
    if value.has(SR.I()) or (value.is_numeric() and not value.is_real()):
        raise CircuitError(f"the value must be real, got {brief(value)}", entry=f"{entry}.value")


def _integral(expr, var, upper):
    # int_0^upper expr d var; polynomials in var integrate exactly, anything
    # else Maxima cannot do is kept as an unevaluated integral
    try:
        return expr.integral(var, 0, upper)
    except (ValueError, TypeError, RuntimeError, NotImplementedError):
        return definite_integral(expr, var, 0, upper, hold=True)


class Branch(namedtuple('Branch', 'index name kind tail head value')):
    r"""
    One elementary branch: position ``index`` of its entry in the branch
    list, element ``name`` (also its symbol), ``kind`` (see
    :data:`~sage_dynsym.circuits.elements.BRANCH_KINDS`), oriented from node
    ``tail`` to node ``head``; ``value`` is the element's symbolic value
    (for a nonlinear resistor: ``None`` for the unknown function
    ``function(name)``, or its characteristic as an expression in ``u``).

    A branch is an instance of the class of its kind (``Branch(...)``
    makes one of the right class); the attributes and methods below say
    what the element contributes to each analysis, the defaults being
    those of an element that contributes nothing there.

    EXAMPLES::

        sage: from sage_dynsym.circuits.elements import parse_entries
        sage: branches, _ = parse_entries([[1, 2, 'L1'], [2, 1, 'C1']])
        sage: b = branches[0]; b
        Branch(index=0, name='L1', kind='inductor', tail=1, head=2, value=L1)
        sage: b.kind, b.tail, b.head
        ('inductor', 1, 2)

    TESTS::

        sage: from sage_dynsym.circuits.elements import Branch
        sage: Branch(0, 'D1', 'diode', 1, 2, None)
        Traceback (most recent call last):
        ...
        CircuitError: unknown kind 'diode'; expected one of resistor, inductor, capacitor, voltage_source, current_source, nonlinear_resistor
        sage: b == loads(dumps(b))
        True
    """
    __slots__ = ()

    #: The kind's name in a long-form entry (``kind: resistor``).
    kind_name = None
    #: The first letter of a short-form name of this kind.
    prefix = None
    #: What the value is called in messages when it must be positive
    #: (``'resistance'``), else ``None``.
    quantity = None
    #: Why a zero value is refused and what to do instead.
    zero_value = None
    #: The letter standing for the element's own variable in its value
    #: (:data:`CURRENT` or :data:`VOLTAGE`), or ``None``.
    own = None
    #: The letter of its state variable (:data:`CURRENT`: an inductor's
    #: current ``i<k>``; :data:`VOLTAGE`: a capacitor's voltage ``u<k>``),
    #: or ``None``.
    state = None
    #: Whether the name stands for a symbolic function (a characteristic)
    #: rather than a symbol.
    is_function = False
    #: Whether the branch voltage is a state variable or a source value.
    sets_voltage = False
    #: Whether the branch current is a state variable or a source value.
    sets_current = False
    #: Whether the current is a function of the voltage (:meth:`current`).
    voltage_controlled = False
    #: Whether the voltage is a function of the current.
    current_controlled = False
    #: Whether voltage and current are unknowns of the resistive part of
    #: modified nodal analysis.
    resistive = False
    #: The place in the normal tree (lower first): voltages known from the
    #: state and the sources first, currents last.
    tree_rank = None

    def __new__(cls, index, name, kind, tail, head, value):
        element = ELEMENTS.get(kind)
        if element is None:
            raise CircuitError(f"unknown kind {kind!r}; expected one of {', '.join(ELEMENTS)}")
        return super().__new__(element, index, name, kind, tail, head, value)

    def __repr__(self):
        fields = ", ".join(f"{f}={v!r}" for f, v in zip(self._fields, self))
        return f"Branch({fields})"

    # -- the entry ---------------------------------------------------------

    @classmethod
    def own_variable(cls):
        r"""
        The symbol standing for the element's own variable in its value
        (``i`` for inductors, ``u`` for capacitors and nonlinear
        resistors), or ``None``.

        EXAMPLES::

            sage: from sage_dynsym.circuits.elements import Capacitor, Resistor
            sage: Capacitor.own_variable(), Resistor.own_variable()
            (u, None)
        """
        return SR.var(cls.own) if cls.own else None

    @classmethod
    def default_value(cls, name):
        r"""
        The value of an element entered by its name only (short form): the
        symbol ``name``.

        EXAMPLES::

            sage: from sage_dynsym.circuits.elements import Resistor, NonlinearResistor
            sage: Resistor.default_value('R1'), NonlinearResistor.default_value('f1')
            (R1, None)
        """
        return SR.var(name)

    @classmethod
    def check(cls, value, entry):
        r"""
        Check the physical sense of a value of this kind (for the entry
        ``entry``): real (no ``I``); depending on no current or voltage but
        the element's own (:attr:`own`); a *numeric* resistance, inductance
        or capacitance positive (a zero one is refused with what to do
        instead). Symbolic values are not assumed to have any sign.

        EXAMPLES::

            sage: from sage_dynsym.circuits.elements import Resistor, Capacitor, Inductor
            sage: Resistor.check(SR(2), 'b'); Resistor.check(var('R0'), 'b')
            sage: Capacitor.check(SR(0), 'branches[1]')
            Traceback (most recent call last):
            ...
            CircuitError: branches[1].value: a capacitance of 0 is an open circuit: remove the branch instead
            sage: Inductor.check(var('L0')*var('u'), 'branches[1]')
            Traceback (most recent call last):
            ...
            CircuitError: branches[1].value: the value of an inductor cannot depend on u
        """
        if value is None:
            return
        value = SR(value)
        foreign = {str(v) for v in value.variables()} & ({CURRENT, VOLTAGE} - {cls.own})
        if foreign:
            article = 'an' if cls.kind_name[0] in 'aeiou' else 'a'
            raise CircuitError(f"the value of {article} {cls.kind_name} cannot depend on "
                               f"{', '.join(sorted(foreign))}", entry=f"{entry}.value")
        check_real(value, entry)
        if cls.quantity is None or value.variables():
            return
        if value.is_zero():
            raise CircuitError(cls.zero_value, entry=f"{entry}.value")
        try:
            negative = bool(value < 0)
        except (TypeError, ValueError):
            return
        if negative:
            raise CircuitError(f"the {cls.quantity} must be positive, got {brief(value)}"
                               f"{cls._negative_hint}", entry=f"{entry}.value")

    _negative_hint = ""

    def _default(self):
        # whether the value is what the short form gives
        return self.value is not None and self.value.is_symbol() and str(self.value) == self.name

    def long_entry(self):
        r"""
        The branch as a long-form entry ``{from, to, kind, name, value}``,
        the value as an expression (no ``value`` for a nonlinear resistor
        without characteristic).

        EXAMPLES::

            sage: from sage_dynsym.circuits.elements import Branch
            sage: Branch(3, 'C1', 'capacitor', 2, 1, var('C0')*(1 + var('u')^2)).long_entry()
            {'from': 2, 'kind': 'capacitor', 'name': 'C1', 'to': 1, 'value': (u^2 + 1)*C0}
        """
        entry = {'from': self.tail, 'to': self.head, 'kind': self.kind, 'name': self.name}
        if self.value is not None:
            entry['value'] = self.value
        return entry

    def entry(self):
        r"""
        The branch as an entry of a description file: the short form
        ``[from, to, name]`` when the name's first letter gives the kind
        and the value is the name's symbol, else the long form with the
        value as text.

        EXAMPLES::

            sage: from sage_dynsym.circuits.elements import Branch
            sage: Branch(0, 'L1', 'inductor', 1, 2, var('L1')).entry()
            [1, 2, 'L1']
            sage: Branch(0, 'L1', 'inductor', 1, 2, 2*var('L0')).entry()
            {'from': 1, 'kind': 'inductor', 'name': 'L1', 'to': 2, 'value': '2*L0'}
        """
        if self.name[0] == self.prefix and self._default():
            return [self.tail, self.head, self.name]
        entry = self.long_entry()
        if 'value' in entry:
            entry['value'] = str(entry['value'])
        return entry

    def subs(self, substitution):
        r"""
        The branch with ``substitution`` (a dict ``{symbol: value}``)
        applied to its value.

        EXAMPLES::

            sage: from sage_dynsym.circuits.elements import Branch
            sage: Branch(1, 'R1', 'resistor', 1, 2, var('R1')).subs({var('R1'): 5})
            Branch(index=1, name='R1', kind='resistor', tail=1, head=2, value=5)
        """
        if self.value is None:
            return self
        return self._replace(value=SR(self.value).subs(substitution))

    # -- state and sources -------------------------------------------------

    def state_symbol(self, number):
        r"""
        The element's state variable numbered ``number``: ``i<number>``
        (an inductor's current), ``u<number>`` (a capacitor's voltage), or
        ``None`` for an element without state.

        EXAMPLES::

            sage: from sage_dynsym.circuits.elements import Branch
            sage: Branch(0, 'C1', 'capacitor', 1, 2, var('C1')).state_symbol(3)
            u3
            sage: Branch(0, 'R1', 'resistor', 1, 2, var('R1')).state_symbol(3) is None
            True
        """
        return SR.var(f"{self.state}{number}") if self.state else None

    def value_at(self, variable):
        r"""
        The value with the element's own variable (``i`` or ``u``, see
        :attr:`own`) replaced by ``variable``: a nonlinear inductance
        `L(i)` at a current, a nonlinear capacitance `C(u)` at a voltage.

        EXAMPLES::

            sage: from sage_dynsym.circuits.elements import Branch
            sage: C0, u, u2 = var('C0 u u2')
            sage: Branch(0, 'C1', 'capacitor', 1, 2, C0*(1 + u^2)).value_at(u2)
            (u2^2 + 1)*C0
        """
        own = self.own_variable()
        return self.value if own is None else SR(self.value).subs({own: variable})

    def known_voltage(self, symbol):
        r"""
        The branch voltage where the state or a source fixes it: the state
        variable ``symbol`` of a capacitor, a voltage source's value;
        ``None`` for other elements.

        EXAMPLES::

            sage: from sage_dynsym.circuits.elements import Branch
            sage: Branch(0, 'E1', 'voltage_source', 0, 1, var('E1')).known_voltage(None)
            E1
            sage: Branch(0, 'C1', 'capacitor', 0, 1, var('C1')).known_voltage(var('u2'))
            u2
        """
        return None

    def known_current(self, symbol):
        r"""
        The branch current where the state or a source fixes it: the state
        variable ``symbol`` of an inductor, a current source's value;
        ``None`` for other elements.

        EXAMPLES::

            sage: from sage_dynsym.circuits.elements import Branch
            sage: Branch(0, 'I1', 'current_source', 0, 1, var('I1')).known_current(None)
            I1
            sage: Branch(0, 'R1', 'resistor', 0, 1, var('R1')).known_current(var('i1')) is None
            True
        """
        return None

    def fixed_voltage(self):
        r"""
        The voltage a source imposes (its value, possibly a function of
        ``t``), ``None`` for elements that are not voltage sources.

        EXAMPLES::

            sage: from sage_dynsym.circuits.elements import Branch
            sage: E0, w, t = var('E0 w t')
            sage: Branch(0, 'E1', 'voltage_source', 0, 1, E0*sin(w*t)).fixed_voltage()
            E0*sin(t*w)
        """
        return None

    def fixed_current(self):
        r"""
        The current a source drives (its value), ``None`` for elements that
        are not current sources.

        EXAMPLES::

            sage: from sage_dynsym.circuits.elements import Branch
            sage: Branch(0, 'I1', 'current_source', 0, 1, var('I1')).fixed_current()
            I1
        """
        return None

    def is_inductive(self):
        r"""
        Whether the element stores magnetic energy: its current is a state
        variable (:attr:`state` is :data:`CURRENT`), it is a winding that
        mutual inductances may couple, and its term in the loop method is
        kinetic. The analyses ask this instead of testing the class.

        EXAMPLES::

            sage: from sage_dynsym.circuits.elements import Branch
            sage: [Branch(0, n, k, 1, 2, var(n)).is_inductive()
            ....:  for n, k in [('L1', 'inductor'), ('C1', 'capacitor'), ('I1', 'current_source')]]
            [True, False, False]
        """
        return self.state == CURRENT

    def is_capacitive(self):
        r"""
        Whether the element stores electric energy: its voltage is a state
        variable (:attr:`state` is :data:`VOLTAGE`).

        EXAMPLES::

            sage: from sage_dynsym.circuits.elements import Branch
            sage: [Branch(0, n, k, 1, 2, var(n)).is_capacitive()
            ....:  for n, k in [('C1', 'capacitor'), ('E1', 'voltage_source'), ('L1', 'inductor')]]
            [True, False, False]
        """
        return self.state == VOLTAGE

    # -- the Lagrangians of linear circuits -----------------------------------

    def is_linear(self):
        r"""
        Whether the element's law is linear: not a nonlinear resistor, and
        an inductance or capacitance that does not depend on its own
        current or voltage.

        EXAMPLES::

            sage: from sage_dynsym.circuits.elements import Branch
            sage: L0, i = var('L0 i')
            sage: Branch(0, 'L1', 'inductor', 1, 2, L0).is_linear()
            True
            sage: Branch(0, 'L1', 'inductor', 1, 2, L0/(1 + i^2)).is_linear()
            False
        """
        return self.own is None or not SR(self.value).has(SR.var(self.own))

    def loop_term(self):
        r"""
        The element's term in the loop-current Lagrangian of a linear
        circuit, a pair ``(role, weight)`` with ``role`` ``'kinetic'``
        (`T \mathrel{+}= \tfrac12 w\, i_b^2`), ``'potential'`` (`\Pi
        \mathrel{+}= \tfrac12 w\, Q_b^2`) or ``'dissipation'`` (`R
        \mathrel{+}= \tfrac12 w\, i_b^2`), `i_b` the branch current and
        `Q_b` its charge; ``None`` for sources (a voltage source is a
        generalized force, :meth:`fixed_voltage`; a current source fixes a
        loop current, :meth:`fixed_current`).

        EXAMPLES::

            sage: from sage_dynsym.circuits.elements import Branch
            sage: Branch(0, 'C1', 'capacitor', 1, 2, var('C1')).loop_term()
            ('potential', 1/C1)
        """
        return None

    def node_term(self):
        r"""
        The element's term in the node-potential Lagrangian of a linear
        circuit, a pair ``(role, weight)`` as in :meth:`loop_term`, in the
        branch flux linkage `\Delta_b` and its voltage `\dot\Delta_b`:
        ``'kinetic'`` (`\tfrac12 w\, \dot\Delta_b^2`), ``'potential'``
        (`\tfrac12 w\, \Delta_b^2`, inductors; coupled windings take the
        inverse of their inductance matrix instead) or ``'dissipation'``
        (`\tfrac12 w\, \dot\Delta_b^2`); ``None`` for sources (a current
        source is a generalized force, a voltage source ties two node
        fluxes).

        EXAMPLES::

            sage: from sage_dynsym.circuits.elements import Branch
            sage: Branch(0, 'C1', 'capacitor', 1, 2, var('C1')).node_term()
            ('kinetic', C1)
        """
        return None

    # -- the mixed potential -------------------------------------------------

    def current_potential(self, current):
        r"""
        The element's term `\int_0^{i} u\, di` in the current potential
        `F(i)` when its current is ``current``; ``None`` when it has none.

        EXAMPLES::

            sage: from sage_dynsym.circuits.elements import Branch
            sage: Branch(0, 'R1', 'resistor', 1, 2, var('R1')).current_potential(var('i1'))
            -1/2*R1*i1^2
        """
        return None

    def voltage_potential(self, voltage, s):
        r"""
        The element's term `\int_0^{u} i\, du` in the voltage potential
        `G(u)` when its voltage is ``voltage`` (``s``: the variable of
        integration); ``None`` when it has none.

        EXAMPLES::

            sage: from sage_dynsym.circuits.elements import Branch
            sage: u, s = var('u s')
            sage: Branch(0, 'I1', 'current_source', 1, 2, var('I1')).voltage_potential(u, s)
            I1*u
        """
        return None

    # -- modified nodal analysis ---------------------------------------------

    def resistance(self):
        r"""
        The resistance `R` of a linear resistor (`u_b = -R\, i_b`), ``None``
        for other elements.

        EXAMPLES::

            sage: from sage_dynsym.circuits.elements import Branch
            sage: Branch(0, 'R1', 'resistor', 1, 2, var('R1')).resistance()
            R1
        """
        return None

    def current(self, voltage):
        r"""
        The branch current as a function of the branch voltage ``voltage``
        for a voltage-controlled element (:attr:`voltage_controlled`),
        ``None`` for the others.

        EXAMPLES::

            sage: from sage_dynsym.circuits.elements import Branch
            sage: Branch(0, 'f1', 'nonlinear_resistor', 1, 2, None).current(var('u3'))
            f1(u3)
        """
        return None


class Resistor(Branch):
    r"""
    A linear resistor, `u_b = -R\, i_b` (short-form prefix ``R``).

    EXAMPLES: its terms, by hand `T = 0`, `R = \tfrac12 R i^2` (loop method),
    `\tfrac12 \dot\Delta^2/R` (node method), `F = \int_0^i (-R i)\, di`,
    `G = \int_0^u (-u/R)\, du`::

        sage: from sage_dynsym.circuits.elements import Branch
        sage: R = Branch(0, 'R1', 'resistor', 1, 2, var('R1')); type(R).__name__
        'Resistor'
        sage: R.loop_term(), R.node_term(), R.resistance(), R.current(var('u'))
        (('dissipation', R1), ('dissipation', 1/R1), R1, -u/R1)
        sage: R.current_potential(var('i')), R.voltage_potential(var('u'), var('s'))
        (-1/2*R1*i^2, -1/2*u^2/R1)

    TESTS::

        sage: from sage_dynsym.circuits.elements import Resistor
        sage: Resistor.check(SR(-1), 'branches[1]')
        Traceback (most recent call last):
        ...
        CircuitError: branches[1].value: the resistance must be positive, got -1; an active element is a nonlinear resistor (kind: nonlinear_resistor) with its characteristic
    """
    __slots__ = ()
    kind_name = 'resistor'
    prefix = 'R'
    quantity = 'resistance'
    zero_value = "a resistance of 0 is a short circuit: join its two nodes into one instead"
    _negative_hint = ("; an active element is a nonlinear resistor (kind: nonlinear_resistor) "
                      "with its characteristic")
    voltage_controlled = current_controlled = resistive = True
    tree_rank = 2

    def loop_term(self):
        return ('dissipation', self.value)

    def node_term(self):
        return ('dissipation', 1 / self.value)

    def current_potential(self, current):
        return -self.value * current ** 2 / 2

    def voltage_potential(self, voltage, s):
        return -voltage ** 2 / (2 * self.value)

    def resistance(self):
        return self.value

    def current(self, voltage):
        return -voltage / self.value


class Inductor(Branch):
    r"""
    An inductor, `u_b = -L(i_b)\, di_b/dt` (short-form prefix ``L``; a long
    form value may depend on its own current ``i``). Its current is a state
    variable ``i<k>``; mutual inductances couple inductors (see
    :mod:`~sage_dynsym.circuits.elements.windings`).

    EXAMPLES::

        sage: from sage_dynsym.circuits.elements import Branch
        sage: L0, i = var('L0 i')
        sage: L = Branch(0, 'L1', 'inductor', 1, 2, L0/(1 + i^2))
        sage: L.value_at(var('i2')), L.state_symbol(2), L.known_current(var('i2'))
        (L0/(i2^2 + 1), i2, i2)
        sage: L.sets_current, L.sets_voltage, L.is_linear()
        (True, False, False)

    TESTS::

        sage: from sage_dynsym.circuits.elements import Inductor
        sage: Inductor.check(SR(-1), 'branches[1]')
        Traceback (most recent call last):
        ...
        CircuitError: branches[1].value: the inductance must be positive, got -1
    """
    __slots__ = ()
    kind_name = 'inductor'
    prefix = 'L'
    quantity = 'inductance'
    zero_value = "an inductance of 0 is a short circuit: join its two nodes into one instead"
    own = state = CURRENT
    sets_current = True
    tree_rank = 4

    def known_current(self, symbol):
        return symbol

    def loop_term(self):
        return ('kinetic', self.value)

    def node_term(self):
        return ('potential', 1 / self.value)


class Capacitor(Branch):
    r"""
    A capacitor, `i_b = -C(u_b)\, du_b/dt` (short-form prefix ``C``; a long
    form value may depend on its own voltage ``u``). Its voltage is a state
    variable ``u<k>``.

    EXAMPLES::

        sage: from sage_dynsym.circuits.elements import Branch
        sage: C = Branch(0, 'C1', 'capacitor', 1, 2, var('C1'))
        sage: C.loop_term(), C.node_term(), C.known_voltage(var('u2'))
        (('potential', 1/C1), ('kinetic', C1), u2)

    TESTS::

        sage: from sage_dynsym.circuits.elements import Capacitor
        sage: Capacitor.check(SR(-2), 'branches[1]')
        Traceback (most recent call last):
        ...
        CircuitError: branches[1].value: the capacitance must be positive, got -2
    """
    __slots__ = ()
    kind_name = 'capacitor'
    prefix = 'C'
    quantity = 'capacitance'
    zero_value = "a capacitance of 0 is an open circuit: remove the branch instead"
    own = state = VOLTAGE
    sets_voltage = True
    tree_rank = 1

    def known_voltage(self, symbol):
        return symbol

    def loop_term(self):
        return ('potential', 1 / self.value)

    def node_term(self):
        return ('kinetic', self.value)


class VoltageSource(Branch):
    r"""
    A voltage source, `u_b = E`: it raises the potential from its ``from``
    node to its ``to`` node by `E` (short-form prefix ``E``; the value may
    depend on ``t``).

    EXAMPLES::

        sage: from sage_dynsym.circuits.elements import Branch
        sage: E = Branch(0, 'E1', 'voltage_source', 0, 1, var('E1'))
        sage: E.fixed_voltage(), E.fixed_current(), E.loop_term(), E.known_voltage(None)
        (E1, None, None, E1)
    """
    __slots__ = ()
    kind_name = 'voltage_source'
    prefix = 'E'
    sets_voltage = True
    tree_rank = 0

    def known_voltage(self, symbol):
        return self.value

    def fixed_voltage(self):
        return self.value

class CurrentSource(Branch):
    r"""
    A current source, `i_b = I`: it drives `I` from its ``from`` node to its
    ``to`` node (short-form prefix ``I``; the value may depend on ``t``).

    EXAMPLES::

        sage: from sage_dynsym.circuits.elements import Branch
        sage: I1 = Branch(0, 'I1', 'current_source', 0, 1, var('I1'))
        sage: I1.fixed_current(), I1.current(var('u')), I1.voltage_potential(var('u'), var('s'))
        (I1, I1, I1*u)
    """
    __slots__ = ()
    kind_name = 'current_source'
    prefix = 'I'
    sets_current = voltage_controlled = True
    tree_rank = 5

    def known_current(self, symbol):
        return self.value

    def fixed_current(self):
        return self.value
    def current(self, voltage):
        return self.value

    def voltage_potential(self, voltage, s):
        return self.value * voltage


class NonlinearResistor(Branch):
    r"""
    A nonlinear voltage-controlled resistor, `i_b = f(u_b)` (short-form
    prefix ``f``). Without a value its characteristic is the symbolic
    function ``function(name)``; a long-form value gives it as an
    expression in ``u``. Its term in `G(u)` is `\int_0^u f(s)\, ds`.

    EXAMPLES::

        sage: from sage_dynsym.circuits.elements import Branch
        sage: u, s, g = var('u s g')
        sage: f = Branch(0, 'f1', 'nonlinear_resistor', 1, 2, None)
        sage: f.current(var('u2')), f.voltage_potential(var('u2'), s)
        (f1(u2), integrate(f1(s), s, 0, u2))
        sage: h = Branch(1, 'f2', 'nonlinear_resistor', 1, 2, g*u^3 - u)
        sage: h.current(var('u2')), h.voltage_potential(var('u2'), s)
        (g*u2^3 - u2, 1/4*g*u2^4 - 1/2*u2^2)
        sage: h.is_linear(), h.entry()
        (False, {'from': 1, 'kind': 'nonlinear_resistor', 'name': 'f2', 'to': 2, 'value': 'g*u^3 - u'})
    """
    __slots__ = ()
    kind_name = 'nonlinear_resistor'
    prefix = 'f'
    own = VOLTAGE
    is_function = True
    voltage_controlled = resistive = True
    tree_rank = 3

    @classmethod
    def default_value(cls, name):
        return None

    def _default(self):
        return self.value is None

    def is_linear(self):
        return False

    def current(self, voltage):
        if self.value is None:
            return symbolic_function(self.name)(voltage)
        return self.value.subs({self.own_variable(): voltage})

    def voltage_potential(self, voltage, s):
        if self.value is None:
            return definite_integral(self.current(s), s, 0, voltage, hold=True)
        return _integral(self.current(s), s, voltage)


def state_symbols(branches, positions):
    r"""
    The state variables of the branches at ``positions`` (inductors and
    capacitors), numbered `1, 2, \ldots` in that order: a dictionary
    ``{position: symbol}`` (see :meth:`Branch.state_symbol`).

    EXAMPLES::

        sage: from sage_dynsym.circuits.elements import parse_entries
        sage: from sage_dynsym.circuits.elements.kinds import state_symbols
        sage: branches, _ = parse_entries([[1, 2, 'C1'], [2, 3, 'R1'], [3, 1, 'L1']])
        sage: state_symbols(branches, [2, 0])
        {0: u2, 2: i1}
    """
    return {p: branches[p].state_symbol(k + 1) for k, p in enumerate(positions)}


#: The element classes by kind, in the order of the short-form prefixes'
#: documentation.
ELEMENTS = {cls.kind_name: cls for cls in (Resistor, Inductor, Capacitor, VoltageSource,
                                           CurrentSource, NonlinearResistor)}
