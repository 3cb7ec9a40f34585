r"""
Operating points: the steady motions a model is linearized about

An :class:`OperatingPoint` names a steady motion: the coordinates that stay
fixed (``at``) and the velocities that stay constant (``velocities``),
possibly in terms of the parameters, e.g. a bicycle running upright and
straight at the forward speed `v`. The coordinates it does not fix move
(a heading, a position on the plane, a wheel's angle); the velocities of
the fixed coordinates are zero, and those it does not give follow from the
constraints -- which must determine them: a velocity they leave free (the
heading rate of a rolling disk) is given, or its coordinate fixed, and the
error says which. It is plain data, read from the ``operating_points:``
section of a description file (:meth:`MechanicalSystem.operating_point
<sage_dynsym.mechanics.system.MechanicalSystem.operating_point>`) or built
directly, and handed to :func:`~sage_dynsym.analysis.linear.linearize`.

EXAMPLES::

    sage: from sage_dynsym.analysis.operating_point import OperatingPoint
    sage: lean, steer, dthetaR, v, rR = var('lean steer dthetaR v rR')
    sage: P = OperatingPoint('upright', {lean: 0, steer: 0}, {dthetaR: -v/rR}); P
    Operating point 'upright': lean = 0, steer = 0, dthetaR = -v/rR
    sage: P.at(), P.velocities(), P.coordinates() is None
    ({lean: 0, steer: 0}, {dthetaR: -v/rR}, True)
"""
from sage.structure.sage_object import SageObject
from sage.symbolic.ring import SR

from ..errors import AnalysisError

__all__ = ['OperatingPoint']


class OperatingPoint(SageObject):
    r"""
    A steady motion, as data (see the module documentation).

    INPUT:

    - ``name`` -- a string (or ``None``)
    - ``at`` -- dict ``{coordinate: value}``: the coordinates that stay
      fixed
    - ``velocities`` -- (optional) dict ``{velocity: value}``: velocities that
      stay constant (values may contain parameters); those of the fixed
      coordinates are zero, the others follow from the constraints, which
      must determine them (see the module documentation)
    - ``coordinates`` -- (optional) the coordinates to linearize in when
      :func:`~sage_dynsym.analysis.linear.linearize` is not told

    EXAMPLES::

        sage: from sage_dynsym.analysis.operating_point import OperatingPoint
        sage: th, dphi = var('theta dphi')
        sage: OperatingPoint('rolling', {th: 0}, {dphi: var('w')}, coordinates=[th])
        Operating point 'rolling': theta = 0, dphi = w (coordinates theta)

    TESTS::

        sage: OperatingPoint('p', {th^2: 0})
        Traceback (most recent call last):
        ...
        AnalysisError: operating point 'p': at: expected symbols as keys, got theta^2
        sage: OperatingPoint('p', [th])
        Traceback (most recent call last):
        ...
        AnalysisError: operating point 'p': at: expected a dict {coordinate: value}, got [theta]
    """

    def __init__(self, name, at, velocities=None, coordinates=None):
        self._name = name
        self._at = self._mapping(at, 'at')
        self._velocities = self._mapping(velocities or {}, 'velocities')
        self._coordinates = None if coordinates is None else [SR(q) for q in coordinates]

    def _mapping(self, data, entry):
        if not isinstance(data, dict):
            raise AnalysisError(f"expected a dict {{{'coordinate' if entry == 'at' else 'velocity'}"
                                f": value}}, got {data}", entry=self._entry(entry))
        out = {}
        for key, value in data.items():
            symbol = SR(key)
            if not symbol.is_symbol():
                raise AnalysisError(f"expected symbols as keys, got {symbol}",
                                    entry=self._entry(entry))
            out[symbol] = SR(value)
        return out

    def _entry(self, key):
        return f"operating point {self._name!r}: {key}" if self._name else f"operating point: {key}"

    def _repr_(self):
        items = ", ".join(f"{k} = {v}" for k, v in list(self._at.items())
                          + list(self._velocities.items()))
        coordinates = ("" if self._coordinates is None else
                       f" (coordinates {', '.join(map(str, self._coordinates))})")
        name = f" {self._name!r}" if self._name else ""
        return f"Operating point{name}: {items}{coordinates}"

    def name(self):
        r"""The name (or ``None``).

        EXAMPLES::

            sage: from sage_dynsym.analysis.operating_point import OperatingPoint
            sage: OperatingPoint('upright', {var('lean'): 0}).name()
            'upright'
        """
        return self._name

    def at(self):
        r"""The fixed coordinates and their values (a new dict).

        EXAMPLES::

            sage: from sage_dynsym.analysis.operating_point import OperatingPoint
            sage: OperatingPoint('upright', {var('lean'): 0}).at()
            {lean: 0}
        """
        return dict(self._at)

    def velocities(self):
        r"""The velocities given and their values (a new dict).

        EXAMPLES::

            sage: from sage_dynsym.analysis.operating_point import OperatingPoint
            sage: OperatingPoint('p', {}, {var('dx'): 1}).velocities()
            {dx: 1}
        """
        return dict(self._velocities)

    def coordinates(self):
        r"""The coordinates to linearize in, or ``None`` when not given.

        EXAMPLES::

            sage: from sage_dynsym.analysis.operating_point import OperatingPoint
            sage: OperatingPoint('p', {var('x'): 0}, coordinates=[var('x')]).coordinates()
            [x]
        """
        return None if self._coordinates is None else list(self._coordinates)

    def subs(self, values):
        r"""
        The operating point with ``values`` (a dict ``{parameter: value}``)
        substituted in its values.

        EXAMPLES::

            sage: from sage_dynsym.analysis.operating_point import OperatingPoint
            sage: v, dx = var('v dx')
            sage: OperatingPoint('p', {}, {dx: 2*v}).subs({v: 3})
            Operating point 'p': dx = 6
        """
        return OperatingPoint(self._name, {k: v.subs(values) for k, v in self._at.items()},
                              {k: v.subs(values) for k, v in self._velocities.items()},
                              self._coordinates)

    def __eq__(self, other):
        r"""
        Operating points are values.

        EXAMPLES::

            sage: from sage_dynsym.analysis.operating_point import OperatingPoint
            sage: x = var('x')
            sage: OperatingPoint('p', {x: 0}) == OperatingPoint('p', {x: 0}), OperatingPoint('p', {x: 0}) == 1
            (True, False)
        """
        return (isinstance(other, OperatingPoint) and self._name == other._name
                and _same(self._at, other._at) and _same(self._velocities, other._velocities)
                and [str(q) for q in self._coordinates or ()]
                == [str(q) for q in other._coordinates or ()])

    def __ne__(self, other):
        return not self == other

    def __hash__(self):
        return hash((self._name, tuple(sorted(map(str, self._at)))))


def _same(a, b):
    return (list(map(str, a)) == list(map(str, b))
            and all(SR(a[k]).is_trivially_equal(SR(b[k])) for k in a))

