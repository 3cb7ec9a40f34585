r"""
Description files: reading and writing models as YAML

A description file is human-editable YAML (format:
:doc:`/description_files`), read with PyYAML's
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
import stat
import sys
import tempfile

import yaml

from .errors import DescriptionError, DynSymError, ModelError, brief
from .expressions import (ExpressionParser, velocity, acceleration, momentum,
                          MAX_INTEGER_DIGITS)
from .names import check_name, check_mechanical_names

MECHANICAL_KEYS = {'kind', 'name', 'parameters', 'coordinates', 'force_function',
                   'dissipation', 'forces', 'bodies', 'results'}
REQUIRED_MECHANICAL = ('coordinates', 'bodies')
BODY_KEYS = {'name', 'parent', 'rotations', 'joint', 'velocity', 'mass_center', 'mass',
             'inertia'}
FIELD_KEYS = {'uniform_gravity', 'newtonian', 'expression'}
NEWTONIAN_KEYS = {'nu', 'r', 'direction'}

#: Largest description file read (bytes).
MAX_FILE_BYTES = 32 * 2**20
#: Deepest nesting of YAML lists and mappings.
MAX_YAML_DEPTH = 50
#: Most YAML aliases (``*name``) in one file.
MAX_YAML_ALIASES = 100
#: Most YAML values once aliases are expanded (the "billion laughs" bomb
#: expands 81 aliases into 10^9 values).
MAX_YAML_VALUES = 100_000
#: Most generalized coordinates of a mechanical description.
MAX_COORDINATES = 50
#: Most bodies of a mechanical description.
MAX_BODIES = 50
#: Most parameters of a description.
MAX_PARAMETERS = 500
#: Longest text of one expression in a ``results:`` section (the
#: description's own expressions have
#: :data:`~sage_dynsym.expressions.MAX_EXPRESSION_LENGTH`).
MAX_RESULT_LENGTH = 4 * 2**20
#: Longest name of a model or a body.
MAX_TITLE_LENGTH = 200


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


class _Refused(yaml.YAMLError):
    # a limit of the reader, with the place in the file
    def __init__(self, message, mark=None):
        where = f" (line {mark.line + 1}, column {mark.column + 1})" if mark else ""
        super().__init__(message + where)


class _Loader(yaml.SafeLoader):
    r"""
    PyYAML's safe loader with limits: nesting depth, number of aliases,
    size once aliases are expanded, digits of integers; duplicate keys and
    merge keys (``<<``) are errors. The composer of PyYAML recurses once per
    nesting level: the depth is checked before each level.
    """

    def __init__(self, stream):
        super().__init__(stream)
        self._depth = 0
        self._aliases = 0

    def compose_node(self, parent, index):
        if self.check_event(yaml.AliasEvent):
            self._aliases += 1
            if self._aliases > MAX_YAML_ALIASES:
                raise _Refused(f"more than {MAX_YAML_ALIASES} YAML aliases (MAX_YAML_ALIASES)",
                               self.peek_event().start_mark)
            return super().compose_node(parent, index)
        self._depth += 1
        if self._depth > MAX_YAML_DEPTH:
            raise _Refused(f"lists and mappings nested deeper than {MAX_YAML_DEPTH} levels "
                           "(MAX_YAML_DEPTH)", self.peek_event().start_mark)
        try:
            return super().compose_node(parent, index)
        finally:
            self._depth -= 1

    def construct_document(self, node):
        _check_expanded_size(node)
        return super().construct_document(node)

    def construct_mapping(self, node, deep=False):
        if isinstance(node, yaml.MappingNode):
            seen = {}
            for key_node, _ in node.value:
                if key_node.tag == 'tag:yaml.org,2002:merge':
                    raise _Refused("YAML merge keys (<<) are not supported in description "
                                   "files", key_node.start_mark)
                key = self.construct_object(key_node, deep=True)
                try:
                    first = seen.setdefault(key, key_node)
                except TypeError:
                    continue            # unhashable: the base class says so
                if first is not key_node:
                    raise _Refused(f"duplicate key {brief(key)} (first at line "
                                   f"{first.start_mark.line + 1})", key_node.start_mark)
        return super().construct_mapping(node, deep=deep)

    def construct_yaml_int(self, node):
        text = str(node.value).replace('_', '').lstrip('+-')
        if len(text) > MAX_INTEGER_DIGITS:
            raise _Refused(f"an integer with {len(text)} digits (at most {MAX_INTEGER_DIGITS}; "
                           "MAX_INTEGER_DIGITS)", node.start_mark)
        return super().construct_yaml_int(node)


_Loader.add_constructor('tag:yaml.org,2002:int', _Loader.construct_yaml_int)


def _check_expanded_size(root):
    # values counted with aliases expanded (memoized: shared nodes are
    # counted once per use, in linear time), and no recursive alias
    size, state, stack = {}, {}, [(root, False)]
    while stack:
        node, done = stack.pop()
        key = id(node)
        if done:
            children = _children(node)
            size[key] = 1 + sum(size[id(c)] for c in children)
            if size[key] > MAX_YAML_VALUES:
                raise _Refused(f"more than {MAX_YAML_VALUES} values once YAML aliases are "
                               "expanded (MAX_YAML_VALUES)", node.start_mark)
            state[key] = 2
            continue
        if state.get(key) == 2:
            continue
        if state.get(key) == 1:
            raise _Refused("a YAML alias refers to a list or mapping that contains it",
                           node.start_mark)
        state[key] = 1
        stack.append((node, True))
        for child in _children(node):
            if state.get(id(child)) == 1:
                raise _Refused("a YAML alias refers to a list or mapping that contains it",
                               child.start_mark)
            stack.append((child, False))


def _children(node):
    if isinstance(node, yaml.SequenceNode):
        return node.value
    if isinstance(node, yaml.MappingNode):
        return [x for pair in node.value for x in pair]
    return []


def read_yaml(path):
    r"""
    Read a description file: UTF-8 text of at most :data:`MAX_FILE_BYTES`
    bytes, parsed by PyYAML's safe loader with limits (nesting depth
    :data:`MAX_YAML_DEPTH`, :data:`MAX_YAML_ALIASES` aliases,
    :data:`MAX_YAML_VALUES` values once aliases are expanded, integers of
    at most :data:`~sage_dynsym.expressions.MAX_INTEGER_DIGITS` digits);
    duplicate keys are errors. Any problem becomes a
    :class:`~sage_dynsym.errors.DescriptionError` naming the file.

    EXAMPLES::

        sage: from sage_dynsym.description import read_yaml
        sage: import tempfile
        sage: def write(text, mode='w'):
        ....:     f = tempfile.NamedTemporaryFile(mode, suffix='.yaml', delete=False)
        ....:     _ = f.write(text); f.close(); return f.name
        sage: read_yaml(write("kind: !!python/object/apply:os.system ['echo hacked']\n"))
        Traceback (most recent call last):
        ...
        DescriptionError: ...: the file contains a YAML tag that would construct a Python object (...); description files may only hold plain data
        sage: read_yaml('/nonexistent.yaml')
        Traceback (most recent call last):
        ...
        DescriptionError: /nonexistent.yaml: cannot read the file: No such file or directory

    TESTS::

        sage: read_yaml(write("kind: circuit\nname: a\nkind: mechanical\n"))
        Traceback (most recent call last):
        ...
        DescriptionError: ...: not valid YAML: duplicate key 'kind' (first at line 1) (line 3, column 1)
        sage: read_yaml(write("[" * 100 + "]" * 100))
        Traceback (most recent call last):
        ...
        DescriptionError: ...: not valid YAML: lists and mappings nested deeper than 50 levels (MAX_YAML_DEPTH) (line 1, column 51)
        sage: read_yaml(write(b"kind: \xff\xfe\n", 'wb'))
        Traceback (most recent call last):
        ...
        DescriptionError: ...: the file is not UTF-8 text (invalid byte 0xff at byte 6)
        sage: bomb = "a: &a [x, x, x, x, x, x, x, x, x, x]\n" + "".join(
        ....:     f"{c}: &{c} [{', '.join(['*' + p] * 10)}]\n" for p, c in zip('abcdefg', 'bcdefgh'))
        sage: read_yaml(write(bomb))
        Traceback (most recent call last):
        ...
        DescriptionError: ...: not valid YAML: more than 100000 values once YAML aliases are expanded (MAX_YAML_VALUES) (line 5, column 4)
        sage: read_yaml(write("a: &a [*a]\n"))
        Traceback (most recent call last):
        ...
        DescriptionError: ...: not valid YAML: a YAML alias refers to a list or mapping that contains it (line 1, column 4)
        sage: read_yaml(write("mass: " + "9" * 5000 + "\n"))
        Traceback (most recent call last):
        ...
        DescriptionError: ...: not valid YAML: an integer with 5000 digits (at most 1000; MAX_INTEGER_DIGITS) (line 1, column 7)
        sage: read_yaml(tempfile.gettempdir())
        Traceback (most recent call last):
        ...
        DescriptionError: ...: cannot read the file: not a regular file
        sage: read_yaml(0)
        Traceback (most recent call last):
        ...
        DescriptionError: 0: expected a file name, got 0
    """
    source = str(path)
    if not isinstance(path, (str, bytes, os.PathLike)):
        raise DescriptionError(f"expected a file name, got {brief(path)}", source=brief(path))
    try:
        if not stat.S_ISREG(os.stat(path).st_mode):
            raise DescriptionError("cannot read the file: not a regular file", source=source)
        with open(path, 'rb') as stream:
            raw = stream.read(MAX_FILE_BYTES + 1)
    except OSError as err:
        raise DescriptionError(f"cannot read the file: {err.strerror or err}",
                               source=source) from None
    except (TypeError, ValueError) as err:
        raise DescriptionError(f"cannot read the file: {err}", source=source) from None
    if len(raw) > MAX_FILE_BYTES:
        raise DescriptionError(f"the file is larger than {MAX_FILE_BYTES} bytes "
                               "(MAX_FILE_BYTES)", source=source)
    try:
        text = raw.decode('utf-8')
    except UnicodeDecodeError as err:
        raise DescriptionError(f"the file is not UTF-8 text (invalid byte "
                               f"0x{raw[err.start]:02x} at byte {err.start})",
                               source=source) from None
    loader = None
    try:
        loader = _Loader(text)
        return loader.get_single_data()
    except yaml.constructor.ConstructorError as err:
        if err.problem and 'python/' in err.problem:
            raise DescriptionError("the file contains a YAML tag that would construct a Python "
                                   f"object ({err.problem}); description files may only hold "
                                   "plain data", source=source) from None
        raise DescriptionError(f"not valid YAML: {_yaml_problem(err)}", source=source) from None
    except yaml.YAMLError as err:
        raise DescriptionError(f"not valid YAML: {_yaml_problem(err)}", source=source) from None
    finally:
        if loader is not None:
            loader.dispose()


def _yaml_problem(err):
    # one line: what is wrong and where (PyYAML's text quotes the line)
    problem = getattr(err, 'problem', None)
    if problem is None:
        return " ".join(str(err).replace('"<unicode string>", ', '').split())
    context = getattr(err, 'context', None)
    mark = getattr(err, 'problem_mark', None)
    where = f" (line {mark.line + 1}, column {mark.column + 1})" if mark else ""
    return f"{context + ': ' if context else ''}{problem}{where}"


def load(path, results=False):
    r"""
    Load a description file.

    INPUT:

    - ``path`` -- a file name
    - ``results`` -- (default: ``False``) if ``True``, also return the
      parsed ``results:`` section (a dictionary, empty if there is none)

    OUTPUT: a :class:`~sage_dynsym.mechanical_system.MechanicalSystem` or a
    :class:`~sage_dynsym.circuits.circuit.Circuit` (and the results)

    Every problem is a :class:`~sage_dynsym.errors.DynSymError` naming the
    file and the entry (an unexpected failure inside Sage too, with its
    class).

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
    source = str(path)
    try:
        return _load(path, results, source)
    except DynSymError as err:
        raise err if err.source else err.with_context(source=source) from None
    except RecursionError:
        raise DescriptionError("the description is nested too deeply to be read",
                               source=source) from None
    except MemoryError:
        raise DescriptionError("not enough memory to read the description",
                               source=source) from None
    except Exception as err:    # a failure inside Sage: still the package's error
        raise DescriptionError(f"could not build the model ({type(err).__name__}: "
                               f"{brief(str(err))})", source=source) from None


