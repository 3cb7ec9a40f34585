r"""
Recursive numerical right-hand sides of trees of rigid bodies

For a :class:`~sage_dynsym.numerics.body_tree.BodyTree` the accelerations
are computed without forming the equations of motion symbolically: the
recursive algorithms of rigid-body dynamics [Fea2008]_ are written out
once, symbolically, as an :class:`~sage_dynsym.numerics.graph.ExpressionGraph`
with the model's structure folded in (zero and constant entries, the axes of
the elementary rotations, parameter values when asked), and the graph is
compiled to C:

- the velocities and the accelerations at `\ddot q = 0` frame by frame
  (each joint is a translation by the joint point `r_{0k}(q, t)` followed
  by the body's elementary rotations, whose angles may be coordinates,
  constants or functions of `t`), with uniform gravity as an acceleration
  of the inertial frame;
- the recursive Newton--Euler pass [Fea2008]_ (Table 5.1): forces of the
  bodies about their joint points, summed from the leaves and projected on
  the joints' axes -- the inertial, gravity and load terms of the
  equations at `\ddot q = 0`;
- the composite rigid-body algorithm [Fea2008]_ (Table 6.2) for the mass
  matrix `M`;
- the factorization `M = L^T D L` in the order of the tree, leaves first,
  which creates no fill-in for a tree ([Fea2008]_, Section 6.5, "LTDL"),
  and the solution of `M \ddot q = F` (with holonomic constraints: the
  multipliers from `J M^{-1} J^T \mu = \gamma - J M^{-1} F`; constraints
  on the velocities `A\dot q + b = 0`, such as rolling without slipping,
  add their rows `A\ddot q = \gamma_A` to those of `J`, see
  :mod:`~sage_dynsym.numerics.form`).

The rest of the forcing -- the dissipation `\partial R/\partial \dot q`,
the generalized forces, the gradient of a force function given as an
expression, and for a prescribed joint velocity `v_{0k}` that is not the
derivative of `r_{0k}` the terms by which Lagrange's equations of the
kinetic energy differ from Kane's -- is differentiated symbolically (small
expressions) and added. The equations are the Lagrange equations of
:mod:`~sage_dynsym.dynamics.lagrangian` for the same model; only the way
to the numbers differs.

EXAMPLES: a pendulum `\ddot\varphi = -(g/l)\sin\varphi`::

    sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
    sage: from sage_dynsym.numerics.recursive import RecursiveForm
    sage: phi, m, l, g = var('phi m l g')
    sage: rod = TreeBody(0, rotations=[(1, phi)], mass=m, mass_center=[0, 0, -l],
    ....:                inertia=diagonal_matrix([m*l^2, m*l^2, 0]))
    sage: F = RecursiveForm(BodyTree([rod], [phi], gravity=[0, 0, -g])); F
    Recursive form of a tree of 1 body in (phi), parameters (g, l, m)
    sage: K = F.kernel()
    sage: K(0.0, [pi.n()/2, 0.0], [9.81, 2.0, 1.0])
    array([ 0.   , -4.905])

REFERENCES:

.. [Fea2008] R. Featherstone, *Rigid Body Dynamics Algorithms*, Springer
   2008: chapters 5 (recursive Newton--Euler), 6 (composite rigid body,
   sparse factorization ``LTDL``).
"""
from sage.symbolic.ring import SR

from ..errors import AnalysisError
from ..symbols import t as _t
from .articulated_body import articulated_accelerations
from .composite_body import mass_matrix
from .form import constraint_terms, resolved, velocity_constraint_terms
from .graph import ExpressionGraph, SymbolicConverter
from .newton_euler import applied_forces, forcing, generalized_forces, inverse_dynamics
from .tree_kinematics import TreeKinematics, not_applicable, tree_order
from .tree_solve import PIVOT_TOLERANCE, dense_solve, ltdl

__all__ = ['RecursiveForm', 'unsupported', 'tree_accelerations', 'graph_kinematics',
           'generalized_forces', 'inverse_dynamics', 'check_backend', 'compiled_library',
           'LARGE_GRAPH', 'PIVOT_TOLERANCE']


