"""ViZDoom's scenarios (issue 22): buttons and game variables by ViZDoom's names, the
Python scenario class and its events, the registered environments (the API checker,
seeds, the vector environments) and each scenario's rules."""
import warnings

import numpy as np
import pytest

gym = pytest.importorskip("gymnasium")

import wallbsp.envs  # noqa: E402  (registers the ids)
from gymnasium.utils.env_checker import check_env  # noqa: E402
from wallbsp.envs import gamevars  # noqa: E402
from wallbsp.envs.scenarios import ScenarioEnv, scenario_tree  # noqa: E402
from wallbsp.envs.vizdoom import SCENARIOS, Basic, HealthGathering  # noqa: E402
from wallbsp.envs.vizdoom_source import VizdoomMissing, scenarios_dir  # noqa: E402
from wallbsp.game.scenario import Scenario  # noqa: E402
from wallbsp.game.world import World  # noqa: E402
from wallbsp.doom import info  # noqa: E402

SMALL = {"size": (32, 24)}
# these play on ViZDoom's own maps, converted from a ViZDoom installation (none shipped)
ON_VIZDOOM_MAPS = {"wallbsp/MyWayHome-v0", "wallbsp/DeadlyCorridor-v0",
                   "wallbsp/HealthGatheringSupreme-v0", "wallbsp/PredictPosition-v0"}


def have_vizdoom() -> bool:
    try:
        scenarios_dir()
        return True
    except VizdoomMissing:
        return False


def needs_maps(env_id):
    if env_id in ON_VIZDOOM_MAPS and not have_vizdoom():
        pytest.skip("ViZDoom's scenario maps are not installed (pip install vizdoom)")


def make(env_id, **options):
    return gym.make(env_id, **{**SMALL, **options}).unwrapped


@pytest.mark.parametrize("env_id", sorted(SCENARIOS))
def test_every_scenario_passes_the_checker(env_id):
    needs_maps(env_id)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        check_env(gym.make(env_id, **SMALL), skip_render_check=True)


@pytest.mark.parametrize("env_id", sorted(SCENARIOS))
def test_every_scenario_reproduces_from_its_seed(env_id):
    needs_maps(env_id)
    def run(seed):
        env = make(env_id)
        obs, _ = env.reset(seed=seed)
        env.action_space.seed(seed)
        out = [obs["rgb"].copy()]
        for _ in range(60):
            obs, r, term, trunc, inf = env.step(env.action_space.sample())
            out.append((obs["rgb"].copy(), r, term, trunc, obs["gamevars"].copy()))
            if term or trunc:
                break
        return out
    a, b = run(3), run(3)
    assert len(a) == len(b)
    assert np.array_equal(a[0], b[0])
    for x, y in zip(a[1:], b[1:]):
        assert np.array_equal(x[0], y[0]) and x[1:4] == y[1:4] and np.array_equal(x[4], y[4])


@pytest.mark.parametrize("env_id", sorted(SCENARIOS))
def test_no_method_of_the_play_is_replaced(env_id):
    """A scenario reads the play's event log and sets the play's own rules: after its
    episode has begun and run, no attribute of the play hides a method of its class."""
    needs_maps(env_id)
    env = make(env_id, observations=("gamevars",))
    env.reset(seed=0)
    env.action_space.seed(0)
    for _ in range(20):
        env.step(env.action_space.sample())
    play = env.world.play
    assert [n for n in vars(play) if callable(getattr(type(play), n, None))] == []


def test_scenarios_run_in_the_vector_env():
    envs = wallbsp.envs.make_vec("wallbsp/DefendTheCenter-v0", 2, workers=1, **SMALL)
    try:
        obs, infos = envs.reset(seed=0)
        assert obs["rgb"].shape == (2, 24, 32, 3) and obs["gamevars"].shape == (2, 2)
        for _ in range(20):
            obs, rewards, term, trunc, infos = envs.step(envs.action_space.sample())
        assert rewards.shape == (2,) and "HEALTH" in infos
    finally:
        envs.close()


def test_basic_rules():
    env = make("wallbsp/Basic-v0")
    obs, inf = env.reset(seed=0)
    assert inf["tics"] == 14 and inf["AMMO2"] == 50 and env.action_space.n == 4
    caco = [mo for mo in env.world.play.thinkers() if getattr(mo, "type", None) == info.MT_HEAD]
    assert len(caco) == 1 and caco[0].health == 1 and caco[0].x == 0
    # a shot costs 5 and a tic 1; turn the player to face the cacodemon and fire
    p = env.world.play.players[0].mo
    from wallbsp.doom.fixed import point_to_angle2
    p.angle = point_to_angle2(p.x, p.y, caco[0].x, caco[0].y)
    rewards = []
    for i in range(10):                  # the pistol fires on its attack's second frame
        obs, r, term, trunc, inf = env.step(3 if i == 0 else 0)
        rewards.append(r)
        if term:
            break
    assert inf["AMMO2"] == 49 and term and rewards[-1] == pytest.approx(-1 - 5 + 106)
    assert rewards[:-1] == [-1.0] * (len(rewards) - 1) and len(rewards) == 5
    assert env.world.kills[0] == 1


def test_basic_times_out_at_300_tics():
    env = make("wallbsp/Basic-v0", observations=("gamevars",))
    env.reset(seed=1)
    n, total = 0, 0.0
    while True:
        _, r, term, trunc, inf = env.step(0)
        n, total = n + 1, total + r
        if term or trunc:
            break
    assert trunc and not term and inf["tics"] == 314 and n == 300 and total == -300
    assert env.world.player.health == 100          # the cacodemon never woke (A_Look hook)