def _load(path, results, source):
    data = read_yaml(path)
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
        raise DescriptionError(f"expected 'mechanical' or 'circuit', got {brief(kind)}",
                               entry='kind', source=source)
    if not results:
        return model
    return model, _parse_results(model, data.get('results') or {}, source)


def _check_keys(data, allowed, entry, source, what):
    if not isinstance(data, dict):
        raise DescriptionError(f"expected a mapping ({what}), got {brief(data)}",
                               entry=entry, source=source)
    for key in data:
        if key not in allowed:
            raise DescriptionError(f"unknown key {brief(key)}; {what} has the keys "
                                   f"{', '.join(sorted(allowed))}", entry=entry, source=source)


def _names(data, key, source, required=True, limit=None):
    if key not in data and required:
        raise DescriptionError(f"missing key {key!r} (a list of symbol names)",
                               entry=key, source=source)
    value = data.get(key, [])
    if not isinstance(value, list):
        raise DescriptionError(f"expected a list of symbol names, got {brief(value)}",
                               entry=key, source=source)
    if limit is not None and len(value) > limit:
        raise DescriptionError(f"{len(value)} names; a description file has at most {limit} "
                               f"(MAX_{key.upper()})", entry=key, source=source)
    return [check_name(v, f"{key}[{i}]", source=source) for i, v in enumerate(value)]


