r"""
The interactive pages of the worksheets

- :func:`system_builder` -- enter a model in form fields, see its
  equations, save it (:class:`~sage_dynsym.interact.builder.SystemBuilder`);
- :func:`equations_explorer` -- choose the form of the equations (Lagrange,
  Routh with chosen cyclic coordinates, Hamilton; Brayton--Moser and the
  loop / node Lagrangians for circuits) and see it as LaTeX;
- the stability explorer is
  :meth:`~sage_dynsym.interact.stability.StabilityStudy.explorer`.

All are built on Sage's ``@interact`` (``sage_interactive``) and ipywidgets;
in a Jupyter notebook with the SageMath kernel, display the returned widget
(or make it the last expression of a cell).

EXAMPLES::

    sage: from sage_dynsym import load
    sage: from sage_dynsym.description import example_path
    sage: from sage_dynsym.interact.pages import equations_explorer
    sage: w = equations_explorer(load(example_path('spherical_pendulum.yaml')))
    ...Lagrange equations of spherical pendulum
    <IPython.core.display.Math object>
    sage: [c.description for c in w.kwargs_widgets]
    ['form', 'cyclic']
    sage: w.kwargs_widgets[0].value = 'Routh'   # the page is redrawn
    ...Routh equations of spherical pendulum
    <IPython.core.display.Math object>
    sage: w = equations_explorer(load(example_path('rlc_ladder.yaml')))
    ...Brayton-Moser equations of RLC ladder with three sections
    <IPython.core.display.Math object>
    sage: [c.description for c in w.kwargs_widgets]
    ['form']
"""
from ..dynamics.model import Model
from ..errors import DynSymError

__all__ = ['equations_explorer', 'system_builder']


def equations_explorer(model):
    r"""
    The equations-explorer page for ``model`` (a mechanical system, a
    circuit or a Lagrangian): a choice of form and of the cyclic
    coordinates for Routh's form.

    OUTPUT: the interactive widget

    EXAMPLES: a Lagrangian given directly (the page is drawn once)::

        sage: from sage_dynsym import Lagrangian
        sage: from sage_dynsym.symbols import velocity
        sage: from sage_dynsym.interact.pages import equations_explorer
        sage: x, m, k = var('x m k')
        sage: w = equations_explorer(Lagrangian(m*velocity(x)^2/2 - k*x^2/2, [x]))
        ...Lagrange equations of the model
        <IPython.core.display.Math object>
        sage: w.kwargs_widgets[0].options
        ('Lagrange', 'Routh', 'Hamilton')
    """
    import ipywidgets as W
    from IPython.display import display, Math
    from sage.repl.ipython_kernel.interact import sage_interactive
    from .forms import derive, derivation_latex, equation_forms
    forms = list(equation_forms(model))
    coordinates = []
    if 'Routh' in forms:            # a Lagrangian form: the choice of cyclic coordinates
        L = model.characteristic_functions()['lagrangian']() if isinstance(model, Model) \
            else model
        coordinates = [str(q) for q in L.coordinates()]
        cyclic = [str(q) for q in L.cyclic_coordinates()]
    name = (model.name() if isinstance(model, Model) else None) or 'the model'
    controls = {'form': W.ToggleButtons(options=forms, value=forms[0], description='form')}
    if coordinates:
        controls['cyclic'] = W.SelectMultiple(options=coordinates, value=cyclic,
                                              description='cyclic', rows=min(4, len(coordinates)))

    def page(form, **cyclic_choice):     # no cyclic control without a Routh form
        cyclic = cyclic_choice.get('cyclic', ())
        print(f"{form} equations of {name}")
        try:
            d = derive(model, form, cyclic=cyclic)
        except DynSymError as err:
            print(f"not available: {err}")
            return
        if d.note:
            print(d.note)
        display(Math(derivation_latex(d)))

    return sage_interactive(page, **controls)


def system_builder():
    r"""
    The system-builder page (a new
    :class:`~sage_dynsym.interact.builder.SystemBuilder`'s widget).

    EXAMPLES::

        sage: from sage_dynsym.interact.pages import system_builder
        sage: system_builder()
        VBox(children=(ToggleButtons(...
    """
    from .builder import SystemBuilder
    builder = SystemBuilder()
    builder.derive()
    return builder.widget
