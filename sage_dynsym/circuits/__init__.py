r"""
Electrical circuits: graph, Lagrangians (loop and node methods), Brayton--Moser
mixed potential, state equations of any solvable circuit (modified nodal
analysis), description files.
"""
from .circuit import Circuit
from .elements import Branch, Coupling
from .mixed_potential import MixedPotential
from .linear import LoopAnalysis, NodeAnalysis
from .nodal import NodalAnalysis
from .description import circuit_from_dict, circuit_to_dict