def title(data, entry, source=None):
    r"""
    The ``name`` of a model or body: a text (or a number) of at most
    :data:`MAX_TITLE_LENGTH` characters, or ``None`` if absent.

    EXAMPLES::

        sage: from sage_dynsym.description import title
        sage: title({'name': 'pendulum'}, 'name'), title({}, 'name')
        ('pendulum', None)
        sage: title({'name': [1, 2]}, 'bodies[0].name')
        Traceback (most recent call last):
        ...
        DescriptionError: bodies[0].name: expected a text, got [1, 2]
    """
    value = data.get('name')
    if value is None:
        return None
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        value = str(value)
    if not isinstance(value, str):
        raise DescriptionError(f"expected a text, got {brief(value)}", entry=entry,
                               source=source)
    if len(value) > MAX_TITLE_LENGTH:
        raise DescriptionError(f"a name of {len(value)} characters (at most "
                               f"{MAX_TITLE_LENGTH}; MAX_TITLE_LENGTH)", entry=entry,
                               source=source)
    return value


def _refusals(coordinates, velocities_allowed, where):
    # names that are declared in no description but mean something: a
    # velocity in a position, an acceleration or momentum anywhere
    refused = {}
    for q in coordinates:
        if not velocities_allowed:
            refused[str(velocity(q))] = (f"{velocity(q)} is the velocity of the coordinate "
                                         f"{q}, which {where}")
        refused[str(acceleration(q))] = (f"{acceleration(q)} is the acceleration of the "
                                         f"coordinate {q}; a description holds no accelerations")
        refused[str(momentum(q))] = (f"{momentum(q)} is the momentum of the coordinate {q}; "
                                     "a description holds no momenta")
    return refused


