r"""
Steady motions solved for: their values, existence and stability

:func:`steady_motions` solves the conditions of a steady motion
(:func:`~sage_dynsym.analysis.steady.steady_motion_conditions`) for
unknowns in its operating point, exactly, and returns
:class:`SteadyMotionSolution` objects, which answer the questions of
stationary motions with the same meaning (``point()``, ``values()``,
``conditions()``, ``stability()``: see
:mod:`~sage_dynsym.analysis.motion_solution`); their stability is that of
the linearization about them
(:func:`~sage_dynsym.analysis.steady.steady_linearization`).

EXAMPLES: see :func:`steady_motions`.

REFERENCES:

- E. J. Routh, *Advanced Rigid Dynamics*, Macmillan 1905, art. 244 (the
  rolling disk)
- J. I. Neimark, N. A. Fufaev, *Dynamics of Nonholonomic Systems*, AMS
  1972, chapter III (stability of steady motions)
"""
from sage.matrix.constructor import matrix, block_diagonal_matrix, identity_matrix
from sage.symbolic.ring import SR

from ..errors import AnalysisError
from ..arguments import model_argument, symbol_arguments
from ..symbols import velocity
from ..algebra.conditions import simplify_conjunction
from ..algebra.solving import SolutionList, solve_exactly
from .linear import LinearSystem
from .motion_solution import MotionSolution
from .verdict import verdict_from_parts
from .operating_point import OperatingPoint
from .steady import steady_motion_conditions, steady_linearization, split_point

__all__ = ['steady_motions', 'SteadyMotionSolution', 'SteadyMotions']


def steady_motions(system, point, solve_for, positive=(), speeds=None, coordinates=None):
    r"""
    The steady motions of the form ``point`` whose values ``solve_for``
    are unknown: the real solutions of :func:`steady_motion_conditions`,
    exactly (:func:`~sage_dynsym.algebra.solving.solve_exactly`), with the
    conditions for them to exist.

    INPUT:

    - ``system``, ``point``, ``speeds`` -- as for :func:`steady_motion_conditions`
    - ``solve_for`` -- the unknowns (symbols in the values of ``point``)
    - ``positive`` -- parameters declared positive
    - ``coordinates`` -- (optional) the coordinates to linearize in for the
      stability of each motion; default: those of ``point``, else the
      coordinates it fixes

    OUTPUT: a :class:`SteadyMotions`: iterate over it for the
    :class:`SteadyMotionSolution` objects, which answer ``point()``,
    ``values()``, ``conditions()`` and ``stability()`` as stationary motions
    do (:mod:`~sage_dynsym.analysis.motion_solution`)

    EXAMPLES: the disk of :func:`steady_motion_conditions` rolling on a
    circle, its spin rate for a given tilt and turning rate::

        sage: from sage_dynsym import MechanicalSystem, RigidBody, UniformGravity
        sage: from sage_dynsym.analysis.operating_point import OperatingPoint
        sage: from sage_dynsym.analysis.steady_solutions import steady_motions
        sage: x, y, psi, th, phi, m, r, A, C, g = var('x y psi theta phi m r A C g')
        sage: frame = RigidBody('frame', joint=[x, y, 0], rotations=[(3, psi), (1, th)])
        sage: disk = RigidBody('disk', parent='frame', joint=[0, 0, r], rotations=[(2, phi)],
        ....:                  mass=m, inertia=diagonal_matrix([A, C, A]))
        sage: S = MechanicalSystem([frame, disk], [x, y, psi, th, phi],
        ....:                      force_function=UniformGravity([0, 0, -g]),
        ....:                      rolling=[{'body': 'disk', 'radius': r, 'axle': 2}])
        sage: th0, Om, om = var('theta0 Omega omega')
        sage: point = OperatingPoint('turning', {th: th0}, {var('dpsi'): Om, var('dphi'): om})
        sage: sols = steady_motions(S, point, [om], positive=[m, r, A, C, g]); sols
        1 steady motion 'turning' in omega
        sage: s, = sols; s.conditions()
        [cos(theta0) != 0, Omega != 0]
        sage: bool(s.values()[om] == -(g*m*r + (m*r^2 - A + C)*Om^2*cos(th0))*sin(th0)
        ....:                           / ((m*r^2 + C)*Om*cos(th0)))
        True
        sage: s.point() == {th: th0, var('dpsi'): Om, var('dphi'): s.values()[om]}
        True

    Upright, the disk spinning at the rate `W` runs straight; it is stable
    in first approximation iff `C(C + mr^2)W^2 > mgrA` (Routh, *Advanced
    Rigid Dynamics*, art. 244)::

        sage: W = var('W')
        sage: upright = OperatingPoint('upright', {th: 0}, {var('dpsi'): Om, var('dphi'): W})
        sage: s, = steady_motions(S, upright, [Om], positive=[m, r, A, C, g],
        ....:                     coordinates=[th, psi]); s
        Steady motion 'upright' {theta: 0, dpsi: 0, dphi: W}
        sage: for case in s.stability().cases(): print(case.verdict(), case.region())
        stable in first approximation [[C*W^2*m*r^2 + C^2*W^2 - A*g*m*r > 0]]
        unstable [[C*W^2*m*r^2 + C^2*W^2 - A*g*m*r < 0]]
    """
    conditions = [e for e in steady_motion_conditions(system, point, speeds).values()
                  if not e.is_zero()]
    positive = symbol_arguments(positive, 'positive', error=AnalysisError)
    found = solve_exactly(conditions, solve_for, positive=positive)
    point = split_point(point, *_coordinates_and_velocities(system))
    return SteadyMotions(point, found, [SteadyMotionSolution(system, point, s, positive,
                                                             coordinates, speeds)
                                        for s in found])


