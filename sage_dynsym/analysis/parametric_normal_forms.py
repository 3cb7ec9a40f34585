r"""
Birkhoff normal forms with free parameters, exactly: the field of the data

With parameters left free, the coefficients of a normal form are
algebraic functions of them: rational in the parameters, the irrational
constants of the data (e.g. `\sqrt 3`) and the roots `\lambda_k = i\omega_k`
of the linearization. :class:`FieldArithmetic` computes in that field,

.. MATH::

    F = \mathbb Q(\mu)[c, \lambda_1, \dots, \lambda_n] / P,

`P` the prime component (over the rational functions `\mathbb Q(\mu)` of
the parameters) of the relations of the constants and of the symmetric
functions of the `\lambda_k^2` (the characteristic polynomial) that holds at
a sample point. Every element is reduced by a Gröbner basis of `P`, every
divisor is inverted in `F` (a Singular ``lift``), so that the size of a
coefficient is bounded by the degree of `F`: only the degrees in the
parameters grow. The divisors of the Lie series are invertible in `F` when
they are not zero *identically*: the normal form holds for the parameters
off their zeros (the resonances, given exactly by
:func:`~sage_dynsym.dynamics.nonlinear_stability.exceptional_values`).

:func:`arnold_polynomial` gives Arnold's determinant of degree 4 as an
element of `F` and the polynomial in the parameters whose zeros contain
those of the determinant (its norm from `F` down to `\mathbb Q(\mu)`): the
degenerate values exactly.

EXAMPLES: a pendulum of stiffness `k`, `H = p^2/2 + k(q^2/2 - q^4/24)`:
`H = \omega I - I^2/16` with `\omega = \sqrt k`::

    sage: from sage_dynsym.analysis.parametric_normal_forms import FieldArithmetic
    sage: from sage_dynsym.analysis.normal_forms import normal_form
    sage: B = PolynomialRing(QQ, 'k'); S = PolynomialRing(B, 'q, p')
    sage: A = FieldArithmetic(S('p^2/2 + k*q^2/2 - k*q^4/24'), 1, {'k': None}, sample={'k': 4})
    sage: nf = normal_form(A, 4); nf.coefficients()
    {(1,): omega1, (2,): -1/16}

REFERENCES:

- A. Deprit, A. Deprit-Bartholomé, Stability of the triangular Lagrangian
  points, Astronomical Journal 72 (1967) 173--179.
- K. R. Meyer, G. R. Hall, D. Offin, Introduction to Hamiltonian Dynamical
  Systems and the N-Body Problem, 2nd ed., Springer 2009, section 13.4.
"""
import itertools

from sage.misc.misc_c import prod
from sage.rings.complex_interval_field import ComplexIntervalField
from sage.rings.complex_mpfr import ComplexField
from sage.rings.fraction_field import FractionField
from sage.rings.polynomial.polynomial_ring_constructor import PolynomialRing
from sage.rings.rational_field import QQ
from sage.matrix.constructor import matrix

from ..errors import AnalysisError
from .normal_forms import FormalArithmetic, DECISION_BITS

__all__ = ['FieldArithmetic', 'arnold_polynomial']


