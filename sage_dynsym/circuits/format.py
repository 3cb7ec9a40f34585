r"""
The description format of circuits (read and write)

A circuit description (format: :doc:`/description_files`) is a mapping
with the keys ``kind: circuit``, ``name``, ``branches`` (the branch list
of :mod:`~sage_dynsym.circuits.elements`), ``parameters``, ``positive``
and ``results`` (written by ``save``, ignored when reading).
:func:`read_circuit` builds a circuit from it (what
:meth:`Circuit.from_dict <sage_dynsym.circuits.circuit.Circuit.from_dict>`
calls), :func:`circuit_mapping` gives the mapping of a circuit (each
element in the short form wherever its value is its own symbol),
:func:`circuit_results` the ``results:`` section ``save`` writes, and
:func:`result_symbols` the names such a section may use when it is read
back. This module imports neither the circuit class nor its earlier
format functions (:mod:`~sage_dynsym.circuits.description`).

EXAMPLES::

    sage: from sage_dynsym.circuits import Circuit
    sage: from sage_dynsym.circuits.format import circuit_mapping, circuit_results
    sage: C = Circuit([[1, 2, 'L1'], {'from': 2, 'to': 1, 'kind': 'capacitor', 'name': 'C1',
    ....:              'value': '2*C0'}], parameters=['C0'], name='LC')
    sage: circuit_mapping(C)
    {'branches': [[1, 2, 'L1'], {'from': 2, 'kind': 'capacitor', 'name': 'C1', 'to': 1, 'value': '2*C0'}],
     'kind': 'circuit',
     'name': 'LC',
     'parameters': ['C0']}
    sage: circuit_results(C)['state_equations']
    ['u2', '-i1']
"""
from sage.misc.latex import latex

from ..errors import CircuitError, DescriptionError, DynSymError, brief
from ..io.fields import declared_names, title, MAX_PARAMETERS
from ..symbols import check_name, velocity, acceleration, momentum

__all__ = ['KEYS', 'MAX_BRANCHES', 'read_circuit', 'circuit_mapping', 'circuit_results',
           'result_symbols']

#: The keys of a circuit description.
KEYS = {'kind', 'name', 'branches', 'parameters', 'positive', 'results'}

#: Most branches (entries of ``branches``) of a circuit description.
MAX_BRANCHES = 2000


def read_circuit(cls, data, source=None):
    r"""
    The circuit of class ``cls`` described by the mapping ``data``
    (``source``: the file, named in errors); every key is checked, the
    branch list by the circuit.

    EXAMPLES::

        sage: from sage_dynsym.circuits import Circuit
        sage: from sage_dynsym.circuits.format import read_circuit
        sage: read_circuit(Circuit, {'kind': 'circuit', 'branches': [[1, 2, 'L1'], [2, 1, 'C1']],
        ....:                        'positive': ['L1']}).positive_parameters()
        [L1]

    TESTS: see :func:`~sage_dynsym.circuits.description.circuit_from_dict`, and::

        sage: read_circuit(Circuit, {'kind': 'circuit', 'branches': [[1, 2, 'L1']], 'name': 3})
        Traceback (most recent call last):
        ...
        DescriptionError: name: expected a text, got 3
    """
    if not isinstance(data, dict):
        raise DescriptionError(f"a circuit description is a mapping, got {type(data).__name__}",
                               source=source)
    for key in data:
        if key not in KEYS:
            raise DescriptionError("unknown key; a circuit description has keys "
                                   f"{', '.join(sorted(KEYS))}", entry=str(key)[:60],
                                   source=source)
    if data.get('kind') != 'circuit':
        raise DescriptionError(f"expected 'circuit', got {brief(data.get('kind'))}",
                               entry='kind', source=source)
    if 'branches' not in data:
        raise DescriptionError("missing key 'branches' (a list of [from, to, element])",
                               entry='branches', source=source)
    branches = data['branches']
    if not isinstance(branches, list) or not branches:
        raise DescriptionError(f"expected a non-empty list of branches, got {brief(branches)}",
                               entry='branches', source=source)
    if len(branches) > MAX_BRANCHES:
        raise DescriptionError(f"{len(branches)} branches; a description file has at most "
                               f"{MAX_BRANCHES} (MAX_BRANCHES)", entry='branches', source=source)
    name = data.get('name')
    if name is not None and not isinstance(name, str):
        raise DescriptionError(f"expected a text, got {brief(name)}", entry='name', source=source)
    name = title(data, 'name', source)
    parameters = data.get('parameters', [])
    if not isinstance(parameters, list) or not all(
            isinstance(p, str) and p.isidentifier() for p in parameters):
        raise DescriptionError(f"expected a list of symbol names, got {brief(parameters)}",
                               entry='parameters', source=source)
    if len(parameters) > MAX_PARAMETERS:
        raise DescriptionError(f"{len(parameters)} names; a description file has at most "
                               f"{MAX_PARAMETERS} (MAX_PARAMETERS)", entry='parameters',
                               source=source)
    for i, p in enumerate(parameters):
        check_name(p, f"parameters[{i}]", source=source)
    positive = declared_names(data, 'positive', source, required=False, limit=MAX_PARAMETERS)
    try:
        return cls(branches, name=name, parameters=parameters, positive=positive)
    except DynSymError as err:
        raise err.with_context(source=source) from err




