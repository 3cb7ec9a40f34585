"""
The plain-data chains of ``reference/chains.py`` given to sage_dynsym.

The one place where tests and benchmarks turn a description (the fields
read by ``reference/sympy_chain.py``) into a ``MechanicalSystem``; the
strings are test-authored, parsed by SymPy and converted by Sage. (It is
not in ``reference/``, which stays independent of Sage and sage_dynsym.)
"""
from fractions import Fraction


def sage_chain_parts(desc):
    """
    The pieces of the ``MechanicalSystem`` of ``desc``, converted but not
    assembled (benchmarks time the assembly): a list of keyword dicts for
    ``RigidBody`` (with ``name``), the coordinates, the parameters and the
    gravity vector.
    """
    import sympy
    from sage.all import SR
    names = {n: sympy.Symbol(n) for n in desc['coordinates'] + desc['parameters'] + ['t']}

    def conv(x):
        if isinstance(x, Fraction):
            return SR(x.numerator) / SR(x.denominator)
        if isinstance(x, str):
            return SR(sympy.parse_expr(x, local_dict=dict(names)))
        return SR(x)

    bodies = [dict(name=f'body{k}', parent=b['parent'], velocity=None,
                   rotations=[(axis, conv(angle)) for axis, angle in b['rotations']],
                   joint=[conv(x) for x in b['joint']],
                   mass_center=[conv(x) for x in b['mass_center']], mass=conv(b['mass']),
                   inertia=[[conv(x) for x in row] for row in b['inertia']])
              for k, b in enumerate(desc['bodies'], start=1)]
    return (bodies, [SR.var(q) for q in desc['coordinates']],
            [SR.var(p) for p in desc['parameters']], [conv(x) for x in desc['gravity']])


def assemble(bodies, coordinates, parameters, gravity):
    """The ``MechanicalSystem`` of the pieces of :func:`sage_chain_parts`."""
    from sage_dynsym import MechanicalSystem, RigidBody, UniformGravity
    rigid = [RigidBody(b['name'], **{k: v for k, v in b.items() if k != 'name'})
             for b in bodies]
    return MechanicalSystem(rigid, coordinates=coordinates, parameters=parameters,
                            force_function=UniformGravity(gravity))


def sage_chain(desc):
    """A sage_dynsym ``MechanicalSystem`` for a plain-data chain description."""
    return assemble(*sage_chain_parts(desc))


def exact_accelerations(record, point):
    """
    The accelerations solving the equations ``E = 0`` of ``record`` (an
    equations record, linear in the accelerations) at ``point`` (symbol name
    -> number, ``t`` included), in 150-bit arithmetic: a NumPy array of
    floats. The columns of the linear system are the differences of ``E`` at
    unit accelerations; the point is substituted once.
    """
    import numpy as np
    from sage.all import SR, RealField, matrix, vector
    R = RealField(150)
    ddq = record.accelerations()
    base = {SR.var(k): R(v) for k, v in point.items()}
    at_point = [SR(e).subs(base) for e in record.equations()]     # linear in ddq
    zero = {a: R(0) for a in ddq}

    def E(at):
        return vector(R, [R(e.subs(at)) for e in at_point])
    e0 = E(zero)
    columns = []
    for a in ddq:
        unit = dict(zero)
        unit[a] = R(1)
        columns.append(E(unit) - e0)
    return np.array([float(v) for v in matrix(R, columns).transpose().solve_right(-e0)])
