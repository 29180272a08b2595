"""Issue 34's environments: an action outside the action space is one ValueError line (the
verdict of the space's ``contains``) before the world moves; options are checked against
docs/environments.md's ranges before anything is allocated or built."""
import numpy as np
import pytest

gym = pytest.importorskip("gymnasium")

import wallbsp.envs  # noqa: E402  (registers the ids)
from wallbsp.envs.checks import check_action, check_batch  # noqa: E402
from wallbsp.generate import generate_level  # noqa: E402

SMALL = {"size": (32, 24), "observations": ("pose",)}
HUGE = 10 ** 400


@pytest.fixture(scope="module")
def level():
    return generate_level(3, walls=60).level


def make(env_id, **options):
    return gym.make(env_id, **options).unwrapped


def pose_after(env, action):
    """The pose after a refused ``action``, and that it was refused in one line."""
    with pytest.raises(ValueError) as caught:
        env.step(action)
    assert "\n" not in str(caught.value) and "action" in str(caught.value)
    return env.world.tic_count, env.world.player.x, env.world.player.angle


@pytest.mark.parametrize("kind,bad,good", [
    ("discrete", [-1, -14, 14, 1.5, "3", HUGE, None, [3], np.float64(3), np.int8(-1)],
     [3, np.int64(13), np.array(2), True]),
    ("multidiscrete", [[3, 0, 0, 0, 0], [0, 0, 0, 0, -1], [1, 0, 0, 0], np.zeros(5) + 0.5,
                       "00000", [[0] * 5], 7],
     [[2, 2, 2, 1, 1], np.array([0, 1, 0, 1, 0], np.int8)]),
    ("box", [[0, 0, 0, 0, float("nan")], np.zeros(4), [2, 0, 0, 0, 0], ["a"] * 5, 0.5,
             [HUGE, 0, 0, 0, 0]],
     [np.zeros(5, np.float32), [1, -1, 0.5, 0, 0], np.zeros(5)]),
])
def test_actions_outside_the_space_are_refused_and_the_world_does_not_move(level, kind, bad,
                                                                           good):
    env = make("wallbsp/Exit-v0", level=level, action_space=kind, **SMALL)
    env.reset(seed=1)
    before = (env.world.tic_count, env.world.player.x, env.world.player.angle)
    for action in bad:
        assert pose_after(env, action) == before, action
    for action in good:
        env.step(action)
    assert env.world.tic_count == len(good)


def test_the_verdict_is_the_space_s_own():
    from gymnasium import spaces
    cases = [(spaces.Discrete(14), [-1, 0, 13, 14, 1.5, "3", True, np.int64(5), np.array(5),
                                    np.array([5]), np.uint8(200)]),
             (spaces.MultiDiscrete([3, 3, 2]), [[0, 0, 0], [2, 2, 1], [3, 0, 0], [0, 0],
                                                np.array([1, 1, 1], np.int8), [-1, 0, 0]]),
             (spaces.MultiBinary(3), [[0, 1, 1], [2, 0, 0], np.array([1, 0, 1]), [0, 1]]),
             (spaces.Box(-1.0, 1.0, (2,), np.float32), [np.zeros(2, np.float32), [2, 0],
                                                        [np.nan, 0], np.zeros(3, np.float32)])]
    for space, actions in cases:
        for action in actions:
            try:
                check_action(space, action)
                ours = True
            except ValueError:
                ours = False
            assert ours == space.contains(action), (space, action)


def test_a_vector_env_checks_the_whole_batch_first():
    from gymnasium import spaces
    check_batch(spaces.Discrete(14), np.array([0, 13, 5]), 3)
    for bad in (np.array([0, 14, 5]), [0, "3", 1], np.array([0, 1]), np.array([0.5, 1, 2])):
        with pytest.raises(ValueError, match="the actions must be 3 of"):
            check_batch(spaces.Discrete(14), bad, 3)
    box = spaces.Box(-1.0, 1.0, (5,), np.float32)
    check_batch(box, np.zeros((2, 5)), 2)
    with pytest.raises(ValueError):
        check_batch(box, np.full((2, 5), np.nan), 2)


