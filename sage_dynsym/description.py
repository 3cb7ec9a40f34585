r"""
Description files: reading and writing models as YAML

A description file is human-editable YAML (contract §1), read with PyYAML's
*safe* loader: tags that would construct Python objects are refused, and
every expression is a string parsed by
:class:`~sage_dynsym.expressions.ExpressionParser` restricted to the
declared symbols (never ``eval``). Errors name the file, the entry and what
was expected.

A mechanical system::

    kind: mechanical
    name: spherical pendulum
    parameters: [m, l, g]
    coordinates: [psi, theta]
    force_function:
      uniform_gravity: [0, 0, -g]    # or newtonian: {nu: .., r: .., direction: [..]}
                                     # or expression: "U(q, t)"
    dissipation: "c*dtheta^2/2"      # optional Rayleigh function (velocities d<name>)
    forces: ["0", "M0*sin(w*t)"]     # optional, one per coordinate
    bodies:
      - name: pendulum
        parent: 0                    # 0, a body name or a 1-based body index
        rotations: [[3, psi], [1, theta]]
        joint: [0, 0, 0]
        velocity: [0, 0, 0]          # optional; default: time derivative of joint
        mass_center: [0, 0, l]
        mass: m
        inertia: [[m*l^2, 0, 0], [0, m*l^2, 0], [0, 0, 0]]

A circuit (``kind: circuit``) is handled by
:mod:`sage_dynsym.circuits.description`.

:func:`save` writes the description back with a ``results:`` section (the
Lagrangian and the equations, as text and LaTeX); :func:`load` with
``results=True`` parses that section again so that a later session can
reuse it.

EXAMPLES::

    sage: import os, tempfile
    sage: from sage_dynsym import load, save
    sage: from sage_dynsym.description import example_path
    sage: S = load(example_path('spherical_pendulum.yaml')); S
    Mechanical system 'spherical pendulum': 1 body, coordinates (psi, theta)
    sage: path = os.path.join(tempfile.mkdtemp(), 'pendulum.yaml')
    sage: save(S, path)
    sage: S2, results = load(path, results=True)
    sage: bool(results['lagrangian'] == S.lagrangian().expr())
    True
    sage: results['lagrange_equations'] == S.lagrangian().lagrange_equations()
    True
"""
import os
import sys

import yaml

from .errors import DescriptionError, ModelError
from .expressions import ExpressionParser, velocity, acceleration, momentum

MECHANICAL_KEYS = {'kind', 'name', 'parameters', 'coordinates', 'force_function',
                   'dissipation', 'forces', 'bodies', 'results'}
REQUIRED_MECHANICAL = ('coordinates', 'bodies')
BODY_KEYS = {'name', 'parent', 'rotations', 'joint', 'velocity', 'mass_center', 'mass',
             'inertia'}
FIELD_KEYS = {'uniform_gravity', 'newtonian', 'expression'}
NEWTONIAN_KEYS = {'nu', 'r', 'direction'}


def example_path(name):
    r"""
    The path of a bundled example description file.

    EXAMPLES::

        sage: from sage_dynsym.description import example_path
        sage: os.path.basename(example_path('spherical_pendulum.yaml'))
        'spherical_pendulum.yaml'
    """
    here = os.path.dirname(os.path.abspath(__file__))
    in_source = os.path.join(os.path.dirname(here), 'examples', name)
    if os.path.exists(in_source):
        return in_source
    # installed with pip: setup.py puts the examples under <prefix>/share
    return os.path.join(sys.prefix, 'share', 'sage_dynsym', 'examples', name)


def read_yaml(path):
    r"""
    Read a YAML file with the safe loader; any problem becomes a
    :class:`~sage_dynsym.errors.DescriptionError` naming the file.

    EXAMPLES::

        sage: from sage_dynsym.description import read_yaml
        sage: import tempfile
        sage: f = tempfile.NamedTemporaryFile('w', suffix='.yaml', delete=False)
        sage: _ = f.write("kind: !!python/object/apply:os.system ['echo hacked']\n"); f.close()
        sage: read_yaml(f.name)
        Traceback (most recent call last):
        ...
        DescriptionError: ...: the file contains a YAML tag that would construct a Python object (...); description files may only hold plain data
        sage: read_yaml('/nonexistent.yaml')
        Traceback (most recent call last):
        ...
        DescriptionError: /nonexistent.yaml: cannot read the file: ...
    """
    try:
        with open(path, encoding='utf-8') as stream:
            return yaml.safe_load(stream)
    except OSError as err:
        raise DescriptionError(f"cannot read the file: {err.strerror}", source=str(path)) from None
    except yaml.constructor.ConstructorError as err:
        raise DescriptionError("the file contains a YAML tag that would construct a Python "
                               f"object ({err.problem}); description files may only hold "
                               "plain data", source=str(path)) from None
    except yaml.YAMLError as err:
        raise DescriptionError(f"not valid YAML: {err}", source=str(path)) from None


