r"""
Typed arguments of the public functions

The public functions and methods check their arguments with these helpers
before they compute or allocate anything, so that a wrong type or an
impossible value is an error of the package naming the argument and the
value (never a traceback from inside Python, NumPy or Sage, never a silent
coercion):

- :func:`count` -- an integer count (a number of samples or points, a
  degree, a seed): Python, NumPy or Sage integers only, never a ``bool``,
  a ``float`` (``points=2.9`` is not 2 samples) or a string, and at most a
  limit that the caller can raise;
- :func:`finite_real` -- a finite real number (Python, NumPy or Sage
  numbers, constant expressions such as ``pi``), never a string, a
  ``bool``, ``nan`` or an infinity;
- :func:`flag` -- ``True`` or ``False``;
- :func:`known_symbols` -- symbols (or their names) that must be among the
  valid ones, listed in the message when one is not;
- :func:`check_declared_signs` -- values given for parameters declared
  positive must be positive;
- :func:`expression_argument`, :func:`expression_list`,
  :func:`matrix_argument` -- a symbolic expression, a list of them, a
  matrix (never a string, which is not parsed here);
- :func:`model_argument` -- an object of the kind a function works on
  (a Lagrangian, a model, an equations record), recognised by its methods;
- :func:`count_option` -- :func:`count` for a command-line option.

The module loads no Sage (it imports Sage's symbolic ring only when a
value needs it), so the command lines check their options before Sage is
loaded; it sits just above :mod:`sage_dynsym.errors` in the layers of the
package.

EXAMPLES::

    sage: from sage_dynsym.arguments import count, finite_real, known_symbols
    sage: count(5, 'points', minimum=2)
    5
    sage: count(float(2.9), 'points', minimum=2)
    Traceback (most recent call last):
    ...
    ModelError: points: expected an integer, got 2.9 (float)
    sage: finite_real(pi, 't_end')
    3.141592653589793
    sage: x, y = var('x y')
    sage: known_symbols(['x', y], [x, y], 'solve_for')
    [x, y]
"""
import argparse
import math
import numbers

from .errors import DynSymError, ModelError, brief

__all__ = ['is_integer', 'count', 'finite_real', 'flag', 'choice', 'known_symbols',
           'symbol_arguments', 'expression_argument', 'expression_list', 'matrix_argument',
           'model_argument', 'check_declared_signs', 'count_option']


def _shown(value):
    r"""``value`` for a message: a Python builtin with its type (``'7' (str)``,
    ``2.9 (float)``), anything else as it prints."""
    if value is None or type(value) in (str, bytes, bool, float, complex, list, tuple, dict):
        return f"{brief(value)} ({type(value).__name__})"
    return brief(value)


def is_integer(value):
    r"""
    Whether ``value`` is an integer of Python, NumPy or Sage (a ``bool`` is
    not).

    EXAMPLES::

        sage: from sage_dynsym.arguments import is_integer
        sage: import numpy as np
        sage: is_integer(3), is_integer(int(3)), is_integer(np.int64(3))
        (True, True, True)
        sage: is_integer(True), is_integer(3.0), is_integer('3'), is_integer(3/1)
        (False, False, False, False)
    """
    return isinstance(value, numbers.Integral) and not isinstance(value, bool)


