r"""
A census of the relative equilibria of a Lie--Poisson system on its
symplectic leaves

The equilibria of `\dot x = J(x)\nabla H(x)` on a symplectic leaf `\{C_i =
c_i\}` (the levels of the Casimirs `C_1, \dots, C_k`) are, at the regular
points of the leaf, the critical points of `H` restricted to it: the
solutions of

.. MATH::

    \nabla H = \sum_i \lambda_i \nabla C_i, \qquad C_i = c_i,

the critical points of `W = H - \sum_i \lambda_i (C_i - c_i)` in `(x,
\lambda)` (the relative equilibria of the rigid body and of Kirchhoff's
equations). The levels `c_i` may depend on the parameters of the census, and
so may `H`. :func:`leaf_census` counts them over one or two parameters as
:func:`~sage_dynsym.analysis.census.equilibrium_census` counts the
equilibria of a Lagrangian:

1. the *bifurcation set*, by elimination (Singular): the ideal of the
   critical points of `W` with the parameters as variables is decomposed
   into its prime components; a component over a proper subset of the
   parameter space gives its equations; a component of isolated points
   (over a generic parameter) gives the projection of its points where the
   Hessian of `W` in `(x, \lambda)` -- the bordered Hessian of `H - \lambda
   \cdot C` on the tangent space of the leaf -- is singular; a component of
   families gives the projection of its points where the projection onto
   the parameters is not a submersion (its fibre is singular there, where
   the real family is born, dies or changes), and its intersections with
   the other components; and where the leaf itself is singular (the
   gradients of the Casimirs dependent on the level) is added;
2. the *cells* as for the Lagrangian census (intervals, or a cylindrical
   decomposition for two parameters), each with a rational sample;
3. at each sample the relative equilibria are solved exactly
   (:func:`~sage_dynsym.analysis.stationary.stationary_solutions` with the
   levels), the isolated real ones counted, each with its stability:
   ``'stable'`` by the energy--Casimir method (the second variation of `H -
   \lambda\cdot C` definite on the tangent space of the leaf),
   ``'unstable'`` for a root of the linearization with a positive real
   part, ``'stable in first approximation'`` where the linearization
   restricted to the leaf (the characteristic polynomial without the `k`
   zero roots transversal to the leaf) has all its roots simple and on the
   imaginary axis, ``'undecided'`` otherwise, computed in the number field
   of each point with certified signs
   (:func:`~sage_dynsym.analysis.point_stability.relative_equilibrium_verdict`).
   The positive-dimensional
   components with real points (decided exactly: :func:`has_real_points`)
   are reported as families, with their dimensions, never counted as
   points.

The count of isolated relative equilibria and the energy--Casimir stable
count are constant on the cells. The count stable in first approximation
also changes where two roots of the linearization on the leaf collide
without any equilibrium degenerating: those boundaries
(:func:`leaf_first_approximation_polynomials`, the discriminant of the
characteristic polynomial on the leaf eliminated on the relative
equilibria) are computed when ``cells(first_approximation=True)`` is
asked for; its cells have a constant
``stable_count(first_approximation=True)``.

EXAMPLES: the free rigid body, `H = \frac12 \sum M_i^2/I_i` with `I =
(1, 2, 3)`, on the spheres `|M|^2 = c^2`: six relative equilibria (the
rotations about the principal axes), four stable (the largest and the
smallest axes; Euler, Arnold), the only bifurcation at `c = 0`::

    sage: from sage_dynsym.analysis.leaf_census import leaf_census
    sage: M1, M2, M3, c = var('M1 M2 M3 c')
    sage: J = matrix([[0, -M3, M2], [M3, 0, -M1], [-M2, M1, 0]])
    sage: H = M1^2/2 + M2^2/4 + M3^2/6
    sage: leaf_census(H, [M1^2 + M2^2 + M3^2], J, [M1, M2, M3], [c], [c^2])
    Census of the relative equilibria on the levels M1^2 + M2^2 + M3^2 = c^2 over c: bifurcation set [c]
      c < 0 (sample c = -1): 6 relative equilibria, 4 stable
      0 < c (sample c = 1): 6 relative equilibria, 4 stable

REFERENCES:

- V. I. Arnold, *Mathematical Methods of Classical Mechanics*, 2nd ed.,
  Springer, 1989, §29 and Appendix 2.
- J. E. Marsden, T. S. Ratiu, *Introduction to Mechanics and Symmetry*,
  2nd ed., Springer, 1999, §1.7 (the energy--Casimir method).
- D. Lazard, F. Rouillier, *Solving parametric polynomial systems*, J.
  Symbolic Comput. 42 (2007) 636--667 (discriminant varieties).
"""
import random

