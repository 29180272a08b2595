"""The multi-agent environment (``wallbsp.envs.multiagent``): a PettingZoo ``ParallelEnv`` of
2-4 players in one world.  Skips without pettingzoo (the ``multi`` extra)."""
import warnings

import numpy as np
import pytest

pytest.importorskip("pettingzoo")

with warnings.catch_warnings():      # pettingzoo.test loads its deprecated example envs
    warnings.simplefilter("ignore", DeprecationWarning)
    from pettingzoo.test import api_test, parallel_api_test, parallel_seed_test

from wallbsp.envs import aec_env, parallel_env  # noqa: E402
from wallbsp.game.scenario import Scenario  # noqa: E402

SMALL = {"size": (32, 24), "max_tics": 40}
ATTACK = 1                            # DEFAULT_BUTTONS[0]: discrete action 1


# the AEC test's opinions on Dict observations (ours, as the single-agent envs' are Dicts)
@pytest.mark.filterwarnings("ignore:Observation is not a NumPy array")
@pytest.mark.filterwarnings("ignore:Observation space for each agent probably")
def test_parallel_api_and_seeding():
    with warnings.catch_warnings():
        warnings.simplefilter("error")          # no "live agent was not given ..."
        parallel_api_test(parallel_env(players=3, observations=("rgb", "pose", "gamevars"),
                                       **SMALL), num_cycles=60)
    parallel_seed_test(lambda: parallel_env(mode="altdeath", action_space="multibinary",
                                            observations=("rgb", "labels"), **SMALL),
                       num_cycles=20)
    api_test(aec_env(mode="coop", action_space="box", observations=("depth",), **SMALL),
             num_cycles=20)


def _run(seed, steps=30, **options):
    env = parallel_env(players=2, observations=("rgb", "pose"), **SMALL, **options)
    obs, _ = env.reset(seed=seed)
    out = [obs]
    for a in env.possible_agents:
        env.action_space(a).seed(seed)
    for _ in range(steps):
        if not env.agents:
            break
        out.append(env.step({a: env.action_space(a).sample() for a in env.agents})[0])
    return out


def test_an_episode_reproduces_from_its_seed_and_agents_see_their_own_views():
    a, b, c = _run(7), _run(7), _run(8)
    assert len(a) == len(b)
    for x, y in zip(a, b):
        for agent in x:
            assert np.array_equal(x[agent]["rgb"], y[agent]["rgb"])
            assert np.array_equal(x[agent]["pose"], y[agent]["pose"])
    # another seed: other deathmatch starts
    assert not np.array_equal(a[0]["player_0"]["pose"], c[0]["player_0"]["pose"]) \
        or not np.array_equal(a[0]["player_1"]["pose"], c[0]["player_1"]["pose"])
    first = a[0]
    assert not np.array_equal(first["player_0"]["rgb"], first["player_1"]["rgb"])
    assert not np.array_equal(first["player_0"]["pose"], first["player_1"]["pose"])


def test_deathmatch_rewards_a_frag_and_punishes_the_death():
    env = parallel_env(players=2, mode="deathmatch", size=(32, 24), max_tics=2000,
                       frag_limit=1, observations=("labels",))
    env.reset(seed=0)
    env.world.place_player(0, -420, 90, player=0)
    env.world.place_player(0, -320, 270, player=1)
    victim = env.world.players[1].thing
    obs, rewards, terms, truncs, infos = env.step({"player_0": 0, "player_1": 0})
    assert victim in obs["player_0"]["labels"][..., 1][obs["player_0"]["labels"][..., 0] == 4]
    total = {"player_0": 0.0, "player_1": 0.0}
    for _ in range(400):
        obs, rewards, terms, truncs, infos = env.step({"player_0": ATTACK, "player_1": 0})
        for agent, r in rewards.items():
            total[agent] += r
        if not env.agents:
            break
    assert total == {"player_0": 1.0, "player_1": -1.0}
    assert terms == {"player_0": True, "player_1": True}        # the frag limit
    assert infos["player_0"]["frags"] == 1 and infos["player_1"]["deaths"] == 1
    assert not truncs["player_0"]


def test_damage_reward_is_the_health_taken_from_the_other_player_in_the_duel_room():
    env = parallel_env(players=2, mode="deathmatch", level="duel", size=(32, 24),
                       max_tics=2000, frag_reward=0.0, death_penalty=0.0, damage_reward=1.0,
                       observations=("pose",))
    env.reset(seed=0)
    env.world.place_player(0, -150, 90, player=0)
    env.world.place_player(0, 150, 270, player=1)
    total = {"player_0": 0.0, "player_1": 0.0}
    for _ in range(60):                             # the weapon comes up, shots miss
        _, rewards, _, _, infos = env.step({"player_0": ATTACK, "player_1": 0})
        for agent, r in rewards.items():
            total[agent] += r
        if infos["player_1"]["health"] < 40:       # before a death (its overkill counts)
            break
    taken = 100 - infos["player_1"]["health"]
    assert taken > 0 and total == {"player_0": float(taken), "player_1": 0.0}