def mechanical_system_from_dict(data, source=None):
    r"""
    Build a :class:`~sage_dynsym.mechanical_system.MechanicalSystem` from a
    description mapping.

    INPUT:

    - ``data`` -- the mapping of a ``kind: mechanical`` description
    - ``source`` -- (optional) file name for error messages

    Names are checked against the reserved names (see
    :mod:`sage_dynsym.names`) and each other. Positions, angles, masses,
    inertia tensors and the force function depend on the coordinates, the
    parameters and ``t`` only; velocities ``d<q>`` may appear in the joint
    velocities, the dissipation function and the generalized forces.

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
        ExpressionError: f.yaml: bodies[0].mass: undeclared symbol 'q' in 'm*q'; declared symbols are: k, m, t, x
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
        sage: d['bodies'][0]['mass'] = 'm'; d['force_function'] = {'expression': '-k*dx^2'}
        sage: mechanical_system_from_dict(d, 'f.yaml')
        Traceback (most recent call last):
        ...
        ExpressionError: f.yaml: force_function.expression: dx is the velocity of the coordinate x, which the force function U(q, t) cannot depend on: velocity-dependent forces belong in 'dissipation' or 'forces' (in '-k*dx^2')
        sage: d['force_function'] = None; d['bodies'][0]['joint'] = ['x + dx', 0, 0]
        sage: mechanical_system_from_dict(d, 'f.yaml')
        Traceback (most recent call last):
        ...
        ExpressionError: f.yaml: bodies[0].joint[0]: dx is the velocity of the coordinate x, which cannot appear in positions, angles, masses or inertia (in 'x + dx')
        sage: d['bodies'][0]['joint'] = ['x', 0, 0]; d['parameters'] = ['m', 'dx']
        sage: mechanical_system_from_dict(d, 'f.yaml')
        Traceback (most recent call last):
        ...
        DescriptionError: f.yaml: parameters[1]: the name 'dx' is the velocity of the coordinate 'x' (coordinates[0]); choose another name
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
    name = title(data, 'name', source)
    parameters = _names(data, 'parameters', source, required=False, limit=MAX_PARAMETERS)
    coordinates = _names(data, 'coordinates', source, limit=MAX_COORDINATES)
    check_mechanical_names(coordinates, parameters, DescriptionError, source)
    velocities = [str(velocity(q)) for q in coordinates]
    parsers = {
        'geometry': ExpressionParser(parameters + coordinates, refused=_refusals(
            coordinates, False, "cannot appear in positions, angles, masses or inertia")),
        'force': ExpressionParser(parameters + coordinates, refused=_refusals(
            coordinates, False, "the force function U(q, t) cannot depend on: "
            "velocity-dependent forces belong in 'dissipation' or 'forces'")),
        'motion': ExpressionParser(parameters + coordinates + velocities,
                                   refused=_refusals(coordinates, True, "")),
    }
    bodies_data = data['bodies']
    if not isinstance(bodies_data, list):
        raise DescriptionError(f"expected a list of bodies, got {brief(bodies_data)}",
                               entry='bodies', source=source)
    if len(bodies_data) > MAX_BODIES:
        raise DescriptionError(f"{len(bodies_data)} bodies; a description file has at most "
                               f"{MAX_BODIES} (MAX_BODIES)", entry='bodies', source=source)
    from .mechanical_system import MechanicalSystem
    motion = parsers['motion']
    try:
        bodies = [_body(b, i, parsers, source) for i, b in enumerate(bodies_data)]
        n = len(coordinates)
        forces = data.get('forces')
        if forces is not None:
            if not isinstance(forces, list) or len(forces) != n:
                raise DescriptionError(f"expected a list of {n} expressions, one per "
                                       f"coordinate, got {brief(forces)}", entry='forces')
            forces = [motion.parse(f, entry=f'forces[{i}]') for i, f in enumerate(forces)]
        dissipation = motion.parse(data.get('dissipation', 0), entry='dissipation')
        field = _force_field(data.get('force_function'), parsers['force'])
        symbols = [motion.parse(q) for q in coordinates]
        return MechanicalSystem(bodies, symbols,
                                parameters=[motion.parse(p) for p in parameters],
                                force_function=field, dissipation=dissipation,
                                forces=forces, name=name)
    except DynSymError as err:
        raise err.with_context(source=source) from None


def _body(data, index, parsers, source):
    from .rigid_body import RigidBody
    entry = f"bodies[{index}]"
    _check_keys(data, BODY_KEYS, entry, source, "a body")
    if 'name' not in data:
        raise DescriptionError("missing key 'name'", entry=entry, source=source)
    name = title(data, f"{entry}.name", source)
    geometry, motion = parsers['geometry'], parsers['motion']

    def vector(key, default, parser=geometry):
        value = data.get(key, default)
        if value is None:
            return None
        if not isinstance(value, list) or len(value) != 3:
            raise DescriptionError(f"expected a list of 3 expressions, got {brief(value)}",
                                   entry=f"{entry}.{key}")
        return [parser.parse(c, entry=f"{entry}.{key}[{i}]") for i, c in enumerate(value)]

    rotations_data = data.get('rotations') or []
    if not isinstance(rotations_data, list):
        raise DescriptionError(f"expected a list of pairs [axis, angle], got "
                               f"{brief(rotations_data)}", entry=f"{entry}.rotations")
    rotations = []
    for i, rotation in enumerate(rotations_data):
        sub = f"{entry}.rotations[{i}]"
        if not isinstance(rotation, list) or len(rotation) != 2:
            raise DescriptionError(f"expected a pair [axis, angle], got {brief(rotation)}",
                                   entry=sub)
        axis = rotation[0]
        if isinstance(axis, bool) or axis not in (1, 2, 3):
            raise ModelError(f"rotation axis must be 1, 2 or 3 (x, y, z), got {brief(axis)}",
                             entry=sub)
        rotations.append((int(axis), geometry.parse(rotation[1], entry=sub)))
    inertia = data.get('inertia')
    if inertia is not None:
        if not (isinstance(inertia, list) and len(inertia) == 3 and
                all(isinstance(row, list) and len(row) == 3 for row in inertia)):
            raise DescriptionError(f"expected a 3x3 matrix (3 rows of 3 expressions), got "
                                   f"{brief(inertia)}", entry=f"{entry}.inertia")
        inertia = [[geometry.parse(c, entry=f"{entry}.inertia[{i}][{j}]")
                    for j, c in enumerate(row)] for i, row in enumerate(inertia)]
    parent = data.get('parent', 0)
    if not isinstance(parent, (int, str)) or isinstance(parent, bool):
        raise DescriptionError(f"expected 0, a body name or a body index, got {brief(parent)}",
                               entry=f"{entry}.parent")
    try:
        return RigidBody(name, parent=parent, rotations=rotations,
                         joint=vector('joint', [0, 0, 0]),
                         velocity=vector('velocity', None, motion),
                         mass_center=vector('mass_center', [0, 0, 0]),
                         mass=geometry.parse(data.get('mass', 0), entry=f"{entry}.mass"),
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
            raise DescriptionError(f"expected a list of 3 expressions, got {brief(value)}",
                                   entry=entry)
        return UniformGravity([parser.parse(c, entry=f"{entry}[{i}]") for i, c in enumerate(value)])
    _check_keys(value, NEWTONIAN_KEYS, entry, None, "a Newtonian field")
    missing = NEWTONIAN_KEYS - set(value)
    if missing:
        raise DescriptionError(f"missing key(s) {', '.join(sorted(missing))}", entry=entry)
    direction = value['direction']
    if not isinstance(direction, list) or len(direction) != 3:
        raise DescriptionError(f"expected a list of 3 expressions, got {brief(direction)}",
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

    The file is replaced atomically (:func:`write_atomically`): an
    interrupted save leaves the previous file as it was.

    EXAMPLES::

        sage: import tempfile
        sage: from sage_dynsym import load, save
        sage: from sage_dynsym.description import example_path
        sage: C = load(example_path('nonlinear_circuit.yaml'))
        sage: path = tempfile.mktemp(suffix='.yaml')
        sage: save(C, path)
        sage: load(path)
        Circuit 'nonlinear circuit of Example 2' with 13 branches on 5 nodes

    TESTS::

        sage: save(C, '/nonexistent/folder/c.yaml')
        Traceback (most recent call last):
        ...
        DescriptionError: /nonexistent/folder/c.yaml: cannot write the file: No such file or directory
    """
    from .mechanical_system import MechanicalSystem
    if isinstance(model, MechanicalSystem):
        data = mechanical_system_to_dict(model)
    else:
        from .circuits.description import circuit_to_dict
        data = circuit_to_dict(model)
    if results:
        data['results'] = model_results(model)
    write_atomically(path, lambda stream: yaml.safe_dump(data, stream, sort_keys=False,
                                                         allow_unicode=True, width=100))


