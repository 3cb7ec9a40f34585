r"""
Poisson structures: the named Lie algebras and user-given brackets

A :class:`PoissonStructure` is a Poisson matrix `J(x)`, `J_{ij} = \{x_i,
x_j\}`, on coordinates `x`; the bracket of two functions is `\{F, G\} =
\nabla F^T J \nabla G` and the equations of a Hamiltonian `H` are `\dot x
= J\nabla H`. It is checked to be skew-symmetric and to satisfy the Jacobi
identity.

**Sign convention.** On the dual of a Lie algebra with structure constants
`[e_i, e_j] = c_{ij}^k e_k` the Lie--Poisson bracket is the *minus*
bracket

.. MATH::

    \{x_i, x_j\} = -c_{ij}^k\, x_k,

the bracket of the components of the momentum in the *body* frame: the
reduction of the canonical bracket `\{q, p\} = 1` by left translations
(Arnold, *Mathematical Methods of Classical Mechanics*, App. 2; Marsden &
Ratiu, *Introduction to Mechanics and Symmetry*, Thm. 13.1.1). For the
rigid body `[e_i, e_j] = \varepsilon_{ijk} e_k` (the cross product) gives
`\{M_i, M_j\} = -\varepsilon_{ijk} M_k` and Euler's equations `\dot M =
M \times \partial H/\partial M`.

The named algebras (:func:`lie_algebra`), with `\kappa = 0, 1, -1` for
`e(3)`, `so(4)`, `so(3,1)` (Borisov & Mamaev, *Rigid Body Dynamics*,
§1.6):

- ``'so3'``: `M_1, M_2, M_3`; `\{M_i, M_j\} = -\varepsilon_{ijk} M_k`;
- ``'e3'``, ``'so4'``, ``'so31'``: `M_1, M_2, M_3, \gamma_1, \gamma_2,
  \gamma_3` (for ``'e3'``; `p_i` for the others, and also for ``'e3'`` with
  ``variables=['M', 'p']``):

  .. MATH::

      \{M_i, M_j\} = -\varepsilon_{ijk} M_k,\quad
      \{M_i, \gamma_j\} = -\varepsilon_{ijk}\gamma_k,\quad
      \{\gamma_i, \gamma_j\} = -\kappa\,\varepsilon_{ijk} M_k,

  so that `\dot M = M\times\partial H/\partial M + \gamma\times\partial
  H/\partial\gamma`, `\dot\gamma = \gamma\times\partial H/\partial M +
  \kappa\,\gamma\times\partial H/\partial\gamma` -- the Euler--Poisson and
  Kirchhoff equations for `\kappa = 0`;
- ``'e4'``: `M_{12}, M_{13}, M_{14}, M_{23}, M_{24}, M_{34}, p_1, \dots,
  p_4`, the dual of `so(4) \ltimes \mathbb{R}^4` with the basis `F_{ij} =
  e_j e_i^T - e_i e_j^T` (`i < j`) of `so(4)`, acting on `\mathbb{R}^4` by
  matrix multiplication. `F_{23}, -F_{13}, F_{12}` are the matrices of `e_1
  \times, e_2\times, e_3\times`, so `M_{23}, -M_{13}, M_{12}, p_1, p_2, p_3`
  satisfy the brackets of `e(3)`.

EXAMPLES::

    sage: from sage_dynsym.lie.algebras import lie_algebra, poisson_structure
    sage: E = lie_algebra('e3'); E
    Lie-Poisson structure e3 on (M1, M2, M3, gamma1, gamma2, gamma3)
    sage: E.matrix()
    [      0     -M3      M2       0 -gamma3  gamma2]
    [     M3       0     -M1  gamma3       0 -gamma1]
    [    -M2      M1       0 -gamma2  gamma1       0]
    [      0 -gamma3  gamma2       0       0       0]
    [ gamma3       0 -gamma1       0       0       0]
    [-gamma2  gamma1       0       0       0       0]
    sage: lie_algebra('e(3)', variables=['M', 'p']).variables()
    [M1, M2, M3, p1, p2, p3]

A user's Poisson matrix, and structure constants `[e_1, e_2] = e_3`,
`[e_3, e_1] = e_1`, ... are checked::

    sage: x, y, z = var('x y z')
    sage: poisson_structure(matrix([[0, z, -y], [-z, 0, x], [y, -x, 0]]), [x, y, z])
    Poisson structure on (x, y, z)
    sage: poisson_structure({(0, 1): {2: 1}, (1, 2): {0: 1}, (2, 0): {1: 1}}, [x, y, z]).matrix()
    [ 0 -z  y]
    [ z  0 -x]
    [-y  x  0]
    sage: poisson_structure(matrix([[0, x, 0], [-x, 0, y], [0, -y, 0]]), [x, y, z])
    Traceback (most recent call last):
    ...
    ModelError: algebra: the matrix breaks the Jacobi identity: {x, {y, z}} + {y, {z, x}} + {z, {x, y}} = x, not 0

REFERENCES:

- V. I. Arnold, *Mathematical Methods of Classical Mechanics*, 2nd ed.,
  Springer, 1989, Appendix 2.
- J. E. Marsden, T. S. Ratiu, *Introduction to Mechanics and Symmetry*,
  2nd ed., Springer, 1999, ch. 13 and §15.7.
- A. V. Borisov, I. S. Mamaev, *Rigid Body Dynamics*, De Gruyter, 2018, §1.6.
"""
import re

