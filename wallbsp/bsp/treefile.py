"""The compiled tree's file (``.wbsp``, SPEC §3): writing it, and reading it back without
trusting it.

A tree file is a zip archive whose members are stored, not compressed: ``header.json``
(format, version, the level's hash, how it was compiled), ``level.json`` (the level, as
``dumps_level`` writes it) and one ``.npy`` array per name of ``ARRAY_LAYOUT``.  Members are
written in a fixed order with a fixed time stamp, so the same tree gives the same bytes.

Reading assumes the file may be crafted.  Before anything is decompressed or allocated the
archive must hold exactly the expected members, each stored, together no larger than the
file, and every array header must parse to the expected dtype with shapes that agree with
each other and with the member's declared size; arrays are then read in pieces straight into
their final buffers.  So a file can never make the reader use more memory than the file's
own size, plus the parsed level.  Whether the arrays form a sound tree for the level is
``treecheck``'s question, asked by ``load_tree`` before the tree is handed out.
"""
from __future__ import annotations

import hashlib
import io
import json
import os
import re
import struct
import tokenize
import zipfile
import zlib
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from wallbsp.files import InputError, open_regular, write_atomically
from wallbsp.level.conflicts import seg_limit
from wallbsp.level.model import Level, LevelError
from wallbsp.level.io import content_hash, dumps_level, level_from_dict, parse_json

TREE_FORMAT = "wallbsp-tree"
TREE_VERSION = 1
ARRAY_LAYOUT = {   # name: (dtype, trailing shape; None for a scalar)
    "node_line": ("int64", (3,)), "node_child": ("int32", (2,)),
    "node_bbox": ("float64", (4,)), "node_segs": ("int32", (2,)),
    "leaf_sector": ("int32", ()), "seg_wall": ("int32", ()), "seg_flip": ("bool", ()),
    "seg_t": ("int64", (4,)), "seg_xy": ("float64", (4,)),
    "root": ("int64", None), "max_depth": ("int64", None),
}
NODE_ARRAYS = ("node_line", "node_child", "node_bbox", "node_segs")
SEG_ARRAYS = ("seg_wall", "seg_flip", "seg_t", "seg_xy")
HEADER_LIMIT = 1 << 16         # header.json is a few hundred bytes
_ZIP_TIME = (1980, 1, 1, 0, 0, 0)   # fixed, so the same tree gives the same bytes
_CHUNK = 1 << 20               # arrays are read in pieces of this size
_SHA256 = re.compile(r"[0-9a-f]{64}")

# what zipfile raises for a damaged archive: a corrupted header can claim encryption or an
# unknown compression (NotImplementedError, RuntimeError), or break its own parsing
_DAMAGED_ZIP = (zipfile.BadZipFile, zipfile.LargeZipFile, OSError, EOFError, ValueError,
                NotImplementedError, RuntimeError, zlib.error, struct.error, KeyError,
                IndexError, OverflowError)
# what numpy's .npy header parser raises for header text that is not a header
_BAD_NPY_HEADER = (ValueError, SyntaxError, TypeError, tokenize.TokenError, RecursionError,
                   MemoryError, OverflowError, UnicodeDecodeError, struct.error)


class TreeError(LevelError):
    """A compiled tree file that cannot be used: one line, with the file."""


@dataclass
class TreeFile:
    """What a tree file holds, read but not yet checked as a tree."""
    level: Level
    arrays: dict
    candidates: int | str | None
    seed: int


# -- writing ----------------------------------------------------------------------------------

def write_tree_file(path, level: Level, arrays: dict, candidates, seed) -> None:
    """Write the tree atomically; the same tree always gives the same bytes."""
    header = {"format": TREE_FORMAT, "version": TREE_VERSION,
              "level_sha256": content_hash(level), "candidates": candidates, "seed": seed}
    members = {"header.json": json.dumps(header, sort_keys=True).encode(),
               "level.json": dumps_level(level).encode()}
    for name in ARRAY_LAYOUT:
        buf = io.BytesIO()
        np.lib.format.write_array(buf, np.asarray(arrays[name]), allow_pickle=False)
        members[name + ".npy"] = buf.getvalue()
    write_atomically(path, _zip_bytes(members))


def _zip_bytes(members) -> bytes:
    buf = io.BytesIO()
    with zipfile.ZipFile(buf, "w", zipfile.ZIP_STORED) as zf:
        for name, data in members.items():
            info = zipfile.ZipInfo(name, date_time=_ZIP_TIME)
            info.external_attr = 0o644 << 16
            zf.writestr(info, data)
    return buf.getvalue()