from sage.arith.functions import lcm
from sage.libs.singular.function_factory import ff
from sage.matrix.constructor import matrix
from sage.rings.polynomial.polynomial_ring_constructor import PolynomialRing
from sage.rings.qqbar import AA
from sage.rings.rational_field import QQ
from sage.symbolic.ring import SR

from ..errors import AnalysisError
from ._census import (log, census_arguments, check_values, stationary_ideal,
                      add_zero_set_factors, check_main_thread, verdict_counts)
from .census import Census
from .charts import configuration_points
from .energy_casimir import hamiltonian_field
from .point_stability import relative_equilibrium_verdict
from .stationary import stationary_solutions

__all__ = ['has_real_points', 'leaf_bifurcation_polynomials',
           'leaf_first_approximation_polynomials', 'relative_equilibria_at', 'leaf_census']

#: the number of random choices tried before a critical locus is given up
ATTEMPTS = 4


def has_real_points(ideal):
    r"""
    Whether the complex variety of a polynomial ideal over `\QQ` has a real
    point, decided exactly. A nonempty real algebraic set has a point
    nearest to any given point `a`; on a prime component of dimension `d`
    it is a singular point or a critical point of `|x - a|^2`, where the
    `(n - d + 1)`-minors of the Jacobian matrix (of `n - d` random
    combinations of the generators) bordered by `x - a` vanish: a
    subvariety of smaller dimension, decided in turn, down to finitely many
    points (solved over the real algebraic numbers).

    INPUT:

    - ``ideal`` -- an ideal of a multivariate polynomial ring over `\QQ`

    OUTPUT: a boolean

    EXAMPLES: the circle `x^2 + y^2 = 1` is real, `x^2 + y^2 = -1` is not,
    nor the intersection of the sphere with a plane beyond it::

        sage: from sage_dynsym.analysis.leaf_census import has_real_points
        sage: R.<x, y, z> = QQ[]
        sage: [has_real_points(R.ideal([x^2 + y^2 - r])) for r in (1, -1)]
        [True, False]
        sage: [has_real_points(R.ideal([x^2 + y^2 + z^2 - 1, x + y + z - t])) for t in (1, 2)]
        [True, False]

    TESTS: a real point only where the variety is singular (the isolated
    real point of `x^2 + y^2 = 0` on a complex surface)::

        sage: has_real_points(R.ideal([x^2 + y^2])), has_real_points(R.ideal([x^2 + y^2 + 1]))
        (True, False)
    """
    return any(_prime_has_real_points(Q) for Q in ideal.minimal_associated_primes())


def _without_linear_variables(Q):
    r"""
    The prime ``Q`` in fewer variables, with the same real points up to a
    polynomial bijection: a variable `v` of a generator `a v + h` (`a` a
    nonzero rational, `h` free of `v`) is `-h/a`, substituted into the
    others; variables that no generator uses (free) are dropped. A boolean
    when no variable is left: whether there are (real) points.

    EXAMPLES::

        sage: from sage_dynsym.analysis.leaf_census import _without_linear_variables
        sage: R.<x, y, z, w> = QQ[]
        sage: _without_linear_variables(R.ideal([y - x^2, z^2 + y^2 - 1]))
        Ideal (x^4 + z^2 - 1) of Multivariate Polynomial Ring in x, z over Rational Field
    """
    R = Q.ring()
    gens = [g for g in Q.groebner_basis() if g != 0]
    solved = True
    while solved:
        solved = False
        for g in gens:
            v = next((v for v in g.variables()
                      if g.degree(v) == 1 and g.coefficient({v: 1}).is_constant()), None)
            if v is not None:
                a = QQ(g.coefficient({v: 1}))
                value = -(g - a * v) / a
                gens = [f.subs({v: value}) for f in gens if f is not g]
                gens = [f for f in gens if f != 0]
                solved = True
                break
    used = [v for v in R.gens() if any(f.degree(v) > 0 for f in gens)]
    if not used:
        return not gens     # no relation left: real (a constant one: no point)
    S = PolynomialRing(R.base_ring(), len(used), [str(v) for v in used])   # multivariate
    image = R.hom([S(str(v)) if v in used else S.zero() for v in R.gens()], S)
    return S.ideal([image(f) for f in gens])


