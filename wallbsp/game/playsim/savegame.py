"""Saving and loading a running ``Play`` exactly: a loaded game goes on as the saved one
would have, tic for tic (the same trace).

    data = save_game(play)                      # bytes
    play = load_game(data, wad_path, files)     # a new Play, the saved state
    save_game_file(play, path); load_game_file(path, wad_path, files)

Our own format, not vanilla's ``p_saveg.c`` (which drops state a later tic reads: removed
objects still targeted, scratch globals, the overrun emulations' targets) and not pickle
(nothing but the package's own structures is ever made from a file).  A save is:

    8 bytes   magic b"WBSPSAVE"
    u32 LE    format version (FORMAT_VERSION)
    u32 LE    header length, u32 LE body length
    header    JSON (UTF-8): the WADs (name, size, sha256: the IWAD, then each PWAD), the
              game mode and version, the map (lump name, or our level's name), episode,
              map, skill, game state, gametic, leveltime, fast monsters, a sha256 of the
              map's structure (``map_fingerprint``) and a description
    body      zlib-compressed JSON: the state, ``savestate.py`` (read back by
              ``saverestore.py``): every thinker in list order, the map's changing
              fields, the players, every other attribute of the play
    32 bytes  sha256 of everything before it

Loading checks all of it before anything is made: a truncated, damaged or foreign file, a
save of another WAD or map, a save from another version of the structures, is one
``SaveError`` (a ``ValueError``) naming the file and the place — ``save.wsg: byte 12: ...``
or ``save.wsg: body: thinkers[12].target: no thinker 9000`` — and nothing is changed.
Loading makes a new ``Play`` (``cls``: the class to make, e.g. the World's), loads the
map's geometry from the WAD as ``P_SetupLevel`` does (or from ``level=(level, tree)`` for
one of our levels), then writes the saved state over it, with the fast-monster tables of
the saved game (the new play's own: nothing process-wide changes).

Saving needs a level (``SaveError`` before the first one loads); it works in any game
state after that (level, intermission, finale), as the level's state is kept until the
next loads.  Not saved: what the caller attached (``play.sound``: attach it to the loaded
play again) and what a ``Play`` subclass lists in ``SAVEGAME_DERIVED`` (savestate.py).
"""
import hashlib
import json
import os
import struct
import zlib
from array import array

from wallbsp.files import InputError, read_input, write_atomically

from . import game as _game
from .savelimits import (MAX_BODY_BYTES, MAX_HEADER_BYTES, MAX_PARSED_BYTES,
                         check_script_state, parsed_size_bound)
from .saverestore import Decoder
from .savestate import Encoder, SaveError
from .structs import COMMERCIAL, EXE_DOOM_1_9

__all__ = ["SaveError", "save_game", "load_game", "save_game_file", "load_game_file",
           "read_header", "map_fingerprint", "FORMAT_VERSION", "MAGIC"]

MAGIC = b"WBSPSAVE"
FORMAT_VERSION = 1
_PREFIX = struct.Struct("<8sIII")
DIGEST_SIZE = 32
MAX_SAVE_BYTES = 256 << 20


# -- identities ----------------------------------------------------------------------------
_wad_ids = {}


def wad_identity(path):
    """{"name", "size", "sha256"} of a WAD file (cached by path, size and mtime)."""
    try:
        st = os.stat(path)
        key = (os.path.realpath(path), st.st_size, st.st_mtime_ns)
        found = _wad_ids.get(key)
        if found is None:
            h = hashlib.sha256()
            with open(path, "rb") as f:
                for chunk in iter(lambda: f.read(1 << 20), b""):
                    h.update(chunk)
            found = _wad_ids[key] = {"name": os.path.basename(os.fspath(path)),
                                     "size": st.st_size, "sha256": h.hexdigest()}
    except OSError as e:
        raise SaveError(f"{path}: cannot read the WAD: {e.strerror or e}") from None
    return dict(found)


def map_fingerprint(play):
    """sha256 of the loaded map's structure (what loading rebuilds and never changes):
    vertexes, each side's sector, lines, segs, subsectors, nodes, blockmap, reject."""
    vx = {id(v): i for i, v in enumerate(play.vertexes)}
    ints = [len(play.vertexes), len(play.sectors), len(play.sides), len(play.lines),
            len(play.segs), len(play.subsectors), len(play.nodes)]
    for v in play.vertexes:
        ints += (v.x, v.y)
    for s in play.sides:
        ints.append(s.sector.id if s.sector is not None else -2)
    for ln in play.lines:
        ints += (vx.get(id(ln.v1), -1), vx.get(id(ln.v2), -1), ln.sidenum[0], ln.sidenum[1])
    for sg in play.segs:
        ints += (vx.get(id(sg.v1), -1), vx.get(id(sg.v2), -1), sg.offset, sg.angle,
                 sg.linedef.id if sg.linedef is not None else -1)
    for ss in play.subsectors:
        ints += (ss.numlines, ss.firstline)
    for n in play.nodes:
        ints += (n.x, n.y, n.dx, n.dy, n.children[0], n.children[1])
    ints += play.blockmaplump
    h = hashlib.sha256(array("q", ints).tobytes())
    h.update(bytes(play.rejectmatrix))
    return h.hexdigest()


