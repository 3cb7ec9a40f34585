"""
A corpus of malformed and hostile description files.

Each case is ``(name, content, expect, fragment)``: ``content`` the bytes
(or text) of the file, ``expect`` either ``'error'`` (``load`` must raise
the package's own error, naming the file, containing ``fragment`` when
given) or ``'ok'`` (the file is valid and must load; the command line must
report it). The cases cover every class of the reliability issue -- files
that gave tracebacks, crashed, hung, ate memory or gave silently wrong
models -- and more.

``python tests/hostile/corpus.py DIR`` writes the corpus to ``DIR``.
"""
import os
import sys

PENDULUM = """\
kind: mechanical
name: {name}
parameters: [m, l, g]
coordinates: [psi, theta]
force_function:
  uniform_gravity: [0, 0, -g]
bodies:
  - name: pendulum
    parent: 0
    rotations: [[3, psi], [1, theta]]
    joint: [0, 0, 0]
    mass_center: [0, 0, l]
    mass: m
    inertia: [[m*l^2, 0, 0], [0, m*l^2, 0], [0, 0, 0]]
"""

SLIDER = """\
kind: mechanical
name: {name}
parameters: [{parameters}]
coordinates: [{coordinates}]
{extra}bodies:
  - name: slider
    joint: [x, 0, 0]
    mass: {mass}
{body_extra}"""

RLC = """\
kind: circuit
name: {name}
{extra}branches:
  - [0, 1, E1]
  - [1, 2, R1]
  - [2, 3, L1]
  - [3, 0, C1]
{more}"""


def slider(name, parameters="m, k", coordinates="x", mass="m", extra="", body_extra=""):
    return SLIDER.format(name=name, parameters=parameters, coordinates=coordinates, mass=mass,
                         extra=extra, body_extra=body_extra)


def pendulum(name, old=None, new=None):
    text = PENDULUM.format(name=name)
    if old is not None:
        assert old in text, old
        text = text.replace(old, new)
    return text


def rlc(name, more="", extra=""):
    return RLC.format(name=name, more=more, extra=extra)


def ladder(name, n, inductive_load=False):
    lines = ["kind: circuit", f"name: {name}", "branches:", "  - [0, 1, E1]"]
    node = 1
    for k in range(1, n + 1):
        lines += [f"  - [{node}, {node + 1}, R{k}]", f"  - [{node + 1}, {node + 2}, L{k}]",
                  f"  - [{node + 2}, 0, C{k}]"]
        node += 2
    if inductive_load:
        lines += [f"  - [{node}, {node + 1}, R{n + 1}]", f"  - [{node + 1}, 0, L{n + 1}]"]
    else:
        lines.append(f"  - [{node}, 0, R{n + 1}]")
    return "\n".join(lines) + "\n"


def many_coordinates(name, n, chain=True):
    names = [f"q{k}" for k in range(1, n + 1)]
    lines = ["kind: mechanical", f"name: {name}", "parameters: [m, g]",
             f"coordinates: [{', '.join(names)}]", "force_function:",
             "  uniform_gravity: [0, 0, -g]", "bodies:"]
    for k in range(1, n + 1):
        lines.append(f"  - {{name: b{k}, parent: {k - 1 if chain else 0}, "
                     f"joint: [q{k}, 0, 0], mass: m}}")
    return "\n".join(lines) + "\n"


def nested_sin(depth):
    return "sin(" * depth + "m" + ")" * depth


def billion_laughs():
    lines = ['a: &a ["lol", "lol", "lol", "lol", "lol", "lol", "lol", "lol", "lol"]']
    for prev, cur in zip("abcdefgh", "bcdefghi"):
        lines.append(f"{cur}: &{cur} [{', '.join(['*' + prev] * 9)}]")
    lines.append("kind: mechanical\ncoordinates: *i\nbodies: []")
    return "\n".join(lines) + "\n"


