r"""
Lie--Poisson systems

A :class:`LiePoissonSystem` is a Hamiltonian `H(x)` on a Poisson
structure `J(x)` (:mod:`.algebras`): the equations are

.. MATH::

    \dot x_i = \{x_i, H\} = \sum_j J_{ij}(x)\, \frac{\partial H}{\partial x_j},

with the minus Lie--Poisson bracket `\{x_i, x_j\} = -c_{ij}^k x_k` of the
body frame. For the rigid body this is the reduction of the canonical
bracket of the Euler angles and their momenta (a motion of the Lagrange
equations in Euler angles, mapped to `M = I\omega` and the vertical
`\gamma` in the body's axes, is a motion of these equations: see
:func:`~sage_dynsym.lie.builders.euler_poisson`). On `e(3)`:

.. MATH::

    \dot M = M\times\frac{\partial H}{\partial M} + \gamma\times
    \frac{\partial H}{\partial\gamma},\qquad
    \dot\gamma = \gamma\times\frac{\partial H}{\partial M}.

EXAMPLES:

The heavy top (Euler--Poisson equations), centre of mass on the third
axis at the height `z_0` above the fixed point, `\gamma` the upward
vertical::

    sage: from sage_dynsym.lie.system import LiePoissonSystem
    sage: M1, M2, M3, g1, g2, g3 = var('M1 M2 M3 gamma1 gamma2 gamma3')
    sage: A, C, m, g, z0 = var('A C m g z0')
    sage: H = (M1^2 + M2^2)/(2*A) + M3^2/(2*C) + m*g*z0*g3
    sage: S = LiePoissonSystem('e3', H); S
    Lie-Poisson system on e3 (M1, M2, M3, gamma1, gamma2, gamma3) with H = g*gamma3*m*z0 + 1/2*M3^2/C + 1/2*(M1^2 + M2^2)/A
    sage: S.equations()
    [g*gamma2*m*z0 + (A - C)*M2*M3/(A*C),
     -g*gamma1*m*z0 - (A - C)*M1*M3/(A*C),
     0,
     M3*gamma2/C - M2*gamma3/A,
     -M3*gamma1/C + M1*gamma3/A,
     M2*gamma1/A - M1*gamma2/A]
    sage: S.casimirs()
    [M1*gamma1 + M2*gamma2 + M3*gamma3, gamma1^2 + gamma2^2 + gamma3^2]
    sage: S.polynomial_integrals(2, new_only=True)       # Lagrange's case
    [M3]
    sage: S.is_integral(M3), S.is_integral(M1)
    (True, False)

The sleeping top, `M = (0, 0, M_3)`, `\gamma = (0, 0, 1)`: stable if
`M_3^2 > 4 A m g z_0` (Maievski's condition; Arnold, *Mathematical
Methods*, §30)::

    sage: sols = S.stationary_solutions([M3], levels=[None, 1, None],
    ....:                               positive=[A, C, m, g, z0])
    sage: s = next(s for s in sols if s.point()[g3] == 1 and s.point()[M1] == 0); s.point()
    {M1: 0, M2: 0, M3: M3, gamma1: 0, gamma2: 0, gamma3: 1}
    sage: s.stability_region(positive=[A, C, m, g, z0])
    [[4*A*g*m*z0 - M3^2 < 0]]

REFERENCES:

- V. I. Arnold, *Mathematical Methods of Classical Mechanics*, 2nd ed.,
  Springer, 1989, §§28--30 and Appendix 2.
- D. R. Merkin, *Introduction to the Theory of Stability*, Springer, 1997,
  ch. 5.
"""
import re

from sage.misc.cachefunc import cached_method
from sage.misc.latex import latex
from sage.symbolic.ring import SR

from ..analysis import linearize as _linearize
from ..analysis.motion import FirstOrderEquations
from ..analysis.stationary import stationary_solutions as _stationary_solutions
from ..analysis.census import register_census
from ..dynamics.model import Model
from ..errors import ModelError, AnalysisError, brief
from ..arguments import expression_list, symbol_arguments
from ..symbols import exact_decimals
from ..numerics.methods import NumericalMethods
from ..numerics.values import check_model_values
from .algebras import NAMED, PoissonStructure, default_names, poisson_structure
from .format import LiePoissonFormat
from .report import report_title, report_sections
from .integrals import (casimirs as _casimirs, polynomial_integrals as _polynomial_integrals,
                        MAX_DEGREE, MAX_BASIS, basis_size, check_degree)

__all__ = ['LiePoissonSystem']

