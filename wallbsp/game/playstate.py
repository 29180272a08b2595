"""What the renderer and the queries read of DOOM's play simulation: a ``WorldState`` fed
from a ``Play`` once a tic (``PlayState.sync``), so the renderer draws the play without
knowing it.

- **Sectors**: ``floor``, ``ceiling`` and ``light`` are the Play's ``floorheight``,
  ``ceilingheight`` (map units, from fixed point) and ``lightlevel`` (so flickering lights
  are the playsim's light thinkers, random numbers and all); ``version`` moves only when a
  height changed, so the renderer's caches keyed on it survive a tic where only lights
  changed.  Floor flats that a special changed are ``floor_textures``.
- **Walls**: wall ``i`` is a line of the Play (``wall_lines``: DOOM's linedefs in order,
  less the ones the importer leaves out, SPEC §2b), its front side the line's right side
  (its left one where the line has no right side).  A switch's pressed texture and the
  offset of a scrolling wall (special 48) are ``wall_textures`` and ``wall_x_offset``;
  only the sides of lines that had a special when the level was loaded are watched (no
  other line ever changes its texture).  ``leveltime`` is the Play's (the renderer runs
  DOOM's animated flats and textures by it).
- **Things**: every map object (``mobj``) is a thing of ``PlayThings`` (a ``Things``),
  drawn in its *current* state's frame: ``type`` there is a picture code (the sprite
  number × 256 + the frame letter), ``bright`` the state's full-bright bit, ``angle`` the
  mobj's, ``z`` its feet.  Thing ``i`` of the level's THINGS entries is the mobj that entry
  spawned (``slots`` given at load); mobjs spawned later (missiles, puffs, blood, drops,
  the spawner's cubes) are appended, and a removed mobj's thing stays, not ``alive``, so a
  thing's index never changes while the level is played.  ``ThingsView`` is what
  ``World.things`` shows callers: the same arrays, ``type`` the editor number (DOOM's
  ``doomednum``, -1 for objects no map places) and ``mobjtype`` DOOM's ``MT_*``.
- A thing of a level's own type (SPEC §2b ``thing_types``, a number DOOM does not know)
  is no map object: DOOM could not spawn it.  It stands where the level puts it, drawn
  as its type says (``static``), and the play does not see it: it neither blocks nor is
  picked up.
"""
from __future__ import annotations

import operator
from itertools import compress
from operator import ne

import numpy as np

from wallbsp.sim import info
from wallbsp.sim.state import WorldState
from wallbsp.sim.things import Things, leaf_sectors, locate_leaves
from wallbsp.sim.things import spawned_at
from wallbsp.sim.thingrows import write_rows
from wallbsp.sim.thingtypes import COUNTKILL, NOSECTOR, ThingInfo, thing_info

__all__ = ["PlayState", "PlayThings", "ThingsView", "wall_lines", "picture_code",
           "FRAC", "ANGLE_DEGREES"]

FRAC = 1.0 / 65536.0
ANGLE_DEGREES = 360.0 / 4294967296.0
FF_FULLBRIGHT, FF_FRAMEMASK = 0x8000, 0x7FFF
# what a mobj's picture and place depend on, read in one call per mobj
_READ = operator.attrgetter("x", "y", "z", "angle", "state", "flags", "radius", "height")
_TEXTURES = operator.attrgetter("toptexture", "midtexture", "bottomtexture")
# what the renderer reads of a sector, in one call per sector
_SECTOR = operator.attrgetter("floorheight", "ceilingheight", "lightlevel", "floorpic")
SCROLL_SPECIAL = 48                     # the wall whose texture scrolls left
STATIC_CODE = 1 << 24                   # picture codes of the level's own types: + type
DOOM_TYPES = frozenset(info.DOOMEDNUM) | {1, 2, 3, 4, 11}


def picture_code(sprite: int, frame: int) -> int:
    """The key the renderer chooses a thing's picture by: sprite and frame letter."""
    return (sprite << 8) | (frame & FF_FRAMEMASK & 0xFF)


def wall_lines(play) -> list:
    """``[(line, front side, back side or -1), ...]`` of each wall: the Play's lines in
    order without those with no side or no length, a line with only a left side turned
    round (the importer's rule, ``level.wadmap``)."""
    walls = []
    for line in play.lines:
        right, left = line.sidenum
        if right == -1 and left == -1:
            continue
        if line.v1.x == line.v2.x and line.v1.y == line.v2.y:
            continue
        if right == -1:
            walls.append((line, left, -1))
        else:
            walls.append((line, right, left))
    return walls