def count(value, name, minimum=1, maximum=None, error=ModelError, entry=None, what=None,
          raise_with=None):
    r"""
    ``value`` as a Python ``int``, checked to be an integer between
    ``minimum`` and ``maximum``.

    INPUT:

    - ``value`` -- the argument
    - ``name`` -- its name, for the message
    - ``minimum`` -- (default: 1) the smallest value allowed
    - ``maximum`` -- (optional) the largest value allowed (a size limit)
    - ``error`` -- (default: :class:`~sage_dynsym.errors.ModelError`) the
      class of the error raised
    - ``entry`` -- (default: ``name``) the entry named by the error
    - ``what`` -- (optional) what is counted, e.g. ``"samples"``
    - ``raise_with`` -- (optional) how to raise ``maximum``, e.g.
      ``"max_points="``

    EXAMPLES::

        sage: from sage_dynsym.arguments import count
        sage: count(3, 'degree'), count(int(0), 'seed', minimum=0)
        (3, 0)

    TESTS::

        sage: count(True, 'degree')
        Traceback (most recent call last):
        ...
        ModelError: degree: expected an integer, got True (bool)
        sage: count('7', 'points')
        Traceback (most recent call last):
        ...
        ModelError: points: expected an integer, got '7' (str)
        sage: count(1, 'points', minimum=2, what='samples')
        Traceback (most recent call last):
        ...
        ModelError: points: expected at least 2 samples, got 1
        sage: count(10^9, 'points', maximum=10^6, what='samples', raise_with='max_points=')
        Traceback (most recent call last):
        ...
        ModelError: points: 1000000000 samples are more than the limit of 1000000; raise it with max_points= if that is what you want
    """
    entry = name if entry is None else entry
    if not is_integer(value):
        raise error(f"expected an integer, got {_shown(value)}", entry=entry)
    value = int(value)
    noun = f" {what}" if what else ""
    if value < minimum:
        raise error(f"expected at least {minimum}{noun}, got {value}", entry=entry)
    if maximum is not None and value > maximum:
        hint = f"; raise it with {raise_with} if that is what you want" if raise_with else ""
        raise error(f"{value}{noun} {'are' if what else 'is'} more than the limit of "
                    f"{maximum}{hint}", entry=entry)
    return value


def finite_real(value, name, entry=None, error=ModelError, minimum=None, strict=False):
    r"""
    ``value`` as a finite Python ``float``.

    INPUT:

    - ``value`` -- a Python, NumPy or Sage number, or a constant symbolic
      expression (``pi``, ``sqrt(2)``); not a string, a ``bool``, ``nan``,
      an infinity or a complex number
    - ``name`` -- the name of the quantity, for the message
    - ``entry`` -- (default: ``name``) the entry named by the error
    - ``error`` -- (default: :class:`~sage_dynsym.errors.ModelError`) the
      class of the error raised
    - ``minimum`` -- (optional) a lower bound: ``value >= minimum``, or
      ``value > minimum`` with ``strict=True``

    EXAMPLES::

        sage: from sage_dynsym.arguments import finite_real
        sage: finite_real(pi, 'a'), finite_real(3/4, 'b'), finite_real(int(2), 'c')
        (3.141592653589793, 0.75, 2.0)

    TESTS::

        sage: finite_real(float('nan'), 'x', entry='initial')
        Traceback (most recent call last):
        ...
        ModelError: initial: the value of x must be a finite real number, got nan
        sage: finite_real(oo, 'k', entry='values')
        Traceback (most recent call last):
        ...
        ModelError: values: the value of k must be a finite real number, got +Infinity
        sage: finite_real('1', 't0')
        Traceback (most recent call last):
        ...
        ModelError: t0: the value of t0 must be a real number, got '1' (str)
        sage: finite_real(True, 't_end')
        Traceback (most recent call last):
        ...
        ModelError: t_end: the value of t_end must be a real number, got True (bool)
        sage: finite_real(var('x'), 'g'), finite_real(I, 'g')
        Traceback (most recent call last):
        ...
        ModelError: g: the value of g must be a real number, got x
        sage: finite_real(-1, 'rtol', minimum=0, strict=True)
        Traceback (most recent call last):
        ...
        ModelError: rtol: the value of rtol must be greater than 0, got -1
    """
    entry = name if entry is None else entry
    number = None
    if not isinstance(value, (str, bytes, bool)) and value is not None:
        if isinstance(value, numbers.Real):
            number = complex(float(value))
        else:
            try:
                from sage.symbolic.ring import SR
                number = complex(SR(value))
            except (TypeError, ValueError, ArithmeticError):
                number = None
    if number is None or number.imag != 0:
        shown = _shown(value) if isinstance(value, (str, bytes, bool)) or value is None \
            else brief(value)
        raise error(f"the value of {name} must be a real number, got {shown}", entry=entry)
    if not math.isfinite(number.real):
        raise error(f"the value of {name} must be a finite real number, got {value}",
                    entry=entry)
    number = float(number.real)
    if minimum is not None and (number < minimum or (strict and number == minimum)):
        raise error(f"the value of {name} must be {'greater than' if strict else 'at least'} "
                    f"{minimum}, got {value}", entry=entry)
    return number


