"""DOOM's animated flats and wall textures (p_spec.c: ``animdefs``, P_InitPicAnims and the
loop of P_UpdateSpecials), found in a level's resources.

An animation is a run of pictures from a first name to a last, *in the order its source
holds them* (a WAD's lumps between the flat markers, or its TEXTURE1 then TEXTURE2
entries; a folder of PNGs: its names sorted), used only when the source that holds the
first name also holds the last one after it.  Every ``speed`` tics each member shows the
next picture of the run: DOOM's

    pic = basepic + ((leveltime / speed + i) % numpics)    for each number i of the run

where the numbers are the source's own (``first`` is ``basepic``), so member ``k`` of a run
shows member ``(leveltime // speed + first + k) % n`` (``shown``).  P_UpdateSpecials runs
at the end of each tic before ``leveltime`` counts it, so the picture drawn after ``L``
tics is the one of tic ``L - 1``, and before the first tic every name shows itself
(``update_tic``).
"""
from __future__ import annotations

import weakref
from typing import NamedTuple

__all__ = ["ANIMDEFS", "Animation", "animations", "shown", "update_tic"]

# (is a wall texture, first name, last name, tics per picture): DOOM's animdefs, in order
ANIMDEFS = (
    (False, "NUKAGE1", "NUKAGE3", 8), (False, "FWATER1", "FWATER4", 8),
    (False, "SWATER1", "SWATER4", 8), (False, "LAVA1", "LAVA4", 8),
    (False, "BLOOD1", "BLOOD3", 8),
    (False, "RROCK05", "RROCK08", 8), (False, "SLIME01", "SLIME04", 8),
    (False, "SLIME05", "SLIME08", 8), (False, "SLIME09", "SLIME12", 8),
    (True, "BLODGR1", "BLODGR4", 8), (True, "SLADRIP1", "SLADRIP3", 8),
    (True, "BLODRIP1", "BLODRIP4", 8), (True, "FIREWALA", "FIREWALL", 8),
    (True, "GSTFONT1", "GSTFONT3", 8), (True, "FIRELAV3", "FIRELAVA", 8),
    (True, "FIREMAG1", "FIREMAG3", 8), (True, "FIREBLU1", "FIREBLU2", 8),
    (True, "ROCKRED1", "ROCKRED3", 8),
    (True, "BFALL1", "BFALL4", 8), (True, "SFALL1", "SFALL4", 8),
    (True, "WFALL1", "WFALL4", 8), (True, "DBRAIN1", "DBRAIN4", 8),
)


class Animation(NamedTuple):
    """One run: ``kind`` ``"flat"`` or ``"wall"``, its ``names`` in order, ``speed`` (tics
    a picture) and ``first``, the source's number of its first name (DOOM's basepic)."""
    kind: str
    names: tuple
    speed: int
    first: int


def update_tic(leveltime: int):
    """The tic whose P_UpdateSpecials chose the pictures drawn after ``leveltime`` tics, or
    None before the first tic (every name shows itself)."""
    return leveltime - 1 if leveltime > 0 else None


def shown(animation: Animation, k: int, tic: int) -> int:
    """The member of ``animation`` that member ``k`` shows at ``tic`` (DOOM's rule)."""
    return (tic // animation.speed + animation.first + k) % len(animation.names)


_FOUND: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()


def animations(resources) -> tuple:
    """The ``Animation``s of a ``ResourceSet`` (module docstring), found once per set; an
    empty tuple for None."""
    if resources is None:
        return ()
    try:
        found = _FOUND.get(resources)
    except TypeError:                          # an unhashable stand-in: no caching
        return _find(resources)
    if found is None:
        found = _FOUND[resources] = _find(resources)
    return found


def _find(resources) -> tuple:
    found, numbered = [], {}
    for is_wall, start, end, speed in ANIMDEFS:
        kind = "wall" if is_wall else "flat"
        source = next((s for s in resources.sources if s.has(kind, start)), None)
        if source is None:
            continue
        key = (id(source), kind)
        if key not in numbered:
            numbered[key] = _numbers(source, kind)
        numbers = numbered[key]
        first, last = numbers[start], numbers.get(end, -1)
        if last <= first:
            continue                           # DOOM stops with "bad cycle" here
        names = tuple(n for n, i in sorted(numbers.items(), key=lambda item: item[1])
                      if first <= i <= last)
        if all(resources.has(kind, n) for n in names):
            found.append(Animation(kind, names, speed, first))
    return tuple(found)


def _numbers(source, kind: str) -> dict:
    """Name -> number in the source's order: a WAD's own numbers (``WadTextures.numbers``),
    a folder's names sorted."""
    wad = getattr(source, "textures", None)
    if wad is not None and hasattr(wad, "numbers"):
        return wad.numbers(kind)
    return {name: i for i, name in enumerate(sorted(source.names(kind)))}
