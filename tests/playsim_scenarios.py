"""Demos and a PWAD that take the play simulation where the Freedoom demos never go: level
exits, secret exits, the intermission, Doom II's text screens, Doom's victory, and other
skills and settings on the Freedoom demos' own tics.  Their reference traces in
tests/oracle/ (``scenario-*.trace``) were made by Chocolate Doom with the trace patch
(shared/oracle/build-trace-doom.sh) from exactly these bytes:

    write_pwad(path, PWAD_MAPS[wad]); write the .lmp of scenario_demo(name)
    DOOMTRACE=out chocolate-doom -iwad WAD.wad -file PWAD -timedemo LMP -nosound -nomusic

and cut to their first ``TRACE_LINES[name]`` lines.  The net-game demos were steered by
this simulation (aiming at the other player) and are stored as they were traced.
"""
import struct

# Tiny test maps: two square rooms 256 wide side by side; the player starts in the west one
# facing east, an imp and a health bonus wait in the east one, and the line between the
# rooms is a walk-over exit (52) or secret exit (124).
PWAD_MAPS = {
    "freedoom1": (("E1M3", 124), ("E1M9", 52), ("E1M7", 52), ("E1M8", 52)),
    "freedoom2": (("MAP01", 52), ("MAP06", 52), ("MAP07", 52), ("MAP15", 124),
                  ("MAP31", 124), ("MAP32", 52)),
}
# name -> (IWAD, how the demo is made: ("run" or "items", skill, episode, map, tics) on
# the PWAD, ("patch", lump, {offset: byte}) of a Freedoom demo, ("lmp", PWAD) stored, its
# PWAD the net-game map ("net"), that map with things ("items") or none)
#   exits-*: run east, tap use every 20 tics, fire every 37: through the exits and the
#   intermissions onto the IWAD's next map (MAP01 -> MAP02; MAP06 -> text -> MAP07 -> MAP08;
#   MAP15 -> secret MAP31 -> MAP32 -> MAP16; E1M3 -> secret E1M9 -> E1M4; E1M7 -> E1M8 ->
#   victory); items-*: one test map (ITEM_THINGS) run over weapons, a key, armour and
#   powers, then the IWAD's next map with weapon changes and fire; patched: a Freedoom
#   demo's own tics under another header
SCENARIOS = {
    "exits-map01": ("freedoom2", ("run", 2, 1, 1, 400)),
    "exits-map06": ("freedoom2", ("run", 2, 1, 6, 500)),
    "exits-map15": ("freedoom2", ("run", 3, 1, 15, 600)),
    "exits-e1m3": ("freedoom1", ("run", 2, 1, 3, 500)),
    "exits-e1m7": ("freedoom1", ("run", 3, 1, 7, 300)),
    "nightmare-f1demo1": ("freedoom1", ("patch", "DEMO1", {1: 4})),
    "fast-respawn-f1demo2": ("freedoom1", ("patch", "DEMO2", {5: 1, 6: 1})),
    "nightmare-f2demo1": ("freedoom2", ("patch", "DEMO1", {1: 4})),
    "nomonsters-f2demo3": ("freedoom2", ("patch", "DEMO3", {7: 1})),
    "baby-f2demo4": ("freedoom2", ("patch", "DEMO4", {1: 0})),
    # two players on the net-game map (PWAD_MAPS with net=True), demos stored in
    # tests/oracle/: co-op (player 1 shoots player 2 dead, who comes back at his start,
    # then player 1 leaves by the switch) and deathmatch (both aim and fire, come back at
    # random deathmatch starts; then player 1 leaves), each through the intermission's
    # net-game tally onto MAP02
    "items-map01": ("freedoom2", ("items", 3, 1, 1, 500)),
    "items-e1m1": ("freedoom1", ("items", 3, 1, 1, 500)),
    "coop-map01": ("freedoom2", ("lmp", "net")),
    "deathmatch-map01": ("freedoom2", ("lmp", "net")),
    # deathmatch 2 on the net-game map with DM_ITEM_THINGS: the players take things, fight,
    # and the things come back after 30 seconds (P_RespawnSpecials); then MAP02
    "deathmatch2-items-map01": ("freedoom2", ("lmp", "items")),
    # four players at random on Freedoom's own MAP01 in deathmatch: a respawn facing 180
    # degrees puts the fog where 20 * finetangent[0] wraps around (tic 641)
    "deathmatch4-map01": ("freedoom2", ("lmp", None)),
}
TRACE_LINES = {"exits-map01": 216, "exits-map06": 232, "exits-map15": 248,
               "exits-e1m3": 232, "exits-e1m7": 32, "nightmare-f1demo1": 800,
               "fast-respawn-f1demo2": 800, "nightmare-f2demo1": 800,
               "nomonsters-f2demo3": 800, "baby-f2demo4": 800, "coop-map01": 500,
               "deathmatch-map01": 821, "items-map01": 467, "items-e1m1": 459,
               "deathmatch2-items-map01": 1900, "deathmatch4-map01": 800}


