"""The world's targets (SPEC §8, §10); prints one JSON object.

    python tools/bench.py world            # the full run (about a minute)
    python tools/bench.py world --quick    # a smoke run (E1M1 only)

The world is DOOM's play simulation (``wallbsp.game.playsim``), so these time its tics.

1. ``World.tic`` on MAP12 (freedoom2.wad, the largest map), the player standing at the
   start, nothing awake: the level's light effects and the idle monsters' looks; the median
   of single tics.  Target ≤ 0.5 ms.
2. ``World.tic`` on MAP12 with every monster awake (each set chasing the player, as a noise
   would wake it) and 20 doors moving (their lines used through DOOM's ``P_UseSpecialLine``
   with every key held): the median of single tics while they act.  Target ≤ 1 ms
   (issue 20).
3. Rendering a ``World`` against rendering the static tree along the scripted E1M1 walk
   (walk.py; freedoom1.wad), 320x200 front to back: every door of the map opened at the
   start and one tic run before each frame, so the renderer meets changed heights; the two
   frames of a camera timed one after the other, alternately first; the ratio of the summed
   frame times of a pass, the median over the passes.  Target ≤ 1.10.

Without the Freedoom WADs it prints what is missing and measures nothing.  The full run
rewrites the "world" section of docs/benchmarks.md (not with --quick or --no-docs).
"""
from __future__ import annotations

import statistics
import time

from wallbsp import World, compile_level, render

from .freedoom import FREEDOOM, absent_wads, load_map
from .report import machine, machine_line, markdown_table, run_script, script_parser
from .walk import walk_frames, walk_path

IDLE_TARGET_MS, ACTIVE_TARGET_MS, RENDER_TARGET = 0.5, 1.0, 1.10
ACTIVE_MOVERS = 20
SIZE = (320, 200)
# DOOM's manual doors (DR, D1 and the locked ones; not the blazing 117/118, soon open)
MANUAL_DOORS = frozenset((1, 26, 27, 28, 31, 32, 33, 34))


def main(argv=None) -> int:
    parser = script_parser(__doc__, "a smoke run: E1M1 only, fewer tics, a 30-frame walk")
    return run_script(parser, run, "world", section, argv=argv)


def run(args) -> dict:
    missing = absent_wads()
    if missing:
        return {"machine": machine(), "quick": args.quick, "missing": missing}
    tics = 200 if args.quick else 3000
    e1m1 = compile_level(load_map(FREEDOOM[0], "E1M1"))
    # --quick ticks E1M1 too: compiling MAP12 would be most of a smoke run
    ticked = (e1m1, "E1M1") if args.quick else \
        (compile_level(load_map(FREEDOOM[1], "MAP12")), "MAP12")
    return {"machine": machine(), "quick": args.quick,
            "idle": idle_tics(*ticked, tics),
            "active": active_tics(*ticked, ACTIVE_MOVERS, 60 if args.quick else 300),
            "render": render_ratio(e1m1, 30 if args.quick else walk_frames(),
                                   1 if args.quick else 5)}


def timed_tics(world, count: int) -> list[float]:
    times = []
    for _ in range(count):
        started = time.perf_counter()
        world.tic()
        times.append(time.perf_counter() - started)
    return times


def idle_tics(tree, name: str, count: int) -> dict:
    world = World(tree)
    timed_tics(world, 35)                     # the pistol comes up; caches are built
    times = timed_tics(world, count)
    median = 1000 * statistics.median(times)
    return {"map": name, "tics": count, "active_movers": world.active_movers,
            "thinkers": sum(1 for _ in world.play.thinkers()),
            "median_ms": round(median, 4),
            "p90_ms": round(1000 * sorted(times)[int(0.9 * len(times))], 4),
            "target_ms": IDLE_TARGET_MS, "meets_target": median <= IDLE_TARGET_MS}


def door_lines(world, count: int) -> list:
    """An opening line of each of up to ``count`` shut manual doors of the play, the doors
    that open furthest first (they move longest)."""
    play = world.play
    lines = {}
    for line in play.lines:
        back = line.backsector
        if line.special in MANUAL_DOORS and back is not None \
                and back.ceilingheight <= back.floorheight:
            lines.setdefault(back.id, line)
    rise = {s: _lowest_neighbour_ceiling(play.sectors[s]) - play.sectors[s].ceilingheight
            for s in lines}
    return [lines[s] for s in sorted(lines, key=lambda s: (-rise[s], s))[:count]]


def _lowest_neighbour_ceiling(sector):
    heights = [other.ceilingheight for line in sector.lines
               for other in (line.frontsector, line.backsector)
               if other is not None and other is not sector]
    return min(heights, default=sector.ceilingheight)


def open_doors(world, lines) -> None:
    """Use ``lines`` as the player would, holding every key."""
    play = world.play
    player = play.players[0]
    player.cards = [True] * len(player.cards)
    for line in lines:
        play.p_use_special_line(player.mo, line, 0)
    world.state.sync()


