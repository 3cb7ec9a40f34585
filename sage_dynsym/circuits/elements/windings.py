r"""
Coupled windings: mutual inductances and the inductance matrix

A mutual inductance couples two inductors ``L1, L2`` (long form only,
``{kind: mutual, between: [L1, L2], value: M12}``): then `u_1 = -(L_1\,
di_1/dt + M_{12}\, di_2/dt)` and symmetrically. Such an entry is a
:class:`Coupling`; :func:`winding_matrix` is the inductance matrix of
inductor branches with the couplings between them, which every analysis
uses.

**The inductance matrix must be positive semi-definite.** The magnetic energy of inductors `L_k` coupled by mutual inductances
`M_{jk}` is `\tfrac12 i^T \mathcal{L} i`, `\mathcal{L}` the symmetric
matrix with the inductances on its diagonal and the mutual inductances off
it. A passive set of windings stores no negative energy: `\mathcal{L}` is
positive semi-definite, i.e. all its principal minors are `\ge 0`
(`M^2 \le L_1 L_2` for two windings; `M^2 = L_1 L_2` is perfect
coupling). A circuit that breaks this is not physical: its "passive"
network can create energy (a transformer with `M^2 > L_1 L_2` and
resistive loads has a growing solution).

:func:`inductance_conditions` checks each group of coupled windings when
the circuit is built:

- numbers (exact or floating-point, to rounding) are decided;
- symbolic values are decided under the signs declared positive (``M =
  2\sqrt{L_1 L_2}`` with `L_1, L_2 > 0` is refused);
- what the declared signs do not decide is returned as conditions
  (``L1*L2 - M^2 >= 0``), shown in the report and by
  :meth:`Circuit.conditions() <sage_dynsym.circuits.circuit.Circuit.conditions>`,
  and checked against the values given to the numerical methods.

A mutual inductance is a constant of the windings: its value may depend on
parameters and element values only, not on a current or a voltage
(checked when the entry is read, :meth:`Coupling.check`). A group of windings
with a current-dependent (nonlinear) inductance is checked where the
currents vanish.

EXAMPLES::

    sage: from sage_dynsym.circuits import Circuit
    sage: def transformer(M, **options):
    ....:     return Circuit([[0, 1, 'R1'], [1, 0, 'L1'], [2, 0, 'L2'], [0, 2, 'R2'],
    ....:                    {'kind': 'mutual', 'between': ['L1', 'L2'], 'value': M}], **options)
    sage: transformer('M', parameters=['M'], positive=['L1', 'L2']).conditions()
    [L1*L2 - M^2 >= 0]
    sage: transformer('sqrt(L1*L2)/2', positive=['L1', 'L2']).conditions()
    []
    sage: transformer('2*sqrt(L1*L2)', positive=['L1', 'L2'])
    Traceback (most recent call last):
    ...
    CircuitError: branches[4]: the inductance matrix of the coupled windings L1, L2 is not positive semi-definite for any value of the declared positive parameters: its minor -3*L1*L2 (rows L1, L2) is negative; passive windings need all the principal minors of the matrix >= 0 (for two: M^2 <= L1*L2)
    sage: Circuit([[0, 1, 'R1'], {'from': 1, 'to': 0, 'kind': 'inductor', 'name': 'L1', 'value': 1},
    ....:          {'from': 2, 'to': 0, 'kind': 'inductor', 'name': 'L2', 'value': 1}, [0, 2, 'R2'],
    ....:          {'kind': 'mutual', 'between': ['L1', 'L2'], 'value': 2}])
    Traceback (most recent call last):
    ...
    CircuitError: branches[4]: the inductance matrix of the coupled windings L1, L2 is not positive semi-definite: its smallest eigenvalue is -1 (the matrix is [1, 2; 2, 1]); passive windings need all the principal minors of the matrix >= 0 (for two: M^2 <= L1*L2)

REFERENCES:

- C. A. Desoer, E. S. Kuh, *Basic Circuit Theory*, McGraw-Hill, 1969,
  ch. 8 (coupled inductors, the energy of a passive transformer).
"""
from collections import namedtuple
from itertools import combinations

from sage.matrix.constructor import matrix
from sage.rings.qqbar import AA
from sage.symbolic.ring import SR

from ...errors import CircuitError, brief
from ...symbols import is_exact
from ..graph import UnionFind
from .kinds import CURRENT, VOLTAGE, check_real

__all__ = ['MAX_COUPLED_WINDINGS', 'Coupling', 'check_couplings', 'winding_matrix',
           'winding_groups', 'coupled_groups', 'inductance_matrix', 'inductance_conditions']

