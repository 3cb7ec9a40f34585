r"""
Symbolic expressions written as straight-line code (Python or C)

:func:`write_code` walks the expression trees of Sage's symbolic ring once
and writes them as assignments in Python (``math`` functions) or C
(``math.h``): a subexpression used more than once is computed once into a
temporary (common subexpression elimination), quotients are written as
quotients, small integer powers as products. The text is the package's
own: numbers are written as floating-point literals, functions come from a
fixed table and symbol names are used only when they are plain
identifiers, so the code can be compiled or run without evaluating any
text a user wrote.

EXAMPLES::

    sage: from sage_dynsym.numerics.expressions import write_code
    sage: x, y = var('x y')
    sage: temps, results = write_code([sin(x*y) + x*y, 1/(1 + x^2)], {x: 'x', y: 'y'})
    sage: temps, results
    ([('_e0', 'x*y')], ['_e0 + math.sin(_e0)', '1.0/(x**2 + 1.0)'])
    sage: write_code([(x + y)^3/y], {x: 'x', y: 'y'}, language='c')
    ([('_e0', 'x + y')], ['_e0*_e0*_e0/y'])
"""
import builtins
import keyword
import operator
import re

from sage.symbolic.operators import add_vararg, mul_vararg
from sage.symbolic.ring import SR

from ..errors import AnalysisError

__all__ = ['FUNCTIONS', 'C_KEYWORDS', 'MATH_H_NAMES', 'is_reserved', 'identifier', 'StructuralKey',
           'real_constant', 'function_name', 'write_code', 'symbols_and_functions',
           'linear_coefficients']

#: Sage's function names -> (Python ``math`` name, C ``math.h`` name).
FUNCTIONS = {
    'sin': ('math.sin', 'sin'), 'cos': ('math.cos', 'cos'), 'tan': ('math.tan', 'tan'),
    'exp': ('math.exp', 'exp'), 'log': ('math.log', 'log'), 'abs': ('abs', 'fabs'),
    'sinh': ('math.sinh', 'sinh'), 'cosh': ('math.cosh', 'cosh'),
    'tanh': ('math.tanh', 'tanh'), 'arcsin': ('math.asin', 'asin'),
    'arccos': ('math.acos', 'acos'), 'arctan': ('math.atan', 'atan'),
    'arctan2': ('math.atan2', 'atan2'), 'arcsinh': ('math.asinh', 'asinh'),
    'arccosh': ('math.acosh', 'acosh'), 'arctanh': ('math.atanh', 'atanh'),
}

_IDENTIFIER = re.compile(r'[A-Za-z][A-Za-z0-9_]*\Z')

#: The keywords of C (up to C23) and of common extensions.
C_KEYWORDS = frozenset("""
    auto break case char const continue default do double else enum extern float for goto if
    inline int long register restrict return short signed sizeof static struct switch typedef
    union unsigned void volatile while alignas alignof bool constexpr false nullptr
    static_assert thread_local true typeof typeof_unqual asm fortran complex imaginary
    """.split())

_MATH_FUNCTIONS = """
    acos acosh asin asinh atan atan2 atanh cbrt ceil copysign cos cosh erf erfc exp exp2 expm1
    fabs fdim floor fma fmax fmin fmod frexp hypot ilogb ldexp lgamma llrint llround log log10
    log1p log2 logb lrint lround modf nan nearbyint nextafter nexttoward pow remainder remquo
    rint round scalbln scalbn sin sinh sqrt tan tanh tgamma trunc j0 j1 jn y0 y1 yn gamma drem
    finite significand scalb exp10 pow10 sincos lgamma_r gamma_r roundeven fmaximum fminimum
    """.split()
#: The names ``<math.h>`` defines (C99 to C23 and glibc): its functions with
#: their ``f`` and ``l`` variants, its macros and types. A symbol of one of
#: these names would be replaced by the preprocessor or clash with the
#: library, and the generated C would not compile or would compute something
#: else. Names of the forms ``M_*``, ``FP_*`` and ``HUGE_VAL*`` are reserved
#: too (:func:`is_reserved`).
MATH_H_NAMES = frozenset(
    _MATH_FUNCTIONS + [f + suffix for f in _MATH_FUNCTIONS for suffix in ('f', 'l')]
    + """NAN INFINITY HUGE_VAL HUGE_VALF HUGE_VALL MAXFLOAT DOMAIN SING OVERFLOW UNDERFLOW
    TLOSS PLOSS X_TLOSS MATH_ERRNO MATH_ERREXCEPT math_errhandling signgam float_t double_t
    isnan isinf isfinite isnormal signbit fpclassify isgreater isgreaterequal isless
    islessequal islessgreater isunordered iseqsig issignaling issubnormal iszero iscanonical
    errno""".split())
