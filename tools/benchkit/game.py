"""The walkthrough as the game a person plays (issue 21's target): frames per second of
``wallbsp walk`` on freedoom1's E1M1 with DOOM's status bar, weapon and sound, in a
960 × 720 (4:3) window at 320 × 200 inside, and the per-frame CPU time of the HUD and sound work.

    python tools/bench.py game            # 20 s of play
    python tools/bench.py game --quick    # 4 s
    python tools/bench.py game --widescreen   # the widescreen view: 1280 x 720, 426 x 200 inside

The walkthrough runs as a person plays it: ``step_frame`` with the real time since the last
frame (tics at 35 a second, the view blended between them), no frame cap, a scripted player
holding keys through ``controls.press``/``release`` (walking, turning, firing the pistol
every two seconds).  The window is a real X11 window: the ``DISPLAY`` given, else an Xvfb
started for the run.  Sound is the walkthrough's ``SoundSystem`` through pygame.mixer
(SDL's ``dummy`` audio driver when the machine has no audio device: SDL_mixer still mixes),
music when SDL_mixer can play MIDI here.

HUD and sound work a frame: the main thread's CPU time (``time.thread_time``) in
``Hud.draw`` (status bar, weapon, message, flash), ``Hud.tick``, ``SoundSystem.update`` and
``start_sound``, summed over the run and divided by the frames (the tics' share is spread
over the frames, as it is in play); ``frame_cpu_ms`` is the main thread's CPU a whole frame
(what the frame rate would be without waiting for the X server or other processes).
Targets: ≥ 200 frames/s; HUD and sound ≤ 0.3 ms a frame.  The load average is reported:
the machine may be shared.
"""
from __future__ import annotations

import os
import shutil
import subprocess
import time

from .freedoom import FREEDOOM, absent_wads
from .report import machine, markdown_table, run_script, script_parser

TARGET_FPS, TARGET_MS = 200.0, 0.3
SECONDS, QUICK_SECONDS, WARM_SECONDS = 20.0, 4.0, 2.0
WINDOW, SIZE = (960, 720), (320, 200)      # 4:3, as the walkthrough shows 320 x 200
WIDE_WINDOW = (1280, 720)                  # 16:9: --widescreen


def main(argv=None) -> int:
    parser = script_parser(__doc__, f"{QUICK_SECONDS:.0f} s of play")
    parser.add_argument("--widescreen", action="store_true", help="the widescreen view in a "
                        "1280 x 720 window (never written to docs/benchmarks.md)")
    return run_script(parser, run, "game", section, argv=argv)


def run(args) -> dict:
    if args.widescreen:
        args.no_docs = True                 # docs/benchmarks.md keeps the 4:3 target's run
    missing = absent_wads()
    if missing:
        return {"machine": machine(), "quick": args.quick, "missing": missing}
    xvfb = _display()
    try:
        audio = _audio_driver()
        result = _play(QUICK_SECONDS if args.quick else SECONDS, args.widescreen)
    finally:
        if xvfb is not None:
            xvfb.terminate()
            xvfb.wait()
    fps, hud_ms = result["fps"], result["hud_sound_ms"]
    return {"machine": machine(), "quick": args.quick, "audio_driver": audio,
            "load_average": [round(v, 2) for v in os.getloadavg()], **result,
            "target_fps": TARGET_FPS, "target_ms": TARGET_MS,
            "meets_fps": fps >= TARGET_FPS, "meets_ms": hud_ms <= TARGET_MS}


