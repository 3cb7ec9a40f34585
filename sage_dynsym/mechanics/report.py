r"""
The report of a mechanical system

The sections (see :mod:`sage_dynsym.dynamics.reporting`) of the report of
a :class:`~sage_dynsym.mechanics.system.MechanicalSystem`: its Lagrangian,
the constraints, the Lagrange equations and the constraint forces, the
Routh function for the cyclic coordinates, the stationary motions (or
equilibria, or the steady motions of its operating points, linearized)
with their stability, and the Hamiltonian. The Lagrangian's size is
estimated from the description (:func:`lagrangian_estimate`) before it is
derived.

EXAMPLES::

    sage: from sage_dynsym import load
    sage: from sage_dynsym.description import example_path
    sage: S = load(example_path('spherical_pendulum.yaml'))
    sage: S.report_title()
    '== spherical pendulum (mechanical system: 1 body, coordinates psi, theta) =='
    sage: [s.key for s in S.report_sections()][:4]
    [None, 'lagrangian', ('lagrangian', 'equations'), 'equations']
"""
from sage.symbolic.ring import SR

from ..algebra.size import polynomial_terms, determinant_terms, TERMS_CAP
from ..dynamics.lagrangian_report import (equations_lines, constraint_forces_lines,
                                          routh_function, routh_lines, hamiltonian_lines,
                                          stationary_estimate, stationary_lines,
                                          equations_estimate, check_routh_scheme,
                                          coefficient_conditions_lines)
from ..dynamics.reporting import ReportSection, formula_lines, conditions_lines
from ..errors import BudgetError
from .force_functions import force_term_data

