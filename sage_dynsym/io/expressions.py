r"""
The safe expression parser

Expressions given as text (description files, widgets) are parsed with
Sage's symbolic-expression parser restricted to declared names and the
fixed list of mathematical functions of :mod:`sage_dynsym.symbols`:
nothing is ever evaluated as Python. Before Sage sees the text, its size is
checked against documented limits (length, nesting depth, digits, exponents
and towers of powers), so hostile input cannot exhaust time or memory.

EXAMPLES::

    sage: from sage_dynsym.io.expressions import ExpressionParser
    sage: P = ExpressionParser(['m', 'l', 'theta'])
    sage: P.parse("m*l^2*sin(theta)^2")
    l^2*m*sin(theta)^2
    sage: P.parse("m*x")
    Traceback (most recent call last):
    ...
    ExpressionError: undeclared symbol 'x' in 'm*x'; declared symbols are: l, m, t, theta
"""
import math
import numbers
import re
from fractions import Fraction

from sage.misc.parser import Parser
from sage.symbolic.ring import SR
from sage.symbolic.function_factory import function as symbolic_function
from sage.rings.integer import Integer
from sage.rings.rational_field import QQ

from ..errors import ExpressionError, brief
from ..symbols import t, ALLOWED_FUNCTIONS, CONSTANTS

__all__ = ['MAX_EXPRESSION_LENGTH', 'MAX_NESTING_DEPTH', 'MAX_INTEGER_DIGITS',
           'MAX_DECIMAL_EXPONENT', 'MAX_EXPONENT', 'MAX_POWER_TOWER', 'MAX_NUMBER_DIGITS',
           'MAX_DEGREE', 'check_expression_text', 'ExpressionParser']

def _exact_decimal(text):
    return QQ(Fraction(text))


# ----------------------------------------------------------------------
# size limits, checked on the text before Sage's parser sees it

#: Longest expression text (characters) of a description entry.
MAX_EXPRESSION_LENGTH = 10_000
#: Deepest nesting of parentheses, function calls, signs and powers.
MAX_NESTING_DEPTH = 100
#: Most digits in one number written in an expression (``123``, ``1.25``).
MAX_INTEGER_DIGITS = 1000
#: Largest decimal exponent of a number such as ``1.5e-7`` (in absolute value).
MAX_DECIMAL_EXPONENT = 1000
#: Largest number (numerator and denominator) in an exponent: ``x^1000``.
MAX_EXPONENT = 1000
#: Highest exponent tower: ``a^b^c^d`` is a tower of height 3.
MAX_POWER_TOWER = 3
#: Most digits of any number the expression evaluates while being read
#: (``2^1000`` has 302 digits, ``9^9^9`` about 369 million).
MAX_NUMBER_DIGITS = 10_000
#: Largest effective degree of a power: ``(x^100)^200`` has degree 20,000.
MAX_DEGREE = 10_000

_LOG10_2 = math.log10(2)

_TOKEN = re.compile(r"""
    (?P<space>\s+)
  | (?P<number>(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?)
  | (?P<name>[^\W\d]\w*)
  | (?P<op>\*\*|[-+*/^(),])
""", re.VERBOSE)

#: arities of the parser's functions (default 1)
_ARITY = {'atan2': (2, 2), 'arctan2': (2, 2), 'log': (1, 2)}


def _quote(text, limit=80):
    r"""
    ``repr`` of ``text``, shortened to about ``limit`` characters (error
    messages must stay short whatever the input).

    EXAMPLES::

        sage: from sage_dynsym.io.expressions import _quote
        sage: _quote("m*l^2"), _quote("x" * 1000)
        ("'m*l^2'", "'xxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx...' (1000 characters)")
    """
    if len(text) <= limit:
        return repr(text)
    return f"{text[:limit - 12]!r}"[:-1] + f"...' ({len(text)} characters)"


def _digits(value):
    # decimal digits of the height max(|numerator|, denominator) of a rational
    height = max(abs(value.numerator), value.denominator)
    return max(1.0, height.bit_length() * _LOG10_2)


