r"""
Where the roots of a characteristic polynomial lie: the left half-plane
and the imaginary axis

The zero solution of a linear system with characteristic polynomial
`\chi(\lambda)` (real coefficients, polynomial in parameters) is

- *asymptotically stable* iff every root has a negative real part: the
  Liénard--Chipart conditions of `\chi`;
- *stable (not asymptotically)* iff every root is in the closed left
  half-plane and those on the imaginary axis are semisimple (as many
  eigenvectors as their multiplicity).

Roots on the imaginary axis, `\pm i\omega`, are roots of both `\chi(\lambda)`
and `\chi(-\lambda)`. So `\chi` is split into

.. MATH::

    \chi(\lambda) = \lambda^z\, E(\lambda)\, R(\lambda), \qquad
    E = \gcd\big(\chi_1(\lambda), \chi_1(-\lambda)\big),

with `z` the roots at zero for all parameter values and `\chi_1 = \chi /
\lambda^z`: the *symmetric factor* `E` (an even polynomial: its roots come
in pairs `\pm\lambda`) and the rest `R`, whose roots are never symmetric
for generic parameter values. Then:

- if `E` is constant and `z = 0`: asymptotic stability iff the
  Liénard--Chipart conditions of `\chi` hold; otherwise a root has a
  positive real part -- or, when the coefficient of `\lambda^{N-1}` is
  identically zero (no damping: the roots sum to zero), every root is on
  the imaginary axis, which happens only where every odd coefficient
  vanishes (a set given by equations);
- otherwise asymptotic stability is impossible, and the system is stable
  in first approximation iff the roots of `E` are on the imaginary axis and
  simple -- its polynomial in `\mu = \lambda^2` has only real, negative,
  simple roots (:func:`~sage_dynsym.analysis.hurwitz.real_negative_roots_conditions`,
  by the Hermite--Biehler theorem) --, `R` satisfies the Liénard--Chipart
  conditions, and the roots at zero and the repeated factors of `E`, if
  any, are semisimple (checked by ranks of the state matrix over the field
  of the parameters); where they are not, the first approximation does not
  decide.

Each polynomial condition is sign-correct whatever the sign of a leading
coefficient: the conditions are those of the polynomial multiplied by its
leading coefficient (Hurwitz determinants scale by powers of it).

The boundaries of the stable set are named: *divergence* where a real
root passes through zero (the constant coefficient, `\det(K + P)` for a
mechanical system, vanishes) and *flutter* where two roots meet on the
imaginary axis and leave it (the discriminant of the polynomial in `\mu`,
or the Hurwitz determinant `\Delta_{N-1}` with damping).

EXAMPLES: Ziegler's column without damping (see
:mod:`~sage_dynsym.analysis.kelvin_chetaev`): `\chi` is even, so `E =
\chi`::

    sage: from sage_dynsym.analysis.spectrum import spectrum_regions
    sage: lam, P, k, l, m = var('lam P k l m')
    sage: chi = 2*l^4*m^2*lam^4 - (2*P*l - 7*k)*l^2*m*lam^2 + k^2
    sage: S = spectrum_regions(chi, lam, positive=[k, l, m]); S
    Spectrum of 2*l^4*lam^4*m^2 - (2*P*l - 7*k)*l^2*lam^2*m + k^2: symmetric factor of degree 4
    sage: S.asymptotic(), S.marginal()
    (None, [[2*P*l - 7*k < 0, 4*P^2*l^2 - 28*P*k*l + 41*k^2 > 0]])
    sage: S.boundaries()
    {'flutter': [4*P^2*l^2 - 28*P*k*l + 41*k^2 == 0]}

A damped oscillator: no symmetric factor; asymptotically stable where the
Liénard--Chipart conditions hold::

    sage: c = var('c')
    sage: S = spectrum_regions(m*lam^2 + c*lam + k, lam, positive=[m, k]); S.asymptotic()
    [[c > 0]]
    sage: S.marginal(), S.boundaries()
    (None, {'flutter': [c == 0]})

REFERENCES:

- F. R. Gantmacher, *The Theory of Matrices*, vol. 2, Chelsea, 1959,
  ch. XV (Routh--Hurwitz, Liénard--Chipart, Hermite--Biehler).
- D. R. Merkin, *Introduction to the Theory of Stability*, Springer, 1997,
  ch. 5 and 6.
- O. N. Kirillov, *Nonconservative Stability Problems of Modern Physics*,
  De Gruyter, 2013, ch. 1 and 2 (flutter and divergence, the
  characteristic polynomial on the imaginary axis).
"""
from sage.matrix.constructor import identity_matrix
from sage.rings.fraction_field import FractionField
from sage.rings.rational_field import QQ
from sage.structure.sage_object import SageObject
from sage.symbolic.ring import SR

