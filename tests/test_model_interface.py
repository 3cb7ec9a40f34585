"""
The model interface: consumers know models only through it.

* A kind defined in another package (tests/toy_kind/toy_oscillator.py,
  registered by an entry point of a temporary distribution) goes through
  load, the report, the command line, the equation forms, a stability map
  and save; the stability map is checked against the roots of
  m s^2 + c s + k computed by NumPy.
* The consumers (description, report, scale, interact, the command line)
  contain no switch on the kind of a model: no ``hasattr`` on models, no
  ``.kind ==``, no import of a kind's class.
"""
import ast
import os
import pathlib
import subprocess
import sys
import textwrap

ROOT = pathlib.Path(__file__).resolve().parent.parent
PACKAGE = ROOT / "sage_dynsym"
CONSUMERS = ["description.py", "__main__.py", "report", "scale", "interact"]
KIND_CLASSES = {"Circuit", "MechanicalSystem", "LiePoissonSystem"}
KIND_MODULES = ("circuits", "mechanics", "lie")


def _distribution(tmp_path):
    site = tmp_path / "site"
    site.mkdir()
    (site / "toy_oscillator.py").write_text(
        (ROOT / "tests" / "toy_kind" / "toy_oscillator.py").read_text())
    info = site / "toy_oscillator-0.1.dist-info"
    info.mkdir()
    (info / "METADATA").write_text("Metadata-Version: 2.1\nName: toy-oscillator\nVersion: 0.1\n")
    (info / "entry_points.txt").write_text(
        "[sage_dynsym.kinds]\noscillator = toy_oscillator:Oscillator\n")
    return site


SCRIPT = textwrap.dedent(r'''
    import sys, numpy as np
    from sage_dynsym import load, save, kinds
    from sage_dynsym.report import report
    from sage_dynsym.scale import stability_map
    from sage_dynsym.interact.forms import available_forms, derive
    from sage_dynsym.__main__ import main

    path, copy = sys.argv[1], sys.argv[2]
    assert kinds()['oscillator'].__module__ == 'toy_oscillator', kinds()
    M = load(path)
    assert repr(M) == "Oscillator 'toy'", repr(M)

    text = report(M)
    assert text.splitlines()[0] == "== toy (oscillator) ==", text
    assert "dv/dt = -(c*v + k*x)/m" in text, text
    assert "characteristic polynomial:" in text, text
    assert "State equations" not in report(M, sections=['stability'])

    assert available_forms(M) == ['state']
    assert derive(M, 'state').equations[0] == ("\\dot{x}", M.equations()[0])

    # asymptotically stable exactly when all roots of m s^2 + c s + k have Re < 0
    S = stability_map(M, {'c': (-1, 1, 9)}, fixed={'m': 2, 'k': 3}, client=False)
    (axis,) = S.axes().values()
    expected = [max(np.roots([2.0, c, 3.0]).real) < 0 for c in axis]
    assert list(S.stable()) == expected, (list(S.stable()), expected)

    save(M, copy)
    again, results = load(copy, results=True)
    assert again.to_dict() == M.to_dict(), (again.to_dict(), M.to_dict())
    assert [str(e) for e in results['equations']] == [str(e) for e in M.equations()]

    assert main([path, '--sections', 'equations']) == 0
    print("toy kind: ok")
''')


def test_a_kind_from_another_package_goes_everywhere(tmp_path):
    site = _distribution(tmp_path)
    path = tmp_path / "toy.yaml"
    path.write_text("kind: oscillator\nname: toy\nparameters: [m, k, c]\npositive: [m, k]\n"
                    "mass: m\nstiffness: k\ndamping: c\n")
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(site), str(ROOT)]))
    run = subprocess.run([sys.executable, "-c", SCRIPT, str(path), str(tmp_path / "copy.yaml")],
                         capture_output=True, text=True, env=env, timeout=600)
    assert run.returncode == 0, run.stdout[-3000:] + run.stderr[-3000:]
    assert "toy kind: ok" in run.stdout
    assert "== toy (oscillator) ==" in run.stdout     # the command line's report


def _consumer_files():
    for name in CONSUMERS:
        path = PACKAGE / name
        yield from (sorted(path.rglob("*.py")) if path.is_dir() else [path])


def kind_attributes():
    r"""The public attributes some kind of model has beyond the interface:
    testing for one of them is asking the model for its kind. ``simulate``
    is the documented protocol of sweeps (any object with it), not a kind."""
    from sage_dynsym import Circuit, MechanicalSystem
    from sage_dynsym.lie.system import LiePoissonSystem
    from sage_dynsym.dynamics.model import Model
    names = set()
    for cls in (Circuit, MechanicalSystem, LiePoissonSystem):
        names |= {n for n in dir(cls) if not n.startswith('_')}
    return names - set(dir(Model)) - {'simulate'}


def kind_switches(source, attributes):
    r"""The lines of ``source`` that ask a model for its kind: ``hasattr``
    of one of ``attributes``, a comparison with a model's ``.kind``, an
    import of a kind's class or module."""
    found = []
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.Call) and getattr(node.func, 'id', None) == 'hasattr' \
                and len(node.args) == 2 and isinstance(node.args[1], ast.Constant) \
                and node.args[1].value in attributes:
            found.append((node.lineno, f"hasattr {node.args[1].value}"))
        elif isinstance(node, ast.Compare) and any(
                isinstance(side, ast.Attribute) and side.attr == 'kind'
                and not (isinstance(side.value, ast.Attribute) and side.value.attr == 'dtype')
                for side in [node.left, *node.comparators]):
            found.append((node.lineno, ".kind compared"))
        elif isinstance(node, ast.ImportFrom):
            module = (node.module or "").lstrip(".")
            names = {alias.name for alias in node.names}
            if names & KIND_CLASSES or any(part in KIND_MODULES for part in module.split(".")):
                found.append((node.lineno, f"import from {module}"))
    return found


def test_the_kind_switch_rule_itself():
    attributes = {'branches', 'bodies'}
    assert kind_switches("if hasattr(model, 'branches'): pass", attributes)
    assert not kind_switches("if hasattr(verdict, 'cases'): pass", attributes)
    assert kind_switches("if model.kind == 'circuit': pass", attributes)
    assert not kind_switches("if array.dtype.kind in 'biuf': pass", attributes)
    assert kind_switches("from ..circuits.circuit import Circuit", attributes)
    assert kind_switches("from ..mechanics import description", attributes)
    assert not kind_switches("model.free_linear_system(at)", attributes)
    assert not kind_switches("from ..dynamics.model import Model", attributes)


def test_consumers_do_not_switch_on_kinds():
    # description.py is the registry: it lists the package's own kinds
    # (and checks a class's kind), and keeps its earlier public names
    allowed = {("description.py", "import from circuits.circuit"),
               ("description.py", "import from lie.system"),
               ("description.py", "import from mechanics.system"),
               ("description.py", "import from mechanics.description"),
               ("description.py", ".kind compared")}
    attributes = kind_attributes()
    assert {'branches', 'bodies', 'lhs_matrix'} <= attributes
    found = [f"{path.relative_to(PACKAGE)}:{line}: {what}"
             for path in _consumer_files()
             for line, what in kind_switches(path.read_text(), attributes)
             if (str(path.relative_to(PACKAGE)), what) not in allowed]
    assert not found, "kind switches in consumers:\n" + "\n".join(found)
