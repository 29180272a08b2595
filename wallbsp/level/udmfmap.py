"""UDMF maps (a map marker, TEXTMAP ... ENDMAP) read into the record arrays of a DOOM-format
map, which ``wadmap`` then turns into a level exactly as it does THINGS, LINEDEFS, SIDEDEFS,
VERTEXES and SECTORS (so DOOM's numbering holds: sector i is the i-th ``sector`` block, thing
i the i-th ``thing`` block, walls follow the ``linedef`` blocks in order).

Namespaces: ``doom``, ``heretic``, ``strife`` and ``zdoomtranslated`` carry DOOM-numbered
specials, taken as they are (the tag is ``arg0``, or ``id`` when ``arg0`` is 0: the UDMF
specification has converters write a DOOM tag as both); ``zdoom``, ``hexen`` and ``vavoom``
carry Hexen-style action specials, which ``udmfspecials`` maps onto DOOM's numbers where DOOM
has the same action (doors, lifts, exits, teleports, a few floors), with one warning naming
the rest (they do nothing here).  A missing namespace is read as ``doom``, an unknown one as
``zdoom``, with a warning.

Fields (UDMF 1.1; unknown fields and blocks are ignored, as the specification asks):
- ``vertex``: x, y (floats; rounded to the nearest integer, one warning if any were not whole);
- ``linedef``: v1, v2, sidefront (required), sideback (-1: none), blocking, blockmonsters,
  twosided, dontpegtop, dontpegbottom, secret, blocksound, dontdraw, mapped → DOOM's flag
  bits; special, arg0..arg4, id;
- ``sidedef``: offsetx, offsety, texturetop, texturemiddle, texturebottom, sector (required);
- ``sector``: heightfloor, heightceiling, texturefloor, textureceiling (required), lightlevel
  (160), special, id (the tag);
- ``thing``: x, y, type (required), angle, skill1..skill5, ambush, single, coop, dm → DOOM's
  option bits (skill 1 or 2 → bit 0, 3 → bit 1, 4 or 5 → bit 2, ambush 8, not single 16, and
  Boom's not-deathmatch 32 and not-coop 64).
Scripts and other lumps of the map (BEHAVIOR, SCRIPTS, DIALOGUE, ZNODES, ...) and the WAD's
DECORATE, ZSCRIPT and LOADACS are reported as ignored in one warning.  A malformed TEXTMAP, a
missing required field, a value of the wrong type or an index out of range is one
``LevelError`` line: ``file.wad: MAP01: TEXTMAP:LINE:COLUMN: what``.
"""
from __future__ import annotations

import math

import numpy as np

from wallbsp.assets.wad import Wad, open_wad
from wallbsp.files import LevelError
from wallbsp.geometry import COORD_LIMIT
from wallbsp.level.format import MAX_NUMBER
from wallbsp.level.udmf import Block, Textmap, parse
from wallbsp.level.udmfspecials import (DOOM_STYLE, HEXEN_STYLE, hexen_line_special,
    hexen_sector_special)

NO_SIDE = 0xFFFF            # the vanilla sentinel ``wadmap`` reads as "no sidedef"
WAD_SCRIPT_LUMPS = ("DECORATE", "ZSCRIPT", "LOADACS")
LINE_FLAGS = {"blocking": 1, "blockmonsters": 2, "twosided": 4, "dontpegtop": 8,
              "dontpegbottom": 16, "secret": 32, "blocksound": 64, "dontdraw": 128,
              "mapped": 256}

THING = np.dtype([("x", "<i8"), ("y", "<i8"), ("angle", "<i8"), ("type", "<u2"),
                  ("flags", "<u2")])
LINEDEF = np.dtype([("v1", "<i8"), ("v2", "<i8"), ("flags", "<u2"), ("special", "<u2"),
                    ("tag", "<u2"), ("right", "<u4"), ("left", "<u4")])
VERTEX = np.dtype([("x", "<i8"), ("y", "<i8")])


def is_udmf(wad: Wad, map_name: str) -> bool:
    """Whether ``map_name`` is a UDMF map: its marker followed by TEXTMAP."""
    names = wad.names
    marker = wad.index.get(map_name)
    return marker is not None and marker + 1 < len(names) and names[marker + 1] == "TEXTMAP"


def map_is_udmf(wad_path, map_name: str) -> bool:
    """Whether map ``map_name`` of the WAD at ``wad_path`` is a UDMF map (DOOM's play
    simulation loads only DOOM-format map lumps; a UDMF map is played as its level)."""
    with open_wad(wad_path) as wad:
        return is_udmf(wad, map_name.upper())