_RESERVED_PATTERN = re.compile(r'(M|FP)_\w*\Z|HUGE_VAL\w*\Z')

#: Names the generated code cannot give to a symbol: the C keywords and the
#: names of ``<math.h>``, the Python keywords and builtins, the modules the
#: code uses (``math``, ``numpy``), the package's own C functions, and ``E``.
_RESERVED = (set(keyword.kwlist) | set(dir(builtins)) | C_KEYWORDS | MATH_H_NAMES
             | {'math', 'numpy', 'np', 'main', 'free', 'malloc', 'dynsym_rhs', 'dynsym_solve',
                'E'})
for _python, _c in FUNCTIONS.values():
    _RESERVED.add(_c)


def is_reserved(name):
    r"""
    Whether ``name`` is reserved in the generated code (C or Python), so
    that a symbol of that name is renamed there.

    EXAMPLES::

        sage: from sage_dynsym.numerics.expressions import is_reserved
        sage: [is_reserved(n) for n in ('M_PI', 'NAN', 'int', 'lambda', 'sum', 'x', 'R1')]
        [True, True, True, True, True, False, False]
    """
    return name in _RESERVED or bool(_RESERVED_PATTERN.match(name))


def identifier(symbol, index, taken=()):
    r"""
    The name of ``symbol`` in generated code: its own name when it is a
    plain identifier (letters, digits, underscores, not starting with an
    underscore) that is not reserved in C or Python (:func:`is_reserved`:
    keywords, the names of ``<math.h>`` such as ``M_PI`` or ``NAN``,
    builtins), else ``_s<index>``. So the C and the Python code accept the
    same models.

    EXAMPLES::

        sage: from sage_dynsym.numerics.expressions import identifier
        sage: identifier(var('psi1'), 0), identifier(SR.symbol('lambda'), 1), identifier(SR.symbol('a b'), 2)
        ('psi1', '_s1', '_s2')
        sage: identifier(var('M_PI'), 3), identifier(var('NAN'), 4)
        ('_s3', '_s4')
    """
    name = str(symbol)
    if _IDENTIFIER.match(name) and not is_reserved(name) and name not in taken:
        return name
    return f'_s{index}'


class StructuralKey:
    r"""
    A symbolic expression as a dictionary key, compared by structure
    (``==`` of Sage expressions builds an equation, not a truth value):
    shared subexpressions are found once when expressions are walked.

    EXAMPLES::

        sage: from sage_dynsym.numerics.expressions import StructuralKey
        sage: x = var('x')
        sage: seen = {StructuralKey(sin(x)^2): 1}
        sage: StructuralKey(sin(x)^2) in seen, StructuralKey(sin(x)*sin(x)) in seen
        (True, True)
        sage: StructuralKey(cos(x)) in seen
        False
    """
    __slots__ = ('expr', 'hash')

    def __init__(self, expr):
        self.expr = expr
        self.hash = hash(expr)

    def __hash__(self):
        return self.hash

    def __eq__(self, other):
        return self.expr.is_trivially_equal(other.expr)


def real_constant(e, entry, hint=""):
    r"""
    The constant expression ``e`` as a float; an
    :class:`~sage_dynsym.errors.AnalysisError` (on ``entry``, with
    ``hint`` appended) when it has no numerical value or is not real.

    EXAMPLES::

        sage: from sage_dynsym.numerics.expressions import real_constant
        sage: real_constant(sqrt(2)/2, 'code')
        0.7071067811865476
        sage: real_constant(I, 'code')
        Traceback (most recent call last):
        ...
        AnalysisError: code: the constant I is not real
        sage: f = function('f'); real_constant(f(1), 'map', hint='; give it a value')
        Traceback (most recent call last):
        ...
        AnalysisError: map: f(1) has no numerical value; give it a value
    """
    try:
        z = complex(e)
    except (TypeError, ValueError) as err:
        raise AnalysisError(f"{e} has no numerical value{hint}", entry=entry) from err
    if z.imag != 0:
        raise AnalysisError(f"the constant {e} is not real", entry=entry)
    return float(z.real)


