r"""
Nonlinear stability of equilibria of conservative systems: the Birkhoff
normal form of a model, and the verdicts beyond the first approximation

:func:`birkhoff_normal_form` expands the Hamiltonian of a
:class:`~sage_dynsym.dynamics.lagrangian.Lagrangian`,
:class:`~sage_dynsym.dynamics.lagrangian.RouthFunction` (a steady motion
as an equilibrium of the reduced system) or
:class:`~sage_dynsym.dynamics.hamiltonian.Hamiltonian` at an equilibrium
and normalizes it (:mod:`~sage_dynsym.analysis.normal_forms`).
:func:`nonlinear_stability` decides Lyapunov stability where the theory
does:

- ``'unstable'``: a root of the linearization off the imaginary axis
  (Lyapunov's theorem on the first approximation); in two degrees of
  freedom a resonance `\omega_1 = 2\omega_2` with a nonzero resonant term
  of degree 3, or `\omega_1 = 3\omega_2` when the resonant term of degree
  4 dominates (Markeev's theorems);
- ``'stable'``: a definite quadratic part of the energy (Lagrange--Dirichlet:
  the energy is a Lyapunov function, whatever the resonances); in two
  degrees of freedom Arnold--Moser: no resonance up to order 4 and
  Arnold's determinant `D \ne 0` (or, with ``order=6``, `D = 0` and the
  determinant of degree 6 nonzero, no resonance up to order 6); the
  resonance 1:3 when the terms in the actions dominate (Markeev);
- ``'stable in first approximation'`` in more degrees of freedom: the
  normal form is then a formal statement only (formal stability);
- ``'undecided'``: what the order computed does not decide, said so.

EXAMPLES: the pendulum at its lower position (a minimum of the energy)::

    sage: from sage_dynsym import Lagrangian
    sage: from sage_dynsym.dynamics.nonlinear_stability import birkhoff_normal_form, nonlinear_stability
    sage: q, dq = var('q dq')
    sage: L = Lagrangian(dq^2/2 + cos(q), [q])
    sage: nf = birkhoff_normal_form(L, {q: 0}, order=6, exact=True)
    sage: {m: QQ(c) for m, c in nf.coefficients(exact=True).items()}
    {(1,): 1, (2,): -1/16, (3,): -1/256}
    sage: nonlinear_stability(L, {q: 0})
    stable: the energy has a strict minimum at the equilibrium (Lagrange-Dirichlet): ...

REFERENCES:

- A. P. Markeev, Libration points in celestial mechanics
  and space dynamics, Nauka, Moscow 1978.
- V. I. Arnold, V. V. Kozlov, A. I.
  Neishtadt, Mathematical aspects of classical and celestial mechanics,
  3rd ed., Springer 2006, sections 7.3 and 8.3.
- K. R. Meyer, G. R. Hall, D. Offin (see :mod:`~sage_dynsym.analysis.normal_forms`).
"""
from sage.rings.polynomial.polynomial_ring_constructor import PolynomialRing
from sage.rings.qqbar import QQbar
from sage.rings.rational_field import QQ
from sage.symbolic.ring import SR
from sage.symbolic.operators import add_vararg, mul_vararg
import math
import operator

from ..errors import AnalysisError, brief
from ..analysis.normal_forms import normal_form, FormalArithmetic, BirkhoffNormalForm
from ..analysis.parametric_normal_forms import FieldArithmetic, arnold_polynomial
from ..analysis.normal_form_stability import normal_form_stability, stability_over_parameter
from .hamiltonian import Hamiltonian

__all__ = ['birkhoff_normal_form', 'nonlinear_stability', 'BirkhoffNormalForm',
           'polynomial_hamiltonian', 'exceptional_values', 'taylor_polynomial']


