r"""
The named operating points of a mechanical system

A description file may name steady motions of its system,

.. code-block:: yaml

    operating_points:
      upright:                      # a name
        at: {lean: 0, steer: 0}     # coordinates that stay fixed
        velocities: {dthetaR: -v/rR}   # velocities that stay constant
        coordinates: [lean, steer]  # optional: the coordinates to linearize in

read into :class:`~sage_dynsym.analysis.operating_point.OperatingPoint`
objects; :func:`checked_operating_points` checks them against the system
(known coordinates and velocities, values in the parameters only).

EXAMPLES::

    sage: from sage_dynsym.mechanics.operating_points import checked_operating_points
    sage: x, th, dx, dth, v = var('x theta dx dtheta v')
    sage: P = checked_operating_points({'straight': {'at': {'theta': 0}, 'velocities': {dx: v}}},
    ....:                              [x, th], [dx, dth], [v]); P
    {'straight': Operating point 'straight': theta = 0, dx = v}
    sage: P['straight'].at()
    {theta: 0}
"""
from sage.symbolic.ring import SR

from ..errors import ModelError
from ..io.fields import check_mapping
from ..analysis.operating_point import OperatingPoint
from ..symbols import t

__all__ = ['POINT_KEYS', 'checked_operating_points', 'operating_point_to_dict']

#: The keys of one operating point.
POINT_KEYS = ('at', 'coordinates', 'velocities')


def _symbol(key, known, what, entry):
    names = {str(s): s for s in known}
    name = key if isinstance(key, str) else str(SR(key))
    if name not in names:
        plural = 'velocities' if what == 'a velocity' else 'coordinates'
        raise ModelError(f"{name} is not {what}; the {plural} are "
                         f"{', '.join(names) or '(none)'}", entry=entry)
    return names[name]


def checked_operating_points(points, coordinates, velocities, parameters=None):
    r"""
    The operating points ``points`` (a dict ``{name: point}``, each an
    :class:`~sage_dynsym.analysis.operating_point.OperatingPoint` or a dict
    with the keys ``at``, ``velocities`` and ``coordinates``, names or
    symbols as keys) checked against the coordinates, velocities and
    parameters (``None``: not declared) of a system.

    OUTPUT: a dict ``{name: OperatingPoint}``

    EXAMPLES: see the module documentation.

    TESTS::

        sage: from sage_dynsym.mechanics.operating_points import checked_operating_points
        sage: x, dx, v = var('x dx v')
        sage: checked_operating_points({'p': {'at': {'y': 0}}}, [x], [dx])
        Traceback (most recent call last):
        ...
        ModelError: operating_points.p.at: y is not a coordinate; the coordinates are x
        sage: checked_operating_points({'p': {'velocities': {'x': 1}}}, [x], [dx])
        Traceback (most recent call last):
        ...
        ModelError: operating_points.p.velocities: x is not a velocity; the velocities are dx
        sage: checked_operating_points({'p': {'at': {x: dx}}}, [x], [dx])
        Traceback (most recent call last):
        ...
        ModelError: operating_points.p.at.x: the value dx depends on the coordinates or velocities; give it in the parameters
        sage: checked_operating_points({'p': {'at': {x: var('k')}}}, [x], [dx], [v])
        Traceback (most recent call last):
        ...
        ModelError: operating_points.p.at.x: undeclared symbol k; declared are: v
        sage: checked_operating_points({'p': {'speed': 1}}, [x], [dx])
        Traceback (most recent call last):
        ...
        ModelError: operating_points.p: unknown key 'speed'; an operating point has the keys at, coordinates, velocities
        sage: checked_operating_points([1], [x], [dx])
        Traceback (most recent call last):
        ...
        ModelError: operating_points: expected a mapping {name: {at: ..., velocities: ...}}, got [1]
    """
    if points is None:
        return {}
    if not isinstance(points, dict):
        raise ModelError("expected a mapping {name: {at: ..., velocities: ...}}, got "
                         f"{points!r}", entry="operating_points")
    dynamic = set(coordinates) | set(velocities)
    out = {}
    for name, point in points.items():
        entry = f"operating_points.{name}"
        if not isinstance(name, str) or not name:
            raise ModelError(f"expected a name, got {name!r}", entry="operating_points")
        if isinstance(point, OperatingPoint):
            point = {'at': point.at(), 'velocities': point.velocities(),
                     'coordinates': point.coordinates()}
        check_mapping(point, POINT_KEYS, "an operating point", entry)
        values = {}
        for key, known, what in (('at', coordinates, 'a coordinate'),
                                 ('velocities', velocities, 'a velocity')):
            data = point.get(key) or {}
            if not isinstance(data, dict):
                raise ModelError(f"expected a mapping {{name: value}}, got {data!r}",
                                 entry=f"{entry}.{key}")
            values[key] = {}
            for k, value in data.items():
                symbol = _symbol(k, known, what, f"{entry}.{key}")
                sub = f"{entry}.{key}.{symbol}"
                try:
                    value = SR(value)
                except (TypeError, ValueError) as err:
                    raise ModelError(f"expected an expression, got {value!r}",
                                     entry=sub) from err
                if any(v in dynamic for v in value.variables()):
                    raise ModelError(f"the value {value} depends on the coordinates or "
                                     "velocities; give it in the parameters", entry=sub)
                if parameters is not None:
                    for v in value.variables():
                        if v not in parameters and v != t:
                            raise ModelError(f"undeclared symbol {v}; declared are: "
                                             + ", ".join(map(str, parameters)), entry=sub)
                values[key][symbol] = value
        listed = point.get('coordinates')
        if listed is not None:
            if not isinstance(listed, (list, tuple)):
                raise ModelError(f"expected a list of coordinates, got {listed!r}",
                                 entry=f"{entry}.coordinates")
            listed = [_symbol(k, coordinates, 'a coordinate', f"{entry}.coordinates")
                      for k in listed]
        out[name] = OperatingPoint(name, values['at'], values['velocities'], listed)
    return out


def operating_point_to_dict(point):
    r"""
    The description mapping of ``point`` (names and expressions as text),
    the inverse of :func:`checked_operating_points` for one point.

    EXAMPLES::

        sage: from sage_dynsym.analysis.operating_point import OperatingPoint
        sage: from sage_dynsym.mechanics.operating_points import operating_point_to_dict
        sage: th, dx, v = var('theta dx v')
        sage: operating_point_to_dict(OperatingPoint('p', {th: 0}, {dx: 2*v}, [th]))
        {'at': {'theta': '0'}, 'coordinates': ['theta'], 'velocities': {'dx': '2*v'}}
    """
    from ..io.fields import text
    out = {}
    if point.at():
        out['at'] = {str(k): text(v) for k, v in point.at().items()}
    if point.coordinates() is not None:
        out['coordinates'] = [str(q) for q in point.coordinates()]
    if point.velocities():
        out['velocities'] = {str(k): text(v) for k, v in point.velocities().items()}
    return out

