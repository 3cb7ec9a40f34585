"""The interactive builder and the stability maps ask the kind's class.

What differs per kind of model (its fields on the builder's page, its
equations' first form, its free linear system, its name) comes from the
kind's class through the registry (``kinds()``), never from a switch: no
comparison with a kind's name (``kind == 'circuit'``,
``self.kind.value == 'circuit'``) and no ``isinstance`` against a model
class (a registered kind's class or their base ``Model``) in
``interact/builder.py`` and ``scale/maps.py``. Checked on the code
(``ast``), so docstrings (which write descriptions) are not counted; the
kind names and classes are read from the registry, so a new kind is
covered as soon as it exists.
"""
import ast
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parent.parent / "sage_dynsym"
CHECKED = ["interact/builder.py", "scale/maps.py"]


def registry():
    from sage_dynsym import kinds
    from sage_dynsym.dynamics.model import Model
    return set(kinds()), {cls.__name__ for cls in kinds().values()} | {Model.__name__}


def kind_switches(source, kind_names, class_names):
    r"""``(line, what)`` of the comparisons with a kind's name and the
    ``isinstance`` tests against the classes named ``class_names``."""
    def named(node):
        if isinstance(node, ast.Tuple):
            return [n for e in node.elts for n in named(e)]
        name = node.id if isinstance(node, ast.Name) else getattr(node, "attr", None)
        return [name] if name in class_names else []
    found = []
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.Compare):
            sides = [node.left, *node.comparators]
            found += [(node.lineno, f"compared with {side.value!r}") for side in sides
                      if isinstance(side, ast.Constant) and side.value in kind_names]
        elif (isinstance(node, ast.Call) and isinstance(node.func, ast.Name)
              and node.func.id == "isinstance" and len(node.args) == 2):
            found += [(node.lineno, f"isinstance {name}") for name in named(node.args[1])]
    return found


@pytest.mark.parametrize("source, found", [
    ("if self.kind.value == 'circuit':\n    pass\n", [(1, "compared with 'circuit'")]),
    ("x = 'mechanical' != kind\n", [(1, "compared with 'mechanical'")]),
    ("x = isinstance(system, (list, Model))\n", [(1, "isinstance Model")]),
    ("x = isinstance(system, kinds.Circuit)\n", [(1, "isinstance Circuit")]),
    ("x = isinstance(system, (list, tuple, Lagrangian))\n", []),
    ("data = {'kind': 'circuit'}\n", []),
])
def test_the_check_itself(source, found):
    # the checker's verdict on made-up code (so a vacuous checker fails)
    assert kind_switches(source, {"circuit", "mechanical"}, {"Circuit", "Model"}) == found


def test_the_registry_is_read():
    kind_names, class_names = registry()
    assert {"mechanical", "circuit", "lie_poisson"} <= kind_names
    assert {"MechanicalSystem", "Circuit", "LiePoissonSystem", "Model"} <= class_names


@pytest.mark.parametrize("relative", CHECKED)
def test_no_kind_switch(relative):
    kind_names, class_names = registry()
    source = (PACKAGE / relative).read_text(encoding="utf-8")
    found = [f"{relative}:{line}: {what}"
             for line, what in kind_switches(source, kind_names, class_names)]
    assert not found, ("switches on the kind of a model (ask the kind's class, through "
                       "kinds()):\n" + "\n".join(found))


def test_the_builder_offers_the_registered_kinds_and_their_first_form():
    # the page's kinds are the registry's that it has fields for, and the
    # derivation shown is the model class's first form of equations
    from sage_dynsym import kinds
    from sage_dynsym.interact.builder import SystemBuilder
    B = SystemBuilder()
    assert list(B.kind.options) == [k for k in kinds() if k in ("mechanical", "circuit")]
    B.kind.value = "circuit"
    B.branches.value = "0 1 E1\n1 2 R1\n2 3 L1\n3 0 C1"
    B.derive()
    # Brayton-Moser: P = -R1 i^2/2 + (E1 + u) i, so the mixed potential is shown
    assert "P &amp;=" in B.output.value and "error" not in B.status.value
    B.kind.value = "mechanical"
    B.derive()
    assert "L &amp;=" in B.output.value
    assert B.circuit.layout.display == "none" and B.mechanical.layout.display is None
