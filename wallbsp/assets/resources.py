"""A level's texture sources (SPEC §2b, §4b): DOOM WADs and folders of PNG images, searched in
order, each read lazily (only the pictures asked for) and cached per source.

    res = ResourceSet.from_level(level)      # level.resource_paths(), in order
    res = ResourceSet(["freedoom2.wad", "mytextures/"])
    res = shared_resources(level.resource_paths())   # one set for every level naming the
                                                     # same unchanged sources
    res.wall("STARTAN3")      # a wall texture (the sky textures live here too), or None
    res.flat("FLOOR4_8")      # a flat, or None
    res.sprite("POSSA1")      # a sprite lump by its full name, or None
    res.sprite_frame("POSS", "A", 3)   # (Picture, mirrored) for rotation 1..8, or None
    res.sky(level)            # the level's sky texture: level.sky, else DOOM's for the map name
    res.palette               # 256 × 3 uint8: PLAYPAL palette 0 of the first WAD that has one
    res.colormap              # 34 × 256 uint8: COLORMAP of the first WAD that has one, or None
    res.has("flat", "NUKAGE1")          # a name looked up without decoding anything
    res.missing(level)        # warnings for the texture and flat names no source holds

Every picture is a ``Picture`` (``wallbsp.assets.pictures``): ``pixels[x, y]`` column-major
(``width × height``, a wall column is ``pixels[u]``), ``mask[x, y]`` True where opaque, and
``left``/``top`` (DOOM's sprite offsets). WAD pictures are uint8 palette indices
(``picture.paletted``) for ``palette`` and ``colormap``; PNG pictures are RGB
(``width × height × 3`` uint8). Flats are 64 × 64, indexed ``pixels[x mod 64, -y mod 64]``.
Names are case-insensitive (DOOM's are upper case).

Sources
- A WAD (any regular file): wall textures from TEXTURE1/TEXTURE2 composited from PNAMES
  patches (transparent where no patch covers a texel), flats between F_START..F_END or
  FF_START..FF_END (nested F1_/F2_ markers included), sprites between S_START..S_END or
  SS_START..SS_END, PLAYPAL, COLORMAP. A set with no PLAYPAL at all has no colours for WAD
  pictures: they count as missing. A texture's patches are looked up in its own WAD (a PWAD
  whose TEXTURE1 uses the IWAD's patches must carry them).
- A folder: ``NAME.png`` files are wall textures, ``flats/NAME.png`` flats (64 × 64),
  ``sprites/NAME.png`` sprites (offsets: left = width // 2, top = height: centred, feet at the
  bottom). Alpha below 128 is transparent. Read with ``pygame.image.load`` (no window needed),
  after the PNG header's size is checked, so a tiny file cannot ask for a huge picture.

Damaged or unreadable sources are one ``ResourceError`` line (a ``LevelError``: the command
line prints it and exits 2) naming the file and the lump: ``e1.wad: TEXTURE1: texture 5 at
offset 90000 lies past the end of the lump (2100 bytes)``, ``tex/brick.png: not a PNG image``.
"""
from __future__ import annotations

import os
import re
import struct
from collections import OrderedDict
from typing import TYPE_CHECKING
from pathlib import Path

import numpy as np

from wallbsp.assets.catalogue import SKY_FLAT
from wallbsp.files import InputError, LevelError, open_regular
from wallbsp.assets.pictures import FLAT_SIDE, Picture, ResourceError, check_size
from wallbsp.assets.wadtextures import BUDGET_BYTES, wad_textures

if TYPE_CHECKING:                    # a level names its resources; assets sit below levels
    from wallbsp.level.model import Level

__all__ = ["Picture", "PngFolder", "ResourceError", "ResourceSet", "forget_shared_resources",
           "shared_resources", "sky_name"]

OPAQUE_ALPHA = 128
MAX_NOTED = 20
_PNG_MAGIC = b"\x89PNG\r\n\x1a\n"
_PNG_HEAD = struct.Struct(">8sI4sII")     # magic, IHDR length, "IHDR", width, height
_FOLDER_OF = {"wall": "", "flat": "flats", "sprite": "sprites"}
_SPRITE_NAME = re.compile(r"([A-Z0-9_\[\]\\-]{4})([A-Z\[\]\\])([0-8])(?:([A-Z\[\]\\])([0-8]))?")
_FOLDERS: OrderedDict[tuple, "PngFolder"] = OrderedDict()
_FOLDER_CACHE_SIZE = 8
_SHARED: OrderedDict[tuple, "ResourceSet"] = OrderedDict()
_SHARED_CACHE_SIZE = 8