def write_atomically(path, write):
    r"""
    Write a text file so that it is either the old file or the complete new
    one, whatever happens (an exception, Ctrl-C, a killed process, a crash
    of the machine after the call returned).

    ``write(stream)`` writes the text into a temporary file in the same
    folder; the file is flushed and synced to the disk, takes the
    permissions of the file it replaces, and is renamed over ``path`` with
    ``os.replace`` (atomic); the folder is synced too. On any failure the
    temporary file is removed and ``path`` is untouched. A symbolic link is
    followed: its target is replaced.

    INPUT:

    - ``path`` -- the file name
    - ``write`` -- a function of a text stream (UTF-8)

    EXAMPLES::

        sage: import os, tempfile
        sage: from sage_dynsym.description import write_atomically
        sage: folder = tempfile.mkdtemp(); path = os.path.join(folder, 'f.yaml')
        sage: write_atomically(path, lambda s: s.write('kind: circuit\n'))
        sage: def fail(stream):
        ....:     _ = stream.write('half a file')
        ....:     raise KeyboardInterrupt
        sage: write_atomically(path, fail)
        Traceback (most recent call last):
        ...
        KeyboardInterrupt
        sage: open(path).read(), os.listdir(folder)
        ('kind: circuit\n', ['f.yaml'])
    """
    target = os.path.realpath(path)
    folder = os.path.dirname(target) or '.'
    try:
        fd, temporary = tempfile.mkstemp(dir=folder, prefix=f".{os.path.basename(target)}.",
                                         suffix=".tmp")
    except OSError as err:
        raise DescriptionError(f"cannot write the file: {err.strerror or err}",
                               source=str(path)) from None
    try:
        with os.fdopen(fd, 'w', encoding='utf-8') as stream:
            write(stream)
            stream.flush()
            os.fsync(stream.fileno())
        try:
            mode = stat.S_IMODE(os.stat(target).st_mode)
        except FileNotFoundError:
            umask = os.umask(0)
            os.umask(umask)
            mode = 0o666 & ~umask
        os.chmod(temporary, mode)
        os.replace(temporary, target)
    except BaseException as err:
        try:
            os.unlink(temporary)
        except OSError:
            pass
        if isinstance(err, OSError):
            raise DescriptionError(f"cannot write the file: {err.strerror or err}",
                                   source=str(path)) from None
        raise
    try:                        # make the new directory entry durable
        directory = os.open(folder, os.O_RDONLY)
        try:
            os.fsync(directory)
        finally:
            os.close(directory)
    except OSError:
        pass