class _Size:
    r"""
    What the checker knows about a subexpression: its exact value if it is a
    rational number (``value``), else a bound on the digits of the numbers
    inside (``digits``), on the effective degree and on the power tower.
    """
    __slots__ = ('value', 'digits', 'degree', 'tower')

    def __init__(self, value=None, digits=1.0, degree=0, tower=0):
        self.value, self.digits, self.degree, self.tower = value, digits, degree, tower


class _Checker:
    r"""
    A recursive-descent pass over the tokens with the grammar of Sage's
    parser (``sage.misc.parser``): ``expr = term (('+'|'-') term)*``,
    ``term = factor (('*'|'/'|implicit before a name) factor)*``,
    ``factor = ('+'|'-')* power``, ``power = atom ('^' factor)?``,
    ``atom = number | name | name '(' args ')' | '(' expr ')'``. It computes
    nothing big: numbers are followed exactly only while they stay within
    the limits, which are checked before each step.
    """

    def __init__(self, parser, text):
        self.parser, self.text = parser, text
        self.tokens = []
        for match in _TOKEN.finditer(text):
            kind = match.lastgroup
            if kind != 'space':
                value = '^' if match.group() == '**' else match.group()
                self.tokens.append((kind, value, match.start()))
        self.tokens.append(('end', '', len(text)))
        self.pos = 0
        self.depth = 0

    def error(self, message):
        raise ExpressionError(f"malformed expression {_quote(self.text)}: {message}")

    def limit(self, message):
        raise ExpressionError(f"{message} in {_quote(self.text)}")

    def peek(self):
        return self.tokens[self.pos]

    def take(self):
        token = self.tokens[self.pos]
        self.pos += 1
        return token

    def expect(self, op):
        kind, value, where = self.take()
        if value != op or kind != 'op':
            self.unexpected((kind, value, where), f"expected {op!r}")

    def unexpected(self, token, what=None):
        kind, value, where = token
        found = "end of text" if kind == 'end' else repr(value)
        self.error(f"{what + ', found' if what else 'unexpected'} {found} at position {where}")

    def enter(self):
        self.depth += 1
        if self.depth > MAX_NESTING_DEPTH:
            self.limit(f"nesting deeper than {MAX_NESTING_DEPTH} levels (parentheses, function "
                       "calls, signs and powers; MAX_NESTING_DEPTH)")

    def run(self):
        size = self.expr()
        if self.peek()[0] != 'end':
            self.unexpected(self.peek())
        return size

    # -- grammar --------------------------------------------------------

    def expr(self):
        left = self.term()
        while self.peek()[1] in ('+', '-') and self.peek()[0] == 'op':
            op = self.take()[1]
            left = self.combine(op, left, self.term())
        return left

    def term(self):
        left = self.factor()
        while True:
            kind, value, _ = self.peek()
            if kind == 'op' and value in ('*', '/'):
                self.take()
                op = value
            elif kind == 'name':          # implicit multiplication, as in Sage
                op = '*'
            else:
                return left
            left = self.combine(op, left, self.factor())

    def factor(self):
        outer, signs = self.depth, 0
        while self.peek()[0] == 'op' and self.peek()[1] in ('+', '-'):
            signs += self.take()[1] == '-'
            self.enter()
        base = self.atom()
        if self.peek()[0] == 'op' and self.peek()[1] == '^':
            self.take()
            self.enter()
            base = self.power(base, self.factor())
        self.depth = outer
        if signs % 2 and base.value is not None:
            base = _Size(-base.value, base.digits)
        return base

    def atom(self):
        token = self.take()
        kind, value, _ = token
        if kind == 'number':
            return self.number(value)
        if kind == 'name':
            if self.peek()[1] == '(' and self.peek()[0] == 'op':
                return self.call(value)
            self.parser._lookup_var(value)          # undeclared names fail here
            return _Size(digits=0.0, degree=0 if value in CONSTANTS else 1)
        if kind == 'op' and value == '(':
            self.enter()
            inner = self.expr()
            self.expect(')')
            self.depth -= 1
            return inner
        self.unexpected(token)

    def call(self, name):
        self.parser._lookup_function(name)          # unknown functions fail here
        self.take()
        self.enter()
        args = []
        if not (self.peek()[0] == 'op' and self.peek()[1] == ')'):
            args.append(self.expr())
            while self.peek()[0] == 'op' and self.peek()[1] == ',':
                self.take()
                args.append(self.expr())
        self.expect(')')
        self.depth -= 1
        low, high = _ARITY.get(name, (1, 1) if name in ALLOWED_FUNCTIONS else (1, None))
        if len(args) < low or (high is not None and len(args) > high):
            wanted = f"{low}" if low == high else f"{low} to {high}" if high else f"at least {low}"
            self.error(f"{name} takes {wanted} argument{'s' if high != 1 else ''}, "
                       f"got {len(args)}")
        return _Size(digits=max(a.digits for a in args), degree=1,
                     tower=max(a.tower for a in args))

    def number(self, text):
        mantissa, _, exponent = text.lower().partition('e')
        digits = len(mantissa.replace('.', '').lstrip('0'))
        if digits > MAX_INTEGER_DIGITS:
            self.limit(f"a number with {digits} digits (at most {MAX_INTEGER_DIGITS}; "
                       "MAX_INTEGER_DIGITS)")
        if exponent and abs(int(exponent)) > MAX_DECIMAL_EXPONENT:
            self.limit(f"the decimal exponent {exponent} (at most {MAX_DECIMAL_EXPONENT} in "
                       "absolute value; MAX_DECIMAL_EXPONENT)")
        value = Fraction(text)
        return _Size(value, _digits(value))

    # -- arithmetic on sizes ----------------------------------------------

    def check_digits(self, digits):
        if digits > MAX_NUMBER_DIGITS:
            self.limit(f"a number with about {digits:.3g} digits (at most {MAX_NUMBER_DIGITS}; "
                       "MAX_NUMBER_DIGITS)")

    def combine(self, op, a, b):
        if a.value is not None and b.value is not None:
            self.check_digits(a.digits + b.digits + 1)
            if op == '+':
                value = a.value + b.value
            elif op == '-':
                value = a.value - b.value
            elif op == '*':
                value = a.value * b.value
            elif b.value == 0:
                self.limit("division by zero")
            else:
                value = a.value / b.value
            return _Size(value, _digits(value))
        if op == '/' and b.value == 0:
            self.limit("division by zero")
        additive = op in ('+', '-')
        # like terms merge: a sum at most doubles a coefficient
        digits = max(a.digits, b.digits) + _LOG10_2 if additive else a.digits + b.digits
        self.check_digits(digits)
        degree = max(a.degree, b.degree) if additive else a.degree + b.degree
        return _Size(digits=digits, degree=degree, tower=max(a.tower, b.tower))

    def power(self, base, exponent):
        tower = max(base.tower, exponent.tower + 1)
        if tower > MAX_POWER_TOWER:
            self.limit(f"an exponent tower of height {tower} (at most {MAX_POWER_TOWER}; "
                       "MAX_POWER_TOWER)")
        if exponent.value is None:
            # a symbolic exponent: the numbers in it are exponents too
            if exponent.digits > math.log10(MAX_EXPONENT) + 1:
                self.limit(f"numbers of about {exponent.digits:.3g} digits in an exponent "
                           f"(numbers in exponents are at most {MAX_EXPONENT}; MAX_EXPONENT)")
            return _Size(digits=max(base.digits, exponent.digits), degree=1, tower=tower)
        e = exponent.value
        if max(abs(e.numerator), e.denominator) > MAX_EXPONENT:
            self.limit(f"the exponent {_quote(str(e), 40)} (numbers in exponents are at most "
                       f"{MAX_EXPONENT}; MAX_EXPONENT)")
        magnitude = math.ceil(abs(e))
        digits = base.digits * max(1, magnitude)
        self.check_digits(digits)
        degree = base.degree * magnitude
        if degree > MAX_DEGREE:
            self.limit(f"a power of degree {degree} (at most {MAX_DEGREE}; MAX_DEGREE)")
        if base.value is not None and e.denominator == 1:
            if base.value == 0 and e < 0:
                self.limit("division by zero")
            value = base.value ** int(e)
            return _Size(value, _digits(value))
        return _Size(digits=digits, degree=degree, tower=tower)


