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
    sage: nf = birkhoff_normal_form(L, {q: 0}, order=6)
    sage: nf.coefficients(exact=True)
    {(1,): 1, (2,): -1/16, (3,): -1/256}
    sage: nonlinear_stability(L, {q: 0})
    stable: the energy has a strict minimum at the equilibrium (Lagrange-Dirichlet): ...

REFERENCES:

- [Markeev1978]_ A. P. Markeev, Libration points in celestial mechanics
  and space dynamics, Nauka, Moscow 1978.
- [ArnoldKozlovNeishtadt2006]_ V. I. Arnold, V. V. Kozlov, A. I.
  Neishtadt, Mathematical aspects of classical and celestial mechanics,
  3rd ed., Springer 2006, sections 7.3 and 8.3.
- [MeyerHallOffin2009]_ (see :mod:`~sage_dynsym.analysis.normal_forms`).
"""
from sage.rings.polynomial.polynomial_ring_constructor import PolynomialRing
from sage.rings.qqbar import QQbar
from sage.rings.rational_field import QQ
from sage.symbolic.ring import SR
from sage.symbolic.operators import add_vararg, mul_vararg
import operator

from ..errors import AnalysisError
from ..analysis.normal_forms import normal_form, FormalArithmetic, BirkhoffNormalForm
from ..analysis.verdict import StabilityVerdict
from .hamiltonian import Hamiltonian

__all__ = ['birkhoff_normal_form', 'nonlinear_stability', 'BirkhoffNormalForm',
           'polynomial_hamiltonian']


def _hamiltonian(model):
    from .lagrangian import Lagrangian
    if isinstance(model, Hamiltonian):
        H = model
    elif isinstance(model, Lagrangian):
        H = model.hamiltonian()
    else:
        raise AnalysisError(f"expected a Lagrangian, RouthFunction or Hamiltonian, got "
                            f"{type(model).__name__}", entry="model")
    if H.is_singular() or H._conserved_energy() is None:
        raise AnalysisError("the Hamiltonian must be conserved and regular (no explicit "
                            "time, no dissipation or forces, a regular Lagrangian)",
                            entry="model")
    return H


def _point(H, at):
    r"""The equilibrium `(q_0, p_0)` and the parameter values of ``at``."""
    coordinates, momenta = H.coordinates(), H.momenta()
    names = {str(v): v for v in coordinates + momenta}
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
    if any(not g.is_zero() for g in gradient):
        raise AnalysisError(f"{point} is not an equilibrium: the gradient of the "
                            f"Hamiltonian there is {gradient}", entry="at")
    return point, values, expr


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
        (-1/24*k*q1^4 + 1/2*k*q1^2 + 1/2*p1^2, {'k': None})
    """
    H = _hamiltonian(model)
    point, values, expr = _point(H, at)
    variables = H.coordinates() + H.momenta()
    n = len(H.coordinates())
    shifts = [SR.var(f"q{k + 1}") for k in range(n)] + [SR.var(f"p{k + 1}") for k in range(n)]
    shifted = expr.subs({v: point[v] + s for v, s in zip(variables, shifts)})
    series = shifted.taylor(*[(s, 0) for s in shifts], order)
    poly = series.polynomial(ring=PolynomialRing(SR, [str(s) for s in shifts]))
    constants, parameters = {}, set()
    for c in poly.coefficients():
        _collect(c, constants, parameters)
    names = sorted(map(str, parameters))
    symbols = {c: SR.var(f"c{k + 1}") for k, c in enumerate(constants.values())}
    base = PolynomialRing(QQ, names + [str(s) for s in symbols.values()])
    ring = PolynomialRing(base, [str(s) for s in shifts])
    terms = {}
    for e, c in poly.dict().items():
        c = c.subs(symbols) if symbols else c
        terms[e] = _to_base(c, base)
    values_out = {name: values.get(SR.var(name)) for name in names}
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


def birkhoff_normal_form(model, at, order=4, sample=None, prec=None):
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
    - ``prec`` -- (optional) bits of a numeric computation
      (``ComplexField(prec)``); by default exact

    OUTPUT: a :class:`~sage_dynsym.analysis.normal_forms.BirkhoffNormalForm`

    EXAMPLES: L4 of the restricted three-body problem, `\mu = 1/100`::

        sage: from sage_dynsym import Lagrangian
        sage: from sage_dynsym.dynamics.nonlinear_stability import birkhoff_normal_form
        sage: x, y, dx, dy, mu = var('x y dx dy mu')
        sage: r1, r2 = sqrt((x + mu)^2 + y^2), sqrt((x - 1 + mu)^2 + y^2)
        sage: L = Lagrangian(((dx - y)^2 + (dy + x)^2)/2 + (1 - mu)/r1 + mu/r2, [x, y])
        sage: nf = birkhoff_normal_form(L, {x: 1/2 - mu, y: sqrt(3)/2, mu: 1/100})
        sage: nf.frequencies()
        [0.9637049655652809?, -0.2668795391069999?]
        sage: nf.arnold_determinant().real().n(30)
        0.026...

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
    H, values, relations = polynomial_hamiltonian(model, at, order)
    n = len(H.parent().gens()) // 2
    if prec is not None:
        if any(v is None for g, v in values.items() if not g.startswith('c')):
            raise AnalysisError("a numeric normal form needs a value of every parameter "
                                "in at=", entry="prec")
        CC = __import__('sage.rings.complex_mpfr', fromlist=['ComplexField']).ComplexField(prec)
        point = [CC(v) for v in values.values()]
        numeric = H.map_coefficients(lambda c: CC(c(*point)) if point else CC(c),
                                     new_base_ring=CC)
        return normal_form(FormalArithmetic.numeric(numeric, n, prec), order)
    sample = {str(k): v for k, v in (sample or {}).items()}
    return normal_form(FormalArithmetic(H, n, values, relations, sample=sample), order)
