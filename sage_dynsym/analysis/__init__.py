r"""
Qualitative analysis of dynamic systems

The qualitative analysis of :doc:`the method </method>`: stationary
solutions and invariant manifolds (Routh--Lyapunov, also the modified
method with an extended function), their stability by the second
variation and quadratic-form criteria, first approximation
(linearization, force structure, characteristic polynomial,
Routh--Hurwitz and Liénard--Chipart conditions, Kelvin--Chetaev theorems,
roots on the imaginary axis, flutter and divergence, the limit of small
damping; the one stability service LinearSystem.stability), linearization about steady motions with velocity constraints,
and families of equilibria by elimination.
"""
# Sage's symbolic functions, Maxima and coercions need the whole library initialised
# (the package's face loads it lazily, only when a name is used)
import sage.all
del sage  # imported for its effect alone: no name of this module
from .elimination import equilibrium_family, EquilibriumFamily
from .hurwitz import (hurwitz_matrix, hurwitz_determinants, hurwitz_conditions,
                      lienard_chipart_conditions, real_negative_roots_conditions,
                      conservative_stability_conditions)
from .linear import LinearSystem, linearize
from .operating_point import OperatingPoint
from .steady import steady_linearization, steady_motion_conditions, SteadyMotion
from .steady_solutions import steady_motions, SteadyMotionSolution, SteadyMotions
from .motion_solution import MotionSolution
from .quadratic_forms import (sylvester_conditions, definiteness_conditions, form_matrix,
                              restrict_to_subspace, simultaneous_reduction)
# the exact algebra's entry points, also served here
from ..algebra.conditions import simplify_conditions
from ..algebra.solving import solve_exactly, normalize
from ..algebra.quantifier_elimination import exists
from .kelvin_chetaev import kelvin_chetaev, StabilityVerdict
from .damping_limit import small_damping_limit, DampingLimit
from .spectrum import spectrum_regions
from .stability import linear_stability, energy_stability
from .charts import ConfigurationChart, configuration_points
from .census import equilibrium_census, Census, CensusCell, register_census
from .stationary import (stationary_solutions, stationary_motions, check_integral,
                         StationarySolution, StationarySolutions, StationaryProblem,
                         solve_stationary, ModifiedRouthLyapunov)

__all__ = ['equilibrium_family', 'EquilibriumFamily', 'hurwitz_matrix', 'hurwitz_determinants',
           'hurwitz_conditions', 'lienard_chipart_conditions', 'real_negative_roots_conditions',
           'conservative_stability_conditions', 'LinearSystem', 'linearize', 'OperatingPoint',
           'steady_linearization', 'steady_motion_conditions', 'SteadyMotion', 'steady_motions',
           'SteadyMotionSolution', 'SteadyMotions', 'MotionSolution', 'sylvester_conditions',
           'definiteness_conditions', 'form_matrix', 'restrict_to_subspace',
           'simultaneous_reduction', 'simplify_conditions', 'solve_exactly', 'normalize', 'exists',
           'kelvin_chetaev', 'StabilityVerdict', 'small_damping_limit', 'DampingLimit',
           'spectrum_regions', 'linear_stability', 'energy_stability', 'ConfigurationChart',
           'configuration_points', 'equilibrium_census', 'Census', 'CensusCell', 'register_census',
           'stationary_solutions', 'stationary_motions', 'check_integral', 'StationarySolution',
           'StationarySolutions', 'StationaryProblem', 'solve_stationary', 'ModifiedRouthLyapunov']
