"""Our own levels (SPEC §2, §2b) as DOOM's map structures: what ``mapload`` reads from a
WAD's map lumps, made from a ``Level`` and its compiled ``BSPTree``, so that the whole play
simulation runs on JSON levels as on Freedoom's maps.

``p_setup_level_from(level, tree)`` fills exactly the per-level attributes ``mapload``
fills (``vertexes``, ``sectors``, ``sides``, ``lines``, ``subsectors``, ``nodes``,
``segs`` and their ``num*`` counts, ``blockmaplump``/``blockmap``/``bmaporgx``/
``bmaporgy``/``bmapwidth``/``bmapheight``/``blocklinks``, ``rejectmatrix``,
``totallines``; ``maplumps`` is empty), then runs P_GroupLines.  ``p_load_level_things``
is P_LoadThings for the level's ``things`` and ``start``.  ``g_init_new_level(level,
tree, skill)`` starts a game on the level through ``game.py``'s own sequence (G_InitNew,
G_DoLoadLevel, P_SetupLevel: ``self.levelsource`` tells P_SetupLevel to load from here);
``start_level(level, tree, skill)`` makes the ``Play`` and does that.

How a level becomes a DOOM map:

- **Vertexes** are the level's vertices (index for index; |x|, |y| ≤ 32767, as DOOM's
  fixed point needs), followed by the points where the compiler split walls (rounded to
  fixed point), as a node builder appends its split vertices.
- **Sectors** keep their index: heights × 65536 (rounded, for float heights), ``light``,
  ``special``, ``tag``; flats are ``floor_texture``/``ceiling_texture`` (upper case),
  and where a level names none (every version-1 level) the sector's colour in upper case
  (``"#5A4A3A"``), so sectors that look alike share a "flat" (stairs follow equal floor
  flats) and none is the sky by accident; a sector marked ``sky`` gets ``F_SKY1``.
- **Lines** are the walls, index for index, from ``v1`` to ``v2``: the wall's front side
  is on the right of v1 → v2 (SPEC §2), which is DOOM's right sidedef, so ``sidenum[0]``
  is the front side and ``sidenum[1]`` the back (-1 for a one-sided wall).  Flags:
  ML_TWOSIDED for a wall with a ``back``; ML_BLOCKING for ``blocks`` and, as map editors
  set it, for every one-sided wall; ML_DONTPEGTOP/ML_DONTPEGBOTTOM for
  ``upper_unpegged``/``lower_unpegged``; ML_SECRET, ML_SOUNDBLOCK, ML_DONTDRAW for ``secret``,
  ``blocks_sound``, ``hidden``.  ``special`` and ``tag`` are the wall's.
- **Sides**: wall ``i``'s front side, then its back side if it has one, in wall order; the
  textures (upper → top, middle → mid, lower → bottom) in upper case, ``"-"`` where the
  level names none (every version-1 wall); offsets × 65536.
- **Nodes, subsectors, segs** from the compiled tree and the **BLOCKMAP** as a node
  builder makes it: ``levelbsp.py`` (its docstring says how).
- **REJECT**: all zeros (every sector may see every other).

Things: the level's ``things`` in order, as THINGS entries (editor numbers, flags,
angle in degrees); a type DOOM does not know (a level's own ``thing_types``) is left out
rather than stopping the level as vanilla's I_Error would.  The player: if ``things``
holds no player-1 start, the level's ``start`` (rounded to whole map units) is spawned
first, and the player faces the start's exact angle (DOOM would round a THINGS angle down
to 45°).  If it holds one, the things alone place the player, as in DOOM.
"""
from __future__ import annotations

from wallbsp.doom.fixed import FRACBITS, FRACUNIT
from wallbsp.doom.info import ML_BLOCKING, ML_DONTPEGBOTTOM, ML_DONTPEGTOP, ML_TWOSIDED, NF_SUBSECTOR

from .levelbsp import LevelMapError
from .mapload import set_line_ends
from .structs import COMMERCIAL, EXE_DOOM_1_9, Line, MapThing, Sector, Side, Vertex

__all__ = ["LevelMap", "LevelMapError", "start_level", "ML_BLOCKING", "ML_TWOSIDED",
           "NF_SUBSECTOR"]