def _literal(value):
    text = repr(float(value))
    if text in ('inf', '-inf', 'nan'):
        raise AnalysisError(f"the constant {text} has no numerical value", entry="code")
    return text


def function_name(op):
    r"""
    The name of the symbolic function ``op`` (``None`` for an operator
    without one).

    EXAMPLES::

        sage: from sage_dynsym.numerics.expressions import function_name
        sage: function_name(sin(var('x')).operator()), function_name(operator.add)
        ('sin', None)
    """
    try:
        return op.name()
    except AttributeError:
        return None


def write_code(expressions, names, language='python', entry='code', prefix='_e', cse=True):
    r"""
    Straight-line code for ``expressions``.

    INPUT:

    - ``expressions`` -- list of symbolic expressions
    - ``names`` -- dict: symbol -> its name in the code (every symbol of
      the expressions must have one)
    - ``language`` -- ``'python'`` (functions of ``math``) or ``'c'``
    - ``entry`` -- the name used in error messages
    - ``prefix`` -- prefix of the temporaries' names
    - ``cse`` -- (default: ``True``) compute repeated subexpressions once

    OUTPUT: ``(temporaries, results)``: the list of pairs ``(name, text)``
    to assign in this order, and the text of each expression

    Raises :class:`~sage_dynsym.errors.AnalysisError` for a symbol without
    a name, a function without a numerical counterpart and a complex
    constant.

    EXAMPLES::

        sage: from sage_dynsym.numerics.expressions import write_code
        sage: a, b = var('a b')
        sage: write_code([-a*b + cos(a)^2, sqrt(b)], {a: 'a', b: 'b'}, language='c')
        ([('_e0', 'cos(a)')], ['-a*b + _e0*_e0', 'sqrt(b)'])
        sage: write_code([(a + b)^2 + sin(a + b)], {a: 'a', b: 'b'}, cse=False)
        ([], ['(a + b)**2 + math.sin(a + b)'])

    TESTS::

        sage: write_code([a + b], {a: 'a'})
        Traceback (most recent call last):
        ...
        AnalysisError: code: no value for the symbol b
        sage: write_code([function('f')(a)], {a: 'a'})
        Traceback (most recent call last):
        ...
        AnalysisError: code: f(a) has no numerical value
        sage: write_code([I*a], {a: 'a'})
        Traceback (most recent call last):
        ...
        AnalysisError: code: the constant I is not real
    """
    if language not in ('python', 'c'):
        raise AnalysisError(f"language must be 'python' or 'c', got {language!r}", entry=entry)
    names = {StructuralKey(SR(k)): v for k, v in names.items()}
    exprs = [SR(e) for e in expressions]

    # pass 1: how often each compound subexpression is used
    uses = {}
    stack = list(exprs)
    while stack:
        e = stack.pop()
        if e.operator() is None:
            continue
        key = StructuralKey(e)
        uses[key] = uses.get(key, 0) + 1
        if uses[key] == 1:
            stack.extend(e.operands())

    writer = _CodeWriter(names, uses, language, entry, prefix, cse)
    results = [writer.render(e)[0] for e in exprs]
    return writer.temps, results


