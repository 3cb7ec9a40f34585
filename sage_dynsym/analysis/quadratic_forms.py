r"""
Sign-definiteness of quadratic forms

Sylvester's criterion (leading principal minors), restriction of a form to
a linear subspace (the tangent space of the level set of first integrals,
as needed for the second variation `\delta^2 K` in the Routh--Lyapunov
method), and the simultaneous reduction of two forms to sums of squares.

EXAMPLES::

    sage: from sage_dynsym.analysis.quadratic_forms import sylvester_conditions
    sage: x, y, a, b = var('x y a b')
    sage: sylvester_conditions(a*x^2 + 2*x*y + b*y^2, [x, y])
    [a, a*b - 1]
    sage: sylvester_conditions(a*x^2 + 2*x*y + b*y^2, [x, y], sign='negative')
    [-a, a*b - 1]

REFERENCES:

- F. R. Gantmacher, *The Theory of Matrices*, vol. 1, ch. X (Sylvester's
  criterion, pencils of quadratic forms).
- D. R. Merkin, *Introduction to the Theory of Stability*, ch. 3.
"""
from sage.matrix.constructor import matrix
from sage.misc.misc_c import prod
from sage.rings.rational_field import QQ
from sage.symbolic.ring import SR

from ..arguments import expression_argument, expression_list, matrix_argument
from ..errors import AnalysisError
from ..algebra.polynomials import positive_polynomial, odd_factors
from ..algebra.conditions import positive_conditions_all, nonzero_conditions, conjunction
from ..algebra.solving import normalize
from ..algebra.translation import Translation

__all__ = ['form_matrix', 'definiteness_conditions', 'signed_leading_minors',
           'sylvester_conditions', 'semidefiniteness_conditions', 'restrict_to_subspace',
           'simultaneous_reduction']


def form_matrix(form, variables):
    r"""
    The symmetric matrix `A` of a quadratic form `x^T A x`.

    EXAMPLES::

        sage: from sage_dynsym.analysis.quadratic_forms import form_matrix
        sage: x, y = var('x y')
        sage: form_matrix(x^2 + 3*x*y, [x, y])
        [  1 3/2]
        [3/2   0]
        sage: form_matrix(x^2 + y, [x, y])
        Traceback (most recent call last):
        ...
        AnalysisError: quadratic form: x^2 + y is not a quadratic form in (x, y)
    """
    variables = [SR(v) for v in variables]
    form = SR(form)
    A = matrix(SR, [[form.diff(u).diff(v) / 2 for v in variables] for u in variables])
    back = (matrix(SR, [variables]) * A * matrix(SR, [variables]).transpose())[0, 0]
    if any(e.has(v) for e in A.list() for v in variables) or \
            not bool((back - form).expand() == 0):
        raise AnalysisError(f"{form} is not a quadratic form in "
                            f"({', '.join(map(str, variables))})", entry="quadratic form")
    return A


def _symmetric(form_or_matrix, variables):
    if hasattr(form_or_matrix, 'nrows') or isinstance(form_or_matrix, (list, tuple)):
        A = matrix_argument(form_or_matrix, "quadratic form", AnalysisError,
                            square=True).change_ring(SR)
        if not all(bool((A[i, j] - A[j, i]).expand() == 0)
                   for i in range(A.nrows()) for j in range(i)):
            raise AnalysisError("the matrix of a quadratic form must be symmetric; "
                                f"got\n{A}\n(use (A + A^T)/2 for the form x^T A x)",
                                entry="quadratic form")
        return A
    if variables is None:
        raise AnalysisError("a quadratic form given as an expression needs its "
                            "variables", entry="quadratic form")
    return form_matrix(expression_argument(form_or_matrix, "quadratic form", AnalysisError,
                                           expected="a quadratic form or its matrix"),
                       variables)


def definiteness_conditions(quadratic_form_or_matrix, variables=None, sign='positive',
                            positive=()):
    r"""
    Conditions for a quadratic form to be positive (or negative) definite,
    as relationals: Sylvester's criterion with the signs of denominators
    taken into account.

    Each leading principal minor `\Delta_k` is computed exactly as a
    rational function `N_k/D_k`; the condition `\Delta_k > 0` is `N_k D_k >
    0` (the same sign), so no denominator is assumed positive unless its
    factors are declared positive.

    INPUT: as :func:`sylvester_conditions`

    OUTPUT: a list of relationals that must all hold; ``[]`` if the form is
    definite for all admissible values; ``None`` if it never is

    EXAMPLES::

        sage: from sage_dynsym.analysis.quadratic_forms import definiteness_conditions
        sage: x, y, a, b, g = var('x y a b g')
        sage: definiteness_conditions(x^2/g, [x])
        [g > 0]
        sage: definiteness_conditions(matrix([[1, b], [b, -(a + b^2)/g]]))
        [(b^2*g + b^2 + a)*g < 0]
        sage: definiteness_conditions(matrix([[1, 0], [0, -1]])) is None
        True
    """
    if sign not in ('positive', 'negative'):
        raise AnalysisError(f"sign must be 'positive' or 'negative', got {sign!r}",
                            entry="sylvester_conditions")
    A = _symmetric(quadratic_form_or_matrix, variables)
    return positive_conditions_all(signed_leading_minors(A, sign), positive)


