r"""
sage_dynsym: symbolic modelling and qualitative analysis of dynamic systems.

This module only re-exports the public API; see the submodules.
"""
# Symbolic functions, Maxima and the coercion model need the full Sage
# library initialised, also when the package is used from plain Python.
import sage.all  # noqa: F401

from .errors import (DynSymError, ModelError, DescriptionError, ExpressionError,
                     CircuitError, AnalysisError, BudgetError)
from .lagrangian import Lagrangian
from .rigid_body import RigidBody
from .force_functions import UniformGravity, NewtonianField
from .mechanical_system import MechanicalSystem
from .routh import RouthFunction
from .hamiltonian import Hamiltonian
from .dirac import DiracConstraints
from .description import load, save
from .circuits import Circuit
from .analysis import (stationary_solutions, stationary_motions, ModifiedRouthLyapunov,
                       linearize, LinearSystem, hurwitz_matrix, hurwitz_determinants,
                       hurwitz_conditions, lienard_chipart_conditions,
                       real_negative_roots_conditions, conservative_stability_conditions,
                       sylvester_conditions, definiteness_conditions, restrict_to_subspace,
                       simultaneous_reduction, kelvin_chetaev, StabilityVerdict,
                       equilibrium_family, StationarySolution, StationarySolutions,
                       solve_exactly, exists)
