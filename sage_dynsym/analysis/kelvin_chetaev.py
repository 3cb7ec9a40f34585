r"""
Stability of `M\ddot q + (D + 2G)\dot q + (K + P)q = 0` (``G`` half the skew
part of the velocity matrix): the structure of forces and the first
approximation

For a linear (or linearized) mechanical system with `M > 0` (kinetic),
`D = D^T` (dissipative), `G = -G^T` (gyroscopic), `K = K^T` (potential)
and `P = -P^T` (circulatory, non-conservative positional) forces,
:func:`kelvin_chetaev` gives a :class:`~sage_dynsym.analysis.verdict.StabilityVerdict`
for every such system, exact, with the regions of the parameters where each
verdict holds:

- **Kelvin's theorems** (Thomson--Tait--Chetaev; Merkin, ch. 6), for
  `P = 0`: with an isolated minimum of the potential energy (`K > 0`) the
  equilibrium is *stable* for any gyroscopic forces and any dissipation `D
  \ge 0` (Lagrange--Dirichlet; 1st theorem), *asymptotically stable* with
  complete dissipation `D > 0` (2nd theorem); an *odd* degree of
  instability (`\det K < 0`) cannot be stabilized by any gyroscopic or
  dissipative forces (3rd theorem); an *even* one can be stabilized by
  gyroscopic forces (``'stable in first approximation'``, under exact
  conditions), and complete dissipation destroys that (4th theorem).
- **Gyroscopic stabilization** and **circulatory systems** without damping:
  the characteristic polynomial is even, and the linearized system is stable
  iff its polynomial in `\mu = \lambda^2` has only real, negative, simple
  roots (:mod:`~sage_dynsym.analysis.spectrum`); its boundaries are
  *flutter* (two roots meet on the imaginary axis: the discriminant
  vanishes) and *divergence* (a root through zero: `\det(K + P) = 0`).
  With both gyroscopic and circulatory forces and no damping the roots are
  on the imaginary axis only where every odd coefficient vanishes.
- **Damped systems**: the Liénard--Chipart conditions (asymptotic
  stability), and otherwise a root with positive real part.

The first approximation decides asymptotic stability and instability for
the nonlinear system too (Lyapunov); ``'stable in first approximation'``
leaves the nonlinear system open (a critical case), while ``'stable'``
comes from the energy, a Lyapunov function of the nonlinear mechanical
system as well. The parts are disjoint, in this precedence:
asymptotically stable, stable, stable in first approximation, undecided,
unstable (the rest); the boundaries belong to none. The conditions for
the kinetic matrix to be positive definite, if any, are part of every
region; with an indefinite (nonsingular) `M` -- not a mechanical system --
the first approximation alone decides.

EXAMPLES:

**Ziegler's column** (two rigid rods of length `l` with springs `k` at the
joints, masses `2m` and `m`, a follower load `P` at the free end; Ziegler
1952): undamped, stable in first approximation up to the flutter load `P =
(7/2 - \sqrt 2)\,k/l`::

    sage: from sage_dynsym.analysis.kelvin_chetaev import kelvin_chetaev
    sage: P, k, l, m = var('P k l m')
    sage: M = m*l^2*matrix([[3, 1], [1, 1]])
    sage: W = matrix([[2*k - P*l, P*l - k], [-k, k]])        # K + P, the load is not conservative
    sage: v = kelvin_chetaev(M, zero_matrix(2), zero_matrix(2), (W + W.T)/2, (W - W.T)/2,
    ....:                    positive=[k, l, m])
    sage: v.verdict()
    'depends on the parameters'
    sage: for case in v.cases(): print(case.verdict(), case.region())
    stable in first approximation [[2*P*l - 7*k < 0, 4*P^2*l^2 - 28*P*k*l + 41*k^2 > 0]]
    unstable [[2*P*l - 7*k > 0], [4*P^2*l^2 - 28*P*k*l + 41*k^2 < 0]]
    sage: v.boundaries()
    {'flutter': [4*P^2*l^2 - 28*P*k*l + 41*k^2 == 0]}
    sage: v.critical_values(P)
    [-sqrt(2)*k/l + 7/2*k/l]

**Gyroscopic stabilization** of an unstable potential `K = -\mathrm{diag}(a,
b)` (degree of instability 2): stable in first approximation iff `2g >
\sqrt a + \sqrt b` -- here in polynomial form (Merkin, §6.5)::

    sage: a, b, g = var('a b g')
    sage: I2 = identity_matrix(SR, 2); Z = zero_matrix(SR, 2)
    sage: G = matrix([[0, g], [-g, 0]]); K = diagonal_matrix([-a, -b])
    sage: v = kelvin_chetaev(I2, Z, G, K, positive=[a, b]); v.verdict()
    'depends on the parameters'
    sage: v.region()
    [[4*g^2 - a - b > 0, 16*g^4 - 8*a*g^2 - 8*b*g^2 + a^2 - 2*a*b + b^2 > 0]]
    sage: v.at({a: 1, b: 1, g: 2}), v.at({a: 1, b: 1, g: 1/2})
    ('stable in first approximation', 'unstable')

With complete dissipation the stabilization is destroyed (Kelvin--Chetaev,
4th theorem)::

    sage: c = var('c')
    sage: kelvin_chetaev(I2, c*I2, G, K, positive=[a, b, c]).verdict()
    'unstable'

A damped pendulum, and the inverted one (odd degree of instability)::

    sage: kelvin_chetaev(matrix([[1]]), matrix([[c]]), matrix([[0]]), matrix([[1]]),
    ....:                positive=[c]).verdict()
    'asymptotically stable'
    sage: kelvin_chetaev(matrix([[1]]), matrix([[c]]), matrix([[0]]), matrix([[-1]]),
    ....:                positive=[c])
    unstable: the potential energy has an odd degree of instability (1): ...

REFERENCES:

- D. R. Merkin, *Introduction to the Theory of Stability*, Springer, 1997,
  ch. 6 (Kelvin--Chetaev theorems, gyroscopic stabilization,
  non-conservative positional forces).
- N. G. Chetaev, *The Stability of Motion*, Pergamon, 1961, ch. V.
- W. Thomson (Lord Kelvin), P. G. Tait, *Treatise on Natural Philosophy*,
  §345.
- H. Ziegler, Die Stabilitätskriterien der Elastomechanik, *Ing.-Arch.* 20
  (1952) 49--56; *Principles of Structural Stability*, Blaisdell, 1968.
- O. N. Kirillov, *Nonconservative Stability Problems of Modern Physics*,
  De Gruyter, 2013, ch. 1.
"""
from sage.matrix.constructor import matrix, block_matrix, identity_matrix
from sage.symbolic.ring import SR

