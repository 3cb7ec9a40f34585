r"""
Exact algebra

The exact toolkit under the qualitative analysis (and under the
kinematics and the characteristic functions): symbolic expressions
translated into polynomial rings and back, the exact solution of
polynomial and trigonometric systems (irreducible components, real
branches, the conditions under which they exist), conditions and regions
of parameter space as Sage relationals, quantifier elimination, arithmetic
in sines and cosines, fraction-free determinants, and linear algebra on
spaces of polynomials over the field of the parameters.

The modules: :mod:`~sage_dynsym.algebra.polynomials` (conversions),
:mod:`~sage_dynsym.algebra.expression_walk` (the one walk over symbolic
expressions under every translation into polynomials),
:mod:`~sage_dynsym.algebra.translation`,
:mod:`~sage_dynsym.algebra.decomposition`,
:mod:`~sage_dynsym.algebra.solving`, :mod:`~sage_dynsym.algebra.radicals`,
:mod:`~sage_dynsym.algebra.number_fields`,
:mod:`~sage_dynsym.algebra.conditions`,
:mod:`~sage_dynsym.algebra.regions`,
:mod:`~sage_dynsym.algebra.quantifier_elimination`,
:mod:`~sage_dynsym.algebra.trigonometric`,
:mod:`~sage_dynsym.algebra.trig_algebra` (the Sage parents of trigonometric
polynomials and fractions),
:mod:`~sage_dynsym.algebra.trig_linear`,
:mod:`~sage_dynsym.algebra.determinants`, :mod:`~sage_dynsym.algebra.size`
and :mod:`~sage_dynsym.algebra.polynomial_spaces`.
"""
# Sage's symbolic functions, Maxima and coercions need the whole library initialised
# (the package's face loads it lazily, only when a name is used)
import sage.all
del sage  # imported for its effect alone: no name of this module
from .conditions import (positive_conditions, positive_conditions_all, nonzero_conditions,
                         simplify_conditions, simplify_conjunction, conjunction, as_relational)
from .determinants import fraction_free_det
from .quantifier_elimination import exists
from .regions import simplify_region, intersection, negation, partition, drop_redundant
from .number_fields import AlgebraicConstants
from .radicals import roots_in_radicals, real_algebraic_roots
from .size import polynomial_terms, determinant_terms, matrix_terms
from .solving import solve_exactly, normalize
from .translation import Translation, NotAlgebraic, ParameterAtoms
from .trig_algebra import TrigAlgebra, TrigFractions
from .trig_linear import TrigFractionField
from .trigonometric import TrigPolynomialRing, trig_rational_simplify

__all__ = ['positive_conditions', 'positive_conditions_all', 'nonzero_conditions',
           'simplify_conditions', 'simplify_conjunction', 'conjunction', 'as_relational',
           'fraction_free_det', 'exists', 'simplify_region', 'intersection', 'negation',
           'partition', 'polynomial_terms', 'determinant_terms', 'matrix_terms',
           'solve_exactly', 'normalize', 'Translation', 'NotAlgebraic', 'TrigFractionField',
           'TrigPolynomialRing', 'trig_rational_simplify', 'drop_redundant',
           'AlgebraicConstants', 'roots_in_radicals', 'real_algebraic_roots',
           'ParameterAtoms', 'TrigAlgebra', 'TrigFractions']