class FieldArithmetic(FormalArithmetic):
    r"""
    Exact coefficients in the field of the data over the rational
    functions of the free parameters (see the module documentation).

    INPUT: as for :class:`~sage_dynsym.analysis.normal_forms.FormalArithmetic`,
    with at least one free parameter (value ``None``) and its ``sample``
    value (the choices: the order of the modes, the component of the
    relations)

    EXAMPLES::

        sage: from sage_dynsym.analysis.parametric_normal_forms import FieldArithmetic
        sage: B = PolynomialRing(QQ, 'k'); S = PolynomialRing(B, 'q, p')
        sage: FieldArithmetic(S('p^2/2 + k*q^2/2'), 1, {'k': None}, sample={'k': 4})
        exact arithmetic over QQ(k) with values {'k': None}

    TESTS::

        sage: FieldArithmetic(S('p^2/2 + 4*q^2/2'), 1, {'k': 4})
        Traceback (most recent call last):
        ...
        AnalysisError: values: FieldArithmetic is for free parameters (none is free); use FormalArithmetic
    """

    def __init__(self, H, n, values, relations=(), sample=None):
        super().__init__(H, n, values, relations, sample=sample)
        if not self.free:
            raise AnalysisError("FieldArithmetic is for free parameters (none is free); use "
                                "FormalArithmetic", entry="values")
        self._inverses = {}

    def _repr_(self):
        return f"exact arithmetic over QQ({', '.join(self.free)}) with values {self.values}"

    def prepare(self, order):
        r"""Set up the field: the ring over `\mathbb Q(\mu)` of the constants
        and the `\lambda_k`, and the prime of their relations at the sample
        (:func:`~sage_dynsym.analysis.normal_forms.normal_form` calls it).

        EXAMPLES::

            sage: from sage_dynsym.analysis.parametric_normal_forms import FieldArithmetic
            sage: B = PolynomialRing(QQ, 'k'); S = PolynomialRing(B, 'q, p')
            sage: A = FieldArithmetic(S('p^2/2 + k*q^2/2'), 1, {'k': None}, sample={'k': 4})
            sage: A.prepare(4); A.groebner
            [lambda1^2 + k]
        """
        data = self.H.base_ring()
        self.data_ring = data
        constants = [g for g in data.variable_names() if g not in self.free]
        # named by a string: Singular takes QQ(mu) as the field of a ring
        parameters = PolynomialRing(QQ, ", ".join(self.free))
        names = constants + [f"lambda{k + 1}" for k in range(self.n)]
        # the count given: multivariate (Singular's ideals) also for one name
        self.K = PolynomialRing(FractionField(parameters), names, len(names), order='degrevlex')
        self.lambda_gens = list(self.K.gens()[len(constants):])
        self.lambdas = self.lambda_gens
        CC = ComplexField(DECISION_BITS)
        hessian = self._hessian()
        self.lambda_values = self._eigenvalues(
            hessian.apply_map(lambda e: CC(self._data_value(e).center())))
        self.H = self.H.map_coefficients(self.K, self.K)
        self.hessian = self._hessian()
        chi = self._char_poly_in_square(self.hessian)
        s = [lam ** 2 for lam in self.lambda_gens]
        relations = [self.K(r) for r in self.base_relations]
        for j in range(1, self.n + 1):
            e_j = sum(prod(c) for c in itertools.combinations(s, j))
            relations.append(e_j - (-1) ** j * chi[self.n - j])
        self.ideal = self._component(self.K.ideal(relations))
        self.groebner = list(self.ideal.groebner_basis())
        self.c_values = []

    def _component(self, ideal):
        r"""The prime component of ``ideal`` on which the sample point lies."""
        primes = ideal.minimal_associated_primes()
        if len(primes) == 1:
            return primes[0]
        point = self._point()
        tolerance = QQ(2) ** (-DECISION_BITS // 2)
        for prime in primes:
            if all(abs(self._evaluate(g, point)).upper() < tolerance for g in prime.gens()):
                return prime
        raise AnalysisError("the sample point lies on no component of the relations of the "
                            "frequencies: choose another sample", entry="sample")

    def _data_value(self, c):
        CIF = ComplexIntervalField(DECISION_BITS)
        return c(*[CIF(v) for v in self._base_point()])

    def _point(self):
        r"""Values (complex intervals) of the parameters, then of the
        generators of the field at the sample."""
        CIF = ComplexIntervalField(DECISION_BITS)
        parameters = [CIF(self.sample[g]) for g in self.free]
        constants = [CIF(self.values[g]) for g in self.data_ring.variable_names()
                     if g not in self.free]
        return parameters, constants + [CIF(v) for v in self.lambda_values]

    def _evaluate(self, c, point):
        parameters, generators = point
        CIF = ComplexIntervalField(DECISION_BITS)
        total = CIF(0)
        for e, coefficient in self.K(c).dict().items():
            value = coefficient.numerator()(*parameters) / coefficient.denominator()(*parameters)
            total += CIF(value) * prod(x ** k for x, k in zip(generators, e))
        return total

    def _numeric_value(self, c, bits=None):
        return self._evaluate(c, self._point())

    def _inverted(self):
        return []

    def reduce(self, c):
        r"""``c`` reduced by the prime of the relations.

        EXAMPLES::

            sage: from sage_dynsym.analysis.parametric_normal_forms import FieldArithmetic
            sage: B = PolynomialRing(QQ, 'k'); S = PolynomialRing(B, 'q, p')
            sage: A = FieldArithmetic(S('p^2/2 + k*q^2/2'), 1, {'k': None}, sample={'k': 4})
            sage: A.prepare(4); A.reduce(A.lambdas[0]^3)
            (-k)*lambda1
        """
        return self.K(c).reduce(self.groebner)

    def is_zero(self, c):
        r"""Whether ``c`` is zero in the field: identically in the
        parameters (a value that vanishes at special parameters only is not
        zero here).

        EXAMPLES::

            sage: from sage_dynsym.analysis.parametric_normal_forms import FieldArithmetic
            sage: B = PolynomialRing(QQ, 'k'); S = PolynomialRing(B, 'q, p')
            sage: A = FieldArithmetic(S('p^2/2 + k*q^2/2'), 1, {'k': None}, sample={'k': 4})
            sage: A.prepare(4); A.is_zero(A.lambdas[0]^2 + A.K('k')), A.is_zero(A.lambdas[0] - 2)
            (True, False)
        """
        return self.reduce(c).is_zero()

    def exact_value(self, c):
        r"""``None``: the values depend on the free parameters.

        EXAMPLES::

            sage: from sage_dynsym.analysis.parametric_normal_forms import FieldArithmetic
            sage: B = PolynomialRing(QQ, 'k'); S = PolynomialRing(B, 'q, p')
            sage: FieldArithmetic(S('p^2/2 + k*q^2/2'), 1, {'k': None}, sample={'k': 4}).exact_value(1)
        """
        return None

    def inverse(self, x, which=None):
        r"""The inverse of ``x`` in the field (``which`` names it, for the
        cache).

        EXAMPLES::

            sage: from sage_dynsym.analysis.parametric_normal_forms import FieldArithmetic
            sage: B = PolynomialRing(QQ, 'k'); S = PolynomialRing(B, 'q, p')
            sage: A = FieldArithmetic(S('p^2/2 + k*q^2/2'), 1, {'k': None}, sample={'k': 4})
            sage: A.prepare(4); u = A.inverse(2*A.lambdas[0]); u, A.reduce(u * 2*A.lambdas[0])
            (-1/(2*k)*lambda1, 1)
        """
        key = (which, x) if which is not None else x
        if key not in self._inverses:
            x = self.reduce(x)
            if x.is_zero():
                raise AnalysisError("a divisor of the normal form vanishes identically in "
                                    "the parameters: a resonance for every value",
                                    entry="model")
            lifted = self.K(1).lift(self.K.ideal([x] + self.groebner))
            self._inverses[key] = self.reduce(lifted[0])
        return self._inverses[key]

    def symbolic(self, c):
        r"""An element of the field as a symbolic expression in the
        parameters, the constants and ``omega1, ...`` (`\lambda_k \to i\omega_k`).

        EXAMPLES::

            sage: from sage_dynsym.analysis.parametric_normal_forms import FieldArithmetic
            sage: B = PolynomialRing(QQ, 'k'); S = PolynomialRing(B, 'q, p')
            sage: A = FieldArithmetic(S('p^2/2 + k*q^2/2'), 1, {'k': None}, sample={'k': 4})
            sage: A.prepare(4); A.symbolic(A.lambdas[0]^2/A.K('k'))
            -omega1^2/k
        """
        from sage.symbolic.ring import SR
        names = self.K.variable_names()
        images = [SR.var(g) for g in names[:len(names) - self.n]] + \
            [SR.I() * SR.var(f"omega{k + 1}") for k in range(self.n)]
        return sum(SR(coefficient) * prod(x ** k for x, k in zip(images, e))
                   for e, coefficient in self.K(c).dict().items())


def arnold_polynomial(nf):
    r"""
    Arnold's determinant of degree 4 of a normal form computed in a
    :class:`FieldArithmetic` (two degrees of freedom), exactly: a pair
    ``(D, N)``, ``D`` the determinant as an element of the field (its value
    at a point of the parameters is the determinant there) and ``N`` the
    numerator, a polynomial in the parameters, of its norm down to the
    rational functions: ``D`` vanishes only where ``N`` does.

    EXAMPLES: two oscillators `H = (q_1^2 + p_1^2) - a(q_2^2 + p_2^2)/2 +
    q_1^4`; in the actions `H = 2 I_1 - a I_2 + (3/2) I_1^2` (`q_1 =
    \sqrt{2 I_1}\cos\varphi_1`, the average of `\cos^4` is `3/8`), so
    `D = (3/2) a^2`, zero at `a = 0` only (the field of the frequencies is
    of degree 2 here: the norm is `D^2`)::

        sage: from sage_dynsym.analysis.parametric_normal_forms import FieldArithmetic, arnold_polynomial
        sage: from sage_dynsym.analysis.normal_forms import normal_form
        sage: B = PolynomialRing(QQ, 'a'); R = PolynomialRing(B, 'q1, q2, p1, p2')
        sage: q1, q2, p1, p2 = R.gens(); a = B.gen()
        sage: H = (q1^2 + p1^2) - a*(q2^2 + p2^2)/2 + q1^4
        sage: nf = normal_form(FieldArithmetic(H, 2, {'a': None}, sample={'a': 1}))
        sage: D, N = arnold_polynomial(nf); D, N.factor()
        ((3*a^2)/2, a^4)
    """
    A = nf.arithmetic()
    if not isinstance(A, FieldArithmetic) or A.n != 2:
        raise AnalysisError("expected a normal form of two degrees of freedom computed with "
                            "free parameters (FieldArithmetic)", entry="nf")
    if nf.order() < 4:
        raise AnalysisError("the normal form must be of order 4 at least", entry="nf")
    signs = nf.signs()
    # c_m = sign_m Re(-h_m) for the terms I^m of degree 4; on the ray
    # (w2, -w1), w_k = sigma_k lambda_k / i, the powers of i cancel: D lies in F
    D = A.K(0)
    for m, h in nf.action_terms()[0].items():
        if sum(m) != 2:
            continue
        sign = prod(s ** mk for s, mk in zip(signs, m))
        D += sign * A.K(h) * (signs[1] * A.lambdas[1]) ** m[0] * \
            (-signs[0] * A.lambdas[0]) ** m[1]
    D = A.reduce(D)
    # the norm: the determinant of multiplication by D on a basis of F
    basis = A.ideal.normal_basis()
    rows = [[A.reduce(D * b).monomial_coefficient(c) for c in basis] for b in basis]
    norm = matrix(A.K.base_ring(), rows).det()
    return D, norm.numerator().monic()
