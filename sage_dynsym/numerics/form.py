r"""
The numerical form of equations of motion: linear systems to solve per step

A record of :mod:`sage_dynsym.analysis.motion` is turned into the blocks
that a numerical right-hand side evaluates at each state and then solves
(no symbolic inverse):

- second order `E(q, \dot q, \ddot q) = 0`: the mass matrix
  `M = \partial E/\partial \ddot q` and the forcing `F = -E|_{\ddot q = 0}`,
  so that `M \ddot q = F`; with holonomic constraints `f_j(q, t) = 0` and
  their multipliers `\mu_j` (the equations containing
  `-\sum_j \mu_j \partial f_j/\partial q_i`) the augmented system

  .. MATH::

      \begin{pmatrix} M & -J^T \\ J & 0 \end{pmatrix}
      \begin{pmatrix} \ddot q \\ \mu \end{pmatrix} =
      \begin{pmatrix} F \\ \gamma \end{pmatrix}, \qquad
      J = \frac{\partial f}{\partial q}, \quad
      \gamma = -\Bigl(\frac{\partial (J\dot q)}{\partial q}\dot q
      + 2\,\frac{\partial J}{\partial t}\dot q
      + \frac{\partial^2 f}{\partial t^2}\Bigr)

  (the second time derivative of the constraints vanishes); constraints on
  the velocities `g_k = A_k\dot q + b_k = 0` with their multipliers
  `\lambda_k` add the rows `A\ddot q = \gamma_A`, `\gamma_A = -\bigl(
  \frac{\partial (A\dot q + b)}{\partial q}\dot q + \frac{\partial (A\dot q
  + b)}{\partial t}\bigr)` (their first time derivative vanishes) and the
  columns `-A^T` (rolling without slipping, see
  :mod:`~sage_dynsym.dynamics.nonholonomic`);
- first order `B \dot x = F(x)`: `B` (skipped when it is the identity) and `F`.

EXAMPLES::

    sage: from sage_dynsym.analysis.motion import SecondOrderEquations
    sage: from sage_dynsym.numerics.form import NumericalForm
    sage: x, dx, ddx, m, k = var('x dx ddx m k')
    sage: N = NumericalForm(SecondOrderEquations([m*ddx + k*x], [x], [dx], [ddx])); N
    Numerical form M x'' = F in (x), parameters (k, m)
    sage: N.matrix(), N.vector()
    ([m], [-k*x])
"""
import functools
import types

from sage.matrix.constructor import matrix
from sage.symbolic.ring import SR

from ..errors import AnalysisError, ModelError, brief
from ..symbols import t as _t
from .expressions import linear_coefficients, symbols_and_functions

__all__ = ['deferred', 'resolved', 'constraint_terms', 'velocity_constraint_terms', 'as_form', 'NumericalForm']


def deferred(value):
    r"""
    Whether ``value`` is a function (or method) computing a value later,
    rather than a value (symbolic expressions are callable too).

    EXAMPLES::

        sage: from sage_dynsym.numerics.form import deferred
        sage: x = var('x'); deferred(lambda: x), deferred(x^2), deferred(None)
        (True, False, False)
    """
    return isinstance(value, (types.FunctionType, types.MethodType, functools.partial))


def resolved(value):
    r"""
    ``value`` computed now if it is :func:`deferred` (a symbolic expression,
    or ``None`` if the function gives none), else ``value`` itself: how a
    model's energy given as a function is evaluated when first asked for.

    EXAMPLES::

        sage: from sage_dynsym.numerics.form import resolved
        sage: x = var('x'); resolved(lambda: x^2), resolved(lambda: 1).parent(), resolved(x)
        (x^2, Symbolic Ring, x)
        sage: resolved(lambda: None) is None
        True
    """
    if deferred(value):
        value = value()
        return None if value is None else SR(value)
    return value