def _level_name(play):
    source = getattr(play, "levelsource", None)
    return None if source is None else str(getattr(source[0], "name", "") or "level")


# -- saving --------------------------------------------------------------------------------
def save_game(play, description=""):
    """The save of ``play`` as bytes (the module docstring's format)."""
    if not getattr(play, "mapname", None) or play.gamestate == _game.GS_DEMOSCREEN:
        raise SaveError("no level is loaded: nothing to save")
    check_script_state(play)                # a level script's values: JSON ones only
    level = _level_name(play)
    wads = [] if play.wad_path is None else [wad_identity(play.wad_path)]
    wads += [wad_identity(f) for f in play.wad_files]
    header = {"format": "wallbsp save", "version": FORMAT_VERSION, "wads": wads,
              "gamemode": play.gamemode, "gameversion": play.gameversion,
              "map": play.mapname, "level": level, "episode": play.gameepisode,
              "gamemap": play.gamemap, "skill": play.gameskill,
              "gamestate": play.gamestate, "gametic": play.gametic,
              "leveltime": play.leveltime, "fast": bool(play.tables.fast),
              "geometry": map_fingerprint(play), "description": str(description)}
    body = Encoder(play).state()
    head = json.dumps(header, separators=(",", ":")).encode()
    packed = zlib.compress(json.dumps(body, separators=(",", ":")).encode(), 6)
    out = _PREFIX.pack(MAGIC, FORMAT_VERSION, len(head), len(packed)) + head + packed
    return out + hashlib.sha256(out).digest()


def save_game_file(play, path, description=""):
    """Writes ``play``'s save to ``path`` atomically (all of it or, on an error, nothing)."""
    try:
        data = save_game(play, description)
    except SaveError as e:
        raise SaveError(f"{os.fspath(path)}: {e}") from None
    write_atomically(path, data)


# -- loading -------------------------------------------------------------------------------
def read_header(data, source="<save>"):
    """(header dict, compressed body) of a save's bytes, checked (magic, version, sizes,
    digest, the header's fields); ``SaveError`` naming ``source`` and the byte."""
    def fail(offset, what):
        return SaveError(f"{source}: byte {offset}: {what}")

    data = bytes(data)
    if len(data) < _PREFIX.size + DIGEST_SIZE:
        raise fail(len(data), f"truncated: {len(data)} bytes is shorter than any save")
    magic, version, head_len, body_len = _PREFIX.unpack_from(data)
    if magic != MAGIC:
        raise fail(0, "not a wallbsp save (no WBSPSAVE magic)")
    if version != FORMAT_VERSION:
        raise fail(8, f"format version {version}; this wallbsp reads version "
                      f"{FORMAT_VERSION}")
    end = _PREFIX.size + head_len + body_len
    if end + DIGEST_SIZE != len(data):
        which = "truncated" if end + DIGEST_SIZE > len(data) else "trailing bytes"
        raise fail(min(len(data), end), f"{which}: the sizes say {end + DIGEST_SIZE} "
                                        f"bytes, the file has {len(data)}")
    if hashlib.sha256(data[:end]).digest() != data[end:]:
        raise fail(end, "damaged: the sha256 of the save does not match")
    if head_len > MAX_HEADER_BYTES:
        raise fail(12, f"a header of {head_len} bytes; a save's is at most "
                       f"{MAX_HEADER_BYTES}")
    try:
        header = json.loads(data[_PREFIX.size:_PREFIX.size + head_len])
    except (ValueError, RecursionError) as e:
        raise fail(_PREFIX.size, f"the header is not JSON: {e}") from None
    need = {"format": str, "version": int, "wads": list, "gamemode": int,
            "gameversion": int, "map": str, "fast": bool, "geometry": str}
    for key, kind in need.items():
        if not isinstance(header, dict) or type(header.get(key)) is not kind:
            raise fail(_PREFIX.size, f"the header has no {key} ({kind.__name__})")
    if header["format"] != "wallbsp save" or header["version"] != FORMAT_VERSION:
        raise fail(_PREFIX.size, "the header is not a wallbsp save's")
    return header, data[_PREFIX.size + head_len:end]