def load(path, results=False):
    r"""
    Load a description file.

    INPUT:

    - ``path`` -- a file name
    - ``results`` -- (default: ``False``) if ``True``, also return the
      parsed ``results:`` section (a dictionary, empty if there is none)

    OUTPUT: a :class:`~sage_dynsym.mechanical_system.MechanicalSystem` or a
    :class:`~sage_dynsym.circuits.circuit.Circuit` (and the results)

    EXAMPLES::

        sage: from sage_dynsym import load
        sage: from sage_dynsym.description import example_path
        sage: load(example_path('nonlinear_circuit.yaml'))
        Circuit 'nonlinear circuit of Example 2' with 13 branches on 5 nodes

    TESTS::

        sage: import tempfile
        sage: def write(text):
        ....:     f = tempfile.NamedTemporaryFile('w', suffix='.yaml', delete=False)
        ....:     _ = f.write(text); f.close(); return f.name
        sage: load(write("kind: hydraulic\n"))
        Traceback (most recent call last):
        ...
        DescriptionError: ...: kind: expected 'mechanical' or 'circuit', got 'hydraulic'
        sage: load(write("- 1\n- 2\n"))
        Traceback (most recent call last):
        ...
        DescriptionError: ...: a description file holds a mapping of keys, got list
    """
    data = read_yaml(path)
    source = str(path)
    if not isinstance(data, dict):
        raise DescriptionError(f"a description file holds a mapping of keys, got "
                               f"{type(data).__name__}", source=source)
    kind = data.get('kind')
    if kind == 'mechanical':
        model = mechanical_system_from_dict(data, source)
    elif kind == 'circuit':
        from .circuits.description import circuit_from_dict
        model = circuit_from_dict(data, source)
    else:
        raise DescriptionError(f"expected 'mechanical' or 'circuit', got {kind!r}",
                               entry='kind', source=source)
    if not results:
        return model
    return model, _parse_results(model, data.get('results') or {}, source)


def _check_keys(data, allowed, entry, source, what):
    if not isinstance(data, dict):
        raise DescriptionError(f"expected a mapping ({what}), got {data!r}",
                               entry=entry, source=source)
    for key in data:
        if key not in allowed:
            raise DescriptionError(f"unknown key {key!r}; {what} has the keys "
                                   f"{', '.join(sorted(allowed))}", entry=entry, source=source)


def _names(data, key, source, required=True):
    value = data.get(key, [] if not required else None)
    if value is None:
        raise DescriptionError(f"missing key {key!r} (a list of symbol names)",
                               entry=key, source=source)
    if not isinstance(value, list) or not all(isinstance(v, str) and v.isidentifier()
                                              for v in value):
        raise DescriptionError(f"expected a list of symbol names, got {value!r}",
                               entry=key, source=source)
    return value


