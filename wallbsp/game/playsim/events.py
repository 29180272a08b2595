"""What happened in a tic, as plain records: the play's event log.

The play appends a record at DOOM's own place for each of these moments; a caller reads
them after the tic (``play.take_events()`` hands over the list and starts a new one;
``play.events`` is the list being filled).  Recording is an append and changes nothing the
simulation does.  Records refer to the play's own objects (``Mobj``, ``Line``,
``Sector``) and plain ints; they are in the order things happened.

- ``Damaged(target, inflictor, source, amount, health)``: ``P_DamageMobj`` took ``amount``
  from ``target``'s health (after skill and armour), leaving ``health`` (may be below 0).
  ``inflictor`` is what hit it (a missile, a monster, None for the world), ``source`` who
  is blamed (None for the world).  A blow ignored (god mode, a thing not shootable) is not
  recorded.
- ``Killed(target, source)``: ``P_KillMobj``: ``target`` dies (``source`` None for the
  world).  A player's death is a ``Killed`` whose ``target.player`` is set.
- ``PickedUp(item, toucher)``: ``P_TouchSpecialThing`` gave ``item`` to ``toucher`` and
  removed it (an item left on the map, a key in a net game, is not recorded).
- ``LineActivated(line, thing, how, side, special)``: ``P_UseSpecialLine``,
  ``P_CrossSpecialLine`` or ``P_ShootSpecialLine`` let ``thing`` trigger ``line``
  (``how``: ``USED``, ``CROSSED`` or ``SHOT``; ``side`` 0 front, 1 back, -1 for a shot;
  ``special``: the line's special then, before a once-only line clears it), before the
  special acts (a door already moving still counts).
- ``SectorEntered(sector, thing)``: ``P_SetThingPosition`` put a shootable ``thing`` (a
  player, a monster, a barrel) in another sector than the one it was in (a teleport too).
- ``SoundStarted(origin, sfx)``: ``S_StartSound``: ``sfx`` (``info.sfx_*``) from
  ``origin`` (a mobj, a sector's sound origin, None: everywhere).
- ``Woke(actor, target)``: ``A_Look``: a monster saw or heard ``target`` and starts
  chasing it.

A log nobody takes is dropped when it grows past ``EVENTS_LIMIT`` records (at the start
of a tic), so a game that never reads it does not grow.
"""
from typing import NamedTuple

__all__ = ["Damaged", "Killed", "PickedUp", "LineActivated", "SectorEntered",
           "SoundStarted", "Woke", "USED", "CROSSED", "SHOT", "EVENTS_LIMIT"]

USED, CROSSED, SHOT = "used", "crossed", "shot"
EVENTS_LIMIT = 1 << 16


class Damaged(NamedTuple):
    target: object
    inflictor: object
    source: object
    amount: int
    health: int


class Killed(NamedTuple):
    target: object
    source: object


class PickedUp(NamedTuple):
    item: object
    toucher: object


class LineActivated(NamedTuple):
    line: object
    thing: object
    how: str
    side: int
    special: int


class SectorEntered(NamedTuple):
    sector: object
    thing: object


class SoundStarted(NamedTuple):
    origin: object
    sfx: int


class Woke(NamedTuple):
    actor: object
    target: object