def load_game(data, wad_path, files=(), *, source="<save>", cls=None, level=None,
              tables=None):
    """A new ``Play`` in the state ``data`` (``save_game``'s bytes) holds, on the WAD
    ``wad_path`` and PWADs ``files`` the save was made with (``level=(level, tree)``: a
    save of one of our levels; ``tables``: the game's object tables, ``doom.tables.DOOM``
    by default).  ``SaveError`` for anything else, nothing changed."""
    header, packed = read_header(data, source)
    files = tuple(files)
    _check_wads(header, wad_path, files, source)
    if (header.get("level") is None) != (level is None):
        raise SaveError(f"{source}: header.level: the save is of "
                        + (f"our level {header['level']!r}: pass it as level=(level, tree)"
                           if level is None else f"the WAD map {header['map']}, not a level"))
    body = _body(packed, source)
    if cls is None:
        from .play import play_class
        cls = play_class()
    try:
        play = cls(wad_path, files)
    except (OSError, ValueError) as e:
        raise SaveError(f"{source}: {wad_path}: {e}") from None
    if level is not None and wad_path is None:      # as g_init_new_level decides
        play.gamemode, play.gameversion = COMMERCIAL, EXE_DOOM_1_9
    if (play.gamemode, play.gameversion) != (header["gamemode"], header["gameversion"]):
        raise SaveError(f"{source}: header.gamemode: the save is of game mode "
                        f"{header['gamemode']}/{header['gameversion']}, the WAD's is "
                        f"{play.gamemode}/{play.gameversion}")
    _load_map(play, header, level, source)
    play.set_tables((tables or play.tables).fast_monsters(header["fast"]))
    try:
        Decoder(play, body).apply()
    except SaveError as e:
        raise SaveError(f"{source}: body: {e}") from None
    except Exception as e:      # a body this version never writes: still one line
        raise SaveError(f"{source}: body: {type(e).__name__}: {e}") from None
    return play


def _body(packed, source):
    """The body's JSON, its memory bounded before it is made (``savelimits``): inflated
    to at most ``MAX_BODY_BYTES`` (zlib makes no more), parsed only when what parsing
    makes is bounded by ``MAX_PARSED_BYTES``; NaN and infinities are no JSON of a save."""
    try:
        inflater = zlib.decompressobj()
        raw = inflater.decompress(packed, MAX_BODY_BYTES + 1)
        if len(raw) > MAX_BODY_BYTES:
            raise ValueError(f"it inflates to more than {MAX_BODY_BYTES} bytes, more than "
                             f"a save holds")
        if inflater.unconsumed_tail or not inflater.eof:
            raise ValueError("cut short, or followed by other bytes")
        del inflater
        bound = parsed_size_bound(raw)
        if bound > MAX_PARSED_BYTES:
            raise ValueError(f"its {len(raw)} bytes of JSON would take up to {bound} bytes "
                             f"parsed, more than a save's state ({MAX_PARSED_BYTES})")
        return json.loads(raw, parse_constant=_no_constant)
    except (zlib.error, ValueError, RecursionError) as e:
        raise SaveError(f"{source}: body: not a compressed JSON state: {e}") from None


def _no_constant(name):
    raise ValueError(f"{name} is not a number a save holds")


def load_game_file(path, wad_path, files=(), **kwargs):
    """``load_game`` of the file at ``path`` (messages name it)."""
    try:
        data = read_input(path, MAX_SAVE_BYTES)
    except InputError as e:
        raise SaveError(str(e)) from None
    return load_game(data, wad_path, files, source=os.fspath(path), **kwargs)


def _check_wads(header, wad_path, files, source):
    given = ([] if wad_path is None else [wad_path]) + list(files)
    saved = header["wads"]
    if len(saved) != len(given):
        raise SaveError(f"{source}: header.wads: the save was made with {len(saved)} WAD(s) "
                        f"({', '.join(str(w.get('name')) for w in saved if isinstance(w, dict))}),"
                        f" {len(given)} given")
    for i, (want, path) in enumerate(zip(saved, given)):
        have = wad_identity(path)
        if not isinstance(want, dict) or want.get("sha256") != have["sha256"] \
                or want.get("size") != have["size"]:
            want = want if isinstance(want, dict) else {}
            raise SaveError(f"{source}: header.wads[{i}]: the save was made with "
                            f"{want.get('name', '?')} (sha256 {str(want.get('sha256'))[:12]}"
                            f"...), not {path} (sha256 {have['sha256'][:12]}...)")


def _load_map(play, header, level, source):
    """P_SetupLevel's geometry (no things, no specials: the save holds what they made)."""
    play.init_level_modules()
    play.p_init_thinkers()
    mapname = header["map"]
    try:
        if level is not None:
            play.levelsource = tuple(level)
            play.p_setup_level_from(*level)
        else:
            if mapname not in play.wad_dir:
                raise SaveError(f"{source}: header.map: the WAD has no map {mapname}")
            play.mapname = mapname
            play.p_setup_level_geometry(play.map_wad(mapname), mapname)
    except SaveError:
        raise
    except (OSError, ValueError) as e:
        raise SaveError(f"{source}: header.map: cannot load {mapname}: {e}") from None
    if map_fingerprint(play) != header["geometry"]:
        raise SaveError(f"{source}: header.geometry: the map {play.mapname} is not the one "
                        f"saved (its structure differs)")
