"""Levels: the JSON level format of SPEC §2, its validation, warnings and saving.

Everything the rest of the package needs from a level is in the dataclasses below;
their field names are the JSON names.

Reading: ``load_level(path)`` (a file), ``loads_level(text)`` (JSON text) and
``level_from_dict(data)`` (a decoded JSON object) all validate and return a ``Level``.
Writing: ``Level.to_dict()``, ``dumps_level(level)`` (deterministic JSON, one vertex,
sector or wall per line) and ``Level.save(path)`` (atomic).  ``Level.content_hash()`` is
the sha256 of ``dumps_level``, so equal levels hash equal.  Level equality (``==``) is about
content: ``source`` and ``warnings`` are not compared.  ``find_wall_conflicts(segments)``
is the exact crossing/overlap/duplicate search behind the warnings.

Required fields
    ``format`` (``"wallbsp-level"``), ``version`` (``1``), ``vertices``, ``sectors``,
    ``walls``; ``floor`` and ``ceiling`` of a sector; ``v1``, ``v2`` and ``front`` of a
    wall; ``x`` and ``y`` of ``start`` when ``start`` is given.

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
                           F_SKY1).  An extension of SPEC §2, written only when true.
    wall ``back``          ``null`` (a one-sided, solid wall)
    wall ``color``         ``"#8c8c8c"``
    ``upper_color``, ``lower_color``   ``null``: the wall's ``color``

Values
    Coordinates are integers (``3.0`` is rejected) with ``|x|, |y| <= 2**20``.  Heights,
    ``start.x``, ``start.y`` and ``start.angle`` are integers or finite floats within the
    same ``±2**20``.  ``light`` is an integer 0..255.  Colors are ``"#rrggbb"`` (either case,
    kept as written).  ``true``/``false`` is never a number.  Vertex and sector indices
    must exist; a wall's ends must be at different coordinates.

Errors and warnings
    Each is one line, ``source: json.path: what``, e.g.
    ``e1.json: walls[12].v2: vertex 99 does not exist (40 vertices)``; the path is
    ``(root)`` for problems with the file or document as a whole.  The first error raises
    ``LevelError``.  Warnings (legal but suspicious: unknown keys, a floor above its ceiling,
    duplicate, overlapping or crossing walls; a two-sided wall with the same sector on both
    sides is ordinary in DOOM maps, where it carries a see-through texture, and is no warning) are collected in ``Level.warnings`` in a fixed order: unknown keys in document
    order, then sectors, walls, duplicates, overlaps and crossings by wall index, each of
    the last three capped at ``MAX_REPORTED`` lines plus one ``... and N more`` line.
    With ``strict=True`` the first warning raises ``LevelError`` instead.

Saving writes every field explicitly (defaults included) except ``upper_color`` and
``lower_color`` when they are ``None``, and writes whole-number floats as integers
(``90.0`` as ``90``), so a saved level reloads equal to the original.  Unknown keys are
not kept.
"""
from __future__ import annotations

import difflib
import hashlib
import json
import math
import re
from dataclasses import dataclass, field
from fractions import Fraction
from pathlib import Path
from typing import Any, NamedTuple, NoReturn

import numpy as np

from .files import write_atomically
from .geometry import COORD_LIMIT

FORMAT = "wallbsp-level"
VERSION = 1
MAX_REPORTED = 20            # per kind of wall conflict; a messy map stays readable
MAX_LIGHT = 255

_ROOT_KEYS = ("format", "version", "name", "vertices", "sectors", "walls", "start")
_SECTOR_KEYS = ("floor", "ceiling", "light", "floor_color", "ceiling_color", "sky")
_WALL_KEYS = ("v1", "v2", "front", "back", "color", "upper_color", "lower_color")
_START_KEYS = ("x", "y", "angle")
_WALL_KEY_SET = frozenset(_WALL_KEYS)
_WALL_COLOR_KEYS = ("color", "upper_color", "lower_color")
_COLOR = re.compile(r"#[0-9a-fA-F]{6}")
_PLAIN_KEY = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")


class LevelError(ValueError):
    """Bad input, as one line: ``file: json.path: what is wrong``."""


@dataclass(frozen=True)
class Sector:
    floor: float
    ceiling: float
    light: int = 160
    floor_color: str = "#5a4a3a"
    ceiling_color: str = "#303038"
    sky: bool = False


@dataclass(frozen=True)
class Wall:
    v1: int
    v2: int
    front: int
    back: int | None = None
    color: str = "#8c8c8c"
    upper_color: str | None = None   # None: same as color
    lower_color: str | None = None   # None: same as color

    @property
    def drawn_upper_color(self) -> str:
        return self.color if self.upper_color is None else self.upper_color

    @property
    def drawn_lower_color(self) -> str:
        return self.color if self.lower_color is None else self.lower_color


