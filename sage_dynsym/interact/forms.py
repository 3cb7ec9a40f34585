r"""
The forms of the equations of a model, as data and as LaTeX

:func:`derive` computes one classical form of a model's equations --
Lagrange equations of the second kind, Routh equations for chosen cyclic
coordinates, Hamilton equations, or for a circuit the Brayton--Moser state
equations and the loop / node Lagrangians -- and returns the characteristic
function with the list of equations. :func:`derivation_latex` renders it as
one LaTeX ``aligned`` block; the interactive pages
(:mod:`sage_dynsym.interact.pages`) display that block.

EXAMPLES::

    sage: from sage_dynsym import load
    sage: from sage_dynsym.description import example_path
    sage: from sage_dynsym.interact.forms import available_forms, derive, derivation_latex
    sage: S = load(example_path('spherical_pendulum.yaml'))
    sage: available_forms(S)
    ['Lagrange', 'Routh', 'Hamilton']
    sage: d = derive(S, 'Routh', cyclic=['psi'])
    sage: d.function
    ('R', 1/2*dtheta^2*l^2*m - g*l*m*cos(theta) - 1/2*p_psi^2/(l^2*m*sin(theta)^2))
    sage: d.equations[0][1]
    ddtheta*l^2*m - g*l*m*sin(theta) - p_psi^2*cos(theta)/(l^2*m*sin(theta)^3)
    sage: print(derivation_latex(d))
    \begin{aligned}
    R &= \frac{1}{2} \, {\dot{\theta}}^{2} l^{2} m - ...\\
    0 &= {\ddot{\theta}} l^{2} m - ...
    \end{aligned}
"""
from collections import namedtuple

from sage.misc.latex import latex
from sage.symbolic.ring import SR

from ..errors import ModelError

#: ``function`` is a pair (name, expression); ``equations`` a list of pairs
#: ``(lhs, rhs)`` meaning ``lhs = rhs`` (``lhs`` a LaTeX string).
Derivation = namedtuple("Derivation", ["form", "function", "equations", "note"])
Derivation.__doc__ = r"""
One form of the equations of a model, as returned by :func:`derive`.

EXAMPLES::

    sage: from sage_dynsym import load
    sage: from sage_dynsym.description import example_path
    sage: from sage_dynsym.interact.forms import derive
    sage: d = derive(load(example_path('spherical_pendulum.yaml')), 'Lagrange')
    sage: d.form, d.function, d.note
    ('Lagrange', ('L', 1/2*dpsi^2*l^2*m*sin(theta)^2 + 1/2*dtheta^2*l^2*m - g*l*m*cos(theta)), None)
    sage: d.equations[1]
    ('0', -dpsi^2*l^2*m*cos(theta)*sin(theta) + ddtheta*l^2*m - g*l*m*sin(theta))
"""

MECHANICAL_FORMS = ['Lagrange', 'Routh', 'Hamilton']
CIRCUIT_FORMS = ['Brayton-Moser', 'Lagrange (loop)', 'Lagrange (node)', 'Hamilton (loop)']


def _is_circuit(model):
    return getattr(model, 'kind', None) == 'circuit'


def _is_characteristic_function(model):
    # a Lagrangian (or Routh function) given directly, not a model
    return getattr(model, 'kind', None) is None and hasattr(model, 'lagrange_equations')


def available_forms(model):
    r"""
    The names of the forms :func:`derive` accepts for ``model``.

    EXAMPLES::

        sage: from sage_dynsym import load
        sage: from sage_dynsym.description import example_path
        sage: from sage_dynsym.interact.forms import available_forms
        sage: available_forms(load(example_path('rlc_ladder.yaml')))
        ['Brayton-Moser', 'Lagrange (loop)', 'Lagrange (node)', 'Hamilton (loop)']
    """
    return list(CIRCUIT_FORMS if _is_circuit(model) else MECHANICAL_FORMS)


def _lagrangian(model, form):
    if _is_circuit(model):
        return model.lagrangian(method="node" if "node" in form else "loop")
    return model.lagrangian()


def _zero_equations(coordinates, equations):
    return [("0", e) for e in equations]


def _state_equations(circuit):
    rows = list(zip(circuit.state_equation_labels(latex=True), circuit.state_equations()))
    if circuit.has_mixed_potential():
        return Derivation('Brayton-Moser', ('P', circuit.mixed_potential()), rows, None)
    return Derivation('Brayton-Moser', ('B', circuit.lhs_matrix()), rows,
                      "no mixed potential (capacitor loops or inductor cut-sets, or no "
                      "Brayton-Moser split): the state equations B x' = F by nodal analysis")