def signed_leading_minors(A, sign='positive'):
    r"""
    Expressions with the signs of the leading principal minors
    `\Delta_1, \dots, \Delta_n` of ``A`` (times `(-1)^k` for
    ``sign='negative'``): all positive iff ``A`` is definite of that sign
    (Sylvester). Each is the numerator times the denominator of the exact
    minor, so no denominator is assumed positive.

    INPUT:

    - ``A`` -- a square symbolic matrix
    - ``sign`` -- ``'positive'`` (default) or ``'negative'``

    OUTPUT: a list of symbolic expressions

    EXAMPLES::

        sage: from sage_dynsym.analysis.quadratic_forms import signed_leading_minors
        sage: a, b, g = var('a b g')
        sage: signed_leading_minors(matrix([[a, b], [b, 1/g]]))
        [a, -b^2*g^2 + a*g]
        sage: signed_leading_minors(matrix([[a, 0], [0, 1]]), sign='negative')
        [-a, a]
        sage: signed_leading_minors(matrix(SR, 0, 0))
        []
    """
    n = A.nrows()
    if not n:
        return []
    T = Translation([], [], extra=A.list())
    F = T.fraction(SR(1)).parent()
    AF = matrix(F, [[T.fraction(e) for e in row] for row in A.rows()])
    result = []
    for k in range(1, n + 1):
        d = AF[:k, :k].det()
        if sign == 'negative' and k % 2:
            d = -d
        result.append(T.symbolic(F(d.numerator() * d.denominator())))
    return result


def sylvester_conditions(quadratic_form_or_matrix, variables=None, sign='positive',
                         positive=()):
    r"""
    Conditions for a quadratic form to be positive (or negative) definite.

    Sylvester's criterion: a symmetric matrix is positive definite iff its
    leading principal minors `\Delta_1, \dots, \Delta_n` are positive;
    negative definite iff `(-1)^k \Delta_k > 0`. The sign of a denominator
    is never assumed: a minor `N/D` gives the condition `N D > 0` (see
    :func:`definiteness_conditions`, which returns relationals).

    INPUT:

    - ``quadratic_form_or_matrix`` -- a symmetric matrix, or a quadratic
      form (expression) in ``variables``
    - ``variables`` -- the variables of the form (needed for an expression)
    - ``sign`` -- ``'positive'`` (default) or ``'negative'``
    - ``positive`` -- parameters declared positive (used to simplify)

    OUTPUT: a list of expressions which must all be ``> 0``, factored and
    free of conditions implied by the others; ``[]`` if the form is
    definite for all admissible values, ``[-1]`` if it never is

    EXAMPLES:

    The potential energy of a double pendulum near the lower position is
    positive definite, near the upper one negative definite (Merkin,
    ch. 3)::

        sage: from sage_dynsym.analysis.quadratic_forms import sylvester_conditions
        sage: m1, m2, l1, l2, g = var('m1 m2 l1 l2 g')
        sage: K = matrix([[(m1 + m2)*g*l1, 0], [0, m2*g*l2]])
        sage: sylvester_conditions(K, positive=[m1, m2, l1, l2, g])
        []
        sage: sylvester_conditions(-K, sign='negative', positive=[m1, m2, l1, l2, g])
        []

    A denominator of unknown sign is a condition, not an assumption::

        sage: x = var('x')
        sage: sylvester_conditions(x^2/g, [x]), sylvester_conditions(x^2/g, [x], positive=[g])
        ([g], [])
        sage: a, b = var("a b"); sylvester_conditions(matrix([[1, 0], [0, a/b^2]]))
        [a, b^2]

    TESTS::

        sage: sylvester_conditions(matrix([[1, 2], [0, 1]]))
        Traceback (most recent call last):
        ...
        AnalysisError: quadratic form: the matrix of a quadratic form must be symmetric; got
        [1 2]
        [0 1]
        (use (A + A^T)/2 for the form x^T A x)
        sage: sylvester_conditions(matrix([[1, 2], [2, 1]]))
        [-1]
    """
    conditions = definiteness_conditions(quadratic_form_or_matrix, variables, sign, positive)
    if conditions is None:
        return [SR(-1)]
    # as expressions e > 0: f < 0 is -f > 0, f != 0 is f^2 > 0
    as_positive = {'gt': lambda d: d, 'lt': lambda d: -d, 'ne': lambda d: d ** 2}
    return [as_positive[c.operator().__name__](c.lhs() - c.rhs()) for c in conditions]