def _coordinates_and_velocities(system):
    record = system.equations_record() if hasattr(system, 'equations_record') else system
    return record.coordinates(), record.velocities()


class SteadyMotionSolution(MotionSolution):
    r"""
    One steady motion found by :func:`steady_motions`: the operating point
    with the values of the unknowns solved for. It answers :meth:`point`,
    :meth:`values`, :meth:`conditions` and :meth:`stability` as a
    stationary motion does (see :mod:`~sage_dynsym.analysis.motion_solution`).

    INPUT:

    - ``system`` -- the system (as for :func:`steady_motion_conditions`)
    - ``point`` -- the :class:`~sage_dynsym.analysis.operating_point.OperatingPoint`
      with the unknowns
    - ``solution`` -- the solution of its conditions, an
      :class:`~sage_dynsym.algebra.solving.AlgebraicSolution`
    - ``positive`` -- the parameters declared positive
    - ``coordinates``, ``speeds`` -- (optional) for the linearization, see
      :func:`steady_motions`

    EXAMPLES: see :func:`steady_motions`.
    """

    def __init__(self, system, point, solution, positive=(), coordinates=None, speeds=None):
        # built by steady_motions; checked for whoever builds one by hand
        model_argument(point, ['coordinates', 'at'], 'point', "an OperatingPoint",
                       AnalysisError, hint="steady motions come from steady_motions(system, point)")
        super().__init__(solution)
        self._system, self._point, self._positive = system, point, list(positive)
        self._coordinates = coordinates if coordinates is not None else \
            point.coordinates() if point.coordinates() is not None else list(point.at())
        self._speeds = speeds

    def _repr_(self):
        name = f" {self._point.name()!r}" if self._point.name() else ""
        conditions = self._solution.known_conditions()
        return f"Steady motion{name} {self.point()}" + (
            ", if " + " and ".join(map(str, conditions)) if conditions else "")

    def point(self):
        r"""
        The steady motion: the coordinates it fixes and the velocities it
        keeps, with the values solved for (a dict).

        EXAMPLES: see :func:`steady_motions`.
        """
        return {k: v for k, v in list(self.operating_point().at().items())
                + list(self.operating_point().velocities().items())}

    def operating_point(self):
        r"""
        The :class:`~sage_dynsym.analysis.operating_point.OperatingPoint`
        with the values solved for, for
        :func:`~sage_dynsym.analysis.linear.linearize`.

        EXAMPLES::

            sage: from sage_dynsym.analysis.motion import SecondOrderEquations
            sage: from sage_dynsym.analysis.operating_point import OperatingPoint
            sage: from sage_dynsym.analysis.steady_solutions import steady_motions
            sage: x, th, dx, dth, ddx, ddth, m, I, k, a = var('x theta dx dtheta ddx ddtheta m I k a')
            sage: E = SecondOrderEquations([m*ddx, I*ddth + k*(th - a)], [x, th], [dx, dth],
            ....:                          [ddx, ddth])
            sage: s, = steady_motions(E, OperatingPoint('p', {th: var('c')}, {dx: 1}), ['c'])
            sage: s.operating_point()
            Operating point 'p': theta = a, dx = 1
        """
        evaluate = self._solution.evaluate
        return OperatingPoint(self._point.name(),
                              {k: evaluate(v) for k, v in self._point.at().items()},
                              {k: evaluate(v) for k, v in self._point.velocities().items()},
                              self._point.coordinates())

    def linear_system(self):
        r"""
        The linearization about the steady motion (a
        :class:`~sage_dynsym.analysis.linear.LinearSystem`, see
        :func:`steady_linearization`).

        EXAMPLES: see :meth:`stability`.
        """
        if not self.is_explicit():
            raise AnalysisError("the steady motion is given implicitly by the equations "
                                f"{self.equations()}; its linearization needs explicit values",
                                entry="stability")
        system = self._system
        record = system.equations_record() if hasattr(system, 'equations_record') else system
        motion = steady_linearization(record, self.operating_point(), self._coordinates,
                                      self._speeds)
        return LinearSystem(motion.coordinates(), M=motion.M(), S=motion.S(), W=motion.W(),
                            steady_motion=motion)

    def stability(self, positive=None):
        r"""
        The stability of the steady motion in first approximation: the
        roots of the characteristic polynomial of its linearization in the
        coordinates that enter it and in all the velocities. A coordinate
        entering only through its velocity (a heading) drifts along
        neighbouring steady motions: it is followed by its velocity alone,
        so stability is meant with respect to the other coordinates and the
        velocities (Neimark and Fufaev, ch. III).

        OUTPUT: a :class:`~sage_dynsym.analysis.verdict.StabilityVerdict`
        (``'asymptotically stable'``, ``'unstable'``, ``'stable in first
        approximation'``, ``'undecided'`` or ``'depends on the
        parameters'``)

        EXAMPLES: a block sliding at unit speed while a torsion spring holds
        its angle: stable in first approximation for a positive stiffness::

            sage: from sage_dynsym.analysis.motion import SecondOrderEquations
            sage: from sage_dynsym.analysis.operating_point import OperatingPoint
            sage: from sage_dynsym.analysis.steady_solutions import steady_motions
            sage: x, th, dx, dth, ddx, ddth, m, I, k, a = var('x theta dx dtheta ddx ddtheta m I k a')
            sage: E = SecondOrderEquations([m*ddx, I*ddth + k*(th - a)], [x, th], [dx, dth],
            ....:                          [ddx, ddth])
            sage: s, = steady_motions(E, OperatingPoint('p', {th: var('c')}, {dx: 1}), ['c'],
            ....:                     positive=[m, I])
            sage: s.values(), s.linear_system().W()
            ({c: a}, [k])
            sage: for case in s.stability().cases(): print(case.verdict(), case.region())
            stable in first approximation [[k > 0]]
            unstable [[k < 0]]
            sage: s.stability(positive=[m, I, k]).verdict()
            'stable in first approximation'

        TESTS::

            sage: steady_motions(E, OperatingPoint('p', {th: var('c')}, {dx: 1}), ['c'],
            ....:                positive=[m, I])[0].stability(positive=['a b'])
            Traceback (most recent call last):
            ...
            AnalysisError: positive: expected symbols or their names, got 'a b'
        """
        positive = self._positive if positive is None else \
            symbol_arguments(positive, 'positive', error=AnalysisError)
        existence = simplify_conjunction(self.conditions(), positive) or []
        lin = _followed_by_velocities(self.linear_system())
        # the one stability service, taken where the motion exists; a linear
        # system that is stable (not asymptotically) leaves the nonlinear
        # steady motion in the critical case: stable in first approximation
        cases = lin.stability(positive=positive).cases()
        marginal = 'stable in first approximation'
        parts = [(marginal if c.verdict() == 'stable' else c.verdict(), c.region())
                 for c in cases]
        reasons = {c.verdict(): c.reason() for c in cases}
        reasons.setdefault(marginal, reasons.pop('stable', None))
        reasons.setdefault('undecided', "the first approximation does not decide (critical case)")
        order = ['asymptotically stable', marginal, 'undecided', 'unstable']
        parts.sort(key=lambda part: order.index(part[0]))
        return verdict_from_parts(parts, reasons, {}, positive, domain=[existence],
                                  rest='undecided')