#: Most windings in one group of coupled windings whose symbolic inductance
#: matrix is examined (all its `2^n - 1` principal minors); a larger group
#: with symbolic values is refused.
MAX_COUPLED_WINDINGS = 8


class Coupling(namedtuple('Coupling', 'first second value')):
    r"""
    A mutual inductance ``value`` between inductors ``first`` and ``second``.

    EXAMPLES::

        sage: from sage_dynsym.circuits.elements import parse_entries
        sage: _, (c,) = parse_entries([[1, 2, 'L1'], [2, 1, 'L2'],
        ....:     {'kind': 'mutual', 'between': ['L1', 'L2'], 'value': 'M'}], ['M'])
        sage: c, c.value
        (Coupling(first='L1', second='L2', value=M), M)
        sage: c.entry()
        {'between': ['L1', 'L2'], 'kind': 'mutual', 'value': 'M'}
    """
    __slots__ = ()

    #: The kind's name in a description entry.
    kind_name = 'mutual'

    @classmethod
    def own_variable(cls):
        r"""
        ``None``: a mutual inductance is a constant of the windings, its
        value has no own variable.

        EXAMPLES::

            sage: from sage_dynsym.circuits.elements import Coupling
            sage: Coupling.own_variable() is None
            True
        """
        return None

    @classmethod
    def check(cls, value, entry):
        r"""
        Check a mutual inductance ``value`` (for the entry ``entry``): real,
        and a constant of the windings -- a current or a voltage in it would
        make the inductance matrix depend on the state. Its sign is free;
        the inductance matrix is checked as a whole
        (:func:`inductance_conditions`).

        EXAMPLES::

            sage: from sage_dynsym.circuits.elements import Coupling
            sage: Coupling.check(-var('M'), 'branches[2]')
            sage: Coupling.check(var('M')*var('i'), 'branches[2]')
            Traceback (most recent call last):
            ...
            CircuitError: branches[2].value: a mutual inductance may depend on parameters and element values only, got M*i
        """
        value = SR(value)
        check_real(value, entry)
        if {str(v) for v in value.variables()} & {CURRENT, VOLTAGE}:
            raise CircuitError(f"a mutual inductance may depend on parameters and element "
                               f"values only, got {brief(value)}", entry=f"{entry}.value")

    def long_entry(self):
        r"""
        The coupling as an entry of a branch list, the value as an
        expression.

        EXAMPLES::

            sage: from sage_dynsym.circuits.elements import Coupling
            sage: Coupling('L1', 'L2', var('k')*sqrt(var('L1')*var('L2'))).long_entry()
            {'between': ['L1', 'L2'], 'kind': 'mutual', 'value': sqrt(L1*L2)*k}
        """
        return {'kind': self.kind_name, 'between': [self.first, self.second],
                'value': self.value}

    def entry(self):
        r"""
        The coupling as an entry of a description file (the value as text).

        EXAMPLES::

            sage: from sage_dynsym.circuits.elements import Coupling
            sage: Coupling('L1', 'L2', var('M')).entry()
            {'between': ['L1', 'L2'], 'kind': 'mutual', 'value': 'M'}
        """
        return dict(self.long_entry(), value=str(self.value))

    def subs(self, substitution):
        r"""
        The coupling with ``substitution`` (a dict ``{symbol: value}``)
        applied to its value.

        EXAMPLES::

            sage: from sage_dynsym.circuits.elements import Coupling
            sage: Coupling('L1', 'L2', var('M')).subs({var('M'): 1/2})
            Coupling(first='L1', second='L2', value=1/2)
        """
        return self._replace(value=SR(self.value).subs(substitution))


def check_couplings(branches, couplings, positions):
    r"""
    Check that each coupling joins two different inductors of
    ``branches``, and each pair once; ``positions`` are the positions of
    the couplings' entries in the branch list (for the messages).

    EXAMPLES::

        sage: from sage_dynsym.circuits.elements import Branch, Coupling
        sage: from sage_dynsym.circuits.elements.windings import check_couplings
        sage: L1, C1 = Branch(0, 'L1', 'inductor', 1, 2, var('L1')), Branch(1, 'C1', 'capacitor', 2, 1, var('C1'))
        sage: check_couplings([L1, C1], [Coupling('L1', 'C1', var('M'))], [2])
        Traceback (most recent call last):
        ...
        CircuitError: branches[2]: a mutual inductance couples two inductors; C1 is not an inductor
    """
    by_name = {b.name: b for b in branches}
    pairs = set()
    for k, c in zip(positions, couplings):
        for name in (c.first, c.second):
            if name not in by_name or not by_name[name].is_inductive():
                raise CircuitError(f"a mutual inductance couples two inductors; {name} "
                                   "is not an inductor", entry=f"branches[{k}]")
        pair = frozenset((c.first, c.second))
        if len(pair) != 2 or pair in pairs:
            raise CircuitError("a mutual inductance couples two different inductors, "
                               "once", entry=f"branches[{k}]")
        pairs.add(pair)


