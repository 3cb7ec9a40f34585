r"""
Models: the interface every kind of model implements

Everything that consumes a model -- description files, reports, stability
maps, the command line, the interactive pages -- talks to it through this
interface and never asks for its class (``isinstance``, ``hasattr`` or a
test of its ``kind``). A kind of model is a subclass of :class:`Model`
registered under its :attr:`~Model.kind` (see
:func:`sage_dynsym.description.kinds`); what it provides:

- identity: :attr:`Model.kind`, :meth:`Model.name`, :meth:`Model.parameters`,
  :meth:`Model.positive_parameters` (the only signs the analysis may use);
- its description format, both ways, in one place: the class method
  :meth:`Model.from_dict` and :meth:`Model.to_dict`; the ``results:``
  section of a saved file: :meth:`Model.results` and
  :meth:`Model.result_symbols`;
- its equations: :meth:`Model.equations`, and
  :meth:`Model.equations_record`, the neutral record
  (:mod:`sage_dynsym.analysis.motion`) that the analysis and the numerics
  read; :meth:`Model.characteristic_functions`; :meth:`Model.equation_forms`
  (the classical forms of the equations, for pages and worksheets);
- :meth:`Model.free_linear_system`: the linear system with the sources
  switched off, whose stability :func:`~sage_dynsym.scale.maps.stability_map`
  maps;
- :meth:`Model.report_title` and :meth:`Model.report_sections`: the
  sections of its report
  (:class:`~sage_dynsym.dynamics.reporting.ReportSection`, each with an
  estimate of its size and the results of earlier sections it needs), run
  by the one section runner
  (:func:`~sage_dynsym.dynamics.reporting.report_blocks`) within one budget.

EXAMPLES::

    sage: from sage_dynsym import load
    sage: from sage_dynsym.description import example_path
    sage: from sage_dynsym.dynamics.model import Model
    sage: S = load(example_path('spherical_pendulum.yaml'))
    sage: isinstance(S, Model), S.kind
    (True, 'mechanical')
    sage: sorted(S.characteristic_functions())
    ['hamiltonian', 'lagrangian']
    sage: S.equations_record()
    Second-order equations in (psi, theta): ...
    sage: C = load(example_path('nonlinear_circuit.yaml'))
    sage: C.kind, sorted(C.characteristic_functions())
    ('circuit', ['mixed_potential'])
"""
from sage.structure.sage_object import SageObject

from ..numerics.methods import NumericalMethods

__all__ = ['Model', 'linearization_point']


