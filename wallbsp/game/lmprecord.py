"""Recording vanilla DOOM demos (version 1.9 ``.lmp``), as ``G_RecordDemo`` and
``G_WriteDemoTiccmd`` write them, so that DOOM and Chocolate Doom play them back.

    recorder = LmpRecorder(world.play)       # right after the new game, before its first tic
    cmd = recorder.record(world.play, cmd)   # every tic the play runs: the command it must run
    ... ; open("x.lmp", "wb").write(recorder.data())

The header is the game's settings when the recording starts (version 109, skill, episode,
map, deathmatch, respawn, fast, nomonsters, console player, the players present); every tic
then stores 4 bytes a player present (forwardmove, sidemove, the high byte of angleturn,
buttons) and ``data()`` ends with DOOM's 0x80.  A demo keeps one byte of each tic's turn:
as Chocolate Doom does when it records (``lowres_turn``), each turn is rounded to the
nearest 256 units and the error carried to the next tic, and the play must run the rounded
command (``record`` returns it), as DOOM re-reads what it wrote ("make SURE it is exactly the
same").  Reading demos is ``playsim.demos``.
"""
from __future__ import annotations

from wallbsp.game.playsim.demos import DEMO_VERSION, DEMOMARKER, parse_demo
from wallbsp.game.playsim.structs import TicCmd

__all__ = ["LmpRecorder", "round_turn"]


def _int16(value: int) -> int:
    return ((value + 0x8000) & 0xFFFF) - 0x8000


def round_turn(angleturn: int, carry: int) -> tuple[int, int]:
    """G_BuildTiccmd's ``lowres_turn``: ``(turn a demo can hold, carry to the next tic)``."""
    desired = _int16(angleturn + carry)
    rounded = _int16((desired + 128) & 0xFF00)
    return rounded, _int16(desired - rounded)


class LmpRecorder:
    """A v1.9 demo of ``play`` from its next tic on (module doc)."""

    def __init__(self, play):
        self.play = play
        present = [bool(p) for p in play.playeringame]
        self.header = bytes([DEMO_VERSION, play.gameskill, play.gameepisode, play.gamemap,
                             play.deathmatch, int(bool(play.respawnparm)),
                             int(bool(play.fastparm)), int(bool(play.nomonsters)),
                             play.consoleplayer] + [int(p) for p in present])
        self.players = [i for i, p in enumerate(present) if p]
        self.body = bytearray()
        self.carry = [0] * len(present)
        self.tics = 0

    @property
    def recording(self) -> bool:
        return self.play is not None

    def stop(self) -> None:
        """No more tics (a new game started: the demo is of one game, as DOOM's)."""
        self.play = None

    def record(self, play, cmds):
        """Store the tic commands ``cmds`` (one ``TicCmd``, or a list, one per player
        present) that ``play`` is about to run and return them as the demo holds them;
        a play other than the recorded one stops the recording (and gets ``cmds`` back)."""
        if play is not self.play:
            self.stop()
            return cmds
        single = isinstance(cmds, TicCmd)
        given = [cmds] if single else list(cmds)
        if len(given) != len(self.players):
            raise ValueError(f"LmpRecorder: {len(self.players)} players need "
                             f"{len(self.players)} commands a tic, not {len(given)}")
        stored = []
        for number, cmd in zip(self.players, given):
            turn, self.carry[number] = round_turn(cmd.angleturn, self.carry[number])
            self.body += bytes([cmd.forwardmove & 0xFF, cmd.sidemove & 0xFF,
                                (turn >> 8) & 0xFF, cmd.buttons & 0xFF])
            stored.append(TicCmd(cmd.forwardmove, cmd.sidemove, turn, cmd.buttons))
        self.tics += 1
        return stored[0] if single else stored

    def data(self) -> bytes:
        """The whole demo: header, tics, end marker (checked by reading it back)."""
        data = self.header + bytes(self.body) + bytes([DEMOMARKER])
        parse_demo(data, "<recorded demo>")
        return data
