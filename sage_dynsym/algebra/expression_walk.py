r"""
The walk over symbolic expressions that every translation into polynomials shares

Symbolic expressions become polynomials (or fractions) in sines and cosines
in one algebra (:class:`~sage_dynsym.algebra.trigonometric.TrigPolynomialRing`,
the parent :class:`~sage_dynsym.algebra.trig_algebra.TrigAlgebra`), whoever
asks: the kinematics, the simplification, the linear algebra over
trigonometric fractions, the translation of equations into polynomial systems
(:class:`~sage_dynsym.algebra.translation.Translation`). Its scans and its
conversion read an expression this way:

- a sum, a product, an integer power: the arithmetic of the target;
- a symbol, a number: a generator or a coefficient of the target;
- a trigonometric function (`\sin, \cos, \tan, \cot, \sec, \csc`): a
  generator, or an expansion by the addition formulas
  (:func:`split_angle`, :func:`angle_sum`, :func:`trig_value`);
- anything else (`\pi`, `\sqrt 2`, `e^{x}`, `D[0](f)(u)`, a power with a
  fractional exponent): an *atom*, which a target takes as an independent
  generator or refuses with the package's exception.

:class:`ExpressionWalker` is that reading, written once; a target says what
each case gives by overriding its methods (``symbol``, ``number``,
``atom``, ``trig``, ...).

EXAMPLES: the symbols, angles and atoms of an expression (every part
valued `1`)::

    sage: from sage_dynsym.algebra.expression_walk import ExpressionWalker
    sage: class Parts(ExpressionWalker):
    ....:     def __init__(self):
    ....:         self.found = []
    ....:     def symbol(self, e):
    ....:         self.found.append(('symbol', e)); return 1
    ....:     def number(self, e):
    ....:         return 1
    ....:     def atom(self, e):
    ....:         self.found.append(('atom', e)); return 1
    ....:     def trig(self, op, e):
    ....:         self.found.append((op.name(), e.operands()[0])); return 1
    sage: x, m = var('x m')
    sage: P = Parts(); P.walk(m*x^2*cos(2*x) + sqrt(2)/m)
    2
    sage: sorted(P.found, key=str)
    [('atom', sqrt(2)), ('cos', 2*x), ('symbol', m), ('symbol', m), ('symbol', x)]
"""
from functools import reduce
import operator

from sage.functions.trig import sin, cos, tan, cot, sec, csc
from sage.rings.integer_ring import ZZ
from sage.symbolic.operators import add_vararg, mul_vararg
from sage.symbolic.ring import SR

from ..errors import AnalysisError

__all__ = ['ExpressionWalker', 'ExpressionScan', 'TRIGONOMETRIC', 'MAX_ANGLE_MULTIPLE',
           'integer_exponent', 'split_angle', 'angle_sum', 'trig_value']

#: The trigonometric functions the walk recognises.
TRIGONOMETRIC = (sin, cos, tan, cot, sec, csc)

#: The largest integer multiple `k q` of an angle that is expanded by the
#: multiple-angle formulas (higher multiples are refused rather than
#: producing huge polynomials).
MAX_ANGLE_MULTIPLE = 24


def integer_exponent(exponent):
    r"""
    The exponent of a power as a Python integer, or ``None`` if it is not an
    integer.

    EXAMPLES::

        sage: from sage_dynsym.algebra.expression_walk import integer_exponent
        sage: integer_exponent(SR(-2)), integer_exponent(SR(1/2)), integer_exponent(var('n'))
        (-2, None, None)
    """
    if exponent.is_numeric() and exponent.pyobject() in ZZ:
        return int(ZZ(exponent.pyobject()))
    return None