# net-game maps: no imp, four player starts and four deathmatch starts; the middle line
# is plain and the east wall is a switch exit (11)
NET_THINGS = ((64, 128, 0, 1, 7), (448, 128, 180, 2, 7), (64, 224, 0, 3, 7),
              (448, 32, 180, 4, 7), (64, 64, 0, 11, 7), (64, 192, 0, 11, 7),
              (448, 64, 180, 11, 7), (448, 192, 180, 11, 7))


# deathmatch 2 (items come back after 30 seconds): the net-game map with things to take
DM_ITEM_THINGS = NET_THINGS + ((160, 128, 0, 2001, 7), (352, 128, 0, 2011, 7),
                               (256, 64, 0, 2014, 7), (256, 192, 0, 2008, 7),
                               (160, 32, 0, 2048, 7), (352, 224, 0, 2012, 7))

# an exit run over weapons, a key, armour and powers: what carries into the next map
ITEM_THINGS = ((64, 128, 0, 1, 7), (96, 128, 0, 2001, 7), (120, 128, 0, 2002, 7),
               (144, 128, 0, 5, 7), (168, 128, 0, 2018, 7), (192, 128, 0, 2024, 7),
               (216, 128, 0, 2025, 7), (448, 160, 180, 3001, 7))


def room_map(special, things=None, east_wall=0):
    """The lumps of one test map (THINGS .. BLOCKMAP), with hand-made BSP data: the rooms
    are the two subsectors of the one node."""
    verts = [(0, 0), (256, 0), (512, 0), (512, 256), (256, 256), (0, 256)]
    sector = struct.pack("<hh8s8shhh", 0, 128, b"FLOOR4_8", b"CEIL3_5", 160, 0, 0)
    # v1, v2, flags, special, tag, right side, left side
    lines = [(0, 5, 1, 0, 0, 0, -1), (5, 4, 1, 0, 0, 1, -1), (4, 3, 1, 0, 0, 2, -1),
             (3, 2, 1, east_wall, 0, 3, -1), (2, 1, 1, 0, 0, 4, -1), (1, 0, 1, 0, 0, 5, -1),
             (1, 4, 4, special, 0, 6, 7)]
    side_sectors = (0, 0, 1, 1, 1, 0, 1, 0)
    sides = b"".join(struct.pack("<hh8s8s8sh", 0, 0, b"-", b"-",
                                 b"STARTAN3" if i < 6 else b"-", s)
                     for i, s in enumerate(side_sectors))
    east, north, west, south = 0, 16384, -32768, -16384
    segs = [(0, 5, north, 0, 0, 0), (5, 4, east, 1, 0, 0), (4, 1, south, 6, 1, 0),
            (1, 0, west, 5, 0, 0), (4, 3, east, 2, 0, 0), (3, 2, south, 3, 0, 0),
            (2, 1, west, 4, 0, 0), (1, 4, north, 6, 0, 0)]
    node = struct.pack("<4h4h4h2H", 256, 0, 0, 256, 256, 0, 256, 512, 256, 0, 0, 256,
                       0x8001, 0x8000)
    if things is None:
        things = [(128, 128, 0, 1, 7), (448, 160, 180, 3001, 7), (400, 64, 90, 2014, 7)]
    orgx, orgy, cols, rows = -8, -8, 5, 3

    def touches(line, bx, by):
        (x1, y1), (x2, y2) = verts[line[0]], verts[line[1]]
        x0, y0 = orgx + bx * 128, orgy + by * 128
        return max(x1, x2) >= x0 and min(x1, x2) <= x0 + 128 and \
            max(y1, y2) >= y0 and min(y1, y2) <= y0 + 128
    offsets, body = [], []
    for by in range(rows):
        for bx in range(cols):
            offsets.append(4 + cols * rows + len(body))
            body += [0] + [i for i, ln in enumerate(lines) if touches(ln, bx, by)] + [-1]
    words = [orgx, orgy, cols, rows] + offsets + body
    pack = lambda fmt, rows_: b"".join(struct.pack(fmt, *r) for r in rows_)
    return [("THINGS", pack("<5h", things)), ("LINEDEFS", pack("<7h", lines)),
            ("SIDEDEFS", sides), ("VERTEXES", pack("<hh", verts)),
            ("SEGS", pack("<6h", segs)), ("SSECTORS", struct.pack("<4h", 4, 0, 4, 4)),
            ("NODES", node), ("SECTORS", sector * 2), ("REJECT", b"\0"),
            ("BLOCKMAP", struct.pack("<%dh" % len(words), *words))]