SKY_FLAT = "F_SKY1"
MAX_COORD = 32767                   # DOOM's map units: a fixed_t holds ±32768
MAXPLAYERS = 4
PLAYER_STARTS = frozenset((1, 2, 3, 4, 11))


class LevelMap:
    """Mixin: our levels as p_setup.c's structures (see the module docstring)."""

    # ---- the game ---------------------------------------------------------------------------
    def g_init_new_level(self, level, tree, skill=2):
        """G_InitNew on one of our levels: a single-player game at ``skill`` (DOOM's 0-4,
        sk_baby .. sk_nightmare) of ``level`` compiled as ``tree``.  Without a WAD the game
        is Doom II's (v1.9), so every monster and switch of the levels exists."""
        self.levelsource = (level, tree)
        if getattr(self, "wad_path", None) is None:
            self.gamemode, self.gameversion = COMMERCIAL, EXE_DOOM_1_9
        if not any(self.playeringame):
            self.playeringame = [True] + [False] * (MAXPLAYERS - 1)
            self.consoleplayer = 0
        self.g_init_new(skill, 1, 1)

    # ---- the map ------------------------------------------------------------------------------
    def p_setup_level_from(self, level, tree):
        """The map structures of ``level`` and its compiled ``tree`` (module docstring), in
        P_SetupLevel's order, then P_GroupLines and the subsectors' sectors."""
        if tree.level is not level and tree.level != level:
            raise LevelMapError(f"{level.source}: the tree was compiled from another level")
        if not level.walls:
            raise LevelMapError(f"{level.source}: a level without walls cannot be played")
        for i, (x, y) in enumerate(level.vertices):
            if abs(x) > MAX_COORD or abs(y) > MAX_COORD:
                raise LevelMapError(f"{level.source}: vertices[{i}]: ({x}, {y}) is beyond "
                                    f"DOOM's map coordinates (±{MAX_COORD})")
        self.mapname = level.name
        self.maplumps = []
        self.vertexes = [Vertex(x << FRACBITS, y << FRACBITS) for x, y in level.vertices]
        self._level_sectors(level)
        self._level_sides(level)
        self._level_lines(level)
        self._level_blockmap(level)
        self._level_bsp(level, tree)
        self.numvertexes = len(self.vertexes)
        self.p_group_lines()
        for ss, sector in zip(self.subsectors, self._subsector_sectors):
            ss.sector = self.sectors[sector]
        self.rejectmatrix = bytes((self.numsectors * self.numsectors + 7) // 8)
        self._level_texture_heights(level)

    def _level_sectors(self, level):
        sectors = []
        for i, sec in enumerate(level.sectors):
            s = Sector(i)
            s.floorheight = _fixed(sec.floor)
            s.ceilingheight = _fixed(sec.ceiling)
            s.floorpic = (sec.floor_texture or sec.floor_color).upper()
            s.ceilingpic = SKY_FLAT if sec.sky else \
                (sec.ceiling_texture or sec.ceiling_color).upper()
            s.lightlevel, s.special, s.tag = int(sec.light), int(sec.special), int(sec.tag)
            sectors.append(s)
        self.sectors = sectors
        self.numsectors = len(sectors)

    def _level_sides(self, level):
        sides, self._wall_sides = [], []
        for wall in level.walls:
            nums = []
            for side, sector in ((wall.front_side, wall.front), (wall.back_side, wall.back)):
                if sector is None:
                    nums.append(-1)
                    continue
                sd = Side(len(sides))
                if side is not None:
                    sd.toptexture, sd.midtexture, sd.bottomtexture = (
                        (name or "-").upper() for name in (side.upper, side.middle, side.lower))
                    sd.textureoffset = int(side.x_offset) << FRACBITS
                    sd.rowoffset = int(side.y_offset) << FRACBITS
                sd.sector = self.sectors[sector]
                nums.append(sd.id)
                sides.append(sd)
            self._wall_sides.append(nums)
        self.sides = sides
        self.numsides = len(sides)

    def _level_lines(self, level):
        lines, vertexes, sides = [], self.vertexes, self.sides
        for i, wall in enumerate(level.walls):
            ld = Line(i)
            flags = 0
            if wall.back is not None:
                flags |= ML_TWOSIDED
                if wall.blocks:
                    flags |= ML_BLOCKING
            else:
                flags |= ML_BLOCKING
            if wall.upper_unpegged:
                flags |= ML_DONTPEGTOP
            if wall.lower_unpegged:
                flags |= ML_DONTPEGBOTTOM
            flags |= wall.line_bits
            ld.flags, ld.special, ld.tag = flags, int(wall.special), int(wall.tag)
            set_line_ends(ld, vertexes[wall.v1], vertexes[wall.v2])    # as P_LoadLineDefs
            ld.sidenum = list(self._wall_sides[i])
            ld.frontsector = sides[ld.sidenum[0]].sector
            ld.backsector = sides[ld.sidenum[1]].sector if ld.sidenum[1] != -1 else None
            lines.append(ld)
        self.lines = lines
        self.numlines = len(lines)

    # ---- textures --------------------------------------------------------------------------
    def _level_texture_heights(self, level):
        """``texture_height`` for the level: the WAD's textures (if the game has a WAD),
        else the level's resources, else 0 (a texture nobody holds)."""
        if getattr(self, "wad_path", None) is not None:
            heights, first = self._read_texture_heights()
        else:
            heights, first = {}, 0
        self._texture_heights = (_LevelHeights(heights, level), first or 0)

    # ---- things -------------------------------------------------------------------------
    def p_load_level_things(self, level):
        """P_LoadThings for the level's ``start`` and ``things`` (module docstring)."""
        starts = any(t.type == 1 for t in level.things)
        if not starts:
            st = level.start
            self.p_spawn_map_thing(MapThing(int(round(st.x)), int(round(st.y)),
                                            int(st.angle) % 360, 1, 7))
            mo = self.players[0].mo if self.playeringame[0] else None
            if mo is not None:
                mo.angle = round(float(st.angle) % 360.0 * (1 << 32) / 360.0) & 0xFFFFFFFF
        for t in level.things:
            if t.type not in self.tables.doomednum and t.type not in PLAYER_STARTS:
                continue
            self.p_spawn_map_thing(MapThing(int(t.x), int(t.y), int(t.angle) % 360,
                                            int(t.type), int(t.flags)))
        if not self.deathmatch:
            for i in range(MAXPLAYERS):
                if self.playeringame[i] and not self.playerstartsingame[i]:
                    raise LevelMapError(f"{level.source}: no start for player {i + 1}")
                self.playerstartsingame[i] = False


class _LevelHeights(dict):
    """Texture heights (fixed point) by upper-case name; a name the WAD lacks is looked up
    in the level's resources, once, and is 0 where nothing holds it."""

    def __init__(self, heights, level):
        super().__init__(heights)
        self._level = level
        self._resources = None

    def __missing__(self, name):
        height = 0
        if self._resources is None:
            try:
                from wallbsp.assets.resources import shared_resources
                self._resources = shared_resources(self._level.resource_paths()) or False
            except Exception:              # noqa: BLE001 - no resources: heights unknown
                self._resources = False
        if self._resources:
            try:
                picture = self._resources.wall(name)
            except Exception:              # noqa: BLE001 - a damaged texture: unknown
                picture = None
            if picture is not None:
                height = int(picture.height) << FRACBITS
        self[name] = height
        return height


def start_level(level, tree=None, skill=2, wad_path=None):
    """A ``Play`` on ``level`` (compiled here when ``tree`` is None) at DOOM's ``skill``
    (0-4), ready for ``g_ticker``.  ``wad_path``: a WAD for the game mode, texture heights
    and flat numbers (None: Doom II's rules, heights from the level's resources)."""
    from .play import play_class
    if tree is None:
        from wallbsp.bsp.build import compile_level
        tree = compile_level(level)
    play = play_class()(wad_path)
    play.g_init_new_level(level, tree, skill)
    return play


# ---- helpers ---------------------------------------------------------------------------------

def _fixed(height):
    """Map units (int or float) in fixed point."""
    if isinstance(height, int):
        return height << FRACBITS
    return int(round(float(height) * FRACUNIT))
