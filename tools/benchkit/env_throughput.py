"""The learning environments' targets (issue 13); prints one JSON object.

    python tools/bench.py env            # the full run (a few minutes)
    python tools/bench.py env --quick    # a smoke run
    python tools/bench.py env --envs 8   # N for the vector runs (default: 2 x nproc)

The full run also rewrites the "environments" section of docs/benchmarks.md.  Nothing is
trained: one seeded uniform-random sequence of Discrete actions (a new episode when one
ends) drives every environment, every sub-environment of a vector env getting the same
action, so every configuration walks the same way and draws the same views.

Throughput is the best of 10 rounds of 150 steps, the configurations taking turns round by
round (a busy machine only ever takes speed away).  Ten, not five: on this virtual machine
a configuration's rounds within one run vary by up to 2x, and with five the same
configuration measured twice in one run came out at 2,044 and 3,152 steps/s.

1. One environment: ``wallbsp/Exit-v0`` on freedoom1.wad:E1M1 (levels/large.json when
   Freedoom is absent; --quick: a small generated level), 160x120, frame skip 1,
   textured, observing rgb, depth and labels: steps per second (and per CPU second).
   Beside it the same with rgb only, untextured, and ``pose`` only (no frame drawn: the
   World's tics alone), and where a step's time goes (the tics, the frame, the
   observation arrays).
2. ``wallbsp/Explore-v0`` reset (generate a ~500-wall level, compile it, a World, the first
   frame): the median over many seeds, and the median of each part.
3. Vector environments: steps per second (all environments' steps) for 1 environment, and
   for 1, 2 and N under ``AsyncVectorEnv`` (one process each) and 2 under
   ``SyncVectorEnv``; the speed-up of 2 over 1.  Beside them, what bounds that speed-up: ``AsyncVectorEnv``
   with 2 of a do-nothing environment with the same spaces (the protocol's ceiling), and
   the environment in 2 plain processes at once against 1 (what the cores give).
"""
from __future__ import annotations

import os
import statistics
import time

import numpy as np

from wallbsp import render

from .freedoom import FREEDOOM
from .report import machine, machine_line, markdown_table, positive_int, run_script, \
    script_parser
from . import ROOT

SIZE = (160, 120)
TARGET_STEPS = 2500
TARGET_RESET_MS = 50
TARGET_SPEEDUP = 1.6
WARM_STEPS = 50               # step_parts: untimed steps first
VIEW = ("rgb", "depth", "labels")


def exit_level(quick: bool):
    """E1M1 (levels/large.json when Freedoom is absent); a --quick run's is a small
    generated level, so the smoke run does not spend its time compiling."""
    if quick:
        from wallbsp.generate import generate_level
        return generate_level(0, walls=100).level
    e1 = FREEDOOM[0]
    return f"{e1}:E1M1" if e1.exists() else str(ROOT / "levels" / "large.json")


def exit_options(level, **extra) -> dict:
    return {"level": level, "size": SIZE, "frame_skip": 1, "textures": True,
            "observations": VIEW, **extra}


class RandomDriver:
    """An Env or a VectorEnv driven by one seeded uniform-random sequence of Discrete
    actions, stepped in rounds.  Every sub-environment of a vector env gets the same
    action, so all of them, and a single env under the same sequence, walk the same way
    and draw the same views: the configurations do the same work per step."""

    def __init__(self, env, seed: int = 0):
        self.env, self.count = env, getattr(env, "num_envs", 1)
        self.vector = hasattr(env, "num_envs")
        self.best_cpu = 0.0             # steps per CPU second (this process and its workers)
        single = getattr(env, "single_action_space", env.action_space)
        self.actions = np.random.default_rng(seed).integers(single.n, size=1 << 16)
        self.next = 0
        env.reset(seed=seed)

    def rate(self, calls: int) -> float:
        """Steps a second over ``calls`` steps, counting every sub-environment's step (a
        vector env resets its own; a single one is reset here when its episode ends).
        Also keeps the best rate per CPU second spent by this process and the vector env's
        worker processes, which other work on the machine does not lower."""
        env = self.env
        started, cpu = time.perf_counter(), cpu_seconds(env)
        for _ in range(calls):
            action = self.actions[self.next % len(self.actions)]
            self.next += 1
            _, _, terminated, truncated, _ = env.step(
                np.full(self.count, action) if self.vector else action)
            if not self.vector and (terminated or truncated):
                env.reset()
        cpu = cpu_seconds(env) - cpu
        if cpu > 0:
            self.best_cpu = max(self.best_cpu, self.count * calls / cpu)
        return self.count * calls / (time.perf_counter() - started)


