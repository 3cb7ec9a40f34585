r"""
Derivatives of the recursive accelerations through inverse dynamics

The accelerations `\ddot q(q, \dot q)` of a tree solve `\tau(q, \dot q,
\ddot q) = Q(q, \dot q)`, `\tau` the generalized forces of the bodies'
motion (the recursive Newton--Euler algorithm with the accelerations) and
`Q` the applied ones. Differentiating at a fixed `\ddot q` ([CM2018]_):

.. MATH::

    \frac{\partial\ddot q}{\partial x} = M^{-1}\,\frac{\partial(Q - \tau)}
    {\partial x}\Big|_{\ddot q},

so one direction of the state costs the forward-mode derivative of the
Newton--Euler pass (cheaper than that of the articulated-body algorithm,
whose articulated inertias depend on the coordinates) and one solve by `M`.
The solve is the derivative of the articulated-body algorithm with respect
to its generalized forces: the articulated inertias and their factors are
computed once per call, only the sweeps of the forces and accelerations run
per direction ([Fea2008]_, Table 7.1).

:func:`jacobian_graph` writes all of it in one
:class:`~sage_dynsym.numerics.graph.ExpressionGraph`, for
:func:`~sage_dynsym.numerics.compiler.jacobian_c_source`.

REFERENCES:

.. [CM2018] J. Carpentier and N. Mansard, *Analytical derivatives of rigid
   body dynamics algorithms*, Robotics: Science and Systems, 2018.
"""
from .derivatives import tangent
from .articulated_body import articulated_accelerations
from .newton_euler import applied_forces, inverse_dynamics

__all__ = ['inverse_dynamics_graph', 'jacobian_graph']


def inverse_dynamics_graph(form):
    r"""
    ``(graph, tau)``: the generalized forces `\tau(q, \dot q, \ddot q)`
    of the motion of the tree of the
    :class:`~sage_dynsym.numerics.recursive.RecursiveForm` ``form`` (the
    recursive Newton--Euler algorithm with the accelerations, loads
    subtracted), reading `(q, \dot q)` from ``x[0..2n)`` and `\ddot q` from
    ``x[2n..3n)``: Lagrange's equations of the tree are `\tau = Q`, `Q` the
    applied generalized forces.

    EXAMPLES: a mass on a wheel turning freely about `z` (the mass at
    distance `r` on a radial slider): `\tau_\varphi = (J + m r^2)
    \ddot\varphi + 2 m r \dot r\dot\varphi`, `\tau_r = m(\ddot r - r
    \dot\varphi^2)`::

        sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
        sage: from sage_dynsym.numerics.recursive import RecursiveForm
        sage: from sage_dynsym.numerics.rnea_derivatives import inverse_dynamics_graph
        sage: from sage_dynsym.numerics.compiler import run_python
        sage: phi, r = var('phi r')
        sage: wheel = TreeBody(0, rotations=[(3, phi)], inertia=diagonal_matrix([0, 0, 2]))
        sage: slider = TreeBody(1, joint=[r, 0, 0], mass=3)
        sage: G, tau = inverse_dynamics_graph(RecursiveForm(BodyTree([wheel, slider], [phi, r])))
        sage: run_python(G.python_source(tau), '_graph')(0, [0.0, 0.5, 2.0, 1.0, 4.0, 0.5], [])
        [17.0000000000000, -4.50000000000000]
        sage: (2 + 3*0.5^2)*4 + 2*3*0.5*1*2, 3*(0.5 - 0.5*2^2)
        (17.0000000000000, -4.50000000000000)
    """
    kin = form.kinematics()
    ddq = [kin.G.input('x', 2 * kin.n + i) for i in range(kin.n)]
    return kin.G, inverse_dynamics(kin, ddq)


def jacobian_graph(form):
    r"""
    ``(graph, columns, pivots, inputs)`` of the Jacobian of the recursive
    right-hand side of the
    :class:`~sage_dynsym.numerics.recursive.RecursiveForm` ``form`` by the
    state (see the module documentation), for
    :func:`~sage_dynsym.numerics.compiler.jacobian_c_source`, or ``None``
    when the articulated-body algorithm does not apply (constraints, a
    coordinate that moves two bodies).

    The graph reads the state from ``x[0..2n)``, the direction from
    ``x[2n..4n)``; ``x[4n..6n)`` (``inputs`` is `6n`) are zero: the
    generalized forces by which the solve is differentiated and the
    offsets that make the accelerations fixed in the Newton--Euler pass
    nodes of their own.

    EXAMPLES: a pendulum, `\ddot\varphi = -(g/l)\sin\varphi`::

        sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
        sage: from sage_dynsym.numerics.recursive import RecursiveForm
        sage: from sage_dynsym.numerics.rnea_derivatives import jacobian_graph
        sage: phi, m, l, g = var('phi m l g')
        sage: rod = TreeBody(0, rotations=[(1, phi)], mass=m, mass_center=[0, 0, -l],
        ....:                inertia=diagonal_matrix([m*l^2, m*l^2, 0]))
        sage: G, columns, pivots, inputs = jacobian_graph(RecursiveForm(
        ....:     BodyTree([rod], [phi], gravity=[0, 0, -g]), values={g: 9.81, l: 2, m: 1}))
        sage: from sage_dynsym.numerics.compiler import run_python
        sage: f = run_python(G.python_source(columns[0][0]), '_graph')
        sage: f(0, [0.5, 0.0, 1.0, 0.0, 0.0, 0.0], [])
        [0.0, -4.30...]
        sage: -9.81 / 2 * cos(0.5)
        -4.30...
    """
    tree = form.tree()
    if tree.constraints() or tree.velocity_constraints():
        return None
    kin = form.kinematics()
    G, n = kin.G, kin.n
    applied = applied_forces(kin)
    forcing = [G.input('x', 4 * n + i) for i in range(n)]
    result = articulated_accelerations(kin, [G.add(a, b) for a, b in zip(applied, forcing)])
    if result is None:
        return None
    ddq, pivots = result
    fixed = [G.add(a, G.input('x', 5 * n + i)) for i, a in enumerate(ddq)]
    residual = [G.sub(a, b) for a, b in zip(applied, inverse_dynamics(kin, fixed))]
    seeds = {G.input('x', i): G.input('x', 2 * n + i) for i in range(n)}
    seeds.update((a, G.zero) for a in fixed)
    solve = dict(zip(forcing, tangent(G, residual, seeds)))
    columns = [([G.zero] * n + tangent(G, ddq, solve), 0, n)]
    # by the velocities the articulated inertias are constant: the
    # derivative of the articulated-body algorithm itself is the cheaper
    seeds = {G.input('x', n + i): G.input('x', 3 * n + i) for i in range(n)}
    columns.append(([seeds[G.input('x', n + i)] for i in range(n)] + tangent(G, ddq, seeds),
                    n, n))
    return G, columns, pivots, 6 * n
