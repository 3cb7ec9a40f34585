"""The package's imports point down its layers and never close a circle.

Every ``import`` and ``from ... import`` of every module of sage_dynsym
(also the ones inside functions: a lazy import is still a dependency) is
read with ``ast``, resolved to a module of the package, and checked against
the layers below. A module may import modules of a lower layer, and modules
of its own package; an import of a higher layer, or of another package on
the same layer, is an error, and so is any cycle between modules.
"""
import ast
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parent.parent / "sage_dynsym"

#: From the bottom up. The first matching prefix gives a module's layer.
LAYERS = [
    ("errors", ["sage_dynsym.errors"]),
    ("arguments", ["sage_dynsym.arguments"]),
    ("symbols", ["sage_dynsym.symbols"]),
    ("input", ["sage_dynsym.io"]),
    ("algebra and analysis", ["sage_dynsym.analysis"]),
    ("numerics", ["sage_dynsym.numerics"]),
    ("characteristic functions and equations", ["sage_dynsym.dynamics"]),
    ("systems on Lie algebras", ["sage_dynsym.lie"]),
    ("models", ["sage_dynsym.mechanics", "sage_dynsym.circuits"]),
    ("description files", ["sage_dynsym.description"]),
    ("numerics at scale", ["sage_dynsym.scale"]),
    ("presentation", ["sage_dynsym.report", "sage_dynsym.interact"]),
    ("entry points", ["sage_dynsym.__main__", "sage_dynsym"]),
]


def module_name(path):
    parts = list(path.relative_to(PACKAGE.parent).with_suffix("").parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts)


def modules():
    return {module_name(p): p for p in PACKAGE.rglob("*.py")}


def layer_of(name):
    best = None
    for level, (_, prefixes) in enumerate(LAYERS):
        for prefix in prefixes:
            # the package itself (its face) is a layer of its own, not a prefix
            if name == prefix or (prefix != "sage_dynsym" and name.startswith(prefix + ".")):
                if best is None or len(prefix) > best[1]:
                    best = (level, len(prefix), prefix)
    return best


def package_of(name):
    found = layer_of(name)
    return found[2] if found else None


def imports(name, path, known):
    r"""The package modules that ``name`` imports (resolved): ``from P
    import x`` depends on the module ``P.x`` where there is one, else on
    ``P`` itself (a package's face included)."""
    is_package = path.name == "__init__.py"
    base = name.split(".") if is_package else name.split(".")[:-1]

    def resolve(t):
        while t and t not in known:
            t = t.rpartition(".")[0]
        return t

    found = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            found |= {resolve(a.name) for a in node.names}
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                parent = base[:len(base) - node.level + 1] if node.level > 1 else base
                stem = ".".join(parent + ([node.module] if node.module else []))
            else:
                stem = node.module or ""
            for a in node.names:
                candidate = f"{stem}.{a.name}"
                found.add(candidate if candidate in known else resolve(stem))
    return {t for t in found if t and t.startswith("sage_dynsym") and t != name}


def graph():
    known = modules()
    return {name: imports(name, path, known) for name, path in known.items()}


def test_every_module_has_a_layer():
    missing = [name for name in modules() if layer_of(name) is None]
    assert not missing, f"modules outside every layer: {missing}"


def test_imports_point_down():
    wrong = []
    for name, targets in graph().items():
        if name == "sage_dynsym":          # the face re-exports everything
            continue
        level, _, package = layer_of(name)
        for t in targets:
            t_level, _, t_package = layer_of(t)
            if t_level > level or (t_level == level and t_package != package):
                wrong.append(f"{name} -> {t}")
    assert not wrong, "imports that do not point down:\n" + "\n".join(sorted(wrong))


def test_no_cycles():
    g = {k: {t for t in v if t != "sage_dynsym"} for k, v in graph().items()}
    state, stack, cycles = {}, [], []

    def visit(node):
        state[node] = 1
        stack.append(node)
        for t in sorted(g.get(node, ())):
            if state.get(t) == 1:
                cycles.append(stack[stack.index(t):] + [t])
            elif t not in state:
                visit(t)
        stack.pop()
        state[node] = 2

    for node in sorted(g):
        if node not in state:
            visit(node)
    assert not cycles, "import cycles:\n" + "\n".join(" -> ".join(c) for c in cycles)


def test_top_level_stays_small():
    # at most six modules beside the packages
    top = [p.name for p in PACKAGE.glob("*.py")]
    assert len(top) <= 6, f"top-level modules: {sorted(top)}"


@pytest.mark.parametrize("source, target, ok", [
    ("sage_dynsym.analysis.linear", "sage_dynsym.dynamics.lagrangian", False),
    ("sage_dynsym.mechanics.system", "sage_dynsym.dynamics.lagrangian", True),
    ("sage_dynsym.mechanics.system", "sage_dynsym.circuits.circuit", False),
])
def test_the_rule_itself(source, target, ok):
    # the checker's verdict on made-up imports (so a vacuous checker fails)
    level, _, package = layer_of(source)
    t_level, _, t_package = layer_of(target)
    assert (t_level < level or (t_level == level and t_package == package)) == ok
