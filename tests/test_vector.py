"""``wallbsp.envs.make_vec`` (issue 23): the VectorEnv API, next-step autoreset giving what
gymnasium's SyncVectorEnv gives on the same seeds, asynchronous batches, workers that
raise or die, nothing left in /dev/shm.  Small frames and small generated levels, and the
kernels compiled before the workers fork, keep it to seconds."""
import multiprocessing
import os
import signal

import numpy as np
import pytest

gym = pytest.importorskip("gymnasium")

import wallbsp.envs  # noqa: E402,F401  (registers the ids)
from gymnasium.vector import AutoresetMode  # noqa: E402
from wallbsp.envs import WorkerError, make_vec  # noqa: E402
from wallbsp.envs import vecpool  # noqa: E402

SMALL = {"size": (32, 24), "walls": 60, "observations": ("rgb", "depth", "labels", "pose")}
SHORT = {**SMALL, "max_tics": 6}          # episodes end (truncated) within the tests


@pytest.fixture(scope="module", autouse=True)
def warm():
    """Kernels compiled (or loaded) here, before any worker forks."""
    env = gym.make("wallbsp/Explore-v0", **SMALL)
    env.reset(seed=0)
    env.step(1)
    env.close()


@pytest.fixture
def no_leak():
    """None of the shared memory the test's vector envs made is left in /dev/shm."""
    made = len(vecpool.SEGMENTS)
    yield
    names = [name.lstrip("/") for name in list(vecpool.SEGMENTS)[made:]]
    assert not [n for n in names if os.path.exists(os.path.join("/dev/shm", n))]


def sync(env_id, n, **options):
    return gym.vector.SyncVectorEnv([lambda: gym.make(env_id, **options) for _ in range(n)])


def assert_same(a, b, what=""):
    if isinstance(a, dict):
        assert a.keys() == b.keys(), (what, sorted(a), sorted(b))
        for key in a:
            assert_same(a[key], b[key], f"{what}[{key}]")
    elif isinstance(a, tuple):
        assert len(a) == len(b), what
        for i, (x, y) in enumerate(zip(a, b)):
            assert_same(x, y, f"{what}[{i}]")
    else:
        a, b = np.asarray(a), np.asarray(b)
        assert a.dtype == b.dtype and a.shape == b.shape, (what, a.dtype, b.dtype)
        assert np.array_equal(a, b) or (a.dtype == object and list(a) == list(b)), what


@pytest.mark.parametrize("workers", [0, 2])
@pytest.mark.parametrize("env_id", ["wallbsp/Explore-v0", "wallbsp/Find-v0"])
def test_steps_as_sync_vector_env_does_on_the_same_seeds(env_id, workers, no_leak):
    ours, theirs = make_vec(env_id, 3, workers=workers, **SHORT), sync(env_id, 3, **SHORT)
    assert workers == 0 or vecpool.SEGMENTS
    try:
        assert_same(ours.reset(seed=11), theirs.reset(seed=11), "reset")
        rng = np.random.default_rng(1)
        ended = 0
        for t in range(16):                  # two autoresets per environment
            actions = rng.integers(14, size=3)
            got, want = ours.step(actions), theirs.step(actions)
            for i, name in enumerate(["obs", "reward", "terminated", "truncated", "info"]):
                assert_same(got[i], want[i], f"step {t} {name}")
            ended += int(got[3].sum())
        assert ended >= 3
        mask = np.array([True, False, True])
        assert_same(ours.reset(seed=5, options={"reset_mask": mask}),
                    theirs.reset(seed=5, options={"reset_mask": mask}), "masked reset")
        assert_same(ours.step(np.ones(3, int)), theirs.step(np.ones(3, int)), "after")
    finally:
        ours.close()
        theirs.close()


def test_the_vector_env_api(no_leak):
    envs = make_vec("wallbsp/Explore-v0", 4, workers=2, action_space="box", **SMALL)
    single = gym.make("wallbsp/Explore-v0", action_space="box", **SMALL)
    try:
        assert envs.num_envs == 4 and envs.metadata["autoreset_mode"] == AutoresetMode.NEXT_STEP
        assert envs.single_observation_space == single.observation_space
        assert envs.single_action_space == single.action_space
        assert envs.observation_space["rgb"].shape == (4, 24, 32, 3)
        assert envs.action_space.shape == (4, 5)
        obs, infos = envs.reset(seed=0)
        assert envs.observation_space.contains(obs)
        assert infos["_tics"].all() and infos["tics"].dtype == np.int64
        obs, rewards, terminated, truncated, infos = envs.step(envs.action_space.sample())
        assert envs.observation_space.contains(obs)
        assert rewards.dtype == np.float64 and rewards.shape == (4,)
        assert terminated.dtype == truncated.dtype == np.bool_
        obs2 = envs.step(envs.action_space.sample())[0]
        assert not np.shares_memory(obs["rgb"], obs2["rgb"])        # copy=True: new arrays
        assert envs.get_attr("frame_skip") == (1, 1, 1, 1)
        envs.set_attr("tic_cost", [0.5, 0.5, 0.5, 0.5])
        assert envs.call("get_wrapper_attr", "tic_cost") == (0.5,) * 4
        assert len(envs.np_random_seed) == 4
        with pytest.raises(RuntimeError):
            envs.recv()                              # nothing sent
    finally:
        envs.close()
        single.close()
    envs.close()                                     # twice is fine
    assert envs.closed
    with pytest.raises(RuntimeError):
        envs.step(np.zeros((4, 5), np.float32))