def _hamiltonian(model):
    from .lagrangian import Lagrangian
    if isinstance(model, Hamiltonian):
        H = model
    elif isinstance(model, Lagrangian):
        H = model.hamiltonian()
    else:
        raise AnalysisError(f"expected a Lagrangian, RouthFunction or Hamiltonian, got "
                            f"{type(model).__name__}", entry="model")
    if H.is_singular() or H.conserved_energy() is None:
        raise AnalysisError("the Hamiltonian must be conserved and regular (no explicit "
                            "time, no dissipation or forces, a regular Lagrangian)",
                            entry="model")
    return H


def _point(H, at):
    r"""The equilibrium `(q_0, p_0)` and the parameter values of ``at``."""
    coordinates, momenta = H.coordinates(), H.momenta()
    names = {str(v): v for v in coordinates + momenta}
    if at is not None and not isinstance(at, dict):
        raise AnalysisError(f"expected a dict {{coordinate: value}}, got {brief(at)}; e.g. "
                            f"at={{{coordinates[0]}: 0, ...}}", entry="at")
    point, values = {}, {}
    for key, value in (at or {}).items():
        key = SR(key) if not isinstance(key, str) else SR.var(key)
        (point if str(key) in names else values)[names.get(str(key), key)] = SR(value)
    point = {v: value.subs(values) for v, value in point.items()}
    missing = [q for q in coordinates if q not in point]
    if missing:
        raise AnalysisError(f"give the value of every coordinate, missing {missing}; "
                            f"e.g. at={{{coordinates[0]}: 0, ...}}", entry="at")
    velocities = H.lagrangian().velocities()
    momentum_values = [p.subs({v: 0 for v in velocities}).subs(point).subs(values)
                       for p in H.lagrangian().generalized_momenta()]
    for p, p0 in zip(momenta, momentum_values):
        point.setdefault(p, p0)
    expr = H.expr().subs(values)
    gradient = [expr.diff(v).subs(point).simplify_full() for v in coordinates + momenta]
    # with floating-point data the gradient is zero to rounding only
    if any(not g.is_zero() and (g.variables() or _is_exact(g) or abs(g.n()) > 1e-9)
           for g in gradient):
        raise AnalysisError(f"{point} is not an equilibrium: the gradient of the "
                            f"Hamiltonian there is {gradient}", entry="at")
    return point, values, expr


def taylor_polynomial(model, at, order):
    r"""The Taylor polynomial of degree ``order`` of the Hamiltonian of
    ``model`` at the equilibrium ``at`` (see :func:`polynomial_hamiltonian`)
    in the displacements ``q1..qn, p1..pn``, with symbolic coefficients.

    EXAMPLES::

        sage: from sage_dynsym import Lagrangian
        sage: from sage_dynsym.dynamics.nonlinear_stability import taylor_polynomial
        sage: q, dq = var('q dq')
        sage: taylor_polynomial(Lagrangian(dq^2/2 + cos(q), [q]), {q: pi}, 3)
        (-1/2)*q1^2 + 1/2*p1^2 + 1
    """
    H = _hamiltonian(model)
    point, values, expr = _point(H, at)
    variables = H.coordinates() + H.momenta()
    n = len(H.coordinates())
    shifts = [SR.var(f"q{k + 1}") for k in range(n)] + [SR.var(f"p{k + 1}") for k in range(n)]
    shifted = expr.subs({v: point[v] + s for v, s in zip(variables, shifts)})
    series = shifted.taylor(*[(s, 0) for s in shifts], order)
    return series.polynomial(ring=PolynomialRing(SR, [str(s) for s in shifts]))


def _is_exact(value):
    try:
        from sage.rings.qqbar import QQbar as exact_numbers
        return not any(isinstance(a.pyobject(), float) or not a.pyobject() in exact_numbers
                       for a in _numbers(value))
    except (TypeError, ValueError, AttributeError):
        return False


def _numbers(expr):
    if expr.operator() is None:
        return [expr] if not expr.is_symbol() else []
    return [a for op in expr.operands() for a in _numbers(op)]


