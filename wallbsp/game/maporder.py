"""Which map follows which (DOOM's G_DoCompleted): a normal exit goes to the next map, a
secret exit to the secret map, and the secret maps lead back into their episode.

- ``ExMy``: the next map of the episode; a secret exit goes to ``ExM9``, and ``ExM9`` back
  to the map after the one with the secret exit (E1M4, E2M6, E3M7, E4M3); after ``ExM8``
  the next episode's first map.
- ``MAPxx``: the next number; a secret exit from MAP15 goes to MAP31 and from MAP31 to
  MAP32; MAP31 and MAP32 lead to MAP16; MAP30 is the end.
- Any other name: the next map in the WAD's order.

Only maps the WAD has are chosen; None when nothing follows.  ``following_maps`` strings
the maps of one WAD together for the walkthrough.
"""
from __future__ import annotations

import re

__all__ = ["next_map", "following_maps"]

_AFTER_SECRET = {1: 4, 2: 6, 3: 7, 4: 3}       # ExM9 leads on to ExM(this)


def next_map(names, current: str, exit: str = "normal") -> str | None:
    """The map after ``current`` among ``names`` (the WAD's maps) for ``exit``
    (``"normal"`` or ``"secret"``)."""
    present = {n.upper(): n for n in names}
    doom_name, wanted = _doom_next(current.upper(), exit == "secret")
    if doom_name:
        return present.get(wanted)
    order = [n.upper() for n in names]
    if current.upper() in order:
        i = order.index(current.upper())
        return names[i + 1] if i + 1 < len(names) else None
    return None


def following_maps(wad_path, first: str, make_tree, list_maps):
    """``next_level(exit)`` for a walk that starts on map ``first`` of ``wad_path``: the
    tree of the map that follows the one being played (``make_tree(wad_path, name)``), or
    None at the end.  ``list_maps(wad_path)``: the WAD's map names in order."""
    current = [first]

    def following(exit_kind):
        name = next_map(list_maps(wad_path), current[0], exit_kind)
        if name is None:
            return None
        current[0] = name
        return make_tree(wad_path, name)
    return following


def _doom_next(name: str, secret: bool) -> tuple[bool, str | None]:
    """``(whether name is one of DOOM's, the map after it or None at the end)``."""
    episode = re.fullmatch(r"E(\d)M(\d)", name)
    if episode:
        e, m = int(episode.group(1)), int(episode.group(2))
        if secret and m != 9:
            return True, f"E{e}M9"
        if m == 9:
            return True, f"E{e}M{_AFTER_SECRET.get(e, 1)}"
        return True, f"E{e + 1}M1" if m == 8 else f"E{e}M{m + 1}"
    number = re.fullmatch(r"MAP(\d\d)", name)
    if number:
        n = int(number.group(1))
        if secret and n in (15, 31):
            return True, f"MAP{n + 16 if n == 15 else 32}"
        if n in (31, 32):
            return True, "MAP16"
        return True, None if n >= 30 else f"MAP{n + 1:02d}"
    return False, None
