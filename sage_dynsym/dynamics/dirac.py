r"""
Dirac's scheme for singular Lagrangians

When the Hessian `W = \partial^2 L/\partial \dot q^2` is degenerate, the
momenta `p = \partial L/\partial \dot q` are not independent: the
*primary constraints* `\varphi_a(q, p) = 0` hold. Dirac's algorithm [Dir1964]_:

1. canonical Hamiltonian `H_c = p\cdot\dot q - L` (well defined on the
   primary constraint surface) and total Hamiltonian
   `H_T = H_c + u_a \varphi_a`;
2. consistency `\dot\chi = \{\chi, H_c\} + u_a\{\chi, \varphi_a\} \approx 0`
   for every constraint `\chi`: it fixes some multipliers `u_a`, and the
   combinations free of `u` that do not vanish on the constraint surface are
   *secondary constraints*; repeat until nothing new appears;
3. split into *second-class* constraints (the matrix of their brackets is
   invertible on the surface) and *first-class* ones (bracket with every
   constraint vanishes weakly; the first-class primaries generate gauge
   transformations);
4. *Dirac bracket* `\{f, g\}_D = \{f, g\} - \{f, \chi_a\} C^{ab} \{\chi_b, g\}`,
   `C^{ab}` the inverse of the second-class bracket matrix.

Constraints polynomial in the phase variables are reduced on the constraint
surface with a Gröbner basis (Singular); other constraints by solving them
for a variable in which they are linear.

This implementation handles Lagrangians at most quadratic in the velocities
(affine momentum map), which covers the classical examples (first-order
Lagrangians, Lagrange multipliers, gauge-type degeneracies).

REFERENCES:

.. [Dir1964] P. A. M. Dirac, *Lectures on Quantum Mechanics*, Yeshiva
   University, 1964.
.. [HT1992] M. Henneaux, C. Teitelboim, *Quantization of Gauge Systems*,
   Princeton University Press, 1992, ch. 1.

EXAMPLES:

A first-order Lagrangian `L = \tfrac12 (x\dot y - y\dot x) - V(x, y)`: two
second-class primary constraints and `\{x, y\}_D = -1` (so that
`\dot x = -V_y`, `\dot y = V_x`, the Lagrange equations)::

    sage: from sage_dynsym import Lagrangian
    sage: x, y, dx, dy = var('x y dx dy')
    sage: V = function('V')
    sage: D = Lagrangian((x*dy - y*dx)/2 - V(x, y), [x, y]).hamiltonian().constraints()
    sage: D.primary()
    [p_x + 1/2*y, p_y - 1/2*x]
    sage: D.secondary(), D.first_class(), D.second_class()
    ([], [], [p_x + 1/2*y, p_y - 1/2*x])
    sage: D.dirac_bracket(x, y)
    -1

A gauge-type degeneracy `L = \tfrac12 (\dot x - y)^2`: the primary
constraint `p_y = 0` yields the secondary constraint `p_x = 0`; both are
first class::

    sage: D = Lagrangian((dx - y)^2/2, [x, y]).hamiltonian().constraints(); D
    Dirac constraints: 0 second-class, 2 first-class
    sage: D.primary(), D.secondary(), D.first_class()
    ([p_y], [p_x], [p_y, p_x])
"""
from sage.matrix.constructor import matrix, vector
from sage.misc.misc_c import prod
from sage.misc.latex import latex
from sage.structure.sage_object import SageObject
from sage.symbolic.operators import add_vararg, mul_vararg
from sage.symbolic.ring import SR

from ..arguments import expression_list, model_argument
from ..errors import ModelError
from .natural_form import LAGRANGIAN_METHODS, LAGRANGIAN_HINT
from .brackets import poisson_bracket

__all__ = ['DiracConstraints']