def polynomial_hamiltonian(model, at, order):
    r"""
    The Taylor polynomial of degree ``order`` of the Hamiltonian of
    ``model`` at the equilibrium ``at``, as neutral data for
    :mod:`~sage_dynsym.analysis.normal_forms`: a pair ``(H, values,
    relations)`` -- ``H`` a polynomial in ``q1..qn, p1..pn`` (the
    displacements from the point) over a polynomial ring over `\mathbb Q`
    in the parameters and the irrational constants (``c1, ...``), with
    their values and the relations of the constants.

    INPUT:

    - ``model`` -- a Lagrangian, Routh function or Hamiltonian
    - ``at`` -- dict coordinate -> value (momenta default to their value
      at rest, `\partial L/\partial\dot q` at `\dot q = 0`; parameters may
      be given values too)
    - ``order`` -- the degree of the expansion

    EXAMPLES::

        sage: from sage_dynsym import Lagrangian
        sage: from sage_dynsym.dynamics.nonlinear_stability import polynomial_hamiltonian
        sage: q, dq, k = var('q dq k')
        sage: H, values, relations = polynomial_hamiltonian(Lagrangian(dq^2/2 + k*cos(q), [q]), {q: 0}, 4)
        sage: H, values
        ((-1/24*k)*q1^4 + 1/2*k*q1^2 + 1/2*p1^2 - k, {'k': None})
    """
    poly = taylor_polynomial(model, at, order)
    constants, parameters = {}, set()
    for c in poly.coefficients():
        _collect(c, constants, parameters)
    names = sorted(map(str, parameters))
    symbols = {c: SR.var(f"c{k + 1}") for k, c in enumerate(constants.values())}
    base = PolynomialRing(QQ, names + [str(s) for s in symbols.values()])
    ring = PolynomialRing(base, poly.parent().variable_names())
    terms = {}
    for e, c in poly.dict().items():
        c = c.subs(symbols) if symbols else c
        terms[e] = _to_base(c, base)
    values_out = {name: None for name in names}
    relations = []
    for c, s in symbols.items():
        values_out[str(s)] = c
        try:
            relations.append(QQbar(c).minpoly()(base(str(s))))
        except (TypeError, ValueError):
            pass
    return ring(terms), values_out, relations


def _collect(expr, constants, parameters):
    r"""The irrational constants (powers with fractional exponents,
    functions) and the parameters of a coefficient."""
    op = expr.operator()
    if op is None:
        if expr.is_symbol():
            parameters.add(expr)
        return
    if op in (add_vararg, mul_vararg, operator.add, operator.mul) or (
            op is operator.pow and expr.operands()[1] in QQ and
            QQ(expr.operands()[1]).denominator() == 1):
        for operand in expr.operands():
            _collect(operand, constants, parameters)
        return
    if expr.variables():
        raise AnalysisError(f"the Taylor coefficient has the term {expr}, not polynomial in "
                            "the parameters: give them values in at=", entry="at")
    constants.setdefault(str(expr), expr)


def _to_base(c, base):
    numerator, denominator = c.numerator(), c.denominator()
    if denominator.variables():
        raise AnalysisError(f"the Taylor coefficient {c} has a denominator in the "
                            "parameters: give them values in at=", entry="at")
    return base(numerator.polynomial(QQ)) / QQ(denominator) if numerator.variables() \
        else base(QQ(numerator) / QQ(denominator))


