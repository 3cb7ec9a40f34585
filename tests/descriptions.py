"""
Description files shared by several tests (text, written to a temporary
folder by each test).
"""

#: A point mass held on the circle ``x^2 + z^2 = l^2`` of the plane y = 0 by
#: a holonomic constraint, in uniform gravity along -z; ``{constraint}``
#: stands for the constraint's expression.
CARTESIAN_PENDULUM = """\
kind: mechanical
name: Cartesian pendulum
parameters: [m, l, g]
positive: [m, l, g]
coordinates: [x, z]
force_function:
  uniform_gravity: [0, 0, -g]
constraints: ["{constraint}"]
bodies:
  - name: bob
    parent: 0
    joint: [x, 0, z]
    mass: m
"""


def cartesian_pendulum(constraint="x^2 + z^2 - l^2"):
    """The text of :data:`CARTESIAN_PENDULUM` with ``constraint``."""
    return CARTESIAN_PENDULUM.format(constraint=constraint)
