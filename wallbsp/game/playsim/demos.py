"""Vanilla DOOM demos (``.lmp``, version 1.9): the game settings and every tic's commands.

A demo is a 13-byte header — version (109), skill (0-4), episode, map, deathmatch, respawn,
fast, nomonsters, console player, then one byte per player slot telling whether that player
is in the game — followed by 4 bytes a tic for each player in the game (forwardmove and
sidemove as signed bytes, the high byte of angleturn, buttons), and 0x80 where the next tic
would start (``G_ReadDemoTiccmd`` stops there).

``read_demo(path)`` reads a ``.lmp`` file, ``wad_demo(wad_path, "DEMO1")`` a lump of a WAD,
``parse_demo(data, source)`` bytes.  Anything else — truncated, not a demo, another version —
raises ``DemoError`` (a ``ValueError``) naming the source and the byte offset.
"""
import os
import struct
from collections.abc import Sequence
from dataclasses import dataclass, field

from wallbsp.files import InputError, read_input

from .structs import MAXPLAYERS, TicCmd

DEMO_VERSION = 109                  # v1.9: the only format the port plays
DEMOMARKER = 0x80
HEADER_SIZE = 13
TIC_SIZE = 4
MAX_DEMO_BYTES = 64 << 20


class DemoError(ValueError):
    """A demo that cannot be played: the message names the file and the byte offset."""


@dataclass
class DemoTic:
    """One player's command of one tic, as the demo stores it."""
    forwardmove: int                # -128..127
    sidemove: int                   # -128..127
    angleturn: int                  # the stored byte << 8, as a signed 16-bit value
    buttons: int                    # 0..255

    def ticcmd(self) -> TicCmd:
        return TicCmd(self.forwardmove, self.sidemove, self.angleturn, self.buttons)

    def copy_to(self, cmd: TicCmd) -> None:
        """What ``G_ReadDemoTiccmd`` writes into a player's ``cmd`` (the rest keeps its
        value: consistancy and chatchar come from the net command, zero here)."""
        cmd.forwardmove, cmd.sidemove = self.forwardmove, self.sidemove
        cmd.angleturn, cmd.buttons = self.angleturn, self.buttons


@dataclass
class Demo:
    skill: int
    episode: int
    map: int
    deathmatch: int = 0
    respawnparm: bool = False
    fastparm: bool = False
    nomonsters: bool = False
    consoleplayer: int = 0
    playeringame: list = field(default_factory=lambda: [True, False, False, False])
    tics: list = field(default_factory=list)     # tics[n][player]: DemoTic (players in game);
    #                                              a DemoTics when read from a file
    source: str = "<demo>"
    version: int = DEMO_VERSION

    @property
    def players(self) -> list:
        """The indices of the players in the game, in the order their bytes come."""
        return [i for i in range(MAXPLAYERS) if self.playeringame[i]]


def _signed8(b: int) -> int:
    return b - 256 if b >= 128 else b


def _signed16(v: int) -> int:
    v &= 0xFFFF
    return v - 0x10000 if v >= 0x8000 else v


def parse_demo(data: bytes, source: str = "<demo>") -> Demo:
    """The demo in ``data``; ``source`` names it in messages.  Its end marker is found
    before any tic is made, and ``tics`` is a ``DemoTics``: each tic's commands made when
    it is read, so a demo costs its bytes however long it is."""
    data = bytes(data)
    if len(data) < HEADER_SIZE:
        raise DemoError(f"{source}: byte {len(data)}: truncated header ({len(data)} bytes, a "
                        f"v1.9 demo's header is {HEADER_SIZE})")
    version = data[0]
    if version != DEMO_VERSION:
        if version <= 4:
            what = "a v1.0-v1.2 demo"
        elif 104 <= version <= 111:
            what = f"a v{version // 100}.{version % 100} demo"
        else:
            what = "not a DOOM demo"
        raise DemoError(f"{source}: byte 0: version {version} ({what}); only v1.9 demos "
                        f"(version {DEMO_VERSION}) are played")
    skill, episode, gamemap, deathmatch, respawn, fast, nomonsters, console = data[1:9]
    if skill > 4:
        raise DemoError(f"{source}: byte 1: skill {skill} is not 0-4; not a DOOM demo")
    ingame = [bool(b) for b in data[9:13]]
    for i, b in enumerate(data[9:13]):
        if b > 1:
            raise DemoError(f"{source}: byte {9 + i}: player-present flag {b} is not 0 or 1; "
                            f"not a DOOM demo")
    if not any(ingame):
        raise DemoError(f"{source}: bytes 9-12: no player in the game; not a DOOM demo")
    if console >= MAXPLAYERS or not ingame[console]:
        raise DemoError(f"{source}: byte 8: console player {console} is not in the game")
    count = sum(ingame)
    tics = DemoTics(data, count, _tic_count(data, count, source))
    return Demo(skill, episode, gamemap, deathmatch, bool(respawn), bool(fast),
                bool(nomonsters), console, ingame, tics, source)


