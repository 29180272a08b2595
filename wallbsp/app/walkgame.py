"""``wallbsp walk``: what the command line asks of the walkthrough, put together.

- ``walk`` (the bundled game), ``walk LEVEL`` or ``walk WAD:MAP`` (a warp): that level;
  ``walk FOLDER``: a game folder (``game.gamefolder``, docs/modding.md), its first map;
  ``walk WAD`` the WAD's game as DOOM starts it (``startup``: title, demos, menu).
- ``--record X.lmp`` with a WAD: DOOM's v1.9 demo of the game from the map it starts
  on (``game.lmprecord``; headless with ``--frames N`` too); any other ``--record``: the
  walkthrough's JSON demo of the first level.
- ``--playdemo DEMO`` with a WAD: a vanilla demo played in the window with the HUD.
- ``--loadgame N``: the bundled game or a WAD's, started in the game saved in slot N.
- ``--square-pixels``: no 4:3 stretch; ``--widescreen`` the view widened to the window; ``--nosound`` no audio device at all (Chocolate
  Doom's ``-nosound``), ``--nosfx`` / ``--nomusic`` one of the two.
"""
from __future__ import annotations

import os

from wallbsp.app.cliargs import UsageError
from wallbsp.game.gamefolder import is_game_folder, load_game_folder
from wallbsp.app.outputs import check_outputs, write_outputs

__all__ = ["walk_command", "is_lmp", "demo_world", "first_map_name", "Episode", "EPISODE"]


def is_lmp(path) -> bool:
    return path is not None and path.lower().endswith(".lmp")


def _level_spec(args):
    if args.level is None:
        from importlib.resources import files
        return str(files("wallbsp") / "data" / "game.json")
    return args.level


def walk_command(args, load_any, next_level_of) -> None:
    from wallbsp.app.config import KeyConfigError, read_bindings
    from wallbsp.app.vanilla import is_wad
    from wallbsp.app.window import NoDisplayError, check_display
    bundled = args.level is None
    args.level = _level_spec(args)
    check_outputs("walk", [args.screenshot, args.record], [args.level])
    wad_game = is_wad(args.level)
    vanilla = is_lmp(args.record)
    if args.playdemo and not wad_game and ":" not in args.level:
        raise UsageError("walk: --playdemo needs a WAD (wallbsp walk WAD --playdemo DEMO)")
    if args.loadgame is not None:
        _check_loadgame(args, wad_game or bundled)
    try:
        keys = read_bindings(args.keys)
        if args.frames is None:
            check_display()
        setup, world, tree, demo, game = None, None, None, None, None
        summary_holder = {}
        if args.playdemo:
            from wallbsp.app.walkthrough import run_walkthrough
            world = demo_world(_wad_of(args.level), args.playdemo)
            tree = world.tree
            setup = _playback_setup(world)
        elif (wad_game or bundled) and args.frames is None and not (vanilla or args.record):
            from wallbsp.app.startup import run_game
            return run_game(args, keys, load_any)
        elif is_game_folder(args.level):                 # a game of one's own
            from wallbsp.app.walkthrough import run_walkthrough
            from wallbsp.game.world import World
            game = load_game_folder(args.level)
            tree = game.tree(0)
            world = World(tree, args.skill, tables=game.tables)
        else:
            spec = _first_map_spec(args.level) if wad_game else args.level
            from wallbsp.app.walkthrough import run_walkthrough
            tree = load_any(spec, args, strict=args.strict)
            args.level = spec
        if vanilla and not args.playdemo:
            if _wad_of(args.level) is None:
                raise UsageError("walk: a .lmp demo is recorded on a WAD's map "
                                 "(wallbsp walk WAD[:MAP] --record DEMO.lmp)")
            setup = _record_setup()
        elif args.record:
            from wallbsp.game.demo import demo_for
            demo = demo_for(tree.level, args.skill)
        effects = not (args.nosound or args.nosfx)

        def keep(walk, setup=setup):
            summary_holder["walk"] = walk
            if summary_holder.get("episode") is not None:
                summary_holder["episode"].attach(walk)
            if setup is not None:
                setup(walk)
        episode = Episode(load_any, args) if bundled else None
        summary_holder["episode"] = episode
        summary = run_walkthrough(
            tree, size=args.size, frames=args.frames, turn=args.turn,
            screenshot=args.screenshot, max_fps=args.max_fps, demo=demo,
            next_level=game or episode or next_level_of(args.level, args),
            skill=args.skill,
            sound=effects, music=not (args.nosound or args.nomusic), keys=keys,
            saves=args.saves, aspect=None if args.square_pixels else 4 / 3, world=world,
            setup=keep, menus=True if (vanilla or args.playdemo) else None,
            key_file=args.keys, widescreen=args.widescreen)
    except (NoDisplayError, KeyConfigError) as err:
        raise UsageError(str(err)) from None
    _save_recording(args, demo, summary_holder.get("walk"))
    if args.frames is not None:
        print(summary)