class PlayThings(Things):
    """The map objects of a Play as ``Things`` (module docstring)."""

    def __init__(self, tree, capacity: int = 0):
        super().__init__(tree)
        self.doomednum = np.zeros(0, dtype=np.int64)
        self.mobjtype = np.zeros(0, dtype=np.int64)
        self.mobjs: list = []            # slot -> mobj (None: no mobj ever)
        self._slot: dict = {}            # mobj -> slot
        self._pictures: dict = {}        # picture code -> ThingInfo (what the renderer reads)
        self.static = np.zeros(0, dtype=bool)   # a level's own type: no mobj
        self._reads, self._live = [], []     # the last sync's mobjs and reads
        self.hidden = None               # a mobj no view draws (``hide``)
        self._grow(capacity)

    def _info(self, code: int):
        return self._pictures.get(int(code))

    def mobj(self, i: int):
        """The map object of thing ``i`` (None when it is no longer in the world)."""
        mo = self.mobjs[i] if 0 <= i < len(self.mobjs) else None
        return mo if mo is not None and self.alive[i] else None

    def index_of(self, mo) -> int:
        """The thing index of map object ``mo`` (-1 for one not in the world)."""
        return self._slot.get(mo, -1)

    def _grow(self, n: int) -> None:
        """Arrays for ``n`` things (new ones not alive)."""
        extra = n - len(self.x)
        if extra <= 0:
            return
        for name, fill in (("x", 0.0), ("y", 0.0), ("z", 0.0), ("angle", 0.0), ("type", -1),
                           ("alive", False), ("leaf", 0), ("sector", -1), ("radius", 0.0),
                           ("height", 0.0), ("flags", 0), ("drawn", False), ("bright", False),
                           ("doomednum", -1), ("mobjtype", -1), ("static", False)):
            old = getattr(self, name)
            setattr(self, name, np.concatenate([old, np.full(extra, fill, dtype=old.dtype)]))
        self.mobjs.extend([None] * (n - len(self.mobjs)))

    def sync(self, play, slots=None) -> bool:
        """Read every live mobj of ``play`` (``slots``: mobj -> thing index for the ones
        placed by THINGS entries, at load).  True when anything changed.  Only the mobjs
        whose position, angle, state, flags or size changed since the last call are
        written (a tic where most things stand still costs one read of each)."""
        if slots:
            self._grow(max(slots.values()) + 1)
            for mo, i in slots.items():
                self._slot[mo] = i
                self.mobjs[i] = mo
        mobj_func = type(play).p_mobj_thinker
        cap = play.thinkercap
        th = cap.next
        live = []
        while th is not cap:
            if th.func is mobj_func:
                live.append(th)
            th = th.next
        reads = list(map(_READ, live))
        last_live, last_reads = self._live, self._reads
        if live == last_live:              # the same mobjs in the same order: row by row
            if reads == last_reads:
                return False
            changed = [(mo, r) for mo, r, was in zip(live, reads, last_reads) if r != was]
            gone = []
        else:
            before = dict(zip(last_live, last_reads))
            changed = [(mo, r) for mo, r in zip(live, reads) if before.get(mo) != r]
            now = set(live)
            gone = [mo for mo in last_live if mo not in now]
        self._reads, self._live = reads, live
        return self._apply(changed, gone)

    def place_static(self, level, skill: int) -> None:
        """The level's things of its own types (module docstring), at ``skill``."""
        own = level.thing_types
        if not own:
            return
        placed = [(i, t) for i, t in enumerate(level.things)
                  if t.type not in DOOM_TYPES and t.type in own]
        if not placed:
            return
        flags = np.array([t.flags for _, t in placed], dtype=np.int64)
        placed = [p for p, keep in zip(placed, spawned_at(flags, skill).tolist()) if keep]
        if not placed:
            return
        self._grow(max(i for i, _ in placed) + 1)
        ids = np.array([i for i, _ in placed], dtype=np.int64)
        for i, t in placed:
            kind = thing_info(t.type, own)
            code = STATIC_CODE + int(t.type)
            self._pictures[code] = kind
            self.x[i], self.y[i], self.angle[i] = float(t.x), float(t.y), float(t.angle)
            self.type[i], self.doomednum[i] = code, t.type
            self.radius[i], self.height[i] = kind.radius, kind.height
            self.flags[i], self.drawn[i], self.bright[i] = kind.flags, kind.drawn, kind.bright
        self.static[ids] = self.alive[ids] = True
        self.z[ids] = np.nan                       # on the floor (or from the ceiling) now
        leaf = locate_leaves(self.tree, self.x[ids], self.y[ids])
        self.leaf[ids] = leaf
        self.sector[ids] = leaf_sectors(self.tree)[leaf]
        self._changed(ids)

    def hide(self, mo) -> None:
        """Map object ``mo`` is drawn by no view from now on (a single player's own body,
        which the eye is inside of: DOOM's MINZ cull misses it when the view is blended
        between two tics); its thing keeps its index and every other array."""
        self.hidden = mo
        i = self._slot.get(mo)
        if i is not None and self.drawn[i]:
            self.drawn[i] = False
            self._changed(np.array([i], dtype=np.int64))

    def _learn(self, st, mo) -> None:
        code = picture_code(st.sprite, st.frame)
        flags = mo.flags
        self._pictures[code] = ThingInfo(
            type=code, name=info.SPRNAMES[st.sprite], sprite=info.SPRNAMES[st.sprite],
            frame=chr(ord("A") + (st.frame & FF_FRAMEMASK)), radius=mo.radius >> 16,
            height=mo.height >> 16, flags=flags, bright=bool(st.frame & FF_FULLBRIGHT),
            rotates=True, monster=bool(flags & COUNTKILL))

    def _apply(self, changed, gone) -> bool:
        slot_of, mobjs, states, pictures = self._slot, self.mobjs, info.STATES, self._pictures
        rows = []
        for mo, (x, y, z, angle, state, flags, radius, height) in changed:
            i = slot_of.get(mo)
            if i is None:
                i = slot_of[mo] = len(mobjs)
                mobjs.append(mo)
            st = states[state]
            code = (st.sprite << 8) | (st.frame & 0xFF)
            if code not in pictures:
                self._learn(st, mo)
            rows.append((i, x, y, z, angle, code, st.frame & FF_FULLBRIGHT, flags, radius,
                         height))
        self._grow(len(mobjs))
        if rows:
            a = np.array(rows, dtype=np.int64)
            ids = a[:, 0]
            moved, placed = write_rows(a, self.x, self.y, self.z, self.angle, self.type,
                                       self.bright, self.flags, self.drawn, self.radius,
                                       self.height, self.alive, NOSECTOR, FRAC, ANGLE_DEGREES)
            if moved.any():
                m = ids[moved]
                leaf = locate_leaves(self.tree, self.x[m], self.y[m])
                self.leaf[m] = leaf
                self.sector[m] = leaf_sectors(self.tree)[leaf]
            for i in ids[self.mobjtype[ids] < 0].tolist():
                t = self.mobjs[i].type
                self.mobjtype[i] = t
                self.doomednum[i] = info.MOBJINFO[t].doomednum
            hidden = slot_of.get(self.hidden) if self.hidden is not None else None
            if hidden is not None:           # its row written as drawn again: not so
                self.drawn[hidden] = False
            if placed.any():
                self._changed(ids[placed])
            # a new frame, angle or height only: the renderer reads those arrays each frame
        if gone:
            ids = np.array([slot_of.pop(mo) for mo in gone if mo in slot_of], dtype=np.int64)
            for i in ids.tolist():
                mobjs[i] = None
            self.alive[ids] = False
            self._changed(ids)
        return bool(rows or gone)