def derive(model, form, cyclic=()):
    r"""
    One form of the equations of ``model``.

    INPUT:

    - ``model`` -- a mechanical system, a circuit or a
      :class:`~sage_dynsym.dynamics.lagrangian.Lagrangian`
    - ``form`` -- one of :func:`available_forms` (a Lagrangian accepts the
      mechanical forms)
    - ``cyclic`` -- (default: ``()``) the cyclic coordinates for the Routh
      form (names or symbols); empty means all cyclic coordinates

    OUTPUT: a ``Derivation`` named tuple ``(form, function, equations,
    note)``: ``function`` is ``(name, expression)``, ``equations`` a list of
    pairs ``(lhs_latex, rhs)`` meaning `lhs = rhs`, ``note`` a remark (the
    Dirac constraints of a singular Lagrangian) or ``None``

    EXAMPLES::

        sage: from sage_dynsym import load
        sage: from sage_dynsym.description import example_path
        sage: from sage_dynsym.interact.forms import derive
        sage: H = derive(load(example_path('spherical_pendulum.yaml')), 'Hamilton')
        sage: H.equations[0]
        ('\\dot{\\psi}', p_psi/(l^2*m*sin(theta)^2))
        sage: C = load(example_path('nonlinear_circuit.yaml'))
        sage: derive(C, 'Brayton-Moser').equations[0]
        ('L_{1} \\frac{d i_{1}}{dt}', -u3 + u4 + u6)

    A circuit without a mixed potential (a loop of two capacitors and a
    source) gets its state equations from nodal analysis, each labelled by
    its row of the matrix `B` of `B\\dot x = F`::

        sage: from sage_dynsym.circuits import Circuit
        sage: D = derive(Circuit([[1, 2, 'C1'], [2, 3, 'C2'], [3, 1, 'E1'], [1, 3, 'L1'],
        ....:                     [2, 3, 'R1']]), 'Brayton-Moser')
        sage: D.equations[1], D.note
        (('\\left(C_{1} + C_{2}\\right) \\frac{d u_{2}}{dt}', -u2/R1),
         "no mixed potential (capacitor loops or inductor cut-sets, or no Brayton-Moser split): the state equations B x' = F by nodal analysis")

    TESTS::

        sage: derive(C, 'Lagrange (loop)')
        Traceback (most recent call last):
        ...
        CircuitError: branches[1]: the loop-current method needs a linear circuit, but f1 is nonlinear; use mixed_potential()
        sage: derive(C, 'Routh')
        Traceback (most recent call last):
        ...
        ModelError: unknown form 'Routh': expected one of Brayton-Moser, Lagrange (loop), Lagrange (node), Hamilton (loop)
    """
    forms = MECHANICAL_FORMS if _is_characteristic_function(model) else available_forms(model)
    if form not in forms:
        raise ModelError(f"unknown form {form!r}: expected one of {', '.join(forms)}")
    if form == 'Brayton-Moser':
        return _state_equations(model)
    L = model if _is_characteristic_function(model) else _lagrangian(model, form)
    if form.startswith('Lagrange'):
        return Derivation(form, ('L', L.expr()),
                          _zero_equations(L.coordinates(), L.lagrange_equations()), None)
    if form == 'Routh':
        names = {str(c) for c in cyclic}
        chosen = [q for q in L.coordinates() if str(q) in names] if names \
            else L.cyclic_coordinates()
        if not chosen:
            raise ModelError("the Routh form needs at least one cyclic coordinate; "
                             f"this Lagrangian has none among {L.coordinates()}")
        R = L.routh(chosen)
        return Derivation(form, ('R', R.expr()),
                          _zero_equations(R.coordinates(), R.equations()), None)
    H = L.hamiltonian()
    if H.is_singular():
        D = H.constraints()
        rows = [("0", c) for c in D.constraints()]
        return Derivation(form, ('H', H.expr()), rows,
                          f"singular Lagrangian, Dirac's scheme: {D}")
    rows = []
    for q, p, (dq, dp) in zip(H.coordinates(), H.momenta(), H.equations()):
        rows.append((f"\\dot{{{latex(q)}}}", dq))
        rows.append((f"\\dot{{{latex(p)}}}", dp))
    return Derivation(form, ('H', H.expr()), rows, None)


def derivation_latex(derivation):
    r"""
    The characteristic function and the equations of ``derivation`` as one
    LaTeX ``aligned`` block.

    EXAMPLES::

        sage: from sage_dynsym import Lagrangian
        sage: from sage_dynsym.interact.forms import derive, derivation_latex
        sage: from sage_dynsym.symbols import velocity
        sage: x, m, k = var('x m k'); dx = velocity(x)
        sage: print(derivation_latex(derive(Lagrangian(m*dx^2/2 - k*x^2/2, [x]), 'Lagrange')))
        \begin{aligned}
        L &= \frac{1}{2} \, {\dot{x}}^{2} m - \frac{1}{2} \, k x^{2}\\
        0 &= {\ddot{x}} m + k x
        \end{aligned}
    """
    name, expr = derivation.function
    rows = [f"{name} &= {latex(expr)}"]
    rows += [f"{lhs} &= {latex(rhs)}" for lhs, rhs in derivation.equations]
    return "\\begin{aligned}\n" + "\\\\\n".join(rows) + "\n\\end{aligned}"