def flag(value, name, error=ModelError, entry=None):
    r"""
    ``value`` if it is ``True`` or ``False`` (an option that is a yes or a
    no; a string such as ``'no'`` is not taken as true).

    EXAMPLES::

        sage: from sage_dynsym.arguments import flag
        sage: flag(True, 'project')
        True
        sage: flag('no', 'project')
        Traceback (most recent call last):
        ...
        ModelError: project: expected True or False, got 'no'
    """
    if value is True or value is False:
        return value
    import numpy
    if isinstance(value, numpy.bool_):
        return bool(value)
    raise error(f"expected True or False, got {brief(value)}",
                entry=name if entry is None else entry)


def choice(value, choices, name, error=ModelError, entry=None):
    r"""
    ``value`` if it is one of the strings ``choices``, else an error listing
    them (also for values that are not strings, or cannot be hashed).

    EXAMPLES::

        sage: from sage_dynsym.arguments import choice
        sage: choice('c', ('python', 'c'), 'language')
        'c'
        sage: choice(['c'], ('python', 'c'), 'language')
        Traceback (most recent call last):
        ...
        ModelError: language: ['c'] is not one of python, c
    """
    if not isinstance(value, str) or value not in choices:
        raise error(f"{brief(value)} is not one of {', '.join(choices)}",
                    entry=name if entry is None else entry)
    return value


def _symbol_name(key):
    r"""The name of ``key`` (a string, or a symbolic variable), or ``None``
    for anything else (an expression, a number)."""
    if isinstance(key, str):
        return key
    is_symbol = getattr(key, 'is_symbol', None)
    if callable(is_symbol):
        try:
            return str(key) if is_symbol() else None
        except (TypeError, ValueError):
            return None
    return None


def known_symbols(keys, valid, name, error=ModelError, what="symbol", entry=None):
    r"""
    The symbols of ``valid`` named by ``keys`` (symbols or their names), in
    the order of ``keys``.

    INPUT:

    - ``keys`` -- an iterable of symbols or names (a single string is one
      name)
    - ``valid`` -- the list of the valid symbols
    - ``name`` -- the name of the argument, for the message
    - ``error`` -- (default: :class:`~sage_dynsym.errors.ModelError`) the
      class of the error raised
    - ``what`` -- (default: ``"symbol"``) what the valid symbols are, e.g.
      ``"unknown"``, ``"parameter"``
    - ``entry`` -- (default: ``name``) the entry named by the error

    EXAMPLES::

        sage: from sage_dynsym.arguments import known_symbols
        sage: a, b, x = var('a b x')
        sage: known_symbols([b, 'a'], [a, b], 'positive', what='parameter')
        [b, a]

    TESTS::

        sage: known_symbols([x], [a, b], 'solve_for', what='unknown')
        Traceback (most recent call last):
        ...
        ModelError: solve_for: x is not an unknown of the model; the unknowns are a, b
        sage: known_symbols(['not a name'], [a, b], 'positive', what='parameter')
        Traceback (most recent call last):
        ...
        ModelError: positive: 'not a name' is not a parameter of the model; the parameters are a, b
        sage: known_symbols([a + b], [a, b], 'positive')
        Traceback (most recent call last):
        ...
        ModelError: positive: a + b is not a symbol of the model; the symbols are a, b
        sage: known_symbols(3, [a], 'positive')
        Traceback (most recent call last):
        ...
        ModelError: positive: expected a list of symbols or names, got 3
    """
    entry = name if entry is None else entry
    if isinstance(keys, str):
        keys = [keys]
    try:
        keys = list(keys)
    except TypeError as err:
        raise error(f"expected a list of symbols or names, got {brief(keys)}",
                    entry=entry) from err
    by_name = {str(v): v for v in valid}
    found = []
    for key in keys:
        key_name = _symbol_name(key)
        if key_name is None or key_name not in by_name:
            shown = repr(key) if isinstance(key, str) else brief(key)
            article = 'an' if what[0] in 'aeiou' else 'a'
            listed = ', '.join(by_name) or '(none)'
            raise error(f"{shown} is not {article} {what} of the model; the {what}s are "
                        f"{listed}", entry=entry)
        found.append(by_name[key_name])
    return found