@dataclass(frozen=True)
class Start:
    x: float
    y: float
    angle: float = 90.0


@dataclass
class Level:
    name: str
    vertices: list[tuple[int, int]]
    sectors: list[Sector]
    walls: list[Wall]
    start: Start
    # where a level came from and what was suspicious about it are not its content
    source: str = field(default="<level>", compare=False)   # the file name used in messages
    warnings: list[str] = field(default_factory=list, compare=False)

    def segments(self) -> np.ndarray:
        """The walls' ends as an ``(n, 4)`` int64 array of ``x1, y1, x2, y2`` (v1 → v2)."""
        ends = [self.vertices[w.v1] + self.vertices[w.v2] for w in self.walls]
        return np.array(ends, dtype=np.int64).reshape(-1, 4)

    def to_dict(self) -> dict[str, Any]:
        """The level as a JSON object, every field written out (see the module docstring)."""
        return {
            "format": FORMAT,
            "version": VERSION,
            "name": self.name,
            "vertices": [[_plain(x), _plain(y)] for x, y in self.vertices],
            "sectors": [_sector_dict(s) for s in self.sectors],
            "walls": [_wall_dict(w) for w in self.walls],
            "start": {"x": _plain(self.start.x), "y": _plain(self.start.y),
                      "angle": _plain(self.start.angle)},
        }

    def content_hash(self) -> str:
        """sha256 (hex) of the canonical JSON: equal levels have equal hashes."""
        return hashlib.sha256(dumps_level(self).encode("utf-8")).hexdigest()

    def save(self, path) -> None:
        """Write the level atomically: the file is either the old one or the whole new one.

        The level is validated first (``LevelError`` names ``path``), so a saved file always
        loads.  A failure to write raises ``OSError`` naming ``path``."""
        level_from_dict(self.to_dict(), source=str(path))
        write_atomically(path, dumps_level(self).encode("utf-8"))


# ---------------------------------------------------------------------------------------
# Reading

def load_level(path, strict: bool = False) -> Level:
    """Read and validate a level file; messages name it as ``str(path)``."""
    source = str(path)
    try:
        raw = Path(path).read_bytes()
    except FileNotFoundError:
        raise _error(source, "(root)", "no such file") from None
    except IsADirectoryError:
        raise _error(source, "(root)", "is a directory, not a level file") from None
    except OSError as err:
        raise _error(source, "(root)", f"cannot read: {err.strerror or err}") from None
    try:
        text = raw.decode("utf-8-sig")    # editors on Windows like to add a BOM
    except UnicodeDecodeError as err:
        raise _error(source, "(root)", f"not UTF-8 text (byte 0x{raw[err.start]:02x} at "
                                       f"offset {err.start})") from None
    return loads_level(text, source=source, strict=strict)


def loads_level(text: str, source: str = "<level>", strict: bool = False) -> Level:
    """Parse and validate a level from JSON text."""
    return level_from_dict(_parse_json(text, source), source=source, strict=strict)


def _parse_json(text: str, source: str) -> Any:
    if not text.strip():
        raise _error(source, "(root)", "the file is empty (expected a JSON object)")
    try:
        return json.loads(text)
    except json.JSONDecodeError as err:
        raise _error(source, "(root)", f"malformed JSON at line {err.lineno}, column "
                                       f"{err.colno}: {err.msg}") from None
    except (ValueError, RecursionError) as err:   # e.g. a 5000-digit number, deep nesting
        raise _error(source, "(root)", f"malformed JSON: "
                                       f"{_first_line(str(err)) or type(err).__name__}") from None


def level_from_dict(data: Any, source: str = "<level>", strict: bool = False) -> Level:
    """Validate a decoded JSON object (SPEC §2) and build the Level it describes.

    Raises ``LevelError`` on the first error, or with ``strict=True`` on the first
    warning; otherwise the warnings are in ``level.warnings``."""
    check = _Checker(source)
    root = check.fields(data, "(root)", _ROOT_KEYS)
    _check_format(check, root)
    name = _read_name(check, root)
    vertices = _read_vertices(check, root)
    sectors = _read_sectors(check, root)
    walls = _read_walls(check, root, vertices, len(sectors))
    start = _read_start(check, root, vertices)
    level = Level(name, vertices, sectors, walls, start, source=source)
    _warn_suspicious(check, level)
    level.warnings = check.warnings
    if strict and check.warnings:
        raise LevelError(check.warnings[0])
    return level


