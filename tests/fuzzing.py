"""
The time limit of the property-based tests (``tests/test_reliability_fuzz*.py``).
"""
import pytest
from hypothesis import event

from sage_dynsym import DynSymError


def within(seconds):
    """
    A function ``bounded(function, *args)``: ``function(*args)``, or the
    ``DynSymError`` it raised (both recorded as a Hypothesis event); any
    other exception fails the test, and so does no answer within
    ``seconds`` (a hang).
    """
    def bounded(function, *args):
        from cysignals.alarm import alarm, cancel_alarm, AlarmInterrupt
        alarm(seconds)
        try:
            result = function(*args)
        except DynSymError as err:
            event(f"refused: {type(err).__name__}")
            return err
        except AlarmInterrupt:
            pytest.fail(f"no answer within {seconds} s" + (f" for {args!r:.300}" if args else ""))
        finally:
            cancel_alarm()
        event(f"accepted: {type(result).__name__}")
        return result
    return bounded
