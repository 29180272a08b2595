"""A built tree as lumps: vanilla VERTEXES, SEGS, SSECTORS and NODES, or ZDoom's extended
nodes (XNOD in NODES, SEGS and SSECTORS empty) when the tree passes vanilla's limits.

``node_lumps(nodes, n_own, where, extended=False) -> (lumps dict, warnings list)``
(``extended``: XNOD whatever the size, as zdbsp ``-X``).  Vanilla's limits: every count
and index in a signed 16-bit field (vertexes, segs, subsectors, nodes at most 32767; a
node's child numbers below ``NF_SUBSECTOR``), coordinates and a partition's ``dx, dy`` in
-32768..32767, a seg's offset too.  XNOD (uncompressed, as zdbsp ``-X`` writes it): the
map's own vertex count, the new vertexes in 16.16 fixed point, subsectors as seg counts,
segs as ``v1, v2`` (32-bit), linedef (16-bit), side (8-bit), nodes with 32-bit children
(``0x80000000``: a subsector).
"""
from __future__ import annotations

import struct

import numpy as np

from .builder import LEAF_FLAG
from .gllumps import nodes_v5
from .mapdata import NODE, SEG, SUBSECTOR, VERTEX

VANILLA_MAX = 32767


def vanilla_limits(nodes, n_own_vertexes: int) -> list[str]:
    """What in ``nodes`` a vanilla lump cannot hold (empty: it fits)."""
    problems = []
    for what, count in (("vertexes", len(nodes.vertexes)), ("segs", len(nodes.segs)),
                        ("subsectors", len(nodes.subsectors)), ("nodes", len(nodes.nodes))):
        if count > VANILLA_MAX:
            problems.append(f"{count} {what} (vanilla holds {VANILLA_MAX})")
    for what, values in (("a vertex", nodes.vertexes), ("a seg offset", nodes.segs["offset"]),
                         ("a partition", np.stack([nodes.nodes["dx"], nodes.nodes["dy"]]))):
        if values.size and (values.min() < -32768 or values.max() > 32767):
            problems.append(f"{what} outside -32768..32767")
    return problems


def _records(dtype, fields: dict, n: int) -> bytes:
    out = np.zeros(n, dtype)
    for name, values in fields.items():
        out[name] = values
    return out.tobytes()


def _children(child, flag):
    """Wide children (``builder.LEAF_FLAG`` marks a subsector) with a lump's flag."""
    child = child.astype(np.int64)
    sub = (child & LEAF_FLAG) != 0
    return np.where(sub, (child & ~LEAF_FLAG) | flag, child)


def vanilla_lumps(nodes) -> dict:
    v, s = nodes.vertexes, nodes.segs
    return {
        "VERTEXES": _records(VERTEX, {"x": v[:, 0], "y": v[:, 1]}, len(v)),
        "SEGS": _records(SEG, {k: s[k] for k in SEG.names}, len(s)),
        "SSECTORS": _records(SUBSECTOR, {k: nodes.subsectors[k] for k in SUBSECTOR.names},
                             len(nodes.subsectors)),
        "NODES": _records(NODE, {"x": nodes.nodes["x"], "y": nodes.nodes["y"],
                                 "dx": nodes.nodes["dx"], "dy": nodes.nodes["dy"],
                                 "bbox": nodes.nodes["bbox"],
                                 "child": _children(nodes.nodes["child"], 0x8000)},
                          len(nodes.nodes)),
    }


def xnod_lump(nodes, n_own: int) -> bytes:
    new = nodes.vertexes[n_own:]
    parts = [b"XNOD", struct.pack("<II", n_own, len(new))]
    parts.append((new.astype(np.int64) << 16).astype("<i4").tobytes())
    parts.append(struct.pack("<I", len(nodes.subsectors)))
    parts.append(nodes.subsectors["count"].astype("<u4").tobytes())
    segs = nodes.segs
    rows = np.zeros(len(segs), np.dtype([("v1", "<u4"), ("v2", "<u4"), ("linedef", "<u2"),
                                         ("side", "u1")]))
    rows["v1"], rows["v2"], rows["linedef"], rows["side"] = (segs["v1"], segs["v2"],
                                                              segs["linedef"], segs["side"])
    parts += [struct.pack("<I", len(segs)), rows.tobytes()]
    parts += [struct.pack("<I", len(nodes.nodes)), nodes_v5(nodes.nodes)]
    return b"".join(parts)


def node_lumps(nodes, n_own: int, where: str, extended: bool = False
               ) -> tuple[dict, list[str]]:
    """The lumps; XNOD where vanilla's limits do not hold (a warning) or ``extended``."""
    problems = vanilla_limits(nodes, n_own)
    if not problems and not extended:
        return vanilla_lumps(nodes), []
    own = nodes.vertexes[:n_own]
    lumps = {"VERTEXES": _records(VERTEX, {"x": own[:, 0], "y": own[:, 1]}, n_own),
             "SEGS": b"", "SSECTORS": b"", "NODES": xnod_lump(nodes, n_own)}
    if not problems:
        return lumps, []
    return lumps, [f"{where}: past vanilla's limits ({'; '.join(problems)}): ZDoom extended "
                   f"nodes (XNOD) written; vanilla DOOM and Chocolate Doom cannot load it"]
