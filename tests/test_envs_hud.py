"""The environments' ``hud=True`` (issue 21): DOOM's status bar and weapon in the ``rgb``
observation, as a world and a ``screen.Hud`` ticked the same way draw them; ``depth`` and
``labels`` of the view above the bar, the bar's rows "nothing"."""
import warnings

import numpy as np
import pytest

gym = pytest.importorskip("gymnasium")

import wallbsp.envs  # noqa: E402,F401  (registers the ids)
from gymnasium.utils.env_checker import check_env  # noqa: E402
from wallbsp.app.hudframe import hud_frame  # noqa: E402
from wallbsp.envs import DISCRETE_ACTIONS  # noqa: E402
from wallbsp.envs.actions import buttons_of  # noqa: E402
from wallbsp.game.world import World  # noqa: E402
from wallbsp.generate import generate_level  # noqa: E402
from wallbsp.screen.hud import Hud, bar_height, view_size  # noqa: E402

ACTIONS = list(DISCRETE_ACTIONS)
SIZE = (64, 40)


@pytest.fixture(scope="module")
def level():
    return generate_level(3, walls=60).level


def make(level, **options):
    return gym.make("wallbsp/Exit-v0", level=level, size=SIZE, **options).unwrapped


def test_the_rgb_observation_is_the_view_with_the_status_bar_and_weapon(level):
    env = make(level, hud=True, observations=("rgb", "depth", "labels"))
    obs, _ = env.reset(seed=0)
    twin, hud = World(env.world.tree, env.skill), Hud()
    plan = ["noop"] * 12 + ["forward"] * 6 + ["turn_left"] * 3     # the weapon bobs
    for name in plan:
        obs, *_ = env.step(ACTIONS.index(name))
        twin.tic(**buttons_of("discrete", ACTIONS.index(name)).tic_inputs(first=True))
        hud.tick(twin.play)
    expected, view = hud_frame(twin, twin.camera(env.fov), *SIZE, hud=hud)
    assert np.array_equal(obs["rgb"], expected)
    vh = view_size(*SIZE)[1]
    assert view.color.shape[:2] == (vh, SIZE[0])
    assert np.array_equal(obs["depth"][:vh], view.depth)
    assert np.isinf(obs["depth"][vh:]).all()
    assert np.array_equal(obs["labels"][:vh, :, 0], view.kind)
    assert (obs["labels"][vh:] == (0, -1)).all()
    assert SIZE[1] - vh == bar_height(SIZE[1])
    plain = make(level, observations=("rgb",))
    plain.reset(seed=0)
    for name in plan:
        bare, *_ = plain.step(ACTIONS.index(name))
    assert not np.array_equal(bare["rgb"][vh:], obs["rgb"][vh:])     # the bar is drawn


def test_hud_envs_pass_the_checker_and_render_the_picture(level):
    env = gym.make("wallbsp/Exit-v0", level=level, size=SIZE, hud=True,
                   observations=("rgb", "depth", "labels", "pose"), render_mode="rgb_array")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")          # depth's Box reaches inf
        check_env(env)
    obs, _ = env.reset(seed=1)
    assert np.array_equal(env.render(), obs["rgb"])


def test_a_pickup_message_reaches_the_huds_observation(level):
    env = make(level, hud=True, observations=("rgb",))
    env.reset(seed=0)
    env.world.messages.append((env.world.tic_count, "Picked up a medikit."))
    env.step(ACTIONS.index("noop"))
    assert env._hud.message.on and env._hud.message.text == "Picked up a medikit."


def test_a_vector_env_draws_the_hud_into_its_batch(level):
    from wallbsp.envs.vector import make_vec
    keys = ("rgb", "depth", "labels")
    vec = make_vec("wallbsp/Exit-v0", num_envs=2, workers=0, level=level, size=SIZE, hud=True,
                   observations=keys)
    one = make(level, hud=True, observations=keys)
    try:
        batch, _ = vec.reset(seed=0)
        alone, _ = one.reset(seed=0)
        for _ in range(5):
            batch, *_ = vec.step(np.array([ACTIONS.index("forward")] * 2))
            alone, *_ = one.step(ACTIONS.index("forward"))
        for key in keys:
            assert np.array_equal(batch[key][0], alone[key]), key
    finally:
        vec.close()
