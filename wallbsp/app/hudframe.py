"""Headless frames with DOOM's screen around the view (``--hud``): the 3-D view rendered
into the rows above the status bar, then ``wallbsp.screen``'s ``Hud`` over it."""
from __future__ import annotations

import numpy as np

from wallbsp.screen.hud import Hud, view_size

__all__ = ["hud_frame", "play_with_hud", "raise_weapon"]


def hud_frame(world, camera, width: int, height: int, hud: Hud | None = None, **render_options):
    """``(rgb, view frame)``: ``world`` seen by ``camera`` in the top ``view_size`` rows of
    a ``width × height`` picture, the status bar, weapon, message and flash drawn by ``hud``
    (a fresh one when None: the straight face)."""
    from wallbsp.render import render
    hud = hud or Hud()
    vw, vh = view_size(width, height, hud.statusbar)
    frame = render(world, camera, vw, vh, **render_options)
    rgb = np.zeros((height, width, 3), np.uint8)
    rgb[:vh] = frame.color
    return hud.draw(rgb, world.play), frame


def play_with_hud(world, tics) -> Hud:
    """Runs the tic commands ``tics`` on ``world`` with a ``Hud`` ticked after each level
    tic (DOOM's ST_Ticker and HU_Ticker), the world's messages put up as they come."""
    hud = Hud()
    last = world.messages[-1] if world.messages else None
    for cmd in tics:
        world.tic(cmd)
        if world.play.gamestate == 0:          # GS_LEVEL: G_Ticker runs them
            hud.tick(world.play)
        newest = world.messages[-1] if world.messages else None
        if newest is not last:
            last = newest
            hud.say(newest[1])
    return hud


def raise_weapon(play, player) -> None:
    """The player's weapon at rest at the top (its ready state, ``sy`` = WEAPONTOP, no
    flash), as it is once P_BringUpWeapon's raise is over: a still frame of a level's
    start shows the weapon ready, not below the view."""
    from wallbsp.screen.weapon import WEAPONTOP
    from wallbsp.doom.fixed import FRACUNIT
    weapon, flash = player.psprites
    weapon.state = play.weaponinfo[player.readyweapon].readystate
    weapon.sx, weapon.sy = FRACUNIT, WEAPONTOP
    flash.state = None
