"""Opening and saving: a level JSON file or a ``WAD:MAP``; saving writes level JSON
version 2 atomically and keeps the previous file as ``NAME.bak``; ``autosave`` writes
``NAME.autosave`` beside it (or in the temporary folder for a level with no file);
``export`` writes a DOOM PWAD with the node builder's nodes (``wallbsp.nodes.export``), for
Chocolate Doom and other ports."""
from __future__ import annotations

import dataclasses
import re
import shutil
import tempfile
from pathlib import Path

from wallbsp.files import write_atomically
from wallbsp.level.io import dumps_level, level_from_dict, level_to_dict, load_level
from wallbsp.level.wadmap import load_wad_level, parse_wad_spec

__all__ = ["Storage", "iwad_of", "map_name_of", "read_level"]


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

    def export(self, path, map_name: str | None = None, fmt: str = "doom", iwad=None) -> list:
        """Write the level as a DOOM PWAD at ``path`` (``fmt`` ``"doom"``: the DOOM format
        with nodes, blockmap and reject from wallbsp's node builder; ``"udmf"``: UDMF).
        ``map_name``: by default the map the level came from, else MAP01; ``iwad``: by
        default the level's IWAD resource, whose missing texture names are replaced.  The
        notes to show (names replaced, things left out).  Play it with
        ``chocolate-doom -iwad IWAD -file OUT.wad -warp 1 1`` (or ``-warp 1`` for MAPxx)."""
        from wallbsp.nodes.export import export_level
        if fmt not in ("doom", "udmf"):
            raise ValueError(f"export format is 'doom' or 'udmf', not {fmt!r}")
        iwad = iwad if iwad is not None else iwad_of(self.level)
        return export_level(self.level, path, map_name or map_name_of(self.level), fmt,
                            None if iwad is None else str(iwad))

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


_MAP_NAME = re.compile(r"E[1-9]M[1-9]|MAP[0-9][0-9]", re.IGNORECASE)


def map_name_of(level) -> str:
    """The map a level came from (``E1M1`` of ``freedoom1.wad:E1M1``, or a level named like
    a map), else ``MAP01``."""
    for text in (str(level.source).rsplit(":", 1)[-1], level.name):
        if _MAP_NAME.fullmatch(text or ""):
            return text.upper()
    return "MAP01"


def iwad_of(level) -> Path | None:
    """The level's first resource that is an IWAD (whose names an export checks), if any."""
    for path in level.resource_paths():
        if path.suffix.lower() == ".wad" and path.is_file():
            with open(path, "rb") as f:
                if f.read(4) == b"IWAD":
                    return path
    return None


def _as_version_2(level):
    return level if level.version == 2 else dataclasses.replace(level, version=2)

