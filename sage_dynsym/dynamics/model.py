r"""
Models: the common interface of mechanical systems, circuits and systems on
Lie algebras

Everything that consumes a model -- description files, reports, the
interactive pages -- talks to it through this small interface instead of
asking for its class:

- :attr:`Model.kind`: the ``kind`` of its description file
  (``'mechanical'``, ``'circuit'``, ``'lie_poisson'``);
- :meth:`Model.name`, :meth:`Model.parameters`;
- :meth:`Model.equations`: its equations of motion;
- :meth:`Model.characteristic_functions`: the characteristic functions it
  has, by name -- a Lagrangian only where one exists (a nonlinear circuit
  has a mixed potential instead, a Lie--Poisson system a Hamiltonian only);
- :meth:`Model.to_dict`: its description mapping (what ``save`` writes);
- :meth:`Model.results`: the ``results:`` section of a saved description,
  and :meth:`Model.result_symbols`, the names such a section may use.

EXAMPLES::

    sage: from sage_dynsym import load
    sage: from sage_dynsym.description import example_path
    sage: from sage_dynsym.dynamics.model import Model
    sage: S = load(example_path('spherical_pendulum.yaml'))
    sage: isinstance(S, Model), S.kind
    (True, 'mechanical')
    sage: sorted(S.characteristic_functions())
    ['hamiltonian', 'lagrangian']
    sage: C = load(example_path('nonlinear_circuit.yaml'))
    sage: C.kind, sorted(C.characteristic_functions())
    ('circuit', ['mixed_potential'])
"""
from sage.structure.sage_object import SageObject


class Model(SageObject):
    r"""
    Base class of the models (see the module documentation). Subclasses
    set :attr:`kind` and implement :meth:`equations`, :meth:`to_dict`,
    :meth:`characteristic_functions` and :meth:`results`.

    EXAMPLES::

        sage: from sage_dynsym.dynamics.model import Model
        sage: Model().equations()
        Traceback (most recent call last):
        ...
        NotImplementedError: <abstract method equations>
    """
    #: The ``kind`` of the model's description file.
    kind = None

    def name(self):
        r"""The model's name (``None`` if it has none).

        EXAMPLES::

            sage: from sage_dynsym.dynamics.model import Model
            sage: Model().name() is None
            True
        """
        return getattr(self, '_name', None)

    def parameters(self):
        r"""The declared parameters (``None`` when they were not declared).

        EXAMPLES::

            sage: from sage_dynsym.dynamics.model import Model
            sage: Model().parameters() is None
            True
        """
        return getattr(self, '_parameters', None)

    def positive_parameters(self):
        r"""
        The parameters declared positive (``positive=`` or the ``positive:``
        key of a description file); the analysis assumes no other sign.

        EXAMPLES::

            sage: from sage_dynsym import load
            sage: from sage_dynsym.description import example_path
            sage: load(example_path('spherical_pendulum.yaml')).positive_parameters()
            [m, l, g]
        """
        return list(getattr(self, '_positive', []))

    def equations(self):
        r"""The equations of motion of the model.

        EXAMPLES: see the subclasses.
        """
        raise NotImplementedError("<abstract method equations>")

    def characteristic_functions(self):
        r"""
        The characteristic functions the model has: a dict from names
        (``'lagrangian'``, ``'hamiltonian'``, ``'mixed_potential'``, ...)
        to functions of no argument that build them.

        EXAMPLES: see the module documentation.
        """
        raise NotImplementedError("<abstract method characteristic_functions>")

    def to_dict(self):
        r"""The description mapping of the model (what ``save`` writes).

        EXAMPLES: see the subclasses.
        """
        raise NotImplementedError("<abstract method to_dict>")

    def results(self):
        r"""
        The ``results:`` section of a saved description: characteristic
        functions and equations as text, with their LaTeX forms.

        EXAMPLES: see the subclasses.
        """
        raise NotImplementedError("<abstract method results>")

    def result_symbols(self, results):
        r"""
        The symbol names and function names a ``results:`` section of this
        model may use (to parse it back), a pair of lists.

        EXAMPLES: see the subclasses.
        """
        raise NotImplementedError("<abstract method result_symbols>")
