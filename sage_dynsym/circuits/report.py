r"""
The report of a circuit

The sections (see :mod:`sage_dynsym.dynamics.reporting`) of the report of
a :class:`~sage_dynsym.circuits.circuit.Circuit`: its state equations (by
the mixed potential when the circuit is complete, else by nodal analysis),
the mixed potential and its time derivative along the state equations, the
loop Lagrangian and its equations, and the stability of the free circuit
(sources off). Their size is estimated from the element values
(:func:`circuit_estimate`) before they are derived.

EXAMPLES::

    sage: from sage_dynsym import load
    sage: from sage_dynsym.description import example_path
    sage: C = load(example_path('nonlinear_circuit.yaml'))
    sage: C.report_title()
    '== nonlinear circuit of Example 2 (circuit: 13 branches on 5 nodes) =='
    sage: [s.name for s in C.report_sections()]
    ['Conditions', 'State equations', 'Mixed potential', 'State equations', 'dP/dt',
     'Loop Lagrangian', 'Lagrangian', 'Lagrange equations', 'Stability of the free circuit']
"""
from sage.symbolic.ring import SR

from ..algebra.size import polynomial_terms, TERMS_CAP
from ..dynamics.lagrangian_report import (equations_lines, characteristic_estimate,
                                          check_routh_scheme)
from ..dynamics.reporting import ReportSection, formula_lines, conditions_lines
from ..errors import CircuitError

__all__ = ['circuit_estimate', 'report_title', 'report_sections', 'free_stability_lines']


def circuit_estimate(circuit):
    r"""
    The size estimate of a circuit's mixed potential and state equations
    (and of its loop Lagrangian), checked before they are derived: the
    number of branches times the square of the most terms of one element
    value (a value is integrated, and multiplied by currents and voltages
    that are sums over the loops).

    EXAMPLES::

        sage: from sage_dynsym.circuits import Circuit
        sage: from sage_dynsym.circuits.report import circuit_estimate
        sage: circuit_estimate(Circuit([[1, 2, 'R1'], [2, 1, 'C1']]))
        2
        sage: circuit_estimate(Circuit([[1, 2, 'R1'], {'from': 2, 'to': 1, 'kind': 'capacitor',
        ....:     'name': 'C1', 'value': '(u + C0)^2'}], parameters=['C0']))
        18
    """
    values = [b.value for b in circuit.branches() if b.value is not None]
    values += [c.value for c in circuit.couplings()]
    largest = max([polynomial_terms(v) for v in values] + [1])
    return min(len(circuit.branches()) * largest ** 2, TERMS_CAP)


def report_title(circuit):
    r"""
    The heading of the report of ``circuit``.

    EXAMPLES: see the module documentation.
    """
    return (f"== {circuit.name() or 'circuit'} (circuit: {len(circuit.branches())} "
            f"branches on {len(circuit.nodes())} nodes) ==")


