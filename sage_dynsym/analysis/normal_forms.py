r"""
Birkhoff normal forms of Hamiltonians at elliptic equilibria

The data: a polynomial Hamiltonian `H(q, p)` in canonical pairs, the
Taylor expansion of a Hamiltonian at an equilibrium moved to the origin,
whose linearization `\dot z = J S z` (`S` the Hessian, `J` the symplectic
unit) has simple roots `\pm i\omega_k` on the imaginary axis.

**The quadratic part.** For each mode a left eigenvector `w_k` of `JS`
for `\lambda_k = i\omega_k` and `w'_k` for `-\lambda_k` give complex
canonical coordinates `\xi_k = w_k^T z`, `\eta_k = w'^T_k z / c_k` with
`c_k = w_k^T J w'_k` (`\{\xi_k, \eta_k\} = 1`), in which
`H_2 = \sum_k \lambda_k \xi_k \eta_k`. The action of the mode is
`I_k = i\sigma_k \xi_k\eta_k = (x_k^2 + y_k^2)/2`, `\sigma_k = \pm 1` the sign
of the quadratic energy on the mode, so that
`H_2 = \sum_k \sigma_k \omega_k I_k`: the *signed frequencies*
`\sigma_k\omega_k`.

**The nonlinear terms** are normalized order by order by Lie series
(Deprit's method, a composition of Lie transforms): at degree `d` the
generating function `W_d = \sum h_{ab}/(\lambda\cdot(a - b))\,
\xi^a\eta^b` removes every term of degree `d` that is not resonant
(`\lambda\cdot(a-b) \ne 0`), and `H \leftarrow \exp(L_{W_d}) H` with
`L_W F = \{F, W\}`; the coordinate functions are carried along
(:meth:`BirkhoffNormalForm.transformation`). Without resonances what
remains depends on the products `\xi_k\eta_k` only: the Birkhoff normal
form in the actions `H = \sum \sigma_k\omega_k I_k + \sum c_{kl} I_k I_l +
\dots`.

**Arithmetic.** The coefficients are either numbers of a
``ComplexField`` of any precision, or exact: polynomials over `\mathbb Q`
in formal generators -- the parameters, the irrational constants of the
data (e.g. `\sqrt 3`), `\lambda_k` and the inverses of the divisors
(Deprit's expressions in the frequencies). The powers of the `\lambda_k`
and of the constants are reduced by their relations (the characteristic
polynomial), and every decision (a zero divisor, a vanishing determinant)
is taken on the value: by interval arithmetic, and exactly with
algebraic numbers when the interval does not decide.

EXAMPLES:

The pendulum `H = p^2/2 + 1 - \cos q` (`I - I^2/16 - I^3/256`)::

    sage: from sage_dynsym.analysis.normal_forms import normal_form, FormalArithmetic
    sage: R = PolynomialRing(QQ, 'q, p'); q, p = R.gens()
    sage: H = p^2/2 + q^2/2 - q^4/24 + q^6/720
    sage: nf = normal_form(FormalArithmetic.numeric(H, 1, prec=100), 6)
    sage: nf.frequencies()
    [1.0000000000000000000000000000]
    sage: nf.coefficients()
    {(1,): 1.0000000000000000000000000000,
     (2,): -0.062500000000000000000000000000,
     (3,): -0.0039062500000000000000000000000}

REFERENCES:

- A. Deprit, Canonical transformations depending on a small
  parameter, Celestial Mechanics 1 (1969) 12--30.
- K. R. Meyer, G. R. Hall, D. Offin, Introduction to
  Hamiltonian Dynamical Systems and the N-Body Problem, 2nd ed., Springer
  2009, chapters 10 and 13.
"""
import itertools

from sage.arith.misc import gcd
from sage.matrix.constructor import matrix, identity_matrix, block_matrix
from sage.misc.cachefunc import cached_method
from sage.misc.misc_c import prod
from sage.modules.free_module_element import vector
from sage.rings.complex_interval_field import ComplexIntervalField
from sage.rings.complex_mpfr import ComplexField
from sage.rings.integer_ring import ZZ
from sage.rings.polynomial.polynomial_ring_constructor import PolynomialRing
from sage.rings.polynomial.term_order import TermOrder
from sage.rings.qqbar import QQbar, AA
from sage.rings.rational_field import QQ
from sage.rings.real_mpfr import RealField
from sage.structure.sage_object import SageObject
from sage.symbolic.ring import SR

from ..errors import AnalysisError

__all__ = ['DECISION_BITS', 'symplectic_unit', 'FormalArithmetic', 'normal_form',
           'BirkhoffNormalForm']

#: Bits of the interval arithmetic that decides signs and zeros.
DECISION_BITS = 256


def symplectic_unit(n):
    r"""The matrix `J = \begin{pmatrix} 0 & I \\ -I & 0\end{pmatrix}` of
    `n` canonical pairs `(q, p)`.

    EXAMPLES::

        sage: from sage_dynsym.analysis.normal_forms import symplectic_unit
        sage: symplectic_unit(1)
        [ 0  1]
        [-1  0]
    """
    return block_matrix(ZZ, [[0, identity_matrix(ZZ, n)], [-identity_matrix(ZZ, n), 0]],
                        subdivide=False)