class DiracConstraints(SageObject):
    r"""
    Dirac's constraint analysis of a singular Lagrangian.

    Built by :meth:`Lagrangian.hamiltonian()
    <sage_dynsym.dynamics.lagrangian.Lagrangian.hamiltonian>`; see the module
    documentation for the algorithm.

    INPUT:

    - ``lagrangian`` -- a singular natural Lagrangian
    - ``momenta`` -- list of momentum symbols
    - ``max_stages`` -- (default: 10) bound on the number of consistency
      stages

    EXAMPLES:

    A particle on a circle enforced by a Lagrange multiplier `\lambda` (a
    coordinate without velocity in `L`): the chain
    `p_\lambda \to x^2+y^2-1 \to x p_x + y p_y \to \dots` of four
    second-class constraints::

        sage: from sage_dynsym import Lagrangian
        sage: x, y, lam, dx, dy = var('x y lam dx dy')
        sage: L = Lagrangian((dx^2 + dy^2)/2 + lam*(x^2 + y^2 - 1), [x, y, lam])
        sage: D = L.hamiltonian().constraints()
        sage: D.stages()
        [[p_lam],
         [x^2 + y^2 - 1],
         [p_x*x + p_y*y],
         [lam*x^2 + lam*y^2 + 1/2*p_x^2 + 1/2*p_y^2]]
        sage: D
        Dirac constraints: 4 second-class, 0 first-class
        sage: D.dirac_bracket(x, y), D.dirac_bracket(x, var('p_x'))
        (0, y^2)

    (`\{x, p_x\}_D = 1 - x^2 = y^2` on the circle, [HT1992]_ §1.3.)

    TESTS:

    An inconsistent system is reported::

        sage: Lagrangian(y + 0*dx, [x, y]).hamiltonian()
        Traceback (most recent call last):
        ...
        ModelError: lagrangian: the constraints are inconsistent: 1 = 0 (no motion satisfies the equations)
    """

    def __init__(self, lagrangian, momenta, max_stages=10):
        model_argument(lagrangian, LAGRANGIAN_METHODS, "lagrangian", "a Lagrangian",
                       hint=LAGRANGIAN_HINT)
        momenta = expression_list(momenta, "momenta", expected="a list of momentum symbols")
        if not lagrangian.is_natural():
            raise ModelError("Dirac's scheme is implemented for Lagrangians at most "
                             "quadratic in the velocities", entry="lagrangian")
        self._lagrangian = lagrangian
        self._q = lagrangian.coordinates()
        self._p = list(momenta)
        self._build_primary()
        self._multipliers = [SR.var(f'u{k + 1}') for k in range(len(self._primary))]
        self._run_consistency(max_stages)
        self._classify()

    # ------------------------------------------------------------------
    # construction

    def _build_primary(self):
        A, A1, A0 = self._lagrangian.decomposition()
        dq = self._lagrangian.velocities()
        n = len(self._q)
        rows, cols = A.pivot_rows(), A.pivots()
        # an invertible block A[rows, cols] solves for the determined velocities
        block = A.matrix_from_rows_and_columns(rows, cols)
        shifted = vector(SR, self._p) - A1
        solved = block.solve_right(vector(SR, [shifted[i] for i in rows]))
        self._velocity_map = {v: 0 for v in dq}
        self._velocity_map.update({dq[j]: s.simplify_rational() for j, s in zip(cols, solved)})
        # every other row of A is a combination of the pivot rows: a primary constraint
        primary = []
        inverse = block.inverse()
        for k in range(n):
            if k in rows:
                continue
            coefficients = vector(SR, [A[k, j] for j in cols]) * inverse
            phi = shifted[k] - sum(c * shifted[i] for c, i in zip(coefficients, rows))
            primary.append(_normalize(phi))
        self._primary = primary
        velocities = [self._velocity_map[v] for v in dq]
        self._H_c = (sum(p * v for p, v in zip(self._p, velocities))
                     - self._lagrangian.expr().subs(self._velocity_map)).expand()

    def _bracket(self, f, g):
        return poisson_bracket(f, g, self._q, self._p)

    def _run_consistency(self, max_stages):
        self._stages = [list(self._primary)]
        constraints = list(self._primary)
        u = vector(SR, self._multipliers)
        self._determined = {}
        for _ in range(max_stages):
            reducer = _SurfaceReducer(constraints, self._p + self._q)
            # rows: d(chi)/dt = b + M u  for every constraint found so far
            M = matrix(SR, [[reducer(self._bracket(chi, phi)) for phi in self._primary]
                            for chi in constraints])
            b = vector(SR, [reducer(self._bracket(chi, self._H_c)) for chi in constraints])
            new = []
            # combinations w with w^T M = 0 on the surface leave w.b = 0
            # as conditions free of multipliers
            combined = M.augment(matrix.identity(SR, len(constraints))).echelon_form()
            for row in combined.rows():
                if any(reducer(e) != 0 for e in row[:M.ncols()]):
                    continue
                chi = _normalize(reducer(row[M.ncols():] * b))
                if chi.is_zero():
                    continue
                if chi.is_constant():
                    raise ModelError(f"the constraints are inconsistent: {chi} = 0 "
                                     "(no motion satisfies the equations)",
                                     entry="lagrangian")
                if chi not in constraints and chi not in new:
                    new.append(chi)
            if not new:
                self._solve_multipliers(M, b, u, reducer)
                self._constraints = constraints
                return
            self._stages.append(new)
            constraints = constraints + new
        raise ModelError(f"no closure of the constraint algorithm after {max_stages} stages",
                         entry="lagrangian")

    def _solve_multipliers(self, M, b, u, reducer):
        if not self._multipliers:
            return
        from sage.symbolic.relation import solve
        equations = [e == 0 for e in (M * u + b) if reducer(e) != 0]
        solutions = solve(equations, self._multipliers, solution_dict=True) if equations else [{}]
        if solutions:
            self._determined = {k: reducer(v) for k, v in solutions[0].items()
                                if not any(v.has(w) for w in self._multipliers)}

    def _classify(self):
        reducer = _SurfaceReducer(self._constraints, self._p + self._q)
        chis = self._constraints
        Delta = matrix(SR, len(chis), len(chis),
                       lambda a, b: reducer(self._bracket(chis[a], chis[b])))
        second = list(Delta.pivot_rows()) if Delta.nrows() else []
        self._second = [chis[i] for i in second]
        C = Delta.matrix_from_rows_and_columns(second, second)
        self._C_inverse = C.inverse() if second else matrix(SR, 0, 0)
        self._reducer = reducer
        first = []
        for k, chi in enumerate(chis):
            if k in second:
                continue
            # remove the part of chi that fails to commute with the second class
            correction = sum(reducer(self._bracket(chi, self._second[a]))
                             * self._C_inverse[a, b] * self._second[b]
                             for a in range(len(second)) for b in range(len(second)))
            first.append(_normalize(chi - correction))
        self._first = first

    # ------------------------------------------------------------------
    # results

    def _repr_(self):
        return (f"Dirac constraints: {len(self._second)} second-class, "
                f"{len(self._first)} first-class")

    def _latex_(self):
        return r",\ ".join(latex(c) + r" \approx 0" for c in self._constraints)

    def velocity_map(self):
        r"""
        The determined velocities as functions of `(q, p)` (the others set
        to zero): a dictionary.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, y, dx, dy = var('x y dx dy')
            sage: D = Lagrangian((dx - y)^2/2, [x, y]).hamiltonian().constraints()
            sage: D.velocity_map()
            {dx: p_x + y, dy: 0}
        """
        return dict(self._velocity_map)

    def canonical_hamiltonian(self):
        r"""
        The canonical Hamiltonian `H_c = p\cdot\dot q - L` on the primary
        constraint surface.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, y, dx, dy = var('x y dx dy')
            sage: D = Lagrangian((dx - y)^2/2, [x, y]).hamiltonian().constraints()
            sage: D.canonical_hamiltonian()
            1/2*p_x^2 + p_x*y
        """
        return self._H_c

    def primary(self):
        r"""
        The primary constraints `\varphi_a` (meaning `\varphi_a = 0`).

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, y, dx, dy = var('x y dx dy')
            sage: Lagrangian(x*dy, [x, y]).hamiltonian().constraints().primary()
            [p_x, p_y - x]
        """
        return list(self._primary)

    def secondary(self):
        r"""
        The secondary constraints, in the order they were found.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, y, dx, dy = var('x y dx dy')
            sage: Lagrangian((dx - y)^2/2, [x, y]).hamiltonian().constraints().secondary()
            [p_x]
        """
        return [c for stage in self._stages[1:] for c in stage]

    def stages(self):
        r"""
        The constraints by stage: primary first, then each generation of
        secondary constraints.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, y, dx, dy = var('x y dx dy')
            sage: Lagrangian((dx - y)^2/2, [x, y]).hamiltonian().constraints().stages()
            [[p_y], [p_x]]
        """
        return [list(s) for s in self._stages]

    def constraints(self):
        r"""
        All constraints (primary, then secondary).

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, y, dx, dy = var('x y dx dy')
            sage: Lagrangian((dx - y)^2/2, [x, y]).hamiltonian().constraints().constraints()
            [p_y, p_x]
        """
        return list(self._constraints)

    def first_class(self):
        r"""
        A basis of the first-class constraints (brackets with all constraints
        vanish on the constraint surface).

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, y, dx, dy = var('x y dx dy')
            sage: Lagrangian((dx - y)^2/2, [x, y]).hamiltonian().constraints().first_class()
            [p_y, p_x]
        """
        return list(self._first)

    def second_class(self):
        r"""
        The second-class constraints `\chi_a`.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, y, dx, dy = var('x y dx dy')
            sage: Lagrangian(x*dy - y*dx, [x, y]).hamiltonian().constraints().second_class()
            [p_x + y, p_y - x]
        """
        return list(self._second)

    def second_class_matrix(self):
        r"""
        The matrix `C_{ab} = \{\chi_a, \chi_b\}` of the second-class
        constraints (on the constraint surface).

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, y, dx, dy = var('x y dx dy')
            sage: Lagrangian(x*dy - y*dx, [x, y]).hamiltonian().constraints().second_class_matrix()
            [ 0  2]
            [-2  0]
        """
        return self._C_inverse.inverse() if self._second else matrix(SR, 0, 0)

    def multipliers(self):
        r"""
        The multipliers `u_a` of the primary constraints in the total
        Hamiltonian, and the values the consistency conditions fix (a
        dictionary; multipliers absent from it remain arbitrary).

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, y, dx, dy = var('x y dx dy')
            sage: D = Lagrangian(x*dy - y*dx - x^2 - y^2, [x, y]).hamiltonian().constraints()
            sage: D.multipliers()
            ([u1, u2], {u1: -y, u2: x})
        """
        return list(self._multipliers), dict(self._determined)

    def total_hamiltonian(self):
        r"""
        `H_T = H_c + \sum_a u_a \varphi_a` with the multipliers fixed by the
        consistency conditions substituted.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, y, dx, dy = var('x y dx dy')
            sage: Lagrangian((dx - y)^2/2, [x, y]).hamiltonian().constraints().total_hamiltonian()
            1/2*p_x^2 + p_y*u1 + p_x*y
        """
        H_T = self._H_c + sum(u * phi for u, phi in zip(self._multipliers, self._primary))
        return H_T.subs(self._determined)

    def dirac_bracket(self, f, g):
        r"""
        The Dirac bracket `\{f, g\}_D` with respect to the second-class
        constraints, reduced on the constraint surface.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, y, dx, dy = var('x y dx dy')
            sage: D = Lagrangian(x*dy - y*dx, [x, y]).hamiltonian().constraints()
            sage: D.dirac_bracket(x, y), D.dirac_bracket(x, var('p_x'))
            (-1/2, 1/2)
        """
        value = self._bracket(f, g)
        n = len(self._second)
        left = [self._bracket(f, chi) for chi in self._second]
        right = [self._bracket(chi, g) for chi in self._second]
        value -= sum(left[a] * self._C_inverse[a, b] * right[b]
                     for a in range(n) for b in range(n))
        return self._reducer.simplify(value)

    def equations(self):
        r"""
        Hamilton--Dirac equations: pairs `(\dot q_i, \dot p_i)` computed as
        `\{\cdot, H_c + \sum v_k \varphi^{(1)}_k\}_D` with arbitrary
        multipliers `v_k` for the first-class primary constraints.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, y, dx, dy = var('x y dx dy')
            sage: D = Lagrangian((dx - y)^2/2, [x, y]).hamiltonian().constraints()
            sage: D.equations()
            [(p_x + y, 0), (v1, 0)]

        (`\dot p_y = -p_x`, which vanishes on the constraint surface.)
        """
        primary_first = [phi for phi in self._first if any(
            bool((phi - c).expand() == 0) for c in self._primary)]
        gauge = [SR.var(f'v{k + 1}') for k in range(len(primary_first))]
        H_E = self._H_c + sum(v * phi for v, phi in zip(gauge, primary_first))
        return [(self.dirac_bracket(q, H_E), self.dirac_bracket(p, H_E))
                for q, p in zip(self._q, self._p)]


