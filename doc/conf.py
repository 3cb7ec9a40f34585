# Sphinx configuration of the sage_dynsym documentation.
project = "sage_dynsym"
author = "the sage_dynsym developers"
extensions = ["sphinx.ext.autodoc", "sphinx.ext.mathjax"]
master_doc = "index"
exclude_patterns = ["_build"]
html_theme = "alabaster"
