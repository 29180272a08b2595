"""RLlib's view of the scenarios (wallbsp/envs/rllib.py) and the training entry point
(tools/train.py).  The adapter's screen and rewards are checked with numpy alone; the
training smoke test runs only where Ray RLlib and torch are installed (the ``rl`` extra),
never in CI."""
import importlib.util
import json

import numpy as np
import pytest

pytest.importorskip("gymnasium")

from wallbsp.envs.rllib import Screen, area_weights, make_env  # noqa: E402

HAVE_RLLIB = all(importlib.util.find_spec(m) for m in ("ray", "torch"))


def brute_force_area(image, size):
    """Each output cell the overlap-weighted mean of the input cells it covers."""
    height, width = image.shape[:2]
    out = np.zeros((size, size) + image.shape[2:])
    for i in range(size):
        y0, y1 = i * height / size, (i + 1) * height / size
        for j in range(size):
            x0, x1 = j * width / size, (j + 1) * width / size
            total, weight = 0.0, 0.0
            for y in range(int(y0), int(np.ceil(y1))):
                for x in range(int(x0), int(np.ceil(x1))):
                    w = (min(y1, y + 1) - max(y0, y)) * (min(x1, x + 1) - max(x0, x))
                    total, weight = total + w * image[y, x].astype(float), weight + w
            out[i, j] = total / weight
    return out


def test_screen_is_the_area_average_in_minus_one_to_one():
    rng = np.random.default_rng(0)
    image = rng.integers(0, 256, (30, 40, 3), dtype=np.uint8)
    colour = Screen(30, 40, size=16, gray=False)(image)
    assert colour.shape == (16, 16, 3) and colour.dtype == np.float32
    np.testing.assert_allclose(colour, brute_force_area(image, 16) * 2 / 255 - 1, atol=1e-5)
    gray = Screen(30, 40, size=16)(image)
    luma = image.astype(float) @ [0.299, 0.587, 0.114]
    np.testing.assert_allclose(gray[..., 0], brute_force_area(luma, 16) * 2 / 255 - 1,
                               atol=1e-5)


def test_screen_takes_a_batch_as_its_frames_one_by_one():
    rng = np.random.default_rng(1)
    batch = rng.integers(0, 256, (3, 24, 32, 3), dtype=np.uint8)
    screen = Screen(24, 32, size=10, gray=False)
    np.testing.assert_allclose(screen(batch), np.stack([screen(f) for f in batch]), atol=1e-6)
    assert screen(np.full((24, 32, 3), 255, np.uint8)).min() == pytest.approx(1.0)
    assert screen(np.zeros((24, 32, 3), np.uint8)).max() == pytest.approx(-1.0)


def test_area_weights_cover_every_input_cell_once():
    weights = area_weights(64, 120)
    np.testing.assert_allclose(weights.sum(axis=1), 1, rtol=1e-6)
    # each input row contributes its whole area (64/120 of an output row's total)
    np.testing.assert_allclose(weights.sum(axis=0), 64 / 120, rtol=1e-5)


def test_vector_env_sees_the_screen_and_scaled_rewards_of_the_plain_env():
    config = {"scenario": "basic", "size": 42, "reward_scale": 0.01}
    vector = make_env({**config, "num_envs": 2})
    plain = make_env(config)
    try:
        assert vector.single_observation_space.shape == (42, 42, 1)
        obs, _ = vector.reset(seed=3)
        first, _ = plain.reset(seed=4)             # the vector's second env: seed 3 + 1
        np.testing.assert_allclose(obs[1], first, atol=1e-6)
        raw = make_env({**config, "reward_scale": 1.0})
        raw.reset(seed=4)
        for action in (3, 3, 1, 2, 3):
            _, reward, *_ = plain.step(action)
            _, raw_reward, *_ = raw.step(action)
            assert reward == pytest.approx(raw_reward * 0.01)
            obs, rewards, *_ = vector.step(np.array([0, action]))
            assert rewards[1] == pytest.approx(reward)
        raw.close()
    finally:
        vector.close()
        plain.close()


