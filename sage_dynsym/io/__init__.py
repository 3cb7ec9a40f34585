r"""
Input and output: the safe expression parser, reading YAML description
files within limits, their common fields, and atomic writing.
"""
