"""Messages and the automap's title in the WAD's words (issue 32's look beside Chocolate
Doom): the IWAD's DEHACKED BEX strings replace DOOM's English as DEH_String does."""
import os

import numpy as np
import pytest

from wallbsp.screen.art import OwnArt, WadArt
from wallbsp.screen.dehstrings import ENGLISH, map_title, shown
from wallbsp.screen.messages import paint_text

FREEDOOM1 = "/usr/share/games/doom/freedoom1.wad"
FREEDOOM2 = "/usr/share/games/doom/freedoom2.wad"
have_wads = pytest.mark.skipif(not (os.path.exists(FREEDOOM1) and os.path.exists(FREEDOOM2)),
                               reason="Freedoom is not installed")


@have_wads
def test_freedooms_dehacked_words_the_messages_and_map_titles():
    art = WadArt([FREEDOOM1])
    assert shown("Picked up an armor bonus.", art) == "Got a 1% armor bonus."
    assert shown(ENGLISH["GOTSHOTGUN"], art) == "You got the pump-action shotgun!"
    assert shown("not one of DOOM's", art) == "not one of DOOM's"
    assert map_title(art, "E1M1", "ignored") == "C1M1: Outer Prison"
    assert map_title(WadArt([FREEDOOM2]), "MAP01", "x") == "MAP01: Hydroelectric Plant"
    painted, english = (paint_text(t, art)[1] for t in ("Got a 1% armor bonus.",
                                                          "Picked up an armor bonus."))
    assert not np.array_equal(painted, english)


def test_our_own_art_keeps_the_text_and_our_levels_their_names():
    art = OwnArt()
    assert shown("Picked up an armor bonus.", art) == "Picked up an armor bonus."
    assert map_title(art, None, "The outpost") == "The outpost"
