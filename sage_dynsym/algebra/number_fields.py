r"""
Exact algebraic constants in a number field

Parameter values such as `\cos(\pi/10) = \sqrt{2\sqrt 5 + 10}/4` or
`\sin(\pi/10) = (\sqrt 5 - 1)/4` make the coefficients of a characteristic
polynomial irrational. The polynomial machinery of the analysis works over
`\QQ`; these constants are therefore written in one number field `K =
\QQ(\alpha)` (Sage's ``number_field_elements_from_algebraics``): each is a
polynomial with rational coefficients in `\alpha`, and `\alpha` becomes a
symbol. Every identity, condition and region computed with the symbol
holds for its value in particular (a region found empty for all values of
the symbol is empty at its value); :meth:`AlgebraicConstants.back` puts
the exact value back. `\alpha` is one of the constants when one of them
generates `K`.

EXAMPLES::

    sage: from sage_dynsym.algebra.number_fields import AlgebraicConstants
    sage: v = var('v')
    sage: K = AlgebraicConstants([cos(pi/10)*v + sin(pi/10), sqrt(5)*v^2]); K
    Algebraic constants in Number Field in a0 with defining polynomial x^4 - 20*x^2 + 80 with a0 = 2*a, alpha = sqrt(2*sqrt(5) + 10)
    sage: e = K.forward(cos(pi/10)*v + sin(pi/10)); e
    1/8*alpha_K^2 + 1/4*alpha_K*v - 3/2
    sage: bool(K.back(e) == cos(pi/10)*v + sin(pi/10))
    True
    sage: AlgebraicConstants([v + 1/2]).is_trivial()
    True
"""
import operator

from sage.rings.qqbar import QQbar, AA, number_field_elements_from_algebraics
from sage.rings.rational_field import QQ
from sage.structure.sage_object import SageObject
from sage.symbolic.operators import add_vararg, mul_vararg
from sage.symbolic.ring import SR

__all__ = ['AlgebraicConstants']


def _is_atom(expr):
    if expr.variables() or expr.is_numeric() or expr.operator() in (add_vararg, mul_vararg):
        return False                    # floats and complex numbers are not ours
    if expr.operator() is operator.pow and expr.operands()[1].is_integer():
        return False                    # a power of a constant: the constant is the atom
    try:
        QQbar(expr)
    except (TypeError, ValueError, NotImplementedError):
        return False
    return True


def _atoms(expr, found):
    r"""The maximal constant subexpressions of ``expr`` that are algebraic
    and not rational (sums and products are entered)."""
    expr = SR(expr)
    if _is_atom(expr):
        if all(str(expr) != str(f) for f in found):
            found.append(expr)
        return
    for operand in expr.operands():
        _atoms(operand, found)


def _replace(expr, images):
    r"""``expr`` with its maximal algebraic constants replaced by their
    images (keyed by their text): not inside one another, as ``subs``
    would."""
    expr = SR(expr)
    if _is_atom(expr):
        return images.get(str(expr), expr)
    operands = expr.operands()
    if not operands:
        return expr
    return expr.operator()(*[_replace(o, images) for o in operands])


class AlgebraicConstants(SageObject):
    r"""
    The irrational algebraic constants of some expressions, in one number
    field (see the module documentation).

    INPUT:

    - ``expressions`` -- symbolic expressions (or matrices' entries)
    - ``name`` -- (default: ``'alpha_K'``) the name of the symbol of the
      generator

    EXAMPLES::

        sage: from sage_dynsym.algebra.number_fields import AlgebraicConstants
        sage: K = AlgebraicConstants([sqrt(2)*var('x') + sqrt(3)])
        sage: K.symbol(), K.value()
        (alpha_K, sqrt(sqrt(3) + 2))
        sage: K.forward(sqrt(2)*var('x') + sqrt(3))
        alpha_K^3*x + alpha_K^2 - 3*alpha_K*x - 2
    """

    def __init__(self, expressions, name='alpha_K'):
        found = []
        for e in expressions:
            _atoms(e, found)
        self._symbol = SR.symbol(name)
        self._forward, self._value, self._field = {}, None, None
        if not found:
            return
        K, elements, hom = number_field_elements_from_algebraics(
            [QQbar(c) for c in found], minimal=True)
        generator = None
        for c, x in zip(found, elements):
            if x.minpoly().degree() == K.degree() and AA(c) > 0:
                generator, element = c, x
                break
        if generator is None:
            sign = 1 if AA(hom(K.gen())) > 0 else -1
            generator = sign * SR(hom(K.gen()).radical_expression())
            element = sign * K.gen()
        L, from_L, to_L = K.change_generator(element)
        self._field, self._value = L, generator
        for c, x in zip(found, elements):
            coefficients = to_L(x).polynomial().list()
            self._forward[str(c)] = sum(QQ(a) * self._symbol ** k for k, a in enumerate(coefficients))

    def _repr_(self):
        if self.is_trivial():
            return "Algebraic constants: none (rational)"
        return f"Algebraic constants in {self._field}, alpha = {self._value}"

    def is_trivial(self):
        r"""Whether there is no irrational algebraic constant.

        EXAMPLES::

            sage: from sage_dynsym.algebra.number_fields import AlgebraicConstants
            sage: AlgebraicConstants([sqrt(2)]).is_trivial()
            False
        """
        return not self._forward

    def symbol(self):
        r"""The symbol standing for the generator.

        EXAMPLES::

            sage: from sage_dynsym.algebra.number_fields import AlgebraicConstants
            sage: AlgebraicConstants([sqrt(2)]).symbol()
            alpha_K
        """
        return self._symbol

    def value(self):
        r"""The exact value of the generator (positive), a symbolic
        expression; ``None`` when trivial.

        EXAMPLES::

            sage: from sage_dynsym.algebra.number_fields import AlgebraicConstants
            sage: AlgebraicConstants([cos(pi/7)]).value()
            cos(1/7*pi)
        """
        return self._value

    def forward(self, expr):
        r"""``expr`` with its algebraic constants written in the generator's
        symbol.

        EXAMPLES::

            sage: from sage_dynsym.algebra.number_fields import AlgebraicConstants
            sage: K = AlgebraicConstants([cos(pi/7)])
            sage: K.forward(cos(pi/7)^3)
            alpha_K^3
        """
        return _replace(expr, self._forward).expand() if self._forward else SR(expr)

    def back(self, expr):
        r"""``expr`` with the generator's symbol replaced by its value.

        EXAMPLES::

            sage: from sage_dynsym.algebra.number_fields import AlgebraicConstants
            sage: K = AlgebraicConstants([sqrt(2)])
            sage: K.back(K.symbol()^2 + 1)
            3
        """
        return SR(expr).subs({self._symbol: self._value}) if self._forward else SR(expr)
