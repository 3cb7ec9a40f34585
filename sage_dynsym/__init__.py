r"""
sage_dynsym: symbolic modelling and qualitative analysis of dynamic systems.

This module only re-exports the public API. The package is layered, each
layer importing only the ones below it:

- :mod:`~sage_dynsym.errors`, :mod:`~sage_dynsym.symbols` -- exceptions,
  the package's symbols and reserved names;
- :mod:`sage_dynsym.io` -- the safe expression parser and the reading and
  writing of files;
- :mod:`sage_dynsym.analysis` -- exact algebra and qualitative analysis;
- :mod:`sage_dynsym.dynamics` -- characteristic functions and equations
  (Lagrangian, Routh function, Hamiltonian, Dirac's scheme) and the common
  interface of models;
- :mod:`sage_dynsym.lie` -- systems on Lie algebras;
- :mod:`sage_dynsym.mechanics`, :mod:`sage_dynsym.circuits` -- the models;
- :mod:`~sage_dynsym.description` -- description files (``load``,
  ``save``); :mod:`sage_dynsym.scale` -- numerics at scale;
- :mod:`~sage_dynsym.report`, :mod:`sage_dynsym.interact` -- reports and
  interactive pages; ``__main__`` -- the command line.

The modules of earlier versions (``sage_dynsym.dynamics.lagrangian``,
``sage_dynsym.mechanics.system``, ...) remain importable under their old
names.
"""
import importlib
import sys

# Symbolic functions, Maxima and the coercion model need the full Sage
# library initialised, also when the package is used from plain Python.
import sage.all  # noqa: F401

from .errors import (DynSymError, ModelError, DescriptionError, ExpressionError,
                     CircuitError, AnalysisError, BudgetError)
from .dynamics.lagrangian import Lagrangian, RouthFunction
from .dynamics.hamiltonian import Hamiltonian
from .dynamics.dirac import DiracConstraints
from .dynamics.compact import equations_cse, CompactEquations
from .dynamics.nonholonomic import NonholonomicLagrangian
from .dynamics.reduced import ReducedEquations
from .mechanics.rigid_body import RigidBody
from .mechanics.force_functions import UniformGravity, NewtonianField
from .mechanics.loads import Load
from .mechanics.rolling import RollingDisk
from .mechanics.system import MechanicalSystem
from .description import load, save
from .circuits import Circuit, NodalAnalysis
from .analysis import (stationary_solutions, stationary_motions, ModifiedRouthLyapunov,
                       linearize, LinearSystem, hurwitz_matrix, hurwitz_determinants,
                       hurwitz_conditions, lienard_chipart_conditions,
                       real_negative_roots_conditions, conservative_stability_conditions,
                       sylvester_conditions, definiteness_conditions, restrict_to_subspace,
                       simultaneous_reduction, kelvin_chetaev, StabilityVerdict,
                       equilibrium_family, StationarySolution, StationarySolutions,
                       solve_exactly, exists, OperatingPoint, steady_motion_conditions,
                       steady_motions)
from .analysis.trigonometric import trig_rational_simplify
from .lie import (LiePoissonSystem, PoissonStructure, lie_algebra, poisson_structure,
                  casimirs, polynomial_integrals, euler_poisson, kirchhoff)
from .numerics import NumericalMethods, Trajectory, numerical_rhs, simulate, generate_code
from .scale import stability_map, StabilityMap, sweep, Sweep

#: Earlier module names and where they live now.
_MOVED = {
    'names': 'symbols',
    'expressions': 'io.expressions',
    'trig': 'analysis.trigonometric',
    'lagrangian': 'dynamics.lagrangian',
    'routh': 'dynamics.lagrangian',
    'natural_equations': 'dynamics.natural_equations',
    'hamiltonian': 'dynamics.hamiltonian',
    'dirac': 'dynamics.dirac',
    'frames': 'mechanics.frames',
    'rigid_body': 'mechanics.rigid_body',
    'force_functions': 'mechanics.force_functions',
    'kinematics': 'mechanics.kinematics',
    'mechanical_system': 'mechanics.system',
}
for _old, _new in _MOVED.items():
    sys.modules[f"{__name__}.{_old}"] = importlib.import_module(f".{_new}", __name__)
del _old, _new
