r"""
Lie--Poisson systems of rigid bodies: Euler--Poisson and Kirchhoff

Both builders give systems on `e(3)` with the brackets of
:mod:`.algebras` (`\{M_i, M_j\} = -\varepsilon_{ijk}M_k`, `\{M_i,
\gamma_j\} = -\varepsilon_{ijk}\gamma_k`):

- :func:`euler_poisson`: a heavy rigid body with a fixed point, from its
  mechanical description. `M = I\omega` is the angular momentum about the
  fixed point and `\gamma` the unit vector of the field's inertial axis
  (the vertical, upward for ``uniform_gravity: [0, 0, -g]``), both in the
  body's axes;

  .. MATH::

      H = \tfrac12 M\cdot I^{-1}M - m\, g_k\,(r_c\cdot\gamma), \qquad
      \dot M = M\times\omega + \gamma\times\frac{\partial H}{\partial\gamma},
      \quad \dot\gamma = \gamma\times\omega,

  `g = g_k e_k` the field, `r_c` the centre of mass in the body's axes.
- :func:`kirchhoff`: a rigid body in an ideal fluid at rest at infinity.
  The kinetic energy of body and fluid is `T = \tfrac12 (\Omega, V)^T
  \Lambda (\Omega, V)`, `\Lambda = \Lambda_b + \Lambda_f`, with
  `\Lambda_b = \begin{pmatrix} I & m[r_c]_\times \\ -m[r_c]_\times &
  mE\end{pmatrix}` the body's and `\Lambda_f` the fluid's added masses;
  `(M, p) = \Lambda(\Omega, V)` are the impulsive moment and force and `H =
  \tfrac12 (M, p)^T\Lambda^{-1}(M, p)` (Lamb, *Hydrodynamics*, §§124--127;
  Borisov & Mamaev, *Rigid Body Dynamics*, §1.7).

EXAMPLES::

    sage: from sage_dynsym.lie.builders import kirchhoff
    sage: I1, I2, I3, m, K1, K2, K3 = var('I1 I2 I3 m K1 K2 K3')
    sage: S = kirchhoff(inertia=diagonal_matrix([I1, I2, I3]), mass=m,
    ....:               added_masses=diagonal_matrix([0, 0, 0, K1, K2, K3]))
    sage: S.hamiltonian()
    1/2*M1^2/I1 + 1/2*M2^2/I2 + 1/2*M3^2/I3 + 1/2*p1^2/(K1 + m) + 1/2*p2^2/(K2 + m) + 1/2*p3^2/(K3 + m)

REFERENCES:

- H. Lamb, *Hydrodynamics*, 6th ed., Cambridge, 1932, §§124--127.
- A. V. Borisov, I. S. Mamaev, *Rigid Body Dynamics*, De Gruyter, 2018,
  §§1.2, 1.7.
"""
from sage.matrix.constructor import matrix, block_matrix, identity_matrix
from sage.modules.free_module_element import vector
from sage.rings.polynomial.polynomial_ring_constructor import PolynomialRing
from sage.rings.rational_field import QQ
from sage.symbolic.ring import SR

from ..arguments import model_argument
from ..errors import ModelError, brief
from .algebras import collect
from .system import LiePoissonSystem

__all__ = ['euler_poisson', 'kirchhoff']


def _inverse(A, entry):
    r"""
    The inverse of a symbolic matrix, over the field of rational functions
    of its symbols when its entries are rational (exact, canonical).
    """
    symbols = sorted({a for c in A.list() for a in SR(c).variables()}, key=str)
    try:
        F = PolynomialRing(QQ, len(symbols), [str(a) for a in symbols]).fraction_field() \
            if symbols else QQ
        B = matrix(F, A.nrows(), A.ncols(), [F(SR(c)) for c in A.list()])
    except (TypeError, ValueError, ArithmeticError):
        B = None
    if B is not None:
        if B.det() == 0:
            raise ModelError(f"the matrix is singular: {A.rows()}", entry=entry)
        return B.inverse().change_ring(SR)
    if bool(A.det().simplify_full() == 0):
        raise ModelError(f"the matrix is singular: {A.rows()}", entry=entry)
    return A.inverse().simplify_rational()