#: Names that look like coordinates: a Hamiltonian using one that is not a
#: variable of the system is refused unless it is declared a parameter.
_COORDINATE_LIKE = re.compile(r'(M|gamma|p|P|L)\d+')
_DEFAULT_NAMES = {n for name in NAMED for n in default_names(name)}


class LiePoissonSystem(LiePoissonFormat, Model, NumericalMethods):
    r"""
    A Hamiltonian system `\dot x = J(x)\nabla H` on a Lie algebra (or any
    Poisson structure).

    INPUT:

    - ``algebra`` -- ``'so3'``, ``'e3'``, ``'so4'``, ``'so31'``, ``'e4'``
      (:func:`~sage_dynsym.lie.algebras.lie_algebra`), a Poisson matrix
      `J_{ij} = \{x_i, x_j\}`, structure constants, or a
      :class:`~sage_dynsym.lie.algebras.PoissonStructure`; a matrix or
      structure constants are checked for skew-symmetry and the Jacobi
      identity
    - ``hamiltonian`` -- `H`, an expression in the variables and parameters
    - ``variables`` -- (optional for a named algebra) the coordinates: as
      many symbols or names, or one prefix per block (``['M', 'p']`` on
      ``'e3'``)
    - ``parameters`` -- (optional) the parameters; if given, `H` and `J`
      may use no other symbols. By default every other symbol is a
      parameter, except names that look like coordinates (``gamma1``,
      ``M3``, ``p2``, ...), which must then be declared
    - ``name`` -- (optional) a name
    - ``positive`` -- (optional) parameters known to be positive (masses,
      moments of inertia): the default of the analysis methods
    - ``reduction`` -- (optional) a dict giving each variable in terms of
      the coordinates and velocities of a mechanical model (set by the
      builders of :mod:`.builders`)

    EXAMPLES: see the module documentation. A user's algebra, the
    two-dimensional non-abelian one `[e_1, e_2] = e_2`::

        sage: from sage_dynsym.lie.system import LiePoissonSystem
        sage: x, y = var('x y')
        sage: S = LiePoissonSystem({(x, y): {y: 1}}, x*y, variables=[x, y])
        sage: S.poisson_matrix(), S.equations()
        (
        [ 0 -y]
        [ y  0], [-x*y, y^2]
        )
        sage: TestSuite(S).run()

    TESTS::

        sage: M1, M2, M3, g1 = var('M1 M2 M3 gamma1')
        sage: LiePoissonSystem('so3', M1^2 + g1)
        Traceback (most recent call last):
        ...
        ModelError: hamiltonian: the Hamiltonian uses gamma1, which is not a variable of so3 (M1, M2, M3); declare it in parameters= if it is a constant
        sage: LiePoissonSystem('so3', M1^2 + var('k')*M2, parameters=[])
        Traceback (most recent call last):
        ...
        ModelError: hamiltonian: undeclared symbol k: the Hamiltonian may use the variables M1, M2, M3 and the parameters (none declared)
        sage: LiePoissonSystem('so5', M1^2)
        Traceback (most recent call last):
        ...
        ModelError: algebra: unknown Lie algebra 'so5'; the named algebras are so3, e3, so4, so31, e4 (or give a Poisson matrix or structure constants)
        sage: LiePoissonSystem('e3', M1^2, variables=[M1, M2, M3])
        Traceback (most recent call last):
        ...
        ModelError: variables: e3 has 6 coordinates (M1, M2, M3, gamma1, gamma2, gamma3) or 2 prefixes (e.g. ['M', 'gamma']), got 3 variables: ['M1', 'M2', 'M3']
        sage: LiePoissonSystem([[0, x], [-x, 0], [0, 0]], x, variables=[x, y])
        Traceback (most recent call last):
        ...
        ModelError: algebra: expected a square 2x2 matrix (one row and column per variable x, y), got 3 rows of lengths [2, 2, 2]
    """

    def __init__(self, algebra, hamiltonian, variables=None, parameters=None, name=None,
                 positive=(), reduction=None):
        self._structure = poisson_structure(algebra, variables)
        self._positive = symbol_arguments(positive, 'positive')
        self._reduction = None if reduction is None else dict(reduction)
        x = self._structure.variables()
        try:
            self._H = SR(hamiltonian)
        except (TypeError, ValueError) as err:
            raise ModelError(f"expected an expression, got {brief(hamiltonian)} ({err})",
                             entry="hamiltonian") from err
        self._name = name
        names = {str(v) for v in x}
        where = (f"{self._structure.name()} ({', '.join(_names_of(x))})"
                 if self._structure.name() else f"the system ({', '.join(_names_of(x))})")
        others = sorted({a for a in self._H.variables() if str(a) not in names}, key=str)
        if parameters is not None:
            self._parameters = symbol_arguments(parameters, 'parameters')
            declared = {str(a) for a in self._parameters}
            for a in others + self._structure.parameters():
                if str(a) not in declared:
                    what = "the Hamiltonian" if a in others else "the Poisson matrix"
                    raise ModelError(
                        f"undeclared symbol {a}: {what} may use the variables "
                        f"{', '.join(_names_of(x))} and the parameters "
                        f"{', '.join(sorted(declared)) or '(none declared)'}",
                        entry="hamiltonian" if a in others else "algebra")
        else:
            for a in others:
                if str(a) in _DEFAULT_NAMES or _COORDINATE_LIKE.fullmatch(str(a)):
                    raise ModelError(f"the Hamiltonian uses {a}, which is not a variable of "
                                     f"{where}; declare it in parameters= if it is a constant",
                                     entry="hamiltonian")
            self._parameters = sorted(set(others) | set(self._structure.parameters()),
                                      key=str)
        for a in self._positive:
            if str(a) not in {str(b) for b in self._parameters}:
                raise ModelError(f"{a} is declared positive but is not a parameter (the "
                                 f"parameters are {', '.join(map(str, self._parameters))})",
                                 entry="positive")

    # -- description ---------------------------------------------------------

    def _repr_(self):
        what = self._structure.name() or "a Poisson structure"
        name = f" '{self._name}'" if self._name else ""
        return (f"Lie-Poisson system{name} on {what} "
                f"({', '.join(map(str, self.variables()))}) with H = {self._H}")

    def _latex_(self):
        what = self._structure.name()
        where = r"\mathfrak{%s}" % what if what else r"\mathbb{R}^{%d}" % len(self.variables())
        return r"H = %s \text{ on } %s" % (latex(self._H), where)

    def report_title(self):
        r"""The heading of the system's report (see :mod:`~sage_dynsym.lie.report`).

        EXAMPLES::

            sage: from sage_dynsym.lie.system import LiePoissonSystem
            sage: LiePoissonSystem('so3', var('M1')^2/2).report_title()
            '== Lie-Poisson system on so3: variables M1, M2, M3 =='
        """
        return report_title(self)

    def report_sections(self):
        r"""The sections of the system's report (see :mod:`~sage_dynsym.lie.report`).

        EXAMPLES::

            sage: from sage_dynsym.lie.system import LiePoissonSystem
            sage: [s.key for s in LiePoissonSystem('so3', var('M1')^2/2).report_sections()]
            ['hamiltonian', 'equations', 'casimirs', 'integrals', 'stationary']
        """
        return report_sections(self)

    def name(self):
        r"""
        The name (or ``None``).

        EXAMPLES::

            sage: from sage_dynsym.lie.system import LiePoissonSystem
            sage: LiePoissonSystem('so3', var('M1')^2, name='top').name()
            'top'
        """
        return self._name

    def reduction(self):
        r"""
        The map from a mechanical model's coordinates and velocities to the
        variables (a dict), or ``None``; see
        :func:`~sage_dynsym.lie.builders.euler_poisson`.

        EXAMPLES::

            sage: from sage_dynsym.lie.system import LiePoissonSystem
            sage: LiePoissonSystem('so3', var('M1')^2).reduction() is None
            True
        """
        return None if self._reduction is None else dict(self._reduction)

    def structure(self):
        r"""
        The :class:`~sage_dynsym.lie.algebras.PoissonStructure`.

        EXAMPLES::

            sage: from sage_dynsym.lie.system import LiePoissonSystem
            sage: LiePoissonSystem('so3', var('M1')^2).structure()
            Lie-Poisson structure so3 on (M1, M2, M3)
        """
        return self._structure

    def variables(self):
        r"""
        The coordinates `x`, in the order of the equations.

        EXAMPLES::

            sage: from sage_dynsym.lie.system import LiePoissonSystem
            sage: LiePoissonSystem('e3', var('M1')^2, variables=['M', 'p']).variables()
            [M1, M2, M3, p1, p2, p3]
        """
        return self._structure.variables()

    def parameters(self):
        r"""
        The parameters (declared, or the other symbols of `H` and `J`).

        EXAMPLES::

            sage: from sage_dynsym.lie.system import LiePoissonSystem
            sage: LiePoissonSystem('so3', var('M1')^2/var('A')).parameters()
            [A]
        """
        return list(self._parameters)

    def positive_parameters(self):
        r"""
        The parameters declared positive.

        EXAMPLES::

            sage: from sage_dynsym.lie.system import LiePoissonSystem
            sage: A = var('A')
            sage: LiePoissonSystem('so3', var('M1')^2/A, positive=[A]).positive_parameters()
            [A]
        """
        return list(self._positive)

    def hamiltonian(self):
        r"""
        The Hamiltonian `H`.

        EXAMPLES::

            sage: from sage_dynsym.lie.system import LiePoissonSystem
            sage: LiePoissonSystem('so3', var('M1')^2/2).hamiltonian()
            1/2*M1^2
        """
        return self._H

    def poisson_matrix(self):
        r"""
        The Poisson matrix `J`, `J_{ij} = \{x_i, x_j\}`.

        EXAMPLES::

            sage: from sage_dynsym.lie.system import LiePoissonSystem
            sage: LiePoissonSystem('so3', var('M1')^2).poisson_matrix()
            [  0 -M3  M2]
            [ M3   0 -M1]
            [-M2  M1   0]
        """
        return self._structure.matrix()

    def poisson_bracket(self, F, G):
        r"""
        `\{F, G\} = \nabla F^T J \nabla G`.

        EXAMPLES::

            sage: from sage_dynsym.lie.system import LiePoissonSystem
            sage: M1, M2, M3 = var('M1 M2 M3')
            sage: S = LiePoissonSystem('so3', M1^2)
            sage: S.poisson_bracket(M1, M2), S.poisson_bracket(M1^2 + M2^2 + M3^2, M1)
            (-M3, 0)
        """
        return self._structure.bracket(F, G)

    @cached_method
    def equations(self):
        r"""
        The right-hand sides `\dot x_i = \{x_i, H\}`, in the order of
        :meth:`variables`.

        EXAMPLES: Euler's equations of the free rigid body::

            sage: from sage_dynsym.lie.system import LiePoissonSystem
            sage: M1, M2, M3 = var('M1 M2 M3'); A1, A2, A3 = var('A1 A2 A3')
            sage: S = LiePoissonSystem('so3', (M1^2/A1 + M2^2/A2 + M3^2/A3)/2)
            sage: S.equations()
            [(A2 - A3)*M2*M3/(A2*A3), -(A1 - A3)*M1*M3/(A1*A3), (A1 - A2)*M1*M2/(A1*A2)]
        """
        return self._structure.vector_field(self._H)

    def is_integral(self, F):
        r"""
        Whether `\{F, H\} = 0` identically.

        EXAMPLES::

            sage: from sage_dynsym.lie.system import LiePoissonSystem
            sage: M1, M2, M3 = var('M1 M2 M3')
            sage: S = LiePoissonSystem('so3', (M1^2 + M2^2)/2 + M3^2)
            sage: S.is_integral(M3), S.is_integral(M1), S.is_integral(sin(M3))
            (True, False, True)
        """
        return bool(SR(self.poisson_bracket(F, self._H)).is_zero())

    def casimirs(self, degree=4, max_degree=MAX_DEGREE, max_basis=MAX_BASIS):
        r"""
        The independent polynomial Casimirs of the structure up to
        ``degree``, computed from the Poisson matrix
        (:func:`~sage_dynsym.lie.integrals.casimirs`), by increasing degree;
        ``max_degree`` and ``max_basis`` bound the search (the degree, the
        number of unknown coefficients). Computed once per degree.

        EXAMPLES::

            sage: from sage_dynsym.lie.system import LiePoissonSystem
            sage: LiePoissonSystem('so31', var('M1')^2).casimirs()
            [M1^2 + M2^2 + M3^2 - p1^2 - p2^2 - p3^2, M1*p1 + M2*p2 + M3*p3]

        TESTS::

            sage: LiePoissonSystem('so3', var('M1')^2).casimirs(degree=[])
            Traceback (most recent call last):
            ...
            AnalysisError: casimirs: expected an integer, got [] (list)
        """
        degree = check_degree(degree, "casimirs", len(self.variables()), max_degree, max_basis)
        return list(self._casimirs(degree))

    def _test_casimirs(self, **options):
        r"""Run by ``TestSuite``: Casimirs (degree <= 2) commute with all, are integrals."""
        tester = self._tester(**options)
        for C in self.casimirs(degree=2):
            brackets = [SR(self.poisson_bracket(C, x)) for x in self.variables()]
            tester.assertTrue(all(b.is_zero() for b in brackets) and self.is_integral(C))

    @cached_method
    def _casimirs(self, degree):
        return _casimirs(self._structure, degree, parameters=self._parameters, max_degree=degree,
                         max_basis=basis_size(len(self.variables()), degree))

    def polynomial_integrals(self, degree, new_only=False, conditions=False, levels=None,
                             max_degree=MAX_DEGREE, max_basis=MAX_BASIS):
        r"""
        A basis of the polynomial first integrals of degree at most
        ``degree``, modulo constants (products of integrals count); see
        :func:`~sage_dynsym.lie.integrals.polynomial_integrals`.

        INPUT:

        - ``degree`` -- the largest degree
        - ``new_only`` -- (default: ``False``) only the integrals outside
          the algebra generated by `H`, the Casimirs and the integrals of
          lower degree
        - ``conditions`` -- (default: ``False``) also return the families
          of parameter values on which there are more integrals: a pair
          ``(basis, jumps)``, see
          :class:`~sage_dynsym.lie.integrals.IntegralJump`; only ``True``
          or ``False``
        - ``levels`` -- (optional) a dict ``{g: c}`` of Casimirs or
          integrals and their values: the integrals on that invariant
          level, modulo its ideal (:mod:`~sage_dynsym.lie.levels`)
          :class:`~sage_dynsym.lie.integrals.IntegralJump`
        - ``max_degree``, ``max_basis`` -- (default:
          :data:`~sage_dynsym.lie.integrals.MAX_DEGREE`,
          :data:`~sage_dynsym.lie.integrals.MAX_BASIS`) the limits of the
          search (the degree, the number of unknown coefficients), checked
          before it starts

        EXAMPLES: Kovalevskaya's case, `A = B = 2C`, the centre of mass in
        the equatorial plane at `(x_0, 0, 0)`: a new integral of degree 4,
        `16C^4\big[(p^2 - q^2 - c\gamma_1)^2 + (2pq - c\gamma_2)^2\big]`,
        `M = (2Cp, 2Cq, Cr)`, `c = mgx_0/C` (Kovalevskaya, Acta Math. 12
        (1889))::

            sage: from sage_dynsym.lie.system import LiePoissonSystem
            sage: M1, M2, M3, g1, g2, g3 = var('M1 M2 M3 gamma1 gamma2 gamma3')
            sage: C, m, g, x0 = var('C m g x0')
            sage: S = LiePoissonSystem('e3', (M1^2 + M2^2)/(4*C) + M3^2/(2*C) + m*g*x0*g1)
            sage: S.polynomial_integrals(3, new_only=True)
            []
            sage: K, = S.polynomial_integrals(4, new_only=True); K.factor()
            16*C^2*g^2*gamma1^2*m^2*x0^2 + 16*C^2*g^2*gamma2^2*m^2*x0^2 - 8*C*M1^2*g*gamma1*m*x0 + 8*C*M2^2*g*gamma1*m*x0 - 16*C*M1*M2*g*gamma2*m*x0 + M1^4 + 2*M1^2*M2^2 + M2^4
            sage: bool(K == (M1^2 - M2^2 - 4*C*m*g*x0*g1)^2 + (2*M1*M2 - 4*C*m*g*x0*g2)^2)
            True

        The Goryachev--Chaplygin case, `A = B = 4C`, has a cubic integral
        only on the level of the area integral `(M, \gamma) = 0`::

            sage: GC = LiePoissonSystem('e3', (M1^2 + M2^2 + 4*M3^2)/(8*C) + m*g*x0*g1)
            sage: GC.polynomial_integrals(3, new_only=True)
            []
            sage: GC.polynomial_integrals(3, new_only=True, levels={M1*g1 + M2*g2 + M3*g3: 0})
            [-4*C*M1*g*gamma3*m*x0 + M1^2*M3 + M2^2*M3]

        TESTS::

            sage: GC.polynomial_integrals(2, conditions='yes')
            Traceback (most recent call last):
            ...
            AnalysisError: polynomial_integrals: conditions must be True or False, got 'yes'
        """
        return _polynomial_integrals(self._structure, self._H, degree, new_only=new_only,
                                     conditions=conditions, parameters=self._parameters,
                                     levels=levels, max_degree=max_degree,
                                     max_basis=max_basis)

    def stationary_solutions(self, integrals=(), levels=None, positive=None, multipliers=None,
                             solve_for=None):
        r"""
        Stationary solutions by the Routh--Lyapunov method over the
        integrals `[H] + ` :meth:`casimirs` `+` ``integrals``, through
        :func:`~sage_dynsym.analysis.stationary.stationary_solutions` (with
        the equations, so that each solution's first approximation is
        available).

        INPUT:

        - ``integrals`` -- further first integrals (checked)
        - ``levels`` -- one entry per integral after `H` (Casimirs first):
          a prescribed value or ``None``
        - ``positive`` -- (default: :meth:`positive_parameters`) parameters
          declared positive
        - ``multipliers``, ``solve_for`` -- as for
          :func:`~sage_dynsym.analysis.stationary.stationary_solutions`

        EXAMPLES: permanent rotations of the Euler top on `e(3)` (no
        gravity), `\gamma` on the unit sphere, rotation about the first
        axis: stable when `A_1` is the largest or the smallest moment
        (Arnold, *Mathematical Methods*, §29)::

            sage: from sage_dynsym.lie.system import LiePoissonSystem
            sage: M1, M2, M3 = var('M1 M2 M3'); A1, A2, A3 = var('A1 A2 A3')
            sage: S = LiePoissonSystem('so3', (M1^2/A1 + M2^2/A2 + M3^2/A3)/2)
            sage: sols = S.stationary_solutions(positive=[A1, A2, A3])
            sage: [s.point() for s in sols]
            [{M1: 0, M2: 0, M3: 0}, {M1: M1, M2: 0, M3: 0}, {M1: 0, M2: M2, M3: 0}, {M1: 0, M2: 0, M3: M3}]
            sage: sols[1].stability_region()
            [[A1 - A2 > 0, A1 - A3 > 0, M1 != 0]]

        TESTS::

            sage: S.stationary_solutions(levels=[1, 2])
            Traceback (most recent call last):
            ...
            AnalysisError: stationary_solutions: levels has 2 entries; it needs one per integral after H (the Casimirs M1^2 + M2^2 + M3^2, then the integrals given): 1
        """
        integrals = expression_list(integrals, "integrals", AnalysisError,
                                    expected="a list of integrals (symbolic expressions)")
        all_integrals = [self._H] + self.casimirs() + integrals
        if levels is not None and len(levels) != len(all_integrals) - 1:
            raise AnalysisError(
                f"levels has {len(levels)} entries; it needs one per integral after H (the "
                f"Casimirs {', '.join(map(str, self.casimirs())) or '(none)'}, then the "
                f"integrals given): {len(all_integrals) - 1}", entry="stationary_solutions")
        positive = self._positive if positive is None else positive
        return _stationary_solutions(all_integrals, self.variables(), equations=self.equations(),
                                     multipliers=multipliers, levels=levels, positive=positive,
                                     solve_for=solve_for)

    def equilibrium_census(self, parameters, levels=None, positive=None, values=None,
                           executor=None):
        r"""
        The census of the relative equilibria on the levels of the Casimirs
        over one or two parameters (symbols of `H` or of the ``levels``):
        the bifurcation set, the cells, and in each the numbers of isolated
        relative equilibria, of stable ones (energy--Casimir; in first
        approximation on the leaf) and the families; see
        :func:`~sage_dynsym.analysis.leaf_census.leaf_census`.

        INPUT:

        - ``parameters`` -- one or two symbols
        - ``levels`` -- one level per Casimir, in the order of
          :meth:`casimirs` (as for :meth:`stationary_solutions`): numbers
          or expressions in the parameters
        - ``positive`` -- (default: :meth:`positive_parameters`) symbols
          declared positive; a parameter declared positive is censused over
          its positive values
        - ``values`` -- values of the other parameters
        - ``executor`` -- as for
          :func:`~sage_dynsym.analysis.census.equilibrium_census`

        OUTPUT: a :class:`~sage_dynsym.analysis.census.Census`

        EXAMPLES: the free rigid body on the sphere `|M|^2 = 1`, with the
        moments of inertia `1, a, 3`: the rotations about the largest and
        the smallest axes are stable whatever the order (Euler; Arnold,
        *Mathematical Methods*, §29); the bifurcations are at `a = 1` and
        `a = 3`, where two moments are equal and a circle of relative
        equilibria replaces four of them (at such a value ``count_at``
        counts the isolated ones only)::

            sage: from sage_dynsym.lie.system import LiePoissonSystem
            sage: M1, M2, M3, a, c = var('M1 M2 M3 a c')
            sage: S = LiePoissonSystem('so3', (M1^2 + M2^2/a + M3^2/3)/2, positive=[a])
            sage: S.equilibrium_census([a], levels=[1])
            Census of the relative equilibria on the levels M1^2 + M2^2 + M3^2 = 1 over a > 0: bifurcation set [a - 1, a - 3]
              0 < a < 1 (sample a = 1/2): 6 relative equilibria, 4 stable
              1 < a < 3 (sample a = 2): 6 relative equilibria, 4 stable
              3 < a (sample a = 4): 6 relative equilibria, 4 stable
            sage: S.equilibrium_census([a], levels=[1]).count_at({a: 3})
            (2, 2)
        """
        from ..analysis.leaf_census import leaf_census
        return leaf_census(self._H, self.casimirs(), self.poisson_matrix(), self.variables(),
                           parameters, levels, values=values, executor=executor,
                           positive=self._positive if positive is None else positive)

    def linearize(self, at):
        r"""
        The first-approximation system at the equilibrium ``at`` (a dict
        over the variables), see :func:`~sage_dynsym.analysis.linear.linearize`.

        EXAMPLES: the rotation about the middle axis is unstable::

            sage: from sage_dynsym.lie.system import LiePoissonSystem
            sage: M1, M2, M3 = var('M1 M2 M3')
            sage: S = LiePoissonSystem('so3', (M1^2 + M2^2/2 + M3^2/3)/2)
            sage: S.linearize({M1: 0, M2: 1, M3: 0}).characteristic_polynomial(var('lam'))
            lam^3 - 1/12*lam
        """
        return _linearize(self.equations(), at, self.variables())

    def nonlinear_stability(self, at, integrals=(), positive=None):
        r"""
        The Lyapunov stability of the equilibrium ``at`` by the
        energy--Casimir method (the second variation of `H + \sum\lambda_i
        C_i` on the Casimir level), then the first approximation: see
        :func:`~sage_dynsym.analysis.energy_casimir.energy_casimir_stability`.

        INPUT:

        - ``at`` -- dict variable -> exact value (and parameter -> value)
        - ``integrals`` -- (optional) first integrals besides the Casimirs
          (e.g. a momentum of a symmetry: the energy--Casimir--momentum
          method)
        - ``positive`` -- (default: the system's) symbols declared positive

        OUTPUT: a :class:`~sage_dynsym.analysis.verdict.StabilityVerdict`

        EXAMPLES: the free rigid body about its axes (Euler; moments of
        inertia `A_1 < A_2 < A_3`)::

            sage: from sage_dynsym.lie.system import LiePoissonSystem
            sage: M1, M2, M3 = var('M1 M2 M3')
            sage: S = LiePoissonSystem('so3', (M1^2 + M2^2/2 + M3^2/3)/2)
            sage: [S.nonlinear_stability(dict(zip([M1, M2, M3], e))).verdict()
            ....:  for e in identity_matrix(3)]
            ['stable', 'unstable', 'stable']
        """
        from ..analysis.energy_casimir import energy_casimir_stability
        return energy_casimir_stability(
            self._H, self.casimirs(), self.poisson_matrix(), self.variables(), at,
            integrals=integrals, positive=self._positive if positive is None else positive)

    def free_linear_system(self, at=None):
        r"""
        The first-approximation system at ``at`` (a dict over the
        variables; the others 0, by default the origin): what
        :func:`~sage_dynsym.scale.maps.stability_map` maps (a Lie--Poisson
        system has no sources to switch off).

        EXAMPLES: the rotation about the second axis; Euler's classical
        result `\lambda^2 = -(1/A_2 - 1/A_1)(1/A_2 - 1/A_3) M_2^2` (unstable
        about the middle axis)::

            sage: from sage_dynsym.lie.system import LiePoissonSystem
            sage: M1, M2, M3, A1, A2, A3, lam = var('M1 M2 M3 A1 A2 A3 lam')
            sage: S = LiePoissonSystem('so3', (M1^2/A1 + M2^2/A2 + M3^2/A3)/2)
            sage: p = S.free_linear_system({M2: 1}).characteristic_polynomial(lam)
            sage: bool((p/(A1^2*A2^2*A3^2)).expand()
            ....:      == (lam^3 + (1/A2 - 1/A1)*(1/A2 - 1/A3)*lam).expand())
            True
        """
        from ..dynamics.model import linearization_point
        return self.linearize(linearization_point(at, self.variables()))

    def subs(self, values):
        r"""
        The system with parameter values substituted (in `H` and in the
        Poisson matrix); the substituted parameters are no longer
        parameters.

        EXAMPLES: Kovalevskaya's case from a general heavy body::

            sage: from sage_dynsym.lie.system import LiePoissonSystem
            sage: M1, M2, M3, g1 = var('M1 M2 M3 gamma1'); A, B, C, c = var('A B C c')
            sage: S = LiePoissonSystem('e3', M1^2/(2*A) + M2^2/(2*B) + M3^2/(2*C) + c*g1,
            ....:                      positive=[A, B, C])
            sage: K = S.subs({A: 2*C, B: 2*C}); K.parameters(), K.positive_parameters()
            ([C, c], [C])
            sage: len(K.polynomial_integrals(4, new_only=True))
            1

        TESTS::

            sage: S.subs({'A': -1})
            Traceback (most recent call last):
            ...
            ModelError: subs: A is declared positive, got -1
        """
        check_model_values(self, values, entry="subs")
        values = {SR.var(k) if isinstance(k, str) else SR(k): SR(v)
                  for k, v in exact_decimals(values).items()}
        names = {str(k) for k in values}
        for k in values:
            if str(k) not in {str(a) for a in self._parameters}:
                raise ModelError(f"{k} is not a parameter (the parameters are "
                                 f"{', '.join(map(str, self._parameters))})", entry="values")
        structure = self._structure
        if any(str(a) in names for a in structure.parameters()):
            structure = PoissonStructure(structure.matrix().subs(values),
                                         structure.variables(), name=structure.name())
        remaining = sorted({a for v in values.values() for a in v.variables()} |
                           {a for a in self._parameters if str(a) not in names}, key=str)
        reduction = None if self._reduction is None else \
            {k: SR(v).subs(values) for k, v in self._reduction.items()}
        return LiePoissonSystem(structure, self._H.subs(values), parameters=remaining,
                                name=self._name, reduction=reduction,
                                positive=[a for a in self._positive if str(a) not in names])

    def equations_record(self):
        r"""
        The equations `\dot x = J(x)\nabla H` as neutral data
        (:class:`~sage_dynsym.analysis.motion.FirstOrderEquations` in
        :meth:`variables`); through it the system gets ``numerical_rhs``,
        ``simulate`` and ``code`` of
        :class:`~sage_dynsym.numerics.methods.NumericalMethods`, with `H`
        as the energy of the trajectories.

        EXAMPLES::

            sage: from sage_dynsym.lie.system import LiePoissonSystem
            sage: M1, M2, M3, a = var('M1 M2 M3 a')
            sage: S = LiePoissonSystem('so3', (M1^2 + M2^2/2 + M3^2/a)/2)
            sage: S.equations_record()
            First-order equations x' = F(x) in (M1, M2, M3)
            sage: f = S.numerical_rhs({a: 3})
            sage: f(0, [1.0, 2.0, 3.0])
            array([-1.,  2., -1.])
            sage: T = S.simulate({a: 3}, {M1: 1, M2: 0.1, M3: 0.1}, 10)
            sage: T.energy_drift() < 1e-9
            True

        TESTS::

            sage: LiePoissonSystem('so3', M1^2/a).numerical_rhs({})
            Traceback (most recent call last):
            ...
            ModelError: values: missing values of the parameters a
        """
        return FirstOrderEquations(self.equations(), self.variables())

    def _conserved_energy(self):
        return self._H

    # ------------------------------------------------------------------
    # the model interface

    kind = 'lie_poisson'


    def characteristic_functions(self):
        r"""
        The characteristic function of the system: its Hamiltonian (a
        Lie--Poisson system has no Lagrangian).

        EXAMPLES::

            sage: from sage_dynsym.lie.system import LiePoissonSystem
            sage: M1, A = var('M1 A')
            sage: LiePoissonSystem('so3', M1^2/A).characteristic_functions()['hamiltonian']()
            M1^2/A
        """
        return {'hamiltonian': self.hamiltonian}

    def equation_forms(self):
        r"""
        The form of the system's equations: the Lie--Poisson equations
        `\dot x_i = \{x_i, H\}` (a
        :class:`~sage_dynsym.dynamics.derivations.Derivation`).

        EXAMPLES::

            sage: from sage_dynsym.lie.system import LiePoissonSystem
            sage: M1, M2, M3 = var('M1 M2 M3')
            sage: d = LiePoissonSystem('so3', (M1^2 + M2^2)/2 + M3^2).equation_forms()['Lie-Poisson']()
            sage: d.function, d.equations[0]
            (('H', 1/2*M1^2 + 1/2*M2^2 + M3^2), ('\\dot{M_{1}}', M2*M3))
        """
        from sage.misc.latex import latex
        from ..dynamics.derivations import Derivation

        def derivation(cyclic=()):
            rows = [(f"\\dot{{{latex(x)}}}", f) for x, f in zip(self.variables(), self.equations())]
            return Derivation('Lie-Poisson', ('H', self.hamiltonian()), rows, None)
        return {'Lie-Poisson': derivation}


def _census(system, parameters, positive=(), values=None, chart=None, regular=None,
            executor=None, levels=None):
    r"""The census of :func:`~sage_dynsym.analysis.census.equilibrium_census`
    for a Lie--Poisson system: :meth:`LiePoissonSystem.equilibrium_census`."""
    if chart is not None or regular is not None:
        raise AnalysisError("a Lie-Poisson system has no chart or regular chart: its "
                            "relative equilibria are points of its variables", entry="chart")
    return system.equilibrium_census(parameters, levels=levels, positive=positive,
                                     values=values, executor=executor)


register_census(LiePoissonSystem, _census)


def _names_of(symbols):
    return [str(s) for s in symbols]