def symbol_arguments(values, name, error=ModelError, entry=None):
    r"""
    ``values`` (symbolic variables or their names) as a list of symbolic
    variables: a name must be an identifier, nothing else (an expression, a
    number, ``'not a name'``) is accepted.

    EXAMPLES::

        sage: from sage_dynsym.arguments import symbol_arguments
        sage: m = var('m')
        sage: symbol_arguments([m, 'g'], 'positive')
        [m, g]

    TESTS::

        sage: symbol_arguments(['not a name'], 'positive')
        Traceback (most recent call last):
        ...
        ModelError: positive: expected symbols or their names, got 'not a name'
        sage: symbol_arguments([m + 1], 'positive')
        Traceback (most recent call last):
        ...
        ModelError: positive: expected symbols or their names, got m + 1
        sage: symbol_arguments(m, 'positive')
        Traceback (most recent call last):
        ...
        ModelError: positive: expected a list of symbols or names, got m
    """
    from sage.symbolic.ring import SR
    entry = name if entry is None else entry
    items = None
    if not isinstance(values, str) and getattr(values, 'is_symbol', None) is None:
        try:
            items = list(values)
        except TypeError:
            pass
    if items is None:
        raise error(f"expected a list of symbols or names, got {brief(values)}", entry=entry)
    found = []
    for value in items:
        key = _symbol_name(value)
        if key is None or not key.isidentifier():
            raise error(f"expected symbols or their names, got "
                        f"{repr(value) if isinstance(value, str) else brief(value)}",
                        entry=entry)
        found.append(SR.var(key) if isinstance(value, str) else value)
    return found


def _refused(value, name, expected, error, entry, hint=None):
    return error(f"expected {expected}, got {_shown(value)}" + (f"; {hint}" if hint else ""),
                 entry=name if entry is None else entry)


_NOT_EXPRESSIONS = (str, bytes, bool, list, tuple, dict, set, type(None))


def expression_argument(value, name, error=ModelError, entry=None,
                        expected="a symbolic expression", hint=None):
    r"""
    ``value`` as a symbolic expression: numbers, symbolic expressions and
    polynomials are; ``None``, strings (user text goes through the safe
    parser, :mod:`sage_dynsym.io.expressions`), containers and objects
    that are not expressions (a model) are errors naming ``name``, saying
    what was ``expected`` and, with ``hint``, the call that works.

    EXAMPLES::

        sage: from sage_dynsym.arguments import expression_argument
        sage: expression_argument(3, 'poly'), expression_argument(QQ['x'].gen()^2, 'poly')
        (3, x^2)
        sage: expression_argument('x^2', 'poly', expected="a polynomial", hint="use var('x')")
        Traceback (most recent call last):
        ...
        ModelError: poly: expected a polynomial, got 'x^2' (str); use var('x')
        sage: expression_argument(None, 'expr')
        Traceback (most recent call last):
        ...
        ModelError: expr: expected a symbolic expression, got None (NoneType)
    """
    from sage.symbolic.ring import SR
    if not isinstance(value, _NOT_EXPRESSIONS):
        try:
            return SR(value)
        except (TypeError, ValueError, ArithmeticError):
            pass
    raise _refused(value, name, expected, error, entry, hint)


