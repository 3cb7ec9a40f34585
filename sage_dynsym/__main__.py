r"""
Command line: ``python -m sage_dynsym FILE [FILE ...]`` (or ``sage-dynsym``).

Loads each description file and prints its report (characteristic
function and equations, as text and LaTeX, and the analysis). A bad file
gives a one-line error on standard error naming the file and the entry,
never a traceback; the other files are still reported.

Options:

- ``--sections LIST`` -- comma-separated report sections (see
  :data:`sage_dynsym.report.sections.SECTIONS`), e.g. ``lagrangian,equations``;
- ``--no-analysis`` -- leave out the analysis sections (stationary motions,
  stability, dP/dt);
- ``--budget N`` -- the size budget of each section in polynomial terms
  (default :data:`sage_dynsym.report.sections.DEFAULT_BUDGET`): a section whose
  estimated size is larger is replaced by one line saying so;
- ``--time-limit S`` -- give up on a file after ``S`` seconds (one error
  line, then the next file);
- ``-o FILE`` -- also write the reports to ``FILE`` (replaced atomically;
  its folder must exist, which is checked before any report is computed).

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
    from .report.sections import DEFAULT_BUDGET
    parser = argparse.ArgumentParser(
        prog="sage-dynsym",
        description="Derive the equations of the models in description files "
                    "(YAML) and print them as text and LaTeX, with their analysis.",
        epilog="sage-dynsym map FILE --param NAME=LOW:HIGH:N ...: a stability map of the "
               "model on Dask (sage-dynsym map --help).")
    parser.add_argument("files", nargs="+", metavar="FILE", help="description files")
    parser.add_argument("-o", "--output", help="also write the reports to this file")
    parser.add_argument("--sections", type=_sections, metavar="LIST",
                        help="comma-separated sections to print: lagrangian, equations, "
                             "routh, stationary, hamiltonian, mixed_potential, "
                             "state_equations, lyapunov, stability (default: all)")
    parser.add_argument("--no-analysis", action="store_true",
                        help="leave out the analysis sections (stationary, lyapunov, "
                             "stability)")
    parser.add_argument("--budget", type=count_option, default=DEFAULT_BUDGET, metavar="N",
                        help="size budget of each section, in polynomial terms "
                             f"(default: {DEFAULT_BUDGET})")
    parser.add_argument("--time-limit", type=count_option, metavar="S",
                        help="give up on a file after S seconds")
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
    from .description import load, write_atomically
    from .errors import DynSymError, brief
    from .report import report
    reports, status, failed = [], 0, []

    for path in args.files:
        try:
            text = _with_time_limit(args.time_limit, lambda: report(
                load(path), sections=args.sections, budget=args.budget,
                analysis=not args.no_analysis, failed=failed))
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
        print(text, end="\n\n", flush=True)
        reports.append(text)
    if args.output:
        try:
            write_atomically(args.output, lambda s: s.write("\n\n".join(reports) + "\n"))
        except DynSymError as err:
            status = fail(args.output, err)
    return status or (INCOMPLETE if failed else 0)


class _TimeLimit(Exception):
    pass


def _with_time_limit(seconds, compute):
    if not seconds:
        return compute()
    from cysignals.alarm import alarm, cancel_alarm, AlarmInterrupt
    alarm(seconds)
    try:
        return compute()
    except AlarmInterrupt:
        raise _TimeLimit() from None
    finally:
        cancel_alarm()


if __name__ == "__main__":
    sys.exit(main())
