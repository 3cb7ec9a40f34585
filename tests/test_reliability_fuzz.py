"""
Property-based fuzzing (hypothesis) of the expression parser and of the
description-file grammar: whatever the text or the structure, the only
exceptions are the package's own (``DynSymError``), and nothing hangs (each
example runs under an alarm).

The strategies follow the grammar -- declared and reserved names, numbers
of every size, operators, functions (allowed or not), nesting, junk
characters; mechanical and circuit descriptions with every key, values of
every YAML type, bodies, rotations, inertia tensors, branches in both
forms -- so that most examples get deep into the reader. Runs are
deterministic (``derandomize``); ``make test-slow`` runs them.
"""
import copy
import math
import os
import tempfile

import pytest
import yaml
from hypothesis import given, strategies as st
from conftest import fuzz_settings
from fuzzing import within

from sage.all import SR
from sage_dynsym import load, DynSymError
from sage_dynsym.io.expressions import ExpressionParser
from sage_dynsym.description import mechanical_system_from_dict
from sage_dynsym.circuits.description import circuit_from_dict

# hundreds of random descriptions: `make test-slow` (CI) runs it
pytestmark = pytest.mark.slow

SECONDS = 20        # per example: a hang fails the test


bounded = within(SECONDS)


# -- expressions -----------------------------------------------------------

DECLARED = ["m", "l", "g", "k", "x", "theta"]
OTHER_NAMES = ["q", "dx", "ddx", "p_x", "lambda", "None", "t", "sin", "pi", "e", "I", "E",
               "λ", "_x", "lambda1", "u1", "i1", "matrix", "x²", "__import__", "oo", "NaN"]
FUNCTIONS = ["sin", "cos", "tan", "exp", "log", "sqrt", "abs", "atan2", "arctan2", "sinh",
             "asin", "gamma", "f", "eval", "factorial", "__import__", "diff", "m"]
JUNK = list("!=<>[]{};:'\"`\\#@$%&|~?\t\n\x00−²٣.,") + ["**", "//", "==", "!="]

digits = st.text("0123456789", min_size=1, max_size=1200)
numbers = st.one_of(
    st.integers(0, 10**6).map(str), digits,
    st.builds(lambda a, b, c: f"{a}.{b}e{c}", st.integers(0, 999), st.integers(0, 999),
              st.integers(-3000, 3000)),
    st.sampled_from([".5", "1.", "1e", "1e+", "0", "00", "1.5.3", "2E5", "1e-999999999"]))
atoms = st.one_of(st.sampled_from(DECLARED), st.sampled_from(DECLARED), numbers,
                  st.sampled_from(OTHER_NAMES), st.sampled_from(["pi", "e", "I"]))


def _combine(inner):
    return st.one_of(
        st.tuples(inner, st.sampled_from(["+", "-", "*", "/", "^", "**", " ", ""]), inner)
        .map("".join),
        inner.map(lambda s: f"({s})"),
        st.tuples(st.sampled_from(["-", "+", "--", "-+-"]), inner).map("".join),
        st.tuples(st.sampled_from(FUNCTIONS), st.lists(inner, max_size=3))
        .map(lambda t: f"{t[0]}({', '.join(t[1])})"),
        st.tuples(inner, st.sampled_from(JUNK), inner).map("".join),
        st.tuples(st.integers(1, 300), inner).map(lambda t: "(" * t[0] + t[1] + ")" * t[0]),
        st.lists(inner, min_size=2, max_size=6).map("^".join),
    )


expressions = st.one_of(st.recursive(atoms, _combine, max_leaves=25),
                        st.text(max_size=60),
                        st.text(alphabet="mxl0123456789+-*/^() .e", max_size=80))


@fuzz_settings(3000)
@given(expressions)
def test_expression_parser(text):
    parser = ExpressionParser(DECLARED)
    result = bounded(parser.parse, text, "fuzz")
    if not isinstance(result, DynSymError):
        assert result.parent() is SR
        assert not result.is_infinity()


@fuzz_settings(300)
@given(st.one_of(st.integers(-10**2000, 10**2000), st.floats(), st.fractions(),
                 st.booleans(), st.none(), st.lists(st.integers(), max_size=2)))
def test_expression_parser_on_values(value):
    result = bounded(ExpressionParser(DECLARED).parse, value, "fuzz")
    if not isinstance(result, DynSymError):
        assert isinstance(value, (int, float)) and math.isfinite(value) or \
            not isinstance(value, float)


# -- description files ----------------------------------------------------

good_expressions = st.recursive(
    st.sampled_from(["m", "l", "g", "k", "x", "theta", "1", "2", "3", "1/3", "0.5", "pi"]),
    lambda inner: st.one_of(
        st.tuples(inner, st.sampled_from(["+", "-", "*", "/", "^"]), inner).map("".join),
        inner.map(lambda s: f"sin({s})"), inner.map(lambda s: f"({s})^2")),
    max_leaves=5)