def _prime_has_real_points(Q):
    d = Q.dimension()
    if d < 0:
        return False
    reduced = _without_linear_variables(Q)
    if isinstance(reduced, bool):
        return reduced
    if reduced.ring().ngens() < Q.ring().ngens():
        return has_real_points(reduced)
    if d == 0:
        return bool(Q.variety(AA))
    R = Q.ring()
    x = R.gens()
    for attempt in range(ATTEMPTS):
        rng = random.Random(attempt)
        rows = [[f.derivative(v) for v in x] for f in _combinations(Q, len(x) - d, rng)]
        rows.append([v - rng.randint(-9, 9) for v in x])
        Z = Q + R.ideal(matrix(R, rows).minors(len(x) - d + 1))
        # a strictly smaller subvariety (Q is prime): unless every point was
        # critical for this choice (a sphere about a, say)
        if Z.dimension() < d:
            return has_real_points(Z)
    raise AnalysisError(f"whether the component {Q} has real points was not decided: every "
                        f"point was critical in {ATTEMPTS} random choices",
                        entry="equilibrium_census")


def _combinations(Q, count, rng):
    r"""``count`` combinations of the generators of ``Q`` with random
    integer coefficients: where `Q` has codimension ``count``, their
    Jacobian matrix has the rank of that of `Q` at its generic points."""
    gens = [g for g in Q.gens() if g != 0]
    return [sum(rng.randint(-9, 9) * g for g in gens) for _ in range(count)]


def _critical_locus(Q, state, fibre):
    r"""The polynomials in the parameters where the projection of the
    prime component ``Q`` (fibres of dimension ``fibre``) onto them is
    not a submersion: ``Q`` with the maximal minors of the Jacobian matrices
    in the ``state`` variables of two choices of random combinations of its
    generators, eliminated (``[]`` when nothing was found in the attempts).
    Each choice adds the points where its own combinations lose rank; the
    two together keep only those where `Q`'s Jacobian matrix does."""
    R = Q.ring()
    size = len(state) - fibre
    for attempt in range(0, 2 * ATTEMPTS, 2):
        minors = []
        for rng in (random.Random(attempt), random.Random(attempt + 1)):
            combos = _combinations(Q, size, rng)
            minors += matrix(R, [[f.derivative(v) for v in state] for f in combos]).minors(size)
        found = [g for g in (Q + R.ideal(minors)).elimination_ideal(state).gens() if g != 0]
        if found:
            return found
    return []


def _components(ideal):
    r"""
    The minimal associated primes of ``ideal``, split first by Singular's
    factorizing Groebner basis (the whole ideal, with the parameters as
    variables, can take minutes where its parts take milliseconds); the
    primes of one part contained in those of another dropped.

    EXAMPLES::

        sage: from sage_dynsym.analysis.leaf_census import _components
        sage: R.<x, y> = QQ[]
        sage: sorted(str(Q.gens()) for Q in _components(R.ideal([x*y, x*(x - 1)])))
        ['[x]', '[y, x - 1]']
        sage: sorted(str(Q.gens()) for Q in _components(R.ideal([x*y*(y - 1), x*(x - 1)*y])))
        ['[x]', '[y - 1, x - 1]', '[y]']
    """
    R = ideal.ring()
    found = []
    for part in ff.facstd(ideal):
        for Q in R.ideal(list(part)).minimal_associated_primes():
            if all(Q != K for K in found):
                found.append(Q)
    return [Q for Q in found if not any(K != Q and K <= Q for K in found)]