class ThingsView:
    """``World.things``: the things' arrays as callers know them (``type``: the editor
    number, -1 for objects no map places; ``mobjtype``: DOOM's ``MT_*``; ``alive``: still
    in the world).  Everything else is ``PlayThings``'."""

    def __init__(self, things: PlayThings):
        self._things = things

    @property
    def type(self) -> np.ndarray:
        return self._things.doomednum

    def info(self, i: int):
        """The ``ThingInfo`` of thing ``i``'s editor number (None for one no map places)."""
        number = int(self._things.doomednum[i])
        return thing_info(number, self._things.own_types) if number >= 0 else None

    def __len__(self) -> int:
        return len(self._things)

    def __getattr__(self, name):
        return getattr(self._things, name)


class PlayState(WorldState):
    """A ``WorldState`` read from a ``Play`` (module docstring)."""

    def __init__(self, tree, play, skill: int = 3, slots=None):
        super().__init__(tree, skill)
        self.play = play
        self._things = PlayThings(tree, capacity=len(tree.level.things))
        self._things.place_static(tree.level, skill)
        self.walls = wall_lines(play)
        self._watched = []               # (wall, side number, Side, textures at load)
        self._scrolling = []             # (wall, Side, offset at load)
        for wall, (line, front, back) in enumerate(self.walls):
            if not line.special:
                continue
            for side, sidenum in ((0, front), (1, back)):
                if sidenum >= 0:
                    sd = play.sides[sidenum]
                    self._watched.append((wall, side, sd, self._textures_of(sd)))
            if line.special == SCROLL_SPECIAL:
                sd = play.sides[front]
                self._scrolling.append((wall, sd, sd.textureoffset))
        self._watched_sides = [sd for _, _, sd, _ in self._watched]
        self._textures_now = list(map(_TEXTURES, self._watched_sides))
        self._floorpics = [s.floorpic for s in play.sectors]     # as loaded
        self._sectors = None             # the last sync's reads (_SECTOR) of every sector
        self.sync(slots)
        self.things.version = 0

    @staticmethod
    def _textures_of(sd):
        return (sd.toptexture, sd.midtexture, sd.bottomtexture)

    def sync(self, slots=None) -> None:
        """Read the Play's state after a tic (or at load)."""
        play = self.play
        self.leveltime = play.leveltime
        sectors = list(map(_SECTOR, play.sectors))
        if sectors != self._sectors:
            if self._sectors is None or len(sectors) != len(self._sectors):
                self._read_sectors(sectors)
            else:
                self._sectors_changed(sectors, self._sectors)
            self._sectors = sectors
        textures = list(map(_TEXTURES, self._watched_sides))
        if textures != self._textures_now:
            self._textures_now = textures
            self._read_textures()
        for wall, sd, first in self._scrolling:
            self.wall_x_offset[wall] = (sd.textureoffset - first) * FRAC
        self._things.sync(play, slots)

    def _read_sectors(self, sectors) -> None:
        """Every sector's heights, light and floor flat (at load)."""
        self.floor = np.array([s[0] for s in sectors], dtype=np.float64) * FRAC
        self.ceiling = np.array([s[1] for s in sectors], dtype=np.float64) * FRAC
        self.light = np.array([s[2] for s in sectors], dtype=np.float64)
        self.version += 1
        self._sectors_changed(sectors, [(*s[:3], pic) for s, pic in zip(sectors,
                                                                         self._floorpics)])

    def _sectors_changed(self, sectors, was) -> None:
        """The sectors whose read differs from ``was``: only those are written."""
        moved = pictures = False
        for i in compress(range(len(sectors)), map(ne, sectors, was)):
            floor, ceiling, light, pic = sectors[i]
            old_floor, old_ceiling, old_light, old_pic = was[i]
            if floor != old_floor or ceiling != old_ceiling:
                self.floor[i], self.ceiling[i] = floor * FRAC, ceiling * FRAC
                moved = True
            if light != old_light:
                self.light[i] = light
            if pic != old_pic:
                self.floor_textures[i] = None if pic == "-" else pic
                pictures = True
        if moved:
            self.version += 1
        if pictures:
            self.texture_version += 1

    def _read_textures(self) -> None:
        """The watched sides' textures into ``wall_textures`` (only those that differ from
        the level's as it was loaded)."""
        for wall, side, sd, first in self._watched:
            now = self._textures_of(sd)
            if now == first and not self.wall_textures:
                continue
            for part, was, name in zip(("upper", "middle", "lower"), first, now):
                key = (wall, side, part)
                if name == was:
                    if key in self.wall_textures:
                        del self.wall_textures[key]
                        self.texture_version += 1
                elif self.wall_textures.get(key, was) != (None if name == "-" else name) \
                        or key not in self.wall_textures:
                    self.wall_textures[key] = None if name == "-" else name
                    self.texture_version += 1

    def set_sector(self, i: int, floor=None, ceiling=None, light=None) -> None:
        """Change sector ``i`` in the play itself (heights to DOOM's fixed point), then read
        it back: the play owns the sectors."""
        sector = self.play.sectors[i]
        if floor is not None:
            sector.floorheight = int(round(float(floor) * 65536))
        if ceiling is not None:
            sector.ceilingheight = int(round(float(ceiling) * 65536))
        if light is not None:
            sector.lightlevel = int(light)
        self.sync()

    def set_light(self, i: int, light) -> None:
        self.set_sector(i, light=light)
