"""``p_setup.c``: a map's lumps from a WAD into DOOM's structures (vertexes, sectors,
sides, lines, subsectors, nodes, segs, the blockmap and the reject matrix, then
P_GroupLines) and the map's things handed to P_SpawnMapThing.  A NODES lump holding
ZDoom's extended nodes (XNOD, ZNOD) is read by ``extnodes`` instead of SSECTORS, NODES and
SEGS.  ``r_main.c``'s
R_PointOnSide / R_PointInSubsector, which walk the map's own BSP nodes, are in the base
class ``BspTables`` (``bsptables.py``).

Per-level state (``init_mapload``, C's globals of p_setup.c): ``vertexes``, ``sectors``,
``sides``, ``lines``, ``subsectors``, ``nodes``, ``segs`` (lists of ``structs`` objects,
with ``numvertexes``, ``numsectors``, ... their lengths), ``blockmaplump`` (the BLOCKMAP
lump as a list of signed 16-bit ints, as Chocolate Doom's ``short *`` reads it),
``blockmap`` (the index in ``blockmaplump`` where C's ``blockmap`` pointer points: 4, past
the header), ``bmaporgx``/``bmaporgy`` (fixed point), ``bmapwidth``/``bmapheight``,
``blocklinks`` (one ``None``-or-first-mobj a block), ``rejectmatrix`` (bytes, padded as
Chocolate Doom pads a short REJECT), ``totallines``, ``maplumps`` (the map's raw lumps by
``info.ML_*`` index, for P_LoadThings).

Textures and flats are kept as their upper-case names (R_TextureNumForName and
R_FlatNumForName compare names case-insensitively).
"""
import struct

from wallbsp.doom import info
from wallbsp.doom.fixed import FRACBITS, MAXINT, MININT, c_div, fixed_div, wrap32

from .bsptables import BspTables
from .structs import (COMMERCIAL, ST_HORIZONTAL, ST_NEGATIVE, ST_POSITIVE, ST_VERTICAL, Line,
                      MapThing, Node, Sector, Seg, Side, Subsector, Vertex)
from wallbsp.doom.info import MAPBLOCKSHIFT, MAXRADIUS

BOXTOP, BOXBOTTOM, BOXLEFT, BOXRIGHT = range(4)
MAXPLAYERS = 4

# the map lumps' records (doomdata.h), all little-endian
MAPVERTEX = struct.Struct("<2h")
MAPSECTOR = struct.Struct("<2h8s8s3h")
MAPSIDEDEF = struct.Struct("<2h8s8s8sh")
MAPLINEDEF = struct.Struct("<7h")
MAPSUBSECTOR = struct.Struct("<2h")
MAPNODE = struct.Struct("<12h2H")          # children are unsigned short in mapnode_t
MAPSEG = struct.Struct("<6h")
MAPTHING = struct.Struct("<5h")

# Doom II's monsters: an executable of another game mode stops reading THINGS at the first
# (arachnotron, arch-vile, boss brain, boss shooter, hell knight, mancubus, pain elemental,
# chaingunner, revenant, Wolfenstein SS)
DOOM2_ONLY = frozenset((68, 64, 88, 89, 69, 67, 71, 65, 66, 84))

# what Chocolate Doom reads at address 0 for a NULL sector (its default DOS 6.22 dump)
_NULL_SECTOR_FLOOR, _NULL_SECTOR_CEILING = 0x00199257, 0x007006F4
# vanilla's REJECT overrun read the zone allocator's next block header: its words
_REJECTPAD_ZONE = (0, 50, 0x1D4A11)        # block header word, PU_LEVEL, ZONEID


