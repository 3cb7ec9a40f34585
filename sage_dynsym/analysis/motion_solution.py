r"""
Solved motions: one interface for stationary and steady motions

A stationary motion (:func:`~sage_dynsym.analysis.stationary.stationary_motions`,
:func:`~sage_dynsym.analysis.stationary.stationary_solutions`) and a steady
motion (:func:`~sage_dynsym.analysis.steady_solutions.steady_motions`) are both real
solutions of equations solved exactly
(:func:`~sage_dynsym.algebra.solving.solve_exactly`), and both answer the
same questions with the same meaning:

- :meth:`~MotionSolution.point` -- where the motion is: a dict over the
  state quantities it fixes (coordinates or momenta, and for a steady
  motion the velocities it keeps), with the solution's values in them;
- :meth:`~MotionSolution.values` -- the values of every unknown solved for
  (a dict; an unknown the solution leaves free maps to itself);
- :meth:`~MotionSolution.conditions` -- the conditions on the parameters
  for the motion to exist and be real;
- :meth:`~MotionSolution.stability` -- a
  :class:`~sage_dynsym.analysis.verdict.StabilityVerdict`.

:class:`MotionSolution` is their common base; their verdicts come from the
one stability service,
:meth:`LinearSystem.stability <sage_dynsym.analysis.linear.LinearSystem.stability>`.

EXAMPLES: the conical motions of a spherical pendulum and the upright
rolling of a disk, through the same four calls::

    sage: from sage_dynsym import load, MechanicalSystem, RigidBody, UniformGravity
    sage: from sage_dynsym.analysis import stationary_motions, steady_motions, OperatingPoint
    sage: R = load('examples/spherical_pendulum.yaml').lagrangian().routh([var('psi')])
    sage: conical = stationary_motions(R, solve_for=R.momenta(), positive=var('m l g'))[0]
    sage: x, y, psi, th, phi, m, r, A, C, g, W, Om = var('x y psi theta phi m r A C g W Omega')
    sage: frame = RigidBody('frame', joint=[x, y, 0], rotations=[(3, psi), (1, th)])
    sage: disk = RigidBody('disk', parent='frame', joint=[0, 0, r], rotations=[(2, phi)],
    ....:                  mass=m, inertia=diagonal_matrix([A, C, A]))
    sage: S = MechanicalSystem([frame, disk], [x, y, psi, th, phi],
    ....:                      force_function=UniformGravity([0, 0, -g]),
    ....:                      rolling=[{'body': 'disk', 'radius': r, 'axle': 2}])
    sage: upright = OperatingPoint('upright', {th: 0}, {var('dpsi'): Om, var('dphi'): W},
    ....:                          coordinates=[th, psi])
    sage: rolling = steady_motions(S, upright, [Om], positive=[m, r, A, C, g])[0]
    sage: for s in (conical, rolling):
    ....:     print(s.point(), s.values(), s.conditions(), s.stability().verdict())
    {p_psi: l*m*sqrt(-g*l/cos(theta))*sin(theta)^2} {p_psi: l*m*sqrt(-g*l/cos(theta))*sin(theta)^2} [cos(theta) < 0, sin(theta) != 0] stable
    {theta: 0, dpsi: 0, dphi: W} {Omega: 0} [] depends on the parameters
"""
from sage.structure.sage_object import SageObject

__all__ = ['MotionSolution']


