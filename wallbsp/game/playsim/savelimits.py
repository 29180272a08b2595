"""What a save may hold (issue 34): the bounds ``savegame.load_game`` checks before it
allocates, and the ranges of the values DOOM's structures keep, checked on the loaded
``Play`` before it is handed out (a ``SaveError`` naming the place, nothing else changed).

Memory: a save's body inflates to at most ``MAX_BODY_BYTES`` (zlib's ``max_length``: no
more is ever made), and before it is parsed ``parsed_size_bound`` (an upper bound of what
``json.loads`` makes of it, counted from its brackets, commas and bytes) must be within
``MAX_PARSED_BYTES``.  The thinkers are at most ``MAX_THINKERS`` before one is made, and
those no longer in the thinker list (removed objects still pointed at) at most
``unlisted_limit``, which the map's size and the listed thinkers set.  So a load's peak
stays within a few times the file plus about 250 MB whatever the file says.  A real save
is far inside these: Freedoom's maps save 100-550 KB of JSON (about 600 bytes a thinker),
whose bound is about 23 bytes a byte, so the limit is met at about 8 MB of a real save's
JSON, some 14,000 thinkers.

Values: every integer in the body is within DOOM's 32-bit words (fixed point and counts
signed, angles and flags unsigned: ``INT_LOW`` .. ``INT_HIGH``), every float finite; the
fields that index DOOM's tables (a mobj's type, state and sprite, a player's weapons, a
weapon sprite's state) are within their tables; the fixed-length lists of a player keep
their lengths; and the counts the map's own load sets (``numsectors``, the blockmap's
size, ...) are the map's.

A level script's saved state (``game.leveltimers``: ``play.level_script``) is JSON values
only — numbers within 32 bits, finite floats, strings, True/False/None, lists and
dictionaries with string keys — at most ``MAX_SCRIPT_VALUES`` of them nested at most
``MAX_SCRIPT_DEPTH`` deep, checked when a game is saved and when it is loaded
(``check_script_state``).
"""
from wallbsp.doom import info
from wallbsp.doom.tables import ammo_count

from .savestate import SaveError
from .structs import (MAXPLAYERS, NUMAMMO, NUMCARDS, NUMPOWERS, NUMPSPRITES, NUMWEAPONS,
                      MapThing, Mobj, Player, PspDef, TicCmd)

__all__ = ["MAX_BODY_BYTES", "MAX_PARSED_BYTES", "MAX_THINKERS", "MAX_HEADER_BYTES",
           "INT_LOW", "INT_HIGH", "parsed_size_bound", "check_thinker_count", "unlisted_limit",
           "check_map_counts", "check_loaded", "MAP_COUNTS", "SCRIPT_STATE", "SCRIPT_KEYS",
           "check_script_state", "check_script_value"]

MAX_BODY_BYTES = 32 << 20
MAX_PARSED_BYTES = 192 << 20
MAX_HEADER_BYTES = 1 << 20
MAX_THINKERS = 1 << 16
UNLISTED_SPARE = 1024
INT_LOW, INT_HIGH = -(1 << 31), (1 << 32) - 1
INT32 = (-(1 << 31), (1 << 31) - 1)
# what json.loads makes, at most, of each (CPython 3.11, 64-bit, measured on the worst
# bodies: nested empty lists, one-key objects): a container, an element, a byte
_OBJECT_COST, _ARRAY_COST, _ELEMENT_COST, _BYTE_COST = 240, 104, 64, 3
MAP_COUNTS = ("numvertexes", "numsectors", "numsides", "numlines", "numsegs",
              "numsubsectors", "numnodes", "bmapwidth", "bmapheight", "bmaporgx",
              "bmaporgy")


SCRIPT_STATE = "level_script"
SCRIPT_KEYS = ("script", "loads", "tic", "order", "state", "timers")
MAX_SCRIPT_VALUES = 1 << 16
MAX_SCRIPT_DEPTH = 32


def parsed_size_bound(raw: bytes) -> int:
    """An upper bound of the bytes ``json.loads(raw)`` allocates (module docstring)."""
    return (_OBJECT_COST * raw.count(b"{") + _ARRAY_COST * raw.count(b"[")
            + _ELEMENT_COST * (raw.count(b",") + raw.count(b":") + 1)
            + _BYTE_COST * len(raw))


def check_thinker_count(rows, listed, play) -> None:
    """At most ``MAX_THINKERS``, ``listed`` of them in the thinker list; the others (removed
    objects something still points at) at most ``unlisted_limit``, before one is made."""
    if len(rows) > MAX_THINKERS:
        raise SaveError(f"thinkers: {len(rows)} rows, more than a save holds "
                        f"({MAX_THINKERS})")
    if type(listed) is not int or not 0 <= listed <= len(rows):
        raise SaveError(f"listed: {_short(listed)} is not a count of the {len(rows)} thinkers")
    limit = unlisted_limit(listed, play)
    if len(rows) - listed > limit:
        raise SaveError(f"thinkers: {len(rows) - listed} removed thinkers still pointed at, "
                        f"more than this map's game can point at ({limit})")


