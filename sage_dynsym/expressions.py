r"""
Symbols, safe parsing and time derivatives

sage_dynsym works with plain symbolic variables: a generalized coordinate
``q`` has the velocity symbol ``dq`` and the acceleration symbol ``ddq``;
time is the variable ``t``. Total time derivatives of expressions in
``q, dq, t`` are taken with :func:`time_derivative`.

Expressions given as text (description files, widgets) are parsed with
Sage's symbolic-expression parser restricted to declared names and a fixed
list of mathematical functions: nothing is ever evaluated as Python.

EXAMPLES::

    sage: from sage_dynsym.expressions import (velocity, acceleration,
    ....:     time_derivative, ExpressionParser)
    sage: theta = var('theta')
    sage: velocity(theta), acceleration(theta)
    (dtheta, ddtheta)
    sage: latex(velocity(theta))
    {\dot{\theta}}
    sage: time_derivative(sin(theta), [theta])
    dtheta*cos(theta)

    sage: P = ExpressionParser(['m', 'l', 'theta'])
    sage: P.parse("m*l^2*sin(theta)^2")
    l^2*m*sin(theta)^2
    sage: P.parse("m*x")
    Traceback (most recent call last):
    ...
    ExpressionError: undeclared symbol 'x' in 'm*x'; declared symbols are: l, m, t, theta
"""
import numbers
from fractions import Fraction

from sage.misc.latex import latex
from sage.misc.parser import Parser
from sage.symbolic.ring import SR
from sage.symbolic.function_factory import function as symbolic_function
from sage.rings.integer import Integer
from sage.rings.rational_field import QQ
from sage.functions import all as sage_functions
from sage.symbolic.constants import pi, e as euler_e, I as imaginary_unit

from .errors import ExpressionError

#: The time variable shared by every model.
t = SR.var('t')

ALLOWED_FUNCTIONS = {
    name: getattr(sage_functions, name)
    for name in ('sin', 'cos', 'tan', 'cot', 'sec', 'csc',
                 'arcsin', 'arccos', 'arctan', 'arctan2',
                 'sinh', 'cosh', 'tanh', 'exp', 'log', 'sqrt', 'abs_symbolic')
}
ALLOWED_FUNCTIONS.update(asin=ALLOWED_FUNCTIONS['arcsin'],
                         acos=ALLOWED_FUNCTIONS['arccos'],
                         atan=ALLOWED_FUNCTIONS['arctan'],
                         atan2=ALLOWED_FUNCTIONS['arctan2'],
                         abs=ALLOWED_FUNCTIONS['abs_symbolic'])
del ALLOWED_FUNCTIONS['abs_symbolic']

CONSTANTS = {'pi': pi, 'e': euler_e, 'I': imaginary_unit}


def _exact_decimal(text):
    return QQ(Fraction(text))


def _latex_base(name):
    return latex(SR.var(name))


def velocity(q):
    r"""
    Return the velocity symbol ``d<q>`` of the coordinate ``q``.

    INPUT:

    - ``q`` -- a symbolic variable (or its name)

    OUTPUT: a symbolic variable whose LaTeX form is `\dot q`

    EXAMPLES::

        sage: from sage_dynsym.expressions import velocity
        sage: velocity(var('psi')), latex(velocity('psi'))
        (dpsi, {\dot{\psi}})
    """
    name = str(q)
    return SR.var('d' + name, latex_name=r'\dot{%s}' % _latex_base(name))


def acceleration(q):
    r"""
    Return the acceleration symbol ``dd<q>`` of the coordinate ``q``.

    EXAMPLES::

        sage: from sage_dynsym.expressions import acceleration
        sage: acceleration(var('x')), latex(acceleration('x'))
        (ddx, {\ddot{x}})
    """
    name = str(q)
    return SR.var('dd' + name, latex_name=r'\ddot{%s}' % _latex_base(name))


def momentum(q):
    r"""
    Return the momentum symbol ``p_<q>`` conjugate to ``q``.

    EXAMPLES::

        sage: from sage_dynsym.expressions import momentum
        sage: momentum(var('theta')), latex(momentum('theta'))
        (p_theta, {p_{\theta}})
    """
    name = str(q)
    return SR.var('p_' + name, latex_name=r'p_{%s}' % _latex_base(name))


