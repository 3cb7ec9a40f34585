"""The way a solve goes does not depend on the machine's load or on an
unlucky random draw, and no way it can take runs without a bound.

- The term order chosen by trying (``fastest_order``) is the same on a
  busy machine: the candidates get budgets of processor time, not of the
  clock. A busy machine is simulated by a child that waits (sleeps) before
  it computes: it takes longer on the clock, not more processor time.
- A system solved in the order chosen gets a budget of processor time
  there, then is solved in ``degrevlex``.
- The branches of an implicit family are solved symbolically when a test
  at random values says they are radicals; the values are distinct, and
  the symbolic solve has a budget of processor time. Brun's problem on
  M.gamma = 0 drew two equal values once in about thirty runs, and the
  symbolic solve that followed ran for over half an hour (a CI run hung
  there).
"""
import time

import pytest

from sage.all import QQ, PolynomialRing, TermOrder
from sage.rings.polynomial.multi_polynomial_ideal import MPolynomialIdeal

import sage_dynsym.algebra.term_orders as term_orders


def test_a_delayed_candidate_keeps_its_place(monkeypatch):
    R = PolynomialRing(QQ, 'x, y, z', order='degrevlex')
    x, y, z = R.gens()
    I = R.ideal([x**2 + y*z - 1, y**2 - x*z, z**3 - x - y])
    original = MPolynomialIdeal.groebner_basis

    def costly_in_degrevlex(wait):
        # the ring's own order (degrevlex) first waits 2 s of the clock (as
        # if the machine were busy) or computes for 2 s; the other candidate
        # does neither
        def groebner_basis(self, *args, **kwargs):
            if self.ring().term_order().name() == 'degrevlex':
                if wait:
                    time.sleep(2)
                else:
                    start = time.process_time()
                    while time.process_time() - start < 2:
                        pass
            return original(self, *args, **kwargs)
        return groebner_basis
    monkeypatch.setattr(term_orders, 'ORDER_TRIAL_SECONDS', 1)
    lex = TermOrder('lex')
    # on the clock the ring's order would lose its 1 s and lex would be
    # chosen; in processor time it finishes well within its second
    monkeypatch.setattr(MPolynomialIdeal, 'groebner_basis', costly_in_degrevlex(wait=True))
    assert term_orders.fastest_order(I, [None, lex]) is None
    # computing for 2 s, it loses its second of processor time
    monkeypatch.setattr(MPolynomialIdeal, 'groebner_basis', costly_in_degrevlex(wait=False))
    assert term_orders.fastest_order(I, [None, lex]) == lex


def test_a_failed_trial_chooses_nothing(monkeypatch):
    # a trial that fails (an error, a crash) says nothing about the orders:
    # the ring's own order is kept, not the next candidate
    R = PolynomialRing(QQ, 'x, y', order='degrevlex')
    x, y = R.gens()
    original = MPolynomialIdeal.groebner_basis

    def failing_in_degrevlex(self, *args, **kwargs):
        if self.ring().term_order().name() == 'degrevlex':
            raise RuntimeError("a failure in the child")
        return original(self, *args, **kwargs)
    monkeypatch.setattr(MPolynomialIdeal, 'groebner_basis', failing_in_degrevlex)
    assert term_orders.fastest_order(R.ideal([x**2 - y, y**2 - x]), [None, TermOrder('lex')]) is None


def _brun_level_zero_logged(monkeypatch, **patches):
    # Brun's problem on M.gamma = 0 with symbolic coefficients, solved with
    # the attributes ``patches`` of the solver replaced; its own test checks
    # the solutions (by hand, see there); what the solver logged
    import sage_dynsym.algebra.solving as solving
    from test_stationary_noise import test_brun_symbolic_level_zero_axes_on_circles
    for name, value in patches.items():
        monkeypatch.setattr(solving, name, value)
    logged = []
    monkeypatch.setattr(solving, '_log', logged.append)
    test_brun_symbolic_level_zero_axes_on_circles()
    return logged


@pytest.mark.slow
def test_a_system_slow_in_the_order_chosen_is_solved_in_degrevlex(monkeypatch):
    # its basis takes 0.02 s in degrevlex, so the block order is never
    # chosen for it; forced into the block order, its solve runs for over a
    # quarter of an hour there. Over CHOSEN_ORDER_SECONDS it is solved in
    # degrevlex
    logged = _brun_level_zero_logged(monkeypatch, CHOSEN_ORDER_SECONDS=5,
                                     fastest_order=lambda ideal, candidates: candidates[-1])
    assert any("not solved within 5 s of processor time in the term order matrix (cpu)" in m
               for m in logged)


@pytest.mark.slow
def test_branches_over_their_budget_stay_implicit(monkeypatch):
    # the route an unlucky draw took (the test at random values taken as
    # saying radicals): the symbolic solve of the branches of its families
    # is stopped at its budget, and the families stay implicit
    logged = _brun_level_zero_logged(monkeypatch, BRANCH_SOLVE_SECONDS=2,
                                     _radicals_at_random_values=lambda *args: True)
    assert any("branches not solved within 2 s of processor time (cpu): kept implicit" in m
               for m in logged)