def cases():
    """The list of cases ``(name, content, expect, fragment)``."""
    C = []

    def add(name, content, expect="error", fragment=None):
        C.append((name, content, expect, fragment))

    # -- files that are valid: they must load and report ----------------
    add("ok_pendulum", pendulum("ok_pendulum"), "ok")
    add("ok_sage_names", slider("ok_sage_names", "m, psi, gamma, beta, E", mass="m*gamma"), "ok")
    add("ok_unicode_name", slider("ok_unicode_name", "m, θ", mass="m*θ"), "ok")
    add("ok_massless_carrier", pendulum("ok_massless_carrier", "    mass: m\n", "    mass: 0\n")
        .replace("[[m*l^2, 0, 0], [0, m*l^2, 0], [0, 0, 0]]", "[[0, 0, 0], [0, 0, 0], [0, 0, 0]]"),
        "ok")
    add("ok_symbolic_products_of_inertia", pendulum(
        "ok_symbolic_products_of_inertia", "parameters: [m, l, g]",
        "parameters: [m, l, g, A, B, C, D]").replace(
        "[[m*l^2, 0, 0], [0, m*l^2, 0], [0, 0, 0]]", "[[A, -D, 0], [-D, B, 0], [0, 0, C]]"), "ok")
    add("ok_thin_rod", pendulum("ok_thin_rod").replace(
        "[[m*l^2, 0, 0], [0, m*l^2, 0], [0, 0, 0]]", "[[1/3, 0, 0], [0, 1/3, 0], [0, 0, 0]]"),
        "ok")
    add("ok_utf8_bom", "\ufeff" + pendulum("ok_utf8_bom"), "ok")
    add("ok_long_sum", slider("ok_long_sum", mass="+".join(["m"] * 3000)), "ok")
    add("ok_velocity_in_dissipation", slider(
        "ok_velocity_in_dissipation", "m, c", extra="dissipation: c*dx^2/2\n"), "ok")
    add("ok_rlc", rlc("ok_rlc"), "ok")
    add("ok_ladder_40", ladder("ok_ladder_40", 40), "ok")
    add("ok_ladder_40_inductive_load", ladder("ok_ladder_40_inductive_load", 40, True), "ok")
    add("ok_ladder_300", ladder("ok_ladder_300", 300), "ok")
    add("ok_current_source_cut_set", "kind: circuit\nname: ok_current_source_cut_set\n"
        "branches:\n  - [0, 1, I1]\n  - [1, 2, R1]\n  - [2, 0, C1]\n", "ok")
    add("ok_huge_mass_expansion", slider("ok_huge_mass_expansion", "m, l, g, k",
                                         mass="(x + m + l + g + k)^1000"), "ok")
    add("ok_huge_capacitance_expansion", rlc("ok_huge_capacitance_expansion", extra="parameters: "
        "[C0, L0, M, K]\n", more="  - {from: 3, to: 0, kind: capacitor, name: C2, value: "
        "'(u + C0 + L0 + M + K)^1000'}\n  - {from: 3, to: 0, kind: nonlinear_resistor, name: f1,"
        " value: '(u + C0 + L0 + M + K)^1000'}\n"), "ok")
    add("ok_positive_values", rlc("ok_positive_values", more="  - {from: 3, to: 0, kind: "
        "resistor, name: R2, value: 2.5}\n"), "ok")

    # -- bytes, encodings, sizes -----------------------------------------
    add("binary", bytes(range(256)) * 40, "error", "not UTF-8")
    add("latin1", "kind: mechanical\nname: caf\xe9\n".encode("latin-1"), "error", "not UTF-8")
    add("utf16", pendulum("utf16").encode("utf-16"), "error", "not UTF-8")
    add("nul_byte", "kind: mechanical\x00\ncoordinates: []\n", "error", "not valid YAML")
    add("empty", "", "error", "a mapping")
    add("only_comments", "# nothing here\n", "error", "a mapping")
    add("too_large", "# " + "x" * (33 * 2**20) + "\n", "error", "MAX_FILE_BYTES")
    add("control_chars", "kind: mechanical\nname: \x07\x1b[31m\n", "error", "not valid YAML")

    # -- YAML structure -----------------------------------------------
    add("top_level_list", "- kind: mechanical\n", "error", "a mapping")
    add("top_level_scalar", "42\n", "error", "a mapping")
    add("two_documents", pendulum("a") + "---\n" + pendulum("b"), "error", "not valid YAML")
    add("nested_50000_flow_lists", "kind: [" + "[" * 50000 + "]" * 50000 + "]\n", "error",
        "MAX_YAML_DEPTH")
    add("nested_50000_flow_maps", "a: " + "{a: " * 50000 + "1" + "}" * 50000 + "\n", "error",
        "MAX_YAML_DEPTH")
    add("nested_2000_block", "".join(" " * i + "- \n" for i in range(2000)), "error",
        "MAX_YAML_DEPTH")
    add("unclosed_50000", "[" * 50000, "error", "MAX_YAML_DEPTH")
    add("billion_laughs", billion_laughs(), "error", "MAX_YAML_VALUES")
    add("recursive_alias", "kind: mechanical\ncoordinates: &a [*a]\nbodies: []\n", "error",
        "contains it")
    add("many_aliases", "a: &a x\nb: [" + ", ".join(["*a"] * 500) + "]\n", "error",
        "MAX_YAML_ALIASES")
    add("duplicate_top_key", pendulum("duplicate_top_key") + "kind: circuit\n", "error",
        "duplicate key 'kind'")
    add("duplicate_body_key", pendulum("duplicate_body_key", "    mass: m\n",
                                       "    mass: m\n    mass: 2*m\n"), "error",
        "duplicate key 'mass'")
    add("duplicate_coordinates_key", pendulum("duplicate_coordinates_key") +
        "coordinates: [psi]\n", "error", "duplicate key")
    add("merge_key", "base: &b {mass: m}\n" + pendulum("merge_key", "    mass: m\n",
                                                       "    <<: *b\n"), "error", "merge keys")
    add("python_object_apply", "kind: !!python/object/apply:os.system ['touch HACKED']\n",
        "error", "construct a Python object")
    add("python_name", "kind: !!python/name:os.system\n", "error", "construct a Python object")
    add("python_module", "kind: !!python/module:os\n", "error", "construct a Python object")
    add("binary_tag_mass", pendulum("binary_tag_mass", "    mass: m\n",
                                    "    mass: !!binary aGVsbG8=\n"), "error",
        "expected an expression")
    add("timestamp_mass", pendulum("timestamp_mass", "    mass: m\n", "    mass: 2001-12-14\n"),
        "error", "expected an expression")
    add("unhashable_key", "? [a, b]\n: 1\n", "error", "not valid YAML")
    add("tab_indentation", "kind:\tmechanical\n\t- x\n", "error", "not valid YAML")
    add("unclosed_bracket", "kind: mechanical\ncoordinates: [x, y\n", "error", "not valid YAML")
    add("yaml_int_million_digits", pendulum("yaml_int_million_digits", "    mass: m\n",
                                            "    mass: " + "9" * 10**6 + "\n"), "error",
        "MAX_INTEGER_DIGITS")
    add("yaml_hex_huge", pendulum("yaml_hex_huge", "    mass: m\n",
                                  "    mass: 0x" + "f" * 5000 + "\n"), "error",
        "MAX_INTEGER_DIGITS")
    add("mass_1e400", pendulum("mass_1e400", "    mass: m\n", "    mass: 1.0e+400\n"), "error",
        "finite number")
    add("mass_nan", pendulum("mass_nan", "    mass: m\n", "    mass: .nan\n"), "error",
        "finite number")
    add("mass_minus_inf", pendulum("mass_minus_inf", "    mass: m\n", "    mass: -.inf\n"),
        "error", "finite number")
    add("anchor_on_kind", "kind: mechanical\nname: &n anchor_on_kind\nparameters: [m]\n"
        "coordinates: [x]\nbodies:\n  - {name: *n, joint: [x, 0, 0], mass: m}\n", "ok")

    # -- keys and shapes -------------------------------------------------
    add("unknown_top_key", pendulum("unknown_top_key") + "author: me\n", "error",
        "unknown key 'author'")
    add("missing_kind", pendulum("missing_kind").replace("kind: mechanical\n", ""), "error",
        "kind")
    add("kind_hydraulic", pendulum("kind_hydraulic").replace("mechanical", "hydraulic"),
        "error", "expected one of 'mechanical', 'circuit', 'lie_poisson'")
    add("kind_list", pendulum("kind_list").replace("kind: mechanical", "kind: [mechanical]"),
        "error", "expected one of 'mechanical', 'circuit', 'lie_poisson'")
    add("coordinates_missing", pendulum("coordinates_missing", "coordinates: [psi, theta]\n", ""),
        "error", "missing key 'coordinates'")
    add("coordinates_string", pendulum("coordinates_string", "coordinates: [psi, theta]",
                                       "coordinates: psi"), "error", "list of symbol names")
    add("coordinates_ints", pendulum("coordinates_ints", "coordinates: [psi, theta]",
                                     "coordinates: [1, 2]"), "error", "symbol name")
    add("bodies_mapping", pendulum("bodies_mapping").split("bodies:")[0] +
        "bodies: {a: 1}\n", "error", "list of bodies")
    add("body_list", pendulum("body_list").split("bodies:")[0] + "bodies:\n  - [1, 2]\n",
        "error", "expected a mapping")
    add("body_without_name", pendulum("body_without_name", "  - name: pendulum\n    parent",
                                      "  - parent"), "error", "missing key 'name'")
    add("body_name_list", pendulum("body_name_list", "name: pendulum", "name: [a, b]"),
        "error", "expected a text")
    add("rotations_not_list", pendulum("rotations_not_list", "[[3, psi], [1, theta]]", "psi"),
        "error", "pairs")
    add("rotation_triple", pendulum("rotation_triple", "[[3, psi], [1, theta]]",
                                    "[[3, psi, 1]]"), "error", "pair")
    add("rotation_axis_4", pendulum("rotation_axis_4", "[1, theta]", "[4, theta]"), "error",
        "rotation axis")
    add("rotation_axis_text", pendulum("rotation_axis_text", "[1, theta]", "[x, theta]"),
        "error", "rotation axis")
    add("rotation_axis_bool", pendulum("rotation_axis_bool", "[1, theta]", "[true, theta]"),
        "error", "rotation axis")
    add("joint_two", pendulum("joint_two", "joint: [0, 0, 0]", "joint: [0, 0]"), "error",
        "3 expressions")
    add("inertia_2x2", pendulum("inertia_2x2", "[[m*l^2, 0, 0], [0, m*l^2, 0], [0, 0, 0]]",
                                "[[1, 0], [0, 1]]"), "error", "3x3")
    add("inertia_not_symmetric", pendulum(
        "inertia_not_symmetric", "[[m*l^2, 0, 0]", "[[m*l^2, 1, 0]"), "error", "symmetric")
    add("parent_unknown", pendulum("parent_unknown", "parent: 0", "parent: nowhere"), "error",
        "unknown parent")
    add("parent_cycle", pendulum("parent_cycle", "parent: 0", "parent: arm") +
        "  - {name: arm, parent: pendulum, mass: m}\n", "error", "cycle")
    add("parent_index_out_of_range", pendulum("parent_index_out_of_range", "parent: 0",
                                              "parent: 7"), "error", "out of range")
    add("parent_float", pendulum("parent_float", "parent: 0", "parent: 1.5"), "error",
        "body name or a body index")
    add("forces_wrong_length", pendulum("forces_wrong_length") + "forces: [0]\n", "error",
        "one per coordinate")
    add("force_function_two_keys", pendulum(
        "force_function_two_keys", "  uniform_gravity: [0, 0, -g]\n",
        "  uniform_gravity: [0, 0, -g]\n  expression: g\n"), "error", "exactly one")
    add("newtonian_missing_key", pendulum(
        "newtonian_missing_key", "  uniform_gravity: [0, 0, -g]\n",
        "  newtonian: {nu: g, r: l}\n"), "error", "missing key")
    add("long_model_name", pendulum("x" * 5000), "error", "MAX_TITLE_LENGTH")
    add("ok_coordinates_50", many_coordinates("ok_coordinates_50", 50, chain=False), "ok")
    add("coordinates_1001", many_coordinates("coordinates_1001", 1001), "error",
        "MAX_COORDINATES")
    add("coordinates_5000", many_coordinates("coordinates_5000", 5000), "error",
        "MAX_COORDINATES")
    add("bodies_1010", many_coordinates("bodies_1010", 10).replace(
        "bodies:", "bodies:\n" + "".join(f"  - {{name: extra{k}}}\n" for k in range(1000)))
        .replace("bodies:\n\n", "bodies:\n"), "error", "MAX_BODIES")
    add("parameters_10001", slider("parameters_10001",
                                   ", ".join(f"a{k}" for k in range(10001))),
        "error", "MAX_PARAMETERS")

    # -- names ----------------------------------------------------------
    add("coordinate_lambda", slider("coordinate_lambda", coordinates="lambda")
        .replace("[x, 0, 0]", "[lambda, 0, 0]"), "error", "Python keyword")
    add("coordinate_t", slider("coordinate_t", coordinates="t").replace("[x, 0, 0]",
                                                                        "[t, 0, 0]"),
        "error", "reserved: the time")
    add("coordinates_x_and_dx", slider("coordinates_x_and_dx", coordinates="x, dx"), "error",
        "the velocity of the coordinate 'x'")
    add("parameter_dx", slider("parameter_dx", "m, dx"), "error", "the velocity")
    add("parameter_ddx", slider("parameter_ddx", "m, ddx"), "error", "the acceleration")
    add("parameter_p_x", slider("parameter_p_x", "m, p_x"), "error", "the momentum")
    add("parameter_sin", slider("parameter_sin", "m, sin"), "error", "function sin")
    add("parameter_I", slider("parameter_I", "m, I"), "error", "imaginary unit")
    add("parameter_pi", slider("parameter_pi", "m, pi"), "error", "constant pi")
    add("parameter_e", slider("parameter_e", "m, e"), "error", "constant e")
    add("parameter_None", slider("parameter_None", "m, None"), "error", "Python keyword")
    add("parameter_print", slider("parameter_print", "m, print"), "error",
        "cannot make 'print'")
    add("parameter_lambda1", slider("parameter_lambda1", "m, lambda1"), "error", "multiplier")
    add("parameter_xi_x", slider("parameter_xi_x", "m, xi_x"), "error", "deviation")
    add("parameter_underscore", slider("parameter_underscore", "m, x_"), "error", "underscore")
    add("parameter_u1_mechanical", slider("parameter_u1_mechanical", "m, u1"), "error",
        "Dirac")
    add("parameter_also_coordinate", slider("parameter_also_coordinate", "m, x"), "error",
        "declared twice")
    add("parameter_starts_with_digit", slider("parameter_starts_with_digit", "m, '2x'"), "error",
        "symbol name")
    add("parameter_with_space", slider("parameter_with_space", "m, 'a b'"), "error",
        "symbol name")
    add("parameter_superscript", slider("parameter_superscript", "m, 'x²'"), "error",
        "symbol name")
    add("parameter_100_chars", slider("parameter_100_chars", "m, " + "a" * 100), "error",
        "MAX_NAME_LENGTH")

    # -- expressions ----------------------------------------------------
    add("parentheses_100000", slider("parentheses_100000", mass="(" * 100000 + "m" + ")" * 100000),
        "error", "MAX_EXPRESSION_LENGTH")
    add("parentheses_2000", slider("parentheses_2000", mass="(" * 2000 + "m" + ")" * 2000),
        "error", "MAX_NESTING_DEPTH")
    add("nested_sin_3000", slider("nested_sin_3000", mass=nested_sin(3000)), "error",
        "MAX_EXPRESSION_LENGTH")
    add("nested_sin_500", slider("nested_sin_500", mass=nested_sin(500)), "error",
        "MAX_NESTING_DEPTH")
    add("unary_minus_5000", slider("unary_minus_5000", mass="-" * 5000 + "m"), "error",
        "MAX_NESTING_DEPTH")
    add("polynomial_1e6_chars", slider("polynomial_1e6_chars",
                                       mass="+".join(["m*k^2"] * 170000)), "error",
        "MAX_EXPRESSION_LENGTH")
    add("integer_1e6_digits", slider("integer_1e6_digits", mass="'" + "7" * 10**6 + "*m'"),
        "error", "MAX_EXPRESSION_LENGTH")
    add("integer_5000_digits", slider("integer_5000_digits", mass="'" + "7" * 5000 + "*m'"),
        "error", "MAX_INTEGER_DIGITS")
    add("tiny_decimal", slider("tiny_decimal", mass="m*1e-999999999"), "error",
        "MAX_DECIMAL_EXPONENT")
    add("power_tower_999", slider("power_tower_999", mass="9^9^9"), "error", "MAX_EXPONENT")
    add("three_to_ten_to_ten", slider("three_to_ten_to_ten", mass="3^(10^10)*m"), "error",
        "MAX_EXPONENT")
    add("symbolic_tower", slider("symbolic_tower", mass="m^k^m^k^m"), "error",
        "MAX_POWER_TOWER")
    add("power_of_power", slider("power_of_power", mass="((2*m)^1000)^1000"), "error",
        "MAX_NUMBER_DIGITS")
    add("degree_20000", slider("degree_20000", mass="(m^100)^200"), "error", "MAX_DEGREE")
    add("huge_exponent_symbolic", slider("huge_exponent_symbolic", mass="m^(10^10*k)"), "error",
        "MAX_EXPONENT")
    add("factorial", slider("factorial", mass="m!"), "error", "not allowed")
    add("keyword_argument", slider("keyword_argument", mass="'sqrt(2, prec=10^9)*m'"), "error",
        "undeclared symbol 'prec'")
    add("import_os", slider("import_os", mass="\"__import__('os').system('touch HACKED')\""),
        "error", "unknown function '__import__'")
    add("python_lambda", slider("python_lambda", mass="'lambda: 1'"), "error",
        "undeclared symbol 'lambda'")
    add("semicolon", slider("semicolon", mass="'m; import os'"), "error", "not allowed")
    add("list_in_expression", slider("list_in_expression", mass="'[m]'"), "error",
        "not allowed")
    add("relation", slider("relation", mass="'m == 1'"), "error", "not allowed")
    add("unknown_function", slider("unknown_function", mass="gamma(m)"), "error",
        "unknown function 'gamma'")
    add("undeclared_symbol", slider("undeclared_symbol", mass="m*q"), "error",
        "undeclared symbol 'q'")
    add("log0_mass", slider("log0_mass", mass="log(0)"), "error", "not a finite value")
    add("tan_pi_half", slider("tan_pi_half", mass="m + tan(pi/2)"), "error",
        "not a finite value")
    add("atan2_00", slider("atan2_00", mass="atan2(0, 0)"), "error", "not a finite value")
    add("division_by_zero", slider("division_by_zero", mass="m/0"), "error", "division by zero")
    add("symbolic_division_by_zero", slider("symbolic_division_by_zero", mass="m/(x - x)"),
        "error", "division by zero")
    add("mass_list", slider("mass_list", mass="[m]"), "error", "expected an expression")
    add("mass_bool", slider("mass_bool", mass="true"), "error", "expected an expression")
    add("mass_mapping", slider("mass_mapping", mass="{a: 1}"), "error",
        "expected an expression")
    add("unicode_minus", slider("unicode_minus", mass="'m − 1'"), "error", "not allowed")
    add("wrong_arity", slider("wrong_arity", mass="sin(m, k)"), "error", "takes 1 argument")
    add("empty_expression", slider("empty_expression", mass="''"), "error",
        "malformed expression")

    # -- physical values --------------------------------------------------
    add("negative_mass", slider("negative_mass", mass="-2"), "error", "non-negative")
    add("negative_constant_mass", slider("negative_constant_mass", mass="1 - pi"), "error",
        "non-negative")
    add("complex_mass", slider("complex_mass", mass="I*m"), "error", "must be real")
    add("sqrt_minus_one_mass", slider("sqrt_minus_one_mass", mass="sqrt(-1)*m"), "error",
        "must be real")
    add("inertia_not_psd", pendulum("inertia_not_psd").replace(
        "[[m*l^2, 0, 0], [0, m*l^2, 0], [0, 0, 0]]", "[[1, 2, 0], [2, 1, 0], [0, 0, 1]]"),
        "error", "positive semi-definite")
    add("inertia_triangle", pendulum("inertia_triangle").replace(
        "[[m*l^2, 0, 0], [0, m*l^2, 0], [0, 0, 0]]", "[[1, 0, 0], [0, 1, 0], [0, 0, 3]]"),
        "error", "triangle inequality")
    add("inertia_negative_moment", pendulum("inertia_negative_moment").replace(
        "[[m*l^2, 0, 0], [0, m*l^2, 0], [0, 0, 0]]", "[[-1, 0, 0], [0, 1, 0], [0, 0, 1]]"),
        "error", "non-negative")
    add("inertia_complex", pendulum("inertia_complex").replace(
        "[[m*l^2, 0, 0]", "[[I*m*l^2, 0, 0]"), "error", "must be real")
    add("force_function_velocity", slider("force_function_velocity",
                                          extra="force_function:\n  expression: k*dx^2\n"),
        "error", "velocity-dependent forces belong")
    add("gravity_with_velocity", slider("gravity_with_velocity",
                                        extra="force_function:\n  uniform_gravity: [0, 0, -k*dx]\n"),
        "error", "force function U(q, t) cannot depend")
    add("joint_with_velocity", slider("joint_with_velocity").replace("[x, 0, 0]",
                                                                      "[x + dx, 0, 0]"),
        "error", "cannot appear in positions")
    add("mass_with_acceleration", slider("mass_with_acceleration", mass="m + ddx"), "error",
        "acceleration")
    add("dissipation_with_momentum", slider("dissipation_with_momentum",
                                            extra="dissipation: p_x^2\n"), "error", "momentum")

    # -- circuits -------------------------------------------------------
    long = "  - {{from: 3, to: 0, kind: {kind}, name: {name}, value: {value}}}\n"
    add("resistor_zero", rlc("resistor_zero", long.format(kind="resistor", name="R2", value=0)),
        "error", "short circuit")
    add("capacitor_zero", rlc("capacitor_zero", long.format(kind="capacitor", name="C2",
                                                            value="'0'")), "error",
        "open circuit")
    add("inductor_zero", rlc("inductor_zero", long.format(kind="inductor", name="L2",
                                                          value="0.0")), "error",
        "short circuit")
    add("resistor_negative", rlc("resistor_negative", long.format(kind="resistor", name="R2",
                                                                  value=-1)), "error",
        "must be positive")
    add("capacitor_complex", rlc("capacitor_complex", long.format(kind="capacitor", name="C2",
                                                                  value="I*C0"),
                                 extra="parameters: [C0]\n"), "error", "must be real")
    add("node_negative", rlc("node_negative", "  - [-1, 0, R2]\n"), "error", "node number")
    add("node_float", rlc("node_float", "  - [1.5, 0, R2]\n"), "error", "integer or a name")
    add("node_huge", rlc("node_huge", "  - [1000000000000, 0, R2]\n"), "error", "node number")
    add("node_bool", rlc("node_bool", "  - [true, 0, R2]\n"), "error", "integer or a name")
    add("node_name_space", rlc("node_name_space", "  - ['a b', 0, R2]\n"), "error",
        "identifier")
    add("self_loop", rlc("self_loop", "  - [2, 2, R2]\n"), "error", "self-loop")
    add("disconnected", rlc("disconnected", "  - [7, 8, R2]\n"), "error", "disconnected")
    add("circuit_parameter_q1", rlc("circuit_parameter_q1", extra="parameters: [q1]\n"), "error",
        "loop charge")
    add("circuit_parameter_i1", rlc("circuit_parameter_i1", extra="parameters: [i1]\n"), "error",
        "inductor current")
    add("circuit_parameter_u2", rlc("circuit_parameter_u2", extra="parameters: [u2]\n"), "error",
        "capacitor voltage")
    add("circuit_parameter_phi2", rlc("circuit_parameter_phi2", extra="parameters: [phi2]\n"),
        "error", "node potential")
    add("circuit_parameter_t", rlc("circuit_parameter_t", extra="parameters: [t]\n"), "error",
        "the time")
    add("element_named_q1", rlc("element_named_q1", "  - {from: 3, to: 0, kind: resistor, "
                                                   "name: q1}\n"), "error", "reserved")
    add("element_named_I", rlc("element_named_I", "  - [3, 0, I]\n"), "error",
        "imaginary unit")
    add("element_duplicate", rlc("element_duplicate", "  - [3, 0, R1]\n"), "error",
        "duplicate element name")
    add("parameter_equals_element", rlc("parameter_equals_element", extra="parameters: [R1]\n"),
        "error", "declared twice")
    add("unknown_prefix", rlc("unknown_prefix", "  - [3, 0, X1]\n"), "error",
        "unknown element prefix")
    add("branch_two_items", rlc("branch_two_items", "  - [3, 0]\n"), "error", "short-form")
    add("mutual_not_inductors", rlc("mutual_not_inductors", "  - {kind: mutual, between: "
                                                           "[R1, C1], value: M}\n",
                                    extra="parameters: [M]\n"), "error", "two inductors")
    add("value_undeclared", rlc("value_undeclared", long.format(kind="resistor", name="R2",
                                                                value="R0*x")), "error",
        "undeclared symbol")
    add("value_hostile", rlc("value_hostile", long.format(kind="resistor", name="R2",
                                                          value="9^9^9")), "error",
        "MAX_EXPONENT")
    add("branches_3000", ladder("branches_3000", 1000), "error", "MAX_BRANCHES")
    add("branches_empty", "kind: circuit\nbranches: []\n", "error", "non-empty list")
    add("circuit_name_mapping", rlc("circuit_name_mapping").replace(
        "name: circuit_name_mapping", "name: {a: 1}"), "error", "expected a text")
    add("circuit_unknown_key", rlc("circuit_unknown_key") + "colour: red\n", "error",
        "unknown key")
    return C


def write(folder):
    """Write every case to ``folder``; return ``{name: (path, expect, fragment)}``."""
    os.makedirs(folder, exist_ok=True)
    written = {}
    for name, content, expect, fragment in cases():
        path = os.path.join(folder, name + ".yaml")
        data = content.encode("utf-8") if isinstance(content, str) else content
        with open(path, "wb") as stream:
            stream.write(data)
        written[name] = (path, expect, fragment)
    return written


if __name__ == "__main__":
    for name, (path, expect, _) in write(sys.argv[1]).items():
        print(expect, path)
