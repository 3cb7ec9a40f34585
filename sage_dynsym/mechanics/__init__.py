r"""
Systems of rigid bodies: frames, bodies, force functions, kinematics, the
mechanical system and its description format.
"""