def report_sections(circuit):
    r"""
    The sections of the report of ``circuit`` (see the module
    documentation), in order.

    EXAMPLES: see the module documentation, and
    :func:`~sage_dynsym.report.writer.report`.
    """
    estimate = circuit_estimate(circuit)
    what = "branches times the squared terms of the largest element value"
    incomplete = ("the circuit is not complete (the mixed potential exists for complete "
                  "circuits only; its state equations come from nodal analysis)")

    def state_equations(context):
        try:
            context.results['state equations'] = circuit.state_equations()
        except CircuitError as err:
            return [f"No state equations: {err}"]
        # the mixed potential exists for complete circuits only; the others
        # get their state equations from nodal analysis
        context.results['complete'] = circuit.has_mixed_potential()
        return []

    def mixed_potential(context):
        if not context.results['complete']:
            return None
        return ["Mixed potential P(i, u):"] + formula_lines("P = ", circuit.mixed_potential())

    def equations(context):
        lines = ["State equations (L di/dt = dP/di, C du/dt = -dP/du)" if
                 context.results['complete'] else
                 "State equations (nodal analysis; capacitor loops and inductor cut-sets "
                 "reduce the state):"]
        for label, e in zip(circuit.state_equation_labels(),
                            context.results['state equations']):
            lines += formula_lines(f"[{label}] ", e)
        return lines

    def lyapunov(context):
        if not context.results['complete']:
            return None
        # dP/dt = sum of (dP/dx_k) dx_k/dt: each state equation squared
        context.check("dP/dt (the squares of the state equations)",
                      sum(polynomial_terms(e) ** 2 for e in context.results['state equations']))
        return (["Time derivative of P along the state equations (Lyapunov analogue):"]
                + formula_lines("dP/dt = ", circuit.brayton_moser().time_derivative()))

    def loop_lagrangian(context):
        try:
            context.results['loop lagrangian'] = circuit.lagrangian(method="loop")
        except CircuitError as err:
            return [f"No loop Lagrangian: {err}"]
        return []

    def loop(section):
        return lambda context: section(context.results['loop lagrangian'], context)

    return [
        ReportSection(None, "Conditions", lambda context: conditions_lines(circuit)),
        ReportSection(('mixed_potential', 'state_equations', 'lyapunov', 'state equations'),
                      "State equations", state_equations, estimate=lambda context: estimate,
                      what=f"the state equations ({what})"),
        ReportSection('mixed_potential', "Mixed potential", mixed_potential,
                      needs=['state equations'], absent=incomplete),
        ReportSection('state_equations', "State equations", equations,
                      needs=['state equations']),
        ReportSection('lyapunov', "dP/dt", lyapunov, needs=['state equations'],
                      analysis=True, absent=incomplete),
        ReportSection(('lagrangian', 'equations', 'stability', 'loop lagrangian'),
                      "Loop Lagrangian", loop_lagrangian, estimate=lambda context: estimate,
                      what=f"the loop Lagrangian ({what})"),
        ReportSection('lagrangian', "Lagrangian",
                      loop(lambda L, context: ["Lagrangian (loop-current method):"]
                           + formula_lines("L = ", L.expr())),
                      needs=['loop lagrangian']),
        ReportSection('equations', "Lagrange equations", loop(equations_lines),
                      needs=['loop lagrangian']),
        ReportSection('stability', "Stability of the free circuit",
                      loop(lambda L, context: free_stability_lines(circuit, L, context)),
                      needs=['loop lagrangian'], analysis=True),
    ]


def free_stability_lines(circuit, L, context):
    r"""
    The stability of the free circuit (sources off), asked of its free
    state equations (:meth:`~sage_dynsym.circuits.circuit.Circuit.free_linear_system`,
    what the stability map judges too) by the stability service
    (:meth:`~sage_dynsym.analysis.linear.LinearSystem.stability`), the
    element values positive. ``L``, the loop Lagrangian, sizes the work.

    EXAMPLES::

        sage: from sage_dynsym.circuits import Circuit
        sage: from sage_dynsym.circuits.report import free_stability_lines
        sage: from sage_dynsym.dynamics.reporting import ReportContext, render
        sage: C = Circuit([[0, 1, 'R1'], [1, 2, 'L1'], [2, 0, 'C1']])
        sage: print("\n".join(render(free_stability_lines(C, C.lagrangian(),
        ....:                                               ReportContext({}, 100)))))
        Stability of the free circuit (sources off), from its state equations:
          characteristic polynomial: ...
          stability: asymptotically stable (energy): ...
    """
    sources = circuit.source_values_off()
    # declared signs, else the symbols of the element values (physical
    # resistances, inductances and capacitances; mutual inductances have no sign)
    values = circuit.positive_parameters() or sorted(
        {v for b in circuit.branches() if b.value is not None
         for v in SR(b.value).variables()} - set(sources), key=str)
    from ..analysis.stability import energy_stability
    lam = SR.var('lambda_')
    free = L.subs(sources) if sources else L
    context.check("the characteristic polynomial (permanent bound of the determinant)",
                  characteristic_estimate(free))
    system = circuit.free_linear_system()
    poly = system.characteristic_polynomial(lam, positive=values)
    lines = ["Stability of the free circuit (sources off), from its state equations:"]
    lines += formula_lines("characteristic polynomial: ", poly, variables=[lam])
    # a passive circuit is decided by its energy, without the Routh scheme
    verdict = energy_stability(system, positive=values)
    if verdict is None:
        check_routh_scheme(poly, lam, context.budget)
        verdict = system.stability(positive=values)
    return lines + verdict.report_lines()
