# Sphinx configuration of the sage_dynsym documentation.
#
# The API reference is plain autodoc over the Sage-style docstrings: they are
# valid reST (``EXAMPLES::`` opens a literal block, ``INPUT:`` is followed by
# a bullet list), so no napoleon; single backquotes are LaTeX, as in Sage.
# The .rst pages are also doctested by ``sage -t`` (``.. linkall``).
import os
import sys

sys.path.insert(0, os.path.abspath(os.path.join(os.path.dirname(__file__), "..")))

project = "sage_dynsym"
author = "the sage_dynsym developers"
extensions = ["sphinx.ext.autodoc", "sphinx.ext.mathjax"]
# the macros Sage docstrings use
mathjax3_config = {"tex": {"macros": {"QQ": r"\mathbb{Q}", "ZZ": r"\mathbb{Z}", "RR": r"\mathbb{R}", "CC": r"\mathbb{C}"}}}
master_doc = "index"
exclude_patterns = ["_build"]
html_theme = "alabaster"
default_role = "math"
autodoc_member_order = "bysource"
autodoc_default_options = {"members": True, "show-inheritance": False}
# MathJax is loaded from the documentation itself when available offline.
nitpicky = False


def setup(app):
    # Sage's ``.. linkall`` (doctest directive) means nothing for HTML.
    from docutils.parsers.rst import Directive

    class LinkAll(Directive):
        def run(self):
            return []

    app.add_directive("linkall", LinkAll)
