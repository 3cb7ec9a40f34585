r"""
Families of equilibria by elimination

The equilibria of `\dot x = F(x)` are the zeros of `F`. To describe them as
a family, some unknowns are eliminated:

1. an equation that is *linear* in an unknown to eliminate (the unknown
   does not occur in its coefficient, nor inside a function), with a
   coefficient free of the other unknowns to eliminate, is solved for it
   and the solution substituted into the other equations -- repeated while
   possible; a non-numeric coefficient is recorded as a condition ``!= 0``.
   Unknown functions (such as the characteristics ``f1(u6)`` of nonlinear
   resistors) may stay unevaluated in this step;
2. only what remains goes to a Gröbner basis (Singular: the elimination
   ideal over `\QQ` in all symbols); this needs polynomial equations.

In circuits and mechanics most unknowns appear linearly (Kirchhoff's laws),
so step 1 usually does everything: on Example 4 it takes a few
milliseconds, a plain elimination ideal of the whole system over 300 s.

EXAMPLES:

Example 4 of :doc:`the method </method>`: equilibria of the circuit's
state equations (11), first with the resistor characteristics left as
unknown functions::

    sage: from sage_dynsym.analysis.elimination import equilibrium_family
    sage: i1, i2, u3, u4, u5, u6 = var('i1 i2 u3 u4 u5 u6')
    sage: I0, I01, I02 = var('I0 I01 I02')
    sage: f1, f2, f3, f4 = [function('f%d' % j) for j in (1, 2, 3, 4)]
    sage: rhs = [u4 + u6 - u3, u5 - u4, I01 + i1 + f3(u3),
    ....:        i2 - i1 + f2(u4) - I0, I02 - i2 + f4(u5), -i1 - I0 + f1(u6)]
    sage: fam = equilibrium_family(rhs, [i1, i2, u3, u4, u5, u6],
    ....:                          eliminate=[u3, u5, i1, i2])
    sage: fam.substitutions()
    {i1: -I0 + f1(u6), i2: I02 + f4(u4), u3: u4 + u6, u5: u4}
    sage: fam.equations()
    [-I0 + I01 + f1(u6) + f3(u4 + u6), I02 - f1(u6) + f2(u4) + f4(u4)]

The source currents that make `(u_4, u_6) = (u_4^0, u_6^0)` an
equilibrium -- a family of equilibria parametrized by `u_4^0, u_6^0`::

    sage: u40, u60 = var('u40 u60')
    sage: sol = fam.parameters_for({u4: u40, u6: u60}, [I01, I02])
    sage: sol
    {I01: I0 - f1(u60) - f3(u40 + u60), I02: f1(u60) - f2(u40) - f4(u40)}
    sage: pt = fam.point({u4: u40, u6: u60}, parameters=sol); pt
    {i1: -I0 + f1(u60),
     i2: f1(u60) - f2(u40),
     u3: u40 + u60,
     u4: u40,
     u5: u40,
     u6: u60}
    sage: [e.subs(pt).subs(sol) for e in rhs]
    [0, 0, 0, 0, 0, 0]

With the cubic characteristics `f_j(u) = g_j u (u - 3 s_j)^2` the
remaining equations are polynomial; here no Gröbner basis is needed at
all::

    sage: g = var('g1 g2 g3 g4'); s = var('s1 s2 s3 s4')
    sage: cubic = [lambda u, j=j: g[j]*u*(u - 3*s[j])^2 for j in range(4)]
    sage: rhs3 = [u4 + u6 - u3, u5 - u4, I01 + i1 + cubic[2](u3),
    ....:         i2 - i1 + cubic[1](u4) - I0, I02 - i2 + cubic[3](u5), -i1 - I0 + cubic[0](u6)]
    sage: fam3 = equilibrium_family(rhs3, [i1, i2, u3, u4, u5, u6],
    ....:                           eliminate=[u3, u5, i1, i2])
    sage: fam3.used_groebner(), [sorted(e.variables(), key=str) for e in fam3.equations()]
    (False, [[I0, I01, g1, g3, s1, s3, u4, u6], [I02, g1, g2, g4, s1, s2, s4, u4, u6]])
    sage: sol3 = fam3.parameters_for({u4: u40, u6: u60}, [I01, I02])
    sage: bool(sol3[I01] == I0 - cubic[0](u60) - cubic[2](u40 + u60))
    True

TESTS::

    sage: equilibrium_family([sin(u3) - u4], [u3, u4], eliminate=[u3])
    Traceback (most recent call last):
    ...
    AnalysisError: right-hand side 0: elimination needs polynomial equations; got -u4 + sin(u3) (substitute the unknown functions and non-polynomial terms first)
    sage: equilibrium_family([f1(u3)*u4^2 - 1, u4^2 - u3], [u3, u4], eliminate=[u4])
    Traceback (most recent call last):
    ...
    AnalysisError: right-hand side 0: elimination needs polynomial equations; got u4^2*f1(u3) - 1 (substitute the unknown functions and non-polynomial terms first)
"""
from sage.rings.polynomial.polynomial_ring_constructor import PolynomialRing
from sage.rings.rational_field import QQ
from sage.symbolic.ring import SR

