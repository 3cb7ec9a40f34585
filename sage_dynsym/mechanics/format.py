r"""
The description format of mechanical systems (read and written)

The keys of a mechanical description file (format:
:doc:`/description_files`; how the files are read safely:
:mod:`sage_dynsym.description`), their checks, and the mapping written
back. A mechanical system::

    kind: mechanical
    name: spherical pendulum
    parameters: [m, l, g]
    coordinates: [psi, theta]
    force_function:
      uniform_gravity: [0, 0, -g]    # or newtonian: {nu: .., r: .., direction: [..]}
                                     # or expression: "U(q, t)"
                                     # or a list of such terms, added together
    dissipation: "c*dtheta^2/2"      # optional Rayleigh function (velocities d<name>)
    forces: ["0", "M0*sin(w*t)"]     # optional, one per coordinate
    loads:                           # optional forces at body points and torques
      - {body: pendulum, point: [0, 0, l], force: [F, 0, 0], axes: 0}
    constraints: []                  # optional holonomic constraints f(q, t) (== 0)
    nonholonomic: []                 # optional constraints linear in the velocities (== 0)
    rolling:                         # optional thin disks rolling on the plane z = 0
      - {body: wheel, radius: r, axle: 2}
    operating_points:                # optional named steady motions
      straight: {at: {lean: 0}, velocities: {dspin: w}, coordinates: [lean]}
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
:mod:`sage_dynsym.circuits.description`. The class reads its files with
:meth:`MechanicalSystem.from_dict
<sage_dynsym.mechanics.system.MechanicalSystem.from_dict>`, which calls
:func:`read_mechanical_system`; the functions of
:mod:`sage_dynsym.mechanics.description` keep their earlier names.

:meth:`MechanicalFormat.to_dict` gives the mapping back, the one that
:func:`~sage_dynsym.description.save` writes (with a ``results:``
section).

EXAMPLES: a slider on a spring, read from its mapping and written back::

    sage: from sage_dynsym import MechanicalSystem
    sage: d = {'kind': 'mechanical', 'name': 'slider', 'parameters': ['m', 'k'],
    ....:      'coordinates': ['x'], 'force_function': {'expression': '-k*x^2/2'},
    ....:      'bodies': [{'name': 'b', 'joint': ['x', 0, 0], 'mass': 'm'}]}
    sage: S = MechanicalSystem.from_dict(d); S
    Mechanical system 'slider': 1 body, coordinates (x)
    sage: S.to_dict()['force_function'], S.to_dict()['bodies'][0]['joint']
    ({'expression': '-1/2*k*x^2'}, ['x', '0', '0'])
    sage: MechanicalSystem.from_dict(S.to_dict()).lagrangian().expr()
    1/2*dx^2*m - 1/2*k*x^2
"""
import re

from sage.misc.latex import latex
from sage.symbolic.ring import SR

from ..errors import DescriptionError, DynSymError, ModelError, brief
from ..io.expressions import ExpressionParser
from ..io.fields import (check_keys, declared_names, declared_positive, title, MAX_PARAMETERS,
                         text as _text)
from ..symbols import (velocity, acceleration, momentum, check_mechanical_names,
                       ALLOWED_FUNCTIONS, CONSTANTS)
from .force_functions import force_term_to_dict
from .operating_points import operating_point_to_dict

__all__ = ['MECHANICAL_KEYS', 'ROLLING_KEYS', 'OPERATING_POINT_KEYS', 'REQUIRED_MECHANICAL',
           'BODY_KEYS', 'FIELD_KEYS', 'NEWTONIAN_KEYS', 'LOAD_KEYS', 'MAX_COORDINATES',
           'MAX_BODIES', 'MAX_TERMS', 'read_mechanical_system', 'MechanicalFormat']

MECHANICAL_KEYS = {'kind', 'name', 'parameters', 'positive', 'coordinates', 'force_function',
                   'dissipation', 'forces', 'loads', 'constraints', 'nonholonomic', 'rolling',
                   'operating_points', 'bodies', 'results'}
ROLLING_KEYS = {'body', 'radius', 'axle'}
OPERATING_POINT_KEYS = {'at', 'velocities', 'coordinates'}
REQUIRED_MECHANICAL = ('coordinates', 'bodies')
BODY_KEYS = {'name', 'parent', 'rotations', 'joint', 'velocity', 'mass_center', 'mass',
             'inertia'}
