"""Rules of DOOM's texture names that the game and the renderer both follow."""
from __future__ import annotations

__all__ = ["switched_name"]


def switched_name(name: str | None) -> str | None:
    """The other texture of a switch pair (``SW1BRCOM`` ↔ ``SW2BRCOM``), or None: DOOM's
    switch list pairs only names of this form, so the rule is the naming convention."""
    if not name:
        return None
    upper = name.upper()
    if upper.startswith("SW1") and len(upper) > 3:
        return "SW2" + name[3:]
    if upper.startswith("SW2") and len(upper) > 3:
        return "SW1" + name[3:]
    return None
