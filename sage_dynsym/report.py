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
from sage.misc.latex import latex

from .errors import DynSymError


def _formula(lines, label, expr, indent="  "):
    lines.append(f"{indent}{label}{expr}")
    lines.append(f"{indent}  LaTeX: {latex(expr)}")


def _mechanical(system, lines):
    coordinates = ", ".join(map(str, system.coordinates()))
    n = len(system.bodies())
    lines.append(f"== {system.name() or 'mechanical system'} (mechanical system: {n} "
                 f"bod{'y' if n == 1 else 'ies'}, coordinates {coordinates}) ==")
    L = system.lagrangian()
    lines.append("Lagrangian L = T + U:")
    _formula(lines, "", L.expr())
    _lagrangian_equations(L, lines)
    cyclic = L.cyclic_coordinates()
    if cyclic and len(cyclic) < len(L.coordinates()):
        R = L.routh(cyclic)
        lines.append(f"Routh function for the cyclic coordinates {', '.join(map(str, cyclic))} "
                     f"(momenta {', '.join(map(str, R.momenta()))}):")
        _formula(lines, "R = ", R.expr())
        lines.append("Routh equations (E_i = 0):")
        for q, e in zip(R.coordinates(), R.equations()):
            _formula(lines, f"[{q}] ", e)
    _stationary(L, cyclic, lines)
    H = L.hamiltonian()
    if H.is_singular():
        D = H.constraints()
        lines.append(f"Singular Lagrangian: Dirac's scheme ({D}):")
        for c in D.constraints():
            _formula(lines, "constraint ", c)
    lines.append("Hamiltonian:")
    _formula(lines, "H = ", H.expr())


def _stationary(L, cyclic, lines):
    r"""The stationary motions (Routh function at rest, solved for the cyclic
    momenta) or equilibria, each with its existence conditions and a
    stability verdict (Routh--Lyapunov, then first approximation)."""
    from .analysis import stationary_motions
    reduced = L.routh(cyclic) if cyclic and len(cyclic) < len(L.coordinates()) else L
    routh = reduced is not L
    what = ("Stationary motions (Routh function at rest, cyclic momenta constant)"
            if routh else "Equilibria (equations at rest)")
    positive = getattr(L, 'positive_parameters', lambda: [])()
    try:
        solutions = stationary_motions(reduced, solve_for=reduced.momenta() if routh else None,
                                       positive=positive)
    except DynSymError as err:
        lines.append(f"{what}: not available ({err})")
        return
    lines.append(f"{what}:")
    for e in solutions.equations():
        _formula(lines, "0 = ", e)
    if solutions.is_empty():
        lines.append("  no real solutions (for generic parameter values)")
    if not solutions.is_complete():
        lines.append("  (transcendental equations: solutions found by Maxima's solve, "
                     "possibly not all)")
    for k, s in enumerate(solutions, 1):
        values = ", ".join(f"{v} = {e}" for v, e in s.point().items() if str(v) != str(e))
        kind = "isolated" if s.dimension() == 0 else f"{s.dimension()}-parameter family"
        if not s.is_explicit():
            kind += ", implicit"
        lines.append(f"  solution {k} ({kind}): {values or 'given by its equations'}")
        for e in s.equations():
            _formula(lines, "0 = ", e, indent="    ")
        try:
            conditions = s.conditions()
            if conditions:
                lines.append("    exists if: " + ", ".join(map(str, conditions)))
            verdict = s.stability()
        except DynSymError as err:
            lines.append(f"    stability: not decided ({err})")
            continue
        _verdict(verdict, lines)


def _verdict(verdict, lines):
    if verdict.verdict() != 'depends on the parameters':
        method = f" ({verdict.method()})" if verdict.method() else ""
        lines.append(f"    stability: {verdict.verdict()}{method}: {verdict.reason()}")
        return
    lines.append("    stability depends on the parameters:")
    for v in verdict.cases():
        where = " or ".join("[" + ", ".join(map(str, alt)) + "]" for alt in v.region())
        lines.append(f"      {v.verdict()} ({v.method()}) where {where}")