def semidefiniteness_conditions(A, positive=()):
    r"""
    Conditions for a symmetric matrix to be positive semidefinite: every
    principal minor (not only the leading ones) is nonnegative.

    INPUT:

    - ``A`` -- a symmetric matrix
    - ``positive`` -- parameters declared positive

    OUTPUT: a list of relations ``f >= 0`` (factored; minors that are
    nonnegative by the declarations, or products of factors already
    required, are left out), ``[]`` if it always holds, ``None`` if never

    EXAMPLES: a damping matrix acting on one coordinate only::

        sage: from sage_dynsym.analysis.quadratic_forms import semidefiniteness_conditions
        sage: c, d = var('c d')
        sage: semidefiniteness_conditions(matrix([[c, 0], [0, 0]]))
        [c >= 0]
        sage: semidefiniteness_conditions(matrix([[c + d, -d], [-d, d]]), positive=[c])
        [d >= 0]
        sage: semidefiniteness_conditions(matrix([[1, 0], [0, -1]])) is None
        True
    """
    from itertools import combinations
    A = _symmetric(A, None)
    n = A.nrows()
    T = Translation([], [], extra=A.list())
    F = T.fraction(SR(1)).parent()
    AF = matrix(F, [[T.fraction(e) for e in row] for row in A.rows()])
    names = T.positive_names(positive)
    flat = T.flat_ring()
    entries = []            # (sign, odd factors) of each minor that can be negative
    for size in range(1, n + 1):
        for idx in combinations(range(n), size):
            d = AF.matrix_from_rows_and_columns(list(idx), list(idx)).det()
            if d == 0:
                continue
            p = d.numerator() * d.denominator()
            if flat is None or p.is_constant():
                if QQ(p if flat is None else p.constant_coefficient()) < 0:
                    return None
                continue
            sign, odd = odd_factors(flat(p).factor(), names)
            if not odd:
                if sign < 0:
                    return None
                continue
            if (sign, odd) not in entries:
                entries.append((sign, odd))
    # variables required >= 0 count as positive in the other minors
    single = {str(odd[0]) for sign, odd in entries if sign > 0 and len(odd) == 1
              and odd[0].is_gen()}
    result = []
    for sign, odd in entries:
        if not (sign > 0 and len(odd) == 1 and odd[0].is_gen()) and sign > 0 and \
                all(str(f) in single or positive_polynomial(f, names | single) for f in odd):
            continue
        result.append(T.symbolic(sign * prod(odd)) >= 0)
    return result


def restrict_to_subspace(quadratic_form_or_matrix, constraints, variables,
                         with_conditions=False):
    r"""
    The restriction of a quadratic form to the linear subspace
    `\{\xi : C\xi = 0\}`.

    Used for the second variation `\delta^2 K` on the tangent space of the
    level set of first integrals: ``constraints`` are the linear forms
    `dV_j|_{x^0}\cdot\xi`.

    INPUT:

    - ``quadratic_form_or_matrix`` -- as in :func:`sylvester_conditions`
    - ``constraints`` -- list of linear forms in ``variables`` (or a matrix
      `C`, one row per constraint)
    - ``variables`` -- the variables `\xi`
    - ``with_conditions`` -- (default: ``False``) also return the
      conditions (relationals ``p != 0``) under which the elimination is
      valid: the pivots divided by

    OUTPUT: a pair ``(form, free)``: the restricted quadratic form as an
    expression in the free variables ``free`` (the constraints are solved
    for the other variables); with ``with_conditions``, a triple
    ``(form, free, conditions)``

    EXAMPLES: `x^2 - y^2 + z^2` is positive on the plane `y = 0`::

        sage: from sage_dynsym.analysis.quadratic_forms import restrict_to_subspace
        sage: x, y, z, a = var('x y z a')
        sage: restrict_to_subspace(x^2 - y^2 + z^2, [y], [x, y, z])
        (x^2 + z^2, [x, z])
        sage: restrict_to_subspace(x^2 + y^2, [x + y], [x, y])
        (2*y^2, [y])
        sage: restrict_to_subspace(x^2 + y^2, [a*x + y], [x, y], with_conditions=True)
        ((a^2 + 1)*x^2, [x], [])
        sage: restrict_to_subspace(x^2 + y^2, [a*x], [x, y], with_conditions=True)
        (y^2, [y], [a != 0])
    """
    variables = expression_list(variables, "variables", AnalysisError, names=True)
    A = _symmetric(quadratic_form_or_matrix, variables)
    if hasattr(constraints, 'nrows'):
        rows = [list(r) for r in matrix(SR, constraints).rows()]
    else:
        rows = [[c.diff(v) for v in variables] for c in expression_list(
            constraints, "constraints", AnalysisError,
            expected="a list of linear forms (or their matrix)")]
    sol, conditions = {}, []
    rows = [[normalize(e) for e in r] for r in rows]
    for r in range(len(rows)):
        row = rows[r]
        candidates = [j for j, e in enumerate(row) if not e.is_zero()
                      and variables[j] not in sol]
        if not candidates:
            continue
        # a numerical pivot needs no condition; else the shortest
        j = min(candidates, key=lambda j: (not row[j].is_numeric(), len(str(row[j]))))
        pivot = row[j]
        if not pivot.is_numeric():
            conditions = conjunction(conditions, nonzero_conditions(pivot)) or []
        value = -sum(row[k] * variables[k] for k in range(len(variables)) if k != j) / pivot
        sol = {v: e.subs({variables[j]: value}) for v, e in sol.items()}
        sol[variables[j]] = value
        for later in rows[r + 1:]:
            c = later[j]
            if not c.is_zero():
                for k in range(len(variables)):
                    later[k] = normalize(later[k] - c * row[k] / pivot)
    free = [v for v in variables if v not in sol]
    x = matrix(SR, [variables]).transpose()
    form = (x.transpose() * A * x)[0, 0].subs(sol)
    form = _collect_quadratic(form, free)
    return (form, free, conditions) if with_conditions else (form, free)