class _Checker:
    """Where messages go: errors raise at once, warnings are collected in order."""

    def __init__(self, source: str):
        self.source = source
        self.warnings: list[str] = []
        self._good_colors: set[str] = set()     # a map uses few colors many times

    def fail(self, path: str, what: str) -> NoReturn:
        _fail(self.source, path, what)

    def warn(self, path: str, what: str) -> None:
        self.warnings.append(_message(self.source, path, what))

    def fields(self, value: Any, path: str, known: tuple[str, ...]) -> dict:
        """The JSON object at path; its unknown keys are warned about, not kept."""
        if not isinstance(value, dict):
            self.fail(path, f"expected an object, got {_describe(value)}")
        for key in value:
            if key not in known:
                self.warn(_child(path, str(key)),
                          f"unknown key, ignored{_did_you_mean(str(key), known)}")
        return value

    def required(self, obj: dict, key: str, path: str) -> Any:
        if key not in obj:
            self.fail(_child(path, key), "missing (required)")
        return obj[key]

    def list(self, obj: dict, key: str) -> list:
        value = self.required(obj, key, "(root)")
        if not isinstance(value, (list, tuple)):
            self.fail(key, f"expected a list, got {_describe(value)}")
        return value

    def integer(self, value: Any, path: str, what: str) -> int:
        if isinstance(value, (int, np.integer)) and not isinstance(value, bool):
            return int(value)
        if isinstance(value, float) and math.isfinite(value) and value.is_integer():
            self.fail(path, f"expected {what}, got the float {value!r} "
                            f"(write it without the fraction: {int(value)})")
        self.fail(path, f"expected {what}, got {_describe(value)}")

    def number(self, value: Any, path: str, what: str) -> int | float:
        """An integer or finite float within ±COORD_LIMIT (the one range of the map)."""
        if isinstance(value, bool) or not isinstance(value, (int, float, np.integer,
                                                             np.floating)):
            self.fail(path, f"expected {what} (a number), got {_describe(value)}")
        if isinstance(value, (float, np.floating)) and not math.isfinite(value):
            self.fail(path, f"expected {what} (a finite number), got {_describe(value)}")
        if abs(value) > COORD_LIMIT:
            self.fail(path, f"{what} {_short(value)} is out of range (|value| <= 2**20)")
        return _plain(value)

    def coordinate(self, value: Any, path: str, axis: str) -> int:
        value = self.integer(value, path, f"an integer {axis} coordinate")
        if abs(value) > COORD_LIMIT:
            self.fail(path, f"{axis} = {_short(value)} is out of range (|{axis}| <= 2**20 "
                            f"= {COORD_LIMIT})")
        return value

    def index(self, value: Any, path: str, thing: str, count: int) -> int:
        value = self.integer(value, path, f"an integer ({thing} index)")
        if not 0 <= value < count:
            plural = "vertices" if thing == "vertex" else thing + "s"
            self.fail(path, f"{thing} {_short(value)} does not exist ({count} {plural})")
        return value

    def all_seen_colors(self, values) -> bool:
        """Whether every value is a color already checked (a map reuses a few colors)."""
        try:
            return self._good_colors.issuperset(values)
        except TypeError:             # an unhashable value: not a color
            return False

    def is_color(self, value: Any) -> bool:
        if not isinstance(value, str):
            return False
        if value not in self._good_colors:
            if not _COLOR.fullmatch(value):
                return False
            self._good_colors.add(value)
        return True

    def color(self, value: Any, path: str) -> str:
        if not self.is_color(value):
            self.fail(path, f'expected a color "#rrggbb", got {_describe(value)}')
        return value


def _check_format(check: _Checker, root: dict) -> None:
    fmt = check.required(root, "format", "(root)")
    if not isinstance(fmt, str) or fmt != FORMAT:
        check.fail("format", f'expected "{FORMAT}", got {_describe(fmt)}')
    version = check.required(root, "version", "(root)")
    check.integer(version, "version", f"the integer {VERSION}")
    if version != VERSION:
        check.fail("version", f"unsupported version {_short(version)} "
                              f"(this wallbsp reads version {VERSION})")


def _read_name(check: _Checker, root: dict) -> str:
    if "name" not in root:
        return _default_name(check.source)
    if not isinstance(root["name"], str):
        check.fail("name", f"expected a string, got {_describe(root['name'])}")
    return root["name"]


def _default_name(source: str) -> str:
    return "" if source.startswith("<") else Path(source).stem