def winding_matrix(inductors, couplings, currents=None):
    r"""
    The inductance matrix of the inductor branches ``inductors``, in that
    order: their inductances on the diagonal -- at the currents
    ``currents`` (one per inductor) for inductances depending on their own
    current, else as given -- and the mutual inductances of ``couplings``
    between them off it.

    EXAMPLES::

        sage: from sage_dynsym.circuits.elements import Branch, Coupling
        sage: from sage_dynsym.circuits.elements.windings import winding_matrix
        sage: L0, i, M = var('L0 i M')
        sage: L1 = Branch(0, 'L1', 'inductor', 0, 1, L0/(1 + i^2))
        sage: L2 = Branch(1, 'L2', 'inductor', 1, 0, var('L2'))
        sage: winding_matrix([L1, L2], [Coupling('L1', 'L2', M)], currents=[var('i1'), var('i2')])
        [L0/(i1^2 + 1)             M]
        [            M            L2]
    """
    index = {b.name: k for k, b in enumerate(inductors)}
    L = matrix(SR, len(inductors), len(inductors))
    for k, b in enumerate(inductors):
        L[k, k] = b.value if currents is None else b.value_at(currents[k])
    for c in couplings:
        if c.first in index and c.second in index:
            j, k = index[c.first], index[c.second]
            L[j, k] += c.value
            L[k, j] += c.value
    return L


def winding_groups(inductors, couplings):
    r"""
    The inductor branches ``inductors`` grouped by the mutual inductances
    ``couplings`` joining them (connected components of the coupling
    graph, single inductors included): a list of lists of branches, each
    in the order of ``inductors``, the groups in the order of their first
    inductor.

    EXAMPLES::

        sage: from sage_dynsym.circuits.elements import parse_entries
        sage: from sage_dynsym.circuits.elements.windings import winding_groups
        sage: br, cp = parse_entries([[0, 1, 'L1'], [1, 0, 'L2'], [0, 2, 'L3'], [2, 0, 'R1'],
        ....:     {'kind': 'mutual', 'between': ['L3', 'L1'], 'value': 'M'}], ['M'])
        sage: [[b.name for b in g] for g in winding_groups(br[:3], cp)]
        [['L1', 'L3'], ['L2']]
    """
    joined = UnionFind(b.name for b in inductors)
    for c in couplings:
        joined.union(c.first, c.second)
    groups = {}
    for b in inductors:
        groups.setdefault(joined.find(b.name), []).append(b)
    return list(groups.values())


def coupled_groups(circuit):
    r"""
    The groups of inductors joined by mutual inductances (connected
    components of the coupling graph, each with at least one coupling), as
    lists of names in the order of the branches, with the position of the
    entry of a coupling in each group (for error messages).

    EXAMPLES::

        sage: from sage_dynsym.circuits import Circuit
        sage: from sage_dynsym.circuits.elements.windings import coupled_groups
        sage: C = Circuit([[0, 1, 'L1'], [1, 0, 'L2'], [0, 2, 'L3'], [2, 0, 'R1'],
        ....:     {'kind': 'mutual', 'between': ['L3', 'L1'], 'value': 'M'}], parameters=['M'])
        sage: coupled_groups(C)
        [(['L1', 'L3'], 0)]
    """
    couplings = circuit.couplings()
    first = {}
    for k, c in enumerate(couplings):
        first.setdefault(c.first, k)
        first.setdefault(c.second, k)
    coupled = [b for b in circuit.branches() if b.name in first]
    groups = [[b.name for b in group] for group in winding_groups(coupled, couplings)]
    found = [(names, min(first[n] for n in names)) for names in groups]
    return sorted(found, key=lambda item: item[1])


