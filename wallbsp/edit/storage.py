"""Opening and saving: a level JSON file or a ``WAD:MAP``; saving writes level JSON
version 2 atomically and keeps the previous file as ``NAME.bak``; ``autosave`` writes
``NAME.autosave`` beside it (or in the temporary folder for a level with no file)."""
from __future__ import annotations

import dataclasses
import shutil
import tempfile
from pathlib import Path

from wallbsp.files import write_atomically
from wallbsp.level.io import dumps_level, level_from_dict, level_to_dict, load_level
from wallbsp.level.wadmap import load_wad_level, parse_wad_spec

__all__ = ["Storage", "read_level"]


def read_level(path_or_wad_map):
    """The level at a path or ``WAD:MAP`` (LevelError, one line, if it is not one)."""
    spec = parse_wad_spec(str(path_or_wad_map))
    if spec is not None:
        return load_wad_level(*spec)
    return load_level(path_or_wad_map)


class Storage:
    """The editor's file commands (mixed into ``Editor``)."""

    @classmethod
    def open(cls, path_or_wad_map, **options):
        """An editor on the level at a path or ``WAD:MAP``.  A WAD map is saved as JSON:
        its path is None until ``save(path)`` names one."""
        level = read_level(path_or_wad_map)
        path = None if parse_wad_spec(str(path_or_wad_map)) else Path(path_or_wad_map)
        return cls(level, path, **options)

    def save(self, path=None) -> Path:
        """Write the level as JSON (version 2) atomically; a file already there is kept as
        ``NAME.bak`` first.  The saved level is validated on the way (it always loads)."""
        path = Path(path) if path is not None else self.path
        if path is None:
            raise ValueError("no file to save to: give a path")
        level = _as_version_2(self.level)
        text = dumps_level(level)
        level_from_dict(level_to_dict(level), source=str(path))
        if path.exists():
            shutil.copy2(path, path.with_name(path.name + ".bak"))
        write_atomically(path, text.encode("utf-8"))
        self.path, self.saved_version = path, self.version
        return path

    @property
    def dirty(self) -> bool:
        """Whether there are edits since the level was opened or last saved."""
        return self.version != self.saved_version

    def autosave(self, force: bool = False) -> Path | None:
        """Write the level to its autosave file if it changed since the last autosave (or
        ``force``); the file written, or None."""
        if not force and getattr(self, "_autosaved", 0) == self.version:
            return None
        base = self.path or Path(tempfile.gettempdir()) / f"{self.level.name or 'untitled'}.json"
        target = base.with_name(base.name + ".autosave")
        write_atomically(target, dumps_level(_as_version_2(self.level)).encode("utf-8"))
        self._autosaved = self.version
        return target


def _as_version_2(level):
    return level if level.version == 2 else dataclasses.replace(level, version=2)