def mechanical_system_from_dict(data, source=None):
    r"""
    Build a :class:`~sage_dynsym.mechanical_system.MechanicalSystem` from a
    description mapping.

    INPUT:

    - ``data`` -- the mapping of a ``kind: mechanical`` description
    - ``source`` -- (optional) file name for error messages

    EXAMPLES::

        sage: from sage_dynsym.description import mechanical_system_from_dict
        sage: d = {'kind': 'mechanical', 'parameters': ['m', 'k'], 'coordinates': ['x'],
        ....:      'force_function': {'expression': '-k*x^2/2'},
        ....:      'bodies': [{'name': 'b', 'joint': ['x', 0, 0], 'mass': 'm'}]}
        sage: mechanical_system_from_dict(d).lagrangian()
        Lagrangian in coordinates (x) : 1/2*dx^2*m - 1/2*k*x^2

    TESTS::

        sage: d['bodies'][0]['mass'] = 'm*q'
        sage: mechanical_system_from_dict(d, 'f.yaml')
        Traceback (most recent call last):
        ...
        ExpressionError: f.yaml: bodies[0].mass: undeclared symbol 'q' in 'm*q'; declared symbols are: dx, k, m, t, x
        sage: d['bodies'][0]['mass'] = '-m'; d['bodies'][0]['colour'] = 'red'
        sage: mechanical_system_from_dict(d, 'f.yaml')
        Traceback (most recent call last):
        ...
        DescriptionError: f.yaml: bodies[0]: unknown key 'colour'; a body has the keys inertia, joint, mass, mass_center, name, parent, rotations, velocity
        sage: del d['bodies'][0]['colour']; d['bodies'][0]['mass'] = -1
        sage: mechanical_system_from_dict(d, 'f.yaml')
        Traceback (most recent call last):
        ...
        ModelError: f.yaml: bodies[0].mass: the mass must be non-negative, got -1
        sage: mechanical_system_from_dict({'kind': 'mechanical', 'bodies': []}, 'f.yaml')
        Traceback (most recent call last):
        ...
        DescriptionError: f.yaml: coordinates: missing key 'coordinates' (a list of symbol names)
        sage: d = {'kind': 'mechanical', 'coordinates': ['x'], 'bodies': [{'name': 'b',
        ....:      'rotations': [[3, 'x', 1]]}]}
        sage: mechanical_system_from_dict(d, 'f.yaml')
        Traceback (most recent call last):
        ...
        DescriptionError: f.yaml: bodies[0].rotations[0]: expected a pair [axis, angle], got [3, 'x', 1]
    """
    _check_keys(data, MECHANICAL_KEYS, None, source, "a mechanical description")
    for key in REQUIRED_MECHANICAL:
        if key not in data:
            raise DescriptionError(f"missing key {key!r} (a list of "
                                   f"{'symbol names' if key == 'coordinates' else 'bodies'})",
                                   entry=key, source=source)
    parameters = _names(data, 'parameters', source, required=False)
    coordinates = _names(data, 'coordinates', source)
    velocities = ['d' + q for q in coordinates]
    parser = ExpressionParser(parameters + coordinates + velocities)
    bodies_data = data['bodies']
    if not isinstance(bodies_data, list):
        raise DescriptionError(f"expected a list of bodies, got {bodies_data!r}",
                               entry='bodies', source=source)
    from .mechanical_system import MechanicalSystem
    try:
        bodies = [_body(b, i, parser, source) for i, b in enumerate(bodies_data)]
        n = len(coordinates)
        forces = data.get('forces')
        if forces is not None:
            if not isinstance(forces, list) or len(forces) != n:
                raise DescriptionError(f"expected a list of {n} expressions, one per "
                                       f"coordinate, got {forces!r}", entry='forces')
            forces = [parser.parse(f, entry=f'forces[{i}]') for i, f in enumerate(forces)]
        dissipation = parser.parse(data.get('dissipation', 0), entry='dissipation')
        field = _force_field(data.get('force_function'), parser)
        symbols = [parser.parse(q) for q in coordinates]
        return MechanicalSystem(bodies, symbols,
                                parameters=[parser.parse(p) for p in parameters],
                                force_function=field, dissipation=dissipation,
                                forces=forces, name=data.get('name'))
    except ModelError as err:
        raise err.with_context(source=source) from None


def _body(data, index, parser, source):
    from .rigid_body import RigidBody
    entry = f"bodies[{index}]"
    _check_keys(data, BODY_KEYS, entry, source, "a body")
    if 'name' not in data:
        raise DescriptionError("missing key 'name'", entry=entry, source=source)
    name = str(data['name'])

    def vector(key, default):
        value = data.get(key, default)
        if value is None:
            return None
        if not isinstance(value, list) or len(value) != 3:
            raise DescriptionError(f"expected a list of 3 expressions, got {value!r}",
                                   entry=f"{entry}.{key}")
        return [parser.parse(c, entry=f"{entry}.{key}[{i}]") for i, c in enumerate(value)]

    rotations = []
    for i, rotation in enumerate(data.get('rotations') or []):
        sub = f"{entry}.rotations[{i}]"
        if not isinstance(rotation, list) or len(rotation) != 2:
            raise DescriptionError(f"expected a pair [axis, angle], got {rotation!r}", entry=sub)
        rotations.append((rotation[0], parser.parse(rotation[1], entry=sub)))
    inertia = data.get('inertia')
    if inertia is not None:
        if not (isinstance(inertia, list) and len(inertia) == 3 and
                all(isinstance(row, list) and len(row) == 3 for row in inertia)):
            raise DescriptionError(f"expected a 3x3 matrix (3 rows of 3 expressions), got "
                                   f"{inertia!r}", entry=f"{entry}.inertia")
        inertia = [[parser.parse(c, entry=f"{entry}.inertia[{i}][{j}]")
                    for j, c in enumerate(row)] for i, row in enumerate(inertia)]
    parent = data.get('parent', 0)
    if not isinstance(parent, (int, str)) or isinstance(parent, bool):
        raise DescriptionError(f"expected 0, a body name or a body index, got {parent!r}",
                               entry=f"{entry}.parent")
    try:
        return RigidBody(name, parent=parent, rotations=rotations,
                         joint=vector('joint', [0, 0, 0]), velocity=vector('velocity', None),
                         mass_center=vector('mass_center', [0, 0, 0]),
                         mass=parser.parse(data.get('mass', 0), entry=f"{entry}.mass"),
                         inertia=inertia)
    except ModelError as err:
        # the body reports "<name>.<field>"; the file reader speaks of bodies[i]
        field = err.entry.split('.', 1)[1] if err.entry and '.' in err.entry else None
        raise type(err)(err.message, entry=f"{entry}.{field}" if field else entry) from None


