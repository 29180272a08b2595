"""Files in and out.  Writing: nothing is ever half-written (a temporary file in the same
folder, then an atomic rename); every file wallbsp writes goes through ``write_atomically``.
Reading: ``read_input`` reads a user's file, or standard input for ``-``, refusing what is
not a regular file (a FIFO, a device such as /dev/zero, a directory) without blocking on
it, and anything larger than the caller's limit; every loader of user files uses it (or
``open_regular``, the same refusal, for a reader that streams a large file)."""
from __future__ import annotations

import os
import stat
import sys
import tempfile
from pathlib import Path

STDIN = "-"


class LevelError(ValueError):
    """Bad input, as one line: ``file: json.path: what is wrong`` (a level, a WAD, a
    picture, a tree); ``wallbsp.LevelError``."""


class InputError(ValueError):
    """A file that cannot be read as input; ``reason`` says why without naming the file
    (each loader names it in its own format), ``str()`` names it too."""

    def __init__(self, path, reason: str):
        super().__init__(f"{path}: {reason}")
        self.path = str(path)
        self.reason = reason


def read_input(path, limit: int) -> bytes:
    """All the bytes of the regular file at ``path`` (``"-"``: standard input), at most
    ``limit`` of them; ``InputError`` otherwise."""
    if os.fspath(path) == STDIN:
        return _read_capped(sys.stdin.buffer, STDIN, limit)
    with open_regular(path) as f:
        size = os.fstat(f.fileno()).st_size
        if size > limit:
            raise InputError(path, _too_big(size, limit))
        return _read_capped(f, path, limit, size)


def open_regular(path):
    """The regular file at ``path`` opened for reading in binary (for a reader that
    streams it); anything else is an ``InputError``, refused before it is opened."""
    try:
        _check_regular(path, os.stat(path).st_mode)   # stat never blocks, open may
        f = open(path, "rb", opener=_open_without_waiting)
    except FileNotFoundError:
        raise InputError(path, "no such file") from None
    except OSError as err:
        raise InputError(path, f"cannot read: {err.strerror or err}") from None
    try:
        # the path may have been replaced between stat and open: check what was opened
        _check_regular(path, os.fstat(f.fileno()).st_mode)
    except InputError:
        f.close()
        raise
    return f


def _open_without_waiting(path, flags: int) -> int:
    # should a FIFO replace the file after the stat, opening it must not wait for a writer
    return os.open(path, flags | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_NOCTTY", 0))


def _check_regular(path, mode: int) -> None:
    if stat.S_ISREG(mode):
        return
    if stat.S_ISDIR(mode):
        raise InputError(path, "is a directory, not a file")
    kind = ("a FIFO (named pipe)" if stat.S_ISFIFO(mode)
            else "a device" if stat.S_ISCHR(mode) or stat.S_ISBLK(mode)
            else "a socket" if stat.S_ISSOCK(mode) else "not a regular file")
    raise InputError(path, f"is {kind}, not a regular file; refusing to read it")


def _read_capped(stream, path, limit: int, size: int | None = None) -> bytes:
    """At most ``limit`` bytes of ``stream``; ``size``: what the file holds, so that no
    buffer of ``limit`` bytes is made for a small file (a read of n makes n first)."""
    try:
        data = stream.read(limit + 1 if size is None else min(size, limit) + 1)
        if data is not None and size is not None and size < len(data) <= limit:
            data += stream.read(limit + 1 - len(data))      # it grew since the stat
    except OSError as err:
        raise InputError(path, f"cannot read: {err.strerror or err}") from None
    if data is None:        # a non-blocking read with nothing there yet
        raise InputError(path, "not ready to be read (a FIFO or device?)")
    if len(data) > limit:
        raise InputError(path, _too_big(None, limit))
    return data


def _too_big(size: int | None, limit: int) -> str:
    have = f"{size} bytes, " if size is not None else ""
    return f"too large ({have}more than the limit of {limit} bytes)"


def write_atomically(path, data: bytes) -> None:
    """Write ``data`` to ``path``: all of it, or (on any error) nothing."""
    path = Path(os.fspath(path))
    directory = path.parent
    try:
        fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=directory)
    except OSError as err:
        raise OSError(err.errno, err.strerror, str(path)) from None
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(data)
            f.flush()
            os.fsync(f.fileno())
        os.chmod(tmp, _new_file_mode(path))
        os.replace(tmp, path)
    except OSError as err:
        _remove_quietly(tmp)
        raise OSError(err.errno, err.strerror, str(path)) from None
    except BaseException:
        _remove_quietly(tmp)
        raise


def _new_file_mode(path: Path) -> int:
    """The replaced file's permissions, or what a plain open() would have given."""
    try:
        return path.stat().st_mode & 0o7777
    except OSError:
        umask = os.umask(0)
        os.umask(umask)
        return 0o666 & ~umask


def _remove_quietly(path: str) -> None:
    try:
        os.unlink(path)
    except OSError:
        pass