def sky_name(map_name: str) -> str:
    """DOOM's sky texture for a map: SKY1-SKY4 by episode for ExMy; SKY1, SKY2, SKY3 for
    MAP01-11, 12-20, 21-32. A map name may be followed by more text (``"E1M1 (doom.wad)"``)."""
    m = re.match(r"\s*(?:E(\d)M\d|MAP(\d\d))", map_name, re.IGNORECASE)
    if m and m.group(1):
        return f"SKY{min(max(int(m.group(1)), 1), 4)}"
    if m:
        number = int(m.group(2))
        return "SKY1" if number < 12 else "SKY2" if number < 21 else "SKY3"
    return "SKY1"


class ResourceSet:
    """The texture sources of a level, searched in order (see the module's docstring)."""

    def __init__(self, paths):
        self.sources = [_open_source(Path(p)) for p in paths]
        self._sprite_frames: list[dict] | None = None
        self._found: dict[tuple[str, str], Picture | None] = {}    # lookups answered
        self._tables: dict[str, np.ndarray | None] = {}

    @classmethod
    def from_level(cls, level: Level) -> "ResourceSet":
        return cls(level.resource_paths())

    # -- lookups ----------------------------------------------------------------------------
    def wall(self, name: str) -> Picture | None:
        return self._find("wall", name)

    def flat(self, name: str) -> Picture | None:
        return self._find("flat", name)

    def sprite(self, name: str) -> Picture | None:
        return self._find("sprite", name)

    def has(self, kind: str, name: str) -> bool:
        """Whether a source holds ``name`` in namespace ``kind`` (nothing is decoded)."""
        name = name.upper()
        return any(_guard(lambda: s.has(kind, name)) for s in self._usable())

    def sky(self, level: Level) -> Picture | None:
        return self.wall(level.sky or sky_name(level.name))

    def sprite_frame(self, sprite: str, frame: str, rotation: int):
        """``(picture, mirrored)`` for a sprite's frame seen from rotation 1..8 (DOOM's
        R_InstallSpriteLump naming: ``POSSA1``, ``POSSA2A8`` (A8 mirrored), ``POSSA0`` for
        every rotation), from the first source that has it; None when none has."""
        if self._sprite_frames is None:
            self._sprite_frames = [_guard(lambda: _sprite_frames(s.names("sprite")))
                                   for s in self._usable()]
        sprite, frame = sprite.upper(), frame.upper()
        for source, frames in zip(self._usable(), self._sprite_frames):
            found = frames.get((sprite, frame, rotation)) or frames.get((sprite, frame, 0))
            if found:
                return _guard(lambda: source.picture("sprite", found[0])), found[1]
        return None

    @property
    def palette(self) -> np.ndarray | None:
        return self._first_table("palette")

    @property
    def colormap(self) -> np.ndarray | None:
        return self._first_table("colormap")

    def missing(self, level: Level) -> list[str]:
        """One warning per texture or flat name the level uses that no source holds, at its
        first use: ``e1.json: walls[3].front_side.middle: texture BRICK7 not found``."""
        notes, seen = [], set()
        for kind, place, name in _used_names(level):
            key = (kind, name.upper())
            if key not in seen:
                seen.add(key)
                if not self.has(kind, name):
                    what = "texture" if kind == "wall" else kind
                    notes.append(f"{level.source}: {place}: {what} {name} not found in the "
                                 f"level's resources; its colour is drawn")
        if len(notes) > MAX_NOTED:
            notes[MAX_NOTED:] = [f"{level.source}: ... and {len(notes) - MAX_NOTED} more "
                                 f"names not found"]
        return notes

    # -- the search -------------------------------------------------------------------------
    def _usable(self) -> list:
        # WAD pictures are palette indices: without a palette they cannot be drawn
        if self.palette is None:
            return [s for s in self.sources if isinstance(s, PngFolder)]
        return self.sources

    def _find(self, kind: str, name: str) -> Picture | None:
        key = (kind, name.upper())
        if key not in self._found:
            self._found[key] = next(
                (p for p in (_guard(lambda: s.picture(*key)) for s in self._usable())
                 if p is not None), None)
        return self._found[key]

    def _first_table(self, which: str):
        if which not in self._tables:
            self._tables[which] = next(
                (t for t in (_guard(lambda: getattr(s, which)) for s in self.sources)
                 if t is not None), None)
        return self._tables[which]


