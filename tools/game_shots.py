#!/usr/bin/env python3
"""Five moments of the game beside Chocolate Doom's (issue 32): the title, the attract loop
playing DEMO1, a message (E1M1's first armour bonus), the automap near E1M1's start and the
intermission after E1M1, each pair side by side in ``docs/game_<moment>.png``.

    python tools/game_shots.py [--out docs] [--keep DIR]

Both games run in real windows of 960 × 720 (4:3) under X (the ``DISPLAY`` given, else an
Xvfb started here), driven by xdotool and photographed with ImageMagick's ``import
-window``: what a player sees, not the games' own screenshot files (Chocolate Doom's are
1600 × 1200, ours the internal 320 × 200 without the automap).  The same input reaches
both through two v1.9 demos made here with wallbsp's play simulation (which Chocolate
Doom plays in sync): ``pickup.lmp`` walks from E1M1's start over the three armour bonuses
by the south-east door and stands (the message, then Tab for the automap); ``exit.lmp`` presses E1M1's exit switch from a
start moved beside it (a copy of freedoom1.wad whose E1M1 player start is at (-250, 1280)
facing the switch: the rest of the map and the intermission are E1M1's).  The moments are
taken at the same wall-clock times after each window appears, so a demo's frame may be
a few tics apart between the two.  ``docs/game_widescreen.png`` is ours alone: the message
moment in a 1280 × 720 window with ``--widescreen`` (Crispy Doom's view).
"""
from __future__ import annotations

import argparse
import math
import os
import shutil
import struct
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

WAD = "/usr/share/games/doom/freedoom1.wad"
DOOM = "/usr/games/chocolate-doom"
WINDOW = (960, 720)
EXIT_START = (-250, 1280, 180)       # E1M1's exit room, facing the switch at x = -400
ARMOUR_ROUTE = ((400.0, 90.0), (780.0, 40.0), (912.0, 32.0))   # E1M1's armour bonuses
MOMENTS = ("title", "attract", "message", "automap", "intermission")
DEMO_SECONDS = 30


# -- the demos ----------------------------------------------------------------------------------

def exit_wad(folder: Path) -> Path:
    """A copy of freedoom1.wad (its own name: Chocolate Doom knows an IWAD by it) whose
    E1M1 player 1 start is ``EXIT_START``."""
    data = bytearray(Path(WAD).read_bytes())
    count, directory = struct.unpack_from("<ii", data, 4)
    entries = [struct.unpack_from("<ii8s", data, directory + 16 * i) for i in range(count)]
    index = next(i for i, e in enumerate(entries) if e[2].rstrip(b"\0") == b"E1M1")
    offset, size, name = entries[index + 1]
    assert name.rstrip(b"\0") == b"THINGS"
    for record in range(offset, offset + size, 10):
        if struct.unpack_from("<h", data, record + 6)[0] == 1:
            struct.pack_into("<hhh", data, record, *EXIT_START)
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / "freedoom1.wad"
    path.write_bytes(bytes(data))
    return path


def record(wad: str, steer, seconds: int = DEMO_SECONDS) -> bytes:
    """A v1.9 demo of E1M1 at skill 3: ``steer(world)`` the tic command of each tic (None:
    stand still), through the walkthrough's tic path (the intermission's tics too)."""
    from wallbsp.app import walkthrough as app
    from wallbsp.app.gameflow import GameFlow
    from wallbsp.bsp.build import compile_level
    from wallbsp.game.lmprecord import LmpRecorder
    from wallbsp.game.ticcmds import ticcmd
    from wallbsp.level.wadmap import load_wad_level
    walk = app.Walkthrough.at_start(compile_level(load_wad_level(wad, "E1M1")), skill=3)
    walk.overlay = GameFlow(walk, app.start_level, tempfile.mkdtemp())
    walk.recorder = LmpRecorder(walk.world.play)
    for _ in range(35 * seconds):
        app.run_tic(walk, steer(walk.world) or ticcmd())
    return walk.recorder.data()


def to_the_armour(state):
    """Walk along ``ARMOUR_ROUTE`` (turning toward each point first), then stand."""
    from wallbsp.game.ticcmds import ticcmd

    def steer(world):
        player = world.player
        route = ARMOUR_ROUTE[state.setdefault("next", 0):]
        if route and math.hypot(route[0][0] - player.x, route[0][1] - player.y) < 20:
            state["next"] += 1
            route = route[1:]
        if not route:
            return None
        want = math.degrees(math.atan2(route[0][1] - player.y, route[0][0] - player.x))
        turn = (want - player.angle + 180.0) % 360.0 - 180.0
        return ticcmd(forward=1.0 if abs(turn) < 20 else 0.0, turn=max(-8.0, min(8.0, turn)))
    return steer