def leaf_bifurcation_polynomials(H, casimirs, variables, levels, parameters):
    r"""
    The bifurcation set of the relative equilibria of `H` on the levels
    `C_i = c_i` of the Casimirs (see the module documentation): irreducible
    polynomials in the parameters.

    INPUT:

    - ``H`` -- the Hamiltonian, polynomial in the variables
    - ``casimirs`` -- the Casimirs `C_i`
    - ``variables`` -- the variables `x`
    - ``levels`` -- the values `c_i`, expressions in the parameters
    - ``parameters`` -- the symbols of the census (the only ones left in
      ``H`` and ``levels``)

    OUTPUT: a list of symbolic polynomials in the parameters

    EXAMPLES: Brun's problem, `H = \frac12 (M, I^{-1}M) + \frac12 (\gamma,
    I\gamma)` with `I = (1, 2, 3)`, on the levels `(M, \gamma) = c`,
    `(\gamma, \gamma) = 1`: the bifurcation values are `|c| = I_k`::

        sage: from sage_dynsym.analysis.leaf_census import leaf_bifurcation_polynomials
        sage: M1, M2, M3, g1, g2, g3, c = var('M1 M2 M3 g1 g2 g3 c')
        sage: H = (M1^2 + M2^2/2 + M3^2/3)/2 + (g1^2 + 2*g2^2 + 3*g3^2)/2
        sage: C = [M1*g1 + M2*g2 + M3*g3, g1^2 + g2^2 + g3^2]
        sage: sorted(leaf_bifurcation_polynomials(H, C, [M1, M2, M3, g1, g2, g3], [c, 1], [c]))
        [c - 3, c - 2, c - 1, c + 1, c + 2, c + 3]

    TESTS: a level that is singular for every value of the parameter::

        sage: x, y, z = var('x y z')
        sage: leaf_bifurcation_polynomials(x + c*y, [x^2 + y^2 + z^2], [x, y, z], [0], [c])
        Traceback (most recent call last):
        ...
        AnalysisError: levels: the level [x^2 + y^2 + z^2 == 0] is singular (the gradients of the Casimirs dependent) for every value of c: choose levels where the leaves are regular
    """
    x = [SR(v) for v in variables]
    W, u = _lagrange_function(H, casimirs, x, levels)
    hessian = matrix(SR, [[W.diff(a).diff(b) for b in u] for a in u]).det()
    G = matrix(SR, [[SR(C).diff(v) for v in x] for C in casimirs])
    minors = G.minors(len(casimirs)) if casimirs else []
    T, ideal, state, extra = stationary_ideal(
        [W.diff(v) for v in u], u, parameters,
        [hessian] + [SR(C) - SR(c) for C, c in zip(casimirs, levels)] + minors)
    P = T.ring()
    found = []
    if casimirs:
        singular = [g for g in P.ideal(extra[1:]).elimination_ideal(state).gens() if g != 0]
        if not singular:
            raise AnalysisError(
                f"the level {[SR(C) == SR(c) for C, c in zip(casimirs, levels)]} is singular "
                "(the gradients of the Casimirs dependent) for every value of "
                f"{', '.join(map(str, parameters))}: choose levels where the leaves are "
                "regular", entry="levels")
        add_zero_set_factors(singular, found)
    primes = _components(ideal)
    log(f"{len(primes)} components of the relative equilibria")
    families = []
    for Q in primes:
        below = [g for g in Q.elimination_ideal(state).gens() if g != 0]
        if below:
            add_zero_set_factors(below, found)
            continue
        fibre = Q.dimension() - len(parameters)
        if fibre == 0:
            gens = [g for g in (Q + P.ideal([extra[0]])).elimination_ideal(state).gens()
                    if g != 0]
        else:
            families.append(Q)
            gens = _critical_locus(Q, state, fibre)
        if not gens:
            raise AnalysisError(f"the relative equilibria of the component {Q} are degenerate "
                                f"for all values of {', '.join(map(str, parameters))}",
                                entry="equilibrium_census")
        add_zero_set_factors(gens, found)
    for Q in families:
        for other in [R for R in primes if R is not Q]:
            meet = [g for g in (Q + other).elimination_ideal(state).gens() if g != 0]
            if meet:
                add_zero_set_factors(meet, found)
    return sorted((T.symbolic(f) for f in found), key=str)


def _lagrange_function(H, casimirs, x, levels):
    r"""`W = H - \sum_i \lambda_i (C_i - c_i)` and its unknowns `(x,
    \lambda)`: the relative equilibria on the leaf are its critical points."""
    lam = [SR.var(f"leaf_multiplier{i + 1}") for i in range(len(casimirs))]
    W = SR(H) - sum(m * (SR(C) - SR(c)) for m, C, c in zip(lam, casimirs, levels))
    return W, x + lam


