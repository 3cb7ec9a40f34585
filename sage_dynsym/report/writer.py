r"""
Plain-text and LaTeX reports of a model

:func:`report` derives what a description file's model has to offer
(Lagrangian, Lagrange equations, Routh function for the cyclic coordinates,
Hamiltonian; for circuits the mixed potential and state equations, and the
loop Lagrangian of a linear circuit) and renders it as readable text with the
LaTeX form of every formula. The command line ``python -m sage_dynsym`` (or
``sage-dynsym``) prints it for each file given.

EXAMPLES::

    sage: from sage_dynsym import load
    sage: from sage_dynsym.description import example_path
    sage: from sage_dynsym.report import report
    sage: print(report(load(example_path('spherical_pendulum.yaml'))))
    == spherical pendulum (mechanical system: 1 body, coordinates psi, theta) ==
    Lagrangian L = T + U:
      1/2*dpsi^2*l^2*m*sin(theta)^2 + 1/2*dtheta^2*l^2*m - g*l*m*cos(theta)
      LaTeX: ...
    Lagrange equations (E_i = 0):
      [psi] 2*dpsi*dtheta*l^2*m*cos(theta)*sin(theta) + ddpsi*l^2*m*sin(theta)^2
      ...
    Routh function for the cyclic coordinates psi (momenta p_psi):
      ...
    Stationary motions (Routh function at rest, cyclic momenta constant):
      0 = -(g*l^3*m^2*sin(theta)^4 + p_psi^2*cos(theta))/(l^2*m*sin(theta)^3)
      ...
    Hamiltonian:
      ...
"""
# Sage's symbolic functions, Maxima and coercions need the whole library initialised
# first (the package's face loads it lazily, only when a name is used)
import sage.all  # noqa: F401

from sage.misc.latex import latex
from sage.symbolic.ring import SR

from ..algebra.size import polynomial_terms, TERMS_CAP as _TERMS_CAP
from ..errors import DynSymError, BudgetError
from ..arguments import count

from .sections import DEFAULT_BUDGET, SECTIONS, ANALYSIS_SECTIONS

#: Largest number of partial states of the permanent bound before the
#: cruder product bound is used.
_PERMANENT_STATES = 20_000


def determinant_terms(counts):
    r"""
    An upper bound of the number of terms of the expanded determinant of a
    matrix whose entries have ``counts[i][j]`` terms: the permanent of the
    counts (each permutation contributes the product of its entries' term
    counts), computed row by row over the open columns; when that needs
    too many partial states, the smaller of the products of the row sums
    and of the column sums.

    EXAMPLES::

        sage: from sage_dynsym.report import determinant_terms
        sage: determinant_terms([[2, 1], [1, 3]])
        7
        sage: determinant_terms([[1, 1, 0], [1, 1, 1], [0, 1, 1]])   # tridiagonal
        3
        sage: determinant_terms([[1] * 8 for _ in range(8)]) == factorial(8)
        True
        sage: determinant_terms([[1] * 40 for _ in range(40)])   # the product bound, capped
        1000000000000000000000000000000
        sage: determinant_terms([[1, 0], [1, 0]])
        0
    """
    n = len(counts)
    last = {}
    for j in range(n):
        rows = [i for i in range(n) if counts[i][j]]
        if not rows:
            return 0
        last[j] = rows[-1]
    states = {frozenset(): 1}
    for i in range(n):
        closing = {j for j in range(n) if last[j] == i}
        new = {}
        for used, value in states.items():
            for j in range(n):
                c = counts[i][j]
                if c and j not in used:
                    key = used | {j}
                    if closing <= key:
                        key -= closing
                        new[key] = new.get(key, 0) + value * c
        states = new
        if len(states) > _PERMANENT_STATES:
            rows = 1
            for row in counts:
                rows = min(rows * sum(row), _TERMS_CAP)
            cols = 1
            for j in range(n):
                cols = min(cols * sum(counts[i][j] for i in range(n)), _TERMS_CAP)
            return min(rows, cols)
    return min(sum(states.values()), _TERMS_CAP)


def _matrix_terms(M):
    return [[polynomial_terms(e) for e in row] for row in M.rows()]