from ..arguments import matrix_argument, symbol_arguments
from ..errors import AnalysisError
from ..algebra.determinants import fraction_free_det
from .quadratic_forms import definiteness_conditions, semidefiniteness_conditions
from ..algebra.regions import simplify_region, negation, intersection
from ..algebra.solving import normalize
from .spectrum import spectrum_regions
from .verdict import StabilityVerdict, verdict_from_parts

__all__ = ['force_matrices', 'state_matrix', 'kelvin_chetaev', 'StabilityVerdict']


def force_matrices(M, D, G, K, P=None):
    r"""
    The matrices `M, D, G, K, P` of the forces of `M\ddot q + (D + 2G)\dot q
    + (K + P)q = 0` over ``SR``, checked to be square of the same size
    (``P = None`` is the zero matrix).

    EXAMPLES::

        sage: from sage_dynsym.analysis.kelvin_chetaev import force_matrices
        sage: m, k = var('m k')
        sage: force_matrices([[m]], [[0]], [[0]], [[k]])
        ([m], [0], [0], [k], [0])
        sage: force_matrices(identity_matrix(2), zero_matrix(2), zero_matrix(2), [[k]])
        Traceback (most recent call last):
        ...
        AnalysisError: kelvin_chetaev: K is 1x1, expected 2x2 like M
    """
    M, D, G, K = (matrix_argument(X, name, AnalysisError, entry="kelvin_chetaev",
                                  expected=f"the matrix {name} (a Sage matrix or a list of rows)",
                                  hint="lin.kelvin_chetaev() takes them from a linearization")
                  .change_ring(SR) for X, name in ((M, 'M'), (D, 'D'), (G, 'G'), (K, 'K')))
    n = M.nrows()
    P = matrix(SR, n, n) if P is None else \
        matrix_argument(P, 'P', AnalysisError, entry="kelvin_chetaev").change_ring(SR)
    for name, X in (('M', M), ('D', D), ('G', G), ('K', K), ('P', P)):
        if X.nrows() != n or X.ncols() != n:
            raise AnalysisError(f"{name} is {X.nrows()}x{X.ncols()}, expected {n}x{n} "
                                "like M", entry="kelvin_chetaev")
    return M, D, G, K, P


