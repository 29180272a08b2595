"""One of our levels as a playable DOOM PWAD: ``wallbsp export LEVEL -o OUT.wad``.

Public API: ``export_level(level, path, map_name="MAP01", fmt="doom", iwad=None) -> notes``
and ``level_map_lumps(level, map_name) -> {lump: bytes}`` (the DOOM-format lumps before the
node builder runs), ``udmf_text(level) -> str``.

How a level becomes a map: vertices are VERTEXES (integers, within -32768..32767, else a
``LevelError``); each wall a linedef (v1, v2; a one-sided wall ``ML_BLOCKING``, a two-sided
one ``ML_TWOSIDED`` and ``ML_BLOCKING`` if it ``blocks``; the unpegged, secret, sound-blocking
and hidden flags; special and
tag) with a sidedef per side (offsets, texture names, ``-`` for none; a one-sided wall with no
middle texture gets ``DEFAULT_WALL``); sectors keep heights (rounded), light, flats (a sky
sector's ceiling is ``F_SKY1``, a missing flat ``DEFAULT_FLAT``), special and tag; things
keep x, y, angle, type and flags (a thing of a type the level defines itself, which no
DOOM port knows, is left out with a note), and the start becomes player 1's start unless a thing of
type 1 is there already.  Then the node builder makes the rest (``wadnodes.rebuild_map``; for
UDMF, TEXTMAP and its ZNODES, ``wadnodes.rebuild_udmf_map``).

Our PNG resources are not converted: a texture or flat the level names must be in the WAD
the map is played with.  With ``iwad`` given, names it lacks are replaced by its defaults
and listed once; without, the note says so once.
"""
from __future__ import annotations

import numpy as np

from wallbsp.files import LevelError
from wallbsp.assets.wad import open_wad
from wallbsp.assets.wadwrite import Lump, WadImage
from wallbsp.level.model import Level

from .mapdata import LINEDEF, SECTOR, SIDEDEF, THING, VERTEX
from .wadnodes import NodeOptions, rebuild_map, rebuild_udmf_map

DEFAULT_WALL, DEFAULT_FLAT, SKY_FLAT = "STARTAN3", "FLOOR4_8", "F_SKY1"
ML_BLOCKING, ML_TWOSIDED, ML_DONTPEGTOP, ML_DONTPEGBOTTOM = 1, 4, 8, 16


def _name8(name) -> bytes:
    return (name or "-").upper().encode("latin-1")[:8]


def _side(side, one_sided: bool):
    middle = getattr(side, "middle", None) or (DEFAULT_WALL if one_sided else None)
    return (int(getattr(side, "x_offset", 0)), int(getattr(side, "y_offset", 0)),
            _name8(getattr(side, "upper", None)), _name8(getattr(side, "lower", None)),
            _name8(middle))


def level_map_lumps(level: Level, map_name: str = "MAP01") -> dict:
    where = f"{level.source}: {map_name}"
    verts = np.array(level.vertices, np.int64).reshape(-1, 2)
    if verts.size and (verts.min() < -32768 or verts.max() > 32767):
        raise LevelError(f"{where}: vertices: a DOOM map's coordinates are 16-bit "
                         f"(-32768..32767); this level reaches {int(np.abs(verts).max())}")
    vertexes = np.zeros(len(verts), VERTEX)
    vertexes["x"], vertexes["y"] = verts[:, 0], verts[:, 1]
    sides, lines = [], np.zeros(len(level.walls), LINEDEF)
    for i, w in enumerate(level.walls):
        two = w.back is not None
        flags = (ML_TWOSIDED if two else ML_BLOCKING) | (ML_BLOCKING if two and w.blocks else 0)
        flags |= (ML_DONTPEGTOP if w.upper_unpegged else 0) | \
            (ML_DONTPEGBOTTOM if w.lower_unpegged else 0) | w.line_bits
        lines[i] = (w.v1, w.v2, flags, w.special, w.tag, len(sides),
                    len(sides) + 1 if two else 0xFFFF)
        sides.append(_side(w.front_side, not two) + (w.front,))
        if two:
            sides.append(_side(w.back_side, False) + (w.back,))
    sidedefs = np.array(sides, SIDEDEF) if sides else np.zeros(0, SIDEDEF)
    sectors = np.zeros(len(level.sectors), SECTOR)
    for i, s in enumerate(level.sectors):
        sectors[i] = (round(s.floor), round(s.ceiling), _name8(s.floor_texture or DEFAULT_FLAT),
                      _name8(SKY_FLAT if s.sky else (s.ceiling_texture or DEFAULT_FLAT)),
                      max(0, min(255, int(s.light))), s.special, s.tag)
    things = [(int(t.x), int(t.y), int(round(t.angle)), t.type, t.flags)
              for t in level.things if t.type not in level.thing_types]
    if not any(t[3] == 1 for t in things):
        st = level.start
        things.insert(0, (int(round(st.x)), int(round(st.y)), int(round(st.angle)) % 360, 1, 7))
    return {"THINGS": np.array(things, THING).tobytes(), "LINEDEFS": lines.tobytes(),
            "SIDEDEFS": sidedefs.tobytes(), "VERTEXES": vertexes.tobytes(),
            "SECTORS": sectors.tobytes()}