FIELD_KEYS = {'uniform_gravity', 'newtonian', 'expression'}
NEWTONIAN_KEYS = {'nu', 'r', 'direction'}
LOAD_KEYS = {'body', 'point', 'force', 'torque', 'axes'}
#: Most generalized coordinates of a mechanical description (a 500-link
#: chain with two rotations per link, a floating-base humanoid with hands).
MAX_COORDINATES = 1000
#: Most bodies of a mechanical description (a cable of 1,000 segments).
MAX_BODIES = 1000
#: Most terms of a force function, loads and constraints of a description.
MAX_TERMS = 200


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


def read_mechanical_system(cls, data, source=None):
    r"""
    Build a :class:`~sage_dynsym.mechanics.system.MechanicalSystem` (the
    class ``cls``: this module does not import it, the class calls this
    function from its ``from_dict``) from a description mapping.

    INPUT:

    - ``cls`` -- the class built
    - ``data`` -- the mapping of a ``kind: mechanical`` description
    - ``source`` -- (optional) file name for error messages

    Names are checked against the reserved names (see
    :mod:`sage_dynsym.symbols`) and each other. Positions, angles, masses,
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

    Several force-function terms, loads and constraints; errors name the
    entry::

        sage: d = {'kind': 'mechanical', 'parameters': ['m', 'k', 'g', 'F'],
        ....:      'coordinates': ['x', 'z'],
        ....:      'force_function': [{'uniform_gravity': [0, 0, '-g']}, {'expression': '-k*x^2/2'}],
        ....:      'loads': [{'body': 'b', 'force': ['F', 0, 0]}],
        ....:      'bodies': [{'name': 'b', 'joint': ['x', 0, 'z'], 'mass': 'm'}]}
        sage: S = mechanical_system_from_dict(d); S.force_function(), S.generalized_forces()
        (-1/2*k*x^2 - g*m*z, [F, 0])
        sage: d['force_function'][1] = {'expression': '-k*dx^2'}
        sage: mechanical_system_from_dict(d, 'f.yaml')
        Traceback (most recent call last):
        ...
        ExpressionError: f.yaml: force_function[1].expression: dx is the velocity of the coordinate x, which the force function U(q, t) cannot depend on: velocity-dependent forces belong in 'dissipation' or 'forces' (in '-k*dx^2')
        sage: d['force_function'] = None; d['loads'][0]['body'] = 'c'
        sage: mechanical_system_from_dict(d, 'f.yaml')
        Traceback (most recent call last):
        ...
        ModelError: f.yaml: loads[0].body: unknown body 'c'; known bodies are: b
        sage: d['loads'][0] = {'body': 'b', 'point': [0, 'dx', 0], 'force': [1, 0, 0]}
        sage: mechanical_system_from_dict(d, 'f.yaml')
        Traceback (most recent call last):
        ...
        ExpressionError: f.yaml: loads[0].point[1]: dx is the velocity of the coordinate x, which cannot appear in positions, angles, masses or inertia (in 'dx')
        sage: d['loads'] = []; d['constraints'] = ['k - 1']
        sage: mechanical_system_from_dict(d, 'f.yaml')
        Traceback (most recent call last):
        ...
        ModelError: f.yaml: constraints[0]: the constraint k - 1 == 0 does not depend on the coordinates x, z

    Velocity constraints, rolling disks and operating points::

        sage: d['constraints'] = []; d['nonholonomic'] = ['dx - ddz']
        sage: mechanical_system_from_dict(d, 'f.yaml')
        Traceback (most recent call last):
        ...
        ExpressionError: f.yaml: nonholonomic[0]: ddz is the acceleration of the coordinate z; a description holds no accelerations (in 'dx - ddz')
        sage: d['nonholonomic'] = ['dx - k*dz']; d['rolling'] = [{'body': 'b', 'radius': 'k', 'axle': 0}]
        sage: mechanical_system_from_dict(d, 'f.yaml')
        Traceback (most recent call last):
        ...
        ModelError: f.yaml: rolling[0].axle: expected 1, 2 or 3 (the axis of the body along the axle), got 0
        sage: d['rolling'] = []; d['operating_points'] = {'p': {'at': {'z': 'x'}}}
        sage: mechanical_system_from_dict(d, 'f.yaml')
        Traceback (most recent call last):
        ...
        ExpressionError: f.yaml: operating_points.p.at.z: x is a coordinate; the values of an operating point are in the parameters (in 'x')
        sage: d['operating_points'] = {'p': {'at': {'z': 0}, 'velocities': {'dx': 'F'}}}
        sage: mechanical_system_from_dict(d, 'f.yaml').operating_point('p')
        Operating point 'p': z = 0, dx = F
    """
    check_keys(data, MECHANICAL_KEYS, None, source, "a mechanical description")
    for key in REQUIRED_MECHANICAL:
        if key not in data:
            raise DescriptionError(f"missing key {key!r} (a list of "
                                   f"{'symbol names' if key == 'coordinates' else 'bodies'})",
                                   entry=key, source=source)
    name = title(data, 'name', source)
    parameters = declared_names(data, 'parameters', source, required=False, limit=MAX_PARAMETERS)
    positive = declared_positive(data, parameters, source)
    coordinates = declared_names(data, 'coordinates', source, limit=MAX_COORDINATES)
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
        'constraint': ExpressionParser(parameters + coordinates, refused=_refusals(
            coordinates, False, "a holonomic constraint f(q, t) cannot depend on")),
        'value': ExpressionParser(parameters, refused=_value_refusals(coordinates)),
    }
    bodies_data = data['bodies']
    if not isinstance(bodies_data, list):
        raise DescriptionError(f"expected a list of bodies, got {brief(bodies_data)}",
                               entry='bodies', source=source)
    if len(bodies_data) > MAX_BODIES:
        raise DescriptionError(f"{len(bodies_data)} bodies; a description file has at most "
                               f"{MAX_BODIES} (MAX_BODIES)", entry='bodies', source=source)
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
        loads = [_load(d, i, parsers) for i, d in enumerate(_entries(data, 'loads'))]
        constraints = [parsers['constraint'].parse(f, entry=f'constraints[{i}]')
                       for i, f in enumerate(_entries(data, 'constraints'))]
        nonholonomic = [motion.parse(g, entry=f'nonholonomic[{i}]')
                        for i, g in enumerate(_entries(data, 'nonholonomic'))]
        rolling = [_rolling(d, i, parsers) for i, d in enumerate(_entries(data, 'rolling'))]
        points = _operating_points(data.get('operating_points'), parsers['value'])
        symbols = [motion.parse(q) for q in coordinates]
        return cls(bodies, symbols,
                   parameters=[motion.parse(p) for p in parameters],
                   force_function=field, dissipation=dissipation,
                   forces=forces, name=name,
                   positive=[motion.parse(p) for p in positive],
                   loads=loads, constraints=constraints,
                   nonholonomic=nonholonomic, rolling=rolling,
                   operating_points=points)
    except DynSymError as err:
        raise err.with_context(source=source) from err