class _CodeWriter:
    """The state of :func:`write_code`: the symbols' names, how often each
    compound subexpression is used, and the temporaries written so far."""

    def __init__(self, names, uses, language, entry, prefix, cse):
        self.names, self.uses, self.entry = names, uses, entry
        self.python, self.prefix, self.cse = language == 'python', prefix, cse
        self.temps, self.done = [], {}

    def store(self, key, text):
        name = f'{self.prefix}{len(self.temps)}'
        self.temps.append((name, text))
        self.done[key] = (name, 3)
        return name, 3

    def atomic(self, e):
        """``e`` as a name or literal (stored in a temporary if compound)."""
        text, prec = self.render(e)
        if prec == 3 and re.match(r'[A-Za-z_0-9.]+\Z', text):
            return text
        key = StructuralKey(e)
        return self.done[key][0] if key in self.done else self.store(key, text)[0]

    def render(self, e):
        """``(text, precedence)``: 3 atom, 2 product, 1 sum or negative."""
        op = e.operator()
        if op is None:
            key = StructuralKey(e)
            if key in self.names:
                return self.names[key], 3
            if e.is_symbol():
                raise AnalysisError(f"no value for the symbol {e}", entry=self.entry)
            value = real_constant(e, self.entry)
            return _literal(value), (3 if value >= 0 else 1)
        key = StructuralKey(e)
        if key in self.done:
            return self.done[key]
        if not e.variables():
            value = real_constant(e, self.entry)
            return _literal(value), (3 if value >= 0 else 1)
        if op is add_vararg:
            item = self._sum(e.operands())
        elif op is mul_vararg:
            item = self._product(e.operands())
        elif op is operator.pow:
            item = self._power(*e.operands())
        elif function_name(op) in FUNCTIONS:
            function = FUNCTIONS[function_name(op)][0 if self.python else 1]
            item = f"{function}({', '.join(self.render(o)[0] for o in e.operands())})", 3
        else:
            raise AnalysisError(f"{e} has no numerical value", entry=self.entry)
        if self.cse and self.uses.get(key, 0) > 1:
            return self.store(key, item[0])
        return item

    def _signed(self, e):
        """``(negative, text, precedence)`` of a term of a sum."""
        if e.operator() is mul_vararg and StructuralKey(e) not in self.done and not (
                self.cse and self.uses.get(StructuralKey(e), 0) > 1):
            factors = e.operands()
            coefficient = [f for f in factors if f.operator() is None and f.is_numeric()]
            if coefficient and real_constant(coefficient[0], self.entry) < 0:
                rest = [f for f in factors if f is not coefficient[0]]
                c = -real_constant(coefficient[0], self.entry)
                text, prec = self._product(rest, c)
                return True, text, prec
        text, prec = self.render(e)
        if prec == 1 and text.startswith('-') and _is_number(text[1:]):
            return True, text[1:], 3
        return False, text, prec

    def _sum(self, terms):
        parts = []
        for e in terms:
            negative, text, prec = self._signed(e)
            text = text if prec >= 2 else f'({text})'
            if not parts:
                parts.append(f'-{text}' if negative else text)
            else:
                parts.append(f' - {text}' if negative else f' + {text}')
        return ''.join(parts), 1

    def _product(self, factors, coefficient=None):
        numerator, denominator = [], []
        if coefficient is None:
            rest = []
            for f in factors:
                if f.operator() is None and f.is_numeric():
                    value = real_constant(f, self.entry)
                    coefficient = value if coefficient is None else value * coefficient
                else:
                    rest.append(f)
            factors = rest
        for f in factors:
            if (f.operator() is operator.pow and StructuralKey(f) not in self.done and
                    not (self.cse and self.uses.get(StructuralKey(f), 0) > 1)):
                base, exponent = f.operands()
                if exponent.is_numeric() and exponent < 0:
                    denominator.append(self._power(base, -exponent))
                    continue
            numerator.append(self.render(f))
        negative = coefficient is not None and coefficient < 0
        if coefficient is not None and abs(coefficient) != 1:
            numerator.insert(0, (_literal(abs(coefficient)), 3))
        text = '*'.join(_wrap(item, 2) for item in numerator) or '1.0'
        if denominator:
            below = '*'.join(_wrap(item, 2) for item in denominator)
            text += '/' + (_wrap(denominator[0], 3) if len(denominator) == 1 else f'({below})')
        if negative:
            return f'-{text}', 1
        return text, (2 if len(numerator) + len(denominator) > 1 or denominator else
                      numerator[0][1])

    def _power(self, base, exponent):
        if exponent.is_integer():
            n = int(exponent)
            if n < 0:
                text, prec = self._power(base, -exponent)
                return '1.0/' + (text if prec == 3 else f'({text})'), 2
            if n == 1:
                return self.render(base)
            if self.python:
                return f'{_wrap(self.render(base), 3)}**{n}', 3
            if n <= 4:
                return '*'.join([self.atomic(base)] * n), 2
            return f'pow({self.render(base)[0]}, {n}.0)', 3
        if exponent.is_numeric() and exponent == SR(1) / 2:
            return f"{'math.sqrt' if self.python else 'sqrt'}({self.render(base)[0]})", 3
        if exponent.is_numeric() and exponent == -SR(1) / 2:
            return f"1.0/{'math.sqrt' if self.python else 'sqrt'}({self.render(base)[0]})", 2
        if self.python:
            return f'{_wrap(self.render(base), 3)}**{_wrap(self.render(exponent), 3)}', 3
        return f'pow({self.render(base)[0]}, {self.render(exponent)[0]})', 3


