"""Animated flats and wall textures (DOOM's P_UpdateSpecials, ``assets.animations``) drawn
by the world state's ``leveltime``, as an index remap over the packed textures.

The tree's ``TexturePack`` holds every picture of each run one of its names belongs to
(``members``), and its ``Cycles`` say, for the pack's texture ids, which run each member is
of.  Per ``LevelTextures`` the places that show a member (planes per sector, wall parts per
side key) are found once (``Animated``); a frame whose tic of animation differs from the
last one drawn rewrites only those places in its own copies of the plane bases and the
part table, from the id each member shows then.  Nothing is repacked, and a frame of a
level with no animated surface reads the LevelTextures' own tables as before.
"""
from __future__ import annotations

import weakref

import numpy as np

from wallbsp.assets.animations import update_tic

__all__ = ["Cycles", "MemberSlots", "members", "animated_tables"]

SIZE_FIELDS = 5                 # part_table's base, pitch, stride, height, width


def members(runs, kind: str, names) -> set:
    """Every name of the runs of ``kind`` that hold one of ``names`` (the pack must hold
    all pictures a named surface can come to show)."""
    names = set(names)
    return {n for run in runs if run.kind == kind and names.intersection(run.names)
            for n in run.names}


class Cycles:
    """The runs among a pack's texture ids: ``member_of[id]`` is the member number of
    texture ``id`` (-1: not animated); ``shown_ids(tic)`` the id each member shows."""

    def __init__(self, runs, n_textures: int):
        self.runs = runs                  # (Animation, ids of its names in the pack)
        self.member_of = np.full(max(n_textures, 1), -1, dtype=np.int64)
        self.ids = np.concatenate([ids for _, ids in runs]).astype(np.int64)
        self.member_of[self.ids] = np.arange(len(self.ids))
        self.speeds = tuple(sorted({run.speed for run, _ in runs}))
        # per member, the terms of ``shown`` (first + k, speed, run length) and where its
        # run's ids start in ``ids``: a step's ids are one numpy expression, not a loop
        def per_member(value):
            return np.concatenate([np.full(len(ids), value(run), dtype=np.int64)
                                   for run, ids in runs])
        self._start = np.repeat(np.cumsum([0] + [len(ids) for _, ids in runs])[:-1],
                                [len(ids) for _, ids in runs]).astype(np.int64)
        self._offset = per_member(lambda run: run.first) + np.concatenate(
            [np.arange(len(ids), dtype=np.int64) for _, ids in runs])
        self._speed = per_member(lambda run: run.speed)
        self._length = per_member(lambda run: len(run.names))

    @classmethod
    def of(cls, runs, walls: dict, flats: dict, n_textures: int):
        """The ``Cycles`` of the runs whose every picture is packed (None: no run is)."""
        packed = []
        for run in runs:
            ids = [(walls if run.kind == "wall" else flats).get(n, -1) for n in run.names]
            if min(ids) >= 0:
                packed.append((run, np.array(ids, dtype=np.int64)))
        return cls(packed, n_textures) if packed else None

    def step(self, leveltime: int):
        """What decides the pictures after ``leveltime`` tics: the tic of animation per
        speed (None before the first tic)."""
        tic = update_tic(leveltime)
        return None if tic is None else tuple(tic // s for s in self.speeds)

    def shown_ids(self, leveltime: int) -> np.ndarray:
        """The texture id each member shows after ``leveltime`` tics."""
        tic = update_tic(leveltime)
        if tic is None:
            return self.ids
        return self.ids[self._start + (tic // self._speed + self._offset) % self._length]


class Animated:
    """The places of one ``LevelTextures`` that show a member, and its tables as drawn at
    the last step (module docstring)."""

    def __init__(self, tex, cycles: Cycles):
        self.cycles = cycles
        member_of = cycles.member_of
        self.plane_base = np.ascontiguousarray(tex.base[tex.plane_texture])
        planes = member_of[tex.plane_texture].reshape(-1)
        self.plane_at = np.flatnonzero(planes >= 0)
        self.plane_member = planes[self.plane_at]
        parts = np.where(tex.key_texture >= 0, member_of[np.maximum(tex.key_texture, 0)], -1)
        part, key = np.nonzero(parts >= 0)
        self.part_at, self.part_member = (part, key), parts[part, key]
        self.part_table = tex.part_table.copy() if len(key) else tex.part_table
        # per texture id: its sizes as part_table holds them (pegging keeps the named one's
        # height, as DOOM's R_StoreWallRange reads the untranslated texture's)
        self.sizes = np.stack([tex.base, tex.pitch, tex.stride, tex.height, tex.width],
                              axis=-1).astype(np.float64)
        self.base = tex.base
        self.last = None
        self.any = bool(len(self.plane_at) or len(key))

    def at(self, leveltime: int):
        """``(part_table, plane_base)`` after ``leveltime`` tics."""
        step = self.cycles.step(leveltime)
        if step != self.last:
            ids = self.cycles.shown_ids(leveltime)
            self.plane_base.reshape(-1)[self.plane_at] = self.base[ids[self.plane_member]]
            if len(self.part_member):
                self.part_table[self.part_at + (slice(0, SIZE_FIELDS),)] = \
                    self.sizes[ids[self.part_member]]
            self.last = step
        return self.part_table, self.plane_base


class MemberSlots:
    """The animated ones among some places' wall texture names, for pictures drawn from an
    atlas (the masked pass's middles: DOOM's R_RenderMaskedSegRange reads
    ``texturetranslation[midtexture]``): ``at(leveltime)`` is the places' slots with each
    member's the slot of the picture it shows then, by the rule ``Cycles`` draws solid walls
    by.  ``of`` gives None when no place shows a member whose every picture has a slot."""

    def __init__(self, slots, places, start, offset, speed, length, pictures):
        self.slots = slots.copy()                     # the places' slots as drawn now
        self.own = slots[places]
        self.places, self.start, self.offset = places, start, offset
        self.speed, self.length, self.pictures = speed, length, pictures
        self.speeds = tuple(sorted(set(speed.tolist())))
        self.last = None

    @classmethod
    def of(cls, runs, slots, places, names, slot_of):
        """``slots`` (per place, -1: none) with ``places`` named ``names``; ``slot_of(name)``
        is a picture's slot (None: no picture)."""
        member = {n.upper(): (run, k) for run in runs if run.kind == "wall"
                  for k, n in enumerate(run.names)}
        pictures, run_start, rows = [], {}, []
        for place, name in zip(places, names):
            found = None if name is None else member.get(name.upper())
            if found is None:
                continue
            run, k = found
            if run not in run_start:
                run_slots = [slot_of(n) for n in run.names]
                run_start[run] = None if None in run_slots else len(pictures)
                if run_start[run] is not None:
                    pictures.extend(run_slots)
            if run_start[run] is not None:
                rows.append((place, run_start[run], run.first + k, run.speed, len(run.names)))
        if not rows:
            return None
        columns = [np.array(c, dtype=np.int64) for c in zip(*rows)]
        return cls(slots, *columns, np.array(pictures, dtype=np.int64))

    def at(self, leveltime: int) -> np.ndarray:
        """The places' slots after ``leveltime`` tics (rewritten only when a picture turns)."""
        tic = update_tic(leveltime)
        step = None if tic is None else tuple(tic // s for s in self.speeds)
        if step != self.last:
            self.slots[self.places] = self.own if tic is None else self.pictures[
                self.start + (tic // self.speed + self.offset) % self.length]
            self.last = step
        return self.slots


_ANIMATED: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()


def animated_tables(tex, leveltime: int):
    """``(part_table, plane_base)`` of ``tex`` (a ``LevelTextures``) after ``leveltime``
    tics, or None when none of its surfaces is animated."""
    cycles = tex.pack.cycles
    if cycles is None:
        return None
    found = _ANIMATED.get(tex)
    if found is None:
        found = _ANIMATED[tex] = Animated(tex, cycles)
    return found.at(leveltime) if found.any else None