def constraint_terms(constraints, coordinates, velocities):
    r"""
    The Jacobian `J = \partial f/\partial q` of holonomic constraints
    `f(q, t) = 0`, the right-hand side `\gamma` of `J\ddot q = \gamma`
    (see the module documentation) and `\partial f/\partial t`, as
    ``(J, gamma, f_t)`` (``J`` a list of rows).

    EXAMPLES: a point on a circle turning at the rate `w`::

        sage: from sage_dynsym.numerics.form import constraint_terms
        sage: x, y, dx, dy, w, t = var('x y dx dy w t')
        sage: constraint_terms([x*sin(w*t) - y*cos(w*t)], [x, y], [dx, dy])
        ([[sin(t*w), -cos(t*w)]],
         [-w^2*y*cos(t*w) + w^2*x*sin(t*w) - 2*dx*w*cos(t*w) - 2*dy*w*sin(t*w)],
         [w*x*cos(t*w) + w*y*sin(t*w)])
    """
    J = [[SR(fj).diff(qi) for qi in coordinates] for fj in constraints]
    gamma = []
    for row, fj in zip(J, constraints):
        Jdq = sum(a * b for a, b in zip(row, velocities))
        gamma.append(-(sum(SR(Jdq).diff(qk) * dk for qk, dk in zip(coordinates, velocities))
                       + 2 * SR(Jdq).diff(_t) + SR(fj).diff(_t, 2)))
    return J, gamma, [SR(fj).diff(_t) for fj in constraints]


def velocity_constraint_terms(constraints, coordinates, velocities):
    r"""
    The rows `A = \partial g/\partial \dot q` of constraints on the
    velocities `g = A(q, t)\dot q + b(q, t) = 0`, the right-hand side
    `\gamma_A` of `A\ddot q = \gamma_A` (see the module documentation;
    the first time derivative of `g` vanishes) and `b`, as
    ``(A, gamma_A, b)`` (``A`` a list of rows).

    EXAMPLES: a point moving along `(1, y)`::

        sage: from sage_dynsym.numerics.form import velocity_constraint_terms
        sage: x, y, dx, dy = var('x y dx dy')
        sage: velocity_constraint_terms([y*dx - dy], [x, y], [dx, dy])
        ([[y, -1]], [-dx*dy], [0])
    """
    g = [SR(gk) for gk in constraints]
    rows = [[gk.diff(v) for v in velocities] for gk in g]
    gamma = [-(sum(gk.diff(qk) * dk for qk, dk in zip(coordinates, velocities)) + gk.diff(_t))
             for gk in g]
    return rows, gamma, [gk.subs({v: 0 for v in velocities}) for gk in g]


def as_form(equations):
    r"""
    ``equations`` if it is a numerical form already (a
    :class:`NumericalForm`, or any object with its ``state``/``kernel``
    methods, such as a :class:`~sage_dynsym.numerics.recursive.RecursiveForm`),
    else the :class:`NumericalForm` of the record ``equations``.

    EXAMPLES::

        sage: from sage_dynsym.analysis.motion import FirstOrderEquations
        sage: from sage_dynsym.numerics.form import as_form
        sage: x = var('x'); N = as_form(FirstOrderEquations([-x], [x])); N
        Numerical form x' = F in (x), parameters ()
        sage: as_form(N) is N
        True
    """
    if hasattr(equations, 'kernel') and hasattr(equations, 'state'):
        return equations
    return NumericalForm(equations)


