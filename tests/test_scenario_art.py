"""ViZDoom's scenarios without Freedoom's IWAD: their levels take our own sprite and
texture folders (wallbsp/data/game, wallbsp/data/textures; tools/make_game_art.py) as their
pictures, so every frame their things can show has one of ours and basic's cacodemon is
drawn as our picture, not a box; with the IWAD the level names it alone, as before."""
import os
from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("gymnasium")

from test_game_level import reachable_frames  # noqa: E402
from wallbsp.assets.resources import ResourceSet  # noqa: E402
from wallbsp.envs import scenarios  # noqa: E402
from wallbsp.envs.scenarios import ScenarioEnv, our_resources, scenario_tree  # noqa: E402
from wallbsp.envs.vizdoom import Basic  # noqa: E402
from wallbsp.render.frame import KIND_THING  # noqa: E402
from wallbsp.doom import info  # noqa: E402

FREEDOOM = "/usr/share/games/doom/freedoom2.wad"
# what the scenarios spawn (wallbsp/envs/vizdoom_rooms.py, vizdoom_maps.py), what those fire
# or drop, and the effects of shots and respawns
SCENARIO_THINGS = ("MT_HEAD", "MT_SERGEANT", "MT_TROOP", "MT_POSSESSED", "MT_SHOTGUY",
                   "MT_CHAINGUY", "MT_MISC11", "MT_MISC2", "MT_MISC0", "MT_HEADSHOT",
                   "MT_TROOPSHOT", "MT_ROCKET", "MT_CLIP", "MT_SHOTGUN", "MT_CHAINGUN",
                   "MT_PUFF", "MT_BLOOD", "MT_TFOG", "MT_PLAYER")


@pytest.fixture
def no_iwad(monkeypatch, tmp_path):
    monkeypatch.setenv("WALLBSP_IWAD", str(tmp_path / "nowhere.wad"))
    monkeypatch.setattr(scenarios, "IWAD_PATHS", (str(tmp_path / "none.wad"),))


def test_without_an_iwad_a_scenario_level_names_our_folders(no_iwad):
    level = scenario_tree("basic").level
    assert [str(p) for p in level.resources] == our_resources()
    assert all(Path(p).is_dir() for p in our_resources())
    assert ResourceSet.from_level(level).sprite("HEADA0") is not None


def test_every_frame_of_the_scenarios_things_has_our_picture():
    res = ResourceSet(our_resources())
    missing = sorted(f for name in SCENARIO_THINGS for f in reachable_frames(getattr(info, name))
                     if res.sprite_frame(*f, 1) is None)
    assert missing == []


def test_basic_s_cacodemon_is_drawn_with_our_picture(no_iwad):
    env = ScenarioEnv(Basic, size=(160, 120), observations=("rgb", "labels"))
    obs, _ = env.reset(seed=0)
    caco = next(mo for mo in env.world.play.thinkers() if getattr(mo, "type", None) ==
                info.MT_HEAD)
    index = env.world.state.things.index_of(caco)
    labels = obs["labels"]
    drawn = (labels[..., 0] == KIND_THING) & (labels[..., 1] == index)
    pixels = obs["rgb"][drawn].astype(int)
    assert len(pixels) > 40
    # a box is one flat colour; our cacodemon is red skin with a green eye and white teeth
    assert len({tuple(p) for p in pixels}) >= 8
    r, g, b = pixels.mean(axis=0)
    assert r > 1.5 * g and r > 1.5 * b
    assert ((pixels[:, 1] > pixels[:, 0] + 30)).any()                 # the eye
    assert ((pixels.min(axis=1) > 0.7 * pixels.max(axis=1)) & (pixels.max(axis=1) > 90)).any()


@pytest.mark.skipif(not os.path.isfile(FREEDOOM), reason="Freedoom's IWAD is not installed")
def test_with_freedoom_the_level_names_the_iwad_alone(monkeypatch):
    monkeypatch.setenv("WALLBSP_IWAD", FREEDOOM)
    assert [str(p) for p in scenario_tree("basic").level.resources] == [FREEDOOM]
    monkeypatch.delenv("WALLBSP_IWAD")
    monkeypatch.setattr(scenarios, "IWAD_PATHS", ("/nonexistent/doom2.wad", FREEDOOM))
    assert [str(p) for p in scenario_tree("basic").level.resources] == [FREEDOOM]