def to_the_exit(world):
    """Walk west to the switch and press use until the level is left."""
    from wallbsp.game.ticcmds import ticcmd
    if world.play.gamestate != 0 or world.exited:
        return None
    x = world.player.x
    return ticcmd(forward=1.0 if x > -370 else 0.0, use=x < -360 and world.tic_count % 4 == 0)


# -- the two games under X ----------------------------------------------------------------------

def xdo(*args) -> str:
    return subprocess.run(["xdotool", *args], capture_output=True, text=True).stdout.strip()


def window_of(pid: int, timeout: float = 120.0) -> str:
    """The id of process ``pid``'s newest window (SDL sets ``_NET_WM_PID``), waited for."""
    end = time.time() + timeout
    while time.time() < end:
        found = xdo("search", "--pid", str(pid)).split()
        if found:
            return found[-1]
        time.sleep(0.1)
    raise SystemExit(f"game_shots: no window of process {pid} after {timeout:.0f} s")


def grab(window: str, path: Path) -> None:
    subprocess.run(["import", "-window", window, f"png:{path}"], check=True)


def key(window: str, name: str) -> None:
    xdo("windowfocus", "--sync", window)
    xdo("key", name)


class Session:
    """One game process; ``at(seconds, action)`` runs ``action(window)`` that long after
    ``start`` (the window's appearing, or what ``ready`` waits for)."""

    def __init__(self, command, env, ready=None):
        log = open(Path(env["HOME"]) / "game.log", "ab")
        self.process = subprocess.Popen(command, env=env, stdin=subprocess.DEVNULL,
                                        stdout=log, stderr=log)
        log.close()
        print(f"game_shots: {' '.join(map(str, command[-3:]))}", file=sys.stderr)
        try:
            window_of(self.process.pid, 300.0)          # a cold numba cache compiles for a minute or two
            if ready is not None:
                ready()
        except BaseException:
            self.close()
            raise
        self.start = time.time()

    def at(self, seconds, action) -> None:
        time.sleep(max(0.0, self.start + seconds - time.time()))
        action(window_of(self.process.pid))        # ours opens its window again after the title

    def close(self) -> None:
        self.process.terminate()
        try:
            self.process.wait(10)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()


def chocolate(home: Path, wad: str, *extra):
    folder = home / ".local" / "share" / "chocolate-doom"
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "chocolate-doom.cfg").write_text(
        f"fullscreen 0\nwindow_width {WINDOW[0]}\nwindow_height {WINDOW[1]}\n"
        "aspect_ratio_correct 1\nshow_endoom 0\ngrabmouse 0\n")
    (folder / "default.cfg").write_text("screenblocks 10\n")     # ours: the view full width
    env = dict(os.environ, HOME=str(home), SDL_AUDIODRIVER="dummy")
    return [DOOM, "-iwad", wad, "-nosound", *extra], env


def ours(home: Path, wad: str, *extra):
    cache = os.environ.get("XDG_CACHE_HOME") or str(Path.home() / ".cache")
    env = dict(os.environ, HOME=str(home), SDL_AUDIODRIVER="dummy", XDG_CACHE_HOME=cache,
               WALLBSP_STARTUP_LOG=str(home / "startup.log"))     # the compiled kernels kept
    return [sys.executable, "-m", "wallbsp", "walk", wad, "--nosound", *extra], env


def ready_of(home: Path):
    """Waits for our start's ``ready`` moment (the attract loop begins then)."""
    def wait():
        log = home / "startup.log"
        end = time.time() + 300
        while time.time() < end:
            if log.exists() and '"ready"' in log.read_text():
                return
            time.sleep(0.1)
    return wait


def take(side, home: Path, wads: dict, demos: dict, shots: Path) -> None:
    """The five moments of one game (``side``: ``chocolate`` or ``ours``)."""
    make = chocolate if side == "chocolate" else ours
    demo_flag = "-playdemo" if side == "chocolate" else "--playdemo"
    shot = lambda moment: lambda w: grab(w, shots / f"{side}-{moment}.png")   # noqa: E731
    command, env = make(home, wads["real"])
    ready = ready_of(home) if side == "ours" else None
    game = Session(command, env, ready)
    try:
        game.at(1.5, shot("title"))
        game.at(8.0, shot("attract"))                 # TITLEPIC's 170 tics, then DEMO1
    finally:
        game.close()
    command, env = make(home, wads["real"], demo_flag, str(demos["pickup"]))
    game = Session(command, env)
    try:
        game.at(6.5, shot("message"))                 # the bonuses at tics 141-170
        game.at(9.5, lambda w: key(w, "Tab"))          # the message gone (tic 310)
        game.at(10.5, shot("automap"))
    finally:
        game.close()
    if side == "ours":                                # Crispy Doom's view, ours alone
        command, env = make(home, wads["real"], demo_flag, str(demos["pickup"]),
                            "--widescreen")
        game = Session(command, env)
        try:
            game.at(6.5, shot("widescreen"))
        finally:
            game.close()
    command, env = make(home, wads["exit"], demo_flag, str(demos["exit"]))
    game = Session(command, env)
    try:
        game.at(8.0, shot("intermission"))            # the level left at tic 40
    finally:
        game.close()


