r"""
Command line: ``python -m sage_dynsym FILE [FILE ...]`` (or ``sage-dynsym``).

Loads each description file and prints its report, section by section as
each is computed: the characteristic function and equations, and the
analysis. A formula longer than a few lines is summarised (what it is, its
degree in the variable that matters, its number of terms, its leading
terms), with a pointer to its full form. Every section asked for prints a
line: its result, or why it is not there (``skipped`` over the budget, with
how to raise it; ``not available`` for the model). A bad file gives a
one-line error on standard error naming the file and the entry, never a
traceback; the other files are still reported.

Options:

- ``--sections LIST`` -- comma-separated report sections (see
  :data:`sage_dynsym.report.sections.SECTIONS`), e.g. ``lagrangian,equations``;
- ``--no-analysis`` -- leave out the analysis sections (stationary motions,
  stability, dP/dt, first integrals);
- ``--full`` -- print every formula in full;
- ``--latex`` -- print the LaTeX of every formula printed in full;
- ``--budget N`` -- the size budget of each section in polynomial terms
  (default :data:`sage_dynsym.report.sections.DEFAULT_BUDGET`): a section whose
  estimated size is larger is replaced at once by one line saying so;
- ``--time-limit S`` -- give up on a file after ``S`` seconds (one error
  line, then the next file);
- ``--progress`` -- say on standard error which section is being computed
  (the default when standard error is a terminal);
- ``-o FILE`` -- also write the reports to ``FILE``, in full: every formula
  with its LaTeX (replaced atomically; its folder must exist, which is
  checked before any report is computed).

Exit status:

- 0 -- every file was reported; a section over the budget (``skipped``:
  ``--budget`` raises it) or one the model does not have (``not
  available (...)``, e.g. a Hamiltonian of a constrained system, dP/dt of
  perfectly coupled windings) is one line saying why, and counts as
  reported;
- 1 -- some file could not be read or reported (or ``-o`` not written),
  each one line on standard error naming the file and the entry or option;
- 2 -- the command line itself is wrong (an unknown option, a bad number),
  with argparse's usage message;
- 3 -- every file was reported, but some section failed on an error that
  is not the package's own: its line says ``section failed:`` and the
  error (a defect to report).

``sage-dynsym map FILE --param NAME=LOW:HIGH:N ...`` computes a stability
map of the model on Dask instead (see :mod:`sage_dynsym.scale.cli`).
"""
import argparse
import os
import sys

from .arguments import count_option

#: Exit status of a run whose reports all printed but some section of
#: which failed on an error that is not the package's own.
INCOMPLETE = 3


def _sections(text):
    from .report.sections import SECTIONS
    keys = [k.strip() for k in text.split(",") if k.strip()]
    for key in keys:
        if key not in SECTIONS:
            raise argparse.ArgumentTypeError(f"unknown section {key!r}; the sections are: "
                                             f"{', '.join(SECTIONS)}")
    return keys