def expression_list(values, name, error=ModelError, entry=None,
                    expected="a list of symbolic expressions", hint=None, names=False):
    r"""
    ``values`` (a list, tuple, vector or other iterable that is not a
    string, a mapping or a single expression) as a list of symbolic
    expressions; anything else is an error as for
    :func:`expression_argument`. With ``names=True`` the items are
    unknowns or variables: symbols, their names, or values of functions
    such as ``f(x)``.

    EXAMPLES::

        sage: from sage_dynsym.arguments import expression_list
        sage: x = var('x')
        sage: expression_list((x, 1), 'equations')
        [x, 1]
        sage: expression_list(x, 'equations')
        Traceback (most recent call last):
        ...
        ModelError: equations: expected a list of symbolic expressions, got x
        sage: expression_list([x, None], 'equations')
        Traceback (most recent call last):
        ...
        ModelError: equations: expected a list of symbolic expressions, got [x, None] (list)
        sage: expression_list(['x', function('f')(x)], 'unknowns', names=True)
        [x, f(x)]
        sage: expression_list([x, 2], 'unknowns', names=True)
        Traceback (most recent call last):
        ...
        ModelError: unknowns: expected a list of symbolic expressions, got [x, 2] (list)
    """
    from sage.symbolic.ring import SR
    items = None
    if not isinstance(values, (str, bytes, dict)) and not hasattr(values, 'is_symbol'):
        try:
            items = list(values)
        except TypeError:
            items = None
    try:
        if items is not None:
            found = [SR.var(v) if names and isinstance(v, str) and v.isidentifier() else
                     expression_argument(v, name, error, entry) for v in items]
            if not names or all(_is_unknown(v) for v in found):
                return found
    except DynSymError:
        pass
    raise _refused(values, name, expected, error, entry, hint)


def _is_unknown(value):
    # a symbol, or the value of a function such as f(x)
    from sage.symbolic.function import Function
    return value.is_symbol() or isinstance(value.operator(), Function)


def matrix_argument(value, name, error=ModelError, entry=None, square=False,
                    expected=None, hint=None):
    r"""
    ``value`` (a Sage matrix, or a list of rows) as a matrix over the
    symbolic ring (``square=True``: a square one); anything else is an
    error naming ``name``.

    EXAMPLES::

        sage: from sage_dynsym.arguments import matrix_argument
        sage: matrix_argument([[1, 2], [3, 4]], 'K')
        [1 2]
        [3 4]
        sage: matrix_argument([[1, 2]], 'K', square=True)
        Traceback (most recent call last):
        ...
        ModelError: K: expected a square matrix, got a 1x2 matrix
        sage: matrix_argument('K', 'K')
        Traceback (most recent call last):
        ...
        ModelError: K: expected a matrix (or a list of rows), got 'K' (str)
    """
    from sage.matrix.constructor import matrix
    from sage.structure.element import Matrix
    from sage.symbolic.ring import SR
    expected = expected or f"a {'square ' if square else ''}matrix (or a list of rows)"
    M = None
    if isinstance(value, Matrix):
        M = value
    elif isinstance(value, (list, tuple)) and value and \
            all(isinstance(r, (list, tuple)) or hasattr(r, 'list') for r in value):
        try:
            M = matrix(SR, [list(r) for r in value])
        except (TypeError, ValueError, ArithmeticError):
            M = None
    if M is None:
        raise _refused(value, name, expected, error, entry, hint)
    if square and not M.is_square():
        raise error(f"expected a square matrix, got a {M.nrows()}x{M.ncols()} matrix",
                    entry=name if entry is None else entry)
    return M


