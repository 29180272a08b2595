"""A game folder: levels, actors, scripts, pictures and sounds in one folder, played by
``wallbsp walk mygame/``.

    mygame/
      game.json        {"name": "My game", "episode": "Knee-deep", "maps": ["map01.json"],
                        "actors": "actors.py", "skills": ["Easy", "Normal", "Hard", ...]}
      actors.py        the game's classes (wallbsp.content): every Actor, Item and Weapon
                       it defines is added to the play's tables
      map01.json       levels (their "script" and "resources" relative to the folder:
                       "resources": ["."] finds sprites/ and sounds/ here)
      door.py          a level's script (game.levelscript)
      sprites/SPITA1.png ...   sounds/DSSPITSI.wav ...

``game.toml`` may stand for ``game.json`` (the same keys).  A map entry is a level file
name, ``{"level": "map01.json", "title": "The Hall"}`` (the title: the level's name in the
intermission and messages), or ``{"wad": "doom2.wad", "map": "MAP01", "script": "x.py"}``
for a WAD's map with a script of the game's (its intermission shows the WAD's own name
picture).  The menus show the game's episode and skill names (``episode_names``,
``skill_names``; DOOM's skills when it names none).  ``load_game_folder(path)`` →
``GameFolder`` (``tables``, ``maps``, ``tree(i)``, ``level(n)``, ``next_level``; itself the
walkthrough's ``next_level``); anything wrong is one ``LevelError`` line naming the file.
"""
from __future__ import annotations

import dataclasses
import json
from dataclasses import dataclass, field
from pathlib import Path

from wallbsp.files import LevelError

from .levelscript import run_file

__all__ = ["GameFolder", "load_game_folder", "is_game_folder", "MANIFESTS"]

MANIFESTS = ("game.json", "game.toml")
KEYS = ("name", "episode", "maps", "actors", "skills")
MAX_MANIFEST_BYTES = 1 << 20


def is_game_folder(path) -> bool:
    path = Path(path)
    return path.is_dir() and any((path / m).is_file() for m in MANIFESTS)


@dataclass
class GameFolder:
    """A loaded game folder (module docstring)."""
    folder: Path
    name: str
    episode: str
    maps: list                      # level file paths, or (wad, map, script or None)
    skills: tuple = ()
    titles: list = field(default_factory=list)     # each map's title, or None
    tables: object = None           # doom.tables.Tables with the game's actors
    classes: list = field(default_factory=list)
    _trees: dict = field(default_factory=dict)

    def tree(self, i: int):
        """Map ``i`` compiled (once)."""
        if i not in self._trees:
            from wallbsp.bsp.build import compile_level
            entry = self.maps[i]
            if isinstance(entry, tuple):
                from wallbsp.level.wadmap import load_wad_level
                level = load_wad_level(str(entry[0]), entry[1])
                if entry[2] is not None:        # the game's script, by its absolute path
                    level = dataclasses.replace(level, script=str(self.folder / entry[2]))
            else:
                from wallbsp.level.io import load_level
                level = load_level(entry)
                title = self.titles[i] if i < len(self.titles) else None
                if title is not None:           # the intermission's and messages' name
                    level = dataclasses.replace(level, name=title)
            self._trees[i] = compile_level(level)
        return self._trees[i]

    @property
    def episode_names(self) -> tuple:
        """The menus' episode (one a game folder)."""
        return (self.episode,)

    @property
    def skill_names(self) -> tuple:
        """The menus' skills (none named: DOOM's)."""
        return tuple(self.skills)

    def next_level(self, exit_kind):
        """The walkthrough's next level after an exit: the following map (or None after
        the last)."""
        current = getattr(self, "current", 0) + 1
        if current >= len(self.maps):
            return None
        self.current = current
        return self.tree(current)

    __call__ = next_level                   # the walkthrough's next_level(exit)

    def level(self, number: int):
        """Map ``number`` (1-based; a new game, idclev1N), or None."""
        if not 1 <= number <= len(self.maps):
            return None
        self.current = number - 1
        return self.tree(number - 1)


