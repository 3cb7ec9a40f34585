r"""
Quantifier elimination over the reals

Deciding stability by the Routh--Lyapunov method asks whether *some*
choice of free multipliers makes a quadratic form definite: a formula
`\exists \lambda:\ f_1(\lambda, a) > 0 \wedge \dots \wedge f_k(\lambda, a) > 0`
whose quantifier must be eliminated to get conditions on the parameters
`a` alone. Likewise the parameters for which an implicit solution set has a
real point: `\exists x:\ g_1(x, a) = 0 \wedge \dots`.

:func:`exists` does this

- in closed form when a single quantified variable occurs in a single
  condition, to degree at most 2 (`A\lambda^2 + B\lambda + C > 0` has a
  solution iff `A > 0`, or `A < 0` and `B^2 - 4AC > 0`, or `A = 0` and
  (`B \ne 0` or `C > 0`));
- otherwise with QEPCAD B (cylindrical algebraic decomposition; the
  ``passagemath-qepcad`` package ships the program), run as a separate
  process with a time limit.

The result is a disjunction of conjunctions: a list of alternatives, each a
list of relationals (``[]`` is "always", an empty list of alternatives is
"never").

EXAMPLES::

    sage: from sage_dynsym.algebra.quantifier_elimination import exists
    sage: l, a, b = var('l a b')
    sage: exists([l], [a*l^2 + b*l + 1 > 0, l*a - b < 0, l > 0], positive=[a])
    [[b > 0]]
    sage: exists([l], [1 - l^2 > 0, a - l > 0])
    [[a + 1 > 0]]
    sage: exists([l], [-l^2 - 1 > 0])
    []

REFERENCES:

- G. E. Collins, H. Hong, *Partial cylindrical algebraic decomposition for
  quantifier elimination*, J. Symbolic Comput. 12 (1991) 299--328.
- C. W. Brown, *QEPCAD B: a program for computing with semi-algebraic sets
  using CADs*, ACM SIGSAM Bulletin 37 (2003) 97--108.
"""
import math
import re
import signal
import shlex
import subprocess

from sage.misc.misc_c import prod
from sage.misc.verbose import verbose
from sage.rings.integer_ring import ZZ
from sage.rings.rational_field import QQ
from sage.symbolic.ring import SR

from ..arguments import expression_list
from ..errors import AnalysisError
from .conditions import simplify_conjunction
from .translation import Translation

__all__ = ['QEPCAD_TIMEOUT', 'QEPCAD_WALL_FACTOR', 'QEPCAD_MEMCELLS', 'QEPCAD_ANSWERS_KEPT', 'exists', 'exists_real_solution']

#: Time limit of one QEPCAD run: seconds of its processor time, so that
#: whether a question is decided does not depend on the machine's load.
QEPCAD_TIMEOUT = 60

#: A QEPCAD run is also stopped after this many times its time limit in
#: wall-clock seconds (a process that waits instead of computing).
QEPCAD_WALL_FACTOR = 10

#: Memory cells given to QEPCAD (its garbage-collected space).
QEPCAD_MEMCELLS = 20_000_000

#: How many QEPCAD answers are remembered (by their input script).
QEPCAD_ANSWERS_KEPT = 512

# QEPCAD's printed answer (or the time limit it ran out of) for each input
# script: the stability regions of the solutions of one model ask the same
# emptiness questions many times (the two covers of SO(3) by Euler angles
# give each orientation twice), each up to QEPCAD's time limit. The
# script names its variables x0, x1, ...: the answer is read back with the
# symbols of the question being asked, not of the one remembered.
_answers = {}

_OPS = {'>': '>', '<': '<', '>=': '>=', '<=': '<=', '==': '=', '!=': '/='}


def _relation_parts(condition):
    c = SR(condition)
    if not c.is_relational():
        return c, '>'
    name = {'gt': '>', 'lt': '<', 'ge': '>=', 'le': '<=', 'eq': '==', 'ne': '!='}
    op = c.operator().__name__
    return c.lhs() - c.rhs(), name[op]


