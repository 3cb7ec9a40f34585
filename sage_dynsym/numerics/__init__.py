r"""
Numerics: compiled right-hand sides, simulation, trajectories and code
generation for the equations of motion of every model (see
:mod:`~sage_dynsym.numerics.methods`).

EXAMPLES::

    sage: from sage_dynsym.numerics import NumericalMethods, numerical_rhs, simulate, Trajectory
"""
# Sage's symbolic functions, Maxima and coercions need the whole library initialised
# (the package's face loads it lazily, only when a name is used)
import sage.all
del sage  # imported for its effect alone: no name of this module
from .codegen import generate_code, GeneratedCode
from .energy import quadratic_energy
from .events import Event
from .form import NumericalForm
from .methods import NumericalMethods
from .rhs import numerical_rhs, RightHandSide, StateJacobian
from .simulate import simulate
from .trajectory import Trajectory

__all__ = ['NumericalMethods', 'NumericalForm', 'numerical_rhs', 'RightHandSide', 'StateJacobian',
           'simulate',
           'Trajectory', 'generate_code', 'GeneratedCode', 'quadratic_energy', 'Event']
