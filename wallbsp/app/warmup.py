"""Compiling what play needs before play starts: the game's warm-up.

numba compiles a kernel the first time it is called with new argument types (and keeps
the machine code on disk for the next run).  A game that compiled during play would stop
for seconds at its first door, first shot, first menu; so before play the warm-up runs
what play runs, in the order play needs it, on a throwaway game of the level about to be
played: the level loaded, a frame of the view with the status bar, weapon and message,
tics of a scripted player walking, opening doors and firing (the play's walks, sight,
collision), the screen's flashes (damage and pickup tints, the invulnerability colours),
another internal resolution.  ``warm_steps(tree)`` are the steps, as ``(label, function)``
pairs, for a progress bar (``startup``); ``warm_up(tree)`` runs them all.  Nothing here
touches the game that is then played.
"""
from __future__ import annotations

__all__ = ["warm_steps", "warm_up", "WARM_TICS"]

WARM_TICS = 140             # tics of the scripted player (four seconds of play)


def warm_steps(tree, size=(320, 200), skill=3):
    """The warm-up's steps for ``tree`` at the internal resolution ``size``."""
    state = {}

    def level():
        import numpy as np
        from wallbsp.app.walkthrough import Walkthrough
        from wallbsp.scene.things import locate_leaves
        state["walk"] = Walkthrough.at_start(tree, size, skill=skill)
        start = tree.level.start
        locate_leaves(tree, np.array([start.x], float), np.array([start.y], float))  # moves

    def view():
        from wallbsp.app.gamescreen import compose
        walk = state["walk"]
        walk.hud.say("WARMING UP")
        compose(walk)
        walk.textures = False
        compose(walk)
        walk.textures = True

    def play(part):
        def run():
            from wallbsp.app.gamescreen import compose
            from wallbsp.app.walkthrough import run_tic
            from wallbsp.game.newcomer import Newcomer
            walk = state["walk"]
            bot = state.setdefault("bot", Newcomer(part))
            for tic in range(WARM_TICS // 2):
                run_tic(walk, bot.command(walk.world))
                if tic % 10 == 0:
                    compose(walk)
        return run

    def flashes():
        from wallbsp.app.gamescreen import compose
        from wallbsp.screen.art import INVERSE
        walk = state["walk"]
        player = walk.world.play.players[walk.world.play.consoleplayer]
        for damage, bonus, colormap in ((10, 0, 0), (0, 6, 0), (0, 0, INVERSE)):
            player.damagecount, player.bonuscount = damage, bonus
            player.fixedcolormap = colormap
            compose(walk)
        walk.paused = True
        compose(walk)

    def other_size():
        from wallbsp.app.gamescreen import compose
        walk = state["walk"]
        walk.size = (size[0] * 2, size[1] * 2)
        walk.statusbar = walk.hud.statusbar = False
        compose(walk)

    return [("loading the level", level), ("the view", view), ("walking", play(1)),
            ("fighting", play(2)), ("the screen's flashes", flashes),
            ("another size", other_size)]


def warm_up(tree, size=(320, 200), skill=3, progress=None) -> None:
    """Every step of ``warm_steps``; ``progress(done, total, label)`` after each."""
    steps = warm_steps(tree, size, skill)
    for done, (label, step) in enumerate(steps, 1):
        step()
        if progress is not None:
            progress(done, len(steps), label)