class FormalArithmetic(SageObject):
    r"""
    The coefficients of a normal form computation: a ring with the value of
    each of its generators.

    Either numeric (a ``ComplexField``) or exact: a polynomial ring over
    `\mathbb Q` whose generators are the parameters and constants of the
    data (with their values: exact algebraic numbers, numbers, or ``None``
    for a free parameter, which then needs a ``sample`` value for the
    choices that depend on the point), one `\lambda_k` per mode and the
    inverses of the divisors, added by :meth:`prepare`.

    INPUT:

    - ``H`` -- a polynomial over ``base`` in `q_1..q_n, p_1..p_n`
    - ``n`` -- the number of degrees of freedom
    - ``values`` -- dict generator name of ``base`` -> value (exact or numeric)
    - ``relations`` -- polynomials in the generators of ``base`` that
      vanish at the values (e.g. ``s^2 - 3`` for `s = \sqrt 3`)
    - ``sample`` -- (optional) values of the free parameters for the choices

    EXAMPLES::

        sage: from sage_dynsym.analysis.normal_forms import FormalArithmetic
        sage: B = PolynomialRing(QQ, 'a'); R = PolynomialRing(B, 'q, p'); q, p = R.gens()
        sage: A = FormalArithmetic(p^2/2 + B.0*q^2/2, 1, {'a': 4}); A
        exact arithmetic in a with values {'a': 4}
        sage: FormalArithmetic.numeric(p^2/2 + q^2, 1)
        numeric arithmetic (53 bits)
    """

    def __init__(self, H, n, values, relations=(), sample=None, prec=None):
        self.H = H
        self.n = n
        self.prec = prec
        self.values = dict(values)
        self.sample = dict(sample or {})
        self.base_relations = list(relations)
        self.free = [g for g, v in self.values.items() if v is None]
        if self.free and any(g not in self.sample for g in self.free):
            raise AnalysisError(f"give a sample value of the parameters {self.free} "
                                "(sample={...}) for the choices that depend on the point",
                                entry="sample")

    @classmethod
    def numeric(cls, H, n, prec=53):
        r"""Numeric coefficients in ``ComplexField(prec)`` (``H`` over any
        ring that converts to it).

        EXAMPLES::

            sage: from sage_dynsym.analysis.normal_forms import FormalArithmetic
            sage: R = PolynomialRing(QQ, 'q, p'); q, p = R.gens()
            sage: FormalArithmetic.numeric(p^2/2 + q^2/2, 1, prec=80).H.base_ring()
            Complex Field with 80 bits of precision
        """
        K = ComplexField(prec)
        return cls(H.change_ring(K), n, {}, prec=prec)

    def _repr_(self):
        if self.prec is not None:
            return f"numeric arithmetic ({self.prec} bits)"
        names = ", ".join(_names(self.H.base_ring()))
        return f"exact arithmetic in {names} with values {self.values}"

    def is_numeric(self):
        r"""Whether the coefficients are numbers (else exact).

        EXAMPLES: the pendulum `H = p^2/2 + a q^2/2 - a q^4/24` at `a = 4`
        (frequency 2), normalized exactly::

            sage: from sage_dynsym.analysis.normal_forms import FormalArithmetic, normal_form
            sage: B = PolynomialRing(QQ, 'a'); S = PolynomialRing(B, 'q, p')
            sage: A = FormalArithmetic(S('p^2/2 + a*q^2/2 - a*q^4/24'), 1, {'a': 4})
            sage: N = normal_form(A, 4); lam, = A.lambdas
            sage: A.is_numeric(), FormalArithmetic.numeric(S('p^2 + q^2'), 1).is_numeric()
            (False, True)
        """
        return self.prec is not None

    def prepare(self, order):
        r"""Set up the ring of the computation: `\lambda_k` and the inverses
        of the divisors `j\cdot\lambda` (``|j| <= order``) and of `c_k`
        (:func:`normal_form` calls it).

        EXAMPLES: the pendulum `H = p^2/2 + a q^2/2 - a q^4/24` at `a = 4`
        (frequency 2), normalized exactly::

            sage: from sage_dynsym.analysis.normal_forms import FormalArithmetic, normal_form
            sage: B = PolynomialRing(QQ, 'a'); S = PolynomialRing(B, 'q, p')
            sage: A = FormalArithmetic(S('p^2/2 + a*q^2/2 - a*q^4/24'), 1, {'a': 4})
            sage: N = normal_form(A, 4); lam, = A.lambdas
            sage: A.prepare(4); A.lambdas, A.groebner
            ([lambda1], [a + lambda1^2])
        """
        n = self.n
        hessian = self._hessian()
        self.hessian = hessian
        if self.is_numeric():
            self.K = self.H.base_ring()
            self.lambdas = self._eigenvalues(hessian.change_ring(self.K))
            return
        base = self.H.base_ring()
        self.divisors = [j for j in itertools.product(range(-order, order + 1), repeat=n)
                         if 0 < sum(map(abs, j)) <= order and next(x for x in j if x) > 0]
        names = list(_names(base)) + [f"lambda{k + 1}" for k in range(n)] + \
            [f"u_c{k + 1}" for k in range(n)] + [f"u_{k}" for k in range(len(self.divisors))]
        self.K = PolynomialRing(QQ, names, order='lex')
        gens = self.K.gens()
        m = len(_names(base))
        self.lambda_gens = list(gens[m:m + n])
        self.c_inverses = list(gens[m + n:m + 2 * n])
        self.divisor_inverses = list(gens[m + 2 * n:])
        CC = ComplexField(DECISION_BITS)
        self.lambda_values = self._eigenvalues(
            hessian.apply_map(lambda e: CC(self._numeric_value(e).center())))
        self.lambdas = self.lambda_gens
        # the relations: the constants', and the symmetric functions of the
        # lambda_k^2, the roots of the characteristic polynomial in lambda^2
        chi = self._char_poly_in_square(hessian.change_ring(self.K))
        s = [lam ** 2 for lam in self.lambda_gens]
        relations = [self.K(r) for r in self.base_relations]
        for j in range(1, n + 1):
            e_j = sum(prod(c) for c in itertools.combinations(s, j))
            relations.append(e_j - (-1) ** j * chi[n - j])
        self.ideal = self.K.ideal(relations)
        self.groebner = self.ideal.groebner_basis()

    def _hessian(self):
        n = self.n
        X = self.H.parent().gens()
        H2 = self.H.parent()({e: c for e, c in self.H.dict().items() if sum(e) == 2})
        return matrix(self.H.base_ring(), 2 * n, 2 * n,
                      lambda i, j: H2.derivative(X[i]).derivative(X[j]).constant_coefficient())

    def _char_poly_in_square(self, S):
        r"""The characteristic polynomial of `JS` is `P(\lambda^2)`: the
        coefficients of the monic `P` (constant first)."""
        A = symplectic_unit(self.n).change_ring(S.base_ring()) * S
        chi = A.charpoly('x').list()
        return [chi[2 * k] for k in range(self.n + 1)]

    def _eigenvalues(self, S):
        r"""`\lambda_k = i\omega_k`, `\omega_1 > \omega_2 > ... > 0` (numbers
        of a ``ComplexField``), or an error naming the roots off the axis."""
        K = S.base_ring()
        A = symplectic_unit(self.n).change_ring(K) * S
        roots = A.charpoly('x').roots(multiplicities=False)
        eps = RealField(K.prec())(2) ** (-K.prec() // 2)
        upper = sorted([r for r in roots if r.imag() > 0], key=lambda r: -r.imag())
        if len(roots) != 2 * self.n or any(abs(r.real()) > eps for r in roots) or \
                len(upper) != self.n:
            raise AnalysisError(f"the linearization has the roots {roots}: a normal form "
                                "needs simple roots on the imaginary axis (use "
                                "nonlinear_stability for the other cases)", entry="at")
        return [K(0, r.imag()) for r in upper]

    def _numeric_value(self, c, bits=None):
        r"""The value of a coefficient in ``ComplexIntervalField`` (or the
        numeric coefficient itself)."""
        if self.is_numeric():
            return c
        CIF = ComplexIntervalField(DECISION_BITS)
        point = [CIF(v) for v in self._base_point()]
        if c.parent() is self.H.base_ring():
            return c(*point) if point else CIF(c)
        point += [CIF(v) for v in self._lambda_point()]
        # the inverted elements are free of the inverses
        filled = point + [CIF(0)] * (self.K.ngens() - len(point))
        point += [1 / x(*filled) for x in self._inverted()]
        return self.K(c)(*point)

    def symbolic(self, c):
        r"""An element of the ring of the computation as a symbolic
        expression: the parameters and constants by their names,
        `\lambda_k \to i\omega_k` (symbols ``omega1, ...``) and each
        inverse generator by the inverse of its element.

        EXAMPLES: the pendulum `H = p^2/2 + a q^2/2 - a q^4/24`, frequency
        `\sqrt a`::

            sage: from sage_dynsym.analysis.normal_forms import FormalArithmetic, normal_form
            sage: B = PolynomialRing(QQ, 'a'); S = PolynomialRing(B, 'q, p')
            sage: A = FormalArithmetic(S('p^2/2 + a*q^2/2 - a*q^4/24'), 1, {'a': None},
            ....:                      sample={'a': 4})
            sage: N = normal_form(A, 4); A.symbolic(A.lambdas[0]^2 + A.K('a'))
            -omega1^2 + a
        """
        omegas = [SR.var(f"omega{k + 1}") for k in range(self.n)]
        images = [SR.var(g) for g in _names(self.H.base_ring())] + [SR.I() * w for w in omegas]
        images += [1 / x(*(images + [0] * (self.K.ngens() - len(images))))
                   for x in self._inverted()]
        return self.K(c)(*(images + [0] * (self.K.ngens() - len(images))))

    def _base_point(self):
        return [self.values[g] if self.values[g] is not None else self.sample[g]
                for g in _names(self.H.base_ring())]

    def _lambda_point(self):
        # rigorous enclosures from the exact roots when the data are exact
        exact = None if self.free else self.exact_lambdas()
        return exact if exact is not None else self.lambda_values

    def _inverted(self):
        # c_k not computed yet stand as 1: their inverses do not occur yet
        return list(self.c_values) + [self.K(1)] * (self.n - len(self.c_values)) + [sum(j_k * lam for j_k, lam in zip(j, self.lambda_gens))
                                      for j in self.divisors]

    def reduce(self, c):
        r"""``c`` reduced by the relations of the exact generators (itself
        when numeric).

        EXAMPLES: the pendulum `H = p^2/2 + a q^2/2 - a q^4/24` at `a = 4`
        (frequency 2), normalized exactly::

            sage: from sage_dynsym.analysis.normal_forms import FormalArithmetic, normal_form
            sage: B = PolynomialRing(QQ, 'a'); S = PolynomialRing(B, 'q, p')
            sage: A = FormalArithmetic(S('p^2/2 + a*q^2/2 - a*q^4/24'), 1, {'a': 4})
            sage: N = normal_form(A, 4); lam, = A.lambdas
            sage: A.reduce(A.K('a') * lam)
            -lambda1^3
        """
        return c if self.is_numeric() else c.reduce(self.groebner)

    def value(self, c):
        r"""The value of ``c`` as a complex interval (exact mode) or number.

        EXAMPLES: the pendulum `H = p^2/2 + a q^2/2 - a q^4/24` at `a = 4`
        (frequency 2), normalized exactly::

            sage: from sage_dynsym.analysis.normal_forms import FormalArithmetic, normal_form
            sage: B = PolynomialRing(QQ, 'a'); S = PolynomialRing(B, 'q, p')
            sage: A = FormalArithmetic(S('p^2/2 + a*q^2/2 - a*q^4/24'), 1, {'a': 4})
            sage: N = normal_form(A, 4); lam, = A.lambdas
            sage: A.value(lam)
            2*I
        """
        return self._numeric_value(c)

    def is_zero(self, c):
        r"""Whether the value of ``c`` is zero: decided by intervals, then
        exactly; ``None`` when only the working precision says so.

        EXAMPLES: the pendulum `H = p^2/2 + a q^2/2 - a q^4/24` at `a = 4`
        (frequency 2), normalized exactly::

            sage: from sage_dynsym.analysis.normal_forms import FormalArithmetic, normal_form
            sage: B = PolynomialRing(QQ, 'a'); S = PolynomialRing(B, 'q, p')
            sage: A = FormalArithmetic(S('p^2/2 + a*q^2/2 - a*q^4/24'), 1, {'a': 4})
            sage: N = normal_form(A, 4); lam, = A.lambdas
            sage: A.is_zero(lam^2 + 4), A.is_zero(lam)
            (True, False)
        """
        if self.is_numeric():
            K = c.parent()
            return True if abs(c) < RealField(K.prec())(2) ** (-K.prec() // 2) else False
        if c.is_zero():
            return True
        v = self.value(c)
        if not v.contains_zero():
            return False
        exact = self.exact_value(c)
        return None if exact is None else exact.is_zero()

    def exact_value(self, c):
        r"""The value of ``c`` in ``QQbar`` (``None`` if a value is not exact).

        EXAMPLES: the pendulum `H = p^2/2 + a q^2/2 - a q^4/24` at `a = 4`
        (frequency 2), normalized exactly::

            sage: from sage_dynsym.analysis.normal_forms import FormalArithmetic, normal_form
            sage: B = PolynomialRing(QQ, 'a'); S = PolynomialRing(B, 'q, p')
            sage: A = FormalArithmetic(S('p^2/2 + a*q^2/2 - a*q^4/24'), 1, {'a': 4})
            sage: N = normal_form(A, 4); lam, = A.lambdas
            sage: A.exact_value(lam^3)
            -8*I
        """
        if self.is_numeric() or self.free:
            return None
        lambdas = self.exact_lambdas()
        if lambdas is None:
            return None
        point = self._exact_parameters() + lambdas
        inverses = []
        for x in self._inverted():
            inverses.append(1 / x(*(point + [QQbar(0)] * (self.K.ngens() - len(point)))))
        return c(*(point + inverses))

    @cached_method
    def exact_lambdas(self):
        r"""
        The `\lambda_k` as algebraic numbers (the root nearest to each
        numeric one); ``None`` if a value of the parameters is not exact.
        """
        point = self._exact_parameters()
        if point is None:
            return None
        S = self.hessian.apply_map(lambda e: e(*point) if point else QQbar(e))
        A = symplectic_unit(self.n).change_ring(QQbar) * S
        roots = A.charpoly('x').roots(QQbar, multiplicities=False)
        return [min(roots, key=lambda r: abs(ComplexField(DECISION_BITS)(r) - lam))
                for lam in self.lambda_values]

    def _exact_parameters(self):
        # the values of the parameters in QQbar, None if one is not exact
        try:
            return [QQbar(self.values[g]) for g in _names(self.H.base_ring())]
        except (TypeError, ValueError):
            return None

    def inverse(self, x, which=None):
        r"""The inverse of ``x``: a number, or the generator that stands for
        it (``which``: ``('c', k)`` or the divisor vector).

        EXAMPLES: the pendulum `H = p^2/2 + a q^2/2 - a q^4/24` at `a = 4`
        (frequency 2), normalized exactly::

            sage: from sage_dynsym.analysis.normal_forms import FormalArithmetic, normal_form
            sage: B = PolynomialRing(QQ, 'a'); S = PolynomialRing(B, 'q, p')
            sage: A = FormalArithmetic(S('p^2/2 + a*q^2/2 - a*q^4/24'), 1, {'a': 4})
            sage: N = normal_form(A, 4); lam, = A.lambdas
            sage: u = A.inverse(2*lam, ('d', (2,))); u, A.exact_value(u)
            (u_1, -0.25000000000000000?*I)
        """
        if self.is_numeric():
            return 1 / x
        if which[0] == 'c':
            return self.c_inverses[which[1]]
        j = which[1]
        sign = 1 if next(x for x in j if x) > 0 else -1
        return sign * self.divisor_inverses[self.divisors.index(tuple(sign * a for a in j))]


def _names(ring):
    return () if ring is QQ else ring.variable_names()


def _bracket(f, g, gens, n):
    return sum(f.derivative(gens[k]) * g.derivative(gens[n + k])
               - f.derivative(gens[n + k]) * g.derivative(gens[k]) for k in range(n))


class _PhaseRing:
    r"""Polynomials in `\xi, \eta`: over the numbers, or (exact mode) one
    flat polynomial ring over `\mathbb Q` with the generators of the
    coefficients after the phase variables, so that Singular multiplies."""

    def __init__(self, A):
        n = A.n
        names = [f"xi{k + 1}" for k in range(n)] + [f"eta{k + 1}" for k in range(n)]
        self.n, self.A, self.flat = n, A, not A.is_numeric()
        if self.flat:
            self.P = PolynomialRing(A.K.base_ring(), names + list(A.K.variable_names()),
                                    order=TermOrder('degrevlex', 2 * n)
                                    + TermOrder('lex', A.K.ngens()))
            self.groebner = [self.P(g) for g in A.groebner]
        else:
            self.P = PolynomialRing(A.K, names)
        self.gens = self.P.gens()[:2 * n]

    def coefficient(self, c):
        return self.P(c)

    def monomial(self, e):
        return prod(x ** k for x, k in zip(self.gens, e))

    def terms(self, f):
        r"""``f`` as a dict: phase exponents -> coefficient (in ``A.K``)."""
        if not self.flat:
            return {tuple(e): c for e, c in f.dict().items()}
        found, m, K = {}, 2 * self.n, self.A.K
        for e, c in f.dict().items():
            found[e[:m]] = found.get(e[:m], 0) + c * K.monomial(*e[m:])
        return found

    def part(self, f, degrees):
        m = 2 * self.n
        return self.P({e: c for e, c in f.dict().items() if sum(e[:m]) in degrees})

    def reduce(self, f):
        if self.flat:
            return f.reduce(self.groebner)
        # rounding leaves traces of the terms that cancel: below the
        # threshold of A.is_zero they are zero
        eps = RealField(self.A.prec)(2) ** (-self.A.prec // 2)
        return self.P({e: c for e, c in f.dict().items() if abs(c) >= eps})

    def graded(self, f):
        r"""``f`` by its degrees in the phase variables: a dict degree ->
        homogeneous part."""
        m, parts = 2 * self.n, {}
        for e, c in f.dict().items():
            parts.setdefault(sum(e[:m]), {})[e] = c
        return {d: self.P(terms) for d, terms in parts.items()}

    def lie_transform(self, f, W, top):
        r"""`\exp(L_W) f = \sum_j \{\dots\{f, W\}, \dots, W\}/j!` up to degree
        ``top``, for ``W`` homogeneous: the bracket of parts of degrees `a`
        and `b` has the degree `a + b - 2`, so the parts that would exceed
        ``top`` are never multiplied (nor sorted out afterwards)."""
        if W.is_zero():
            return f
        w = sum(next(iter(W.dict()))[:2 * self.n])
        result = self.graded(f)
        term, j = result, 1
        while True:
            found = {}
            for d, part in term.items():
                if d + w - 2 <= top:
                    found[d + w - 2] = found.get(d + w - 2, 0) + \
                        _bracket(part, W, self.gens, self.n)
            term = {d: self.reduce(part) / j for d, part in found.items()}
            term = {d: part for d, part in term.items() if not part.is_zero()}
            if not term:
                return self.reduce(sum(result.values(), self.P(0)))
            for d, part in term.items():
                result[d] = result.get(d, 0) + part
            j += 1


def normal_form(arithmetic, order=4):
    r"""
    The Birkhoff normal form of ``arithmetic.H`` up to degree ``order``.

    INPUT:

    - ``arithmetic`` -- a :class:`FormalArithmetic` (numeric or exact)
    - ``order`` -- (default: 4) the degree of the normal form (at least 2)

    OUTPUT: a :class:`BirkhoffNormalForm`

    EXAMPLES: two oscillators `H = (q_1^2 + p_1^2) - (q_2^2 + p_2^2)/2 +
    q_1^2 q_2^2`, frequencies `2` and `-1`, the quartic term averaged to
    `(4 I_1 I_2)/(2\cdot 1)`, i.e. `q_k^2 \to I_k/\omega_k`::

        sage: from sage_dynsym.analysis.normal_forms import normal_form, FormalArithmetic
        sage: R = PolynomialRing(QQ, 'q1, q2, p1, p2'); q1, q2, p1, p2 = R.gens()
        sage: H = (q1^2 + p1^2) - (q2^2 + p2^2)/2 + q1^2*q2^2
        sage: nf = normal_form(FormalArithmetic(H.change_ring(PolynomialRing(QQ, 'a')), 2, {'a': 0}))
        sage: nf.frequencies(), nf.coefficients()[(1, 1)].n()
        ([2, -1], 1.00000000000000)

    TESTS::

        sage: normal_form(FormalArithmetic.numeric(R(q1^2 + p1^2 - q2^2 + p2^2), 2))
        Traceback (most recent call last):
        ...
        AnalysisError: at: the linearization has the roots ... a normal form needs simple roots on the imaginary axis ...
    """
    if order < 2:
        raise AnalysisError(f"order must be at least 2, got {order}", entry="order")
    A = arithmetic
    A.prepare(order)
    n, K = A.n, A.K
    S = A.hessian.apply_map(K) if not A.is_numeric() else A.hessian
    J = symplectic_unit(n).change_ring(K)
    M = J * S
    w, w_dash, c = [], [], []
    A.c_values = []
    for k, lam in enumerate(A.lambdas):
        w_k = _eigenvector(A, M.transpose(), lam, None)
        w_dash_k = _eigenvector(A, M.transpose(), -lam, w_k[1])
        c_k = A.reduce((w_k[0] * J * w_dash_k[0]))
        w.append(w_k[0])
        w_dash.append(w_dash_k[0])
        c.append(c_k)
        A.c_values.append(c_k)
    columns = [J * w_dash[k] * A.inverse(c[k], ('c', k)) for k in range(n)] + \
        [-J * w[k] for k in range(n)]
    T = matrix(K, columns).transpose()
    phase = _PhaseRing(A)
    z = T.apply_map(phase.coefficient) * vector(phase.gens)
    Hz = phase.P(0)
    for e, h in A.H.dict().items():
        if 2 <= sum(e) <= order:
            Hz += phase.coefficient(K(h)) * prod(x ** k for x, k in zip(z, e))
    Hz = phase.reduce(phase.part(Hz, range(2, order + 1)))
    generators = []
    for d in range(3, order + 1):
        W = phase.P(0)
        for e, h in phase.terms(phase.part(Hz, [d])).items():
            j = tuple(e[k] - e[n + k] for k in range(n))
            divisor = sum(j_k * lam for j_k, lam in zip(j, A.lambdas))
            zero = True if not any(j) else A.is_zero(A.reduce(divisor))
            if zero is False:
                W += phase.coefficient(A.reduce(h * A.inverse(divisor, ('d', j)))) * \
                    phase.monomial(e)
        generators.append(W)
        Hz = phase.lie_transform(Hz, W, order)
    return BirkhoffNormalForm(A, order, phase, Hz, T, generators, (w, w_dash, c))


def _eigenvector(A, B, lam, column):
    r"""A left eigenvector of `JS` for ``lam``: a column of the adjugate of
    `(JS)^T - \lambda`, the one largest in value (or the given one)."""
    n2 = B.nrows()
    adj = (B - lam * identity_matrix(B.base_ring(), n2)).adjugate()
    if column is None:
        sizes = [sum(abs(A.value(A.reduce(adj[i, j]))).upper() if not A.is_numeric() else
                     abs(adj[i, j]) for i in range(n2)) for j in range(n2)]
        column = max(range(n2), key=lambda j: sizes[j])
    return adj.column(column).apply_map(A.reduce), column


class BirkhoffNormalForm(SageObject):
    r"""
    The Birkhoff normal form of a Hamiltonian at an elliptic equilibrium
    (see the module documentation; made by :func:`normal_form`, or from a
    model by :func:`~sage_dynsym.dynamics.nonlinear_stability.birkhoff_normal_form`).

    EXAMPLES::

        sage: from sage_dynsym.analysis.normal_forms import normal_form, FormalArithmetic
        sage: R = PolynomialRing(QQ, 'q, p'); q, p = R.gens()
        sage: nf = normal_form(FormalArithmetic.numeric(p^2/2 + q^2/2 - q^4/24, 1))
        sage: nf
        Birkhoff normal form of order 4 in 1 degree(s) of freedom: -0.0625000000000000*I1^2 + I1

    TESTS:

    Normal forms have no value equality (their arithmetic holds rings of
    coefficients and floating-point numbers), so the pickling test is
    skipped; the degrees, signs and frequencies are consistent::

        sage: TestSuite(nf).run(skip='_test_pickling')
        sage: R = PolynomialRing(QQ, 'q1, q2, p1, p2'); q1, q2, p1, p2 = R.gens()
        sage: H = (q1^2 + p1^2)/2 - 2*(q2^2 + p2^2) + q1^2*q2^2
        sage: TestSuite(normal_form(FormalArithmetic.numeric(H, 2))).run(skip='_test_pickling')
        sage: B = PolynomialRing(QQ, 'k'); R = PolynomialRing(B, 'q, p'); q, p = R.gens()
        sage: nf = normal_form(FormalArithmetic(p^2/2 + q^2/2 + B.0*q^4, 1, {'k': None}, sample={'k': 1}))
        sage: TestSuite(nf).run(skip='_test_pickling')
    """

    def __init__(self, arithmetic, order, phase, H, T, generators, modes):
        self._A = arithmetic
        self._order = order
        self._phase = phase
        self._H = H
        self._T = T
        self._generators = generators
        self._modes = modes

    def _repr_(self):
        n = self._A.n
        return (f"Birkhoff normal form of order {self._order} in {n} degree(s) of freedom: "
                f"{self.polynomial()}")

    def _test_degrees(self, **options):
        r"""One sign and one frequency per degree of freedom, by decreasing
        `\omega_k`; the terms are of degrees 1 to ``order/2`` in the
        actions, and with numerical data the terms of degree 1 are the
        signed frequencies (`H_2 = \sum \sigma_k\omega_k I_k`).

        EXAMPLES: run by ``TestSuite`` (see the class).
        """
        tester = self._tester(**options)
        n, frequencies = self._A.n, self.frequencies()
        tester.assertEqual(len(frequencies), n)
        tester.assertTrue(set(self.signs()) <= {1, -1})
        coefficients = self.coefficients()
        for m in coefficients:
            tester.assertEqual(len(m), n)
            tester.assertTrue(1 <= sum(m) <= self._order // 2)
        if self._A.free:
            return
        omegas = [abs(f) for f in frequencies]
        tester.assertEqual(omegas, sorted(omegas, reverse=True))
        if self._A.is_numeric():
            for k, f in enumerate(frequencies):
                unit = tuple(int(j == k) for j in range(n))
                tester.assertAlmostEqual(float(coefficients[unit]), float(f))

    def order(self):
        r"""The degree up to which the Hamiltonian is normalized.

        EXAMPLES::

            sage: from sage_dynsym.analysis.normal_forms import normal_form, FormalArithmetic
            sage: R = PolynomialRing(QQ, 'q, p'); q, p = R.gens()
            sage: normal_form(FormalArithmetic.numeric(p^2/2 + q^2/2, 1), 6).order()
            6
        """
        return self._order

    def degrees_of_freedom(self):
        r"""The number of degrees of freedom `n` (canonical pairs).

        EXAMPLES::

            sage: from sage_dynsym.analysis.normal_forms import FormalArithmetic, normal_form
            sage: R = PolynomialRing(QQ, 'q1, q2, p1, p2'); q1, q2, p1, p2 = R.gens()
            sage: H = (p1^2 + q1^2)/2 + (p2^2 + 4*q2^2)/2 + q1^4
            sage: normal_form(FormalArithmetic.numeric(H, 2), 4).degrees_of_freedom()
            2
        """
        return self._A.n

    @cached_method
    def signs(self):
        r"""The sign `\sigma_k` of the quadratic energy on each mode.

        EXAMPLES::

            sage: from sage_dynsym.analysis.normal_forms import normal_form, FormalArithmetic
            sage: R = PolynomialRing(QQ, 'q1, q2, p1, p2'); q1, q2, p1, p2 = R.gens()
            sage: H = (q1^2 + p1^2)/2 - 2*(q2^2 + p2^2)
            sage: normal_form(FormalArithmetic.numeric(H, 2)).signs()
            [-1, 1]
        """
        A = self._A
        n = A.n
        J = symplectic_unit(n)
        signs = []
        CC = ComplexField(DECISION_BITS if not A.is_numeric() else A.prec)
        S = A.hessian.apply_map(lambda e: CC(A.value(e).center()) if not A.is_numeric()
                                else e)
        for k in range(n):
            w_dash = self._modes[1][k].apply_map(
                lambda e: CC(A.value(e).center()) if not A.is_numeric() else e)
            v = J.change_ring(CC) * w_dash
            energy = (v.conjugate() * S * v).real()
            signs.append(1 if energy > 0 else -1)
        return signs

    def frequencies(self):
        r"""
        The signed frequencies `\sigma_k\omega_k`, `\omega_1 > \omega_2 >
        \dots`, the sign that of the quadratic energy on the mode
        (`H_2 = \sum \sigma_k\omega_k I_k`): algebraic numbers when the data
        are exact, else numbers; with a free parameter, the symbols
        ``omega1, ...`` signed.

        EXAMPLES::

            sage: from sage_dynsym.analysis.normal_forms import normal_form, FormalArithmetic
            sage: R = PolynomialRing(QQ, 'q1, q2, p1, p2'); q1, q2, p1, p2 = R.gens()
            sage: H = (q1^2 + p1^2)/2 - 2*(q2^2 + p2^2)
            sage: normal_form(FormalArithmetic.numeric(H, 2)).frequencies()
            [-4.00000000000000, 1.00000000000000]
        """
        A = self._A
        if A.is_numeric():
            return [s * lam.imag() for s, lam in zip(self.signs(), A.lambdas)]
        if A.free:
            return [s * SR.var(f"omega{k + 1}") for k, s in enumerate(self.signs())]
        return [s * AA(lam.imag()) for s, lam in zip(self.signs(), A.exact_lambdas())]

    def action_terms(self):
        r"""
        The normal form's terms, in the ring of the computation: a pair of
        dicts, exponents ``(m_1, .., m_n)`` of the actions -> coefficient of
        `\prod (\xi_k\eta_k)^{m_k}`, and the resonant terms apart
        (exponents of `(\xi, \eta)` -> coefficient).

        EXAMPLES::

            sage: from sage_dynsym.analysis.normal_forms import normal_form, FormalArithmetic
            sage: R = PolynomialRing(QQ, 'q, p'); q, p = R.gens()
            sage: nf = normal_form(FormalArithmetic.numeric(p^2/2 + q^2/2 - q^4/24, 1), 4)
            sage: terms, resonant = nf.action_terms(); sorted(terms), resonant
            ([(1,), (2,)], {})
        """
        n = self._A.n
        terms, resonant = {}, {}
        for e, h in self._phase.terms(self._H).items():
            if all(e[k] == e[n + k] for k in range(n)):
                terms[tuple(e[:n])] = h
            else:
                resonant[tuple(e)] = h
        return terms, resonant

    def _real_factor(self, m):
        r"""`\prod (-i\sigma_k)^{m_k}` (`\xi_k\eta_k = -i\sigma_k I_k`)."""
        signs = self.signs()
        phase = (-sum(m)) % 4
        sign = prod(s ** mk for s, mk in zip(signs, m))
        return sign, phase

    def coefficients(self, exact=False):
        r"""
        The normal form in the actions: a dict exponents ``(m_1, ..,
        m_n)`` -> the coefficient of `I_1^{m_1}\cdots I_n^{m_n}` (the
        terms of degree 2 are the signed frequencies). Numbers (real
        intervals of :data:`DECISION_BITS` bits in exact mode, algebraic
        numbers with ``exact=True``); with a free parameter, symbolic
        expressions in the parameters, constants and ``omega1, ...``.

        EXAMPLES: see the module documentation, and::

            sage: from sage_dynsym.analysis.normal_forms import normal_form, FormalArithmetic
            sage: B = PolynomialRing(QQ, 'k'); R = PolynomialRing(B, 'q, p'); q, p = R.gens()
            sage: H = p^2/2 + q^2/2 + B.0*q^4
            sage: nf = normal_form(FormalArithmetic(H, 1, {'k': None}, sample={'k': 1}))
            sage: nf.coefficients()[(2,)]
            3/2*k/omega1^2
            sage: nf.relations()
            [-omega1^2 + 1]
        """
        A = self._A
        terms, _ = self.action_terms()
        result = {}
        for m, h in terms.items():
            sign, phase = self._real_factor(m)
            if A.free and not A.is_numeric():
                result[m] = sign * self._symbolic_real(h, phase)
            elif exact and not A.is_numeric():
                result[m] = AA(sign * (A.exact_value(h) * [1, QQbar.gen(), -1, -QQbar.gen()][phase]).real())
            else:
                result[m] = self._real_value(m, h)
        return result

    def _real_value(self, m, h):
        r"""The coefficient of `I^m` from the term ``h`` of
        `\prod(\xi_k\eta_k)^{m_k}`: a number (an interval in exact mode)."""
        A = self._A
        sign, phase = self._real_factor(m)
        if A.is_numeric():
            return sign * (h * [1, A.K.gen(), -1, -A.K.gen()][phase]).real()
        i = A.value(A.K(0)).parent().gen()
        return sign * (A.value(h) * [1, i, -1, -i][phase]).real()

    def _symbolic_real(self, h, phase):
        r"""The real value of `i^{phase} h` as a symbolic expression: each
        generator `\lambda_k \to i\omega_k` (see
        :meth:`FormalArithmetic.symbolic_images`; the imaginary parts cancel)."""
        value = (SR.I() ** phase * self._A.symbolic(h)).expand()
        return value.real_part().simplify_rational() if value.has(SR.I()) else value.simplify_rational()

    def relations(self):
        r"""With a free parameter: the relations of the symbols
        ``omega1, ...`` (the characteristic polynomial's coefficients as
        symmetric functions of the `\omega_k^2`) and of the constants.

        EXAMPLES: see :meth:`coefficients`.
        """
        return [self._A.symbolic(r).expand() for r in self._A.groebner]

    def polynomial(self):
        r"""The normal form as a polynomial in the actions ``I1, ...``
        (the resonant terms apart, see :meth:`resonant_terms`).

        EXAMPLES: see the class documentation.
        """
        coefficients = self.coefficients()
        ring = (PolynomialRing(SR, [f"I{k + 1}" for k in range(self._A.n)]) if self._A.free
                else PolynomialRing(next(iter(coefficients.values())).parent(),
                                    [f"I{k + 1}" for k in range(self._A.n)]))
        return ring(coefficients)

    def resonant_terms(self):
        r"""The terms of the normal form that are not functions of the
        actions (left by a resonance): a dict exponents of
        `(\xi_1..\xi_n, \eta_1..\eta_n)` -> coefficient (in the ring of
        the computation).

        EXAMPLES::

            sage: from sage_dynsym.analysis.normal_forms import normal_form, FormalArithmetic
            sage: R = PolynomialRing(QQ, 'q1, q2, p1, p2'); q1, q2, p1, p2 = R.gens()
            sage: H = (q1^2 + p1^2) - (q2^2 + p2^2)/2 + q1*q2^2
            sage: sorted(normal_form(FormalArithmetic.numeric(H, 2), 3).resonant_terms())
            [(0, 2, 1, 0), (1, 0, 0, 2)]
        """
        return self.action_terms()[1]

    def hamiltonian(self):
        r"""The normal form as a polynomial in the complex canonical
        coordinates `\xi_k, \eta_k` (``xi1, .., eta1, ..``), over the ring
        of the computation.

        EXAMPLES::

            sage: from sage_dynsym.analysis.normal_forms import normal_form, FormalArithmetic
            sage: R = PolynomialRing(QQ, 'q, p'); q, p = R.gens()
            sage: normal_form(FormalArithmetic.numeric(p^2/2 + q^2/2, 1)).hamiltonian()
            1.00000000000000*I*xi1*eta1
        """
        return self._H

    def transformation(self):
        r"""
        The change of variables: a pair ``(T, phi)``, `T` the matrix of
        the linear map `(q, p) = T (\xi, \eta)` and ``phi`` the list of the
        polynomials `(\xi, \eta) = \varphi(\xi', \eta')` of the Lie series
        (degree ``order - 1``), so that `H(T\varphi(\xi', \eta'))`
        equals :meth:`hamiltonian` at `(\xi', \eta')` up to degree
        ``order``.

        EXAMPLES::

            sage: from sage_dynsym.analysis.normal_forms import normal_form, FormalArithmetic
            sage: R = PolynomialRing(QQ, 'q, p'); q, p = R.gens()
            sage: H = p^2/2 + q^2/2 - q^3/6
            sage: nf = normal_form(FormalArithmetic.numeric(H, 1, prec=80), 4)
            sage: T, phi = nf.transformation()
            sage: z = T * vector(phi)
            sage: error = (H.change_ring(T.base_ring())(*z) - nf.hamiltonian())
            sage: max(abs(c) for e, c in error.dict().items() if sum(e) <= 4) < 1e-20
            True
        """
        phase = self._phase
        coordinates = list(phase.gens)
        for W in self._generators:
            coordinates = [phase.lie_transform(x, W, self._order - 1) for x in coordinates]
        return self._T, coordinates

    def generators(self):
        r"""The generating functions `W_3, W_4, \dots` of the Lie transforms
        (polynomials in `\xi, \eta`).

        EXAMPLES::

            sage: from sage_dynsym.analysis.normal_forms import normal_form, FormalArithmetic
            sage: R = PolynomialRing(QQ, 'q, p'); q, p = R.gens()
            sage: len(normal_form(FormalArithmetic.numeric(p^2/2 + q^2/2, 1), 5).generators())
            3
        """
        return list(self._generators)

    def arithmetic(self):
        r"""The :class:`FormalArithmetic` of the computation.

        EXAMPLES::

            sage: from sage_dynsym.analysis.normal_forms import normal_form, FormalArithmetic
            sage: R = PolynomialRing(QQ, 'q, p'); q, p = R.gens()
            sage: normal_form(FormalArithmetic.numeric(p^2/2 + q^2/2, 1)).arithmetic()
            numeric arithmetic (53 bits)
        """
        return self._A

    def form_values(self, degree):
        r"""
        The coefficients of the terms in the actions of degree ``degree``
        (in the phase variables) as values: a dict exponents of the actions
        -> number (an interval in exact mode).

        EXAMPLES: the pendulum, `H = I - I^2/16`::

            sage: from sage_dynsym.analysis.normal_forms import normal_form, FormalArithmetic
            sage: R = PolynomialRing(QQ, 'q, p'); q, p = R.gens()
            sage: nf = normal_form(FormalArithmetic.numeric(p^2/2 + q^2/2 - q^4/24, 1), 4)
            sage: nf.form_values(4)
            {(2,): -0.0625000000000000}
        """
        return {m: self._real_value(m, h) for m, h in self.action_terms()[0].items()
                if 2 * sum(m) == degree}

    def arnold_determinant(self, degree=4):
        r"""
        Arnold's determinant: in two degrees of freedom the term of degree
        ``degree`` of the normal form, a form `H_{2m}(I_1, I_2)` in the
        actions, on the ray where `H_2 = w_1 I_1 + w_2 I_2` vanishes,
        `D = H_{2m}(w_2, -w_1)` (for `m = 2`:
        `D = c_{20} w_2^2 - c_{11} w_1 w_2 + c_{02} w_1^2`, Deprit's and
        Markeev's `D`); in more degrees of freedom the determinant of the
        Hessian of `H_4` bordered by the frequencies (isoenergetic
        nondegeneracy). A number (an interval in exact mode); with a free
        parameter, a symbolic expression.

        EXAMPLES: `H = I_1 - 2 I_2 + I_1^2 + I_2^2` gives `4 + 1 = 5`::

            sage: from sage_dynsym.analysis.normal_forms import normal_form, FormalArithmetic
            sage: R = PolynomialRing(QQ, 'q1, q2, p1, p2'); q1, q2, p1, p2 = R.gens()
            sage: I1, I2 = (q1^2 + p1^2)/2, (q2^2 + p2^2)/2
            sage: nf = normal_form(FormalArithmetic.numeric(I1 - 2*I2 + I1^2 + I2^2, 2))
            sage: nf.arnold_determinant()
            5.00000000000000

        TESTS::

            sage: nf.arnold_determinant(5)
            Traceback (most recent call last):
            ...
            AnalysisError: degree: expected an even degree from 4 to the order 4, got 5
        """
        if degree % 2 or not 4 <= degree <= self._order:
            raise AnalysisError(f"expected an even degree from 4 to the order {self._order}, "
                                f"got {degree}", entry="degree")
        n = self._A.n
        if self._A.free:
            w = self.frequencies()
            form = {m: c for m, c in self.coefficients().items() if 2 * sum(m) == degree}
            return self._on_ray(form, w)
        w = [s * (lam.imag() if self._A.is_numeric() else self._A.value(lam).imag())
             for s, lam in zip(self.signs(), self._A.lambdas)]
        form = self.form_values(degree)
        if n == 2:
            return self._on_ray(form, w)
        ring = PolynomialRing(w[0].parent(), [f"I{k + 1}" for k in range(n)])
        H4 = ring(form)
        hessian = matrix([[H4.derivative(a).derivative(b).constant_coefficient()
                           for b in ring.gens()] + [w[i]] for i, a in enumerate(ring.gens())])
        return matrix(list(hessian) + [list(w) + [0]]).det()

    @staticmethod
    def _on_ray(form, w):
        return sum(c * w[1] ** m[0] * (-w[0]) ** m[1] for m, c in form.items())

    def resonances(self, order, tolerance=QQ((1, 20))):
        r"""
        The resonance relations `k\cdot w = 0` of order `|k| \le` ``order``
        that hold or nearly hold: a list of pairs ``(k, k.w)`` with
        `|k\cdot w| \le` ``tolerance`` (`k_1 > 0`, `k` not a multiple of a
        shorter one), ordered by `|k\cdot w|`; an exact resonance has the
        value ``0``.

        EXAMPLES::

            sage: from sage_dynsym.analysis.normal_forms import normal_form, FormalArithmetic
            sage: R = PolynomialRing(QQ, 'q1, q2, p1, p2'); q1, q2, p1, p2 = R.gens()
            sage: H = (q1^2 + p1^2) - (q2^2 + p2^2)/2
            sage: nf = normal_form(FormalArithmetic(H.change_ring(PolynomialRing(QQ, 'a')), 2, {'a': 0}))
            sage: nf.resonances(3)
            [((1, 2), 0)]
        """
        A = self._A
        if A.free:
            raise AnalysisError("the resonances depend on the free parameters: give them "
                                "values, or use critical_values()", entry="resonances")
        w = self.frequencies()
        found = []
        for k in itertools.product(range(-order, order + 1), repeat=A.n):
            if sum(map(abs, k)) > order or not any(k) or next(x for x in k if x) < 0 or \
                    _gcd(k) != 1:
                continue
            value = sum(a * b for a, b in zip(k, w))
            exact_zero = (value == 0) if not A.is_numeric() else \
                abs(value) < RealField(A.prec)(2) ** (-A.prec // 2)
            if exact_zero or abs(value) <= tolerance:
                found.append((k, 0 if exact_zero else value))
        return sorted(found, key=lambda kv: abs(kv[1]))


    def resonant_amplitude(self, degree):
        r"""
        The amplitude `a` of the resonant terms of degree ``degree``,
        written `a\,\prod I_k^{(a_k + b_k)/2}\cos(\dots)`: for each pair of
        conjugate terms `\alpha\xi^a\eta^b + \beta\xi^b\eta^a`,
        `a = 2\sqrt{\alpha\beta\prod(-i\sigma_k)^{a_k + b_k}}` (summed
        over the pairs; ``0`` when there is no resonant term).

        EXAMPLES: `H = (q_1^2 + p_1^2) - (q_2^2 + p_2^2)/2 + q_1 q_2^2`,
        resonance `2 \cdot 1 = 1\cdot 2`; `q_1 q_2^2 = \sqrt{I_1/2}
        (I_2/1)\,2\cos\varphi_1 \cos^2\varphi_2` averages to
        `\sqrt{2}/2\, I_1^{1/2} I_2 \cos(\varphi_1 - 2\varphi_2)`::

            sage: from sage_dynsym.analysis.normal_forms import normal_form, FormalArithmetic
            sage: R = PolynomialRing(QQ, 'q1, q2, p1, p2'); q1, q2, p1, p2 = R.gens()
            sage: H = (q1^2 + p1^2) - (q2^2 + p2^2)/2 + q1*q2^2
            sage: normal_form(FormalArithmetic.numeric(H, 2), 3).resonant_amplitude(3)
            0.707106781186548
        """
        A = self._A
        n = A.n
        signs = self.signs()
        total, seen = 0, set()
        terms = self.resonant_terms()
        for e, alpha in terms.items():
            if sum(e) != degree or e in seen:
                continue
            partner = tuple(e[n:]) + tuple(e[:n])
            seen |= {e, partner}
            beta = terms.get(partner, 0)
            power = sum(e[k] + e[n + k] for k in range(n))
            sign = prod(s ** (e[k] + e[n + k]) for k, s in enumerate(signs))
            a, b = (alpha, beta) if A.is_numeric() else (A.value(alpha), A.value(beta))
            i = a.parent().gen()
            square = (a * b * sign * (-i) ** power).real()
            total += 2 * square.abs().sqrt()
        return total


def _gcd(k):
    return gcd(list(k))
