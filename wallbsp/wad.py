"""DOOM-format maps (vanilla WAD files) imported as wallbsp levels (SPEC §2).

Public API:
- ``import_wad(wad_path, map_name) -> dict``: the level dict of one map (``E1M1``, ``MAP01``...);
- ``load_wad_level(wad_path, map_name, strict=False) -> Level``: the same, validated;
- ``parse_wad_spec(text) -> (wad, map) | None``: reads the ``WAD:MAP`` form of a level argument.

Reader: our own, a few hundred lines of ``struct`` and numpy structured dtypes, rather than the
``omgifol`` package. We need a small, read-only part of the format (the directory, five map lumps,
PLAYPAL, flats, PNAMES/TEXTURE1/TEXTURE2 and patches). Numpy reads a whole lump of records in one
call, so a 10,000-linedef map imports in milliseconds; every malformed byte can be reported as one
line with its place (``file: MAP: LUMP[i]: what``); and the project gains no dependency. omgifol is
pure Python (one Python object per record, slow on large maps), raises its own exceptions from deep
inside, and would be one more package to install for a few hundred lines we can own and test.

How a map becomes a level:
- Walls are the linedefs, in order, less the ones dropped with a warning: a linedef with no
  sidedef, and a zero-length one (both ends at one point; real maps have them). Wall ``i`` is the
  ``i``-th kept linedef. The right sidedef's sector is ``front``, the left's ``back``; a linedef
  with only a left sidedef is turned round (v1 and v2 swapped) so that its one side is the front.
- Vertices are the ends of the kept walls, deduplicated by coordinate and numbered in order of
  first use (the node builder's extra vertices at the end of VERTEXES are dropped).
- Sectors are SECTORS, all of them, in order (sector ``i`` is DOOM's sector ``i``): floor,
  ceiling, light (clamped to 0..255 as DOOM's renderer does; a warning unless it was 256).
- The start is the last player-1 start (THINGS type 1), as in DOOM, where earlier ones only spawn
  voodoo dolls; without one, the centre of the vertices' bounding box, looking north.
- Colours are averages through palette 0 of PLAYPAL: a flat's over its 64×64 pixels, a wall
  texture's over the opaque pixels of its TEXTURE1/TEXTURE2 composite of PNAMES patches. A wall's
  ``color`` is its middle texture; a two-sided wall without one takes its upper, else lower,
  texture, else grey. ``upper_color`` is the upper texture of the side with the higher ceiling
  (falling back to the other side), ``lower_color`` the lower texture of the side with the lower
  floor, as those are the sides DOOM draws them on. Sky ceilings (F_SKY1) are sky blue and the
  sector is marked ``sky`` (drawn full bright), and so is the upper part between two sky
  sectors, which DOOM leaves open to the sky. Missing textures are grey, with a warning. Colours are cached per WAD (path, size and mtime).
- Errors (a truncated or malformed WAD, a missing map, a bad index) are one ``LevelError`` line:
  ``freedoom2.wad: directory: ...`` or ``freedoom2.wad: MAP01: LINEDEFS[12]: ...``.
Hexen-format and UDMF maps are recognised and refused.
"""
from __future__ import annotations

import os
import re
import struct
from collections import OrderedDict
from contextlib import contextmanager
from dataclasses import dataclass, field
from typing import BinaryIO, Iterator

import numpy as np

from .level import Level, LevelError, Sector, level_from_dict

GREY = "#808080"        # a wall or flat without a texture, or one the WAD lacks
SKY_BLUE = "#87ceeb"    # F_SKY1 ceilings
SKY_FLAT = "F_SKY1"
MAX_NOTED = 20          # warnings of one kind per map, then "... and N more"
NO_SIDE = 0xFFFF        # vanilla's -1 sidedef, read unsigned so big maps may use 32768..65534

_HEADER = struct.Struct("<4sii")
_DIRENTRY = np.dtype([("pos", "<i4"), ("size", "<i4"), ("name", "S8")])
_THING = np.dtype([("x", "<i2"), ("y", "<i2"), ("angle", "<i2"), ("type", "<i2"), ("flags", "<i2")])
_LINEDEF = np.dtype([("v1", "<u2"), ("v2", "<u2"), ("flags", "<i2"), ("special", "<i2"),
                     ("tag", "<i2"), ("right", "<u2"), ("left", "<u2")])