def cpu_seconds(env) -> float:
    """CPU seconds used so far by this process and by ``env``'s worker processes (an
    ``AsyncVectorEnv``'s ``processes``; /proc/PID/stat's utime + stime)."""
    total = time.process_time()
    for process in getattr(env, "processes", ()):
        with open(f"/proc/{process.pid}/stat") as f:
            fields = f.read().rsplit(")", 1)[1].split()
        total += (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")
    return total


def best_rates(drivers: dict, steps: int, rounds: int) -> dict:
    """Each driver's best steps/s over ``rounds`` rounds of ``steps`` calls, the drivers
    taking turns round by round (each round the same stretch of the walk for all), so a
    busy spell on the machine hits all alike and the best round is the least disturbed."""
    best = {name: 0.0 for name in drivers}
    for _ in range(rounds):
        for name, driver in drivers.items():
            best[name] = max(best[name], driver.rate(steps))
    return {name: round(v, 1) for name, v in best.items()}


def one_env(level, steps: int, rounds: int) -> dict:
    import gymnasium as gym
    variants = {"rgb+depth+labels, textured": {},
                "rgb, textured": {"observations": ("rgb",)},
                "rgb+depth+labels, untextured": {"textures": False},
                "pose only (no frame)": {"observations": ("pose",)}}
    drivers = {name: RandomDriver(gym.make("wallbsp/Exit-v0", **exit_options(level, **extra)))
               for name, extra in variants.items()}
    out = best_rates(drivers, steps, rounds)
    for driver in drivers.values():
        driver.env.close()
    return out, {name: round(d.best_cpu, 1) for name, d in drivers.items()}


def step_parts(level, steps: int) -> dict:
    """Milliseconds a step spends in the World's tic, drawing the frame and making the
    observation arrays (medians), on the target configuration."""
    import gymnasium as gym
    from wallbsp.envs.actions import buttons_of
    from wallbsp.envs.observations import view_observation
    env = gym.make("wallbsp/Exit-v0", **exit_options(level)).unwrapped
    env.reset(seed=0)
    rng = np.random.default_rng(0)
    parts = {"tic": [], "frame": [], "arrays": []}
    for step in range(steps + WARM_STEPS):
        buttons = buttons_of("discrete", int(rng.integers(env.action_space.n)))
        t0 = time.perf_counter()
        env.world.tic(**buttons.tic_inputs(first=True))
        t1 = time.perf_counter()
        frame = render(env.world, env.world.camera(env.fov), *SIZE)
        t2 = time.perf_counter()
        view_observation(frame, VIEW)
        t3 = time.perf_counter()
        if step >= WARM_STEPS:             # a new env's first steps build its caches
            for key, value in zip(parts, (t1 - t0, t2 - t1, t3 - t2)):
                parts[key].append(value)
    return {key: round(1000 * statistics.median(v), 3) for key, v in parts.items()}


def explore_reset(resets: int) -> dict:
    """Median milliseconds of ``Explore-v0``'s reset and of its parts, over seeds."""
    import gymnasium as gym
    from wallbsp import compile_level
    from wallbsp.game.world import World
    from wallbsp.generate import generate_level
    env = gym.make("wallbsp/Explore-v0", size=SIZE, observations=VIEW).unwrapped
    env.reset(seed=0)                     # imports and first-use tables out of the way
    whole, cpu, parts = [], [], {"generate": [], "compile": [], "world": [], "first_frame": []}
    walls = []
    for seed in range(1, resets + 1):
        t0, c0 = time.perf_counter(), time.process_time()
        env.reset(seed=seed)
        whole.append(time.perf_counter() - t0)
        cpu.append(time.process_time() - c0)
        t0 = time.perf_counter()
        generated = generate_level(seed)
        t1 = time.perf_counter()
        tree = compile_level(generated.level)
        t2 = time.perf_counter()
        world = World(tree)
        t3 = time.perf_counter()
        render(world, world.camera(env.fov), *SIZE)
        t4 = time.perf_counter()
        walls.append(len(generated.level.walls))
        for key, value in zip(parts, (t1 - t0, t2 - t1, t3 - t2, t4 - t3)):
            parts[key].append(value)
    return {"reset_ms_median": round(1000 * statistics.median(whole), 1),
            "reset_cpu_ms_median": round(1000 * statistics.median(cpu), 1),
            "parts_ms_median": {k: round(1000 * statistics.median(v), 1)
                                for k, v in parts.items()},
            "walls_median": int(statistics.median(walls)), "resets": resets}


class NullEnv:
    """Gymnasium's side of a step alone: an env with ``wallbsp/Exit-v0``'s spaces whose step
    does nothing but hand over new copies of one observation and an info dict like the real
    one's.  ``AsyncVectorEnv`` over it measures what the protocol itself allows."""

    def __new__(cls, options):
        import gymnasium as gym

        class _Null(gym.Env):
            def __init__(self):
                real = gym.make("wallbsp/Exit-v0", **options)
                self.observation_space = real.observation_space
                self.action_space = real.action_space
                self.obs = real.reset(seed=0)[0]
                real.close()

            def reset(self, *, seed=None, options=None):
                super().reset(seed=seed)
                return self._observation(), {}

            def step(self, action):
                return self._observation(), 0.0, False, False, {"tics": 1, "exited": False,
                                                                "health": 100}

            def _observation(self):
                return {k: v.copy() for k, v in self.obs.items()}

        return _Null()


class PlainProcesses:
    """``count`` plain environments in as many processes, each driven like a
    ``RandomDriver`` (the same actions, so the same walk), stepped together round by
    round: what the cores give, measured in the same rounds as the configurations it
    bounds.  Steps/s of a round: every process's steps over the time until the last one
    finished.  ``close()`` ends the processes."""

    def __init__(self, options, count: int = 2):
        import multiprocessing
        context = multiprocessing.get_context("fork")
        self.count, self.best_cpu, self.env = count, 0.0, self
        self.conns, self.processes = [], []
        for _ in range(count):
            mine, theirs = context.Pipe()
            process = context.Process(target=_plain_loop, args=(options, theirs), daemon=True)
            process.start()
            self.conns.append(mine)
            self.processes.append(process)
        for conn in self.conns:
            conn.recv()                               # built and reset

    def rate(self, calls: int) -> float:
        started = time.perf_counter()
        for conn in self.conns:
            conn.send(calls)
        for conn in self.conns:
            conn.recv()
        return self.count * calls / (time.perf_counter() - started)

    def close(self) -> None:
        for conn in self.conns:
            conn.send(None)
        for process in self.processes:
            process.join(5)


def _plain_loop(options, conn):
    import gymnasium as gym
    driver = RandomDriver(gym.make("wallbsp/Exit-v0", **options))
    conn.send("ready")
    while (calls := conn.recv()) is not None:
        driver.rate(calls)
        conn.send("done")


def _lone_rate(options, steps, rounds, start, results):
    """A worker of ``plain_processes``: one environment's best rate, started together."""
    import gymnasium as gym
    driver = RandomDriver(gym.make("wallbsp/Exit-v0", **options))
    driver.rate(steps)                       # warm
    start.wait()
    results.put(max(driver.rate(steps) for _ in range(rounds)))


def plain_processes(options, steps: int, rounds: int, count: int) -> float:
    """Steps/s of ``count`` single environments in as many plain processes at once (no
    gymnasium in between)."""
    import multiprocessing
    context = multiprocessing.get_context("fork")
    start, results = context.Barrier(count), context.Queue()
    workers = [context.Process(target=_lone_rate, args=(options, steps, rounds, start, results))
               for _ in range(count)]
    for worker in workers:
        worker.start()
    total = sum(results.get() for _ in workers)
    for worker in workers:
        worker.join()
    return total


def vector_envs(level, counts, steps: int, rounds: int) -> dict:
    import gymnasium as gym
    options = exit_options(level)

    def fns(n):
        return [lambda: gym.make("wallbsp/Exit-v0", **options) for _ in range(n)]
    drivers = {"1": RandomDriver(gym.make("wallbsp/Exit-v0", **options))}
    drivers.update({f"async {n}": RandomDriver(gym.vector.AsyncVectorEnv(fns(n)))
                    for n in counts})
    drivers["sync 2"] = RandomDriver(gym.vector.SyncVectorEnv(fns(2)))
    drivers["async 2, do-nothing env"] = RandomDriver(
        gym.vector.AsyncVectorEnv([lambda: NullEnv(options) for _ in range(2)]))
    out = best_rates(drivers, steps, rounds)
    # what the two cores give: 2 plain processes against 1, one right after the other
    plain = [plain_processes(options, steps, rounds, n) for n in (1, 2)]
    out["2 plain processes"] = round(plain[1], 1)
    for driver in drivers.values():
        driver.env.close()
    out["speedup_async_2"] = round(out["async 2"] / out["1"], 2)
    out["speedup_async_2_over_async_1"] = round(out["async 2"] / out["async 1"], 2)
    out["speedup_plain_2"] = round(plain[1] / plain[0], 2)
    cpu = {name: round(d.best_cpu, 1) for name, d in drivers.items()}
    # on an idle machine with 2 cores: 2 cores' worth of the async run's CPU rate, and
    # never more than two single environments
    bound = min(2.0 * cpu["async 2"], 2.0 * cpu["1"]) / cpu["1"] if cpu["1"] else None
    return out, cpu, None if bound is None else round(bound, 2)


def main(argv=None) -> int:
    parser = script_parser(__doc__, "a smoke run: few steps and resets")
    parser.add_argument("--envs", type=positive_int, default=2 * len(os.sched_getaffinity(0)),
                        help="N, the largest number of vector environments (default 2 x nproc)")
    return run_script(parser, run, "environments", section, argv=argv)


def run(args) -> dict:
    import wallbsp.envs  # noqa: F401 - registers the ids
    load = os.getloadavg()[0]
    steps, rounds = (10, 1) if args.quick else (150, 10)
    level = exit_level(args.quick)
    counts = sorted({1, 2, args.envs})
    single, single_cpu = one_env(level, steps, rounds)
    reset = explore_reset(1 if args.quick else 40)
    vectors, vectors_cpu, bound = vector_envs(level, counts, steps, rounds)
    return {"machine": machine(), "load_average": load, "quick": args.quick,
            "level": getattr(level, "name", level), "size": f"{SIZE[0]}x{SIZE[1]}",
            "steps": steps, "rounds": rounds,
            "one_env_steps_per_s": single, "one_env_steps_per_cpu_s": single_cpu,
            "step_ms_median": step_parts(level, steps),
            "explore_reset": reset, "vector_steps_per_s": vectors,
            "vector_steps_per_cpu_s": vectors_cpu, "async_2_speedup_cpu_bound": bound,
            "targets": {"one_env_steps_per_s": TARGET_STEPS,
                        "explore_reset_ms": TARGET_RESET_MS,
                        "async_2_speedup": TARGET_SPEEDUP},
            "meets": {"one_env": single["rgb+depth+labels, textured"] >= TARGET_STEPS,
                      "explore_reset": reset["reset_ms_median"] <= TARGET_RESET_MS,
                      "async_2_speedup": vectors["speedup_async_2"] >= TARGET_SPEEDUP}}


def section(report) -> str:
    one = report["one_env_steps_per_s"]
    parts = report["step_ms_median"]
    reset = report["explore_reset"]
    vec = report["vector_steps_per_s"]
    yes = {True: "yes", False: "NO"}
    targets = markdown_table(
        ["target", "measured", "wanted", "met"],
        [["one env, steps/s", one["rgb+depth+labels, textured"], f"≥ {TARGET_STEPS}",
          yes[report["meets"]["one_env"]]],
         ["Explore-v0 reset, median ms", reset["reset_ms_median"], f"≤ {TARGET_RESET_MS}",
          yes[report["meets"]["explore_reset"]]],
         ["AsyncVectorEnv 2 / one env", vec["speedup_async_2"], f"≥ {TARGET_SPEEDUP}",
          yes[report["meets"]["async_2_speedup"]]]])
    return "\n\n".join([
        "## Learning environments (Gymnasium)",
        f"Regenerate: `python tools/bench.py env`. {machine_line(report['machine'])} "
        f"Load average when it started: {report['load_average']:.1f}. "
        f"`wallbsp/Exit-v0` on `{report['level']}`, {report['size']}, frame skip 1, a "
        f"seeded random sequence of Discrete actions, the same for every environment; "
        f"steps/s is the best of {report['rounds']} rounds of {report['steps']} calls of "
        "step (counting all environments' steps), the configurations taking turns round by "
        "round.",
        targets,
        "Steps per second of one environment (and per second of the process's CPU time, "
        "which other work on the machine does not lower):",
        markdown_table(["observations", "steps/s", "steps per CPU s"],
                       [[k, v, report["one_env_steps_per_cpu_s"][k]] for k, v in one.items()]),
        f"Where a step goes (median ms): the World's tic {parts['tic']}, the frame "
        f"{parts['frame']}, the observation arrays {parts['arrays']}.",
        f"`Explore-v0` reset over {reset['resets']} seeds (~{reset['walls_median']} walls): "
        f"median {reset['reset_ms_median']} ms ({reset['reset_cpu_ms_median']} ms of CPU "
        f"time); parts (median ms): "
        + ", ".join(f"{k} {v}" for k, v in reset["parts_ms_median"].items()) + ".",
        "Vector environments (all environments' steps together; per CPU second counts this "
        "process and the workers):",
        markdown_table(["environments", "steps/s", "steps per CPU s"],
                       [[k, v, report["vector_steps_per_cpu_s"].get(k, "—")]
                        for k, v in vec.items() if not k.startswith("speedup")]),
        f"Measured speed-up of AsyncVectorEnv with 2 over one environment: "
        f"{vec['speedup_async_2']}; what the CPU time allows on an idle 2-core machine "
        f"(2 × the async run's steps per CPU second, at most 2 × one's, over one's): "
        f"{report['async_2_speedup_cpu_bound']}.  AsyncVectorEnv with 2 over AsyncVectorEnv "
        f"with 1 (the same protocol on both sides): {vec['speedup_async_2_over_async_1']}.  "
        f"The same environment in two plain "
        f"processes at once, no gymnasium in between, against one such process run just "
        f"before: {vec['speedup_plain_2']} ×.  "
        f"AsyncVectorEnv with 2 of a do-nothing environment with the same spaces (its "
        f"step only copies one observation) does {vec['async 2, do-nothing env']} steps/s: "
        "the protocol's own ceiling, whatever the environment."])