def wake_monsters(world) -> int:
    """Every monster chasing the player, as a noise that reached it would have it."""
    from wallbsp.doom import info
    play = world.play
    target = play.players[0].mo
    woken = 0
    for th in list(play.thinkers()):
        if getattr(th, "flags", 0) & info.MF_COUNTKILL and th.health > 0:
            th.target = target
            play.p_set_mobj_state(th, th.info.seestate)
            woken += 1
    return woken


def active_tics(tree, name: str, count: int, tics: int) -> dict:
    """Tics while every monster is awake and ``count`` doors (fewer if the map has fewer)
    move."""
    world = World(tree)
    timed_tics(world, 35)
    woken = wake_monsters(world)
    open_doors(world, door_lines(world, count))
    started = world.active_movers
    times, moving = [], 0
    for _ in range(tics):
        before = world.active_movers
        times += timed_tics(world, 1)
        moving += before >= started
    median = 1000 * statistics.median(times)
    return {"map": name, "monsters_awake": woken, "movers_started": started,
            "tics": len(times), "tics_with_all_moving": moving,
            "median_ms": round(median, 4), "target_ms": ACTIVE_TARGET_MS,
            "meets_target": median <= ACTIVE_TARGET_MS}


def render_ratio(tree, frames: int, passes: int) -> dict:
    """Each pass: a fresh World with every door of the map opened at the start, one tic
    (untimed) before each frame, so the heights the renderer reads change between frames;
    the World's frame and the tree's at the same camera, alternately first."""
    cameras = walk_path(tree, frames)
    render(tree, cameras[0], *SIZE)
    static, live, moving, ratios = 0.0, 0.0, 0, []
    for _ in range(passes):
        before = (static, live)
        world = World(tree)
        open_doors(world, door_lines(world, len(world.level.walls)))
        render(world, cameras[0], *SIZE)
        for i, camera in enumerate(cameras):
            version = world.state.version
            world.tic()
            moving += world.state.version != version
            if i % 2:
                live += _frame_seconds(world, camera)
                static += _frame_seconds(tree, camera)
            else:
                static += _frame_seconds(tree, camera)
                live += _frame_seconds(world, camera)
        ratios.append((live - before[1]) / (static - before[0]))
    ratio = statistics.median(ratios)      # a pass disturbed by other work counts once
    count = passes * len(cameras)
    return {"map": "E1M1", "frames": len(cameras), "passes": passes,
            "frames_with_moving_heights": moving, "size": f"{SIZE[0]}x{SIZE[1]}",
            "static_ms": round(1000 * static / count, 3),
            "world_ms": round(1000 * live / count, 3),
            "ratio": round(ratio, 4), "pass_ratios": [round(r, 4) for r in ratios],
            "target": RENDER_TARGET, "meets_target": ratio <= RENDER_TARGET}


def _frame_seconds(source, camera) -> float:
    started = time.perf_counter()
    render(source, camera, *SIZE)
    return time.perf_counter() - started


def section(result: dict) -> str:
    head = ["## The world's targets",
            f"Regenerate: `python tools/bench.py world`. {machine_line(result['machine'])}"]
    if "missing" in result:
        return "\n\n".join(head + [f"Not measured: {', '.join(result['missing'])} missing."])
    idle, active, frames = result["idle"], result["active"], result["render"]
    yes = lambda met: "yes" if met else "NO"            # noqa: E731
    rows = [[f"`World.tic`, nothing awake ({idle['map']})", f"{idle['median_ms']} ms (median)",
             f"≤ {idle['target_ms']} ms", yes(idle["meets_target"])],
            [f"`World.tic`, {active['monsters_awake']} monsters awake and "
             f"{active['movers_started']} doors moving ({active['map']})",
             f"{active['median_ms']} ms (median of {active['tics']} tics)",
             f"≤ {active['target_ms']} ms", yes(active["meets_target"])],
            [f"render a World / the static tree (E1M1 walk, {frames['size']})",
             f"{frames['ratio']} ({frames['world_ms']} / {frames['static_ms']} ms a frame)",
             f"≤ {frames['target']}", yes(frames["meets_target"])]]
    return "\n\n".join(head + [
        "Single tics of DOOM's play simulation timed with `time.perf_counter`, the player "
        f"standing at the start; the idle world still runs its {idle['thinkers']} thinkers "
        "(lights, monsters looking); then every monster is set chasing the player and the "
        f"{active['movers_started']} doors are the map's slowest shut doors (not blazing), "
        "used at once. The render ratio is that of the summed frame "
        f"times of {frames['frames']} frames, world and tree interleaved, the median of "
        f"{frames['passes']} passes ({', '.join(map(str, frames['pass_ratios']))}); "
        f"every door of E1M1 opened at the start and a tic run before each frame (heights "
        f"changed before {frames['frames_with_moving_heights']} of the world's frames).",
        markdown_table(["measure", "value", "target", "met"], rows)])
