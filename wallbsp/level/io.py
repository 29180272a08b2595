"""The level file (SPEC §2, §2b): reading and validating JSON, warnings, saving.

Reading: ``load_level(path)`` (a file, or ``-`` for standard input), ``loads_level(text)``
(JSON text) and ``level_from_dict(data)`` (a decoded JSON object) all validate and return a
``Level``; ``read_level_input(path)`` then ``level_from_input(data, path)`` is
``load_level`` in two steps, for a caller that looks at the bytes first (the CLI: tree or
level?).  ``parse_json(data, source)`` is the JSON decoding they share: any failure,
including nesting too deep for Python, is one ``LevelError`` line.
Writing (``levelwrite``): ``dumps_level(level)``, ``content_hash(level)``; here
``save_level(level, path)`` (validates, then writes atomically).

Required fields
    ``format`` (``"wallbsp-level"``), ``version`` (``1`` or ``2``), ``vertices``,
    ``sectors``, ``walls``; ``floor`` and ``ceiling`` of a sector; ``v1``, ``v2`` and
    ``front`` of a wall; ``x`` and ``y`` of ``start`` when ``start`` is given; ``x``, ``y``
    and ``type`` of a thing; ``sprite`` of a thing type.

Defaults of optional fields
    ``name``               the file's stem (``e1`` for ``maps/e1.json``); ``""`` when the
                           source is not a file name (``"<level>"``)
    ``start``              the centre of the vertices' bounding box (``(0, 0)`` without
                           vertices), angle 90 (looking north)
    ``start.angle``        90
    sector ``light``       160
    ``floor_color``        ``"#5a4a3a"``
    ``ceiling_color``      ``"#303038"``
    sector ``sky``         ``false``; ``true``: the ceiling is open sky, drawn in
                           ``ceiling_color`` at full brightness, never dimmed (DOOM's
                           F_SKY1).  An extension of SPEC §2, written only when true and
                           not implied by ``ceiling_texture`` ``"F_SKY1"``.
    wall ``back``          ``null`` (a one-sided, solid wall)
    wall ``color``         ``"#8c8c8c"``
    ``upper_color``, ``lower_color``   ``null``: the wall's ``color``

Version 2 (each optional; a version-1 file warns about them as unknown keys)
    ``resources``          ``[]``: a list of paths (WADs or PNG folders), relative to the
                           level file's folder
    ``sky``                ``null``: the sky texture's name
    ``things``             ``[]``; a thing's ``angle`` 0, ``flags`` 7
    ``thing_types``        ``{}``: ``{"TYPE": {"sprite", "radius" (20), "height" (16),
                           "solid" (false)}}``, TYPE an integer 0..65535 written in decimal
    wall ``front_side``, ``back_side``   ``null`` (colours only); in a side ``upper``,
                           ``middle``, ``lower`` are names (``"-"``, ``null`` or missing: no
                           texture), ``x_offset``, ``y_offset`` integers (0).  A one-sided
                           wall has no ``back_side``.
    wall ``upper_unpegged``, ``lower_unpegged``, ``blocks``, ``secret``,
                           ``blocks_sound``, ``hidden``   ``false`` (written only when true)
    wall and sector ``special``, ``tag``   ``0`` (integers 0..65535, DOOM's numbering)
    sector ``floor_texture``, ``ceiling_texture``   ``null`` (``"-"`` too)

Values
    Coordinates are integers (``3.0`` is rejected) with ``|x|, |y| <= 2**20``.  Heights,
    ``start.x``, ``start.y``, angles, radii and thing-type heights are integers or finite
    floats within the same ``±2**20``.  ``light`` is an integer 0..255.  Colors are
    ``"#rrggbb"`` (either case, kept as written).  Texture, flat and sprite names are
    non-empty strings without ``"/"``, kept as written (DOOM's have at most 8 characters;
    a PNG file's stem may be longer).  ``true``/``false`` is never a number.  Vertex and
    sector indices must exist; a wall's ends must be at different coordinates.

Errors and warnings
    Each is one line, ``source: json.path: what``, e.g.
    ``e1.json: walls[12].v2: vertex 99 does not exist (40 vertices)``; the path is
    ``(root)`` for problems with the file or document as a whole.  The first error raises
    ``LevelError``.  Warnings (legal but suspicious: unknown keys, a floor above its ceiling,
    duplicate, overlapping or crossing walls; a two-sided wall with the same sector on both
    sides is ordinary in DOOM maps, where it carries a see-through texture, and is no
    warning) are collected in ``Level.warnings`` in a fixed order: unknown keys in document
    order, then sectors, walls, duplicates, overlaps and crossings by wall index, each of
    the last three capped at ``MAX_REPORTED`` lines plus one ``... and N more`` line.
    With ``strict=True`` the first warning raises ``LevelError`` instead;
    ``check_conflicts=False`` leaves out the search for duplicate, overlapping and crossing
    walls (the tree file's reader does: its level was searched when it was compiled).
"""
from __future__ import annotations

import contextlib
import gc
import json
import os
from pathlib import Path
from typing import Any

from wallbsp.level.conflicts import conflict_warnings, find_wall_conflicts, too_many_crossings
from wallbsp.files import STDIN, InputError, read_input, write_atomically
from wallbsp.level.jsoncheck import ROOT, Checker, level_error
from wallbsp.level.model import Level, LevelError
from wallbsp.level.read import read_level
from wallbsp.level.write import content_hash, dumps_level, level_to_dict