from sage.matrix.constructor import matrix
from sage.misc.latex import latex
from sage.structure.sage_object import SageObject
from sage.symbolic.ring import SR

from ..algebra.solving import normalize, vanishes
from ..arguments import expression_argument
from ..errors import AnalysisError, ModelError, brief
from ..algebra.polynomial_spaces import PolynomialContext, monomial_expression

__all__ = ['NAMED', 'algebra_name', 'default_names', 'PoissonStructure', 'collect', 'lie_algebra',
           'structure_constants_matrix', 'poisson_structure']

#: The named algebras: name -> (description, block names, block sizes).
NAMED = {
    'so3': ("so(3)", ('M',), (3,)),
    'e3': ("e(3) = so(3) + R^3", ('M', 'gamma'), (3, 3)),
    'so4': ("so(4)", ('M', 'p'), (3, 3)),
    'so31': ("so(3,1)", ('M', 'p'), (3, 3)),
    'e4': ("e(4) = so(4) + R^4", ('M', 'p'), (6, 4)),
}

_KAPPA = {'e3': 0, 'so4': 1, 'so31': -1}
_PAIRS4 = [(1, 2), (1, 3), (1, 4), (2, 3), (2, 4), (3, 4)]


def _eps(i, j, k):
    return (i - j) * (j - k) * (k - i) // 2


def algebra_name(name):
    r"""
    The canonical name of a named algebra (``'so(3,1)'`` -> ``'so31'``),
    or ``None``.

    EXAMPLES::

        sage: from sage_dynsym.lie.algebras import algebra_name
        sage: algebra_name('so(3,1)'), algebra_name('E3'), algebra_name('sl2')
        ('so31', 'e3', None)
    """
    key = re.sub(r'[\s(),_]', '', str(name)).lower()
    return key if key in NAMED else None


def default_names(name, prefixes=None):
    r"""
    The default coordinate names of the named algebra ``name`` (a key of
    ``NAMED``), block by block, each block's names made of its prefix (or
    of the given ``prefixes``) and an index.

    EXAMPLES::

        sage: from sage_dynsym.lie.algebras import default_names
        sage: default_names('e3')
        ['M1', 'M2', 'M3', 'gamma1', 'gamma2', 'gamma3']
        sage: default_names('so3', ['L'])
        ['L1', 'L2', 'L3']
        sage: default_names('e4')[:3], default_names('e4')[-1]
        (['M12', 'M13', 'M14'], 'p4')
    """
    _, blocks, sizes = NAMED[name]
    prefixes = blocks if prefixes is None else prefixes
    if name == 'e4':
        return [f"{prefixes[0]}{i}{j}" for i, j in _PAIRS4] + \
            [f"{prefixes[1]}{k}" for k in range(1, 5)]
    return [f"{p}{k}" for p, n in zip(prefixes, sizes) for k in range(1, n + 1)]


