r"""
Circuit description files

A circuit description (format: :doc:`/description_files`) is a mapping
with the keys

- ``kind: circuit`` (required),
- ``name`` (optional title),
- ``branches`` (required): a list of ``[from, to, element]`` entries or
  long-form mappings (see :mod:`~sage_dynsym.circuits.elements`),
- ``parameters`` (optional): extra symbols used in long-form values,
- ``positive`` (optional): parameters and element values known to be
  positive (see :meth:`~sage_dynsym.dynamics.model.Model.positive_parameters`),
- ``results`` (optional): written by ``save``; ignored when reading.

The generic ``sage_dynsym.load`` reads the YAML file safely and hands the
mapping to :meth:`Circuit.from_dict
<sage_dynsym.circuits.circuit.Circuit.from_dict>` (the format is read by
:func:`~sage_dynsym.circuits.format.read_circuit`); ``save`` writes
:meth:`Circuit.to_dict <sage_dynsym.circuits.circuit.Circuit.to_dict>`
plus a ``results:`` section. Expressions are parsed by
:class:`~sage_dynsym.io.expressions.ExpressionParser`, never evaluated.
:func:`circuit_from_dict` and :func:`circuit_to_dict` are the earlier
names of these methods.

EXAMPLES::

    sage: from sage_dynsym.circuits.description import circuit_from_dict, circuit_to_dict
    sage: data = {'kind': 'circuit', 'name': 'RC', 'branches': [[1, 2, 'R1'], [2, 1, 'C1'],
    ....:         {'from': 1, 'to': 2, 'kind': 'current_source', 'value': '2*I0', 'name': 'I1'}],
    ....:         'parameters': ['I0']}
    sage: C = circuit_from_dict(data); C
    Circuit 'RC' with 3 branches on 2 nodes
    sage: circuit_to_dict(C) == data
    True
    sage: circuit_from_dict({'kind': 'circuit', 'branches': [[1, 2, 'R1'], [2, 1, 'X1']]},
    ....:                   source='bad.yaml')
    Traceback (most recent call last):
    ...
    CircuitError: bad.yaml: branches[1]: unknown element prefix 'X' in 'X1'; ...
"""
from .circuit import Circuit
from .format import KEYS, MAX_BRANCHES

__all__ = ['circuit_from_dict', 'circuit_to_dict', 'KEYS', 'MAX_BRANCHES']


def circuit_from_dict(data, source=None):
    r"""
    Build a :class:`~sage_dynsym.circuits.circuit.Circuit` from a
    description mapping: :meth:`Circuit.from_dict
    <sage_dynsym.circuits.circuit.Circuit.from_dict>`.

    INPUT:

    - ``data`` -- the mapping read from a description file
    - ``source`` -- (optional) the file name, used in error messages

    OUTPUT: a ``Circuit``

    TESTS::

        sage: from sage_dynsym.circuits.description import circuit_from_dict
        sage: circuit_from_dict({'kind': 'circuit'}, source='c.yaml')
        Traceback (most recent call last):
        ...
        DescriptionError: c.yaml: branches: missing key 'branches' (a list of [from, to, element])
        sage: circuit_from_dict({'kind': 'circuit', 'branches': [[1, 2, 'R1']], 'colour': 1})
        Traceback (most recent call last):
        ...
        DescriptionError: colour: unknown key; a circuit description has keys branches, kind, name, parameters, positive, results
        sage: circuit_from_dict({'kind': 'mechanical', 'branches': []})
        Traceback (most recent call last):
        ...
        DescriptionError: kind: expected 'circuit', got 'mechanical'
        sage: circuit_from_dict({'kind': 'circuit', 'branches': {'a': 1}})
        Traceback (most recent call last):
        ...
        DescriptionError: branches: expected a non-empty list of branches, got {'a': 1}
        sage: circuit_from_dict({'kind': 'circuit', 'branches': [[1, 2, 'R1'], [2, 2, 'C1']]}, 'x.yaml')
        Traceback (most recent call last):
        ...
        CircuitError: x.yaml: branches[1]: self-loop: branch C1 joins node 2 to itself
        sage: circuit_from_dict({'kind': 'circuit', 'branches': [[1, 2, 'R1'], [2, 1, 'C1']],
        ....:                    'parameters': ['q1']}, 'x.yaml')
        Traceback (most recent call last):
        ...
        CircuitError: x.yaml: parameters[0]: the name 'q1' is reserved: a loop charge, a coordinate of the loop method (q<k>); choose another name
        sage: circuit_from_dict({'kind': 'circuit', 'branches': [[1, 2, 'R1'],
        ....:     {'from': 2, 'to': 1, 'kind': 'capacitor', 'name': 'C1', 'value': 0}]}, 'x.yaml')
        Traceback (most recent call last):
        ...
        CircuitError: x.yaml: branches[1].value: a capacitance of 0 is an open circuit: remove the branch instead
        sage: circuit_from_dict({'kind': 'circuit', 'branches': [[1, 2, 'R1'], [2, 1, 'C1']],
        ....:                    'positive': ['R1', 'C1']}).positive_parameters()
        [R1, C1]
        sage: circuit_from_dict({'kind': 'circuit', 'branches': [[1, 2, 'R1'], [2, 1, 'C1']],
        ....:                    'positive': ['R2']}, 'x.yaml')
        Traceback (most recent call last):
        ...
        CircuitError: x.yaml: positive[0]: R2 is neither a parameter nor an element value of the circuit (positive lists symbols known to be positive)
    """
    return Circuit.from_dict(data, source)


def circuit_to_dict(circuit):
    r"""
    The description mapping of ``circuit`` (inverse of
    :func:`circuit_from_dict`): :meth:`Circuit.to_dict
    <sage_dynsym.circuits.circuit.Circuit.to_dict>`.

    EXAMPLES::

        sage: from sage_dynsym.circuits import Circuit
        sage: from sage_dynsym.circuits.description import circuit_to_dict
        sage: circuit_to_dict(Circuit([[1, 2, 'L1'], [2, 1, 'R1']]))
        {'branches': [[1, 2, 'L1'], [2, 1, 'R1']], 'kind': 'circuit'}
    """
    return circuit.to_dict()
