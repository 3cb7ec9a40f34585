r"""
Command line: ``sage-dynsym map FILE --param NAME=LOW:HIGH:N ...``

Computes the stability map of the model of a description file (its
``linearize(model, at, sources=False)``, see
:func:`~sage_dynsym.analysis.linear.linearize`: a circuit's free state
equations around the zero state, a mechanical
model's Lagrangian around ``--at``, by default all coordinates 0) and
writes it as a picture (``PREFIX.png``) and as arrays (``PREFIX.npz``, see
:meth:`~sage_dynsym.scale.maps.StabilityMap.save`). The region of the
Liénard--Chipart conditions of the characteristic polynomial is drawn over
the map when they can be derived, and their agreement with the map is
printed; so are the shares of the three classes of the map (asymptotically
stable, stable in first approximation, unstable: see
:meth:`~sage_dynsym.scale.maps.StabilityMap.classes`) and, where the exact
classes can be derived from the characteristic polynomial, the agreement
of each class with them (off the boundaries).

Options:

- ``--param NAME=LOW:HIGH:N`` -- a parameter of the map and its range
  (once per parameter; one or two for a picture);
- ``--value NAME=VALUE`` -- the value of another symbol (every symbol of
  the system needs a value): a number or an exact constant, read by the
  package's expression reader (never evaluated): ``9.81`` is `981/100`,
  ``pi/2``, ``sqrt(2)/2``;
- ``--at NAME=VALUE`` -- the point of linearization (state variables or
  coordinates; default 0), as for ``--value``: ``--at theta=pi``. A point
  that is not an equilibrium, or where the coordinates are singular, is an
  error naming the coordinate and suggesting a point that works (see
  :mod:`~sage_dynsym.scale.equilibria`);
- ``--samples N``, ``--seed S`` -- ``N`` random points instead of the grid
  (``S`` a non-negative integer);
- ``--max-points N`` -- the most points (default
  :data:`~sage_dynsym.scale.points.MAX_POINTS`), checked before anything
  is loaded or computed;
- ``--method auto|polynomial|eigvals``;
- ``--scheduler ADDRESS`` -- a Dask scheduler to use (default: this
  process, or a local cluster when the work is estimated to take longer
  than :data:`~sage_dynsym.scale.cluster.CLUSTER_THRESHOLD` seconds),
  ``--cluster`` to always start a local cluster, ``--workers N`` for the
  local cluster, ``--numpy`` for no Dask, ``--timeout S`` to reach the
  scheduler;
- ``--progress`` -- Dask's progress bar;
- ``-o PREFIX`` -- the output files (default: the file's name with
  ``_map``, in the current directory); the folder must exist and be
  writable; existing files are refused at once, before the model is loaded
  or anything computed, unless ``--force`` is given: then they are replaced
  atomically (the old file or the complete new one).

Errors are one line on standard error naming the file and the option or
the entry of the description, and exit status 1 (2 for a malformed command
line, with argparse's usage message). A symbol given twice to ``--value``
or ``--at``, a ``--at`` that names no state variable or coordinate of the
model, a value breaking the model's declared signs are errors.

EXAMPLES::

    sage: from sage_dynsym.scale.cli import main
    sage: from sage_dynsym.description import example_path
    sage: prefix = tmp_filename()
    sage: main([example_path('rlc_ladder.yaml'), '--param', 'R1=-1:2:31', '--param', 'R2=-1:2:31',
    ....:       '--value', 'R3=1', '--value', 'R4=2', '--value', 'L1=1', '--value', 'L2=1',
    ....:       '--value', 'L3=1', '--value', 'C1=1', '--value', 'C2=1', '--value', 'C3=1',
    ....:       '--numpy', '-o', prefix])
    RLC ladder with three sections: stability map of 31 x 31 points in (R1, R2): 66.6% asymptotically stable (method: polynomial)
    Lienard-Chipart conditions: agree at 100.0% of the points
    classes: 66.6% asymptotically stable, 0.0% stable in first approximation, 33.4% unstable
    exact classes: agree at 100.0% (asymptotically stable), 100.0% (unstable)
    wrote ....png, ....npz
    0
    sage: main([example_path('rlc_ladder.yaml'), '--param', 'R1=0:1:0', '--numpy'])
    sage-dynsym: error: ...rlc_ladder.yaml: --param[R1]: empty range (0.0, 1.0, 0): n must be a positive integer
    1
    sage: main([example_path('rlc_ladder.yaml'), '--param', 'R1=0:1:100000', '--param',
    ....:       'R2=0:1:100000', '--numpy'])
    sage-dynsym: error: ...rlc_ladder.yaml: --param: 10000000000 points are more than the limit of 10000000; raise it with --max-points if that is what you want
    1
    sage: main([example_path('rlc_ladder.yaml'), '--param', 'R1=0:1:3', '--numpy', '-o',
    ....:       '/no/such/dir/out'])
    sage-dynsym: error: ...rlc_ladder.yaml: -o: the folder /no/such/dir does not exist
    1

Existing output files are refused before anything is computed::

    sage: main([example_path('rlc_ladder.yaml'), '--param', 'R1=0:1:3', '--numpy', '-o', prefix])
    sage-dynsym: error: ...rlc_ladder.yaml: -o: ....png, ....npz exist already: give --force to replace them, or another -o PREFIX
    1

The inverted pendulum of the cart (``theta = pi``; the pendulum hangs at
``theta = 0``), unstable whatever the spring and the damper::

    sage: main([example_path('cart_pendulum_spring_damper.yaml'), '--param', 'k=0.5:5:11',
    ....:       '--param', 'c=0.1:2:11', '--value', 'M=1', '--value', 'm=1/2', '--value', 'l=1',
    ....:       '--value', 'g=9.81', '--at', 'theta=pi', '--numpy', '-o', prefix + '_cart'])
    cart pendulum with spring and damper: stability map of 11 x 11 points in (k, c): 0.0% asymptotically stable (method: polynomial)
    no Lienard-Chipart conditions (never asymptotically stable)
    classes: 0.0% asymptotically stable, 0.0% stable in first approximation, 100.0% unstable
    exact classes: agree at 100.0% (unstable)
    wrote ..._cart.png, ..._cart.npz
    0
"""
import argparse
import math
import os
import sys

