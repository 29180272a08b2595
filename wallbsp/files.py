"""Writing files so that nothing is ever half-written: a temporary file in the same
folder, then an atomic rename.  Every file wallbsp writes goes through here."""
from __future__ import annotations

import os
import tempfile
from pathlib import Path


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
