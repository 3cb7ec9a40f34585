r"""
Description files: reading and writing models as YAML

A description file is human-editable YAML (format:
:doc:`/description_files`), read with PyYAML's
*safe* loader: tags that would construct Python objects are refused, and
every expression is a string parsed by
:class:`~sage_dynsym.io.expressions.ExpressionParser` restricted to the
declared symbols (never ``eval``). Errors name the file, the entry and what
was expected.

The required key ``kind`` chooses the format: ``mechanical`` (see
:mod:`sage_dynsym.mechanics.description`), ``circuit`` (see
:mod:`sage_dynsym.circuits.description`) or ``lie_poisson`` (see
:mod:`sage_dynsym.lie.description`).

:func:`save` writes the description back with a ``results:`` section (the
Lagrangian and the equations, as text and LaTeX); :func:`load` with
``results=True`` parses that section again so that a later session can
reuse it.

EXAMPLES::

    sage: import os, tempfile
    sage: from sage_dynsym import load, save
    sage: from sage_dynsym.description import example_path
    sage: S = load(example_path('spherical_pendulum.yaml')); S
    Mechanical system 'spherical pendulum': 1 body, coordinates (psi, theta)
    sage: path = os.path.join(tempfile.mkdtemp(), 'pendulum.yaml')
    sage: save(S, path)
    sage: S2, results = load(path, results=True)
    sage: bool(results['lagrangian'] == S.lagrangian().expr())
    True
    sage: results['lagrange_equations'] == S.lagrangian().lagrange_equations()
    True
"""
# Sage's symbolic functions, Maxima and coercions need the whole library initialised
# first (the package's face loads it lazily, only when a name is used)
import sage.all
del sage  # imported for its effect alone: no name of this module
import os
import sys

import yaml

from .arguments import flag, model_argument
from .errors import DescriptionError, DynSymError, brief, in_source
from .io.expressions import ExpressionParser
from .io.fields import MAX_RESULT_LENGTH, title
from .io.files import write_atomically
from .io.yaml import read_yaml
# earlier public names of this module
from .mechanics.description import mechanical_system_from_dict, mechanical_system_to_dict

__all__ = ['example_path', 'load', 'ENTRY_POINTS', 'kinds', 'register_kind', 'model_from_dict',
           'model_results', 'save', 'title', 'mechanical_system_from_dict',
           'mechanical_system_to_dict']


def example_path(name):
    r"""
    The path of a bundled example description file.

    EXAMPLES::

        sage: from sage_dynsym.description import example_path
        sage: os.path.basename(example_path('spherical_pendulum.yaml'))
        'spherical_pendulum.yaml'
    """
    here = os.path.dirname(os.path.abspath(__file__))
    in_source = os.path.join(os.path.dirname(here), 'examples', name)
    if os.path.exists(in_source):
        return in_source
    # installed with pip: setup.py puts the examples under <prefix>/share
    return os.path.join(sys.prefix, 'share', 'sage_dynsym', 'examples', name)


def load(path, results=False):
    r"""
    Load a description file.

    INPUT:

    - ``path`` -- a file name
    - ``results`` -- (default: ``False``) if ``True``, also return the
      parsed ``results:`` section (a dictionary, empty if there is none)

    OUTPUT: a :class:`~sage_dynsym.mechanics.system.MechanicalSystem` or a
    :class:`~sage_dynsym.circuits.circuit.Circuit` (and the results)

    Every problem is a :class:`~sage_dynsym.errors.DynSymError` naming the
    file and the entry (an unexpected failure inside Sage too, with its
    class).

    EXAMPLES::

        sage: from sage_dynsym import load
        sage: from sage_dynsym.description import example_path
        sage: load(example_path('nonlinear_circuit.yaml'))
        Circuit 'nonlinear circuit of Example 2' with 13 branches on 5 nodes

    TESTS::

        sage: import tempfile
        sage: def write(text):
        ....:     f = tempfile.NamedTemporaryFile('w', suffix='.yaml', delete=False)
        ....:     _ = f.write(text); f.close(); return f.name
        sage: load(write("kind: hydraulic\n"))
        Traceback (most recent call last):
        ...
        DescriptionError: ...: kind: expected one of 'mechanical', 'circuit', 'lie_poisson', got 'hydraulic'
        sage: load(write("- 1\n- 2\n"))
        Traceback (most recent call last):
        ...
        DescriptionError: ...: a description file holds a mapping of keys, got list
    """
    source = str(path)
    with in_source(source):
        try:
            return _load(path, results, source)
        except DynSymError:
            raise
        except RecursionError as cause:
            raise DescriptionError("the description is nested too deeply to be read",
                                   source=source) from cause
        except MemoryError as cause:
            raise DescriptionError("not enough memory to read the description",
                                   source=source) from cause
        except Exception as err:    # a failure inside Sage: still the package's error
            raise DescriptionError(f"could not build the model ({type(err).__name__}: "
                                   f"{brief(str(err))})", source=source) from err