def _cross_matrix(r):
    return matrix(SR, [[0, -r[2], r[1]], [r[2], 0, -r[0]], [-r[1], r[0], 0]])


def _prefixes(names, default):
    names = default if names is None else names
    if isinstance(names, str):
        names = [n for n in names.replace(',', ' ').split() if n]
    if not isinstance(names, (list, tuple)) or len(names) != 2:
        raise ModelError(f"expected two prefixes (angular momentum and the other vector), got "
                         f"{brief(names)}", entry="names")
    return [str(n) for n in names]


def euler_poisson(system, names=None):
    r"""
    The Euler--Poisson system of a heavy rigid body with a fixed point.

    INPUT:

    - ``system`` -- a mechanical system (see
      :class:`~sage_dynsym.mechanics.system.MechanicalSystem`) with one
      massive body; any other bodies are massless carriers (for Euler
      angles); every joint is at the origin and fixed, so the massive body
      turns about a fixed point `O`. Its force field is a uniform field
      along one inertial axis (``uniform_gravity: [0, 0, -g]``) or none;
      no dissipation, no generalized forces
    - ``names`` -- (default: ``['M', 'gamma']``) the prefixes of the two
      vectors

    OUTPUT: a :class:`~sage_dynsym.lie.system.LiePoissonSystem` on `e(3)`;
    its :meth:`~sage_dynsym.lie.system.LiePoissonSystem.reduction` maps
    each variable to its expression in the coordinates and velocities of
    ``system`` (`M = I\omega`, `\gamma_i` the direction cosines of the
    field's axis)

    EXAMPLES: the heavy top in Euler angles::

        sage: from sage_dynsym import MechanicalSystem, RigidBody, UniformGravity
        sage: from sage_dynsym.lie.builders import euler_poisson
        sage: psi, theta, phi, A, B, C, m, g, z0 = var('psi theta phi A B C m g z0')
        sage: top = RigidBody('top', rotations=[(3, psi), (1, theta), (3, phi)], mass=m,
        ....:                 mass_center=[0, 0, z0], inertia=diagonal_matrix([A, B, C]))
        sage: S = euler_poisson(MechanicalSystem([top], [psi, theta, phi],
        ....:                   force_function=UniformGravity([0, 0, -g])))
        sage: S.hamiltonian()
        g*gamma3*m*z0 + 1/2*M1^2/A + 1/2*M2^2/B + 1/2*M3^2/C
        sage: S.reduction()
        {M1: (dpsi*sin(phi)*sin(theta) + dtheta*cos(phi))*A,
         M2: (dpsi*cos(phi)*sin(theta) - dtheta*sin(phi))*B,
         M3: (dpsi*cos(theta) + dphi)*C,
         gamma1: sin(phi)*sin(theta),
         gamma2: cos(phi)*sin(theta),
         gamma3: cos(theta)}

    TESTS::

        sage: euler_poisson(MechanicalSystem([top, RigidBody('ball', mass=m)], [psi, theta, phi]))
        Traceback (most recent call last):
        ...
        ModelError: bodies: euler_poisson needs one massive body, got 2: top, ball
        sage: tilted = UniformGravity([0, -g, -g])
        sage: euler_poisson(MechanicalSystem([top], [psi, theta, phi], force_function=tilted))
        Traceback (most recent call last):
        ...
        ModelError: force_function: euler_poisson needs the field along one inertial axis, got (0, -g, -g) (turn the inertial axes)
    """
    model_argument(system, ('bodies', 'force_terms'), "system", "a mechanical system",
                   hint="e.g. euler_poisson(MechanicalSystem([top], [psi, theta, phi], "
                   "force_function=UniformGravity([0, 0, -g])))")
    prefixes = _prefixes(names, ['M', 'gamma'])
    bodies = system.bodies()
    massive = [k for k, b in enumerate(bodies, 1) if not b.is_massless()]
    if len(massive) != 1:
        raise ModelError(f"euler_poisson needs one massive body, got {len(massive)}: "
                         f"{', '.join(b.name() for b in bodies if not b.is_massless())}",
                         entry="bodies")
    k = massive[0]
    body = bodies[k - 1]
    for i, b in enumerate(bodies):
        velocity = b.velocity()
        if any(not SR(c).is_zero() for c in b.joint()) or (
                velocity is not None and any(not SR(c).is_zero() for c in velocity)):
            raise ModelError(f"euler_poisson needs a fixed point: the joint of body "
                             f"{b.name()!r} must be the origin, at rest", entry=f"bodies[{i}]")
    if not SR(system.dissipation()).is_zero() or any(
            not SR(f).is_zero() for f in system.generalized_forces()):
        raise ModelError("euler_poisson needs a conservative system (no dissipation, no "
                         "generalized forces)", entry="forces")
    field = system.force_field()
    axis, g_axis = 2, SR(0)
    if field is not None:
        if not hasattr(field, 'acceleration'):
            raise ModelError(f"euler_poisson needs a uniform field (or none), got {field}",
                             entry="force_function")
        g = vector(SR, field.acceleration())
        nonzero = [i for i in range(3) if not g[i].is_zero()]
        if len(nonzero) > 1:
            raise ModelError(f"euler_poisson needs the field along one inertial axis, got {g} "
                             "(turn the inertial axes)", entry="force_function")
        if nonzero:
            axis, g_axis = nonzero[0], g[nonzero[0]]
    I = matrix(SR, body.inertia())
    Iinv = _inverse(I, "inertia")
    M = [SR.var(f"{prefixes[0]}{i}") for i in range(1, 4)]
    gamma = [SR.var(f"{prefixes[1]}{i}") for i in range(1, 4)]
    Mv, gv = vector(SR, M), vector(SR, gamma)
    rc = vector(SR, body.mass_center())
    H = (Mv * (Iinv * Mv)) / 2 - body.mass() * g_axis * (rc * gv)
    H = collect(H, M + gamma)
    alpha = system.direction_cosines(k)
    momentum = I * vector(SR, system.angular_velocity(k))
    reduction = {Mi: _simplify(e) for Mi, e in zip(M, momentum)}
    reduction.update({gi: _simplify(alpha[axis, i]) for i, gi in enumerate(gamma)})
    return LiePoissonSystem('e3', H, variables=M + gamma, parameters=system.parameters(),
                            name=system.name(), reduction=reduction)


