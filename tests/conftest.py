"""pytest set-up: Sage must be fully initialised before sage_dynsym is used."""
import sage.all  # noqa: F401


def slow_except(values, fast, ids=None):
    r"""The parameters ``values`` for ``pytest.mark.parametrize``, all but
    those in ``fast`` marked slow: ``make test`` runs the ``fast`` ones,
    ``make test-slow`` (CI) the others. ``ids`` names a value."""
    import pytest
    return [pytest.param(v, marks=() if v in fast else pytest.mark.slow,
                         id=ids(v) if ids else None) for v in values]