def model_argument(value, methods, name, expected, error=ModelError, entry=None, hint=None):
    r"""
    ``value`` if it has the methods ``methods`` (names) -- how a function
    recognises the kind of object it works on (a Lagrangian, a model, a
    Lie--Poisson system) without asking for its class --, else an error
    naming ``name``, saying what was ``expected`` and, with ``hint``, the
    call that works.

    EXAMPLES::

        sage: from sage_dynsym.arguments import model_argument
        sage: from sage_dynsym import Lagrangian
        sage: L = Lagrangian(var('dx')^2/2, [var('x')])
        sage: model_argument(L, ['coordinates', 'routh'], 'lagrangian', "a Lagrangian") is L
        True
        sage: model_argument(42, ['coordinates'], 'lagrangian', "a Lagrangian",
        ....:                hint="build one with Lagrangian(expr, coordinates)")
        Traceback (most recent call last):
        ...
        ModelError: lagrangian: expected a Lagrangian, got 42; build one with Lagrangian(expr, coordinates)
    """
    if not all(callable(getattr(value, m, None)) for m in methods):
        raise _refused(value, name, expected, error, entry, hint)
    return value


def check_declared_signs(values, positive, name="values", error=ModelError):
    r"""
    Check that the numbers in ``values`` (a dict, symbols or names as keys)
    given for the parameters in ``positive`` (declared positive) are
    positive. Keys that are not declared positive, and values that are not
    numbers (expressions, function definitions), are not checked here.

    EXAMPLES::

        sage: from sage_dynsym.arguments import check_declared_signs
        sage: m, l, g = var('m l g')
        sage: check_declared_signs({m: 1, 'l': 2, g: -9.81}, [m, l])
        sage: check_declared_signs({m: 1, 'l': -2}, [m, l])
        Traceback (most recent call last):
        ...
        ModelError: values: l is declared positive, got -2
        sage: check_declared_signs({m: 0}, [m], name='fixed')
        Traceback (most recent call last):
        ...
        ModelError: fixed: m is declared positive, got 0
        sage: check_declared_signs({m: SR(-1)}, [m])
        Traceback (most recent call last):
        ...
        ModelError: values: m is declared positive, got -1
        sage: check_declared_signs({m: lambda x: x, l: -l}, [m, l])
    """
    declared = {str(p) for p in positive}
    if not declared or not isinstance(values, dict):
        return
    for key, value in values.items():
        key_name = _symbol_name(key)
        if key_name not in declared or isinstance(value, (str, bytes, bool)):
            continue
        try:        # a Sage number, callable as symbolic expressions are, counts
            number = finite_real(value, key_name)
        except ModelError:
            continue            # not a number: the caller's own checks say so
        if not number > 0:
            raise error(f"{key_name} is declared positive, got {value}", entry=name)


def count_option(text, minimum=1, maximum=None):
    r"""
    The integer of a command-line option (``argparse`` type): an integer
    of at least ``minimum`` (and at most ``maximum``), else
    ``argparse.ArgumentTypeError``.

    EXAMPLES::

        sage: from sage_dynsym.arguments import count_option
        sage: count_option('12')
        12
        sage: count_option('2.5')
        Traceback (most recent call last):
        ...
        ArgumentTypeError: expected a positive integer, got '2.5'
        sage: count_option('-1', minimum=0)
        Traceback (most recent call last):
        ...
        ArgumentTypeError: expected a non-negative integer, got '-1'
        sage: count_option('5000', maximum=1000)
        Traceback (most recent call last):
        ...
        ArgumentTypeError: expected an integer from 1 to 1000, got '5000'
    """
    try:
        value = int(text, 10)
    except (TypeError, ValueError):
        value = None
    if value is None or value < minimum or (maximum is not None and value > maximum):
        if maximum is not None:
            expected = f"an integer from {minimum} to {maximum}"
        else:
            expected = {0: "a non-negative integer", 1: "a positive integer"}.get(
                minimum, f"an integer of at least {minimum}")
        raise argparse.ArgumentTypeError(f"expected {expected}, got {text!r}")
    return value
