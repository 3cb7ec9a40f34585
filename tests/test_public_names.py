"""Every public module says what it offers in ``__all__``, as Sage's modules
do: the functions and classes it defines, and the names it re-exports from
elsewhere (an import that the module does not use itself is a re-export,
and is declared there; otherwise it is an unused import). The faces of the
package and of its subpackages show only their names and subpackages, no
helper modules (``importlib``, ``sys``, ``sage``)."""
import ast
import functools
import importlib
import inspect
import types

import pytest

from deprecated_aliases import DEPRECATED_ALIASES, PACKAGE, is_deprecated_alias


def _name(path):
    parts = path.relative_to(PACKAGE.parent).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


@functools.lru_cache(maxsize=None)
def public_modules():
    r"""``{dotted name: path}`` of the public modules: no part of the name
    private, no deprecated alias."""
    found = {}
    for path in sorted(PACKAGE.rglob("*.py")):
        name = _name(path)
        if is_deprecated_alias(path) or any(p.startswith("_") for p in name.split(".")):
            continue
        found[name] = path
    return found


def declared_all(tree):
    r"""Whether the module assigns ``__all__`` at its top level."""
    return any(isinstance(node, (ast.Assign, ast.AugAssign, ast.AnnAssign))
               and "__all__" in {t.id for t in ast.walk(node) if isinstance(t, ast.Name)
                                 and isinstance(t.ctx, ast.Store)}
               for node in tree.body)


def unused_imports(source, exported=()):
    r"""The names the module ``source`` imports and never uses, and does not
    declare in ``exported`` (its ``__all__``)."""
    tree = ast.parse(source)
    imported = {}
    for node in ast.walk(tree):
        if isinstance(node, (ast.Import, ast.ImportFrom)):
            for alias in node.names:
                if alias.name == "*":
                    continue
                bound = alias.asname or alias.name.split(".")[0]
                imported.setdefault(bound, node.lineno)
    used = {node.id for node in ast.walk(tree) if isinstance(node, ast.Name)
            and not isinstance(node.ctx, ast.Store)}
    return sorted(f"{name} (line {line})" for name, line in imported.items()
                  if name not in used and name not in exported and name != "__future__")


@pytest.mark.parametrize("name", sorted(public_modules()))
def test_every_public_module_declares_its_names(name):
    path = public_modules()[name]
    source = path.read_text(encoding="utf-8")
    assert declared_all(ast.parse(source)), f"{name}: no __all__ (after the imports)"
    module = importlib.import_module(name)
    names = module.__all__
    assert isinstance(names, (list, tuple)) and all(isinstance(n, str) for n in names)
    assert len(set(names)) == len(names), f"{name}: names twice in __all__"
    missing = [n for n in names if not hasattr(module, n)]
    assert not missing, f"{name}: __all__ names what the module does not have: {missing}"
    defined = [key for key, value in vars(module).items()
               if not key.startswith("_") and (inspect.isfunction(value) or inspect.isclass(value))
               and getattr(value, "__module__", None) == name]
    undeclared = sorted(set(defined) - set(names))
    assert not undeclared, f"{name}: defines {undeclared}, not in __all__"
    unused = unused_imports(source, names)
    assert not unused, f"{name}: imports it neither uses nor re-exports: {unused}"


def _faces():
    return [name for name, path in public_modules().items() if path.name == "__init__.py"]


@pytest.mark.parametrize("name", _faces())
def test_faces_show_no_helper_modules(name):
    face = importlib.import_module(name)
    # a submodule is bound under its name; a deprecated alias under its old
    # name, as the module at its new place
    helpers = [key for key in dir(face) if not key.startswith("__")
               and isinstance(getattr(face, key), types.ModuleType)
               and getattr(face, key).__name__ != f"{name}.{key}"
               and f"{name}.{key}" not in DEPRECATED_ALIASES]
    assert not helpers, f"dir({name}) shows the helper modules {helpers}"


@pytest.mark.parametrize("source, unused", [
    ("import os\n", ["os (line 1)"]),
    ("import os.path\nos.path.join('a')\n", []),
    ("from a import b, c\nb()\n", ["c (line 1)"]),
    ("from a import b as d\n__all__ = ['d']\n", []),
    ("import sage.all\ndel sage\n", []),
    ("def f():\n    from a import b\n    return 1\n", ["b (line 2)"]),
])
def test_the_unused_import_rule_itself(source, unused):
    exported = ["d"] if "__all__" in source else []
    assert unused_imports(source, exported) == unused