def birkhoff_normal_form(model, at, order=4, sample=None, prec=None, exact=False):
    r"""
    The Birkhoff normal form of the Hamiltonian of ``model`` at the
    equilibrium ``at`` (see :mod:`~sage_dynsym.analysis.normal_forms`).

    INPUT:

    - ``model`` -- a Lagrangian, Routh function or Hamiltonian (conserved)
    - ``at`` -- dict coordinate -> value at the equilibrium (and,
      optionally, parameter -> value)
    - ``order`` -- (default: 4) the degree of the normal form
    - ``sample`` -- (optional) values of the parameters left free, for the
      choices that depend on the point (the order of the frequencies and
      the signs of the modes); the coefficients are then expressions in the
      parameters and the symbols ``omega1, ...``
    - ``prec`` -- (default: 256) bits of a numeric computation
      (``ComplexField(prec)``)
    - ``exact`` -- (default: ``False``) compute with exact coefficients
      (formal generators, see :class:`~sage_dynsym.analysis.normal_forms.FormalArithmetic`),
      also when every parameter has a value; exact coefficients swell, and
      beyond small problems numerics are faster

    OUTPUT: a :class:`~sage_dynsym.analysis.normal_forms.BirkhoffNormalForm`

    EXAMPLES: L4 of the restricted three-body problem, `\mu = 1/100`::

        sage: from sage_dynsym import Lagrangian
        sage: from sage_dynsym.dynamics.nonlinear_stability import birkhoff_normal_form
        sage: x, y, dx, dy, mu = var('x y dx dy mu')
        sage: r1, r2 = sqrt((x + mu)^2 + y^2), sqrt((x - 1 + mu)^2 + y^2)
        sage: L = Lagrangian(((dx - y)^2 + (dy + x)^2)/2 + (1 - mu)/r1 + mu/r2, [x, y])
        sage: nf = birkhoff_normal_form(L, {x: 1/2 - mu, y: sqrt(3)/2, mu: 1/100}, prec=100)
        sage: nf.frequencies()  # rel tol 1e-25
        [0.96332210908509951194826582374, -0.26834774854251271758146030705]
        sage: nf.arnold_determinant()  # rel tol 1e-20
        0.099733995547560912150549025882

    TESTS::

        sage: birkhoff_normal_form(L, {x: 0, y: 0, mu: 1/100})
        Traceback (most recent call last):
        ...
        AnalysisError: at: {...} is not an equilibrium: ...
        sage: birkhoff_normal_form(L, {x: 1/2 - mu, y: sqrt(3)/2})
        Traceback (most recent call last):
        ...
        AnalysisError: sample: give a sample value of the parameters ['mu'] ...
    """
    if not exact:
        poly = taylor_polynomial(model, at, order)
        if not any(c.variables() for c in poly.coefficients()):
            from sage.rings.complex_mpfr import ComplexField
            CC = ComplexField(prec or 256)
            numeric = poly.map_coefficients(CC, new_base_ring=CC)
            return normal_form(FormalArithmetic.numeric(numeric, poly.parent().ngens() // 2,
                                                        prec or 256), order)
    H, values, relations = polynomial_hamiltonian(model, at, order)
    n = len(H.parent().gens()) // 2
    sample = {str(k): v for k, v in (sample or {}).items()}
    if any(v is None for v in values.values()):
        # free parameters: exact in the field of the data over QQ(params)
        return normal_form(FieldArithmetic(H, n, values, relations, sample=sample), order)
    return normal_form(FormalArithmetic(H, n, values, relations, sample=sample), order)