@pytest.mark.parametrize("env_id,options,name", [
    ("wallbsp/Explore-v0", dict(skill=3.5), "skill"),
    ("wallbsp/Explore-v0", dict(walls=-5), "walls"),
    ("wallbsp/Explore-v0", dict(walls=10 ** 7), "walls"),
    ("wallbsp/Explore-v0", dict(frame_skip=float("inf")), "frame_skip"),
    ("wallbsp/Explore-v0", dict(size=(float("inf"), 5)), "width"),
    ("wallbsp/Explore-v0", dict(size=(100000, 100000)), "width"),
    ("wallbsp/Explore-v0", dict(size=(4096, 4096)), "pixels"),
    ("wallbsp/Explore-v0", dict(size="160x120"), "size"),
    ("wallbsp/Explore-v0", dict(observations=None), "observations"),
    ("wallbsp/Explore-v0", dict(max_tics=HUGE), "max_tics"),
    ("wallbsp/Explore-v0", dict(fov=180), "fov"),
    ("wallbsp/Explore-v0", dict(textures="no"), "textures"),
    ("wallbsp/Explore-v0", dict(action_space=None), "action_space"),
    ("wallbsp/Explore-v0", dict(cell=float("nan")), "cell"),
    ("wallbsp/Explore-v0", dict(candidates=1.5), "candidates"),
    ("wallbsp/Exit-v0", dict(level=5), "level"),
    ("wallbsp/Exit-v0", dict(level="x.json", tic_cost=float("inf")), "tic_cost"),
    ("wallbsp/Basic-v0", dict(observations=None), "observations"),
    ("wallbsp/Basic-v0", dict(buttons="ATTACK"), "buttons"),
    ("wallbsp/Basic-v0", dict(skill=0), "skill"),
])
def test_options_out_of_range_are_one_line_naming_them(env_id, options, name):
    with pytest.raises(ValueError) as caught:
        make(env_id, **options)
    text = str(caught.value)
    assert name in text and "\n" not in text and len(text) < 300


def test_reset_s_seed_and_options_are_checked(level):
    env = make("wallbsp/Exit-v0", level=level, **SMALL)
    for seed in (-1, 1.5, "1", HUGE):
        with pytest.raises(ValueError, match="seed"):
            env.reset(seed=seed)
    with pytest.raises(ValueError, match="options"):
        env.reset(options=[1])
    env.reset(seed=np.int64(5))


def test_multiagent_actions_and_options():
    pytest.importorskip("pettingzoo")
    from wallbsp.envs import parallel_env
    for options, name in ((dict(players=5), "players"), (dict(size=(0, 5)), "width"),
                          (dict(observations=None), "observations"),
                          (dict(mode=None), "mode"), (dict(frag_limit=0.5), "frag_limit")):
        with pytest.raises(ValueError, match=name):
            parallel_env(**options)
    env = parallel_env(size=(32, 24), max_tics=5, observations=("pose",))
    env.reset(seed=1)
    for actions in ({"player_0": -1}, {"player_9": 0}, [0, 0], {"player_1": 1.5}):
        with pytest.raises(ValueError):
            env.step(actions)
    assert env.world.tic_count == 0
    env.step({"player_0": 1, "player_1": None})
    assert env.world.tic_count == 1


def test_a_vector_env_refuses_a_bad_batch_before_any_env_steps():
    from wallbsp.envs import make_vec
    envs = make_vec("wallbsp/Explore-v0", 2, workers=0, size=(32, 24), walls=60,
                    observations=("pose",))
    try:
        obs, _ = envs.reset(seed=3)
        for bad in (np.array([0, 14]), np.array([1, -1]), [1.5, 1], np.array([1])):
            with pytest.raises(ValueError, match="actions"):
                envs.step(bad)
        with pytest.raises(ValueError, match="seed"):
            envs.reset(seed=[1, -1])
        again, *_ = envs.step(np.array([0, 0]))
        assert np.array_equal(again["pose"], obs["pose"])     # noop: nobody moved before
    finally:
        envs.close()
