"""A map's nodes read back from any of the formats ``wallbsp nodes`` writes, into one shape.

``read_nodes(where, lumps, vertexes=None, gl=False) -> ReadNodes`` reads
- the normal nodes (``gl=False``): vanilla SEGS, SSECTORS, NODES, or ZDoom's extended
  nodes in NODES (``XNOD``, or ``ZNOD``: the same after 4 bytes, zlib-compressed), whose
  new vertexes follow the map's own;
- the GL nodes (``gl=True``): glBSP's GL_VERT, GL_SEGS, GL_SSECT, GL_NODES in v2 (``gNd2``,
  glBSP's and zdbsp's default), v3 or v5 (``gNd5``, what ``wallbsp nodes --gl`` writes),
  or, when the map has a ZNODES lump (a UDMF map), ZDoom's ``XGLN``/``ZGLN``, ``XGL2``/
  ``ZGL2`` (32-bit linedef numbers) or ``XGL3``/``ZGL3`` (16.16 partitions) there; the same
  in SSECTORS (where zdbsp ``-g -X`` puts them beside XNOD).

``lumps`` are the map's lumps by name; ``vertexes`` the map's own as an ``(n, 2)`` int
array (default: the VERTEXES lump; a UDMF map's come from its TEXTMAP).  ``ReadNodes``:
``kind`` (the format's name), ``vertexes`` ``(n, 2)`` int64 in 16.16 fixed point (the
map's, then the nodes' own), ``segs`` ``(k, 5)`` int64 (v1, v2, linedef, -1 for a
miniseg, side, partner, -1 for none), ``subsectors`` ``(s, 2)`` (first
seg, count), ``nodes`` (records: ``x, y, dx, dy`` in 16.16, ``bbox`` in map units,
``child`` with ``builder.LEAF_FLAG`` marking a subsector), ``gl`` (GL nodes: each
subsector's segs must close).  A lump too short for what it says it holds, or a bad
magic, is a ``NodesError`` (a ``ValueError``) naming the lump and the place.
"""
from __future__ import annotations

import zlib
from dataclasses import dataclass

import numpy as np

from wallbsp.files import LevelError

from .builder import LEAF_FLAG

FRAC = 1 << 16
EXTENDED = (b"XNOD", b"ZNOD")
GL_EXTENDED = (b"XGLN", b"ZGLN", b"XGL2", b"ZGL2", b"XGL3", b"ZGL3")
WIDE_NODE = np.dtype([("x", np.int64), ("y", np.int64), ("dx", np.int64), ("dy", np.int64),
                      ("bbox", np.int64, (2, 4)), ("child", np.int64, (2,))])


class NodesError(LevelError):
    """Node lumps that cannot be read (too short, a bad magic, a bad count)."""


@dataclass
class ReadNodes:
    kind: str
    vertexes: np.ndarray
    segs: np.ndarray
    subsectors: np.ndarray
    nodes: np.ndarray
    gl: bool = False


class _Reader:
    """Little-endian fields from a lump, each read checked against its length."""

    def __init__(self, where: str, lump: str, data: bytes, at: int = 0):
        self.where, self.lump, self.data, self.at = where, lump, data, at

    def fail(self, what: str):
        raise NodesError(f"{self.where}: {self.lump}: {what}")

    def count(self, what: str) -> int:
        return self.array(what, "<u4", 1)[0].item()

    def array(self, what: str, dtype, n: int) -> np.ndarray:
        dtype = np.dtype(dtype)
        end = self.at + dtype.itemsize * n
        if end > len(self.data):
            self.fail(f"ends at byte {len(self.data)}, inside {what} (byte {self.at}: "
                      f"{n} x {dtype.itemsize} bytes)")
        out = np.frombuffer(self.data, dtype, n, self.at)
        self.at = end
        return out

    def done(self):
        if self.at != len(self.data):
            self.fail(f"{len(self.data) - self.at} bytes left over after the nodes")


