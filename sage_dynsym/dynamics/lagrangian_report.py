r"""
Report sections of a Lagrangian

The pieces of a report that every model with a Lagrangian shares (a
mechanical system, the loop Lagrangian of a linear circuit): the Lagrange
equations and the constraint forces, the Routh function for the cyclic
coordinates, the stationary motions or equilibria with their stability, the
Hamiltonian -- each with the estimate of its size that the report's budget
is checked against (see :mod:`sage_dynsym.dynamics.reporting`).

EXAMPLES::

    sage: from sage_dynsym import Lagrangian
    sage: from sage_dynsym.dynamics.lagrangian_report import equations_lines
    sage: from sage_dynsym.dynamics.reporting import ReportContext, render
    sage: x, dx, m, k = var('x dx m k')
    sage: L = Lagrangian(m*dx^2/2 - k*x^2/2, [x])
    sage: print("\n".join(render(equations_lines(L, ReportContext({}, 100)))))
    Lagrange equations (E_i = 0):
      [x] ddx*m + k*x
        LaTeX: {\ddot{x}} m + k x
"""
from sage.symbolic.ring import SR

from ..algebra.size import polynomial_terms, determinant_terms, matrix_terms
from ..errors import BudgetError, DynSymError
from .reporting import formula_lines

__all__ = ['equations_estimate', 'characteristic_estimate', 'equations_lines',
           'constraint_forces_lines', 'routh_function', 'routh_lines', 'hamiltonian_lines',
           'stationary_estimate', 'stationary_lines', 'check_routh_scheme',
           'coefficient_conditions_lines']


def equations_estimate(L):
    r"""
    The size estimate of the Lagrange equations of ``L``, checked before
    they are derived: for each coordinate, the terms of `\partial L/\partial
    \dot q_i` times `2n + 1` (the total time derivative differentiates each
    factor in `q, \dot q, t`), plus those of `\partial L/\partial q_i`, of
    the dissipation and of the generalized force.

    EXAMPLES::

        sage: from sage_dynsym import Lagrangian
        sage: from sage_dynsym.dynamics.lagrangian_report import equations_estimate
        sage: x, dx, m, k = var('x dx m k')
        sage: equations_estimate(Lagrangian(m*dx^2/2 - k*x^2/2, [x]))
        4
    """
    q, dq = L.coordinates(), L.velocities()
    expr, R = SR(L.expr()), SR(L.dissipation())
    n, total = len(q), 0
    for x, v, Q in zip(q, dq, L.generalized_forces()):
        total += (polynomial_terms(expr.diff(v)) * (2 * n + 1) + polynomial_terms(expr.diff(x))
                  + polynomial_terms(R.diff(v)) + polynomial_terms(Q))
    return total


def characteristic_estimate(L):
    r"""
    The size estimate of the characteristic polynomial
    `\det(M\lambda^2 + (D + G)\lambda + K)` of ``L`` linearized at the
    origin, checked before the linearization: the permanent bound
    (:func:`~sage_dynsym.algebra.size.determinant_terms`) of the term
    counts of the second derivatives of `L` and of the dissipation that make
    up the matrix.

    EXAMPLES::

        sage: from sage_dynsym.circuits import Circuit
        sage: from sage_dynsym.dynamics.lagrangian_report import characteristic_estimate
        sage: C = Circuit([[0, 1, 'R1'], [1, 2, 'L1'], [2, 0, 'C1']])
        sage: characteristic_estimate(C.lagrangian())   # L1*lambda^2 + R1*lambda + 1/C1
        3
    """
    q, dq = L.coordinates(), L.velocities()
    expr, R = SR(L.expr()), SR(L.dissipation())
    by_velocity = [expr.diff(v) for v in dq]
    by_coordinate = [expr.diff(x) for x in q]
    damping = [R.diff(v) for v in dq]
    counts = [[polynomial_terms(by_velocity[i].diff(dq[j]))
               + polynomial_terms(damping[i].diff(dq[j]))
               + polynomial_terms(by_velocity[i].diff(q[j]))
               + polynomial_terms(by_coordinate[i].diff(q[j])) for j in range(len(q))]
              for i in range(len(q))]
    return determinant_terms(counts)


def equations_lines(L, context):
    r"""
    The Lagrange equations of ``L`` (with the constraints and their
    multipliers), checked against the budget of ``context`` first.

    EXAMPLES: see the module documentation.
    """
    context.check("the Lagrange equations (terms of dL/d(dq_i) times 2n + 1, and of dL/dq_i)",
                  equations_estimate(L))
    lines = ["Lagrange equations (E_i = 0):"]
    for q, e in zip(L.coordinates(), L.lagrange_equations()):
        lines += formula_lines(f"[{q}] ", e, variables=L.accelerations(),
                               named="the accelerations")
    for mu, f in zip(L.multipliers(), L.constraints()):
        lines += formula_lines(f"constraint with multiplier {mu} (terms -{mu} df/dq_i): 0 = ", f)
    for mu, g in zip(L.velocity_multipliers(), L.nonholonomic_constraints()):
        lines += formula_lines(f"velocity constraint with multiplier {mu} (terms -{mu} "
                               "dg/d(dq_i)): 0 = ", g)
    return lines