def _variables(name, variables):
    n = sum(NAMED[name][2])
    nblocks = len(NAMED[name][1])
    if variables is None:
        names = default_names(name)
    else:
        if isinstance(variables, str):
            variables = [v for v in re.split(r'[\s,]+', variables) if v]
        variables = _listed(variables)
        if len(variables) == nblocks and nblocks < n and all(
                isinstance(v, str) or getattr(v, 'is_symbol', lambda: False)()
                for v in variables):
            names = default_names(name, [str(v) for v in variables])
        elif len(variables) == n:
            names = variables
        else:
            expected = f"{n} coordinates ({', '.join(default_names(name))})"
            if nblocks > 1:
                expected += f" or {nblocks} prefixes (e.g. {list(NAMED[name][1])})"
            raise ModelError(f"{name} has {expected}, got {len(variables)} variables: "
                             f"{brief([str(v) for v in variables])}", entry="variables")
    return _symbols(names)


def _listed(names):
    r"""``names`` as a list, or a :class:`ModelError` for what is not a list."""
    if isinstance(names, (str, bytes, dict)) or not hasattr(names, '__iter__'):
        raise ModelError(f"expected a list of variables, got {brief(names)}", entry="variables")
    return list(names)


def _symbols(names):
    names = _listed(names)
    out = []
    for i, v in enumerate(names):
        try:
            s = SR(v) if not isinstance(v, str) else SR.var(v)
        except (TypeError, ValueError) as err:
            raise ModelError(f"expected a symbol name, got {brief(v)} ({err})",
                             entry=f"variables[{i}]") from err
        if not s.is_symbol():
            raise ModelError(f"expected a symbolic variable, got {s}", entry=f"variables[{i}]")
        out.append(s)
    if len(set(map(str, out))) != len(out):
        raise ModelError(f"the variables must be distinct, got {out}", entry="variables")
    return out


def _named_matrix(name, x):
    n = len(x)
    J = matrix(SR, n, n)
    if name == 'e4':
        return _semidirect_matrix(x)
    M = x[:3]
    for i in range(3):
        for j in range(3):
            for k in range(3):
                e = _eps(i, j, k)
                if e:
                    J[i, j] -= e * M[k]
                    if n == 6:
                        g = x[3:]
                        J[i, 3 + j] -= e * g[k]
                        J[3 + j, i] += e * g[k]
                        J[3 + i, 3 + j] -= _KAPPA[name] * e * M[k]
    return J


def _semidirect_matrix(x):
    # so(4) + R^4 from matrix commutators: F_ij = e_j e_i^T - e_i e_j^T
    def F(i, j):
        A = matrix(SR, 4, 4)
        A[j - 1, i - 1], A[i - 1, j - 1] = 1, -1
        return A

    basis = [F(i, j) for i, j in _PAIRS4]

    def coordinates(A):     # of a skew matrix in the basis F_ij
        return [A[j - 1, i - 1] for i, j in _PAIRS4]
    M, p = x[:6], x[6:]
    J = matrix(SR, 10, 10)
    for a in range(6):
        for b in range(6):
            c = coordinates(basis[a] * basis[b] - basis[b] * basis[a])
            J[a, b] = -sum(ck * Mk for ck, Mk in zip(c, M))
        for k in range(4):
            image = basis[a].column(k)           # F_a e_k
            J[a, 6 + k] = -sum(image[l] * p[l] for l in range(4))
            J[6 + k, a] = -J[a, 6 + k]
    return J


