r"""
Modules moved (the exact algebra from ``sage_dynsym.analysis`` and
``lie._polynomials`` to ``sage_dynsym.algebra``, the top-level modules into
their layers): every earlier module path still imports, warns with a
``DeprecationWarning`` naming the new module, and is the same module object,
with the names it had; the renamed method keeps its old name.
"""
import importlib
import sys

import pytest

import sage.all  # noqa: F401

from deprecated_aliases import DEPRECATED_ALIASES

#: (old module, new module), as they were released.
MOVED = [
    ("names", "symbols"),
    ("expressions", "io.expressions"),
    ("trig", "algebra.trigonometric"),
    ("lagrangian", "dynamics.lagrangian"),
    ("routh", "dynamics.lagrangian"),
    ("natural_equations", "dynamics.natural_equations"),
    ("hamiltonian", "dynamics.hamiltonian"),
    ("dirac", "dynamics.dirac"),
    ("frames", "mechanics.frames"),
    ("rigid_body", "mechanics.rigid_body"),
    ("force_functions", "mechanics.force_functions"),
    ("kinematics", "mechanics.kinematics"),
    ("mechanical_system", "mechanics.system"),
    ("circuits.inductance", "circuits.elements.windings"),
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
]


def import_old(old):
    r"""Import ``sage_dynsym.<old>`` afresh (the warning comes at the first
    import of a process only) and return the module and the warnings."""
    name = f"sage_dynsym.{old}"
    sys.modules.pop(name, None)
    with pytest.warns(DeprecationWarning) as caught:
        __import__(name)        # as the import statement does (no importlib frame)
    return sys.modules[name], caught


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
def test_an_earlier_path_warns_and_is_the_same_module(old, new):
    module, caught = import_old(old)
    assert module is importlib.import_module(f"sage_dynsym.{new}")
    package, _, child = f"sage_dynsym.{old}".rpartition(".")
    assert getattr(importlib.import_module(package), child) is module
    ours = [w for w in caught if w.category is DeprecationWarning
            and str(w.message).startswith(f"sage_dynsym.{old} is deprecated")]
    assert len(ours) == 1 and f"import sage_dynsym.{new} instead" in str(ours[0].message)
    # the warning points at the import, not at the alias or at importlib
    assert ours[0].filename == __file__


@pytest.mark.parametrize("old, names", OLD_IMPORTS)
def test_the_earlier_names_import(old, names):
    if f"sage_dynsym.{old}" in DEPRECATED_ALIASES:
        module, _ = import_old(old)
    else:
        module = importlib.import_module(f"sage_dynsym.{old}")
    missing = [n for n in names if not hasattr(module, n)]
    assert not missing


def test_the_moved_table_is_the_one_of_the_package():
    # every move listed here has its alias module, and there is no other alias
    assert DEPRECATED_ALIASES == {f"sage_dynsym.{old}" for old, _ in MOVED}


def test_the_package_imports_no_earlier_name():
    # the package's own modules import the new names: importing all of them
    # with deprecation warnings as errors, in a fresh process, succeeds; and
    # (no import hook) the finders and path hooks after Sage are the same
    # after importing every module, the earlier names too
    import subprocess
    code = ("import importlib, pkgutil, sys, warnings, sage.all\n"
            "before = (list(sys.meta_path), list(sys.path_hooks))\n"
            "import sage_dynsym\n"
            "aliases = set(%r)\n"
            "names = [info.name for info in pkgutil.walk_packages(sage_dynsym.__path__,"
            " 'sage_dynsym.')]\n"
            "with warnings.catch_warnings():\n"
            "    warnings.filterwarnings('error', category=DeprecationWarning,"
            " module='sage_dynsym')\n"
            "    for name in names:\n"
            "        if name not in aliases:\n"
            "            importlib.import_module(name)\n"
            "warnings.simplefilter('ignore', DeprecationWarning)\n"
            "for name in sorted(aliases):\n"
            "    importlib.import_module(name)\n"
            "assert len(names) > 150, len(names)\n"
            "assert (list(sys.meta_path), list(sys.path_hooks)) == before, 'an import hook'\n"
            ) % sorted(DEPRECATED_ALIASES)
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         timeout=300)
    assert run.returncode == 0, run.stderr[-3000:]


def test_the_lyapunov_function_keeps_its_one_letter_name():
    from sage.all import var
    from sage_dynsym import stationary_solutions
    x, y = var("x y")
    sols = stationary_solutions([x**2 + y**2], [x, y])
    assert sols.lyapunov_function() is sols.K()
    assert str(sols.lyapunov_function()) == str(x**2 + y**2)


# ----------------------------------------------------------------------
# No import hook: the earlier names are plain modules (issue 31), not a
# finder on sys.meta_path that maps names as they are asked for.

_HOOK_WORDS = ("meta_path", "path_hooks", "MetaPathFinder", "PathEntryFinder", "importlib.abc",
               "importlib.machinery", "find_spec", "exec_module")


def test_no_module_of_the_package_installs_an_import_hook():
    from deprecated_aliases import PACKAGE
    found = [f"{path.relative_to(PACKAGE)}: {word}" for path in sorted(PACKAGE.rglob("*.py"))
             for word in _HOOK_WORDS if word in path.read_text(encoding="utf-8")]
    assert not found


@pytest.mark.parametrize("old, new", MOVED)
def test_an_earlier_path_is_a_plain_module(old, new):
    # its docstring, the import of moved_module and one call naming the new module
    from deprecated_aliases import PACKAGE
    import ast
    path = PACKAGE.joinpath(*old.split(".")).with_suffix(".py")
    body = ast.parse(path.read_text(encoding="utf-8")).body
    assert len(body) == 3 and isinstance(body[0].value, ast.Constant)
    assert ast.unparse(body[1]) == "from sage_dynsym.errors import moved_module"
    assert ast.unparse(body[2]) == f"moved_module(__name__, 'sage_dynsym.{new}')"
