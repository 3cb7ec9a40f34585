r"""
Input and output: the safe expression parser, reading YAML description
files within limits, their common fields, and atomic writing.
"""
# Sage's symbolic functions, Maxima and coercions need the whole library initialised
# (the package's face loads it lazily, only when a name is used)
import sage.all
del sage  # imported for its effect alone: no name of this module

__all__ = []
