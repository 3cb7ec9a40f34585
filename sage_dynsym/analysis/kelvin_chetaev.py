r"""
The Kelvin--Chetaev theorems on the influence of the structure of forces

For `M\ddot z + (D + 2G)\dot z + Kz = 0` with `M > 0` (no
non-conservative positional forces, `P = 0`) the stability of the
equilibrium is decided by the signs of `K` and `D` and the presence of `G`
(Thomson--Tait--Chetaev theorems, as in Merkin, ch. 6):

1. `K > 0` (isolated minimum of the potential energy): stable for any
   gyroscopic forces and any dissipation `D \ge 0` (Lagrange--Dirichlet;
   Kelvin's first theorem);
2. `K > 0` and complete dissipation `D > 0`: *asymptotically* stable, for
   any `G` (second theorem);
3. odd degree of instability (`\det K < 0`): unstable for any `G` and
   `D \ge 0`; gyroscopic stabilization is impossible (third theorem);
4. even degree of instability (`\det K > 0`, `K` not positive definite):
   unstable without gyroscopic forces; with `G \ne 0` and `D = 0`
   gyroscopic stabilization is *possible* -- it happens when the
   polynomial in `\lambda^2` of `\det(M\lambda^2 + 2G\lambda + K)` has only
   real negative roots (the conditions are given); complete dissipation
   `D > 0` destroys it: unstable (fourth theorem).

With symbolic parameters several cases may be possible; each is returned
with the conditions (``> 0``) under which it applies.

EXAMPLES:

An unstable potential `K = -\mathrm{diag}(a, b)` (even degree of
instability 2) stabilized by gyroscopic forces: the classical condition
`2g > \sqrt a + \sqrt b`, here in polynomial form (Merkin, §6.5)::

    sage: from sage_dynsym.analysis.kelvin_chetaev import kelvin_chetaev
    sage: a, b, g = var('a b g')
    sage: M = identity_matrix(SR, 2); Z = zero_matrix(SR, 2)
    sage: G = matrix([[0, g], [-g, 0]]); K = diagonal_matrix([-a, -b])
    sage: v = kelvin_chetaev(M, Z, G, K, Z, positive=[a, b]); v
    gyroscopic stabilization possible if [4*g^2 - a - b, 16*g^4 - 8*a*g^2 - 8*b*g^2 + a^2 - 2*a*b + b^2]: even degree of instability (2) of the potential energy, gyroscopic forces present, no dissipation (Kelvin-Chetaev, 4th theorem); stable in the first approximation under the conditions
    sage: v.verdict(), v.conditions()
    ('gyroscopic stabilization possible',
     [4*g^2 - a - b, 16*g^4 - 8*a*g^2 - 8*b*g^2 + a^2 - 2*a*b + b^2])

With complete dissipation the stabilization is destroyed::

    sage: c = var('c')
    sage: kelvin_chetaev(M, c*M, G, K, Z, positive=[a, b, c]).verdict()
    'destroyed by dissipation'

REFERENCES:

- D. R. Merkin, *Introduction to the Theory of Stability*, Springer, 1997,
  ch. 6 (Kelvin--Chetaev theorems, gyroscopic stabilization).
- N. G. Chetaev, *The Stability of Motion*, Pergamon, 1961, ch. V.
- W. Thomson (Lord Kelvin), P. G. Tait, *Treatise on Natural Philosophy*,
  §345.
"""
from sage.matrix.constructor import matrix
from sage.structure.sage_object import SageObject
from sage.symbolic.ring import SR

from .hurwitz import simplify_conditions, conservative_stability_conditions
from .quadratic_forms import sylvester_conditions, _det


