r"""
Command line: ``python -m sage_dynsym FILE [FILE ...]`` (or ``sage-dynsym``).

Loads each description file and prints its report (characteristic
function and equations, as text and LaTeX). A bad file gives a one-line
error on standard error and exit status 1, never a traceback.
"""
import argparse
import sys


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
    """
    parser = argparse.ArgumentParser(
        prog="sage-dynsym",
        description="Derive the equations of the models in description files "
                    "(YAML) and print them as text and LaTeX.")
    parser.add_argument("files", nargs="+", metavar="FILE", help="description files")
    parser.add_argument("-o", "--output", help="also write the reports to this file")
    args = parser.parse_args(argv)

    from .description import load
    from .errors import DynSymError
    from .report import report
    reports, status = [], 0
    for path in args.files:
        try:
            text = report(load(path))
        except DynSymError as err:
            print(f"sage-dynsym: error: {err}", file=sys.stderr)
            status = 1
            continue
        except KeyboardInterrupt:
            print("sage-dynsym: interrupted", file=sys.stderr)
            return 130
        print(text, end="\n\n", flush=True)
        reports.append(text)
    if args.output:
        with open(args.output, "w", encoding="utf-8") as stream:
            stream.write("\n\n".join(reports) + "\n")
    return status


if __name__ == "__main__":
    sys.exit(main())