from ..arguments import expression_list
from ..errors import AnalysisError

__all__ = ['EquilibriumFamily', 'equilibrium_family']


def _polynomial_system(equations, symbols):
    names = sorted({str(v) for v in symbols})
    R = PolynomialRing(QQ, names, len(names), order='degrevlex')
    polys = []
    for k, e in enumerate(equations):
        try:
            num, den = e.numerator_denominator(normalize=True) if e.variables() else (e, SR(1))
            polys.append(num.polynomial(ring=R))
        except (TypeError, ValueError, NotImplementedError, AttributeError) as err:
            raise AnalysisError(
                f"elimination needs polynomial equations; got {e} (substitute "
                f"the unknown functions and non-polynomial terms first)",
                entry=f"right-hand side {k}") from err
    return R, polys


def _linear_coefficient(e, v, todo):
    r"""The coefficient ``c`` if ``e = c*v + r`` with ``v`` in neither ``c``
    nor ``r`` (also not inside a function) and no unknown to eliminate in
    ``c``; else ``None``."""
    if not e.has(v):
        return None
    c = e.diff(v)
    if c.is_zero() or any(c.has(w) for w in todo):
        return None
    return c


class EquilibriumFamily:
    r"""
    The equilibria of a polynomial system after elimination: substitutions
    for the eliminated unknowns and the remaining equations.

    Created by :func:`equilibrium_family`.

    EXAMPLES::

        sage: from sage_dynsym.analysis.elimination import equilibrium_family
        sage: x, y, z, a = var('x y z a')
        sage: fam = equilibrium_family([y - x^2, z - y - a, z*x - 1], [x, y, z],
        ....:                          eliminate=[y, z]); fam
        Family of equilibria: 2 unknowns eliminated, 1 equations remain
        sage: fam.substitutions(), fam.equations()
        ({y: x^2, z: x^2 + a}, [(x^2 + a)*x - 1])
    """

    def __init__(self, variables, substitutions, equations, nonzero, groebner):
        self._variables = list(variables)
        self._subs = substitutions         # ordered list of (unknown, value)
        self._equations = equations
        self._nonzero = nonzero
        self._groebner = groebner

    def __repr__(self):
        return (f"Family of equilibria: {len(self._subs)} unknowns eliminated, "
                f"{len(self._equations)} equations remain")

    def substitutions(self):
        r"""
        The eliminated unknowns as functions of the others, a dict
        ``{unknown: expression}`` (fully back-substituted; unknowns eliminated
        by Gröbner bases are not in it).


        EXAMPLES::

            sage: from sage_dynsym.analysis.elimination import equilibrium_family
            sage: x, y, z, a = var('x y z a')
            sage: fam = equilibrium_family([y - x^2, z - y - a, z*x - 1], [x, y, z],
            ....:                          eliminate=[y, z])
            sage: fam.substitutions()
            {y: x^2, z: x^2 + a}
        """
        result = {}
        for v, value in reversed(self._subs):
            result[v] = value.subs(result)
        return {k: result[k] for k in sorted(result, key=str)}

    def equations(self):
        r"""
        The remaining polynomial equations (expressions ``== 0``) in the
        unknowns not eliminated and the parameters.


        EXAMPLES::

            sage: from sage_dynsym.analysis.elimination import equilibrium_family
            sage: x, y, z, a = var('x y z a')
            sage: fam = equilibrium_family([y - x^2, z - y - a, z*x - 1], [x, y, z],
            ....:                          eliminate=[y, z])
            sage: fam.equations()
            [(x^2 + a)*x - 1]
        """
        return list(self._equations)

    def nonzero_conditions(self):
        r"""
        Expressions assumed nonzero (coefficients divided by).

        EXAMPLES::

            sage: from sage_dynsym.analysis.elimination import equilibrium_family
            sage: x, y, a = var('x y a')
            sage: fam = equilibrium_family([a*x - y, y^2 - 1], [x, y], eliminate=[x])
            sage: fam.nonzero_conditions(), fam.substitutions(), fam.equations()
            ([a], {x: y/a}, [y^2 - 1])
        """
        return list(self._nonzero)

    def used_groebner(self):
        r"""
        Whether a Gröbner basis was needed after substitution.

        EXAMPLES::

            sage: from sage_dynsym.analysis.elimination import equilibrium_family
            sage: x, y, z = var('x y z')
            sage: fam = equilibrium_family([x^2 + y^2 - 1, x^2 - y, z - x*y],
            ....:                          [x, y, z], eliminate=[x, z])
            sage: fam.used_groebner(), fam.equations(), fam.substitutions()
            (True, [y^2 + y - 1], {z: x*y})
        """
        return self._groebner

    def point(self, values, parameters=None):
        r"""
        The full equilibrium point for given values of the unknowns that
        were not eliminated, a dict ``{unknown: value}``.

        INPUT:

        - ``values`` -- dict giving the unknowns left
        - ``parameters`` -- (optional) dict of parameter values to use


        EXAMPLES::

            sage: from sage_dynsym.analysis.elimination import equilibrium_family
            sage: x, y, z, a = var('x y z a')
            sage: fam = equilibrium_family([y - x^2, z - y - a, z*x - 1], [x, y, z],
            ....:                          eliminate=[y, z])
            sage: fam.point({x: 1}, parameters={a: 0})
            {x: 1, y: 1, z: 1}
        """
        values = {SR(k): SR(v) for k, v in values.items()}
        subs = dict(values)
        if parameters:
            subs.update({SR(k): SR(v) for k, v in parameters.items()})
        point = dict(values)
        for v, e in self.substitutions().items():
            point[v] = e.subs(subs)
        return {v: point[SR(v)] for v in self._variables if SR(v) in point}

    def parameters_for(self, values, parameters):
        r"""
        Values of ``parameters`` that make the point given by ``values`` an
        equilibrium: the remaining equations at that point solved for them.

        INPUT:

        - ``values`` -- dict ``{unknown: value}`` for the unknowns left
          (values may be symbolic, e.g. ``u40``)
        - ``parameters`` -- list of parameters to solve for

        OUTPUT: a dict ``{parameter: expression}``

        Raises :class:`AnalysisError` if the equations do not determine them
        uniquely (then see :meth:`equations`).


        EXAMPLES::

            sage: from sage_dynsym.analysis.elimination import equilibrium_family
            sage: x, y, z, a = var('x y z a')
            sage: fam = equilibrium_family([y - x^2, z - y - a, z*x - 1], [x, y, z],
            ....:                          eliminate=[y, z])
            sage: fam.parameters_for({x: 2}, [a])
            {a: -7/2}
        """
        eqs = [p.subs({SR(k): SR(v) for k, v in values.items()}) for p in self._equations]
        eqs = [e for e in eqs if not bool(e.expand() == 0)]
        symbols = set().union(*(e.variables() for e in eqs)) | {SR(p) for p in parameters}
        sub = equilibrium_family(eqs, list(symbols), eliminate=list(parameters))
        got = sub.substitutions()
        if sub.equations() or set(got) != {SR(p) for p in parameters}:
            raise AnalysisError(
                f"the equations at the point do not determine {list(parameters)} "
                f"uniquely; remaining equations: {sub.equations()}",
                entry="parameters_for")
        return {SR(p): got[SR(p)] for p in parameters}


