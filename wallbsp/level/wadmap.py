"""DOOM-format maps (vanilla WAD files) imported as wallbsp levels (SPEC §2, §2b).

Public API:
- ``import_wad(wad_path, map_name) -> dict``: the level dict of one map (``E1M1``, ``MAP01``...);
- ``load_wad_level(wad_path, map_name, strict=False) -> Level``: the same, validated;
- ``list_maps(wad_path)``: the map names of a WAD; ``map_lump_indices(wad, map_name)``: the
  directory index of each lump of a map (THINGS ... BLOCKMAP);
- ``parse_wad_spec(text) -> (wad, map) | None``: reads the ``WAD:MAP`` form of a level argument.

Reader: our own (``archive``), a few hundred lines of ``struct`` and numpy structured dtypes,
rather than the ``omgifol`` package: numpy reads a whole lump of records in one call, so a
10,000-linedef map imports in milliseconds; every malformed byte is one line with its place
(``file: MAP: LUMP[i]: what``); and the project gains no dependency.

How a map becomes a version-2 level (DOOM's numbering is kept, SPEC §2b):
- ``resources`` names the WAD (an absolute path, so the saved level works from any folder).
- Walls are the linedefs, in order, less the ones dropped with a warning: a linedef with no
  sidedef, and a zero-length one (both ends at one point; real maps have them). Wall ``i`` is the
  ``i``-th kept linedef. The right sidedef's sector is ``front``, the left's ``back``; a linedef
  with only a left sidedef is turned round (v1 and v2 swapped) so that its one side is the front.
  Each side's textures and offsets are ``front_side``/``back_side``; the flags ML_DONTPEGTOP (8)
  and ML_DONTPEGBOTTOM (16) are ``upper_unpegged``/``lower_unpegged``, ML_BLOCKING (1) on a
  two-sided line is ``blocks``; ML_SECRET (32), ML_SOUNDBLOCK (64) and ML_DONTDRAW (128) are
  ``secret``, ``blocks_sound`` and ``hidden``; ``special`` and ``tag`` are the linedef's.
- Vertices are the ends of the kept walls, deduplicated by coordinate and numbered in order of
  first use (the node builder's extra vertices at the end of VERTEXES are dropped).
- Sectors are SECTORS, all of them, in order (sector ``i`` is DOOM's sector ``i``): floor,
  ceiling, light (clamped to 0..255 as DOOM's renderer does; a warning unless it was 256),
  flats, special and tag.
- Things are THINGS, all of them, in order. The start is the last player-1 start (type 1), as
  in DOOM, where earlier ones only spawn voodoo dolls; without one, the centre of the vertices'
  bounding box, looking north.
- Colours (the fallback wherever a texture is not drawn) are averages through palette 0 of
  PLAYPAL (``colours``). A wall's ``color`` is its middle texture; a two-sided wall without one
  takes its upper, else lower, texture, else grey. ``upper_color`` is the upper texture of the
  side with the higher ceiling (falling back to the other side), ``lower_color`` the lower
  texture of the side with the lower floor, as those are the sides DOOM draws them on. Sky
  ceilings (F_SKY1) are sky blue and the sector is marked ``sky`` (drawn full bright), and so is
  the upper part between two sky sectors, which DOOM leaves open to the sky. A texture or flat
  the WAD lacks is grey, with a warning.
- Errors (a truncated or malformed WAD, a missing map, a bad index) are one ``LevelError`` line:
  ``freedoom2.wad: directory: ...`` or ``freedoom2.wad: MAP01: LINEDEFS[12]: ...``.
UDMF maps (TEXTMAP ... ENDMAP) are read by ``udmfmap`` into the same records and go the same
way; Hexen-format binary maps (BEHAVIOR) are recognised and refused.
"""
from __future__ import annotations

import os
import re

import numpy as np

from wallbsp.level.model import Level, LevelError, Sector
from wallbsp.level.format import FORMAT, WALL_LINE_BITS
from wallbsp.level.io import level_from_dict
from wallbsp.level import udmfmap
from wallbsp.assets.wad import Wad, lump_name, open_wad
from wallbsp.assets.colours import (GREY, SKY_BLUE, SKY_FLAT, WadColours, name_colours,
    wad_colours)

MAX_NOTED = 20          # warnings of one kind per map, then "... and N more"
NO_SIDE = 0xFFFF        # vanilla's -1 sidedef, read unsigned so big maps may use 32768..65534
ML_BLOCKING, ML_DONTPEGTOP, ML_DONTPEGBOTTOM = 1, 8, 16

