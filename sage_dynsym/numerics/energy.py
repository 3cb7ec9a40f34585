r"""
The quadratic energy of lossless linear first-order systems

For `B\dot x = S x` with `B` constant and symmetric and `S` constant and
skew-symmetric, `E = \tfrac12 x^T B x` is conserved:
`\dot E = x^T B \dot x = x^T S x = 0`. Lossless LC circuits (inductors,
capacitors and mutual inductances, no resistors or sources) are of this
form, with `E` the magnetic plus the electric energy.

EXAMPLES::

    sage: from sage_dynsym.analysis.motion import FirstOrderEquations
    sage: from sage_dynsym.numerics.energy import quadratic_energy
    sage: i, u, L, C, R = var('i u L C R')
    sage: quadratic_energy(FirstOrderEquations([-u, i], [i, u], lhs_matrix=[L, C]))
    1/2*L*i^2 + 1/2*C*u^2
    sage: quadratic_energy(FirstOrderEquations([-u - R*i, i], [i, u], lhs_matrix=[L, C])) is None
    True
"""
from sage.matrix.constructor import matrix
from sage.modules.free_module_element import vector
from sage.symbolic.ring import SR

__all__ = ['quadratic_energy']


def quadratic_energy(equations):
    r"""
    `\tfrac12 x^T B x` if ``equations`` (a
    :class:`~sage_dynsym.analysis.motion.FirstOrderEquations`) is
    `B\dot x = S x` with `B` symmetric and `S` skew-symmetric, both free of
    the state and of time; else ``None``.

    EXAMPLES: see the module documentation; mutual inductance `M`::

        sage: from sage_dynsym.analysis.motion import FirstOrderEquations
        sage: from sage_dynsym.numerics.energy import quadratic_energy
        sage: i1, i2, u1, u2, L1, L2, M, C1, C2 = var('i1 i2 u1 u2 L1 L2 M C1 C2')
        sage: E = FirstOrderEquations([-u1, -u2, i1, i2], [i1, i2, u1, u2],
        ....:                         lhs_matrix=[[L1, M, 0, 0], [M, L2, 0, 0], [0, 0, C1, 0], [0, 0, 0, C2]])
        sage: quadratic_energy(E).expand()
        1/2*L1*i1^2 + M*i1*i2 + 1/2*L2*i2^2 + 1/2*C1*u1^2 + 1/2*C2*u2^2

    TESTS::

        sage: x, y = var('x y')
        sage: quadratic_energy(FirstOrderEquations([y, -x^3], [x, y])) is None
        True
    """
    from ..symbols import t
    x = equations.variables()
    B = equations.lhs_matrix()
    F = equations.rhs()
    S = matrix(SR, [[f.diff(v) for v in x] for f in F]) if x else matrix(SR, 0, 0)
    blocks = list(B.list()) + list(S.list())
    if any(e.has(v) for e in blocks for v in x + [t]):
        return None
    if any(not (f - sum(S[k, j] * v for j, v in enumerate(x))).expand().is_zero()
           for k, f in enumerate(F)):
        return None
    if not (B - B.transpose()).is_zero() or not (S + S.transpose()).is_zero():
        return None
    X = vector(SR, x)
    return (X * B * X) / 2