def shared_resources(paths) -> ResourceSet:
    """The ``ResourceSet`` of ``paths``, shared by every caller naming the same sources while
    none of them changes (each source's resolved path and stamp: a WAD's inode, size and
    modification time, a folder's and its ``flats``/``sprites`` subfolders' modification
    times), so levels drawn from one texture folder decode and look up each picture once.
    The last few sets are kept; a forked process starts with none (a WAD source keeps its
    file open, and a parent and child reading through one handle would race)."""
    paths = [Path(p) for p in paths]
    key = tuple((os.path.realpath(p), _stamp(p)) for p in paths)
    found = _SHARED.get(key)
    if found is None:
        found = ResourceSet(paths)
        _SHARED[key] = found
        while len(_SHARED) > _SHARED_CACHE_SIZE:
            _SHARED.popitem(last=False)
    else:
        _SHARED.move_to_end(key)
    return found


def forget_shared_resources() -> None:
    """Empties the cache of ``shared_resources`` (done in every forked child)."""
    _SHARED.clear()


os.register_at_fork(after_in_child=forget_shared_resources)


def _stamp(path: Path):
    if path.is_dir():
        return _folder_stamp(path)
    try:
        st = path.stat()
    except OSError:
        return None                         # ResourceSet says what is wrong with it
    return (st.st_ino, st.st_size, st.st_mtime_ns, st.st_ctime_ns)


def _guard(call):
    """``call()``, with the archive's errors (a LevelError naming the WAD) as ResourceErrors."""
    try:
        return call()
    except ResourceError:
        raise
    except LevelError as e:
        raise ResourceError(str(e)) from None


def _open_source(path: Path):
    if path.is_dir():
        return png_folder(path)
    if not path.exists():
        raise ResourceError(f"{path}: cannot read: no such file or folder")
    if not path.is_file():
        raise ResourceError(f"{path}: not a WAD file or a folder of PNG images")
    return _WadSource(_guard(lambda: wad_textures(path)))


class _WadSource:
    """A WAD's pictures behind the same three-namespace interface as a PNG folder."""

    def __init__(self, textures):
        self.textures = textures

    def has(self, kind: str, name: str) -> bool:
        return getattr(self.textures, f"has_{kind}")(name)

    def names(self, kind: str) -> list[str]:
        return getattr(self.textures, f"{kind}_names")()

    def picture(self, kind: str, name: str) -> Picture | None:
        return getattr(self.textures, kind)(name)

    @property
    def palette(self):
        return self.textures.palette

    @property
    def colormap(self):
        return self.textures.colormap


def _sprite_frames(names: list[str]) -> dict:
    """(sprite, frame, rotation) -> (lump name, mirrored) for a source's sprite names."""
    frames: dict = {}
    for name in names:
        m = _SPRITE_NAME.fullmatch(name)
        if m:
            frames[(m.group(1), m.group(2), int(m.group(3)))] = (name, False)
            if m.group(4):
                frames[(m.group(1), m.group(4), int(m.group(5)))] = (name, True)
    return frames


def _used_names(level: Level):
    """(namespace, JSON path, name) for every texture and flat name the level uses."""
    for i, wall in enumerate(level.walls):
        for side_key in ("front_side", "back_side"):
            side = getattr(wall, side_key)
            for part in ("upper", "middle", "lower"):
                name = getattr(side, part) if side is not None else None
                if name is not None:
                    yield "wall", f"walls[{i}].{side_key}.{part}", name
    for i, sector in enumerate(level.sectors):
        for key in ("floor_texture", "ceiling_texture"):
            name = getattr(sector, key)
            if name is not None and name.upper() != SKY_FLAT:
                yield "flat", f"sectors[{i}].{key}", name


# ---------------------------------------------------------------------------------------------
# PNG folders