_SIDEDEF = np.dtype([("xoff", "<i2"), ("yoff", "<i2"), ("upper", "S8"), ("lower", "S8"),
                     ("middle", "S8"), ("sector", "<u2")])
_VERTEX = np.dtype([("x", "<i2"), ("y", "<i2")])
_SECTOR = np.dtype([("floor", "<i2"), ("ceiling", "<i2"), ("floor_flat", "S8"),
                    ("ceiling_flat", "S8"), ("light", "<i2"), ("special", "<i2"), ("tag", "<i2")])
_MAPPATCH = np.dtype([("x", "<i2"), ("y", "<i2"), ("patch", "<i2"), ("stepdir", "<i2"),
                      ("colormap", "<i2")])
_MAPTEXTURE = struct.Struct("<8sihhih")   # name, masked, width, height, columndirectory, patchcount

_MAP_LUMPS = ("THINGS", "LINEDEFS", "SIDEDEFS", "VERTEXES", "SEGS", "SSECTORS", "NODES",
              "SECTORS", "REJECT", "BLOCKMAP", "BEHAVIOR", "SCRIPTS")
_NEEDED = {"THINGS": _THING, "LINEDEFS": _LINEDEF, "SIDEDEFS": _SIDEDEF,
           "VERTEXES": _VERTEX, "SECTORS": _SECTOR}
_LUMP_NAME = re.compile(r"[A-Za-z0-9_\-\[\]]{1,8}")


# ---------------------------------------------------------------------------------------------
# The WAD file: header, directory, lumps

@dataclass
class _Textures:
    """What a WAD says about colours, read once per WAD and filled in lazily per name."""
    palette: np.ndarray | None                     # 256 × 3 float
    flats: dict[str, int]                          # flat name -> lump index
    textures: dict[str, tuple[int, int, np.ndarray]]   # name -> (width, height, patches)
    notes: list[str]                               # problems found in the texture lumps
    colours: dict[str, str | None] = field(default_factory=dict)   # "F:NAME"/"T:NAME" -> colour
    patches: dict[int, tuple] = field(default_factory=dict)        # lump -> (cols, rows, values)


@dataclass
class _Tables:
    """The parsed directory of one WAD file, cached by path, inode, mtime, ctime and size."""
    names: list[str]
    pos: np.ndarray
    size: np.ndarray
    file_size: int
    index: dict[str, int]         # name -> the last lump of that name, as W_GetNumForName finds
    textures: _Textures | None = None


@dataclass
class _Wad:
    """An open WAD: its label for messages, the file, and its cached tables."""
    label: str
    file: BinaryIO
    tables: _Tables

    def read(self, i: int) -> bytes:
        t = self.tables
        pos, size = int(t.pos[i]), int(t.size[i])
        if pos < 0 or size < 0 or pos + size > t.file_size:
            raise LevelError(f"{self.label}: directory[{i}]: lump {t.names[i]} at offset {pos} "
                             f"({size} bytes) lies outside the file ({t.file_size} bytes)")
        self.file.seek(pos)
        raw = self.file.read(size)
        if len(raw) != size:   # the file shrank under us
            raise LevelError(f"{self.label}: directory[{i}]: lump {t.names[i]} is truncated")
        return raw


_CACHE: OrderedDict[tuple, _Tables] = OrderedDict()
_CACHE_SIZE = 8


@contextmanager
def _open_wad(wad_path) -> Iterator[_Wad]:
    label = str(wad_path)
    try:
        f = open(wad_path, "rb")
    except OSError as e:
        raise LevelError(f"{label}: cannot read: {e.strerror or e}") from None
    with f:
        st = os.fstat(f.fileno())
        key = (os.path.realpath(wad_path), st.st_ino, st.st_mtime_ns, st.st_ctime_ns,
               st.st_size)
        tables = _CACHE.get(key)
        if tables is None:
            tables = _read_directory(f, label, st.st_size)
            _CACHE[key] = tables
            while len(_CACHE) > _CACHE_SIZE:
                _CACHE.popitem(last=False)
        yield _Wad(label, f, tables)