def _records(where, lump, raw, dtype):
    if raw is None:
        raise NodesError(f"{where}: {lump}: missing")
    reader = _Reader(where, lump, raw)
    if len(raw) % np.dtype(dtype).itemsize:
        reader.fail(f"{len(raw)} bytes is not a whole number of "
                    f"{np.dtype(dtype).itemsize}-byte records")
    return reader.array("its records", dtype, len(raw) // np.dtype(dtype).itemsize)


def _nodes(rows, fixed: bool, leaf_bit: int):
    out = np.zeros(len(rows), WIDE_NODE)
    scale = 1 if fixed else FRAC
    for k, name in enumerate(("x", "y", "dx", "dy")):
        out[name] = rows["xy"][:, k].astype(np.int64) * scale
    out["bbox"] = rows["bbox"]
    child = rows["child"].astype(np.int64)
    out["child"] = np.where(child & leaf_bit, (child & ~leaf_bit) | LEAF_FLAG, child)
    return out


def _node_dtype(fixed: bool, child: str):
    return np.dtype([("xy", "<i4" if fixed else "<i2", (4,)), ("bbox", "<i2", (2, 4)),
                     ("child", child, (2,))])


def _subsectors(counts):
    counts = counts.astype(np.int64)
    first = np.concatenate([[0], np.cumsum(counts)[:-1]]) if len(counts) else counts
    return np.stack([first, counts], axis=1).reshape(-1, 2)


def _vanilla(where, lumps, own):
    segs = _records(where, "SEGS", lumps.get("SEGS"), np.dtype(
        [("v1", "<u2"), ("v2", "<u2"), ("angle", "<u2"), ("linedef", "<u2"),
         ("side", "<i2"), ("offset", "<i2")]))
    subs = _records(where, "SSECTORS", lumps.get("SSECTORS"),
                    np.dtype([("count", "<u2"), ("first", "<u2")]))
    nodes = _records(where, "NODES", lumps.get("NODES"), _node_dtype(False, "<u2"))
    rows = np.stack([segs["v1"], segs["v2"], segs["linedef"], segs["side"],
                     np.full(len(segs), -1)], axis=1).astype(np.int64).reshape(-1, 5)
    return ReadNodes("vanilla", own, rows, np.stack(
        [subs["first"], subs["count"]], axis=1).astype(np.int64).reshape(-1, 2),
        _nodes(nodes, False, 0x8000))


def _unpacked(where, lump, raw, compressed_magic):
    """The lump's body after its magic (inflated for a Z... magic)."""
    if raw[:4] not in compressed_magic:
        return raw
    try:
        return raw[:4] + zlib.decompress(raw[4:])
    except zlib.error as err:
        raise NodesError(f"{where}: {lump}: {raw[:4].decode()}: its zlib data is "
                         f"damaged ({err})") from None


def _new_vertexes(r, own, n_map):
    n_org = r.count("the map's vertex count")
    if n_org > n_map:
        r.fail(f"made for {n_org} map vertexes; the map has {n_map}")
    n_new = r.count("the new vertex count")
    new = r.array("the new vertexes", "<i4", 2 * n_new).astype(np.int64).reshape(-1, 2)
    return np.concatenate([own[:n_org], new])


def _extended(where, lump, raw, own, n_map, gl):
    magic = raw[:4]
    data = _unpacked(where, lump, raw, (b"ZNOD", b"ZGLN", b"ZGL2", b"ZGL3"))
    r = _Reader(where, lump, data, 4)
    vertexes = _new_vertexes(r, own, n_map)
    nsub = r.count("the subsector count")
    subs = _subsectors(r.array("the subsectors", "<u4", nsub))
    nseg = r.count("the seg count")
    if not gl:
        segs = r.array("the segs", np.dtype([("v1", "<u4"), ("v2", "<u4"),
                                             ("line", "<u2"), ("side", "u1")]), nseg)
        v2, partner = segs["v2"].astype(np.int64), np.full(nseg, -1)
        miniseg = 1 << 40                       # none: XNOD has no minisegs
    else:
        wide = magic[1:] in (b"GL2", b"GL3")
        segs = r.array("the segs", np.dtype([("v1", "<u4"), ("partner", "<u4"),
                       ("line", "<u4" if wide else "<u2"), ("side", "u1")]), nseg)
        v2 = _next_v1(segs["v1"].astype(np.int64), subs, r)
        partner = segs["partner"].astype(np.int64)
        partner = np.where(partner == 0xFFFFFFFF, -1, partner)
        miniseg = 0xFFFFFFFF if wide else 0xFFFF
    line = segs["line"].astype(np.int64)
    rows = np.stack([segs["v1"].astype(np.int64), v2, np.where(line == miniseg, -1, line),
                     segs["side"], partner], axis=1).astype(np.int64).reshape(-1, 5)
    nnode = r.count("the node count")
    nodes = r.array("the nodes", _node_dtype(magic[1:] == b"GL3", "<u4"), nnode)
    r.done()
    kind = magic.decode()
    return ReadNodes(kind, vertexes, rows, subs, _nodes(nodes, magic[1:] == b"GL3",
                                                        0x80000000), gl)


def _next_v1(v1, subs, r):
    """ZDoom's GL segs store v1 only: a seg ends where the next of its subsector starts."""
    if len(subs) and subs[-1].sum() != len(v1):
        r.fail(f"its subsectors hold {int(subs[-1].sum())} segs; it has {len(v1)}")
    nxt = np.arange(1, len(v1) + 1)
    last = subs[:, 0] + subs[:, 1] - 1
    ok = subs[:, 1] > 0
    nxt[last[ok]] = subs[ok, 0]
    return v1[nxt % max(1, len(v1))] if len(v1) else v1


# glBSP's GL node versions read: (GL vertex flag, the segs' and subsectors' index width, the
# partner's "none", the nodes' child width and subsector flag). v2 is glBSP's and zdbsp's
# default; v3 widens segs and subsectors (their lumps start "gNd3" too); v5 also the nodes.
GL_VERSIONS = {b"gNd2": (0x8000, "<u2", 0xFFFF, "<u2", 0x8000),
               b"gNd3": (1 << 30, "<u4", 0xFFFFFFFF, "<u2", 0x8000),
               b"gNd5": (0x80000000, "<u4", 0xFFFFFFFF, "<u4", 0x80000000)}


def _gl_nodes(where, lumps, own):
    """glBSP's GL_VERT, GL_SEGS, GL_SSECT and GL_NODES, in any of ``GL_VERSIONS``."""
    raw = lumps.get("GL_VERT")
    if raw is None:
        raise NodesError(f"{where}: GL_VERT: missing")
    magic = raw[:4]
    if magic not in GL_VERSIONS:
        what = f"GL nodes v{raw[3:4].decode('latin-1')}" if raw[:3] == b"gNd" else \
            f"magic {raw[:4]!r} (GL nodes v1)"
        raise NodesError(f"{where}: GL_VERT: {what}; v2, v3 and v5 are read")
    if magic == b"gNd2" and (lumps.get("GL_SEGS") or b"")[:4] == b"gNd3":
        magic = b"gNd3"                 # glBSP's v3 keeps GL_VERT's "gNd2"
    gl_flag, index, none, child, leaf = GL_VERSIONS[magic]
    new = _records(where, "GL_VERT", raw[4:], np.dtype(("<i4", (2,)))).astype(np.int64)
    vertexes = np.concatenate([own, new])
    segs = _records(where, "GL_SEGS", _after_magic(lumps.get("GL_SEGS"), magic), np.dtype(
        [("v1", index), ("v2", index), ("line", "<u2"), ("side", "<u2"), ("partner", index)]))
    v = [segs[k].astype(np.int64) for k in ("v1", "v2")]
    v = [np.where(x & gl_flag, (x & ~gl_flag) + len(own), x) for x in v]
    line, partner = segs["line"].astype(np.int64), segs["partner"].astype(np.int64)
    rows = np.stack([v[0], v[1], np.where(line == 0xFFFF, -1, line), segs["side"],
                     np.where(partner == none, -1, partner)], axis=1)
    subs = _records(where, "GL_SSECT", _after_magic(lumps.get("GL_SSECT"), magic),
                    np.dtype([("count", index), ("first", index)]))
    nodes = _records(where, "GL_NODES", lumps.get("GL_NODES"), _node_dtype(False, child))
    return ReadNodes(f"GL v{magic[3:].decode()}", vertexes,
                     rows.astype(np.int64).reshape(-1, 5),
                     np.stack([subs["first"], subs["count"]], axis=1).astype(np.int64)
                     .reshape(-1, 2), _nodes(nodes, False, leaf), True)


def _after_magic(raw, magic):
    """v3's GL_SEGS and GL_SSECT begin with the version's magic too."""
    return raw[4:] if raw is not None and magic == b"gNd3" and raw[:4] == magic else raw


def has_gl(lumps: dict) -> bool:
    return "ZNODES" in lumps or "GL_VERT" in lumps or \
        lumps.get("SSECTORS", b"")[:4] in GL_EXTENDED


def read_nodes(where: str, lumps: dict, vertexes=None, gl: bool = False) -> ReadNodes:
    if vertexes is None:
        vertexes = _records(where, "VERTEXES", lumps.get("VERTEXES"),
                            np.dtype([("x", "<i2"), ("y", "<i2")]))
        vertexes = np.stack([vertexes["x"], vertexes["y"]], axis=1)
    own = np.asarray(vertexes, np.int64).reshape(-1, 2) * FRAC
    if gl:
        if "ZNODES" in lumps:
            raw = lumps["ZNODES"]
            if raw[:4] not in GL_EXTENDED:
                raise NodesError(f"{where}: ZNODES: magic {raw[:4]!r} is none of "
                                 f"{', '.join(m.decode() for m in GL_EXTENDED)}")
            return _extended(where, "ZNODES", raw, own, len(own), True)
        raw = lumps.get("SSECTORS", b"")
        if raw[:4] in GL_EXTENDED:                   # zdbsp -g -X / -z: GL nodes there
            return _extended(where, "SSECTORS", raw, own, len(own), True)
        return _gl_nodes(where, lumps, own)
    raw = lumps.get("NODES", b"")
    if raw[:4] in EXTENDED:
        return _extended(where, "NODES", raw, own, len(own), False)
    if raw[:4] in GL_EXTENDED:
        return _extended(where, "NODES", raw, own, len(own), True)
    return _vanilla(where, lumps, own)