def state_matrix(M, S, W):
    r"""
    The matrix `A` of `\dot x = Ax`, `x = (q, \dot q)`, for `M\ddot q +
    S\dot q + Wq = 0`.

    EXAMPLES::

        sage: from sage_dynsym.analysis.kelvin_chetaev import state_matrix
        sage: m, c, k = var('m c k')
        sage: state_matrix(matrix([[m]]), matrix([[c]]), matrix([[k]]))
        [   0    1]
        [-k/m -c/m]
    """
    n = M.nrows()
    Mi = M.inverse()
    return block_matrix(SR, [[matrix(SR, n, n), identity_matrix(SR, n)],
                             [-Mi * W, -Mi * S]], subdivide=False)


def _possible(conditions):
    return conditions is not None


def _reasons(M, D, G, K, P, spectrum, positive, mechanical=True):
    r"""The reason of each verdict, from the structure of forces (the
    theorems on it only for a mechanical system, `M > 0`)."""
    n = M.nrows()
    has_D, has_G = not D.is_zero(), not G.is_zero()
    has_P = not P.is_zero() or not mechanical       # no Kelvin-Chetaev theorems then
    complete = has_D and _possible(definiteness_conditions(D, positive=positive))
    detK = fraction_free_det(K)
    odd = not has_P and _possible(simplify_region([[detK < 0]], positive) or None)
    odd_always = odd and simplify_region([[detK < 0]], positive) == [[]]
    root = "a root of the characteristic polynomial has a positive real part " \
        "(Lyapunov's theorem on the first approximation)"
    unstable = []
    if odd:
        negative = 1 if n == 1 else _negative_eigenvalues(K)
        degree = f" ({negative})" if negative is not None else ""
        where = "" if odd_always else "where det K < 0 "
        unstable.append(f"{where}the potential energy has an odd degree of instability"
                        f"{degree}: no gyroscopic or dissipative forces can stabilize it "
                        "(Thomson-Tait-Chetaev; Kelvin-Chetaev, 3rd theorem)")
    if not has_P and has_G and complete and not odd_always and n > 1:
        unstable.append("complete dissipation destroys the gyroscopic stabilization of an "
                        "even degree of instability (Kelvin-Chetaev, 4th theorem)")
    if not has_P and not has_G and not odd_always and n > 1:
        unstable.append("an even degree of instability without gyroscopic forces stays "
                        "unstable (Kelvin-Chetaev, 4th theorem)")
    if has_P and mechanical and not has_D:
        unstable.append("circulatory forces beyond the flutter boundary (two roots meet "
                        "on the imaginary axis and leave it) or the divergence boundary "
                        "(a real root through zero)")
    if not has_D and spectrum.symmetric_degree() == 0:
        unstable.append("without damping the roots sum to zero: a root off the imaginary "
                        "axis has a positive real part")
    unstable.append(root)
    if odd_always:
        unstable = unstable[:1]
    asymptotic = "every root of the characteristic polynomial has a negative real part " \
        "(Liénard-Chipart conditions; Lyapunov's theorem on the first approximation)"
    if not has_P and complete:
        asymptotic += "; with K > 0 and complete dissipation D > 0 this is the 2nd " \
            "theorem of Kelvin-Chetaev"
    total = 2 * n - spectrum.symmetric_degree() - spectrum.zero_roots()
    marginal = ("every root of the characteristic polynomial is on the imaginary axis and "
                "simple" if total == 0 else
                "the roots of the characteristic polynomial that come in pairs +-lambda are "
                "on the imaginary axis and simple, the others have negative real parts")
    marginal += ": the linearized system is stable, not asymptotically; the first " \
        "approximation does not decide the stability of the nonlinear system (critical case)"
    if not has_P and has_G and not has_D:
        marginal += "; where K is not positive definite this is gyroscopic stabilization " \
            "of an even degree of instability (Thomson-Tait-Chetaev), destroyed by any " \
            "complete dissipation (Kelvin-Chetaev, 4th theorem)"
    if has_P and mechanical and not has_D:
        marginal += "; circulatory forces: inside the flutter and divergence boundaries " \
            "(small damping may lower the flutter boundary: small_damping_limit)"
    if not has_D and spectrum.symmetric_degree() == 0:
        marginal += "; without damping this happens only where every odd coefficient " \
            "vanishes"
    return {
        'asymptotically stable': asymptotic,
        'stable': "the total energy is a Lyapunov function: the potential energy has an "
                  "isolated minimum (K > 0), the dissipation is nonnegative (D >= 0) and "
                  "gyroscopic forces cannot destroy this stability (Lagrange-Dirichlet; "
                  "Kelvin-Chetaev, 1st theorem)",
        'stable in first approximation': marginal,
        'undecided': "every root is in the closed left half-plane, but a multiple root on "
                     "the imaginary axis is not semisimple: the linearized solutions grow "
                     "like t, and the nonlinear terms decide",
        'unstable': "; ".join(unstable),
    }