def nonlinear_stability(model, at, order=4, positive=(), prec=256, interval=None):
    r"""
    Lyapunov stability of an equilibrium of a conservative system beyond
    the first approximation (see the module documentation for the
    theorems).

    INPUT:

    - ``model`` -- a Lagrangian, Routh function or Hamiltonian (conserved),
      or a Lie--Poisson system (then the energy--Casimir method, see
      :meth:`~sage_dynsym.lie.system.LiePoissonSystem.nonlinear_stability`)
    - ``at`` -- dict coordinate -> value at the equilibrium, with a value
      of every parameter
    - ``order`` -- (default: 4) the degree of the normal form (6 decides
      where Arnold's determinant of degree 4 vanishes)
    - ``positive`` -- (optional) symbols declared positive (recorded in
      the verdict)
    - ``prec`` -- (default: 256) bits of the numeric normal form; the
      linearization, the frequencies and the resonances are exact
    - ``interval`` -- (optional) a pair ``(a, b)``: with one parameter
      left free in ``at`` (two degrees of freedom), the verdict over
      `a < \mu < b`, case by case: between the exceptional values of
      :func:`exceptional_values` (decided at an exact rational sample of
      each interval) and at each of them (exactly at the boundary of the
      first approximation and at the resonances; at a zero of Arnold's
      determinant, a numerical approximation, ``'undecided'`` at order 4
      and decided by the determinant of degree 6 with ``order=6``)

    OUTPUT: a :class:`~sage_dynsym.analysis.verdict.StabilityVerdict`

    EXAMPLES: L4 of the restricted three-body problem::

        sage: from sage_dynsym import Lagrangian
        sage: from sage_dynsym.dynamics.nonlinear_stability import nonlinear_stability
        sage: x, y, dx, dy, mu = var('x y dx dy mu')
        sage: r1, r2 = sqrt((x + mu)^2 + y^2), sqrt((x - 1 + mu)^2 + y^2)
        sage: L = Lagrangian(((dx - y)^2 + (dy + x)^2)/2 + (1 - mu)/r1 + mu/r2, [x, y])
        sage: L4 = {x: 1/2 - mu, y: sqrt(3)/2}
        sage: nonlinear_stability(L, {**L4, mu: 1/100})
        stable: Arnold-Moser theorem: ...
        sage: nonlinear_stability(L, {**L4, mu: 1/20})
        unstable: a root of the linearization has a positive real part ...
        sage: mu2 = (1 - sqrt(1 - 64/675))/2             # omega1 = 2 omega2
        sage: nonlinear_stability(L, {**L4, mu: mu2}).reason()
        'resonance 1:2 (k = (1, 2)) with a nonzero resonant term of degree 3 (amplitude ...): unstable (Markeev)'

    Over the mass ratio (Deprit's diagram; the exceptional values are
    cases of their own, see :func:`exceptional_values`; at Routh's value
    the double root on the imaginary axis is a critical case left
    'undecided')::

        sage: v = nonlinear_stability(L, L4, interval=(0, 1/2))  # long time
        sage: [(c.verdict(), c.region()[0][0].rhs().n(digits=8)) for c in v.cases()]  # long time
        [('stable', 0.00000000),
         ('undecided', 0.010913668),
         ('stable', 0.010913668),
         ('unstable', 0.013516016),
         ('stable', 0.013516016),
         ('unstable', 0.024293897),
         ('stable', 0.024293897),
         ('undecided', 0.038520897),
         ('unstable', 0.038520897)]
        sage: v.cases()[7].reason()  # long time
        'first approximation: multiple or zero roots of the linearization: ...'
        sage: v.at({mu: 1/50}), v.at({mu: 1/10})  # long time
        ('stable', 'unstable')

    TESTS::

        sage: nonlinear_stability(L, L4)
        Traceback (most recent call last):
        ...
        AnalysisError: at: give a value to the parameters ['mu'], or leave one free with interval=(a, b) ...

    A Lie--Poisson system, by the energy--Casimir method (Euler's free
    rigid body rotating about the axis of its smallest moment of inertia)::

        sage: from sage_dynsym.lie.system import LiePoissonSystem
        sage: M1, M2, M3 = var('M1 M2 M3')
        sage: S = LiePoissonSystem('so3', (M1^2 + M2^2/2 + M3^2/3)/2)
        sage: nonlinear_stability(S, {M1: 1, M2: 0, M3: 0}).method()
        'energy-Casimir'
    """
    if callable(getattr(model, 'nonlinear_stability', None)):
        # a model with a method of its own (a Lie-Poisson system: energy-Casimir)
        return model.nonlinear_stability(at, positive=positive or None)
    H = taylor_polynomial(model, at, 2)
    free = sorted({str(v) for c in H.coefficients() for v in c.variables()})
    if free and (len(free) > 1 or interval is None):
        raise AnalysisError(f"give a value to the parameters {free}, or leave one free with "
                            "interval=(a, b) for the cases over it (in two degrees of "
                            "freedom; see also exceptional_values)", entry="at")
    if free:
        return _over_parameter(model, at, free[0], interval, order, positive, prec)
    return normal_form_stability(
        H, lambda degree: birkhoff_normal_form(model, at, degree, prec=prec),
        order=order, positive=positive, prec=prec)