from ..errors import AnalysisError
from ..algebra.polynomials import parameter_ring, to_ring, to_sr
from ..algebra.conditions import nonzero_conditions
from .hurwitz import polynomial_arguments
from .hurwitz import (lienard_chipart_conditions, real_negative_roots_conditions,
                      hurwitz_determinants)
from ..algebra.regions import simplify_region
from ..algebra.translation import ParameterAtoms

__all__ = ['SpectrumRegions', 'spectrum_regions']


def _as_relations(expressions):
    return [SR(e) > 0 for e in expressions]


def _scaled(f, L):
    r"""``f`` times its leading coefficient in ``L``: the same roots, and
    conditions computed for it are right whatever the sign of that
    coefficient."""
    lc = f.polynomial(L).leading_coefficient()
    if _is_number(lc):
        return f if QQ(lc) > 0 else -f
    return f * f.parent()(lc)


def _is_number(c):
    return c in QQ


def _primitive(f, L):
    r"""``f`` without its content in ``L`` (the factor free of ``L``)."""
    u = f.polynomial(L)
    if any(_is_number(c) for c in u.coefficients()):
        return f
    content = u.coefficients()[0]
    for c in u.coefficients()[1:]:
        content = content.gcd(c)
    return f // f.parent()(content)


class SpectrumRegions(SageObject):
    r"""
    Where the roots of a characteristic polynomial lie, as regions of the
    parameters: see the module documentation. Created by
    :func:`spectrum_regions`.

    EXAMPLES::

        sage: from sage_dynsym.analysis.spectrum import spectrum_regions
        sage: lam, k = var('lam k')
        sage: S = spectrum_regions(lam^2 + k, lam); S.marginal()
        [[k > 0]]
        sage: TestSuite(S).run(skip=['_test_pickling'])
    """

    def __init__(self, poly, var, positive=(), matrix=None):
        poly, name = polynomial_arguments(poly, var)
        self._poly = SR(poly)
        self._var = SR.var(name)
        atoms = self._atoms = ParameterAtoms([self._poly], [self._var], positive)
        positive = atoms.positive()
        name = str(self._var)
        ring = parameter_ring(atoms.symbols(), extra=[name])
        L = ring.gen(ring.ngens() - 1)
        chi = to_ring(atoms.expression(self._poly).expand(), ring, "characteristic polynomial")
        if chi.degree(L) < 1:
            raise AnalysisError(f"expected a polynomial of degree at least 1 in {name}, got "
                                f"{self._poly}", entry="characteristic polynomial")
        self._zero = min(e[ring.ngens() - 1] for e in chi.exponents())
        chi1 = chi // L ** self._zero
        E = _primitive(chi1.gcd(chi1.subs({L: -L})), L)
        rest = chi1 // E
        repeated = E.gcd(E.derivative(L))
        Es = E // repeated if repeated.degree(L) > 0 else E
        self._degree_E = E.degree(L)
        lam = SR(L)
        mu = SR.symbol()
        boundaries = {'divergence': [], 'flutter': []}
        self._asymptotic = self._marginal = self._undecided = None
        self._semisimple = True

        def hurwitz_boundaries(f):
            n = f.degree(L)
            a0 = f.polynomial(L).leading_coefficient()
            boundaries['divergence'] += _zero_set(to_sr(f.subs({L: 0})), positive)
            if n >= 2:
                delta = hurwitz_determinants(to_sr(f), lam)[n - 2]
                boundaries['flutter'] += _zero_set(delta * to_sr(a0) ** (n - 1), positive)

        if E.degree(L) == 0 and self._zero == 0:
            self._asymptotic = simplify_region([_as_relations(lienard_chipart_conditions(
                to_sr(_scaled(chi1, L)), lam, positive))], positive)
            hurwitz_boundaries(chi1)
            odd = _coefficients(chi1, L)[1::2]
            if odd and odd[0] == 0:
                # no damping (the roots sum to zero): stable in first
                # approximation only where every odd coefficient vanishes
                h = _in_mu(chi1, L, ring, mu, even_part=True)
                h = real_negative_roots_conditions(to_sr(_scaled(h, _gen(mu, h.parent()))),
                                                   mu, positive)
                equations = [to_sr(c * ~c.lc()) == 0 for c in odd if c != 0]
                self._marginal = simplify_region([equations + _as_relations(h)], positive)
        else:
            conds = []
            if Es.degree(L) > 0:
                h = _in_mu(Es, L, ring, mu)
                M = _gen(mu, h.parent())
                conds += real_negative_roots_conditions(to_sr(_scaled(h, M)), mu, positive)
                boundaries['divergence'] += _zero_set(to_sr(h.subs({M: 0})), positive)
                if h.degree(M) >= 2:
                    # the discriminant, as a resultant in the ring (Singular)
                    lc = h.parent()(h.polynomial(M).leading_coefficient())
                    disc = h.resultant(h.derivative(M), M) // lc
                    boundaries['flutter'] += _zero_set(to_sr(disc), positive)
            if rest.degree(L) > 0:
                conds += lienard_chipart_conditions(to_sr(_scaled(rest, L)), lam, positive)
                hurwitz_boundaries(rest)
            region = simplify_region([_as_relations(conds)], positive)
            if region:
                checks = ([L] if self._zero else []) + \
                    ([repeated] if repeated.degree(L) > 0 else [])
                if checks:
                    if matrix is None:
                        raise AnalysisError("multiple roots on the imaginary axis for all "
                                            "parameter values: give the state matrix to "
                                            "decide whether they are semisimple",
                                            entry="spectrum_regions")
                    self._semisimple = _semisimple(matrix, checks, atoms, L)
                if self._semisimple:
                    self._marginal = region
                else:
                    self._undecided = region
        self._boundaries = {k: [atoms.restore_relation(r) for r in v]
                            for k, v in boundaries.items() if v}
        self._asymptotic = atoms.relations(self._asymptotic)
        self._marginal = atoms.relations(self._marginal) if self._marginal else None
        self._undecided = atoms.relations(self._undecided) if self._undecided else None
        if self._asymptotic == []:
            self._asymptotic = None

    def _repr_(self):
        what = (f"symmetric factor of degree {self._degree_E}" if self._degree_E else
                "no symmetric factor")
        if self._zero:
            what += f", {self._zero} zero roots"
        return f"Spectrum of {self._poly}: {what}"

    def parameter_atoms(self):
        r"""The :class:`~sage_dynsym.algebra.translation.ParameterAtoms` of
        the polynomial: its non-polynomial parts (``cos(alpha)``) as
        independent parameters, read in the package's trigonometric algebra.

        EXAMPLES::

            sage: from sage_dynsym.analysis.spectrum import spectrum_regions
            sage: from sage_dynsym.algebra.trig_algebra import TrigAlgebra
            sage: lam, k, a = var('lam k a')
            sage: S = spectrum_regions(lam^2 + k*cos(a), lam)
            sage: S.parameter_atoms().algebra() is TrigAlgebra([], [k, lam], [cos(a)])
            True
        """
        return self._atoms

    def asymptotic(self):
        r"""The region where every root has a negative real part (``None``
        if nowhere).

        EXAMPLES::

            sage: from sage_dynsym.analysis.spectrum import spectrum_regions
            sage: lam, c = var('lam c')
            sage: spectrum_regions(lam^2 + c*lam + 1, lam).asymptotic()
            [[c > 0]]
        """
        return self._asymptotic

    def marginal(self):
        r"""
        The region where the system is stable but not asymptotically: the
        roots on the imaginary axis simple or semisimple, the others with
        negative real parts (``None`` if nowhere).

        EXAMPLES: an undamped pair of oscillators with a gyroscopic
        coupling `g` and a circulatory one `\nu`: stable in first
        approximation only where `g\nu = 0`::

            sage: from sage_dynsym.analysis.spectrum import spectrum_regions
            sage: lam, g, nu, k1, k2 = var('lam g nu k1 k2')
            sage: chi = matrix([[lam^2 + k1, g*lam + nu], [-g*lam - nu, lam^2 + k2]]).det()
            sage: spectrum_regions(chi, lam, positive=[k1, k2]).marginal()
            [[g^4 + 2*g^2*k1 + 2*g^2*k2 + k1^2 - 2*k1*k2 + k2^2 - 4*nu^2 > 0, g*nu == 0]]
        """
        return self._marginal

    def undecided(self):
        r"""
        The region where every root is in the closed left half-plane but a
        multiple root on the imaginary axis is not semisimple: the linear
        system grows secularly, the nonlinear terms decide (``None`` if
        nowhere).

        EXAMPLES: a free particle, `\ddot x = 0`::

            sage: from sage_dynsym.analysis.spectrum import spectrum_regions
            sage: lam = var('lam')
            sage: S = spectrum_regions(lam^2, lam, matrix=matrix([[0, 1], [0, 0]]))
            sage: S.undecided(), S.marginal()
            ([[]], None)
        """
        return self._undecided

    def boundaries(self):
        r"""
        The boundaries: ``{'divergence': [...], 'flutter': [...]}``, each a
        list of relations ``f == 0`` (the factors of the constant
        coefficient, of the discriminant of the polynomial in `\mu =
        \lambda^2`, of the Hurwitz determinant `\Delta_{N-1}`).

        EXAMPLES::

            sage: from sage_dynsym.analysis.spectrum import spectrum_regions
            sage: lam, k, p = var('lam k p')
            sage: spectrum_regions((lam^2 + 1)*(lam^2 + k) + p^2, lam).boundaries()
            {'divergence': [p^2 + k == 0], 'flutter': [k - 2*p - 1 == 0, k + 2*p - 1 == 0]}
        """
        return {k: list(v) for k, v in self._boundaries.items()}

    def zero_roots(self):
        r"""The number of roots at zero for all parameter values.

        EXAMPLES::

            sage: from sage_dynsym.analysis.spectrum import spectrum_regions
            sage: lam, d = var('lam d')
            sage: spectrum_regions(lam^2 + d*lam, lam, matrix=matrix([[0, 1], [0, -d]])).zero_roots()
            1
        """
        return self._zero

    def symmetric_degree(self):
        r"""The degree of the symmetric factor `E` (roots in pairs `\pm\lambda`).

        EXAMPLES::

            sage: from sage_dynsym.analysis.spectrum import spectrum_regions
            sage: lam, d, k = var('lam d k')
            sage: spectrum_regions((lam^2 + k)*(lam + d), lam).symmetric_degree()
            2
        """
        return self._degree_E

    def is_semisimple(self):
        r"""Whether the roots on the imaginary axis for all parameter values
        (at zero, repeated factors) are semisimple (``True`` if there are
        none).

        EXAMPLES::

            sage: from sage_dynsym.analysis.spectrum import spectrum_regions
            sage: lam = var('lam')
            sage: spectrum_regions(lam^2, lam, matrix=matrix([[0, 1], [0, 0]])).is_semisimple()
            False
            sage: spectrum_regions(lam^2, lam, matrix=zero_matrix(2)).is_semisimple()
            True
        """
        return self._semisimple


