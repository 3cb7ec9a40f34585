"""Every public function, class and method of the package has a docstring
with an example (the doctests are the documentation), and no docstring
sends the reader to a document outside the repository."""
import importlib
import inspect
import pkgutil
import re

import sage_dynsym

from deprecated_aliases import DEPRECATED_ALIASES

#: Methods every class gets from Python or Sage: not the package's to document.
INHERITED = {"dump", "dumps", "save", "rename", "reset_name", "category", "db", "parent",
             "version", "plot"}


def package_modules():
    for info in pkgutil.walk_packages(sage_dynsym.__path__, prefix="sage_dynsym."):
        # a deprecated alias warns and is the module it names, checked there
        if info.name.endswith("__main__") or info.name in DEPRECATED_ALIASES or any(
                part.startswith("_") for part in info.name.split(".")[1:]):
            continue
        yield importlib.import_module(info.name)


def public_objects():
    seen = set()
    for module in package_modules():
        for name, obj in vars(module).items():
            if name.startswith("_") or getattr(obj, "__module__", None) != module.__name__:
                continue
            if not (inspect.isfunction(obj) or inspect.isclass(obj)):
                continue
            key = f"{module.__name__}.{name}"
            if key in seen:
                continue
            seen.add(key)
            yield key, obj
            if inspect.isclass(obj):
                for attr, member in vars(obj).items():
                    if attr.startswith("_") or attr in INHERITED:
                        continue
                    if inspect.isfunction(member) or isinstance(member, (staticmethod,
                                                                         classmethod)):
                        yield f"{key}.{attr}", getattr(obj, attr)


def has_example(obj):
    doc = inspect.getdoc(obj) or ""
    return "sage:" in doc or "EXAMPLES:" in doc and ("see " in doc.lower())


def test_every_public_object_has_an_example():
    missing = [key for key, obj in public_objects() if not has_example(obj)]
    assert not missing, (f"{len(missing)} public objects without an example:\n"
                         + "\n".join(missing))


def test_no_reference_to_outside_documents():
    pattern = re.compile(r"\bspec\b[^=\[]|\bcontract\b|method\.md", re.IGNORECASE)
    offenders = []
    for module in package_modules():
        source = inspect.getsource(module)
        for number, line in enumerate(source.splitlines(), 1):
            if pattern.search(line) and "sage:" not in line:
                offenders.append(f"{module.__name__}:{number}: {line.strip()}")
    assert not offenders, "\n".join(offenders)