class _Report:
    r"""
    The lines of a report and its sections: which are wanted, their budget,
    and :meth:`run`, which turns any failure of a section into one line.
    """

    def __init__(self, sections, budget, failed=None):
        self.lines, self.wanted, self.budget = [], set(sections), budget
        self.failed = [] if failed is None else failed

    def want(self, *keys):
        return any(k in self.wanted for k in keys)

    def check(self, what, estimate):
        if estimate > self.budget:
            raise BudgetError(what, estimate=estimate, budget=self.budget)

    def run(self, title, body):
        r"""
        Run ``body(lines)``; its lines are kept if it succeeds, else one line
        says why the section is missing: over the budget, not available
        (the package's error), or failed (any other error, with its class;
        its title is added to ``failed``). Returns the body's value, or
        ``None``. ``KeyboardInterrupt`` is not caught.
        """
        lines = []
        try:
            value = body(lines)
        except BudgetError as err:
            self.lines.append(f"{title}: skipped, {err.message} (raise it with --budget)")
            return None
        except DynSymError as err:
            self.lines.append(f"{title}: not available ({_clip(str(err))})")
            return None
        except Exception as err:    # Sage, Maxima, memory, recursion: one line, no traceback
            self.lines.append(f"{title}: section failed: {type(err).__name__}: "
                              f"{_clip(str(err))}")
            self.failed.append(title)
            return None
        self.lines.extend(lines)
        return value


def _clip(text, limit=300):
    text = " ".join(text.split())
    return text if len(text) <= limit else text[:limit - 3] + "..."


def _formula(lines, label, expr, indent="  "):
    lines.append(f"{indent}{label}{expr}")
    lines.append(f"{indent}  LaTeX: {latex(expr)}")


def lagrangian_estimate(system):
    r"""
    The size estimate of a mechanical system's Lagrangian, checked before it
    is derived: `n^2 2^r T^2` polynomial terms for `n` coordinates (the
    entries of the mass matrix), `r` the most angles that vary along one
    chain of bodies from the inertial frame (each such rotation at most
    doubles the terms of a direction cosine) and `T` the most terms of one
    datum of the description (a mass, an inertia entry, a vector component,
    the force function), squared as velocities are.

    EXAMPLES::

        sage: from sage_dynsym import load
        sage: from sage_dynsym.description import example_path
        sage: from sage_dynsym.report import lagrangian_estimate
        sage: lagrangian_estimate(load(example_path('spherical_pendulum.yaml')))
        16
        sage: from sage_dynsym import MechanicalSystem, RigidBody
        sage: x, m, k = var('x m k')
        sage: lagrangian_estimate(MechanicalSystem([RigidBody('b', joint=[x, 0, 0],
        ....:                                               mass=(m + k)^3)], [x]))
        16
    """
    from ..mechanics.force_functions import UniformGravity, NewtonianField
    depth, data = [0], []
    for k, body in enumerate(system.bodies(), 1):
        turning = sum(1 for _, angle in body.rotations() if SR(angle).variables())
        depth.append(depth[system.parent_index(k)] + turning)
        data += [body.mass()] + body.inertia().list() + list(body.joint())
        data += list(body.velocity() or ()) + list(body.mass_center())
    for field in system.force_terms():
        if isinstance(field, UniformGravity):
            data += list(field.acceleration())
        elif isinstance(field, NewtonianField):
            nu, r, e = field.parameters()
            data += [nu, r] + list(e)
        else:
            data.append(field)
    for load in system.loads():
        data += load.expressions()
    # the constraints given (the derived contact conditions of rolling disks
    # enter the equations linearly, through their multipliers)
    data += system.constraint_set().given_holonomic()
    largest = max([polynomial_terms(e) for e in data] + [1])
    n = len(system.coordinates())
    return min(n ** 2 * 2 ** max(depth) * largest ** 2, _TERMS_CAP)