def graph_kinematics(tree, values=None):
    r"""
    The :class:`~sage_dynsym.numerics.tree_kinematics.TreeKinematics` of
    ``tree`` over a new :class:`~sage_dynsym.numerics.graph.ExpressionGraph`
    whose inputs are ``t``, the state ``x`` (coordinates, then velocities)
    and the parameters ``p`` of ``tree`` without those of ``values``
    (numbers folded into the graph).

    EXAMPLES::

        sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
        sage: from sage_dynsym.numerics.recursive import graph_kinematics
        sage: x, m, k = var('x m k')
        sage: K = graph_kinematics(BodyTree([TreeBody(0, joint=[x, 0, 0], mass=m)], [x],
        ....:                               potential=-k*x^2), {k: 2})
        sage: K.G.show(K.convert(k*x + m))
        'p[0] + (x[0]*2.0)'
    """
    G = ExpressionGraph()
    values = values or {}
    q, dq = tree.coordinates(), tree.velocities()
    inputs = {_t: G.input('t')}
    inputs.update({v: G.input('x', i) for i, v in enumerate(q + dq)})
    parameters = [v for v in tree.parameters() if v not in values]
    inputs.update({v: G.input('p', j) for j, v in enumerate(parameters)})
    return TreeKinematics(tree, G, SymbolicConverter(G, inputs, values))


def tree_accelerations(kin, solver='auto'):
    r"""
    The accelerations `\ddot q` (in the order of the coordinates) of the
    tree of ``kin`` (a
    :class:`~sage_dynsym.numerics.tree_kinematics.TreeKinematics`, in
    either arithmetic), the margins of the pivots of the factorizations
    (not positive where the system is singular, see
    :mod:`~sage_dynsym.numerics.tree_solve`), and the solver used:
    ``'articulated'`` (the articulated-body algorithm: models without
    constraints whose coordinates each move one body) or ``'ltdl'`` (the
    mass matrix of the composite rigid-body algorithm, factorized; with
    holonomic constraints the multipliers from `J M^{-1} J^T \mu = \gamma
    - J M^{-1} F`, the rows `A\ddot q = \gamma_A` of the constraints on
    the velocities added to those of `J`).

    EXAMPLES: a point on the circle `x^2 + y^2 = 1`, in the symbolic
    arithmetic; at `(1, 0)` moving with speed 1 its acceleration is the
    centripetal one::

        sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
        sage: from sage_dynsym.numerics.spatial import SymbolicArithmetic
        sage: from sage_dynsym.numerics.tree_kinematics import TreeKinematics
        sage: from sage_dynsym.numerics.recursive import tree_accelerations
        sage: x, y, dx, dy = var('x y dx dy')
        sage: tree = BodyTree([TreeBody(0, joint=[x, y, 0], mass=1)], [x, y],
        ....:                 constraints=[x^2 + y^2 - 1])
        sage: ddq, pivots, solver = tree_accelerations(TreeKinematics(tree, SymbolicArithmetic()))
        sage: solver, [e.subs(x=1, y=0, dx=0, dy=1) for e in ddq]
        ('ltdl', [-1, 0])
    """
    G, tree = kin.G, kin.tree
    constraints = tree.constraints()
    velocity_constraints = tree.velocity_constraints()
    if solver != 'ltdl' and not constraints and not velocity_constraints:
        result = articulated_accelerations(kin, applied_forces(kin))
        if result is not None:
            return result + ('articulated',)
    if solver == 'articulated':
        raise not_applicable("the articulated-body algorithm needs a model without "
                             "constraints whose coordinates each move one body")
    M = mass_matrix(kin)
    F = forcing(kin)
    pivots = []
    solve = ltdl(G, M, tree_order(kin.steps, kin.n), pivots)
    ddq = solve(F)
    if constraints or velocity_constraints:
        # the rows J ddq = gamma of the holonomic constraints and A ddq =
        # gamma_A of those on the velocities take the same multipliers'
        # elimination (the constraint forces J^T mu + A^T lambda)
        J, gamma, _ = constraint_terms(constraints, kin.q, kin.dq)
        A, gamma_A, _ = velocity_constraint_terms(velocity_constraints, kin.q, kin.dq)
        J = [[kin.convert(e) for e in row] for row in J + A]
        gamma = [kin.convert(e) for e in gamma + gamma_A]
        Y = [solve(row) for row in J]
        m = len(J)
        S = [[G.dot(J[a], Y[b]) for b in range(m)] for a in range(m)]
        rhs = [G.sub(gamma[a], G.dot(J[a], ddq)) for a in range(m)]
        mu = dense_solve(G, S, rhs, pivots, [S[a][a] for a in range(m)])
        ddq = [G.add(ddq[i], G.dot([Y[b][i] for b in range(m)], mu)) for i in range(kin.n)]
    return ddq, pivots, 'ltdl'


