"""The rules on a real map: every door of Freedoom's E1M1 opens far enough to walk through."""
from pathlib import Path
from types import SimpleNamespace

import pytest

from wallbsp.game.rules import Rules
from wallbsp.game.specials import LINE_SPECIALS
from wallbsp.sim.state import WorldState

FREEDOOM1 = Path("/usr/share/games/doom/freedoom1.wad")
PLAYER_HEIGHT = 56


@pytest.mark.skipif(not FREEDOOM1.exists(), reason="Freedoom is not installed")
def test_every_door_of_e1m1_opens_high_enough_for_the_player(freedoom_cache):
    level = freedoom_cache.level("freedoom1.wad", "E1M1")
    # the rules need the tree only to find where things are; no teleporters are used here
    state = WorldState(SimpleNamespace(level=level))
    rules = Rules(level, state, locate=lambda x, y: None)
    doors = {}         # door sector -> one wall that opens it (using a second would close it)
    for i, w in enumerate(level.walls):
        if w.special in LINE_SPECIALS and LINE_SPECIALS[w.special].trigger == "D":
            doors.setdefault(w.back, i)
    shut = {s for s in doors if state.ceiling[s] - state.floor[s] < 1}
    assert len(shut) >= 10
    for i in doors.values():
        rules.use_line(i, 0, keys={"blue", "red", "yellow"})
    for _ in range(60):
        rules.tic()
    for s in shut:
        assert state.ceiling[s] - state.floor[s] >= PLAYER_HEIGHT, s