def circuit_estimate(circuit):
    r"""
    The size estimate of a circuit's mixed potential and state equations
    (and of its loop Lagrangian), checked before they are derived: the
    number of branches times the square of the most terms of one element
    value (a value is integrated, and multiplied by currents and voltages
    that are sums over the loops).

    EXAMPLES::

        sage: from sage_dynsym.circuits import Circuit
        sage: from sage_dynsym.report import circuit_estimate
        sage: circuit_estimate(Circuit([[1, 2, 'R1'], [2, 1, 'C1']]))
        2
        sage: circuit_estimate(Circuit([[1, 2, 'R1'], {'from': 2, 'to': 1, 'kind': 'capacitor',
        ....:     'name': 'C1', 'value': '(u + C0)^2'}], parameters=['C0']))
        18
    """
    values = [b.value for b in circuit.branches() if b.value is not None]
    values += [c.value for c in circuit.couplings()]
    largest = max([polynomial_terms(v) for v in values] + [1])
    return min(len(circuit.branches()) * largest ** 2, _TERMS_CAP)


def _conditions(model, out):
    # what the declared signs leave open for the model to be physical: the
    # rest of the report holds where these hold
    conditions = model.conditions()
    if conditions:
        out.lines.append("Conditions for the model to be physical (not decided by the declared "
                         "signs): " + ", ".join(map(str, conditions)))


def _mechanical(system, out):
    coordinates = ", ".join(map(str, system.coordinates()))
    n = len(system.bodies())
    out.lines.append(f"== {system.name() or 'mechanical system'} (mechanical system: {n} "
                     f"bod{'y' if n == 1 else 'ies'}, coordinates {coordinates}) ==")
    _conditions(system, out)

    def lagrangian(lines):
        out.check("the Lagrangian (n^2 2^r T^2: coordinates, varying angles along a chain, "
                  "terms of the data)",
                  lagrangian_estimate(system))
        L = system.lagrangian()
        if out.want('lagrangian'):
            lines.append("Lagrangian L = T + U:")
            _formula(lines, "", L.expr())
        return L

    L = out.run("Lagrangian", lagrangian)
    if L is None:
        return
    constrained = bool(system.constraint_set().lines())
    if constrained and out.want('lagrangian', 'equations'):
        out.lines.append("Constraints (holonomic: f(q, t) = 0; on the velocities: linear in "
                         "them, not integrable):")
        out.lines.extend("  " + line for line in system.constraint_set().lines())
    velocity = getattr(L, 'nonholonomic_constraints', lambda: [])()
    if out.want('equations'):
        out.run("Lagrange equations", lambda lines: _lagrangian_equations(L, lines, out))
        if L.constraints() or velocity:
            out.run("Constraint forces", lambda lines: _constraint_forces(L, lines, out))
    cyclic = L.cyclic_coordinates()
    # absent from L but not cyclic: a damper, a force or a constraint acts on it
    acted = [q for q in L.coordinates() if q not in cyclic and not L.expr().has(q)]
    if acted and out.want('routh', 'stationary'):
        out.lines.append(f"Not cyclic (absent from L, but the dissipation, a generalized force "
                         f"or a constraint acts on them): {', '.join(map(str, acted))}")
    partial = bool(cyclic) and len(cyclic) < len(L.coordinates())
    R = None
    if partial and out.want('routh', 'stationary'):
        R = out.run("Routh function", lambda lines: _routh(L, cyclic, lines, out))
    if out.want('stationary') and system.operating_points():
        for name, point in system.operating_points().items():
            found = out.run(f"Stationary motions (operating point {name!r})",
                            lambda lines, point=point: _operating_point(system, L, point, lines,
                                                                        out))
            if found is not None:
                out.run(f"Stability conditions (operating point {name!r})",
                        lambda lines, found=found: _stability_conditions(
                            *found, system.positive_parameters(), lines, out))
    if out.want('stationary') and velocity:
        if not system.operating_points():
            out.lines.append("Stationary motions: give operating points (operating_points:) to "
                             "linearize about steady motions with velocity constraints")
    elif out.want('stationary'):
        if partial and R is None:
            out.lines.append("Stationary motions: not available (the Routh function is not)")
        else:
            def stationary(lines):
                # the solver splits the system into cases: up to 2^k for k unknowns
                F = R or L
                out.check("the stationary motions (terms of the function at rest times 2^k "
                          "for k unknowns)",
                          polynomial_terms(F.expr()) * 2 ** len(F.coordinates()))
                _stationary(L, cyclic, lines, system.positive_parameters())
            out.run("Stationary motions" if partial else "Equilibria", stationary)
    if out.want('hamiltonian'):
        out.run("Hamiltonian", lambda lines: _hamiltonian(L, lines, out))