def _followed_by_velocities(lin):
    # M z'' + S z' + W z = 0 as a first-order system in the coordinates that
    # enter W and all the velocities: a coordinate absent from W (its column
    # zero) only drifts, its zero root is not a perturbation of the motion
    M, S, W = lin.M(), lin.S(), lin.W()
    z = lin.variables()
    n = len(z)
    kept = [j for j in range(n) if not W.column(j).is_zero()]
    if len(kept) == n:
        return lin
    p = len(kept)
    B = block_diagonal_matrix(identity_matrix(SR, p), M)
    J = matrix(SR, p + n, p + n)
    for a, j in enumerate(kept):
        J[a, p + j] = 1
        for i in range(n):
            J[p + i, a] = -W[i, j]
    J.set_block(p, p, -S)
    return LinearSystem([z[j] for j in kept] + [velocity(v) for v in z], J=J, B=B)


class SteadyMotions(SolutionList):
    r"""
    The steady motions found by :func:`steady_motions` (iterable): their
    :class:`SteadyMotionSolution` objects.

    INPUT:

    - ``point`` -- the operating point with the unknowns
    - ``solutions`` -- the solution set of its conditions, a
      :class:`~sage_dynsym.algebra.solving.SolutionSet`
    - ``motions`` -- the :class:`SteadyMotionSolution` objects

    EXAMPLES: see :func:`steady_motions`. No steady motion::

        sage: from sage_dynsym.analysis.motion import SecondOrderEquations
        sage: from sage_dynsym.analysis.operating_point import OperatingPoint
        sage: from sage_dynsym.analysis.steady_solutions import steady_motions
        sage: x, dx, ddx, F = var('x dx ddx F')
        sage: S = steady_motions(SecondOrderEquations([ddx - F^2 - 1], [x], [dx], [ddx]),
        ....:                    OperatingPoint('p', {}, {dx: 1}), [F]); S
        No steady motions 'p' in F (for generic parameter values)
        sage: S.is_empty(), S.is_complete(), len(S)
        (True, True, 0)
    """

    def __init__(self, point, solutions, motions):
        model_argument(point, ['coordinates', 'at'], 'point', "an OperatingPoint",
                       AnalysisError, hint="steady motions come from steady_motions(system, point)")
        if isinstance(motions, (str, bytes)) or not hasattr(motions, '__iter__'):
            raise AnalysisError(f"motions: expected the steady motions found, got {motions!r}")
        SolutionList.__init__(self, motions)
        self._point, self._set = point, solutions

    def _repr_(self):
        name = f" {self._point.name()!r}" if self._point.name() else ""
        unknowns = ", ".join(map(str, self._set.translation().unknowns()))
        n = len(self._solutions)
        if not n:
            return f"No steady motions{name} in {unknowns} (for generic parameter values)"
        return f"{n} steady motion{'s' if n != 1 else ''}{name} in {unknowns}"

    def is_complete(self):
        r"""Whether the list is complete (``True``: the solution is exact).

        EXAMPLES: see :class:`SteadyMotions`.
        """
        return self._set.is_complete()

    def is_empty(self):
        r"""Whether there is no steady motion of the form asked for.

        EXAMPLES: see :class:`SteadyMotions`.
        """
        return not self._solutions