def _negative_eigenvalues(K):
    r"""The number of negative eigenvalues of a numerical ``K`` (``None``
    for a symbolic one)."""
    if any(SR(x).variables() for x in K.list()):
        return None
    from sage.rings.qqbar import AA
    try:
        return sum(1 for e in K.change_ring(AA).eigenvalues() if e < 0)
    except (TypeError, ValueError):
        return None


def kelvin_chetaev(M, D, G, K, P=None, positive=()):
    r"""
    ``G`` is HALF the skew part of the velocity matrix: the system is
    `M\ddot z + (D + 2G)\dot z + (K + P) z = 0` (for the matrices of one's
    own equations `M\ddot z + S\dot z + Wz = 0` use
    :meth:`LinearSystem.from_equations(M, S, W)
    <sage_dynsym.analysis.linear.LinearSystem.from_equations>` and its
    :meth:`~sage_dynsym.analysis.linear.LinearSystem.stability`). The
    stability of its zero solution, exact, with the regions of the
    parameters (see the module documentation).

    INPUT:

    - ``M, D, G, K, P`` -- the square matrices (see
      :class:`~sage_dynsym.analysis.linear.LinearSystem`); ``P`` may be
      ``None`` (zero)
    - ``positive`` -- parameters declared positive

    OUTPUT: a :class:`~sage_dynsym.analysis.verdict.StabilityVerdict`:
    ``'asymptotically stable'``, ``'stable'``, ``'stable in first
    approximation'``, ``'unstable'`` or ``'undecided'`` (with the region
    where it holds, ``[[]]`` for everywhere), or ``'depends on the
    parameters'`` with :meth:`~sage_dynsym.analysis.verdict.StabilityVerdict.cases`
    and the stable set as its region; ``boundaries()`` gives the flutter
    and divergence boundaries

    EXAMPLES: see the module documentation. A conservative system with a
    symbolic stiffness::

        sage: from sage_dynsym.analysis.kelvin_chetaev import kelvin_chetaev
        sage: m, k = var('m k')
        sage: v = kelvin_chetaev(matrix([[m]]), matrix([[0]]), matrix([[0]]),
        ....:                    matrix([[k]]), positive=[m])
        sage: v.verdict()
        'depends on the parameters'
        sage: [(case.verdict(), case.region()) for case in v.cases()]
        [('stable', [[k > 0]]), ('unstable', [[k < 0]])]

    An undamped system with gyroscopic and circulatory forces: unstable
    except where their product vanishes (Kirillov, 2013, ch. 1)::

        sage: g, p = var('g p')
        sage: v = kelvin_chetaev(identity_matrix(2), zero_matrix(2), matrix([[0, g], [-g, 0]]),
        ....:                    diagonal_matrix([1, 2]), matrix([[0, p], [-p, 0]]))
        sage: [(case.verdict(), case.region()) for case in v.cases()]
        [('stable in first approximation',
          [[16*g^4 + 24*g^2 - 4*p^2 + 1 > 0, g*p == 0]]),
         ('unstable', [[16*g^4 + 24*g^2 - 4*p^2 + 1 < 0], [p != 0, g != 0]])]

    TESTS: an indefinite kinetic matrix (not a mechanical system: the first
    approximation alone), and a singular one::

        sage: kelvin_chetaev(matrix([[1, 0], [0, -1]]), zero_matrix(2), zero_matrix(2),
        ....:                identity_matrix(2)).verdict()
        'unstable'
        sage: kelvin_chetaev(matrix([[1, 0], [0, 0]]), zero_matrix(2), zero_matrix(2),
        ....:                identity_matrix(2))
        Traceback (most recent call last):
        ...
        AnalysisError: kelvin_chetaev: the kinetic matrix M = [(1, 0), (0, 0)] is singular: the equations are not of second order in every coordinate
        sage: kelvin_chetaev(identity_matrix(2), zero_matrix(2), zero_matrix(2), matrix([[1]]))
        Traceback (most recent call last):
        ...
        AnalysisError: kelvin_chetaev: K is 1x1, expected 2x2 like M
    """
    M, D, G, K, P = force_matrices(M, D, G, K, P)
    positive = symbol_arguments(positive, "positive", AnalysisError)
    kinetic = definiteness_conditions(M, positive=positive)
    mechanical = kinetic is not None
    if not mechanical:
        # not a mechanical system: the first approximation still decides,
        # the theorems on the structure of forces do not apply
        if normalize(fraction_free_det(M)).is_zero():
            raise AnalysisError(f"the kinetic matrix M = {list(M)} is singular: the "
                                "equations are not of second order in every coordinate",
                                entry="kelvin_chetaev")
        kinetic = []
    domain = [kinetic]
    S, W = D + 2 * G, K + P
    lam = SR.symbol()
    chi = fraction_free_det(M * lam ** 2 + S * lam + W, positive=positive)
    spectrum = spectrum_regions(chi, lam, positive, matrix=state_matrix(M, S, W))
    asymptotic, marginal = spectrum.asymptotic(), spectrum.marginal()
    kelvin = None
    if mechanical and P.is_zero():
        K_definite = definiteness_conditions(K, positive=positive)
        D_semidefinite = semidefiniteness_conditions(D, positive=positive)
        if D_semidefinite is not None:
            # Kelvin's theorems: with D >= 0 and det K != 0 asymptotic stability
            # needs K > 0, and so does any stability without gyroscopic forces
            outside = negation([D_semidefinite], positive) or []
            needs_K = ([K_definite] if K_definite is not None else []) + outside + \
                [[fraction_free_det(K) == 0]]
            asymptotic = intersection(asymptotic, needs_K, positive) if asymptotic else None
            if G.is_zero() and marginal:
                marginal = intersection(marginal, needs_K, positive)
            if K_definite is not None:
                kelvin = [K_definite + D_semidefinite]
    parts = [('asymptotically stable', asymptotic), ('stable', kelvin),
             ('stable in first approximation', marginal),
             ('undecided', spectrum.undecided())]
    return verdict_from_parts(parts, _reasons(M, D, G, K, P, spectrum, positive, mechanical),
                              spectrum.boundaries(), positive, domain=domain,
                              methods={'stable': 'Kelvin-Chetaev'})