def _read_vertices(check: _Checker, root: dict) -> list[tuple[int, int]]:
    return [_read_vertex(check, item, i) for i, item in enumerate(check.list(root, "vertices"))]


def _read_vertex(check: _Checker, item: Any, i: int) -> tuple[int, int]:
    # the common case costs one test; the rest is for saying what is wrong
    if type(item) is list and len(item) == 2:
        x, y = item
        if (type(x) is int and type(y) is int
                and -COORD_LIMIT <= x <= COORD_LIMIT and -COORD_LIMIT <= y <= COORD_LIMIT):
            return (x, y)
    path = f"vertices[{i}]"
    if not isinstance(item, (list, tuple)) or len(item) != 2:
        check.fail(path, f"expected a pair [x, y], got {_describe(item)}")
    return (check.coordinate(item[0], path + "[0]", "x"),
            check.coordinate(item[1], path + "[1]", "y"))


def _read_sectors(check: _Checker, root: dict) -> list[Sector]:
    return [_read_sector(check, item, f"sectors[{i}]")
            for i, item in enumerate(check.list(root, "sectors"))]


def _read_sector(check: _Checker, item: Any, path: str) -> Sector:
    obj = check.fields(item, path, _SECTOR_KEYS)
    floor = check.number(check.required(obj, "floor", path), path + ".floor", "a floor height")
    ceiling = check.number(check.required(obj, "ceiling", path), path + ".ceiling",
                           "a ceiling height")
    optional = {}
    if "light" in obj:
        optional["light"] = _read_light(check, obj["light"], path + ".light")
    for key in ("floor_color", "ceiling_color"):
        if key in obj:
            optional[key] = check.color(obj[key], f"{path}.{key}")
    if "sky" in obj:
        if not isinstance(obj["sky"], bool):
            check.fail(path + ".sky", f"expected true or false, got {_describe(obj['sky'])}")
        optional["sky"] = obj["sky"]
    return Sector(floor, ceiling, **optional)


def _read_light(check: _Checker, value: Any, path: str) -> int:
    light = check.integer(value, path, f"an integer light level 0..{MAX_LIGHT}")
    if not 0 <= light <= MAX_LIGHT:
        check.fail(path, f"light {_short(light)} is outside 0..{MAX_LIGHT}")
    return light


def _read_walls(check: _Checker, root: dict, vertices: list, n_sectors: int) -> list[Wall]:
    walls = []
    for i, item in enumerate(check.list(root, "walls")):
        wall = (_plain_wall(check, item, len(vertices), n_sectors)
                or _read_wall(check, item, f"walls[{i}]", len(vertices), n_sectors))
        if vertices[wall.v1] == vertices[wall.v2]:
            x, y = vertices[wall.v1]
            check.fail(f"walls[{i}]", f"zero-length wall: v1 (vertex {wall.v1}) and v2 (vertex "
                                      f"{wall.v2}) are both at ({x}, {y})")
        walls.append(wall)
    return walls


def _plain_wall(check: _Checker, item: Any, n_vertices: int, n_sectors: int) -> Wall | None:
    """The wall, when it is valid and has nothing unusual (most walls of a big map);
    None sends it to ``_read_wall``, which says what is wrong."""
    if type(item) is not dict or not item.keys() <= _WALL_KEY_SET:
        return None
    v1, v2, front, back = item.get("v1"), item.get("v2"), item.get("front"), item.get("back")
    if not (type(v1) is int and 0 <= v1 < n_vertices and type(v2) is int and 0 <= v2 < n_vertices
            and type(front) is int and 0 <= front < n_sectors
            and (back is None or type(back) is int and 0 <= back < n_sectors)):
        return None
    colors = {key: item[key] for key in _WALL_COLOR_KEYS if key in item}
    if not check.all_seen_colors(colors.values()):
        return None
    return Wall(v1, v2, front, back, **colors)


def _read_wall(check: _Checker, item: Any, path: str, n_vertices: int, n_sectors: int) -> Wall:
    obj = check.fields(item, path, _WALL_KEYS)
    v1 = check.index(check.required(obj, "v1", path), path + ".v1", "vertex", n_vertices)
    v2 = check.index(check.required(obj, "v2", path), path + ".v2", "vertex", n_vertices)
    front = check.index(check.required(obj, "front", path), path + ".front", "sector", n_sectors)
    back = obj.get("back")
    if back is not None:
        back = check.index(back, path + ".back", "sector", n_sectors)
    optional = {}
    if "color" in obj:
        optional["color"] = check.color(obj["color"], path + ".color")
    for key in ("upper_color", "lower_color"):
        if obj.get(key) is not None:
            optional[key] = check.color(obj[key], f"{path}.{key}")
    return Wall(v1, v2, front, back, **optional)


