r"""
Symbols: the names the package gives a meaning to

sage_dynsym works with plain symbolic variables: a generalized coordinate
``q`` has the velocity symbol ``dq`` (:func:`velocity`), the acceleration
symbol ``ddq`` (:func:`acceleration`) and the momentum symbol ``p_q``
(:func:`momentum`); time is the variable :data:`t`, and total time
derivatives are taken with :func:`time_derivative`. The functions and
constants that expressions given as text may use are
:data:`ALLOWED_FUNCTIONS` and :data:`CONSTANTS`.

This module is also the one registry of the names a model may not declare.
Every name declared in a model -- a parameter, a coordinate, a circuit
element -- becomes a Sage symbolic variable and is printed as itself. A
declared name that is also a name the package gives a meaning to would make
the model silently wrong (a parameter ``dx`` *is* the velocity of the
coordinate ``x``) or its results unreadable (a parameter ``sin`` prints
like the function). This module lists those names in one place:

- the functions of the expression parser (:data:`PARSER_FUNCTIONS`) and its
  constants ``pi``, ``e``, ``I`` (:data:`CONSTANTS`, :data:`CONSTANT_MEANINGS`);
- the time ``t``;
- the names derived from every coordinate ``q`` (:data:`COORDINATE_DERIVED`):
  ``d<q>`` (velocity), ``dd<q>`` (acceleration), ``p_<q>`` (momentum);
- the names the package creates (:data:`MECHANICAL_PATTERNS`,
  :data:`CIRCUIT_PATTERNS`): multipliers ``lambda<j>`` of the
  Routh--Lyapunov method, deviations ``xi_<x>`` of the second variation,
  the multipliers ``u<k>``, ``v<k>`` of Dirac's scheme, the multipliers
  ``mu<j>`` of constraints (:func:`constraint_multipliers`); in circuits the
  state variables ``i<k>`` (inductor currents) and ``u<k>`` (capacitor
  voltages), the loop charges ``q<k>``, the node potentials ``phi<k>`` and
  their velocities and momenta, the placeholders ``i``, ``u`` of an
  element's own current and voltage, and ``D``, ``diff``, ``integrate``
  (printed in derivatives and integrals of the characteristics);
- names beginning or ending with an underscore and names beginning with
  ``dynsym`` or ``qe_unknown``, kept for the package's internal symbols.

:func:`check_names` checks declared names against the registry and against
each other; a clash is an error naming both uses. Names that merely exist
in Sage (``psi``, ``gamma``, ``beta``, ``E``) are ordinary names. Python
keywords (``lambda``) and names Sage cannot make into variables are refused
with a clear message.

EXAMPLES::

    sage: from sage_dynsym.symbols import check_mechanical_names
    sage: check_mechanical_names(['x', 'theta'], ['m', 'gamma', 'E'])
    sage: check_mechanical_names(['x'], ['m', 'dx'])
    Traceback (most recent call last):
    ...
    ModelError: parameters[1]: the name 'dx' is the velocity of the coordinate 'x' (coordinates[0]); choose another name
    sage: check_mechanical_names(['lambda'], [])
    Traceback (most recent call last):
    ...
    ModelError: coordinates[0]: 'lambda' is a Python keyword, which Sage cannot make into a variable; choose another name (e.g. 'lam')
    sage: check_mechanical_names(['x'], ['pi'])
    Traceback (most recent call last):
    ...
    ModelError: parameters[0]: the name 'pi' is reserved: the constant pi of the expression parser; choose another name
"""
# Sage's symbolic functions, Maxima and coercions need the whole library initialised
# first (the package's face loads it lazily, only when a name is used)
import sage.all
del sage  # imported for its effect alone: no name of this module
import keyword
import re

from sage.functions import all as sage_functions
from sage.misc.latex import latex
from sage.symbolic.constants import pi, e as euler_e, I as imaginary_unit
from sage.rings.real_mpfr import RealNumber
from sage.symbolic.ring import SR

from .errors import ModelError, DescriptionError, brief

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

