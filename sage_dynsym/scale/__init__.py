r"""
Scale-out: stability maps and parameter sweeps on Dask

The symbolic work of the package fits one machine; what comes next often
does not: a stability diagram is the characteristic roots at `10^5` to
`10^8` parameter points, a robustness study a sweep of simulations. This
subpackage cuts such computations into chunks that run as tasks of
``dask.distributed`` -- a local cluster of processes by default, any Dask
scheduler when there is one, or plain NumPy in this process:

- :func:`~sage_dynsym.scale.maps.stability_map` -- the stability of a linear
  system over a grid or random samples of parameters, a
  :class:`~sage_dynsym.scale.maps.StabilityMap`;
- :func:`~sage_dynsym.scale.sweeps.sweep` -- any function of the parameters
  (or a model's simulation) over the same kind of points, a
  :class:`~sage_dynsym.scale.sweeps.Sweep`;
- :func:`~sage_dynsym.scale.equilibria.equilibrium_census` -- the census
  of the equilibria over the parameters, its sample points solved in
  Dask's process pool when the work is large.

See :mod:`sage_dynsym.scale.cluster` for where the chunks run.

The names are imported on first use: the command line
(:mod:`sage_dynsym.scale.cli`) parses its arguments, and answers
``--help``, without loading Sage.
"""
from ..errors import lazy_face

_SOURCE = {'stability_map': '.maps', 'StabilityMap': '.maps', 'model_linear_system': '.maps',
           'sweep': '.sweeps', 'Sweep': '.sweeps', 'stability_class': '.kernel',
           'equilibrium_census': '.equilibria'}

__all__ = list(_SOURCE)

__getattr__, __dir__ = lazy_face(__name__, _SOURCE)
del lazy_face