#: Graphs of more nodes are compiled at ``-O1``: for their straight-line
#: code ``-O2`` takes two to three times as long (100 links: 25 s against
#: 12 s) and the calls are not measurably faster.
LARGE_GRAPH = 20_000


def check_backend(backend, what):
    r"""
    Refuse a ``backend`` other than ``'auto'``, ``'c'`` and ``'python'``
    (``what`` names the call in the error).

    EXAMPLES::

        sage: from sage_dynsym.numerics.recursive import check_backend
        sage: check_backend('c', 'numerical_rhs')
        sage: check_backend(['c'], 'numerical_rhs')
        Traceback (most recent call last):
        ...
        AnalysisError: numerical_rhs: backend must be 'auto', 'c' or 'python', got ['c']
    """
    if not isinstance(backend, str) or backend not in ('auto', 'c', 'python'):
        raise AnalysisError(f"backend must be 'auto', 'c' or 'python', got {backend!r}",
                            entry=what)


def compiled_library(graph, source, backend, what, flags=None):
    r"""
    The C library of the code of ``graph`` for ``backend``, or ``None``
    where Python evaluates it: with ``backend='python'``, or with
    ``'auto'`` when no C compiler works (said at verbose level 1); with
    ``'c'`` a failure is an error. ``source`` is a function giving the C
    source (only called when C is tried), ``what`` names the code in errors,
    ``flags`` are the compiler's (default:
    :func:`~sage_dynsym.numerics.compiler.optimization_flags` with the
    limit :data:`LARGE_GRAPH`).

    EXAMPLES::

        sage: from sage_dynsym.numerics.graph import ExpressionGraph
        sage: from sage_dynsym.numerics.recursive import compiled_library
        sage: compiled_library(ExpressionGraph(), None, 'python', 'numerical_rhs') is None
        True
        sage: compiled_library(ExpressionGraph(), None, 'fortran', 'numerical_rhs')
        Traceback (most recent call last):
        ...
        AnalysisError: numerical_rhs: backend must be 'auto', 'c' or 'python', got 'fortran'
    """
    from .compiler import compile_c, optimization_flags
    from sage.misc.verbose import verbose
    check_backend(backend, what)
    if backend == 'python':
        return None
    try:
        return compile_c(source(), flags=flags or optimization_flags(graph, LARGE_GRAPH))
    except (AnalysisError, OSError) as error:
        if backend == 'c':
            raise
        verbose(f"C backend unavailable ({error}); using Python", level=1)
        return None

def unsupported(tree):
    r"""
    Why the recursive form cannot represent ``tree``, or ``None`` when it
    can: the bodies' masses, mass centres and inertia tensors must be
    constant (parameters only), the prescribed joint velocities linear in
    the velocities, and every function a known one.

    EXAMPLES::

        sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
        sage: from sage_dynsym.numerics.recursive import unsupported
        sage: x, m = var('x m')
        sage: unsupported(BodyTree([TreeBody(0, joint=[x, 0, 0], mass=m)], [x])) is None
        True
        sage: unsupported(BodyTree([TreeBody(0, joint=[x, 0, 0], mass=m*x)], [x]))
        'the mass, mass centre or inertia of body 1 depends on the coordinates, velocities or t'
        sage: unsupported(BodyTree([TreeBody(0, joint=[x, 0, 0], velocity=[var('dx')^2, 0, 0])], [x]))
        'the relative velocity of body 1 is not linear in the velocities'
        sage: unsupported(BodyTree([TreeBody(0, joint=[function('f')(x), 0, 0])], [x]))
        'f is not a known function (the equations take definitions of functions)'
    """
    from .expressions import symbols_and_functions
    k = tree.varying_inertia()
    if k is not None:
        return (f"the mass, mass centre or inertia of body {k} depends on the "
                "coordinates, velocities or t")
    k = tree.nonlinear_velocity()
    if k is not None:
        return f"the relative velocity of body {k} is not linear in the velocities"
    functions = symbols_and_functions(tree.expressions())[1]
    if functions:
        return (f"{', '.join(functions)} {'is' if len(functions) == 1 else 'are'} not a known "
                "function (the equations take definitions of functions)")
    return None


