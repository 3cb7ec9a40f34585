r"""
Electrical circuits: graph, Lagrangians (loop and node methods), Brayton--Moser
mixed potential and state equations, description files.
"""
from .circuit import Circuit
from .elements import Branch, Coupling
from .mixed_potential import MixedPotential
from .linear import LoopAnalysis, NodeAnalysis
from .description import circuit_from_dict, circuit_to_dict
