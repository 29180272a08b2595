"""``wallbsp play WAD DEMO``: a vanilla DOOM demo (version 1.9 ``.lmp``, a file or a lump
such as ``DEMO1``) played by DOOM's play simulation, going on to the next map after an
exit as DOOM does.  ``--trace`` writes Chocolate Doom's trace format line for line
(``shared/oracle/README.md``), ``--timedemo`` prints tics per second, ``--json`` the final
state."""
from __future__ import annotations

import json
import time

from wallbsp.app.outputs import check_outputs, write_outputs
from wallbsp.files import LevelError

__all__ = ["is_wad", "play_vanilla"]

FRACUNIT = 1 << 16


def is_wad(path: str) -> bool:
    """A DOOM archive (``IWAD``/``PWAD`` magic), as opposed to a level or tree file."""
    try:
        with open(path, "rb") as f:
            return f.read(4) in (b"IWAD", b"PWAD")
    except OSError:
        return False


def play_vanilla(args) -> None:
    from wallbsp.game.playsim.demos import DemoError, load_demo
    from wallbsp.game.playsim.mapload import MapLoadError
    from wallbsp.game.playsim.play import play_class
    from wallbsp.game.playsim.trace import trace_line
    check_outputs("play", [args.trace, args.screenshot], [args.level, args.demo])
    try:
        demo = load_demo(args.level, args.demo)
        play = play_class()(args.level)
        play.g_do_play_demo(demo)
        hud = new_hud() if args.screenshot and args.hud else None
        lines, started = [], time.perf_counter()
        for commands in demo.tics:
            ticked = play.g_ticker(commands)
            if ticked and args.trace:
                line = trace_line(play)
                if line is not None:
                    lines.append(line)
            if hud is not None and ticked and play.gamestate == 0:    # ST_Ticker, HU_Ticker
                hud.tick(play)
        seconds = time.perf_counter() - started
    except (DemoError, MapLoadError) as err:
        raise LevelError(str(err)) from None
    outputs = {}
    if args.trace:
        outputs[args.trace] = "".join(line + "\n" for line in lines).encode()
    if args.screenshot:
        outputs[args.screenshot] = screenshot(play, args.size, hud)
    write_outputs(outputs)
    if args.timedemo:
        tics = len(demo.tics)
        print(f"timed {tics} gametics in {seconds:.3f} s: {tics / max(seconds, 1e-9):.1f} tics/s")
    state = final_state(play, len(demo.tics))
    if args.json:
        print(json.dumps(state, sort_keys=True))
    elif not args.timedemo:
        width = max(len(k) for k in state)
        for key, value in state.items():
            print(f"{key:<{width}}  {value}")


def final_state(play, tics: int) -> dict:
    """The player's state when the demo ends, in map units and degrees (SPEC §8's keys)."""
    from wallbsp.game.playsim.game import GS_LEVEL
    player = play.players[play.consoleplayer]
    mo = player.mo
    state = {"tics": tics, "map": map_name(play), "leveltime": play.leveltime,
             "health": player.health, "armor": player.armorpoints,
             "kills": player.killcount, "items": player.itemcount,
             "secrets": player.secretcount, "exited": play.gamestate != GS_LEVEL}
    if mo is not None:
        state.update(x=mo.x / FRACUNIT, y=mo.y / FRACUNIT, z=mo.z / FRACUNIT,
                     angle=round((mo.angle & 0xFFFFFFFF) * 360 / 2**32, 6))
    return state


def map_name(play) -> str:
    from wallbsp.game.playsim.structs import COMMERCIAL
    if play.gamemode == COMMERCIAL:             # Doom II's MAPxx
        return f"MAP{play.gamemap:02d}"
    return f"E{play.gameepisode}M{play.gamemap}"


def new_hud():
    from wallbsp.screen.hud import Hud
    return Hud()


def screenshot(play, size, hud=None) -> bytes:
    """The console player's view when the demo ends: the map compiled into a tree, its
    heights, lights and things read from the play as the World reads them; with ``hud``,
    DOOM's status bar and weapon around it."""
    from wallbsp.bsp.build import compile_level
    from wallbsp.camera import Camera
    from wallbsp.game.playstate import PlayState
    from wallbsp.image import png_bytes
    from wallbsp.level.wadmap import load_wad_level
    from wallbsp.render import render
    tree = compile_level(load_wad_level(play.wad_path, map_name(play)))
    state = PlayState(tree, play, play.gameskill + 1)
    player = play.players[play.consoleplayer]
    mo = player.mo
    camera = Camera(mo.x / FRACUNIT, mo.y / FRACUNIT, player.viewz / FRACUNIT,
                    (mo.angle & 0xFFFFFFFF) * 360 / 2**32)
    if hud is not None:
        from wallbsp.app.hudframe import hud_frame
        return png_bytes(hud_frame(state, camera, *size, hud=hud)[0])
    return png_bytes(render(state, camera, *size).color)
