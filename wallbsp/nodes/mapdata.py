"""A DOOM-format map's lumps as numpy records, checked (what the node builder reads).

Public API:
- ``MapData``: ``name``, ``where`` (for messages), ``lumps`` (name -> bytes, the map's own),
  ``things``, ``linedefs``, ``sidedefs``, ``vertexes``, ``sectors`` (numpy records);
- ``map_data(label, name, lumps) -> MapData``: from a map's lumps (``WadImage.map_span``);
  a UDMF map's (TEXTMAP) through ``level.udmfmap`` (wider integer fields, ``udmf`` set:
  its vertexes are all its own, and its nodes go in ZNODES);
- the record dtypes ``THING``, ``LINEDEF``, ``SIDEDEF``, ``VERTEX``, ``SECTOR``, ``SEG``,
  ``SUBSECTOR``, ``NODE`` (doomdata.h's, little-endian), and ``NO_SIDE``.

A bad map (a lump that is not whole records, an index past its table) is one ``LevelError``
line: ``freedoom2.wad: MAP01: LINEDEFS[12]: right sidedef 900 does not exist (850 sidedefs)``.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from wallbsp.files import LevelError
from wallbsp.level.udmfmap import read_textmap

NO_SIDE = 0xFFFF
THING = np.dtype([("x", "<i2"), ("y", "<i2"), ("angle", "<i2"), ("type", "<u2"),
                  ("flags", "<u2")])
LINEDEF = np.dtype([("v1", "<u2"), ("v2", "<u2"), ("flags", "<u2"), ("special", "<u2"),
                    ("tag", "<u2"), ("right", "<u2"), ("left", "<u2")])
SIDEDEF = np.dtype([("xoff", "<i2"), ("yoff", "<i2"), ("upper", "S8"), ("lower", "S8"),
                    ("middle", "S8"), ("sector", "<u2")])
VERTEX = np.dtype([("x", "<i2"), ("y", "<i2")])
SECTOR = np.dtype([("floor", "<i2"), ("ceiling", "<i2"), ("floor_flat", "S8"),
                   ("ceiling_flat", "S8"), ("light", "<i2"), ("special", "<u2"),
                   ("tag", "<u2")])
SEG = np.dtype([("v1", "<u2"), ("v2", "<u2"), ("angle", "<u2"), ("linedef", "<u2"),
                ("side", "<i2"), ("offset", "<i2")])
SUBSECTOR = np.dtype([("count", "<u2"), ("first", "<u2")])
NODE = np.dtype([("x", "<i2"), ("y", "<i2"), ("dx", "<i2"), ("dy", "<i2"),
                 ("bbox", "<i2", (2, 4)), ("child", "<u2", (2,))])
_NEEDED = {"THINGS": THING, "LINEDEFS": LINEDEF, "SIDEDEFS": SIDEDEF, "VERTEXES": VERTEX,
           "SECTORS": SECTOR}


@dataclass
class MapData:
    name: str
    where: str
    lumps: dict
    things: np.ndarray
    linedefs: np.ndarray
    sidedefs: np.ndarray
    vertexes: np.ndarray
    sectors: np.ndarray
    udmf: bool = False


def records(where: str, lump: str, raw: bytes, dtype) -> np.ndarray:
    if len(raw) % dtype.itemsize:
        raise LevelError(f"{where}: {lump}: {len(raw)} bytes is not a whole number of "
                         f"{dtype.itemsize}-byte records")
    return np.frombuffer(raw, dtype)


def map_data(label: str, name: str, lumps: dict) -> MapData:
    """The checked records of map ``name`` from its lumps (name -> bytes)."""
    where = f"{label}: {name}"
    if "TEXTMAP" in lumps:
        return udmf_map_data(where, name, lumps)
    if "BEHAVIOR" in lumps:
        raise LevelError(f"{where}: Hexen-format maps (BEHAVIOR) are not supported")
    for lump in _NEEDED:
        if lump not in lumps:
            raise LevelError(f"{where}: {lump}: missing")
    got = {lump: records(where, lump, lumps[lump], dtype) for lump, dtype in _NEEDED.items()}
    data = MapData(name, where, lumps, got["THINGS"], got["LINEDEFS"], got["SIDEDEFS"],
                   got["VERTEXES"], got["SECTORS"])
    _check(data)
    return data


def _first(mask) -> int | None:
    bad = np.flatnonzero(mask)
    return int(bad[0]) if bad.size else None


def _check(m: MapData) -> None:
    nv, ns, nsec = len(m.vertexes), len(m.sidedefs), len(m.sectors)
    for end in ("v1", "v2"):
        i = _first(m.linedefs[end] >= nv)
        if i is not None:
            raise LevelError(f"{m.where}: LINEDEFS[{i}]: {end}: vertex {m.linedefs[end][i]} "
                             f"does not exist ({nv} vertexes)")
    for side in ("right", "left"):
        i = _first((m.linedefs[side] != NO_SIDE) & (m.linedefs[side] >= ns))
        if i is not None:
            raise LevelError(f"{m.where}: LINEDEFS[{i}]: {side} sidedef "
                             f"{m.linedefs[side][i]} does not exist ({ns} sidedefs)")
    used = np.zeros(ns, bool)
    for side in ("right", "left"):
        used[m.linedefs[side][m.linedefs[side] != NO_SIDE]] = True
    i = _first(used & (m.sidedefs["sector"] >= nsec))
    if i is not None:
        raise LevelError(f"{m.where}: SIDEDEFS[{i}]: sector {m.sidedefs['sector'][i]} does "
                         f"not exist ({nsec} sectors)")


def udmf_map_data(where: str, name: str, lumps: dict) -> MapData:
    """A UDMF map's records (``udmfmap``'s: coordinates rounded to whole units)."""
    things, linedefs, sidedefs, vertexes, sectors = read_textmap(lumps["TEXTMAP"], where, [])
    data = MapData(name, where, lumps, things, linedefs, sidedefs, vertexes, sectors, True)
    _check(data)
    return data
