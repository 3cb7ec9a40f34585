"""Only the elements package names the kinds of circuit elements.

Nor does any module outside ``circuits/elements/kinds.py`` (where the
classes are defined) switch on an element's class with ``isinstance``:
what differs per kind is a method or attribute of the element class.

The analyses (loop and node Lagrangians, mixed potential, modified nodal
analysis), the circuit class and every other module ask the element
objects of ``sage_dynsym.circuits.elements`` what they contribute; none
compares an element's kind with a string. Checked on the code (``ast``
string constants outside docstrings, so the examples of the documentation,
which write branch entries, are not counted) of every module of the
package outside ``circuits/elements/``; the kind names themselves are read
from the package, so a new kind is covered as soon as it exists.
"""
import ast
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parent.parent / "sage_dynsym"
ELEMENTS = PACKAGE / "circuits" / "elements"

#: Modules that write description mappings, where an element kind is a word
#: of the file format (``{'kind': 'mutual', ...}``), not a test of an object:
#: the system builder's text syntax ``mutual L1 L2 = M`` becomes that entry.
FORMAT_WRITERS = {"interact/builder.py"}


def kind_names():
    from sage_dynsym.circuits.elements import ELEMENTS as classes, Coupling
    return {cls.kind_name for cls in classes.values()} | {Coupling.kind_name}


def docstrings(tree):
    found = set()
    for node in ast.walk(tree):
        if isinstance(node, (ast.Module, ast.ClassDef, ast.FunctionDef,
                             ast.AsyncFunctionDef)) and node.body:
            first = node.body[0]
            if isinstance(first, ast.Expr) and isinstance(first.value, ast.Constant):
                found.add(id(first.value))
    return found


def kind_strings(path, names):
    tree = ast.parse(path.read_text(encoding="utf-8"))
    skip = docstrings(tree)
    return [(node.lineno, node.value) for node in ast.walk(tree)
            if isinstance(node, ast.Constant) and isinstance(node.value, str)
            and node.value in names and id(node) not in skip]


def test_the_kinds_are_known():
    assert {"resistor", "inductor", "capacitor", "voltage_source", "current_source",
            "nonlinear_resistor", "mutual"} <= kind_names()


@pytest.mark.parametrize("source, found", [
    ("if b.kind == 'capacitor':\n    pass\n", [(1, "capacitor")]),
    ("def f():\n    '''kind: 'capacitor' in a docstring'''\n    return 'mutual'\n",
     [(3, "mutual")]),
])
def test_the_check_itself(tmp_path, source, found):
    # the checker's verdict on made-up code (so a vacuous checker fails)
    path = tmp_path / "module.py"
    path.write_text(source, encoding="utf-8")
    assert kind_strings(path, kind_names()) == found


def test_no_kind_strings_outside_the_elements_package():
    names = kind_names()
    offenders = []
    for path in sorted(PACKAGE.rglob("*.py")):
        relative = path.relative_to(PACKAGE).as_posix()
        if ELEMENTS in path.parents or relative in FORMAT_WRITERS:
            continue
        offenders += [f"{relative}:{line}: {value!r}"
                      for line, value in kind_strings(path, names)]
    assert not offenders, ("element kinds named outside circuits/elements/ (ask the "
                           "element object instead):\n" + "\n".join(offenders))


def element_class_names():
    from sage_dynsym.circuits.elements import ELEMENTS as classes, Branch
    return {cls.__name__ for cls in classes.values()} | {Branch.__name__}


def isinstance_switches(source, names):
    r"""``(line, class name)`` of the calls ``isinstance(x, C)`` (or with a
    tuple of classes) in the code ``source`` with ``C`` one of ``names``."""
    def named(node):
        if isinstance(node, ast.Tuple):
            return [n for e in node.elts for n in named(e)]
        name = node.id if isinstance(node, ast.Name) else getattr(node, "attr", None)
        return [name] if name in names else []
    return [(node.lineno, name) for node in ast.walk(ast.parse(source))
            if isinstance(node, ast.Call) and isinstance(node.func, ast.Name)
            and node.func.id == "isinstance" and len(node.args) == 2
            for name in named(node.args[1])]


@pytest.mark.parametrize("source, found", [
    ("if isinstance(b, Inductor):\n    pass\n", [(1, "Inductor")]),
    ("x = isinstance(b, (kinds.Capacitor, int))\n", [(1, "Capacitor")]),
    ("x = isinstance(b, Circuit) and b.is_inductive()\n", []),
])
def test_the_isinstance_check_itself(source, found):
    assert isinstance_switches(source, element_class_names()) == found


def test_no_isinstance_switch_on_element_classes():
    names = element_class_names()
    assert {"Inductor", "Capacitor", "Resistor", "Branch"} <= names
    offenders = [f"{path.relative_to(PACKAGE).as_posix()}:{line}: {name}"
                 for path in sorted(PACKAGE.rglob("*.py"))
                 if path != ELEMENTS / "kinds.py"
                 for line, name in isinstance_switches(path.read_text(encoding="utf-8"),
                                                       names)]
    assert not offenders, ("isinstance switches on circuit element classes (ask the "
                           "element object instead):\n" + "\n".join(offenders))