def unlisted_limit(listed: int, play) -> int:
    """What can point at a removed thinker: a listed one's target and tracer, a sector's
    and a line's special and sound target, a player's attacker, the globals, and chains of
    these a few long (the removed ones' own two pointers): generously, this many."""
    return 2 * listed + 2 * (len(play.sectors) + len(play.lines)) + UNLISTED_SPARE


def check_map_counts(saved: dict, loaded: dict) -> None:
    """The map's own counts (``loaded``: as the map's load set them) against the save's."""
    for name in MAP_COUNTS:
        if name in saved and name in loaded and saved[name] != loaded[name]:
            raise SaveError(f"globals.{name}: {_short(saved[name])}, the map's is "
                            f"{loaded[name]}")


def check_loaded(play, thinkers) -> None:
    """The loaded state's indices and fixed lengths (module docstring)."""
    tables = play.tables                 # the play's own (a game's actors, skill 5's speeds)
    for i, th in enumerate(thinkers):
        if isinstance(th, Mobj):
            _check_mobj(th, tables, f"thinkers[{i}]")
    for k, p in enumerate(play.players):
        _check_player(p, tables, f"players[{k}]")
    for name, seq in (("sectors", play.sectors), ("sides", play.sides),
                      ("lines", play.lines)):
        for i, obj in enumerate(seq):
            _check_words(obj, _MAP_WORDS[name], f"{name}[{i}]")
    check_script_state(play)
    width, height = getattr(play, "bmapwidth", 0), getattr(play, "bmapheight", 0)
    links = getattr(play, "blocklinks", None)
    if links is not None and (type(links) is not list or len(links) != width * height):
        raise SaveError(f"globals.blocklinks: not the map's {width}x{height} blocks")


def check_script_state(play) -> None:
    """``play``'s level script state, if it has one (module docstring)."""
    data = vars(play).get(SCRIPT_STATE)
    if data is None:
        return
    where = f"globals.{SCRIPT_STATE}"
    if type(data) is not dict or sorted(data) != sorted(SCRIPT_KEYS):
        raise SaveError(f"{where}: not a level script's state ({', '.join(SCRIPT_KEYS)})")
    if type(data["script"]) is not str:
        raise SaveError(f"{where}.script: {_short(data['script'])} is not a file name")
    for key in ("loads", "tic", "order"):
        _ranged_value(data[key], 0, INT32[1], f"{where}.{key}")
    if type(data["state"]) is not dict:
        raise SaveError(f"{where}.state: not a dictionary")
    timers = data["timers"]
    if type(timers) is not list:
        raise SaveError(f"{where}.timers: not a list")
    for i, timer in enumerate(timers):
        here = f"{where}.timers[{i}]"
        if type(timer) is not list or len(timer) != 5:
            raise SaveError(f"{here}: not [due, order, period, name, arguments]")
        for k, low in ((0, 0), (1, 0), (2, 0)):
            _ranged_value(timer[k], low, INT32[1], here)
        if type(timer[3]) is not str or not timer[3].removeprefix("level.").isidentifier():
            raise SaveError(f"{here}: {_short(timer[3])} is not a function's name")
        if type(timer[4]) is not list:
            raise SaveError(f"{here}: its arguments are not a list")
    check_script_value(data["state"], f"{where}.state")
    check_script_value(timers, f"{where}.timers")


def check_script_value(value, where) -> None:
    """``value`` is JSON values only, within the bounds (module docstring)."""
    stack, count = [(value, where, 0)], 0
    while stack:
        v, here, depth = stack.pop()
        count += 1
        if count > MAX_SCRIPT_VALUES:
            raise SaveError(f"{where}: more than {MAX_SCRIPT_VALUES} values")
        if depth > MAX_SCRIPT_DEPTH:
            raise SaveError(f"{here}: nested deeper than {MAX_SCRIPT_DEPTH}")
        t = type(v)
        if t is int:
            _ranged_value(v, *INT32, here)
        elif t is float:
            if v != v or v in (float("inf"), float("-inf")):
                raise SaveError(f"{here}: {v} is not a finite number")
        elif t is list:
            stack.extend((x, f"{here}[{k}]", depth + 1) for k, x in enumerate(v))
        elif t is dict:
            for k, x in v.items():
                if type(k) is not str:
                    raise SaveError(f"{here}: the key {_short(k)} is not a string")
                stack.append((x, f"{here}[{k!r}]", depth + 1))
        elif not (t is str or t is bool or v is None):
            raise SaveError(f"{here}: a {t.__name__} is not a value a save holds (numbers, "
                            f"strings, True, False, None, lists and dictionaries of them)")


def _ranged_value(value, low, high, where) -> None:
    if type(value) is not int or not low <= value <= high:
        raise SaveError(f"{where}: {_short(value)} is not an integer from {low} to {high}")