def read_udmf_map(wad: Wad, map_name: str, notes: list[str]):
    """(things, linedefs, sidedefs, vertices, sectors) of a UDMF map as record arrays with the
    field names ``wadmap`` reads; warnings are appended to ``notes``."""
    where = f"{wad.label}: {map_name}"
    textmap, others = _map_lumps(wad, map_name, where)
    reader = _Reader(_parsed(wad.read(textmap), where), where, notes)
    arrays = reader.read()
    ignored = list(dict.fromkeys(others)) + [f"{n} (WAD)" for n in WAD_SCRIPT_LUMPS
                                             if n in wad.index]
    if reader.thing_specials:
        ignored.append(f"{reader.thing_specials} thing special"
                       f"{'s' * (reader.thing_specials > 1)}")
    if ignored:
        notes.append(f"{where}: ignored (wallbsp runs no ACS scripts or DECORATE actors and "
                     f"builds its own tree): {', '.join(ignored)}")
    return arrays


def read_textmap(raw: bytes, where: str, notes: list[str]):
    """(things, linedefs, sidedefs, vertices, sectors) from a TEXTMAP lump's bytes (``where``
    names the file and the map), as ``read_udmf_map`` reads them."""
    return _Reader(_parsed(raw, where), where, notes).read()


def _parsed(raw: bytes, where: str) -> Textmap:
    text = raw.decode("utf-8") if _is_utf8(raw) else raw.decode("latin-1")
    return parse(text, f"{where}: TEXTMAP")


def _is_utf8(raw: bytes) -> bool:
    try:
        raw.decode("utf-8")
    except UnicodeDecodeError:
        return False
    return True


def _map_lumps(wad: Wad, map_name: str, where: str) -> tuple[int, list[str]]:
    """TEXTMAP's directory index and the names of the map's other lumps up to ENDMAP."""
    names = wad.names
    start = wad.index[map_name] + 1
    for i in range(start + 1, len(names)):
        if names[i] == "ENDMAP":
            return start, names[start + 1:i]
    raise LevelError(f"{where}: ENDMAP: missing (a UDMF map ends with an ENDMAP lump)")