def pwad_lumps(maps, net=False, items=False):
    lumps = []
    for name, special in maps:
        lumps.append((name, b""))
        if net:
            lumps += room_map(0, DM_ITEM_THINGS if items else NET_THINGS, 11)
        else:
            lumps += room_map(special, ITEM_THINGS if items else None)
    return lumps


def scenario_pwad(name):
    """(maps, net, items): what ``write_pwad`` needs for scenario ``name``'s PWAD, or None."""
    iwad, (kind, *args) = SCENARIOS[name]
    if kind == "run":
        return PWAD_MAPS[iwad], False, False
    if kind == "lmp":
        return None if args[0] is None else ((("MAP01", 0),), True, args[0] == "items")
    if kind == "items":
        _, episode, gamemap, _ = args
        name = "MAP%02d" % gamemap if iwad == "freedoom2" else "E%dM%d" % (episode, gamemap)
        return ((name, 52),), False, True
    return None


def write_pwad(path, maps, net=False, items=False):
    from wallbsp.game.playsim.demos import wad_image
    with open(path, "wb") as f:
        f.write(wad_image(pwad_lumps(maps, net, items)))


def scenario_demo(name, iwad_path):
    """The .lmp bytes of scenario ``name``."""
    _, (kind, *args) = SCENARIOS[name]
    if kind == "lmp":
        from pathlib import Path
        return (Path(__file__).resolve().parent / "oracle" / f"scenario-{name}.lmp").read_bytes()
    if kind == "patch":
        from wallbsp.game.playsim.demos import wad_lump
        lump, patch = args
        raw = bytearray(wad_lump(iwad_path, lump))
        for offset, value in patch.items():
            raw[offset] = value
        return bytes(raw)
    skill, episode, gamemap, count = args
    tics = []
    for i in range(count):
        buttons = (2 if i % 20 == 10 else 0) | (1 if i % 37 == 5 else 0)
        if kind == "items" and i > 150:
            # hold fire in bursts and change weapons: 1 fist .. 4 chaingun, by turns
            buttons = (1 if i % 50 < 20 else 0) | (4 | ((i // 60) % 4) << 3 if i % 60 == 0 else 0)
        turn = 2 if (i // 200) % 2 else 0
        tics.append(struct.pack("<bbBB", 50, 0, turn, buttons))
    header = bytes([109, skill, episode, gamemap, 0, 0, 0, 0, 0, 1, 0, 0, 0])
    return header + b"".join(tics) + b"\x80"