def leaf_first_approximation_polynomials(H, casimirs, poisson_matrix, variables, levels,
                                         parameters):
    r"""
    The boundaries, in the parameters, of the stability in first
    approximation of the isolated relative equilibria on the levels `C_i =
    c_i`: irreducible polynomials in the parameters.

    At a relative equilibrium the linearization of `\dot x = J(x)\nabla H`
    has the characteristic polynomial `z^k p(z)` (`k` the number of
    Casimirs: the roots transversal to the leaf), `p` the one of the
    linearization on the leaf, even for a Hamiltonian system: `p(z) =
    q(z^2)`. Its roots are all simple and on the imaginary axis (stable in
    first approximation) iff those of `q` are simple, real and negative;
    that changes only where a root of `q` crosses zero (`q(0) = 0`, where
    the equilibrium is degenerate on its leaf) or two roots collide (the
    discriminant of `q` vanishes). The projections of those two sets on the
    parameters are computed by elimination (Singular) on each component of
    isolated relative equilibria of the stationary ideal (see
    :func:`leaf_bifurcation_polynomials`); a component where `q` has a
    multiple root everywhere adds nothing (its equilibria are never stable
    in first approximation; the energy--Casimir verdict changes only where
    they are degenerate).

    INPUT: as for :func:`leaf_bifurcation_polynomials`, with
    ``poisson_matrix`` the matrix `J(x)`

    OUTPUT: a list of symbolic polynomials in the parameters

    EXAMPLES: Brun's problem (see :func:`leaf_bifurcation_polynomials`):
    besides the degenerate values `|c| = 1, 2, 3`, pairs of roots collide
    at the zeros of a polynomial of degree 4 in `c`::

        sage: from sage_dynsym.analysis.leaf_census import leaf_first_approximation_polynomials
        sage: M1, M2, M3, g1, g2, g3, c = var('M1 M2 M3 g1 g2 g3 c')
        sage: H = (M1^2 + M2^2/2 + M3^2/3)/2 + (g1^2 + 2*g2^2 + 3*g3^2)/2
        sage: C = [M1*g1 + M2*g2 + M3*g3, g1^2 + g2^2 + g3^2]
        sage: J = block_matrix([[matrix([[0, -M3, M2], [M3, 0, -M1], [-M2, M1, 0]]),
        ....:                    matrix([[0, -g3, g2], [g3, 0, -g1], [-g2, g1, 0]])],
        ....:                   [matrix([[0, -g3, g2], [g3, 0, -g1], [-g2, g1, 0]]), 0]])
        sage: leaf_first_approximation_polynomials(H, C, J, [M1, M2, M3, g1, g2, g3], [c, 1], [c])
        [c + 1, c + 2, c + 3, c - 1, c - 2, c - 3, c^4 + 14*c^2 + 1, c^4 - 4*c^2 + 16]

    Neither quartic has a real root: the count stable in first
    approximation changes only where the count does.

    TESTS: a function that is not a Casimir of `J`: the linearization on
    its levels is not Hamiltonian::

        sage: x, y, z = var('x y z')
        sage: leaf_first_approximation_polynomials((x^2 + 2*y^2 + 3*z^2)/2, [x + y],
        ....:     matrix([[0, x, 0], [-x, 0, 1], [0, -1, 0]]), [x, y, z], [c], [c])
        Traceback (most recent call last):
        ...
        AnalysisError: casimirs: the characteristic polynomial of the linearization on the leaf is not even on the relative equilibria [-1/2*x + y, z, leaf_multiplier1 - x, c - 3/2*x]: the linearization is not Hamiltonian on the levels of x + y; give the Casimirs of J (all of them)
    """
    x = [SR(v) for v in variables]
    W, u = _lagrange_function(H, casimirs, x, levels)
    field = hamiltonian_field(H, poisson_matrix, x)
    entries = [f.diff(v) for f in field for v in x]
    T, ideal, state, _ = stationary_ideal([W.diff(v) for v in u], u, parameters, entries)
    P = T.ring()
    # the parameters may have denominators: a multiple dA of the Jacobian
    # matrix (d in the parameters) has the roots d z, simple and imaginary
    # where those of A are, for d real and nonzero
    fractions = [T.fraction(e) for e in entries]
    d = lcm([f.denominator() for f in fractions])
    A = matrix(P, len(x), len(x), [T.to_ring((f * d).numerator()) for f in fractions])
    coefficients = A.charpoly('z').list()[len(casimirs):]
    even, odd = coefficients[::2], coefficients[1::2]
    R = PolynomialRing(QQ, list(P.variable_names()) + ['leaf_w'])
    w = R.gen(len(P.gens()))
    q = sum(R(str(a)) * w ** i for i, a in enumerate(even))
    back = R.hom(list(P.gens()) + [P.zero()], P)
    boundaries = [even[0]] + ([back(q.discriminant(w))] if len(even) > 2 else [])
    found = []
    for Q in _components(ideal):
        if any(g != 0 for g in Q.elimination_ideal(state).gens()) or \
                Q.dimension() > len(parameters):
            continue        # over a proper subset of the parameters, or a family
        if any(Q.reduce(a) != 0 for a in odd):
            raise AnalysisError(
                f"the characteristic polynomial of the linearization on the leaf is not even "
                f"on the relative equilibria {[T.symbolic(g) for g in Q.gens()]}: the "
                "linearization is not Hamiltonian on the levels of "
                f"{', '.join(map(str, casimirs))}; give the Casimirs of J (all of them)",
                entry="casimirs")
        for b in boundaries:
            gens = [g for g in (Q + P.ideal([b])).elimination_ideal(state).gens() if g != 0]
            if gens:
                add_zero_set_factors(gens, found)
    # the factors of d came with the multiple dA: where d = 0 the system is
    # not defined (the stationary ideal is saturated there)
    d = T.to_ring(d)
    return sorted((T.symbolic(f) for f in found if not f.divides(d)), key=str)