# -- reading ----------------------------------------------------------------------------------

def read_tree_file(path) -> TreeFile:
    """Read a tree file's level and arrays; anything wrong with the file is a TreeError
    naming it.  The arrays are not checked as a tree here (see ``treecheck``)."""
    where = os.fspath(path)
    with _open_regular(where) as f:
        size = os.fstat(f.fileno()).st_size
        try:
            with zipfile.ZipFile(f) as zf:
                return _read_members(where, zf, size)
        except (TreeError, LevelError):
            raise
        except _DAMAGED_ZIP as err:
            raise TreeError(f"{where}: not a wallbsp tree, or a damaged one "
                            f"({type(err).__name__}: {err})") from None


def _open_regular(path):
    """The file opened for reading; a FIFO, device or directory is refused before it is
    opened (reading one would block or never end)."""
    try:
        return open_regular(path)
    except InputError as err:
        raise TreeError(f"{path}: {err.reason}") from None


def _read_members(path, zf: zipfile.ZipFile, file_size: int) -> TreeFile:
    infos = _check_directory(path, zf, file_size)
    header = _read_header(path, zf, infos["header.json"])
    shapes = {name: _array_shape(path, zf, infos[name + ".npy"], name) for name in ARRAY_LAYOUT}
    _check_shapes_agree(path, shapes)
    level = _read_level(path, zf, infos["level.json"], header["level_sha256"])
    segs, limit = shapes["seg_wall"][0], seg_limit(len(level.walls))
    if segs > limit:        # walls crossing everywhere (docs/limits.md): its tables outgrow it
        raise TreeError(f"{path}: {segs} segs for {len(level.walls)} walls, more than a "
                        f"level may compile to ({limit})")
    arrays = {name: _read_array(path, zf, infos[name + ".npy"], name, shapes[name])
              for name in ARRAY_LAYOUT}
    return TreeFile(level, arrays, header["candidates"], header["seed"])


def _check_directory(path, zf, file_size):
    """Exactly the expected members, each stored (not compressed), together no larger than
    the file: the declared sizes then bound every byte the reader will take in."""
    infos = zf.infolist()
    expected = {"header.json", "level.json"} | {name + ".npy" for name in ARRAY_LAYOUT}
    names = [info.filename for info in infos]
    unknown = sorted(set(names) - expected)
    if unknown:
        raise TreeError(f"{path}: unexpected member {unknown[0]!r}: not a wallbsp tree")
    missing = sorted(expected - set(names))
    if missing:
        raise TreeError(f"{path}: {missing[0]}: missing")
    if len(names) != len(expected):
        raise TreeError(f"{path}: a member appears twice in the archive")
    for info in infos:
        if info.compress_type != zipfile.ZIP_STORED or info.compress_size != info.file_size:
            raise TreeError(f"{path}: {info.filename}: compressed; tree files store their "
                            f"members as they are (recompile it)")
    if sum(info.file_size for info in infos) > file_size:
        raise TreeError(f"{path}: its members claim more bytes than the file holds")
    if zf.getinfo("header.json").file_size > HEADER_LIMIT:
        raise TreeError(f"{path}: header.json: larger than {HEADER_LIMIT} bytes")
    return {info.filename: info for info in infos}


def _read_header(path, zf, info):
    header = _parse_member(path, zf, info)
    if not isinstance(header, dict) or header.get("format") != TREE_FORMAT:
        raise TreeError(f"{path}: header.json: format: not a {TREE_FORMAT} file")
    if header.get("version") != TREE_VERSION:
        raise TreeError(f"{path}: header.json: version: {header.get('version')!r} is not "
                        f"supported (this wallbsp reads version {TREE_VERSION}); recompile")
    digest, k, seed = header.get("level_sha256"), header.get("candidates"), header.get("seed")
    if not (isinstance(digest, str) and _SHA256.fullmatch(digest)):
        raise TreeError(f"{path}: header.json: level_sha256: not a sha256 hex digest")
    if not (k is None or k == "all" or _natural(k) and k >= 1):
        raise TreeError(f"{path}: header.json: candidates: {k!r} is not a count or 'all'")
    if not _natural(seed):
        raise TreeError(f"{path}: header.json: seed: {seed!r} is not a non-negative integer")
    return header


def _natural(value) -> bool:
    return type(value) is int and value >= 0


