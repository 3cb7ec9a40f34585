r"""
Mechanical systems and description mappings, by their earlier names

A mechanical system reads and writes its description format itself:
:meth:`MechanicalSystem.from_dict
<sage_dynsym.mechanics.system.MechanicalSystem.from_dict>` (the format is in
:mod:`sage_dynsym.mechanics.format`) and :meth:`MechanicalSystem.to_dict
<sage_dynsym.mechanics.system.MechanicalSystem.to_dict>`. The functions here
are the names they had before, and the limits of the format.

EXAMPLES::

    sage: from sage_dynsym.mechanics.description import (mechanical_system_from_dict,
    ....:                                                mechanical_system_to_dict, MAX_BODIES)
    sage: S = mechanical_system_from_dict({'kind': 'mechanical', 'coordinates': ['x'],
    ....:     'bodies': [{'name': 'b', 'joint': ['x', 0, 0], 'mass': 1}]})
    sage: mechanical_system_to_dict(S)['coordinates'], MAX_BODIES
    (['x'], 1000)
"""
from .format import (MECHANICAL_KEYS, ROLLING_KEYS, OPERATING_POINT_KEYS,
                     REQUIRED_MECHANICAL, BODY_KEYS, FIELD_KEYS, NEWTONIAN_KEYS, LOAD_KEYS,
                     MAX_COORDINATES, MAX_BODIES, MAX_TERMS)
from .system import MechanicalSystem

__all__ = ['mechanical_system_from_dict', 'mechanical_system_to_dict', 'MECHANICAL_KEYS',
           'ROLLING_KEYS', 'OPERATING_POINT_KEYS', 'REQUIRED_MECHANICAL', 'BODY_KEYS',
           'FIELD_KEYS', 'NEWTONIAN_KEYS', 'LOAD_KEYS', 'MAX_COORDINATES', 'MAX_BODIES',
           'MAX_TERMS']


def mechanical_system_from_dict(data, source=None):
    r"""
    The mechanical system of a description mapping:
    :meth:`MechanicalSystem.from_dict
    <sage_dynsym.mechanics.system.MechanicalSystem.from_dict>` (the format:
    :func:`~sage_dynsym.mechanics.format.read_mechanical_system`).

    EXAMPLES::

        sage: from sage_dynsym.mechanics.description import mechanical_system_from_dict
        sage: mechanical_system_from_dict({'kind': 'mechanical', 'coordinates': ['x'],
        ....:     'bodies': [{'name': 'b', 'joint': ['x', 0, 0], 'mass': 1}]})
        Mechanical system: 1 body, coordinates (x)
    """
    return MechanicalSystem.from_dict(data, source)


def mechanical_system_to_dict(system):
    r"""
    The description mapping of ``system`` (inverse of
    :func:`mechanical_system_from_dict`): :meth:`MechanicalSystem.to_dict
    <sage_dynsym.mechanics.system.MechanicalSystem.to_dict>`.

    EXAMPLES::

        sage: from sage_dynsym import load
        sage: from sage_dynsym.description import example_path
        sage: from sage_dynsym.mechanics.description import mechanical_system_to_dict
        sage: mechanical_system_to_dict(load(example_path('spherical_pendulum.yaml')))['kind']
        'mechanical'
    """
    return system.to_dict()
