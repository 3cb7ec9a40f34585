r"""
Lie--Poisson systems and description mappings, by their earlier names

A Lie--Poisson system reads and writes its description format itself:
:meth:`LiePoissonSystem.from_dict
<sage_dynsym.lie.system.LiePoissonSystem.from_dict>` (the format is in
:mod:`sage_dynsym.lie.format`) and :meth:`LiePoissonSystem.to_dict
<sage_dynsym.lie.system.LiePoissonSystem.to_dict>`; its report is in
:mod:`sage_dynsym.lie.report`. The names here are those they had before.

EXAMPLES::

    sage: from sage_dynsym.lie.description import lie_poisson_from_dict, lie_poisson_to_dict
    sage: S = lie_poisson_from_dict({'kind': 'lie_poisson', 'algebra': 'so3',
    ....:                            'hamiltonian': 'M1^2 + M3^2'})
    sage: lie_poisson_to_dict(S)['hamiltonian']
    'M1^2 + M3^2'
"""
from .format import LIE_POISSON_KEYS, MAX_VARIABLES, MAX_PARAMETERS
from .report import LIE_SECTIONS, lie_report, lie_estimates
from .system import LiePoissonSystem

__all__ = ['lie_poisson_from_dict', 'lie_poisson_to_dict', 'LIE_POISSON_KEYS', 'MAX_VARIABLES',
           'MAX_PARAMETERS', 'LIE_SECTIONS', 'lie_report', 'lie_estimates']


def lie_poisson_from_dict(data, source=None):
    r"""
    The Lie--Poisson system of a description mapping:
    :meth:`LiePoissonSystem.from_dict
    <sage_dynsym.lie.system.LiePoissonSystem.from_dict>` (the format:
    :func:`~sage_dynsym.lie.format.read_lie_poisson_system`).

    EXAMPLES::

        sage: from sage_dynsym.lie.description import lie_poisson_from_dict
        sage: lie_poisson_from_dict({'kind': 'lie_poisson', 'algebra': 'so3',
        ....:                        'hamiltonian': 'M3^2/2'}).equations()
        [M2*M3, -M1*M3, 0]
    """
    return LiePoissonSystem.from_dict(data, source)


def lie_poisson_to_dict(system):
    r"""
    The description mapping of a Lie--Poisson system (inverse of
    :func:`lie_poisson_from_dict`): :meth:`LiePoissonSystem.to_dict
    <sage_dynsym.lie.system.LiePoissonSystem.to_dict>`.

    EXAMPLES::

        sage: from sage_dynsym.lie.description import lie_poisson_to_dict
        sage: from sage_dynsym.lie.system import LiePoissonSystem
        sage: M1, A, x, y = var('M1 A x y')
        sage: d = lie_poisson_to_dict(LiePoissonSystem('so3', M1^2/A, positive=[A], name='top'))
        sage: d['algebra'], d['positive']
        ('so3', ['A'])
        sage: lie_poisson_to_dict(LiePoissonSystem([[0, x], [-x, 0]], y, variables=[x, y]))['algebra']
        {'poisson_matrix': [['0', 'x'], ['-x', '0']]}
    """
    return system.to_dict()
