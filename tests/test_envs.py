"""The Gymnasium environments (SPEC §9, issue 13): the API checker, seeds, rewards of each
task, the action tables, observations, render modes and vector environments.  Small
frames and small generated levels keep it quick."""
import math
import os
import subprocess
import sys
import warnings
from dataclasses import replace

import numpy as np
import pytest

gym = pytest.importorskip("gymnasium")

import wallbsp.envs  # noqa: E402  (registers the ids)
from gymnasium.utils.env_checker import check_env  # noqa: E402
from wallbsp.envs import DISCRETE_ACTIONS, TURN_DEGREES, Buttons
from wallbsp.envs.actions import buttons_of
from wallbsp.generate import generate_level
from wallbsp.assets.catalogue import TEXTURE_DIR
from wallbsp.level.io import save_level

SMALL = {"size": (32, 24), "walls": 60}
ACTIONS = list(DISCRETE_ACTIONS)


@pytest.fixture(scope="module")
def exit_level():
    return generate_level(3, walls=60)


def make(env_id, **options):
    return gym.make(env_id, **options).unwrapped


def quietly_check(env, render=False):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")          # depth's Box reaches inf, as SPEC §5 says
        check_env(env, skip_render_check=not render)


@pytest.mark.parametrize("env_id", ["wallbsp/Explore-v0", "wallbsp/Find-v0"])
def test_generated_envs_pass_the_checker(env_id):
    quietly_check(gym.make(env_id, **SMALL, observations=("rgb", "depth", "labels", "pose")))


def test_exit_env_passes_the_checker_with_every_observation(exit_level):
    quietly_check(gym.make("wallbsp/Exit-v0", level=exit_level.level, size=(32, 24),
                           observations=("rgb", "depth", "labels", "automap", "pose"),
                           action_space="box"), render=True)


def test_observations_have_their_shapes_and_types(exit_level):
    env = make("wallbsp/Exit-v0", level=exit_level.level, size=(40, 30),
               observations=("rgb", "depth", "labels", "automap", "pose"))
    obs, _ = env.reset(seed=0)
    assert obs["rgb"].shape == (30, 40, 3) and obs["rgb"].dtype == np.uint8
    assert obs["depth"].shape == (30, 40) and obs["depth"].dtype == np.float32
    assert obs["labels"].shape == (30, 40, 2) and obs["labels"].dtype == np.int32
    assert obs["automap"].shape == (30, 40, 3) and obs["automap"].any()
    start = exit_level.level.start
    assert obs["pose"].tolist()[:2] == [start.x, start.y]
    kinds = set(np.unique(obs["labels"][..., 0]).tolist())
    assert {1, 2, 3} <= kinds                    # walls, floor and ceiling in view
    walls = obs["labels"][..., 0] == 1
    assert np.isfinite(obs["depth"][walls]).all() and (obs["depth"][walls] > 0).all()
    assert (obs["labels"][walls][:, 1] >= 0).all()


def test_view_observations_are_the_frame_in_new_c_ordered_arrays(exit_level):
    """The frame's column-major buffers, copied row-major (a vector env's batch copy is
    then a plain memory copy); a step later the arrays kept are unchanged."""
    env = make("wallbsp/Exit-v0", level=exit_level.level, size=(40, 30),
               observations=("rgb", "depth", "labels", "automap"))
    obs, _ = env.reset(seed=0)
    frame = env.frame
    assert np.array_equal(obs["rgb"], frame.color)
    assert np.array_equal(obs["depth"], frame.depth)
    assert np.array_equal(obs["labels"][..., 0], frame.kind)
    assert np.array_equal(obs["labels"][..., 1], frame.index)
    assert all(a.flags.c_contiguous and a.flags.owndata for a in obs.values())
    kept = {k: v.copy() for k, v in obs.items()}
    new, *_ = env.step(ACTIONS.index("turn_left"))
    assert not np.array_equal(new["rgb"], kept["rgb"])          # the view turned ...
    assert all(np.array_equal(obs[k], kept[k]) for k in obs)    # ... the old arrays did not


