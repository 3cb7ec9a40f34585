"""
Circuit description files and bad input.

Expected values come from the specification (Example 2, equations (11)),
typed here independently of the code; error cases are the ones listed in
issue 3.
"""
import pathlib

import pytest
import yaml

from sage.all import SR, function, identity_matrix, jacobian, var
from sage_dynsym.circuits import Circuit, circuit_from_dict, circuit_to_dict
from sage_dynsym.errors import CircuitError, DescriptionError

EXAMPLES = pathlib.Path(__file__).resolve().parent.parent / "examples"


def read(name):
    path = EXAMPLES / name
    return circuit_from_dict(yaml.safe_load(path.read_text()), source=str(path))


def load_text(text, source="test.yaml"):
    return circuit_from_dict(yaml.safe_load(text), source=source)


def test_example_2_state_equations_as_printed_in_the_method():
    C = read("nonlinear_circuit.yaml")
    i1, i2, u3, u4, u5, u6 = var('i1 i2 u3 u4 u5 u6')
    I0, I01, I02 = var('I0 I01 I02')
    f1, f2, f3, f4 = (function(f"f{k}") for k in range(1, 5))
    expected = {                                   # (11) of doc/method.rst
        ('L1', i1): u4 + u6 - u3,
        ('L2', i2): u5 - u4,
        ('C3', u3): I01 + i1 + f3(u3),
        ('C2', u4): i2 - i1 + f2(u4) - I0,
        ('C4', u5): I02 - i2 + f4(u5),
        ('C1', u6): -i1 - I0 + f1(u6),
    }
    got = {(name, x): rhs for (x, name), rhs in zip(C.state_variables(), C.state_equations())}
    assert list(got) == list(expected)
    for key in expected:
        assert bool((got[key] - expected[key]).expand() == 0), key
    BM = C.brayton_moser()
    assert BM.current_potential() == 0
    assert bool((BM.coupling_term() - (i1 * (u4 + u6 - u3) + i2 * (u5 - u4))).expand() == 0)
    s = SR.var('s')
    G = (I01 * u3 + I02 * u5 - I0 * (u4 + u6)
         + sum(f(s).integral(s, 0, u, hold=True)
               for f, u in ((f3, u3), (f2, u4), (f4, u5), (f1, u6))))
    assert bool((BM.voltage_potential() - G).expand() == 0)
    assert [x[2] for x in BM.omega_i()] == ['L1', 'L2']
    assert BM.loops() == [[(1, 2, 'L1'), (2, 3, 'C1'), (3, 5, 'C2'), (5, 1, 'C3')],
                          [(3, 4, 'L2'), (4, 5, 'C4'), (5, 3, 'C2')]]


@pytest.mark.parametrize("name", ["nonlinear_circuit.yaml", "rlc_ladder.yaml",
                                  "coupled_inductors.yaml"])
def test_round_trip(name):
    C = read(name)
    text = yaml.safe_dump(circuit_to_dict(C), sort_keys=False)
    D = load_text(text)
    assert D == C and D.name() == C.name()
    assert [bool(a == b) for a, b in zip(C.state_equations(), D.state_equations())] \
        == [True] * len(C.state_equations())


def test_long_form_round_trip_with_values():
    text = """
kind: circuit
name: long form
parameters: [g, s1, C0]
branches:
  - {from: 1, to: 2, kind: inductor, value: L1}
  - {from: 2, to: 1, kind: capacitor, name: C1, value: "C0*(1 + u^2)"}
  - {from: 2, to: 1, kind: nonlinear_resistor, name: f1, value: "g*u*(u - 3*s1)^2"}
"""
    C = load_text(text)
    D = load_text(yaml.safe_dump(circuit_to_dict(C)))
    assert C == D
    g, s1, u2, i1 = var('g s1 u2 i1')
    # C du/dt = -dP/du with f1 cubic: the characteristic itself comes back
    assert bool((C.state_equations()[1] - (-i1 + g * u2 * (u2 - 3 * s1) ** 2)).expand() == 0)


@pytest.mark.parametrize("branches, message", [
    ("[[1, 2, R1], [2, 3, X1]]", "test.yaml: branches[1]: unknown element prefix 'X'"),
    ("[[1, 2, R1], [2, 2, C1]]", "test.yaml: branches[1]: self-loop"),
    ("[[1, 2, R1], [3, 4, C1]]", "test.yaml: the circuit graph is disconnected"),
    ("[[1, 2, R1], [2, 1, R1]]", "test.yaml: branches[1]: duplicate element name"),
    ("[[1, 2, R1], {from: 2, to: 1, kind: capacitor, value: 'R1*x'}]",
     "test.yaml: branches[1].value: undeclared symbol 'x'"),
    ("[[1, 2, R1], {from: 2, to: 1, kind: diode, value: D1}]",
     "test.yaml: branches[1].kind: unknown kind 'diode'"),
    ("[[1, 2, L1], [2, 1, C1], {kind: mutual, between: [L1], value: M}]",
     "test.yaml: branches[2].between: 'between' must list two inductor names"),
    ("[[1, 2, L1], [2, 1, M1]]", "test.yaml: branches[1]: unknown element prefix 'M'"),
    ("[[1, 2, R1], [2, 1]]", "test.yaml: branches[1]: a short-form branch is"),
    ("[[1, 2.5, R1], [2, 1, C1]]", "test.yaml: branches[0]: a node must be an integer"),
    ("[[1, 2, R1], {from: 2, to: 1, kind: resistor, value: 'R1*u', name: R2}]",
     "test.yaml: branches[1].value: the value of a resistor cannot depend on u"),
])
def test_bad_description_names_file_and_entry(branches, message):
    with pytest.raises(CircuitError) as err:
        load_text(f"kind: circuit\nbranches: {branches}\n")
    assert str(err.value).startswith(message), str(err.value)


