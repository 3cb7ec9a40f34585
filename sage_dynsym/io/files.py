r"""
Writing files atomically

A description written over its own file must never be lost half-way:
:func:`write_atomically` writes a temporary file in the same folder, syncs
it and renames it over the old one.

EXAMPLES::

    sage: import os, tempfile
    sage: from sage_dynsym.io.files import write_atomically
    sage: path = os.path.join(tempfile.mkdtemp(), 'f.txt')
    sage: write_atomically(path, lambda stream: stream.write('hello\n'))
    sage: open(path).read()
    'hello\n'
"""
import os
import stat
import tempfile

from ..errors import DescriptionError, brief

__all__ = ['write_atomically']


def write_atomically(path, write, binary=False):
    r"""
    Write a text file so that it is either the old file or the complete new
    one, whatever happens (an exception, Ctrl-C, a killed process, a crash
    of the machine after the call returned).

    ``write(stream)`` writes the text into a temporary file in the same
    folder; the file is flushed and synced to the disk, takes the
    permissions of the file it replaces, and is renamed over ``path`` with
    ``os.replace`` (atomic); the folder is synced too. On any failure the
    temporary file is removed and ``path`` is untouched. A symbolic link is
    followed: its target is replaced.

    INPUT:

    - ``path`` -- the file name
    - ``write`` -- a function of a text stream (UTF-8), or of a binary
      stream with ``binary=True``
    - ``binary`` -- (default: ``False``) whether the file is binary

    EXAMPLES::

        sage: import os, tempfile
        sage: from sage_dynsym.io.files import write_atomically
        sage: folder = tempfile.mkdtemp(); path = os.path.join(folder, 'f.yaml')
        sage: write_atomically(path, lambda s: s.write('kind: circuit\n'))
        sage: def fail(stream):
        ....:     _ = stream.write('half a file')
        ....:     raise KeyboardInterrupt
        sage: write_atomically(path, fail)
        Traceback (most recent call last):
        ...
        KeyboardInterrupt
        sage: open(path).read(), os.listdir(folder)
        ('kind: circuit\n', ['f.yaml'])
        sage: write_atomically(path, lambda s: s.write(b'\x00\x01'), binary=True)
        sage: open(path, 'rb').read()
        b'\x00\x01'

    TESTS::

        sage: write_atomically('a\x00b.yaml', lambda s: s.write(''))
        Traceback (most recent call last):
        ...
        DescriptionError: 'a\x00b.yaml': cannot write the file: embedded null byte
        sage: write_atomically(42, lambda s: s.write(''))
        Traceback (most recent call last):
        ...
        DescriptionError: 42: expected a file name, got 42
    """
    if not isinstance(path, (str, os.PathLike)) or not os.fspath(path):
        raise DescriptionError(f"expected a file name, got {brief(path)}", source=brief(path))
    try:
        target = os.path.realpath(path)
        folder = os.path.dirname(target) or '.'
        fd, temporary = tempfile.mkstemp(dir=folder, prefix=f".{os.path.basename(target)}.",
                                         suffix=".tmp")
    except (OSError, ValueError, TypeError) as err:    # ValueError: a NUL byte in the name
        reason = err.strerror if isinstance(err, OSError) and err.strerror else err
        name = str(path)
        raise DescriptionError(f"cannot write the file: {reason}",
                               source=name if name.isprintable() else brief(name)) from err
    try:
        with (os.fdopen(fd, 'wb') if binary else os.fdopen(fd, 'w', encoding='utf-8')) as stream:
            write(stream)
            stream.flush()
            os.fsync(stream.fileno())
        try:
            mode = stat.S_IMODE(os.stat(target).st_mode)
        except FileNotFoundError:
            umask = os.umask(0)
            os.umask(umask)
            mode = 0o666 & ~umask
        os.chmod(temporary, mode)
        os.replace(temporary, target)
    except BaseException as err:
        try:
            os.unlink(temporary)
        except OSError:
            pass
        if isinstance(err, OSError):
            raise DescriptionError(f"cannot write the file: {err.strerror or err}",
                                   source=str(path)) from err
        raise
    try:                        # make the new directory entry durable
        directory = os.open(folder, os.O_RDONLY)
        try:
            os.fsync(directory)
        finally:
            os.close(directory)
    except OSError:
        pass
