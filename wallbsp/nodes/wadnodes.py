"""Rebuilding a WAD's maps: ``wallbsp nodes IN.wad -o OUT.wad``.

Public API:
- ``NodeOptions``: the build's ``BuildOptions``, ``maps`` (names, or None: every map),
  ``reject`` (``"sight"``: ``reject``'s table; ``"zero"``: all zeros; ``"keep"``: the map's
  own when it has the right size, as zdbsp ``-E``);
- ``rebuild_wad(image, label, options) -> list[MapReport]``: every chosen DOOM-format map of
  the ``WadImage`` gets new VERTEXES, SEGS, SSECTORS, NODES, REJECT and BLOCKMAP, in DOOM's
  lump order; every other lump (and a map's own THINGS, LINEDEFS, SIDEDEFS, SECTORS) keeps
  its bytes.  A map's old GL nodes (``GL_<map>``) are dropped: they would not match.
  UDMF maps are left as they are, with a warning;
- ``MapReport``: per map ``name``, ``segs``, ``subsectors``, ``nodes``, ``vertexes`` (split
  ones), ``depth``, ``seg_ratio`` (SEGS entries / (one-sided + 2 x two-sided linedefs)),
  ``seconds``, ``extended`` and ``warnings``.
"""
from __future__ import annotations

import time
from dataclasses import dataclass, field

from wallbsp.files import LevelError
from wallbsp.assets.wadwrite import MAP_LUMPS, Lump, WadImage

from .blockmap import BlockmapTooBig, blockmap_lump
from .builder import BuildOptions, build_nodes
from .lumps import node_lumps
from .mapdata import NO_SIDE, map_data
from .reject import reject_lump


@dataclass(frozen=True)
class NodeOptions:
    build: BuildOptions = BuildOptions()
    maps: tuple | None = None
    reject: str = "sight"


@dataclass
class MapReport:
    name: str
    segs: int = 0
    subsectors: int = 0
    nodes: int = 0
    vertexes: int = 0
    depth: int = 0
    seg_ratio: float = 0.0
    seconds: float = 0.0
    extended: bool = False
    warnings: list = field(default_factory=list)


def seg_denominator(linedefs) -> int:
    """One-sided + 2 x two-sided linedefs: the segs a tree without a split would hold."""
    return int((linedefs["right"] != NO_SIDE).sum() + (linedefs["left"] != NO_SIDE).sum())


def rebuild_map(label: str, name: str, own: dict, options: NodeOptions):
    """The map's lumps in DOOM's order (``[Lump]``, after its marker: the ones the build
    does not make are ``own``'s, name -> ``Lump``) and its report."""
    started = time.perf_counter()
    m = map_data(label, name, {k: lump.data for k, lump in own.items()})
    nodes = build_nodes(m, options.build)
    new, warnings = node_lumps(nodes, nodes.own_vertexes, m.where)
    try:
        new["BLOCKMAP"] = blockmap_lump(m.linedefs, m.vertexes, m.where)
    except BlockmapTooBig as err:
        new["BLOCKMAP"] = b""
        warnings.append(f"{err}; an empty BLOCKMAP written (ports that build their own "
                        f"accept it)")
    size = (len(m.sectors) ** 2 + 7) // 8
    kept = options.reject == "keep" and len(m.lumps.get("REJECT", b"")) == size
    new["REJECT"] = m.lumps["REJECT"] if kept else reject_lump(m, zero=options.reject == "zero")
    if options.reject == "keep" and not kept:
        warnings.append(f"{m.where}: REJECT: missing or not {size} bytes; a new one built")
    out = [Lump(lump, new[lump]) if lump in new else own[lump] for lump in MAP_LUMPS
           if lump in new or lump in own]
    report = MapReport(name, len(nodes.segs), len(nodes.subsectors), len(nodes.nodes),
                       len(nodes.vertexes) - nodes.own_vertexes, nodes.depth,
                       len(nodes.segs) / max(1, seg_denominator(m.linedefs)),
                       time.perf_counter() - started, bool(warnings and new["SEGS"] == b""),
                       warnings)
    return out, report


def rebuild_wad(image: WadImage, label: str, options: NodeOptions = NodeOptions()):
    """Rebuild the chosen maps of ``image`` in place; their reports, in WAD order."""
    markers = image.maps()
    names = [image.lumps[i].name for i in markers]
    wanted = names if options.maps is None else [n.upper() for n in options.maps]
    missing = [n for n in wanted if n not in names]
    if missing:
        raise LevelError(f"{label}: {missing[0]}: no such map ({len(names)} maps: "
                         f"{', '.join(names[:8])}{' ...' if len(names) > 8 else ''})")
    reports = []
    for marker in reversed(markers):        # from the end: earlier indices stay valid
        name = image.lumps[marker].name
        if name not in wanted:
            continue
        start, stop = image.map_span(marker)
        own = image.lumps[start + 1:stop]
        if own and own[0].name == "TEXTMAP":
            reports.append(MapReport(name, warnings=[f"{label}: {name}: a UDMF map; left as "
                                                     f"it is (its ZNODES are not rebuilt)"]))
            continue
        by_name = {lump.name: lump for lump in own if not lump.name.startswith("GL_")}
        lumps, report = rebuild_map(label, name, by_name, options)
        image.replace_span(start + 1, stop, lumps)
        reports.append(report)
    return reports[::-1]
