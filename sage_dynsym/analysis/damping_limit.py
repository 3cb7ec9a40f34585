r"""
The limit of vanishing damping: the destabilization paradox

Give the damping matrix a fixed shape, `D = \varepsilon D_0`, and let
`\varepsilon \to 0^+`. Every Liénard--Chipart condition of
`\det(M\lambda^2 + (\varepsilon D_0 + 2G)\lambda + K + P)` is a polynomial
`f(\varepsilon, a) = \varepsilon^k f_k(a) + O(\varepsilon^{k+1})` in
`\varepsilon` and the parameters `a`; for small `\varepsilon > 0` its sign
is that of its lowest coefficient `f_k(a)` (off the set where `f_k`
vanishes). The region where all lowest coefficients are positive is the
set of parameters at which the system is asymptotically stable for every
sufficiently small damping of that shape.

For circulatory systems this limit region is in general *smaller* than the
region of stability of the undamped system, and depends on the shape
`D_0`: the critical load of Ziegler's column with two equal small dampers
tends to `41/28\, k/l \approx 1.46\, k/l`, not to the undamped flutter load
`(7/2 - \sqrt2)\, k/l \approx 2.09\, k/l` (Ziegler 1952; Bottema 1956
explained it by the singularity of the stability boundary at `\varepsilon =
0`, a Whitney umbrella).

EXAMPLES::

    sage: from sage_dynsym.analysis.damping_limit import small_damping_limit
    sage: P, k, l, m = var('P k l m')
    sage: M = m*l^2*matrix([[3, 1], [1, 1]])
    sage: W = matrix([[2*k - P*l, P*l - k], [-k, k]])
    sage: D0 = matrix([[2, -1], [-1, 1]])                     # equal dampers at the joints
    sage: lim = small_damping_limit(M, D0, zero_matrix(2), (W + W.T)/2, (W - W.T)/2,
    ....:                           positive=[k, l, m]); lim
    Small damping of the shape [[2, -1], [-1, 1]]: asymptotically stable in the limit where [28*P*l - 41*k < 0]; without damping: depends on the parameters
    sage: lim.region()
    [[28*P*l - 41*k < 0]]
    sage: lim.critical_values(P)
    {'small damping limit': [41/28*k/l], 'undamped': [-sqrt(2)*k/l + 7/2*k/l]}

REFERENCES:

- H. Ziegler, Die Stabilitätskriterien der Elastomechanik, *Ing.-Arch.* 20
  (1952) 49--56.
- O. Bottema, The Routh--Hurwitz condition for the biquadratic equation,
  *Indag. Math.* 18 (1956) 403--406.
- O. N. Kirillov, *Nonconservative Stability Problems of Modern Physics*,
  De Gruyter, 2013, ch. 1 (Ziegler's paradox) and ch. 4.
"""
from sage.matrix.constructor import matrix
from sage.structure.sage_object import SageObject
from sage.symbolic.ring import SR

from ..arguments import symbol_arguments
from ..errors import AnalysisError
from .critical import critical_values
from ..algebra.determinants import fraction_free_det
from .kelvin_chetaev import kelvin_chetaev, force_matrices
from ..algebra.regions import simplify_region, prune_empty
from .spectrum import spectrum_regions

__all__ = ['DampingLimit', 'small_damping_limit']

_OPS = {'gt': lambda e: e > 0, 'lt': lambda e: e < 0, 'ne': lambda e: e != 0}


def _lowest(relation, eps):
    r"""The relation with its expression replaced by its lowest-order
    coefficient in ``eps`` (``None`` if it does not depend on a sign)."""
    op = relation.operator().__name__
    e = (relation.lhs() - relation.rhs()).expand()
    terms = [(k, c) for c, k in e.coefficients(eps) if not SR(c).is_zero()]
    k, c = min(terms, key=lambda t: t[0])
    if op not in _OPS:
        raise AnalysisError(f"unexpected relation {relation} in the limit of small damping",
                            entry="small_damping_limit")
    return _OPS[op](SR(c).factor())