def _collect_quadratic(form, variables):
    r"""A quadratic form with normalized, factored coefficients."""
    form = SR(form).expand()
    terms = []
    for i, u in enumerate(variables):
        for v in variables[i:]:
            c = form.diff(u).diff(v) / (2 if u is v or str(u) == str(v) else 1)
            c = normalize(c.subs({w: 0 for w in variables}))
            if not c.is_zero():
                terms.append(_factored(c) * u * v)
    return sum(terms, SR(0))


def _factored(expr):
    try:
        return expr.factor()
    except (TypeError, ValueError, ArithmeticError):
        return expr


def simultaneous_reduction(A, B, positive=()):
    r"""
    Reduce two quadratic forms simultaneously to sums of squares.

    For symmetric `A` and positive definite `B` there is `T` with
    `T^T B T = I`, `T^T A T = \mathrm{diag}(\mu_1, \dots, \mu_n)`, where
    `\mu_i` are the roots of `\det(A - \mu B) = 0`. `A` is positive
    definite iff all `\mu_i > 0` -- e.g. `A` the potential, `B` the kinetic
    energy: `\mu_i` are the squared eigenfrequencies.

    INPUT:

    - ``A``, ``B`` -- symmetric matrices, ``B`` positive definite
    - ``positive`` -- (optional) symbols declared positive (assumptions for
      the roots and square roots; a sign still needed is an
      :class:`~sage_dynsym.errors.AnalysisError` naming it)

    OUTPUT: a pair ``(mu, T)``: the list of the `\mu_i` and the matrix `T`
    (when the roots are found explicitly)

    EXAMPLES::

        sage: from sage_dynsym.analysis.quadratic_forms import simultaneous_reduction
        sage: A = matrix(QQ, [[2, 1], [1, 2]]); B = identity_matrix(QQ, 2)
        sage: mu, T = simultaneous_reduction(A, B)
        sage: mu
        [1, 3]
        sage: T.transpose()*B*T == 1, T.transpose()*A*T == diagonal_matrix(mu)
        (True, True)
    """
    from ..algebra.polynomials import maxima_without_questions
    with maxima_without_questions("simultaneous_reduction", positive):
        return _simultaneous_reduction(_symmetric(A, None), _symmetric(B, None))


def _simultaneous_reduction(A, B):
    n = A.nrows()
    mu_ = SR.var('mu_')
    roots = (A - mu_ * B).det().roots(mu_, multiplicities=True)
    mus = sorted([r for r, m in roots for _ in range(m)], key=lambda r: (str(r)))
    try:
        mus = sorted(mus)
    except (TypeError, ValueError):
        pass
    cols = []
    for r in sorted(set(mus), key=lambda r: mus.index(r)):
        V = (A - r * B).right_kernel().basis()
        V = [matrix(SR, v).transpose() for v in V]
        # Gram-Schmidt with respect to B inside the eigenspace
        ortho = []
        for v in V:
            for w in ortho:
                v = v - (w.transpose() * B * v)[0, 0] * w
            v = v / (v.transpose() * B * v)[0, 0].sqrt()
            ortho.append(v.apply_map(lambda e: e.simplify_full()))
        cols += ortho
    if len(cols) != n:
        raise AnalysisError("could not reduce the forms (B must be positive "
                            "definite)", entry="simultaneous_reduction")
    T = cols[0]
    for c in cols[1:]:
        T = T.augment(c)
    return mus, T
