"""``wallbsp walk WAD`` and ``wallbsp walk``: the game started as DOOM starts it.

A window at once with the title picture (the WAD's ``TITLEPIC``; for the bundled game ours,
``tools/make_title_picture.py``) and a progress bar, while a thread makes everything play
needs: the first map a new game plays and the first demo's map compiled, every kernel play
calls compiled (``warmup``; numba keeps them on disk, so later starts are quick).  Then
DOOM's attract loop (``attract``: title, the WAD's demos with the status bar, credits; the
bundled game's title and its shipped demo) until a key opens the menu, whose New Game asks
episode and skill as DOOM's does.

With ``WALLBSP_STARTUP_LOG=FILE`` in the environment a JSON line is appended to FILE for
each moment of the start (``window``, each step of the progress bar, ``ready``), with
``time.time()`` and facts (the CPU seconds of each process, kernels compiled in the warm-up),
and one for every kernel compiled once play has begun (``compiled_in_play``: there should be
none), so a benchmark can time and check it from outside.
"""
from __future__ import annotations

import json
import os
import struct
import threading
import time

import numpy as np

from wallbsp.app.window import prefer_plain_framebuffer

__all__ = ["run_game", "TitleScreen", "note_moment", "title_rgb", "WadGame", "OwnGame"]

BAR_COLOUR, BAR_BACK = (200, 40, 30), (40, 10, 8)
BAR = 100                   # the progress bar's steps
FRAME_SECONDS = 1 / 10      # how often the window answers while the game is made


def note_moment(name: str, **facts) -> None:
    """A line for the start's benchmark (module doc), with ``facts`` about the moment."""
    path = os.environ.get("WALLBSP_STARTUP_LOG")
    if path:
        with open(path, "a") as f:
            f.write(json.dumps({"event": name, "time": time.time(), **facts}) + "\n")