def test_each_agent_sees_its_own_frame_through_the_screen():
    pytest.importorskip("pettingzoo")
    from wallbsp.envs import parallel_env
    from wallbsp.envs.rllib import Screen, ScreenedAgents
    screen = Screen(60, 80, size=10)
    env = ScreenedAgents(parallel_env(players=2, size=(80, 60), observations=("rgb",)), screen)
    plain = parallel_env(players=2, size=(80, 60), observations=("rgb",))
    try:
        seen, _ = env.reset(seed=5)
        raw, _ = plain.reset(seed=5)
        assert sorted(seen) == env.possible_agents == ["player_0", "player_1"]
        for _ in range(3):
            actions = {agent: 1 for agent in env.agents}
            seen, rewards, *_ = env.step(actions)
            raw, raw_rewards, *_ = plain.step(actions)
            assert rewards == raw_rewards
        for agent in env.possible_agents:
            assert env.observation_space(agent).contains(seen[agent])
            np.testing.assert_allclose(seen[agent], screen(raw[agent]["rgb"]), atol=1e-6)
    finally:
        env.close()
        plain.close()


def test_bad_config_is_one_clear_error():
    with pytest.raises(ValueError, match="unknown scenario 'nope'"):
        make_env({"scenario": "nope"})
    with pytest.raises(ValueError, match="unknown env config keys"):
        make_env({"scenario": "basic", "colour": True})


@pytest.mark.skipif(not HAVE_RLLIB, reason='Ray RLlib and torch are the optional "rl" '
                                           'extra (pip install -e ".[rl]"); CI has neither')
def test_train_two_iterations_writes_progress_and_a_checkpoint(tmp_path):
    from toolscripts import tool_script
    train = tool_script("train")
    args = train.parse(["basic", "--iterations", "2", "--runners", "0", "--envs", "2",
                        "--batch", "192", "--minibatch", "64", "--epochs", "1", "--size", "42",
                        "--cpus", "1", "--out", str(tmp_path)])
    lines = train.train(args)
    written = [json.loads(l) for l in (tmp_path / "progress.jsonl").read_text().splitlines()]
    assert [l["iteration"] for l in written] == [1, 2] and written == lines
    assert lines[1]["env_steps"] >= 2 * 192
    # 96 steps an environment: every basic episode (75 steps at frame skip 4) ends in it
    assert lines[0]["episodes"] >= 2
    assert -500 < lines[0]["return_mean"] <= 106      # +106 the kill, the best a step gives
    assert sum(lines[0]["env_steps_node"].values()) == lines[0]["env_steps"]
    assert any((tmp_path / "checkpoints").rglob("*.pt")) or \
        any((tmp_path / "checkpoints").rglob("module_state*"))


@pytest.mark.skipif(not HAVE_RLLIB or not importlib.util.find_spec("pettingzoo"),
                    reason='Ray RLlib, torch and pettingzoo are the optional "rl" extra '
                           '(pip install -e ".[rl]"); CI has none of them')
def test_two_agents_share_one_policy_through_rllibs_multi_agent_api(tmp_path):
    from toolscripts import tool_script
    train = tool_script("train")
    args = train.parse(["deathmatch", "--agents", "2", "--level", "duel", "--max-tics", "140",
                        "--damage-reward", "0.01", "--iterations", "1", "--runners", "0",
                        "--batch", "96", "--minibatch", "48", "--epochs", "1", "--size", "42",
                        "--cpus", "1", "--checkpoint-every", "0", "--out", str(tmp_path)])
    args.reward_scale = 1.0                     # as main() sets it for deathmatch
    lines = train.train(args)
    assert len(lines) == 1 and lines[0]["env_steps"] >= 96
    # 35 steps an episode (140 tics, frame skip 4): both agents' episodes end in it
    assert lines[0]["episodes"] >= 2
    assert sorted(lines[0]["agent_return_mean"]) == ["player_0", "player_1"]
    assert lines[0]["entropy"] is not None