def set_line_ends(ld, v1, v2):
    """P_LoadLineDefs' geometry of a line from its two vertexes: ``dx``, ``dy`` (32-bit, as
    C's sums), the slope type and the bounding box."""
    ld.v1, ld.v2 = v1, v2
    ld.dx = wrap32(v2.x - v1.x)
    ld.dy = wrap32(v2.y - v1.y)
    if not ld.dx:
        ld.slopetype = ST_VERTICAL
    elif not ld.dy:
        ld.slopetype = ST_HORIZONTAL
    elif fixed_div(ld.dy, ld.dx) > 0:
        ld.slopetype = ST_POSITIVE
    else:
        ld.slopetype = ST_NEGATIVE
    box = ld.bbox
    box[BOXLEFT], box[BOXRIGHT] = (v1.x, v2.x) if v1.x < v2.x else (v2.x, v1.x)
    box[BOXBOTTOM], box[BOXTOP] = (v1.y, v2.y) if v1.y < v2.y else (v2.y, v1.y)


class MapLoadError(ValueError):
    """A WAD or map that DOOM could not load (I_Error's cases)."""


def _records(raw, record):
    """The lump's whole records (DOOM ignores a partial last one: W_LumpLength / size)."""
    n = len(raw) // record.size
    return [record.unpack_from(raw, i * record.size) for i in range(n)]


def _name8(raw):
    return raw.split(b"\0", 1)[0].decode("latin-1").upper()


def wad_directory(data):
    """The WAD's lumps as (name, offset, size), in directory order."""
    if len(data) < 12 or data[:4] not in (b"IWAD", b"PWAD"):
        raise MapLoadError("not a WAD (bad header)")
    count, offset = struct.unpack_from("<ii", data, 4)
    if count < 0 or offset < 12 or offset + 16 * count > len(data):
        raise MapLoadError(f"WAD directory of {count} entries at {offset} runs past the end")
    entries = []
    for i in range(count):
        pos, size, name = struct.unpack_from("<ii8s", data, offset + 16 * i)
        if pos < 0 or size < 0 or pos + size > len(data):
            raise MapLoadError(f"lump {i} ({_name8(name)}) lies outside the WAD")
        entries.append((_name8(name), pos, size))
    return entries


def read_map_lumps(wad_path_or_bytes, lumpname):
    """The map's marker and the ten lumps after it (THINGS ... BLOCKMAP) by ``ML_*``
    index: the last lump called ``lumpname`` (W_GetNumForName) plus fixed offsets, as
    P_SetupLevel takes them (it does not check their names)."""
    data = wad_path_or_bytes
    if not isinstance(data, (bytes, bytearray, memoryview)):
        with open(wad_path_or_bytes, "rb") as f:
            data = f.read()
    data = bytes(data)
    entries = wad_directory(data)
    lumpname = lumpname.upper()
    found = [i for i, (name, _, _) in enumerate(entries) if name == lumpname]
    if not found:
        raise MapLoadError(f"W_GetNumForName: {lumpname} not found!")
    start = found[-1]
    if start + info.ML_BLOCKMAP >= len(entries):
        raise MapLoadError(f"map {lumpname}: the WAD ends before its BLOCKMAP lump")
    return [data[pos:pos + size] for _, pos, size in entries[start:start + info.ML_BLOCKMAP + 1]]


def pad_reject(length, totallines):
    """Chocolate Doom's PadRejectArray: the ``length`` bytes vanilla read past a short
    REJECT lump -- the zone block header that followed it, then zeros."""
    words = (((totallines * 4 + 3) & ~3) + 24,) + _REJECTPAD_ZONE
    pad = b"".join(struct.pack("<I", w) for w in words)
    return pad[:length] + bytes(max(0, length - len(pad)))