__all__ = ['lagrangian_estimate', 'report_title', 'report_sections', 'operating_point_lines',
           'stability_condition_lines']


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
        sage: from sage_dynsym.mechanics.report import lagrangian_estimate
        sage: lagrangian_estimate(load(example_path('spherical_pendulum.yaml')))
        16
        sage: from sage_dynsym import MechanicalSystem, RigidBody
        sage: x, m, k = var('x m k')
        sage: lagrangian_estimate(MechanicalSystem([RigidBody('b', joint=[x, 0, 0],
        ....:                                               mass=(m + k)^3)], [x]))
        16
    """
    depth, data = [0], []
    for k, body in enumerate(system.bodies(), 1):
        turning = sum(1 for _, angle in body.rotations() if SR(angle).variables())
        depth.append(depth[system.parent_index(k)] + turning)
        data += [body.mass()] + body.inertia().list() + list(body.joint())
        data += list(body.velocity() or ()) + list(body.mass_center())
    for term in system.force_terms():
        data += force_term_data(term)
    for load in system.loads():
        data += load.expressions()
    # the constraints given (the derived contact conditions of rolling disks
    # enter the equations linearly, through their multipliers)
    data += system.constraint_set().given_holonomic()
    largest = max([polynomial_terms(e) for e in data] + [1])
    n = len(system.coordinates())
    return min(n ** 2 * 2 ** max(depth) * largest ** 2, TERMS_CAP)


def report_title(system):
    r"""
    The heading of the report of ``system``.

    EXAMPLES: see the module documentation.
    """
    coordinates = ", ".join(map(str, system.coordinates()))
    n = len(system.bodies())
    return (f"== {system.name() or 'mechanical system'} (mechanical system: {n} "
            f"bod{'y' if n == 1 else 'ies'}, coordinates {coordinates}) ==")


def report_sections(system):
    r"""
    The sections of the report of the mechanical system ``system`` (see the
    module documentation), in order.

    EXAMPLES: see the module documentation, and
    :func:`~sage_dynsym.report.writer.report`.
    """
    positive = system.positive_parameters()

    def lagrangian(context):
        L = context.results['lagrangian'] = system.lagrangian()
        cyclic = L.cyclic_coordinates()
        context.results['cyclic'] = cyclic
        # some but not all coordinates cyclic: a Routh function reduces the system
        context.results['partial'] = bool(cyclic) and len(cyclic) < len(L.coordinates())
        return ["Lagrangian L = T + U:"] + formula_lines("", L.expr(), variables=L.velocities(),
                                                          named="the velocities")

    def constraints(context):
        if not system.constraint_set().lines():
            return None
        return (["Constraints (holonomic: f(q, t) = 0; on the velocities: linear in them, "
                 "not integrable):"] + ["  " + line for line in system.constraint_set().lines()])

    def not_cyclic(context):
        L, cyclic = context.results['lagrangian'], context.results['cyclic']
        # absent from L but not cyclic: a damper, a force or a constraint acts on it
        acted = [q for q in L.coordinates() if q not in cyclic and not L.expr().has(q)]
        if not acted:
            return None
        return [f"Not cyclic (absent from L, but the dissipation, a generalized force or a "
                f"constraint acts on them): {', '.join(map(str, acted))}"]

    def routh(context):
        L, cyclic = context.results['lagrangian'], context.results['cyclic']
        if not context.results['partial']:
            return None
        R = context.results['routh'] = routh_function(L, cyclic, context)
        return routh_lines(R, cyclic, context) if context.shown else []

    sections = [
        ReportSection(None, "Conditions", lambda context: conditions_lines(system)),
        ReportSection('lagrangian', "Lagrangian", lagrangian,
                      estimate=lambda context: lagrangian_estimate(system),
                      what="the Lagrangian (n^2 2^r T^2: coordinates, varying angles along a "
                           "chain, terms of the data)"),
        ReportSection(('lagrangian', 'equations'), "Constraints", constraints,
                      needs=['lagrangian'], auxiliary=True),
        ReportSection('equations', "Lagrange equations",
                      lambda context: equations_lines(context.results['lagrangian'], context),
                      needs=['lagrangian']),
        ReportSection('equations', "Constraint forces",
                      lambda context: constraint_forces_lines(context.results['lagrangian'],
                                                              context),
                      needs=['lagrangian'], auxiliary=True),
        ReportSection(('routh', 'stationary'), "Not cyclic", not_cyclic, needs=['lagrangian'],
                      auxiliary=True),
        ReportSection('routh', "Routh function", routh, needs=['lagrangian'],
                      absent="no Routh reduction: the Lagrangian has no cyclic coordinate, or "
                             "only cyclic ones"),
    ]
    points = system.operating_points()
    for name, point in points.items():
        sections += _operating_point_sections(system, name, point, positive)
    if system.nonholonomic_constraints():
        if not points:
            sections.append(ReportSection(
                'stationary', "Stationary motions",
                lambda context: ["Stationary motions: give operating points "
                                 "(operating_points:) to linearize about steady motions with "
                                 "velocity constraints"], analysis=True))
    else:
        sections.append(_stationary_section(positive))
    sections.append(ReportSection(
        'hamiltonian', "Hamiltonian",
        lambda context: hamiltonian_lines(context.results['lagrangian'], context),
        needs=['lagrangian']))
    return sections


def _stationary_section(positive):
    def stationary(context):
        L, R = context.results['lagrangian'], context.results.get('routh')
        if context.results['partial'] and R is None:
            return ["Stationary motions: not available (the Routh function is not)"]
        F = R if R is not None else L
        context.check("the stationary motions (terms of the function at rest times 2^k for "
                      "k unknowns)", stationary_estimate(F))
        return stationary_lines(L, R, positive)

    return ReportSection(
        'stationary',
        lambda results: "Stationary motions" if results.get('partial') else "Equilibria",
        stationary, needs=['lagrangian'], uses=['routh'], analysis=True)


def _operating_point_sections(system, name, point, positive):
    key = f"operating point {name!r}"

    def motion(context):
        lines, found = operating_point_lines(system, context.results['lagrangian'], point,
                                             context)
        context.results[key] = found
        return lines

    def stability(context):
        poly, lam, linear = context.results[key]
        try:
            return stability_condition_lines(poly, lam, positive, context, linear=linear)
        except BudgetError as err:
            # the conditions in the coefficients cost nothing; the coefficients
            # are in the report already
            lines = coefficient_conditions_lines(poly, lam, err.message)
            if lines is None:
                raise
            return [f"Stability conditions ({key}):"] + lines

    return [ReportSection(('stationary', key), f"Stationary motions ({key})", motion,
                          needs=['lagrangian'], analysis=True),
            ReportSection('stationary', f"Stability conditions ({key})", stability,
                          needs=[key], analysis=True)]


def operating_point_lines(system, L, point, context):
    r"""
    A steady motion of ``system`` (its operating ``point``): the
    linearization in the coordinates of the operating point, and its
    characteristic polynomial. Returns the lines and the triple
    ``(polynomial, variable, linear system)``.

    EXAMPLES: the report of ``examples/whipple_bicycle.yaml``
    (``sage-dynsym examples/whipple_bicycle.yaml``); see also
    :mod:`~sage_dynsym.analysis.steady`.
    """
    from ..analysis import linearize
    context.check("the linearization about the operating point (the terms of the Lagrange "
                  "equations)", equations_estimate(L))
    linear = linearize(system, point)
    motion = linear.steady_motion()
    given = ", ".join(f"{k} = {v}" for k, v in list(point.at().items())
                      + list(point.velocities().items()))
    lines = [f"Stationary motions (operating point {point.name()!r}: {given}), linearized "
             f"in {', '.join(map(str, motion.coordinates()))}:"]
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
        lines += formula_lines(f"{label} = ", [list(row) for row in X.rows()], indent="    ")
    lam = SR.var('lambda_')
    context.check("the characteristic polynomial (permanent bound of the determinant)",
                  determinant_terms([[polynomial_terms(a) + polynomial_terms(b)
                                      + polynomial_terms(c) for a, b, c in zip(*rows)]
                                     for rows in zip(linear.M().rows(), linear.S().rows(),
                                                     linear.W().rows())]))
    poly = linear.characteristic_polynomial(lam).expand()
    lines += formula_lines("characteristic polynomial: ", poly, variables=[lam])
    return lines, (poly, lam, linear)


def stability_condition_lines(poly, lam, positive, context, linear=None):
    r"""
    The stability of a linear system, as report lines: the verdict of the
    stability service (:meth:`~sage_dynsym.analysis.linear.LinearSystem.stability`)
    for ``linear``, with the parameters ``positive`` declared positive
    (ignorable coordinates left out, said in the reason); without
    ``linear``, for the companion system of the characteristic polynomial
    ``poly`` in ``lam``. The Routh scheme of ``poly`` is checked against
    the budget first.

    EXAMPLES::

        sage: from sage_dynsym.mechanics.report import stability_condition_lines
        sage: from sage_dynsym.dynamics.reporting import ReportContext
        sage: lam, c, k = var('lam c k')
        sage: for line in stability_condition_lines(lam^2 + c*lam + k, lam, [c],
        ....:                                       ReportContext({}, 100)):
        ....:     print(line)
          stability depends on the parameters:
            asymptotically stable (first approximation) where [k > 0]: ...
            unstable (first approximation) where [k < 0]: ...
    """
    from ..analysis import LinearSystem
    if linear is None:
        coefficients = SR(poly).expand().coefficients(lam, sparse=False)
        n = len(coefficients) - 1
        companion = [[1 if j == i + 1 else 0 for j in range(n)] for i in range(n - 1)]
        companion.append([-c / coefficients[-1] for c in coefficients[:-1]])
        linear = LinearSystem([SR.var(f'x{i}') for i in range(n)], J=companion)
    from ..algebra.translation import ParameterAtoms
    # the budget counts terms: atoms such as cos(alpha) count as symbols
    check_routh_scheme(ParameterAtoms([poly], [lam]).expression(poly), lam, context.budget)
    return linear.stability(positive=positive).report_lines()
