"""Picking things up and being stopped by them: DOOM's PIT_CheckThing and P_TouchSpecialThing.

- ``touch_pickups(things, inventory, x, y, z, ...)``: the player at (x, y) with feet at ``z``
  touches every item (MF_SPECIAL) whose box meets its own (``|dx|, |dy| < 16 + radius``)
  and that is within reach in height (the item's feet no more than 8 below the player's
  feet and no higher than its head, 56 above them).  Each one the inventory takes is
  removed from the world; one it refuses stays where it is.  Call it after the player's
  move every tic, at the new position (DOOM touches items while checking the new spot).
- ``blocked_at(things, x, y)``: whether a player there overlaps a solid thing's box
  (DOOM's P_CheckPosition refusal).  ``queries.move`` keeps the player out of those
  boxes itself: their sides (``segments.box_sides`` of ``Things.solid_boxes``) block its
  sweep as walls do.
"""
from __future__ import annotations

from wallbsp.sim.queries import PLAYER_HEIGHT, PLAYER_RADIUS
from wallbsp.sim.thingtypes import COUNTITEM, SOLID, SPECIAL
from wallbsp.game.inventory import BLUE, GREEN, Inventory

__all__ = ["PLAYER_RADIUS", "PLAYER_HEIGHT", "BELOW_REACH", "pick_up", "touch_pickups",
           "blocked_at"]

BELOW_REACH = 8          # an item this far below the feet can still be picked up


def pick_up(inventory: Inventory, pickup) -> bool:
    """Give ``pickup`` (a ``thingtypes.Pickup``) to the inventory by DOOM's rules; whether it
    was taken."""
    kind, item, amount, limit = pickup.kind, pickup.item, pickup.amount, pickup.limit
    if kind == "health":
        if item == "megasphere":
            inventory.health = limit
            inventory.give_armour(BLUE)
            return True
        if limit > 100:
            return inventory.give_bonus_health(amount, limit)
        return inventory.give_body(amount)
    if kind == "armour":
        if limit > amount:
            return inventory.give_bonus_armour(amount, limit)
        return inventory.give_armour(BLUE if amount >= 200 else GREEN)
    if kind == "ammo":
        if item == "backpack":
            return inventory.give_backpack()
        return inventory.give_ammo(item, amount)
    if kind == "weapon":
        return inventory.give_weapon(item, pickup.ammo, amount)
    if kind == "key":
        return inventory.give_key(item)
    if kind == "powerup":
        return inventory.give_power(item, amount)
    raise ValueError(f"unknown pickup kind {kind!r}")


def touch_pickups(things, inventory: Inventory, x, y, z, floor, ceiling,
                  radius=PLAYER_RADIUS, height=PLAYER_HEIGHT) -> list:
    """Pick up what the player touches (module docstring); ``floor``/``ceiling``: the
    sectors' heights now (for the items' feet).  Returns ``[(thing, message), ...]`` for
    the items taken, which are removed from ``things``."""
    near = things.overlapping(x, y, radius, SPECIAL)
    if not near.size:
        return []
    delta = things.feet(near, floor, ceiling) - z
    near = near[(delta <= height) & (delta >= -BELOW_REACH)]
    taken = []
    for i in near.tolist():
        info = things.info(i)
        if info is None or info.pickup is None or not pick_up(inventory, info.pickup):
            continue
        if info.flags & COUNTITEM:
            inventory.items += 1
        things.remove(i)
        taken.append((i, f"Picked up the {info.name}."))
    return taken


def blocked_at(things, x, y, radius=PLAYER_RADIUS) -> bool:
    """Whether a mover of ``radius`` at (x, y) overlaps a solid thing's box (DOOM refuses
    such a move: P_CheckPosition)."""
    return bool(things.overlapping(x, y, radius, SOLID).size)
