"""Starting DOOM's play simulation on a level: which map it plays, and the ``Play`` that
remembers which THINGS entry spawned which map object.

- A level imported from a WAD (``wad_map_of``: it names the WAD among its resources and
  came from ``WAD:MAP``, or is a saved import of that map, same content) is played on the
  WAD's own map: the Play loads the map's lumps (its nodes, blockmap and reject), exactly
  DOOM's.
- Any other level is handed to the Play as a level (``levelmap``'s
  ``p_setup_level_from(level, tree)``, which builds DOOM's structures from it).

``world_play_class()`` is ``Play`` with two additions: ``thing_slots`` (mobj -> index of
the THINGS entry, or of the level's thing, that spawned it; SPEC §2b's numbering) and
``loads`` (how many times a level was loaded, so a reload after a death is noticed).
"""
from __future__ import annotations

import os
import re

from wallbsp.game.playsim.play import play_class

__all__ = ["wad_map_of", "world_play_class", "map_numbers"]

_MAP_NAME = re.compile(r"^(E[1-9]M[1-9]|MAP[0-9][0-9])$")
_IMPORTED_NAME = re.compile(r"^(E[1-9]M[1-9]|MAP[0-9][0-9]) \((.+)\)$")


def map_numbers(map_name: str) -> tuple[int, int]:
    """``(episode, map)`` of ``E2M3`` or ``MAP15`` (episode 1 for Doom II's maps)."""
    if map_name.startswith("MAP"):
        return 1, int(map_name[3:])
    return int(map_name[1]), int(map_name[3])


def wad_map_of(level):
    """``(wad path, map name)`` when ``level`` is a WAD's map as the importer made it,
    else None (module docstring)."""
    wads = [str(p) for p in level.resource_paths() if str(p).lower().endswith(".wad")]
    if not wads:
        return None
    source = str(level.source)
    if ":" in source:
        wad, map_name = source.rsplit(":", 1)
        map_name = map_name.upper()
        if _MAP_NAME.match(map_name) and any(_same_file(wad, w) for w in wads):
            return os.path.abspath(wad), map_name
    named = _IMPORTED_NAME.match(level.name or "")
    if named is None:
        return None
    map_name, base = named.groups()
    for wad in wads:
        if os.path.basename(wad) == base and os.path.isfile(wad) and _same_map(level, wad,
                                                                                  map_name):
            return os.path.abspath(wad), map_name
    return None


def _same_file(a, b) -> bool:
    try:
        return os.path.samefile(a, b)
    except OSError:
        return False


def _same_map(level, wad, map_name) -> bool:
    """Whether ``level`` is the importer's level of ``wad``'s ``map_name`` (a saved import
    that nobody edited)."""
    from wallbsp.level.write import content_hash
    from wallbsp.level.wadmap import load_wad_level
    try:
        return content_hash(load_wad_level(wad, map_name)) == content_hash(level)
    except Exception:                      # noqa: BLE001 - not that map: play the level
        return False


_WORLD_PLAY = None


def world_play_class():
    """``Play`` remembering which map thing spawned each mobj (module docstring)."""
    global _WORLD_PLAY
    if _WORLD_PLAY is None:
        base = play_class()

        class WorldPlay(base):
            loads = 0

            def p_setup_level(self, *args, **kwargs):
                self.begin_things()
                self.loads += 1
                return super().p_setup_level(*args, **kwargs)

            def begin_things(self):
                """Map things are numbered from 0 again (a level is loading)."""
                self.thing_slots = {}
                self.thing_number = 0

            def p_spawn_map_thing(self, mthing):
                last = self.thinkercap.prev
                super().p_spawn_map_thing(mthing)
                added = self.thinkercap.prev
                if added is not last:
                    self.thing_slots[added] = self.thing_number
                self.thing_number += 1

        WorldPlay.__module__ = __name__
        _WORLD_PLAY = WorldPlay
    return _WORLD_PLAY
