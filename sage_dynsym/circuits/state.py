r"""
The state equations of a circuit: which analysis gives them, and their labels

A complete circuit gets its state equations `B\dot x = F(x)` from the
Brayton--Moser mixed potential
(:class:`~sage_dynsym.circuits.mixed_potential.MixedPotential`), any other
solvable one from modified nodal analysis
(:class:`~sage_dynsym.circuits.nodal.NodalAnalysis`); both answer
``state_variables()``, ``state_equations()`` and ``lhs_matrix()``.
:class:`StateEquations` gives a
:class:`~sage_dynsym.circuits.circuit.Circuit` its methods on them.

EXAMPLES::

    sage: from sage_dynsym.circuits import Circuit
    sage: from sage_dynsym.circuits.state import state_form
    sage: state_form(Circuit([[1, 2, 'L1'], [2, 1, 'C1']]))
    Brayton-Moser mixed potential of Circuit with 2 branches on 2 nodes
    sage: state_form(Circuit([[1, 2, 'L1'], [2, 1, 'C1'], [2, 1, 'C2']]))
    Modified nodal analysis of Circuit with 3 branches on 2 nodes
"""
from sage.symbolic.ring import SR

from ..errors import CircuitError
from ..numerics.energy import quadratic_energy
from .nodal import NotExplicitError

__all__ = ['state_form', 'equation_labels', 'StateEquations']


def state_form(circuit):
    r"""
    The analysis that gives the state equations of ``circuit``: its
    mixed potential when it is complete, else its modified nodal analysis.

    Raises :class:`~sage_dynsym.errors.CircuitError` when neither exists;
    when nodal analysis finds the equations implicit
    (:class:`~sage_dynsym.circuits.nodal.NotExplicitError`), the message
    gives both reasons.

    EXAMPLES: see the module documentation, and

    TESTS::

        sage: from sage_dynsym.circuits import Circuit
        sage: from sage_dynsym.circuits.state import state_form
        sage: state_form(Circuit([[1, 2, 'f1'], [2, 3, 'R1'], [3, 1, 'C1']]))
        Traceback (most recent call last):
        ...
        CircuitError: branches[0]: no Brayton-Moser split: ...; no explicit state equations: ...
    """
    try:
        return circuit.brayton_moser()
    except CircuitError as split:
        try:
            return circuit.nodal_analysis()
        except NotExplicitError as err:
            raise CircuitError(f"{split.message}; {err.message}",
                               entry=split.entry or err.entry) from err


def equation_labels(lhs, states, latex=False):
    r"""
    The left-hand sides of `B\dot x = F(x)` row by row, ``lhs`` the matrix
    `B` and ``states`` the state variables `x`, as text (``latex=True``:
    LaTeX): ``C1 du2/dt``, ``(C1 + C2) du2/dt``, ``L1 di1/dt + M di2/dt``.

    EXAMPLES::

        sage: from sage_dynsym.circuits.state import equation_labels
        sage: L1, L2, M, i1, i2 = var('L1 L2 M i1 i2')
        sage: equation_labels(matrix([[L1, M], [M, L1 + L2]]), [i1, i2])
        ['L1 di1/dt + M di2/dt', 'M di1/dt + (L1 + L2) di2/dt']
        sage: equation_labels(matrix([[1]]), [i1], latex=True)
        ['\\frac{d i_{1}}{dt}']
    """
    from sage.misc.latex import latex as to_latex
    labels = []
    for i in range(lhs.nrows()):
        terms = []
        for b, v in zip(lhs.row(i), states):
            if b.is_zero():
                continue
            b = SR(b)
            simple = b.is_symbol() or b.is_numeric()
            if latex:
                factor = "" if b == 1 else (to_latex(b) if simple
                                            else f"\\left({to_latex(b)}\\right)")
                terms.append(f"{factor} \\frac{{d {to_latex(v)}}}{{dt}}".strip())
            else:
                factor = "" if b == 1 else (f"{b} " if simple else f"({b}) ")
                terms.append(f"{factor}d{v}/dt")
        labels.append(" + ".join(terms))
    return labels


