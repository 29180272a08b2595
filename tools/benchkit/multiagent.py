"""Several agents in one world (issue 22, item 5): the PettingZoo environment's steps per
second for 2 and 4 agents at 160x120; prints one JSON object.

    python tools/bench.py multiagent            # the full run (about a minute)
    python tools/bench.py multiagent --quick    # a smoke run

The full run also rewrites the "multiagent" section of docs/benchmarks.md.  Each
configuration is ``wallbsp.envs.parallel_env`` in deathmatch on the bundled arena (and on
freedoom2.wad:MAP01 when Freedoom is installed), frame skip 1, every agent given a
seeded uniform-random Discrete action each step; one step is one tic of the world and one
160x120 frame per agent.  Steps/s is the best of the rounds, the configurations taking
turns round by round (a busy machine only ever takes speed away); agent-steps/s is steps/s
times the agents.  Beside the frames, ``pose`` only (no frame drawn: the world's tics
alone for N players).
"""
from __future__ import annotations

import os
import time

import numpy as np

from .freedoom import FREEDOOM
from .report import machine, machine_line, markdown_table, run_script, script_parser

SIZE = (160, 120)
AGENTS = (2, 4)
OBSERVATIONS = {"rgb": ("rgb",), "rgb+depth+labels": ("rgb", "depth", "labels"),
                "pose (no frame)": ("pose",)}


def levels(quick: bool) -> dict:
    found = {"arena": "arena"}
    map01 = FREEDOOM[1]
    if not quick and map01.exists():
        found["freedoom2 MAP01"] = f"{map01}:MAP01"
    return found


class Driver:
    """One environment stepped with seeded random actions (a new episode when one ends)."""

    def __init__(self, level, players: int, observations):
        from wallbsp.envs import parallel_env
        self.env = parallel_env(level=level, players=players, mode="deathmatch", size=SIZE,
                                observations=observations, max_tics=10 ** 6)
        self.env.reset(seed=0)
        n = self.env.action_space("player_0").n
        self.actions = np.random.default_rng(0).integers(n, size=(1 << 14, players))
        self.at = 0

    def rate(self, steps: int) -> float:
        env = self.env
        agents = env.possible_agents
        start = time.perf_counter()
        for _ in range(steps):
            row = self.actions[self.at % len(self.actions)]
            self.at += 1
            if not env.agents:
                env.reset()
            env.step(dict(zip(agents, row.tolist())))
        return steps / (time.perf_counter() - start)


def measure(quick: bool) -> list:
    steps, rounds = (5, 1) if quick else (100, 5)
    drivers = {}
    for name, level in levels(quick).items():
        for players in AGENTS:
            for obs_name, keys in OBSERVATIONS.items():
                if quick and obs_name != "rgb":
                    continue
                driver = Driver(level, players, keys)
                driver.rate(3)                       # warm: the kernels, the first frames
                drivers[(name, players, obs_name)] = driver
    best = dict.fromkeys(drivers, 0.0)
    for _ in range(rounds):
        for key, driver in drivers.items():
            best[key] = max(best[key], driver.rate(steps))
    return [{"level": name, "agents": players, "observations": obs_name,
             "steps_per_s": round(rate, 1), "agent_steps_per_s": round(rate * players, 1)}
            for (name, players, obs_name), rate in best.items()]


def main(argv=None) -> int:
    parser = script_parser(__doc__, "a smoke run: a few steps, the arena only, rgb only")
    return run_script(parser, run, "multiagent", section, argv=argv)


def run(args) -> dict:
    load = os.getloadavg()[0]
    rows = measure(args.quick)
    return {"machine": machine(), "load_average": load, "quick": args.quick,
            "size": f"{SIZE[0]}x{SIZE[1]}", "rows": rows}


def section(report) -> str:
    return "\n\n".join([
        "## Several agents in one world (PettingZoo)",
        f"Regenerate: `python tools/bench.py multiagent`. {machine_line(report['machine'])} "
        f"Load average when it started: {report['load_average']:.1f} (a shared machine: "
        "other work running at the same time lowers these). `wallbsp.envs.parallel_env` in "
        f"deathmatch, {report['size']}, frame skip 1, seeded random Discrete actions; a step "
        "is one tic and one frame per agent; best of 5 rounds of 100 steps.",
        markdown_table(["level", "agents", "observations", "steps/s", "agent-steps/s"],
                       [[r["level"], r["agents"], r["observations"], r["steps_per_s"],
                         r["agent_steps_per_s"]] for r in report["rows"]])])
