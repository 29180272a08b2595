"""WAD files as editable lists of lumps, written back byte for byte where unchanged.

Public API:
- ``read_wad_image(path) -> WadImage``: every lump of a WAD (``Lump``: ``name``, ``data``),
  in directory order, with what is needed to write it back as it was;
- ``WadImage``: ``magic`` (``b"IWAD"`` or ``b"PWAD"``), ``lumps``; ``maps()`` the map
  markers' indices, ``map_span(i)`` the lumps of the map at marker ``i``,
  ``replace_span(start, stop, lumps)``; ``to_bytes()``, ``write(path)`` (atomic, through
  ``files.write_atomically``);
- ``MAP_LUMPS``: a DOOM-format map's lumps in DOOM's order (``ML_*``), ``GL_LUMPS`` the v5
  GL nodes' lumps after a ``GL_<map>`` marker (``GL_LEVEL`` for a map name of more than 5
  letters, glBSP's v5 rule), which ``map_span`` counts as the map's.

Round trip: a lump read from a file and not replaced keeps its 8 raw name bytes (some tools
leave garbage after the NUL), the bytes between it and the lump before it (deutex pads lumps
to 4 bytes with whatever was in its buffer, as in both Freedoom IWADs), its offset when it is
empty, and its place in a run of directory entries that share one lump's data.  So a WAD we
read and do not change is written as the same bytes, and a changed one keeps every unchanged
lump's bytes; new lumps follow each other without padding.  A WAD whose lumps are not stored
in directory order (or whose directory is not at the end) is written in directory order, then
byte for byte only if nothing changed.
"""
from __future__ import annotations

import struct
from dataclasses import dataclass, field

from wallbsp.files import write_atomically
from wallbsp.assets.wad import HEADER, lump_name, open_wad

MAP_LUMPS = ("THINGS", "LINEDEFS", "SIDEDEFS", "VERTEXES", "SEGS", "SSECTORS", "NODES",
             "SECTORS", "REJECT", "BLOCKMAP")
HEXEN_LUMPS = ("BEHAVIOR", "SCRIPTS")
GL_LUMPS = ("GL_VERT", "GL_SEGS", "GL_SSECT", "GL_NODES", "GL_PVS")
_ENTRY = struct.Struct("<ii8s")
_MAX_GAP = 64          # padding between lumps kept on a round trip (deutex pads to 4)


@dataclass
class _Origin:
    """Where a lump was in the file it was read from."""
    pos: int
    raw_name: bytes
    gap: bytes             # bytes between the previous stored lump's end and this one


@dataclass
class Lump:
    """One directory entry: its name and its bytes (``origin``: set by the reader, kept
    while the lump is unchanged)."""
    name: str
    data: bytes
    origin: _Origin | None = field(default=None, repr=False, compare=False)


@dataclass
class WadImage:
    """A WAD's header magic and lumps, in directory order."""
    magic: bytes
    lumps: list[Lump]
    source: bytes | None = field(default=None, repr=False)   # the file, if not sequential
    tail_gap: bytes = field(default=b"", repr=False)         # bytes before the directory
    _read_lumps: tuple = field(default=(), repr=False)

    def names(self) -> list[str]:
        return [lump.name for lump in self.lumps]

    def maps(self) -> list[int]:
        """The indices of the map markers (a marker followed by THINGS or TEXTMAP)."""
        names = self.names()
        return [i for i in range(len(names) - 1) if names[i + 1] in ("THINGS", "TEXTMAP")]

    def map_span(self, marker: int) -> tuple[int, int]:
        """``(marker, stop)``: the marker and its map's lumps are ``lumps[marker:stop]``."""
        names = self.names()
        if names[marker + 1] == "TEXTMAP":
            stop = names.index("ENDMAP", marker + 1) + 1 if "ENDMAP" in names[marker:] \
                else len(names)
            return marker, stop
        seen, i = set(), marker + 1
        while i < len(names) and names[i] in MAP_LUMPS + HEXEN_LUMPS and names[i] not in seen:
            seen.add(names[i])
            i += 1
        gl = f"GL_{names[marker]}" if len(names[marker]) <= 5 else "GL_LEVEL"
        if i < len(names) and names[i] == gl:        # a map's GL nodes go with it
            i += 1
            while i < len(names) and names[i] in GL_LUMPS:
                i += 1
        return marker, i

    def replace_span(self, start: int, stop: int, lumps: list[Lump]) -> None:
        self.lumps[start:stop] = lumps

    def unchanged(self) -> bool:
        return len(self._read_lumps) == len(self.lumps) and all(
            a is b for a, b in zip(self._read_lumps, self.lumps))

    def to_bytes(self) -> bytes:
        if self.source is not None and self.unchanged():
            return self.source
        same = self.unchanged()
        return _layout(self.magic, self.lumps, self.tail_gap if same else b"", same)

    def write(self, path) -> None:
        """The WAD to ``path``: all of it or nothing."""
        write_atomically(path, self.to_bytes())


def _layout(magic: bytes, lumps: list[Lump], tail_gap: bytes, exact: bool) -> bytes:
    body = bytearray()
    entries = []
    shared: dict[tuple[int, int], int] = {}      # (origin pos, size) -> new pos
    for lump in lumps:
        origin = lump.origin
        size = len(lump.data)
        raw = origin.raw_name if origin is not None else lump.name.encode("latin-1")
        if not size:         # an empty lump's offset means nothing: kept unless it could
            here = HEADER.size + len(body)     # point past the end of a changed file
            keep = origin is not None and (exact or 0 <= origin.pos <= here)
            pos = origin.pos if keep else here
        elif origin is not None and (origin.pos, size) in shared:
            pos = shared[(origin.pos, size)]
        else:
            if origin is not None:
                body += origin.gap
            pos = HEADER.size + len(body)
            body += lump.data
            if origin is not None:
                shared[(origin.pos, size)] = pos
        entries.append(_ENTRY.pack(pos, size, raw))
    body += tail_gap
    return HEADER.pack(magic, len(entries), HEADER.size + len(body)) + bytes(body) + \
        b"".join(entries)


def read_wad_image(path) -> WadImage:
    """Every lump of the WAD at ``path``, with what writing it back unchanged needs."""
    with open_wad(path) as wad:
        d = wad.directory
        data = [wad.read(i) for i in range(len(d.names))]
        with open(wad.path, "rb") as f:
            whole = f.read()
    magic, count, offset = HEADER.unpack_from(whole)
    raw_names = [whole[offset + 16 * i + 8: offset + 16 * i + 16] for i in range(count)]
    lumps, end, sequential = [], HEADER.size, True
    seen: set[tuple[int, int]] = set()
    for i in range(count):
        pos, size = int(d.pos[i]), int(d.size[i])
        gap = b""
        if size and (pos, size) not in seen:
            if pos < end or pos - end > _MAX_GAP:
                sequential = False
            else:
                gap = whole[end:pos]
            end = max(end, pos + size)
            seen.add((pos, size))
        lumps.append(Lump(lump_name(raw_names[i]) if raw_names[i] else "", data[i],
                          _Origin(pos, raw_names[i], gap)))
    tail = whole[end:offset] if 0 <= offset - end <= _MAX_GAP else b""
    if offset - end != len(tail) or offset + 16 * count != len(whole):
        sequential = False
    image = WadImage(magic, lumps, None if sequential else whole, tail, tuple(lumps))
    return image