def _routh(L, cyclic, lines, out):
    A = L.mass_matrix()
    index = [L.coordinates().index(q) for q in cyclic]
    block = A.matrix_from_rows_and_columns(index, index)
    out.check("the Routh function (determinant of the cyclic block of the mass matrix, "
              "times the terms of L)",
              determinant_terms(_matrix_terms(block)) * polynomial_terms(L.expr()))
    R = L.routh(cyclic)
    if out.want('routh'):
        lines.append(f"Routh function for the cyclic coordinates {', '.join(map(str, cyclic))} "
                     f"(momenta {', '.join(map(str, R.momenta()))}):")
        _formula(lines, "R = ", R.expr())
        out.check("the Routh equations", equations_estimate(R))
        lines.append("Routh equations (E_i = 0):")
        for q, e in zip(R.coordinates(), R.equations()):
            _formula(lines, f"[{q}] ", e)
    return R


def _hamiltonian(L, lines, out):
    n = len(L.coordinates())
    out.check("the Hamiltonian (n^2 times the determinant of the mass matrix)",
              n ** 2 * determinant_terms(_matrix_terms(L.mass_matrix())))
    H = L.hamiltonian()
    if H.is_singular():
        D = H.constraints()
        lines.append(f"Singular Lagrangian: Dirac's scheme ({D}):")
        for c in D.constraints():
            _formula(lines, "constraint ", c)
    lines.append("Hamiltonian:")
    _formula(lines, "H = ", H.expr())


def _stationary(L, cyclic, lines, positive=()):
    r"""The stationary motions (Routh function at rest, solved for the cyclic
    momenta) or equilibria, each with its existence conditions and a
    stability verdict (Routh--Lyapunov, then first approximation)."""
    from ..analysis import stationary_motions
    reduced = L.routh(cyclic) if cyclic and len(cyclic) < len(L.coordinates()) else L
    routh = reduced is not L
    what = ("Stationary motions (Routh function at rest, cyclic momenta constant)"
            if routh else "Equilibria (equations at rest)")
    try:
        solutions = stationary_motions(reduced, solve_for=reduced.momenta() if routh else None,
                                       positive=positive)
    except DynSymError as err:
        lines.append(f"{what}: not available ({err})")
        return
    lines.append(f"{what}:")
    for e in solutions.equations():
        _formula(lines, "0 = ", e)
    lines.extend(solutions.report_lines(
        lambda out, e: _formula(out, "0 = ", e, indent="    ")))


def _linear_circuit_stability(circuit, L, lines, out):
    from ..analysis import linearize, lienard_chipart_conditions
    sources = {SR.var(b.name): 0 for b in circuit.branches()
               if b.kind in ('voltage_source', 'current_source')}
    # declared signs, else the symbols of the element values (physical
    # resistances, inductances and capacitances; mutual inductances have no sign)
    values = circuit.positive_parameters() or sorted(
        {v for b in circuit.branches() if b.value is not None
         for v in SR(b.value).variables()} - set(sources), key=str)
    lam = SR.var('lambda_')
    free = L.subs(sources) if sources else L
    out.check("the characteristic polynomial (permanent bound of the determinant)",
              characteristic_estimate(free))
    system = linearize(free, {q: 0 for q in free.coordinates()})
    poly = system.characteristic_polynomial(lam, positive=values)
    lines.append("Stability of the free circuit (sources off), loop method:")
    _formula(lines, "characteristic polynomial: ", poly)
    if poly.subs({lam: 0}).is_zero():
        lines.append("  lambda = 0 is a root: some loop charge is not fixed by a capacitor, "
                     "so the zero solution in loop charges is not asymptotically stable "
                     "(the currents may still decay)")
        return
    _check_routh_scheme(poly, lam, out.budget)
    conditions = lienard_chipart_conditions(poly, lam, positive=values, budget=out.budget)
    if conditions:
        lines.append("  Lienard-Chipart conditions (each > 0), element values positive:")
        for c in conditions:
            _formula(lines, "", c, indent="    ")
    else:
        lines.append("  asymptotically stable for all positive element values "
                     "(Lienard-Chipart conditions hold identically)")