class TitleScreen:
    """The window while the game is made: the title picture, a progress bar, a line."""

    def __init__(self, title, window, aspect=4 / 3):
        import pygame
        prefer_plain_framebuffer()
        pygame.display.init()
        pygame.font.init()
        self.display = pygame.display.set_mode(window, pygame.RESIZABLE)
        pygame.display.set_caption("wallbsp")
        self.font = pygame.font.Font(None, 22)
        self.title = pygame.surfarray.make_surface(np.ascontiguousarray(title.transpose(1, 0, 2)))
        self.aspect = aspect
        self.done, self.total, self.label = 0, 1, "starting"
        self.scaled = None              # (size, the title scaled to it)

    def progress(self, done, total, label) -> None:
        if label != self.label:
            note_moment(label)
        self.done, self.total, self.label = done, total, label

    def draw(self) -> None:
        import pygame
        width, height = self.display.get_size()
        aspect = self.aspect or 1.6
        w, h = (round(height * aspect), height) if width > height * aspect \
            else (width, round(width / aspect))
        x0, y0 = (width - w) // 2, (height - h) // 2
        if self.scaled is None or self.scaled[0] != (w, h):
            self.scaled = (w, h), pygame.transform.scale(self.title, (w, h))
        self.display.fill((0, 0, 0))
        self.display.blit(self.scaled[1], (x0, y0))
        bar = pygame.Rect(x0 + w // 8, y0 + h - h // 12, w * 3 // 4, max(4, h // 60))
        pygame.draw.rect(self.display, BAR_BACK, bar)
        filled = bar.copy()
        filled.width = bar.width * self.done // max(1, self.total)
        pygame.draw.rect(self.display, BAR_COLOUR, filled)
        text = self.font.render(f"preparing the game: {self.label}", True, (230, 230, 230))
        self.display.blit(text, (bar.x, bar.y - text.get_height() - 4))
        pygame.display.flip()

    def wait(self, thread) -> bool:
        """Redraw until ``thread`` ends, when the progress or the window changed (a cold
        start compiles on both cores: the title's redraws would take a fifth of one);
        False if the window was closed meanwhile."""
        import pygame
        shown = None
        while thread.is_alive():
            for event in pygame.event.get():
                if event.type == pygame.QUIT:
                    return False
                if event.type in (pygame.VIDEORESIZE, pygame.VIDEOEXPOSE, pygame.WINDOWEXPOSED):
                    shown = None
            if shown != (self.done, self.total, self.label):
                shown = (self.done, self.total, self.label)
                self.draw()
            thread.join(FRAME_SECONDS)
        self.draw()
        return True


def title_rgb(art, wad, name="TITLEPIC") -> np.ndarray:
    """The title page as 200 x 320 RGB, black where the WAD has none, decoded here in plain
    Python: the art's own decoder is a compiled kernel, and the window must not wait for
    numba (seconds on the first start) before it shows anything."""
    canvas = np.zeros((200, 320), np.int64) - 1
    from wallbsp.assets.wad import open_wad
    try:
        with open_wad(wad) as opened:
            raw = opened.lump(name)
        width, height, left, top = struct.unpack_from("<hhhh", raw)
        for x, offset in enumerate(struct.unpack_from(f"<{width}I", raw, 8)):
            while 0 <= x < 320 and raw[offset] != 0xFF:
                row, length = raw[offset], raw[offset + 1]
                column = np.frombuffer(raw, np.uint8, length, offset + 3)
                rows = slice(row - top, min(200, row - top + length))
                canvas[rows, x - left] = column[:rows.stop - rows.start]
                offset += length + 4
    except (TypeError, struct.error, IndexError, ValueError, OSError):
        pass                                  # no title, or one that is not a patch: black
    palette = np.vstack([art.palettes[0], np.zeros((1, 3), np.uint8)])
    return palette[canvas].astype(np.uint8)


def run_game(args, keys, load_any) -> None:
    """The WAD's game, or the bundled one (module doc)."""
    from wallbsp.app.precompile import Precompile
    compiling = Precompile().start()    # first: its process imports numba while the window opens
    try:
        _run_game(args, keys, load_any, compiling)
    finally:
        compiling.stop()


def _run_game(args, keys, load_any, compiling) -> None:
    from wallbsp.app.vanilla import is_wad
    source = WadGame(args.level) if is_wad(args.level) else OwnGame(args.level, load_any, args)
    aspect = None if args.square_pixels else 4 / 3
    window = (1280, 720) if args.widescreen else (960, 720) if aspect else (960, 600)
    screen = TitleScreen(source.title(), window, aspect)
    screen.draw()
    note_moment("window")
    made = {}
    thread = threading.Thread(target=prepare, args=(source, args, made, screen.progress,
                                                    compiling), daemon=True)
    thread.start()
    if not screen.wait(thread):
        return
    if "error" in made:
        raise made["error"]
    note_moment("ready")
    if os.environ.get("WALLBSP_STARTUP_LOG"):
        from wallbsp.app.precompile import on_compile
        on_compile(lambda kernel: note_moment("compiled_in_play", kernel=kernel))
    _attract_and_play(args, keys, source, made)


def _cpu_seconds() -> float:
    import resource
    usage = resource.getrusage(resource.RUSAGE_SELF)
    return round(usage.ru_utime + usage.ru_stime, 2)


class WadGame:
    """What the start needs of a WAD: its title, first map, demos and their Worlds."""

    def __init__(self, wad):
        from wallbsp.screen.art import WadArt
        self.wad = wad
        self.art = WadArt([wad])

    def title(self):
        return title_rgb(self.art, self.wad)

    def first_tree(self, progress):
        from wallbsp.app.walkgame import first_map_name
        from wallbsp.bsp.build import compile_level
        from wallbsp.level.wadmap import load_wad_level
        first = first_map_name(self.wad)
        progress(0, BAR, f"compiling {first}")
        return first, compile_level(load_wad_level(self.wad, first))

    def sequence(self, first):
        from wallbsp.app.attract import attract_sequence
        from wallbsp.game.playsim.demos import wad_directory
        return attract_sequence(set(wad_directory(self.wad)), first.startswith("MAP"))

    def demo_world(self, lump):
        from wallbsp.app.walkgame import demo_world
        try:
            return demo_world(self.wad, lump)
        except Exception:               # noqa: BLE001 - a demo this port cannot play
            return None

    def tree_of(self, walk, trees):
        from wallbsp.app.gameflow import wad_trees
        compile_tree = wad_trees(walk.world)
        return lambda name: trees[name] if name in trees \
            else trees.setdefault(name, compile_tree(name))


class OwnGame:
    """The bundled game: our title picture, its level, its shipped demo in the loop."""

    def __init__(self, level, load_any, args):
        from wallbsp.app.walkgame import Episode
        from wallbsp.screen.art import OwnArt
        self.level, self.load_any, self.args = level, load_any, args
        self.art = OwnArt()
        self.tree = None
        self.episode = Episode(load_any, args)

    def title(self):
        import pygame
        from wallbsp.screen.art import OWN_ART
        try:
            picture = pygame.image.load(str(OWN_ART / "TITLEPIC.png"))
            return pygame.surfarray.array3d(picture).transpose(1, 0, 2)
        except (pygame.error, OSError):
            return np.zeros((200, 320, 3), np.uint8)

    def first_tree(self, progress):
        progress(0, BAR, "compiling the level")
        self.tree = self.load_any(self.level, self.args, strict=self.args.strict)
        return self.tree.level.name, self.tree

    def sequence(self, first):
        from wallbsp.app.walkgame import EPISODE
        title = ("page", "TITLEPIC", 170)
        return [step for n in range(1, len(EPISODE) + 1) for step in (title, ("demo", f"level{n}"))]

    def demo_world(self, lump):
        from importlib.resources import files
        from wallbsp.game.demo import check_level, load_demo
        from wallbsp.game.world import World
        try:
            demo = load_demo(str(files("wallbsp") / "data" / "game" / "demos" / f"{lump}.json"))
            from wallbsp.app.walkgame import EPISODE
            number = int(lump[len("level"):]) if lump[len("level"):].isdigit() else 0
            tree = self.tree if number == 1 else self.episode.tree(EPISODE[number - 1])
            check_level(demo, tree.level)
            world = World(tree, demo.skill)
        except (OSError, ValueError, IndexError):   # not the bundled level, or no demo
            return None
        world.demo_commands = list(demo.tics)
        return world

    def tree_of(self, walk, trees):
        self.episode.attach(walk)
        walk.next_level = self.episode
        return None


def prepare(source, args, made, progress, compiling=None) -> None:
    """In the thread: the first map compiled, the first demo's World, the plan's kernels
    compiled in two processes (``compiling``, a started ``precompile.Precompile``, if any),
    the kernels warmed; what is made goes in ``made`` (an error as ``made["error"]``)."""
    try:
        from wallbsp.app.precompile import count_compiles
        from wallbsp.app.warmup import warm_steps
        first, tree = source.first_tree(progress)
        made["trees"] = {first: tree}
        made["sequence"] = source.sequence(first)
        demo = next((step[1] for step in made["sequence"] if step[0] == "demo"), None)
        world = None
        if demo is not None:
            progress(BAR // 10, BAR, f"loading {demo}")
            world = source.demo_world(demo)
        made["world"], made["demo"] = world, demo
        steps = warm_steps(tree, tuple(args.size), args.skill)
        facts = {} if compiling is None else compiling.finish(lambda share: progress(
            round(BAR * (0.2 + 0.6 * share)), BAR, "compiling kernels in two processes"))
        note_moment("compiled", **facts)
        first_step = 0.8 if facts else 0.2           # of the bar: the steps fill the rest
        with count_compiles() as compiled:
            for k, (label, step) in enumerate(steps):
                progress(round(BAR * (first_step + (1 - first_step) * k / len(steps))), BAR,
                         label)
                step()
        note_moment("warmed", warmup_compiles=compiled[0], game_cpu_s=_cpu_seconds())
        progress(1, 1, "ready")
    except Exception as err:            # noqa: BLE001 - raised again in the main thread
        made["error"] = err


def _attract_and_play(args, keys, source, made) -> None:
    from wallbsp.app import walkthrough as app
    from wallbsp.app.attract import Attract
    trees, world = made["trees"], made["world"]
    first_tree = next(iter(trees.values()))
    demo_worlds = {} if world is None else {made["demo"]: world}   # the first one, made

    def make_world(lump):
        return demo_worlds.pop(lump, None) or source.demo_world(lump)

    def setup(walk):
        tree_of = source.tree_of(walk, trees)
        if tree_of is not None:
            walk.overlay.tree_of = tree_of
        Attract(made["sequence"], source.art, make_world, app.start_level).begin(walk)
        if args.loadgame is not None:
            walk.overlay.load(walk, args.loadgame)         # DOOM's -loadgame: past the title

    effects = not (args.nosound or args.nosfx)
    app.run_walkthrough(first_tree, size=args.size, max_fps=args.max_fps, skill=args.skill,
                        sound=effects, music=not (args.nosound or args.nomusic), keys=keys,
                        saves=args.saves, aspect=None if args.square_pixels else 4 / 3,
                        world=world, setup=setup, menus=True, key_file=args.keys,
                        widescreen=args.widescreen)
