"""Does the bundled game let a newcomer live?  Issue 32's target: a scripted newcomer
(``wallbsp.game.newcomer``: a random walk, fire held toward the nearest monster in sight)
survives level 1's first minute, its start room and the hall behind the first door, at
skill 2 in most of 20 runs.

    python tools/bench.py newcomer            # 20 runs (seeds 0-19) at skills 2 and 3
    python tools/bench.py newcomer --quick    # 5 runs
    python tools/bench.py newcomer --level OLD.json --no-docs   # another level, beside it

Each run: a fresh World of ``wallbsp/data/game.json`` at the skill, the newcomer's command
every tic for 60 seconds of game time (2,100 tics; a death ends the run: using after
death would start again).  Reported per skill: the runs alive at the end, the health left
(median), the kills, and the runs that got through the first door (into the hall).
"""
from __future__ import annotations

import statistics

from .report import machine, markdown_table, run_script, script_parser

RUNS, QUICK_RUNS, TICS = 20, 5, 35 * 60
SKILLS = (2, 3)
HALL_Y = 352.0          # map units: north of the start room's door is the hall


def main(argv=None) -> int:
    parser = script_parser(__doc__, f"{QUICK_RUNS} runs a skill")
    parser.add_argument("--level", help="another level file (default: the bundled level 1)")
    return run_script(parser, run, "newcomer", section, argv=argv)


def one_run(tree, skill: int, seed: int) -> dict:
    from wallbsp.game.newcomer import Newcomer
    from wallbsp.game.world import World
    world = World(tree, skill)
    bot = Newcomer(seed)
    reached_hall = False
    for tic in range(TICS):
        world.tic(bot.command(world))
        reached_hall |= world.player.y > HALL_Y
        if world.dead:
            break
    return {"alive": not world.dead, "tics": tic + 1, "health": max(0, world.player.health),
            "kills": world.kills[0], "hall": reached_hall}


def run(args) -> dict:
    from importlib.resources import files
    from wallbsp.bsp.build import compile_level
    from wallbsp.level.io import load_level
    path = args.level or str(files("wallbsp") / "data" / "game.json")
    tree = compile_level(load_level(path))
    runs = QUICK_RUNS if args.quick else RUNS
    result = {"machine": machine(), "quick": args.quick, "runs": runs, "tics": TICS,
              "level": args.level or "wallbsp/data/game.json"}
    for skill in SKILLS:
        rows = [one_run(tree, skill, seed) for seed in range(runs)]
        result[f"skill{skill}"] = {
            "alive": sum(r["alive"] for r in rows),
            "through_first_door": sum(r["hall"] for r in rows),
            "median_health": statistics.median(r["health"] for r in rows),
            "median_kills": statistics.median(r["kills"] for r in rows)}
    result["meets"] = result["skill2"]["alive"] > runs // 2
    return result


def section(result: dict) -> str:
    rows = [[f"skill {s}", result[f"skill{s}"]["alive"], result[f"skill{s}"]["through_first_door"],
             result[f"skill{s}"]["median_health"], result[f"skill{s}"]["median_kills"]]
            for s in SKILLS]
    return ("## A newcomer on the bundled level (issue 32)\n\n"
            f"`python tools/bench.py newcomer`: {result['runs']} runs a skill of the scripted "
            f"newcomer (random walk, fire held toward the nearest monster in sight), "
            f"{result['tics']} tics each on level 1 from its start.\n\n"
            + markdown_table(["skill", "alive at the end", "through the first door",
                              "median health", "median kills"], rows)
            + f"\n\nTarget (alive in most runs at skill 2): "
              f"{'met' if result['meets'] else 'not met'}.\n")