#: The entry-point group under which other packages register kinds of
#: models (``[project.entry-points."sage_dynsym.kinds"]``, ``name =
#: "package.module:ModelClass"``).
ENTRY_POINTS = 'sage_dynsym.kinds'

_registered = {}


def kinds():
    r"""
    The registry of the kinds of models: a dict from the ``kind`` of a
    description file to the model class (a subclass of
    :class:`~sage_dynsym.dynamics.model.Model`) -- the package's own kinds,
    those of other packages (entry points of the group
    :data:`ENTRY_POINTS`) and those given to :func:`register_kind`.
    ``load``, ``save``, the report, stability maps and the command line
    find a model's format and methods here, by kind only.

    EXAMPLES::

        sage: from sage_dynsym import kinds
        sage: sorted(kinds())
        ['circuit', 'lie_poisson', 'mechanical']
        sage: kinds()['circuit']
        <class 'sage_dynsym.circuits.circuit.Circuit'>
    """
    from importlib.metadata import entry_points
    from .circuits.circuit import Circuit
    from .lie.system import LiePoissonSystem
    from .mechanics.system import MechanicalSystem
    found = {cls.kind: cls for cls in (MechanicalSystem, Circuit, LiePoissonSystem)}
    for point in entry_points(group=ENTRY_POINTS):
        try:
            cls = point.load()
        except Exception as err:        # a broken plugin must not break load()
            raise DescriptionError(f"the kind {point.name!r} of another package cannot be "
                                   f"loaded from {point.value} ({type(err).__name__}: "
                                   f"{brief(str(err))})", entry=ENTRY_POINTS) from err
        found[_checked_kind(cls, point.name)] = cls
    found.update(_registered)
    return found


def register_kind(cls):
    r"""
    Register ``cls`` (a subclass of
    :class:`~sage_dynsym.dynamics.model.Model` with a :attr:`kind` and the
    interface's methods) as the model class of description files of its
    ``kind``, for this session. Returns ``cls``, so that it can decorate
    the class.

    EXAMPLES: see ``doc/architecture.rst`` (how to add a kind); refused::

        sage: from sage_dynsym.description import register_kind
        sage: register_kind(int)
        Traceback (most recent call last):
        ...
        DescriptionError: kind: a kind of model is a subclass of Model with a kind name, got <class 'int'>
    """
    _registered[_checked_kind(cls)] = cls
    return cls


def _checked_kind(cls, name=None):
    from .dynamics.model import Model
    if not (isinstance(cls, type) and issubclass(cls, Model) and isinstance(cls.kind, str)
            and cls.kind.isidentifier()):
        raise DescriptionError("a kind of model is a subclass of Model with a kind name, got "
                               f"{brief(cls)}", entry='kind')
    if name is not None and name != cls.kind:
        raise DescriptionError(f"the entry point {name!r} names a class of kind "
                               f"{cls.kind!r}", entry=ENTRY_POINTS)
    return cls.kind


