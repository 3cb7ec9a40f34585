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
- :func:`~sage_dynsym.scale.sweep.sweep` -- any function of the parameters
  (or a model's simulation) over the same kind of points, a
  :class:`~sage_dynsym.scale.sweep.Sweep`.

See :mod:`sage_dynsym.scale.cluster` for where the chunks run.
"""
from .maps import stability_map, StabilityMap, model_linear_system
from .kernel import stability_class
from .sweep import sweep, Sweep