_THING = np.dtype([("x", "<i2"), ("y", "<i2"), ("angle", "<i2"), ("type", "<u2"),
                   ("flags", "<u2")])
_LINEDEF = np.dtype([("v1", "<u2"), ("v2", "<u2"), ("flags", "<u2"), ("special", "<u2"),
                     ("tag", "<u2"), ("right", "<u2"), ("left", "<u2")])
_SIDEDEF = np.dtype([("xoff", "<i2"), ("yoff", "<i2"), ("upper", "S8"), ("lower", "S8"),
                     ("middle", "S8"), ("sector", "<u2")])
_VERTEX = np.dtype([("x", "<i2"), ("y", "<i2")])
_SECTOR = np.dtype([("floor", "<i2"), ("ceiling", "<i2"), ("floor_flat", "S8"),
                    ("ceiling_flat", "S8"), ("light", "<i2"), ("special", "<u2"), ("tag", "<u2")])

_MAP_LUMPS = ("THINGS", "LINEDEFS", "SIDEDEFS", "VERTEXES", "SEGS", "SSECTORS", "NODES",
              "SECTORS", "REJECT", "BLOCKMAP", "BEHAVIOR", "SCRIPTS")
_NEEDED = {"THINGS": _THING, "LINEDEFS": _LINEDEF, "SIDEDEFS": _SIDEDEF,
           "VERTEXES": _VERTEX, "SECTORS": _SECTOR}
_LUMP_NAME = re.compile(r"[A-Za-z0-9_\-\[\]]{1,8}")


# ---------------------------------------------------------------------------------------------
# Map lumps

def _map_names(wad: Wad) -> list[str]:
    names = wad.names
    return [names[i] for i in range(len(names) - 1) if names[i + 1] in ("THINGS", "TEXTMAP")]


def list_maps(wad_path) -> list[str]:
    """The names of the maps in a WAD, in directory order."""
    with open_wad(wad_path) as wad:
        return _map_names(wad)


def _describe_maps(maps: list[str]) -> str:
    if not maps:
        return "the WAD has no maps"
    shown = maps if len(maps) <= 8 else maps[:4] + ["..."] + maps[-2:]
    return f"{len(maps)} map{'s' * (len(maps) > 1)}: {', '.join(shown)}"


def map_lump_indices(wad: Wad, map_name: str) -> dict[str, int]:
    """The directory index of each lump of map ``map_name`` (THINGS ... BLOCKMAP), in order
    (DOOM-format maps only: ``import_wad`` reads UDMF maps through ``udmfmap``)."""
    names = wad.names
    marker = wad.index.get(map_name)
    following = names[marker + 1] if marker is not None and marker + 1 < len(names) else None
    if following == "TEXTMAP":
        raise LevelError(f"{wad.label}: {map_name}: UDMF maps (TEXTMAP) are not supported")
    if following != "THINGS":
        raise LevelError(f"{wad.label}: {map_name}: no such map "
                         f"({_describe_maps(_map_names(wad))})")
    lumps: dict[str, int] = {}
    i = marker + 1
    while i < len(names) and names[i] in _MAP_LUMPS and names[i] not in lumps:
        lumps[names[i]] = i
        i += 1
    if "BEHAVIOR" in lumps:
        raise LevelError(f"{wad.label}: {map_name}: Hexen-format maps (BEHAVIOR) are not supported")
    for lump in _NEEDED:
        if lump not in lumps:
            raise LevelError(f"{wad.label}: {map_name}: {lump}: missing")
    return lumps


def _read_records(wad: Wad, where: str, lump: str, index: int) -> np.ndarray:
    dtype = _NEEDED[lump]
    raw = wad.read(index)
    if len(raw) % dtype.itemsize:
        raise LevelError(f"{where}: {lump}: {len(raw)} bytes is not a whole number of "
                         f"{dtype.itemsize}-byte records")
    return np.frombuffer(raw, dtype)


def _first_bad(mask: np.ndarray) -> int | None:
    bad = np.flatnonzero(mask)
    return int(bad[0]) if bad.size else None


def _check_indices(where: str, lines, sides, n_vertices: int, n_sectors: int) -> None:
    for end in ("v1", "v2"):
        i = _first_bad(lines[end] >= n_vertices)
        if i is not None:
            raise LevelError(f"{where}: LINEDEFS[{i}]: {end}: vertex {lines[end][i]} does not "
                             f"exist ({n_vertices} vertices)")
    for side in ("right", "left"):
        i = _first_bad((lines[side] != NO_SIDE) & (lines[side] >= len(sides)))
        if i is not None:
            raise LevelError(f"{where}: LINEDEFS[{i}]: {side} sidedef {lines[side][i]} does not "
                             f"exist ({len(sides)} sidedefs)")
    # Only sidedefs that a linedef uses matter; DOOM never looks at the others either.
    used = np.zeros(len(sides), bool)
    for side in ("right", "left"):
        used[lines[side][lines[side] != NO_SIDE]] = True
    i = _first_bad(used & (sides["sector"] >= n_sectors))
    if i is not None:
        raise LevelError(f"{where}: SIDEDEFS[{i}]: sector {sides['sector'][i]} does not exist "
                         f"({n_sectors} sectors)")