# the Sage-free part of the package: --help and argument errors answer at once
from ..arguments import count_option
from .cluster import CLUSTER_THRESHOLD

__all__ = ['parser', 'EXAMPLE', 'main']


def _assignment(text, what):
    name, sep, value = text.partition('=')
    name = name.strip()
    if not sep or not name.isidentifier():
        raise argparse.ArgumentTypeError(f"expected NAME={what}, got {text!r}")
    return name, value.strip()


def _number(text):
    try:
        value = float(text)
    except ValueError as err:
        raise argparse.ArgumentTypeError(f"expected a number, got {text!r}") from err
    return value


def _param(text):
    name, value = _assignment(text, "LOW:HIGH:N")
    parts = value.split(':')
    if len(parts) not in (2, 3):
        raise argparse.ArgumentTypeError(f"expected NAME=LOW:HIGH:N, got {text!r}")
    low, high = _number(parts[0]), _number(parts[1])
    if len(parts) == 2:
        return name, (low, high)
    try:
        n = int(parts[2])
    except ValueError as err:
        raise argparse.ArgumentTypeError(f"expected an integer number of points in {text!r}") \
            from err
    return name, (low, high, n)


def _value(text):
    # the text of the value: read exactly (pi/2, sqrt(2)/2) once Sage is loaded
    name, value = _assignment(text, "VALUE")
    if not value:
        raise argparse.ArgumentTypeError(f"expected NAME=VALUE, got {text!r}")
    return name, value


def parser():
    r"""The argument parser of ``sage-dynsym map``.

    EXAMPLES::

        sage: from sage_dynsym.scale.cli import parser
        sage: parser().parse_args(['f.yaml', '--param', 'R=0:5:400', '--value', 'g=0.5']).param
        [('R', (0.0, 5.0, 400))]
    """
    from .points import MAX_POINTS
    from .cluster import MAX_WORKERS
    p = argparse.ArgumentParser(
        prog="sage-dynsym map",
        description="Stability map of the model of a description file over a grid of "
                    "parameter values; writes PREFIX.png and PREFIX.npz. Small maps are "
                    "computed in this process, large ones on a local Dask cluster "
                    "(or on --scheduler).",
        formatter_class=argparse.RawDescriptionHelpFormatter,
        epilog=EXAMPLE)
    p.add_argument("file", metavar="FILE", help="description file (circuit or mechanical)")
    p.add_argument("--param", type=_param, action="append", required=True,
                   metavar="NAME=LOW:HIGH:N", help="a parameter of the map and its range")
    p.add_argument("--value", type=_value, action="append", default=[], metavar="NAME=VALUE",
                   help="the value of another symbol: a number or an exact constant "
                        "(9.81, pi/2, sqrt(2)/2)")
    p.add_argument("--at", type=_value, action="append", default=[], metavar="NAME=VALUE",
                   help="the point of linearization, as for --value (default: 0; "
                        "e.g. --at theta=pi)")
    p.add_argument("--samples", type=count_option, metavar="N",
                   help="N random points instead of the grid")
    p.add_argument("--seed", type=lambda text: count_option(text, minimum=0), default=0,
                   help="seed of the random points (a non-negative integer)")
    p.add_argument("--max-points", type=count_option, default=MAX_POINTS, metavar="N",
                   help=f"the most points (default: {MAX_POINTS})")
    p.add_argument("--method", choices=("auto", "polynomial", "eigvals"), default="auto",
                   help="roots of the compiled characteristic polynomial (polynomial), or "
                        "eigenvalues of the compiled matrices (eigvals); auto: polynomial "
                        "up to degree 16")
    where = p.add_mutually_exclusive_group()
    where.add_argument("--scheduler", metavar="ADDRESS", help="address of a Dask scheduler")
    where.add_argument("--numpy", action="store_true", help="compute in this process, no Dask")
    where.add_argument("--cluster", action="store_true",
                       help="always start a local Dask cluster (default: only when the "
                            "work is estimated to take longer than "
                            f"{CLUSTER_THRESHOLD} s in this process)")
    p.add_argument("--workers", type=lambda text: count_option(text, maximum=MAX_WORKERS),
                   metavar="N", help="workers of the local cluster (default: one per core)")
    p.add_argument("--timeout", type=count_option, default=10, metavar="S",
                   help="seconds to reach the scheduler (default: 10)")
    p.add_argument("--progress", action="store_true", help="show Dask's progress bar")
    p.add_argument("-o", "--output", metavar="PREFIX", help="output files PREFIX.png, PREFIX.npz "
                   "(default: the file's name with _map, in the current directory)")
    p.add_argument("--force", action="store_true", help="replace existing output files "
                   "(without it, existing files are refused before anything is computed)")
    return p