small_expressions = st.one_of(
    good_expressions, good_expressions, good_expressions,
    st.sampled_from(["-1", "-m", "I*m", "log(0)", "dx", "x + dx", "ddx", "k*dx^2", "9^9^9",
                     "q", "1e400"]),
    st.integers(-3, 3), st.floats(allow_nan=True, allow_infinity=True),
    st.recursive(atoms, _combine, max_leaves=6))
yaml_values = st.one_of(small_expressions, st.none(), st.booleans(),
                        st.lists(small_expressions, max_size=4),
                        st.dictionaries(st.sampled_from(["a", "mass", "kind"]), small_expressions,
                                        max_size=2))
vectors = st.one_of(*[st.lists(good_expressions, min_size=3, max_size=3)] * 3,
                    st.lists(small_expressions, min_size=3, max_size=3), yaml_values)
numeric_entries = st.integers(-3, 6)
good_inertias = st.one_of(
    st.builds(lambda a, b, c, d: [[a, d, 0], [d, b, 0], [0, 0, c]],
              numeric_entries, numeric_entries, numeric_entries, st.integers(-2, 2)),
    st.builds(lambda a, b, c: [[a, 0, 0], [0, b, 0], [0, 0, c]],
              good_expressions, good_expressions, good_expressions))
inertias = st.one_of(
    st.lists(st.lists(numeric_entries, min_size=3, max_size=3), min_size=3, max_size=3),
    st.builds(lambda a, b, c, d: [[a, d, 0], [d, b, 0], [0, 0, c]],
              numeric_entries, numeric_entries, numeric_entries, st.integers(-2, 2)),
    st.builds(lambda a, b, c: [[a, 0, 0], [0, b, 0], [0, 0, c]],
              good_expressions, good_expressions, good_expressions),
    st.lists(st.lists(small_expressions, min_size=3, max_size=3), min_size=3, max_size=3),
    yaml_values)
names = st.one_of(st.sampled_from(["x", "theta", "psi", "m", "l", "g", "k"]),
                  st.sampled_from(OTHER_NAMES), st.text(max_size=6), st.integers())
hostile_values = st.one_of(yaml_values, names, inertias,
                           st.lists(st.one_of(names, small_expressions), max_size=3))


def _paths(data, prefix=()):
    # every (container, key) of a nested structure of dicts and lists
    items = data.items() if isinstance(data, dict) else enumerate(data)
    for key, value in list(items):
        yield data, key
        if isinstance(value, (dict, list)):
            yield from _paths(value, prefix + (key,))


def _mutate(data, rnd, replacements):
    """Replace, delete or add one or two entries anywhere in ``data`` (or none)."""
    if rnd.random() < 0.3:
        return data
    data = copy.deepcopy(data)
    for value in replacements[:rnd.randint(1, len(replacements))]:
        places = list(_paths(data))
        if not places:
            break
        container, key = rnd.choice(places)
        action = rnd.random()
        if action < 0.7:
            container[key] = value
        elif action < 0.85:
            del container[key]
        elif isinstance(container, dict):
            container[rnd.choice(["extra", "colour", "Mass", "", 1])] = value
        else:
            container.append(value)
    return data


def mutated(strategy):
    return st.builds(_mutate, strategy, st.randoms(use_true_random=False),
                     st.lists(hostile_values, min_size=1, max_size=2))


pairs = st.tuples(st.sampled_from([1, 2, 3]), good_expressions).map(list)
good_bodies = st.builds(
    lambda k, parent, rotations, joint, centre, mass, inertia: {
        "name": "abc"[k], "parent": min(parent, k), "rotations": rotations, "joint": joint,
        "mass_center": centre, "mass": mass, "inertia": inertia},
    st.integers(0, 2), st.integers(0, 2), st.lists(pairs, max_size=3),
    st.lists(good_expressions, min_size=3, max_size=3),
    st.lists(good_expressions, min_size=3, max_size=3), good_expressions, good_inertias)
force_functions = st.one_of(
    st.fixed_dictionaries({"uniform_gravity": st.lists(good_expressions, min_size=3,
                                                       max_size=3)}),
    st.fixed_dictionaries({"expression": good_expressions}),
    st.fixed_dictionaries({"newtonian": st.fixed_dictionaries(
        {"nu": small_expressions, "r": small_expressions, "direction": vectors})}))
good_mechanical = st.fixed_dictionaries(
    {"kind": st.just("mechanical"),
     "coordinates": st.sampled_from([["x", "theta"], ["theta", "x"]]),
     "parameters": st.just(["m", "l", "g", "k"]),
     "bodies": st.lists(good_bodies, min_size=1, max_size=3, unique_by=lambda b: b["name"])},
    optional={"name": st.text(max_size=10), "force_function": force_functions,
              "dissipation": st.one_of(good_expressions, st.just("k*dx^2/2")),
              "forces": st.lists(good_expressions, min_size=2, max_size=2)})
