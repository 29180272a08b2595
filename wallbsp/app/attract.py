"""DOOM's attract loop (``D_DoAdvanceDemo``): the title picture, the WAD's demos playing,
the credits, round and round until a key opens the menu.

``Attract(wad, art)`` is ``walk.attract`` while the loop runs: the walkthrough asks it for
the page shown (``page``: a picture over the whole screen, counting its tics down in
``tic``), tells it when a demo played back has ended (``advance``: the next page or demo,
a World made by ``make_world(lump)`` whose ``demo_commands`` are the demo's tic commands),
and a key in the loop opens DOOM's menu
(``controls``).  A new game, a load or a warp ends the loop (``start_level``).  The pages
are DOOM's: TITLEPIC 170 tics (Doom II 11 seconds), CREDIT 200; the demos DEMO1-DEMO4
that the WAD holds and that are single-player v1.9 demos.
"""
from __future__ import annotations

import numpy as np

from wallbsp.screen.remap import paste

__all__ = ["Attract", "attract_sequence", "PAGE_TICS"]

PAGE_TICS = {"TITLEPIC": 170, "CREDIT": 200}
COMMERCIAL_TITLE_TICS = 35 * 11


def attract_sequence(lumps, commercial: bool) -> list:
    """D_DoAdvanceDemo's order of pages and demos, with what the WAD lacks left out."""
    title = ("page", "TITLEPIC", COMMERCIAL_TITLE_TICS if commercial else 170)
    credit = ("page", "CREDIT", 200)
    order = [title, ("demo", "DEMO1"), credit, ("demo", "DEMO2"), title, ("demo", "DEMO3"),
             credit, ("demo", "DEMO4")]
    return [step for step in order if step[1] in lumps]


class Attract:
    """The attract loop of one WAD (module doc); ``make_world(lump)`` is the World of a
    demo (None when it cannot be played here)."""

    def __init__(self, sequence, art, make_world, start_level):
        self.sequence = sequence or [("page", "TITLEPIC", 170)]
        self.art = art
        self.make_world = make_world
        self.start_level = start_level
        self.index = -1
        self.page = None            # the page's name while one shows
        self.page_tics = 0
        self._pictures = {}

    def begin(self, walk) -> None:
        self.index = -1
        self.advance(walk)

    def advance(self, walk) -> None:
        """The next step: a page, or a demo (played from its first tic)."""
        for _ in range(len(self.sequence)):
            self.index = (self.index + 1) % len(self.sequence)
            step = self.sequence[self.index]
            if step[0] == "page":
                self.page, self.page_tics = step[1], step[2]
                walk.attract = self
                return
            world = self.make_world(step[1])
            if world is not None:
                self.page = None
                self.start_level(walk, world.tree, "", world=world)
                walk.attract = self
                walk.playback = iter(world.demo_commands)
                return

    def tic(self, walk) -> None:
        """One tic of a page."""
        self.page_tics -= 1
        if self.page_tics <= 0:
            self.advance(walk)

    def draw(self, picture) -> None:
        """The page over the whole picture (nearest pixels from 320 x 200)."""
        if self.page is None:
            return
        height, width = picture.shape[:2]
        key = (self.page, width, height)
        if key not in self._pictures:
            self._pictures.clear()
            self._pictures[key] = page_picture(self.art, self.page, width, height)
        rgb, mask = self._pictures[key]
        picture[...] = 0
        paste(picture, rgb, mask)


def page_picture(art, name, width, height):
    """``(rgb, mask)`` of the page ``name`` scaled to ``width`` x ``height``."""
    patch = art.patch(name) if art is not None else None
    if patch is None:
        return np.zeros((height, width, 3), np.uint8), np.zeros((height, width), bool)
    rgb, mask = art.rgb(patch)
    ys = np.minimum(np.arange(height) * 200 // height, rgb.shape[0] - 1)
    xs = np.minimum(np.arange(width) * 320 // width, rgb.shape[1] - 1)
    return (np.ascontiguousarray(rgb[ys[:, None], xs[None, :]]),
            np.ascontiguousarray(mask[ys[:, None], xs[None, :]]))