class ExpressionWalker:
    r"""
    The reading of a symbolic expression shared by the translations into
    polynomials (see the module documentation): :meth:`walk` dispatches on
    the operator of each node, the methods below say what a node gives.

    A subclass overrides :meth:`symbol`, :meth:`number` and :meth:`atom`
    (refuse or register), and, as needed, :meth:`known` (generators looked
    up whole), :meth:`trig`, :meth:`takes_power`, :meth:`operands` and the arithmetic
    :meth:`add`, :meth:`mul`, :meth:`power`. By default the arithmetic is
    that of the values (``sum``, product, ``**``) and a trigonometric
    function that is not expanded is an atom.

    EXAMPLES: a walker that evaluates at numbers (symbols have values,
    atoms are refused)::

        sage: from sage_dynsym.algebra.expression_walk import ExpressionWalker
        sage: class At(ExpressionWalker):
        ....:     def __init__(self, values):
        ....:         self.values = values
        ....:     def symbol(self, e):
        ....:         return self.values[e]
        ....:     def number(self, e):
        ....:         return QQ(e)
        ....:     def atom(self, e):
        ....:         raise ValueError(e)
        sage: x, y = var('x y')
        sage: At({x: 2, y: 3}).walk(x^2*y - 1/y)
        35/3
        sage: At({x: 2}).walk(sqrt(x))
        Traceback (most recent call last):
        ...
        ValueError: sqrt(x)
    """

    def walk(self, e):
        r"""
        The value of the symbolic expression ``e`` for this walker.

        EXAMPLES: see the class documentation.
        """
        e = SR(e)
        value = self.known(e)
        if value is not None:
            return value
        op = e.operator()
        if op is None:
            if e.is_symbol():
                return self.symbol(e)
            if e.is_numeric():
                return self.number(e)
            return self.atom(e)       # constants: pi, e, ...
        if op is add_vararg:
            return self.add([self.walk(x) for x in self.operands(e)])
        if op is mul_vararg:
            return self.mul([self.walk(x) for x in self.operands(e)])
        if op is operator.pow:
            base, exponent = e.operands()
            k = integer_exponent(exponent)
            if k is not None and self.takes_power(k):
                return self.power(self.walk(base), k)
            return self.atom(e)
        if op in TRIGONOMETRIC:
            return self.trig(op, e)
        return self.atom(e)

    def operands(self, e):
        r"""The terms of a sum or the factors of a product ``e``, in the
        order they are walked (default: Sage's).

        EXAMPLES::

            sage: from sage_dynsym.algebra.expression_walk import ExpressionWalker
            sage: ExpressionWalker().operands(var('x')*var('y'))
            [x, y]
        """
        return e.operands()

    def known(self, e):
        r"""The value of ``e`` if it is a generator looked up whole, else
        ``None`` (default: nothing is).

        EXAMPLES::

            sage: from sage_dynsym.algebra.expression_walk import ExpressionWalker
            sage: ExpressionWalker().known(var('x')) is None
            True
        """
        return None

    def symbol(self, e):
        r"""The value of the symbol ``e`` (to be overridden).

        EXAMPLES::

            sage: from sage_dynsym.algebra.expression_walk import ExpressionWalker
            sage: ExpressionWalker().symbol(var('x'))
            Traceback (most recent call last):
            ...
            NotImplementedError: ExpressionWalker reads no symbol
        """
        raise NotImplementedError(f"{type(self).__name__} reads no symbol")

    def number(self, e):
        r"""The value of the number ``e`` (to be overridden).

        EXAMPLES::

            sage: from sage_dynsym.algebra.expression_walk import ExpressionWalker
            sage: ExpressionWalker().number(SR(2))
            Traceback (most recent call last):
            ...
            NotImplementedError: ExpressionWalker reads no number
        """
        raise NotImplementedError(f"{type(self).__name__} reads no number")

    def atom(self, e):
        r"""The value of an atom ``e`` (to be overridden): register it as a
        generator, or refuse it.

        EXAMPLES::

            sage: from sage_dynsym.algebra.expression_walk import ExpressionWalker
            sage: ExpressionWalker().atom(pi)
            Traceback (most recent call last):
            ...
            NotImplementedError: ExpressionWalker reads no atom
        """
        raise NotImplementedError(f"{type(self).__name__} reads no atom")

    def trig(self, op, e):
        r"""The value of ``e = op(argument)``, a trigonometric function
        (default: an atom).

        EXAMPLES::

            sage: from sage_dynsym.algebra.expression_walk import ExpressionWalker
            sage: class Atoms(ExpressionWalker):
            ....:     def atom(self, e):
            ....:         return e
            sage: Atoms().trig(sin, sin(var('x')))
            sin(x)
        """
        return self.atom(e)

    def takes_power(self, k):
        r"""Whether integer powers of exponent ``k`` are arithmetic (default:
        all); otherwise the power is an atom.

        EXAMPLES::

            sage: from sage_dynsym.algebra.expression_walk import ExpressionWalker
            sage: ExpressionWalker().takes_power(-1)
            True
        """
        return True

    def add(self, values):
        r"""The sum of ``values`` (a nonempty list).

        EXAMPLES::

            sage: from sage_dynsym.algebra.expression_walk import ExpressionWalker
            sage: ExpressionWalker().add([1, 2, 3]), ExpressionWalker().mul([2, 3, 4])
            (6, 24)
        """
        return reduce(operator.add, values)

    def mul(self, values):
        r"""The product of ``values`` (a nonempty list).

        EXAMPLES: see :meth:`add`.
        """
        return reduce(operator.mul, values)

    def power(self, value, k):
        r"""``value`` to the integer power ``k``.

        EXAMPLES::

            sage: from sage_dynsym.algebra.expression_walk import ExpressionWalker
            sage: ExpressionWalker().power(QQ(2), -2)
            1/4
        """
        return value ** k