# -- the pairs --------------------------------------------------------------------------------

def pair_picture(left: Path, right: Path, out: Path, scale: float = 2 / 3) -> None:
    """Chocolate Doom's window beside ours, scaled by ``scale``, each named above."""
    import pygame
    pygame.font.init()
    font = pygame.font.Font(None, 26)
    pictures = []
    for path in (left, right):
        loaded = pygame.image.load(str(path))          # ImageMagick may write a palette PNG
        picture = pygame.Surface(loaded.get_size(), 0, 32)
        picture.blit(loaded, (0, 0))
        pictures.append(picture)
    size = (round(WINDOW[0] * scale), round(WINDOW[1] * scale))
    gap, top = 8, 28
    sheet = pygame.Surface((2 * size[0] + gap, size[1] + top))
    sheet.fill((24, 24, 24))
    for k, (picture, label) in enumerate(zip(pictures, ("Chocolate Doom 3.0.0", "wallbsp"))):
        x = k * (size[0] + gap)
        sheet.blit(pygame.transform.smoothscale(picture, size), (x, top))
        sheet.blit(font.render(label, True, (230, 230, 230)), (x + 6, 5))
    pygame.image.save(sheet, str(out))


def write_pairs(shots: Path, out: Path) -> None:
    """The pairs, and our widescreen view (1280 x 720) scaled as they are."""
    import pygame
    wide = shots / "ours-widescreen.png"
    if wide.exists():
        picture = pygame.image.load(str(wide))
        size = picture.get_size()
        pygame.image.save(pygame.transform.scale(picture, (size[0] * 2 // 3, size[1] * 2 // 3)),
                          str(out / "game_widescreen.png"))
    for moment in MOMENTS:
        path = out / f"game_{moment}.png"
        pair_picture(shots / f"chocolate-{moment}.png", shots / f"ours-{moment}.png", path)
        print(path)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", default=str(ROOT / "docs"), help="where the pairs go")
    parser.add_argument("--keep", help="keep the single shots in this folder")
    parser.add_argument("--pairs", metavar="DIR", help="only put together the shots kept in "
                        "DIR by an earlier --keep")
    args = parser.parse_args(argv)
    if args.pairs:
        write_pairs(Path(args.pairs), Path(args.out))
        return 0
    for tool in (DOOM, "xdotool", "import"):
        if shutil.which(tool) is None:
            print(f"game_shots: {tool} is not installed", file=sys.stderr)
            return 2
    xvfb = start_display()
    work = Path(tempfile.mkdtemp(prefix="game_shots-"))
    try:
        shots = Path(args.keep) if args.keep else work / "shots"
        shots.mkdir(parents=True, exist_ok=True)
        wads = {"real": WAD, "exit": str(exit_wad(work / "exitwad"))}
        demos = {"pickup": work / "pickup.lmp", "exit": work / "exit.lmp"}
        demos["pickup"].write_bytes(record(WAD, to_the_armour({})))
        demos["exit"].write_bytes(record(wads["exit"], to_the_exit))
        for side in ("chocolate", "ours"):
            home = work / side
            home.mkdir()
            take(side, home, wads, demos, shots)
        write_pairs(shots, Path(args.out))
    finally:
        shutil.rmtree(work, ignore_errors=True)
        if xvfb is not None:
            xvfb.terminate()
            xvfb.wait()
    return 0


def start_display():
    """The ``DISPLAY`` given, or an Xvfb started here (returned, to stop at the end)."""
    if os.environ.get("DISPLAY"):
        return None
    for number in range(58, 90):
        if not os.path.exists(f"/tmp/.X11-unix/X{number}"):
            xvfb = subprocess.Popen(["Xvfb", f":{number}", "-screen", "0", "1280x1024x24"],
                                    stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            while not os.path.exists(f"/tmp/.X11-unix/X{number}"):
                time.sleep(0.1)
            os.environ["DISPLAY"] = f":{number}"
            return xvfb
    raise SystemExit("game_shots: no free X display from :58 to :89")


if __name__ == "__main__":
    sys.exit(main())
