r"""
Coupled windings: the inductance matrix must be positive semi-definite

The magnetic energy of inductors `L_k` coupled by mutual inductances
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
(checked when the entry is read, see
:func:`~sage_dynsym.circuits.elements.parse_entries`). A group of windings
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
from itertools import combinations

from sage.matrix.constructor import matrix
from sage.rings.qqbar import AA
from sage.symbolic.ring import SR

from ..errors import CircuitError
from ..symbols import is_exact

#: Most windings in one group of coupled windings whose symbolic inductance
#: matrix is examined (all its `2^n - 1` principal minors); a larger group
#: with symbolic values is refused.
MAX_COUPLED_WINDINGS = 8


def coupled_groups(circuit):
    r"""
    The groups of inductors joined by mutual inductances (connected
    components of the coupling graph, each with at least one coupling), as
    lists of names in the order of the branches, with the position of the
    entry of a coupling in each group (for error messages).

    EXAMPLES::

        sage: from sage_dynsym.circuits import Circuit
        sage: from sage_dynsym.circuits.inductance import coupled_groups
        sage: C = Circuit([[0, 1, 'L1'], [1, 0, 'L2'], [0, 2, 'L3'], [2, 0, 'R1'],
        ....:     {'kind': 'mutual', 'between': ['L3', 'L1'], 'value': 'M'}], parameters=['M'])
        sage: coupled_groups(C)
        [(['L1', 'L3'], 0)]
    """
    order = {b.name: k for k, b in enumerate(circuit.branches())}
    parent = {}

    def find(a):
        while parent.setdefault(a, a) != a:
            parent[a] = parent[parent[a]]
            a = parent[a]
        return a
    first = {}
    for c in circuit.couplings():
        parent[find(c.first)] = find(c.second)
    for k, c in enumerate(circuit.couplings()):
        first.setdefault(find(c.first), k)
    groups = {}
    for name in parent:
        groups.setdefault(find(name), []).append(name)
    return [(sorted(names, key=order.get), first[root]) for root, names in
            sorted(groups.items(), key=lambda item: first[item[0]])]


def inductance_matrix(circuit, names):
    r"""
    The inductance matrix of the windings ``names`` of ``circuit``: their
    inductances on the diagonal, the mutual inductances off it.

    EXAMPLES::

        sage: from sage_dynsym.circuits import Circuit
        sage: from sage_dynsym.circuits.inductance import inductance_matrix
        sage: C = Circuit([[0, 1, 'L1'], [1, 0, 'L2'], [0, 1, 'R1'],
        ....:     {'kind': 'mutual', 'between': ['L1', 'L2'], 'value': 'M'}], parameters=['M'])
        sage: inductance_matrix(C, ['L1', 'L2'])
        [L1  M]
        [ M L2]
    """
    index = {name: k for k, name in enumerate(names)}
    value = {b.name: SR(b.value) for b in circuit.branches() if b.name in index}
    L = matrix(SR, len(names), len(names))
    for name, k in index.items():
        L[k, k] = value[name].subs({SR.var('i'): 0})
    for c in circuit.couplings():
        if c.first in index and c.second in index:
            j, k = index[c.first], index[c.second]
            L[j, k] = L[k, j] = SR(c.value)
    return L


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
        sage: from sage_dynsym.circuits.inductance import inductance_conditions
        sage: C = Circuit([[0, 1, 'L1'], [1, 2, 'L2'], [2, 0, 'L3'], [0, 2, 'R1'],
        ....:     {'kind': 'mutual', 'between': ['L1', 'L2'], 'value': 'M'},
        ....:     {'kind': 'mutual', 'between': ['L2', 'L3'], 'value': 'M'}], parameters=['M'],
        ....:     positive=['L1', 'L2', 'L3', 'M'])
        sage: inductance_conditions(C)
        [L1*L2 - M^2 >= 0, L2*L3 - M^2 >= 0, L1*L2*L3 - (L1 + L3)*M^2 >= 0]
    """
    from ..analysis.conditions import positive_conditions
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