_MOBJ_WORDS = ("x", "y", "z", "floorz", "ceilingz", "radius", "height", "momx", "momy",
               "momz", "health", "movecount", "reactiontime", "threshold", "validcount",
               "lastlook")
_MAP_WORDS = {"sectors": ("floorheight", "ceilingheight", "lightlevel", "special", "tag",
                          "soundtraversed", "validcount"),
              "sides": ("textureoffset", "rowoffset"),
              "lines": ("flags", "special", "tag", "validcount")}
_PLAYER_WORDS = ("viewz", "viewheight", "deltaviewheight", "bob", "health", "armorpoints",
                 "attackdown", "usedown", "cheats", "refire", "killcount", "itemcount",
                 "secretcount", "damagecount", "bonuscount", "extralight", "colormap")
_PLAYER_LISTS = (("powers", NUMPOWERS), ("cards", NUMCARDS), ("frags", MAXPLAYERS),
                 ("weaponowned", NUMWEAPONS), ("ammo", NUMAMMO), ("maxammo", NUMAMMO))


def _check_mobj(mo, tables, where) -> None:
    _check_words(mo, _MOBJ_WORDS, where)
    _index(mo, "type", len(tables.mobjinfo), where)
    _index(mo, "state", len(tables.states), where)
    _index(mo, "sprite", len(tables.sprnames), where)
    _ranged(mo, "angle", 0, INT_HIGH, where)
    _ranged(mo, "flags", 0, INT_HIGH, where)
    _ranged(mo, "frame", 0, 0xFFFF, where)
    _ranged(mo, "tics", -1, INT32[1], where)
    _ranged(mo, "movedir", 0, 8, where)
    if getattr(mo, "info", None) is not tables.mobjinfo[mo.type]:
        raise SaveError(f"{where}.info: not the mobjinfo of type {mo.type}")
    for name in ("target", "tracer"):
        value = getattr(mo, name, None)
        if value is not None and not isinstance(value, Mobj):
            raise SaveError(f"{where}.{name}: not a map object")
    player = getattr(mo, "player", None)
    if player is not None and not isinstance(player, Player):
        raise SaveError(f"{where}.player: not a player")
    spot = getattr(mo, "spawnpoint", None)
    if not isinstance(spot, MapThing):
        raise SaveError(f"{where}.spawnpoint: not a map thing")
    _check_words(spot, ("x", "y", "angle", "type", "options"), f"{where}.spawnpoint")


def _check_player(p, tables, where) -> None:
    _check_words(p, _PLAYER_WORDS, where)
    _ranged(p, "playerstate", 0, 2, where)
    _ranged(p, "armortype", 0, 2, where)
    weapons = len(tables.weaponinfo)               # DOOM's, and a game's own after them
    _index(p, "readyweapon", weapons, where)
    _ranged(p, "pendingweapon", 0, max(info.wp_nochange, weapons - 1), where)
    _ranged(p, "fixedcolormap", 0, 255, where)
    if p.mo is not None and not isinstance(p.mo, Mobj):
        raise SaveError(f"{where}.mo: not a map object")
    for name, length in _PLAYER_LISTS:
        length = weapons if name == "weaponowned" else \
            ammo_count(tables) if name in ("ammo", "maxammo") else length
        value = getattr(p, name, None)
        if type(value) is not list or len(value) != length or \
                any(type(v) not in (int, bool) for v in value):
            raise SaveError(f"{where}.{name}: not a list of {length} numbers")
    cmd = p.cmd
    if not isinstance(cmd, TicCmd):
        raise SaveError(f"{where}.cmd: not a tic command")
    for name, low, high in (("forwardmove", -128, 127), ("sidemove", -128, 127),
                            ("angleturn", -32768, 32767), ("buttons", 0, 255)):
        _ranged(cmd, name, low, high, f"{where}.cmd")
    sprites = p.psprites
    if type(sprites) is not list or len(sprites) != NUMPSPRITES or \
            not all(isinstance(s, PspDef) for s in sprites):
        raise SaveError(f"{where}.psprites: not {NUMPSPRITES} weapon sprites")
    for k, psp in enumerate(sprites):
        if psp.state is not None:
            _index(psp, "state", len(tables.states), f"{where}.psprites[{k}]")
        _check_words(psp, ("tics", "sx", "sy"), f"{where}.psprites[{k}]")


def _check_words(obj, names, where) -> None:
    for name in names:
        _ranged(obj, name, *INT32, where)


def _index(obj, name, size, where) -> None:
    _ranged(obj, name, 0, size - 1, where)


def _ranged(obj, name, low, high, where) -> None:
    value = getattr(obj, name, None)
    if type(value) not in (int, bool) or not low <= value <= high:
        raise SaveError(f"{where}.{name}: {_short(value)} is not an integer from {low} "
                        f"to {high}")


def _short(value) -> str:
    text = repr(value) if not isinstance(value, int) or abs(value) < 1 << 64 else \
        f"an integer of {value.bit_length()} bits"
    return text if len(text) <= 40 else text[:37] + "..."
