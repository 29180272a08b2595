"""``render_weapon`` (ViZDoom's option, apart from ``render_hud``): the player's weapon
drawn over the scenario environments' view without the status bar, placed as ZDoom places
it in a 4:3 view (``screen.weapon``'s ``stretched``), on where ViZDoom draws it; drawing
changes nothing of the episodes."""
import numpy as np
import pytest

gym = pytest.importorskip("gymnasium")

import wallbsp.envs  # noqa: E402,F401  (registers the ids)
from wallbsp.screen.hud import Hud  # noqa: E402
from wallbsp.screen.weapon import FF_FRAMEMASK, psprite_columns  # noqa: E402


def basic(size=(160, 120), **options):
    return gym.make("wallbsp/Basic-v0", size=size, observations=("rgb",), **options).unwrapped


def test_the_weapon_is_in_the_frame_with_render_weapon_and_not_without():
    shown, bare = basic(), basic(render_weapon=False)
    assert shown.render_weapon and not bare.render_weapon       # basic's default: shown
    on, _ = shown.reset(seed=3)
    off, _ = bare.reset(seed=3)
    drawn = (on["rgb"] != off["rgb"]).any(axis=-1)
    rows, cols = np.nonzero(drawn)
    # the pistol, at ZDoom's place: its bottom on the frame's, in the middle
    assert drawn.sum() > 300 and rows.max() == 119 and 60 < cols.mean() < 100
    play = shown.world.play
    psp = play.players[0].psprites[0]
    state = play.tables.states[psp.state]
    picture, _ = shown.screen_art().sprite(play.tables.sprnames[state.sprite],
                                           chr(ord("A") + (state.frame & FF_FRAMEMASK)))
    # 200 rows of DOOM's screen over 120: the picture's height times 0.6, not DOOM's 0.5
    assert abs((rows.max() - rows.min() + 1) - picture.height * 120 / 200) <= 2
    shown.close(), bare.close()


def test_scenarios_whose_player_holds_nothing_in_vizdoom_draw_no_weapon():
    gathering = gym.make("wallbsp/HealthGathering-v0", size=(80, 60)).unwrapped
    cover = gym.make("wallbsp/TakeCover-v0", size=(80, 60)).unwrapped
    centre = gym.make("wallbsp/DefendTheCenter-v0", size=(80, 60)).unwrapped
    assert not gathering.render_weapon and not cover.render_weapon and centre.render_weapon
    assert gym.make("wallbsp/HealthGathering-v0", render_weapon=True).unwrapped.render_weapon


def test_at_320x200_the_weapon_is_dooms_full_screen_one_a_unit_to_the_left():
    """At DOOM's own 320 x 200 the stretched placement is DOOM's (one pixel a unit), but
    for the unit ZDoom's weapon rests to the left of DOOM's."""
    env = basic(size=(320, 200))
    obs, _ = env.reset(seed=1)
    bare = basic(size=(320, 200), render_weapon=False)
    view, _ = bare.reset(seed=1)
    doom = Hud(statusbar=False, messages=False, art=env.screen_art()).draw(
        view["rgb"].copy(), env.world.play)
    drawn = (doom != view["rgb"]).any(axis=-1)
    assert drawn.any()
    expected = view["rgb"].copy()
    expected[:, :-1][drawn[:, 1:]] = doom[:, 1:][drawn[:, 1:]]
    assert np.array_equal(obs["rgb"], expected)


def test_the_render_mode_picture_has_the_weapon_too():
    env = gym.make("wallbsp/Basic-v0", size=(80, 60), observations=("rgb",),
                   render_mode="rgb_array")
    obs, _ = env.reset(seed=2)
    assert np.array_equal(env.render(), obs["rgb"])


def test_drawing_the_weapon_changes_no_episode():
    """docs/scenarios.md's statistics stand: a random agent's returns, lengths and game
    variables are the same with and without the weapon drawn."""
    for scenario in ("Basic", "DefendTheCenter"):
        runs = []
        for weapon in (True, False):
            env = gym.make(f"wallbsp/{scenario}-v0", size=(40, 30), frame_skip=4,
                           render_weapon=weapon, max_tics=400)
            env.action_space.seed(5)
            trace = []
            for episode in range(3):
                env.reset(seed=episode)
                done = False
                while not done:
                    _, reward, terminated, truncated, info = env.step(env.action_space.sample())
                    done = terminated or truncated
                    trace.append((reward, info["tics"], info["health"]))
            runs.append(trace)
        assert runs[0] == runs[1]


def test_stretched_placement_fills_the_view_height_as_dooms_fills_200_rows():
    class Picture:
        width, height, left, top = 60, 80, -130, -120
    dooms = psprite_columns(65536, 32 * 65536, Picture, False, 320, 200)
    zdooms = psprite_columns(65536, 32 * 65536, Picture, False, 160, 120, stretched=True)
    assert dooms[2] + len(dooms[3]) == 200          # the picture's bottom row at the bottom
    assert zdooms[2] + len(zdooms[3]) == 120
    assert len(zdooms[3]) == pytest.approx(len(dooms[3]) * 120 / 200, abs=1)
    assert len(zdooms[1]) == pytest.approx(len(dooms[1]) / 2, abs=1)