def _display():
    """The X display to draw on: ``DISPLAY``, or an Xvfb started here (returned to stop)."""
    if os.environ.get("DISPLAY"):
        return None
    if shutil.which("Xvfb") is None:
        raise SystemExit("bench game: no DISPLAY and no Xvfb to start one")
    for number in range(90, 110):
        if not os.path.exists(f"/tmp/.X11-unix/X{number}"):
            xvfb = subprocess.Popen(["Xvfb", f":{number}", "-screen", "0", "1280x800x24"],
                                    stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            for _ in range(50):
                if os.path.exists(f"/tmp/.X11-unix/X{number}"):
                    break
                time.sleep(0.1)
            os.environ["DISPLAY"] = f":{number}"
            os.environ.pop("SDL_VIDEODRIVER", None)
            return xvfb
    raise SystemExit("bench game: no free X display number from :90 to :109")


def _audio_driver() -> str:
    """The audio driver SDL will use: the machine's, else SDL's ``dummy`` (which mixes)."""
    import pygame
    try:
        pygame.mixer.init()
        name = os.environ.get("SDL_AUDIODRIVER") or "default"
    except pygame.error:
        os.environ["SDL_AUDIODRIVER"] = name = "dummy"
    finally:
        if pygame.mixer.get_init():
            pygame.mixer.quit()
    return name


class Timed:
    """Wraps a method of an object with an accumulator of the main thread's CPU time
    (``time.thread_time``: what other processes on a shared machine do not add to)."""

    def __init__(self, owner, name):
        self.inner, self.seconds, self.calls = getattr(owner, name), 0.0, 0
        setattr(owner, name, self)

    def __call__(self, *args, **kwargs):
        self.calls += 1
        start = time.thread_time()
        try:
            return self.inner(*args, **kwargs)
        finally:
            self.seconds += time.thread_time() - start


def _play(seconds: float, widescreen: bool = False) -> dict:
    from wallbsp import compile_level
    from wallbsp.app import controls
    from wallbsp.app.audio import close_sound, open_sound
    from wallbsp.app.walkthrough import (Walkthrough, close_display, open_display,
                                         prepare_renderer, step_frame)
    from wallbsp.level.wadmap import load_wad_level
    tree = compile_level(load_wad_level(str(FREEDOOM[0]), "E1M1"))
    walk = Walkthrough.at_start(tree, SIZE, WIDE_WINDOW if widescreen else WINDOW,
                                widescreen=widescreen)
    walk.show_help = False
    prepare_renderer(walk)
    open_display(walk)
    try:
        open_sound(walk)
        music = walk.sound is not None and walk.sound.music is not None \
            and walk.sound.music.enabled
        from wallbsp.app.gamescreen import picture_size
        return _frames(walk, seconds, step_frame, controls) | {
            "window": list(walk.display.get_size()), "size": list(picture_size(walk)),
            "mixer": walk.sound is not None and walk.sound.mixer is not None,
            "music": bool(music)}
    finally:
        close_sound(walk)
        close_display(walk)


def _frames(walk, seconds, step_frame, controls) -> dict:
    """Play ``seconds`` (after a warm-up) with the scripted keys; the frame times and the
    HUD and sound work."""
    import pygame
    timers = []
    times, last, start = [], time.perf_counter(), time.perf_counter()
    cpu = 0.0
    while True:
        now = time.perf_counter()
        elapsed = now - start
        if elapsed >= WARM_SECONDS + seconds:
            break
        if elapsed >= WARM_SECONDS and not timers:
            timers = [Timed(walk.hud, "draw"), Timed(walk.hud, "tick")]
            if walk.sound is not None:
                timers += [Timed(walk.sound, "update"), Timed(walk.sound, "start_sound")]
            tics_before = walk.world.tic_count
        _script(walk, elapsed, controls, pygame)
        thread = time.thread_time()
        step_frame(walk, min(now - last, 0.1))
        last = now
        if timers:
            times.append(time.perf_counter() - now)
            cpu += time.thread_time() - thread
    work = sum(t.seconds for t in timers)
    frames = len(times)
    total = sum(times)
    times.sort()
    return {"seconds": round(total, 2), "frames": frames, "fps": round(frames / total, 1),
            "median_frame_ms": round(1000 * times[frames // 2], 3),
            "frame_cpu_ms": round(1000 * cpu / frames, 3),
            "tics": walk.world.tic_count - tics_before,
            "hud_sound_ms": round(1000 * work / frames, 4),
            "hud_draw_ms": round(1000 * timers[0].seconds / frames, 4),
            "start_sound_calls": timers[3].calls if len(timers) > 3 else 0}


def _script(walk, elapsed, controls, pygame):
    """The scripted player: walks forward, turns left for a second every four, and fires
    for half a second every two."""
    wanted = {pygame.K_w}
    if elapsed % 4.0 < 1.0:
        wanted.add(pygame.K_LEFT)
    if elapsed % 2.0 < 0.5:
        wanted.add(pygame.K_LCTRL)
    for key in wanted - walk.held:
        controls.press(walk, key)
    for key in walk.held - wanted:
        controls.release(walk, key)


def section(result: dict) -> str:
    if "missing" in result:
        return "Freedoom is not installed: nothing measured."
    (ww, wh), (pw, ph) = result["window"], result["size"]
    rows = [[f"frames/s ({ww} × {wh} window, {pw} × {ph} inside)", result["fps"],
             f"≥ {result['target_fps']:.0f}", "met" if result["meets_fps"] else "not met"],
            ["HUD and sound work, ms a frame", result["hud_sound_ms"],
             f"≤ {result['target_ms']}", "met" if result["meets_ms"] else "not met"]]
    load = ", ".join(str(v) for v in result["load_average"])
    return ("## The walkthrough as a game (issue 21)\n\n"
            f"`python tools/bench.py game`: {result['seconds']} s of scripted play on "
            f"freedoom1 E1M1 (walking, turning, firing) with the status bar, weapon and "
            f"sound (audio driver {result['audio_driver']}, music "
            f"{'on' if result['music'] else 'off'}) under X "
            f"({result['frames']} frames, {result['tics']} tics, median frame "
            f"{result['median_frame_ms']} ms, of it {result['frame_cpu_ms']} ms of the main "
            f"thread's CPU, the rest waiting for the X server and the machine; of the HUD and "
            f"sound work, Hud.draw {result['hud_draw_ms']} ms). Load average {load}; "
            f"{result['machine']['nproc']} cores, {result['machine']['date']}.\n\n"
            + markdown_table(["measure", "value", "target", ""], rows) + "\n")
