r"""
sage_dynsym: symbolic modelling and qualitative analysis of dynamic systems.

This module only re-exports the public API. The package is layered, each
layer importing only the ones below it:

- :mod:`~sage_dynsym.errors`, :mod:`~sage_dynsym.symbols` -- exceptions,
  the package's symbols and reserved names;
- :mod:`sage_dynsym.io` -- the safe expression parser and the reading and
  writing of files;
- :mod:`sage_dynsym.algebra` -- exact algebra (solving, conditions,
  quantifier elimination, trigonometric polynomials);
- :mod:`sage_dynsym.analysis` -- qualitative analysis;
- :mod:`sage_dynsym.dynamics` -- characteristic functions and equations
  (Lagrangian, Routh function, Hamiltonian, Dirac's scheme) and the common
  interface of models;
- :mod:`sage_dynsym.lie` -- systems on Lie algebras;
- :mod:`sage_dynsym.mechanics`, :mod:`sage_dynsym.circuits` -- the models;
- :mod:`~sage_dynsym.description` -- description files (``load``,
  ``save``); :mod:`sage_dynsym.scale` -- numerics at scale;
- :mod:`~sage_dynsym.report`, :mod:`sage_dynsym.interact` -- reports and
  interactive pages; ``__main__`` -- the command line.

The modules of earlier versions (``sage_dynsym.lagrangian``,
``sage_dynsym.mechanical_system``, ``sage_dynsym.analysis.solving``, ...)
remain importable under their old names, as deprecated aliases: each
warns (``DeprecationWarning``) and gives the module at its new place.
"""
from .errors import lazy_face

#: The public names and the module each comes from. They are imported on
#: first use (PEP 562), so that ``import sage_dynsym`` and the command
#: line's ``--help`` do not load Sage; the first name used loads it.
_PUBLIC = {
    '.errors': ['DynSymError', 'ModelError', 'DescriptionError', 'ExpressionError',
                'CircuitError', 'AnalysisError', 'BudgetError'],
    '.dynamics.lagrangian': ['Lagrangian', 'RouthFunction'],
    '.dynamics.hamiltonian': ['Hamiltonian'],
    '.dynamics.dirac': ['DiracConstraints'],
    '.dynamics.compact': ['equations_cse', 'CompactEquations'],
    '.dynamics.nonholonomic': ['NonholonomicLagrangian'],
    '.dynamics.reduced': ['ReducedEquations'],
    '.dynamics.nonlinear_stability': ['birkhoff_normal_form', 'nonlinear_stability',
                                      'BirkhoffNormalForm', 'exceptional_values'],
    '.mechanics.rigid_body': ['RigidBody'],
    '.mechanics.force_functions': ['UniformGravity', 'NewtonianField'],
    '.mechanics.loads': ['Load'],
    '.mechanics.rolling': ['RollingDisk'],
    '.mechanics.system': ['MechanicalSystem'],
    '.mechanics.charts': ['euler_angles', 'model_chart'],
    '.description': ['load', 'save', 'kinds', 'register_kind'],
    '.circuits': ['Circuit', 'NodalAnalysis'],
    '.analysis': ['stationary_solutions', 'stationary_motions', 'ModifiedRouthLyapunov',
                  'linearize', 'LinearSystem', 'hurwitz_matrix', 'hurwitz_determinants',
                  'hurwitz_conditions', 'lienard_chipart_conditions',
                  'real_negative_roots_conditions', 'conservative_stability_conditions',
                  'sylvester_conditions', 'definiteness_conditions', 'restrict_to_subspace',
                  'simultaneous_reduction', 'kelvin_chetaev', 'StabilityVerdict',
                  'equilibrium_family', 'StationarySolution', 'StationarySolutions',
                  'solve_exactly', 'exists', 'small_damping_limit', 'spectrum_regions',
                  'OperatingPoint', 'steady_motion_conditions', 'steady_motions',
                  'SteadyMotionSolution', 'SteadyMotions', 'MotionSolution',
                  'equilibrium_census', 'Census', 'configuration_points',
                  'ConfigurationChart'],
    '.algebra.trigonometric': ['trig_rational_simplify'],
    '.lie': ['LiePoissonSystem', 'PoissonStructure', 'lie_algebra', 'poisson_structure',
             'casimirs', 'polynomial_integrals', 'euler_poisson', 'kirchhoff'],
    '.numerics': ['NumericalMethods', 'Trajectory', 'numerical_rhs', 'simulate',
                  'generate_code', 'Event'],
    '.scale': ['stability_map', 'StabilityMap', 'sweep', 'Sweep', 'stability_class'],
}
_SOURCE = {name: module for module, names in _PUBLIC.items() for name in names}

#: The public names of the package (its subpackages are public too).
__all__ = [name for names in _PUBLIC.values() for name in names]

__getattr__, __dir__ = lazy_face(__name__, _SOURCE, load_sage=True)
del lazy_face
