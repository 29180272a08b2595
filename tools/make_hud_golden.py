#!/usr/bin/env python3
"""Regenerate the status bar's and weapon's golden images, tests/golden/hud_*.png:

    python tools/make_hud_golden.py

Each view below is a 320 × 200 frame (a grey view, then ``wallbsp.screen``'s Hud) of a
player in a given state on Freedoom (``freedoom1.wad``; the super shotgun from
``freedoom2.wad``).  tests/test_screen.py draws the same views, compares them pixel for
pixel with these files and with its own reference (the WAD's patches blitted at DOOM's
positions).  Rerun (and look at the pictures) only after a deliberate change.
"""
from __future__ import annotations

import sys
from pathlib import Path
from types import SimpleNamespace

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

import numpy as np  # noqa: E402

WADS = {"freedoom1": "/usr/share/games/doom/freedoom1.wad",
        "freedoom2": "/usr/share/games/doom/freedoom2.wad"}
BACKGROUND = 96
FRACUNIT = 1 << 16
WEAPONTOP = 32 * FRACUNIT

# name -> (player fields, face index); ammo: clip, shell, cell, misl
BARS = {
    "start": (dict(health=100, armorpoints=0, readyweapon=1, ammo=[50, 0, 0, 0],
                   weaponowned=[1, 1, 0, 0, 0, 0, 0, 0, 0]), 1),
    "armed": (dict(health=67, armorpoints=150, readyweapon=2, ammo=[187, 43, 260, 9],
                   maxammo=[400, 100, 600, 100], weaponowned=[1, 1, 1, 1, 1, 1, 1, 1, 0],
                   cards=[True, False, True, False, True, False]), 9 + 6),
    "hurt": (dict(health=15, armorpoints=7, readyweapon=0, ammo=[0, 3, 0, 0],
                  weaponowned=[1, 1, 1, 0, 0, 0, 0, 0, 0],
                  cards=[True, True, True, True, True, True]), 4 * 8 + 5),
    "turned": (dict(health=45, armorpoints=100, readyweapon=3, ammo=[5, 0, 0, 0],
                    weaponowned=[1, 1, 0, 1, 0, 0, 0, 0, 0]), 2 * 8 + 4),
    "dead": (dict(health=0, armorpoints=0, readyweapon=1, ammo=[12, 0, 0, 0]), 41),
    "god": (dict(health=100, armorpoints=200, readyweapon=6, ammo=[0, 0, 40, 0],
                 weaponowned=[1, 1, 0, 0, 0, 0, 1, 0, 0]), 40),
}

# name -> (wad, weapon wp_*, flash?, sector light); the weapon at rest at the top
WEAPONS = [("fist", "freedoom1", 0, False, 160), ("pistol", "freedoom1", 1, False, 160),
           ("pistol_flash", "freedoom1", 1, True, 160), ("shotgun", "freedoom1", 2, False, 255),
           ("shotgun_flash", "freedoom1", 2, True, 96), ("chaingun", "freedoom1", 3, False, 128),
           ("rocket", "freedoom1", 4, False, 200), ("plasma", "freedoom1", 5, False, 160),
           ("bfg", "freedoom1", 6, False, 160), ("chainsaw", "freedoom1", 7, False, 112),
           ("chaingun_flash", "freedoom1", 3, True, 128),
           ("rocket_flash", "freedoom1", 4, True, 80),
           ("plasma_flash", "freedoom1", 5, True, 160), ("bfg_flash", "freedoom1", 6, True, 160),
           ("supershotgun", "freedoom2", 8, False, 160)]


def fake_play(wad: str, light: int = 160, **fields):
    """What the Hud reads of a play: a ``Player`` with ``fields`` and a map object in a
    sector of light ``light``."""
    from wallbsp.game.playsim.structs import Player
    from wallbsp.doom.rng import Random
    player = Player()
    player.health, player.maxammo = 100, [200, 50, 300, 50]
    player.weaponowned = [1, 1, 0, 0, 0, 0, 0, 0, 0]
    for key, value in fields.items():
        setattr(player, key, value)
    sector = SimpleNamespace(lightlevel=light)
    player.mo = SimpleNamespace(x=0, y=0, angle=0, subsector=SimpleNamespace(sector=sector))
    from wallbsp.doom.tables import DOOM
    return SimpleNamespace(players=[player], consoleplayer=0, netgame=False, deathmatch=0,
                           rng=Random(), wad_path=WADS[wad], wad_files=(), tables=DOOM)


def armed(play, weapon: int, flash: bool):
    """The player holding ``weapon`` at rest (``sx`` 1, ``sy`` at the top): its ready
    state, or with ``flash`` its firing state and its first flash frame."""
    from wallbsp.doom import info
    player = play.players[0]
    player.readyweapon = weapon
    weapon_psp, flash_psp = player.psprites
    weapon_psp.state = firing_state(weapon) if flash else info.WEAPONINFO[weapon].readystate
    flash_psp.state = info.WEAPONINFO[weapon].flashstate if flash else None
    for psp in player.psprites:
        psp.sx, psp.sy = FRACUNIT, WEAPONTOP
    return play


def firing_state(weapon: int) -> int:
    """The weapon's state that fires (its ``A_Fire*`` action sets the flash), after its
    attack state."""
    from wallbsp.doom import info
    state = info.WEAPONINFO[weapon].atkstate
    for _ in range(16):
        if (info.STATES[state].action or "").startswith("A_Fire"):
            return state
        state = info.STATES[state].nextstate
    raise ValueError(f"weapon {weapon} has no firing state")


def hud_frames():
    """``(name, frame, play)`` for every golden view."""
    from wallbsp.screen.hud import Hud
    for name, (fields, face) in BARS.items():
        play = fake_play("freedoom1", **fields)
        hud = Hud(weapon=False)
        hud.face.index = face
        yield f"hud_bar_{name}", draw(hud, play), play
    for name, wad, weapon, flash, light in WEAPONS:
        play = armed(fake_play(wad, light), weapon, flash)
        yield f"hud_weapon_{name}", draw(Hud(), play), play


def draw(hud, play):
    frame = np.full((200, 320, 3), BACKGROUND, np.uint8)
    return hud.draw(frame, play)


def main() -> int:
    from wallbsp.image import save_png
    out = ROOT / "tests" / "golden"
    out.mkdir(parents=True, exist_ok=True)
    for name, frame, _ in hud_frames():
        save_png(out / f"{name}.png", frame)
        print(out / f"{name}.png")
    return 0


if __name__ == "__main__":
    sys.exit(main())