def test_cooperative_players_share_a_kill_and_the_dead_come_back():
    env = parallel_env(players=2, mode="coop", size=(32, 24), max_tics=2000,
                       observations=("pose",))
    env.reset(seed=0)
    world = env.world
    world.place_player(0, -420, 90, player=0)
    Scenario.spawn(world, "ZombieMan", 0, -300, angle=270)
    total = np.zeros(2)
    for _ in range(300):
        _, rewards, *_ = env.step({"player_0": ATTACK, "player_1": 0})
        total += [rewards["player_0"], rewards["player_1"]]
        if world.players[0].kills:
            break
    assert world.players[0].kills == 1 and world.players[1].kills == 0
    assert total[1] == 1.0 and total[0] in (1.0, 0.0)     # shared; 0 if shot back dead
    world.play.p_damage_mobj(world.play.players[1].mo, None, None, 1000)
    _, rewards, _, _, infos = env.step({})
    assert rewards["player_1"] == -1.0 and infos["player_1"]["dead"]
    _, rewards, _, _, infos = env.step({})            # respawn: use pressed for it
    assert not infos["player_1"]["dead"] and infos["player_1"]["health"] == 100
    assert infos["player_1"]["deaths"] == 1


def test_render_weapon_draws_each_agents_own_weapon_over_its_view():
    """ViZDoom's render_weapon: the bottom middle of each agent's rgb (and the render) is
    its weapon; the rest of the view, and the view without it, unchanged."""
    options = dict(players=2, size=(64, 48), max_tics=40, render_mode="rgb_array")
    plain, armed = parallel_env(**options), parallel_env(render_weapon=True, **options)
    plain.reset(seed=3)
    armed.reset(seed=3)
    for _ in range(20):                     # the pistol rises from below the view
        a = plain.step({agent: 0 for agent in plain.agents})[0]
        b = armed.step({agent: 0 for agent in armed.agents})[0]
    for agent in a:
        differ = (a[agent]["rgb"] != b[agent]["rgb"]).any(axis=2)
        rows, cols = np.nonzero(differ)
        assert len(rows) > 20 and rows.min() >= 24 and 12 <= cols.mean() <= 52
    assert not np.array_equal(plain.render(), armed.render())
    assert armed.render().shape == plain.render().shape == (48, 128, 3)


def test_options_are_checked():
    for bad in ({"players": 1}, {"players": 5}, {"mode": "ctf"},
                {"action_space": "continuous"}, {"observations": ("automap",)},
                {"buttons": ("JUMP",)}, {"frag_limit": 0}, {"render_mode": "human"},
                {"render_weapon": "yes"}):
        with pytest.raises(ValueError):
            parallel_env(**bad)


def test_four_agents_on_freedoom2_map01(freedoom_cache):
    tree = freedoom_cache.tree("freedoom2.wad", "MAP01")
    env = parallel_env(level=tree, players=4, mode="deathmatch", size=(48, 32),
                       observations=("rgb", "gamevars"))
    obs, infos = env.reset(seed=2)
    starts = {(s.x, s.y) for s in env.world.play.deathmatchstarts}
    assert len(env.world.play.deathmatchstarts) == 10            # MAP01's own
    assert {(round(p.x), round(p.y)) for p in env.world.players} <= starts
    for _ in range(5):
        obs, *_ = env.step({a: env.action_space(a).sample() for a in env.agents})
    views = [obs[a]["rgb"] for a in env.possible_agents]
    assert all(not np.array_equal(views[0], v) for v in views[1:])
    coop = parallel_env(level=tree, players=4, mode="coop", size=(48, 32))
    coop.reset(seed=0)
    assert [(round(p.x), round(p.y)) for p in coop.world.players] == \
        [(-192, -160), (-192, -208), (-192, -64), (-192, -112)]    # starts 1-4


def test_the_benchmark_runs_quick():
    import json
    import subprocess
    import sys
    from pathlib import Path
    root = Path(__file__).resolve().parent.parent
    done = subprocess.run([sys.executable, str(root / "tools" / "bench.py"), "multiagent",
                           "--quick"], capture_output=True, text=True, timeout=300,
                          check=True)
    rows = json.loads(done.stdout)["rows"]
    assert [r["agents"] for r in rows] == [2, 4]
    assert all(r["steps_per_s"] > 0 and
               abs(r["agent_steps_per_s"] - r["steps_per_s"] * r["agents"]) < 1 for r in rows)