def check_expression_text(text, parser, max_length=MAX_EXPRESSION_LENGTH):
    r"""
    Check an expression text against the size limits of this module before
    it is parsed; raise :class:`~sage_dynsym.errors.ExpressionError` naming
    the limit that is exceeded.

    The limits are module constants: :data:`MAX_EXPRESSION_LENGTH`
    (characters), :data:`MAX_NESTING_DEPTH`, :data:`MAX_INTEGER_DIGITS`
    (digits of one written number), :data:`MAX_DECIMAL_EXPONENT`,
    :data:`MAX_EXPONENT` (numbers in an exponent), :data:`MAX_POWER_TOWER`,
    :data:`MAX_NUMBER_DIGITS` (any number computed while reading) and
    :data:`MAX_DEGREE`. Only the characters of expressions are accepted:
    numbers, names, ``+ - * / ^ ** ( ) ,`` and blanks.

    INPUT:

    - ``text`` -- a string
    - ``parser`` -- the :class:`ExpressionParser` whose names apply
    - ``max_length`` -- (default: :data:`MAX_EXPRESSION_LENGTH`)

    EXAMPLES::

        sage: from sage_dynsym.io.expressions import ExpressionParser, check_expression_text
        sage: P = ExpressionParser(['m', 'x'])
        sage: check_expression_text("m*x^2 + 3^(10^10)*m", P)
        Traceback (most recent call last):
        ...
        ExpressionError: the exponent '10000000000' (numbers in exponents are at most 1000; MAX_EXPONENT) in 'm*x^2 + 3^(10^10)*m'
        sage: check_expression_text("9^9^9", P)
        Traceback (most recent call last):
        ...
        ExpressionError: the exponent '387420489' (numbers in exponents are at most 1000; MAX_EXPONENT) in '9^9^9'
        sage: check_expression_text("m*1e-999999999", P)
        Traceback (most recent call last):
        ...
        ExpressionError: the decimal exponent -999999999 (at most 1000 in absolute value; MAX_DECIMAL_EXPONENT) in 'm*1e-999999999'
        sage: check_expression_text("(" * 200 + "m" + ")" * 200, P)
        Traceback (most recent call last):
        ...
        ExpressionError: nesting deeper than 100 levels (parentheses, function calls, signs and powers; MAX_NESTING_DEPTH) in '((((((...' (401 characters)
        sage: check_expression_text("x^x^x^x^x", P)
        Traceback (most recent call last):
        ...
        ExpressionError: an exponent tower of height 4 (at most 3; MAX_POWER_TOWER) in 'x^x^x^x^x'
        sage: check_expression_text("m!", P)
        Traceback (most recent call last):
        ...
        ExpressionError: the character '!' at position 1 is not allowed in an expression (numbers, names, + - * / ^ ** ( ) , and blanks)
        sage: check_expression_text("2^1000*x + (x^10)^100", P)    # within the limits
    """
    if len(text) > max_length:
        raise ExpressionError(f"an expression of {len(text)} characters (at most {max_length}; "
                              "MAX_EXPRESSION_LENGTH)")
    current, parser._current = parser._current, text      # for the parser's messages
    try:
        _check_text(text, parser)
    finally:
        parser._current = current


