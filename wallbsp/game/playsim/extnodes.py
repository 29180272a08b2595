"""ZDoom's extended nodes (``XNOD``, or zlib-compressed ``ZNOD``, in a map's NODES lump;
SEGS and SSECTORS then empty) into p_setup.c's structures, in place of P_LoadSubsectors,
P_LoadNodes and P_LoadSegs, as ZDoom's loader reads them: the format is decoded by
``nodes.readnodes``; its new vertexes (16.16) follow the map's own, a subsector's first seg
is the sum of the counts before it, a seg's sides and sectors come from its linedef as in
P_LoadSegs.  A seg's ``angle`` is its linedef's direction (turned round for side 1) and its
``offset`` the whole units from its side's start, as a vanilla SEGS lump would hold them
(only the renderer reads either).

The play simulation's node walks (``doom.nodewalks``) mark a subsector child with
NF_SUBSECTOR (0x8000), so a map of more than 32767 nodes or subsectors is refused with a
``MapLoadError``, as are nodes that do not decode or name what does not exist.
"""
import math

from wallbsp.doom.fixed import FRACBITS
from wallbsp.doom.info import NF_SUBSECTOR
from wallbsp.nodes.builder import LEAF_FLAG
from wallbsp.nodes.readnodes import read_nodes

from .mapload import MapLoadError
from .structs import Node, Seg, Subsector, Vertex


class ExtNodes:
    """Mixin: ZDoom's extended nodes for ``mapload``'s P_SetupLevel."""

    def _where(self):
        return f"map {getattr(self, 'mapname', '?')}"

    def p_load_extended_nodes(self, raw):
        where = self._where()
        own = [(v.x >> FRACBITS, v.y >> FRACBITS) for v in self.vertexes]
        try:
            nd = read_nodes(where, {"NODES": bytes(raw)}, own)
        except ValueError as err:
            raise MapLoadError(str(err)) from None
        if max(len(nd.nodes), len(nd.subsectors)) >= NF_SUBSECTOR:
            raise MapLoadError(f"{where}: NODES ({nd.kind}): {len(nd.nodes)} nodes, "
                               f"{len(nd.subsectors)} subsectors: the play simulation's "
                               f"node walks hold {NF_SUBSECTOR - 1}")
        self.vertexes = self.vertexes + [Vertex(int(x), int(y))
                                         for x, y in nd.vertexes[len(own):].tolist()]
        self.numvertexes = len(self.vertexes)
        self._extended_subsectors(nd)
        self._extended_nodes(nd, where)
        self._extended_segs(nd, where)

    def _extended_subsectors(self, nd):
        subsectors = []
        for i, (first, count) in enumerate(nd.subsectors.tolist()):
            if count == 0 or first + count > len(nd.segs):
                raise MapLoadError(f"{self._where()}: NODES: subsector {i} holds segs "
                                   f"{first}..{first + count - 1} of {len(nd.segs)}")
            ss = Subsector()
            ss.numlines, ss.firstline = count, first
            subsectors.append(ss)
        self.subsectors = subsectors
        self.numsubsectors = len(subsectors)

    def _extended_nodes(self, nd, where):
        nodes = []
        for rec in nd.nodes:
            no = Node()
            no.x, no.y, no.dx, no.dy = (int(rec[k]) for k in ("x", "y", "dx", "dy"))
            no.bbox = [[int(v) << FRACBITS for v in box] for box in rec["bbox"].tolist()]
            children = []
            for child in rec["child"].tolist():
                if child & LEAF_FLAG:
                    child = NF_SUBSECTOR | (child & ~LEAF_FLAG)
                    if child & ~NF_SUBSECTOR >= len(nd.subsectors):
                        raise MapLoadError(f"{where}: NODES: a child names subsector "
                                           f"{child & ~NF_SUBSECTOR} of {len(nd.subsectors)}")
                elif child >= len(nd.nodes):
                    raise MapLoadError(f"{where}: NODES: a child names node {child} of "
                                       f"{len(nd.nodes)}")
                children.append(child)
            no.children = children
            nodes.append(no)
        self.nodes = nodes
        self.numnodes = len(nodes)

    def _extended_segs(self, nd, where):
        segs = []
        vertexes, lines, sides = self.vertexes, self.lines, self.sides
        numsides = len(sides)
        for i, (v1, v2, linedef, side, _) in enumerate(nd.segs.tolist()):
            if max(v1, v2) >= len(vertexes) or not 0 <= linedef < len(lines) or side > 1:
                raise MapLoadError(f"{where}: NODES: seg {i} names vertex {max(v1, v2)}, "
                                   f"linedef {linedef}, side {side}: not in the map")
            li = Seg()
            li.v1, li.v2 = vertexes[v1], vertexes[v2]
            ldef = li.linedef = lines[linedef]
            sidenum = ldef.sidenum[side]
            if not 0 <= sidenum < numsides:
                raise MapLoadError(f"{where}: NODES: seg {i}: linedef {linedef} has no "
                                   f"sidedef on side {side}")
            start = ldef.v1 if side == 0 else ldef.v2
            dx, dy = ldef.v2.x - ldef.v1.x, ldef.v2.y - ldef.v1.y
            if side:
                dx, dy = -dx, -dy
            li.angle = (round(math.atan2(dy, dx) / math.tau * 65536) & 0xFFFF) << FRACBITS
            li.offset = round(math.hypot(li.v1.x - start.x, li.v1.y - start.y)
                              / (1 << FRACBITS)) << FRACBITS
            self.seg_sides(li, ldef, side, sides)
            segs.append(li)
        self.segs = segs
        self.numsegs = len(segs)