def _body(data, index, parsers, source):
    from .rigid_body import RigidBody
    entry = f"bodies[{index}]"
    check_keys(data, BODY_KEYS, entry, source, "a body")
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
        raise type(err)(err.message, entry=f"{entry}.{field}" if field else entry) from err


def _entries(data, key):
    # an optional list of at most MAX_TERMS entries
    value = data.get(key)
    if value is None:
        return []
    if not isinstance(value, list):
        raise DescriptionError(f"expected a list, got {brief(value)}", entry=key)
    if len(value) > MAX_TERMS:
        raise DescriptionError(f"{len(value)} entries; a description file has at most "
                               f"{MAX_TERMS} (MAX_TERMS)", entry=key)
    return value


def _value_refusals(coordinates):
    # the values of an operating point are in the parameters
    refused = _refusals(coordinates, False, "cannot appear in the values of an operating point")
    for q in coordinates:
        refused[str(q)] = (f"{q} is a coordinate; the values of an operating point are in the "
                           "parameters")
    return refused


def _rolling(data, index, parsers):
    entry = f"rolling[{index}]"
    check_keys(data, ROLLING_KEYS, entry, None, "a rolling disk")
    for key in sorted(ROLLING_KEYS):
        if key not in data:
            raise DescriptionError(f"missing key {key!r} (a rolling disk has the keys "
                                   f"{', '.join(sorted(ROLLING_KEYS))})", entry=entry)
    body, axle = data['body'], data['axle']
    if not isinstance(body, (int, str)) or isinstance(body, bool):
        raise DescriptionError(f"expected a body name or a 1-based body index, got "
                               f"{brief(body)}", entry=f"{entry}.body")
    if isinstance(axle, bool) or axle not in (1, 2, 3):
        raise ModelError(f"expected 1, 2 or 3 (the axis of the body along the axle), got "
                         f"{brief(axle)}", entry=f"{entry}.axle")
    return {'body': body, 'axle': axle,
            'radius': parsers['geometry'].parse(data['radius'], entry=f"{entry}.radius")}


