"""Demos and PWADs that take p_enemy.c's port (monsters.py, attacks.py, archvile.py,
deaths.py, brain.py) where the Freedoom demos never go: every Doom II monster's attacks and
the level-ending deaths.  Their reference traces in tests/oracle/ (``monsters-*.trace``) were
made by Chocolate Doom with the trace patch (shared/oracle/build-trace-doom.sh) from exactly
these bytes:

    open(PWAD, "wb").write(scenario_pwad(name, iwad_path)); write scenario_demo(name)
    DOOMTRACE=out chocolate-doom -iwad WAD.wad -file PWAD -timedemo LMP -nosound -nomusic

- ``zoo-*``: a Freedoom 2 map whose monsters are all replaced by a cycle of other types
  (arch-viles, revenants, pain elementals, mancubi, spiders, cyberdemons, the boss brain's
  spitter and targets, ...), played by a pseudo-random walk that fires half the time.
- ``coop-*``: the same with two players (a net game), each on its own walk.
- ``boss-*``: a two-room map (``playsim_scenarios.room_map``) where a deaf boss stands on a
  teleport destination in the east room, facing away; the player walks in behind it, turns
  and walks back over the WR teleport line (tagged 666 like the east room), telefragging it:
  A_BossDeath's floor, door or exit (or A_BrainScream .. A_BrainDie for the brain).
- ``keens``: two Commander Keens in line in the east room, shot until both are dead:
  A_KeenDie opens the door tagged 666 after the second.
"""
import struct

from playsim_scenarios import room_map
from wallbsp.game.playsim.demos import wad_image

MONSTERS = {3004, 9, 65, 3001, 3002, 58, 3006, 3005, 69, 3003, 68, 71, 66, 67, 64, 7, 16,
            84, 72}
ZOO = {  # name -> (map, the doomednums replacing its monsters in turn, tics, walk's seed)
    "zoo-map02": ("MAP02", (66, 64, 71, 67), 1500, 6),
    "zoo-map05": ("MAP05", (68, 7, 3003, 3005, 71, 3001, 3002), 1500, 2),
    "zoo-map06": ("MAP06", (88, 16, 89, 87, 16, 87, 88, 7), 1500, 6),
    "zoo-map07": ("MAP07", (67, 68, 16, 3003), 1500, 7),
}
# two players in co-op (a net game: A_Chase's second look, P_LookForPlayers over two players)
COOP = {  # name -> (map, replacing doomednums, tics, the players' walks' seeds, skill)
    "coop-map01": ("MAP01", (64, 66, 67, 71, 68, 16, 7, 72, 69, 3003, 3006, 65, 3005, 58,
                             9, 3001, 3002, 3004), 2000, (3, 4), 2),
}
BOSSES = {  # name -> (IWAD, map name, episode, map, the boss's doomednum)
    "boss-map07": ("freedoom2", "MAP07", 1, 7, 67),
    "boss-map08-brain": ("freedoom2", "MAP08", 1, 8, 88),
    "boss-e1m8": ("freedoom1", "E1M8", 1, 8, 3003),
    "boss-e2m8": ("freedoom1", "E2M8", 2, 8, 16),
    "boss-e4m6": ("freedoom1", "E4M6", 4, 6, 16),
    "boss-e4m8": ("freedoom1", "E4M8", 4, 8, 7),
}
BOSS_TICS, KEEN_TICS = 220, 520
MAP_LUMPS = 10                                # THINGS .. BLOCKMAP after the marker


def iwad_of(name):
    return BOSSES[name][0] if name in BOSSES else "freedoom2"


def _iwad_map(iwad_path, mapname):
    data = open(iwad_path, "rb").read()
    count, offset = struct.unpack_from("<ii", data, 4)
    entries = [struct.unpack_from("<ii8s", data, offset + 16 * i) for i in range(count)]
    names = [e[2].rstrip(b"\0").decode() for e in entries]
    i = names.index(mapname)
    return [(names[j], data[entries[j][0]:entries[j][0] + entries[j][1]])
            for j in range(i + 1, i + 1 + MAP_LUMPS)]


