"""Starting DOOM's play simulation on a level: which map it plays, and the ``Play`` that
remembers which THINGS entry spawned which map object.

- A level imported from an IWAD's DOOM-format map (``wad_map_of``: it names the WAD among
  its resources and came from ``WAD:MAP``, or is a saved import of that map, same
  content) is played on the WAD's own map: the Play loads the map's lumps (its nodes,
  blockmap and reject), exactly DOOM's, with the IWAD's game mode.  A PWAD's or a UDMF
  map is played as a level, as any other.
- Any other level is handed to the Play as a level (``levelmap``'s
  ``p_setup_level_from(level, tree)``, which builds DOOM's structures from it).

``world_play_class()`` is ``Play`` with two additions: ``thing_slots`` (mobj -> index of
the THINGS entry, or of the level's thing, that spawned it, SPEC §2b's numbering: each map
thing P_SpawnMapThing is given is matched to the next of ``level_things`` with its
position, type and flags, so things DOOM skips or leaves out keep their numbers) and
``loads`` (how many times a level was loaded, so a reload after a death is noticed), and
``secret_exit_taken`` (whether the level was left by its secret exit: DOOM's own
``secretexit`` stays false in a Doom II game without MAP31, as with no WAD at all), and
``extra_starts`` (THINGS entries spawned before the map's own: the player and deathmatch
starts a net game needs and the level lacks, made from ``net_starts`` when the map has
loaded, ``game.multiplayer``).
"""
from __future__ import annotations

import os
import re

from wallbsp.game.multiplayer import make_extra_starts
from wallbsp.game.playsim.play import play_class

__all__ = ["wad_map_of", "world_play_class", "map_numbers", "level_thing_keys"]

_MAP_NAME = re.compile(r"^(E[1-9]M[1-9]|MAP[0-9][0-9])$")
_IMPORTED_NAME = re.compile(r"^(E[1-9]M[1-9]|MAP[0-9][0-9]) \((.+)\)$")


def map_numbers(map_name: str) -> tuple[int, int]:
    """``(episode, map)`` of ``E2M3`` or ``MAP15`` (episode 1 for Doom II's maps)."""
    if map_name.startswith("MAP"):
        return 1, int(map_name[3:])
    return int(map_name[1]), int(map_name[3])


def level_thing_keys(level) -> list:
    """``(x, y, type, flags)`` of each of the level's things, as DOOM's THINGS entry holds
    them, to know which thing spawned which map object."""
    return [(int(t.x), int(t.y), int(t.type), int(t.flags)) for t in level.things]


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
        if _MAP_NAME.match(map_name) and any(_same_file(wad, w) for w in wads) \
                and _doom_format_map(wad, map_name):
            return os.path.abspath(wad), map_name
    named = _IMPORTED_NAME.match(level.name or "")
    if named is None:
        return None
    map_name, base = named.groups()
    for wad in wads:
        if os.path.basename(wad) == base and os.path.isfile(wad) \
                and _doom_format_map(wad, map_name) and _same_map(level, wad, map_name):
            return os.path.abspath(wad), map_name
    return None


def _doom_format_map(wad, map_name) -> bool:
    """Whether ``wad`` is an IWAD whose ``map_name`` is in DOOM's format (its marker then
    THINGS, ... as DOOM loads them; not UDMF's TEXTMAP): the maps the Play loads itself."""
    from wallbsp.game.playsim.demos import wad_entries
    try:
        with open(wad, "rb") as f:
            if f.read(4) != b"IWAD":
                return False
        names = [entry[0] for entry in wad_entries(wad)]
    except (OSError, ValueError):
        return False
    at = len(names) - 1 - names[::-1].index(map_name) if map_name in names else -1
    return 0 <= at < len(names) - 1 and names[at + 1] == "THINGS"


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
            level_things = ()
            secret_exit_taken = False
            extra_starts = ()
            net_starts = None

            def p_load_things(self):
                self.spawn_extra_starts()
                return super().p_load_things()

            def p_load_level_things(self, level):
                self.spawn_extra_starts()
                return super().p_load_level_things(level)

            def spawn_extra_starts(self):
                make_extra_starts(self)     # the map has loaded, no thing yet
                for mthing in self.extra_starts:
                    self.p_spawn_map_thing(mthing)

            def p_setup_level(self, *args, **kwargs):
                self.begin_things()
                self.loads += 1
                return super().p_setup_level(*args, **kwargs)

            def g_secret_exit_level(self):
                self.secret_exit_taken = True
                return super().g_secret_exit_level()

            def g_exit_level(self):
                self.secret_exit_taken = False
                return super().g_exit_level()

            def begin_things(self):
                """Map things are matched from the first again (a level is loading)."""
                self.thing_slots = {}
                self.thing_number = 0

            def p_spawn_map_thing(self, mthing):
                last = self.thinkercap.prev
                super().p_spawn_map_thing(mthing)
                number = self._thing_number_of(mthing)
                added = self.thinkercap.prev
                if added is not last and number is not None:
                    self.thing_slots[added] = number

            def _thing_number_of(self, mthing):
                """The index of the level's thing that ``mthing`` is: the next one with
                its position, type and flags (None for a thing the level does not hold,
                such as the start of a level without a player-1 thing)."""
                key = (mthing.x, mthing.y, mthing.type, mthing.options)
                things = self.level_things
                for k in range(self.thing_number, len(things)):
                    if things[k] == key:
                        self.thing_number = k + 1
                        return k
                return None

        WorldPlay.__module__ = __name__
        _WORLD_PLAY = WorldPlay
    return _WORLD_PLAY
