"""No handler swallows a failure.

A handler that catches everything (a bare ``except``, ``except Exception``
or ``except BaseException``) must raise again (the package's error, with the
cause kept), unless it stands at a boundary where the failure is reported to
the user instead of a traceback (the command line, a page, a report section,
a sweep point): those few are listed in :data:`BOUNDARIES`, each with the
reason written in a comment at the ``except`` line. And no ``raise ... from
None``: the cause of an error is kept (``raise ... from err``), so that a
failure inside Sage can still be traced.
"""
import ast
from pathlib import Path

import pytest

from deprecated_aliases import PACKAGE, is_deprecated_alias

#: catch-all handlers that report the failure instead of raising, by
#: ``module path: function``
BOUNDARIES = {
    "__main__.py: main",                    # the command line: one line per failure
    "scale/cli.py: main",
    "dynamics/reporting.py: report_blocks",  # a report: the section says it failed
    "interact/builder.py: _attempt",        # a page: the status line, not a traceback
    "scale/kernel.py: sweep_chunk",         # a sweep: the failure recorded with its point
    "scale/cluster.py: _reply",             # a worker's child: the failure sent back, raised there
}

_WIDE = {"Exception", "BaseException"}


def _catches_everything(handler):
    kinds = handler.type
    if kinds is None:
        return True
    names = kinds.elts if isinstance(kinds, ast.Tuple) else [kinds]
    return any(isinstance(n, ast.Name) and n.id in _WIDE for n in names)


def _functions(tree):
    r"""The innermost function around each handler of ``tree``."""
    owner = {}

    def visit(node, function):
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            function = node.name
        if isinstance(node, ast.ExceptHandler):
            owner[node] = function
        for child in ast.iter_child_nodes(node):
            visit(child, function)
    visit(tree, "<module>")
    return owner


def problems(source, where):
    r"""The swallowing handlers and the ``from None`` of ``source`` (the
    text of the module ``where``, a path relative to the package)."""
    tree, lines = ast.parse(source), source.splitlines()
    found = []
    for handler, function in _functions(tree).items():
        if not _catches_everything(handler):
            continue
        raises = any(isinstance(n, ast.Raise) for n in ast.walk(handler))
        key = f"{where}: {function}"
        if raises:
            continue
        if key not in BOUNDARIES:
            found.append(f"{where}:{handler.lineno}: a catch-all handler in {function}() that "
                         "does not raise (catch what can fail, or raise ... from err)")
        elif "#" not in lines[handler.lineno - 1]:
            found.append(f"{where}:{handler.lineno}: the boundary in {function}() says no "
                         "reason in a comment at its except line")
    for node in ast.walk(tree):
        if (isinstance(node, ast.Raise) and isinstance(node.cause, ast.Constant)
                and node.cause.value is None):
            found.append(f"{where}:{node.lineno}: raise ... from None drops the cause "
                         "(raise ... from err)")
    return found


def _modules():
    return [p for p in sorted(PACKAGE.rglob("*.py")) if not is_deprecated_alias(p)]


def test_no_handler_swallows_a_failure():
    found = []
    for path in _modules():
        found += problems(path.read_text(encoding="utf-8"), path.relative_to(PACKAGE).as_posix())
    assert not found, "\n".join(found)


def test_the_boundaries_are_still_there():
    functions = {f"{p.relative_to(PACKAGE).as_posix()}: {f}"
                 for p in _modules()
                 for h, f in _functions(ast.parse(p.read_text(encoding="utf-8"))).items()
                 if _catches_everything(h)}
    assert BOUNDARIES <= functions, sorted(BOUNDARIES - functions)


@pytest.mark.parametrize("source, count", [
    ("try:\n    f()\nexcept Exception:\n    return []\n", 1),
    ("try:\n    f()\nexcept:\n    pass\n", 1),
    ("try:\n    f()\nexcept (KeyError, BaseException) as e:\n    x = e\n", 1),
    ("try:\n    f()\nexcept KeyError:\n    raise ValueError('k') from None\n", 1),
    ("try:\n    f()\nexcept Exception as e:\n    raise ValueError('k') from e\n", 0),
    ("try:\n    f()\nexcept BaseException:\n    cleanup()\n    raise\n", 0),
    ("try:\n    f()\nexcept KeyError:\n    return []\n", 0),
    ("def main():\n    try:\n        f()\n    except Exception:\n        pass\n", 1),
    ("def main():\n    try:\n        f()\n    except Exception:  # reported\n        pass\n", 0),
])
def test_the_rule_itself(source, count):
    assert len(problems(source, "__main__.py")) == count