def _read_start(check: _Checker, root: dict, vertices: list) -> Start:
    if "start" not in root:
        return Start(*_bbox_centre(vertices))
    obj = check.fields(root["start"], "start", _START_KEYS)
    x = check.number(check.required(obj, "x", "start"), "start.x", "an x position")
    y = check.number(check.required(obj, "y", "start"), "start.y", "a y position")
    if "angle" not in obj:
        return Start(x, y)
    return Start(x, y, check.number(obj["angle"], "start.angle", "an angle in degrees"))


def _bbox_centre(vertices: list) -> tuple[int | float, int | float]:
    if not vertices:
        return (0, 0)
    xy = np.array(vertices, dtype=np.int64)
    lo, hi = xy.min(axis=0), xy.max(axis=0)
    return (_plain(int(lo[0] + hi[0]) / 2), _plain(int(lo[1] + hi[1]) / 2))


# ---------------------------------------------------------------------------------------
# Warnings: legal but suspicious

def _warn_suspicious(check: _Checker, level: Level) -> None:
    for i, s in enumerate(level.sectors):
        if s.floor > s.ceiling:
            check.warn(f"sectors[{i}].floor", f"floor {s.floor} is above ceiling {s.ceiling} "
                                              f"(drawn closed, like a shut door)")
    if len(level.walls) > 1:
        _warn_conflicts(check, level.segments())


def _warn_conflicts(check: _Checker, seg: np.ndarray) -> None:
    conflicts = find_wall_conflicts(seg)
    _warn_capped(check, [(j, f"duplicates walls[{i}] (same ends{_ends(seg, i)})")
                         for i, j in conflicts.duplicates.tolist()[:MAX_REPORTED]],
                 "duplicate walls", total=len(conflicts.duplicates))
    _warn_capped(check, [(i, f"overlaps walls[{j}] (collinear, sharing "
                             f"{_shared_stretch(seg[i], seg[j])})")
                         for i, j in conflicts.overlaps.tolist()[:MAX_REPORTED]],
                 "overlapping walls", total=len(conflicts.overlaps))
    _warn_capped(check, [(i, f"crosses walls[{j}] at {_crossing_point(seg[i], seg[j])}")
                         for i, j in conflicts.crossings.tolist()[:MAX_REPORTED]],
                 "crossings", total=len(conflicts.crossings))


def _warn_capped(check: _Checker, lines: list, noun: str, total: int) -> None:
    for wall, what in lines:
        check.warn(f"walls[{wall}]", what)
    if total > MAX_REPORTED:
        check.warn("walls", f"... and {total - MAX_REPORTED} more {noun}")


def _ends(seg: np.ndarray, i: int) -> str:
    x1, y1, x2, y2 = seg[i].tolist()
    return f" ({x1}, {y1}) and ({x2}, {y2})"


def _shared_stretch(a: np.ndarray, b: np.ndarray) -> str:
    """The common part of two collinear walls: its ends are two of the four wall ends."""
    axis = 0 if abs(int(a[2] - a[0])) >= abs(int(a[3] - a[1])) else 1
    points = sorted([tuple(a[:2].tolist()), tuple(a[2:].tolist()),
                     tuple(b[:2].tolist()), tuple(b[2:].tolist())], key=lambda p: p[axis])
    (x1, y1), (x2, y2) = points[1], points[2]
    return f"({x1}, {y1}) to ({x2}, {y2})"


def _crossing_point(a: np.ndarray, b: np.ndarray) -> str:
    ax, ay, bx, by = a.tolist()
    cx, cy, dx, dy = b.tolist()
    s_a = (dx - cx) * (ay - cy) - (dy - cy) * (ax - cx)
    s_b = (dx - cx) * (by - cy) - (dy - cy) * (bx - cx)
    t = Fraction(s_a, s_a - s_b)
    return f"({_decimal(ax + t * (bx - ax))}, {_decimal(ay + t * (by - ay))})"


def _decimal(value: Fraction) -> str:
    if value.denominator == 1:
        return str(value.numerator)
    return f"{float(value):.3f}".rstrip("0").rstrip(".")


# ---------------------------------------------------------------------------------------
# Wall conflicts: exact integer tests on candidate pairs from a uniform grid

class WallConflicts(NamedTuple):
    """Pairs of wall indices, each ``(k, 2)`` int64, sorted."""
    crossings: np.ndarray    # (i, j), i < j: the interiors cross at a single point
    overlaps: np.ndarray     # (i, j), i < j: collinear, sharing a stretch of positive length,
    #                          with different ends (those are duplicates)
    duplicates: np.ndarray   # (first, later): later has the same two ends as first,
    #                          in either direction; sorted by later