MAX_REPORTED = 20            # per kind of wall conflict; a messy map stays readable
MAX_LEVEL_BYTES = 256 << 20  # far above any real map; stops /dev/zero-like input
STDIN_NAME = "<stdin>"

__all__ = ["MAX_LEVEL_BYTES", "MAX_REPORTED", "content_hash", "dumps_level", "input_name",
           "level_from_dict", "level_from_input", "level_to_dict", "load_level", "loads_level",
           "parse_json", "read_level_input", "save_level"]


def load_level(path, strict: bool = False) -> Level:
    """Read and validate a level file (``-``: standard input); messages name it as
    ``str(path)`` (``<stdin>``).  Relative resource paths are taken from the file's folder."""
    return level_from_input(read_level_input(path), path, strict)


def read_level_input(path) -> bytes:
    """The bytes of the file at ``path`` (``-``: standard input), refusing FIFOs, devices,
    directories and more than ``MAX_LEVEL_BYTES`` with one ``LevelError`` line."""
    try:
        return read_input(path, MAX_LEVEL_BYTES)
    except InputError as err:
        raise level_error(input_name(path), ROOT, err.reason) from None


def level_from_input(data: bytes, path, strict: bool = False) -> Level:
    """The level in ``data``, the bytes read from ``path`` (see ``read_level_input``)."""
    source_dir = None if input_name(path) == STDIN_NAME else Path(path).parent
    return loads_level(data, input_name(path), strict, source_dir)


def input_name(path) -> str:
    """How messages name the input at ``path``: ``<stdin>`` for ``-``."""
    return STDIN_NAME if os.fspath(path) == STDIN else str(path)


def loads_level(text: str | bytes, source: str = "<level>", strict: bool = False,
                source_dir=None) -> Level:
    """Parse and validate a level from JSON text (bytes: UTF-8)."""
    return level_from_dict(parse_json(text, source), source, strict, source_dir)


def parse_json(data: str | bytes, source: str) -> Any:
    """Decode JSON text (bytes: UTF-8, a byte order mark allowed); every failure, even
    nesting too deep for Python, is a one-line ``LevelError`` naming ``source``."""
    text = _utf8(data, source) if isinstance(data, (bytes, bytearray)) else data
    if not text or text.isspace():      # (strip() would copy a big file's text)
        raise level_error(source, ROOT, "the file is empty (expected a JSON object)")
    try:
        with _gc_paused():
            return json.loads(text)
    except json.JSONDecodeError as err:
        raise level_error(source, ROOT, f"malformed JSON at line {err.lineno}, column "
                                        f"{err.colno}: {err.msg}") from None
    except (ValueError, RecursionError) as err:   # e.g. a 5000-digit number, deep nesting
        first = str(err).splitlines()[0] if str(err) else type(err).__name__
        raise level_error(source, ROOT, f"malformed JSON: {first}") from None


def _utf8(raw: bytes, source: str) -> str:
    try:
        return raw.decode("utf-8-sig")    # editors on Windows like to add a BOM
    except UnicodeDecodeError as err:
        raise level_error(source, ROOT, f"not UTF-8 text (byte 0x{raw[err.start]:02x} at "
                                        f"offset {err.start})") from None


def level_from_dict(data: Any, source: str = "<level>", strict: bool = False,
                    source_dir=None, check_conflicts: bool = True) -> Level:
    """Validate a decoded JSON object (SPEC §2, §2b) and build the Level it describes.

    Raises ``LevelError`` on the first error, or with ``strict=True`` on the first
    warning; otherwise the warnings are in ``level.warnings``.  ``check_conflicts=False``
    skips the search for duplicate, overlapping and crossing walls, which are warnings
    only (a compiled tree's level was searched when it was compiled)."""
    check = Checker(source)
    with _gc_paused():
        fields = read_level(check, data)
    level = Level(**fields, source=source, warnings=check.warnings,
                  source_dir=None if source_dir is None else Path(source_dir))
    _warn_suspicious(check, level, check_conflicts)
    if strict and check.warnings:
        raise LevelError(check.warnings[0])
    return level


@contextlib.contextmanager
def _gc_paused():
    """Python's cycle collector off for a while.  Decoding and reading a big level makes
    some 10^5 containers and frees none: the collector would walk the growing heap again
    and again (a quarter of the time) to find nothing."""
    if not gc.isenabled():
        yield
        return
    gc.disable()
    try:
        yield
    finally:
        gc.enable()


def save_level(level: Level, path) -> None:
    """Write the level atomically: the file is either the old one or the whole new one.

    The level is validated first (``LevelError`` names ``path``), so a saved file always
    loads.  A failure to write raises ``OSError`` naming ``path``."""
    level_from_dict(level_to_dict(level), source=str(path))
    write_atomically(path, dumps_level(level).encode("utf-8"))


# ---------------------------------------------------------------------------------------
# Warnings: legal but suspicious

def _warn_suspicious(check: Checker, level: Level, check_conflicts: bool) -> None:
    for i, s in enumerate(level.sectors):
        if s.floor > s.ceiling:
            check.warn(f"sectors[{i}].floor", f"floor {s.floor} is above ceiling {s.ceiling} "
                                              f"(drawn closed, like a shut door)")
    if check_conflicts and len(level.walls) > 1:
        segments = level.segments()
        conflicts = find_wall_conflicts(segments)
        refused = too_many_crossings(conflicts, len(level.walls))
        if refused:
            raise level_error(level.source, "walls", refused)
        for wall, what in conflict_warnings(segments, MAX_REPORTED, conflicts):
            check.warn("walls" if wall is None else f"walls[{wall}]", what)
