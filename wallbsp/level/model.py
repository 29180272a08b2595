"""The level model (SPEC §2, §2b): frozen dataclasses whose field names are the JSON names.

Reading, validating and writing the JSON file are in ``levelio``; the exact search for
crossing, overlapping and duplicate walls is in ``conflicts``.  Equality (``==``) is about
content: ``source``, ``warnings`` and ``source_dir`` are where a level came from, not what
it is, and are not compared (nor hashed by ``levelio.content_hash``).

A ``Level`` holds lists (``vertices``, ``sectors``, ``walls``) for speed and for the
callers that build levels in code; frozen means the fields are never reassigned, so treat
the lists as read-only too.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from wallbsp.files import LevelError
from wallbsp.level.format import NO_TEXTURE, WALL_LINE_BITS

SKY_FLAT = "F_SKY1"      # DOOM's ceiling flat that means "open sky"


@dataclass(frozen=True)
class Side:
    """The textures of one side of a wall (DOOM's sidedef); None: no texture."""
    upper: str | None = None
    middle: str | None = None
    lower: str | None = None
    x_offset: int = 0
    y_offset: int = 0

    def __post_init__(self):
        for part in ("upper", "middle", "lower"):
            if getattr(self, part) == NO_TEXTURE:
                object.__setattr__(self, part, None)


@dataclass(frozen=True)
class Sector:
    floor: float
    ceiling: float
    light: int = 160
    floor_color: str = "#5a4a3a"
    ceiling_color: str = "#303038"
    sky: bool = False
    floor_texture: str | None = None
    ceiling_texture: str | None = None
    special: int = 0
    tag: int = 0

    def __post_init__(self):
        for part in ("floor_texture", "ceiling_texture"):
            if getattr(self, part) == NO_TEXTURE:        # DOOM's "-", as in a file
                object.__setattr__(self, part, None)
        # DOOM draws a ceiling flat named F_SKY1 as the sky; one flag says so everywhere
        if self.ceiling_texture is not None and self.ceiling_texture.upper() == SKY_FLAT:
            object.__setattr__(self, "sky", True)

    @property
    def sky_from_texture(self) -> bool:
        """Whether ``sky`` follows from the ceiling texture (so a file need not say it)."""
        return self.ceiling_texture is not None and self.ceiling_texture.upper() == SKY_FLAT


@dataclass(frozen=True)
class Wall:
    v1: int
    v2: int
    front: int
    back: int | None = None
    color: str = "#8c8c8c"
    upper_color: str | None = None   # None: same as color
    lower_color: str | None = None   # None: same as color
    front_side: Side | None = None   # None: no textures, the colours are drawn
    back_side: Side | None = None
    upper_unpegged: bool = False
    lower_unpegged: bool = False
    blocks: bool = False             # a two-sided wall that nothing walks through
    special: int = 0
    tag: int = 0
    secret: bool = False             # DOOM's ML_SECRET: one-sided on the automap
    blocks_sound: bool = False       # DOOM's ML_SOUNDBLOCK: the second one stops a sound
    hidden: bool = False             # DOOM's ML_DONTDRAW: never on the automap

    @property
    def line_bits(self) -> int:
        """DOOM's linedef bits of ``secret``, ``blocks_sound`` and ``hidden``."""
        return sum(bit for key, bit in WALL_LINE_BITS.items() if getattr(self, key))

    @property
    def drawn_upper_color(self) -> str:
        return self.color if self.upper_color is None else self.upper_color

    @property
    def drawn_lower_color(self) -> str:
        return self.color if self.lower_color is None else self.lower_color


@dataclass(frozen=True)
class Start:
    x: float
    y: float
    angle: float = 90.0


@dataclass(frozen=True)
class Thing:
    """A thing of DOOM's THINGS lump: editor number ``type``, skill/ambush/multiplayer
    ``flags`` bits as DOOM's."""
    x: int
    y: int
    angle: float
    type: int
    flags: int = 7        # skills 1-5, single player: what map editors give a new thing


@dataclass(frozen=True)
class ThingType:
    """A level's own thing type: what it looks like and how big it is."""
    sprite: str
    radius: float = 20      # DOOM's mobjinfo defaults
    height: float = 16
    solid: bool = False


@dataclass(frozen=True)
class Level:
    name: str
    vertices: list[tuple[int, int]]
    sectors: list[Sector]
    walls: list[Wall]
    start: Start
    version: int = 1
    resources: tuple[str, ...] = ()
    things: tuple[Thing, ...] = ()
    thing_types: dict[int, ThingType] = field(default_factory=dict)
    sky: str | None = None
    script: str | None = None       # a Python file of level scripts, relative like resources
    # where a level came from and what was suspicious about it are not its content
    source: str = field(default="<level>", compare=False)   # the file name used in messages
    warnings: list[str] = field(default_factory=list, compare=False)
    source_dir: Path | None = field(default=None, compare=False)   # resources are relative to it

    def segments(self) -> np.ndarray:
        """The walls' ends as an ``(n, 4)`` int64 array of ``x1, y1, x2, y2`` (v1 → v2)."""
        vertices = np.array(self.vertices, dtype=np.int64).reshape(-1, 2)
        ends = np.fromiter((v for w in self.walls for v in (w.v1, w.v2)), np.int64,
                           2 * len(self.walls))
        return vertices[ends].reshape(-1, 4)

    def script_path(self) -> Path | None:
        """``script`` as a path (relative to the level file's folder), or None."""
        if self.script is None:
            return None
        return (self.source_dir if self.source_dir is not None else Path()) / self.script

    def resource_paths(self) -> tuple[Path, ...]:
        """``resources`` as paths: relative ones from the level file's folder (the current
        folder for a level that did not come from a file)."""
        base = self.source_dir if self.source_dir is not None else Path()
        return tuple(base / r for r in self.resources)