def test_same_seed_same_observations_other_seed_other_level():
    def run(seed):
        env = make("wallbsp/Explore-v0", **SMALL)
        obs, info = env.reset(seed=seed)
        frames = [obs]
        for name in ("forward", "turn_left", "run_forward", "strafe_right"):
            frames.append(env.step(ACTIONS.index(name))[0])
        return info["level_seed"], frames

    seed_a, frames_a = run(7)
    seed_b, frames_b = run(7)
    assert seed_a == seed_b
    for a, b in zip(frames_a, frames_b):
        for key in a:
            assert np.array_equal(a[key], b[key]), key
    assert run(8)[0] != seed_a


def test_reset_without_seed_draws_a_new_level():
    env = make("wallbsp/Explore-v0", **SMALL, observations=("pose",))
    seeds = {env.reset(seed=1)[1]["level_seed"]}
    seeds |= {env.reset()[1]["level_seed"] for _ in range(2)}
    assert len(seeds) == 3


def test_explore_rewards_new_ground_once():
    env = make("wallbsp/Explore-v0", **SMALL, observations=("pose",), cell_reward=0.5)
    env.reset(seed=2)
    gained = sum(env.step(ACTIONS.index("run_forward"))[1] for _ in range(20))
    assert gained >= 0.5 and gained % 0.5 == 0
    cells = env.episode_info()["cells_visited"]
    assert cells == 1 + gained / 0.5
    for _ in range(30):                          # momentum runs out
        env.step(ACTIONS.index("noop"))
    assert sum(env.step(ACTIONS.index("noop"))[1] for _ in range(3)) == 0.0


def _facing_the_switch(generated):
    """A point 24 units in front of the first exit switch's middle, facing it."""
    level = generated.level
    wall = level.walls[generated.goal_walls[0]]
    (x1, y1), (x2, y2) = level.vertices[wall.v1], level.vertices[wall.v2]
    length = math.hypot(x2 - x1, y2 - y1)
    nx, ny = (y2 - y1) / length, -(x2 - x1) / length      # the front: right of v1 -> v2
    x, y = (x1 + x2) / 2 + 24 * nx, (y1 + y2) / 2 + 24 * ny
    return x, y, math.degrees(math.atan2(-ny, -nx))


def test_exit_pays_one_on_leaving_and_a_cost_per_tic(exit_level):
    env = make("wallbsp/Exit-v0", level=exit_level.level, size=(32, 24), tic_cost=0.01,
               frame_skip=3)
    env.reset(seed=0)
    _, reward, terminated, truncated, info = env.step(ACTIONS.index("noop"))
    assert reward == pytest.approx(-0.03) and not terminated and info["tics"] == 3
    env.world.place_player(*_facing_the_switch(exit_level))
    _, reward, terminated, truncated, info = env.step(ACTIONS.index("use"))
    assert terminated and not truncated and info["exited"] == "normal"
    assert reward == pytest.approx(0.99) and info["tics"] == 4   # the skip stops at the exit


def test_find_pays_for_touching_the_target_and_labels_show_it():
    env = make("wallbsp/Find-v0", size=(64, 48), walls=60)
    _, info = env.reset(seed=4)
    target = info["target"]
    things = env.world.things
    tx, ty = float(things.x[target]), float(things.y[target])
    level = env.generated.level
    assert level.things[target].type == wallbsp.generate.TARGET_TYPE
    # from the target's room, 80 units off, facing it: in view, labelled with its index
    x, y, angle = _clear_spot_near(env, tx, ty)
    env.world.place_player(x, y, angle)
    obs, reward, terminated, _, info = env.step(ACTIONS.index("noop"))
    assert not terminated and info["target_visible"]
    seen = (obs["labels"][..., 0] == 4) & (obs["labels"][..., 1] == target)
    assert seen.any()
    env.world.place_player(tx + 10, ty, 0.0)
    _, reward, terminated, _, info = env.step(ACTIONS.index("noop"))
    assert terminated and info["found"] and reward == pytest.approx(1 - 1e-4)


