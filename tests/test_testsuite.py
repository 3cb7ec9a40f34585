"""Every result class runs Sage's ``TestSuite`` in its doctests, and checks
invariants of its own there.

``TestSuite(x).run()`` runs every ``_test_*`` method of ``x``: Sage's
(pickling, category) and the package's (a verdict's cases partition its
space, a map's counts add up, a model's description reads back...). The
rule: the docstring of each class below, or of one of its own methods, runs
``TestSuite``; a skipped test is explained in the text beside it; and some
class of the package in its method resolution order defines a ``_test_*``
method (an invariant of its own, not only Sage's).
"""
import importlib
import inspect
import re

import pytest

#: the classes of results (what the package returns and users keep)
RESULT_CLASSES = [
    "sage_dynsym.mechanics.system.MechanicalSystem",
    "sage_dynsym.dynamics.lagrangian.Lagrangian",
    "sage_dynsym.dynamics.lagrangian.RouthFunction",
    "sage_dynsym.dynamics.nonholonomic.NonholonomicLagrangian",
    "sage_dynsym.dynamics.compact.CompactEquations",
    "sage_dynsym.dynamics.reduced.ReducedEquations",
    "sage_dynsym.dynamics.hamiltonian.Hamiltonian",
    "sage_dynsym.circuits.circuit.Circuit",
    "sage_dynsym.lie.system.LiePoissonSystem",
    "sage_dynsym.lie.algebras.PoissonStructure",
    "sage_dynsym.analysis.linear.LinearSystem",
    "sage_dynsym.analysis.verdict.StabilityVerdict",
    "sage_dynsym.scale.maps.StabilityMap",
    "sage_dynsym.scale.sweeps.Sweep",
    "sage_dynsym.analysis.stationary.StationarySolutions",
    "sage_dynsym.analysis.census.Census",
    "sage_dynsym.analysis.normal_forms.BirkhoffNormalForm",
    "sage_dynsym.numerics.trajectory.Trajectory",
]

_RUN = re.compile(r"sage: .*TestSuite\((.*)\)\.run\((.*)\)")


def _class(name):
    module, _, attr = name.rpartition(".")
    return getattr(importlib.import_module(module), attr)


def _docstrings(klass):
    yield inspect.getdoc(klass) or ""
    for member in vars(klass).values():
        doc = inspect.getdoc(member) if inspect.isfunction(member) else None
        if doc:
            yield doc


def suite_problems(docs):
    r"""What is wrong with the ``TestSuite`` runs of the docstrings
    ``docs``: none, or a skip without a word about it in the text."""
    runs = [(doc, m) for doc in docs for m in _RUN.finditer(doc)]
    if not runs:
        return ["no TestSuite(...).run() in its doctests"]
    found = []
    for doc, m in runs:
        for skipped in re.findall(r"_test_(\w+)", m.group(2)):
            prose = " ".join(line for line in doc.splitlines()
                             if not line.strip().startswith(("sage:", "....:")))
            if skipped not in prose:
                found.append(f"TestSuite({m.group(1)}) skips _test_{skipped} and the text "
                             "does not say why")
    return found


@pytest.mark.parametrize("name", RESULT_CLASSES)
def test_result_classes_run_testsuite(name):
    problems = suite_problems(list(_docstrings(_class(name))))
    assert not problems, f"{name}: " + "; ".join(problems)


@pytest.mark.parametrize("name", RESULT_CLASSES)
def test_result_classes_check_invariants_of_their_own(name):
    own = [f"{k.__name__}.{attr}" for k in _class(name).__mro__
           if k.__module__.startswith("sage_dynsym")
           for attr in vars(k) if attr.startswith("_test_")]
    assert own, f"{name}: no _test_* method of the package in its method resolution order"


@pytest.mark.parametrize("docs, count", [
    (["EXAMPLES::\n\n    sage: 1 + 1\n    2"], 1),
    (["sage: TestSuite(x).run()"], 0),
    (["sage: TestSuite(x).run(skip='_test_pickling')"], 1),
    (["No value equality, so no pickling test::\n\n"
      "    sage: TestSuite(x).run(skip='_test_pickling')"], 0),
])
def test_the_rule_itself(docs, count):
    assert len(suite_problems(docs)) == count