def _parse_member(path, zf, info):
    """A JSON member, decoded: any failure, even nesting too deep for Python, is one line."""
    try:
        return parse_json(zf.read(info), f"{path}:{info.filename}")
    except LevelError as err:
        raise TreeError(str(err)) from None


def _read_level(path, zf, info, digest) -> Level:
    raw = zf.read(info)
    source = f"{path}:level.json"
    try:
        level = level_from_dict(parse_json(raw, source), source, source_dir=Path(path).parent,
                                check_conflicts=False)   # searched when it was compiled
    except LevelError as err:
        raise TreeError(str(err)) from None
    # the writer stores the level as dumps_level gives it, whose sha256 is the level's
    # hash: hashing the stored bytes spares serialising the level again
    if hashlib.sha256(raw).hexdigest() != digest and content_hash(level) != digest:
        raise TreeError(f"{path}: the embedded level does not match the tree's level hash")
    return level


def _array_shape(path, zf, info, name):
    """The member's array shape, from its .npy header alone, after checking the dtype, the
    shape's form and that header plus data is exactly the member's declared size."""
    dtype, trailing = ARRAY_LAYOUT[name]
    with zf.open(info) as f:
        try:
            shape, fortran, found, header_size = _npy_header(f)
        except _BAD_NPY_HEADER as err:
            raise TreeError(f"{path}: {name}: unreadable array header "
                            f"({type(err).__name__}: {_first_line(err)})") from None
    rank_ok = shape == () if trailing is None else (
        len(shape) == 1 + len(trailing) and tuple(shape[1:]) == trailing)
    if found != np.dtype(dtype) or fortran or not rank_ok or min(shape, default=0) < 0:
        raise TreeError(f"{path}: {name}: expected {dtype} with trailing shape {trailing}, "
                        f"found {found} {shape}")
    need = header_size + _product(shape) * found.itemsize
    if need != info.file_size:
        raise TreeError(f"{path}: {name}: its header says {shape}, which needs {need} bytes, "
                        f"but the member holds {info.file_size}")
    return shape


def _product(shape) -> int:
    out = 1
    for n in shape:          # Python integers: a crafted (2**64 - 1,) cannot wrap around
        out *= n
    return out


def _npy_header(f):
    """``(shape, fortran_order, dtype, header bytes)`` of a .npy stream at its start."""
    version = np.lib.format.read_magic(f)
    read = {(1, 0): np.lib.format.read_array_header_1_0,
            (2, 0): np.lib.format.read_array_header_2_0}.get(version)
    if read is None:
        raise ValueError(f"npy version {version} is not supported")
    shape, fortran, dtype = read(f)
    return tuple(shape), fortran, dtype, f.tell()


def _first_line(err) -> str:
    text = str(err).strip()
    return text.splitlines()[0][:200] if text else "no details"


def _check_shapes_agree(path, shapes):
    """Node arrays share one length, seg arrays another; a tree of N nodes has N + 1
    leaves and at least N segs.  Checked before any array is allocated."""
    nodes = {shapes[name][0] for name in NODE_ARRAYS}
    segs = {shapes[name][0] for name in SEG_ARRAYS}
    if len(nodes) != 1 or len(segs) != 1:
        raise TreeError(f"{path}: node or seg arrays disagree in length")
    (n_nodes,), (n_segs,) = nodes, segs
    if shapes["leaf_sector"][0] != n_nodes + 1 or n_segs < n_nodes:
        raise TreeError(f"{path}: {n_nodes} nodes, {shapes['leaf_sector'][0]} leaves and "
                        f"{n_segs} segs cannot form a tree")


def _read_array(path, zf, info, name, shape):
    """The member's data read in pieces straight into its array (no second copy)."""
    dtype = np.dtype(ARRAY_LAYOUT[name][0])
    out = np.empty(shape, dtype=dtype)
    view = memoryview(out.reshape(-1).view(np.uint8))
    with zf.open(info) as f:
        _npy_header(f)
        done = 0
        while done < len(view):
            piece = f.read(min(_CHUNK, len(view) - done))
            if not piece:
                raise TreeError(f"{path}: {name}: truncated")
            view[done:done + len(piece)] = piece
            done += len(piece)
        f.read(1)                 # reaching the end makes zipfile check the CRC
    if dtype == np.bool_ and out.view(np.uint8).max(initial=0) > 1:
        raise TreeError(f"{path}: {name}: a boolean that is neither 0 nor 1")
    return out