def _check_text(text, parser):
    position = 0
    for match in _TOKEN.finditer(text):
        if match.start() != position:
            break
        position = match.end()
    if position != len(text):
        # names before the bad character first: a call of an unknown
        # function says so rather than complaining about its quotes
        checker = _Checker(parser, text[:position])
        for k, (kind, value, _) in enumerate(checker.tokens):
            if kind == 'name':
                following = checker.tokens[k + 1][1]
                if following == '(':
                    parser._lookup_function(value)
                else:
                    parser._lookup_var(value)
        bad = text[position]
        raise ExpressionError(f"the character {bad!r} at position {position} is not allowed "
                              "in an expression (numbers, names, + - * / ^ ** ( ) , and blanks)")
    # a cheap scan first: deep parentheses never reach the recursive pass
    depth = deepest = 0
    for ch in text:
        if ch == '(':
            depth += 1
            deepest = max(deepest, depth)
        elif ch == ')':
            depth -= 1
    if deepest > MAX_NESTING_DEPTH:
        raise ExpressionError(f"nesting deeper than {MAX_NESTING_DEPTH} levels (parentheses, "
                              f"function calls, signs and powers; MAX_NESTING_DEPTH) in "
                              f"{_quote(text, 20)}")
    _Checker(parser, text).run()