def _exact_symbolic(value):
    r"""A parameter value as an exact symbolic number: a real algebraic
    number by its radicals where it has them, a real number (an
    approximation of a zero found by bisection) by the rational it prints
    as."""
    from sage.rings.qqbar import AA
    if value in QQ:
        return SR(QQ(value))
    if isinstance(value, type(AA(0))):
        exact = value.radical_expression()
        return exact if not isinstance(exact, type(AA(0))) else SR(value)
    return SR(QQ(value))


def _over_parameter(model, at, name, interval, order, positive, prec):
    parameter = SR.var(name)
    found = exceptional_values(model, at, parameter, interval, order=order, prec=prec)

    def verdict_at(value, kinds):
        # at a zero of Arnold's determinant of degree 4 (a rational within
        # the tolerance of the zero) its small value decides nothing: the
        # next degree decides
        degenerate = (4,) if 'Arnold determinant' in kinds else ()
        point = {**at, parameter: _exact_symbolic(value)}
        return normal_form_stability(
            taylor_polynomial(model, point, 2),
            lambda degree: birkhoff_normal_form(model, point, degree, prec=prec),
            order=order, positive=positive, prec=prec, degenerate=degenerate)
    return stability_over_parameter(parameter, interval, found, verdict_at, positive)


def exceptional_values(model, at, parameter, interval, order=4, samples=40, prec=128,
                       tolerance=QQ((1, 10 ** 14))):
    r"""
    The values of one parameter where the verdict of
    :func:`nonlinear_stability` changes, in two degrees of freedom: the
    boundary of stability in first approximation (two frequencies meet),
    the resonances `k_1\omega_1 = k_2\omega_2` with `k_1 + k_2 \le`
    ``order`` (exact: algebraic numbers, roots of resultants of the
    characteristic polynomial), and the zeros of Arnold's determinant
    (numbers: sign changes of `D` on ``samples`` points between the
    resonances, where `D` has its poles, refined by bisection to
    ``tolerance``).

    INPUT:

    - ``model``, ``at`` -- as for :func:`birkhoff_normal_form`, with the
      parameter free (the other parameters given values)
    - ``parameter`` -- the free parameter
    - ``interval`` -- a pair ``(a, b)`` of numbers: where to look
    - ``order`` -- (default: 4) the resonances' order and the degree of
      Arnold's determinant
    - ``samples``, ``prec``, ``tolerance`` -- of the search for the zeros
      of `D`

    OUTPUT: a dict: ``'first approximation'``, ``'resonance k1:k2'`` ->
    a list of algebraic numbers; ``'Arnold determinant'`` -> a list of
    real numbers

    EXAMPLES: the exceptional mass ratios of L4 (Routh's `\mu_1`,
    Deprit's `\mu_c`, the resonances)::

        sage: from sage_dynsym import Lagrangian
        sage: from sage_dynsym.dynamics.nonlinear_stability import exceptional_values
        sage: x, y, dx, dy, mu = var('x y dx dy mu')
        sage: r1, r2 = sqrt((x + mu)^2 + y^2), sqrt((x - 1 + mu)^2 + y^2)
        sage: L = Lagrangian(((dx - y)^2 + (dy + x)^2)/2 + (1 - mu)/r1 + mu/r2, [x, y])
        sage: values = exceptional_values(L, {x: 1/2 - mu, y: sqrt(3)/2}, mu, (0, 1/2))  # long time
        sage: {k: [v.n(digits=12) for v in vs] for k, vs in values.items()}  # long time
        {'Arnold determinant': [0.0109136676772],
         'first approximation': [0.0385208965046],
         'resonance 1:2': [0.0242938971421],
         'resonance 1:3': [0.0135160160225]}
    """
    from sage.rings.qqbar import AA
    from sage.rings.polynomial.polynomial_ring_constructor import PolynomialRing as PR
    H, values, relations = polynomial_hamiltonian(model, at, order)
    name = str(parameter)
    if values.get(name, 0) is not None:
        raise AnalysisError(f"{parameter} must be a free parameter of the Taylor coefficients "
                            f"(free: {[g for g, v in values.items() if v is None]})",
                            entry="parameter")
    others = [g for g, v in values.items() if v is None and g != name]
    if others:
        raise AnalysisError(f"give the parameters {others} values in at=", entry="at")
    a, b = AA(interval[0]), AA(interval[1])
    base = H.base_ring()
    t = PR(AA, 't').gen()
    point = [t if g == name else AA(values[g]) for g in base.variable_names()]
    S, _ = _symbolic_hessian(H, point)
    n = S.nrows() // 2
    if n != 2:
        raise AnalysisError(f"exceptional values are for two degrees of freedom, not {n}",
                            entry="model")
    from ..analysis.normal_forms import symplectic_unit
    chi = (symplectic_unit(n).change_ring(S.base_ring()) * S).charpoly('x')
    try:
        # rational coefficients (the usual case: the constants enter squared)
        # keep the resultants over QQ[t], fast and without algebraic numbers
        chi = chi.change_ring(PR(QQ, 't'))
    except (TypeError, ValueError):
        pass
    s = PR(chi.base_ring(), 's').gen()
    p = sum(chi[2 * k] * s ** k for k in range(n + 1))      # chi(lambda) = p(lambda^2)
    found = {}

    def roots_in(poly):
        poly = poly.numerator() if hasattr(poly, 'numerator') else poly
        if poly.base_ring() is not QQ:
            poly = PR(AA, 't')(poly)
        return sorted(r for r in poly.roots(AA, multiplicities=False) if a < r < b)
    # the discriminant (of a quadratic) by its formula and the resultants in
    # s over the ring of t by Sylvester determinants: Sage asks PARI first, which refuses a polynomial in s
    # over t when PARI's variable t is older than s ('incorrect priority'):
    # the error, caught by Sage, went through an abort that pytest's fault
    # handler printed as 'Fatal Python error: Aborted'
    found['first approximation'] = roots_in(p[1] ** 2 - 4 * p[2] * p[0])   # p is quadratic
    for k1 in range(1, order):
        for k2 in range(k1 + 1, order + 1 - k1):
            if math.gcd(k1, k2) != 1:
                continue
            # omega1/omega2 = k2/k1: s1 = (k2/k1)^2 s2 for two roots s = -omega^2
            q = p.sylvester_matrix(p(s * QQ(k2) ** 2 / QQ(k1) ** 2)).det()
            hits = [r for r in roots_in(q) if _ratio(p, r, k2 / QQ(k1))]
            if hits:
                found[f"resonance {k1}:{k2}"] = hits
    exact = _exact_determinant_zeros(H, values, relations, name, found, a, b, prec)
    found['Arnold determinant'] = exact if exact is not None else _determinant_zeros(
        H, values, name, found, a, b, order, samples, prec, tolerance)
    return dict(sorted(found.items()))


