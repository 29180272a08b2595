"""Pickups and solid things: DOOM's P_TouchSpecialThing and PIT_CheckThing (wallbsp.game)."""
import math

from game_levels import corridor, room, rules_for, wall_between

from wallbsp.game.inventory import Inventory
from wallbsp.game.pickups import blocked_at, pick_up, touch_pickups
from wallbsp.level.model import Thing
from wallbsp.sim.collision import slide
from wallbsp.sim.thingtypes import DOOM_THING_TYPES

STIMPACK, MEDIKIT, BONUS, SOUL, MEGA = 2011, 2012, 2014, 2013, 83
GREEN_ARMOUR, BLUE_ARMOUR, ARMOUR_BONUS = 2018, 2019, 2015
CLIP, BULLET_BOX, BACKPACK, SHOTGUN, CHAINSAW = 2007, 2048, 8, 2001, 2005
BLUE_CARD, BLUE_SKULL, RED_CARD = 5, 40, 13
BERSERK, COMPUTER_MAP = 2023, 2026
BARREL = 2035


def give(inventory, thing_type):
    return pick_up(inventory, DOOM_THING_TYPES[thing_type].pickup)


def test_health_as_doom_counts_it():
    inv = Inventory()
    assert not give(inv, STIMPACK) and inv.health == 100          # refused at 100
    inv.health = 50
    assert give(inv, STIMPACK) and inv.health == 60
    inv.health = 90
    assert give(inv, MEDIKIT) and inv.health == 100               # up to 100 only
    assert give(inv, BONUS) and inv.health == 101                 # bonuses go over 100
    assert give(inv, SOUL) and inv.health == 200
    assert give(inv, SOUL) and inv.health == 200                  # still taken at 200
    inv = Inventory(health=20)
    assert give(inv, MEGA) and (inv.health, inv.armour, inv.armour_class) == (200, 200, 2)


def test_armour_as_doom_counts_it():
    inv = Inventory()
    assert give(inv, GREEN_ARMOUR) and (inv.armour, inv.armour_class) == (100, 1)
    assert not give(inv, GREEN_ARMOUR)                            # not lower: stays
    assert give(inv, BLUE_ARMOUR) and (inv.armour, inv.armour_class) == (200, 2)
    assert not give(inv, GREEN_ARMOUR) and inv.armour == 200
    inv = Inventory()
    assert give(inv, ARMOUR_BONUS) and (inv.armour, inv.armour_class) == (1, 1)


def test_ammo_weapons_and_backpack_as_doom_counts_them():
    inv = Inventory()
    assert give(inv, CLIP) and inv.ammo["bullets"] == 60
    inv.ammo["bullets"] = 195
    assert give(inv, BULLET_BOX) and inv.ammo["bullets"] == 200
    assert not give(inv, CLIP)                                    # full: it stays
    assert give(inv, SHOTGUN) and "shotgun" in inv.weapons and inv.ammo["shells"] == 8
    inv.ammo["shells"] = 50
    assert not give(inv, SHOTGUN)                                 # owned, shells full
    assert give(inv, CHAINSAW) and not give(inv, CHAINSAW)
    assert give(inv, BACKPACK) and inv.max_ammo["bullets"] == 400
    assert inv.ammo["bullets"] == 210 and inv.ammo["cells"] == 20
    assert give(inv, BACKPACK) and inv.max_ammo["bullets"] == 400   # doubled once
    easy = Inventory(skill=1)
    assert give(easy, CLIP) and easy.ammo["bullets"] == 70         # double on skill 1


def test_keys_powers_and_what_locked_doors_are_told():
    inv = Inventory()
    assert give(inv, BLUE_SKULL) and give(inv, BLUE_CARD) and give(inv, RED_CARD)
    assert inv.door_keys == {"blue", "red"}
    inv.health = 30
    assert give(inv, BERSERK) and inv.health == 100 and "berserk" in inv.powers
    assert give(inv, COMPUTER_MAP) and not give(inv, COMPUTER_MAP)


def pickup_world(things):
    level = corridor([room(), room()], things=things)
    rules, state = rules_for(level)
    return level, rules, state


def touch(state, inv, x, y, z=0.0):
    return touch_pickups(state.things, inv, x, y, z, state.floor, state.ceiling)


def test_touching_takes_the_item_and_it_disappears():
    _, _, state = pickup_world([Thing(64, 64, 0, MEDIKIT, 7), Thing(96, 64, 0, STIMPACK, 7)])
    inv = Inventory(health=40)
    # boxes, not circles: 16 + 20 = 36 on each axis, so a diagonal 35 away touches
    taken = touch(state, inv, 64 + 35, 64 - 35)
    assert [i for i, _ in taken] == [0, 1] and inv.health == 75
    assert not state.things.alive[0] and not state.things.alive[1]
    assert touch(state, inv, 64, 64) == []                       # gone for good


def test_a_refused_item_stays_and_far_items_are_not_touched():
    _, _, state = pickup_world([Thing(64, 64, 0, STIMPACK, 7)])
    inv = Inventory()
    assert touch(state, inv, 64, 64) == [] and state.things.alive[0]   # 100 health
    inv.health = 10
    assert touch(state, inv, 64 + 36, 64) == []                  # exactly 36 away: no
    assert touch(state, inv, 64, 64, z=-57.0) == []              # item over the head
    assert touch(state, inv, 64, 64, z=9.0) == []                # item 9 below the feet
    assert touch(state, inv, 64, 64, z=8.0) != [] and inv.health == 20


def test_a_key_picked_up_opens_its_locked_door():
    level = corridor([room(), room()], between={0: {"special": 26}},      # DR blue
                     things=[Thing(40, 64, 0, BLUE_CARD, 7)])
    rules, state = rules_for(level)
    wall = wall_between(level, 0)
    inv = Inventory()
    assert rules.use_line(wall, 0, keys=inv.door_keys) == "needs the blue key"
    assert touch(state, inv, 40, 64)
    assert rules.use_line(wall, 0, keys=inv.door_keys) is None


def test_solid_things_block_a_sliding_player():
    _, _, state = pickup_world([Thing(128, 64, 0, BARREL, 7), Thing(160, 64, 0, STIMPACK, 7)])
    things = state.things
    assert blocked_at(things, 128 + 25, 64) and not blocked_at(things, 128 + 26, 64)
    assert not blocked_at(things, 160, 64)                      # items never block
    sides = things.solid_sides(60, 64, 80)
    assert len(sides) == 4
    # walking east into the barrel (radius 10) stops 16 short of its box
    x, y = slide(60.0, 64.0, 80.0, 0.0, sides, 16.0)
    assert math.isclose(x, 128 - 10 - 16, abs_tol=1e-6) and y == 64.0
    # a glancing walk slides up round the box's corner
    x, y = slide(60.0, 64.0 + 20, 120.0, 0.0, sides, 16.0)
    assert x > 128 - 10 and y > 84.0                   # head on it stopped at 102
    assert max(abs(x - 128) - 10, abs(y - 64) - 10) >= 16 - 1e-6
    assert things.solid_sides(400, 64, 40) == []