def _linear_circuit_stability(circuit, L, lines):
    from sage.symbolic.ring import SR
    from .analysis import linearize, lienard_chipart_conditions
    sources = {SR.var(b.name): 0 for b in circuit.branches()
               if b.kind in ('voltage_source', 'current_source')}
    values = sorted({v for b in circuit.branches() if b.value is not None
                     for v in SR(b.value).variables()} - set(sources), key=str)
    lam = SR.var('lambda_')
    try:
        free = L.subs(sources) if sources else L
        system = linearize(free, {q: 0 for q in free.coordinates()})
        poly = system.characteristic_polynomial(lam)
        conditions = lienard_chipart_conditions(poly, lam, positive=values)
    except DynSymError as err:
        lines.append(f"Stability of the free circuit: not available ({err})")
        return
    lines.append("Stability of the free circuit (sources off), loop method:")
    _formula(lines, "characteristic polynomial: ", poly)
    if poly.subs({lam: 0}).is_zero():
        lines.append("  lambda = 0 is a root: some loop charge is not fixed by a capacitor, "
                     "so the zero solution in loop charges is not asymptotically stable "
                     "(the currents may still decay)")
    elif conditions:
        lines.append("  Lienard-Chipart conditions (each > 0), element values positive:")
        for c in conditions:
            _formula(lines, "", c, indent="    ")
    else:
        lines.append("  asymptotically stable for all positive element values "
                     "(Lienard-Chipart conditions hold identically)")


def _lagrangian_equations(L, lines):
    lines.append("Lagrange equations (E_i = 0):")
    for q, e in zip(L.coordinates(), L.lagrange_equations()):
        _formula(lines, f"[{q}] ", e)


def _circuit(circuit, lines):
    from .errors import CircuitError
    lines.append(f"== {circuit.name() or 'circuit'} (circuit: {len(circuit.branches())} "
                 f"branches on {len(circuit.nodes())} nodes) ==")
    try:
        equations = circuit.state_equations()
    except CircuitError as err:
        lines.append(f"No Brayton-Moser form: {err}")
    else:
        lines.append("Mixed potential P(i, u):")
        _formula(lines, "P = ", circuit.mixed_potential())
        lines.append("State equations (L di/dt = dP/di, C du/dt = -dP/du):")
        for (v, element), e in zip(circuit.state_variables(), equations):
            _formula(lines, f"[{element} d{v}/dt] ", e)
        lines.append("Time derivative of P along the state equations (Lyapunov analogue):")
        _formula(lines, "dP/dt = ", circuit.brayton_moser().time_derivative())
    try:
        L = circuit.lagrangian(method="loop")
    except CircuitError as err:
        lines.append(f"No loop Lagrangian: {err}")
    else:
        lines.append("Lagrangian (loop-current method):")
        _formula(lines, "L = ", L.expr())
        _lagrangian_equations(L, lines)
        _linear_circuit_stability(circuit, L, lines)


def report(model):
    r"""
    A text report of ``model`` (see the module documentation).

    INPUT:

    - ``model`` -- a :class:`~sage_dynsym.mechanical_system.MechanicalSystem`
      or a :class:`~sage_dynsym.circuits.circuit.Circuit`

    OUTPUT: a string

    EXAMPLES::

        sage: from sage_dynsym import load
        sage: from sage_dynsym.description import example_path
        sage: from sage_dynsym.report import report
        sage: text = report(load(example_path('nonlinear_circuit.yaml')))
        sage: print(text.splitlines()[0])
        == nonlinear circuit of Example 2 (circuit: 13 branches on 5 nodes) ==
        sage: 'State equations' in text
        True

    TESTS::

        sage: report(42)
        Traceback (most recent call last):
        ...
        DynSymError: cannot report on Integer: expected a mechanical system or a circuit
    """
    from .mechanical_system import MechanicalSystem
    from .circuits import Circuit
    lines = []
    if isinstance(model, MechanicalSystem):
        _mechanical(model, lines)
    elif isinstance(model, Circuit):
        _circuit(model, lines)
    else:
        raise DynSymError(f"cannot report on {type(model).__name__}: expected a mechanical "
                          "system or a circuit")
    return "\n".join(lines)