class _Reader:
    """Reads the blocks of one TEXTMAP into record arrays."""

    def __init__(self, textmap: Textmap, where: str, notes: list[str]):
        self.textmap, self.where, self.notes = textmap, where, notes
        self.thing_specials = self.fractional = 0
        self._sector_notes: dict[int, int] = {}      # special → sectors (one warning)
        self._bad_names: list[str] = []               # texture names no WAD can hold
        namespace = textmap.globals.get("namespace")
        if namespace is None:
            notes.append(f"{where}: TEXTMAP: no namespace; read as 'doom'")
            namespace = "doom"
        elif not isinstance(namespace, str):
            raise textmap.error(textmap.global_places["namespace"],
                                "namespace: expected a string")
        namespace = namespace.lower()
        if namespace not in DOOM_STYLE + HEXEN_STYLE:
            notes.append(f"{where}: TEXTMAP: unknown namespace {namespace!r}; read as 'zdoom'")
            namespace = "zdoom"
        self.hexen = namespace in HEXEN_STYLE

    # -- fields ---------------------------------------------------------------------------

    def _fail(self, block: Block, key: str | None, number: int, message: str) -> LevelError:
        at = block.where(key) if key else block.at
        return self.textmap.error(at, f"{block.kind} {number}: {message}")

    def _get(self, block: Block, number: int, key: str, kind: type, default=None):
        if key not in block.fields:
            if default is None:
                raise self._fail(block, None, number, f"missing required field {key!r}")
            return default
        value = block.fields[key]
        if kind is bool:
            if not isinstance(value, bool):
                raise self._fail(block, key, number, f"{key}: expected true or false, "
                                                     f"got {value!r}")
        elif kind is str:
            if not isinstance(value, str):
                raise self._fail(block, key, number, f"{key}: expected a string, got {value!r}")
        elif isinstance(value, bool) or not isinstance(value, (int, float)):
            raise self._fail(block, key, number, f"{key}: expected a number, got {value!r}")
        elif not math.isfinite(value):
            raise self._fail(block, key, number, f"{key}: {value!r} is not a finite number")
        elif kind is int:
            if value != int(value):
                raise self._fail(block, key, number, f"{key}: expected an integer, "
                                                     f"got {value!r}")
            value = int(value)
        return value

    def _int_in(self, block, number, key, low, high, default=None) -> int:
        value = self._get(block, number, key, int, default)
        if not low <= value <= high:
            raise self._fail(block, key, number, f"{key}: {value} is out of range "
                                                 f"({low}..{high})")
        return value

    def _index(self, block, number, key, count, noun, default=None) -> int:
        value = self._get(block, number, key, int, default)
        if value != -1 and not 0 <= value < count:
            plural = "vertices" if noun == "vertex" else noun + "s"
            raise self._fail(block, key, number, f"{key}: {noun} {value} does not exist "
                                                 f"({count} {plural})")
        return value

    def _flags(self, block, number, names: dict[str, int]) -> int:
        return sum(bit for key, bit in names.items()
                   if key in block.fields and self._get(block, number, key, bool))

    # -- blocks ---------------------------------------------------------------------------

    def read(self):
        kinds: dict[str, list[Block]] = {"vertex": [], "linedef": [], "sidedef": [],
                                         "sector": [], "thing": []}
        for block in self.textmap.blocks:
            if block.kind in kinds:
                kinds[block.kind].append(block)
        verts = self._vertices(kinds["vertex"])
        sectors = self._sectors(kinds["sector"])
        sides = self._sidedefs(kinds["sidedef"], len(sectors))
        lines = self._linedefs(kinds["linedef"], len(verts), len(sides))
        things = self._things(kinds["thing"])
        if self.fractional:
            self.notes.append(f"{self.where}: TEXTMAP: {self.fractional} fractional "
                              f"coordinate{'s' * (self.fractional > 1)} of vertices and things "
                              f"rounded to whole map units")
        self._note_names()
        return things, lines, sides, verts, sectors

    def _coordinate(self, block, number, key) -> int:
        value = self._get(block, number, key, float)
        whole = math.floor(value + 0.5)
        if whole != value:
            self.fractional += 1
        if abs(whole) > COORD_LIMIT:
            raise self._fail(block, key, number, f"{key}: {value!r} is out of range "
                                                 f"(|{key}| <= 2**20 = {COORD_LIMIT})")
        return whole

    def _vertices(self, blocks) -> np.ndarray:
        out = np.zeros(len(blocks), VERTEX)
        out["x"] = [self._coordinate(b, i, "x") for i, b in enumerate(blocks)]
        out["y"] = [self._coordinate(b, i, "y") for i, b in enumerate(blocks)]
        return out

    def _sectors(self, blocks) -> np.ndarray:
        rows = []
        for i, b in enumerate(blocks):
            special = self._get(b, i, "special", int, 0)
            if self.hexen:
                special = hexen_sector_special(special, self._sector_notes)
            rows.append((self._int_in(b, i, "heightfloor", -COORD_LIMIT, COORD_LIMIT, 0),
                         self._int_in(b, i, "heightceiling", -COORD_LIMIT, COORD_LIMIT, 0),
                         self._name(b, i, "texturefloor"), self._name(b, i, "textureceiling"),
                         self._get(b, i, "lightlevel", int, 160), self._number(special),
                         self._number(self._get(b, i, "id", int, 0))))
        return _records(rows, [("floor", "<i8"), ("ceiling", "<i8"), ("floor_flat", "S"),
                               ("ceiling_flat", "S"), ("light", "<i8"), ("special", "<u2"),
                               ("tag", "<u2")])

    def _sidedefs(self, blocks, n_sectors: int) -> np.ndarray:
        rows = [(self._int_in(b, i, "offsetx", -COORD_LIMIT, COORD_LIMIT, 0),
                 self._int_in(b, i, "offsety", -COORD_LIMIT, COORD_LIMIT, 0),
                 self._name(b, i, "texturetop", "-"), self._name(b, i, "texturebottom", "-"),
                 self._name(b, i, "texturemiddle", "-"),
                 self._index(b, i, "sector", n_sectors, "sector"))
                for i, b in enumerate(blocks)]
        return _records(rows, [("xoff", "<i8"), ("yoff", "<i8"), ("upper", "S"),
                               ("lower", "S"), ("middle", "S"), ("sector", "<i8")])

    def _linedefs(self, blocks, n_vertices: int, n_sides: int) -> np.ndarray:
        if n_sides >= NO_SIDE:
            raise LevelError(f"{self.where}: TEXTMAP: {n_sides} sidedefs; at most "
                             f"{NO_SIDE - 1} are supported")
        out = np.zeros(len(blocks), LINEDEF)
        unmapped: dict[int, int] = {}
        for i, b in enumerate(blocks):
            v1 = self._index(b, i, "v1", n_vertices, "vertex")
            v2 = self._index(b, i, "v2", n_vertices, "vertex")
            if -1 in (v1, v2):
                raise self._fail(b, "v1" if v1 == -1 else "v2", i, "vertex -1 does not exist")
            front = self._index(b, i, "sidefront", n_sides, "sidedef")
            back = self._index(b, i, "sideback", n_sides, "sidedef", -1)
            special = self._get(b, i, "special", int, 0)
            args = [self._get(b, i, f"arg{k}", int, 0) for k in range(5)]
            line_id = self._get(b, i, "id", int, 0 if not self.hexen else -1)
            if self.hexen:
                trigger = {k for k in ("playercross", "playeruse", "monstercross",
                                       "monsteruse", "impact", "playerpush", "monsterpush",
                                       "missilecross", "repeatspecial")
                           if k in b.fields and self._get(b, i, k, bool)}
                special, tag = hexen_line_special(special, args, trigger, unmapped)
            else:
                tag = args[0] if args[0] else max(line_id, 0)
                if not 0 <= special <= MAX_NUMBER:
                    unmapped[special] = unmapped.get(special, 0) + 1
                    special = 0
            flags = self._flags(b, i, LINE_FLAGS)
            out[i] = (v1, v2, flags, special, self._number(tag),
                      NO_SIDE if front == -1 else front, NO_SIDE if back == -1 else back)
        if unmapped:
            shown = ", ".join(f"{s} (×{n})" if n > 1 else str(s)
                              for s, n in sorted(unmapped.items()))
            self.notes.append(f"{self.where}: TEXTMAP: linedef specials with no DOOM "
                              f"equivalent do nothing here: {shown}")
        return out

    def _things(self, blocks) -> np.ndarray:
        out = np.zeros(len(blocks), THING)
        inexact = 0
        for i, b in enumerate(blocks):
            skills = [bool(self._get(b, i, f"skill{k}", bool, False)) for k in range(1, 6)]
            inexact += skills[0] != skills[1] or skills[3] != skills[4]
            flags = ((skills[0] or skills[1]) * 1 | skills[2] * 2 | (skills[3] or skills[4]) * 4
                     | self._flags(b, i, {"ambush": 8})
                     | 16 * (not self._get(b, i, "single", bool, False))
                     | 32 * (not self._get(b, i, "dm", bool, False))
                     | 64 * (not self._get(b, i, "coop", bool, False)))
            self.thing_specials += bool(self._get(b, i, "special", int, 0))
            out[i] = (self._coordinate(b, i, "x"), self._coordinate(b, i, "y"),
                      self._get(b, i, "angle", int, 0),
                      self._int_in(b, i, "type", 0, MAX_NUMBER), flags)
        if inexact:
            self.notes.append(f"{self.where}: TEXTMAP: {inexact} thing{'s' * (inexact > 1)} "
                              f"in skill 1 but not 2 or in 4 but not 5 (or the other way "
                              f"round), which DOOM's flags cannot tell apart: taken as in both")
        return out

    # -- names and numbers ----------------------------------------------------------------

    def _name(self, block, number, key, default=None) -> bytes:
        name = self._get(block, number, key, str, default)
        if "/" in name or "\0" in name or not name.isprintable():
            self._bad_names.append(name)
            name = "-"
        return (name or "-").encode("latin-1", "replace")

    def _number(self, value: int) -> int:
        """A special or tag in DOOM's 16-bit range; anything else is 0 (UDMF's ``id`` -1)."""
        return value if 0 <= value <= MAX_NUMBER else 0

    def _note_names(self) -> None:
        if self._bad_names:
            self.notes.append(f"{self.where}: TEXTMAP: {len(self._bad_names)} texture "
                              f"name{'s' * (len(self._bad_names) > 1)} that no WAD can hold "
                              f"(such as {self._bad_names[0]!r}); no texture drawn")
        if self._sector_notes:
            shown = ", ".join(f"{s} (×{n})" if n > 1 else str(s)
                              for s, n in sorted(self._sector_notes.items()))
            self.notes.append(f"{self.where}: TEXTMAP: sector specials with no exact DOOM "
                              f"equivalent (the nearest DOOM special, or none): {shown}")


def _records(rows: list[tuple], fields: list[tuple[str, str]]) -> np.ndarray:
    """A record array of ``rows``; "S" fields are as wide as their longest name (at least 8)."""
    columns = list(zip(*rows)) if rows else [() for _ in fields]
    dtype = []
    for (name, kind), column in zip(fields, columns):
        if kind == "S":
            kind = f"S{max([8] + [len(c) for c in column])}"
        dtype.append((name, kind))
    out = np.zeros(len(rows), dtype)
    for (name, _), column in zip(fields, columns):
        out[name] = column
    return out
