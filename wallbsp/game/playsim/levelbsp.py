"""Our compiled tree as DOOM's nodes, subsectors and segs, and a node builder's BLOCKMAP,
for ``levelmap`` (this mixin's ``_level_bsp`` and ``_level_blockmap``).

- **Segs.**  Our tree keeps the segs on a partition line in the node; DOOM keeps them in
  the leaves (subsectors), one seg per side of a line per subsector it bounds.  So each of
  a node's segs is pushed down the subtree on the wall's front side (and, for a two-sided
  wall, down the one on its back), split exactly wherever a partition line of that subtree
  crosses it; each piece that reaches a leaf is a seg of that leaf's subsector (side 0 for
  the front, 1 for the back, running v1 → v2 on the front and v2 → v1 on the back,
  ``offset`` the distance from the side's start along the line, ``angle`` the direction in
  a SEGS lump's 16-bit precision).  Split points become vertexes (rounded to fixed point)
  appended after the level's, as a node builder appends its own.
- **Nodes** are numbered children first, so the root is the last node (DOOM's head
  node); ``children[0]`` is the front (our child 0, the right of the partition line), a
  leaf is ``NF_SUBSECTOR | subsector``, subsectors numbered in the walk's order.  A node's
  partition is a wall's end on its line and the direction ``(b, -a)`` scaled up to DOOM's
  size (up to 32767 units, as far as the map's size allows without overflow in
  R_PointOnSide), so R_PointOnSide and P_DivlineSide decide sides with DOOM's precision.
  A node's ``bbox`` per child is its subtree's segs' box (the whole map for a subtree
  without segs).
- **Subsectors' sectors** are the tree's leaf sectors (a leaf that no seg bounds has its
  sector too); a leaf outside the map gets the sector in front of a wall it lies behind,
  as a point outside a DOOM map lands in some nearby subsector.
- **BLOCKMAP** as DOOM's node builders make it: 128-unit blocks from the lowest x and y
  of the walls' ends, ``((max - min) >> 7) + 1`` blocks each way; each block lists, after
  a leading 0 and in line order, every line that touches the block (closed squares, exact
  integer tests), ending with -1; the lump's header is origin, width, height, then one
  offset a block (plain ints: no 16-bit wrap).

DOOM's limits hold: fewer than 32768 nodes and subsectors (``NF_SUBSECTOR``), a
``LevelMapError`` otherwise.
"""
import math

from wallbsp.doom.fixed import FRACBITS, FRACUNIT
from wallbsp.doom.info import ML_TWOSIDED, NF_SUBSECTOR

from .structs import Node, Seg, Subsector, Vertex

BOXTOP, BOXBOTTOM, BOXLEFT, BOXRIGHT = range(4)
MAX_PARTITION = 32767               # a node's dx, dy in map units (a mapnode_t's shorts)


class LevelMapError(ValueError):
    """A level that DOOM's structures cannot hold (coordinates or tree beyond its limits)."""