def test_copy_false_hands_out_the_batch_arrays(no_leak):
    envs = make_vec("wallbsp/Explore-v0", 2, workers=1, copy=False, **SMALL)
    try:
        first = envs.reset(seed=0)[0]
        second = envs.step(np.array([1, 1]))[0]
        assert first["rgb"] is second["rgb"]
    finally:
        envs.close()


def test_gymnasium_wrappers_take_it(no_leak):
    envs = gym.wrappers.vector.RecordEpisodeStatistics(
        make_vec("wallbsp/Explore-v0", 2, workers=1, **SHORT))
    try:
        envs.reset(seed=0)
        episodes = 0
        for _ in range(8):
            infos = envs.step(np.array([1, 3]))[4]
            episodes += int(infos.get("_episode", np.zeros(2, bool)).sum())
        assert episodes == 2
    finally:
        envs.close()


def run_alone(env_id, seed, actions_of, steps, **options):
    """One environment's observations under next-step autoreset, stepped alone."""
    env = gym.make(env_id, **options)
    obs, _ = env.reset(seed=seed)
    seen, ended = [obs["pose"]], False
    for k in range(steps):
        if ended:
            obs, _ = env.reset()
            ended = False
        else:
            obs, _, terminated, truncated, _ = env.step(actions_of(k))
            ended = terminated or truncated
        seen.append(obs["pose"])
    env.close()
    return seen


@pytest.mark.parametrize("workers", [0, 2])
def test_workers_let_frames_go_and_render_draws_them_again(workers, no_leak):
    """The environments' frames are not kept once written out (their caches are the
    batch's); render() draws the same picture the step observed."""
    envs = make_vec("wallbsp/Explore-v0", 2, workers=workers, render_mode="rgb_array",
                    **SMALL)
    try:
        envs.reset(seed=3)
        obs = envs.step(np.array([1, 5]))[0]
        assert envs.get_attr("frame") == (None, None)
        pictures = envs.render()
        assert all(np.array_equal(p, obs["rgb"][i]) for i, p in enumerate(pictures))
    finally:
        envs.close()

@pytest.mark.parametrize("workers", [0, 2])
def test_send_recv_returns_batches_of_finished_environments(workers, no_leak):
    n, batch = 4, 2
    envs = make_vec("wallbsp/Explore-v0", n, workers=workers, batch_size=batch, **SHORT)
    seen = {e: [] for e in range(n)}
    try:
        envs.async_reset(seed=20)
        for _ in range(2 * 9):
            obs, rewards, terminated, truncated, infos = envs.recv()
            ids = infos["env_id"]
            assert len(ids) == batch and rewards.shape == (batch,)
            assert obs["rgb"].shape == (batch, 24, 32, 3) and infos["_tics"].all()
            for j, e in enumerate(ids):
                seen[int(e)].append(obs["pose"][j])
            envs.send(np.array([(int(e) + len(seen[int(e)])) % 14 for e in ids]), ids)
        with pytest.raises(ValueError):
            envs.send(np.array([1]), [int(ids[0])])  # already running
    finally:
        envs.close()
    for e in range(n):                               # each env's own sequence, as alone
        alone = run_alone("wallbsp/Explore-v0", 20 + e, lambda k: (e + k + 1) % 14,
                          len(seen[e]) - 1, **SHORT)
        assert_same(np.array(seen[e]), np.array(alone), f"env {e}")