def _check_routh_scheme(poly, lam, budget):
    # the Hurwitz determinants come from the fraction-free Routh scheme,
    # which stops before a product of more than ``budget`` pairs of terms:
    # run it with the budget first (the costly products are not made)
    from sage.rings.rational_field import QQ
    try:
        from ..analysis.hurwitz import _normalized_coefficients, _routh_scheme
    except ImportError:     # without the probe: the products of the coefficients
        if polynomial_terms(poly) ** 2 > budget:
            raise BudgetError("the Lienard-Chipart conditions (the square of the terms of "
                              "the characteristic polynomial)",
                              estimate=polynomial_terms(poly) ** 2, budget=budget) from None
        return
    a = _normalized_coefficients(poly, lam)
    n = len(a) - 1
    if n < 2 or a[0].parent() is QQ:
        return
    deltas, reached = _routh_scheme(a, n - 1, budget)
    if reached < n - 1 and deltas[reached] != 0:
        raise BudgetError(f"the Lienard-Chipart conditions: a product of the Routh scheme "
                          f"would multiply more than {budget} pairs of terms, over the budget "
                          f"of {budget}")


def equations_estimate(L):
    r"""
    The size estimate of the Lagrange equations of ``L``, checked before
    they are derived: for each coordinate, the terms of `\partial L/\partial
    \dot q_i` times `2n + 1` (the total time derivative differentiates each
    factor in `q, \dot q, t`), plus those of `\partial L/\partial q_i`, of
    the dissipation and of the generalized force.

    EXAMPLES::

        sage: from sage_dynsym import Lagrangian
        sage: from sage_dynsym.report import equations_estimate
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
    (:func:`determinant_terms`) of the term counts of the second
    derivatives of `L` and of the dissipation that make up the matrix.

    EXAMPLES::

        sage: from sage_dynsym.circuits import Circuit
        sage: from sage_dynsym.report import characteristic_estimate
        sage: C = Circuit([[0, 1, 'R1'], [1, 2, 'L1'], [2, 0, 'C1']])
        sage: characteristic_estimate(C.lagrangian())   # L1*lambda^2 + R1*lambda + 1/C1
        3
    """
    q, dq = L.coordinates(), L.velocities()
    expr, R = SR(L.expr()), SR(L.dissipation())
    by_velocity = [expr.diff(v) for v in dq]
    by_coordinate = [expr.diff(x) for x in q]
    damping = [R.diff(v) for v in dq]
    counts = [[polynomial_terms(by_velocity[i].diff(dq[j])) + polynomial_terms(damping[i].diff(dq[j]))
               + polynomial_terms(by_velocity[i].diff(q[j]))
               + polynomial_terms(by_coordinate[i].diff(q[j])) for j in range(len(q))]
              for i in range(len(q))]
    return determinant_terms(counts)


def _lagrangian_equations(L, lines, out):
    out.check("the Lagrange equations (terms of dL/d(dq_i) times 2n + 1, and of dL/dq_i)",
              equations_estimate(L))
    lines.append("Lagrange equations (E_i = 0):")
    for q, e in zip(L.coordinates(), L.lagrange_equations()):
        _formula(lines, f"[{q}] ", e)
    for mu, f in zip(L.multipliers(), L.constraints()):
        _formula(lines, f"constraint with multiplier {mu} (terms -{mu} df/dq_i): 0 = ", f)
    for mu, g in zip(getattr(L, 'velocity_multipliers', lambda: [])(),
                     getattr(L, 'nonholonomic_constraints', lambda: [])()):
        _formula(lines, f"velocity constraint with multiplier {mu} (terms -{mu} dg/d(dq_i)): "
                        "0 = ", g)


def _constraint_forces(L, lines, out):
    out.check("the accelerations and multipliers (the equations' terms times (n + m)^2)",
              equations_estimate(L) * (len(L.coordinates()) + len(L.multipliers())) ** 2)
    solved = L.accelerations_and_multipliers()
    lines.append("Multipliers (constraint forces), solved with the accelerations:")
    for mu in L.multipliers():
        _formula(lines, f"{mu} = ", solved[mu])


