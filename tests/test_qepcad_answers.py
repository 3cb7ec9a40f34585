"""QEPCAD's answers are remembered by their input script: a question asked
again is not run again, and an answer is read back with the symbols of the
question being asked (the script names its variables x0, x1, ...)."""
import shlex
import signal
import subprocess
import time

import pytest

from sage.all import var

import sage_dynsym.algebra.quantifier_elimination as qe


def test_a_question_asked_again_is_not_run_again(monkeypatch):
    a, l = var('a l')
    first = qe.exists([l], [a*l - 1 > 0, l > 0])
    assert first == [[a > 0]]           # l > 1/a > 0 exists iff a > 0

    def refuse(*args, **kwargs):
        raise AssertionError("QEPCAD was run again for a question already answered")
    monkeypatch.setattr(subprocess, 'run', refuse)
    assert qe.exists([l], [a*l - 1 > 0, l > 0]) == first
    # the same script in other symbols: the answer in these symbols
    b, m = var('b m')
    assert qe.exists([m], [b*m - 1 > 0, m > 0]) == [[b > 0]]


def _processor_seconds(command):
    # the limit the shell sets before it starts QEPCAD: sh -c 'ulimit -t N && ...'
    limit = command[2].split()
    return int(limit[limit.index('-t') + 1])


def test_a_question_out_of_time_is_not_run_again_with_no_more_time(monkeypatch):
    a, l = var('a l')
    calls = []

    def too_slow(command, input, timeout, **kwargs):
        # the kernel stops QEPCAD at its limit of processor time (SIGXCPU)
        calls.append(_processor_seconds(command))
        return subprocess.CompletedProcess(command, -signal.SIGXCPU, '', '')
    monkeypatch.setattr(subprocess, 'run', too_slow)
    monkeypatch.setattr(qe, '_answers', {})
    question = ([l], [a*l**2 - 3*l + a > 0, l - a > 0])
    for timeout in (5, 3):
        with pytest.raises(qe.AnalysisError, match="did not finish within 5 s"):
            qe.exists(*question, timeout=timeout)
    assert calls == [5]
    with pytest.raises(qe.AnalysisError, match="did not finish within 9 s"):
        qe.exists(*question, timeout=9)
    assert calls == [5, 9]


def test_the_time_limit_is_processor_time(monkeypatch):
    # a stand-in for QEPCAD, run under the same limit: one that computes
    # is stopped after its second of processor time, one that waits for two
    # seconds of the clock (as on a busy machine) and then answers (TRUE) is
    # not
    a, l = var('a l')
    answer = ("An equivalent quantifier-free formula:\n\nTRUE\n\n"
              "=====================  The End  =======================")
    waits = f"sleep 2; printf '%s\\n' '{answer}'"
    computes = "while :; do :; done"
    for stand_in, expected in ((waits, [[]]), (computes, None)):
        monkeypatch.setattr(qe, '_answers', {})
        monkeypatch.setattr(qe, '_qepcad_command', lambda s=stand_in: f"sh -c {shlex.quote(s)}")
        if expected is None:
            start = time.monotonic()
            with pytest.raises(qe.AnalysisError, match="did not finish within 1 s"):
                qe.exists([l], [a*l - 1 > 0, l > 0], timeout=1)
            assert time.monotonic() - start < 10 * qe.QEPCAD_WALL_FACTOR
        else:
            assert qe.exists([l], [a*l - 1 > 0, l > 0], timeout=1) == expected