class NumericalForm:
    r"""
    The blocks `A y = b` of a record's equations (see the module
    documentation) with the state, the parameters and, for the second
    order, the constraints.

    INPUT:

    - ``record`` -- a :class:`~sage_dynsym.analysis.motion.SecondOrderEquations`
      or :class:`~sage_dynsym.analysis.motion.FirstOrderEquations`
    - ``energy`` -- (optional) a conserved energy in the state variables,
      or a function without arguments computing it (called when the energy
      is first asked for: only an energy drift needs it)

    EXAMPLES::

        sage: from sage_dynsym.analysis.motion import FirstOrderEquations
        sage: from sage_dynsym.numerics.form import NumericalForm
        sage: i, u, L, C = var('i u L C')
        sage: N = NumericalForm(FirstOrderEquations([-u, i], [i, u], lhs_matrix=[L, C]))
        sage: N, N.state(), N.parameters()
        (Numerical form B x' = F in (i, u), parameters (C, L), [i, u], [C, L])
        sage: N.matrix()
        [L 0]
        [0 C]
        sage: N.vector()
        [-u, i]

    TESTS::

        sage: from sage_dynsym import Lagrangian
        sage: from sage_dynsym.analysis.motion import SecondOrderEquations
        sage: x, dx, ddx = var('x dx ddx')
        sage: NumericalForm(Lagrangian(dx^2/2, [x]))
        Traceback (most recent call last):
        ...
        ModelError: equations: expected the equations as a record of sage_dynsym.analysis.motion (SecondOrderEquations or FirstOrderEquations), got Lagrangian in coordinates (x) : 1/2*dx^2; for a model or a characteristic function call its method, model.numerical_rhs(values) or model.simulate(values, initial, t_end), which also check the values against its declared signs
        sage: NumericalForm(SecondOrderEquations([ddx^2 + x], [x], [dx], [ddx]))
        Traceback (most recent call last):
        ...
        AnalysisError: numerical_rhs: the equations are not linear in the accelerations (ddx)
    """

    def __init__(self, record, energy=None):
        from ..analysis.motion import FirstOrderEquations, SecondOrderEquations
        if not isinstance(record, (FirstOrderEquations, SecondOrderEquations)):
            hint = ("; for a model or a characteristic function call its method, "
                    "model.numerical_rhs(values) or model.simulate(values, initial, t_end), "
                    "which also check the values against its declared signs"
                    if callable(getattr(record, 'equations_record', None)) else "")
            raise ModelError(f"expected the equations as a record of "
                             f"sage_dynsym.analysis.motion (SecondOrderEquations or "
                             f"FirstOrderEquations), got {brief(record)}{hint}",
                             entry="equations")
        self._energy = energy if energy is None or deferred(energy) else SR(energy)
        self._constraints, self._J, self._gamma, self._f_t = [], [], [], []
        self._velocity_constraints, self._A = [], []
        if hasattr(record, 'accelerations'):
            self._second_order(record)
        else:
            self._order = 1
            self._state, self._hidden = list(record.variables()), []
            self._n = len(self._state)
            B = record.lhs_matrix()
            self._A = None if B.is_one() else B
            self._b = list(record.rhs())
        self._parameters = self._find_parameters()
        self._kernels = {}

    def _second_order(self, record):
        self._order = 2
        q, dq, ddq = record.coordinates(), record.velocities(), record.accelerations()
        mu, f = record.multipliers(), record.constraints()
        g = record.velocity_constraints()
        mu = mu + record.velocity_multipliers()
        E = record.equations()
        M, F = self._linear_blocks(E, ddq, mu)
        self._state, self._hidden = list(q) + list(dq), list(ddq) + mu
        self._n = len(q)
        self._constraints = f
        self._velocity_constraints = g
        if f or g:
            J, gamma, self._f_t = constraint_terms(f, q, dq)
            rows, gamma_velocity, self._b_velocity = velocity_constraint_terms(g, q, dq)
            self._J, self._A_rows, self._gamma = J, rows, gamma + gamma_velocity
            m, n = len(f) + len(g), len(q)
            G = matrix(SR, m, n, J + rows)
            A = matrix(SR, n + m, n + m)
            A[:n, :n] = M
            A[:n, n:] = -G.transpose()
            A[n:, :n] = G
            self._A, self._b = A, F + self._gamma
        else:
            self._A, self._b = M, F

    @staticmethod
    def _linear_blocks(E, ddq, mu):
        # M and F of E = M ddq + (terms in mu) - F: read off the terms when
        # they are products with the accelerations (the equations of large
        # models share subexpressions: differentiating or substituting in
        # them would walk every repetition), else by differentiation
        rows, forcing = [], []
        for e in E:
            split = linear_coefficients(e, ddq + mu)
            if split is None:
                rows.append([e.diff(a) for a in ddq])
                if any(x.has(a) for x in rows[-1] for a in ddq + mu):
                    raise AnalysisError("the equations are not linear in the accelerations ("
                                        f"{', '.join(map(str, ddq))})", entry="numerical_rhs")
                forcing.append(-e.subs({a: 0 for a in ddq + mu}))
            else:
                coefficients, rest = split
                rows.append([coefficients.get(a, SR(0)) for a in ddq])
                forcing.append(-rest)
        return (matrix(SR, rows) if E else matrix(SR, 0, 0)), forcing

    def __repr__(self):
        left = ("M x'' = F" if self._order == 2 else
                ("x' = F" if self._A is None else "B x' = F"))
        if self._constraints:
            left += f" with {len(self._constraints)} constraints"
        if self._velocity_constraints:
            left += f" with {len(self._velocity_constraints)} velocity constraints"
        coords = self._state[:self._n] if self._order == 2 else self._state
        return (f"Numerical form {left} in ({', '.join(map(str, coords))}), parameters "
                f"({', '.join(map(str, self._parameters))})")

    def order(self):
        r"""1 or 2, the order of the equations.

        EXAMPLES: see :meth:`state`.
        """
        return self._order

    def state(self):
        r"""
        The state variables: coordinates then velocities (second order), or
        the variables (first order).

        EXAMPLES::

            sage: from sage_dynsym.analysis.motion import SecondOrderEquations
            sage: from sage_dynsym.numerics.form import NumericalForm
            sage: x, dx, ddx = var('x dx ddx')
            sage: N = NumericalForm(SecondOrderEquations([ddx + x], [x], [dx], [ddx]))
            sage: N.state(), N.order()
            ([x, dx], 2)
        """
        return list(self._state)

    def parameters(self):
        r"""The other symbols of the equations (time excepted), sorted by name.

        EXAMPLES: see the class documentation.
        """
        return list(self._parameters)

    def matrix(self):
        r"""The matrix `A` of `A y = b` (``None`` for the identity).

        EXAMPLES: see the class documentation.
        """
        return self._A

    def vector(self):
        r"""The right-hand side `b` of `A y = b`.

        EXAMPLES: see the class documentation.
        """
        return list(self._b)

    def solve_size(self):
        r"""The size of the linear system `A y = b` solved at each call
        (``None`` when `A` is the identity).

        EXAMPLES::

            sage: from sage_dynsym.analysis.motion import SecondOrderEquations
            sage: from sage_dynsym.numerics.form import NumericalForm
            sage: x, dx, ddx = var('x dx ddx')
            sage: NumericalForm(SecondOrderEquations([ddx + x], [x], [dx], [ddx])).solve_size()
            1
        """
        return None if self._A is None else len(self._b)

    def constraints(self):
        r"""
        The holonomic constraints `f_j(q, t)`, their Jacobian `J` (rows) and
        `\partial f/\partial t`, as ``(f, J, f_t)`` (empty lists when there
        are none).

        EXAMPLES::

            sage: from sage_dynsym.analysis.motion import SecondOrderEquations
            sage: from sage_dynsym.numerics.form import NumericalForm
            sage: x, dx, ddx = var('x dx ddx')
            sage: NumericalForm(SecondOrderEquations([ddx + x], [x], [dx], [ddx])).constraints()
            ([], [], [])
        """
        return list(self._constraints), [list(r) for r in self._J], list(self._f_t)

    def velocity_constraints(self):
        r"""
        The constraints on the velocities `g_k = A_k(q, t)\dot q + b_k(q,
        t)`, as ``(g, A, b)`` (``A`` a list of rows; empty lists when there
        are none).

        EXAMPLES::

            sage: from sage_dynsym.analysis.motion import SecondOrderEquations
            sage: from sage_dynsym.numerics.form import NumericalForm
            sage: x, y, dx, dy, ddx, ddy, la = var('x y dx dy ddx ddy la')
            sage: N = NumericalForm(SecondOrderEquations([ddx - la*y, ddy + la], [x, y], [dx, dy],
            ....:                   [ddx, ddy], velocity_constraints=[y*dx - dy],
            ....:                   velocity_multipliers=[la])); N
            Numerical form M x'' = F with 1 velocity constraints in (x, y), parameters ()
            sage: N.velocity_constraints()
            ([dx*y - dy], [[y, -1]], [0])
            sage: N.matrix(), N.vector()
            (
            [ 1  0 -y]
            [ 0  1  1]
            [ y -1  0], [0, 0, -dx*dy]
            )
        """
        if not self._velocity_constraints:
            return [], [], []
        return (list(self._velocity_constraints), [list(r) for r in self._A_rows],
                list(self._b_velocity))

    def energy(self):
        r"""The conserved energy given (``None`` if none).

        EXAMPLES::

            sage: from sage_dynsym.analysis.motion import SecondOrderEquations
            sage: from sage_dynsym.numerics.form import NumericalForm
            sage: x, dx, ddx = var('x dx ddx')
            sage: E = SecondOrderEquations([ddx + x], [x], [dx], [ddx])
            sage: NumericalForm(E, energy=(dx^2 + x^2)/2).energy()
            1/2*dx^2 + 1/2*x^2
            sage: NumericalForm(E, energy=lambda: x^2).energy()
            x^2
        """
        self._energy = resolved(self._energy)
        return self._energy

    def _expressions(self):
        exprs = list(self._b) + ([] if self._A is None else list(self._A.list()))
        exprs += self._constraints + [a for row in self._J for a in row] + self._f_t
        return exprs + self._velocity_constraints

    def functions(self):
        r"""
        The unspecified functions of the equations (such as the
        characteristics `i = f(u)` of a circuit's nonlinear resistors),
        sorted by name; :meth:`with_functions` gives them a definition.

        EXAMPLES::

            sage: from sage_dynsym.analysis.motion import FirstOrderEquations
            sage: from sage_dynsym.numerics.form import NumericalForm
            sage: u, C = var('u C'); f = function('f')
            sage: NumericalForm(FirstOrderEquations([-f(u)], [u], lhs_matrix=[C])).functions()
            [f]
        """
        if not hasattr(self, '_functions'):
            self._scan()
        return [f for f, _ in self._functions]

    def _scan(self):
        symbols, functions = symbols_and_functions(self._expressions())
        hidden = {str(v) for v in self._state + self._hidden + [_t]}
        self._parameters = [v for name, v in symbols.items() if name not in hidden]
        self._functions = list(functions.values())

    def with_functions(self, values):
        r"""
        The form with its unspecified functions replaced by the definitions
        in ``values`` (keys: the functions or their names; values: Python
        functions of as many symbolic arguments, or callable symbolic
        expressions); ``self`` if it has none. The definitions may use
        parameters (they then need values too). Forms are cached by
        definition, so their code is compiled once.

        EXAMPLES: a nonlinear resistor `i = f(u)` in parallel with a
        capacitor::

            sage: from sage_dynsym.analysis.motion import FirstOrderEquations
            sage: from sage_dynsym.numerics.form import NumericalForm
            sage: u, C, a = var('u C a'); f = function('f')
            sage: N = NumericalForm(FirstOrderEquations([-f(u)], [u], lhs_matrix=[C]))
            sage: M = N.with_functions({'f': lambda v: a*v^3 - v}); M.vector(), M.parameters()
            ([-a*u^3 + u], [C, a])

        TESTS::

            sage: N.with_functions({})
            Traceback (most recent call last):
            ...
            ModelError: values: missing definitions of the functions f (give values['f'] = a function, e.g. lambda u: u^3 - u)
            sage: N.with_functions({f: 2})
            Traceback (most recent call last):
            ...
            ModelError: values: the definition of f must be a function of 1 arguments, got 2
        """
        functions = self.functions()
        if not functions:
            return self
        by_name = {(k.name() if hasattr(k, 'name') and not isinstance(k, str) else str(k)): v
                   for k, v in values.items()}
        missing = [f.name() for f in functions if f.name() not in by_name]
        if missing:
            raise ModelError(f"missing definitions of the functions {', '.join(missing)} (give "
                             f"values['{missing[0]}'] = a function, e.g. lambda u: u^3 - u)",
                             entry="values")
        definitions = {}
        for f in functions:
            arity = self._arity(f)
            arguments = [SR.var(f'_{f.name()}_{k}') for k in range(arity)]
            given = by_name[f.name()]
            try:
                body = SR(given(*arguments))
            except (TypeError, ValueError, ArithmeticError) as err:
                raise ModelError(f"the definition of {f.name()} must be a function of {arity} "
                                 f"arguments, got {given}", entry="values") from err
            definitions[f] = body.function(*arguments)
        key = tuple(str(definitions[f]) for f in functions)
        variants = self.__dict__.setdefault('_variants', {})
        if key not in variants:
            variants[key] = self._substituted(definitions)
        return variants[key]

    def _arity(self, f):
        self.functions()
        return dict((g.name(), arity) for g, arity in self._functions).get(f.name(), 1)

    def _substituted(self, definitions):
        import copy

        def sub(e):
            for f, g in definitions.items():
                e = SR(e).substitute_function(f, g)
            return e
        new = copy.copy(self)
        new.__dict__.pop('_variants', None)
        new._functions, new._kernels = [], {}
        new._b = [sub(e) for e in self._b]
        new._A = None if self._A is None else self._A.apply_map(sub)
        new._constraints = [sub(e) for e in self._constraints]
        new._J = [[sub(e) for e in row] for row in self._J]
        new._gamma, new._f_t = [sub(e) for e in self._gamma], [sub(e) for e in self._f_t]
        new._velocity_constraints = [sub(e) for e in self._velocity_constraints]
        if self._velocity_constraints:
            new._A_rows = [[sub(e) for e in row] for row in self._A_rows]
            new._b_velocity = [sub(e) for e in self._b_velocity]
        energy = self._energy
        new._energy = None if energy is None else (
            lambda: None if self.energy() is None else sub(self.energy())) if deferred(
                energy) else sub(energy)
        new._parameters = new._find_parameters()
        return new

    def _find_parameters(self):
        self._scan()
        return self._parameters

    def kernel(self, backend='auto'):
        r"""
        The compiled evaluation of the blocks (see
        :func:`~sage_dynsym.numerics.compiler.compile_kernel`), built once
        per backend.

        EXAMPLES::

            sage: from sage_dynsym.analysis.motion import SecondOrderEquations
            sage: from sage_dynsym.numerics.form import NumericalForm
            sage: x, dx, ddx, k = var('x dx ddx k')
            sage: N = NumericalForm(SecondOrderEquations([ddx + k*x], [x], [dx], [ddx]))
            sage: N.kernel('python')
            Python kernel: 2 states, 1 parameters
        """
        from .compiler import compile_kernel
        if not isinstance(backend, str):
            raise AnalysisError(f"backend must be 'auto', 'c' or 'python', got {backend!r}",
                                entry="numerical_rhs")
        if backend not in self._kernels:
            self._kernels[backend] = compile_kernel(self, backend)
        return self._kernels[backend]