def _check_loadgame(args, a_game: bool) -> None:
    """``--loadgame N`` starts the bundled game or a WAD's (where the menus load saves), in
    a window, from a slot that holds a save: else one line before any window opens."""
    if not a_game or args.frames is not None or args.record or args.playdemo:
        raise UsageError("walk: --loadgame starts the bundled game or a WAD's game in a "
                         "window (wallbsp walk [WAD] --loadgame N)")
    from wallbsp.app.saves import DAMAGED, read_slots, saves_folder, slot_path
    folder = saves_folder(args.saves)
    found = read_slots(folder)[args.loadgame]
    if found is None:
        raise UsageError(f"walk: --loadgame {args.loadgame}: "
                         f"{slot_path(folder, args.loadgame)}: no save in that slot")
    if found == DAMAGED:
        raise UsageError(f"walk: --loadgame {args.loadgame}: "
                         f"{slot_path(folder, args.loadgame)}: not a save wallbsp can read")


EPISODE = ("game.json", "game2.json", "game3.json")      # the bundled episode's levels, in order


class Episode:
    """``next_level(exit)`` of the bundled game: the level after the one being left (the
    walkthrough's ``world``), compiled; None after the last (the intermission's play goes
    on there again)."""

    def __init__(self, load_any, args):
        self.load_any, self.args, self.walk, self.trees = load_any, args, None, {}

    def attach(self, walk) -> None:
        self.walk = walk

    def tree(self, name):
        if name not in self.trees:
            from importlib.resources import files
            self.trees[name] = self.load_any(str(files("wallbsp") / "data" / name),
                                             self.args, strict=self.args.strict)
        return self.trees[name]

    def level(self, number: int):
        """Level ``number`` (1-based) of the episode, or None (idclev1N)."""
        return self.tree(EPISODE[number - 1]) if 1 <= number <= len(EPISODE) else None

    def __call__(self, exit_kind):
        if self.walk is None:
            return None
        names = [self.tree(name).level.name for name in EPISODE]
        here = self.walk.world.level.name
        if here not in names or names.index(here) + 1 >= len(EPISODE):
            return None
        return self.tree(EPISODE[names.index(here) + 1])


def _save_recording(args, demo, walk) -> None:
    if demo is not None:
        from wallbsp.game.demo import save_demo
        save_demo(demo, args.record)
    elif walk is not None and walk.recorder is not None:
        write_outputs({args.record: walk.recorder.data()})


def _wad_of(spec):
    from wallbsp.app.vanilla import is_wad
    from wallbsp.level.wadmap import parse_wad_spec
    if is_wad(spec):
        return spec
    parsed = parse_wad_spec(spec)
    return parsed[0] if parsed else None


def first_map_name(wad: str) -> str:
    """``E1M1`` (``MAP01`` for Doom II), the map a new game starts on."""
    from wallbsp.level.wadmap import list_maps
    maps = list_maps(wad)
    if not maps:
        raise UsageError(f"{wad}: the WAD has no maps")
    return "E1M1" if "E1M1" in maps else ("MAP01" if "MAP01" in maps else maps[0])


def _first_map_spec(wad: str) -> str:
    return f"{wad}:{first_map_name(wad)}"


def _record_setup():
    def setup(walk):
        from wallbsp.game.lmprecord import LmpRecorder
        walk.recorder = LmpRecorder(walk.world.play)
    return setup


def demo_world(wad: str, demo_spec: str):
    """A World playing the vanilla demo ``demo_spec`` (a .lmp file or a lump of ``wad``),
    at its first tic; ``world.demo`` is the parsed demo."""
    from wallbsp.bsp.build import compile_level
    from wallbsp.files import LevelError
    from wallbsp.game.playsim.demos import DemoError, load_demo
    from wallbsp.game.playload import level_thing_keys, world_play_class
    from wallbsp.game.playsim.game import map_lump_name
    from wallbsp.game.world import World
    from wallbsp.level.wadmap import load_wad_level
    try:
        demo = load_demo(wad, demo_spec)
    except DemoError as err:
        raise LevelError(str(err)) from None
    if sum(demo.playeringame) != 1:
        raise UsageError(f"{demo_spec}: a demo of {sum(demo.playeringame)} players; the "
                         f"window plays single-player demos (wallbsp play plays any)")
    play = world_play_class()(wad)
    name = map_lump_name(play.gamemode, demo.episode, demo.map)
    tree = compile_level(load_wad_level(wad, name))
    play.level_things = level_thing_keys(tree.level)
    play.g_do_play_demo(demo)
    world = World(tree, demo.skill + 1, play=play)
    world.demo = demo
    world.demo_commands = [row[0].ticcmd() for row in demo.tics]
    return world


def _playback_setup(world):
    def setup(walk):
        walk.playback = iter(world.demo_commands)
    return setup


def silence_audio(nosound: bool) -> None:
    """No audio device is opened with ``--nosound``; SDL is told so before pygame starts."""
    if nosound:
        os.environ.setdefault("SDL_AUDIODRIVER", "dummy")