def _force_field(data, parser):
    from .force_functions import UniformGravity, NewtonianField
    if data is None:
        return None
    _check_keys(data, FIELD_KEYS, 'force_function', None, "a force function")
    if len(data) != 1:
        raise DescriptionError("give exactly one of uniform_gravity, newtonian, expression",
                               entry='force_function')
    (key, value), = data.items()
    entry = f"force_function.{key}"
    if key == 'expression':
        return parser.parse(value, entry=entry)
    if key == 'uniform_gravity':
        if not isinstance(value, list) or len(value) != 3:
            raise DescriptionError(f"expected a list of 3 expressions, got {value!r}", entry=entry)
        return UniformGravity([parser.parse(c, entry=f"{entry}[{i}]") for i, c in enumerate(value)])
    _check_keys(value, NEWTONIAN_KEYS, entry, None, "a Newtonian field")
    missing = NEWTONIAN_KEYS - set(value)
    if missing:
        raise DescriptionError(f"missing key(s) {', '.join(sorted(missing))}", entry=entry)
    direction = value['direction']
    if not isinstance(direction, list) or len(direction) != 3:
        raise DescriptionError(f"expected a list of 3 expressions, got {direction!r}",
                               entry=f"{entry}.direction")
    return NewtonianField(parser.parse(value['nu'], entry=f"{entry}.nu"),
                          parser.parse(value['r'], entry=f"{entry}.r"),
                          [parser.parse(c, entry=f"{entry}.direction[{i}]")
                           for i, c in enumerate(direction)])


# ----------------------------------------------------------------------
# writing

def _text(expr):
    return str(expr)


def mechanical_system_to_dict(system):
    r"""
    The description mapping of ``system`` (inverse of
    :func:`mechanical_system_from_dict`).

    EXAMPLES::

        sage: from sage_dynsym import load
        sage: from sage_dynsym.description import example_path, mechanical_system_to_dict
        sage: d = mechanical_system_to_dict(load(example_path('spherical_pendulum.yaml')))
        sage: d['bodies'][0]['rotations'], d['force_function']
        ([[3, 'psi'], [1, 'theta']], {'uniform_gravity': ['0', '0', '-g']})
    """
    from .force_functions import UniformGravity, NewtonianField
    out = {'kind': 'mechanical'}
    if system.name():
        out['name'] = system.name()
    if system.parameters() is not None:
        out['parameters'] = [str(p) for p in system.parameters()]
    out['coordinates'] = [str(q) for q in system.coordinates()]
    field = system.force_field()
    if isinstance(field, UniformGravity):
        out['force_function'] = {'uniform_gravity': [_text(c) for c in field.acceleration()]}
    elif isinstance(field, NewtonianField):
        nu, r, e = field.parameters()
        out['force_function'] = {'newtonian': {'nu': _text(nu), 'r': _text(r),
                                               'direction': [_text(c) for c in e]}}
    elif field is not None:
        out['force_function'] = {'expression': _text(field)}
    if not system.dissipation().is_zero():
        out['dissipation'] = _text(system.dissipation())
    if any(not f.is_zero() for f in system.generalized_forces()):
        out['forces'] = [_text(f) for f in system.generalized_forces()]
    bodies = []
    for k, body in enumerate(system.bodies(), 1):
        entry = {'name': body.name(), 'parent': system.parent_index(k),
                 'rotations': [[axis, _text(angle)] for axis, angle in body.rotations()],
                 'joint': [_text(c) for c in body.joint()],
                 'mass_center': [_text(c) for c in body.mass_center()],
                 'mass': _text(body.mass()),
                 'inertia': [[_text(c) for c in row] for row in body.inertia().rows()]}
        if body.velocity() is not None:
            entry['velocity'] = [_text(c) for c in body.velocity()]
        bodies.append(entry)
    out['bodies'] = bodies
    return out