def test_a_slow_environment_does_not_hold_the_batch(no_leak):
    gate = multiprocessing.Event()                   # env 0's step waits until it opens
    envs = make_vec(SlowEnv, 4, workers=2, batch_size=2, gate=gate)
    try:
        envs.async_reset(seed=0)                     # env 0 (seed 0) is slow, on worker 0
        ids = []
        while 0 not in ids:                          # until env 0 is held in a step
            ids = envs.recv()[4]["env_id"]
            envs.send(np.zeros(2, np.int64), ids)
        for _ in range(5):                           # the others go on meanwhile
            ids = envs.recv()[4]["env_id"]
            envs.send(np.zeros(2, np.int64), ids)
            assert 0 not in ids
        gate.set()
        while 0 not in ids:                          # and env 0 comes back once let go
            ids = envs.recv()[4]["env_id"]
            envs.send(np.zeros(2, np.int64), ids)
    finally:
        gate.set()
        envs.close()


class SlowEnv(gym.Env):
    """A tiny environment; the one reset with seed ``slow_seed`` says it is in a step
    (``entered.set()``) and waits there until ``gate`` opens, the one with ``bad_seed``
    raises on its second step, ``exit_seed`` dies there, ``hang_seed`` says it is there
    (``entered``) and never returns from it.  ``gate`` and ``entered``: multiprocessing events, shared with forked workers."""

    observation_space = gym.spaces.Box(0, 1, (2,), np.float32)
    action_space = gym.spaces.Discrete(2)

    def __init__(self, gate=None, entered=None, slow_seed=0, bad_seed=None, exit_seed=None,
                 hang_seed=None):
        self.gate, self.entered, self.slow_seed = gate, entered, slow_seed
        self.bad_seed, self.exit_seed, self.hang_seed = bad_seed, exit_seed, hang_seed
        self.seed_, self.t = None, 0

    def reset(self, *, seed=None, options=None):
        super().reset(seed=seed)
        if seed is not None:
            self.seed_ = seed
        self.t = 0
        return np.zeros(2, np.float32), {"t": 0}

    def step(self, action):
        self.t += 1
        if self.seed_ == self.slow_seed:
            if self.entered is not None:
                self.entered.set()
            if self.gate is not None:
                self.gate.wait()
        if self.t == 2 and self.seed_ == self.bad_seed:
            raise ValueError("the bad environment")
        if self.t == 2 and self.seed_ == self.exit_seed:
            os._exit(3)
        if self.t == 2 and self.seed_ == self.hang_seed:
            if self.entered is not None:
                self.entered.set()
            multiprocessing.Event().wait()           # nobody sets it: hangs
        return np.full(2, self.t / 10, np.float32), 1.0, False, False, {"t": self.t}


@pytest.mark.parametrize("workers", [0, 2])
def test_an_environment_that_raises_is_one_error_naming_it_and_its_seed(workers, no_leak):
    envs = make_vec(SlowEnv, 4, workers=workers, bad_seed=12)
    envs.reset(seed=10)                              # env 2 gets seed 12
    envs.step(np.zeros(4, np.int64))
    with pytest.raises(WorkerError, match=r"env 2 \(seed 12\).*the bad environment") as caught:
        envs.step(np.zeros(4, np.int64))
    assert caught.value.env == 2 and caught.value.seed == 12
    assert envs.closed and all(p.exitcode is not None for p in envs.processes)
    envs.close()


def test_a_worker_that_dies_is_one_error_naming_the_environment(no_leak):
    envs = make_vec(SlowEnv, 4, workers=2, exit_seed=13)
    envs.reset(seed=10)                              # env 3 (worker 1) exits on step 2
    envs.step(np.zeros(4, np.int64))
    with pytest.raises(WorkerError, match=r"worker 1 .*died \(exit status 3\) while stepping "
                                          r"env 3 \(seed 13\)"):
        envs.step(np.zeros(4, np.int64))
    assert all(p.exitcode is not None for p in envs.processes)
    envs.close()


def test_a_killed_worker_is_reported_and_the_others_shut_down(no_leak):
    # the gate is never opened: setting an event a killed process waited on would hang
    gate, entered = multiprocessing.Event(), multiprocessing.Event()
    envs = make_vec(SlowEnv, 4, workers=2, gate=gate, entered=entered, slow_seed=10)
    try:
        envs.reset(seed=10)
        envs.send(np.zeros(4, np.int64))             # env 0 is held in worker 0's step
        assert entered.wait(600)                     # (a bound only for a broken pool)
        os.kill(envs.processes[0].pid, signal.SIGKILL)
        with pytest.raises(WorkerError,
                           match=r"worker 0 .*killed by SIGKILL.*env 0 \(seed 10\)"):
            envs.recv()
        assert all(p.exitcode is not None for p in envs.processes)
    finally:
        envs.close()


