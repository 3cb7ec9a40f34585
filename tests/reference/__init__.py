"""
Independent reference implementations used by the cross-check tests.

Nothing here imports sage_dynsym: the models are rebuilt from plain data with
other tools (``sympy.physics.mechanics``) so that agreement is evidence.
"""