class MapLoad(BspTables):
    """Mixin: p_setup.c and R_PointInSubsector."""

    def init_mapload(self):
        self.vertexes, self.sectors, self.sides, self.lines = [], [], [], []
        self.subsectors, self.nodes, self.segs = [], [], []
        self.numvertexes = self.numsectors = self.numsides = self.numlines = 0
        self.numsubsectors = self.numnodes = self.numsegs = 0
        self.blockmaplump, self.blockmap, self.blocklinks = [], 4, []
        self.bmaporgx = self.bmaporgy = self.bmapwidth = self.bmapheight = 0
        self.rejectmatrix = b""
        self.totallines = 0
        self.maplumps = []
        self.null_sector = None

    # ---- the level ----------------------------------------------------------------------

    def p_setup_level_geometry(self, wad_path_or_bytes, lumpname=None):
        """P_SetupLevel's loading of map ``lumpname`` (``"E1M4"``, ``"MAP15"``), in its
        order: blockmap, vertexes, sectors, sides, lines, subsectors, nodes, segs, then
        P_GroupLines and the reject matrix.  Called with the lump name alone, the WAD is
        ``self.wad_path``."""
        if lumpname is None:
            wad_path_or_bytes, lumpname = self.wad_path, wad_path_or_bytes
        lumps = self.maplumps = read_map_lumps(wad_path_or_bytes, lumpname)
        self.p_load_block_map(lumps[info.ML_BLOCKMAP])
        self.p_load_vertexes(lumps[info.ML_VERTEXES])
        self.p_load_sectors(lumps[info.ML_SECTORS])
        self.p_load_side_defs(lumps[info.ML_SIDEDEFS])
        self.p_load_line_defs(lumps[info.ML_LINEDEFS])
        if lumps[info.ML_NODES][:4] in (b"XNOD", b"ZNOD"):     # ZDoom's (``extnodes``)
            self.p_load_extended_nodes(lumps[info.ML_NODES])
        else:
            self.p_load_subsectors(lumps[info.ML_SSECTORS])
            self.p_load_nodes(lumps[info.ML_NODES])
            self.p_load_segs(lumps[info.ML_SEGS])
        self.p_group_lines()
        self.p_load_reject(lumps[info.ML_REJECT])

    def p_load_vertexes(self, raw):
        self.vertexes = [Vertex(x << FRACBITS, y << FRACBITS)
                         for x, y in _records(raw, MAPVERTEX)]
        self.numvertexes = len(self.vertexes)

    def p_load_sectors(self, raw):
        sectors = []
        for i, (floor, ceiling, floorpic, ceilingpic, light, special, tag) in \
                enumerate(_records(raw, MAPSECTOR)):
            s = Sector(i)
            s.floorheight = floor << FRACBITS
            s.ceilingheight = ceiling << FRACBITS
            s.floorpic = _name8(floorpic)
            s.ceilingpic = _name8(ceilingpic)
            s.lightlevel, s.special, s.tag = light, special, tag
            sectors.append(s)
        self.sectors = sectors
        self.numsectors = len(sectors)

    def p_load_side_defs(self, raw):
        sides = []
        for i, (xoff, yoff, top, bottom, mid, sector) in enumerate(_records(raw, MAPSIDEDEF)):
            sd = Side(i)
            sd.textureoffset = xoff << FRACBITS
            sd.rowoffset = yoff << FRACBITS
            sd.toptexture, sd.bottomtexture, sd.midtexture = _name8(top), _name8(bottom), \
                _name8(mid)
            sd.sector = self.sectors[sector]
            sides.append(sd)
        self.sides = sides
        self.numsides = len(sides)

    def p_load_line_defs(self, raw):
        """Lines with their slope type, bounding box and sectors (sidenum -1: none)."""
        lines = []
        vertexes, sides = self.vertexes, self.sides
        for i, (v1, v2, flags, special, tag, side0, side1) in \
                enumerate(_records(raw, MAPLINEDEF)):
            ld = Line(i)
            ld.flags, ld.special, ld.tag = flags, special, tag
            set_line_ends(ld, vertexes[v1], vertexes[v2])
            ld.sidenum = [side0, side1]
            ld.frontsector = sides[side0].sector if side0 != -1 else None
            ld.backsector = sides[side1].sector if side1 != -1 else None
            lines.append(ld)
        self.lines = lines
        self.numlines = len(lines)

    def p_load_subsectors(self, raw):
        subsectors = []
        for numsegs, firstseg in _records(raw, MAPSUBSECTOR):
            ss = Subsector()
            ss.numlines, ss.firstline = numsegs, firstseg
            subsectors.append(ss)
        self.subsectors = subsectors
        self.numsubsectors = len(subsectors)

    def p_load_nodes(self, raw):
        nodes = []
        for rec in _records(raw, MAPNODE):
            no = Node()
            no.x, no.y, no.dx, no.dy = (v << FRACBITS for v in rec[:4])
            no.bbox = [[v << FRACBITS for v in rec[4:8]], [v << FRACBITS for v in rec[8:12]]]
            no.children = [rec[12], rec[13]]
            nodes.append(no)
        self.nodes = nodes
        self.numnodes = len(nodes)

    def p_load_segs(self, raw):
        segs = []
        vertexes, lines, sides = self.vertexes, self.lines, self.sides
        numsides = len(sides)
        for i, (v1, v2, angle, linedef, side, offset) in enumerate(_records(raw, MAPSEG)):
            li = Seg()
            li.v1, li.v2 = vertexes[v1], vertexes[v2]
            li.angle = (angle << FRACBITS) & 0xFFFFFFFF
            li.offset = offset << FRACBITS
            ldef = li.linedef = lines[linedef]
            sidenum = ldef.sidenum[side]
            if not 0 <= sidenum < numsides:        # e6y's check, kept by Chocolate Doom
                raise MapLoadError(f"P_LoadSegs: linedef {linedef} for seg {i} references "
                                   f"a non-existent sidedef {sidenum & 0xFFFFFFFF}")
            self.seg_sides(li, ldef, side, sides)
            segs.append(li)
        self.segs = segs
        self.numsegs = len(segs)

    def seg_sides(self, li, ldef, side, sides):
        """The seg's sidedef and the sectors in front of it and behind it (P_LoadSegs)."""
        sidenum = ldef.sidenum[side]
        li.sidedef = sides[sidenum]
        li.frontsector = sides[sidenum].sector
        if ldef.flags & info.ML_TWOSIDED:
            back = ldef.sidenum[side ^ 1]
            # a "glass hack" one-sided window: vanilla read a sector at address 0
            li.backsector = sides[back].sector if 0 <= back < len(sides) \
                else self._null_sector()
        else:
            li.backsector = None

    def _null_sector(self):
        """GetSectorAtNullAddress: one sector a level, its heights what DOS held there."""
        null = self.null_sector
        if null is None:
            null = self.null_sector = Sector(-1)
            null.floorheight, null.ceilingheight = _NULL_SECTOR_FLOOR, _NULL_SECTOR_CEILING
            null.floorpic = null.ceilingpic = ""
        return null

    def p_load_block_map(self, raw):
        """The BLOCKMAP lump as Chocolate Doom keeps it: every word a signed short (so
        offsets past 32767 go negative, as in vanilla), the header's origin in fixed
        point, and an empty thing chain for each block."""
        count = len(raw) // 2
        lump = self.blockmaplump = list(struct.unpack_from("<%dh" % count, raw))
        if count < 4:
            raise MapLoadError(f"BLOCKMAP of {len(raw)} bytes has no header")
        self.blockmap = 4
        self.bmaporgx = lump[0] << FRACBITS
        self.bmaporgy = lump[1] << FRACBITS
        self.bmapwidth = lump[2]
        self.bmapheight = lump[3]
        self.blocklinks = [None] * max(0, self.bmapwidth * self.bmapheight)

    def p_group_lines(self):
        """Each subsector's sector, each sector's lines (line order, a line once even if
        both its sides face the sector), the sound origin at the middle of the lines'
        box and that box in blocks, grown by MAXRADIUS."""
        segs = self.segs
        for ss in self.subsectors:
            ss.sector = segs[ss.firstline].sidedef.sector
        total = 0
        for li in self.lines:
            total += 1
            li.frontsector.linecount += 1
            if li.backsector is not None and li.backsector is not li.frontsector:
                li.backsector.linecount += 1
                total += 1
        self.totallines = total
        for sector in self.sectors:
            sector.lines = []
            sector.linecount = 0
        for li in self.lines:
            if li.frontsector is not None:
                li.frontsector.lines.append(li)
                li.frontsector.linecount += 1
            if li.backsector is not None and li.frontsector is not li.backsector:
                li.backsector.lines.append(li)
                li.backsector.linecount += 1
        for sector in self.sectors:
            self._sector_boxes(sector)

    def _sector_boxes(self, sector):
        bbox = [MININT, MAXINT, MAXINT, MININT]       # M_ClearBox
        for li in sector.lines:
            _add_to_box(bbox, li.v1.x, li.v1.y)
            _add_to_box(bbox, li.v2.x, li.v2.y)
        sector.soundorg.x = c_div(wrap32(bbox[BOXRIGHT] + bbox[BOXLEFT]), 2)
        sector.soundorg.y = c_div(wrap32(bbox[BOXTOP] + bbox[BOXBOTTOM]), 2)
        box = sector.blockbox
        block = wrap32(bbox[BOXTOP] - self.bmaporgy + MAXRADIUS) >> MAPBLOCKSHIFT
        box[BOXTOP] = self.bmapheight - 1 if block >= self.bmapheight else block
        block = wrap32(bbox[BOXBOTTOM] - self.bmaporgy - MAXRADIUS) >> MAPBLOCKSHIFT
        box[BOXBOTTOM] = 0 if block < 0 else block
        block = wrap32(bbox[BOXRIGHT] - self.bmaporgx + MAXRADIUS) >> MAPBLOCKSHIFT
        box[BOXRIGHT] = self.bmapwidth - 1 if block >= self.bmapwidth else block
        block = wrap32(bbox[BOXLEFT] - self.bmaporgx - MAXRADIUS) >> MAPBLOCKSHIFT
        box[BOXLEFT] = 0 if block < 0 else block

    def p_load_reject(self, raw):
        """The REJECT lump; a short one is padded with what vanilla read past its end."""
        minlength = (self.numsectors * self.numsectors + 7) // 8
        if len(raw) >= minlength:
            self.rejectmatrix = bytes(raw)
        else:
            self.rejectmatrix = bytes(raw) + pad_reject(minlength - len(raw), self.totallines)

    # ---- things -------------------------------------------------------------------------

    def p_load_things(self):
        """P_LoadThings: each THINGS entry, in order, to P_SpawnMapThing -- except that an
        executable not of Doom II's mode stops at the first Doom II monster (vanilla's
        ``break``: the rest of the list is lost too).  Then every player in the game must
        have had a start (unless deathmatch)."""
        for x, y, angle, type_, options in _records(self.maplumps[info.ML_THINGS], MAPTHING):
            if self.gamemode != COMMERCIAL and type_ in DOOM2_ONLY:
                break
            self.p_spawn_map_thing(MapThing(x, y, angle, type_, options))
        if not self.deathmatch:
            for i in range(MAXPLAYERS):
                if self.playeringame[i] and not self.playerstartsingame[i]:
                    raise MapLoadError(f"P_LoadThings: Player {i + 1} start missing "
                                       f"(vanilla crashes here)")
                self.playerstartsingame[i] = False


def _add_to_box(box, x, y):
    """M_AddToBox, with its ``else if``: a point that lowers the left edge is not also
    tested against the right one (so the first point only sets left and bottom)."""
    if x < box[BOXLEFT]:
        box[BOXLEFT] = x
    elif x > box[BOXRIGHT]:
        box[BOXRIGHT] = x
    if y < box[BOXBOTTOM]:
        box[BOXBOTTOM] = y
    elif y > box[BOXTOP]:
        box[BOXTOP] = y