# ---------------------------------------------------------------------------------------------
# The level dict

def import_wad(wad_path, map_name: str, *, warnings: list[str] | None = None) -> dict:
    """The SPEC §2b (version 2) level dict of map ``map_name`` in the WAD at ``wad_path``.
    Wall ``i`` is the ``i``-th linedef kept. Warnings (dropped linedefs, missing textures) are
    appended to ``warnings`` when given; errors raise ``LevelError`` as one line."""
    notes = warnings if warnings is not None else []
    map_name = map_name.upper()
    with open_wad(wad_path) as wad:
        where = f"{wad.label}: {map_name}"
        if udmfmap.is_udmf(wad, map_name):
            things, lines, sides, verts, sectors = udmfmap.read_udmf_map(wad, map_name, notes)
        else:
            lumps = map_lump_indices(wad, map_name)
            things, lines, sides, verts, sectors = (
                _read_records(wad, where, lump, lumps[lump]) for lump in _NEEDED)
        _check_indices(where, lines, sides, len(verts), len(sectors))
        walls = _kept_walls(where, lines, verts, notes)
        vertices, v1, v2 = _renumber_vertices(verts, walls["v1"], walls["v2"])
        colours = wad_colours(wad)
        sector_dicts = _sector_dicts(where, colours, sectors, notes)
        wall_dicts = _wall_dicts(where, colours, walls, v1, v2, sides, sectors, notes)
        _add_wall_fields(wall_dicts, walls, lines, sides)
        notes[:0] = colours.notes
    return {
        "format": FORMAT, "version": 2,
        "name": f"{map_name} ({os.path.basename(str(wad_path))})",
        "resources": [os.path.abspath(wad_path)],
        "vertices": vertices.tolist(),
        "sectors": sector_dicts,
        "walls": wall_dicts,
        "start": _start(things, vertices),
        "things": _thing_dicts(things),
    }


def _kept_walls(where: str, lines: np.ndarray, verts: np.ndarray, notes: list[str]) -> dict:
    """Linedefs as (v1, v2, front side, back side) arrays, turned round where only the left side
    exists, without those that have no side or no length."""
    right, left = lines["right"].astype(np.int64), lines["left"].astype(np.int64)
    has_right, has_left = right != NO_SIDE, left != NO_SIDE
    turn = has_left & ~has_right
    v1 = np.where(turn, lines["v2"], lines["v1"]).astype(np.int64)
    v2 = np.where(turn, lines["v1"], lines["v2"]).astype(np.int64)
    no_side = ~has_right & ~has_left
    zero = (verts["x"][v1] == verts["x"][v2]) & (verts["y"][v1] == verts["y"][v2]) & ~no_side
    _note_capped(notes, where, [f"LINEDEFS[{i}]: no sidedefs; dropped"
                                for i in np.flatnonzero(no_side)[:MAX_NOTED + 1].tolist()],
                 int(no_side.sum()), "linedefs without sidedefs dropped")
    _note_capped(notes, where, [f"LINEDEFS[{i}]: zero length (both ends at "
                                f"({verts['x'][v1[i]]}, {verts['y'][v1[i]]})); dropped"
                                for i in np.flatnonzero(zero)[:MAX_NOTED + 1].tolist()],
                 int(zero.sum()), "zero-length linedefs dropped")
    keep = ~no_side & ~zero
    return {"linedef": np.flatnonzero(keep), "v1": v1[keep], "v2": v2[keep],
            "front": np.where(turn, left, right)[keep],
            "back": np.where(has_left & has_right, left, -1)[keep]}


def _note_capped(notes: list[str], where: str, lines: list[str], total: int, noun: str) -> None:
    # a messy map's warnings stay readable: the first few of a kind, then a count
    notes.extend(f"{where}: {line}" for line in lines[:MAX_NOTED])
    if total > MAX_NOTED:
        notes.append(f"{where}: ... and {total - MAX_NOTED} more {noun}")