def _replace_monsters(things, cycle):
    out = bytearray(things)
    k = 0
    for j in range(len(things) // 10):
        x, y, angle, type_, options = struct.unpack_from("<5h", out, 10 * j)
        if type_ in MONSTERS:
            # every skill, never deaf
            struct.pack_into("<5h", out, 10 * j, x, y, angle, cycle[k % len(cycle)],
                             (options | 7) & ~8)
            k += 1
    return bytes(out)


def _room_with_tag(things, special):
    """room_map with the east room and the middle line tagged 666."""
    lumps = dict(room_map(special, things))
    west = struct.pack("<hh8s8shhh", 0, 128, b"FLOOR4_8", b"CEIL3_5", 160, 0, 0)
    east = struct.pack("<hh8s8shhh", 0, 128, b"FLOOR4_8", b"CEIL3_5", 160, 0, 666)
    lumps["SECTORS"] = west + east
    lines = bytearray(lumps["LINEDEFS"])
    struct.pack_into("<h", lines, len(lines) - 6, 666)     # the middle line's tag
    lumps["LINEDEFS"] = bytes(lines)
    return [(name, lumps[name]) for name, _ in room_map(special, things)]


def scenario_pwad(name, iwad_path):
    """The PWAD bytes of scenario ``name`` (``iwad_path``: the IWAD a zoo map comes from)."""
    if name in ZOO or name in COOP:
        mapname, cycle = (ZOO.get(name) or COOP[name])[:2]
        lumps = [(n, _replace_monsters(raw, cycle) if n == "THINGS" else raw)
                 for n, raw in _iwad_map(iwad_path, mapname)]
    elif name in BOSSES:
        _, mapname, _, _, boss = BOSSES[name]
        things = [(128, 128, 0, 1, 7), (448, 128, 0, 14, 7), (448, 128, 0, boss, 7 | 8)]
        lumps = _room_with_tag(things, 97)
    else:
        mapname = "MAP01"
        things = [(128, 128, 0, 1, 7), (400, 128, 180, 72, 7), (480, 128, 180, 72, 7)]
        lumps = _room_with_tag(things, 0)
    return wad_image([(mapname, b"")] + lumps)


def _tic(forward=0, side=0, turn=0, buttons=0):
    return struct.pack("<bbBB", forward, side, turn & 0xFF, buttons)


def _random_walk(count, seed):
    """Walk, strafe and turn in 17-tic spells, fire half the time, use now and then,
    switch weapons every 200 tics (a 32-bit LCG, so the bytes never change)."""
    state = seed
    tics = []

    def rand(n):
        nonlocal state
        state = (state * 1103515245 + 12345) & 0x7FFFFFFF
        return (state >> 8) % n
    forward = side = turn = 0
    for t in range(count):
        if t % 17 == 0:
            forward = (50, 50, 25, 0, -25)[rand(5)]
            side = (0, 0, 24, -24)[rand(4)]
            turn = (0, 0, 0, 2, -2, 5, -5)[rand(7)]
        buttons = (1 if rand(2) else 0) | (2 if rand(20) == 0 else 0)
        if t % 200 == 100:
            buttons |= 4 | (rand(7) << 3)
        tics.append(_tic(forward, side, turn, buttons))
    return tics


def scenario_demo(name):
    """The .lmp bytes of scenario ``name``."""
    if name in ZOO:
        mapname, _, count, seed = ZOO[name]
        skill, episode, gamemap = 1, 1, int(mapname[3:])
        tics = _random_walk(count, seed)
    elif name in COOP:
        mapname, _, count, seeds, skill = COOP[name]
        walks = [_random_walk(count, seed) for seed in seeds]
        header = bytes([109, skill, 1, int(mapname[3:]), 0, 0, 0, 0, 0, 1, 1, 0, 0])
        return header + b"".join(a + b for a, b in zip(*walks)) + b"\x80"
    elif name in BOSSES:
        _, _, episode, gamemap, _ = BOSSES[name]
        skill = 2
        # east into the boss's room, turn round, back west over the teleport line, wait
        tics = [_tic(50)] * 14 + [_tic(turn=128)] + [_tic(50)] * 40
        tics += [_tic()] * (BOSS_TICS - len(tics))
    else:
        skill, episode, gamemap = 2, 1, 1
        tics = [_tic(buttons=1)] * KEEN_TICS
    header = bytes([109, skill, episode, gamemap, 0, 0, 0, 0, 0, 1, 0, 0, 0])
    return header + b"".join(tics) + b"\x80"


SCENARIOS = sorted(ZOO) + sorted(COOP) + sorted(BOSSES) + ["keens"]