def _operating_points(data, parser):
    if data is None:
        return None
    if not isinstance(data, dict):
        raise DescriptionError("expected a mapping {name: {at: {...}, velocities: {...}}}, got "
                               f"{brief(data)}", entry='operating_points')
    if len(data) > MAX_TERMS:
        raise DescriptionError(f"{len(data)} entries; a description file has at most "
                               f"{MAX_TERMS} (MAX_TERMS)", entry='operating_points')
    points = {}
    for name, point in data.items():
        entry = f"operating_points.{name}"
        if not isinstance(name, str):
            raise DescriptionError(f"expected a name, got {brief(name)}",
                                   entry='operating_points')
        check_keys(point, OPERATING_POINT_KEYS, entry, None, "an operating point")
        parsed = {}
        for key in ('at', 'velocities'):
            values = point.get(key) or {}
            if not isinstance(values, dict):
                raise DescriptionError(f"expected a mapping {{name: value}}, got "
                                       f"{brief(values)}", entry=f"{entry}.{key}")
            parsed[key] = {str(k): parser.parse(v, entry=f"{entry}.{key}.{k}")
                           for k, v in values.items()}
        listed = point.get('coordinates')
        if listed is not None:
            if not isinstance(listed, list) or not all(isinstance(k, str) for k in listed):
                raise DescriptionError(f"expected a list of coordinate names, got "
                                       f"{brief(listed)}", entry=f"{entry}.coordinates")
            parsed['coordinates'] = listed
        points[name] = parsed
    return points


def _load(data, index, parsers):
    entry = f"loads[{index}]"
    check_keys(data, LOAD_KEYS, entry, None, "a load")
    if 'body' not in data:
        raise DescriptionError("missing key 'body' (a body name or 1-based index)", entry=entry)
    if not ('force' in data or 'torque' in data):
        raise DescriptionError("a load needs a 'force', a 'torque' or both", entry=entry)
    load = {}
    for key in ('body', 'axes'):
        if key in data:
            value = data[key]
            if not isinstance(value, (int, str)) or isinstance(value, bool):
                raise DescriptionError(f"expected {'0, ' if key == 'axes' else ''}a body name "
                                       f"or a 1-based body index, got {brief(value)}",
                                       entry=f"{entry}.{key}")
            load[key] = value
    for key in ('point', 'force', 'torque'):
        if data.get(key) is None:
            continue
        value = data[key]
        if not isinstance(value, list) or len(value) != 3:
            raise DescriptionError(f"expected a list of 3 expressions, got {brief(value)}",
                                   entry=f"{entry}.{key}")
        parser = parsers['geometry'] if key == 'point' else parsers['motion']
        load[key] = [parser.parse(c, entry=f"{entry}.{key}[{i}]") for i, c in enumerate(value)]
    return load


def _force_field(data, parser):
    if data is None:
        return None
    if isinstance(data, list):
        if not data:
            raise DescriptionError("expected at least one term (or no force_function key)",
                                   entry='force_function')
        if len(data) > MAX_TERMS:
            raise DescriptionError(f"{len(data)} terms; a description file has at most "
                                   f"{MAX_TERMS} (MAX_TERMS)", entry='force_function')
        return [_force_term(term, parser, f"force_function[{i}]")
                for i, term in enumerate(data)]
    return _force_term(data, parser, 'force_function')


