"""What the renderer reads of DOOM's play simulation: a ``WorldState`` fed
from a ``Play`` once a tic (``PlayState.sync``), so the renderer draws the play without
knowing it.

- **Sectors**: ``floor``, ``ceiling`` and ``light`` are the Play's ``floorheight``,
  ``ceilingheight`` (map units, from fixed point) and ``lightlevel`` (so flickering lights
  are the playsim's light thinkers, random numbers and all); ``version`` moves only when a
  height changed, so the renderer's caches keyed on it survive a tic where only lights
  changed.  Floor flats that a special changed are ``floor_textures``.  After tics whose
  touched list the play vouches for (``PlayThings.incremental``), only the sectors that
  can have changed in them are read: those of the thinkers that ran (doors, lifts, floors,
  ceilings, lights) and those tagged by a light-switch line (``LIGHT_SWITCHES``, DOOM's
  only sector writes outside a thinker but for a mover's flat set with its thinker); any
  other call (at load, after a restore, ``set_sector``) reads all of them.
- **Walls**: wall ``i`` is a line of the Play (``wall_lines``: DOOM's linedefs in order,
  less the ones the importer leaves out, SPEC §2b), its front side the line's right side
  (its left one where the line has no right side).  A switch's pressed texture and the
  offset of a scrolling wall (special 48) are ``wall_textures`` and ``wall_x_offset``;
  only the sides of lines that had a special when the level was loaded are watched (no
  other line ever changes its texture), and after tics the play vouches for only when it
  counted a switch turned or a button back (``sides_changed``).  ``leveltime`` is the
  Play's (the renderer runs DOOM's animated flats and textures by it).
- **Things**: ``PlayThings`` (``game.playthings``), read from the mobjs each tic.
"""
from __future__ import annotations

import operator
from itertools import compress
from operator import ne

import numpy as np

from wallbsp.game.playthings import (ANGLE_DEGREES, FRAC, PlayThings, ThingsView,
                                     picture_code)
from wallbsp.scene.state import WorldState

__all__ = ["PlayState", "PlayThings", "ThingsView", "wall_lines", "picture_code",
           "FRAC", "ANGLE_DEGREES"]

_TEXTURES = operator.attrgetter("toptexture", "midtexture", "bottomtexture")
# what the renderer reads of a sector, in one call per sector
_SECTOR = operator.attrgetter("floorheight", "ceilingheight", "lightlevel", "floorpic")
SCROLL_SPECIAL = 48                     # the wall whose texture scrolls left
# line specials that set the tagged sectors' light at once (EV_LightTurnOn,
# EV_TurnTagLightsOff), no thinker involved
LIGHT_SWITCHES = frozenset((12, 13, 35, 79, 80, 81, 104, 138, 139))


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


class PlayState(WorldState):
    """A ``WorldState`` read from a ``Play`` (module docstring)."""

    def __init__(self, tree, play, skill: int = 3, slots=None):
        super().__init__(tree, skill)
        self.play = play
        self._things = PlayThings(tree, capacity=len(tree.level.things))
        self._things.place_static(tree.level, skill, play.tables)
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
        tags = {line.tag for line in play.lines if line.special in LIGHT_SWITCHES}
        self._switched = frozenset(s.id for s in play.sectors if s.tag in tags)
        self._sides_changed = None       # the play's count of switched textures, last read
        self.sync(slots)
        self.things.version = 0

    @staticmethod
    def _textures_of(sd):
        return (sd.toptexture, sd.midtexture, sd.bottomtexture)

    def sync(self, slots=None, every_sector=False) -> None:
        """Read the Play's state after a tic (or at load); ``every_sector``: read all the
        sectors, not only those a tic can change (module docstring)."""
        play = self.play
        self._things.sync(play, slots)
        self.leveltime = play.leveltime
        if self._things.incremental and not every_sector and self._sectors is not None \
                and len(play.sectors) == len(self._sectors):
            self._sync_movers(play.sectors)
        else:
            self._sync_sectors(list(map(_SECTOR, play.sectors)))
        switched = play.sides_changed
        if not self._things.incremental or switched != self._sides_changed:
            self._sides_changed = switched
            textures = list(map(_TEXTURES, self._watched_sides))
            if textures != self._textures_now:
                self._textures_now = textures
                self._read_textures()
        for wall, sd, first in self._scrolling:
            self.wall_x_offset[wall] = (sd.textureoffset - first) * FRAC

    def _sync_sectors(self, sectors) -> None:
        """Every sector's read (``_SECTOR``) against the last one."""
        if sectors != self._sectors:
            if self._sectors is None or len(sectors) != len(self._sectors):
                self._read_sectors(sectors)
            else:
                self._sectors_changed(sectors, self._sectors)
            self._sectors = sectors             # a list of its own: _sync_movers edits it

    def _sync_movers(self, all_sectors) -> None:
        """Only the sectors of the thinkers that ran and the light switches' ones."""
        ids = set(self._switched)
        for th in self._things.movers:
            sector = getattr(th, "sector", None)     # a removed mobj has none
            if sector is not None:
                ids.add(sector.id)
        ids.discard(-1)                  # the null sector: no sector of the map
        last = self._sectors
        changed = []
        for i in sorted(ids):
            read = _SECTOR(all_sectors[i])
            if read != last[i]:
                changed.append((i, read, last[i]))
                last[i] = read
        if changed:
            self._write_sectors(changed)

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
        self._write_sectors((i, sectors[i], was[i]) for i in
                            compress(range(len(sectors)), map(ne, sectors, was)))

    def _write_sectors(self, changed) -> None:
        """``(sector, read now, read before)`` of each changed sector into the arrays."""
        moved = pictures = False
        for i, (floor, ceiling, light, pic), (old_floor, old_ceiling, old_light, old_pic) \
                in changed:
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
        self.sync(every_sector=True)

    def set_light(self, i: int, light) -> None:
        self.set_sector(i, light=light)
