r"""
Exceptions raised by sage_dynsym

Every error a user can provoke with bad input is one of these classes, with a
message naming the offending entry and saying what was expected. They also
derive from the matching built-in class (``ValueError`` or ``TypeError``) so
that generic ``except ValueError`` code keeps working.

EXAMPLES::

    sage: from sage_dynsym.errors import DescriptionError, DynSymError
    sage: err = DescriptionError("rotation axis must be 1, 2 or 3, got 4",
    ....:                        entry="bodies[0].rotations[1]", source="top.yaml")
    sage: print(err)
    top.yaml: bodies[0].rotations[1]: rotation axis must be 1, 2 or 3, got 4
    sage: isinstance(err, DynSymError), isinstance(err, ValueError)
    (True, True)
"""
import reprlib
from contextlib import contextmanager

__all__ = ['brief', 'DynSymError', 'ModelError', 'DescriptionError', 'ExpressionError',
           'CircuitError', 'AnalysisError', 'BudgetError', 'in_source', 'moved_module',
           'lazy_face']

_BRIEF = reprlib.Repr()
_BRIEF.maxlevel, _BRIEF.maxstring, _BRIEF.maxother = 3, 60, 60
_BRIEF.maxlist = _BRIEF.maxdict = _BRIEF.maxtuple = _BRIEF.maxset = 6


def brief(value):
    r"""
    A short ``repr`` of ``value`` for error messages: long texts, deep or
    long lists and mappings (such as YAML alias bombs) are abbreviated with
    ``...``.

    EXAMPLES::

        sage: from sage_dynsym.errors import brief
        sage: brief([1, 2, 3]), brief({'a': [[[[1]]]]})
        ('[1, 2, 3]', "{'a': [[[...]]]}")
        sage: brief(list(range(100)))
        '[0, 1, 2, 3, 4, 5, ...]'
        sage: len(brief("x" * 10**6)) < 100
        True
    """
    return _BRIEF.repr(value)


class DynSymError(Exception):
    r"""
    Base class of all errors raised by sage_dynsym.

    INPUT:

    - ``message`` -- what is wrong and what was expected
    - ``entry`` -- (optional) the name or path of the offending entry,
      e.g. ``"bodies[1].parent"``
    - ``source`` -- (optional) the file the entry comes from

    EXAMPLES::

        sage: from sage_dynsym.errors import DynSymError
        sage: raise DynSymError("something is off", entry="bodies[0]")
        Traceback (most recent call last):
        ...
        DynSymError: bodies[0]: something is off
    """

    def __init__(self, message, entry=None, source=None):
        self.message = message
        self.entry = entry
        self.source = source
        super().__init__(self._full_message())

    def _full_message(self):
        parts = [p for p in (self.source, self.entry) if p]
        return ": ".join(parts + [self.message])

    def with_context(self, entry=None, source=None):
        r"""
        Return a copy of this error with an outer entry path and/or a file.

        EXAMPLES::

            sage: from sage_dynsym.errors import ModelError
            sage: e = ModelError("must be symmetric", entry="inertia")
            sage: print(e.with_context(entry="bodies[2]", source="f.yaml"))
            f.yaml: bodies[2].inertia: must be symmetric
        """
        if entry and self.entry:
            entry = f"{entry}.{self.entry}"
        return self._copy(entry or self.entry, source or self.source)

    def _copy(self, entry, source):
        # this error at another place: a subclass with more state keeps it
        return type(self)(self.message, entry=entry, source=source)


class ModelError(DynSymError, ValueError):
    r"""
    An inconsistent or non-physical model: unknown parent body, cycle of
    parents, bad rotation axis, non-symmetric inertia tensor, undeclared
    symbol, wrong vector length, ...

    EXAMPLES::

        sage: from sage_dynsym.errors import ModelError
        sage: issubclass(ModelError, ValueError)
        True
    """


class DescriptionError(ModelError):
    r"""
    A description file that cannot be read: YAML syntax, unknown or missing
    keys, malformed expressions, attempts to construct Python objects.

    EXAMPLES::

        sage: from sage_dynsym.errors import DescriptionError, ModelError
        sage: issubclass(DescriptionError, ModelError)
        True
    """


class ExpressionError(ModelError):
    r"""
    A malformed expression string, or one using an undeclared symbol or a
    function that is not allowed.

    EXAMPLES::

        sage: from sage_dynsym.errors import ExpressionError
        sage: print(ExpressionError("undeclared symbol 'x'", entry="mass"))
        mass: undeclared symbol 'x'
    """


class CircuitError(ModelError):
    r"""
    A circuit graph that cannot be handled: disconnected graph, self-loop,
    unknown element, a circuit that is not *complete* (no Brayton--Moser
    split), ...

    EXAMPLES::

        sage: from sage_dynsym.errors import CircuitError, ModelError
        sage: issubclass(CircuitError, ModelError)
        True
    """


class AnalysisError(DynSymError, ValueError):
    r"""
    Input to an analysis routine that does not fit its assumptions: a point
    that is not a solution, a non-symmetric quadratic form, an integral that
    is not conserved, non-polynomial input to elimination.

    EXAMPLES::

        sage: from sage_dynsym.errors import AnalysisError
        sage: issubclass(AnalysisError, ValueError)
        True
    """