def find_wall_conflicts(segments) -> WallConflicts:
    """Crossing, overlapping and duplicate walls among ``(n, 4)`` integer segments
    ``x1, y1, x2, y2`` with ``|coordinates| <= 2**20`` and no zero-length segment.

    Walls that only touch (a shared end, an end on another wall: a T-junction) do not
    conflict.  Candidate pairs share a grid cell, so the cost grows with the number of
    walls near each other, not with the square of the number of walls."""
    seg = np.asarray(segments, dtype=np.int64).reshape(-1, 4)
    crossings, overlaps = [], []
    for i, j in _candidate_batches(seg):
        crossing, overlapping = _conflicts_among(seg, i, j)
        crossings.append(crossing)
        overlaps.append(overlapping)
    n = len(seg)
    return WallConflicts(_unique_pairs(crossings, n), _unique_pairs(overlaps, n),
                         _duplicate_pairs(seg))


def _unique_pairs(batches: list, n: int) -> np.ndarray:
    """Sorted distinct rows: two walls sharing several cells are found once per cell."""
    if not batches:
        return np.empty((0, 2), dtype=np.int64)
    pairs = np.concatenate(batches)
    codes = np.unique(pairs[:, 0] * n + pairs[:, 1])
    return np.column_stack((codes // n, codes % n))


def _orient(px, py, qx, qy, rx, ry):
    """Twice the signed area of p, q, r: > 0 when r is left of p → q.  Below 2**43 in
    magnitude for map coordinates, so int64 is exact."""
    return (qx - px) * (ry - py) - (qy - py) * (rx - px)


def _conflicts_among(seg: np.ndarray, i: np.ndarray, j: np.ndarray):
    """The crossing pairs and the overlapping (not duplicate) pairs among candidates (i, j)."""
    ax, ay, bx, by = seg[i].T
    cx, cy, dx, dy = seg[j].T
    s1 = np.sign(_orient(ax, ay, bx, by, cx, cy))
    s2 = np.sign(_orient(ax, ay, bx, by, dx, dy))
    # wall j strictly on one side of wall i's line can neither cross nor overlap it
    near = np.flatnonzero(s1 * s2 <= 0)
    i, j, s1, s2 = i[near], j[near], s1[near], s2[near]
    ax, ay, bx, by, cx, cy, dx, dy = (v[near] for v in (ax, ay, bx, by, cx, cy, dx, dy))
    s3 = np.sign(_orient(cx, cy, dx, dy, ax, ay))
    s4 = np.sign(_orient(cx, cy, dx, dy, bx, by))
    crossing = (s1 * s2 < 0) & (s3 * s4 < 0)
    collinear = np.flatnonzero((s1 == 0) & (s2 == 0))
    overlapping = _share_a_stretch(seg[i[collinear]], seg[j[collinear]])
    return (np.column_stack((i[crossing], j[crossing])),
            np.column_stack((i[collinear[overlapping]], j[collinear[overlapping]])))


def _share_a_stretch(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """For collinear walls a[k], b[k]: a common part of positive length, other ends."""
    ax, ay, bx, by = a.T
    cx, cy, dx, dy = b.T
    # along a's dominant axis the projection of its line is one-to-one
    use_x = np.abs(bx - ax) >= np.abs(by - ay)
    p1, p2 = np.where(use_x, ax, ay), np.where(use_x, bx, by)
    q1, q2 = np.where(use_x, cx, cy), np.where(use_x, dx, dy)
    shared = (np.minimum(np.maximum(p1, p2), np.maximum(q1, q2))
              - np.maximum(np.minimum(p1, p2), np.minimum(q1, q2)))
    same_ends = (np.all(a == b, axis=1)
                 | ((ax == dx) & (ay == dy) & (bx == cx) & (by == cy)))
    return (shared > 0) & ~same_ends


def _duplicate_pairs(seg: np.ndarray) -> np.ndarray:
    """(first, later) for every wall whose two ends an earlier wall already has."""
    n = len(seg)
    if n < 2:
        return np.empty((0, 2), dtype=np.int64)
    swap = (seg[:, 0] > seg[:, 2]) | ((seg[:, 0] == seg[:, 2]) & (seg[:, 1] > seg[:, 3]))
    ends = np.where(swap[:, None], seg[:, [2, 3, 0, 1]], seg)
    order = np.lexsort((np.arange(n), ends[:, 3], ends[:, 2], ends[:, 1], ends[:, 0]))
    ends = ends[order]
    starts_group = np.ones(n, dtype=bool)
    starts_group[1:] = np.any(ends[1:] != ends[:-1], axis=1)
    first = order[np.maximum.accumulate(np.where(starts_group, np.arange(n), 0))]
    pairs = np.column_stack((first[~starts_group], order[~starts_group]))
    return pairs[np.argsort(pairs[:, 1], kind="stable")]


def _candidate_batches(seg: np.ndarray, batch: int = 1 << 20):
    """Pairs (i, j), i < j, of walls listed in a common grid cell, in batches of about
    ``batch`` pairs so memory stays bounded however crowded a cell is.  A pair of walls
    sharing several cells comes once per cell."""
    if len(seg) < 2:
        return
    walls, cells = _cells_touched(seg, _cell_size(seg))
    order = np.lexsort((walls, cells))          # by cell, then wall: so i < j below
    walls, cells = walls[order], cells[order]
    later = _later_in_run(cells)
    cuts = np.searchsorted(np.cumsum(later), np.arange(batch, int(later.sum()), batch))
    edges = np.unique(np.r_[0, cuts, len(cells)]).tolist()
    for start, end in zip(edges[:-1], edges[1:]):
        left = np.repeat(np.arange(start, end), later[start:end])
        right = left + 1 + _ranks_within_runs(later[start:end])
        yield walls[left], walls[right]


def _cell_size(seg: np.ndarray) -> int:
    """About one typical wall, so most walls touch few cells; at least a quarter of the
    mean extent, so a few very long walls cannot multiply the cell count."""
    extent = np.maximum(np.abs(seg[:, 2] - seg[:, 0]), np.abs(seg[:, 3] - seg[:, 1]))
    return max(1, int(np.median(extent)), int(extent.mean() // 4))


def _cells_touched(seg: np.ndarray, cell: int):
    """(wall, cell code) for every grid cell a wall passes through or touches.

    A wall is walked along its dominant axis one column of cells at a time; within a
    column its other coordinate changes by at most one cell, so it touches at most two.
    Any point two walls share lies in a cell both are listed in."""
    dx, dy = np.abs(seg[:, 2] - seg[:, 0]), np.abs(seg[:, 3] - seg[:, 1])
    x_major = (dx >= dy) & (dx > 0)
    y_major = dy > dx                # zero-length walls touch nothing (they are errors)
    walls_x, major_x, minor_x = _columns_walked(seg[x_major], cell)
    walls_y, major_y, minor_y = _columns_walked(seg[y_major][:, [1, 0, 3, 2]], cell)
    walls = np.concatenate((np.flatnonzero(x_major)[walls_x], np.flatnonzero(y_major)[walls_y]))
    cx = np.concatenate((major_x, minor_y))
    cy = np.concatenate((minor_x, major_y))
    offset = COORD_LIMIT + 1        # cell coordinates are >= -COORD_LIMIT
    return walls, (cx + offset) * (4 * offset) + (cy + offset)


def _columns_walked(seg: np.ndarray, cell: int):
    """(wall, column, row) of every cell touched by walls with ``|dx| >= |dy|``, dx != 0."""
    x1, y1, x2, y2 = seg.T
    flip = x1 > x2
    xa, ya = np.where(flip, x2, x1), np.where(flip, y2, y1)
    xb, yb = np.where(flip, x1, x2), np.where(flip, y1, y2)
    first, last = xa // cell, xb // cell
    wall = np.repeat(np.arange(len(seg)), last - first + 1)
    column = first[wall] + _ranks_within_runs(last - first + 1)
    # the wall's y at the column's two edges, clipped to its ends, exactly as rows:
    # row = floor((ya*dx + (x - xa)*dy) / (dx*cell)), all below 2**44
    dx, dy = (xb - xa)[wall], (yb - ya)[wall]
    x_lo = np.maximum(xa[wall], column * cell)
    x_hi = np.minimum(xb[wall], (column + 1) * cell)
    base = ya[wall] * dx
    row_lo = (base + (x_lo - xa[wall]) * dy) // (dx * cell)
    row_hi = (base + (x_hi - xa[wall]) * dy) // (dx * cell)
    row_min, row_max = np.minimum(row_lo, row_hi), np.maximum(row_lo, row_hi)
    spans = row_max - row_min + 1
    index = np.repeat(np.arange(len(wall)), spans)
    return wall[index], column[index], row_min[index] + _ranks_within_runs(spans)


def _ranks_within_runs(lengths: np.ndarray) -> np.ndarray:
    """``concatenate([arange(k) for k in lengths])`` without a Python loop."""
    total = int(lengths.sum())
    starts = np.cumsum(lengths) - lengths
    return np.arange(total) - np.repeat(starts, lengths)


def _later_in_run(keys: np.ndarray) -> np.ndarray:
    """For each entry of a sorted array, how many entries after it have the same key."""
    m = len(keys)
    run_starts = np.flatnonzero(np.r_[True, keys[1:] != keys[:-1]])
    run_ends = np.r_[run_starts[1:], m]
    return np.repeat(run_ends, np.diff(np.r_[run_starts, m])) - np.arange(m) - 1


# ---------------------------------------------------------------------------------------
# Writing

def dumps_level(level: Level) -> str:
    """Deterministic JSON: fixed key order, one vertex, sector or wall per line."""
    members = [f'  "{key}": {_dump_rows(value) if isinstance(value, list) else _dump_row(value)}'
               for key, value in level.to_dict().items()]
    return "{\n" + ",\n".join(members) + "\n}\n"


def _dump_rows(rows: list) -> str:
    if not rows:
        return "[]"
    return "[\n" + ",\n".join("    " + _dump_row(row) for row in rows) + "\n  ]"


def _dump_row(value: Any) -> str:
    return json.dumps(value, ensure_ascii=False, allow_nan=False, separators=(", ", ": "))


def _sector_dict(s: Sector) -> dict[str, Any]:
    out = {"floor": _plain(s.floor), "ceiling": _plain(s.ceiling), "light": s.light,
           "floor_color": s.floor_color, "ceiling_color": s.ceiling_color}
    if s.sky:
        out["sky"] = True
    return out


def _wall_dict(w: Wall) -> dict[str, Any]:
    out = {"v1": w.v1, "v2": w.v2, "front": w.front, "back": w.back, "color": w.color}
    if w.upper_color is not None:
        out["upper_color"] = w.upper_color
    if w.lower_color is not None:
        out["lower_color"] = w.lower_color
    return out


def _plain(value):
    """Whole-number floats as ints, so 90.0 and 90 are written (and hashed) alike;
    numpy scalars as Python numbers."""
    if isinstance(value, np.generic):
        value = value.item()
    if isinstance(value, float) and value.is_integer():
        return int(value)
    return value


# ---------------------------------------------------------------------------------------
# Messages

def _fail(source: str, path: str, what: str) -> NoReturn:
    raise _error(source, path, what)


def _error(source: str, path: str, what: str) -> LevelError:
    return LevelError(_message(source, path, what))


def _message(source: str, path: str, what: str) -> str:
    return _one_line(f"{source}: {path}: {what}")


def _one_line(text: str) -> str:
    """One line however odd the input: line breaks in a file name are shown escaped."""
    if text.isprintable():
        return text
    return "".join(c if c.isprintable() else repr(c)[1:-1] for c in text)


def _first_line(text: str) -> str:
    return text.splitlines()[0] if text else ""


def _child(path: str, key: str) -> str:
    name = key if _PLAIN_KEY.fullmatch(key) else f"[{json.dumps(key)}]"
    if path == "(root)":
        return name
    return f"{path}{name}" if name.startswith("[") else f"{path}.{name}"


def _did_you_mean(key: str, known: tuple[str, ...]) -> str:
    close = difflib.get_close_matches(key, known, n=1, cutoff=0.6)
    return f' (did you mean "{close[0]}"?)' if close else ""


def _describe(value: Any) -> str:
    """A JSON value as its author would name it, short and on one line."""
    if value is None:
        return "null"
    if isinstance(value, (bool, np.bool_)):
        return "true" if value else "false"
    if isinstance(value, (int, np.integer)):
        return f"the integer {_short(value)}"
    if isinstance(value, (float, np.floating)):
        if math.isnan(value):
            return "NaN"
        if math.isinf(value):
            return "Infinity" if value > 0 else "-Infinity"
        return f"the float {float(value)!r}"
    if isinstance(value, str):
        text = json.dumps(value)
        return "the string " + (text if len(text) <= 40 else text[:36] + '..."')
    if isinstance(value, (list, tuple)):
        return f"a list of {len(value)} item{'s' if len(value) != 1 else ''}"
    if isinstance(value, dict):
        return "an object"
    return f"a {type(value).__name__}"


def _short(value) -> str:
    """A number for a message; huge integers are not spelled out."""
    if isinstance(value, (int, np.integer)) and abs(int(value)) >= 10 ** 30:
        return f"{'-' if value < 0 else ''}<{abs(int(value)).bit_length()}-bit integer>"
    return str(value)
