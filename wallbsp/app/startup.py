"""``wallbsp walk WAD``: the game started as DOOM starts it.

A window at once with the title picture (the WAD's ``TITLEPIC``, or ours) and a progress
bar, while a thread makes everything play needs: the first map a new game plays and the
first demo's map compiled, every kernel play calls compiled (``warmup``; numba keeps them
on disk, so later starts are quick).  Then DOOM's attract loop (``attract``: title, the
WAD's demos with the status bar, credits) until a key opens the menu, whose New Game asks
episode and skill as DOOM's does.

With ``WALLBSP_STARTUP_LOG=FILE`` in the environment a JSON line is appended to FILE for
each moment of the start (``window``, ``ready``), with ``time.time()``, so a benchmark can
time it from outside.
"""
from __future__ import annotations

import json
import os
import threading
import time

import numpy as np

__all__ = ["run_game", "TitleScreen", "note_moment"]

BAR_COLOUR, BAR_BACK = (200, 40, 30), (40, 10, 8)
FRAME_SECONDS = 1 / 30


def note_moment(name: str) -> None:
    """A line for the start's benchmark (module doc)."""
    path = os.environ.get("WALLBSP_STARTUP_LOG")
    if path:
        with open(path, "a") as f:
            f.write(json.dumps({"event": name, "time": time.time()}) + "\n")


class TitleScreen:
    """The window while the game is made: the title picture, a progress bar, a line."""

    def __init__(self, art, window, aspect=4 / 3):
        import pygame
        pygame.display.init()
        pygame.font.init()
        self.display = pygame.display.set_mode(window, pygame.RESIZABLE)
        pygame.display.set_caption("wallbsp")
        self.font = pygame.font.Font(None, 22)
        from wallbsp.app.attract import page_picture
        rgb, mask = page_picture(art, "TITLEPIC", 320, 200)
        rgb = np.where(mask[..., None], rgb, 0).astype(np.uint8)
        self.title = pygame.surfarray.make_surface(rgb.transpose(1, 0, 2))
        self.aspect = aspect
        self.done, self.total, self.label = 0, 1, "starting"

    def progress(self, done, total, label) -> None:
        self.done, self.total, self.label = done, total, label

    def draw(self) -> None:
        import pygame
        width, height = self.display.get_size()
        aspect = self.aspect or 1.6
        w, h = (round(height * aspect), height) if width > height * aspect \
            else (width, round(width / aspect))
        x0, y0 = (width - w) // 2, (height - h) // 2
        self.display.fill((0, 0, 0))
        self.display.blit(pygame.transform.scale(self.title, (w, h)), (x0, y0))
        bar = pygame.Rect(x0 + w // 8, y0 + h - h // 12, w * 3 // 4, max(4, h // 60))
        pygame.draw.rect(self.display, BAR_BACK, bar)
        filled = bar.copy()
        filled.width = bar.width * self.done // max(1, self.total)
        pygame.draw.rect(self.display, BAR_COLOUR, filled)
        text = self.font.render(f"preparing the game: {self.label}", True, (230, 230, 230))
        self.display.blit(text, (bar.x, bar.y - text.get_height() - 4))
        pygame.display.flip()

    def wait(self, thread) -> bool:
        """Redraw until ``thread`` ends; False if the window was closed meanwhile."""
        import pygame
        while thread.is_alive():
            for event in pygame.event.get():
                if event.type == pygame.QUIT:
                    return False
            self.draw()
            thread.join(FRAME_SECONDS)
        self.draw()
        return True


def run_game(args, keys) -> None:
    """The WAD's game (module doc)."""
    from wallbsp.app.walkgame import demo_world
    from wallbsp.screen.art import WadArt
    wad = args.level
    aspect = None if args.square_pixels else 4 / 3
    window = (960, 720) if aspect else (960, 600)
    art = WadArt([wad])
    screen = TitleScreen(art, window, aspect)
    screen.draw()
    note_moment("window")
    made = {}
    thread = threading.Thread(target=_prepare, args=(wad, args, made, screen.progress,
                                                     demo_world), daemon=True)
    thread.start()
    if not screen.wait(thread):
        return
    if "error" in made:
        raise made["error"]
    note_moment("ready")
    _attract_and_play(args, keys, wad, art, made)


def _prepare(wad, args, made, progress, demo_world) -> None:
    """In the thread: the maps compiled, the first demo's World, the kernels warmed."""
    try:
        from wallbsp.app.attract import attract_sequence
        from wallbsp.app.warmup import warm_steps
        from wallbsp.app.walkgame import first_map_name
        from wallbsp.bsp.build import compile_level
        from wallbsp.game.playsim.demos import wad_directory
        from wallbsp.level.wadmap import load_wad_level
        lumps = set(wad_directory(wad))
        first = first_map_name(wad)
        made["sequence"] = attract_sequence(lumps, commercial=first.startswith("MAP"))
        progress(0, 8, f"compiling {first}")
        made["trees"] = {first: compile_level(load_wad_level(wad, first))}
        demo = next((s[1] for s in made["sequence"] if s[0] == "demo"), None)
        world = None
        if demo is not None:
            progress(1, 8, f"loading {demo}")
            world = _demo_or_none(demo_world, wad, demo)
        made["world"], made["demo"] = world, demo
        steps = warm_steps(made["trees"][first], tuple(args.size), args.skill)
        for k, (label, step) in enumerate(steps):
            progress(2 + k, 2 + len(steps), label)
            step()
        progress(1, 1, "ready")
    except Exception as err:            # noqa: BLE001 - raised again in the main thread
        made["error"] = err


def _demo_or_none(demo_world, wad, lump):
    try:
        return demo_world(wad, lump)
    except Exception:                   # noqa: BLE001 - a demo this port cannot play
        return None


def _attract_and_play(args, keys, wad, art, made) -> None:
    from wallbsp.app import walkthrough as app
    from wallbsp.app.attract import Attract
    from wallbsp.app.gameflow import wad_trees
    trees = made["trees"]
    world = made["world"]
    first_tree = next(iter(trees.values()))
    demo_worlds = {}

    if world is not None:
        demo_worlds[made["demo"]] = world          # made already: the first one shown

    def make_world(lump):
        from wallbsp.app.walkgame import demo_world
        return demo_worlds.pop(lump, None) or _demo_or_none(demo_world, wad, lump)

    def setup(walk):
        compile_tree = wad_trees(walk.world)
        walk.overlay.tree_of = lambda name: trees[name] if name in trees \
            else trees.setdefault(name, compile_tree(name))
        Attract(made["sequence"], art, make_world, app.start_level).begin(walk)

    effects = not (args.nosound or args.nosfx)
    app.run_walkthrough(first_tree, size=args.size, max_fps=args.max_fps, skill=args.skill,
                        sound=effects, music=not (args.nosound or args.nomusic), keys=keys,
                        saves=args.saves, aspect=None if args.square_pixels else 4 / 3,
                        world=world, setup=setup, menus=True)