def _wrap(item, level):
    text, prec = item
    return text if prec >= level else f'({text})'


def _is_number(text):
    try:
        float(text)
    except ValueError:
        return False
    return True


def symbols_and_functions(expressions):
    r"""
    The symbols and the unspecified functions of ``expressions``, found by
    one walk that visits every distinct subexpression once (large equations
    of motion share their subexpressions many times over).

    OUTPUT: two dicts, name -> symbol and name -> ``(function, arity)``

    EXAMPLES::

        sage: from sage_dynsym.numerics.expressions import symbols_and_functions
        sage: x, y = var('x y'); f = function('f')
        sage: symbols_and_functions([x*f(x, y) + diff(f(x, y), x), sin(y)])
        ({'x': x, 'y': y}, {'f': (f, 2)})
    """
    symbols, functions, seen = {}, {}, set()
    stack = [SR(e) for e in expressions]
    while stack:
        e = stack.pop()
        key = StructuralKey(e)
        if key in seen:
            continue
        seen.add(key)
        op = e.operator()
        if op is None:
            if e.is_symbol():
                symbols[str(e)] = e
            continue
        kind = type(op).__name__
        if kind == 'NewSymbolicFunction':
            functions[op.name()] = (op, len(e.operands()))
        elif kind == 'FDerivativeOperator':
            functions.setdefault(op.function().name(), (op.function(), len(e.operands())))
        stack.extend(e.operands())
    return dict(sorted(symbols.items())), dict(sorted(functions.items()))


def linear_coefficients(expression, unknowns):
    r"""
    ``expression`` as `\sum_j c_j u_j + r` in the symbols ``unknowns``
    `u_j`, read off its terms without differentiating or substituting (a
    walk that visits every distinct subexpression once): the dict
    `u_j \mapsto c_j` (nonzero ones) and `r`; ``None`` when a term is not a
    product of one unknown with factors free of them.

    EXAMPLES::

        sage: from sage_dynsym.numerics.expressions import linear_coefficients
        sage: a, b, x, y = var('a b x y')
        sage: linear_coefficients(a*sin(b)*x + x + b*y + cos(a), [x, y])
        ({x: a*sin(b) + 1, y: b}, cos(a))
        sage: linear_coefficients(x^2 + y, [x, y]) is None, linear_coefficients(x*sin(y), [x, y]) is None
        (True, True)
    """
    unknowns = [SR(u) for u in unknowns]
    targets = {StructuralKey(u) for u in unknowns}
    memo = {}

    def mentions(e):
        # post-order walk with a memo: does e contain an unknown?
        stack = [(e, False)]
        while stack:
            node, expanded = stack.pop()
            key = StructuralKey(node)
            if key in memo:
                continue
            if key in targets:
                memo[key] = True
            elif node.operator() is None:
                memo[key] = False
            elif expanded:
                memo[key] = any(memo[StructuralKey(o)] for o in node.operands())
            else:
                stack.append((node, True))
                stack.extend((o, False) for o in node.operands())
        return memo[StructuralKey(e)]

    expression = SR(expression)
    terms = expression.operands() if expression.operator() is add_vararg else [expression]
    coefficients, rest = {}, []
    for term in terms:
        if not mentions(term):
            rest.append(term)
            continue
        if StructuralKey(term) in targets:
            unknown, factor = term, SR(1)
        elif term.operator() is mul_vararg:
            hits = [f for f in term.operands() if StructuralKey(f) in targets]
            others = [f for f in term.operands() if StructuralKey(f) not in targets]
            if len(hits) != 1 or any(mentions(f) for f in others):
                return None
            unknown, factor = hits[0], SR(1).mul(*others) if others else SR(1)
        else:
            return None
        coefficients.setdefault(StructuralKey(unknown), []).append(factor)
    out = {}
    for u in unknowns:
        if StructuralKey(u) in coefficients:
            out[u] = SR(0).add(*coefficients[StructuralKey(u)])
    return out, SR(0).add(*rest)
