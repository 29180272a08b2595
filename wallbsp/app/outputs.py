"""What a command writes: every output path checked before anything is read or computed,
and the files written together (all of them or none), so a bad ``--ids`` path never leaves a
PNG behind.  Plus the byte encodings of a frame's extra outputs.
"""
from __future__ import annotations

import io
import os

import numpy as np

from wallbsp.files import write_atomically

__all__ = ["OutputError", "check_outputs", "write_outputs", "ids_bytes", "depth_bytes"]


class OutputError(ValueError):
    """An output path that cannot be written: one line naming it."""


def check_outputs(command, outputs, inputs=()):
    """Refuse output paths that cannot be written: a missing or read-only folder, a
    directory, one path named twice, an input file.  ``None`` entries are skipped."""
    seen = {os.path.realpath(p): "the input" for p in inputs if p and p != "-"}
    for path in filter(None, outputs):
        full = os.path.realpath(path)
        folder, shown = os.path.dirname(full), os.path.dirname(path) or "."
        if full in seen:
            raise OutputError(f"{path}: named as {seen[full]} of wallbsp {command} too")
        seen[full] = "another output"
        if os.path.isdir(full):
            raise OutputError(f"{path}: is a directory")
        if not os.path.isdir(folder):
            raise OutputError(f"{path}: folder {shown} does not exist")
        if not os.access(folder, os.W_OK):
            raise OutputError(f"{path}: folder {shown} is not writable")


def write_outputs(outputs: dict) -> None:
    """Write ``{path: bytes}`` together: each file is staged beside its target first and
    only when every one is complete are they all renamed into place."""
    staged = []
    try:
        for path, data in outputs.items():
            folder, name = os.path.split(os.fspath(path))
            stage = os.path.join(folder, f".{name}.{os.getpid()}.partial")
            write_atomically(stage, data)
            staged.append((stage, path))
        for stage, path in staged:
            os.replace(stage, path)
    finally:
        for stage, _ in staged:
            if os.path.lexists(stage):
                os.unlink(stage)


def ids_bytes(frame) -> bytes:
    """A frame's ``kind`` and ``index`` as an ``.npz``."""
    buf = io.BytesIO()
    np.savez(buf, kind=np.ascontiguousarray(frame.kind), index=np.ascontiguousarray(frame.index))
    return buf.getvalue()


def depth_bytes(frame) -> bytes:
    """A frame's depth buffer (float32) as an ``.npy``."""
    buf = io.BytesIO()
    np.save(buf, np.ascontiguousarray(frame.depth), allow_pickle=False)
    return buf.getvalue()
