"""Pictures of textures, flats and things for the panel and the browsers, from the level's
resources (its WADs and PNG folders: ``assets.resources``), made into small pygame
surfaces once and kept.  A level with no resources has no pictures: the names are shown.
"""
from __future__ import annotations

import pygame

from wallbsp.assets.resources import ResourceError, shared_resources
from wallbsp.editor.thingkinds import kind_of

__all__ = ["Pictures", "KINDS", "pictures_of"]

KINDS = ("walls", "flats", "things")
_NAMESPACE = {"walls": "wall", "flats": "flat"}


class Pictures:
    """The level's pictures as thumbnails: ``thumbnail(kind, name, side)``; ``names(kind)``."""

    def __init__(self, level):
        self.paths = level.resource_paths()
        try:
            self.resources = shared_resources(self.paths) if self.paths else None
        except ResourceError:
            self.resources = None
        self._thumbs = {}
        self._names = {}

    def names(self, kind: str) -> list:
        """Every texture or flat name the sources hold (sorted), or thing types."""
        if kind == "things":
            from wallbsp.editor.thingkinds import known_types
            return list(known_types())
        if kind not in self._names:
            found = set()
            for source in self.resources.sources if self.resources else ():
                try:
                    found.update(n.upper() for n in source.names(_NAMESPACE[kind]))
                except (ResourceError, OSError):
                    continue
            self._names[kind] = sorted(found)
        return self._names[kind]

    def thumbnail(self, kind: str, name, side: int):
        """A surface at most ``side`` pixels square, or None (no picture)."""
        key = (kind, name, side)
        if key not in self._thumbs:
            self._thumbs[key] = self._make(kind, name, side)
        return self._thumbs[key]

    def _make(self, kind, name, side):
        if self.resources is None or name is None:
            return None
        try:
            picture = self._picture(kind, name)
            if picture is None:
                return None
            palette = self.resources.palette
            if picture.paletted and palette is None:
                return None
            rgb = picture.rgb(palette)
        except (ResourceError, OSError):
            return None
        surface = pygame.surfarray.make_surface(rgb)
        surface.set_colorkey(None)
        w, h = surface.get_size()
        scale = min(side / w, side / h, 2.0)
        size = (max(1, int(w * scale)), max(1, int(h * scale)))
        return pygame.transform.scale(surface, size)

    def _picture(self, kind, name):
        if kind == "walls":
            return self.resources.wall(name)
        if kind == "flats":
            return self.resources.flat(name)
        sprite = kind_of(int(name)).sprite
        if sprite is None:
            return None
        found = self.resources.sprite_frame(sprite, "A", 1)
        return found[0] if found else self.resources.sprite(sprite + "A0")


def pictures_of(session) -> Pictures:
    """The session's level's pictures, made again when the level names other resources."""
    level = session.level
    if session.pictures is None or session.pictures.paths != level.resource_paths():
        session.pictures = Pictures(level)
    return session.pictures
