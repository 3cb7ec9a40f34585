r"""
Mechanical systems handed to the recursive numerics

:func:`body_tree` writes a :class:`~sage_dynsym.mechanics.system.MechanicalSystem`
as the neutral :class:`~sage_dynsym.numerics.body_tree.BodyTree` of the
numerics -- bodies, uniform gravity, loads, the other terms of the force
function as one expression, dissipation, generalized forces, constraints
(holonomic ones and those on the velocities: rolling without slipping) --
and :func:`numerical_form` chooses how its right-hand side is computed:

- ``'recursive'``: by the recursive algorithms of
  :mod:`~sage_dynsym.numerics.recursive`, without the symbolic equations of
  motion (the build time grows about like the square of the number of
  bodies);
- ``'equations'``: from the Lagrange equations of
  :meth:`~sage_dynsym.mechanics.system.MechanicalSystem.lagrangian`;
- ``'auto'`` (default): ``'recursive'`` when it applies (see
  :func:`~sage_dynsym.numerics.recursive.unsupported`), else
  ``'equations'``, with the reason logged (logger ``sage_dynsym.numerics``).

Both give the same accelerations (``tests/test_recursive_rhs.py``).

EXAMPLES::

    sage: from sage_dynsym import load
    sage: from sage_dynsym.description import example_path
    sage: from sage_dynsym.mechanics.recursive_numerics import body_tree, numerical_form
    sage: S = load(example_path('spherical_pendulum.yaml'))
    sage: body_tree(S)
    Tree of 1 body in (psi, theta), parameters (g, l, m)
    sage: numerical_form(S)
    Recursive form of a tree of 1 body in (psi, theta), parameters (g, l, m)
    sage: numerical_form(S, 'equations')
    Numerical form M x'' = F in (psi, theta), parameters (g, l, m)
"""
import logging

from ..errors import ModelError
from ..numerics.body_tree import BodyTree
from ..numerics.methods import object_cache
from ..numerics.recursive import RecursiveForm, unsupported
from .force_functions import split_force_terms

__all__ = ['ALGORITHMS', 'body_tree', 'numerical_form']

_LOG = logging.getLogger('sage_dynsym.numerics')
ALGORITHMS = ('auto', 'recursive', 'equations')


def body_tree(system):
    r"""
    The :class:`~sage_dynsym.numerics.body_tree.BodyTree` of ``system``:
    the tree holds the system's own bodies and loads (no copy of them),
    with the bodies' parents' indices.

    Uniform gravity becomes the tree's gravity; the other terms of the
    force function (Newtonian fields, expressions) are evaluated
    symbolically and their sum becomes its ``potential``.

    EXAMPLES::

        sage: from sage_dynsym import MechanicalSystem, RigidBody, UniformGravity
        sage: from sage_dynsym.mechanics.recursive_numerics import body_tree
        sage: x, m, k, g, F = var('x m k g F')
        sage: S = MechanicalSystem([RigidBody('b', joint=[0, 0, x], mass=m)], [x],
        ....:                      force_function=[UniformGravity([0, 0, -g]), -k*x^2/2],
        ....:                      loads=[{'body': 'b', 'force': [0, 0, F]}])
        sage: T = body_tree(S); T.gravity(), T.potential(), T.loads()
        ((0, 0, -g), -1/2*k*x^2, [Load on 'b' at (0, 0, 0): force (0, 0, F), in the inertial axes])
        sage: T.loads()[0] is S.loads()[0]
        True
    """
    bodies = system.bodies()
    gravity, potential = split_force_terms(system.force_terms(), system.kinematics())
    # the generalized forces given as such (those of the loads come from the tree)
    return BodyTree(bodies, system.coordinates(), gravity=gravity, loads=system.loads(),
                    parents=[system.parent_index(k) for k in range(1, len(bodies) + 1)],
                    potential=potential, dissipation=system.dissipation(),
                    forces=system.given_forces(),
                    constraints=system.constraints(),
                    velocity_constraints=system.nonholonomic_constraints())


def numerical_form(system, algorithm='auto'):
    r"""
    The numerical form of ``system`` for ``algorithm`` (see the module
    documentation): a :class:`~sage_dynsym.numerics.recursive.RecursiveForm`
    or the :class:`~sage_dynsym.numerics.form.NumericalForm` of the Lagrange
    equations; built once per system and algorithm. The conserved energy
    (for ``energy_drift``) is computed only when asked for.

    EXAMPLES: see the module documentation; a body whose mass depends on a
    coordinate takes the equations::

        sage: from sage_dynsym import MechanicalSystem, RigidBody
        sage: from sage_dynsym.mechanics.recursive_numerics import numerical_form
        sage: x, m = var('x m')
        sage: S = MechanicalSystem([RigidBody('b', joint=[x, 0, 0], mass=m*(1 + x^2))], [x])
        sage: numerical_form(S)
        Numerical form M x'' = F in (x), parameters (m)

    TESTS::

        sage: numerical_form(S, 'recursive')
        Traceback (most recent call last):
        ...
        ModelError: algorithm: the recursive form does not apply: the mass, mass centre or inertia of body 1 depends on the coordinates, velocities or t
        sage: numerical_form(S, 'fastest')
        Traceback (most recent call last):
        ...
        ModelError: algorithm: must be 'auto', 'recursive' or 'equations', got 'fastest'
    """
    if algorithm not in ALGORITHMS:
        raise ModelError(f"must be 'auto', 'recursive' or 'equations', got {algorithm!r}",
                         entry="algorithm")
    cache = object_cache(system)
    if algorithm in cache:
        return cache[algorithm]
    form = None
    if algorithm != 'equations':
        tree = body_tree(system)
        reason = unsupported(tree)
        if reason is None:
            form = RecursiveForm(tree, energy=lambda: system.lagrangian().conserved_energy())
        elif algorithm == 'recursive':
            raise ModelError(f"the recursive form does not apply: {reason}", entry="algorithm")
        else:
            _LOG.info("numerical_rhs: the equations of motion are used: %s", reason)
    if form is None:
        form = system.lagrangian().numerical_form()
    cache[algorithm] = form
    return form