def _check_finite(expr, text):
    # log(0), tan(pi/2), atan2(0, 0): Sage returns infinities or NaN
    stack, seen = [expr], 0
    while stack:
        e = stack.pop()
        seen += 1
        if e.operator() is None:
            if e.is_infinity() or (not e.is_symbol() and str(e) in ('NaN', 'undefined')):
                raise ExpressionError(f"the expression {_quote(text)} is not a finite "
                                      f"value (it contains {e})")
        elif seen < 100000:
            stack.extend(e.operands())


class ExpressionParser:
    r"""
    A parser of expression strings restricted to declared symbols.

    INPUT:

    - ``symbols`` -- iterable of names (strings) or symbolic variables that
      may appear; ``t`` is always allowed
    - ``functions`` -- (optional) iterable of names of *unknown* functions
      allowed in expressions (they become ``function(name)``)
    - ``refused`` -- (optional) a mapping ``{name: reason}`` of names that
      must not appear, with the reason given in the error
    - ``max_length`` -- (default: :data:`MAX_EXPRESSION_LENGTH`) the longest
      text accepted

    Allowed functions: ``sin cos tan cot sec csc arcsin arccos arctan
    arctan2 sinh cosh tanh exp log sqrt abs`` (and ``asin acos atan atan2``);
    constants ``pi``, ``e``, ``I``. Integers and decimals are read exactly
    (``0.5`` becomes ``1/2``) so that results stay exact. The text is
    checked against the size limits of this module
    (:func:`check_expression_text`) before Sage's parser reads it, and the
    value must be finite.

    EXAMPLES::

        sage: from sage_dynsym.io.expressions import ExpressionParser
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
        ExpressionError: malformed expression 'sin(': unexpected end of text at position 4
        sage: P.parse(3)
        3
        sage: P.parse([1])
        Traceback (most recent call last):
        ...
        ExpressionError: expected an expression (a string or a number), got list [1]
        sage: P.parse(float('inf'), entry='mass')
        Traceback (most recent call last):
        ...
        ExpressionError: mass: expected a finite number, got inf
        sage: P.parse("g + log(0)")
        Traceback (most recent call last):
        ...
        ExpressionError: the expression 'g + log(0)' is not a finite value (it contains -Infinity)
        sage: P.parse("atan2(0, 0)")
        Traceback (most recent call last):
        ...
        ExpressionError: the expression 'atan2(0, 0)' is not a finite value (it contains NaN)
        sage: P.parse("g/(u - u)")
        Traceback (most recent call last):
        ...
        ExpressionError: malformed expression 'g/(u - u)': symbolic division by zero
        sage: P.parse("sin(g, u)")
        Traceback (most recent call last):
        ...
        ExpressionError: malformed expression 'sin(g, u)': sin takes 1 argument, got 2
        sage: ExpressionParser(['x'], refused={'dx': "the velocity dx cannot appear here"}).parse("dx")
        Traceback (most recent call last):
        ...
        ExpressionError: the velocity dx cannot appear here (in 'dx')
        sage: P.parse(10**2000)
        Traceback (most recent call last):
        ...
        ExpressionError: a number with about 2e+03 digits (at most 1000; MAX_INTEGER_DIGITS)
    """

    def __init__(self, symbols, functions=(), refused=None, max_length=MAX_EXPRESSION_LENGTH):
        self._symbols = {}
        for s in symbols:
            try:
                self._symbols[str(s)] = SR.var(str(s))
            except ValueError as err:
                raise ExpressionError(f"{str(s)!r} cannot be a symbol name ({err})") from err
        self._symbols.setdefault('t', t)
        self._functions = dict(ALLOWED_FUNCTIONS)
        for name in functions:
            self._functions[str(name)] = symbolic_function(str(name))
        self._refused = dict(refused or {})
        self._max_length = max_length
        self._current = None
        self._parser = Parser(make_int=Integer,
                              make_float=_exact_decimal,
                              make_var=self._lookup_var,
                              make_function=self._lookup_function)

    def symbols(self):
        r"""
        Names that may appear in expressions.

        EXAMPLES::

            sage: from sage_dynsym.io.expressions import ExpressionParser
            sage: ExpressionParser(['b', 'a']).symbols()
            ['a', 'b', 't']
        """
        return sorted(self._symbols)

    def _lookup_var(self, name):
        if name in self._symbols:
            return self._symbols[name]
        if name in self._refused:
            raise ExpressionError(f"{self._refused[name]} (in {_quote(self._current)})")
        if name in CONSTANTS:
            return CONSTANTS[name]
        raise ExpressionError(
            f"undeclared symbol {name!r} in {_quote(self._current)}; declared "
            f"symbols are: {', '.join(sorted(self._symbols))}")

    def _lookup_function(self, name):
        if name in self._functions:
            return self._functions[name]
        raise ExpressionError(
            f"unknown function {name!r} in {_quote(self._current)}; allowed "
            f"functions are: {', '.join(sorted(self._functions))}")

    def _number(self, value, entry):
        if isinstance(value, numbers.Rational):
            value = QQ(value)
            height = max(abs(int(value.numerator())), int(value.denominator()))
            digits = height.bit_length() * _LOG10_2
            if digits > MAX_INTEGER_DIGITS:
                raise ExpressionError(f"a number with about {digits:.3g} digits (at most "
                                      f"{MAX_INTEGER_DIGITS}; MAX_INTEGER_DIGITS)", entry=entry)
            return SR(value)
        value = float(value)
        if not math.isfinite(value):
            raise ExpressionError(f"expected a finite number, got {value}", entry=entry)
        return SR(_exact_decimal(repr(value)))

    def parse(self, text, entry=None):
        r"""
        Parse ``text`` into a symbolic expression.

        INPUT:

        - ``text`` -- a string, or a number (returned as an exact constant)
        - ``entry`` -- (optional) the entry name used in error messages

        EXAMPLES::

            sage: from sage_dynsym.io.expressions import ExpressionParser
            sage: ExpressionParser(['m']).parse("m/2 + 1e-1")
            1/2*m + 1/10
            sage: ExpressionParser(['m']).parse("m +* 2", entry="mass")
            Traceback (most recent call last):
            ...
            ExpressionError: mass: malformed expression 'm +* 2': unexpected '*' at position 3
        """
        if isinstance(text, bool) or not isinstance(text, (str, numbers.Real)):
            raise ExpressionError(
                "expected an expression (a string or a number), got "
                f"{type(text).__name__} {brief(text)}", entry=entry)
        if not isinstance(text, str):
            return self._number(text, entry)
        self._current = text
        try:
            check_expression_text(text, self, self._max_length)
            result = SR(self._parser.parse_expression(text))
            _check_finite(result, text)
            return result
        except ExpressionError as err:
            raise err.with_context(entry=entry) from err
        except Exception as err:  # the parser raises SyntaxError/TypeError/ValueError/...
            raise ExpressionError(f"malformed expression {_quote(text)}: {err}",
                                  entry=entry) from err
        finally:
            self._current = None
