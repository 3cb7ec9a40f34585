r"""
Systems on Lie algebras

Lie--Poisson systems `\dot x = J(x)\nabla H` on the duals of Lie algebras
(named ones: `so(3)`, `e(3)`, `so(4)`, `so(3,1)`, `e(4)`, or given by a
Poisson matrix or structure constants): their equations, Casimirs, the
search for polynomial first integrals by undetermined coefficients (with
the parameter values where more integrals exist), stationary motions by
the Routh--Lyapunov method, and the Euler--Poisson and Kirchhoff systems of
rigid bodies.
"""
# Sage's symbolic functions, Maxima and coercions need the whole library initialised
# (the package's face loads it lazily, only when a name is used)
import sage.all
del sage  # imported for its effect alone: no name of this module
from .algebras import PoissonStructure, lie_algebra, poisson_structure
from .integrals import IntegralJump, casimirs, polynomial_integrals
from .system import LiePoissonSystem
from .builders import euler_poisson, kirchhoff
from .description import lie_poisson_from_dict, lie_poisson_to_dict, lie_report, LIE_SECTIONS

__all__ = ['PoissonStructure', 'lie_algebra', 'poisson_structure', 'IntegralJump', 'casimirs',
           'polynomial_integrals', 'LiePoissonSystem', 'euler_poisson', 'kirchhoff',
           'lie_poisson_from_dict', 'lie_poisson_to_dict', 'lie_report', 'LIE_SECTIONS']
