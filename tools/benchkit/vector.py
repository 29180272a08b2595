"""``make_vec``'s targets (issue 23), in one run; prints one JSON object.

    python tools/bench.py vector            # the full run (a few minutes)
    python tools/bench.py vector --quick    # a smoke run (a small generated level)

``wallbsp/Exit-v0`` on freedoom1.wad:E1M1 (levels/large.json without Freedoom), 160x120,
textured, rgb+depth+labels, frame skip 1, driven by one seeded random sequence of
Discrete actions (every environment of a vector env gets the same action, so every
configuration walks the same way and draws the same views).  Steps/s counts every
environment's steps; each is the best of 10 rounds of 150 calls, the configurations
taking turns round by round (a busy machine only takes speed away):

1. one plain environment (``gymnasium.make``);
2. ``make_vec`` with 8 environments on 2 workers (``copy=True``, the default, and
   ``copy=False``), and the same driven asynchronously (``send``/``recv``, batch 4);
3. gymnasium's ``AsyncVectorEnv`` with 2 environments;
4. ``make_vec`` with ``workers=0`` and 8 environments;
5. ``make_vec`` with 2 environments on 2 workers (one each: the protocol without several
   environments taking turns in one process's caches);
6. the protocols alone: ``make_vec`` 8 on 2 workers and ``AsyncVectorEnv`` 2 of a
   do-nothing environment with the same spaces (``env_throughput.NullEnv``).

7. what the cores give: the same environment in 2 plain processes at once, each walking
   the same way, taking its turn in the same rounds (``env_throughput.PlainProcesses``):
   the ceiling any configuration of 2 processes can reach on this machine in this run.

Beside them: the round trip of the wake-ups a worker could sleep on (a pipe byte, a POSIX
semaphore, an eventfd, a raw futex, ``multiprocessing.Connection``).

Resets (``wallbsp/Explore-v0``, a new ~500-wall level each episode, its default one-minute
episodes): 8 environments on 2 workers, asynchronous batches of 4, steps/s over the same
number of steps with episodes ending (and new levels made) against the same levels
without resets (``max_tics`` out of reach).
"""
from __future__ import annotations

import ctypes
import mmap
from functools import partial
import multiprocessing
import os
import time

import numpy as np

from .env_throughput import NullEnv, PlainProcesses, RandomDriver, best_rates, exit_level, \
    exit_options
from .report import machine, machine_line, markdown_table, run_script, script_parser

TARGETS = {"make_vec_8x2_over_one": 1.8, "make_vec_8x2_over_async_2": 3.0,
           "workers0_8_over_one": 0.95, "resets_over_no_resets": 0.8}
ENVS, WORKERS, BATCH = 8, 2, 4


class AsyncDriver(RandomDriver):
    """A ``make_vec`` env driven by ``send``/``recv``: each call receives one batch and
    sends it straight back with the next actions."""

    def __init__(self, env, seed: int = 0):
        self.env, self.count = env, env.batch_size
        self.best_cpu = 0.0
        self.actions = np.random.default_rng(seed).integers(env.single_action_space.n,
                                                            size=1 << 16)
        self.next = 0
        env.async_reset(seed=seed)
        self.steps = 0

    def rate(self, calls: int) -> float:
        from .env_throughput import cpu_seconds
        env = self.env
        started, cpu = time.perf_counter(), cpu_seconds(env)
        for _ in range(calls):
            _, _, _, _, info = env.recv()
            action = self.actions[self.next % len(self.actions)]
            self.next += 1
            ids = info["env_id"]
            env.send(np.full(len(ids), action), ids)
        cpu = cpu_seconds(env) - cpu
        if cpu > 0:
            self.best_cpu = max(self.best_cpu, self.count * calls / cpu)
        self.steps += self.count * calls
        return self.count * calls / (time.perf_counter() - started)


def _null(options, **_):
    """``env_throughput.NullEnv``: the spaces of the real one, a step that only hands
    over a copy of one observation (what a vector env's protocol costs on its own)."""
    return NullEnv(options)


