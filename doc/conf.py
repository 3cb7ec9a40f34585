# Sphinx configuration of the sage_dynsym documentation.
#
# The API reference is plain autodoc over the Sage-style docstrings: they are
# valid reST (``EXAMPLES::`` opens a literal block, ``INPUT:`` is followed by
# a bullet list), so no napoleon; single backquotes are LaTeX, as in Sage.
# The .rst pages are also doctested by ``sage -t`` (``.. linkall``).
#
# The built pages load nothing from another host (the documentation is read
# offline too; tests/browser/test_docs_offline.py checks it): MathJax 3 comes
# from the files of the ``sphinx-mathjax-offline`` package, copied into
# ``_static/mathjax`` (its Sphinx extension is not used: it does not declare
# itself safe for parallel builds), and the theme brings its own assets.
import glob
import importlib.util
import os
import shutil
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.abspath(os.path.join(HERE, "..")))

project = "sage_dynsym"
author = "the sage_dynsym developers"
extensions = ["sphinx.ext.autodoc", "sphinx.ext.autosummary", "sphinx.ext.mathjax"]
# a folder holding mathjax/ (tex-chtml.js, its components and fonts)
MATHJAX_PARENT = os.path.join(
    importlib.util.find_spec("sphinx-mathjax-offline").submodule_search_locations[0], "static")
mathjax_path = "mathjax/tex-chtml.js"
# the macros Sage docstrings use
mathjax3_config = {"tex": {"macros": {"QQ": r"\mathbb{Q}", "ZZ": r"\mathbb{Z}", "RR": r"\mathbb{R}", "CC": r"\mathbb{C}"}}}
master_doc = "index"
exclude_patterns = ["_build"]
default_role = "math"
autodoc_member_order = "bysource"
# A package's ``__all__`` names what it re-exports (lazily): each object is
# documented once, on the page of the module that defines it.
autodoc_default_options = {"members": True, "show-inheritance": False, "ignore-module-all": True}
nitpicky = False

# One page per module: the reference_<layer>.rst pages list their modules
# in ``autosummary`` tables (with the first line of each docstring), whose
# ``:toctree: api`` makes the module pages children of the layer's page.
# Those pages are written here at the start of every build (a title and the
# module's ``automodule``; autosummary's own generator would inspect every
# member of every module for nothing): they are build products, not in git,
# and a renamed or removed module leaves no stale page.
API_DIR = os.path.join(HERE, "api")
autosummary_generate = False

html_theme = "furo"
html_title = "sage_dynsym"
html_static_path = ["_static", MATHJAX_PARENT]
# code examples wrap to the page, never cut
html_css_files = ["sage_dynsym.css"]


def _write_module_pages(app):
    from sphinx.ext.autosummary.generate import find_autosummary_in_files
    from sphinx.util.rst import escape

    shutil.rmtree(API_DIR, ignore_errors=True)
    os.makedirs(API_DIR)
    layers = sorted(glob.glob(os.path.join(HERE, "reference_*.rst")))
    for entry in find_autosummary_in_files(layers):
        # the title without the package's name keeps the navigation readable
        title = escape(entry.name.removeprefix("sage_dynsym."))
        with open(os.path.join(API_DIR, entry.name + ".rst"), "w") as page:
            page.write(f"{title}\n{'=' * len(title)}\n\n.. automodule:: {entry.name}\n")


def setup(app):
    # Sage's ``.. linkall`` (doctest directive) means nothing for HTML.
    from docutils.parsers.rst import Directive

    class LinkAll(Directive):
        def run(self):
            return []

    app.add_directive("linkall", LinkAll)
    # before Sphinx looks for the source files
    app.connect("builder-inited", _write_module_pages)