def exists(quantified, conditions, positive=(), timeout=QEPCAD_TIMEOUT):
    r"""
    Eliminate `\exists` ``quantified`` from the conjunction of
    ``conditions``.

    INPUT:

    - ``quantified`` -- list of symbols
    - ``conditions`` -- list of relationals (or expressions, meaning ``> 0``),
      rational in their symbols (other parts are atoms)
    - ``positive`` -- symbols declared positive (assumed)
    - ``timeout`` -- seconds of processor time allowed to QEPCAD

    OUTPUT: a list of alternatives, each a list of relationals in the
    remaining symbols

    Raises :class:`~sage_dynsym.errors.AnalysisError` when QEPCAD is not
    available, fails or runs out of time.

    EXAMPLES::

        sage: from sage_dynsym.algebra.quantifier_elimination import exists
        sage: l, a = var('l a')
        sage: exists([l], [l^2 - a > 0])          # closed form
        [[]]
        sage: exists([l], [a - l^2 > 0])
        [[a > 0]]
        sage: exists([l], [a*l - 1 > 0, l > 0], positive=[])   # QEPCAD
        [[a > 0]]
    """
    quantified = expression_list(quantified, "quantified", AnalysisError, names=True)
    parts = [_relation_parts(c) for c in expression_list(
        conditions, "conditions", AnalysisError, expected="a list of relations such as a > 0")]
    qnames = {str(v) for v in quantified}
    involved = [(e, op) for e, op in parts if any(str(v) in qnames for v in e.variables())]
    outside = [(e, op) for e, op in parts if (e, op) not in involved]
    used = {str(v) for e, _ in involved for v in e.variables()} & qnames
    if not involved:
        return _simplified_alternatives([[_relational(e, op) for e, op in outside]], positive)
    if len(used) == 1 and len(involved) == 1 and involved[0][1] == '>':
        closed = _closed_form(involved[0][0], SR.var(used.pop()), positive)
        if closed is not None:
            rest = [_relational(e, op) for e, op in outside]
            return _simplified_alternatives([alt + rest for alt in closed], positive)
    return _qepcad(quantified, parts, positive, timeout)


def _relational(e, op):
    return {'>': e > 0, '<': e < 0, '>=': e >= 0, '<=': e <= 0, '==': e == 0,
            '!=': e != 0}[op]


def _closed_form(f, v, positive):
    r"""`\exists v: f > 0` for `f` of degree at most 2 in `v`, or ``None``."""
    T = Translation([], [], extra=[f])
    fr = T.fraction(f)
    num, den = fr.numerator(), fr.denominator()
    g = T.flat_ring()(num * den)       # same sign as f
    gen = T.flat_ring()(T.fraction(v))
    if g.degree(gen) > 2 or den.degree(T.fraction(v).numerator()) > 0:
        return None
    c = [T.symbolic(g.coefficient({gen: k})) for k in range(3)]
    C, B, A = c
    if A.is_zero():
        return [[B != 0], [B == 0, C > 0]]
    return [[A > 0], [A < 0, B ** 2 - 4 * A * C > 0], [A == 0, B != 0], [A == 0, B == 0, C > 0]]


def _simplified_alternatives(alternatives, positive):
    r"""Simplify each conjunction; drop impossible ones; ``[[]]`` if one
    always holds."""
    result = []
    for alt in alternatives:
        simple = simplify_conjunction(alt, positive)
        if simple is None:
            continue
        if not simple:
            return [[]]
        if simple not in result:
            result.append(simple)
    return result


# ---------------------------------------------------------------------------
# QEPCAD
# ---------------------------------------------------------------------------

def _qepcad_command():
    try:
        from sage.interfaces.qepcad import _qepcad_cmd
        return _qepcad_cmd(QEPCAD_MEMCELLS)
    except Exception as err:      # the feature check raises various errors
        raise AnalysisError("quantifier elimination needs QEPCAD (install "
                            f"passagemath-qepcad): {err}", entry="exists") from err


def _qepcad_polynomial(poly):
    r"""A polynomial over `\QQ` in QEPCAD's input syntax, scaled by a
    positive integer to have integer coefficients."""
    if poly.is_constant():
        return str(ZZ(QQ(poly.constant_coefficient()) * QQ(poly.constant_coefficient()).denominator()))
    scale = prod((QQ(c).denominator() for c in poly.coefficients()), ZZ(1))
    poly = poly * scale
    names = [str(g) for g in poly.parent().gens()]
    terms = []
    for exps, c in sorted(poly.dict().items(), reverse=True):
        exps = (exps,) if isinstance(exps, int) else exps
        factors = [f"{names[k]}^{e}" if e > 1 else names[k] for k, e in enumerate(exps) if e]
        c = ZZ(c)
        sign = '-' if c < 0 else '+'
        mag = abs(c)
        body = ' '.join(([str(mag)] if mag != 1 or not factors else []) + factors)
        terms.append((sign, body))
    text = ('-' if terms[0][0] == '-' else '') + terms[0][1]
    for sign, body in terms[1:]:
        text += f" {sign} {body}"
    return text