class Model(SageObject):
    r"""
    Base class of the kinds of models (see the module documentation).
    Subclasses set :attr:`kind` and implement the methods that raise
    ``NotImplementedError`` here.

    EXAMPLES::

        sage: from sage_dynsym.dynamics.model import Model
        sage: Model().equations()
        Traceback (most recent call last):
        ...
        NotImplementedError: <abstract method equations>
    """
    #: The ``kind`` of the model's description file (its registry name).
    kind = None

    # -- identity --------------------------------------------------------

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

    # -- the description format -------------------------------------------

    @classmethod
    def from_dict(cls, data, source=None):
        r"""
        The model of a description mapping of this kind (what a description
        file holds); ``source`` names the file in errors.

        EXAMPLES: see the subclasses.
        """
        raise NotImplementedError("<abstract method from_dict>")

    def to_dict(self):
        r"""The description mapping of the model (what ``save`` writes);
        :meth:`from_dict` reads it back.

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

    # -- equations ---------------------------------------------------------

    def equations(self):
        r"""The equations of motion of the model.

        EXAMPLES: see the subclasses.
        """
        raise NotImplementedError("<abstract method equations>")

    def equations_record(self):
        r"""
        The equations as a neutral record of
        :mod:`sage_dynsym.analysis.motion` (what the analysis and the
        numerics read).

        EXAMPLES: see the module documentation.
        """
        raise NotImplementedError("<abstract method equations_record>")

    #: the name of earlier versions, written once for all models
    to_linearizer = NumericalMethods.to_linearizer

    def characteristic_functions(self):
        r"""
        The characteristic functions the model has: a dict from names
        (``'lagrangian'``, ``'hamiltonian'``, ``'mixed_potential'``, ...)
        to functions of no argument that build them.

        EXAMPLES: see the module documentation.
        """
        raise NotImplementedError("<abstract method characteristic_functions>")

    def equation_forms(self):
        r"""
        The classical forms of the model's equations: a dict from the
        name of each form (in the order a page offers them) to a function
        building its :class:`~sage_dynsym.dynamics.derivations.Derivation`
        (the keyword ``cyclic`` names the cyclic coordinates of a Routh
        form).

        EXAMPLES: see the subclasses and
        :mod:`~sage_dynsym.dynamics.derivations`.
        """
        raise NotImplementedError("<abstract method equation_forms>")

    # -- analysis and reports ----------------------------------------------

    def free_linear_system(self, at=None):
        r"""
        The linear system of the model with its sources switched off,
        around the state ``at`` (a dict; default: the zero state, or the
        model's own reference state): a
        :class:`~sage_dynsym.analysis.linear.LinearSystem`, what
        :func:`~sage_dynsym.scale.maps.stability_map` maps.

        EXAMPLES: see the subclasses.
        """
        raise NotImplementedError("<abstract method free_linear_system>")

    def report_title(self):
        r"""The heading of the model's report (one line).

        EXAMPLES: see the subclasses.
        """
        raise NotImplementedError("<abstract method report_title>")

    def report_sections(self):
        r"""
        The sections of the model's report, in the order they are printed:
        a list of :class:`~sage_dynsym.dynamics.reporting.ReportSection`.

        EXAMPLES: see the subclasses.
        """
        raise NotImplementedError("<abstract method report_sections>")

    # -- invariants, run by ``TestSuite`` -----------------------------------

    def _test_description(self, **options):
        r"""The description mapping reads back to the same description, and
        the signs declared are of parameters of the model.

        EXAMPLES: run by ``TestSuite(model).run()`` (see the subclasses).
        """
        tester = self._tester(**options)
        data = self.to_dict()
        tester.assertEqual(type(self).from_dict(data).to_dict(), data)
        # parameters() is None where none were declared (then any symbol)
        if self.parameters() is not None:
            tester.assertLessEqual(set(self.positive_parameters()), set(self.parameters()))

    def _test_pickling(self, **options):
        r"""Models compare by identity (two loads of a file are two
        models), so the pickled copy is compared by its description.

        EXAMPLES: run by ``TestSuite(model).run()`` (see the subclasses).
        """
        from sage.misc.persist import dumps, loads
        tester = self._tester(**options)
        tester.assertEqual(loads(dumps(self)).to_dict(), self.to_dict())


def linearization_point(at, variables, what="state variable"):
    r"""
    The point of a :meth:`Model.free_linear_system`: every variable 0,
    then the values of ``at`` (a dict over ``variables``, symbols or their
    names); a name that is not one of ``variables`` is refused before any
    work.

    INPUT:

    - ``at`` -- a dict or ``None``
    - ``variables`` -- the state variables (or coordinates) of the system
    - ``what`` -- (default: ``"state variable"``) what they are, for the
      message

    EXAMPLES::

        sage: from sage_dynsym.dynamics.model import linearization_point
        sage: x, y = var('x y')
        sage: linearization_point({'y': 1}, [x, y])
        {x: 0, y: 1}
        sage: linearization_point({var('z'): 1}, [x, y], what="coordinate")
        Traceback (most recent call last):
        ...
        AnalysisError: at: z is not a coordinate of the model; the coordinates are x, y
        sage: linearization_point(0, [x, y])
        Traceback (most recent call last):
        ...
        AnalysisError: at: expected a dict {state variable: value}, got 0
    """
    from sage.symbolic.ring import SR
    from ..arguments import known_symbols
    from ..errors import AnalysisError, brief
    if not isinstance(at, (dict, type(None))):
        raise AnalysisError(f"expected a dict {{{what}: value}}, got {brief(at)}", entry="at")
    at = at or {}
    keys = known_symbols(list(at), list(variables), 'at', error=AnalysisError, what=what)
    point = {v: SR(0) for v in variables}
    point.update({k: SR(v) for k, v in zip(keys, at.values())})
    return point