def constraint_forces_lines(L, context):
    r"""
    The multipliers of the constraints of ``L`` (the constraint forces),
    solved with the accelerations; ``None`` without constraints.

    EXAMPLES::

        sage: from sage_dynsym import Lagrangian
        sage: from sage_dynsym.dynamics.lagrangian_report import constraint_forces_lines
        sage: from sage_dynsym.dynamics.reporting import ReportContext
        sage: x, y, dx, dy, g = var('x y dx dy g')
        sage: L = Lagrangian((dx^2 + dy^2)/2 - g*y, [x, y], constraints=[x^2 + y^2 - 1])
        sage: constraint_forces_lines(L, ReportContext({}, 10^5))[:2]
        ['Multipliers (constraint forces), solved with the accelerations:',
         Formula mu1 = ...]
    """
    if not (L.constraints() or L.nonholonomic_constraints()):
        return None
    context.check("the accelerations and multipliers (the equations' terms times (n + m)^2)",
                  equations_estimate(L) * (len(L.coordinates()) + len(L.multipliers())) ** 2)
    solved = L.accelerations_and_multipliers()
    lines = ["Multipliers (constraint forces), solved with the accelerations:"]
    for mu in L.multipliers():
        lines += formula_lines(f"{mu} = ", solved[mu])
    return lines


def routh_function(L, cyclic, context):
    r"""
    The Routh function of ``L`` for the ``cyclic`` coordinates, checked
    against the budget of ``context`` first (the determinant of the cyclic
    block of the mass matrix, times the terms of `L`).

    EXAMPLES::

        sage: from sage_dynsym import load
        sage: from sage_dynsym.description import example_path
        sage: from sage_dynsym.dynamics.lagrangian_report import routh_function
        sage: from sage_dynsym.dynamics.reporting import ReportContext
        sage: L = load(example_path('spherical_pendulum.yaml')).lagrangian()
        sage: routh_function(L, L.cyclic_coordinates(), ReportContext({}, 10^5)).momenta()
        [p_psi]
    """
    A = L.mass_matrix()
    index = [L.coordinates().index(q) for q in cyclic]
    block = A.matrix_from_rows_and_columns(index, index)
    context.check("the Routh function (determinant of the cyclic block of the mass matrix, "
                  "times the terms of L)",
                  determinant_terms(matrix_terms(block)) * polynomial_terms(L.expr()))
    return L.routh(cyclic)


def routh_lines(R, cyclic, context):
    r"""
    The Routh function ``R`` and its equations, checked against the budget.

    EXAMPLES: see :func:`routh_function`; the report of the spherical
    pendulum in :mod:`sage_dynsym.report.writer`.
    """
    lines = [f"Routh function for the cyclic coordinates {', '.join(map(str, cyclic))} "
             f"(momenta {', '.join(map(str, R.momenta()))}):"]
    lines += formula_lines("R = ", R.expr(), variables=R.velocities(), named="the velocities")
    context.check("the Routh equations", equations_estimate(R))
    lines.append("Routh equations (E_i = 0):")
    for q, e in zip(R.coordinates(), R.equations()):
        lines += formula_lines(f"[{q}] ", e, variables=R.accelerations(),
                               named="the accelerations")
    return lines


def hamiltonian_lines(L, context):
    r"""
    The Hamiltonian of ``L`` (Dirac's scheme for a singular Lagrangian),
    checked against the budget first (`n^2` times the determinant of the
    mass matrix).

    EXAMPLES::

        sage: from sage_dynsym import Lagrangian
        sage: from sage_dynsym.dynamics.lagrangian_report import hamiltonian_lines
        sage: from sage_dynsym.dynamics.reporting import ReportContext
        sage: x, dx = var('x dx')
        sage: hamiltonian_lines(Lagrangian(dx^2/2 - x^2/2, [x]), ReportContext({}, 100))
        ['Hamiltonian:', Formula H = 1/2*p_x^2 + 1/2*x^2]
    """
    n = len(L.coordinates())
    context.check("the Hamiltonian (n^2 times the determinant of the mass matrix)",
                  n ** 2 * determinant_terms(matrix_terms(L.mass_matrix())))
    H = L.hamiltonian()
    lines = []
    if H.is_singular():
        D = H.constraints()
        lines.append(f"Singular Lagrangian: Dirac's scheme ({D}):")
        for c in D.constraints():
            lines += formula_lines("constraint ", c)
    lines.append("Hamiltonian:")
    lines += formula_lines("H = ", H.expr(), variables=H.momenta(), named="the momenta")
    return lines


def stationary_estimate(F):
    r"""
    The size estimate of the stationary motions (or equilibria) of the
    characteristic function ``F``: the terms of ``F`` times `2^k` for `k`
    unknowns (the exact solver splits the system into cases).

    EXAMPLES::

        sage: from sage_dynsym import Lagrangian
        sage: from sage_dynsym.dynamics.lagrangian_report import stationary_estimate
        sage: x, dx = var('x dx')
        sage: stationary_estimate(Lagrangian(dx^2/2 - x^4/4 + x^2/2, [x]))
        6
    """
    return polynomial_terms(F.expr()) * 2 ** len(F.coordinates())