def _qepcad(quantified, parts, positive, timeout):
    exprs = [e for e, _ in parts] + list(quantified)
    T = Translation([], [], extra=exprs)
    flat = T.flat_ring()
    qnames = {str(v) for v in quantified}
    params = T.parameters()
    names = [str(g) for g in flat.gens()]
    qvars = [names[k] for k, p in enumerate(params) if str(p) in qnames]
    free = [n for n in names if n not in qvars]
    atoms = []
    for e, op in parts:
        fr = T.fraction(e)
        poly = flat(fr.numerator() * fr.denominator()) if op not in ('==', '!=') \
            else flat(fr.numerator())
        atoms.append(f"{_qepcad_polynomial(poly)} {_OPS[op]} 0")
    formula = ''.join(f"(E {v})" for v in qvars) + "[ " + r" /\ ".join(atoms) + " ]"
    assume = [f"{names[k]} > 0" for k in sorted(int(n[1:]) for n in T.positive_names(positive))]
    script = "[ sage_dynsym ]\n(" + ','.join(free + qvars) + f")\n{len(free)}\n{formula}.\n"
    if assume:
        script += "assume [ " + r" /\ ".join(assume) + " ]\n"
    script += "go\ngo\ngo\nfinish\n"
    verbose(f"QEPCAD: {formula}", level=1, caller_name="exists")
    text = _qepcad_answer(script, timeout)
    symbols = {n: (T.symbolic(flat.gen(k))) for k, n in enumerate(names)}
    alternatives = _TarskiParser(text, flat, symbols).dnf()
    return _simplified_alternatives(alternatives, positive)


def _qepcad_answer(script, timeout):
    r"""QEPCAD's quantifier-free answer to ``script``, remembered; a script
    that ran out of time is not run again with a time limit no larger."""
    known = _answers.get(script)
    if known is not None and (known[0] == 'answer' or timeout <= known[1]):
        if known[0] == 'answer':
            return known[1]
        raise AnalysisError(f"QEPCAD did not finish within {known[1]} s (raise "
                            "timeout=, or simplify the problem)", entry="exists")
    if len(_answers) >= QEPCAD_ANSWERS_KEPT:
        _answers.pop(next(iter(_answers)))
    # the limit of processor time set by the shell that starts QEPCAD
    # (ulimit -t, whole seconds): the kernel stops it there
    seconds = max(1, math.ceil(timeout))
    command = ['sh', '-c', f'ulimit -t {seconds} && exec "$@"', 'sh']
    command += shlex.split(_qepcad_command())
    try:
        run = subprocess.run(command, input=script, capture_output=True, text=True,
                             timeout=QEPCAD_WALL_FACTOR * seconds)
        over = run.returncode in (-signal.SIGXCPU, -signal.SIGKILL)
    except subprocess.TimeoutExpired:
        over = True
    if over:
        _answers[script] = ('timeout', timeout)
        raise AnalysisError(f"QEPCAD did not finish within {timeout} s (raise "
                            "timeout=, or simplify the problem)", entry="exists")
    match = re.search(r"An equivalent quantifier-free formula:\s*(.*?)\s*=+\s+The End",
                      run.stdout, re.S)
    if match is None:
        tail = (run.stdout + run.stderr).strip().splitlines()[-3:]
        raise AnalysisError("QEPCAD failed: " + ' | '.join(tail), entry="exists")
    _answers[script] = ('answer', ' '.join(match.group(1).split()))
    return _answers[script][1]