def relative_equilibria_at(H, casimirs, poisson_matrix, variables, levels):
    r"""
    The relative equilibria on one leaf, at numerical values of the
    parameters: the isolated real ones with their stability on the leaf,
    and the dimensions of the families with real points.

    INPUT:

    - ``H``, ``casimirs``, ``poisson_matrix``, ``variables`` -- the
      system, without parameters
    - ``levels`` -- the values of the Casimirs (exact numbers)

    OUTPUT: a pair ``(points, families)``: a list of pairs ``(point,
    verdict)``, ``point`` a :class:`~sage_dynsym.analysis.charts.ConfigurationPoint`,
    and a sorted list of dimensions

    EXAMPLES: the free rigid body on the sphere `|M|^2 = 1`::

        sage: from sage_dynsym.analysis.leaf_census import relative_equilibria_at
        sage: M1, M2, M3 = var('M1 M2 M3')
        sage: J = matrix([[0, -M3, M2], [M3, 0, -M1], [-M2, M1, 0]])
        sage: points, families = relative_equilibria_at(M1^2/2 + M2^2/4 + M3^2/6,
        ....:                        [M1^2 + M2^2 + M3^2], J, [M1, M2, M3], [1])
        sage: sorted((p.embedding(), v) for p, v in points), families
        ([((-1, 0, 0), 'stable'),
          ((0, -1, 0), 'unstable'),
          ((0, 0, -1), 'stable'),
          ((0, 0, 1), 'stable'),
          ((0, 1, 0), 'unstable'),
          ((1, 0, 0), 'stable')],
         [])

    A symmetric body, `I_1 = I_2`: the rotations about the equatorial axes
    make a circle on the sphere::

        sage: points, families = relative_equilibria_at((M1^2 + M2^2)/2 + M3^2/6,
        ....:                        [M1^2 + M2^2 + M3^2], J, [M1, M2, M3], [1])
        sage: len(points), families
        (2, [1])
    """
    x = [SR(v) for v in variables]
    field = hamiltonian_field(H, poisson_matrix, x)
    sols = stationary_solutions([SR(H)] + [SR(C) for C in casimirs], x, equations=list(field),
                                levels=list(levels))
    found = []
    points = configuration_points(sols, None, found)
    # (the ends of a family's branches are not listed as points: the
    # solver drops a point only where a listed branch contains it exactly)
    families = sorted(d for _, _, d in _real_families(found, sols.multipliers()))
    verdicts = [relative_equilibrium_verdict(H, casimirs, poisson_matrix, x,
                                             [p.value(v) for v in x]) for p in points]
    return list(zip(points, verdicts)), families