def _operating_point(system, L, point, lines, out):
    r"""A steady motion: the linearization in the coordinates of the
    operating point, its characteristic polynomial and the Lienard--Chipart
    conditions (see :mod:`~sage_dynsym.analysis.steady`)."""
    from ..analysis import linearize
    out.check("the linearization about the operating point (the terms of the Lagrange "
              "equations)", equations_estimate(L))
    linear = linearize(system, point)
    motion = linear.steady_motion()
    given = ", ".join(f"{k} = {v}" for k, v in list(point.at().items())
                      + list(point.velocities().items()))
    lines.append(f"Stationary motions (operating point {point.name()!r}: {given}), linearized "
                 f"in {', '.join(map(str, motion.coordinates()))}:")
    lines.append(f"  independent speeds: {', '.join(map(str, motion.speeds()))}"
                 + "".join(f"; {k} = {v} to first order"
                           for k, v in motion.dependent_coordinates().items())
                 + (f"; left out (ignorable): {', '.join(map(str, motion.dropped()))}"
                    if motion.dropped() else "")
                 + (f"; decoupled speeds: {', '.join(map(str, motion.decoupled_speeds()))}"
                    if motion.decoupled_speeds() else ""))
    lines.append("  velocities along the motion: " + ", ".join(
        f"{k} = {v}" for k, v in motion.velocities().items()))
    if motion.multipliers():
        lines.append("  constraint multipliers along the motion: " + ", ".join(
            f"{k} = {v}" for k, v in motion.multipliers().items()))
    lines.append("  M z'' + S z' + W z = 0 with")
    for label, X in (("M", linear.M()), ("S", linear.S()), ("W", linear.W())):
        _formula(lines, f"{label} = ", [list(row) for row in X.rows()], indent="    ")
    lam = SR.var('lambda_')
    out.check("the characteristic polynomial (permanent bound of the determinant)",
              determinant_terms([[polynomial_terms(a) + polynomial_terms(b) + polynomial_terms(c)
                                  for a, b, c in zip(*rows)]
                                 for rows in zip(linear.M().rows(), linear.S().rows(),
                                                 linear.W().rows())]))
    poly = linear.characteristic_polynomial(lam).expand()
    _formula(lines, "characteristic polynomial: ", poly)
    return poly, lam


def _stability_conditions(poly, lam, positive, lines, out):
    # the Lienard--Chipart conditions of the roots other than lambda = 0;
    # sines and cosines of parameters (a steer axis tilt) are symbols there
    from ..analysis import lienard_chipart_conditions
    from ..algebra.trigonometric import TrigPolynomialRing
    zeros = 0
    while poly.subs({lam: 0}).is_zero() and poly.degree(lam) > 0:
        poly, zeros = (poly / lam).expand(), zeros + 1
    if zeros:
        lines.append(f"  lambda = 0 is a root of multiplicity {zeros} (neutral directions: a "
                     "family of steady motions); the conditions concern the other roots")
    if poly.degree(lam) < 1:
        return
    ring = TrigPolynomialRing.for_expressions([poly], [lam], fractions=True)
    symbols = {}
    for angle in ring.angles():
        tag = len(symbols) // 2
        symbols[SR(angle).cos()] = SR.var(f'dynsym_cos{tag}')
        symbols[SR(angle).sin()] = SR.var(f'dynsym_sin{tag}')
    back = {v: k for k, v in symbols.items()}
    flat = poly.subs(symbols)
    odd = [flat.coefficient(lam, k) for k in range(1, flat.degree(lam) + 1, 2)]
    if all(SR(c).is_zero() for c in odd):
        # no dissipation: stable in first approximation when the roots are
        # simple and purely imaginary, i.e. h(mu) of p = h(lambda^2) has
        # simple negative real roots
        from ..analysis import real_negative_roots_conditions
        mu = SR.var('mu_')
        even = flat.subs({lam: mu.sqrt()}).expand()
        _check_routh_scheme(even, mu, out.budget)
        conditions = real_negative_roots_conditions(even, mu, positive=positive,
                                                    budget=out.budget)
        lines.append("  no asymptotic stability (the odd coefficients vanish: no dissipation);"
                     " the roots are simple and purely imaginary iff (each > 0)"
                     + (", with the declared positive parameters:" if positive else ":"))
        for c in conditions:
            _formula(lines, "", SR(c).subs(back), indent="    ")
        return
    _check_routh_scheme(flat, lam, out.budget)
    conditions = lienard_chipart_conditions(flat, lam, positive=positive, budget=out.budget)
    if conditions:
        lines.append("  Lienard-Chipart conditions (each > 0) for asymptotic stability"
                     + (", with the declared positive parameters:" if positive else ":"))
        for c in conditions:
            _formula(lines, "", SR(c).subs(back), indent="    ")
    else:
        lines.append("  asymptotically stable for all admissible parameters (the "
                     "Lienard-Chipart conditions hold identically)")