class LevelBsp:
    """Mixin: the BSP and blockmap halves of ``levelmap``."""

    # ---- BLOCKMAP -------------------------------------------------------------------------
    def _level_blockmap(self, level):
        """A node builder's BLOCKMAP (module docstring) as ``mapload`` keeps the lump."""
        verts = level.vertices
        used = {v for w in level.walls for v in (w.v1, w.v2)}
        xs = [verts[v][0] for v in used]
        ys = [verts[v][1] for v in used]
        orgx, orgy = min(xs), min(ys)
        width = ((max(xs) - orgx) >> 7) + 1
        height = ((max(ys) - orgy) >> 7) + 1
        blocks = [[] for _ in range(width * height)]
        for i, wall in enumerate(level.walls):
            (x1, y1), (x2, y2) = verts[wall.v1], verts[wall.v2]
            x1 -= orgx
            x2 -= orgx
            y1 -= orgy
            y2 -= orgy
            dx, dy = x2 - x1, y2 - y1
            # the blocks whose closed squares the line's box touches
            bx0 = max(0, (min(x1, x2) - 1) >> 7)
            bx1 = min(width - 1, max(x1, x2) >> 7)
            by0 = max(0, (min(y1, y2) - 1) >> 7)
            by1 = min(height - 1, max(y1, y2) >> 7)
            axis = dx == 0 or dy == 0
            for by in range(by0, by1 + 1):
                ly, hy = by << 7, (by + 1) << 7
                row = by * width
                for bx in range(bx0, bx1 + 1):
                    if not axis:
                        lx, hx = bx << 7, (bx + 1) << 7
                        # the square's corners all strictly on one side: not touched
                        c1 = dx * (ly - y1) - dy * (lx - x1)
                        c2 = dx * (ly - y1) - dy * (hx - x1)
                        c3 = dx * (hy - y1) - dy * (lx - x1)
                        c4 = dx * (hy - y1) - dy * (hx - x1)
                        if (c1 > 0 and c2 > 0 and c3 > 0 and c4 > 0) or \
                                (c1 < 0 and c2 < 0 and c3 < 0 and c4 < 0):
                            continue
                    blocks[row + bx].append(i)
        lump = [orgx, orgy, width, height]
        offset = 4 + len(blocks)
        offsets = []
        body = []
        for block in blocks:
            offsets.append(offset + len(body))
            body.append(0)
            body.extend(block)
            body.append(-1)
        self.blockmaplump = lump + offsets + body
        self.blockmap = 4
        self.bmaporgx, self.bmaporgy = orgx << FRACBITS, orgy << FRACBITS
        self.bmapwidth, self.bmapheight = width, height
        self.blocklinks = [None] * (width * height)

    # ---- the BSP -------------------------------------------------------------------------
    def _level_bsp(self, level, tree):
        """Nodes, subsectors and segs from the compiled tree (module docstring)."""
        node_line = tree.node_line.tolist()
        node_child = tree.node_child.tolist()
        node_segs = tree.node_segs.tolist()
        leaf_sector = tree.leaf_sector.tolist()
        seg_wall = tree.seg_wall.tolist()
        seg_flip = tree.seg_flip.tolist()
        seg_t = tree.seg_t.tolist()
        verts = level.vertices
        walls = level.walls
        nleaves = len(leaf_sector)
        if len(node_line) >= NF_SUBSECTOR or nleaves > NF_SUBSECTOR:
            raise LevelMapError(f"{level.source}: {len(node_line)} nodes and {nleaves} "
                                f"leaves: more than DOOM's nodes can number "
                                f"({NF_SUBSECTOR - 1})")
        ends = [(verts[w.v1], verts[w.v2]) for w in walls]

        # every seg of every node down its wall's side(s) to the leaves
        pieces = [[] for _ in range(nleaves)]          # leaf -> [(wall, side, t0, t1)]
        void_sector = [None] * nleaves
        for node, (start, stop) in enumerate(node_segs):
            front_child, back_child = node_child[node]
            for s in range(start, stop):
                w = seg_wall[s]
                wall = walls[w]
                n0, d0, n1, d1 = seg_t[s]
                near, far = (back_child, front_child) if seg_flip[s] else \
                    (front_child, back_child)
                for leaf, t0, t1 in _push(node_line, node_child, ends[w], near, n0, d0, n1, d1):
                    pieces[leaf].append((w, 0, t0, t1))
                for leaf, t0, t1 in _push(node_line, node_child, ends[w], far, n0, d0, n1, d1):
                    if wall.back is not None:
                        pieces[leaf].append((w, 1, t0, t1))
                    elif void_sector[leaf] is None:
                        void_sector[leaf] = wall.front

        # nodes children first (the root last), leaves numbered as the walk meets them
        node_num, leaf_num, order, leaves = {}, {}, [], []
        if tree.root >= 0:
            stack = [(tree.root, False)]
            while stack:
                item, expanded = stack.pop()
                if item < 0:
                    leaf_num[~item] = len(leaves)
                    leaves.append(~item)
                elif expanded:
                    node_num[item] = len(order)
                    order.append(item)
                else:
                    stack.append((item, True))
                    stack.append((node_child[item][1], False))
                    stack.append((node_child[item][0], False))
        else:
            leaf_num[~tree.root] = 0
            leaves.append(~tree.root)

        # the segs, subsector by subsector
        vertexes = self.vertexes
        split_vertexes = {}
        lines, sides = self.lines, self.sides
        segs, subsectors, sectors_of = [], [], []
        leaf_box = []
        for leaf in leaves:
            ss = Subsector()
            ss.firstline = len(segs)
            box = None
            for w, side, t0, t1 in pieces[leaf]:
                ld = lines[w]
                (x1, y1), (x2, y2) = ends[w]
                a = _vertex(vertexes, split_vertexes, ld.v1, ld.v2, x1, y1, x2, y2, t0)
                b = _vertex(vertexes, split_vertexes, ld.v1, ld.v2, x1, y1, x2, y2, t1)
                li = Seg()
                length = math.hypot(x2 - x1, y2 - y1)
                if side == 0:
                    li.v1, li.v2 = a, b
                    along = t0[0] / t0[1]
                    li.angle = _bam16(x2 - x1, y2 - y1)
                else:
                    li.v1, li.v2 = b, a
                    along = 1 - t1[0] / t1[1]
                    li.angle = _bam16(x1 - x2, y1 - y2)
                li.offset = round(along * length * FRACUNIT)
                li.linedef = ld
                li.sidedef = sides[ld.sidenum[side]]
                li.frontsector = li.sidedef.sector
                li.backsector = sides[ld.sidenum[side ^ 1]].sector \
                    if ld.flags & ML_TWOSIDED else None
                segs.append(li)
                for v in (a, b):
                    box = _grow(box, v.x, v.y)
            ss.numlines = len(segs) - ss.firstline
            subsectors.append(ss)
            leaf_box.append(box)
            sector = leaf_sector[leaf]
            if sector < 0:
                sector = void_sector[leaf]
                if sector is None:
                    sector = walls[pieces[leaf][0][0]].front if pieces[leaf] else 0
            sectors_of.append(sector)
        for ss in subsectors:                       # P_GroupLines reads segs[firstline]
            if not ss.numlines:
                ss.firstline = min(ss.firstline, len(segs) - 1)
        self.vertexes = vertexes
        self.segs, self.numsegs = segs, len(segs)
        self.subsectors, self.numsubsectors = subsectors, len(subsectors)
        self._subsector_sectors = sectors_of

        # the nodes: partition, children, the children's boxes
        xs = [p[0] for p in verts]
        ys = [p[1] for p in verts]
        span = max(max(xs) - min(xs), max(ys) - min(ys), 1)
        limit = max(1, min(MAX_PARTITION, 0x7FFFFFFF // (2 * span)))
        whole = [max(ys) << FRACBITS, min(ys) << FRACBITS, min(xs) << FRACBITS,
                 max(xs) << FRACBITS]
        subtree_box = {}
        nodes = []
        for node in order:
            a, b, c = node_line[node]
            no = Node()
            first = node_segs[node][0]
            px, py = ends[seg_wall[first]][0]          # a wall's end: a point on the line
            k = max(1, limit // max(abs(a), abs(b)))
            no.x, no.y = px << FRACBITS, py << FRACBITS
            no.dx, no.dy = (b * k) << FRACBITS, (-a * k) << FRACBITS
            children, boxes = [], []
            for child in node_child[node]:
                if child < 0:
                    children.append(NF_SUBSECTOR | leaf_num[~child])
                    box = leaf_box[leaf_num[~child]]
                else:
                    children.append(node_num[child])
                    box = subtree_box[child]
                boxes.append(box)
            merged = None
            for box in boxes:
                if box is not None:
                    merged = _grow(_grow(merged, box[BOXLEFT], box[BOXBOTTOM]),
                                   box[BOXRIGHT], box[BOXTOP])
            subtree_box[node] = merged
            no.children = children
            no.bbox = [list(box) if box is not None else list(whole) for box in boxes]
            nodes.append(no)
        self.nodes, self.numnodes = nodes, len(nodes)


# ---- helpers ---------------------------------------------------------------------------------

def _push(node_line, node_child, wall_ends, item, n0, d0, n1, d1):
    """The pieces ``(leaf, (n, d), (n, d))`` of the wall's part ``[n0/d0, n1/d1]`` in the
    subtree ``item``, split exactly where the subtree's partition lines cross it."""
    (x1, y1), (x2, y2) = wall_ends
    out = []
    stack = [(item, n0, d0, n1, d1)]
    while stack:
        item, n0, d0, n1, d1 = stack.pop()
        if item < 0:
            out.append((~item, (n0, d0), (n1, d1)))
            continue
        a, b, c = node_line[item]
        s1 = a * x1 + b * y1 + c
        ds = a * x2 + b * y2 + c - s1
        e0 = s1 * d0 + ds * n0           # sign of the side at t0 (d0 > 0)
        e1 = s1 * d1 + ds * n1
        front, back = node_child[item]
        if e0 <= 0 and e1 <= 0:            # (both 0, on the line, cannot happen: the
            stack.append((front, n0, d0, n1, d1))   # compiler merges collinear segs)
        elif e0 >= 0 and e1 >= 0:
            stack.append((back, n0, d0, n1, d1))
        else:
            # s(t) = s1 + t ds = 0 at t = -s1 / ds
            nm, dm = -s1, ds
            if dm < 0:
                nm, dm = -nm, -dm
            g = math.gcd(nm, dm)
            nm, dm = nm // g, dm // g
            first, second = (front, back) if e0 < 0 else (back, front)
            stack.append((first, n0, d0, nm, dm))
            stack.append((second, nm, dm, n1, d1))
    return out


def _vertex(vertexes, split, v1, v2, x1, y1, x2, y2, t):
    """The Vertex at parameter ``t = (n, d)`` of the line v1 → v2: the line's own at its
    ends, else one split vertex per fixed-point point (appended to ``vertexes``)."""
    n, d = t
    if n == 0:
        return v1
    if n == d:
        return v2
    fx = _round_div((x1 * d + n * (x2 - x1)) << FRACBITS, d)
    fy = _round_div((y1 * d + n * (y2 - y1)) << FRACBITS, d)
    v = split.get((fx, fy))
    if v is None:
        v = split[(fx, fy)] = Vertex(fx, fy)
        vertexes.append(v)
    return v


def _round_div(num, den):
    return (2 * num + den) // (2 * den)


def _bam16(dx, dy):
    """The direction's binary angle as a SEGS lump holds it (16 bits, shifted up)."""
    turns = math.atan2(dy, dx) / (2 * math.pi)
    return (round(turns * 65536) & 0xFFFF) << FRACBITS


def _grow(box, x, y):
    """``[top, bottom, left, right]`` grown to hold (x, y) (None: empty)."""
    if box is None:
        return [y, y, x, x]
    if y > box[BOXTOP]:
        box[BOXTOP] = y
    if y < box[BOXBOTTOM]:
        box[BOXBOTTOM] = y
    if x < box[BOXLEFT]:
        box[BOXLEFT] = x
    if x > box[BOXRIGHT]:
        box[BOXRIGHT] = x
    return box
