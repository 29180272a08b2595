"""The walkthrough's saved games: six slots (DOOM's) as files of ``playsim.savegame``'s format
in a saves folder (``--saves DIR``; by default ``$XDG_DATA_HOME/wallbsp/saves`` or
``~/.local/share/wallbsp/saves``).

    folder = saves_folder(None)
    read_slots(folder)                      # six descriptions, None for an empty slot
    save_world(world, folder, 2, "BEFORE THE DOOR")      # atomic: all of it or nothing
    world = load_world(folder, 2, world, tree_of)        # a World going on from the save

A save is written atomically; loading validates it all before anything changes, so a
damaged or foreign save (another WAD, another map, not a save at all) is one ``SaveError``
line naming the file and the place, and the game in play goes on untouched.  A save edited
with its digest made anew is loaded twice: the first copy plays ``TRIAL_TICS`` idle tics,
so a saved state that cannot play fails there, not in the game the player goes on with.
"""
from __future__ import annotations

import os
from pathlib import Path

from wallbsp.files import InputError, read_input
from wallbsp.game.playload import world_play_class
from wallbsp.game.playsim.savegame import (MAX_SAVE_BYTES, SaveError, load_game, read_header,
                                           save_game_file)
from wallbsp.game.world import World

__all__ = ["SLOTS", "saves_folder", "slot_path", "read_slots", "save_world", "load_world",
           "SaveError", "DAMAGED"]

SLOTS = 6
DAMAGED = "(unreadable save)"
TRIAL_TICS = 35             # one second of play tried before a loaded game is taken


def saves_folder(given=None) -> Path:
    """``given``, or the XDG data folder's ``wallbsp/saves``."""
    if given:
        return Path(given)
    base = os.environ.get("XDG_DATA_HOME") or os.path.join(os.path.expanduser("~"),
                                                           ".local", "share")
    return Path(base) / "wallbsp" / "saves"


def slot_path(folder, slot: int) -> Path:
    return Path(folder) / f"wallbsp{slot}.wsg"


def read_slots(folder) -> list:
    """Each slot's description (M_ReadSaveStrings): None for no file, ``DAMAGED`` for a
    file that is not a sound save (loading it says why)."""
    found = []
    for slot in range(SLOTS):
        path = slot_path(folder, slot)
        if not path.is_file():
            found.append(None)
            continue
        try:
            header = read_header(read_input(path, MAX_SAVE_BYTES), str(path))[0]
            found.append(str(header.get("description") or "")[:23] or "?")
        except (SaveError, InputError, OSError):
            found.append(DAMAGED)
    return found


def save_world(world, folder, slot: int, name: str) -> Path:
    """Writes ``world``'s play to the slot's file (the folder made if needed)."""
    path = slot_path(folder, slot)
    try:
        Path(folder).mkdir(parents=True, exist_ok=True)
    except OSError as e:
        raise SaveError(f"{folder}: cannot make the saves folder: {e.strerror or e}") from None
    save_game_file(world.play, path, name)
    return path


def load_world(folder, slot: int, world, tree_of) -> World:
    """A new World going on from the slot's save, of the game ``world`` plays (its WAD, or
    its level); ``tree_of(map_name)`` compiles another map of the same WAD.  SaveError for
    anything wrong; ``world`` is not touched."""
    path = slot_path(folder, slot)
    try:
        data = read_input(path, MAX_SAVE_BYTES)
    except InputError as e:
        raise SaveError(str(e)) from None
    header = read_header(data, str(path))[0]
    if world.wad_map is None:
        tree, wad, level = world.tree, None, (world.tree.level, world.tree)
    else:
        wad, level = world.wad_map[0], None
        tree = world.tree if header["map"] == world.wad_map[1] else None
        if tree is None:
            if not isinstance(header.get("map"), str) or tree_of is None:
                raise SaveError(f"{path}: header.map: no such map in this game")
            try:
                tree = tree_of(header["map"])
            except (OSError, ValueError) as e:
                raise SaveError(f"{path}: header.map: {e}") from None
    skill = header.get("skill")
    skill = skill + 1 if isinstance(skill, int) and 0 <= skill <= 4 else world.skill
    trial = _world_of(data, wad, level, tree, skill, path, world.tables)
    _try_tics(trial, path)
    return _world_of(data, wad, level, tree, skill, path, world.tables)


def _world_of(data, wad, level, tree, skill, path, tables=None) -> World:
    """(``tables``: the game's own, wallbsp.content)"""
    try:
        play = load_game(data, wad, source=str(path), cls=world_play_class(), level=level,
                         tables=tables)
        return World(tree, skill, play=play, tables=tables)
    except SaveError:
        raise
    except Exception as e:
        # load_game checks the structure and the ranges of DOOM's own fields, not every
        # value of every object; a save edited with its digest made anew can still hold one
        # no World can be made from (an OverflowError, say): the game in play goes on
        raise SaveError(f"{path}: body: the saved state makes no world "
                        f"({type(e).__name__}: {e})") from None


def _try_tics(trial: World, path) -> None:
    """Plays ``TRIAL_TICS`` idle tics of a second copy of the loaded game: a save edited
    with its digest made anew (a string where DOOM keeps a number, a state number past the
    table) fails there, as one ``SaveError`` line, not in the game the player goes on with."""
    try:
        for _ in range(TRIAL_TICS):
            trial.tic()
    except Exception as e:        # any failure of a state this version never writes
        raise SaveError(f"{path}: body: the saved state does not play "
                        f"({type(e).__name__}: {e})") from None
