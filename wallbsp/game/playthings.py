"""The map objects of a ``Play`` as the renderer's ``Things`` (read by ``PlayState.sync``,
``game.playstate``).

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

import itertools
import operator

import numpy as np

from wallbsp.doom import tables as doom_tables
from wallbsp.scene.things import Things, leaf_sectors, locate_leaves, walk_arrays
from wallbsp.scene.things import spawned_at
from wallbsp.scene.thingrows import ROW, write_rows
from wallbsp.scene.thingtypes import COUNTKILL, NOSECTOR, ThingInfo, thing_info

__all__ = ["PlayThings", "ThingsView", "picture_code", "FRAC", "ANGLE_DEGREES"]

FRAC = 1.0 / 65536.0
ANGLE_DEGREES = 360.0 / 4294967296.0
FF_FULLBRIGHT, FF_FRAMEMASK = 0x8000, 0x7FFF
# what a mobj's picture and place depend on, read in one call per mobj
_READ = operator.attrgetter("x", "y", "z", "angle", "state", "flags", "radius", "height")
STATIC_CODE = 1 << 24                   # picture codes of the level's own types: + type
PLAYER_STARTS = frozenset((1, 2, 3, 4, 11))
DOOM_TYPES = frozenset(doom_tables.DOOM.doomednum) | PLAYER_STARTS
_READERS = itertools.count(1)            # a number for each PlayThings (Play.take_touched)


def picture_code(sprite: int, frame: int) -> int:
    """The key the renderer chooses a thing's picture by: sprite and frame letter."""
    return (sprite << 8) | (frame & FF_FRAMEMASK & 0xFF)


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
        self._read_of: dict = {}         # mobj -> its read (``_READ``) at the last sync
        self._reader = next(_READERS)    # who takes the play's touched list
        self.tables = doom_tables.DOOM   # the synced play's object tables
        self.incremental = False         # the last sync read only what a tic touched
        self.movers: list = []           # the last sync's other thinkers (doors, lights, ...)
        self.hidden = None               # a mobj no view draws (``hide``)
        self._walk = (*walk_arrays(tree), int(tree.root))   # write_rows' tree
        self._found = np.empty(64, dtype=np.int64)           # write_rows' things found
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
        """Read the live mobjs of ``play`` that may have changed since the last call (all
        of them at load, after a restore or whenever the play cannot say: ``slots``, mobj
        -> thing index for the ones placed by THINGS entries, at load).  True when anything
        changed.  Only the mobjs whose position, angle, state, flags or size changed are
        written; ``incremental`` says whether the play's touched list was used (then
        ``movers`` are the other thinkers that ran, else every one in the list)."""
        if slots:
            self._grow(max(slots.values()) + 1)
            for mo, i in slots.items():
                self._slot[mo] = i
                self.mobjs[i] = mo
        self.tables = play.tables
        touched = play.take_touched(self._reader)
        self.incremental = touched is not None and not slots
        if self.incremental:
            live, gone = self._touched_mobjs(play, touched)
        else:
            live, gone = self._every_mobj(play)
        reads = list(map(_READ, live))
        last = self._read_of
        changed = [(mo, r) for mo, r in zip(live, reads) if last.get(mo) != r]
        for mo, r in changed:
            last[mo] = r
        for mo in gone:
            del last[mo]
        if not changed and not gone:
            return False
        return self._apply(changed, gone)

    def _touched_mobjs(self, play, touched) -> tuple:
        """``(mobjs to read, mobjs gone)`` from the play's touched list (and the players'
        things, which change in their own think); the touched thinkers that are no mobj
        are ``movers``."""
        mobj_func = type(play).p_mobj_thinker
        touched = dict.fromkeys(touched)
        for i, p in enumerate(play.players):
            if play.playeringame[i] and p.mo is not None:
                touched[p.mo] = None
        live, gone, movers, last = [], [], [], self._read_of
        for th in touched:
            if th.func is mobj_func:             # first: a mobj has no ``sector`` to miss
                live.append(th)
            elif getattr(th, "sector", None) is not None:
                movers.append(th)                # a door, lift, light...: no mobj
            elif th in last:                     # removed (a mobj never read: skipped)
                gone.append(th)
        self.movers = movers
        return live, gone

    def _every_mobj(self, play) -> tuple:
        """``(every live mobj, mobjs read before and gone)``, walking the thinker list;
        ``movers`` are its other thinkers."""
        mobj_func = type(play).p_mobj_thinker
        cap = play.thinkercap
        th = cap.next
        live, movers = [], []
        while th is not cap:
            if th.func is mobj_func:
                live.append(th)
            else:
                movers.append(th)
            th = th.next
        self.movers = movers
        now = set(live)
        return live, [mo for mo in self._read_of if mo not in now]

    def place_static(self, level, skill: int, tables=doom_tables.DOOM) -> None:
        """The level's things of its own types (module docstring), at ``skill``; a type
        the play spawns (in its ``tables``) is the play's."""
        own = level.thing_types
        if not own:
            return
        spawned = tables.doomednum
        placed = [(i, t) for i, t in enumerate(level.things)
                  if t.type not in spawned and t.type not in PLAYER_STARTS and t.type in own]
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
            type=code, name=self.tables.sprnames[st.sprite],
            sprite=self.tables.sprnames[st.sprite],
            frame=chr(ord("A") + (st.frame & FF_FRAMEMASK)), radius=mo.radius >> 16,
            height=mo.height >> 16, flags=flags, bright=bool(st.frame & FF_FULLBRIGHT),
            rotates=True, monster=bool(flags & COUNTKILL))

    def _apply(self, changed, gone) -> bool:
        slot_of, mobjs, states, pictures = self._slot, self.mobjs, self.tables.states, self._pictures
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
            rows += (i, x, y, z, angle, code, st.frame & FF_FULLBRIGHT, flags, radius, height)
        if rows:
            self._grow(len(mobjs))
            self._write(np.array(rows, dtype=np.int64))
        if gone:
            ids = np.array([slot_of.pop(mo) for mo in gone if mo in slot_of], dtype=np.int64)
            for i in ids.tolist():
                mobjs[i] = None
            self.alive[ids] = False
            self._changed(ids)
        return bool(rows or gone)

    def _write(self, rows) -> None:
        """``rows`` (``thingrows``) into the arrays, in one compiled call."""
        hidden = self._slot.get(self.hidden, -1) if self.hidden is not None else -1
        n = len(rows) // ROW
        if len(self._found) < 2 * n:
            self._found = np.empty(4 * n, dtype=np.int64)
        n_moved, n_placed, shown, sure, untyped = write_rows(
            rows, self.x, self.y, self.z, self.angle, self.type, self.bright, self.flags,
            self.drawn, self.radius, self.height, self.alive, self.leaf, self.sector,
            self.mobjtype, *self._walk, NOSECTOR, FRAC, ANGLE_DEGREES, hidden, self._found)
        if not sure:                         # near a node's line: Python's exact test
            moved = self._found[:n_moved].copy()
            leaf = locate_leaves(self.tree, self.x[moved], self.y[moved])
            self.leaf[moved] = leaf
            self.sector[moved] = leaf_sectors(self.tree)[leaf]
        if untyped:
            ids = rows[::ROW]
            for i in ids[self.mobjtype[ids] < 0].tolist():
                t = self.mobjs[i].type
                self.mobjtype[i] = t
                self.doomednum[i] = self.tables.mobjinfo[t].doomednum
        if n_placed and shown:               # none drawn, before or now: no frame changes
            self._changed(self._found[n:n + n_placed])
        # a new frame, angle or height only: the renderer reads those arrays each frame


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