__all__ = ['t', 'ALLOWED_FUNCTIONS', 'CONSTANTS', 'velocity', 'acceleration', 'momentum',
           'time_derivative', 'MAX_NAME_LENGTH', 'TIME', 'CONSTANT_MEANINGS', 'COORDINATE_DERIVED',
           'COMMON_PATTERNS', 'MECHANICAL_PATTERNS', 'CIRCUIT_PATTERNS', 'CIRCUIT_VARIABLES',
           'parser_functions', 'reserved_meaning', 'constraint_multipliers', 'check_name',
           'check_names', 'check_mechanical_names', 'exact_decimals', 'is_exact']

CONSTANTS = {'pi': pi, 'e': euler_e, 'I': imaginary_unit}


def _latex_base(name):
    return latex(SR.var(name))


def velocity(q):
    r"""
    Return the velocity symbol ``d<q>`` of the coordinate ``q``.

    INPUT:

    - ``q`` -- a symbolic variable (or its name)

    OUTPUT: a symbolic variable whose LaTeX form is `\dot q`

    EXAMPLES::

        sage: from sage_dynsym.symbols import velocity
        sage: velocity(var('psi')), latex(velocity('psi'))
        (dpsi, {\dot{\psi}})
    """
    name = str(q)
    return SR.var('d' + name, latex_name=r'\dot{%s}' % _latex_base(name))


def acceleration(q):
    r"""
    Return the acceleration symbol ``dd<q>`` of the coordinate ``q``.

    EXAMPLES::

        sage: from sage_dynsym.symbols import acceleration
        sage: acceleration(var('x')), latex(acceleration('x'))
        (ddx, {\ddot{x}})
    """
    name = str(q)
    return SR.var('dd' + name, latex_name=r'\ddot{%s}' % _latex_base(name))