class RecursiveForm:
    r"""
    The recursive right-hand side of a
    :class:`~sage_dynsym.numerics.body_tree.BodyTree` (see the module
    documentation), usable wherever a
    :class:`~sage_dynsym.numerics.form.NumericalForm` is: by
    :class:`~sage_dynsym.numerics.rhs.RightHandSide` and
    :func:`~sage_dynsym.numerics.simulate.simulate`.

    INPUT:

    - ``tree`` -- a :class:`~sage_dynsym.numerics.body_tree.BodyTree`
    - ``energy`` -- (optional) a conserved energy, or a function without
      arguments computing it when it is first asked for
    - ``solver`` -- ``'auto'`` (default), ``'articulated'`` or ``'ltdl'``:
      how the accelerations are found, by the articulated-body algorithm
      ([Fea2008]_, Table 7.1; `O(n)` operations, for models without
      constraints whose coordinates each move one body, the default for
      them) or from the mass matrix of the composite rigid-body algorithm
      factorized as `L^T D L`
    - ``values`` -- (optional) values of parameters to write into the code
      as numbers (folded with the rest); the others are inputs of the
      kernel, so that one compilation serves every set of values

    Raises :class:`~sage_dynsym.errors.AnalysisError` when the tree is
    outside the recursive form (see :func:`unsupported`).

    EXAMPLES: see the module documentation; a slider on a turntable turning
    at the prescribed rate `w` (a rheonomic rotation) is pushed outwards by
    the centrifugal force `m w^2 x`::

        sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
        sage: from sage_dynsym.numerics.recursive import RecursiveForm
        sage: x, w, m = var('x w m'); t = var('t')
        sage: table = TreeBody(0, rotations=[(3, w*t)])
        sage: bead = TreeBody(1, joint=[x, 0, 0], mass=m)
        sage: F = RecursiveForm(BodyTree([table, bead], [x]))
        sage: F.kernel('python')(0.0, [2.0, 0.0], [1.0, 3.0])     # m = 1, w = 3
        array([ 0., 18.])
        sage: F.state(), F.parameters(), F.order(), F.solve_size()
        ([x, dx], [m, w], 2, None)

    The same with the rate folded into the code::

        sage: F = RecursiveForm(BodyTree([table, bead], [x]), values={w: 3})
        sage: F.parameters(), F.kernel('python')(0.0, [2.0, 0.0], [1.0])
        ([m], array([ 0., 18.]))

    TESTS::

        sage: RecursiveForm(BodyTree([TreeBody(0, joint=[x, 0, 0], mass=m*t)], [x]))
        Traceback (most recent call last):
        ...
        AnalysisError: numerical_rhs: the recursive form does not apply: the mass, mass centre or inertia of body 1 depends on the coordinates, velocities or t
    """

    def __init__(self, tree, energy=None, solver='auto', values=None):
        reason = unsupported(tree)
        if reason is not None:
            raise AnalysisError(f"the recursive form does not apply: {reason}",
                                entry="numerical_rhs")
        if solver not in ('auto', 'articulated', 'ltdl'):
            raise AnalysisError(f"solver must be 'auto', 'articulated' or 'ltdl', got "
                                f"{solver!r}", entry="numerical_rhs")
        self._solver = solver
        self._tree = tree
        self._values = {}
        if values:
            by_name = {str(k): v for k, v in values.items()}
            self._values = {p: float(by_name[str(p)]) for p in tree.parameters()
                            if str(p) in by_name}
        self._energy = energy
        self._state = tree.coordinates() + tree.velocities()
        self._kernels = {}
        self._graph = None
        self._jacobian = {}

    def __repr__(self):
        n = len(self._tree.bodies())
        return (f"Recursive form of a tree of {n} bod{'y' if n == 1 else 'ies'} in "
                f"({', '.join(map(str, self._tree.coordinates()))}), parameters "
                f"({', '.join(map(str, self.parameters()))})")

    def kinematics(self):
        r"""
        A new kinematic pass of the tree over a new expression graph, the
        parameter values of the form folded in (see
        :func:`graph_kinematics`): for code built from the same algorithms,
        such as the inverse dynamics
        (:func:`~sage_dynsym.numerics.newton_euler.inverse_dynamics`).

        EXAMPLES::

            sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
            sage: from sage_dynsym.numerics.recursive import RecursiveForm
            sage: x, m = var('x m')
            sage: F = RecursiveForm(BodyTree([TreeBody(0, joint=[x, 0, 0], mass=m)], [x]),
            ....:                   values={m: 2})
            sage: K = F.kinematics(); K.n, K.G.show(K.convert(m*x))
            (1, 'x[0]*2.0')
        """
        return self._tree.kinematics('graph', self._values)

    def tree(self):
        r"""The :class:`~sage_dynsym.numerics.body_tree.BodyTree`.

        EXAMPLES::

            sage: from sage_dynsym.numerics.body_tree import BodyTree
            sage: from sage_dynsym.numerics.recursive import RecursiveForm
            sage: RecursiveForm(BodyTree([], [])).tree()
            Tree of 0 bodies in (), parameters ()
        """
        return self._tree

    def solver(self):
        r"""
        The solver: ``'articulated'`` or ``'ltdl'`` once the graph is
        built (see the class documentation), else the one asked for.

        EXAMPLES::

            sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
            sage: from sage_dynsym.numerics.recursive import RecursiveForm
            sage: x, y = var('x y')
            sage: F = RecursiveForm(BodyTree([TreeBody(0, joint=[x, y, 0], mass=1)], [x, y]))
            sage: F.solver(), F.graph() is not None, F.solver()
            ('auto', True, 'articulated')
            sage: F = RecursiveForm(BodyTree([TreeBody(0, joint=[x, y, 0], mass=1)], [x, y],
            ....:                            constraints=[x - y^2]))
            sage: F.graph() is not None, F.solver()
            (True, 'ltdl')
        """
        return self._solver

    def order(self):
        r"""2: the equations are of second order.

        EXAMPLES: see the class documentation.
        """
        return 2

    def state(self):
        r"""The coordinates then the velocities.

        EXAMPLES: see the class documentation.
        """
        return list(self._state)

    def parameters(self):
        r"""The parameters, in the order of the parameter array of the kernel.

        EXAMPLES: see the class documentation.
        """
        return [p for p in self._tree.parameters() if p not in self._values]

    def singular_chart(self, x):
        r"""
        The message naming a rotation chart singular at the state ``x`` (a
        body's three successive elementary rotations by coordinates, whose
        angular-velocity matrix has the determinant `\pm\cos` of the middle
        angle when the outer axes differ (Cardan angles) and `\pm\sin` of it
        when they are equal (Euler angles)), or ``None``.

        The compiled right-hand side and Jacobian refuse the states where
        a pivot is small against its scale (see
        :data:`~sage_dynsym.numerics.tree_solve.PIVOT_TOLERANCE`); this says
        why when the cause is the chart.

        EXAMPLES: a free body by the (3, 2, 1) sequence, at `\theta = \pi/2`::

            sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
            sage: from sage_dynsym.numerics.recursive import RecursiveForm
            sage: psi, theta, phi = var('psi theta phi')
            sage: base = TreeBody(0, rotations=[(3, psi), (2, theta), (1, phi)], mass=1,
            ....:                 inertia=diagonal_matrix([1, 2, 3]), name='base')
            sage: F = RecursiveForm(BodyTree([base], [psi, theta, phi]))
            sage: F.singular_chart([0.0, float(pi/2), 0.0, 0, 0, 0])
            "the rotation chart of body 'base' is singular at theta = pi/2 (gimbal lock): ..."
            sage: F.singular_chart([0.0, 1.5, 0.0, 0, 0, 0]) is None
            True
        """
        import math
        position = {q: i for i, q in enumerate(self._tree.coordinates())}
        for k, body in enumerate(self._tree.bodies(), 1):
            rotations = body.rotations()
            for (a1, _), (a2, angle), (a3, _) in zip(rotations, rotations[1:], rotations[2:]):
                if a1 == a2 or a2 == a3 or angle not in position:
                    continue
                value = float(x[position[angle]])
                if abs(math.cos(value) if a1 != a3 else math.sin(value)) > 1e-5:
                    continue
                where = str(SR(round(2 * value / math.pi)) * SR.pi() / 2)
                where = {'1/2*pi': 'pi/2', '-1/2*pi': '-pi/2'}.get(where, where)
                name = repr(body.name()) if body.name() else f"number {k}"
                return (f"the rotation chart of body {name} is singular at {angle} = "
                        f"{where} (gimbal lock): its angular velocity does not determine the "
                        f"rates of the angles (state {list(map(float, x))}); use another "
                        f"sequence of axes for attitudes near this one, e.g. a chart whose "
                        f"middle angle is away from {where} there")
        return None

    def solve_size(self):
        r"""``None``: the kernel solves for the accelerations itself.

        EXAMPLES: see the class documentation.
        """
        return None

    def constraints(self):
        r"""
        The holonomic constraints, their Jacobian and `\partial f/\partial t`
        (as :meth:`NumericalForm.constraints
        <sage_dynsym.numerics.form.NumericalForm.constraints>`).

        EXAMPLES::

            sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
            sage: from sage_dynsym.numerics.recursive import RecursiveForm
            sage: x, y = var('x y')
            sage: RecursiveForm(BodyTree([TreeBody(0, joint=[x, y, 0], mass=1)], [x, y],
            ....:                        constraints=[x^2 + y^2 - 1])).constraints()
            ([x^2 + y^2 - 1], [[2*x, 2*y]], [0])
        """
        from .form import constraint_terms
        f = self._tree.constraints()
        J, _, f_t = constraint_terms(f, self._tree.coordinates(), self._tree.velocities())
        return f, J, f_t

    def velocity_constraints(self):
        r"""
        The constraints on the velocities `g_k = A_k\dot q + b_k`, their
        rows `A` and `b` (as :meth:`NumericalForm.velocity_constraints
        <sage_dynsym.numerics.form.NumericalForm.velocity_constraints>`).

        EXAMPLES: a point that must move along `(1, y)`, pushed along `x`::

            sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
            sage: from sage_dynsym.numerics.recursive import RecursiveForm
            sage: x, y, dx, dy = var('x y dx dy')
            sage: F = RecursiveForm(BodyTree([TreeBody(0, joint=[x, y, 0], mass=1)], [x, y],
            ....:                            forces=[1, 0], velocity_constraints=[y*dx - dy]))
            sage: F.velocity_constraints()
            ([dx*y - dy], [[y, -1]], [0])
            sage: F.kernel('python')(0.0, [0.0, 2.0, 1.0, 2.0], [])   # ddx = (1 - y dx dy)/(1 + y^2)
            array([ 1. ,  2. , -0.6,  0.8])
            sage: F.solver()
            'ltdl'
        """
        from .form import velocity_constraint_terms
        g = self._tree.velocity_constraints()
        A, _, b = velocity_constraint_terms(g, self._tree.coordinates(), self._tree.velocities())
        return g, A, b

    def energy(self):
        r"""The conserved energy (``None`` if none), computed when first asked for.

        EXAMPLES::

            sage: from sage_dynsym.numerics.body_tree import BodyTree
            sage: from sage_dynsym.numerics.recursive import RecursiveForm
            sage: x, dx = var('x dx')
            sage: RecursiveForm(BodyTree([], [x]), energy=lambda: dx^2/2).energy()
            1/2*dx^2
        """
        self._energy = resolved(self._energy)
        return self._energy

    def with_functions(self, values):
        r"""``self``: a tree has no unspecified functions.

        EXAMPLES::

            sage: from sage_dynsym.numerics.body_tree import BodyTree
            sage: from sage_dynsym.numerics.recursive import RecursiveForm
            sage: F = RecursiveForm(BodyTree([], [])); F.with_functions({}) is F
            True
        """
        return self

    def graph(self):
        r"""
        ``(graph, outputs, pivots)``: the
        :class:`~sage_dynsym.numerics.graph.ExpressionGraph` of the right-hand
        side, the nodes of `\dot x` and those of the pivots of the
        factorizations (built once).

        EXAMPLES::

            sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
            sage: from sage_dynsym.numerics.recursive import RecursiveForm
            sage: x, k, m = var('x k m')
            sage: F = RecursiveForm(BodyTree([TreeBody(0, joint=[x, 0, 0], mass=m)], [x],
            ....:                            potential=-k*x^2/2))
            sage: G, outputs, pivots = F.graph()
            sage: [G.show(a) for a in outputs]
            ['x[1]', '-((x[0]*p[0])*(1.0/p[1]))']

        The margin of the pivot `m` against its scale, the trace `3m` of
        the translational inertia (see
        :data:`~sage_dynsym.numerics.tree_solve.PIVOT_TOLERANCE`)::

            sage: [G.show(a) for a in pivots]
            ['abs(p[1]) - (1e-12*abs(p[1] + (p[1] + p[1])))']
        """
        if self._graph is None:
            kin = self.kinematics()
            ddq, pivots, self._solver = tree_accelerations(kin, self._solver)
            n = len(ddq)
            G = kin.G
            outputs = [G.input('x', n + i) for i in range(n)] + ddq
            self._graph = (G, outputs, pivots)
        return self._graph

    def kernel(self, backend='auto'):
        r"""
        The compiled evaluation of `\dot x` (a
        :class:`~sage_dynsym.numerics.compiler.Kernel`), built once per
        backend: ``'c'`` (the graph as C, see
        :func:`~sage_dynsym.numerics.compiler.graph_c_source`), ``'python'``,
        or ``'auto'`` (C when a compiler works).

        EXAMPLES: see the class documentation.
        """
        from .compiler import Kernel, graph_c_source, run_python
        check_backend(backend, "numerical_rhs")
        if backend in self._kernels:
            return self._kernels[backend]
        G, outputs, pivots = self.graph()
        header = (f"generated by sage_dynsym: recursive right-hand side of a tree of "
                  f"{len(self._tree.bodies())} bodies in "
                  f"({', '.join(map(str, self._tree.coordinates()))})")
        library = compiled_library(G, lambda: graph_c_source(G, outputs, header, pivots=pivots),
                                   backend, "numerical_rhs")
        kernel = None if library is None else Kernel(self, 'c', library.dynsym_rhs)
        if kernel is None:
            function = run_python(G.python_source(outputs + list(pivots)), '_graph')
            m = len(outputs)

            def evaluate(t, x, p):
                values = function(t, x, p)
                if not all(d > 0 for d in values[m:]):
                    raise ZeroDivisionError
                return values[:m], None
            kernel = Kernel(self, 'python', evaluate)
        self._kernels[backend] = kernel
        return kernel

    def jacobian_graph(self, derivatives=None):
        r"""
        ``(graph, columns, pivots, inputs)``: the derivatives of `\dot x`
        by the state, for
        :func:`~sage_dynsym.numerics.compiler.jacobian_c_source` (the
        direction is read from ``x[2n..4n)``, ``x[4n..inputs)`` are zero):
        ``columns`` gives the derivatives in the directions of the
        coordinates, then in those of the velocities; built once per
        ``derivatives``.

        By ``derivatives(self)`` when given and not ``None`` for the form
        (the inverse dynamics of
        :func:`~sage_dynsym.numerics.rnea_derivatives.jacobian_graph`, which
        :class:`~sage_dynsym.numerics.rhs.StateJacobian` uses), else by
        forward-mode differentiation of the graph of :meth:`graph` (see
        :mod:`~sage_dynsym.numerics.derivatives`).

        EXAMPLES: a pendulum, `\ddot\varphi = -(g/l)\sin\varphi`::

            sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
            sage: from sage_dynsym.numerics.recursive import RecursiveForm
            sage: phi, m, l, g = var('phi m l g')
            sage: rod = TreeBody(0, rotations=[(1, phi)], mass=m, mass_center=[0, 0, -l],
            ....:                inertia=diagonal_matrix([m*l^2, m*l^2, 0]))
            sage: F = RecursiveForm(BodyTree([rod], [phi], gravity=[0, 0, -g]),
            ....:                   values={g: 9.81, l: 2, m: 1})
            sage: from sage_dynsym.numerics.compiler import run_python
            sage: from sage_dynsym.numerics.rnea_derivatives import jacobian_graph
            sage: for method in (None, jacobian_graph):
            ....:     G, columns, pivots, inputs = F.jacobian_graph(method)
            ....:     x = [float(v) for v in [0.5, 0, 1, 1] + [0] * (inputs - 4)]
            ....:     print([run_python(G.python_source(nodes), '_graph')(0, x, [])
            ....:            for nodes, first, count in columns])
            [[0.0, -4.30...], [1.0, 0.0]]
            [[0.0, -4.30...], [1.0, 0.0]]
        """
        from .derivatives import tangent
        if derivatives not in self._jacobian:
            found = None if derivatives is None else derivatives(self)
            if found is None:
                G, outputs, pivots = self.graph()
                m = len(outputs)
                n = m // 2
                columns = []
                for first in (0, n):
                    seeds = {G.input('x', first + i): G.input('x', m + first + i)
                             for i in range(n)}
                    columns.append((tangent(G, outputs, seeds), first, n))
                found = (G, columns, pivots, 2 * m)
            self._jacobian[derivatives] = found
        return self._jacobian[derivatives]

    def jacobian_kernel(self, backend='auto', derivatives=None):
        r"""
        The compiled Jacobian of `\dot x` by the state: a function
        ``jac(t, x, p)`` returning a square NumPy array (raises
        :class:`ZeroDivisionError` where the system is singular), built
        once per backend and ``derivatives`` (see :meth:`jacobian_graph`) as
        :meth:`kernel` (``'c'``: see
        :func:`~sage_dynsym.numerics.compiler.jacobian_c_source`;
        ``'python'``: the derivatives in one direction after the other).

        EXAMPLES: a mass on a spring with a cubic term, `\ddot x = -(k x +
        x^3)/m`::

            sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
            sage: from sage_dynsym.numerics.recursive import RecursiveForm
            sage: x, k, m = var('x k m')
            sage: F = RecursiveForm(BodyTree([TreeBody(0, joint=[x, 0, 0], mass=m)], [x],
            ....:                            potential=-k*x^2/2 - x^4/4))
            sage: for backend in ('python', 'c', 'auto'):
            ....:     print(F.jacobian_kernel(backend)(0.0, [2.0, 1.0], [3.0, 0.5]))
            [[  0.   1.]
             [-30.   0.]]
            [[  0.   1.]
             [-30.   0.]]
            [[  0.   1.]
             [-30.   0.]]
            sage: from sage_dynsym.numerics.rnea_derivatives import jacobian_graph
            sage: print(F.jacobian_kernel(derivatives=jacobian_graph)(0.0, [2.0, 1.0], [3.0, 0.5]))
            [[  0.   1.]
             [-30.   0.]]
        """
        import numpy as np
        from .compiler import (jacobian_c_source, run_python, jacobian_function,
                               optimization_flags, LARGE_JACOBIAN)
        check_backend(backend, "numerical_rhs")
        key = ('jacobian', backend, derivatives)
        if key in self._kernels:
            return self._kernels[key]
        G, columns, pivots, inputs = self.jacobian_graph(derivatives)
        size = 2 * len(self._tree.coordinates())
        header = (f"generated by sage_dynsym: Jacobian of the recursive right-hand side "
                  f"of a tree of {len(self._tree.bodies())} bodies")
        library = compiled_library(
            G, lambda: jacobian_c_source(G, columns, size, header, pivots, inputs),
            backend, "numerical_rhs", flags=optimization_flags(G, LARGE_JACOBIAN))
        function = None if library is None else jacobian_function(library.dynsym_jac, size)
        if function is None:
            outputs = [a for nodes, _, _ in columns for a in nodes]
            python = run_python(G.python_source(outputs + list(pivots)), '_graph')

            def function(t, x, p):
                out = np.empty((size, size))
                extended = [float(v) for v in x] + [0.0] * (inputs - size)
                begin = 0
                for nodes, first, count in columns:
                    for j in range(first, first + count):
                        extended[size + j] = 1.0
                        values = python(t, extended, p)
                        extended[size + j] = 0.0
                        if not all(d > 0 for d in values[len(outputs):]):
                            raise ZeroDivisionError
                        out[:, j] = values[begin:begin + len(nodes)]
                    begin += len(nodes)
                if not np.isfinite(out).all():
                    raise ZeroDivisionError
                return out
        self._kernels[key] = function
        return function

