r"""The package's deprecated aliases: modules kept under an earlier name (say
``sage_dynsym.lagrangian``) that warn and give the module at its new place.
They are recognised by their docstring, and are no part of the layers, the
layout, the reference or the documented surface: the tests that walk the
package leave them out."""
import ast
from pathlib import Path

PACKAGE = Path(__file__).resolve().parent.parent / "sage_dynsym"
#: how the docstring of a deprecated alias begins
MARK = "Deprecated alias of"


def is_deprecated_alias(path):
    doc = ast.get_docstring(ast.parse(Path(path).read_text(encoding="utf-8"))) or ""
    return doc.startswith(MARK)


def _name(path):
    return ".".join(path.relative_to(PACKAGE.parent).with_suffix("").parts)


#: the dotted names of the deprecated aliases, from the source tree
DEPRECATED_ALIASES = frozenset(_name(p) for p in PACKAGE.rglob("*.py") if is_deprecated_alias(p))