class StabilityVerdict(SageObject):
    r"""
    The outcome of a stability test: a verdict, the conditions (all
    ``> 0``) under which it holds, and the reason in plain language.

    ``verdict()`` is one of ``'asymptotically stable'``, ``'stable'``,
    ``'unstable'``, ``'gyroscopic stabilization possible'``, ``'destroyed
    by dissipation'``, ``'undecided'``. When several cases are possible for
    different parameter values, the verdict is ``'undecided'`` (or
    ``'depends on the parameters'``) and :meth:`cases` lists them.

    A verdict may also carry the method that decided it (:meth:`method`)
    and a *region* (:meth:`region`): a list of alternatives, each a list of
    relationals, under which it holds.

    EXAMPLES::

        sage: from sage_dynsym.analysis.kelvin_chetaev import StabilityVerdict, kelvin_chetaev
        sage: a = var('a')
        sage: StabilityVerdict('stable', 'the potential energy has a minimum', conditions=[a])
        stable if [a]: the potential energy has a minimum
        sage: kelvin_chetaev(matrix([[1]]), matrix([[0]]), matrix([[0]]), matrix([[-1]]))
        unstable: the potential energy has an odd degree of instability (1): ...
    """

    def __init__(self, verdict, reason, conditions=(), cases=(), method=None,
                 region=None):
        self._verdict = verdict
        self._reason = reason
        self._conditions = list(conditions)
        self._cases = list(cases)
        self._method = method
        self._region = region

    def method(self):
        r"""The method that decided the verdict (``None`` if not recorded).

        EXAMPLES::

            sage: from sage_dynsym.analysis.kelvin_chetaev import StabilityVerdict
            sage: StabilityVerdict('stable', 'K > 0', method='Routh-Lyapunov').method()
            'Routh-Lyapunov'
        """
        return self._method

    def region(self):
        r"""Where the verdict holds: a list of alternatives, each a list of
        relationals (``[[]]``: everywhere); ``None`` if not recorded.

        EXAMPLES::

            sage: from sage_dynsym.analysis.kelvin_chetaev import StabilityVerdict
            sage: a = var('a')
            sage: StabilityVerdict('stable', 'K > 0', region=[[a > 0]]).region()
            [[a > 0]]
        """
        return None if self._region is None else [list(alt) for alt in self._region]

    def verdict(self):
        r"""The verdict (a string).

        EXAMPLES::

            sage: from sage_dynsym.analysis.kelvin_chetaev import kelvin_chetaev
            sage: v = kelvin_chetaev(matrix([[1]]), matrix([[0]]), matrix([[0]]), matrix([[-1]]))
            sage: v.verdict()
            'unstable'
        """
        return self._verdict

    def reason(self):
        r"""Why, in plain language, with the theorem used.

        EXAMPLES::

            sage: from sage_dynsym.analysis.kelvin_chetaev import kelvin_chetaev
            sage: v = kelvin_chetaev(matrix([[1]]), matrix([[0]]), matrix([[0]]), matrix([[-1]]))
            sage: v.reason()
            'the potential energy has an odd degree of instability (1): no gyroscopic or dissipative forces can stabilize it (Kelvin-Chetaev, 3rd theorem)'
        """
        return self._reason

    def conditions(self):
        r"""Conditions (expressions ``> 0``) under which the verdict holds.

        EXAMPLES::

            sage: from sage_dynsym.analysis.kelvin_chetaev import kelvin_chetaev
            sage: v = kelvin_chetaev(matrix([[1]]), matrix([[0]]), matrix([[0]]), matrix([[-1]]))
            sage: v.conditions()
            []
        """
        return list(self._conditions)

    def cases(self):
        r"""The possible cases (each a :class:`StabilityVerdict`).

        EXAMPLES::

            sage: from sage_dynsym.analysis.kelvin_chetaev import kelvin_chetaev
            sage: v = kelvin_chetaev(matrix([[1]]), matrix([[0]]), matrix([[0]]), matrix([[-1]]))
            sage: len(v.cases())
            1
        """
        return list(self._cases) if self._cases else [self]

    def _repr_(self):
        cond = f" if {self._conditions}" if self._conditions else ""
        if self._region is not None and self._region != [[]]:
            cond = " where " + " or ".join(
                "[" + ", ".join(map(str, alt)) + "]" for alt in self._region)
        return f"{self._verdict}{cond}: {self._reason}"


def _impossible(conds):
    return len(conds) == 1 and SR(conds[0]).is_constant()


def _possible(conds):
    return not _impossible(conds)