def _renumber_vertices(verts: np.ndarray, v1: np.ndarray, v2: np.ndarray):
    """The distinct positions of the wall ends, in order of first use, and v1, v2 renumbered."""
    ends = np.stack([v1, v2], axis=1).ravel()
    x, y = verts["x"][ends].astype(np.int64), verts["y"][ends].astype(np.int64)
    key = (x << 32) | (y & 0xFFFFFFFF)       # UDMF maps may pass 16 bits (SPEC: 2**20)
    _, first, inverse = np.unique(key, return_index=True, return_inverse=True)
    order = np.argsort(first)
    rank = np.empty_like(order)
    rank[order] = np.arange(order.size)
    ids = rank[inverse.ravel()]
    picked = first[order]
    return np.stack([x[picked], y[picked]], axis=1), ids[0::2], ids[1::2]


def _sector_dicts(where: str, colours: WadColours, sectors: np.ndarray,
                  notes: list[str]) -> list[dict]:
    n = len(sectors)
    light = sectors["light"].astype(np.int64)
    # Editors write 256 for "full bright" and DOOM draws it as 255: no warning for that one.
    bad = np.flatnonzero((light < 0) | (light > 256))
    _note_capped(notes, where, [f"SECTORS[{i}]: light {light[i]} clamped to 0..255"
                                for i in bad[:MAX_NOTED].tolist()], bad.size, "lights clamped")
    light = light.clip(0, 255)
    found, missing = name_colours(
        np.concatenate([sectors["floor_flat"], sectors["ceiling_flat"]]), colours.flat,
        lambda at, name: f"{where}: SECTORS[{at % n}]: {('floor', 'ceiling')[at // n]} "
                         f"flat {name} not found; grey used")
    notes.extend(missing)
    if colours.palette is None:
        floor, ceiling = np.full(n, Sector.floor_color), np.full(n, Sector.ceiling_color)
    else:
        floor, ceiling = found[:n], found[n:]
    floor_names = _names(sectors["floor_flat"])
    ceiling_names = _names(sectors["ceiling_flat"])
    return [{"floor": f, "ceiling": c, "light": li, "floor_color": fc, "ceiling_color": cc,
             "floor_texture": fn, "ceiling_texture": cn, "special": sp, "tag": tg,
             **({"sky": True} if cn == SKY_FLAT else {})}
            for f, c, li, fc, cc, fn, cn, sp, tg in zip(
                sectors["floor"].tolist(), sectors["ceiling"].tolist(), light.tolist(),
                floor.tolist(), ceiling.tolist(), floor_names, ceiling_names,
                sectors["special"].tolist(), sectors["tag"].tolist())]


def _names(raw: np.ndarray) -> list[str | None]:
    """Texture names as the level writes them: upper case, None for "-" (no texture)."""
    unique, inverse = np.unique(raw, return_inverse=True)     # a map uses few distinct names
    names = [lump_name(n) for n in unique.tolist()]
    names = [None if n in ("-", "") else n for n in names]
    return [names[i] for i in inverse.ravel().tolist()]


def _either(first: np.ndarray, second) -> np.ndarray:
    return np.where(first != "", first, second)


def _side_colours(where: str, colours: WadColours, sides: np.ndarray,
                  notes: list[str]) -> np.ndarray:
    """A 3 × sidedefs str array: the upper, lower and middle texture colours ("" for "-")."""
    n = len(sides)
    parts = ("upper", "lower", "middle")
    found, missing = name_colours(
        np.concatenate([sides[p] for p in parts]), colours.wall,
        lambda at, name: f"{where}: SIDEDEFS[{at % n}]: {parts[at // n]} texture {name} "
                         f"not found; grey used")
    notes.extend(missing)
    if colours.palette is None:
        return np.full((3, n), "", dtype="<U7")
    return found.reshape(3, n)