def _tic_count(data: bytes, players: int, source: str) -> int:
    """The tics before the end marker (``G_ReadDemoTiccmd`` stops at a tic whose first byte
    is 0x80), found in the tics' first bytes alone."""
    stride = TIC_SIZE * players
    end = data.find(bytes([DEMOMARKER]), HEADER_SIZE) if stride == 1 else \
        data[HEADER_SIZE::stride].find(bytes([DEMOMARKER]))
    if end < 0:
        whole = (len(data) - HEADER_SIZE) // stride
        pos = HEADER_SIZE + whole * stride
        if pos < len(data):
            raise DemoError(f"{source}: byte {pos}: truncated tic {whole} "
                            f"({len(data) - pos} bytes left, a tic is {stride})")
        raise DemoError(f"{source}: byte {pos}: truncated: the demo ends without its end "
                        f"marker (0x80) after {whole} tics")
    return end


class DemoTics(Sequence):
    """A demo's tics as ``tics[n][player]`` (``DemoTic`` rows, the players in the game in
    order), made from the demo's bytes when read."""

    def __init__(self, data: bytes, players: int, count: int):
        self.data, self.players, self.count = data, players, count

    def __len__(self) -> int:
        return self.count

    def __getitem__(self, n):
        if isinstance(n, slice):
            return [self._row(k) for k in range(*n.indices(self.count))]
        if not -self.count <= n < self.count:
            raise IndexError(f"tic {n} of {self.count}")
        return self._row(n % self.count)

    def __iter__(self):
        for n in range(self.count):
            yield self._row(n)

    def _row(self, n: int) -> list:
        data, pos = self.data, HEADER_SIZE + n * TIC_SIZE * self.players
        row = []
        for _ in range(self.players):
            fwd, side, turn, buttons = data[pos:pos + TIC_SIZE]
            row.append(DemoTic(_signed8(fwd), _signed8(side), _signed16(turn << 8), buttons))
            pos += TIC_SIZE
        return row

    def __eq__(self, other):
        return list(self) == list(other) if isinstance(other, (list, Sequence)) \
            else NotImplemented


def read_demo(path) -> Demo:
    """The demo in the ``.lmp`` file at ``path`` (a regular file of at most
    ``MAX_DEMO_BYTES``, read as every user file is: ``wallbsp.files.read_input``)."""
    label = os.fspath(path)
    try:
        data = read_input(path, MAX_DEMO_BYTES)
    except InputError as e:
        raise DemoError(f"{label}: byte 0: {e.reason}") from None
    except OSError as e:
        raise DemoError(f"{label}: byte 0: cannot read: {e.strerror or e}") from None
    return parse_demo(data, label)


# -- WAD lumps -------------------------------------------------------------------------------

def wad_entries(wad_path) -> list:
    """The WAD's directory in order: ``(name, offset, size)`` with names upper case."""
    label = os.fspath(wad_path)
    with open(wad_path, "rb") as f:
        head = f.read(12)
        if len(head) < 12 or head[:4] not in (b"IWAD", b"PWAD"):
            raise DemoError(f"{label}: byte 0: not a WAD file")
        count, offset = struct.unpack("<ii", head[4:])
        f.seek(max(offset, 0))
        raw = f.read(16 * max(count, 0))
        if count < 0 or len(raw) != 16 * count:
            raise DemoError(f"{label}: byte {offset}: truncated WAD directory")
    entries = []
    for i in range(count):
        pos, size, name = struct.unpack_from("<ii8s", raw, 16 * i)
        entries.append((name.split(b"\0", 1)[0].decode("latin-1").upper(), pos, size))
    return entries


def wad_directory(wad_path) -> dict:
    """Name (upper case) -> (offset, size) of the LAST lump of each name, as
    ``W_GetNumForName`` finds it."""
    return {name: (pos, size) for name, pos, size in wad_entries(wad_path)}


def wad_image(lumps) -> bytes:
    """A PWAD holding ``lumps`` (``(name, bytes)`` pairs) in order."""
    body, entries = bytearray(), []
    for name, data in lumps:
        entries.append(struct.pack("<ii8s", 12 + len(body), len(data), name.encode("latin-1")))
        body += data
    return b"PWAD" + struct.pack("<ii", len(entries), 12 + len(body)) + bytes(body) + \
        b"".join(entries)


def wad_lump(wad_path, name: str):
    """The bytes of the last lump called ``name`` in the WAD, or None."""
    entry = wad_directory(wad_path).get(name.upper())
    if entry is None:
        return None
    with open(wad_path, "rb") as f:
        f.seek(entry[0])
        data = f.read(entry[1])
    if len(data) != entry[1]:
        raise DemoError(f"{os.fspath(wad_path)}: byte {entry[0]}: lump {name} is truncated")
    return data


def wad_demo(wad_path, lump: str = "DEMO1") -> Demo:
    """The demo in lump ``lump`` (DEMO1..DEMO4) of the WAD at ``wad_path``."""
    data = wad_lump(wad_path, lump)
    label = f"{os.fspath(wad_path)}:{lump.upper()}"
    if data is None:
        raise DemoError(f"{label}: byte 0: the WAD has no lump {lump.upper()}")
    return parse_demo(data, label)


def load_demo(wad_path, demo) -> Demo:
    """``demo`` as a lump name of the WAD (``DEMO1``, ``demo2``) or a ``.lmp`` path."""
    text = os.fspath(demo)
    if not os.path.exists(text) and text.upper().startswith("DEMO") and len(text) <= 8:
        return wad_demo(wad_path, text)
    return read_demo(text)