def _real_families(families, multipliers):
    r"""
    The distinct components of the families of relative equilibria that
    have real points, as triples ``(ideal, translation, dimension)``: the projection of
    each on the variables (on a regular leaf the multipliers are the unique,
    real, solution of a linear system at a real point), the branches of
    one component (the signs of its square roots) counted once.

    EXAMPLES: the symmetric body's circle of rotations about the equatorial
    axes is one component, its two halves `M_2 = \pm\sqrt{1 - M_1^2}` one
    family::

        sage: from sage_dynsym.analysis.leaf_census import _real_families
        sage: from sage_dynsym.analysis.stationary import stationary_solutions
        sage: M1, M2, M3 = var('M1 M2 M3')
        sage: H = (M1^2 + M2^2)/2 + M3^2/6
        sage: X = [-M2*M3/3 + M3*M2, M1*M3/3 - M3*M1, 0]
        sage: sols = stationary_solutions([H, M1^2 + M2^2 + M3^2], [M1, M2, M3],
        ....:                             equations=X, levels=[1])
        sage: [([T.symbolic(g) for g in J.gens()], d) for J, T, d in
        ....:  _real_families([s for s in sols if s.dimension() > 0], sols.multipliers())]
        [([M3, M1^2 + M2^2 - 1], 1)]
    """
    found = []
    for solution in families:
        inner = solution.solution()
        T = inner.translation()
        eliminated = [g for m in multipliers for g in T.generators_of(m)]
        J = inner.ideal().elimination_ideal(eliminated)
        if all(J != K for K, _, _ in found) and has_real_points(J):
            found.append((J, T, solution.dimension()))
    return found


def _leaf_task(system, values):
    r"""One sample point's counts and families (a task: module level,
    picklable arguments)."""
    check_main_thread(values)
    H, casimirs, J, x, levels = system
    log(f"solving at {values}")
    points, families = relative_equilibria_at(
        SR(H).subs(values), casimirs, matrix(SR, J).subs(values), x,
        [SR(c).subs(values) for c in levels])
    return verdict_counts([v for _, v in points]), families


def _symbols(expressions, skip):
    return {str(s): s for e in expressions for s in SR(e).variables() if str(s) not in skip}