def _replace_unknown(lumps: dict, iwad) -> list[str]:
    """Names the IWAD lacks replaced by its defaults; the notes saying which."""
    from wallbsp.assets.wadtextures import wad_textures
    textures = wad_textures(iwad)
    with open_wad(iwad) as wad:
        flats = set(wad.between(("F_START", "FF_START"), ("F_END", "FF_END")))
    sides = np.frombuffer(lumps["SIDEDEFS"], SIDEDEF).copy()
    sectors = np.frombuffer(lumps["SECTORS"], SECTOR).copy()
    gone = set()
    for field in ("upper", "lower", "middle"):
        for i, raw in enumerate(sides[field].tolist()):
            name = raw.decode("latin-1").upper()
            if name not in ("-", "") and textures.definition(name) is None:
                gone.add(name)
                sides[field][i] = DEFAULT_WALL.encode()
    for field in ("floor_flat", "ceiling_flat"):
        for i, raw in enumerate(sectors[field].tolist()):
            name = raw.decode("latin-1").upper()
            if name not in flats:
                gone.add(name)
                sectors[field][i] = DEFAULT_FLAT.encode()
    lumps["SIDEDEFS"], lumps["SECTORS"] = sides.tobytes(), sectors.tobytes()
    return [f"{iwad} lacks {len(gone)} of the level's texture and flat names "
            f"({', '.join(sorted(gone)[:6])}{' ...' if len(gone) > 6 else ''}); "
            f"{DEFAULT_WALL} and {DEFAULT_FLAT} stand in for them"] if gone else []


def udmf_text(level: Level, lumps: dict) -> str:
    """The same map as UDMF (namespace "doom"), from the DOOM-format lumps' records."""
    out = ['namespace = "doom";']
    for t in np.frombuffer(lumps["THINGS"], THING):
        out.append(f"thing {{ x = {t['x']}.0; y = {t['y']}.0; angle = {t['angle']}; "
                   f"type = {t['type']}; skill1 = true; skill2 = true; skill3 = true; "
                   f"skill4 = true; skill5 = true; single = true; }}")
    for v in np.frombuffer(lumps["VERTEXES"], VERTEX):
        out.append(f"vertex {{ x = {v['x']}.0; y = {v['y']}.0; }}")
    for ld in np.frombuffer(lumps["LINEDEFS"], LINEDEF):
        back = "" if ld["left"] == 0xFFFF else f" sideback = {ld['left']};"
        flags = "".join(f" {k} = true;" for bit, k in ((1, "blocking"), (4, "twosided"),
                        (8, "dontpegtop"), (16, "dontpegbottom"), (32, "secret"),
                        (64, "blocksound"), (128, "dontdraw")) if ld["flags"] & bit)
        out.append(f"linedef {{ v1 = {ld['v1']}; v2 = {ld['v2']}; sidefront = {ld['right']};"
                   f"{back}{flags} special = {ld['special']}; id = {ld['tag']}; }}")
    for s in np.frombuffer(lumps["SIDEDEFS"], SIDEDEF):
        names = "".join(f' texture{k} = "{s[k].decode("latin-1")}";'
                        for k in ("upper", "lower", "middle"))
        out.append(f"sidedef {{ offsetx = {s['xoff']}; offsety = {s['yoff']};{names} "
                   f"sector = {s['sector']}; }}")
    for s in np.frombuffer(lumps["SECTORS"], SECTOR):
        out.append(f'sector {{ heightfloor = {s["floor"]}; heightceiling = {s["ceiling"]}; '
                   f'texturefloor = "{s["floor_flat"].decode("latin-1")}"; '
                   f'textureceiling = "{s["ceiling_flat"].decode("latin-1")}"; '
                   f'lightlevel = {s["light"]}; special = {s["special"]}; id = {s["tag"]}; }}')
    return "\n".join(out) + "\n"


def export_level(level: Level, path, map_name: str = "MAP01", fmt: str = "doom",
                 iwad=None) -> list[str]:
    """Write ``level`` as a PWAD at ``path``; the notes to show the user."""
    map_name = map_name.upper()
    lumps = level_map_lumps(level, map_name)
    notes = _replace_unknown(lumps, iwad) if iwad else [
        "our PNG resources are not converted: the textures and flats the level names must "
        "be in the IWAD it is played with"]
    own_types = sum(t.type in level.thing_types for t in level.things)
    if own_types:
        notes.append(f"{own_types} things of the level's own types left out (no DOOM port "
                     f"knows them)")
    if fmt == "udmf":
        body, _ = rebuild_udmf_map(str(level.source), map_name, [
            Lump("TEXTMAP", udmf_text(level, lumps).encode()), Lump("ENDMAP", b"")],
            NodeOptions())
    else:
        own = {k: Lump(k, v) for k, v in lumps.items()}
        body, report = rebuild_map(str(level.source), map_name, own, NodeOptions())
        notes.extend(report.warnings)
    WadImage(b"PWAD", [Lump(map_name, b"")] + body).write(path)
    return notes