class MotionSolution(SageObject):
    r"""
    A motion found by solving its equations exactly: the common interface
    of :class:`~sage_dynsym.analysis.stationary.StationarySolution` and
    :class:`~sage_dynsym.analysis.steady_solutions.SteadyMotionSolution` (see the
    module documentation). Subclasses give :meth:`point` and
    :meth:`stability`.

    INPUT:

    - ``solution`` -- the solution of the equations, an
      :class:`~sage_dynsym.algebra.solving.AlgebraicSolution`

    EXAMPLES: see the module documentation.
    """

    def __init__(self, solution):
        self._solution = solution

    def point(self):
        r"""
        Where the motion is: a dict over the state quantities it fixes
        (coordinates, or momenta, and for a steady motion the velocities it
        keeps), with the solution's values.

        EXAMPLES: see the module documentation.

        TESTS::

            sage: from sage_dynsym.analysis.motion_solution import MotionSolution
            sage: MotionSolution(None).point()
            Traceback (most recent call last):
            ...
            NotImplementedError: a MotionSolution gives point() in its subclasses
        """
        raise NotImplementedError("a MotionSolution gives point() in its subclasses")

    def stability(self, positive=None):
        r"""
        The stability verdict of the motion (a
        :class:`~sage_dynsym.analysis.verdict.StabilityVerdict`), with
        ``positive`` the parameters declared positive (default: those given
        when solving).

        EXAMPLES: see the module documentation.

        TESTS::

            sage: from sage_dynsym.analysis.motion_solution import MotionSolution
            sage: MotionSolution(None).stability()
            Traceback (most recent call last):
            ...
            NotImplementedError: a MotionSolution gives stability() in its subclasses
        """
        raise NotImplementedError("a MotionSolution gives stability() in its subclasses")

    def values(self):
        r"""
        The values of every unknown solved for, a dict; an unknown the
        solution leaves free maps to itself.

        EXAMPLES::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: x, y, a = var('x y a')
            sage: stationary_solutions([(x^2 + a*y^2)/2, x^2 + y^2], [x, y])[1].values()
            {x: x, y: 0, lambda1: -1/2}
        """
        return self._solution.values()

    def conditions(self):
        r"""
        Conditions on the parameters (relationals) for this solution to
        exist and be real; ``[]`` when it exists for all admissible values.

        EXAMPLES: a bead on a hoop turning about its vertical diameter::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: th, m, R, w, g = var('theta m R w g')
            sage: W = -m*R^2*w^2*sin(th)^2/2 - m*g*R*cos(th)
            sage: sols = stationary_solutions([W], [th], positive=[m, R, w, g])
            sage: [(s.point(), s.conditions()) for s in sols]
            [({theta: 0}, []),
             ({theta: pi}, []),
             ({theta: arccos(g/(R*w^2))}, [R*w^2 - g > 0]),
             ({theta: -arccos(g/(R*w^2))}, [R*w^2 - g > 0])]
        """
        return self._solution.conditions()

    def is_reality_decided(self):
        r"""
        Whether the conditions under which the solution is real are known
        (``False`` only for an implicit family with parameters that neither
        a parametrization nor quantifier elimination within its budget
        decided: then :meth:`conditions` is the region where it may be
        real, and the cases of its stability verdict hold at its real
        points there).

        EXAMPLES::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: x, y, a = var('x y a')
            sage: s = stationary_solutions([(x^2 + a*y^2)/2, x^2 + y^2], [x, y])[1]
            sage: s.is_reality_decided()
            True
        """
        return self._solution.is_reality_decided()

    def equations(self):
        r"""
        The relations (expressions ``== 0``) that remain between the
        unknowns left free; empty for an explicit solution.

        EXAMPLES::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: x, y = var('x y')
            sage: s = stationary_solutions([(x^2 + y^2 - 1)^2], [x, y])[1]
            sage: s.dimension(), s.equations()
            (1, [x^2 + y^2 - 1])
        """
        return self._solution.equations()

    def dimension(self):
        r"""
        `0` for an isolated solution, `k > 0` for a `k`-parameter family
        (multipliers are not counted).

        EXAMPLES::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: x, y = var('x y')
            sage: [s.dimension() for s in stationary_solutions([(x^2 + y^2 - 1)^2], [x, y])]
            [0, 1]
        """
        return self._solution.dimension()

    def is_explicit(self):
        r"""Whether every unknown is given explicitly (or left free).

        EXAMPLES::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: x = var('x')
            sage: stationary_solutions([x^6/6 - x^2/2 - x], [x])[0].is_explicit()
            False
        """
        return self._solution.is_explicit()

    def real_points(self):
        r"""
        The real points of an implicit solution without parameters, exact
        (dicts of real algebraic numbers); ``None`` otherwise.

        EXAMPLES::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: x = var('x')
            sage: s = stationary_solutions([x^6/6 - x^2/2 - x], [x])[0]
            sage: s.real_points()
            [{x: 1.167303978261419?}]
        """
        return self._solution.real_points()

    def solution(self):
        r"""The underlying :class:`~sage_dynsym.algebra.solving.AlgebraicSolution`.

        EXAMPLES::

            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: x = var('x')
            sage: stationary_solutions([x^2], [x])[0].solution()
            Solution {x: 0} (dimension 0)
        """
        return self._solution
