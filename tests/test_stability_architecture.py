"""One stability service: no module outside sage_dynsym/analysis decides
stability itself. Read from the source (AST): outside the analysis, no
import of the symbolic criteria (Routh-Hurwitz, Lienard-Chipart, the
spectrum regions, Kelvin-Chetaev, the first approximation), no
construction of a StabilityVerdict, no exact eigenvalues; numerical
eigenvalues only in the map's kernel (scale/kernel.py: the numerical map
that the exact classes are checked against) and the interactive study's
roots (interact/stability.py: numbers shown for given values)."""
import ast
import pathlib

import pytest

PACKAGE = pathlib.Path(__file__).resolve().parent.parent / "sage_dynsym"

#: the deciders of the analysis
DECIDERS = {'lienard_chipart_conditions', 'hurwitz_conditions', 'hurwitz_determinants',
            'hurwitz_matrix', 'real_negative_roots_conditions', 'spectrum_regions',
            'SpectrumRegions', 'kelvin_chetaev', 'first_approximation', 'linear_stability',
            'verdict_from_parts', 'conservative_stability_conditions', 'small_damping_limit'}
#: modules of the analysis that only hold deciders
DECIDER_MODULES = {'hurwitz', 'spectrum', 'kelvin_chetaev', 'verdict', 'damping_limit'}
#: names such a module may give outside: a size estimate, not a decision
#: (the budget of the Routh scheme), the verdict class for type checks,
#: the energy theorem asked first by the circuit report to skip the budget
ALLOWED = {'routh_scheme_fits', 'StabilityVerdict', 'energy_stability'}
NUMERIC_EIGENVALUES = {'scale/kernel.py', 'interact/stability.py'}


def modules_outside_analysis():
    for path in sorted(PACKAGE.rglob("*.py")):
        relative = path.relative_to(PACKAGE).as_posix()
        if relative.startswith("analysis/") or relative == "__init__.py":
            continue            # the analysis itself; the package's re-exports
        yield relative, ast.parse(path.read_text(encoding="utf-8"))


def offences(relative, tree):
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom):
            module = (node.module or '').split('.')
            for alias in node.names:
                if alias.name in ALLOWED:
                    continue
                if alias.name in DECIDERS or (module[-1] in DECIDER_MODULES):
                    found.append(f"imports {alias.name} from {node.module}")
        elif isinstance(node, ast.Call):
            name = node.func.attr if isinstance(node.func, ast.Attribute) else \
                getattr(node.func, 'id', None)
            if name == 'StabilityVerdict':
                found.append("constructs a StabilityVerdict")
            if name in DECIDERS:
                found.append(f"calls {name}")
            if name in ('eigenvalues', 'eigenvectors_right'):
                found.append(f"computes exact eigenvalues ({name})")
            if name == 'eigvals' and relative not in NUMERIC_EIGENVALUES:
                found.append("computes numerical eigenvalues")
    return found


def test_no_module_outside_the_analysis_decides_stability():
    wrong = {relative: offences(relative, tree) for relative, tree in modules_outside_analysis()}
    wrong = {k: v for k, v in wrong.items() if v}
    assert not wrong, "\n".join(f"{k}: {', '.join(v)}" for k, v in wrong.items())


@pytest.mark.parametrize("source, expected", [
    ("from ..analysis import lienard_chipart_conditions", "imports lienard_chipart_conditions"),
    ("from ..analysis.spectrum import _coefficients", "imports _coefficients"),
    ("v = StabilityVerdict('stable', 'why')", "constructs a StabilityVerdict"),
    ("A.eigenvalues()", "computes exact eigenvalues"),
    ("np.linalg.eigvals(A)", "computes numerical eigenvalues"),
])
def test_the_check_finds_each_kind(source, expected):
    # the check itself can fail: each kind of offence, in a module of the report
    assert any(o.startswith(expected) for o in offences('report/x.py', ast.parse(source)))