class PoissonStructure(SageObject):
    r"""
    A Poisson matrix on coordinates, checked for skew-symmetry and the
    Jacobi identity.

    INPUT:

    - ``poisson_matrix`` -- a square matrix (or list of rows) of
      expressions in ``variables`` and parameters, `J_{ij} = \{x_i, x_j\}`
    - ``variables`` -- the coordinates `x`
    - ``name`` -- (optional) the name of a named algebra
    - ``check`` -- (default: ``True``) check the axioms

    Use :func:`poisson_structure` or :func:`lie_algebra` to build one from a
    name, a matrix or structure constants.

    EXAMPLES::

        sage: from sage_dynsym.lie.algebras import PoissonStructure
        sage: q, p = var('q p')
        sage: P = PoissonStructure([[0, 1], [-1, 0]], [q, p]); P
        Poisson structure on (q, p)
        sage: P.bracket(q, p), P.bracket(q^2, p^2), P.is_lie_poisson()
        (1, 4*p*q, False)

    It has no value equality (two of them are equal only if they are the
    same object), so the pickling test, which compares the copy with the
    original, is skipped::

        sage: TestSuite(P).run(skip=['_test_pickling'])

    TESTS::

        sage: PoissonStructure([[0, 1], [1, 0]], [q, p])
        Traceback (most recent call last):
        ...
        ModelError: algebra: the matrix is not skew-symmetric: entry (0, 1) is 1, entry (1, 0) is 1
        sage: PoissonStructure([[0, 1]], [q, p])
        Traceback (most recent call last):
        ...
        ModelError: algebra: expected a square 2x2 matrix (one row and column per variable q, p), got 1 rows of lengths [2]
    """

    def __init__(self, poisson_matrix, variables, name=None, check=True):
        self._variables = _symbols(variables)
        n = len(self._variables)
        try:
            rows = [list(r) for r in poisson_matrix]
        except TypeError as cause:
            raise ModelError(f"expected a Poisson matrix (a list of rows), got "
                             f"{brief(poisson_matrix)}", entry="algebra") from cause
        if len(rows) != n or any(len(r) != n for r in rows):
            raise ModelError(f"expected a square {n}x{n} matrix (one row and column per "
                             f"variable {', '.join(map(str, self._variables))}), got "
                             f"{len(rows)} rows of lengths {[len(r) for r in rows]}",
                             entry="algebra")
        try:
            self._J = matrix(SR, n, n, [SR(c) for r in rows for c in r])
        except (TypeError, ValueError) as err:
            raise ModelError(f"the entries must be expressions: {err}", entry="algebra") \
                from err
        self._J.set_immutable()
        self._name = name
        names = set(map(str, self._variables))
        self._parameters = sorted({a for c in self._J.list() for a in c.variables()
                                   if str(a) not in names}, key=str)
        if check:
            self._check()

    # -- checks -------------------------------------------------------------

    def _check(self):
        J, x, n = self._J, self._variables, len(self._variables)
        for i in range(n):
            for j in range(i, n):
                if not vanishes(J[i, j] + J[j, i], maxima=False):
                    raise ModelError(f"the matrix is not skew-symmetric: entry ({i}, {j}) is "
                                     f"{J[i, j]}, entry ({j}, {i}) is {J[j, i]}", entry="algebra")
        for i in range(n):
            for j in range(i + 1, n):
                for k in range(j + 1, n):
                    jac = sum(J[i, l] * J[j, k].diff(x[l]) + J[j, l] * J[k, i].diff(x[l]) +
                              J[k, l] * J[i, j].diff(x[l]) for l in range(n))
                    if not vanishes(jac, maxima=False):
                        a, b, c = x[i], x[j], x[k]
                        raise ModelError(
                            f"the matrix breaks the Jacobi identity: {{{a}, {{{b}, {c}}}}} + "
                            f"{{{b}, {{{c}, {a}}}}} + {{{c}, {{{a}, {b}}}}} = "
                            f"{_normal(jac)}, not 0", entry="algebra")

    def _test_bracket(self, **options):
        r"""The bracket of :meth:`bracket` takes the matrix's entries on
        the coordinates, and on three polynomials of them it is
        antisymmetric, a derivation (Leibniz's rule) and satisfies the
        Jacobi identity.

        EXAMPLES: run by ``TestSuite`` (see the class).
        """
        tester = self._tester(**options)
        x, J, n = self._variables, self._J, len(self._variables)
        for i in range(n):
            for j in range(n):
                tester.assertTrue(vanishes(self.bracket(x[i], x[j]) - J[i, j], maxima=False))
        F, G, H = x[0] ** 2 + x[-1], x[0] * x[-1] + 1, sum(x) ** 2
        b = self.bracket
        for value in (b(F, G) + b(G, F), b(F, G * H) - b(F, G) * H - G * b(F, H),
                      b(F, b(G, H)) + b(G, b(H, F)) + b(H, b(F, G))):
            tester.assertTrue(vanishes(SR(value).expand(), maxima=False), f"{value} is not 0")

    # -- accessors ---------------------------------------------------------

    def _repr_(self):
        kind = f"Lie-Poisson structure {self._name}" if self._name else "Poisson structure"
        return f"{kind} on ({', '.join(map(str, self._variables))})"

    def _latex_(self):
        return latex(self._J)

    def name(self):
        r"""
        The name of a named algebra, else ``None``.

        EXAMPLES::

            sage: from sage_dynsym.lie.algebras import lie_algebra
            sage: lie_algebra('so(4)').name()
            'so4'
        """
        return self._name

    def variables(self):
        r"""
        The coordinates.

        EXAMPLES::

            sage: from sage_dynsym.lie.algebras import lie_algebra
            sage: lie_algebra('e4').variables()
            [M12, M13, M14, M23, M24, M34, p1, p2, p3, p4]
        """
        return list(self._variables)

    def parameters(self):
        r"""
        The symbols of the matrix that are not coordinates.

        EXAMPLES::

            sage: from sage_dynsym.lie.algebras import PoissonStructure
            sage: x, y, k = var('x y k')
            sage: PoissonStructure([[0, k*x], [-k*x, 0]], [x, y]).parameters()
            [k]
        """
        return list(self._parameters)

    def matrix(self):
        r"""
        The Poisson matrix `J`, `J_{ij} = \{x_i, x_j\}` (immutable).

        EXAMPLES::

            sage: from sage_dynsym.lie.algebras import lie_algebra
            sage: lie_algebra('so3').matrix()
            [  0 -M3  M2]
            [ M3   0 -M1]
            [-M2  M1   0]
        """
        return self._J

    def dimension(self):
        r"""
        The number of coordinates.

        EXAMPLES::

            sage: from sage_dynsym.lie.algebras import lie_algebra
            sage: lie_algebra('e4').dimension()
            10
        """
        return len(self._variables)

    def is_lie_poisson(self):
        r"""
        Whether every entry is a linear form in the coordinates (the dual
        of a Lie algebra).

        EXAMPLES::

            sage: from sage_dynsym.lie.algebras import lie_algebra
            sage: lie_algebra('so31').is_lie_poisson()
            True
        """
        x = self._variables
        for c in self._J.list():
            coefficients = [c.diff(v) for v in x]
            if any(set(d.variables()) & set(x) for d in coefficients):
                return False
            if not vanishes(c - sum(d * v for d, v in zip(coefficients, x)), maxima=False):
                return False
        return True

    def bracket(self, F, G):
        r"""
        `\{F, G\} = \sum_{i,j} \partial_i F\, J_{ij}\, \partial_j G`.

        EXAMPLES::

            sage: from sage_dynsym.lie.algebras import lie_algebra
            sage: E = lie_algebra('e3'); M1, M2, M3, g1, g2, g3 = E.variables()
            sage: E.bracket(M1, M2), E.bracket(M1, g2), E.bracket(g1, g2)
            (-M3, -gamma3, 0)
        """
        x, J = self._variables, self._J
        dF = [expression_argument(F, "F", AnalysisError).diff(v) for v in x]
        dG = [expression_argument(G, "G", AnalysisError).diff(v) for v in x]
        return collect(sum(dF[i] * J[i, j] * dG[j] for i in range(len(x))
                           for j in range(len(x)) if J[i, j] != 0 and dF[i] != 0 and
                           dG[j] != 0), x)

    def vector_field(self, H):
        r"""
        `J\nabla H`, the right-hand sides of `\dot x_i = \{x_i, H\}`.

        EXAMPLES::

            sage: from sage_dynsym.lie.algebras import lie_algebra
            sage: S = lie_algebra('so3'); M1, M2, M3 = S.variables()
            sage: S.vector_field((M1^2 + M2^2 + 2*M3^2)/2)
            [M2*M3, -M1*M3, 0]
        """
        x, J = self._variables, self._J
        dH = [SR(H).diff(v) for v in x]
        return [collect(sum(J[i, j] * dH[j] for j in range(len(x))), x) for i in range(len(x))]

    def context(self, parameters=()):
        r"""
        A :class:`~sage_dynsym.algebra.polynomial_spaces.PolynomialContext` on the
        coordinates, with the parameters of the matrix and ``parameters``.

        EXAMPLES::

            sage: from sage_dynsym.lie.algebras import PoissonStructure
            sage: q, p, a, c = var('q p a c')
            sage: K = PoissonStructure([[0, a], [-a, 0]], [q, p]).context([c])
            sage: K.variables, K.parameters
            ([q, p], [a, c])
            sage: K.element(a*q*p + c*q^2/a, 'H')      # numerator and denominator
            (a^2*q*p + c*q^2, a)
        """
        names = {str(a) for a in self._parameters}
        extra = [a for a in parameters if str(a) not in names]
        return PolynomialContext(self._variables, sorted(self._parameters + extra, key=str))


