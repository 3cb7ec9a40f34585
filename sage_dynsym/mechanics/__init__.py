r"""
Systems of rigid bodies: frames, bodies, force functions, kinematics, the
mechanical system and its description format.
"""
# Sage's symbolic functions, Maxima and coercions need the whole library initialised
# (the package's face loads it lazily, only when a name is used)
import sage.all
del sage  # imported for its effect alone: no name of this module

__all__ = []
