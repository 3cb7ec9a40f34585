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
import sage.all  # noqa: F401
import os
import sys

import yaml

from .errors import DescriptionError, DynSymError, brief
from .io.expressions import ExpressionParser
from .io.fields import MAX_RESULT_LENGTH, title  # noqa: F401
from .io.files import write_atomically
from .io.yaml import read_yaml
from .mechanics.description import mechanical_system_from_dict, mechanical_system_to_dict  # noqa: F401


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
    try:
        return _load(path, results, source)
    except DynSymError as err:
        raise err if err.source else err.with_context(source=source) from None
    except RecursionError:
        raise DescriptionError("the description is nested too deeply to be read",
                               source=source) from None
    except MemoryError:
        raise DescriptionError("not enough memory to read the description",
                               source=source) from None
    except Exception as err:    # a failure inside Sage: still the package's error
        raise DescriptionError(f"could not build the model ({type(err).__name__}: "
                               f"{brief(str(err))})", source=source) from None


def _formats():
    r"""The description formats, by the ``kind`` of the file: functions
    that build a model from the mapping (the models of each kind are in
    layers below this module, which is the only place that knows them
    all)."""
    from .circuits.description import circuit_from_dict
    from .lie.description import lie_poisson_from_dict
    return {'mechanical': mechanical_system_from_dict, 'circuit': circuit_from_dict,
            'lie_poisson': lie_poisson_from_dict}


def model_from_dict(data, source=None):
    r"""
    The model of a description mapping, by its ``kind``.

    EXAMPLES::

        sage: from sage_dynsym.description import model_from_dict
        sage: model_from_dict({'kind': 'circuit', 'branches': [[1, 2, 'L1'], [2, 1, 'C1']]})
        Circuit with 2 branches on 2 nodes
        sage: model_from_dict({'kind': 'hydraulic'}, 'h.yaml')
        Traceback (most recent call last):
        ...
        DescriptionError: h.yaml: kind: expected one of 'mechanical', 'circuit', 'lie_poisson', got 'hydraulic'
    """
    if not isinstance(data, dict):
        raise DescriptionError(f"a description file holds a mapping of keys, got "
                               f"{type(data).__name__}", source=source)
    kind = data.get('kind')
    formats = _formats()
    if not isinstance(kind, str) or kind not in formats:
        raise DescriptionError(f"expected one of {', '.join(map(repr, formats))}, got "
                               f"{brief(kind)}", entry='kind', source=source)
    return formats[kind](data, source)


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
    """
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