class StateEquations:
    r"""
    The state equations `B\dot x = F(x)` of a circuit, from the analysis
    :func:`state_form` chooses, and what is derived from them: the
    equations record of the analysis, the labels of the rows, the stored
    energy. A mix-in of :class:`~sage_dynsym.circuits.circuit.Circuit`,
    which gives ``brayton_moser()`` and ``nodal_analysis()``.

    EXAMPLES::

        sage: from sage_dynsym.circuits import Circuit
        sage: from sage_dynsym.circuits.state import StateEquations
        sage: isinstance(Circuit([[1, 2, 'L1'], [2, 1, 'C1']]), StateEquations)
        True
    """

    def equations(self):
        r"""
        The equations of motion: the right-hand sides of the state
        equations (:meth:`state_equations`; raises
        :class:`~sage_dynsym.errors.CircuitError` for a circuit without
        unique or explicit solution).

        EXAMPLES::

            sage: from sage_dynsym import load
            sage: from sage_dynsym.description import example_path
            sage: load(example_path('nonlinear_circuit.yaml')).equations()[0]
            -u3 + u4 + u6
        """
        return self.state_equations()

    def has_mixed_potential(self):
        r"""
        Whether the circuit is complete (has the Brayton--Moser split);
        then :meth:`state_equations` come from the mixed potential, else
        from :meth:`nodal_analysis`.

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: Circuit([[1, 2, 'L1'], [2, 1, 'C1']]).has_mixed_potential()
            True
            sage: Circuit([[1, 2, 'L1'], [2, 1, 'C1'], [2, 1, 'C2']]).has_mixed_potential()
            False
        """
        try:
            self.brayton_moser()
        except CircuitError:
            return False
        return True

    def _state_form(self):
        # the mixed potential for a complete circuit, else nodal analysis
        return state_form(self)

    def state_variables(self):
        r"""
        The state variables, pairs ``(symbol, element name)``: inductor
        currents ``i1, ..., ir`` first, then capacitor voltages. A loop of
        capacitors (and voltage sources) or a cut-set of inductors (and
        current sources) leaves out one of its elements: the state is a
        maximal set of independent capacitor voltages and inductor currents
        (see :mod:`~sage_dynsym.circuits.nodal`).

        EXAMPLES: a loop of an inductor, a resistor and a capacitor::

            sage: from sage_dynsym.circuits import Circuit
            sage: C = Circuit([[1, 2, 'L1'], [2, 3, 'R1'], [3, 1, 'C1']], name='RLC')
            sage: C.state_variables()
            [(i1, 'L1'), (u2, 'C1')]

        Two capacitors in parallel have one voltage::

            sage: Circuit([[1, 2, 'L1'], [2, 1, 'C1'], [2, 1, 'C2']]).state_variables()
            [(i1, 'L1'), (u2, 'C1')]
        """
        return self._state_form().state_variables()

    def state_equations(self):
        r"""
        The right-hand sides `F` of `B\dot x = F(x)`, `B` the
        :meth:`lhs_matrix`, in the order of :meth:`state_variables`. For a
        complete circuit these are `\partial P/\partial i_k` and
        `-\partial P/\partial u_l` of the mixed potential (the equations
        `L_k\, di_k/dt = \partial P/\partial i_k`, `C_l\, du_l/dt =
        -\partial P/\partial u_l`); otherwise they come from
        :meth:`nodal_analysis`.

        Raises :class:`~sage_dynsym.errors.CircuitError` for a circuit
        without unique solution (a loop of voltage sources, a cut-set of
        current sources) and for nonlinear resistors whose relations cannot
        be solved explicitly, naming the elements.

        EXAMPLES: a loop of an inductor, a resistor and a capacitor::

            sage: from sage_dynsym.circuits import Circuit
            sage: C = Circuit([[1, 2, 'L1'], [2, 3, 'R1'], [3, 1, 'C1']], name='RLC')
            sage: C.state_equations()     # L1 di1/dt = u2 - R1 i1, C1 du2/dt = -i1
            [-R1*i1 + u2, -i1]

        Two capacitors in parallel::

            sage: C = Circuit([[1, 2, 'L1'], [2, 1, 'C1'], [2, 1, 'C2']])
            sage: C.state_equations(), C.lhs_matrix()
            (
                        [     L1       0]
            [u2, -i1], [      0 C1 + C2]
            )

        TESTS::

            sage: Circuit([[1, 2, 'E1'], [2, 1, 'E2'], [1, 2, 'C1']]).state_equations()
            Traceback (most recent call last):
            ...
            CircuitError: branches[1]: the voltage sources E2, E1 form a loop: ...
            sage: Circuit([[1, 2, 'f1'], [2, 3, 'R1'], [3, 1, 'C1']]).state_equations()
            Traceback (most recent call last):
            ...
            CircuitError: branches[0]: no Brayton-Moser split: ...; no explicit state equations: ...
        """
        return self._state_form().state_equations()

    def state_equation_labels(self, latex=False):
        r"""
        The left-hand sides of `B\dot x =` :meth:`state_equations`, row by
        row, as text (``latex=True``: LaTeX), e.g. ``C1 du2/dt`` or, for a
        state reduced by a capacitor loop, ``(C1 + C2) du2/dt``.

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: C = Circuit([[1, 2, 'C1'], [2, 3, 'C2'], [3, 1, 'E1'], [1, 3, 'L1'], [2, 3, 'R1']])
            sage: C.state_equation_labels()
            ['L1 di1/dt', '(C1 + C2) du2/dt']
            sage: C.state_equation_labels(latex=True)[1]
            '\\left(C_{1} + C_{2}\\right) \\frac{d u_{2}}{dt}'
        """
        return equation_labels(self.lhs_matrix(), [v for v, _ in self.state_variables()],
                               latex=latex)

    def lhs_matrix(self):
        r"""
        The matrix `B` of `B\dot x = F(x)`, `F` the :meth:`state_equations`,
        rows and columns in the order of :meth:`state_variables`: the
        inductance matrix (mutual inductances included) and the
        capacitances, block-diagonal; for a reduced state (capacitor loops,
        inductor cut-sets) the effective matrices of
        :meth:`~sage_dynsym.circuits.nodal.NodalAnalysis.lhs_matrix`.

        EXAMPLES: a transformer with galvanically isolated sides::

            sage: from sage_dynsym.circuits import Circuit
            sage: C = Circuit([[0, 1, 'E1'], [1, 0, 'L1'], [2, 3, 'L2'], [3, 2, 'R2'],
            ....:              {'kind': 'mutual', 'between': ['L1', 'L2'], 'value': 'M'}],
            ....:             parameters=['M'])
            sage: C.lhs_matrix(), C.state_equations()
            (
            [L1  M]
            [ M L2], [E1, -R2*i2]
            )
        """
        return self._state_form().lhs_matrix()

    def _conserved_energy(self):
        r"""
        The stored energy `\tfrac12 x^T B x` (`B` the :meth:`lhs_matrix`:
        inductances with their mutual terms, capacitances) when the state
        equations are lossless and linear (see
        :func:`~sage_dynsym.numerics.energy.quadratic_energy`), else
        ``None``; what ``simulate(...).energy_drift()`` measures.

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: Circuit([[1, 2, 'L1'], [2, 1, 'C1']])._conserved_energy()
            1/2*L1*i1^2 + 1/2*C1*u2^2
            sage: Circuit([[1, 2, 'L1'], [2, 3, 'R1'], [3, 1, 'C1']])._conserved_energy() is None
            True
        """
        return quadratic_energy(self.equations_record())

    def equations_record(self):
        r"""
        The state equations as the neutral record of the analysis:
        :class:`~sage_dynsym.analysis.motion.FirstOrderEquations` with the
        right-hand sides, the state variables and `B` (:meth:`lhs_matrix`).
        This is what :func:`~sage_dynsym.analysis.linear.linearize` uses.

        EXAMPLES::

            sage: from sage_dynsym.circuits import Circuit
            sage: from sage_dynsym.analysis.linear import linearize
            sage: C = Circuit([[1, 2, 'L1'], [2, 3, 'R1'], [3, 1, 'C1']])
            sage: F = C.equations_record(); F
            First-order equations B x' = F(x) in (i1, u2)
            sage: linearize(C, {var('i1'): 0, var('u2'): 0}).jacobian()
            [-R1/L1   1/L1]
            [ -1/C1      0]
        """
        from ..analysis.motion import FirstOrderEquations
        return FirstOrderEquations(self.state_equations(),
                                   [x for x, _ in self.state_variables()],
                                   lhs_matrix=self.lhs_matrix())
