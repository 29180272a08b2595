"""Thing types: DOOM's table covers every type the Freedoom maps spawn; values are DOOM's."""
import os
import struct
from pathlib import Path

import pytest

from wallbsp.scene.thingtypes import (DOOM_THING_TYPES, NOSECTOR, SOLID, SPAWNCEILING,
    own_thing_info, thing_info)
from wallbsp.level.wadmap import list_maps, map_lump_indices
from wallbsp.assets.wad import open_wad

FREEDOOM = Path(os.environ.get("FREEDOOM_DIR", "/usr/share/games/doom"))
SKILL_BITS = 0x7


def wad_things(path: Path) -> dict[str, list[tuple[int, int]]]:
    """Each map's THINGS as (type, flags)."""
    maps = {}
    with open_wad(path) as wad:
        for name in list_maps(path):
            raw = wad.read(map_lump_indices(wad, name)["THINGS"])
            records = struct.iter_unpack("<hhhhh", raw[:len(raw) - len(raw) % 10])
            maps[name] = [(t, flags) for _x, _y, _a, t, flags in records]
    return maps


@pytest.fixture(scope="module")
def freedoom_things():
    maps = {}
    for wad in ("freedoom1.wad", "freedoom2.wad"):
        if not (FREEDOOM / wad).exists():
            pytest.skip(f"{FREEDOOM / wad} is absent (Debian package 'freedoom')")
        maps.update(wad_things(FREEDOOM / wad))
    return maps


def test_every_type_spawned_on_the_68_freedoom_maps_has_a_record(freedoom_things):
    assert len(freedoom_things) == 68
    # DOOM looks a type up only when some skill spawns it (P_SpawnMapThing)
    spawned = {t for things in freedoom_things.values() for t, flags in things if flags & SKILL_BITS}
    missing = sorted(t for t in spawned if thing_info(t) is None)
    assert missing == []
    assert len(spawned) > 100


@pytest.mark.parametrize("thing_type,sprite,frame,radius,height,solid", [
    (2001, "SHOT", "A", 20, 16, False),      # shotgun
    (3004, "POSS", "A", 20, 56, True),       # former human
    (2035, "BAR1", "A", 10, 42, True),       # barrel
    (13, "RKEY", "A", 20, 16, False),        # red keycard
    (48, "ELEC", "A", 16, 16, True),         # tall techno column
    (34, "CAND", "A", 20, 16, False),        # a candle is not solid
    (7, "SPID", "A", 128, 100, True),        # spider mastermind
    (15, "PLAY", "N", 20, 16, False),        # dead player: a late frame of the player
])
def test_sample_records_match_doom(thing_type, sprite, frame, radius, height, solid):
    info = thing_info(thing_type)
    assert (info.sprite, info.frame, info.radius, info.height, info.solid) == (
        sprite, frame, radius, height, solid)


def test_monsters_rotate_and_items_do_not():
    assert thing_info(3004).monster and thing_info(3004).rotates
    assert thing_info(3006).monster            # lost soul: not counted, still a monster
    assert not thing_info(2035).monster and not thing_info(2035).rotates
    # Commander Keen hangs still, one rotation; every other monster turns
    assert [t for t, info in DOOM_THING_TYPES.items() if info.monster and not info.rotates] == [72]
    assert not any(info.rotates for info in DOOM_THING_TYPES.values() if info.pickup)


def test_flags_hanging_bright_and_never_drawn():
    assert thing_info(50).hangs and thing_info(50).solid and thing_info(50).height == 84
    assert thing_info(59).hangs and not thing_info(59).solid
    assert thing_info(2013).bright and not thing_info(2012).bright    # soulsphere, medikit
    assert not thing_info(14).drawn and not thing_info(1).drawn       # teleport spot, start
    assert thing_info(3004).drawn
    assert thing_info(72).flags & (SOLID | SPAWNCEILING) == SOLID | SPAWNCEILING   # Keen
    assert thing_info(89).flags & NOSECTOR


@pytest.mark.parametrize("thing_type,kind,item,amount", [
    (2011, "health", "stimpack", 10), (2012, "health", "medikit", 25),
    (2014, "health", "health bonus", 1), (2018, "armour", "green armor", 100),
    (2019, "armour", "blue armor", 200), (2007, "ammo", "bullets", 10),
    (2048, "ammo", "bullets", 50), (2049, "ammo", "shells", 20), (17, "ammo", "cells", 100),
    (2001, "weapon", "shotgun", 8), (2006, "weapon", "bfg9000", 40),
    (5, "key", "blue card", 0), (38, "key", "red skull", 0),
    (2022, "powerup", "invulnerability", 30 * 35),
])
def test_pickups_give_what_doom_gives(thing_type, kind, item, amount):
    pickup = thing_info(thing_type).pickup
    assert (pickup.kind, pickup.item, pickup.amount) == (kind, item, amount)


def test_decorations_and_monsters_are_not_pickups():
    assert thing_info(3004).pickup is None and thing_info(48).pickup is None


def test_a_levels_own_types_come_first():
    own = {2035: {"sprite": "LAMPB0", "radius": 8, "height": 40, "solid": False},
           9000: {"sprite": "BARL", "radius": 12, "height": 30, "solid": True}}
    lamp = thing_info(2035, own)
    assert (lamp.sprite, lamp.frame, lamp.radius, lamp.solid) == ("LAMP", "B", 8, False)
    assert thing_info(9000, own).solid and thing_info(9000, own).frame == "A"
    assert thing_info(9000) is None and thing_info(32000, own) is None


def test_own_types_read_attributes_too():
    class Spec:
        sprite, radius, height, solid = "KEYS", 10, 20, False
    info = own_thing_info(7000, Spec())
    assert (info.type, info.sprite, info.height, info.drawn) == (7000, "KEYS", 20, True)