def _clear_spot_near(env, tx, ty):
    """A point 80 units from the target, in its sector, facing it."""
    locate = env.world.tree.locate
    for k in range(8):
        a = k * math.pi / 4
        x, y = tx + 80 * math.cos(a), ty + 80 * math.sin(a)
        if locate(x, y) == locate(tx, ty):
            return x, y, math.degrees(a + math.pi)
    raise AssertionError("no clear spot near the target")


def test_time_limit_truncates_counting_tics():
    env = make("wallbsp/Explore-v0", **SMALL, observations=("pose",), frame_skip=2,
               max_tics=3)
    env.reset(seed=0)
    _, _, terminated, truncated, info = env.step(0)
    assert (terminated, truncated, info["tics"]) == (False, False, 2)
    _, _, terminated, truncated, info = env.step(0)
    assert (terminated, truncated, info["tics"]) == (False, True, 3)


def test_turning_and_walking_move_the_pose():
    env = make("wallbsp/Explore-v0", **SMALL, observations=("pose",))
    pose = env.reset(seed=5)[0]["pose"]
    turned = env.step(ACTIONS.index("turn_left"))[0]["pose"]
    assert (turned[3] - pose[3]) % 360 == pytest.approx(TURN_DEGREES, abs=1e-4)
    moved = env.step(ACTIONS.index("forward"))[0]["pose"]
    heading = math.radians(turned[3])
    step = moved[:2] - turned[:2]
    assert step @ np.array([math.cos(heading), math.sin(heading)]) > 0


def test_the_three_action_spaces_mean_the_same_buttons():
    assert buttons_of("discrete", ACTIONS.index("run_forward_turn_left")) \
        == Buttons(1.0, 0.0, 1.0, False, True)
    assert buttons_of("multidiscrete", [1, 0, 1, 0, 1]) == Buttons(1.0, 0.0, 1.0, False, True)
    assert buttons_of("multidiscrete", [2, 2, 2, 1, 0]) == Buttons(-1.0, 1.0, -1.0, True, False)
    assert buttons_of("box", np.array([1, 0, 1, -1, 1], np.float32)) \
        == Buttons(1.0, 0.0, 1.0, False, True)
    assert Buttons(turn=1.0, run=True).tic_inputs(first=True)["turn"] == 2 * TURN_DEGREES
    assert Buttons(use=True).tic_inputs(first=False)["use"] is False


@pytest.mark.filterwarnings("ignore::UserWarning")      # gymnasium's, for render_mode="vr"
@pytest.mark.parametrize("options", [{"size": (0, 10)}, {"frame_skip": 0},
                                     {"observations": ("rgb", "smell")},
                                     {"action_space": "joystick"}, {"fov": 180},
                                     {"render_mode": "vr"}, {"candidates": 0},
                                     {"candidates": "some"}])
def test_bad_options_are_errors(options):
    with pytest.raises(ValueError):
        make("wallbsp/Explore-v0", **options)


def test_candidates_reach_the_compiler():
    from wallbsp.bsp.build import DEFAULT_CANDIDATES
    for option, k in (({}, DEFAULT_CANDIDATES), ({"candidates": 1}, 1)):
        env = make("wallbsp/Explore-v0", **SMALL, observations=("pose",), **option)
        env.reset(seed=1)
        assert env.world.tree.candidates == k


def test_exit_needs_a_level():
    with pytest.raises(ValueError, match="level="):
        make("wallbsp/Exit-v0")


def test_a_level_file_is_compiled_once_per_process(tmp_path, exit_level):
    path = tmp_path / "level.json"
    # saved elsewhere, the level keeps its textures by naming their folder absolutely
    save_level(replace(exit_level.level, resources=(str(TEXTURE_DIR),)), path)
    a = make("wallbsp/Exit-v0", level=str(path), textures=False, size=(16, 12))
    b = make("wallbsp/Exit-v0", level=path, textures=False, size=(16, 12))
    assert a.tree is b.tree
    assert a.reset(seed=0)[0]["rgb"].any()