def spectrum_regions(poly, var, positive=(), matrix=None):
    r"""
    Where the roots of ``poly`` in ``var`` lie, as regions of the
    parameters (see the module documentation).

    INPUT:

    - ``poly`` -- a polynomial in ``var`` with coefficients polynomial in
      the parameters (non-polynomial parts such as ``cos(alpha)`` are
      atoms)
    - ``var`` -- the variable
    - ``positive`` -- parameters declared positive
    - ``matrix`` -- (optional) a matrix whose characteristic polynomial has
      the roots of ``poly``; needed only to decide the semisimplicity of
      roots on the imaginary axis for all parameter values

    OUTPUT: a :class:`SpectrumRegions`

    EXAMPLES: see the module documentation.

    TESTS::

        sage: from sage_dynsym.analysis.spectrum import spectrum_regions
        sage: spectrum_regions(var('k'), var('lam'))
        Traceback (most recent call last):
        ...
        AnalysisError: characteristic polynomial: expected a polynomial of degree at least 1 in lam, got k
        sage: spectrum_regions(var('lam')^2, var('lam'))
        Traceback (most recent call last):
        ...
        AnalysisError: spectrum_regions: multiple roots on the imaginary axis for all parameter values: give the state matrix to decide whether they are semisimple
    """
    return SpectrumRegions(poly, var, positive, matrix)