def stationary_lines(L, R, positive=()):
    r"""
    The stationary motions of the Routh function ``R`` (at rest, solved for
    the cyclic momenta) or, when ``R`` is ``None``, the equilibria of
    ``L``, each with its existence conditions and a stability verdict
    (Routh--Lyapunov, then first approximation).

    EXAMPLES::

        sage: from sage_dynsym import Lagrangian
        sage: from sage_dynsym.dynamics.lagrangian_report import stationary_lines
        sage: from sage_dynsym.dynamics.reporting import render
        sage: x, dx = var('x dx')
        sage: print("\n".join(render(stationary_lines(Lagrangian(dx^2/2 + cos(x), [x]), None))))
        Equilibria (equations at rest):
          0 = sin(x)
          ...
          solution 1 (isolated): x = 0
            stability: stable ...
    """
    from ..analysis import stationary_motions
    reduced = L if R is None else R
    what = ("Equilibria (equations at rest)" if R is None else
            "Stationary motions (Routh function at rest, cyclic momenta constant)")
    try:
        solutions = stationary_motions(reduced, solve_for=None if R is None else R.momenta(),
                                       positive=positive)
    except DynSymError as err:
        return [f"{what}: not available ({err})"]
    lines = [f"{what}:"]
    for e in solutions.equations():
        lines += formula_lines("0 = ", e)
    lines.extend(solutions.report_lines(
        lambda out, e: out.extend(formula_lines("0 = ", e, indent="    "))))
    return lines


def check_routh_scheme(poly, lam, budget):
    r"""
    Raise a :class:`~sage_dynsym.errors.BudgetError` when the Hurwitz
    determinants of ``poly`` (in ``lam``) would need a product of more than
    ``budget`` pairs of terms: the fraction-free Routh scheme that computes
    them is run with the budget first, so that no costly product is made.

    EXAMPLES::

        sage: from sage_dynsym.dynamics.lagrangian_report import check_routh_scheme
        sage: lam, a, b, c = var('lam a b c')
        sage: check_routh_scheme(lam^3 + a*lam^2 + b*lam + c, lam, 100)
        sage: check_routh_scheme(lam^3 + (a + b + c)^9*lam^2 + b*lam + c, lam, 10)
        Traceback (most recent call last):
        ...
        BudgetError: the Lienard-Chipart conditions: a product of the Routh scheme would multiply more than 10 pairs of terms, over the budget of 10
    """
    from ..analysis.hurwitz import routh_scheme_fits
    if not routh_scheme_fits(poly, lam, budget):
        raise BudgetError(f"the Lienard-Chipart conditions: a product of the Routh scheme "
                          f"would multiply more than {budget} pairs of terms, over the budget "
                          f"of {budget}")


def coefficient_conditions_lines(poly, lam, reason):
    r"""
    The Liénard--Chipart conditions of the characteristic polynomial
    ``poly`` in ``lam`` stated in its coefficients `a_k` (of `\lambda^k`,
    the roots `\lambda = 0` left out), each coefficient given apart: the
    stability conditions of a polynomial whose expanded conditions are over
    the budget (``reason``, the message of the
    :class:`~sage_dynsym.errors.BudgetError`). ``None`` for a polynomial
    without odd coefficients (no dissipation: these conditions do not
    apply).

    EXAMPLES::

        sage: from sage_dynsym.dynamics.lagrangian_report import coefficient_conditions_lines
        sage: from sage_dynsym.dynamics.reporting import render
        sage: lam, c, k, m = var('lam c k m')
        sage: lines = coefficient_conditions_lines(m*lam^3 + c*lam^2 + k*lam, lam, "too large")
        sage: print("\n".join(render(lines, latex=False)))
          the expanded conditions are over the budget (too large; --budget raises it); lambda = 0 is a root of multiplicity 1 (left out); for the other roots, with a_k the coefficient of lam^k below, the Lienard-Chipart conditions (each > 0):
            a_2
            a_0
            a_1
          where
            a_0 = k
            a_1 = c
            a_2 = m
        sage: coefficient_conditions_lines(lam^2 + k, lam, "too large") is None
        True
    """
    from ..analysis.stability import coefficient_conditions
    found = coefficient_conditions(poly, lam)
    if found is None:
        return None
    zeros, conditions, coefficients = found
    roots = (f"lambda = 0 is a root of multiplicity {zeros} (left out); for the other roots, "
             if zeros else "")
    lines = [f"  the expanded conditions are over the budget ({reason}; --budget raises it); "
             f"{roots}with a_k the coefficient of {lam}^k below, the Lienard-Chipart "
             "conditions (each > 0):"]
    for condition in conditions:
        lines += formula_lines("", condition, indent="    ")
    lines.append("  where")
    for a_k, value in coefficients.items():
        lines += formula_lines(f"{a_k} = ", value, indent="    ")
    return lines
