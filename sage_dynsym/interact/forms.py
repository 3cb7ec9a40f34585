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
from sage.misc.latex import latex

from ..dynamics.derivations import Derivation, lagrangian_forms  # Derivation: its earlier home
from ..dynamics.model import Model
from ..errors import ModelError

__all__ = ['equation_forms', 'available_forms', 'derive', 'derivation_latex', 'Derivation']


def equation_forms(model):
    r"""
    The forms of the equations of ``model``: a dict from names to builders
    of :class:`~sage_dynsym.dynamics.derivations.Derivation` -- the model's
    own :meth:`~sage_dynsym.dynamics.model.Model.equation_forms`, or for a
    Lagrangian (or Routh function) given directly its Lagrange, Routh and
    Hamilton forms.

    EXAMPLES::

        sage: from sage_dynsym import Lagrangian
        sage: from sage_dynsym.interact.forms import equation_forms
        sage: from sage_dynsym.symbols import velocity
        sage: x = var('x')
        sage: list(equation_forms(Lagrangian(velocity(x)^2/2 - x^2/2, [x])))
        ['Lagrange', 'Routh', 'Hamilton']
    """
    if isinstance(model, Model):
        return model.equation_forms()
    return lagrangian_forms(lambda: model)


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
    return list(equation_forms(model))


def derive(model, form, cyclic=()):
    r"""
    One form of the equations of ``model``.

    INPUT:

    - ``model`` -- a model (mechanical system, circuit, Lie--Poisson
      system, ...) or a :class:`~sage_dynsym.dynamics.lagrangian.Lagrangian`
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
    forms = equation_forms(model)
    if form not in forms:
        raise ModelError(f"unknown form {form!r}: expected one of {', '.join(forms)}")
    return forms[form](cyclic=cyclic)


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