def main(argv=None):
    r"""
    Run the command line; return the exit status.

    EXAMPLES::

        sage: from sage_dynsym.__main__ import main
        sage: from sage_dynsym.description import example_path
        sage: main([example_path('spherical_pendulum.yaml')])
        == spherical pendulum ...
        0
        sage: main(['/no/such/file.yaml'])   # the message goes to standard error
        1
        sage: main([example_path('spherical_pendulum.yaml'), '-o', '/no/such/dir/out.txt'])
        sage-dynsym: error: -o: the folder /no/such/dir does not exist
        1
        sage: main([example_path('rlc_ladder.yaml'), '--sections', 'lagrangian', '--budget', '5'])
        == RLC ladder with three sections (circuit: 11 branches on 8 nodes) ==
        Lagrangian (loop-current method):
        ...
        0
        sage: main([example_path('spherical_pendulum.yaml'), '--no-analysis', '--budget', '10'])
        == spherical pendulum (mechanical system: 1 body, coordinates psi, theta) ==
        Lagrangian: skipped, the Lagrangian (...): about 16 polynomial terms, over the budget of 10 (raise it with --budget)
        0

    The ``map`` subcommand (:mod:`sage_dynsym.scale.cli`)::

        sage: main(['map', example_path('rlc_ladder.yaml'), '--param', 'X=0:1:3', '--numpy'])
        sage-dynsym: error: ...rlc_ladder.yaml: stability_map: unknown parameter X: the symbols of the system are C1, C2, C3, L1, L2, L3, R1, R2, R3, R4
        1
    """
    argv = sys.argv[1:] if argv is None else list(argv)
    if argv[:1] == ["map"]:
        from .scale.cli import main as map_main
        return map_main(argv[1:])
    from .report.sections import DEFAULT_BUDGET, SECTIONS, ANALYSIS_SECTIONS
    parser = argparse.ArgumentParser(
        prog="sage-dynsym",
        description="Derive the equations of the models in description files "
                    "(YAML) and print them with their analysis, section by section. "
                    "A formula longer than a few lines is summarised (--full prints it); "
                    "the -o file holds everything, with the LaTeX of every formula.",
        epilog="sage-dynsym map FILE --param NAME=LOW:HIGH:N ...: a stability map of the "
               "model on Dask (sage-dynsym map --help).")
    parser.add_argument("files", nargs="+", metavar="FILE", help="description files")
    parser.add_argument("-o", "--output", metavar="FILE", help="also write the full reports (every formula "
                        "in full, with its LaTeX) to this file")
    parser.add_argument("--sections", type=_sections, metavar="LIST",
                        help="comma-separated sections to print: " + ", ".join(SECTIONS)
                        + " (default: all the model has)")
    parser.add_argument("--no-analysis", action="store_true",
                        help="leave out the analysis sections ("
                             + ", ".join(ANALYSIS_SECTIONS) + ")")
    parser.add_argument("--full", action="store_true",
                        help="print every formula in full (default: a formula longer than a "
                             "few lines is summarised)")
    parser.add_argument("--latex", action="store_true",
                        help="print the LaTeX of each formula printed in full")
    parser.add_argument("--budget", type=count_option, default=DEFAULT_BUDGET, metavar="N",
                        help="size budget of each section, in polynomial terms: a section "
                             "estimated over it is skipped at once, with a line saying so "
                             f"(default: {DEFAULT_BUDGET})")
    parser.add_argument("--time-limit", type=count_option, metavar="S",
                        help="give up on a file after S seconds")
    parser.add_argument("--progress", action="store_true", default=None,
                        help="say on standard error which section is being computed "
                             "(default: when standard error is a terminal)")
    args = parser.parse_args(argv)

    def fail(path, message):
        message = " ".join(str(message).split())        # one line, whatever the error
        print(f"sage-dynsym: error: {message}", file=sys.stderr, flush=True)
        return 1

    if args.output is not None:
        folder = os.path.dirname(args.output) or '.'
        if not os.path.isdir(folder):
            return fail(args.output, f"-o: the folder {folder} does not exist")
        if os.path.isdir(args.output):
            return fail(args.output, f"-o: {args.output} is a folder, not a file")
    from .description import write_atomically
    from .errors import DynSymError, brief
    reports, status, failed = [], 0, []
    show_progress = sys.stderr.isatty() if args.progress is None else args.progress

    for path in args.files:
        written = []        # the full text of the sections printed so far (for -o)
        reports.append(written)
        printed = []        # the blocks printed so far
        try:
            _report(path, args, failed, written, printed, show_progress)
        except DynSymError as err:
            status = fail(path, err)
            continue
        except _TimeLimit:
            status = fail(path, f"{path}: gave up after {args.time_limit} s (--time-limit)")
            continue
        except KeyboardInterrupt:
            print("sage-dynsym: interrupted", file=sys.stderr)
            return 130
        except Exception as err:    # a bug or a failure inside Sage: still one line
            status = fail(path, f"{path}: unexpected {type(err).__name__}: {brief(str(err))}")
            continue
        finally:
            _progress_done(show_progress)
            if printed:     # a blank line after each report, a partial one too
                print(flush=True)
    if args.output:
        text = "\n\n".join("\n".join(lines) for lines in reports if lines)
        try:
            write_atomically(args.output, lambda s: s.write(text + "\n"))
        except DynSymError as err:
            status = fail(args.output, err)
    return status or (INCOMPLETE if failed else 0)


def _report(path, args, failed, written, printed, show_progress):
    r"""Print the report of the file ``path`` section by section, each as
    soon as it is computed (readable, or in full with ``--full``), append
    each block printed to ``printed`` and its full text, with the LaTeX, to
    ``written`` (for ``-o``). With ``--time-limit`` it is computed in a
    forked process killed after that time, which sends each block here to
    be printed: the command goes on to the next file, and a Singular or
    PARI call stopped by an alarm in this process would leave the library
    broken for it (a segfault later). A child that dies (a crash) is one
    error line too."""
    from .description import load
    from .algebra.forked import forked      # here: --help answers without loading Sage
    progress = _progress(path) if show_progress else None

    def shown(block):
        text, full = block
        _progress_done(progress is not None)
        print(text, flush=True)
        printed.append(text)
        written.extend(full)
    if not args.time_limit:
        return _blocks(load(path), args, failed, shown, progress)

    def child(send):
        failures = []
        _blocks(load(path), args, failures, send, progress)
        return failures
    _, (how, value) = forked(child, args.time_limit, receive=shown)
    if how == 'value':
        return failed.extend(value)
    if how == 'error':
        raise value
    if how == 'timeout':
        raise _TimeLimit()
    raise RuntimeError(f"the process computing the report ended without it ({value})")


def _blocks(model, args, failed, shown, progress):
    r"""Pass each block of the report of ``model``, as soon as it is
    computed, to ``shown``: a pair (its text to print, its full text with
    the LaTeX for ``-o``, empty without it)."""
    from .report.writer import report_blocks
    from .dynamics.reporting import render
    blocks = report_blocks(model, sections=args.sections, budget=args.budget,
                           analysis=not args.no_analysis, failed=failed, progress=progress)
    for block in blocks:
        shown(("\n".join(render(block, full=args.full, latex=args.latex)),
               render(block, full=True, latex=True) if args.output else []))


def _progress(path):
    r"""The progress function of the report of ``path``: a status line on
    standard error (rewritten in place on a terminal)."""
    name = os.path.basename(path)
    terminal = sys.stderr.isatty()

    def progress(step):
        message = f"sage-dynsym: {name}: computing {step} ..."
        if terminal:
            print(f"\r\033[K{message[:150]}", end="", file=sys.stderr, flush=True)
        else:
            print(message, file=sys.stderr, flush=True)
    return progress


def _progress_done(shown):
    r"""Clear the status line of :func:`_progress` on a terminal."""
    if shown and sys.stderr.isatty():
        print("\r\033[K", end="", file=sys.stderr, flush=True)


class _TimeLimit(Exception):
    pass


if __name__ == "__main__":
    sys.exit(main())