def _parse_results(model, results, source):
    from .mechanical_system import MechanicalSystem
    if not isinstance(results, dict):
        raise DescriptionError(f"expected a mapping, got {brief(results)}", entry='results',
                               source=source)
    for key in results:
        if not isinstance(key, str):
            raise DescriptionError(f"expected names of results as keys, got {brief(key)}",
                                   entry='results', source=source)
    functions = ()
    if isinstance(model, MechanicalSystem):
        q = [str(v) for v in model.coordinates()]
        symbols = [str(p) for p in model.parameters() or []]
        if model.parameters() is None:
            symbols += sorted({str(v) for v in model.lagrangian().expr().variables()})
    else:
        q = [str(v) for v in model.lagrangian().coordinates()] if 'lagrangian' in results else []
        states = results.get('state_variables', [])
        expected = [str(v) for v, _ in model.state_variables()] if states else []
        if states != expected:
            raise DescriptionError(f"expected the state variables {expected} of the circuit, "
                                   f"got {brief(states)}", entry='results.state_variables',
                                   source=source)
        symbols = list(model.parameters()) + states
        symbols += [b.name for b in model.branches() if b.kind != 'nonlinear_resistor']
        functions = model.elements('nonlinear_resistor')
    symbols += q + [str(velocity(v)) for v in q] + [str(acceleration(v)) for v in q]
    symbols += [str(momentum(v)) for v in q]
    parser = ExpressionParser(symbols, functions=functions, max_length=MAX_RESULT_LENGTH)
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
