"""Players 2-4 in their own colours (DOOM's R_InitTranslationTables and MF_TRANSLATION):
in two- and four-player Worlds on Freedoom's E1M1, player 2's, 3's and 4's bodies are drawn
with the green ramp (palette 0x70-0x7f) turned into the grey (0x60), brown (0x40) and red
(0x20) ones, checked pixel by pixel against
the same frame drawn with the translation bits cleared, through the WAD's own PLAYPAL and
COLORMAP read here."""
from __future__ import annotations

import math

import numpy as np
import pytest

from test_wad import freedoom
from wallbsp.assets.resources import ResourceSet
from wallbsp.camera import Camera
from wallbsp.game.world import World
from wallbsp.render import render
from wallbsp.render.frame import KIND_THING

TRANSLATION = 0xC000000


def lit_colours(wad):
    """``(34 levels, 256)`` rgb triples of every palette index through each COLORMAP row."""
    res = ResourceSet([wad])
    return res.palette[res.colormap].astype(np.int64)


@pytest.fixture(scope="module")
def worlds(freedoom_cache):
    wad = freedoom("freedoom1.wad")
    tree = freedoom_cache.tree("freedoom1.wad", "E1M1")
    return wad, {n: World(tree, 3, players=n) for n in (2, 4)}


def facing(mo, distance=70):
    """A camera ``distance`` in front of map object ``mo``, looking at it."""
    x, y, a = mo.x / 65536, mo.y / 65536, math.radians(mo.angle * 360 / 2 ** 32)
    return Camera(x + distance * math.cos(a), y + distance * math.sin(a), mo.z / 65536 + 41,
                  math.degrees(a) + 180)


@pytest.mark.parametrize("players,player,ramp", [(2, 2, 0x60), (4, 3, 0x40), (4, 4, 0x20)])
def test_players_two_to_four_are_drawn_in_their_colours(worlds, players, player, ramp):
    wad, found = worlds
    world = found[players]
    mo = world.play.players[player - 1].mo
    bits = mo.flags & TRANSLATION
    assert bits >> 26 == player - 1                            # DOOM's P_SpawnPlayer
    assert not world.play.players[0].mo.flags & TRANSLATION    # player 1 keeps green
    body = world.state.things.index_of(mo)
    camera = facing(mo)
    translated = render(world, camera, 160, 100)
    mo.flags &= ~TRANSLATION
    world.state.sync()
    try:
        green = render(world, camera, 160, 100)
    finally:
        mo.flags |= bits
        world.state.sync()
    assert np.array_equal(render(world, camera, 160, 100).color, translated.color)
    own = (translated.kind == KIND_THING) & (translated.index == body)
    assert own.sum() > 500
    changed = (translated.color != green.color).any(-1)
    assert changed.sum() > 100 and not changed[~own].any()   # only that player's body
    # each changed pixel: a green-ramp colour 0x70 + j at some light row k, drawn as
    # ramp + j at the same row
    lit = lit_colours(wad)
    was = green.color[changed].astype(np.int64)
    now = translated.color[changed].astype(np.int64)
    match = ((was[:, None, None] == lit[None, :, 0x70:0x80]).all(-1)
             & (now[:, None, None] == lit[None, :, ramp:ramp + 16]).all(-1))
    assert match.any(axis=(1, 2)).all()