def time_derivative(expr, coordinates, velocities=None, accelerations=None):
    r"""
    Total time derivative of ``expr`` along a motion.

    ``expr`` is an expression in the coordinates ``q``, their velocities
    ``dq`` and time ``t``; the result is
    `\partial_t f + \sum_i (\partial_{q_i} f)\, dq_i + \sum_i
    (\partial_{dq_i} f)\, ddq_i`.

    INPUT:

    - ``expr`` -- a symbolic expression
    - ``coordinates`` -- list of coordinate symbols
    - ``velocities``, ``accelerations`` -- (default: the ``d``/``dd``
      symbols of the coordinates)

    EXAMPLES::

        sage: from sage_dynsym.expressions import time_derivative
        sage: x, dx, t = var('x dx t')
        sage: time_derivative(x^2*dx + t*x, [x])
        ddx*x^2 + (2*dx*x + t)*dx + x
    """
    if velocities is None:
        velocities = [velocity(q) for q in coordinates]
    if accelerations is None:
        accelerations = [acceleration(q) for q in coordinates]
    expr = SR(expr)
    result = expr.diff(t)
    for q, dq, ddq in zip(coordinates, velocities, accelerations):
        result += expr.diff(q) * dq + expr.diff(dq) * ddq
    return result


class ExpressionParser:
    r"""
    A parser of expression strings restricted to declared symbols.

    INPUT:

    - ``symbols`` -- iterable of names (strings) or symbolic variables that
      may appear; ``t`` is always allowed
    - ``functions`` -- (optional) iterable of names of *unknown* functions
      allowed in expressions (they become ``function(name)``)

    Allowed functions: ``sin cos tan cot sec csc arcsin arccos arctan
    arctan2 sinh cosh tanh exp log sqrt abs`` (and ``asin acos atan atan2``);
    constants ``pi``, ``e``, ``I``. Integers and decimals are read exactly
    (``0.5`` becomes ``1/2``) so that results stay exact.

    EXAMPLES::

        sage: from sage_dynsym.expressions import ExpressionParser
        sage: P = ExpressionParser(['g', 'u'], functions=['f1'])
        sage: P.parse("0.5*g*u^2 + f1(u)")
        1/2*g*u^2 + f1(u)
        sage: P.parse("__import__('os').system('ls')")
        Traceback (most recent call last):
        ...
        ExpressionError: unknown function '__import__' in "__import__('os').system('ls')"; allowed functions are: ...

    TESTS::

        sage: P.parse("sin(")
        Traceback (most recent call last):
        ...
        ExpressionError: malformed expression 'sin(': ...
        sage: P.parse(3)
        3
        sage: P.parse([1])
        Traceback (most recent call last):
        ...
        ExpressionError: expected an expression (a string or a number), got list [1]
    """

    def __init__(self, symbols, functions=()):
        self._symbols = {str(s): SR.var(str(s)) for s in symbols}
        self._symbols.setdefault('t', t)
        self._functions = dict(ALLOWED_FUNCTIONS)
        for name in functions:
            self._functions[str(name)] = symbolic_function(str(name))
        self._current = None
        self._parser = Parser(make_int=Integer,
                              make_float=_exact_decimal,
                              make_var=self._lookup_var,
                              make_function=self._lookup_function)

    def symbols(self):
        r"""
        Names that may appear in expressions.

        EXAMPLES::

            sage: from sage_dynsym.expressions import ExpressionParser
            sage: ExpressionParser(['b', 'a']).symbols()
            ['a', 'b', 't']
        """
        return sorted(self._symbols)

    def _lookup_var(self, name):
        if name in self._symbols:
            return self._symbols[name]
        if name in CONSTANTS:
            return CONSTANTS[name]
        raise ExpressionError(
            f"undeclared symbol {name!r} in {self._current!r}; declared "
            f"symbols are: {', '.join(sorted(self._symbols))}")

    def _lookup_function(self, name):
        if name in self._functions:
            return self._functions[name]
        raise ExpressionError(
            f"unknown function {name!r} in {self._current!r}; allowed "
            f"functions are: {', '.join(sorted(self._functions))}")

    def parse(self, text, entry=None):
        r"""
        Parse ``text`` into a symbolic expression.

        INPUT:

        - ``text`` -- a string, or a number (returned as an exact constant)
        - ``entry`` -- (optional) the entry name used in error messages

        EXAMPLES::

            sage: from sage_dynsym.expressions import ExpressionParser
            sage: ExpressionParser(['m']).parse("m/2 + 1e-1")
            1/2*m + 1/10
            sage: ExpressionParser(['m']).parse("m +* 2", entry="mass")
            Traceback (most recent call last):
            ...
            ExpressionError: mass: malformed expression 'm +* 2': ...
        """
        if isinstance(text, bool) or not isinstance(text, (str, numbers.Real)):
            raise ExpressionError(
                "expected an expression (a string or a number), got "
                f"{type(text).__name__} {text!r}", entry=entry)
        if isinstance(text, numbers.Rational):
            return SR(QQ(text))
        if isinstance(text, numbers.Real):
            return SR(_exact_decimal(repr(float(text))))
        self._current = text
        try:
            return SR(self._parser.parse_expression(text))
        except ExpressionError as err:
            raise err.with_context(entry=entry)
        except Exception as err:  # the parser raises SyntaxError/TypeError/...
            raise ExpressionError(f"malformed expression {text!r}: {err}",
                                  entry=entry) from None
        finally:
            self._current = None
