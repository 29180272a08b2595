"""DOOM's cheat codes (``st_stuff.c``, ``am_map.c``), typed during play.

``CheatTyper.key(walk, char)`` sees every letter and digit typed in the game (as
``ST_Responder`` sees every key before the game does; the keys still move the player, as
in DOOM).  A finished sequence changes the play as DOOM's does, through the player's own
fields and cheat flags (``CF_GODMODE``, ``CF_NOCLIP``), and puts DOOM's message up:

- ``iddqd`` god mode (health 100), ``idfa`` all weapons, full ammo (a game's own weapons
  and ammunition too: ``wallbsp.content``), 200 armour (blue),
  ``idkfa`` the same and every key, ``idclip`` / ``idspispopd`` no clipping,
  ``idchoppers`` the chainsaw and invulnerability, ``idmypos`` the position;
- ``idclevXY`` a new game on episode X map Y (Doom II and our levels: map XY), at the
  same skill, through the walkthrough's ``warp(walk, episode, map)``;
- ``iddt`` only with the automap up: the map cheat cycles 0 -> 1 (every line) -> 2 (and
  the things) -> 0 (``walk.map_cheat``).

As in DOOM, no cheat works on Nightmare (skill 5) except ``iddt`` and ``idmypos``.
"""
from __future__ import annotations

import re

from wallbsp.doom import info
from wallbsp.game.playsim.structs import NUMCARDS, NUMWEAPONS

__all__ = ["CheatTyper", "CHEATS", "CF_NOCLIP", "CF_GODMODE"]

CF_NOCLIP, CF_GODMODE = 1, 2            # d_player.h's cheat flags
CHEATS = ("iddqd", "idkfa", "idfa", "idclip", "idspispopd", "idchoppers", "idmypos",
          "iddt", "idclev")
IDFA_ARMOR, IDFA_ARMOR_CLASS = 200, 2
NIGHTMARE = 5


class CheatTyper:
    """The letters typed so far that could still become a cheat (module doc)."""

    def __init__(self):
        self.typed = ""

    def key(self, walk, char: str) -> str | None:
        """One typed character; returns the cheat it finished, if any."""
        self.typed = (self.typed + char.lower())[-12:]
        for cheat in CHEATS:
            if cheat == "idclev":
                done = _idclev(self.typed)
                if done is not None:
                    self.typed = ""
                    _apply_idclev(walk, *done)
                    return cheat
            elif self.typed.endswith(cheat):
                self.typed = ""
                apply_cheat(walk, cheat)
                return cheat
        return None

    @property
    def in_progress(self) -> bool:
        """The letters typed last begin a cheat ("id" at least): the one-shot keys among
        them (F fullscreen, K screenshot, P, L, O ...) are the cheat's, not commands."""
        if re.search(r"idclev\d?$", self.typed):
            return True
        return any(self.typed.endswith(c[:n]) for c in CHEATS for n in range(2, len(c)))


def _idclev(typed: str):
    at = typed.rfind("idclev")
    digits = typed[at + 6:] if at >= 0 else ""
    if at >= 0 and len(digits) == 2 and digits.isdigit():
        return int(digits[0]), int(digits[1])
    return None


def _player(walk):
    play = walk.world.play
    return play.players[play.consoleplayer]


def _say(walk, text: str) -> None:
    walk.hud.say(text)


def apply_cheat(walk, cheat: str) -> None:
    """What ST_Responder (or AM_Responder for ``iddt``) does for ``cheat``."""
    if cheat == "iddt":
        if walk.show_map:
            walk.map_cheat = (walk.map_cheat + 1) % 3
        return
    player = _player(walk)
    if cheat == "idmypos":
        mo = player.mo
        _say(walk, f"ang=0x{mo.angle & 0xFFFFFFFF:x};x,y=(0x{mo.x & 0xFFFFFFFF:x},"
                   f"0x{mo.y & 0xFFFFFFFF:x})")
        return
    if walk.world.skill == NIGHTMARE:
        return
    if cheat == "iddqd":
        player.cheats ^= CF_GODMODE
        if player.cheats & CF_GODMODE:
            if player.mo is not None:
                player.mo.health = 100
            player.health = 100
            _say(walk, "Degreelessness Mode On")
        else:
            _say(walk, "Degreelessness Mode Off")
    elif cheat in ("idfa", "idkfa"):
        player.armorpoints, player.armortype = IDFA_ARMOR, IDFA_ARMOR_CLASS
        # every weapon and all the ammo it can hold: DOOM's, and a game's own after them
        player.weaponowned[:] = [int(i != info.wp_nochange or i < NUMWEAPONS)
                                 for i in range(len(player.weaponowned))]
        player.ammo[:] = list(player.maxammo)
        if cheat == "idkfa":
            player.cards[:] = [True] * NUMCARDS
            _say(walk, "Very Happy Ammo Added")
        else:
            _say(walk, "Ammo (no keys) Added")
    elif cheat in ("idclip", "idspispopd"):
        player.cheats ^= CF_NOCLIP
        _say(walk, "No Clipping Mode ON" if player.cheats & CF_NOCLIP
             else "No Clipping Mode OFF")
    elif cheat == "idchoppers":
        player.weaponowned[info.wp_chainsaw] = 1
        player.powers[info.pw_invulnerability] = 1
        _say(walk, "... doesn't suck - GM")


def _apply_idclev(walk, first: int, second: int) -> None:
    """ST_Responder's idclev: a new game on the map typed, if there is one."""
    if walk.world.skill == NIGHTMARE:
        return
    warp = getattr(walk, "warp", None)
    if warp is not None and warp(walk, first, second):
        _say(walk, "Changing Level...")