def _exact_determinant_zeros(H, values, relations, name, found, a, b, prec):
    r"""The zeros of Arnold's determinant in ``(a, b)`` as real algebraic
    numbers: the roots of its norm (:func:`~sage_dynsym.analysis.parametric_normal_forms.arnold_polynomial`)
    at which the determinant of these modes (not a conjugate's) vanishes,
    checked on the numeric normal form; ``None`` when the exact normal form
    is out of reach (the bisection then decides)."""
    from sage.rings.qqbar import AA
    from sage.rings.complex_mpfr import ComplexField
    from sage.rings.real_mpfi import RIF
    cuts = sorted([a, b] + [r for rs in found.values() for r in rs])
    # a sample where the modes are elliptic and simple (the pieces between
    # the exceptional values, widest first; beyond the first approximation
    # the normal form is refused)
    pieces = sorted(zip(cuts, cuts[1:]), key=lambda p: -RIF(p[1] - p[0]).center())
    norm = None
    for lo, hi in pieces:
        width = (RIF(hi) - RIF(lo)) / 4
        sample = RIF(RIF(lo) + width, RIF(hi) - width).simplest_rational()
        try:
            nf = normal_form(FieldArithmetic(H, 2, values, relations, sample={name: sample}), 4)
        except AnalysisError:
            continue
        _, norm = arnold_polynomial(nf)
        break
    if norm is None:
        return None
    CC = ComplexField(prec)
    names = H.base_ring().variable_names()
    zeros = []
    for root in norm.roots(AA, multiplicities=False):
        if not a < root < b or any(root in rs for rs in found.values()):
            continue
        point = [CC(root) if g == name else CC(values[g]) for g in names]
        numeric = H.map_coefficients(lambda c: CC(c(*point)), new_base_ring=CC)
        try:
            D = normal_form(FormalArithmetic.numeric(numeric, 2, prec), 4).arnold_determinant()
        except AnalysisError:
            continue            # not elliptic there: no normal form, no determinant
        if abs(D) < QQ(2) ** (-prec // 3):
            zeros.append(root)
    return zeros


def _symbolic_hessian(H, point):
    from sage.matrix.constructor import matrix
    n = len(H.parent().gens()) // 2
    X = H.parent().gens()
    H2 = H.parent()({e: c for e, c in H.dict().items() if sum(e) == 2})
    entries = [[H2.derivative(X[i]).derivative(X[j]).constant_coefficient()(*point)
                for j in range(2 * n)] for i in range(2 * n)]
    return matrix(entries), n


def _ratio(p, r, ratio):
    r"""Whether at the parameter ``r`` the two roots `s = -\omega^2` of ``p``
    are negative and `\omega_1/\omega_2 =` ``ratio``."""
    from sage.rings.qqbar import AA
    roots = sorted(p.map_coefficients(lambda c: c(r)).roots(AA, multiplicities=False))
    if len(roots) != 2 or any(x >= 0 for x in roots):
        return False
    return roots[0] == ratio ** 2 * roots[1]


def _determinant_zeros(H, values, name, found, a, b, order, samples, prec, tolerance):
    from sage.rings.complex_mpfr import ComplexField
    from sage.rings.real_mpfr import RealField
    CC = ComplexField(prec)
    names = H.base_ring().variable_names()
    degree = 4

    def D(m):
        point = [CC(m) if g == name else CC(values[g]) for g in names]
        numeric = H.map_coefficients(lambda c: CC(c(*point)), new_base_ring=CC)
        try:
            nf = normal_form(FormalArithmetic.numeric(numeric, 2, prec), degree)
        except AnalysisError:
            return None
        return nf.arnold_determinant(degree)
    cuts = sorted([a, b] + [r for key, rs in found.items() for r in rs])
    zeros = []
    RF = RealField(prec)
    for lo, hi in zip(cuts, cuts[1:]):
        grid = [RF(lo) + (RF(hi) - RF(lo)) * (k + QQ((1, 2))) / samples for k in range(samples)]
        vals = [D(m) for m in grid]
        for (m0, d0), (m1, d1) in zip(zip(grid, vals), zip(grid[1:], vals[1:])):
            if d0 is None or d1 is None or d0.sign() == d1.sign():
                continue
            while m1 - m0 > tolerance:
                mid = (m0 + m1) / 2
                dm = D(mid)
                if dm.sign() == d0.sign():
                    m0, d0 = mid, dm
                else:
                    m1 = mid
            zeros.append((m0 + m1) / 2)
    return zeros