def model_from_dict(data, source=None):
    r"""
    The model of a description mapping, by its ``kind`` (see
    :func:`kinds`).

    EXAMPLES::

        sage: from sage_dynsym.description import model_from_dict
        sage: model_from_dict({'kind': 'circuit', 'branches': [[1, 2, 'L1'], [2, 1, 'C1']]})
        Circuit with 2 branches on 2 nodes
        sage: model_from_dict({'kind': 'hydraulic'}, source='h.yaml')
        Traceback (most recent call last):
        ...
        DescriptionError: h.yaml: kind: expected one of 'mechanical', 'circuit', 'lie_poisson', got 'hydraulic'
    """
    if not isinstance(data, dict):
        raise DescriptionError(f"a description file holds a mapping of keys, got "
                               f"{type(data).__name__}", source=source)
    kind = data.get('kind')
    registry = kinds()
    if not isinstance(kind, str) or kind not in registry:
        raise DescriptionError(f"expected one of {', '.join(map(repr, registry))}, got "
                               f"{brief(kind)}", entry='kind', source=source)
    return registry[kind].from_dict(data, source)


def _load(path, results, source):
    data = read_yaml(path)
    model = model_from_dict(data, source)
    if not results:
        return model
    return model, _parse_results(model, data.get('results') or {}, source)


def model_results(model):
    r"""
    The ``results:`` section written by :func:`save`: characteristic
    function and equations as text, with their LaTeX forms
    (:meth:`~sage_dynsym.dynamics.model.Model.results`).

    EXAMPLES::

        sage: from sage_dynsym import load
        sage: from sage_dynsym.description import example_path, model_results
        sage: sorted(model_results(load(example_path('spherical_pendulum.yaml'))))
        ['lagrange_equations', 'lagrange_equations_latex', 'lagrangian', 'lagrangian_latex']
    """
    return model.results()


def save(model, path, results=True):
    r"""
    Write ``model`` to a description file, by default with a ``results:``
    section (see :func:`model_results`).

    The file is replaced atomically (:func:`write_atomically`): an
    interrupted save leaves the previous file as it was.

    EXAMPLES::

        sage: import tempfile
        sage: from sage_dynsym import load, save
        sage: from sage_dynsym.description import example_path
        sage: C = load(example_path('nonlinear_circuit.yaml'))
        sage: path = tempfile.mktemp(suffix='.yaml')
        sage: save(C, path)
        sage: load(path)
        Circuit 'nonlinear circuit of Example 2' with 13 branches on 5 nodes

    TESTS::

        sage: save(C, '/nonexistent/folder/c.yaml')
        Traceback (most recent call last):
        ...
        DescriptionError: /nonexistent/folder/c.yaml: cannot write the file: No such file or directory
        sage: save('c.yaml', C)
        Traceback (most recent call last):
        ...
        DescriptionError: model: expected a model (a mechanical system, a circuit, a Lie-Poisson system, ...), got 'c.yaml' (str); the call is save(model, path)
    """
    model_argument(model, ('to_dict', 'results'), "model", "a model (a mechanical system, a "
                   "circuit, a Lie-Poisson system, ...)", error=DescriptionError,
                   hint="the call is save(model, path)")
    flag(results, "results", error=DescriptionError)
    data = model.to_dict()
    if results:
        data['results'] = model_results(model)
    write_atomically(path, lambda stream: yaml.safe_dump(data, stream, sort_keys=False,
                                                         allow_unicode=True, width=100))


def _parse_results(model, results, source):
    if not isinstance(results, dict):
        raise DescriptionError(f"expected a mapping, got {brief(results)}", entry='results',
                               source=source)
    for key in results:
        if not isinstance(key, str):
            raise DescriptionError(f"expected names of results as keys, got {brief(key)}",
                                   entry='results', source=source)
    symbols, functions = model.result_symbols(results)
    parser = ExpressionParser(symbols, functions=functions, max_length=MAX_RESULT_LENGTH)
    parsed = {}
    for key, value in results.items():
        if key.endswith('_latex') or key.endswith('_text') or key == 'state_variables':
            parsed[key] = value
        elif isinstance(value, list):
            parsed[key] = [parser.parse(v, entry=f"results.{key}[{i}]")
                           for i, v in enumerate(value)]
        else:
            parsed[key] = parser.parse(value, entry=f"results.{key}")
    return parsed