def leaf_census(H, casimirs, poisson_matrix, variables, parameters, levels, positive=(),
                values=None, executor=None):
    r"""
    The census of the relative equilibria of the Lie--Poisson system
    `\dot x = J(x)\nabla H` on the levels of its Casimirs over one or two
    parameters (see the module documentation); a Lie--Poisson system's
    :meth:`~sage_dynsym.lie.system.LiePoissonSystem.equilibrium_census`
    and :func:`~sage_dynsym.analysis.census.equilibrium_census` call it.

    INPUT:

    - ``H`` -- the Hamiltonian, polynomial in the variables
    - ``casimirs`` -- the Casimirs, in the order of ``levels``
    - ``poisson_matrix`` -- `J(x)`
    - ``variables`` -- the variables `x`
    - ``parameters`` -- one or two symbols: symbols of `H` or of the levels
    - ``levels`` -- one value per Casimir: numbers or expressions in the
      parameters (``[c, 1]`` for `(M, \gamma) = c`, `(\gamma, \gamma) = 1`)
    - ``positive`` -- symbols declared positive (a parameter declared
      positive is censused over its positive values only)
    - ``values`` -- values for the other symbols of `H` and `J`
    - ``executor`` -- as for :func:`~sage_dynsym.analysis.census.equilibrium_census`

    OUTPUT: a :class:`~sage_dynsym.analysis.census.Census`; its cells'
    :meth:`~sage_dynsym.analysis.census.CensusCell.families` give the
    families of relative equilibria

    EXAMPLES: Brun's problem (see :func:`leaf_bifurcation_polynomials`),
    for `c > 0`: the six rotations about the principal axes on every leaf;
    for `1 < c < 3` also a curve of Brun's uniform rotations `M = I\gamma`
    (Borisov and Mamaev, *Rigid Body Dynamics*, the Brun case)::

        sage: from sage_dynsym.analysis.leaf_census import leaf_census
        sage: M1, M2, M3, g1, g2, g3, c = var('M1 M2 M3 g1 g2 g3 c')
        sage: x = [M1, M2, M3, g1, g2, g3]
        sage: H = (M1^2 + M2^2/2 + M3^2/3)/2 + (g1^2 + 2*g2^2 + 3*g3^2)/2
        sage: C = [M1*g1 + M2*g2 + M3*g3, g1^2 + g2^2 + g3^2]
        sage: J = block_matrix([[matrix([[0, -M3, M2], [M3, 0, -M1], [-M2, M1, 0]]),
        ....:                    matrix([[0, -g3, g2], [g3, 0, -g1], [-g2, g1, 0]])],
        ....:                   [matrix([[0, -g3, g2], [g3, 0, -g1], [-g2, g1, 0]]), 0]])
        sage: census = leaf_census(H, C, J, x, [c], [c, 1], positive=[c]); census
        Census of the relative equilibria on the levels M1*g1 + M2*g2 + M3*g3 = c, g1^2 + g2^2 + g3^2 = 1 over c > 0: bifurcation set [c - 1, c - 2, c - 3]
          0 < c < 1 (sample c = 1/2): 6 relative equilibria, 2 stable
          1 < c < 2 (sample c = 3/2): 6 isolated, 0 stable, 2 more stable in first approximation, and a curve of relative equilibria
          2 < c < 3 (sample c = 5/2): 6 isolated, 0 stable, 2 more stable in first approximation, and a curve of relative equilibria
          3 < c (sample c = 4): 6 relative equilibria, 2 stable, 2 more stable in first approximation
        sage: [cell.families() for cell in census.cells()]
        [[], [1], [1], []]
        sage: census.count_at({c: 10})
        (6, 2)
        sage: TestSuite(census).run(skip=['_test_pickling'])

    TESTS::

        sage: a = var('a')
        sage: leaf_census(H, C, J, x, [a], [c, 1])
        Traceback (most recent call last):
        ...
        AnalysisError: parameters: a is neither a symbol of H nor of the levels [c, 1]; the census can be over c
        sage: leaf_census(H, C, J, x, [c], [c])
        Traceback (most recent call last):
        ...
        AnalysisError: levels: give one level per Casimir (M1*g1 + M2*g2 + M3*g3, g1^2 + g2^2 + g3^2), e.g. levels=[c, 1]; got 1
        sage: leaf_census(H + a*g1, C, J, x, [c], [c, 1])
        Traceback (most recent call last):
        ...
        AnalysisError: values: give a value to a (the census is over c), e.g. values={a: 1}
        sage: leaf_census(H, C, J, x, [M1], [c, 1])
        Traceback (most recent call last):
        ...
        AnalysisError: parameters: M1 is a variable of the system, not a parameter

    The boundaries of the stability in first approximation
    (:func:`leaf_first_approximation_polynomials`) add no bifurcation value
    here: the roots of the linearization on the leaf collide only at
    complex `c`. The rotations about the first axis, `\gamma = \pm e_1`,
    are stable in first approximation for every `c \ne 1` (by the
    energy--Casimir method for `c < 1`); those about the third, `\gamma =
    \pm e_3`, by the energy--Casimir method for `c > 3` (their roots on the
    leaf are double: never stable in first approximation alone)::

        sage: census.bifurcation_set(first_approximation=True)
        [c - 1, c - 2, c - 3]
        sage: [(cell.count(), cell.stable_count(), cell.stable_count(first_approximation=True))
        ....:  for cell in census.cells(first_approximation=True)]
        [(6, 2, 2), (6, 0, 2), (6, 0, 2), (6, 2, 4)]
    """
    parameters, positive, values = census_arguments(parameters, positive, values)
    x = [SR(v) for v in variables]
    names = {str(v) for v in x}
    levels = [] if levels is None and not casimirs else levels
    if levels is None or len(levels) != len(casimirs):
        raise AnalysisError(f"give one level per Casimir ({', '.join(map(str, casimirs))}), e.g. "
                            f"levels=[{', '.join(['c'] + ['1'] * (len(casimirs) - 1))}]; got "
                            f"{'none' if levels is None else len(levels)}", entry="levels")
    own = _symbols([H] + list(matrix(SR, poisson_matrix).list()), names)
    leveled = _symbols(levels, names)
    for p in parameters:
        if str(p) in names:
            raise AnalysisError(f"{p} is a variable of the system, not a parameter",
                                entry="parameters")
        if str(p) not in own and str(p) not in leveled:
            raise AnalysisError(f"{p} is neither a symbol of H nor of the levels {list(levels)}; "
                                f"the census can be over {', '.join(sorted(set(own) | set(leveled)))}",
                                entry="parameters")
    check_values(set(own) | set(leveled), parameters, values)
    H = SR(H).subs(values)
    J = matrix(SR, poisson_matrix).subs(values)
    levels = [SR(c).subs(values) for c in levels]
    system = (H, list(casimirs), J, x, levels)

    def boundaries():
        # solved with the parameters symbolic only when asked (a discriminant
        # on each component of relative equilibria)
        return leaf_first_approximation_polynomials(H, casimirs, J, x, levels, parameters)
    what = "the relative equilibria on the levels " + \
        ", ".join(f"{C} = {c}" for C, c in zip(casimirs, levels))
    return Census(parameters, leaf_bifurcation_polynomials(H, casimirs, x, levels, parameters),
                  _leaf_task, lambda s: (system, s), boundaries, positive, executor=executor,
                  what=what)
