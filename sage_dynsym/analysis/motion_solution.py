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

:class:`MotionSolution` is their common base; the first-approximation part
of a verdict is built here for both (:func:`first_approximation_cases`,
:func:`combined_verdict`).

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
from sage.symbolic.ring import SR

from ..algebra.conditions import positive_conditions, positive_conditions_all, \
    simplify_conjunction
from ..errors import AnalysisError
from .verdict import StabilityVerdict


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


def first_approximation_regions(lin, positive):
    r"""
    The regions (lists of alternatives) of asymptotic stability and of
    instability of the linear system ``lin``, from its characteristic
    polynomial: the Liénard--Chipart conditions, and a coefficient of the
    opposite sign to the leading one (a root with positive real part).

    OUTPUT: a pair ``(asymptotic, unstable)``

    EXAMPLES::

        sage: from sage_dynsym.analysis.linear import LinearSystem
        sage: from sage_dynsym.analysis.motion_solution import first_approximation_regions
        sage: c, k = var('c k')
        sage: first_approximation_regions(LinearSystem([var('x')], M=[[1]], S=[[c]], W=[[k]]), [])
        ([[k > 0, c > 0]], [[c < 0], [k < 0]])
    """
    from .hurwitz import lienard_chipart_conditions
    from ..algebra.translation import Translation
    lam = SR.var('lambda_')
    p = lin.characteristic_polynomial(lam, positive=positive)
    if not SR(p).has(lam):          # no dynamics left (e.g. a zero Lagrangian)
        return [], []
    T = Translation([], [], extra=[p])
    f = T.flat_ring()(T.fraction(p))
    gen = T.flat_ring()(T.fraction(lam))
    coefficients = [T.symbolic(f.coefficient({gen: k})) if k else T.symbolic(f.subs({gen: 0}))
                    for k in range(f.degree(gen), -1, -1)]
    zero_roots = 0
    while len(coefficients) > 1 and coefficients[-1].is_zero():
        coefficients.pop()
        zero_roots += 1
    a0 = coefficients[0]
    even = all(c.is_zero() for c in coefficients[1::2])
    tested = coefficients[0::2] if even else coefficients
    unstable = []
    for c in tested[1:]:
        cond = positive_conditions(-a0 * c, positive)
        if cond is not None and cond not in unstable:
            unstable.append(cond)
    asymptotic = []
    if not zero_roots and not even:
        reduced = sum(c * lam ** k for k, c in enumerate(reversed(coefficients)))
        lc = lienard_chipart_conditions((a0 * reduced).expand(), lam, positive=positive)
        cond = positive_conditions_all(lc, positive) if lc else []
        if cond is not None:
            asymptotic.append(cond)
    return asymptotic, unstable


def marginal_region(lin, positive):
    r"""
    The region where ``lin`` is stable in first approximation, not
    asymptotically (:mod:`.spectrum`); ``[]`` if nowhere or not decided.

    EXAMPLES::

        sage: from sage_dynsym.analysis.linear import LinearSystem
        sage: from sage_dynsym.analysis.motion_solution import marginal_region
        sage: marginal_region(LinearSystem([var('x')], M=[[1]], S=[[0]], W=[[var('k')]]), [])
        [[k > 0]]
    """
    from .spectrum import spectrum_regions
    lam = SR.symbol()
    p = lin.characteristic_polynomial(lam, positive=positive)
    if not SR(p).has(lam):
        return []
    try:
        return spectrum_regions(p, lam, positive, matrix=lin.jacobian()).marginal() or []
    except (AnalysisError, ArithmeticError, ValueError, TypeError, ZeroDivisionError):
        return []


def first_approximation_cases(lin, existence, positive, marginal=True):
    r"""
    The verdicts the first approximation ``lin`` gives where the motion
    exists (``existence``, a conjunction): asymptotically stable and
    unstable (Lyapunov's theorems), and, when ``marginal``, stable in first
    approximation where the roots on the imaginary axis are simple.

    OUTPUT: a list of :class:`~sage_dynsym.analysis.verdict.StabilityVerdict`

    EXAMPLES::

        sage: from sage_dynsym.analysis.linear import LinearSystem
        sage: from sage_dynsym.analysis.motion_solution import first_approximation_cases
        sage: k = var('k')
        sage: lin = LinearSystem([var('x')], M=[[1]], S=[[0]], W=[[k]])
        sage: [(v.verdict(), v.region()) for v in first_approximation_cases(lin, [], [])]
        [('unstable', [[k < 0]]), ('stable in first approximation', [[k > 0]])]
    """
    def where(alternatives):
        return [a for a in (simplify_conjunction(existence + alt, positive)
                            for alt in alternatives) if a is not None]

    cases = []
    asymptotic, unstable = first_approximation_regions(lin, positive)
    for verdict, alts, why in (
            ('asymptotically stable', asymptotic,
             "all roots of the characteristic polynomial have negative real "
             "parts (Liénard-Chipart)"),
            ('unstable', unstable, "the characteristic polynomial has a root "
             "with positive real part (Lyapunov's theorem on the first "
             "approximation)")):
        alts = where(alts)
        if alts:
            cases.append(StabilityVerdict(verdict, why, method='first approximation',
                                          region=alts))
    if marginal:
        # where the other tests do not decide: roots simple on the imaginary axis
        alts = where(marginal_region(lin, positive))
        if alts:
            cases.append(StabilityVerdict(
                'stable in first approximation', "the roots of the characteristic "
                "polynomial on the imaginary axis are simple (or semisimple), the "
                "others have negative real parts: the linearized system is stable; "
                "the nonlinear terms decide (critical case)",
                method='first approximation', region=alts))
    return cases


def combined_verdict(cases, existence, undecided="neither the second variation nor the "
                     "first approximation decides (critical case)"):
    r"""
    One verdict from the ``cases`` found: the case that holds wherever the
    motion exists (``existence``), ``'undecided'`` without cases (with the
    reason ``undecided``), else ``'depends on the parameters'`` with the
    cases.

    EXAMPLES::

        sage: from sage_dynsym.analysis.motion_solution import combined_verdict
        sage: from sage_dynsym.analysis.verdict import StabilityVerdict
        sage: combined_verdict([StabilityVerdict('stable', 'why', region=[[]])], []).verdict()
        'stable'
        sage: combined_verdict([], []).verdict()
        'undecided'
    """
    for case in cases:
        if any(set(map(str, alt)) <= set(map(str, existence)) for alt in case.region()):
            return case
    if not cases:
        return StabilityVerdict('undecided', undecided, region=[[]])
    return StabilityVerdict('depends on the parameters', "see cases()", cases=cases)
