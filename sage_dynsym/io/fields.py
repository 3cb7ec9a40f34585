r"""
Fields of description files

The checks every description format shares: a mapping with known keys, a
list of declared names (checked against the reserved names of
:mod:`sage_dynsym.symbols`), the title of a model or a body, and how an
expression is written back as text.

EXAMPLES::

    sage: from sage_dynsym.io.fields import check_keys, declared_names
    sage: check_keys({'kind': 'circuit'}, {'kind', 'name'}, None, 'c.yaml', "a circuit description")
    sage: declared_names({'parameters': ['m', 'l']}, 'parameters', 'p.yaml')
    ['m', 'l']
    sage: declared_names({'parameters': ['m', 'dx']}, 'parameters', 'p.yaml')
    ['m', 'dx']
"""
from ..errors import DescriptionError, ModelError, brief
from ..symbols import check_name

__all__ = ['MAX_PARAMETERS', 'MAX_RESULT_LENGTH', 'MAX_TITLE_LENGTH', 'check_keys', 'check_mapping',
           'declared_names', 'declared_positive', 'title', 'text']

#: Most parameters of a description (a 1,000-body model with a mass, a
#: mass centre, six moments of inertia and a length per body needs 10,000).
MAX_PARAMETERS = 10_000
#: Longest text of one expression in a ``results:`` section (the
#: description's own expressions have
#: :data:`~sage_dynsym.io.expressions.MAX_EXPRESSION_LENGTH`).
MAX_RESULT_LENGTH = 4 * 2**20
#: Longest name of a model or a body.
MAX_TITLE_LENGTH = 200


def check_keys(data, allowed, entry, source, what):
    r"""
    Check that ``data`` is a mapping whose keys are among ``allowed``
    (``what`` names it in the message).

    EXAMPLES::

        sage: from sage_dynsym.io.fields import check_keys
        sage: check_keys({'knd': 1}, {'kind'}, 'model', 'm.yaml', "a model")
        Traceback (most recent call last):
        ...
        DescriptionError: m.yaml: model: unknown key 'knd'; a model has the keys kind
    """
    if not isinstance(data, dict):
        raise DescriptionError(f"expected a mapping ({what}), got {brief(data)}",
                               entry=entry, source=source)
    for key in data:
        if key not in allowed:
            raise DescriptionError(f"unknown key {brief(key)}; {what} has the keys "
                                   f"{', '.join(sorted(allowed))}", entry=entry, source=source)


def check_mapping(value, keys, what, entry, expected="a mapping"):
    r"""
    Check that ``value`` given to a class of models is a dict whose keys
    are among ``keys`` (in the order the message lists them): else a
    :class:`~sage_dynsym.errors.ModelError` naming ``entry``; ``what`` names
    such a mapping (``"a load"``), ``expected`` what else is accepted.

    EXAMPLES::

        sage: from sage_dynsym.io.fields import check_mapping
        sage: check_mapping({'body': 'b'}, ('body', 'radius'), "a disk", 'rolling[0]')
        sage: check_mapping({'bdy': 'b'}, ('body', 'radius'), "a disk", 'rolling[0]')
        Traceback (most recent call last):
        ...
        ModelError: rolling[0]: unknown key 'bdy'; a disk has the keys body, radius
        sage: check_mapping(1, ('body', 'radius'), "a disk", 'rolling[0]', "a Disk or a dict")
        Traceback (most recent call last):
        ...
        ModelError: rolling[0]: expected a Disk or a dict with the keys body, radius, got 1
    """
    if not isinstance(value, dict):
        raise ModelError(f"expected {expected} with the keys {', '.join(keys)}, got {value!r}",
                         entry=entry)
    for key in value:
        if key not in keys:
            raise ModelError(f"unknown key {key!r}; {what} has the keys {', '.join(keys)}",
                             entry=entry)


def declared_names(data, key, source, required=True, limit=None):
    r"""
    The list of names under ``key`` of ``data``, each checked by
    :func:`~sage_dynsym.symbols.check_name` (at most ``limit`` of them).

    EXAMPLES::

        sage: from sage_dynsym.io.fields import declared_names
        sage: declared_names({'coordinates': ['x', 'lambda']}, 'coordinates', 'm.yaml')
        Traceback (most recent call last):
        ...
        DescriptionError: m.yaml: coordinates[1]: 'lambda' is a Python keyword, which Sage cannot make into a variable; choose another name (e.g. 'lam')
    """
    if key not in data and required:
        raise DescriptionError(f"missing key {key!r} (a list of symbol names)",
                               entry=key, source=source)
    value = data.get(key, [])
    if not isinstance(value, list):
        raise DescriptionError(f"expected a list of symbol names, got {brief(value)}",
                               entry=key, source=source)
    if limit is not None and len(value) > limit:
        raise DescriptionError(f"{len(value)} names; a description file has at most {limit} "
                               f"(MAX_{key.upper()})", entry=key, source=source)
    return [check_name(v, f"{key}[{i}]", source=source) for i, v in enumerate(value)]


def declared_positive(data, parameters, source):
    r"""
    The ``positive:`` list of a description: declared parameters known to
    be positive (the analysis assumes no sign that is not declared).

    EXAMPLES::

        sage: from sage_dynsym.io.fields import declared_positive
        sage: declared_positive({'positive': ['m', 'g']}, ['m', 'l', 'g'], 'p.yaml')
        ['m', 'g']
        sage: declared_positive({'positive': ['k']}, ['m'], 'p.yaml')
        Traceback (most recent call last):
        ...
        DescriptionError: p.yaml: positive: 'k' is not a declared parameter (positive: lists parameters known to be positive)
    """
    names = declared_names(data, 'positive', source, required=False, limit=MAX_PARAMETERS)
    for name in names:
        if name not in parameters:
            raise DescriptionError(f"{name!r} is not a declared parameter (positive: lists "
                                   "parameters known to be positive)", entry='positive',
                                   source=source)
    return names


def title(data, entry, source=None):
    r"""
    The ``name`` of a model or body: a text (or a number) of at most
    :data:`MAX_TITLE_LENGTH` characters, or ``None`` if absent.

    EXAMPLES::

        sage: from sage_dynsym.io.fields import title
        sage: title({'name': 'pendulum'}, 'name'), title({}, 'name')
        ('pendulum', None)
        sage: title({'name': [1, 2]}, 'bodies[0].name')
        Traceback (most recent call last):
        ...
        DescriptionError: bodies[0].name: expected a text, got [1, 2]
    """
    value = data.get('name')
    if value is None:
        return None
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        value = str(value)
    if not isinstance(value, str):
        raise DescriptionError(f"expected a text, got {brief(value)}", entry=entry,
                               source=source)
    if len(value) > MAX_TITLE_LENGTH:
        raise DescriptionError(f"a name of {len(value)} characters (at most "
                               f"{MAX_TITLE_LENGTH}; MAX_TITLE_LENGTH)", entry=entry,
                               source=source)
    return value


def text(expr):
    r"""
    An expression as the text a description file holds.

    EXAMPLES::

        sage: from sage_dynsym.io.fields import text
        sage: text(var('m')*var('l')^2)
        'l^2*m'
    """
    return str(expr)
