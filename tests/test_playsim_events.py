"""The play's event log (playsim/events.py) checked against what DOOM itself counts, over a
whole Freedoom demo: the records agree with the kill, item and sound counters, every
death follows its fatal blow, every sector change of a shootable thing is recorded."""
from pathlib import Path

import pytest

from wallbsp.doom import info
from wallbsp.game.playsim import ticker
from wallbsp.game.playsim.events import (CROSSED, SHOT, USED, Damaged, Killed, LineActivated,
                                         PickedUp, SectorEntered, SoundStarted, Woke)
from wallbsp.game.playsim.structs import Mobj
from wallbsp.game.playsim.trace import start_demo

WAD = Path("/usr/share/games/doom/freedoom1.wad")


def _sectors(play):
    return {th: th.subsector.sector for th in play.thinkers()
            if type(th) is Mobj and th.func is not None and th.flags & info.MF_SHOOTABLE}


@pytest.fixture(scope="module")
def demo_log():
    """(play at the end of freedoom1's DEMO1, its records by tic, sector changes missed)."""
    if not WAD.is_file():
        pytest.skip(f"{WAD} is not installed")
    play, demo = start_demo(WAD, "DEMO1")
    tics, missed, before = [], [], _sectors(play)
    for commands in demo.tics:
        play.g_ticker(commands)
        events = play.take_events()
        tics.append(events)
        after = _sectors(play)
        entered = {e.thing: e.sector for e in events if type(e) is SectorEntered}
        for thing, sector in after.items():
            if thing in before and before[thing] is not sector \
                    and entered.get(thing) is not sector:
                missed.append((len(tics), thing.type))
        before = after
    return play, tics, missed


def test_records_agree_with_dooms_counters(demo_log):
    play, tics, _ = demo_log
    events = [e for tic in tics for e in tic]
    player = play.players[0]
    kills = [e for e in events if type(e) is Killed]
    assert len(kills) > 10
    assert sum(1 for e in kills if e.target.flags & info.MF_COUNTKILL) == player.killcount
    picked = [e for e in events if type(e) is PickedUp]
    assert all(e.toucher is player.mo for e in picked)
    assert sum(1 for e in picked if e.item.flags & info.MF_COUNTITEM) == player.itemcount
    assert all(e.item.func is None for e in picked)              # taken off the map
    assert sum(1 for e in events if type(e) is SoundStarted) == play.sounds_started
    assert any(type(e) is Woke and e.target is player.mo for e in events)


def test_every_death_follows_its_fatal_blow(demo_log):
    _, tics, _ = demo_log
    health = {}                     # a monster's health after its last blow (none heal here)
    for events in tics:
        for i, e in enumerate(events):
            if type(e) is Killed:
                blow = events[i - 1]
                assert type(blow) is Damaged and blow.target is e.target
                assert blow.health <= 0 and blow.source is e.source
            elif type(e) is Damaged and e.target.player is None:
                before = health.get(e.target, e.target.info.spawnhealth)
                assert before > 0 and e.health == before - e.amount
                health[e.target] = e.health


def test_line_activations_and_sector_changes(demo_log):
    play, tics, missed = demo_log
    lines = [e for tic in tics for e in tic if type(e) is LineActivated]
    assert {e.how for e in lines} <= {USED, CROSSED, SHOT} and USED in {e.how for e in lines}
    for e in lines:
        assert e.line in play.lines and e.special > 0
        assert e.side in (0, 1) if e.how != SHOT else e.side == -1
    assert missed == []
    entered = [e for tic in tics for e in tic if type(e) is SectorEntered]
    assert any(e.thing is play.players[0].mo for e in entered)


def test_take_hands_the_log_over_and_an_untaken_log_is_dropped(monkeypatch):
    if not WAD.is_file():
        pytest.skip(f"{WAD} is not installed")
    play, demo = start_demo(WAD, "DEMO1")
    play.events.append("mark")
    taken = play.take_events()
    assert taken == ["mark"] and play.events == [] and play.take_events() == []
    monkeypatch.setattr(ticker, "EVENTS_LIMIT", 5)
    longest = 0
    for commands in demo.tics[:400]:
        play.g_ticker(commands)
        longest = max(longest, len(play.events))
    assert 5 < longest < 5 + 400
    assert len(play.events) <= longest