def _normal(e):
    return normalize(SR(e))


def collect(e, variables):
    r"""
    ``e`` as a sum of monomials in ``variables`` with factored
    coefficients, when it is a polynomial in them; else its normal form.

    EXAMPLES::

        sage: from sage_dynsym.lie.algebras import collect
        sage: x, y, a, b = var('x y a b')
        sage: collect(x*y/a - x*y/b + 2*x, [x, y])
        2*x - (a - b)*x*y/(a*b)
        sage: collect(sin(x) - sin(x), [x]), collect(sin(x)*a/a, [x])
        (0, sin(x))
    """
    e = SR(e)
    names = {str(v) for v in variables}
    parameters = sorted({a for a in e.variables() if str(a) not in names}, key=str)
    try:
        P = PolynomialContext(variables, parameters)
        f, d = P.element(e, "expression")
    except AnalysisError:
        return _normal(e)
    return sum((SR(c / d).factor() * monomial_expression(P.variables, m)
                for m, c in P.split(f).items()), SR(0))


def lie_algebra(name, variables=None):
    r"""
    The Lie--Poisson structure of a named algebra (see the module
    documentation for the brackets).

    INPUT:

    - ``name`` -- ``'so3'``, ``'e3'``, ``'so4'``, ``'so31'``, ``'e4'``
      (also written ``'so(3)'``, ``'so(3,1)'``, ...)
    - ``variables`` -- (optional) the coordinates: a list of as many
      symbols or names, or one prefix per block (``['M', 'p']``); default
      as in the module documentation

    EXAMPLES::

        sage: from sage_dynsym.lie.algebras import lie_algebra
        sage: lie_algebra('so4').matrix()[3:, 3:]
        [  0 -M3  M2]
        [ M3   0 -M1]
        [-M2  M1   0]
        sage: lie_algebra('so31').matrix()[3:, 3:]
        [  0  M3 -M2]
        [-M3   0  M1]
        [ M2 -M1   0]

    TESTS::

        sage: lie_algebra('sl2')
        Traceback (most recent call last):
        ...
        ModelError: algebra: unknown Lie algebra 'sl2'; the named algebras are so3, e3, so4, so31, e4 (or give a Poisson matrix or structure constants)
        sage: lie_algebra('e3', variables=var('a b c'))
        Traceback (most recent call last):
        ...
        ModelError: variables: e3 has 6 coordinates (M1, M2, M3, gamma1, gamma2, gamma3) or 2 prefixes (e.g. ['M', 'gamma']), got 3 variables: ['a', 'b', 'c']
    """
    key = algebra_name(name) if isinstance(name, str) else None
    if key is None:
        raise ModelError(f"unknown Lie algebra {brief(name)}; the named algebras are "
                         f"{', '.join(NAMED)} (or give a Poisson matrix or structure "
                         "constants)", entry="algebra")
    x = _variables(key, variables)
    return PoissonStructure(_named_matrix(key, x), x, name=key)