def _simplify(e):
    e = SR(e)
    try:
        return e.factor()
    except (TypeError, ValueError, ArithmeticError):
        return e


def kirchhoff(body=None, added_masses=None, inertia=None, mass=None, mass_center=None,
              names=None, parameters=None, name=None):
    r"""
    Kirchhoff's equations of a rigid body in an ideal fluid.

    INPUT:

    - ``body`` -- (optional) a rigid body (its mass, inertia tensor about
      the origin `O` of its axes, and centre of mass), or give:
    - ``inertia``, ``mass``, ``mass_center`` -- the body's inertia tensor
      about `O`, its mass and its centre of mass (default the origin)
    - ``added_masses`` -- (optional) the fluid's symmetric `6\times 6`
      matrix `\Lambda_f` in the order `(\Omega, V)` (Lamb's coefficients
      `A, B, C, \dots`); default zero (a body in vacuum)
    - ``names`` -- (default: ``['M', 'p']``) the prefixes of the impulsive
      moment and force
    - ``parameters``, ``name`` -- as for
      :class:`~sage_dynsym.lie.system.LiePoissonSystem`

    OUTPUT: a :class:`~sage_dynsym.lie.system.LiePoissonSystem` on `e(3)`
    with the quadratic Hamiltonian `H = \tfrac12 (M, p)^T\Lambda^{-1}(M, p)`

    EXAMPLES: a body with three planes of symmetry, centre of mass at
    `O`: `H = \tfrac12\sum M_i^2/(I_i + J_i) + p_i^2/(m + K_i)`::

        sage: from sage_dynsym.lie.builders import kirchhoff
        sage: from sage_dynsym import RigidBody
        sage: I1, I2, I3, J1, J2, J3, m, K1, K2, K3 = var('I1 I2 I3 J1 J2 J3 m K1 K2 K3')
        sage: ball = RigidBody('ball', mass=m, inertia=diagonal_matrix([I1, I2, I3]))
        sage: S = kirchhoff(ball, diagonal_matrix([J1, J2, J3, K1, K2, K3]))
        sage: S.equations()[0]
        (I2 - I3 + J2 - J3)*M2*M3/((I2 + J2)*(I3 + J3)) + (K2 - K3)*p2*p3/((K2 + m)*(K3 + m))

    The centre of mass off `O` couples `M` and `p`::

        sage: a = var('a')
        sage: S = kirchhoff(inertia=diagonal_matrix([I1, I2, I3]), mass=m, mass_center=[0, 0, a])
        sage: bool(S.hamiltonian().diff(var('M1'), var('p2')) != 0)
        True

    TESTS::

        sage: kirchhoff(inertia=diagonal_matrix([I1, I2, I3]), mass=m, added_masses=[[1, 2]])
        Traceback (most recent call last):
        ...
        ModelError: added_masses: expected a symmetric 6x6 matrix (order Omega, V), got [[1, 2]]
        sage: kirchhoff(inertia=diagonal_matrix([I1, I2, 0]), mass=m)
        Traceback (most recent call last):
        ...
        ModelError: inertia: the matrix is singular: ...
        sage: kirchhoff()
        Traceback (most recent call last):
        ...
        ModelError: body: give a rigid body, or its inertia and mass
    """
    prefixes = _prefixes(names, ['M', 'p'])
    if body is not None:
        model_argument(body, ('inertia', 'mass', 'mass_center', 'name'), "body", "a rigid body",
                       hint="kirchhoff(RigidBody(...)), or kirchhoff(inertia=..., mass=...)")
        inertia, mass, mass_center = body.inertia(), body.mass(), body.mass_center()
        name = name or body.name()
    if inertia is None or mass is None:
        raise ModelError("give a rigid body, or its inertia and mass", entry="body")
    try:
        I = matrix(SR, inertia)
        if I.dimensions() != (3, 3):
            raise ValueError
    except (TypeError, ValueError) as err:
        raise ModelError(f"expected a 3x3 matrix, got {brief(inertia)}", entry="inertia") \
            from err
    m = SR(mass)
    rc = vector(SR, mass_center if mass_center is not None else (0, 0, 0))
    cross = m * _cross_matrix(rc)
    body_matrix = block_matrix(SR, [[I, cross], [-cross, m * identity_matrix(SR, 3)]],
                               subdivide=False)
    fluid = matrix(SR, 6, 6)
    if added_masses is not None:
        try:
            fluid = matrix(SR, added_masses)
            ok = fluid.dimensions() == (6, 6) and fluid.is_symmetric()
        except (TypeError, ValueError):
            ok = False
        if not ok:
            raise ModelError(f"expected a symmetric 6x6 matrix (order Omega, V), got "
                             f"{brief(added_masses)}", entry="added_masses")
    Lam = body_matrix + fluid
    entry = "inertia" if added_masses is None and rc.is_zero() else "added_masses"
    inverse = _inverse(Lam, entry)
    M = [SR.var(f"{prefixes[0]}{i}") for i in range(1, 4)]
    p = [SR.var(f"{prefixes[1]}{i}") for i in range(1, 4)]
    z = vector(SR, M + p)
    H = collect((z * (inverse * z)) / 2, M + p)
    return LiePoissonSystem('e3', H, variables=M + p, parameters=parameters, name=name)