#: The example of ``sage-dynsym map --help``: it runs on a bundled file.
EXAMPLE = """example (the RLC ladder of the bundled examples, in the plane of R1 and R2):
  sage-dynsym map examples/rlc_ladder.yaml --param R1=-1:2:200 --param R2=-1:2:200 \\
      --value R3=1 --value R4=2 --value L1=1 --value L2=1 --value L3=1 \\
      --value C1=1 --value C2=1 --value C3=1 -o ladder"""


def main(argv=None):
    r"""
    Run ``sage-dynsym map``; return the exit status. See the module
    documentation.

    TESTS::

        sage: from sage_dynsym.scale.cli import main
        sage: from sage_dynsym.description import example_path
        sage: main([example_path('rlc_ladder.yaml'), '--param', 'X=0:1:3', '--numpy'])
        sage-dynsym: error: ...rlc_ladder.yaml: stability_map: unknown parameter X: the symbols of the system are C1, C2, C3, L1, L2, L3, R1, R2, R3, R4
        1
    """
    args = parser().parse_args(argv)
    from ..errors import DynSymError, brief
    try:
        return _run(args)
    except DynSymError as err:
        message = str(_located(err, args.file))
    except KeyboardInterrupt:
        print("sage-dynsym: interrupted", file=sys.stderr)
        return 130
    except Exception as err:        # a bug or a failure inside Sage or Dask: one line
        message = f"{args.file}: unexpected {type(err).__name__}: {brief(str(err))}"
    print(f"sage-dynsym: error: {' '.join(message.split())}", file=sys.stderr, flush=True)
    return 1


def _located(err, path):
    r"""``err`` naming the file (its entry names the option or the entry of
    the description)."""
    return err if err.source else err.with_context(source=path)


def _checked(args):
    r"""
    Everything the command line can check before the model is loaded and
    the map computed: no symbol twice, the points (parsed here, once, and
    passed to the map; at most ``--max-points``), the output files (the
    folder exists and is writable; existing files only with ``--force``).
    Returns the output files and the points.
    """
    from ..errors import DescriptionError
    from .points import parse_points
    for option, what, pairs in (('--param', 'parameter', args.param),
                                ('--value', 'value', args.value), ('--at', 'point', args.at)):
        names = [name for name, _ in pairs]
        twice = sorted({n for n in names if names.count(n) > 1})
        if twice:
            raise DescriptionError(f"a {what} is given twice: {', '.join(twice)}", entry=option)
    points = parse_points(dict(args.param), args.samples, args.seed, entry="--param",
                          max_points=args.max_points, samples_entry="--samples",
                          raise_with="--max-points")
    return _outputs(args), points