def structure_constants_matrix(constants, variables):
    r"""
    The Poisson matrix `J_{ij} = -c_{ij}^k x_k` of structure constants.

    INPUT:

    - ``constants`` -- either a nested list ``c[i][j][k]`` (`n \times n
      \times n`), or a dict ``{(i, j): {k: c}}`` giving the nonzero brackets
      `[e_i, e_j] = \sum_k c\, e_k` for some pairs, each pair once (the
      opposite pairs follow by skew-symmetry); indices are 0-based
      positions or the variables themselves (symbols or names)
    - ``variables`` -- the coordinates `x_k` (dual to `e_k`)

    EXAMPLES::

        sage: from sage_dynsym.lie.algebras import structure_constants_matrix
        sage: x, y = var('x y')
        sage: structure_constants_matrix({(x, y): {y: 1}}, [x, y])    # [e_x, e_y] = e_y
        [ 0 -y]
        [ y  0]

    TESTS::

        sage: structure_constants_matrix({(0, 1): {1: 1}, (1, 0): {1: 1}}, [x, y])
        Traceback (most recent call last):
        ...
        ModelError: algebra: the structure constants are not skew-symmetric: [x, y] = y but [y, x] = y; give each pair once (the other order follows by skew-symmetry)
        sage: structure_constants_matrix({(0, 1): {1: 1}, (1, 0): {1: -1}}, [x, y])
        Traceback (most recent call last):
        ...
        ModelError: algebra: the bracket [y, x] is given after [x, y]: give each pair once (the other order follows by skew-symmetry)
        sage: structure_constants_matrix({(0, 1): {1: 1}, (x, y): {1: 1}}, [x, y])
        Traceback (most recent call last):
        ...
        ModelError: algebra: the bracket [x, y] is given twice: give each pair once (the other order follows by skew-symmetry)
        sage: structure_constants_matrix({(0, 0): {1: 1}}, [x, y])
        Traceback (most recent call last):
        ...
        ModelError: algebra: the structure constants are not skew-symmetric: [x, x] = y but [x, x] = y
        sage: structure_constants_matrix({(0, 5): {1: 1}}, [x, y])
        Traceback (most recent call last):
        ...
        ModelError: algebra: index 5 is not a variable: expected 0..1 or one of x, y
    """
    x = _symbols(variables)
    n = len(x)
    names = {str(v): i for i, v in enumerate(x)}

    def index(k):
        if isinstance(k, str) or (not isinstance(k, int) and hasattr(k, 'is_symbol')):
            if str(k) in names:
                return names[str(k)]
        elif isinstance(k, int) and 0 <= k < n:
            return k
        else:
            try:
                k2 = int(k)
                if 0 <= k2 < n and k2 == k:
                    return k2
            except (TypeError, ValueError):
                pass
        raise ModelError(f"index {brief(k)} is not a variable: expected 0..{n - 1} or one of "
                         f"{', '.join(map(str, x))}", entry="algebra")

    brackets = {}
    if isinstance(constants, dict):
        for pair, value in constants.items():
            if not isinstance(pair, (tuple, list)) or len(pair) != 2:
                raise ModelError(f"expected a pair (i, j) as key, got {brief(pair)}",
                                 entry="algebra")
            i, j = index(pair[0]), index(pair[1])
            if not isinstance(value, dict):
                raise ModelError(f"[{x[i]}, {x[j]}]: expected a dict {{k: c}}, got "
                                 f"{brief(value)}", entry="algebra")
            b = sum((SR(c) * x[index(k)] for k, c in value.items()), SR(0))
            once = "give each pair once (the other order follows by skew-symmetry)"
            if (i, j) in brackets:
                raise ModelError(f"the bracket [{x[i]}, {x[j]}] is given twice: {once}",
                                 entry="algebra")
            if (j, i) in brackets:
                if not vanishes(b + brackets[j, i], maxima=False):
                    raise ModelError(f"the structure constants are not skew-symmetric: "
                                     f"[{x[j]}, {x[i]}] = {brackets[j, i]} but [{x[i]}, {x[j]}] "
                                     f"= {b}; {once}", entry="algebra")
                raise ModelError(f"the bracket [{x[i]}, {x[j]}] is given after [{x[j]}, "
                                 f"{x[i]}]: {once}", entry="algebra")
            brackets[i, j] = b
    else:
        try:
            c = [[list(row) for row in layer] for layer in constants]
        except TypeError as err:
            raise ModelError(f"expected structure constants c[i][j][k] or a dict, got "
                             f"{brief(constants)}", entry="algebra") from err
        if len(c) != n or any(len(r) != n or any(len(v) != n for v in r) for r in c):
            raise ModelError(f"expected {n}x{n}x{n} structure constants c[i][j][k], one "
                             "index per variable", entry="algebra")
        for i in range(n):
            for j in range(n):
                brackets[i, j] = sum(SR(c[i][j][k]) * x[k] for k in range(n))
    for (i, j), b in list(brackets.items()):
        if (j, i) in brackets:
            if not vanishes(b + brackets[j, i], maxima=False):
                raise ModelError(f"the structure constants are not skew-symmetric: "
                                 f"[{x[i]}, {x[j]}] = {b} but [{x[j]}, {x[i]}] = "
                                 f"{brackets[j, i]}", entry="algebra")
        else:
            brackets[j, i] = -b
    J = matrix(SR, n, n)
    for (i, j), b in brackets.items():
        J[i, j] = -b
    return J


