r"""
The forms of a circuit's equations

A circuit has the Brayton--Moser state equations (from its mixed potential,
or from nodal analysis when it has none) and, when it is linear, the
Lagrange and Hamilton equations of its loop Lagrangian and the Lagrange
equations of its node Lagrangian
(:class:`~sage_dynsym.dynamics.derivations.Derivation`).

EXAMPLES::

    sage: from sage_dynsym import load
    sage: from sage_dynsym.description import example_path
    sage: from sage_dynsym.circuits.forms import circuit_forms
    sage: forms = circuit_forms(load(example_path('rlc_ladder.yaml')))
    sage: list(forms)
    ['Brayton-Moser', 'Lagrange (loop)', 'Lagrange (node)', 'Hamilton (loop)']
"""
from ..dynamics.derivations import Derivation, lagrangian_forms, lagrange_derivation

__all__ = ['circuit_forms', 'brayton_moser_derivation']


def circuit_forms(circuit):
    r"""
    The forms of the equations of ``circuit``: a dict from their names to
    functions building each :class:`~sage_dynsym.dynamics.derivations.Derivation`.
    A nonlinear circuit lists the Lagrangian forms too; building them says
    why they do not exist.

    EXAMPLES::

        sage: from sage_dynsym import load
        sage: from sage_dynsym.description import example_path
        sage: from sage_dynsym.circuits.forms import circuit_forms
        sage: C = load(example_path('nonlinear_circuit.yaml'))
        sage: circuit_forms(C)['Brayton-Moser']().equations[0]
        ('L_{1} \\frac{d i_{1}}{dt}', -u3 + u4 + u6)
        sage: circuit_forms(C)['Lagrange (loop)']()
        Traceback (most recent call last):
        ...
        CircuitError: branches[1]: the loop-current method needs a linear circuit, but f1 is nonlinear; use mixed_potential()
    """
    loop = lagrangian_forms(lambda: circuit.lagrangian(method="loop"),
                            names=('Lagrange (loop)', None, 'Hamilton (loop)'))
    return {'Brayton-Moser': lambda cyclic=(): brayton_moser_derivation(circuit),
            'Lagrange (loop)': loop['Lagrange (loop)'],
            'Lagrange (node)': lambda cyclic=(): lagrange_derivation(
                circuit.lagrangian(method="node"), 'Lagrange (node)'),
            'Hamilton (loop)': loop['Hamilton (loop)']}


def brayton_moser_derivation(circuit):
    r"""
    The state equations `B\dot x = F(x)` of ``circuit``, each labelled by
    its row of `B`, with the mixed potential `P` when the circuit has one.

    EXAMPLES: a circuit without a mixed potential (a loop of two capacitors
    and a source) gets its state equations from nodal analysis::

        sage: from sage_dynsym.circuits import Circuit
        sage: from sage_dynsym.circuits.forms import brayton_moser_derivation
        sage: D = brayton_moser_derivation(Circuit([[1, 2, 'C1'], [2, 3, 'C2'], [3, 1, 'E1'],
        ....:                                       [1, 3, 'L1'], [2, 3, 'R1']]))
        sage: D.equations[1], D.note
        (('\\left(C_{1} + C_{2}\\right) \\frac{d u_{2}}{dt}', -u2/R1),
         "no mixed potential (capacitor loops or inductor cut-sets, or no Brayton-Moser split): the state equations B x' = F by nodal analysis")
    """
    rows = list(zip(circuit.state_equation_labels(latex=True), circuit.state_equations()))
    if circuit.has_mixed_potential():
        return Derivation('Brayton-Moser', ('P', circuit.mixed_potential()), rows, None)
    return Derivation('Brayton-Moser', ('B', circuit.lhs_matrix()), rows,
                      "no mixed potential (capacitor loops or inductor cut-sets, or no "
                      "Brayton-Moser split): the state equations B x' = F by nodal analysis")