def equilibrium_family(rhs, variables, eliminate, use_groebner=True):
    r"""
    The equilibria of `\dot x = F(x)`: ``rhs`` set to zero, the unknowns
    ``eliminate`` eliminated (by substitution where they appear linearly,
    by a Gröbner basis for the rest).

    INPUT:

    - ``rhs`` -- list of polynomial expressions `F_i` (or equations)
    - ``variables`` -- list of the unknowns `x`
    - ``eliminate`` -- the unknowns to eliminate
    - ``use_groebner`` -- (default: ``True``) eliminate what is not linear
      with an elimination ideal (Singular); if ``False`` such unknowns stay

    OUTPUT: an :class:`EquilibriumFamily`

    EXAMPLES: see the module documentation. The double pendulum's
    equilibria in algebraic form (`c_i = \cos\varphi_i`, `s_i =
    \sin\varphi_i`; Merkin, ch. 2): the gradient of the potential and the
    circle relations give the four equilibria `s_1 = s_2 = 0`::

        sage: from sage_dynsym.analysis.elimination import equilibrium_family
        sage: c1, s1, c2, s2 = var('c1 s1 c2 s2')
        sage: fam = equilibrium_family([s1, s2, c1^2 + s1^2 - 1, c2^2 + s2^2 - 1],
        ....:                          [c1, s1, c2, s2], eliminate=[s1, s2])
        sage: fam.equations()
        [c1^2 - 1, c2^2 - 1]
    """
    variables = expression_list(variables, "variables", AnalysisError, names=True)
    eqs = []
    for e in expression_list(rhs, "rhs", AnalysisError,
                             expected="a list of right-hand sides or equations"):
        eqs.append(e.lhs() - e.rhs() if e.is_relational() else e)
    todo = expression_list(eliminate, "eliminate", AnalysisError, names=True)
    eqs = [e for e in eqs if not e.is_zero()]
    subs, nonzero = [], []
    while todo:
        # prefer numeric coefficients, then the shortest equation
        candidates = []
        for i, e in enumerate(eqs):
            for v in todo:
                c = _linear_coefficient(e, v, todo)
                if c is not None:
                    candidates.append((not c.is_numeric(), len(str(e)), i, v, c))
        if not candidates:
            break
        _, _, i, v, c = min(candidates, key=lambda t: t[:3])
        e = eqs.pop(i)
        if not c.is_numeric():
            nonzero.append(c)
        value = (-(e - c * v) / c).expand()
        eqs = [q.subs({v: value}) for q in eqs]
        eqs = [q for q in eqs if not q.expand().is_zero()]
        subs.append((v, value))
        todo.remove(v)
    groebner = False
    if todo and use_groebner and eqs:
        groebner = True
        symbols = set(variables)
        for e in eqs:
            symbols |= set(e.variables())
        R, polys = _polynomial_system(eqs, symbols)
        polys = R.ideal(polys).elimination_ideal([R(str(v)) for v in todo]).gens()
        eqs = [SR(q).factor() for q in polys if q != 0]
    return EquilibriumFamily(variables, subs, eqs, nonzero, groebner)