class _TarskiParser:
    r"""Parse QEPCAD's quantifier-free output (atoms ``P op 0`` joined by
    ``/\``, ``\/``, ``~`` and brackets; ``TRUE``, ``FALSE``) into a
    disjunctive normal form of symbolic relationals."""

    _TOKEN = re.compile(r"\s*(/\\|\\/|~|\[|\]|TRUE|FALSE|<=|>=|/=|=|<|>|[^\[\]~<>=/\\]+)")

    def __init__(self, text, ring, symbols):
        self._tokens = [t for t in self._TOKEN.findall(text) if t.strip()]
        self._pos = 0
        self._ring = ring
        self._symbols = symbols

    def dnf(self):
        result = self._disjunction()
        if self._pos != len(self._tokens):
            raise AnalysisError("cannot read QEPCAD's answer near "
                                f"{' '.join(self._tokens[self._pos:self._pos + 5])}",
                                entry="exists")
        return result

    def _peek(self):
        return self._tokens[self._pos] if self._pos < len(self._tokens) else None

    def _take(self):
        t = self._peek()
        self._pos += 1
        return t

    def _disjunction(self):
        alts = self._conjunction()
        while self._peek() == '\\/':
            self._take()
            alts = alts + self._conjunction()
        return alts

    def _conjunction(self):
        alts = self._unary()
        while self._peek() == '/\\':
            self._take()
            right = self._unary()
            alts = [a + b for a in alts for b in right]
        return alts

    def _unary(self):
        t = self._take()
        if t == '~':
            return _negate(self._unary())
        if t == '[':
            inner = self._disjunction()
            if self._take() != ']':
                raise AnalysisError("unbalanced brackets in QEPCAD's answer", entry="exists")
            return inner
        if t == 'TRUE':
            return [[]]
        if t == 'FALSE':
            return []
        op = self._take()
        right = self._take()
        if op not in ('<', '>', '<=', '>=', '=', '/=') or right is None:
            raise AnalysisError(f"cannot read the atom {t} {op} {right} of QEPCAD's answer",
                                entry="exists")
        lhs = self._polynomial(t) - self._polynomial(right)
        ops = {'<': '<', '>': '>', '<=': '<=', '>=': '>=', '=': '==', '/=': '!='}
        return [[_relational(lhs, ops[op])]]

    def _polynomial(self, text):
        total = SR(0)
        for sign, term in re.findall(r"([+-]?)\s*([^+-]+)", text.strip()):
            value = SR(1)
            for factor in term.split():
                base, _, power = factor.partition('^')
                if re.fullmatch(r"\d+(/\d+)?", base):
                    b = SR(QQ(base))
                elif base in self._symbols:
                    b = self._symbols[base]
                else:
                    raise AnalysisError(f"unknown symbol {base!r} in QEPCAD's answer",
                                        entry="exists")
                value *= b ** (ZZ(power) if power else 1)
            total += -value if sign == '-' else value
        return total


def _negate(alternatives):
    r"""Negation of a DNF, as a DNF (De Morgan, distributed)."""
    flip = {'>': '<=', '<': '>=', '>=': '<', '<=': '>', '==': '!=', '!=': '=='}
    result = [[]]
    for alt in alternatives:
        options = []
        for c in alt:
            e, op = _relation_parts(c)
            options.append(_relational(e, flip[op]))
        if not options:
            return []
        result = [r + [o] for r in result for o in options]
    return result


def exists_real_solution(translation, prime, positive=(), timeout=QEPCAD_TIMEOUT):
    r"""
    Conditions on the parameters for the component ``prime`` (an ideal of
    ``translation.ring()``) to have a real point: a list of relationals,
    ``None`` if it never has one.

    Raises :class:`~sage_dynsym.errors.AnalysisError` when the conditions
    are not a single conjunction or cannot be computed.

    EXAMPLES::

        sage: from sage_dynsym.algebra.translation import Translation
        sage: from sage_dynsym.algebra.quantifier_elimination import exists_real_solution
        sage: x, a = var('x a')
        sage: T = Translation([x^4 - a], [x])
        sage: exists_real_solution(T, T.ring().ideal(T.equations()))
        [a >= 0]
    """
    unknowns = [SR.var(f"qe_unknown{k}") for k in range(translation.ring().ngens())]
    subs = {g: u for g, u in zip(translation.ring().gens(), unknowns)}
    relations = [translation.symbolic(g, subs) == 0 for g in prime.gens()]
    alternatives = exists(unknowns, relations, positive, timeout)
    if not alternatives:
        return None
    if len(alternatives) > 1:
        raise AnalysisError(f"the solution is real under one of several sets of "
                            f"conditions: {alternatives}", entry="exists_real_solution")
    return alternatives[0]