def _force_term(data, parser, where):
    from .force_functions import UniformGravity, NewtonianField
    check_keys(data, FIELD_KEYS, where, None, "a force-function term")
    if len(data) != 1:
        raise DescriptionError("give exactly one of uniform_gravity, newtonian, expression "
                               "per term (a list of terms adds them)", entry=where)
    (key, value), = data.items()
    entry = f"{where}.{key}"
    if key == 'expression':
        return parser.parse(value, entry=entry)
    if key == 'uniform_gravity':
        if not isinstance(value, list) or len(value) != 3:
            raise DescriptionError(f"expected a list of 3 expressions, got {brief(value)}",
                                   entry=entry)
        return UniformGravity([parser.parse(c, entry=f"{entry}[{i}]") for i, c in enumerate(value)])
    check_keys(value, NEWTONIAN_KEYS, entry, None, "a Newtonian field")
    missing = NEWTONIAN_KEYS - set(value)
    if missing:
        raise DescriptionError(f"missing key(s) {', '.join(sorted(missing))}", entry=entry)
    direction = value['direction']
    if not isinstance(direction, list) or len(direction) != 3:
        raise DescriptionError(f"expected a list of 3 expressions, got {brief(direction)}",
                               entry=f"{entry}.direction")
    nu, r = parser.parse(value['nu'], entry=f"{entry}.nu"), parser.parse(value['r'],
                                                                         entry=f"{entry}.r")
    e = [parser.parse(c, entry=f"{entry}.direction[{i}]") for i, c in enumerate(direction)]
    try:
        return NewtonianField(nu, r, e)
    except ModelError as err:       # its entry is newtonian.<key>
        raise err.with_context(entry=where) from err