mechanical = mutated(good_mechanical)

nodes = st.one_of(st.integers(0, 4), st.integers(0, 4), st.integers(-2, 4),
                  st.sampled_from(["a", "b", "a b", ""]), st.floats(allow_nan=False),
                  st.booleans(), st.none())
element_names = st.one_of(st.builds(lambda p, k: f"{p}{k}", st.sampled_from("RLCEIfRLC"),
                                    st.integers(1, 3)),
                          st.builds(lambda p, k: f"{p}{k}", st.sampled_from("XMqiu"),
                                    st.integers(0, 3)),
                          st.sampled_from(["I", "E", "R", "phi1", "lambda1", "t"]),
                          st.text(max_size=4), st.integers())
good_element = st.builds(lambda p, k: f"{p}{k}", st.sampled_from("RLCEIfRLC"), st.integers(1, 9))
short_branches = st.one_of(
    st.tuples(st.integers(0, 4), st.integers(0, 4), good_element).map(list),
    st.tuples(st.integers(0, 4), st.integers(0, 4), good_element).map(list),
    st.lists(st.one_of(nodes, element_names), min_size=2, max_size=4))
circuit_values = st.one_of(small_expressions, st.sampled_from(["u^2 + C0", "i*L0", "0", "L0",
                                                               "C0*(1 + u^2)", "-1", "2.5"]))
long_branches = st.fixed_dictionaries(
    {"kind": st.sampled_from(["resistor", "inductor", "capacitor", "voltage_source",
                              "current_source", "nonlinear_resistor", "mutual", "diode"]),
     "from": st.integers(0, 4), "to": st.integers(0, 4)},
    optional={"name": good_element, "value": circuit_values,
              "between": st.lists(good_element, min_size=2, max_size=2)})
good_circuits = st.fixed_dictionaries(
    {"kind": st.just("circuit"),
     "branches": st.lists(st.one_of(short_branches, long_branches), min_size=1, max_size=7)},
    optional={"name": st.text(max_size=10), "parameters": st.just(["C0", "L0", "M"])})
ladders = st.builds(
    lambda n, extra: {"kind": "circuit", "branches": [[0, 1, "E1"]] + [
        b for k in range(1, n + 1) for b in ([2 * k - 1, 2 * k, f"R{k}"],
                                             [2 * k, 2 * k + 1, f"L{k}"],
                                             [2 * k + 1, 0, f"C{k}"])] + extra},
    st.integers(1, 4), st.lists(st.one_of(short_branches, long_branches), max_size=2))
circuits = mutated(st.one_of(good_circuits, ladders))


def _load_text(text):
    with tempfile.NamedTemporaryFile("w", suffix=".yaml", delete=False,
                                     encoding="utf-8") as stream:
        stream.write(text)
    try:
        return bounded(load, stream.name)
    finally:
        os.unlink(stream.name)


def _dump(data):
    return yaml.safe_dump(data, allow_unicode=True)


def _from_dict(function, data):
    # a refusal names the file it was given
    result = bounded(function, data, "fuzz.yaml")
    if isinstance(result, DynSymError):
        assert str(result).startswith("fuzz.yaml")


@fuzz_settings(700)
@given(mechanical)
def test_mechanical_descriptions(data):
    _from_dict(mechanical_system_from_dict, data)


@fuzz_settings(500)
@given(circuits)
def test_circuit_descriptions(data):
    _from_dict(circuit_from_dict, data)


@fuzz_settings(300)
@given(st.one_of(mechanical, circuits))
def test_description_files(data):
    result = _load_text(_dump(data))
    if isinstance(result, DynSymError):
        assert str(result).startswith(tempfile.gettempdir())


yaml_fragments = st.sampled_from([
    "kind: mechanical\n", "kind: circuit\n", "coordinates: [x]\n", "bodies:\n", "  - name: b\n",
    "    mass: m\n", "branches:\n", "  - [1, 2, R1]\n", "&a [1, 2]\n", "*a\n", "<<: *a\n",
    "!!python/object/apply:os.system ['ls']\n", "? [a]\n", ": 1\n", "---\n", "...\n", "[[[[",
    "{a: {b: {c:", "\t", "\x00", "\ufeff", "- ", "mass: 1e400\n", "mass: .nan\n", "'", '"'])


@fuzz_settings(500)
@given(st.one_of(st.lists(yaml_fragments, max_size=12).map("".join), st.text(max_size=200)))
def test_raw_yaml_text(text):
    result = _load_text(text)
    assert isinstance(result, DynSymError) or result is not None
