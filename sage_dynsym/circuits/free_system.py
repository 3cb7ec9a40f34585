r"""
The free linear system of a circuit

With its sources switched off, a circuit's state equations `B\dot x = F(x)`
(:meth:`~sage_dynsym.circuits.circuit.Circuit.state_equations`, `B` its
:meth:`~sage_dynsym.circuits.circuit.Circuit.lhs_matrix`) linearized around
the zero state: what a stability map of the circuit maps. A circuit without
state equations (a loop of voltage sources, a cut-set of current sources,
an implicit nonlinear resistor) or without state variables (every inductor
current and capacitor voltage fixed by the sources) has no such system: the
error says why.

EXAMPLES::

    sage: from sage_dynsym.circuits import Circuit
    sage: from sage_dynsym.circuits.free_system import free_linear_system
    sage: C = Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 3, 'L1'], [3, 0, 'C1']])
    sage: S = free_linear_system(C)
    sage: S.variables(), S.lhs_matrix()
    (
            [L1  0]
    [i1, u2], [ 0 C1]
    )
    sage: S.characteristic_polynomial(var('lam'))
    C1*L1*lam^2 + C1*R1*lam + 1
"""
from sage.symbolic.ring import SR

from ..dynamics.model import linearization_point
from ..errors import CircuitError

__all__ = ['free_linear_system']


def free_linear_system(circuit, at=None):
    r"""
    The linear system of ``circuit`` with its sources off, around the zero
    state (``at``, a dict, gives other values to state variables).

    INPUT:

    - ``circuit`` -- a :class:`~sage_dynsym.circuits.circuit.Circuit`
    - ``at`` -- (default: ``None``) a dict of state values

    OUTPUT: a :class:`~sage_dynsym.analysis.linear.LinearSystem`

    EXAMPLES: the ladder of the examples, its free state equations (the
    voltage source off)::

        sage: from sage_dynsym import load
        sage: from sage_dynsym.description import example_path
        sage: from sage_dynsym.circuits.free_system import free_linear_system
        sage: S = free_linear_system(load(example_path('rlc_ladder.yaml')))
        sage: S.variables()
        [i1, i2, i3, u4, u5, u6]
        sage: S.order(), S.lhs_matrix().is_diagonal()
        (1, True)

    TESTS::

        sage: from sage_dynsym.circuits import Circuit
        sage: free_linear_system(Circuit([[0, 1, 'E1'], [0, 1, 'E2'], [1, 2, 'L1'],
        ....:                             [2, 0, 'R1']]))
        Traceback (most recent call last):
        ...
        CircuitError: branches[1]: the voltage sources E2, E1 form a loop: ...
        sage: free_linear_system(Circuit([[0, 1, 'I1'], [1, 0, 'L1'], [1, 2, 'I2'],
        ....:                             [2, 0, 'R1']]))
        Traceback (most recent call last):
        ...
        CircuitError: the circuit has no state variables: the sources fix every inductor current and capacitor voltage
    """
    from ..analysis import linearize
    sources = circuit.source_values_off()
    states = [x for x, _ in circuit.state_variables()]
    if not states:
        raise CircuitError("the circuit has no state variables: the sources fix every "
                           "inductor current and capacitor voltage")
    rhs = [SR(f).subs(sources) for f in circuit.state_equations()]
    return linearize(rhs, linearization_point(at, states), states, lhs_matrix=circuit.lhs_matrix().subs(sources))