class MechanicalFormat:
    r"""
    The description format of a
    :class:`~sage_dynsym.mechanics.system.MechanicalSystem`, read and
    written (a base class of it): :meth:`from_dict` and :meth:`to_dict`,
    and the ``results:`` section of a saved description.

    EXAMPLES: see the module documentation.
    """

    @classmethod
    def from_dict(cls, data, source=None):
        r"""
        The mechanical system of a description mapping (``kind: mechanical``); ``source``
        names the file in errors. The format is read by
        :func:`~sage_dynsym.mechanics.format.read_mechanical_system`.

        EXAMPLES::

            sage: from sage_dynsym import MechanicalSystem
            sage: S = MechanicalSystem.from_dict({'kind': 'mechanical', 'coordinates': ['x'],
            ....:     'parameters': ['m'], 'bodies': [{'name': 'cart', 'joint': ['x', 0, 0], 'mass': 'm'}]})
            sage: S.lagrangian().expr()
            1/2*dx^2*m
        """
        return read_mechanical_system(cls, data, source)

    def to_dict(self):
        r"""
        The description mapping of the system (the inverse of
        :func:`~sage_dynsym.mechanics.description.mechanical_system_from_dict`).

        EXAMPLES::

            sage: from sage_dynsym import load
            sage: from sage_dynsym.description import example_path
            sage: d = load(example_path('spherical_pendulum.yaml')).to_dict()
            sage: d['bodies'][0]['rotations'], d['force_function']
            ([[3, 'psi'], [1, 'theta']], {'uniform_gravity': ['0', '0', '-g']})
        """
        out = {'kind': 'mechanical'}
        if self.name():
            out['name'] = self.name()
        if self.parameters() is not None:
            out['parameters'] = [str(p) for p in self.parameters()]
        if self.positive_parameters():
            out['positive'] = [str(p) for p in self.positive_parameters()]
        out['coordinates'] = [str(q) for q in self.coordinates()]
        terms = [force_term_to_dict(field, _text) for field in self.force_terms()]
        if terms:
            # one term keeps the single-mapping form
            out['force_function'] = terms if isinstance(self.force_field(), list) else terms[0]
        if not self.dissipation().is_zero():
            out['dissipation'] = _text(self.dissipation())
        if any(not f.is_zero() for f in self.given_forces()):
            out['forces'] = [_text(f) for f in self.given_forces()]
        if self.loads():
            out['loads'] = [load.to_dict() for load in self.loads()]
        constraints = self.constraint_set()
        if constraints.given_holonomic():
            out['constraints'] = [_text(f) for f in constraints.given_holonomic()]
        if constraints.given_nonholonomic():
            out['nonholonomic'] = [_text(g) for g in constraints.given_nonholonomic()]
        if constraints.rolling():
            out['rolling'] = [disk.to_dict() for disk in constraints.rolling()]
        if self.operating_points():
            out['operating_points'] = {name: operating_point_to_dict(point)
                                       for name, point in self.operating_points().items()}
        bodies = []
        for k, body in enumerate(self.bodies(), 1):
            entry = {'name': body.name(), 'parent': self.parent_index(k),
                     'rotations': [[axis, _text(angle)] for axis, angle in body.rotations()],
                     'joint': [_text(c) for c in body.joint()],
                     'mass_center': [_text(c) for c in body.mass_center()],
                     'mass': _text(body.mass()),
                     'inertia': [[_text(c) for c in row] for row in body.inertia().rows()]}
            if body.velocity() is not None:
                entry['velocity'] = [_text(c) for c in body.velocity()]
            bodies.append(entry)
        out['bodies'] = bodies
        if self.parameters() is None:
            # a description declares its symbols: those its expressions use
            out = {**{k: v for k, v in out.items() if k in ('kind', 'name')},
                   'parameters': self._undeclared_symbols(out),
                   **{k: v for k, v in out.items() if k not in ('kind', 'name')}}
        return out

    def results(self):
        r"""
        The ``results:`` section of a saved description: the Lagrangian and
        the Lagrange equations, as text and LaTeX.

        EXAMPLES::

            sage: from sage_dynsym import load
            sage: from sage_dynsym.description import example_path
            sage: sorted(load(example_path('spherical_pendulum.yaml')).results())
            ['lagrange_equations', 'lagrange_equations_latex', 'lagrangian', 'lagrangian_latex']
        """
        L = self.lagrangian()
        equations = L.lagrange_equations()
        return {'lagrangian': _text(L.expr()), 'lagrangian_latex': str(latex(L.expr())),
                'lagrange_equations': [_text(e) for e in equations],
                'lagrange_equations_latex': [str(latex(e)) for e in equations]}

    @staticmethod
    def _undeclared_symbols(out):
        # the names the description's expressions use besides the
        # coordinates, their velocities, t, the functions and constants
        own = {q for q in out['coordinates']} | {f"d{q}" for q in out['coordinates']} | {'t'}
        found = set()

        def walk(value):
            if isinstance(value, str):
                found.update(re.findall(r"[A-Za-z_][A-Za-z_0-9]*", value))
            elif isinstance(value, dict):
                walk_entries(value)
            elif isinstance(value, (list, tuple)):
                for v in value:
                    walk(v)
        names = ('kind', 'name', 'coordinates', 'parent', 'body', 'axes')

        def walk_entries(mapping):
            for key, value in mapping.items():
                if key not in names:
                    walk(value)
        walk_entries(out)
        return sorted(found - own - set(ALLOWED_FUNCTIONS) - set(CONSTANTS))

    def result_symbols(self, results):
        r"""
        The names a ``results:`` section of this system may use: the
        parameters (or the symbols of the Lagrangian), the coordinates,
        their velocities, accelerations and momenta; no functions.

        EXAMPLES::

            sage: from sage_dynsym import load
            sage: from sage_dynsym.description import example_path
            sage: symbols, functions = load(example_path('spherical_pendulum.yaml')).result_symbols({})
            sage: sorted(symbols)[:6], functions
            (['ddpsi', 'ddtheta', 'dpsi', 'dtheta', 'g', 'l'], ())
        """
        q = [str(v) for v in self.coordinates()]
        symbols = [str(p) for p in self.parameters() or []]
        if self.parameters() is None:
            symbols += sorted({str(v) for v in self.lagrangian().expr().variables()})
        symbols += q + [str(velocity(SR(v))) for v in q] + [str(acceleration(SR(v))) for v in q]
        symbols += [str(momentum(SR(v))) for v in q]
        if self.constraints() or self.nonholonomic_constraints():
            # the Lagrange equations of the first kind hold the multipliers
            symbols += [str(mu) for mu in self.lagrangian().multipliers()]
        return symbols, ()