def throughput(level, steps: int, rounds: int) -> tuple[dict, dict, float]:
    import gymnasium as gym
    from wallbsp.envs import make_vec
    options = exit_options(level)
    make = {
        "one env": lambda: RandomDriver(gym.make("wallbsp/Exit-v0", **options)),
        "make_vec 8 envs, 2 workers": lambda: RandomDriver(
            make_vec("wallbsp/Exit-v0", ENVS, workers=WORKERS, **options)),
        "make_vec 8 envs, 2 workers, copy=False": lambda: RandomDriver(
            make_vec("wallbsp/Exit-v0", ENVS, workers=WORKERS, copy=False, **options)),
        "make_vec 8 envs, 2 workers, send/recv batch 4": lambda: AsyncDriver(
            make_vec("wallbsp/Exit-v0", ENVS, workers=WORKERS, batch_size=BATCH, **options)),
        "gymnasium AsyncVectorEnv 2": lambda: RandomDriver(gym.vector.AsyncVectorEnv(
            [lambda: gym.make("wallbsp/Exit-v0", **options) for _ in range(2)])),
        "make_vec 8 envs, workers=0": lambda: RandomDriver(
            make_vec("wallbsp/Exit-v0", ENVS, workers=0, **options)),
        "make_vec 2 envs, 2 workers": lambda: RandomDriver(
            make_vec("wallbsp/Exit-v0", 2, workers=WORKERS, **options)),
        "make_vec 8 envs, 2 workers, do-nothing env": lambda: RandomDriver(
            make_vec(partial(_null, options), ENVS, workers=WORKERS)),
        "gymnasium AsyncVectorEnv 2, do-nothing env": lambda: RandomDriver(
            gym.vector.AsyncVectorEnv([partial(_null, options) for _ in range(2)])),
        "2 plain processes at once": lambda: PlainProcesses(options, WORKERS),
    }
    drivers = {name: build() for name, build in make.items()}
    try:
        for driver in drivers.values():
            driver.rate(max(steps // 5, 2))               # first steps build caches
        rates = best_rates(drivers, steps, rounds)
    finally:
        for driver in drivers.values():
            driver.env.close()
    plain = rates.pop("2 plain processes at once")
    cpu = {name: round(d.best_cpu, 1) for name, d in drivers.items() if d.best_cpu}
    return rates, cpu, plain


def resets(quick: bool) -> dict:
    """Asynchronous steps/s of Explore-v0 with episodes ending against without."""
    from wallbsp.envs import make_vec
    options = {"size": (160, 120), "observations": ("rgb", "depth", "labels"),
               "walls": 100 if quick else 500}
    episode = 20 if quick else 2100                   # Explore-v0's default: one minute
    total = (3 if quick else 3) * ENVS * episode      # about three episodes per env
    out = {}
    for name, max_tics in (("no resets", 10 ** 9), ("with resets", episode)):
        env = make_vec("wallbsp/Explore-v0", ENVS, workers=WORKERS, batch_size=BATCH,
                       max_tics=max_tics, **options)
        try:
            driver = AsyncDriver(env)
            driver.rate(max(2, episode // 20))        # caches, first frames
            calls = total // BATCH
            started = time.perf_counter()
            ended = 0
            for _ in range(calls):
                _, _, terminated, truncated, info = env.recv()
                ended += int(terminated.sum() + truncated.sum())
                env.send(np.full(BATCH, driver.actions[driver.next % 4096]), info["env_id"])
                driver.next += 1
            elapsed = time.perf_counter() - started
        finally:
            env.close()
        out[name] = {"steps_per_s": round(calls * BATCH / elapsed, 1),
                     "episodes_ended": ended, "steps": calls * BATCH}
    out["ratio"] = round(out["with resets"]["steps_per_s"] / out["no resets"]["steps_per_s"], 3)
    return out


# -- wake-ups ---------------------------------------------------------------------------

def _ping(n: int, wait, wake, child_wait, child_wake) -> float:
    pid = os.fork()
    if pid == 0:
        try:
            for k in range(n):
                child_wait(k)
                child_wake(k)
        finally:
            os._exit(0)
    started = time.perf_counter()
    for k in range(n):
        wake(k)
        wait(k)
    elapsed = time.perf_counter() - started
    os.waitpid(pid, 0)
    return 1e6 * elapsed / n


def wakeups(n: int) -> dict:
    """Microseconds of one round trip (wake the other process, be woken back)."""
    out = {}
    r1, w1 = os.pipe()
    r2, w2 = os.pipe()
    out["pipe byte"] = _ping(n, lambda k: os.read(r2, 1), lambda k: os.write(w1, b"x"),
                             lambda k: os.read(r1, 1), lambda k: os.write(w2, b"x"))
    for fd in (r1, w1, r2, w2):
        os.close(fd)
    context = multiprocessing.get_context("fork")
    a, b = context.Semaphore(0), context.Semaphore(0)
    out["POSIX semaphore"] = _ping(n, lambda k: b.acquire(), lambda k: a.release(),
                                   lambda k: a.acquire(), lambda k: b.release())
    if hasattr(os, "eventfd"):
        e1, e2 = os.eventfd(0), os.eventfd(0)
        out["eventfd"] = _ping(n, lambda k: os.eventfd_read(e2), lambda k: os.eventfd_write(e1, 1),
                               lambda k: os.eventfd_read(e1), lambda k: os.eventfd_write(e2, 1))
        os.close(e1)
        os.close(e2)
    out["futex (ctypes)"] = _futex(n)
    c1, c2 = context.Pipe()
    out["multiprocessing Connection"] = _ping(
        n, lambda k: c1.recv_bytes(), lambda k: c1.send_bytes(b"x"),
        lambda k: c2.recv_bytes(), lambda k: c2.send_bytes(b"x"))
    return {name: round(v, 1) for name, v in out.items()}


def _futex(n: int):
    if not os.uname().sysname == "Linux":
        return None
    libc = ctypes.CDLL(None, use_errno=True)
    memory = mmap.mmap(-1, 64)
    words = (ctypes.c_int32 * 2).from_buffer(memory)
    address = [ctypes.addressof(words) + 4 * i for i in range(2)]
    futex = 202 if os.uname().machine == "x86_64" else 98

    def wait(i, k):
        while words[i] == k:
            libc.syscall(futex, ctypes.c_void_p(address[i]), 0, k, None, None, 0)

    def wake(i):
        words[i] += 1
        libc.syscall(futex, ctypes.c_void_p(address[i]), 1, 1, None, None, 0)
    result = _ping(n, lambda k: wait(1, k), lambda k: wake(0),
                   lambda k: wait(0, k), lambda k: wake(1))
    del words
    memory.close()
    return result


# -- the run ----------------------------------------------------------------------------

def main(argv=None) -> int:
    parser = script_parser(__doc__, "a smoke run: a small level, few steps")
    return run_script(parser, run, "vector", section, argv=argv)


def run(args) -> dict:
    import wallbsp.envs  # noqa: F401 - registers the ids
    load = os.getloadavg()[0]
    steps, rounds = (10, 1) if args.quick else (150, 10)
    level = exit_level(args.quick)
    rates, cpu, plain = throughput(level, steps, rounds)
    one = rates["one env"]
    ratios = {
        "make_vec_8x2_over_one": round(rates["make_vec 8 envs, 2 workers"] / one, 2),
        "make_vec_8x2_copy_false_over_one":
            round(rates["make_vec 8 envs, 2 workers, copy=False"] / one, 2),
        "make_vec_8x2_send_recv_over_one":
            round(rates["make_vec 8 envs, 2 workers, send/recv batch 4"] / one, 2),
        "make_vec_8x2_over_async_2": round(rates["make_vec 8 envs, 2 workers"]
                                           / rates["gymnasium AsyncVectorEnv 2"], 2),
        "workers0_8_over_one": round(rates["make_vec 8 envs, workers=0"] / one, 2),
        "make_vec_2x2_over_one": round(rates["make_vec 2 envs, 2 workers"] / one, 2),
        "do_nothing_make_vec_8x2_over_async_2":
            round(rates["make_vec 8 envs, 2 workers, do-nothing env"]
                  / rates["gymnasium AsyncVectorEnv 2, do-nothing env"], 2),
        "cpu_efficiency_make_vec_8x2": round(cpu["make_vec 8 envs, 2 workers"]
                                             / cpu["one env"], 2),
        "cpu_efficiency_workers0_8": round(cpu["make_vec 8 envs, workers=0"] / cpu["one env"], 2),
        "two_plain_processes_over_one": round(plain / one, 2),
        "make_vec_8x2_over_two_plain_processes":
            round(rates["make_vec 8 envs, 2 workers"] / plain, 2),
        "make_vec_8x2_send_recv_over_two_plain_processes":
            round(rates["make_vec 8 envs, 2 workers, send/recv batch 4"] / plain, 2),
    }
    reset = resets(args.quick)
    ratios["resets_over_no_resets"] = reset["ratio"]
    return {"machine": machine(), "load_average": load, "quick": args.quick,
            "level": getattr(level, "name", level), "size": "160x120", "steps": steps,
            "rounds": rounds, "steps_per_s": rates, "steps_per_cpu_s": cpu,
            "two_plain_processes_steps_per_s": plain, "explore_resets": reset,
            "wakeup_round_trip_us": wakeups(2000 if args.quick else 20000),
            "ratios": ratios, "targets": TARGETS,
            "meets": {name: ratios[name] >= target for name, target in TARGETS.items()}}


def section(report) -> str:
    rates, cpu, ratios = report["steps_per_s"], report["steps_per_cpu_s"], report["ratios"]
    yes = {True: "yes", False: "NO"}
    names = {"make_vec_8x2_over_one": "make_vec 8 envs / 2 workers over one env",
             "make_vec_8x2_over_async_2": "make_vec 8 envs / 2 workers over AsyncVectorEnv 2",
             "workers0_8_over_one": "make_vec workers=0, 8 envs, over one env",
             "resets_over_no_resets": "Explore-v0 send/recv: with resets over without"}
    reset = report["explore_resets"]
    return "\n\n".join([
        "## Vector environments: make_vec",
        f"Regenerate: `python tools/bench.py vector`. {machine_line(report['machine'])} "
        f"Load average when it started: {report['load_average']:.1f}. `wallbsp/Exit-v0` on "
        f"`{report['level']}`, {report['size']}, textured, rgb+depth+labels, frame skip 1; "
        f"best of {report['rounds']} rounds of {report['steps']} calls, the configurations "
        "taking turns.",
        markdown_table(["target", "measured", "wanted", "met"],
                       [[names[k], ratios[k], f"≥ {v}", yes[report["meets"][k]]]
                        for k, v in report["targets"].items()]),
        markdown_table(["configuration", "steps/s", "steps per CPU s"],
                       [[k, v, cpu.get(k, "—")] for k, v in rates.items()]
                       + [["2 plain processes at once", report["two_plain_processes_steps_per_s"],
                           "—"]]),
        f"What the cores gave in this run: 2 plain processes at once did "
        f"{ratios['two_plain_processes_over_one']} × one (below 1: other work left no core "
        f"to spare, and no configuration of more than one process can show its scaling); "
        f"make_vec 8 envs on 2 workers reached "
        f"{ratios['make_vec_8x2_over_two_plain_processes']} of that, "
        f"{ratios['make_vec_8x2_send_recv_over_two_plain_processes']} with send/recv. "
        f"Steps per CPU second over one env's, which other work lowers less: make_vec 8 "
        f"envs on 2 workers {ratios['cpu_efficiency_make_vec_8x2']}, 8 envs in one process "
        f"(workers=0) {ratios['cpu_efficiency_workers0_8']}.  The protocols alone (a "
        f"do-nothing env with the same spaces): make_vec "
        f"{ratios['do_nothing_make_vec_8x2_over_async_2']} × AsyncVectorEnv's steps/s.",
        f"Explore-v0, 8 envs on 2 workers, send/recv batches of 4: "
        f"{reset['with resets']['steps_per_s']} steps/s with resets "
        f"({reset['with resets']['episodes_ended']} episodes ended in "
        f"{reset['with resets']['steps']} steps) against "
        f"{reset['no resets']['steps_per_s']} without.",
        "Wake-up round trips between two processes (µs): " + ", ".join(
            f"{k} {v}" for k, v in report["wakeup_round_trip_us"].items()) + "."])