def inductance_matrix(circuit, names):
    r"""
    The inductance matrix of the windings ``names`` of ``circuit``: their
    inductances (where the currents vanish) on the diagonal, the mutual
    inductances off it.

    EXAMPLES::

        sage: from sage_dynsym.circuits import Circuit
        sage: from sage_dynsym.circuits.elements.windings import inductance_matrix
        sage: C = Circuit([[0, 1, 'L1'], [1, 0, 'L2'], [0, 1, 'R1'],
        ....:     {'kind': 'mutual', 'between': ['L1', 'L2'], 'value': 'M'}], parameters=['M'])
        sage: inductance_matrix(C, ['L1', 'L2'])
        [L1  M]
        [ M L2]
    """
    by_name = {b.name: b for b in circuit.branches()}
    return winding_matrix([by_name[n] for n in names], circuit.couplings(),
                          currents=[0] * len(names))

_NEEDED = ("passive windings need all the principal minors of the matrix >= 0 (for two: "
           "M^2 <= L1*L2)")


def _shown(L):
    return "[" + "; ".join(", ".join(map(str, row)) for row in L.rows()) + "]"


def _numeric(L, names, entry):
    # exact algebraic numbers are decided exactly (all principal minors), the
    # others (floating-point, transcendental) by the eigenvalues, to rounding
    A = None
    if all(is_exact(e) for e in L.list()):
        try:
            A = matrix(AA, L)
        except (TypeError, ValueError):     # pi, e: not algebraic
            A = None
    if A is not None:
        n = A.nrows()
        ok = all(A.matrix_from_rows_and_columns(list(s), list(s)).det() >= 0
                 for k in range(1, n + 1) for s in combinations(range(n), k))
        smallest = None if ok else min(A.charpoly().roots(AA, multiplicities=False))
    else:
        import numpy as np
        values = np.array([[float(e) for e in row] for row in L.rows()])
        smallest = float(np.linalg.eigvalsh(values)[0])
        ok = smallest >= -1e-12 * max(1.0, float(np.max(np.abs(values))))
    if not ok:
        raise CircuitError(f"the inductance matrix of the coupled windings {', '.join(names)} "
                           f"is not positive semi-definite: its smallest eigenvalue is "
                           f"{float(smallest):.6g} (the matrix is {_shown(L)}); {_NEEDED}",
                           entry=entry)


def inductance_conditions(circuit, entries=None):
    r"""
    Check the groups of coupled windings of ``circuit`` (see the module
    documentation): raises :class:`~sage_dynsym.errors.CircuitError` for
    an inductance matrix that is not positive semi-definite, returns the
    conditions (relationals ``minor >= 0``) that the declared signs leave
    open. ``entries`` (optional) gives the position of the entry of each
    coupling in the branch list, for the messages.

    EXAMPLES: see the module documentation. Three windings::

        sage: from sage_dynsym.circuits import Circuit
        sage: from sage_dynsym.circuits.elements.windings import inductance_conditions
        sage: C = Circuit([[0, 1, 'L1'], [1, 2, 'L2'], [2, 0, 'L3'], [0, 2, 'R1'],
        ....:     {'kind': 'mutual', 'between': ['L1', 'L2'], 'value': 'M'},
        ....:     {'kind': 'mutual', 'between': ['L2', 'L3'], 'value': 'M'}], parameters=['M'],
        ....:     positive=['L1', 'L2', 'L3', 'M'])
        sage: inductance_conditions(C)
        [L1*L2 - M^2 >= 0, L2*L3 - M^2 >= 0, L1*L2*L3 - (L1 + L3)*M^2 >= 0]
    """
    from ...algebra.conditions import positive_conditions
    positive = circuit.positive_parameters()
    conditions = []
    for names, k in coupled_groups(circuit):
        entry = f"branches[{k if entries is None else entries[k]}]"
        L = inductance_matrix(circuit, names)
        if not any(SR(e).variables() for e in L.list()):
            _numeric(L, names, entry)
            continue
        n = L.nrows()
        if n > MAX_COUPLED_WINDINGS:
            raise CircuitError(f"{n} windings are coupled together with symbolic values; at "
                               f"most {MAX_COUPLED_WINDINGS} (MAX_COUPLED_WINDINGS) can be "
                               "checked for a positive semi-definite inductance matrix",
                               entry=entry)
        for size in range(1, n + 1):
            for rows in combinations(range(n), size):
                minor = L.matrix_from_rows_and_columns(list(rows), list(rows)).det()
                minor = SR(minor).simplify_rational()
                negative = positive_conditions(-minor, positive)
                if negative == []:
                    raise CircuitError(
                        f"the inductance matrix of the coupled windings {', '.join(names)} is "
                        "not positive semi-definite for any value of the declared positive "
                        f"parameters: its minor {minor.factor()} (rows "
                        f"{', '.join(names[r] for r in rows)}) is negative; {_NEEDED}",
                        entry=entry)
                if negative is not None:
                    conditions.append(minor >= 0)
    return conditions