def _circuit(circuit, out):
    from ..errors import CircuitError
    out.lines.append(f"== {circuit.name() or 'circuit'} (circuit: {len(circuit.branches())} "
                     f"branches on {len(circuit.nodes())} nodes) ==")
    _conditions(circuit, out)
    estimate = circuit_estimate(circuit)
    if out.want('mixed_potential', 'state_equations', 'lyapunov'):
        def state_equations(lines):
            out.check("the state equations (branches times the squared terms of the "
                      "largest element value)", estimate)
            try:
                return circuit.state_equations()
            except CircuitError as err:
                lines.append(f"No state equations: {err}")
                return None
        equations = out.run("State equations", state_equations)
        # the mixed potential exists for complete circuits only; the others
        # get their state equations from nodal analysis
        split = equations is not None and circuit.has_mixed_potential()
        if split and out.want('mixed_potential'):
            def potential(lines):
                lines.append("Mixed potential P(i, u):")
                _formula(lines, "P = ", circuit.mixed_potential())
            out.run("Mixed potential", potential)
        if equations is not None and out.want('state_equations'):
            def state(lines):
                lines.append("State equations (L di/dt = dP/di, C du/dt = -dP/du)" if split
                             else "State equations (nodal analysis; capacitor loops and "
                                  "inductor cut-sets reduce the state):")
                for label, e in zip(circuit.state_equation_labels(), equations):
                    _formula(lines, f"[{label}] ", e)
            out.run("State equations", state)
        if split and out.want('lyapunov'):
            def lyapunov(lines):
                # dP/dt = sum of (dP/dx_k) dx_k/dt: each state equation squared
                out.check("dP/dt (the squares of the state equations)",
                          sum(polynomial_terms(e) ** 2 for e in equations))
                lines.append("Time derivative of P along the state equations "
                             "(Lyapunov analogue):")
                _formula(lines, "dP/dt = ", circuit.brayton_moser().time_derivative())
            out.run("dP/dt", lyapunov)
    if not out.want('lagrangian', 'equations', 'stability'):
        return

    def loop_lagrangian(lines):
        out.check("the loop Lagrangian (branches times the squared terms of the largest "
                  "element value)", estimate)
        try:
            return circuit.lagrangian(method="loop")
        except CircuitError as err:
            lines.append(f"No loop Lagrangian: {err}")
            return None
    L = out.run("Loop Lagrangian", loop_lagrangian)
    if L is None:
        return
    if out.want('lagrangian'):
        def lagrangian(lines):
            lines.append("Lagrangian (loop-current method):")
            _formula(lines, "L = ", L.expr())
        out.run("Lagrangian", lagrangian)
    if out.want('equations'):
        out.run("Lagrange equations", lambda lines: _lagrangian_equations(L, lines, out))
    if out.want('stability'):
        out.run("Stability of the free circuit",
                lambda lines: _linear_circuit_stability(circuit, L, lines, out))