def png_folder(path: Path) -> "PngFolder":
    """The PNG folder at ``path``, shared while the folder (and its subfolders) are unchanged."""
    key = (os.path.realpath(path),) + _folder_stamp(path)
    folder = _FOLDERS.get(key)
    if folder is None:
        folder = _FOLDERS[key] = PngFolder(path)
        while len(_FOLDERS) > _FOLDER_CACHE_SIZE:
            _FOLDERS.popitem(last=False)
    return folder


def _folder_stamp(path: Path) -> tuple:
    return tuple(_mtime(path / sub) for sub in ("", "flats", "sprites"))


def _mtime(path: Path) -> int | None:
    try:
        return path.stat().st_mtime_ns
    except OSError:
        return None


class PngFolder:
    """A folder of PNG pictures: ``NAME.png`` walls, ``flats/``, ``sprites/``."""
    palette = None
    colormap = None

    def __init__(self, path: Path):
        self.path = Path(path)
        self._index: dict[str, dict[str, Path]] = {}
        self._pictures: dict[tuple[str, str], Picture] = {}
        self.decoded_bytes = 0

    def names(self, kind: str) -> list[str]:
        return list(self._files(kind))

    def has(self, kind: str, name: str) -> bool:
        return name in self._files(kind)

    def picture(self, kind: str, name: str) -> Picture | None:
        path = self._files(kind).get(name)
        if path is None:
            return None
        key = (kind, name)
        if key not in self._pictures:
            picture = _read_png(path, kind)
            self.decoded_bytes += picture.nbytes
            if self.decoded_bytes > BUDGET_BYTES:
                raise ResourceError(f"{path}: decoded pictures of {self.path} exceed "
                                    f"{BUDGET_BYTES >> 20} MB; refused")
            self._pictures[key] = picture
        return self._pictures[key]

    def _files(self, kind: str) -> dict[str, Path]:
        if kind not in self._index:
            folder = self.path / _FOLDER_OF[kind]
            try:
                entries = sorted(folder.iterdir()) if folder.is_dir() else []
            except OSError as e:
                raise ResourceError(f"{folder}: cannot read: {e.strerror or e}") from None
            files: dict[str, Path] = {}
            for entry in entries:
                if entry.suffix.lower() == ".png" and entry.is_file():
                    files.setdefault(entry.stem.upper(), entry)
            self._index[kind] = files
        return self._index[kind]


def _read_png(path: Path, kind: str) -> Picture:
    width, height = _png_size(path)
    check_size(str(path), width, height)
    if kind == "flat" and (width, height) != (FLAT_SIDE, FLAT_SIDE):
        raise ResourceError(f"{path}: a flat is {FLAT_SIDE} × {FLAT_SIDE}, this picture is "
                            f"{width} × {height}")
    import pygame      # only folders of PNGs need it; the import costs a tenth of a second
    try:
        surface = pygame.image.load(str(path))
        rgb = pygame.surfarray.array3d(surface)
        alpha = pygame.surfarray.array_alpha(surface)
    except (pygame.error, OSError, ValueError) as e:
        raise ResourceError(f"{path}: not a readable PNG image ({e})") from None
    if rgb.shape[:2] != (width, height):
        raise ResourceError(f"{path}: the PNG header says {width} × {height}, the image is "
                            f"{rgb.shape[0]} × {rgb.shape[1]}")
    left, top = (width // 2, height) if kind == "sprite" else (0, 0)
    return Picture(np.ascontiguousarray(rgb), alpha >= OPAQUE_ALPHA, left, top)


def _png_size(path: Path) -> tuple[int, int]:
    try:
        with open_regular(path) as f:   # before pygame sees it: a FIFO would block
            head = f.read(_PNG_HEAD.size)
    except InputError as e:
        raise ResourceError(f"{path}: cannot read: {e.reason}") from None
    except OSError as e:
        raise ResourceError(f"{path}: cannot read: {e.strerror or e}") from None
    if len(head) < _PNG_HEAD.size or not head.startswith(_PNG_MAGIC):
        raise ResourceError(f"{path}: not a PNG image")
    _, _, chunk, width, height = _PNG_HEAD.unpack(head)
    if chunk != b"IHDR":
        raise ResourceError(f"{path}: not a PNG image (no IHDR chunk first)")
    return width, height