class DampingLimit(SageObject):
    r"""
    The stability of `M\ddot q + (\varepsilon D_0 + 2G)\dot q + (K + P)q =
    0` for `\varepsilon \to 0^+`, beside that of the undamped system. Created
    by :func:`small_damping_limit`.

    EXAMPLES::

        sage: from sage_dynsym.analysis.damping_limit import small_damping_limit
        sage: k = var('k')
        sage: lim = small_damping_limit(matrix([[1]]), matrix([[1]]), matrix([[0]]), matrix([[k]]))
        sage: lim.region(), lim.undamped().verdict()
        ([[k > 0]], 'depends on the parameters')
        sage: TestSuite(lim).run(skip=['_test_pickling'])
    """

    def __init__(self, M, D0, G, K, P=None, positive=()):
        M, D0, G, K, P = force_matrices(M, D0, G, K, P)
        if D0.is_zero():
            raise AnalysisError("the shape of the damping matrix is zero", entry="damping")
        self._D0 = D0
        self._positive = symbol_arguments(positive, "positive", AnalysisError)
        eps = SR.symbol()
        lam = SR.symbol()
        chi = fraction_free_det(M * lam ** 2 + (eps * D0 + 2 * G) * lam + K + P,
                                positive=self._positive + [eps])
        spectrum = spectrum_regions(chi, lam, self._positive + [eps])
        damped = spectrum.asymptotic() or []
        region = [[_lowest(r, eps) for r in alt] for alt in damped]
        self._region = prune_empty(simplify_region(region, self._positive), self._positive)
        self._undamped = kelvin_chetaev(M, matrix(SR, M.nrows(), M.nrows()), G, K, P,
                                        positive=self._positive)

    def _repr_(self):
        region = " or ".join("[" + ", ".join(map(str, alt)) + "]" for alt in self._region)
        where = ("nowhere" if not self._region else "everywhere" if self._region == [[]]
                 else f"where {region}")
        shape = [list(row) for row in self._D0.rows()]
        return (f"Small damping of the shape {shape}: asymptotically stable in the limit "
                f"{where}; without damping: {self._undamped.verdict()}")

    def region(self):
        r"""
        Where the system is asymptotically stable for every small enough
        damping of the given shape: a list of alternatives, each a list of
        relations (``[]``: nowhere).

        EXAMPLES: a gyroscopically stabilized system is destabilized by
        any complete damping (Kelvin--Chetaev, 4th theorem)::

            sage: from sage_dynsym.analysis.damping_limit import small_damping_limit
            sage: g = var('g')
            sage: small_damping_limit(identity_matrix(2), identity_matrix(2),
            ....:                     matrix([[0, g], [-g, 0]]), -identity_matrix(2)).region()
            []
        """
        return [list(alt) for alt in self._region]

    def undamped(self):
        r"""The verdict of the undamped system (:func:`~sage_dynsym.analysis.kelvin_chetaev.kelvin_chetaev`).

        EXAMPLES::

            sage: from sage_dynsym.analysis.damping_limit import small_damping_limit
            sage: small_damping_limit(matrix([[1]]), matrix([[1]]), matrix([[0]]),
            ....:                     matrix([[1]])).undamped().verdict()
            'stable'
        """
        return self._undamped

    def boundaries(self):
        r"""The boundaries of the limit region: every factor of its
        conditions, as relations ``f == 0``.

        EXAMPLES::

            sage: from sage_dynsym.analysis.damping_limit import small_damping_limit
            sage: k = var('k')
            sage: small_damping_limit(matrix([[1]]), matrix([[1]]), matrix([[0]]),
            ....:                     matrix([[k]])).boundaries()
            [k == 0]
        """
        found = []
        for alt in self._region:
            for r in alt:
                b = (r.lhs() - r.rhs()) == 0
                if str(b) not in map(str, found):
                    found.append(b)
        return found

    def critical_values(self, parameter, values=None):
        r"""
        The critical values of ``parameter`` side by side: without damping
        (:meth:`~sage_dynsym.analysis.verdict.StabilityVerdict.critical_values`)
        and in the limit of small damping.

        INPUT:

        - ``parameter`` -- the parameter that varies (a load)
        - ``values`` -- (optional) values of the other parameters not
          declared positive

        OUTPUT: a dict with the keys ``'undamped'`` and ``'small damping
        limit'``, each a list of expressions

        EXAMPLES: see the module documentation.
        """
        return {'undamped': self._undamped.critical_values(parameter, values=values),
                'small damping limit': critical_values(
                    self._region, {'limit': self.boundaries()}, parameter,
                    positive=self._positive, values=values)}


def small_damping_limit(M, D, G, K, P=None, positive=()):
    r"""
    The stability of `M\ddot q + (\varepsilon D + 2G)\dot q + (K + P)q = 0`
    as `\varepsilon \to 0^+`, reported beside the undamped system (see the
    module documentation).

    INPUT:

    - ``M, G, K, P`` -- the matrices of the system (``P`` may be ``None``)
    - ``D`` -- the *shape* of the damping matrix (its scale goes to zero)
    - ``positive`` -- parameters declared positive

    OUTPUT: a :class:`DampingLimit`

    EXAMPLES: see the module documentation. A conservative system keeps
    its stability boundary::

        sage: from sage_dynsym.analysis.damping_limit import small_damping_limit
        sage: k = var('k')
        sage: small_damping_limit(identity_matrix(2), identity_matrix(2), zero_matrix(2),
        ....:                     diagonal_matrix([k, 1])).critical_values(k)
        {'small damping limit': [0], 'undamped': [0]}

    TESTS::

        sage: small_damping_limit(identity_matrix(2), zero_matrix(2), zero_matrix(2),
        ....:                     identity_matrix(2))
        Traceback (most recent call last):
        ...
        AnalysisError: damping: the shape of the damping matrix is zero
    """
    return DampingLimit(M, D, G, K, P, positive)