def report(model, sections=None, budget=DEFAULT_BUDGET, analysis=True, failed=None):
    r"""
    A text report of ``model`` (see the module documentation).

    INPUT:

    - ``model`` -- a :class:`~sage_dynsym.mechanics.system.MechanicalSystem`
      or a :class:`~sage_dynsym.circuits.circuit.Circuit`
    - ``sections`` -- (default: all) the keys of :data:`SECTIONS` to print
      (the sections that do not apply to the model are ignored)
    - ``budget`` -- (default: :data:`DEFAULT_BUDGET`) the size budget of
      each section, in polynomial terms
    - ``analysis`` -- (default: ``True``) whether to include the analysis
      sections (:data:`ANALYSIS_SECTIONS`)
    - ``failed`` -- (optional) a list: the titles of the sections that
      failed on an error that is not the package's own (``section failed:
      ...``) are appended to it (the command line's exit status 3)

    OUTPUT: a string

    Each section estimates the number of polynomial terms it would create
    *before* its expensive step (expanding a determinant, deriving the
    Lagrangian of a long chain, ...): over the budget it is replaced by one
    line saying so, and the rest of the report is still printed. A section
    that fails for another reason is also one line (the error's class and
    message), never a traceback.

    EXAMPLES::

        sage: from sage_dynsym import load
        sage: from sage_dynsym.description import example_path
        sage: from sage_dynsym.report import report
        sage: text = report(load(example_path('nonlinear_circuit.yaml')))
        sage: print(text.splitlines()[0])
        == nonlinear circuit of Example 2 (circuit: 13 branches on 5 nodes) ==
        sage: 'State equations' in text
        True

    Sections and budget::

        sage: from sage_dynsym.circuits import Circuit
        sage: C = Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 3, 'L1'], [3, 0, 'C1'],
        ....:              [3, 4, 'R2'], [4, 0, 'L2']], name='RLC')
        sage: print(report(C, sections=['lagrangian']))
        == RLC (circuit: 6 branches on 5 nodes) ==
        Lagrangian (loop-current method):
          L = 1/2*L1*dq1^2 + 1/2*L2*dq2^2 - 1/2*(q1 - q2)^2/C1
          LaTeX: ...
        sage: print(report(C, sections=['equations', 'stability'], budget=9))
        == RLC (circuit: 6 branches on 5 nodes) ==
        Lagrange equations: skipped, the Lagrange equations (terms of dL/d(dq_i) times 2n + 1, and of dL/dq_i): about 17 polynomial terms, over the budget of 9 (raise it with --budget)
        Stability of the free circuit: skipped, the characteristic polynomial (permanent bound of the determinant): about 10 polynomial terms, over the budget of 9 (raise it with --budget)
        sage: pendulum = load(example_path('spherical_pendulum.yaml'))
        sage: print(report(pendulum, budget=10))
        == spherical pendulum (mechanical system: 1 body, coordinates psi, theta) ==
        Lagrangian: skipped, the Lagrangian (n^2 2^r T^2: coordinates, varying angles along a chain, terms of the data): about 16 polynomial terms, over the budget of 10 (raise it with --budget)
        sage: print(report(pendulum, sections=['hamiltonian', 'stationary'], analysis=False))
        == spherical pendulum (mechanical system: 1 body, coordinates psi, theta) ==
        Hamiltonian:
          H = ...
          LaTeX: ...

    TESTS::

        sage: report(42)
        Traceback (most recent call last):
        ...
        DynSymError: cannot report on Integer: expected a model (a mechanical system or a circuit)
        sage: report(C, sections=['colour'])
        Traceback (most recent call last):
        ...
        DynSymError: unknown report section 'colour'; the sections are: lagrangian, equations, routh, stationary, hamiltonian, mixed_potential, state_equations, lyapunov, stability, casimirs, integrals
    """
    wanted = list(SECTIONS) if sections is None else list(sections)
    for key in wanted:
        if key not in SECTIONS:
            raise DynSymError(f"unknown report section {key!r}; the sections are: "
                              f"{', '.join(SECTIONS)}")
    if not analysis:
        wanted = [key for key in wanted if key not in ANALYSIS_SECTIONS]
    budget = count(budget, 'budget', error=DynSymError)
    if failed is not None and not isinstance(failed, list):
        raise DynSymError(f"failed must be a list, got {failed!r}")
    out = _Report(wanted, budget, failed)
    renderer = _RENDERERS.get(getattr(model, 'kind', None))
    if renderer is None:
        raise DynSymError(f"cannot report on {type(model).__name__}: expected a model "
                          "(a mechanical system or a circuit)")
    renderer(model, out)
    return "\n".join(out.lines)


def _lie_poisson(system, out):
    from ..lie.description import lie_report
    out.lines.extend(lie_report(system, sections=out.wanted, budget=out.budget,
                                failed=out.failed).split("\n"))


#: How each kind of model is reported (by :attr:`~sage_dynsym.dynamics.model.Model.kind`).
_RENDERERS = {'mechanical': _mechanical, 'circuit': _circuit, 'lie_poisson': _lie_poisson}