class BudgetError(DynSymError):
    r"""
    A computation whose estimated size exceeds its budget (a number of
    polynomial terms): raised *before* the expensive step, so nothing is
    lost but the result of that step.

    INPUT: as for :class:`DynSymError`, and

    - ``estimate`` -- the estimated size
    - ``budget`` -- the budget it exceeds

    EXAMPLES::

        sage: from sage_dynsym.errors import BudgetError
        sage: err = BudgetError("the characteristic polynomial", estimate=10**9, budget=10**5)
        sage: print(err)
        the characteristic polynomial: about 1e+09 polynomial terms, over the budget of 100000
        sage: err.estimate, err.budget
        (1000000000, 100000)

    TESTS: :meth:`~DynSymError.with_context` keeps the estimate::

        sage: e = BudgetError("expansion", estimate=5, budget=2).with_context(source='f.yaml')
        sage: print(e); e.estimate
        f.yaml: expansion: about 5 polynomial terms, over the budget of 2
        5
    """

    def __init__(self, message, entry=None, source=None, estimate=None, budget=None):
        self.estimate, self.budget = estimate, budget
        if estimate is not None and not message.endswith(f"budget of {budget}"):
            message = (f"{message}: about {float(estimate):.3g} polynomial terms, over the "
                       f"budget of {budget}")
        super().__init__(message, entry=entry, source=source)

    def _copy(self, entry, source):
        return type(self)(self.message, entry=entry, source=source, estimate=self.estimate,
                          budget=self.budget)


@contextmanager
def in_source(source):
    r"""
    A context in which an error of the package that names no file is
    raised again naming ``source`` (an error that names one is left as it
    is: the innermost file is the one to fix).

    EXAMPLES::

        sage: from sage_dynsym.errors import ModelError, in_source
        sage: with in_source('top.yaml'):
        ....:     raise ModelError("must be symmetric", entry="inertia")
        Traceback (most recent call last):
        ...
        ModelError: top.yaml: inertia: must be symmetric
        sage: with in_source('top.yaml'):
        ....:     raise ModelError("must be symmetric", source='body.yaml')
        Traceback (most recent call last):
        ...
        ModelError: body.yaml: must be symmetric
    """
    try:
        yield
    except DynSymError as err:
        if err.source:
            raise
        raise err.with_context(source=source) from err


def moved_module(old, new):
    r"""
    Make the module being imported under the earlier name ``old`` the
    module at its new place ``new``, with a ``DeprecationWarning`` that
    points at the ``import`` of the caller (the body of a deprecated alias
    module, e.g. ``sage_dynsym/lagrangian.py``).

    EXAMPLES::

        sage: import warnings, sage_dynsym.dynamics.lagrangian as new
        sage: with warnings.catch_warnings(record=True) as caught:
        ....:     warnings.simplefilter('always')
        ....:     import sage_dynsym.lagrangian as old
        sage: old is new, str(caught[0].message)
        (True, 'sage_dynsym.lagrangian is deprecated: import sage_dynsym.dynamics.lagrangian instead')
    """
    import importlib
    import sys
    import warnings
    # the caller's frame is the alias module's body; the importer is above it
    warnings.warn(f"{old} is deprecated: import {new} instead", DeprecationWarning, stacklevel=3)
    sys.modules[old] = importlib.import_module(new)


def lazy_face(module, sources, load_sage=False):
    r"""
    The ``__getattr__`` and ``__dir__`` (PEP 562) of a package face that
    imports its public names on first use, so that importing the package
    (and the command line's ``--help``) does not load Sage.

    INPUT:

    - ``module`` -- the ``__name__`` of the package
    - ``sources`` -- a dict from each lazy name to the module, relative to
      ``module``, that defines it
    - ``load_sage`` -- (default: ``False``) whether to initialise the whole
      Sage library before the first name is imported (symbolic functions,
      Maxima and the coercion model need it when the package is used from
      plain Python)

    OUTPUT: the pair ``(__getattr__, __dir__)``; a name, once imported, is
    bound in the package, and ``dir()`` of the package lists its ``__all__``,
    its imported subpackages and the dunder names, not its helpers.

    EXAMPLES::

        sage: import sage_dynsym.report as face
        sage: from sage_dynsym.errors import lazy_face
        sage: getattr_, dir_ = lazy_face(face.__name__, {'report': '.writer'})
        sage: getattr_('report') is face.report
        True
        sage: 'report' in dir_() and '_SOURCE' not in dir_()
        True

    TESTS::

        sage: getattr_('nothing')
        Traceback (most recent call last):
        ...
        AttributeError: module 'sage_dynsym.report' has no attribute 'nothing'
    """
    import importlib
    import sys
    from types import ModuleType

    def __getattr__(name):
        if name not in sources:
            raise AttributeError(f"module {module!r} has no attribute {name!r}")
        if load_sage:
            importlib.import_module('sage.all')
        value = getattr(importlib.import_module(sources[name], module), name)
        setattr(sys.modules[module], name, value)
        return value

    def __dir__():
        names = vars(sys.modules[module])
        return sorted(set(names.get('__all__', ())) | {
            key for key, value in names.items()
            if (key.startswith('__') and key.endswith('__'))
            or (isinstance(value, ModuleType) and value.__name__ == f"{module}.{key}")})

    return __getattr__, __dir__
