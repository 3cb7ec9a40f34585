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
from sage.symbolic.ring import SR

from ..errors import AnalysisError
from .hurwitz import simplify_conditions


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
        A = matrix(SR, form_or_matrix)
        if not A.is_square():
            raise AnalysisError(f"expected a square matrix, got {A.nrows()}x{A.ncols()}",
                                entry="quadratic form")
        if not all(bool((A[i, j] - A[j, i]).expand() == 0)
                   for i in range(A.nrows()) for j in range(i)):
            raise AnalysisError("the matrix of a quadratic form must be symmetric; "
                                f"got\n{A}\n(use (A + A^T)/2 for the form x^T A x)",
                                entry="quadratic form")
        return A
    if variables is None:
        raise AnalysisError("a quadratic form given as an expression needs its "
                            "variables", entry="quadratic form")
    return form_matrix(form_or_matrix, variables)


def sylvester_conditions(quadratic_form_or_matrix, variables=None, sign='positive',
                         positive=()):
    r"""
    Conditions for a quadratic form to be positive (or negative) definite.

    Sylvester's criterion: a symmetric matrix is positive definite iff its
    leading principal minors `\Delta_1, \dots, \Delta_n` are positive;
    negative definite iff `(-1)^k \Delta_k > 0`.

    INPUT:

    - ``quadratic_form_or_matrix`` -- a symmetric matrix, or a quadratic
      form (expression) in ``variables``
    - ``variables`` -- the variables of the form (needed for an expression)
    - ``sign`` -- ``'positive'`` (default) or ``'negative'``
    - ``positive`` -- parameters known to be positive (used to simplify)

    OUTPUT: a list of expressions which must all be ``> 0``, simplified
    as in :func:`~sage_dynsym.analysis.hurwitz.simplify_conditions`

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
    if sign not in ('positive', 'negative'):
        raise AnalysisError(f"sign must be 'positive' or 'negative', got {sign!r}",
                            entry="sylvester_conditions")
    A = _symmetric(quadratic_form_or_matrix, variables)
    n = A.nrows()
    minors = [_det(A[:k, :k]) for k in range(1, n + 1)]
    if sign == 'negative':
        minors = [(-1) ** k * m for k, m in enumerate(minors, 1)]
    return simplify_conditions([m.expand() for m in minors], positive)


def _det(A):
    from .linear import _fraction_free_det
    return _fraction_free_det(A) if A.nrows() else SR(1)


def restrict_to_subspace(quadratic_form_or_matrix, constraints, variables):
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

    OUTPUT: a pair ``(form, free)``: the restricted quadratic form as an
    expression in the free variables ``free`` (the constraints are solved
    for the other variables)

    EXAMPLES: `x^2 - y^2 + z^2` is positive on the plane `y = 0`::

        sage: from sage_dynsym.analysis.quadratic_forms import restrict_to_subspace
        sage: x, y, z = var('x y z')
        sage: restrict_to_subspace(x^2 - y^2 + z^2, [y], [x, y, z])
        (x^2 + z^2, [x, z])
        sage: restrict_to_subspace(x^2 + y^2, [x + y], [x, y])
        (2*y^2, [y])
    """
    variables = [SR(v) for v in variables]
    A = _symmetric(quadratic_form_or_matrix, variables)
    if hasattr(constraints, 'nrows'):
        C = matrix(SR, constraints)
    else:
        C = matrix(SR, [[SR(c).diff(v) for v in variables] for c in constraints])
    sol = {}
    if C.nrows():
        E = C.echelon_form()
        pivots = E.pivots()
        for r, pc in enumerate(pivots):
            sol[variables[pc]] = -sum(E[r, j] * variables[j] for j in range(len(variables))
                                      if j != pc) / E[r, pc]
    free = [v for v in variables if v not in sol]
    x = matrix(SR, [variables]).transpose()
    form = (x.transpose() * A * x)[0, 0].subs(sol)
    return form.simplify_rational().expand(), free


def simultaneous_reduction(A, B):
    r"""
    Reduce two quadratic forms simultaneously to sums of squares.

    For symmetric `A` and positive definite `B` there is `T` with
    `T^T B T = I`, `T^T A T = \mathrm{diag}(\mu_1, \dots, \mu_n)`, where
    `\mu_i` are the roots of `\det(A - \mu B) = 0`. `A` is positive
    definite iff all `\mu_i > 0` -- e.g. `A` the potential, `B` the kinetic
    energy: `\mu_i` are the squared eigenfrequencies.

    INPUT:

    - ``A``, ``B`` -- symmetric matrices, ``B`` positive definite

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
    A = _symmetric(A, None)
    B = _symmetric(B, None)
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
