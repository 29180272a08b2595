"""The walkthrough's heads-up display, drawn over the view: the automap (``mapview``'s
transform and layers), the readout, the help line and the last message.

Functions of the walkthrough's state (``app.Walkthrough``) and its open window; the app
calls ``draw_overlays`` once a frame.  No physics, no events.
"""
from __future__ import annotations

import time

from .mapview import MapView, automap_layer, draw_marker, level_bounds, partition_pieces
from .queries import PLAYER_RADIUS

__all__ = ["HELP", "MESSAGE_SECONDS", "draw_overlays", "readout_lines", "draw_automap", "say"]

HELP = ("WASD/arrows move   Left/Right or mouse (M grab) turn   Shift run   E/Space use   "
        "Esc quit",
        "Tab map  O overlay  L lines  R stats  P painter  [ ] resolution  F fullscreen  "
        "K shot  H help")
TEXT, SHADOW = (235, 235, 235), (0, 0, 0)
MESSAGE_SECONDS = 2.0


def say(walk, text, seconds=MESSAGE_SECONDS):
    """Show ``text`` as the walkthrough's message for ``seconds``."""
    walk.message, walk.message_until = text, time.perf_counter() + seconds


def draw_overlays(walk):
    """Whatever the walkthrough's toggles ask for, over the view in the window."""
    if walk.show_map:
        draw_automap(walk)
    if walk.show_readout:
        _draw_text_block(walk, readout_lines(walk), (8, 8))
    if walk.show_help:
        height = walk.display.get_height()
        _draw_text_block(walk, HELP, (8, height - 8 - len(HELP) * walk.font.get_linesize()))
    if walk.message and time.perf_counter() < walk.message_until:
        _draw_text_block(walk, [walk.message], (walk.display.get_width() // 2 - 100, 8))


def readout_lines(walk):
    """The readout: frame time, the walk's statistics, where the player is, and the world:
    its tic, the movers moving, secrets found of all, health."""
    stats, player, world = walk.frame.stats, walk.player, walk.world
    ms = walk.frame_ms
    found, total = world.secrets
    return [f"{ms:.2f} ms  {1000.0 / ms if ms else 0.0:.0f} fps  "
            f"{walk.size[0]}x{walk.size[1]}  {walk.order}",
            f"nodes visited {stats['nodes_visited']}  segs drawn {stats['segs_drawn']}  "
            f"early exit {'yes' if stats['early_exit'] else 'no'}",
            f"x {player.x:.0f}  y {player.y:.0f}  eye {player.eye:.0f}  "
            f"angle {player.angle:.0f}",
            f"tic {world.tic_count}  movers {world.rules.active_movers}  "
            f"secrets {found}/{total}  health {world.inventory.health}"]


def _draw_text_block(walk, lines, topleft):
    """Text with a one-pixel shadow, readable over any part of the view."""
    x, y = topleft
    for line in lines:
        walk.display.blit(walk.font.render(line, True, SHADOW), (x + 1, y + 1))
        walk.display.blit(walk.font.render(line, True, TEXT), (x, y))
        y += walk.font.get_linesize()


# -- the automap ------------------------------------------------------------------------------

def draw_automap(walk):
    """The static layer (cached per window size and mode), then the player and view cone."""
    size = walk.display.get_size()
    view = MapView.centred(level_bounds(walk.tree), size)
    key = (size, walk.map_overlay, walk.show_partitions)
    if walk.map_cache[0] != key:
        walk.map_cache = (key, _map_layer(walk, size, view))
    walk.display.blit(walk.map_cache[1], (0, 0))
    player = walk.player
    draw_marker(walk.display, view, (player.x, player.y), PLAYER_RADIUS, player.angle, walk.fov)


def _map_layer(walk, size, view):
    """The automap's static layer; partition lines computed on first use and kept."""
    if walk.show_partitions and walk.partitions is None:
        walk.partitions = partition_pieces(walk.tree, level_bounds(walk.tree))
    return automap_layer(walk.tree, view, size, walk.display, walk.map_overlay,
                         walk.partitions if walk.show_partitions else None)