def _normalize(expr):
    r"""
    The expanded constraint divided by the numeric coefficient of its first
    term, so that equal constraints (up to a constant factor) compare equal.
    """
    expr = SR(expr).expand()
    if expr.is_zero():
        return expr
    terms = expr.operands() if expr.operator() is add_vararg else [expr]
    first = terms[0]
    if first.is_numeric():
        scale = first
    elif first.operator() is mul_vararg:
        scale = prod(op for op in first.operands() if op.is_numeric())
    else:
        scale = 1
    return (expr / scale).expand()


class _SurfaceReducer:
    r"""
    Reduction of expressions on the surface ``constraints = 0``.

    Polynomial constraints: normal form modulo a Gröbner basis over the
    fraction field of the parameters. Otherwise: substitution of variables in
    which constraints are linear.
    """

    def __init__(self, constraints, variables):
        from sage.rings.polynomial.polynomial_ring_constructor import PolynomialRing
        from sage.rings.rational_field import QQ
        self._constraints = [SR(c) for c in constraints]
        self._variables = [v for v in variables if any(c.has(v) for c in self._constraints)]
        self._ideal = None
        self._substitution = {}
        parameters = sorted({v for c in self._constraints for v in c.variables()}
                            - set(variables), key=str)
        try:
            if not self._constraints or not self._variables:
                raise TypeError
            base = QQ if not parameters else PolynomialRing(
                QQ, [str(v) for v in parameters]).fraction_field()
            self._ring = PolynomialRing(base, [str(v) for v in self._variables],
                                        order='degrevlex')
            self._ideal = self._ring.ideal([self._ring(c) for c in self._constraints])
            self._ideal.groebner_basis()  # computed once, cached by the ideal
        except (TypeError, ValueError, NotImplementedError):
            self._ideal = None
            self._build_substitution()

    def _build_substitution(self):
        for c in self._constraints:
            c = c.subs(self._substitution)
            for v in self._variables:
                if v in self._substitution or not c.has(v):
                    continue
                coefficient = c.diff(v)
                if not coefficient.has(v) and not coefficient.is_zero():
                    value = (v - c / coefficient).expand()
                    self._substitution = {k: w.subs({v: value})
                                          for k, w in self._substitution.items()}
                    self._substitution[v] = value
                    break

    def __call__(self, expr):
        expr = SR(expr)
        if self._ideal is not None:
            try:
                numerator, denominator = expr.numerator(), expr.denominator()
                reduced = self._ideal.reduce(self._ring(numerator))
                return SR(reduced) / denominator
            except (TypeError, ValueError, NotImplementedError):
                pass
        return expr.subs(self._substitution).expand() if self._substitution else expr.expand()

    def simplify(self, expr):
        r"""
        Reduce and tidy (rational simplification).
        """
        return self(SR(expr).simplify_rational()).simplify_rational()