def kelvin_chetaev(M, D, G, K, P=None, positive=()):
    r"""
    Stability of the zero solution of `M\ddot z + (D + 2G)\dot z + (K + P)
    z = 0` from the structure of forces.

    INPUT:

    - ``M, D, G, K, P`` -- the matrices (see
      :class:`~sage_dynsym.analysis.linear.LinearSystem`); ``P`` may be
      ``None`` or zero
    - ``positive`` -- parameters known to be positive

    OUTPUT: a :class:`StabilityVerdict`

    EXAMPLES:

    A damped pendulum (`K = mgl > 0`, `D = c > 0`)::

        sage: from sage_dynsym.analysis.kelvin_chetaev import kelvin_chetaev
        sage: m, g, l, c = var('m g l c')
        sage: kelvin_chetaev(matrix([[m*l^2]]), matrix([[c]]), matrix([[0]]),
        ....:                matrix([[m*g*l]]), positive=[m, g, l, c]).verdict()
        'asymptotically stable'
        sage: kelvin_chetaev(matrix([[m*l^2]]), matrix([[c]]), matrix([[0]]),
        ....:                matrix([[-m*g*l]]), positive=[m, g, l, c])
        unstable: the potential energy has an odd degree of instability (1): no gyroscopic or dissipative forces can stabilize it (Kelvin-Chetaev, 3rd theorem)

    With a symbolic stiffness both cases remain::

        sage: k = var('k')
        sage: v = kelvin_chetaev(matrix([[m]]), matrix([[0]]), matrix([[0]]),
        ....:                    matrix([[k]]), positive=[m]); v.verdict()
        'undecided'
        sage: v.cases()
        [stable if [k]: the potential energy has an isolated minimum (K > 0)...,
         unstable if [-k]: the potential energy has an odd degree of instability...]

    Non-conservative positional forces are outside the theorems::

        sage: p = var('p')
        sage: kelvin_chetaev(identity_matrix(2), zero_matrix(2), zero_matrix(2),
        ....:                identity_matrix(2), matrix([[0, p], [-p, 0]])).verdict()
        'undecided'
    """
    M, D, G, K = (matrix(SR, X) for X in (M, D, G, K))
    n = M.nrows()
    P = matrix(SR, n, n) if P is None else matrix(SR, P)
    cM = sylvester_conditions(M, positive=positive)
    if _impossible(cM):
        return StabilityVerdict('undecided', "the kinetic matrix M is not positive "
                                "definite; the Kelvin-Chetaev theorems do not apply")
    if not P.is_zero():
        return StabilityVerdict('undecided', "non-conservative positional forces "
                                "(P != 0) are present; the Kelvin-Chetaev theorems do "
                                "not apply: use the Hurwitz or Liénard-Chipart "
                                "conditions of the characteristic polynomial")
    cases = []
    cK = sylvester_conditions(K, positive=positive)
    detK = _det(K).expand()
    has_G = not G.is_zero()
    has_D = not D.is_zero()
    cD = sylvester_conditions(D, positive=positive) if has_D else [SR(-1)]
    complete = has_D and not _impossible(cD)
    if _possible(cK):
        if complete:
            cases.append(StabilityVerdict(
                'asymptotically stable',
                "the potential energy has an isolated minimum (K > 0) and the "
                "dissipation is complete (D > 0), whatever the gyroscopic forces "
                "(Kelvin-Chetaev, 2nd theorem)", simplify_conditions(cK + cD, positive)))
        else:
            what = ("partial dissipation (D >= 0 assumed)" if has_D else
                    "no dissipation")
            cases.append(StabilityVerdict(
                'stable',
                "the potential energy has an isolated minimum (K > 0); "
                f"{what}; gyroscopic forces cannot destroy this stability "
                "(Lagrange-Dirichlet, Kelvin-Chetaev 1st theorem)", cK))
    odd = simplify_conditions([-detK], positive)
    if _possible(odd):
        cases.append(StabilityVerdict(
            'unstable',
            "the potential energy has an odd degree of instability"
            + (" (1)" if n == 1 or not odd else "")
            + ": no gyroscopic or dissipative forces can stabilize it "
            "(Kelvin-Chetaev, 3rd theorem)", odd))
    even = simplify_conditions([detK], positive)
    if n > 1 and _possible(even) and cK:
        neg_def = sylvester_conditions(K, sign='negative', positive=positive)
        degree = f" ({n})" if not neg_def and n % 2 == 0 else ""
        base = f"even degree of instability{degree} of the potential energy"
        if not has_G:
            cases.append(StabilityVerdict(
                'unstable', base + ", no gyroscopic forces: unstable (Kelvin-Chetaev, "
                "4th theorem; a real positive root)", even))
        elif complete:
            cases.append(StabilityVerdict(
                'destroyed by dissipation', base + ", gyroscopic forces present, "
                "complete dissipation (D > 0) destroys any gyroscopic "
                "stabilization: unstable (Kelvin-Chetaev, 4th theorem)", even + cD))
        else:
            lam = SR.var('lambda_')
            poly = (M * lam ** 2 + 2 * G * lam + K).det().expand()
            gyro = conservative_stability_conditions(poly, lam, positive=positive)
            conds = simplify_conditions(even + gyro, positive)
            if _possible(conds):
                cases.append(StabilityVerdict(
                    'gyroscopic stabilization possible',
                    base + ", gyroscopic forces present, no dissipation (Kelvin-"
                    "Chetaev, 4th theorem); stable in the first approximation "
                    "under the conditions", conds))
            else:
                cases.append(StabilityVerdict(
                    'unstable', base + ": the gyroscopic forces are too weak to "
                    "stabilize (the polynomial in lambda^2 has non-real or positive "
                    "roots)", even))
    if len(cases) == 1:
        return cases[0]
    if not cases:
        return StabilityVerdict('undecided', "none of the Kelvin-Chetaev cases "
                                "could be established (critical case det K = 0?)")
    return StabilityVerdict('undecided', "depends on the parameters; see cases()",
                            cases=cases)