def poisson_structure(algebra, variables=None):
    r"""
    A :class:`PoissonStructure` from a name, a Poisson matrix, structure
    constants, or a :class:`PoissonStructure` (returned as is, with its
    variables renamed if ``variables`` is given).

    INPUT:

    - ``algebra`` -- a name (:func:`lie_algebra`), a square matrix or list
      of rows (`\{x_i, x_j\}`), structure constants
      (:func:`structure_constants_matrix`: a dict or an `n\times n\times n`
      nested list)
    - ``variables`` -- the coordinates (required for a matrix or structure
      constants, unless a matrix's size fixes default names `x_1, \dots,
      x_n`)

    EXAMPLES::

        sage: from sage_dynsym.lie.algebras import poisson_structure
        sage: poisson_structure('so3', variables=['L'])
        Lie-Poisson structure so3 on (L1, L2, L3)
        sage: poisson_structure([[0, 1], [-1, 0]])
        Poisson structure on (x1, x2)

    TESTS::

        sage: poisson_structure(42)
        Traceback (most recent call last):
        ...
        ModelError: algebra: expected a name (so3, e3, so4, so31, e4), a Poisson matrix or structure constants, got 42
    """
    if isinstance(algebra, PoissonStructure):
        if variables is None:
            return algebra
        x = _symbols(variables)
        if len(x) != algebra.dimension():
            raise ModelError(f"the structure has {algebra.dimension()} coordinates, got "
                             f"{len(x)} variables", entry="variables")
        sub = dict(zip(algebra.variables(), x))
        return PoissonStructure(algebra.matrix().subs(sub), x, name=algebra.name(),
                                check=False)
    if isinstance(algebra, str):
        return lie_algebra(algebra, variables)
    if isinstance(algebra, dict) or _depth(algebra) == 3:
        if variables is None:
            n = len(algebra) if not isinstance(algebra, dict) else None
            if n is None:
                raise ModelError("structure constants given as a dict need variables=",
                                 entry="variables")
            variables = [f"x{k}" for k in range(1, n + 1)]
        return PoissonStructure(structure_constants_matrix(algebra, variables), variables)
    if _depth(algebra) == 2:
        if variables is None:
            variables = [f"x{k}" for k in range(1, len(list(algebra)) + 1)]
        return PoissonStructure(algebra, variables)
    raise ModelError(f"expected a name ({', '.join(NAMED)}), a Poisson matrix or structure "
                     f"constants, got {brief(algebra)}", entry="algebra")


def _depth(obj):
    # 2 for a matrix or list of rows, 3 for nested structure constants
    if hasattr(obj, 'nrows') and hasattr(obj, 'ncols'):
        return 2
    if isinstance(obj, (list, tuple)):
        if not obj:
            return 1
        return 1 + max(_depth(v) for v in obj)
    return 0