def _read_directory(f: BinaryIO, label: str, file_size: int) -> _Tables:
    head = f.read(_HEADER.size)
    if len(head) < _HEADER.size:
        raise LevelError(f"{label}: header: truncated ({file_size} bytes, a WAD header is 12)")
    magic, count, offset = _HEADER.unpack(head)
    if magic not in (b"IWAD", b"PWAD"):
        raise LevelError(f"{label}: header: bad magic {magic!r} (not IWAD or PWAD)")
    end = offset + count * _DIRENTRY.itemsize
    if count < 0 or offset < _HEADER.size or end > file_size:
        raise LevelError(f"{label}: directory: {count} entries at offset {offset} run past the "
                         f"end of the file ({file_size} bytes); truncated or not a WAD")
    f.seek(offset)
    entries = np.frombuffer(f.read(end - offset), _DIRENTRY)
    names = [_name(n) for n in entries["name"].tolist()]
    return _Tables(names, entries["pos"].copy(), entries["size"].copy(), file_size,
                   {n: i for i, n in enumerate(names)})


def _name(raw: bytes) -> str:
    # Names are NUL-padded, but some tools leave garbage after the NUL; DOOM compares upper case.
    return raw.split(b"\0", 1)[0].decode("latin-1").upper()


# ---------------------------------------------------------------------------------------------
# Map lumps

def _map_names(tables: _Tables) -> list[str]:
    names = tables.names
    return [names[i] for i in range(len(names) - 1) if names[i + 1] in ("THINGS", "TEXTMAP")]


def list_maps(wad_path) -> list[str]:
    """The names of the maps in a WAD, in directory order."""
    with _open_wad(wad_path) as wad:
        return _map_names(wad.tables)


def _describe_maps(maps: list[str]) -> str:
    if not maps:
        return "the WAD has no maps"
    shown = maps if len(maps) <= 8 else maps[:4] + ["..."] + maps[-2:]
    return f"{len(maps)} map{'s' * (len(maps) > 1)}: {', '.join(shown)}"


def _find_map_lumps(wad: _Wad, map_name: str) -> dict[str, int]:
    """The lump index of each map lump after the map's marker."""
    names = wad.tables.names
    marker = wad.tables.index.get(map_name)
    following = names[marker + 1] if marker is not None and marker + 1 < len(names) else None
    if following == "TEXTMAP":
        raise LevelError(f"{wad.label}: {map_name}: UDMF maps (TEXTMAP) are not supported")
    if following != "THINGS":
        raise LevelError(f"{wad.label}: {map_name}: no such map "
                         f"({_describe_maps(_map_names(wad.tables))})")
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


def _read_records(wad: _Wad, where: str, lump: str, index: int) -> np.ndarray:
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
# Colours: PLAYPAL, flats, patches, composite textures

def _textures(wad: _Wad) -> _Textures:
    if wad.tables.textures is None:
        wad.tables.textures = _read_texture_tables(wad)
    return wad.tables.textures


def _read_texture_tables(wad: _Wad) -> _Textures:
    t = wad.tables
    notes: list[str] = []
    palette = None
    if "PLAYPAL" in t.index:
        raw = wad.read(t.index["PLAYPAL"])
        if len(raw) >= 768:
            palette = np.frombuffer(raw, np.uint8, 768).reshape(256, 3).astype(np.float64)
    if palette is None:
        notes.append(f"{wad.label}: PLAYPAL: missing or short; all colours are grey")
    patch_lumps = _read_pnames(wad, notes)
    textures: dict[str, tuple[int, int, np.ndarray]] = {}
    for lump in ("TEXTURE1", "TEXTURE2"):
        if lump in t.index:
            _read_texture_lump(wad.read(t.index[lump]), patch_lumps, textures,
                               f"{wad.label}: {lump}", notes)
    return _Textures(palette, _flat_lumps(t), textures, notes)