@pytest.mark.parametrize("text, message", [
    ("kind: circuit\n", "test.yaml: branches: missing key 'branches'"),
    ("kind: circuit\nbranches: []\n", "test.yaml: branches: expected a non-empty list"),
    ("kind: circuit\nbranches: [[1, 2, R1]]\nnodes: 3\n", "test.yaml: nodes: unknown key"),
    ("kind: mechanical\nbranches: [[1, 2, R1]]\n", "test.yaml: kind: expected 'circuit'"),
    ("kind: circuit\nparameters: [1x]\nbranches: [[1, 2, R1]]\n", "test.yaml: parameters:"),
])
def test_bad_top_level(text, message):
    with pytest.raises(DescriptionError) as err:
        load_text(text)
    assert str(err.value).startswith(message), str(err.value)


# --- circuits that cannot be handled (issue 3, item 4) ------------------------

def test_not_complete_capacitor_voltage_source_loop():
    C = Circuit([[1, 2, 'C1'], [2, 3, 'C2'], [3, 1, 'E1'], [1, 3, 'L1'], [2, 3, 'R1']])
    with pytest.raises(CircuitError, match="not complete: the capacitors and voltage "
                                           "sources .* form a loop"):
        C.brayton_moser()


def test_not_complete_inductor_current_source_cut_set():
    C = Circuit([[1, 2, 'L1'], [2, 3, 'I1'], [3, 1, 'C1'], [3, 1, 'R1']])
    with pytest.raises(CircuitError, match="inductors and current sources L1, I1 form a cut-set"):
        C.mixed_potential()


def test_source_position_makes_split_impossible():
    # a current source in series with a voltage-controlled nonlinear resistor
    C = Circuit([[1, 2, 'I1'], [2, 3, 'f1'], [3, 1, 'C1'], [3, 1, 'L1']])
    with pytest.raises(CircuitError, match=r"branches\[1\]: no Brayton-Moser split: the "
                                           "nonlinear resistor f1"):
        C.state_equations()


def test_resistor_network_without_split():
    # R1, R2 divide the capacitor voltage: neither voltage- nor current-determined
    C = Circuit([[1, 2, 'L1'], [2, 3, 'R1'], [3, 1, 'R2'], [2, 1, 'C1']])
    with pytest.raises(CircuitError, match="no Brayton-Moser split: the resistors"):
        C.brayton_moser()
    # ... but the linear methods still apply
    assert len(C.lagrangian(method="loop").coordinates()) == 2
    assert len(C.lagrangian(method="node").coordinates()) == 2
    # and the state equations come from nodal analysis: a parallel RLC with
    # R = R1 + R2, characteristic polynomial s^2 + s/(R C) + 1/(L C)
    B, x = C.lhs_matrix(), [v for v, _ in C.state_variables()]
    A = jacobian(C.state_equations(), x)
    s, R1, R2, L1, C1 = var('s R1 R2 L1 C1')
    p = (s * identity_matrix(2) - B.inverse() * A).det()
    assert (p - (s**2 + s / ((R1 + R2) * C1) + 1 / (L1 * C1))).simplify_full() == 0


def test_linear_methods_reject_source_loops_and_cut_sets():
    with pytest.raises(CircuitError, match=r"voltage sources E\d, E\d form a loop"):
        Circuit([[1, 2, 'E1'], [1, 2, 'E2'], [2, 1, 'R1']]).lagrangian(method="node")
    with pytest.raises(CircuitError, match=r"voltage sources E\d, E\d form a loop"):
        Circuit([[1, 2, 'E1'], [1, 2, 'E2'], [2, 1, 'R1']]).lagrangian(method="loop")
    with pytest.raises(CircuitError, match="current sources form a cut-set"):
        Circuit([[1, 2, 'I1'], [2, 3, 'R1'], [3, 2, 'C1']]).lagrangian(method="loop")
    with pytest.raises(CircuitError, match="ground node 7 is not a node"):
        Circuit([[1, 2, 'R1'], [2, 1, 'C1']]).lagrangian(method="node", ground=7)


def test_circuit_is_immutable_and_hashable():
    C = Circuit([[1, 2, 'R1'], [2, 1, 'C1']])
    assert isinstance(C.branches(), tuple)
    assert hash(C) == hash(Circuit([[1, 2, 'R1'], [2, 1, 'C1']]))
    with pytest.raises(TypeError):
        C.graph().add_edge(1, 3)
