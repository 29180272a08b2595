"""GL nodes (``glnodes.GlNodes``) as lumps: glBSP's v5 GL lumps after a DOOM-format map,
and ZDoom's ZNODES for a UDMF map.

- ``gl_v5_lumps(map_name, gl, n_vertexes, vertexes, linedefs) -> [Lump]``: the marker
  ``GL_<MAP>`` (a map name of more than 5 letters: ``GL_LEVEL`` with ``LEVEL=<MAP>`` in
  it), whose text body holds ``KEY=VALUE`` lines (``BUILDER``, and ``CHECKSUM``: Adler-32
  of the VERTEXES then LINEDEFS lumps, as glBSP computes it); ``GL_VERT`` (``gNd5``, then
  each vertex past the VERTEXES lump's ``n_vertexes`` as 16.16 fixed x, y); ``GL_SEGS``
  (v1, v2 as uint32, bit 31 set for a GL vertex; linedef uint16, 0xFFFF for a miniseg;
  side uint16; partner seg uint32, 0xFFFFFFFF for none); ``GL_SSECT`` (count, first seg,
  uint32); ``GL_NODES`` (x, y, dx, dy, two boxes as int16 like NODES, children uint32 with
  bit 31 for a subsector); ``GL_PVS`` empty, as glBSP writes it.
- ``znodes_lump(gl, n_own, compress) -> bytes``: ZDoom's extended GL nodes, ``ZGLN``
  (zlib-compressed) or ``XGLN`` (``XGL2``/``ZGL2`` when a linedef number needs 32 bits):
  the map's vertex count, the new vertexes (16.16), the subsectors' seg counts, each seg's
  v1, partner, linedef (0xFFFF or 0xFFFFFFFF for a miniseg) and side (a seg's v2 is the
  next seg's v1 in its subsector), then the nodes as XNOD's.
"""
from __future__ import annotations

import struct
import zlib

import numpy as np

from wallbsp.assets.wadwrite import Lump

from .builder import LEAF_FLAG

GL_VERTEX = 0x80000000
BUILDER = "wallbsp"


def gl_marker(map_name: str, checksum: int) -> Lump:
    long_name = len(map_name) > 5
    text = (f"LEVEL={map_name}\n" if long_name else "") + \
        f"BUILDER={BUILDER}\nCHECKSUM=0x{checksum:08x}\n"
    return Lump("GL_LEVEL" if long_name else f"GL_{map_name}", text.encode("ascii"))


def _wide_children(nd, flag):
    child = nd["child"].astype(np.int64)
    return np.where(child & LEAF_FLAG, (child & ~LEAF_FLAG) | flag, child)


def nodes_v5(nd) -> bytes:
    """Nodes with 16-bit partitions and boxes and 32-bit children (GL_NODES v5, XNOD's)."""
    rows = np.zeros(len(nd), np.dtype([("xy", "<i2", (4,)), ("bbox", "<i2", (2, 4)),
                                       ("child", "<u4", (2,))]))
    rows["xy"] = np.stack([nd["x"], nd["y"], nd["dx"], nd["dy"]], axis=1)
    rows["bbox"] = nd["bbox"]
    rows["child"] = _wide_children(nd, 0x80000000)
    return rows.tobytes()


def gl_v5_lumps(map_name: str, gl, n_vertexes: int, vertexes: bytes,
                linedefs: bytes) -> list[Lump]:
    segs = gl.segs
    rows = np.zeros(len(segs), np.dtype([("v1", "<u4"), ("v2", "<u4"), ("linedef", "<u2"),
                                         ("side", "<u2"), ("partner", "<u4")]))
    for k, field in ((0, "v1"), (1, "v2")):
        v = segs[:, k]
        rows[field] = np.where(v < n_vertexes, v, (v - n_vertexes) | GL_VERTEX)
    rows["linedef"] = np.where(segs[:, 2] < 0, 0xFFFF, segs[:, 2])
    rows["side"] = segs[:, 3]
    rows["partner"] = np.where(segs[:, 4] < 0, 0xFFFFFFFF, segs[:, 4])
    subs = gl.subsectors[:, ::-1].astype("<u4")            # count, first
    return [gl_marker(map_name, zlib.adler32(vertexes + linedefs)),
            Lump("GL_VERT", b"gNd5" + gl.vertexes[n_vertexes:].astype("<i4").tobytes()),
            Lump("GL_SEGS", rows.tobytes()), Lump("GL_SSECT", subs.tobytes()),
            Lump("GL_NODES", nodes_v5(gl.nodes)), Lump("GL_PVS", b"")]


def znodes_lump(gl, n_own: int, compress: bool = True) -> bytes:
    segs = gl.segs
    wide = len(segs) and int(segs[:, 2].max()) >= 0xFFFF
    line = ("<u4" if wide else "<u2")
    rows = np.zeros(len(segs), np.dtype([("v1", "<u4"), ("partner", "<u4"), ("line", line),
                                         ("side", "u1")]))
    rows["v1"], rows["side"] = segs[:, 0], segs[:, 3]
    rows["partner"] = np.where(segs[:, 4] < 0, 0xFFFFFFFF, segs[:, 4])
    rows["line"] = np.where(segs[:, 2] < 0, 0xFFFFFFFF if wide else 0xFFFF, segs[:, 2])
    new = gl.vertexes[n_own:]
    body = b"".join([struct.pack("<II", n_own, len(new)), new.astype("<i4").tobytes(),
                     struct.pack("<I", len(gl.subsectors)),
                     gl.subsectors[:, 1].astype("<u4").tobytes(),
                     struct.pack("<I", len(segs)), rows.tobytes(),
                     struct.pack("<I", len(gl.nodes)), nodes_v5(gl.nodes)])
    magic = ("Z" if compress else "X") + ("GL2" if wide else "GLN")
    return magic.encode() + (zlib.compress(body, 9) if compress else body)