def _coefficients(f, L):
    r"""Coefficients of ``f`` in ``L``, highest power first (ring elements)."""
    u = f.polynomial(L)
    return [f.parent()(c) for c in reversed(u.list())]


def _gen(mu, ring):
    return ring.gen(ring.variable_names().index(str(mu)))


def _in_mu(E, L, ring, mu, even_part=False):
    r"""The even polynomial ``E`` in ``L`` (or its even part) as a
    polynomial in `\mu = L^2`."""
    target = parameter_ring([SR(n) for n in ring.variable_names()[:-1]], extra=[str(mu)])
    m = _gen(mu, target)
    result = target.zero()
    for k, c in enumerate(E.polynomial(L).list()):
        if c and k % 2 == 0:
            result += target(to_sr(c)) * m ** (k // 2)
        elif c and not even_part:
            raise AnalysisError("the symmetric factor is not even", entry="spectrum_regions")
    return result


def _zero_set(expr, positive):
    r"""The factors of ``expr`` that can vanish, as relations ``f == 0``."""
    conds = nonzero_conditions(expr, positive)
    if conds is None:
        return []
    return [c.lhs() == 0 for c in conds]


def _semisimple(A, factors, atoms, L):
    r"""Whether the eigenvalues of ``A`` that are roots of each factor are
    semisimple: `\operatorname{rank} e(A) = \operatorname{rank} e(A)^2`,
    over the field of the parameters."""
    A = A.apply_map(atoms.expression)
    symbols = sorted({v for x in A.list() for v in SR(x).variables()}, key=str)
    R = parameter_ring(symbols)
    F = FractionField(R) if R.ngens() else R
    n = A.nrows()

    def element(x):
        num, den = SR(x).numerator_denominator()
        return F(to_ring(num, R, "state matrix")) / F(to_ring(den, R, "state matrix"))

    B = A.apply_map(element, F)
    one = identity_matrix(F, n)
    for e in factors:
        value = 0 * one
        for c in reversed(e.polynomial(L).list()):      # Horner
            value = value * B + element(to_sr(c)) * one
        if value.rank() != (value * value).rank():
            return False
    return True