def model_results(model):
    r"""
    The ``results:`` section written by :func:`save`: characteristic
    function and equations as text, with their LaTeX forms.

    EXAMPLES::

        sage: from sage_dynsym import load
        sage: from sage_dynsym.description import example_path, model_results
        sage: r = model_results(load(example_path('spherical_pendulum.yaml')))
        sage: sorted(r)
        ['lagrange_equations', 'lagrange_equations_latex', 'lagrangian', 'lagrangian_latex']
    """
    from sage.misc.latex import latex
    from .mechanical_system import MechanicalSystem
    if isinstance(model, MechanicalSystem):
        L = model.lagrangian()
        equations = L.lagrange_equations()
        return {'lagrangian': _text(L.expr()), 'lagrangian_latex': str(latex(L.expr())),
                'lagrange_equations': [_text(e) for e in equations],
                'lagrange_equations_latex': [str(latex(e)) for e in equations]}
    return _circuit_results(model)


def _circuit_results(circuit):
    from sage.misc.latex import latex
    from .errors import CircuitError
    results = {}
    try:
        equations = circuit.state_equations()
    except CircuitError:
        pass
    else:
        results['state_variables'] = [str(v) for v, _ in circuit.state_variables()]
        results['state_equations'] = [_text(e) for e in equations]
        results['state_equations_latex'] = [str(latex(e)) for e in equations]
        results['mixed_potential_text'] = _text(circuit.mixed_potential())
        results['mixed_potential_latex'] = str(latex(circuit.mixed_potential()))
    try:
        L = circuit.lagrangian(method="loop")
    except CircuitError:
        pass
    else:
        results['lagrangian'] = _text(L.expr())
        results['lagrangian_latex'] = str(latex(L.expr()))
        results['lagrange_equations'] = [_text(e) for e in L.lagrange_equations()]
    return results


def save(model, path, results=True):
    r"""
    Write ``model`` to a description file, by default with a ``results:``
    section (see :func:`model_results`).

    EXAMPLES::

        sage: import tempfile
        sage: from sage_dynsym import load, save
        sage: from sage_dynsym.description import example_path
        sage: C = load(example_path('nonlinear_circuit.yaml'))
        sage: path = tempfile.mktemp(suffix='.yaml')
        sage: save(C, path)
        sage: load(path)
        Circuit 'nonlinear circuit of Example 2' with 13 branches on 5 nodes
    """
    from .mechanical_system import MechanicalSystem
    if isinstance(model, MechanicalSystem):
        data = mechanical_system_to_dict(model)
    else:
        from .circuits.description import circuit_to_dict
        data = circuit_to_dict(model)
    if results:
        data['results'] = model_results(model)
    with open(path, 'w', encoding='utf-8') as stream:
        yaml.safe_dump(data, stream, sort_keys=False, allow_unicode=True, width=100)


def _parse_results(model, results, source):
    from .mechanical_system import MechanicalSystem
    if not isinstance(results, dict):
        raise DescriptionError(f"expected a mapping, got {results!r}", entry='results',
                               source=source)
    functions = ()
    if isinstance(model, MechanicalSystem):
        q = [str(v) for v in model.coordinates()]
        symbols = [str(p) for p in model.parameters() or []]
        if model.parameters() is None:
            symbols += sorted({str(v) for v in model.lagrangian().expr().variables()})
    else:
        q = [str(v) for v in model.lagrangian().coordinates()] if 'lagrangian' in results else []
        symbols = list(model.parameters()) + results.get('state_variables', [])
        symbols += [b.name for b in model.branches() if b.kind != 'nonlinear_resistor']
        functions = model.elements('nonlinear_resistor')
    symbols += q + [str(velocity(v)) for v in q] + [str(acceleration(v)) for v in q]
    symbols += [str(momentum(v)) for v in q]
    parser = ExpressionParser(symbols, functions=functions)
    parsed = {}
    for key, value in results.items():
        if key.endswith('_latex') or key.endswith('_text') or key == 'state_variables':
            parsed[key] = value
        elif isinstance(value, list):
            parsed[key] = [parser.parse(v, entry=f"results.{key}[{i}]")
                           for i, v in enumerate(value)]
        else:
            parsed[key] = parser.parse(value, entry=f"results.{key}")
    return parsed