def circuit_mapping(circuit):
    r"""
    The description mapping of ``circuit`` (see the module documentation
    and :meth:`~sage_dynsym.circuits.circuit.Circuit.to_dict`).

    EXAMPLES: see the module documentation.
    """
    out = {'kind': circuit.kind}
    if circuit.name():
        out['name'] = circuit.name()
    if circuit.parameters():
        out['parameters'] = list(circuit.parameters())
    if circuit.positive_parameters():
        out['positive'] = [str(p) for p in circuit.positive_parameters()]
    out['branches'] = ([b.entry() for b in circuit.branches()]
                       + [c.entry() for c in circuit.couplings()])
    return out


def circuit_results(circuit):
    r"""
    The ``results:`` section of a saved description of ``circuit``: the
    state equations (where the circuit has them), the mixed potential (of
    a complete circuit) and the loop Lagrangian of a linear circuit, as text and LaTeX (see
    :meth:`~sage_dynsym.circuits.circuit.Circuit.results`).

    EXAMPLES: see the module documentation.
    """
    results = {}
    try:
        equations = circuit.state_equations()
    except CircuitError:
        pass
    else:
        results['state_variables'] = [str(v) for v, _ in circuit.state_variables()]
        results['state_equations'] = [str(e) for e in equations]
        results['state_equations_latex'] = [str(latex(e)) for e in equations]
        if circuit.has_mixed_potential():
            results['mixed_potential_text'] = str(circuit.mixed_potential())
            results['mixed_potential_latex'] = str(latex(circuit.mixed_potential()))
    if all(b.is_linear() for b in circuit.branches()):
        try:
            L = circuit.lagrangian(method="loop")
        except CircuitError:
            pass
        else:
            results['lagrangian'] = str(L.expr())
            results['lagrangian_latex'] = str(latex(L.expr()))
            results['lagrange_equations'] = [str(e) for e in L.lagrange_equations()]
    return results


def result_symbols(circuit, results):
    r"""
    The names a ``results:`` section ``results`` of ``circuit`` may use,
    and its functions (see
    :meth:`~sage_dynsym.circuits.circuit.Circuit.result_symbols`); the
    section's state variables must be the circuit's.

    EXAMPLES::

        sage: from sage_dynsym.circuits import Circuit
        sage: from sage_dynsym.circuits.format import result_symbols
        sage: result_symbols(Circuit([[1, 2, 'L1'], [2, 1, 'C1'], [2, 1, 'f1']]),
        ....:                {'state_variables': ['i1', 'u2']})
        (['i1', 'u2', 'L1', 'C1'], ['f1'])

    TESTS::

        sage: result_symbols(Circuit([[1, 2, 'L1'], [2, 1, 'C1']]), {'state_variables': ['i2']})
        Traceback (most recent call last):
        ...
        DescriptionError: results.state_variables: expected the state variables ['i1', 'u2'] of the circuit, got ['i2']
    """
    if not isinstance(results, dict):
        raise DescriptionError(f"expected the results: section (a mapping), got {brief(results)}",
                               entry='results')
    q = [str(v) for v in circuit.lagrangian().coordinates()] if 'lagrangian' in results else []
    states = results.get('state_variables', [])
    expected = [str(v) for v, _ in circuit.state_variables()] if states else []
    if states != expected:
        raise DescriptionError(f"expected the state variables {expected} of the circuit, "
                               f"got {brief(states)}", entry='results.state_variables')
    symbols = list(circuit.parameters()) + states
    symbols += [b.name for b in circuit.branches() if not b.is_function]
    symbols += q + [str(velocity(v)) for v in q] + [str(acceleration(v)) for v in q]
    symbols += [str(momentum(v)) for v in q]
    return symbols, [b.name for b in circuit.branches() if b.is_function]