def _outputs(args):
    r"""The output files, checked: the picture (one or two parameters on a
    grid, two for random samples) and the arrays."""
    from ..errors import DescriptionError
    prefix = args.output or os.path.splitext(os.path.basename(args.file))[0] + "_map"
    folder = os.path.dirname(prefix) or '.'
    if not os.path.isdir(folder):
        raise DescriptionError(f"the folder {folder} does not exist", entry="-o")
    if not os.path.basename(prefix):
        raise DescriptionError(f"{prefix!r} names a folder: expected PREFIX, e.g. "
                               f"{os.path.join(folder, 'map')}", entry="-o")
    if not os.access(folder, os.W_OK | os.X_OK):
        raise DescriptionError(f"the folder {folder} is not writable", entry="-o")
    n = len(args.param)
    picture = n <= 2 if args.samples is None else n == 2
    outputs = [prefix + ".png"] * picture + [prefix + ".npz"]
    folders = [f for f in outputs if os.path.isdir(f)]
    if folders:
        raise DescriptionError(f"{folders[0]} is a folder: give another -o PREFIX", entry="-o")
    existing = [f for f in outputs if os.path.exists(f)]
    if existing and not args.force:
        one = len(existing) == 1
        raise DescriptionError(f"{', '.join(existing)} {'exists' if one else 'exist'} already: "
                               f"give --force to replace {'it' if one else 'them'}, or another "
                               "-o PREFIX", entry="-o")
    return outputs


def _numbers(pairs, option):
    r"""The values of ``--value`` or ``--at``, read exactly by the package's
    expression reader (never evaluated): numbers and constant expressions
    (``9.81`` is `981/100`, ``pi/2``, ``sqrt(2)/2``). The model's declared
    signs are checked where the values are used (by
    :func:`~sage_dynsym.scale.maps.stability_map`)."""
    from ..errors import DescriptionError, ExpressionError, brief
    from ..io.expressions import ExpressionParser
    reader = ExpressionParser(())
    values = {}
    for name, text in pairs:
        given = f"{name}={text if len(text) <= 60 else text[:57] + '...'}"
        expected = (f"{given}: expected a real number or an exact constant (e.g. 9.81, "
                    "pi/2, sqrt(2)/2)")
        try:
            value = reader.parse(text)
        except ExpressionError as err:
            raise DescriptionError(f"{expected}; {err.message}", entry=option) from err
        try:
            z = None if value.variables() else complex(value)
        except (TypeError, ValueError, OverflowError):
            z = None
        if z is not None and not (math.isfinite(z.real) and math.isfinite(z.imag)):
            raise DescriptionError(f"{given}: the value is beyond floating point (about "
                                   "1.8e308 at most)", entry=option)
        if z is None or z.imag != 0:
            raise DescriptionError(f"{expected}, got {brief(str(value))[1:-1]}", entry=option)
        values[name] = value
    return values


def _run(args):
    outputs, points = _checked(args)    # nothing loaded nor computed before these checks
    values, point = _numbers(args.value, '--value'), _numbers(args.at, '--at')
    from ..description import load
    from ..errors import DynSymError
    from .maps import stability_map
    model = load(args.file)
    client = False if args.numpy else 'local' if args.cluster else (args.scheduler or None)
    S = stability_map(model, points, fixed=values, client=client, at=point,
                      method=args.method, conditions='lienard-chipart', classes='spectrum',
                      workers=args.workers, timeout=args.timeout, progress=args.progress)
    name = model.name() if callable(getattr(model, 'name', None)) else None
    print(f"{name or args.file}: {str(S)[0].lower()}{str(S)[1:]} (method: {S.method()})")
    if S.conditions() is not None:
        print(f"Lienard-Chipart conditions: agree at {100 * S.agreement():.1f}% of the points")
    elif S.note():
        print(S.note())
    shares = [100 * (S.classes() == k).mean() for k in (2, 1, 0)]
    print("classes: {:.1f}% asymptotically stable, {:.1f}% stable in first approximation, "
          "{:.1f}% unstable".format(*shares))
    try:
        agree = S.agreement(by_class=True)
    except DynSymError:
        agree = None
    if agree is not None:
        names = {2: 'asymptotically stable', 1: 'stable in first approximation', 0: 'unstable'}
        print("exact classes: agree at " + ", ".join(
            f"{100 * agree[k]:.1f}% ({names[k]})" for k in (2, 1, 0) if agree[k] == agree[k]))
    _write(S, outputs)
    print("wrote " + ", ".join(outputs))
    return 0


def _write(S, outputs):
    r"""Write the arrays, then the picture, each file replaced atomically
    (the old file or the complete new one, never half a file): the arrays,
    the computed work, are kept whatever happens to the picture."""
    import tempfile
    from ..errors import DescriptionError
    from ..io.files import write_atomically
    try:
        S.save(outputs[-1])
        if outputs[0].endswith(".png"):
            import numpy
            with numpy.errstate(all='ignore'):     # huge axes overflow in region_plot
                G = S.plot()
            with tempfile.TemporaryDirectory() as folder:
                picture = os.path.join(folder, "map.png")
                G.save(picture, figsize=[8, 6])
                with open(picture, 'rb') as stream:
                    data = stream.read()
            write_atomically(outputs[0], lambda stream: stream.write(data), binary=True)
    except OSError as err:
        raise DescriptionError(f"cannot write {err.filename or outputs[0]}: "
                               f"{err.strerror or err}", entry="-o") from err