class ExpressionScan(ExpressionWalker):
    r"""
    A walk that only registers what it meets (the first pass of a
    translation): the arithmetic gives ``None``.

    EXAMPLES::

        sage: from sage_dynsym.algebra.expression_walk import ExpressionScan
        sage: class Symbols(ExpressionScan):
        ....:     def __init__(self):
        ....:         self.found = set()
        ....:     def symbol(self, e):
        ....:         self.found.add(e)
        ....:     def number(self, e):
        ....:         pass
        ....:     def atom(self, e):
        ....:         pass
        sage: S = Symbols(); S.walk(var('x')^2*var('y') + sqrt(2)); sorted(S.found, key=str)
        [x, y]
    """

    def add(self, values):
        r"""Nothing: a scan computes no value.

        EXAMPLES::

            sage: from sage_dynsym.algebra.expression_walk import ExpressionScan
            sage: ExpressionScan().add([None, None]) is None
            True
        """
        return None

    mul = add

    def power(self, value, k):
        r"""Nothing: a scan computes no value.

        EXAMPLES::

            sage: from sage_dynsym.algebra.expression_walk import ExpressionScan
            sage: ExpressionScan().power(None, 2) is None
            True
        """
        return None


def split_angle(op, argument, is_angle, refuse=AnalysisError):
    r"""
    ``argument`` written as `\sum_j k_j q_j + r`: integer multiples of the
    angles `q_j` (the symbols for which ``is_angle`` is true) and a rest `r`
    free of them.

    INPUT:

    - ``op`` -- the trigonometric function applied to ``argument`` (named
      in the messages)
    - ``argument`` -- a symbolic expression
    - ``is_angle`` -- a predicate on symbols
    - ``refuse`` -- the exception class raised when ``argument`` is not of
      that form (a multiple that is not an integer, or above
      :data:`MAX_ANGLE_MULTIPLE`, or an angle left in the rest)

    OUTPUT: a pair ``(multiples, rest)``, ``multiples`` a list of pairs
    ``(q, k)``

    EXAMPLES::

        sage: from sage_dynsym.algebra.expression_walk import split_angle
        sage: q, r, a = var('q r a')
        sage: split_angle(sin, 2*q - r + a, lambda v: v in (q, r))
        ([(q, 2), (r, -1)], a)
        sage: split_angle(sin, q/2, lambda v: v == q)
        Traceback (most recent call last):
        ...
        AnalysisError: sin(1/2*q)
        sage: split_angle(cos, 30*q, lambda v: v == q)
        Traceback (most recent call last):
        ...
        AnalysisError: cos(30*q) (multiples of an angle above 24 are not expanded)
    """
    multiples, rest = [], argument
    for v in argument.variables():
        if not is_angle(v):
            continue
        k = argument.diff(v)
        if not k.is_numeric() or k.pyobject() not in ZZ:
            raise refuse(str(op(argument)))
        k = ZZ(k.pyobject())
        if abs(k) > MAX_ANGLE_MULTIPLE:
            raise refuse(f"{op(argument)} (multiples of an angle above "
                         f"{MAX_ANGLE_MULTIPLE} are not expanded)")
        multiples.append((v, k))
        rest = rest - k * v
    rest = rest.expand()
    if any(is_angle(v) for v in rest.variables()):
        raise refuse(str(op(argument)))
    return multiples, rest


def angle_sum(C, S, multiples, pair):
    r"""
    `(\cos, \sin)` of `r + \sum_j k_j q_j` by the addition formulas, from
    ``(C, S)`` the cosine and sine of `r` and ``pair(q)`` those of each
    angle, in whatever arithmetic they are given.

    EXAMPLES::

        sage: from sage_dynsym.algebra.expression_walk import angle_sum
        sage: q = var('q')
        sage: [e.expand() for e in angle_sum(SR(1), SR(0), [(q, -2)], lambda v: (cos(v), sin(v)))]
        [cos(q)^2 - sin(q)^2, -2*cos(q)*sin(q)]
    """
    for v, k in multiples:
        c, s = pair(v)
        if k < 0:
            s, k = -s, -k
        for _ in range(k):
            C, S = C * c - S * s, S * c + C * s
    return C, S


def trig_value(op, C, S, one=1, divide=operator.truediv):
    r"""
    The trigonometric function ``op`` of an angle whose cosine and sine are
    ``C`` and ``S``, in an arithmetic whose one is ``one`` and quotient
    ``divide``.

    EXAMPLES::

        sage: from sage_dynsym.algebra.expression_walk import trig_value
        sage: [trig_value(f, QQ(3/5), QQ(4/5)) for f in (sin, cos, tan, cot, sec, csc)]
        [4/5, 3/5, 4/3, 3/4, 5/3, 5/4]

    With fractions written as pairs ``(numerator, denominator)``::

        sage: def divide(x, y):
        ....:     return x[0]*y[1], x[1]*y[0]
        sage: trig_value(sec, (3, 5), (4, 5), one=(1, 1), divide=divide)
        (5, 3)
    """
    if op is sin:
        return S
    if op is cos:
        return C
    return {tan: lambda: divide(S, C), cot: lambda: divide(C, S), sec: lambda: divide(one, C),
            csc: lambda: divide(one, S)}[op]()