def test_close_returns_when_a_worker_hangs(monkeypatch, no_leak):
    monkeypatch.setattr(vecpool, "CLOSE_S", 0.3)
    entered = multiprocessing.Event()
    envs = make_vec(SlowEnv, 2, workers=2, hang_seed=1, slow_seed=None, entered=entered)
    envs.reset(seed=0)
    envs.step(np.zeros(2, np.int64))
    envs.send(np.zeros(2, np.int64))                 # env 1 never comes back
    assert entered.wait(600)                         # it is in that step (a bound only
    envs.close()                                     # for a broken pool)
    assert all(p.exitcode is not None for p in envs.processes)
    assert envs.processes[1].exitcode < 0            # stopped by a signal: not waited for


def test_an_environment_that_cannot_be_made_is_named(no_leak):
    with pytest.raises(WorkerError, match="env 0 .*could not be made"):
        make_vec("wallbsp/Exit-v0", 2, workers=1, level="/nonexistent/level.json")
    with pytest.raises(ValueError):
        make_vec("wallbsp/Explore-v0", 2, workers=-1)
    with pytest.raises(ValueError):
        make_vec("wallbsp/Explore-v0", 2, batch_size=3)


class InfoEnv(gym.Env):
    """Infos of every kind: numbers, None, strings, numpy scalars and arrays, nested
    dicts, keys that come and go."""

    observation_space = gym.spaces.Dict({"x": gym.spaces.Box(-1, 1, (3,), np.float32),
                                         "n": gym.spaces.Discrete(5)})
    action_space = gym.spaces.MultiDiscrete([3, 2])

    def reset(self, *, seed=None, options=None):
        super().reset(seed=seed)
        self.t = int(self.np_random.integers(3))
        return self._obs(), {"t": self.t, "name": None}

    def step(self, action):
        self.t += 1 + int(action[0])
        info = {"t": self.t, "name": "odd" if self.t % 2 else None, "f": np.float32(self.t),
                "arr": np.arange(2) * self.t}
        if self.t % 3 == 0:
            info["nested"] = {"a": self.t, "b": True}
        return self._obs(), float(self.t), self.t > 7, False, info

    def _obs(self):
        return {"x": np.full(3, self.t / 10, np.float32), "n": self.t % 5}


@pytest.mark.parametrize("workers", [0, 2])
def test_infos_of_every_kind_and_nested_spaces_match_sync(workers, no_leak):
    ours = make_vec(InfoEnv, 3, workers=workers)
    theirs = gym.vector.SyncVectorEnv([InfoEnv for _ in range(3)])
    try:
        assert_same(ours.reset(seed=4), theirs.reset(seed=4), "reset")
        rng = np.random.default_rng(0)
        for t in range(12):
            actions = np.stack([rng.integers(3, size=3), rng.integers(2, size=3)], axis=1)
            assert_same(ours.step(actions), theirs.step(actions), f"step {t}")
    finally:
        ours.close()
        theirs.close()


def test_workers_started_by_spawn(no_leak):
    envs = make_vec(InfoEnv, 2, workers=1, context="spawn")
    try:
        obs, _ = envs.reset(seed=0)
        assert obs["x"].shape == (2, 3)
        assert envs.step(np.ones((2, 2), np.int64))[4]["_t"].all()
    finally:
        envs.close()


def test_copy_true_batches_stay_as_handed_out(no_leak):
    """Kept observations are never overwritten; a batch nothing holds is written again."""
    envs = make_vec("wallbsp/Explore-v0", 2, workers=1, **SMALL)
    try:
        kept = [envs.reset(seed=0)[0]]
        saved = [{k: v.copy() for k, v in kept[0].items()}]
        for t in range(6):                            # more batches kept than banks
            kept.append(envs.step(np.array([t % 14, 1]))[0])
            saved.append({k: v.copy() for k, v in kept[-1].items()})
        for obs, copy in zip(kept, saved):
            assert_same(obs, copy)
        del kept, saved, obs, copy
        addresses = set()
        for t in range(6):                            # nothing kept: the banks in turn
            obs = envs.step(np.array([1, 1]))[0]
            addresses.add(obs["rgb"].__array_interface__["data"][0])
            del obs
        assert len(addresses) <= 3
    finally:
        envs.close()


def test_gymnasium_make_vec_makes_it(no_leak):
    envs = gym.make_vec("wallbsp/Explore-v0", 2, workers=1, **SMALL)
    try:
        assert isinstance(envs.unwrapped, wallbsp.envs.vector.WallbspVectorEnv)
        assert envs.reset(seed=0)[0]["rgb"].shape == (2, 24, 32, 3)
    finally:
        envs.close()
    envs = gym.make_vec("wallbsp/Explore-v0", 2, vectorization_mode="sync", **SMALL)
    assert isinstance(envs, gym.vector.SyncVectorEnv)
    envs.close()
