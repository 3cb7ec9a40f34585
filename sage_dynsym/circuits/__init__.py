r"""
Electrical circuits: graph, Lagrangians (loop and node methods), Brayton--Moser
mixed potential, state equations of any solvable circuit (modified nodal
analysis), description files.
"""
# Sage's symbolic functions, Maxima and coercions need the whole library initialised
# (the package's face loads it lazily, only when a name is used)
import sage.all
del sage  # imported for its effect alone: no name of this module
from .circuit import Circuit
from .elements import Branch, Coupling
from .graph import CircuitGraph
from .mixed_potential import MixedPotential
from .linear import LoopAnalysis, NodeAnalysis
from .nodal import NodalAnalysis
from .description import circuit_from_dict, circuit_to_dict

__all__ = ['Circuit', 'CircuitGraph', 'Branch', 'Coupling', 'MixedPotential', 'LoopAnalysis',
           'NodeAnalysis', 'NodalAnalysis', 'circuit_from_dict', 'circuit_to_dict']
