"""Rebuilding a WAD's maps: ``wallbsp nodes IN.wad -o OUT.wad``.

Public API:
- ``NodeOptions``: the build's ``BuildOptions``, ``maps`` (names, or None: every map),
  ``reject`` (``"sight"``: ``reject``'s table; ``"zero"``: all zeros; ``"keep"``: the map's
  own when it has the right size, as zdbsp ``-E``), ``gl`` (v5 GL nodes after each
  DOOM-format map, ``gllumps``), ``extended`` (XNOD even within vanilla's limits),
  ``compress`` (a UDMF map's ZNODES as ZGLN rather than XGLN);
- ``rebuild_wad(image, label, options) -> list[MapReport]``: every chosen DOOM-format map of
  the ``WadImage`` gets new VERTEXES, SEGS, SSECTORS, NODES, REJECT and BLOCKMAP, in DOOM's
  lump order; every other lump (and a map's own THINGS, LINEDEFS, SIDEDEFS, SECTORS) keeps
  its bytes.  A map's old GL nodes (``GL_<map>``) are dropped: they would not match.
  A UDMF map (TEXTMAP) keeps its lumps and gets new ZNODES (ZDoom's GL nodes), after
  TEXTMAP;
- ``MapReport``: per map ``name``, ``segs``, ``subsectors``, ``nodes``, ``vertexes`` (split
  ones), ``depth``, ``seg_ratio`` (SEGS entries / (one-sided + 2 x two-sided linedefs)),
  ``seconds``, ``extended``, ``warnings``, and with GL nodes ``gl_segs``, ``minisegs``.
"""
from __future__ import annotations

import time
from dataclasses import dataclass, field

from wallbsp.files import LevelError
from wallbsp.assets.wadwrite import MAP_LUMPS, Lump, WadImage

from .blockmap import BlockmapTooBig, blockmap_lump
from .builder import BuildOptions, build_nodes
from .gllumps import gl_v5_lumps, znodes_lump
from .glnodes import gl_nodes
from .lumps import node_lumps
from .mapdata import NO_SIDE, map_data
from .reject import reject_lump


@dataclass(frozen=True)
class NodeOptions:
    build: BuildOptions = BuildOptions()
    maps: tuple | None = None
    reject: str = "sight"
    gl: bool = False            # add v5 GL nodes after each DOOM-format map
    extended: bool = False      # XNOD even where vanilla's limits hold (zdbsp -X)
    compress: bool = True       # a UDMF map's ZNODES as ZGLN (else XGLN)


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
    gl_segs: int = 0
    minisegs: int = 0


def seg_denominator(linedefs) -> int:
    """One-sided + 2 x two-sided linedefs: the segs a tree without a split would hold."""
    return int((linedefs["right"] != NO_SIDE).sum() + (linedefs["left"] != NO_SIDE).sum())


def rebuild_map(label: str, name: str, own: dict, options: NodeOptions):
    """The map's lumps in DOOM's order (``[Lump]``, after its marker: the ones the build
    does not make are ``own``'s, name -> ``Lump``) and its report."""
    started = time.perf_counter()
    m = map_data(label, name, {k: lump.data for k, lump in own.items()})
    nodes = build_nodes(m, options.build)
    new, warnings = node_lumps(nodes, nodes.own_vertexes, m.where, options.extended)
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
                       time.perf_counter() - started, new["NODES"][:4] == b"XNOD", warnings)
    if options.gl:
        gl = gl_nodes(m, nodes)
        out += gl_v5_lumps(name, gl, len(new["VERTEXES"]) // 4, new["VERTEXES"],
                           own["LINEDEFS"].data)
        report.gl_segs, report.minisegs = len(gl.segs), gl.minisegs
        report.seconds = time.perf_counter() - started
    return out, report


def rebuild_udmf_map(label: str, name: str, own: list, options: NodeOptions):
    """A UDMF map's lumps (TEXTMAP ... ENDMAP, ``[Lump]``) with new ZNODES, and its report."""
    started = time.perf_counter()
    m = map_data(label, name, {lump.name: lump.data for lump in own})
    nodes = build_nodes(m, options.build)
    gl = gl_nodes(m, nodes)
    znodes = Lump("ZNODES", znodes_lump(gl, nodes.own_vertexes, options.compress))
    out = [lump for lump in own if lump.name not in ("ZNODES", "ENDMAP")]
    out[1:1] = [znodes]                      # TEXTMAP, ZNODES, ... (ZDoom's order)
    out.append(Lump("ENDMAP", b""))
    report = MapReport(name, len(nodes.segs), len(gl.subsectors), len(nodes.nodes),
                       len(nodes.vertexes) - nodes.own_vertexes, nodes.depth,
                       len(nodes.segs) / max(1, seg_denominator(m.linedefs)),
                       time.perf_counter() - started, True, [])
    report.gl_segs, report.minisegs = len(gl.segs), gl.minisegs
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
            lumps, report = rebuild_udmf_map(label, name, own, options)
            image.replace_span(start + 1, stop, lumps)
            reports.append(report)
            continue
        by_name = {lump.name: lump for lump in own if not lump.name.startswith("GL_")}
        lumps, report = rebuild_map(label, name, by_name, options)
        image.replace_span(start + 1, stop, lumps)
        reports.append(report)
    return reports[::-1]
