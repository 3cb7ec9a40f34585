r"""
The values given for the parameters of a model

The numerical methods of a model (:meth:`numerical_rhs`, :meth:`simulate`),
its stability maps and its sweeps take values for its parameters. They are
checked against what the model says of itself before anything is
computed:

- a parameter declared positive (``positive:`` of its description, see
  :meth:`~sage_dynsym.dynamics.model.Model.positive_parameters`) gets a
  positive value;
- the physical conditions of the model (its ``conditions()``, e.g. the
  inductance matrix of coupled windings positive semi-definite, the
  direction of a Newtonian field a unit vector) hold at the values, to
  rounding, wherever the values decide them.

EXAMPLES::

    sage: from sage_dynsym.circuits import Circuit
    sage: from sage_dynsym.numerics.values import check_model_values
    sage: C = Circuit([[0, 1, 'R1'], [1, 0, 'L1'], [2, 0, 'L2'], [0, 2, 'R2'],
    ....:              {'kind': 'mutual', 'between': ['L1', 'L2'], 'value': 'M'}],
    ....:             parameters=['M'], positive=['R1', 'R2'])
    sage: C.conditions()
    [L1 >= 0, L2 >= 0, L1*L2 - M^2 >= 0]
    sage: check_model_values(C, {'L1': 1, 'L2': 4, 'M': 1.5, 'R1': 1, 'R2': 1})
    sage: check_model_values(C, {'L1': 1, 'L2': 1, 'M': 2, 'R1': 1, 'R2': 1})
    Traceback (most recent call last):
    ...
    ModelError: values: the values break the condition L1*L2 - M^2 >= 0 of the model (it is -3 there)
    sage: check_model_values(C, {'L1': 1, 'L2': 1, 'M': 0, 'R1': -1, 'R2': 1})
    Traceback (most recent call last):
    ...
    ModelError: values: R1 is declared positive, got -1

Sage numbers and constant expressions count as numbers::

    sage: check_model_values(C, {'L1': 1, 'L2': 1, 'M': SR(2), 'R1': 1, 'R2': 1})
    Traceback (most recent call last):
    ...
    ModelError: values: the values break the condition L1*L2 - M^2 >= 0 of the model (it is -3 there)
    sage: check_model_values(C, {'L1': 1, 'L2': 1, 'M': 0, 'R1': -sqrt(2), 'R2': 1})
    Traceback (most recent call last):
    ...
    ModelError: values: R1 is declared positive, got -sqrt(2)
"""
import operator

from sage.symbolic.operators import add_vararg
from sage.symbolic.ring import SR

from ..algebra.size import polynomial_terms
from ..errors import ModelError
from ..arguments import check_declared_signs, finite_real

__all__ = ['ROUNDING', 'ROUNDING_TERMS', 'holds_to_rounding', 'check_model_values']

#: Relative size of the rounding errors tolerated when a condition is
#: checked at floating-point values (relative to the sum of the absolute
#: values of the terms).
ROUNDING = 1e-9

#: Conditions with more polynomial terms than this are not expanded to
#: estimate the rounding errors.
ROUNDING_TERMS = 10_000


def holds_to_rounding(condition, values):
    r"""
    Whether the relational ``condition`` holds at ``values`` (a dict of
    numbers, symbols or names as keys), to rounding: ``None`` when the
    values leave symbols of the condition free, else ``(holds, value)``,
    ``value`` the left side minus the right side there.

    The comparison tolerates rounding errors of the size :data:`ROUNDING`
    times the sum of the absolute values of the terms: `0.6^2 + 0.8^2 = 1`
    holds, `2^2 = 1` does not.

    EXAMPLES::

        sage: from sage_dynsym.numerics.values import holds_to_rounding
        sage: a, b = var('a b')
        sage: holds_to_rounding(a^2 + b^2 == 1, {a: 0.6, b: 0.8})[0]
        True
        sage: holds_to_rounding(a*b >= 1, {a: 1})
        sage: holds_to_rounding(a - b > 0, {'a': 1, 'b': 2})
        (False, -1.0)
    """
    by_name = {str(k): v for k, v in values.items()}
    expr = SR(condition.lhs() - condition.rhs())
    symbols = expr.variables()
    if any(str(v) not in by_name for v in symbols):
        return None
    point = {v: SR(by_name[str(v)]) for v in symbols}
    try:
        value = finite_real(expr.subs(point), 'condition')
        # the terms the rounding errors come from (a condition too large to
        # expand is judged on its value)
        terms = expr.expand() if polynomial_terms(expr) <= ROUNDING_TERMS else expr
        parts = terms.operands() if terms.operator() is add_vararg else [terms]
        scale = sum(abs(finite_real(SR(t).subs(point), 'term')) for t in parts)
    except ModelError:
        return None
    tolerance = ROUNDING * max(scale, 1e-300)
    op = condition.operator()
    if op is operator.eq:
        holds = abs(value) <= tolerance
    elif op is operator.ne:
        holds = abs(value) > tolerance
    elif op in (operator.ge, operator.gt):
        holds = value >= -tolerance if op is operator.ge else value > tolerance
    else:
        holds = value <= tolerance if op is operator.le else value < -tolerance
    return holds, value


def check_model_values(model, values, entry="values"):
    r"""
    Check the parameter ``values`` given to a numerical method of ``model``
    (see the module documentation): raises
    :class:`~sage_dynsym.errors.ModelError` naming the parameter or the
    condition.

    INPUT:

    - ``model`` -- any object; its ``positive_parameters()`` and
      ``conditions()`` are used when it has them
    - ``values`` -- dict of values (symbols or names as keys)
    - ``entry`` -- the name of the argument, for the message

    EXAMPLES: see the module documentation.
    """
    if not isinstance(values, dict):
        raise ModelError(f"expected a dict of parameter values, got {type(values).__name__}",
                         entry=entry)
    positive = getattr(model, 'positive_parameters', None)
    if callable(positive):
        check_declared_signs(values, positive(), entry)
    conditions = getattr(model, 'conditions', None)
    if not callable(conditions):
        return
    numbers = {k: v for k, v in values.items() if _is_number(v)}
    for condition in conditions():
        result = holds_to_rounding(condition, numbers)
        if result is not None and not result[0]:
            raise ModelError(f"the values break the condition {condition} of the model (it is "
                             f"{result[1]:.6g} there)", entry=entry)


def _is_number(value):
    # a number or a constant expression (symbolic expressions are callable
    # too: only what finite_real refuses is left out, such as a function)
    try:
        finite_real(value, 'value')
    except ModelError:
        return False
    return True