def test_render_modes(exit_level):
    env = make("wallbsp/Exit-v0", level=exit_level.level, size=(32, 24),
               render_mode="rgb_array")
    obs, _ = env.reset(seed=0)
    assert np.array_equal(env.render(), obs["rgb"])
    human = make("wallbsp/Exit-v0", level=exit_level.level, size=(32, 24),
                 render_mode="human", observations=("pose",))
    human.reset(seed=0)
    import pygame
    assert not pygame.display.get_init()         # nothing opened a display before render()
    assert human.render() is None and pygame.display.get_init()
    human.close()
    human.close()


def test_vector_envs_step():
    options = dict(SMALL, observations=("rgb", "pose"))
    fns = [lambda: gym.make("wallbsp/Find-v0", **options) for _ in range(2)]
    for vector in (gym.vector.SyncVectorEnv(fns), gym.vector.AsyncVectorEnv(fns)):
        obs, info = vector.reset(seed=[10, 11])
        assert obs["rgb"].shape == (2, 24, 32, 3)
        assert info["level_seed"][0] != info["level_seed"][1]
        for _ in range(3):
            obs, reward, terminated, truncated, info = vector.step(np.array([1, 3]))
        assert reward.shape == (2,) and obs["pose"].shape == (2, 4)
        vector.close()


def test_import_wallbsp_needs_no_gymnasium_and_the_module_id_form_works():
    code = ("import sys, wallbsp\n"
            "assert 'gymnasium' not in sys.modules, 'import wallbsp imported gymnasium'\n"
            "import gymnasium as gym\n"
            "env = gym.make('wallbsp.envs:wallbsp/Explore-v0', size=(16, 12), walls=40,\n"
            "               observations=('pose',))\n"
            "env.reset(seed=0)\n"
            "import pygame\n"
            "assert not pygame.display.get_init()\n"
            "print('ok')\n")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          env={**os.environ, "SDL_VIDEODRIVER": "dummy"}, timeout=120)
    assert done.returncode == 0 and done.stdout.strip() == "ok", done.stderr


def test_the_throughput_script_reports_every_configuration():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    done = subprocess.run([sys.executable, os.path.join(root, "tools", "bench.py"), "env",
                           "--quick", "--no-docs", "--envs", "2"], capture_output=True,
                          text=True, timeout=300, cwd=root,
                          env={**os.environ, "SDL_VIDEODRIVER": "dummy"})
    assert done.returncode == 0, done.stderr
    import json
    report = json.loads(done.stdout)
    assert set(report["vector_steps_per_s"]) == {
        "1", "async 1", "async 2", "sync 2", "speedup_async_2", "async 2, do-nothing env",
        "2 plain processes", "speedup_plain_2", "speedup_async_2_over_async_1"}
    assert all(v > 0 for v in report["vector_steps_per_s"].values())
    assert len(report["one_env_steps_per_s"]) == 4
    assert all(v > 0 for v in report["one_env_steps_per_s"].values())
    assert report["explore_reset"]["walls_median"] > 300
    assert set(report["meets"]) == {"one_env", "explore_reset", "async_2_speedup"}


def test_a_forked_worker_starts_without_the_parents_trees_or_textures(tmp_path, exit_level):
    from wallbsp.envs import levels
    from wallbsp.assets.resources import shared_resources
    path = tmp_path / "level.json"
    save_level(replace(exit_level.level, resources=(str(TEXTURE_DIR),)), path)
    parent = levels.given_tree(path)
    textures = shared_resources([TEXTURE_DIR])
    read, write = os.pipe()
    pid = os.fork()
    if pid == 0:                                  # the child: a tree of its own
        os.close(read)
        fresh = levels.given_tree(path) is not parent and \
            shared_resources([TEXTURE_DIR]) is not textures
        os.write(write, b"1" if fresh else b"0")
        os._exit(0)
    os.close(write)
    answer = os.read(read, 1)
    os.waitpid(pid, 0)
    os.close(read)
    assert answer == b"1"
    assert levels.given_tree(path) is parent      # the parent keeps its own
    assert shared_resources([TEXTURE_DIR]) is textures