def test_health_gathering_acid_and_medikits():
    env = make("wallbsp/HealthGathering-v0", observations=("gamevars",))
    env.reset(seed=0)
    kits = [mo for mo in env.world.play.thinkers() if getattr(mo, "type", None) == info.MT_MISC11
            and mo.func is not None]
    assert len(kits) == 17                         # 16, and the loop's first
    healths = []
    for _ in range(70):
        _, r, term, trunc, inf = env.step(0)
        healths.append(inf["HEALTH"])
        assert r == 1.0
    # 8 at the level's tics 0, 32, 64, ... (ViZDoom's agent, after its 1 start tic, sees 92
    # and dies at its 384th step)
    assert healths[0] == 92 and healths[31] == 84 and healths[30] == 92


def test_game_variables_and_weapon_buttons():
    world = World(scenario_tree("basic"), 3)
    names = gamevars.VARIABLES
    v = gamevars.game_variables(world, names)
    assert v["HEALTH"] == 100 and v["AMMO2"] == 50 and v["WEAPON2"] == 1
    assert v["SELECTED_WEAPON"] == 2 and v["SELECTED_WEAPON_AMMO"] == 50
    assert v["POSITION_X"] == -384 and v["ON_GROUND"] == 1 and v["DEAD"] == 0
    p = world.play.players[0]
    cmd = gamevars.command(("SELECT_WEAPON1", "ATTACK", "TURN_LEFT_RIGHT_DELTA"),
                           (1, 1, 90.0), p)
    assert cmd.buttons & 1 and cmd.angleturn == -16384
    assert gamevars.command(("SELECT_NEXT_WEAPON",), (1,), p).buttons >> 3 & 7 == 0


def test_events_count_damage_kills_and_pickups():
    class Probe(Scenario):
        level = "basic"

        def reset(self, world, rng):
            self.imp = self.spawn(world, "DoomImp", -200, 32, angle=180)
            self.kit = self.spawn(world, "Medikit", -330, 32)
    world = World(scenario_tree("basic"), 3)
    sc = Probe()
    sc.begin(world, np.random.default_rng(0))
    assert sc.spawn(world, "DoomImp", 5000, 5000) is None      # outside the map
    sc.damage(world, 30)
    kinds = []
    for _ in range(8):
        world.tic(forward=1.0)
        sc.after_tic(world)
        kinds += [e.kind for e in sc.events]
    assert world.player.health == 95                # 70, and the medikit's 25
    assert kinds == ["damage", "pickup"] and sc.kit.func is None
    assert sc.recorder.damage_taken == 30 and sc.recorder.hits_taken == 1
    world.play.p_damage_mobj(sc.imp, None, world.play.players[0].mo, 100)
    world.tic()
    sc.after_tic(world)
    assert sc.recorder.damage_dealt == 100 and sc.recorder.hits == 1
    assert len(sc.killed("DoomImp")) == 1           # recorded between tics: in the next list



def test_spawn_follows_zdoom_solid_things_block_only_solid_spawns():
    """ACS's Spawn under ZDoom: an item may appear on the player (killough's rule in
    PIT_CheckThing: only a solid mover is blocked by solid things) and is picked up when
    the player next moves; a monster there is refused; a wall refuses both.  ViZDoom's
    health_gathering spawns its medikits so (vanilla DOOM's rule refused ~1 in 9
    episodes' medikit, and a random agent lived 20 tics less than ViZDoom's)."""
    world = World(scenario_tree("basic"), 3)
    sc = Scenario()
    mo = world.play.players[0].mo
    x, y = mo.x / 65536, mo.y / 65536
    kit = sc.spawn(world, "Medikit", x + 10, y)
    assert kit is not None and kit.func is not None
    assert sc.spawn(world, "DoomImp", x + 10, y) is None
    assert sc.spawn(world, "Medikit", x, y + 10000) is None        # outside the walls
    sc.damage(world, 30)
    world.tic(forward=1.0)
    assert kit.func is None and world.player.health == 95



def test_spawned_monsters_see_the_player_at_their_first_look():
    """ViZDoom's spawned monsters all wake at their first A_Look (defend_the_line's demons
    all move at tic 12, 120 of 120); DOOM's P_LookForPlayers, from a random lastlook,
    gives up one time in four in a single-player game."""
    world = World(scenario_tree("basic"), 3)
    sc = Scenario()
    demons = [sc.spawn(world, "Demon", 0.0, y, angle=180.0, check=False)
              for y in range(-160, 200, 45)]
    for _ in range(11):                        # the spawn state's 10 tics, then A_Look
        world.tic()
    player = world.play.players[0].mo
    assert all(d.target is player for d in demons)


def test_a_custom_scenario_as_an_environment():
    class Hunt(HealthGathering):
        acid = 0

        def tic(self, world):
            return 10.0 * len(self.picked_up("Medikit"))
    env = ScenarioEnv(Hunt, observations=("gamevars",), buttons=("MOVE_FORWARD",))
    env.reset(seed=0)
    assert env.action_space.n == 2
    assert env.step(0)[1] == 1.0


def test_the_documented_example_runs():
    import re
    from pathlib import Path
    text = (Path(__file__).resolve().parent.parent / "docs" / "scenarios.md").read_text()
    example = re.findall(r"```python\n(.*?)```", text, re.S)[1]
    exec(compile(example, "docs/scenarios.md", "exec"), {"__name__": "example"})


def test_a_scenario_on_vizdoom_s_maps_without_vizdoom_is_one_clear_error(monkeypatch, tmp_path):
    monkeypatch.setenv("WALLBSP_VIZDOOM", str(tmp_path / "nowhere"))
    monkeypatch.setattr("importlib.util.find_spec", lambda name: None)
    with pytest.raises(VizdoomMissing, match="pip install vizdoom"):
        scenarios_dir()
