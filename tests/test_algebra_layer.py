r"""
The exact algebra moved from ``sage_dynsym.analysis`` (and ``lie._polynomials``)
to ``sage_dynsym.algebra``: every earlier module path still imports, as the
same module object, with the names it had; the renamed method keeps its old
name.
"""
import importlib

import pytest

import sage.all  # noqa: F401
import sage_dynsym

#: (old module, new module) of the exact algebra, as they were released.
MOVED = [
    ("analysis._polynomials", "algebra.polynomials"),
    ("analysis.conditions", "algebra.conditions"),
    ("analysis.decomposition", "algebra.decomposition"),
    ("analysis.determinants", "algebra.determinants"),
    ("analysis.quantifier_elimination", "algebra.quantifier_elimination"),
    ("analysis.regions", "algebra.regions"),
    ("analysis.size", "algebra.size"),
    ("analysis.solving", "algebra.solving"),
    ("analysis.translation", "algebra.translation"),
    ("analysis.trig_linear", "algebra.trig_linear"),
    ("analysis.trigonometric", "algebra.trigonometric"),
    ("lie._polynomials", "algebra.polynomial_spaces"),
    ("trig", "algebra.trigonometric"),
]

#: Names imported from the earlier paths (by the documentation, worksheets
#: and the package's own earlier modules).
OLD_IMPORTS = [
    ("analysis.conditions", ["positive_conditions", "positive_conditions_all",
                             "nonzero_conditions", "simplify_conjunction", "conjunction",
                             "holds", "region_holds", "as_relational"]),
    ("analysis.solving", ["solve_exactly", "normalize", "solve_transcendental",
                          "SolutionSet", "AlgebraicSolution", "SolutionList"]),
    ("analysis.quantifier_elimination", ["exists", "exists_real_solution"]),
    ("analysis.regions", ["simplify_region", "intersection", "negation", "partition",
                          "prune_empty"]),
    ("analysis.translation", ["Translation", "NotAlgebraic", "exact_rational",
                              "expand_angles"]),
    ("analysis.trigonometric", ["TrigPolynomialRing", "trig_rational_simplify",
                                "NotPolynomial", "SymbolicBackend", "symbolic_trig"]),
    ("analysis.trig_linear", ["TrigFractionField", "exact_numbers"]),
    ("analysis.determinants", ["fraction_free_det"]),
    ("analysis.decomposition", ["minimal_primes", "separating_form", "shape",
                                "triangular_sets", "ShapePrime"]),
    ("analysis.size", ["polynomial_terms", "TERMS_CAP", "determinant_terms"]),
    ("analysis._polynomials", ["parameter_ring", "to_ring", "to_sr", "polynomial_to_sr",
                               "positive_polynomial", "maxima_without_questions"]),
    ("analysis.hurwitz", ["simplify_conditions", "FACTOR_LIMIT", "hurwitz_conditions",
                          "lienard_chipart_conditions"]),
    ("lie._polynomials", ["PolynomialContext", "LinearProblem", "Reducer", "MAX_MINORS",
                          "primitive", "products", "rank_modulo", "generic_point"]),
]


@pytest.mark.parametrize("old, new", MOVED)
def test_an_earlier_path_is_the_same_module(old, new):
    module = importlib.import_module(f"sage_dynsym.{old}")
    assert module is importlib.import_module(f"sage_dynsym.{new}")
    package, _, child = f"sage_dynsym.{old}".rpartition(".")
    assert getattr(importlib.import_module(package), child) is module


@pytest.mark.parametrize("old, names", OLD_IMPORTS)
def test_the_earlier_names_import(old, names):
    module = importlib.import_module(f"sage_dynsym.{old}")
    missing = [n for n in names if not hasattr(module, n)]
    assert not missing


def test_the_moved_table_is_the_one_of_the_package():
    # every move listed here is served by the package, and no other move of
    # the exact algebra is
    served = {(k, v) for k, v in sage_dynsym._MOVED.items() if v.startswith("algebra.")}
    assert served == set(MOVED)


def test_the_lyapunov_function_keeps_its_one_letter_name():
    from sage.all import var
    from sage_dynsym import stationary_solutions
    x, y = var("x y")
    sols = stationary_solutions([x**2 + y**2], [x, y])
    assert sols.lyapunov_function() is sols.K()
    assert str(sols.lyapunov_function()) == str(x**2 + y**2)
