"""The global environment of ``make doctest``: Sage's own, started once.

``sage -t`` imports the module named by ``--environment`` once, in the
process that forks a child for every file, and gives each file's examples a
copy of its globals. This one is Sage's default environment plus a warm
start: every module of sage_dynsym imported and Maxima started before the
fork, so that the ~180 files do not each pay for that again (about 2.3 s a
file: the doctests take half the time). The examples and their globals are
the same as under plain ``sage -t``; each file still runs in its own fresh
child, so nothing a file does reaches another.
"""
from sage.repl.ipython_kernel.all_jupyter import *  # noqa: F401,F403


def _start():
    import importlib
    import pkgutil

    import sage_dynsym
    from sage.calculus.calculus import maxima

    from deprecated_aliases import DEPRECATED_ALIASES

    for info in pkgutil.walk_packages(sage_dynsym.__path__, 'sage_dynsym.'):
        # a deprecated alias would only warn: its module is imported anyway
        if info.name not in DEPRECATED_ALIASES:
            importlib.import_module(info.name)
    maxima.eval('1+1')


_start()
del _start
