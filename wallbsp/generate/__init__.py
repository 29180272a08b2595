"""Procedural levels (issue 13 part 5): ``generate_level(seed)`` and the walkable-sector
graph ``reachable_sectors(level, start)`` that checks them.

The pipeline position: below ``build`` (it makes ``Level`` objects), above ``level``.
"""
from wallbsp.generate.generator import DEFAULT_WALLS, GOALS, GeneratedLevel, generate_level
from wallbsp.generate.reach import reachable_sectors, sector_links
from wallbsp.assets.catalogue import TARGET_TYPE

__all__ = ["DEFAULT_WALLS", "GOALS", "GeneratedLevel", "TARGET_TYPE", "generate_level",
           "reachable_sectors", "sector_links"]