def load_game_folder(path) -> GameFolder:
    """The game in folder ``path`` (module docstring)."""
    folder = Path(path)
    manifest, data = _manifest(folder)
    unknown = sorted(set(data) - set(KEYS))
    if unknown:
        raise LevelError(f"{manifest}: {unknown[0]}: not a key of a game ({', '.join(KEYS)})")
    maps = data.get("maps")
    if not isinstance(maps, list) or not maps:
        raise LevelError(f"{manifest}: maps: a list of level files (at least one)")
    skills = data.get("skills", [])
    if not isinstance(skills, list) or len(skills) > 5 \
            or not all(isinstance(s, str) for s in skills):
        raise LevelError(f"{manifest}: skills: up to five names, easiest first")
    game = GameFolder(folder, str(data.get("name", folder.name)),
                      str(data.get("episode", data.get("name", folder.name))),
                      [_map_entry(folder, manifest, i, m) for i, m in enumerate(maps)],
                      tuple(skills), [_title(manifest, i, m) for i, m in enumerate(maps)])
    game.classes, game.tables = _actors(folder, manifest, data.get("actors"))
    return game


def _toml(raw) -> dict:
    try:
        import tomllib                   # Python 3.11 and later
    except ImportError:
        raise ValueError("a game.toml needs Python 3.11 or later; use game.json") from None
    return tomllib.loads(raw.decode("utf-8"))


def _manifest(folder):
    for name in MANIFESTS:
        path = folder / name
        if path.is_file():
            try:
                raw = path.read_bytes()[:MAX_MANIFEST_BYTES + 1]
                if len(raw) > MAX_MANIFEST_BYTES:
                    raise ValueError("larger than a manifest can be")
                data = json.loads(raw) if name.endswith(".json") else _toml(raw)
            except (OSError, ValueError, UnicodeDecodeError) as e:
                raise LevelError(f"{path}: {e}") from None
            if not isinstance(data, dict):
                raise LevelError(f"{path}: expected an object of game settings")
            return path, data
    raise LevelError(f"{folder}: no game.json or game.toml (a game folder's manifest)")


def _map_entry(folder, manifest, i, entry):
    if isinstance(entry, dict) and isinstance(entry.get("level"), str):
        entry = entry["level"]
    if isinstance(entry, str):
        path = folder / entry
        if not path.is_file():
            raise LevelError(f"{manifest}: maps[{i}]: no level file {entry!r}")
        return path
    if isinstance(entry, dict) and isinstance(entry.get("wad"), str) \
            and isinstance(entry.get("map"), str):
        wad = folder / entry["wad"]
        if not wad.is_file() and Path(entry["wad"]).is_file():
            wad = Path(entry["wad"])
        script = entry.get("script")
        return (wad, entry["map"].upper(), script if isinstance(script, str) else None)
    raise LevelError(f"{manifest}: maps[{i}]: a level file name, {{\"level\": ...}} or "
                     f"{{\"wad\": ..., \"map\": ...}}")


def _title(manifest, i, entry):
    """A map entry's ``"title"`` (the level's name in the intermission), or None."""
    title = entry.get("title") if isinstance(entry, dict) else None
    if title is not None and (not isinstance(title, str) or not 0 < len(title) <= 40):
        raise LevelError(f"{manifest}: maps[{i}].title: a name of 1 to 40 characters")
    return title


def _actors(folder, manifest, actors):
    """(classes, tables) of the game's actors file (DOOM's tables when it has none)."""
    from wallbsp.content import ContentError, classes_of, game_tables
    from wallbsp.doom.tables import DOOM
    if actors is None:
        return [], DOOM
    path = folder / str(actors)
    if not path.is_file():
        raise LevelError(f"{manifest}: actors: {path}: no such file")
    namespace = run_file(path, f"gameactors:{folder.name}")
    classes = classes_of(namespace)
    try:
        return classes, game_tables(classes)
    except ContentError as e:
        raise LevelError(f"{path}: {e}") from None