def momentum(q):
    r"""
    Return the momentum symbol ``p_<q>`` conjugate to ``q``.

    EXAMPLES::

        sage: from sage_dynsym.symbols import momentum
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

        sage: from sage_dynsym.symbols import time_derivative
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



#: Longest declared name.
MAX_NAME_LENGTH = 64

#: The name of the time variable.
TIME = 't'

#: What the constants of the expression parser are.
CONSTANT_MEANINGS = {'pi': 'the constant pi', 'e': "the constant e (Euler's number)",
                     'I': 'the imaginary unit I'}

#: Names derived from a coordinate ``q``: prefix -> meaning.
COORDINATE_DERIVED = (('d', 'the velocity'), ('dd', 'the acceleration'), ('p_', 'the momentum'))

#: Names the package creates in every kind of model: (pattern, meaning).
COMMON_PATTERNS = (
    (r'lambda\d+', 'a multiplier of the Routh-Lyapunov method (lambda<j>)'),
    (r'xi_\w+', 'a deviation of the second variation (xi_<x>)'),
    (r'_\w*|\w*_', 'a name beginning or ending with an underscore, kept for internal symbols'),
    (r'dynsym\w*|qe_unknown\d*', 'an internal symbol of the package'),
)

#: Names created for mechanical systems (with :data:`COMMON_PATTERNS`).
MECHANICAL_PATTERNS = COMMON_PATTERNS + (
    (r'u[1-9]\d*', "a multiplier of Dirac's scheme (u<k>)"),
    (r'v[1-9]\d*', "a gauge multiplier of Dirac's scheme (v<k>)"),
    (r'mu[1-9]\d*', 'a multiplier of a constraint (mu<j>)'),
)

#: Names created for circuits (with :data:`COMMON_PATTERNS`).
CIRCUIT_PATTERNS = COMMON_PATTERNS + (
    (r'i', "the element's own current in a value expression"),
    (r'u', "the element's own voltage in a value expression"),
    (r'i\d+', 'an inductor current, a state variable (i<k>)'),
    (r'u\d+', 'a capacitor voltage, a state variable (u<k>)'),
    (r'q\d+', 'a loop charge, a coordinate of the loop method (q<k>)'),
    (r'phi\w*', 'a node potential, a coordinate of the node method (phi<k>)'),
    (r'd(q\d+|phi\w*)', 'the velocity of a loop charge or node potential'),
    (r'dd(q\d+|phi\w*)', 'the acceleration of a loop charge or node potential'),
    (r'p_(q\d+|phi\w*)', 'the momentum of a loop charge or node potential'),
    (r'v[1-9]\d*', "a gauge multiplier of Dirac's scheme (v<k>)"),
    (r'D|diff|integrate', "a name Sage prints in derivatives and integrals of the "
                          "characteristics f<k>"),
)

#: The names of a circuit's own variables: an element's current and voltage
#: placeholders, state variables, loop charges and node potentials.
CIRCUIT_VARIABLES = re.compile(r'^([iut]|[iuq]\d+|phi\w*)$')

_COMPILED = {}


def _patterns(kind):
    if kind not in _COMPILED:
        table = MECHANICAL_PATTERNS if kind == 'mechanical' else CIRCUIT_PATTERNS
        _COMPILED[kind] = [(re.compile(p), what) for p, what in table]
    return _COMPILED[kind]


def parser_functions():
    r"""
    The names of the functions the expression parser accepts.

    EXAMPLES::

        sage: from sage_dynsym.symbols import parser_functions
        sage: 'sin' in parser_functions(), 'atan2' in parser_functions(), 'gamma' in parser_functions()
        (True, True, False)
    """
    return frozenset(ALLOWED_FUNCTIONS)


def reserved_meaning(name, kind='mechanical'):
    r"""
    What the package uses ``name`` for, or ``None`` if it is free.

    INPUT:

    - ``name`` -- a string
    - ``kind`` -- ``'mechanical'`` (default) or ``'circuit'``

    EXAMPLES::

        sage: from sage_dynsym.symbols import reserved_meaning
        sage: reserved_meaning('t'), reserved_meaning('sin'), reserved_meaning('lambda2')
        ('the time', 'the function sin of the expression parser', 'a multiplier of the Routh-Lyapunov method (lambda<j>)')
        sage: reserved_meaning('q1', 'circuit'), reserved_meaning('q1'), reserved_meaning('psi')
        ('a loop charge, a coordinate of the loop method (q<k>)', None, None)
    """
    if name == TIME:
        return 'the time'
    if name in CONSTANT_MEANINGS:
        return f'{CONSTANT_MEANINGS[name]} of the expression parser'
    if name in parser_functions():
        return f'the function {name} of the expression parser'
    for pattern, what in _patterns(kind):
        if pattern.fullmatch(name):
            return what
    return None


def constraint_multipliers(count, taken=()):
    r"""
    Symbols ``mu1, mu2, ...`` for the multipliers of ``count`` holonomic
    constraints, skipping the names in ``taken`` (the names ``mu<j>`` are
    reserved in mechanical models, so only a Lagrangian written directly
    can use them).

    INPUT:

    - ``count`` -- the number of constraints
    - ``taken`` -- names (strings or symbols) already in use

    EXAMPLES::

        sage: from sage_dynsym.symbols import constraint_multipliers
        sage: constraint_multipliers(2), constraint_multipliers(2, taken=var('mu1 x'))
        ([mu1, mu2], [mu2, mu3])
    """
    taken = {str(name) for name in taken}
    names, j = [], 0
    while len(names) < count:
        j += 1
        if f'mu{j}' not in taken:
            names.append(f'mu{j}')
    return [SR.var(name, latex_name=r'\mu_{%d}' % int(name[2:])) for name in names]


def check_name(name, entry=None, error=DescriptionError, source=None):
    r"""
    Check that ``name`` can be the name of a symbolic variable: a string,
    an identifier, not a Python keyword, at most :data:`MAX_NAME_LENGTH`
    characters, accepted by Sage. Return it.

    EXAMPLES::

        sage: from sage_dynsym.symbols import check_name
        sage: check_name('theta'), check_name('λ')
        ('theta', 'λ')
        sage: check_name('None', entry='parameters[0]')
        Traceback (most recent call last):
        ...
        DescriptionError: parameters[0]: 'None' is a Python keyword, which Sage cannot make into a variable; choose another name
        sage: check_name('2x', entry='coordinates[1]')
        Traceback (most recent call last):
        ...
        DescriptionError: coordinates[1]: expected a symbol name (letters, digits and underscores, not starting with a digit), got '2x'
        sage: check_name('x' * 100)
        Traceback (most recent call last):
        ...
        DescriptionError: the name 'xxxxxxxxxxxxxxxxxxxxxxxxxxx...xxxxxxxxxxxxxxxxxxxxxxxxxxxx' has 100 characters (at most 64; MAX_NAME_LENGTH)
        sage: check_name('print')
        Traceback (most recent call last):
        ...
        DescriptionError: Sage cannot make 'print' into a variable (The name "print" is not a valid Python identifier.); choose another name
    """
    if not isinstance(name, str) or not name.isidentifier():
        raise error("expected a symbol name (letters, digits and underscores, not starting "
                    f"with a digit), got {brief(name)}", entry=entry, source=source)
    if len(name) > MAX_NAME_LENGTH:
        raise error(f"the name {brief(name)} has {len(name)} characters (at most "
                    f"{MAX_NAME_LENGTH}; MAX_NAME_LENGTH)", entry=entry, source=source)
    if keyword.iskeyword(name):
        hint = " (e.g. 'lam')" if name == 'lambda' else ""
        raise error(f"{name!r} is a Python keyword, which Sage cannot make into a variable; "
                    f"choose another name{hint}", entry=entry, source=source)
    from sage.symbolic.ring import SR
    try:
        SR.var(name)
    except ValueError as err:
        raise error(f"Sage cannot make {name!r} into a variable ({err}); choose another name",
                    entry=entry, source=source) from err
    return name


def check_names(declared, kind='mechanical', error=DescriptionError, source=None):
    r"""
    Check declared names against the registry and against each other.

    INPUT:

    - ``declared`` -- a list of triples ``(name, use, entry)``: ``use`` says
      what the name is (``'parameter'``, ``'coordinate'``, ``'element'``,
      ``'function'``), ``entry`` where it is declared (``'parameters[1]'``)
    - ``kind`` -- ``'mechanical'`` (default) or ``'circuit'``: which names
      the package creates
    - ``error`` -- the error class (default:
      :class:`~sage_dynsym.errors.DescriptionError`)
    - ``source`` -- (optional) the file, for the message

    A name may be declared once; it must not be reserved
    (:func:`reserved_meaning`) nor derived from a declared coordinate
    (``d<q>``, ``dd<q>``, ``p_<q>``).

    EXAMPLES::

        sage: from sage_dynsym.symbols import check_names
        sage: check_names([('x', 'coordinate', 'coordinates[0]'),
        ....:              ('dx', 'coordinate', 'coordinates[1]')])
        Traceback (most recent call last):
        ...
        DescriptionError: coordinates[1]: the name 'dx' is the velocity of the coordinate 'x' (coordinates[0]); choose another name
        sage: check_names([('m', 'parameter', 'parameters[0]'), ('m', 'coordinate', 'coordinates[0]')],
        ....:             source='f.yaml')
        Traceback (most recent call last):
        ...
        DescriptionError: f.yaml: coordinates[0]: the name 'm' is declared twice: as a parameter (parameters[0]) and as a coordinate (coordinates[0])
        sage: check_names([('i1', 'parameter', 'parameters[0]')], kind='circuit')
        Traceback (most recent call last):
        ...
        DescriptionError: parameters[0]: the name 'i1' is reserved: an inductor current, a state variable (i<k>); choose another name
        sage: check_names([('x', 'coordinate', 'coordinates[0]'), ('ddx', 'parameter', 'parameters[0]')])
        Traceback (most recent call last):
        ...
        DescriptionError: parameters[0]: the name 'ddx' is the acceleration of the coordinate 'x' (coordinates[0]); choose another name
    """
    seen, derived = {}, {}
    for name, use, entry in declared:
        check_name(name, entry, error, source)
        if use == 'coordinate':
            for prefix, what in COORDINATE_DERIVED:
                derived.setdefault(prefix + name, (what, name, entry))
    for name, use, entry in declared:
        if name in seen:
            first_use, first_entry = seen[name]
            raise error(f"the name {name!r} is declared twice: as a {first_use} ({first_entry}) "
                        f"and as a {use} ({entry})", entry=entry, source=source)
        seen[name] = (use, entry)
        if name in derived:
            what, q, where = derived[name]
            raise error(f"the name {name!r} is {what} of the coordinate {q!r} ({where}); "
                        "choose another name", entry=entry, source=source)
        meaning = reserved_meaning(name, kind)
        if meaning is not None:
            raise error(f"the name {name!r} is reserved: {meaning}; choose another name",
                        entry=entry, source=source)


def check_mechanical_names(coordinates, parameters=(), error=ModelError, source=None):
    r"""
    Check the names of a mechanical system: the coordinates and parameters
    (symbols or strings) against the registry and each other (see
    :func:`check_names`). For :class:`~sage_dynsym.mechanics.system.MechanicalSystem`
    and the description-file reader.

    EXAMPLES::

        sage: from sage_dynsym.symbols import check_mechanical_names
        sage: check_mechanical_names(var('psi theta'), var('m l g'))
        sage: check_mechanical_names([var('x')], [var('p_x')])
        Traceback (most recent call last):
        ...
        ModelError: parameters[0]: the name 'p_x' is the momentum of the coordinate 'x' (coordinates[0]); choose another name
        sage: check_mechanical_names(['t'], [])
        Traceback (most recent call last):
        ...
        ModelError: coordinates[0]: the name 't' is reserved: the time; choose another name
    """
    declared = [(str(q), 'coordinate', f'coordinates[{i}]') for i, q in enumerate(coordinates)]
    declared += [(str(p), 'parameter', f'parameters[{i}]') for i, p in enumerate(parameters or ())]
    check_names(declared, 'mechanical', error, source)


def exact_decimals(value):
    r"""
    ``value`` (a number, expression, dict or list of them) with every
    floating-point number replaced by the exact decimal it prints as:
    ``0.3`` is `3/10`, ``0.3141592653589793`` is `3141592653589793/10^{16}`
    (a Python float by its shortest round-trip text, a Sage literal by the
    digits typed). Constraints that hold for the symbols then hold for the
    values (`\cos^2 + \sin^2 = 1` exactly), and no rounding enters.

    EXAMPLES::

        sage: from sage_dynsym.symbols import exact_decimals
        sage: x = var('x')
        sage: exact_decimals({'k': [2r, 1.5*x, 0.3r]})
        {'k': [2, 3/2*x, 3/10]}
        sage: exact_decimals(0.3141592653589793)
        3141592653589793/10000000000000000
        sage: exact_decimals(9.81), exact_decimals(float(85)), exact_decimals(SR(0.25r)*x)
        (981/100, 85, 1/4*x)

    TESTS::

        sage: exact_decimals(float('inf'))
        Traceback (most recent call last):
        ...
        ModelError: values: not a finite number: inf
    """
    from fractions import Fraction
    from sage.rings.rational_field import QQ
    if isinstance(value, dict):
        return {k: exact_decimals(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return type(value)(exact_decimals(v) for v in value)
    if isinstance(value, (float, RealNumber)):
        text = repr(value) if isinstance(value, float) else \
            (getattr(value, 'literal', None) or str(value))
        try:
            return QQ(Fraction(text))
        except (ValueError, OverflowError) as err:
            raise ModelError(f"not a finite number: {value}", entry="values") from err
    if not hasattr(value, 'operator'):
        return value
    if value.is_numeric():
        number = value.pyobject()
        return SR(exact_decimals(number)) if isinstance(number, (float, RealNumber)) else value
    operator = value.operator()
    if operator is None:
        return value
    return operator(*[exact_decimals(a) for a in value.operands()])


def is_exact(expr):
    r"""
    Whether the expression ``expr`` has no floating-point number in it (a
    float makes equalities hold only to rounding).

    EXAMPLES::

        sage: from sage_dynsym.symbols import is_exact
        sage: x = var('x')
        sage: is_exact(sqrt(2)/2 + x), is_exact(0.5*x), is_exact(3), is_exact(SR(float(1)))
        (True, False, True, False)
    """
    stack = [SR(expr)]
    while stack:
        e = stack.pop()
        if e.operator() is None:
            if e.is_numeric():
                number = e.pyobject()
                if isinstance(number, (float, complex)) or not number.parent().is_exact():
                    return False
        else:
            stack.extend(e.operands())
    return True
