"""The term order chosen by trying (``fastest_order``) does not depend on
the machine's load: the candidates get budgets of processor time, not of
the clock. Under a loaded test run a candidate that needs a fraction of a
second of computing once lost its slot on the clock, and the order chosen
instead made a later step run for over half an hour.

A busy machine is simulated by a child that waits (sleeps) before it
computes: it takes longer on the clock, not more processor time."""
import time

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
