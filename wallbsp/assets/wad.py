"""WAD files: reading the directory and lumps, and writing a WAD (tests and tools build theirs
here).

Public API:
- ``open_wad(path)``: a context manager giving a ``Wad`` (``label``, ``names``, ``index``,
  ``read(i)``, ``lump(name)``, ``size_of(i)``, ``between(starts, ends)``); the directory is
  read once per file version and cached (``forget_wads()`` empties the cache);
- ``lump_name(raw)``: an 8-byte directory or PNAMES name as DOOM compares it (upper case, up
  to the first NUL);
- ``wad_bytes(lumps, magic)`` / ``write_wad(path, lumps, magic)``: a WAD holding ``lumps``
  (``(name, bytes)`` pairs, in order), written atomically.

Errors (a truncated header or directory, a lump outside the file) are one ``LevelError`` line
naming the file and the place: ``freedoom2.wad: directory[12]: ...``.
"""
from __future__ import annotations

import os
import struct
from collections import OrderedDict
from contextlib import contextmanager
from dataclasses import dataclass
from typing import BinaryIO, Iterable, Iterator

import numpy as np

from wallbsp.files import InputError, open_regular, write_atomically
from wallbsp.files import LevelError

HEADER = struct.Struct("<4sii")


def _read_at(f, pos: int, size: int) -> bytes:
    if hasattr(os, "pread"):
        return os.pread(f.fileno(), size, pos) if size else b""
    f.seek(pos)                       # no pread (Windows): not safe across a fork, as there
    return f.read(size)
DIRENTRY = np.dtype([("pos", "<i4"), ("size", "<i4"), ("name", "S8")])
CACHE_SIZE = 8          # WAD directories kept: a session rarely uses more than an IWAD + PWADs


@dataclass
class Directory:
    """The parsed directory of one WAD file version, shared by every open of it. ``extras``
    holds what other modules derive from the WAD once (texture tables, decoded pictures)."""
    names: list[str]
    pos: np.ndarray
    size: np.ndarray
    file_size: int
    index: dict[str, int]         # name -> the last lump of that name, as W_GetNumForName finds
    extras: dict


@dataclass
class Wad:
    """An open WAD: its label for messages, the file, its cached directory and its path."""
    label: str
    file: BinaryIO
    directory: Directory
    path: str

    @property
    def names(self) -> list[str]:
        return self.directory.names

    @property
    def index(self) -> dict[str, int]:
        return self.directory.index

    @property
    def extras(self) -> dict:
        return self.directory.extras

    def size_of(self, i: int) -> int:
        return int(self.directory.size[i])

    def read(self, i: int) -> bytes:
        d = self.directory
        pos, size = int(d.pos[i]), int(d.size[i])
        if pos < 0 or size < 0 or pos + size > d.file_size:
            raise LevelError(f"{self.label}: directory[{i}]: lump {d.names[i]} at offset {pos} "
                             f"({size} bytes) lies outside the file ({d.file_size} bytes)")
        # pread, not seek + read: processes forked with this file open (vector environments)
        # share its position, and a seek in one would move the other's read
        raw = _read_at(self.file, pos, size)
        if len(raw) != size:   # the file shrank under us
            raise LevelError(f"{self.label}: directory[{i}]: lump {d.names[i]} is truncated")
        return raw

    def lump(self, name: str) -> bytes | None:
        """The last lump called ``name``, or None."""
        i = self.directory.index.get(name)
        return None if i is None else self.read(i)

    def between(self, starts: Iterable[str], ends: Iterable[str]) -> dict[str, int]:
        """Name -> lump index of the non-empty lumps between any start and end marker (nested
        sub-markers such as F1_START are empty and so skipped); a later lump of a name replaces
        an earlier one, as DOOM's loaders do."""
        starts, ends = frozenset(starts), frozenset(ends)
        found: dict[str, int] = {}
        inside = False
        for i, name in enumerate(self.directory.names):
            if name in starts:
                inside = True
            elif name in ends:
                inside = False
            elif inside and self.directory.size[i] > 0:
                found[name] = i
        return found


_CACHE: OrderedDict[tuple, Directory] = OrderedDict()


@contextmanager
def open_wad(wad_path) -> Iterator[Wad]:
    """The WAD at ``wad_path``, open for reading; its directory comes from the cache when the
    file (path, inode, mtime, ctime, size) has not changed."""
    label = str(wad_path)
    try:
        f = open_regular(wad_path)      # a FIFO or device would block or never end
    except InputError as e:
        raise LevelError(f"{label}: cannot read: {e.reason}") from None
    with f:
        st = os.fstat(f.fileno())
        key = (os.path.realpath(wad_path), st.st_ino, st.st_mtime_ns, st.st_ctime_ns,
               st.st_size)
        directory = _CACHE.get(key)
        if directory is None:
            directory = _read_directory(f, label, st.st_size)
            _CACHE[key] = directory
            while len(_CACHE) > CACHE_SIZE:
                _CACHE.popitem(last=False)
        yield Wad(label, f, directory, os.fspath(wad_path))


def forget_wads() -> None:
    """Empties the cache of WAD directories and everything derived from them, so that the next
    use pays what a fresh process pays."""
    _CACHE.clear()


def _read_directory(f: BinaryIO, label: str, file_size: int) -> Directory:
    head = f.read(HEADER.size)
    if len(head) < HEADER.size:
        raise LevelError(f"{label}: header: truncated ({file_size} bytes, a WAD header is 12)")
    magic, count, offset = HEADER.unpack(head)
    if magic not in (b"IWAD", b"PWAD"):
        raise LevelError(f"{label}: header: bad magic {magic!r} (not IWAD or PWAD)")
    end = offset + count * DIRENTRY.itemsize
    if count < 0 or offset < HEADER.size or end > file_size:
        raise LevelError(f"{label}: directory: {count} entries at offset {offset} run past the "
                         f"end of the file ({file_size} bytes); truncated or not a WAD")
    f.seek(offset)
    entries = np.frombuffer(f.read(end - offset), DIRENTRY)
    names = [lump_name(n) for n in entries["name"].tolist()]
    return Directory(names, entries["pos"].copy(), entries["size"].copy(), file_size,
                     {n: i for i, n in enumerate(names)}, {})


def lump_name(raw: bytes) -> str:
    """A NUL-padded 8-byte name. Some tools leave garbage after the NUL; DOOM compares upper
    case."""
    return raw.split(b"\0", 1)[0].decode("latin-1").upper()


def wad_bytes(lumps: Iterable[tuple[str, bytes]], magic: bytes = b"PWAD") -> bytes:
    """A WAD image: header, the lumps in order, then the directory."""
    body, entries = bytearray(), []
    for name, raw in lumps:
        entries.append(struct.pack("<ii8s", HEADER.size + len(body), len(raw),
                                   name.encode("latin-1")))
        body += raw
    return HEADER.pack(magic, len(entries), HEADER.size + len(body)) + bytes(body) + \
        b"".join(entries)


def write_wad(path, lumps: Iterable[tuple[str, bytes]], magic: bytes = b"PWAD") -> None:
    """Writes ``wad_bytes(lumps, magic)`` to ``path``: all of it or nothing."""
    write_atomically(path, wad_bytes(lumps, magic))