def _wall_dicts(where: str, colours: WadColours, walls: dict, v1: np.ndarray,
                v2: np.ndarray, sides: np.ndarray, sectors: np.ndarray,
                notes: list[str]) -> list[dict]:
    upper, lower, middle = _side_colours(where, colours, sides, notes)
    front, two = walls["front"], walls["back"] >= 0
    back = np.where(two, walls["back"], front)        # one-sided: the front stands in, unused
    fsec = sides["sector"][front].astype(np.int64)
    bsec = sides["sector"][back].astype(np.int64)
    # DOOM draws an upper part on the side with the higher ceiling, a lower part on the side
    # with the lower floor; the other side's texture is the fallback.
    high = sectors["ceiling"][fsec] >= sectors["ceiling"][bsec]
    up = _either(np.where(high, upper[front], upper[back]),
                 np.where(high, upper[back], upper[front]))
    low_side = sectors["floor"][fsec] <= sectors["floor"][bsec]
    low = _either(np.where(low_side, lower[front], lower[back]),
                  np.where(low_side, lower[back], lower[front]))
    colour = np.where(two, _either(_either(_either(middle[front], middle[back]), up),
                                   _either(low, GREY)),
                      _either(middle[front], GREY))
    sky = np.array([lump_name(n) == SKY_FLAT for n in sectors["ceiling_flat"].tolist()], bool)
    up = np.where(sky[fsec] & sky[bsec], SKY_BLUE, up)   # DOOM leaves it open to the sky
    out = []
    for a, b, f, k, c, u, lo, t in zip(v1.tolist(), v2.tolist(), fsec.tolist(), bsec.tolist(),
                                       colour.tolist(), up.tolist(), low.tolist(), two.tolist()):
        wall = {"v1": a, "v2": b, "front": f, "back": k if t else None, "color": c}
        if t and u:
            wall["upper_color"] = u
        if t and lo:
            wall["lower_color"] = lo
        out.append(wall)
    return out


def _add_wall_fields(wall_dicts: list[dict], walls: dict, lines: np.ndarray,
                    sides: np.ndarray) -> None:
    """The version-2 fields of each wall: both sides' textures and offsets, pegging, blocking,
    special and tag of its linedef."""
    side_dicts = _side_dicts(sides)
    kept = lines[walls["linedef"]]
    flags = kept["flags"].astype(np.int64)
    for wall, f, k, fl, special, tag in zip(wall_dicts, walls["front"].tolist(),
                                            walls["back"].tolist(), flags.tolist(),
                                            kept["special"].tolist(), kept["tag"].tolist()):
        wall["front_side"] = side_dicts[f]
        if k >= 0:
            wall["back_side"] = side_dicts[k]
        wall.update(upper_unpegged=bool(fl & ML_DONTPEGTOP),
                    lower_unpegged=bool(fl & ML_DONTPEGBOTTOM),
                    blocks=bool(fl & ML_BLOCKING) and k >= 0, special=special, tag=tag)
        wall.update({key: True for key, bit in WALL_LINE_BITS.items() if fl & bit})


def _side_dicts(sides: np.ndarray) -> list[dict]:
    parts = [_names(sides[p]) for p in ("upper", "middle", "lower")]
    return [{"upper": u, "middle": m, "lower": lo, "x_offset": x, "y_offset": y}
            for u, m, lo, x, y in zip(*parts, sides["xoff"].tolist(), sides["yoff"].tolist())]


def _thing_dicts(things: np.ndarray) -> list[dict]:
    return [{"x": x, "y": y, "angle": a, "type": t, "flags": f}
            for x, y, a, t, f in zip(things["x"].tolist(), things["y"].tolist(),
                                     things["angle"].tolist(), things["type"].tolist(),
                                     things["flags"].tolist())]


def _start(things: np.ndarray, vertices: np.ndarray) -> dict:
    players = np.flatnonzero(things["type"] == 1)
    if players.size:    # the last player-1 start is the player; earlier ones are voodoo dolls
        t = things[players[-1]]
        return {"x": int(t["x"]), "y": int(t["y"]), "angle": int(t["angle"]) % 360}
    if vertices.size == 0:
        return {"x": 0, "y": 0, "angle": 90}
    (x0, y0), (x1, y1) = vertices.min(axis=0).tolist(), vertices.max(axis=0).tolist()
    return {"x": (x0 + x1) // 2, "y": (y0 + y1) // 2, "angle": 90}


# ---------------------------------------------------------------------------------------------
# Levels and the WAD:MAP form

def load_wad_level(wad_path, map_name: str, strict: bool = False) -> Level:
    """Map ``map_name`` of a WAD as a validated ``Level``; its warnings are the importer's
    followed by the level's own. ``strict`` turns any warning into a ``LevelError``."""
    notes: list[str] = []
    data = import_wad(wad_path, map_name, warnings=notes)
    if strict and notes:
        raise LevelError(notes[0])
    level = level_from_dict(data, f"{wad_path}:{map_name.upper()}", strict=strict)
    level.warnings[:0] = notes
    return level


def parse_wad_spec(text: str) -> tuple[str, str] | None:
    """``("freedoom2.wad", "MAP01")`` for ``"freedoom2.wad:MAP01"``; None when ``text`` is not
    of that form, or names an existing file (a level path that happens to hold a colon)."""
    text = str(text)
    if ":" not in text or os.path.exists(text):
        return None
    wad, map_name = text.rsplit(":", 1)
    if not wad or not _LUMP_NAME.fullmatch(map_name):
        return None
    return wad, map_name.upper()