def _flat_lumps(t: _Tables) -> dict[str, int]:
    flats: dict[str, int] = {}
    inside = False
    for i, name in enumerate(t.names):
        if name in ("F_START", "FF_START"):
            inside = True
        elif name in ("F_END", "FF_END"):
            inside = False
        elif inside and t.size[i] > 0:     # sub-markers (F1_START...) are empty
            flats[name] = i                # a later flat of the same name replaces an earlier
    return flats


def _read_pnames(wad: _Wad, notes: list[str]) -> list[int]:
    """PNAMES as lump indices, -1 for a patch the WAD lacks."""
    i = wad.tables.index.get("PNAMES")
    if i is None:
        return []
    raw = wad.read(i)
    count = struct.unpack_from("<i", raw)[0] if len(raw) >= 4 else 0
    if not 0 <= count <= (len(raw) - 4) // 8:
        notes.append(f"{wad.label}: PNAMES: {count} names do not fit in {len(raw)} bytes")
        count = max(0, (len(raw) - 4) // 8)
    names = [_name(raw[4 + 8 * k: 12 + 8 * k]) for k in range(count)]
    return [wad.tables.index.get(n, -1) for n in names]


def _read_texture_lump(raw: bytes, patch_lumps: list[int], out: dict, where: str,
                       notes: list[str]) -> None:
    """Adds the texture definitions of TEXTURE1 or TEXTURE2 to ``out``; the first of a name wins,
    as in R_TextureNumForName. Colours are cosmetic, so damage here is a note, not an error."""
    try:
        count = struct.unpack_from("<i", raw)[0]
        if count < 0:     # numpy would read "all the rest" for -1; struct counts from the end
            raise ValueError(f"{count} textures")
        offsets = np.frombuffer(raw, "<i4", count, 4).tolist()
        for k, off in enumerate(offsets):
            if off < 0:
                raise ValueError(f"texture {k} at offset {off}")
            name, _, width, height, _, npatch = _MAPTEXTURE.unpack_from(raw, off)
            if npatch < 0:
                raise ValueError(f"texture {k} has {npatch} patches")
            patches = np.frombuffer(raw, _MAPPATCH, npatch, off + _MAPTEXTURE.size)
            lumps = np.array([patch_lumps[p] if 0 <= p < len(patch_lumps) else -1
                              for p in patches["patch"].tolist()], dtype=np.int64)
            out.setdefault(_name(name), (width, height,
                                         np.stack([patches["x"], patches["y"], lumps], axis=1)))
    except (struct.error, ValueError) as e:
        notes.append(f"{where}: malformed ({e}); textures after that are grey")


def _patch_pixels(raw: bytes) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(columns, rows, palette indices) of a patch's opaque pixels. The posts of all columns are
    walked together, one post per column per step, so the Python loop runs only as many times
    as the busiest column has posts. Damaged posts are cut at the end of the lump."""
    empty = np.zeros(0, np.int64)
    if len(raw) < 8:
        return empty, empty, empty
    width = struct.unpack_from("<H", raw)[0]
    width = min(width, (len(raw) - 8) // 4)
    buf = np.frombuffer(raw, np.uint8)
    n = len(buf)
    cols = np.arange(width, dtype=np.int64)
    pos = np.frombuffer(raw, "<u4", width, 8).astype(np.int64)
    top_prev = np.full(width, -1, np.int64)
    spans = []
    alive = pos + 3 < n
    while alive.any():           # each step moves every column's pos forward by >= 4 bytes
        cols, pos, top_prev = cols[alive], pos[alive], top_prev[alive]
        delta = buf[pos].astype(np.int64)
        live = delta != 0xFF
        cols, pos, top_prev, delta = cols[live], pos[live], top_prev[live], delta[live]
        length = np.minimum(buf[pos + 1].astype(np.int64), n - (pos + 3))
        # DeePsea tall patches: a top delta not below the previous one is relative to it.
        top = np.where(delta <= top_prev, top_prev + delta, delta)
        spans.append((cols, top, pos + 3, length))
        top_prev, pos = top, pos + length + 4
        alive = pos + 3 < n
    if not spans:
        return empty, empty, empty
    cols, tops, starts, lengths = (np.concatenate(a) for a in zip(*spans))
    within = np.arange(lengths.sum()) - np.repeat(np.cumsum(lengths) - lengths, lengths)
    return (np.repeat(cols, lengths), np.repeat(tops, lengths) + within,
            buf[np.repeat(starts, lengths) + within].astype(np.int64))


def _average(palette: np.ndarray, indices: np.ndarray) -> str | None:
    if indices.size == 0:
        return None
    counts = np.bincount(indices.ravel(), minlength=256)[:256]
    r, g, b = (counts @ palette / indices.size).round().astype(int).tolist()
    return f"#{r:02x}{g:02x}{b:02x}"


def _flat_colour(wad: _Wad, tex: _Textures, name: str) -> str | None:
    key = "F:" + name
    if key not in tex.colours:
        lump = tex.flats.get(name)
        tex.colours[key] = None if lump is None else _average(
            tex.palette, np.frombuffer(wad.read(lump), np.uint8))
    return tex.colours[key]


def _texture_colour(wad: _Wad, tex: _Textures, name: str) -> str | None:
    key = "T:" + name
    if key not in tex.colours:
        tdef = tex.textures.get(name)
        tex.colours[key] = None if tdef is None else _composite_colour(wad, tex, *tdef)
    return tex.colours[key]


def _composite_colour(wad: _Wad, tex: _Textures, width: int, height: int,
                      patches: np.ndarray) -> str:
    """The average over the opaque pixels of the composite, later patches painted over earlier
    ones and everything clipped to the texture, as R_GenerateComposite does. Pixels are kept as
    (position, value) lists rather than a canvas, so a damaged 32767 × 32767 header costs
    nothing."""
    keys, values = [], []
    for ox, oy, lump in patches.tolist():
        if lump < 0:
            continue
        if lump not in tex.patches:
            tex.patches[lump] = _patch_pixels(wad.read(lump))
        cols, rows, pixels = tex.patches[lump]
        x, y = cols + ox, rows + oy
        inside = (x >= 0) & (x < width) & (y >= 0) & (y < height)
        keys.append((y * width + x)[inside])
        values.append(pixels[inside])
    if not keys:
        return GREY
    keys, values = np.concatenate(keys)[::-1], np.concatenate(values)[::-1]
    _, last = np.unique(keys, return_index=True)     # first in reverse = painted last
    return _average(tex.palette, values[last]) or GREY


def _name_colours(names: np.ndarray, colour_of, missing) -> tuple[np.ndarray, list[str]]:
    """Colours (a str array, "" for no texture "-") of an array of raw 8-byte names, each
    distinct name looked up once; and ``missing(at, name)`` for the first use ``at`` of each name
    the WAD lacks (those are grey)."""
    unique, first, inverse = np.unique(names, return_index=True, return_inverse=True)
    colours, notes = [], []
    for raw, at in zip(unique.tolist(), first.tolist()):
        name = _name(raw)
        colour = "" if name in ("-", "") else colour_of(name)
        if colour is None:
            notes.append(missing(at, name))
            colour = GREY
        colours.append(colour)
    return np.array(colours, dtype="<U7")[inverse.ravel()], notes


# ---------------------------------------------------------------------------------------------
# The level dict

def import_wad(wad_path, map_name: str, *, warnings: list[str] | None = None) -> dict:
    """The SPEC §2 level dict of map ``map_name`` in the WAD at ``wad_path``. Wall ``i`` is the
    ``i``-th linedef kept. Warnings (dropped linedefs, missing textures) are appended to
    ``warnings`` when given; errors raise ``LevelError`` as one line."""
    notes = warnings if warnings is not None else []
    map_name = map_name.upper()
    with _open_wad(wad_path) as wad:
        where = f"{wad.label}: {map_name}"
        lumps = _find_map_lumps(wad, map_name)
        things, lines, sides, verts, sectors = (
            _read_records(wad, where, lump, lumps[lump]) for lump in _NEEDED)
        _check_indices(where, lines, sides, len(verts), len(sectors))
        walls = _kept_walls(where, lines, verts, notes)
        vertices, v1, v2 = _renumber_vertices(verts, walls["v1"], walls["v2"])
        tex = _textures(wad)
        notes.extend(tex.notes)
        sector_dicts = _sector_dicts(wad, where, tex, sectors, notes)
        wall_dicts = _wall_dicts(wad, where, tex, walls, v1, v2, sides, sectors, notes)
    return {
        "format": "wallbsp-level", "version": 1,
        "name": f"{map_name} ({os.path.basename(str(wad_path))})",
        "vertices": vertices.tolist(),
        "sectors": sector_dicts,
        "walls": wall_dicts,
        "start": _start(things, vertices),
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
    return {"v1": v1[keep], "v2": v2[keep],
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
    key = (x << 16) | (y & 0xFFFF)
    _, first, inverse = np.unique(key, return_index=True, return_inverse=True)
    order = np.argsort(first)
    rank = np.empty_like(order)
    rank[order] = np.arange(order.size)
    ids = rank[inverse.ravel()]
    picked = first[order]
    return np.stack([x[picked], y[picked]], axis=1), ids[0::2], ids[1::2]


def _sector_dicts(wad: _Wad, where: str, tex: _Textures, sectors: np.ndarray,
                  notes: list[str]) -> list[dict]:
    n = len(sectors)
    light = sectors["light"].astype(np.int64)
    # Editors write 256 for "full bright" and DOOM draws it as 255: no warning for that one.
    bad = np.flatnonzero((light < 0) | (light > 256))
    _note_capped(notes, where, [f"SECTORS[{i}]: light {light[i]} clamped to 0..255"
                                for i in bad[:MAX_NOTED].tolist()], bad.size, "lights clamped")
    light = light.clip(0, 255)
    if tex.palette is None:
        floor, ceiling = np.full(n, Sector.floor_color), np.full(n, Sector.ceiling_color)
    else:
        colours, missing = _name_colours(
            np.concatenate([sectors["floor_flat"], sectors["ceiling_flat"]]),
            lambda name: SKY_BLUE if name == SKY_FLAT else _flat_colour(wad, tex, name),
            lambda at, name: f"{where}: SECTORS[{at % n}]: {('floor', 'ceiling')[at // n]} "
                             f"flat {name} not found; grey used")
        notes.extend(missing)
        floor, ceiling = colours[:n], colours[n:]
    sky = [_name(n) == SKY_FLAT for n in sectors["ceiling_flat"].tolist()]
    return [dict({"floor": f, "ceiling": c, "light": li, "floor_color": fc, "ceiling_color": cc},
                 **({"sky": True} if open_sky else {}))
            for f, c, li, fc, cc, open_sky in zip(sectors["floor"].tolist(),
                                                  sectors["ceiling"].tolist(), light.tolist(),
                                                  floor.tolist(), ceiling.tolist(), sky)]


def _either(first: np.ndarray, second) -> np.ndarray:
    return np.where(first != "", first, second)


def _side_colours(wad: _Wad, where: str, tex: _Textures, sides: np.ndarray,
                  notes: list[str]) -> np.ndarray:
    """A 3 × sidedefs str array: the upper, lower and middle texture colours ("" for "-")."""
    n = len(sides)
    if tex.palette is None:
        return np.full((3, n), "", dtype="<U7")
    parts = ("upper", "lower", "middle")
    colours, missing = _name_colours(
        np.concatenate([sides[p] for p in parts]),
        lambda name: _texture_colour(wad, tex, name),
        lambda at, name: f"{where}: SIDEDEFS[{at % n}]: {parts[at // n]} texture {name} "
                         f"not found; grey used")
    notes.extend(missing)
    return colours.reshape(3, n)


def _wall_dicts(wad: _Wad, where: str, tex: _Textures, walls: dict, v1: np.ndarray,
                v2: np.ndarray, sides: np.ndarray, sectors: np.ndarray,
                notes: list[str]) -> list[dict]:
    upper, lower, middle = _side_colours(wad, where, tex, sides, notes)
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
    sky = np.array([_name(n) == SKY_FLAT for n in sectors["ceiling_flat"].tolist()], bool)
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
