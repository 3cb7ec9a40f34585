"""The reference manual covers the package: every module of sage_dynsym has
its page, listed on the page of its layer (doc/reference_<layer>.rst), and
every layer page is in the manual's table of contents (doc/reference.rst).
A module added to the package without a line in the reference fails here,
not silently missing from the documentation."""
import re
from pathlib import Path

from deprecated_aliases import is_deprecated_alias

ROOT = Path(__file__).resolve().parents[1]
DOC = ROOT / "doc"
#: the entries of an ``autosummary`` table: indented dotted names under the directive
ENTRY = re.compile(r"^ {3}(sage_dynsym(?:\.\w+)*)\s*$", re.MULTILINE)


def _modules():
    """(name, is a package) of every public module, from the source tree."""
    for path in sorted((ROOT / "sage_dynsym").rglob("*.py")):
        parts = list(path.relative_to(ROOT).with_suffix("").parts)
        package = parts[-1] == "__init__"
        if package:
            parts.pop()
        # a deprecated alias is documented by the module it gives
        if any(p.startswith("_") and p != "__main__" for p in parts[1:]) \
                or is_deprecated_alias(path):
            continue
        yield ".".join(parts), package


def _listed():
    """module name -> the layer pages listing it."""
    listed = {}
    for page in sorted(DOC.glob("reference_*.rst")):
        for name in ENTRY.findall(page.read_text(encoding="utf-8")):
            listed.setdefault(name, []).append(page.name)
    return listed


def test_every_module_has_a_page_in_the_reference():
    listed = _listed()
    # a package's page is optional: its modules carry the documentation
    missing = [name for name, package in _modules() if not package and name not in listed]
    assert not missing, "modules missing from doc/reference_<layer>.rst: " + ", ".join(missing)


def test_the_reference_lists_only_modules_and_each_once():
    modules = {name for name, _ in _modules()}
    listed = _listed()
    assert len(listed) > 50
    assert not [n for n in listed if n not in modules], "not modules of the package"
    twice = {n: pages for n, pages in listed.items() if len(pages) > 1}
    assert not twice, f"listed more than once: {twice}"


def test_every_layer_page_is_in_the_table_of_contents():
    toctree = (DOC / "reference.rst").read_text(encoding="utf-8")
    entries = set(re.findall(r"^ {3}(reference_\w+)\s*$", toctree, re.MULTILINE))
    assert entries == {p.stem for p in DOC.glob("reference_*.rst")}
