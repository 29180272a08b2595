"""The walkthrough's overlays, drawn over the scaled picture in the window: the automap
(``automap``: DOOM's colours, over the view above the status bar), the readout and the help
line; and ``say``, which puts a line up as DOOM's message (``screen.Hud``, drawn into the
picture with the game's font) and keeps it as ``walk.message``.

Functions of the walkthrough's state (``app.Walkthrough``) and its open window; the app
calls ``draw_overlays`` once a frame.  No physics, no events.
"""
from __future__ import annotations

import time

from wallbsp.app.automap import (MapView, SeenLines, automap_layer, draw_arrow,
    draw_things, level_bounds, line_kinds, partition_pieces)
from wallbsp.screen.hud import view_size

__all__ = ["HELP", "HELP_SECONDS", "MESSAGE_SECONDS", "draw_overlays", "readout_lines", "inventory_lines",
           "texture_mode", "draw_automap", "say", "map_area", "map_view", "whole_map", "seen_lines",
           "map_line_width"]

HELP = ("WASD/arrows move   Left/Right or mouse (M frees it) turn   Shift run   Alt strafe   "
        "E/Space use   Ctrl/click fire   1-7 weapons   Esc menu",
        "F1 all the keys  Tab map  O overlay  L lines  X textures  R readout  "
        "P painter  [ ] resolution  - = status bar  F fullscreen  K shot  H this line")
TEXT, SHADOW = (235, 235, 235), (0, 0, 0)
MESSAGE_SECONDS = 2.0
SCREENHEIGHT = 200
READOUT_Y = 12               # of 200 rows: under the message line (a 7-row font and a gap)
HELP_SECONDS = 15.0          # an interactive walk shows the key help this long at first


def say(walk, text, seconds=MESSAGE_SECONDS):
    """Put ``text`` up as the player's message (the Hud's, for DOOM's four seconds of
    tics); ``walk.message`` keeps it for ``seconds`` of wall time."""
    walk.message, walk.message_until = text, time.perf_counter() + seconds
    if walk.hud is not None:
        walk.hud.say(text)


def draw_overlays(walk):
    """Whatever the walkthrough's toggles ask for, over the picture in the window."""
    if walk.show_map:
        draw_automap(walk)
    if walk.show_readout:
        # below DOOM's message line (HU_MSGY 0, the font's height), never over it
        top = walk.display.get_size()[1] * READOUT_Y // SCREENHEIGHT
        _draw_text_block(walk, readout_lines(walk), (8, top))
    if walk.show_help and walk.help_until is not None and time.perf_counter() > walk.help_until:
        walk.show_help, walk.help_until = False, None    # it covered the weapon; H brings it back
    if walk.show_help and walk.attract is None and walk.playback is None:   # not over a demo
        bottom = map_area(walk)[1]
        _draw_text_block(walk, HELP, (8, bottom - 8 - len(HELP) * walk.font.get_linesize()))
    if walk.help_screen:
        from wallbsp.app.helpscreen import draw_help_screen
        draw_help_screen(walk)


def readout_lines(walk):
    """The readout: frame time and how the view is drawn, the walk's statistics, where the
    player is, the world (its tic, the movers moving, secrets found of all) and what the
    player holds (``inventory_lines``)."""
    stats, player, world = walk.frame.stats, walk.player, walk.world
    ms = walk.frame_ms
    found, total = world.secrets
    return [f"{ms:.2f} ms  {1000.0 / ms if ms else 0.0:.0f} fps  "
            f"{walk.size[0]}x{walk.size[1]}  {walk.order}  {texture_mode(walk)}",
            f"nodes visited {stats['nodes_visited']}  segs drawn {stats['segs_drawn']}  "
            f"early exit {'yes' if stats['early_exit'] else 'no'}",
            f"x {player.x:.0f}  y {player.y:.0f}  eye {player.eye:.0f}  "
            f"angle {player.angle:.0f}",
            f"tic {world.tic_count}  movers {world.active_movers}  "
            f"secrets {found}/{total}",
            *inventory_lines(world.inventory)]


def inventory_lines(inventory):
    """Health, armour and keys held; the weapon in hand and the ammunition of every kind."""
    keys = ", ".join(sorted(inventory.keys)) or "none"
    ammo = "  ".join(f"{kind} {rounds}" for kind, rounds in inventory.ammo.items())
    return [f"health {inventory.health}  armour {inventory.armour}  keys {keys}",
            f"{inventory.weapon}  ammo  {ammo}"]


def texture_mode(walk) -> str:
    """How the view is drawn: ``textures``, or ``flat colours`` (asked for, or a level that
    names no textures)."""
    if not walk.tree.level.resources:
        return "flat colours (no textures)"
    return "textures" if walk.textures else "flat colours"


def _draw_text_block(walk, lines, topleft):
    """Text with a one-pixel shadow, readable over any part of the view."""
    x, y = topleft
    for line in lines:
        walk.display.blit(walk.font.render(line, True, SHADOW), (x + 1, y + 1))
        walk.display.blit(walk.font.render(line, True, TEXT), (x, y))
        y += walk.font.get_linesize()


# -- the automap ------------------------------------------------------------------------------

def map_area(walk):
    """``(width, height)`` of the window above the status bar (all of it without one)."""
    width, height = walk.display.get_size()
    w, h = walk.size
    return width, height * view_size(w, h, walk.statusbar)[1] // h


def draw_automap(walk):
    """The lines in DOOM's colours and rules (redrawn when a height changes, a line is
    seen or the map moves, else cached per window size and mode), the things as they are
    now (with IDDT's second step, ``map_cheat`` 2), then the player's arrow; over the
    window above the status bar."""
    size = map_area(walk)
    view = map_view(walk, size)
    state = walk.world.state
    seen = seen_lines(walk)
    key = (size, walk.map_overlay, walk.show_partitions, id(state), state.version,
           view.scale, view.stretch, view.ox, view.oy, seen.count, walk.map_cheat,
           has_allmap(walk))
    if walk.map_cache[0] != key:
        walk.map_cache = (key, _map_layer(walk, size, view))
    walk.display.blit(walk.map_cache[1], (0, 0))
    walk.display.set_clip((0, 0, *size))           # never over the status bar
    try:
        width = map_line_width(walk)
        if walk.map_cheat >= 2:                     # IDDT twice: the things too
            draw_things(walk.display, view, walk.world.things, width)
        player = walk.player
        draw_arrow(walk.display, view, player.x, player.y, player.angle, width)
        draw_map_title(walk)
    finally:
        walk.display.set_clip(None)


def map_line_width(walk) -> int:
    """DOOM draws the automap's lines a pixel wide on its 200-row screen: as many of the
    window's rows as one of those."""
    return max(1, round(walk.display.get_size()[1] / SCREENHEIGHT))


def draw_map_title(walk):
    """HU_Drawer's level name at the automap's bottom left (``HU_TITLEX`` 0, ``HU_TITLEY``
    167 less the font's height, of DOOM's 4:3 screen), in the WAD's font and words."""
    import pygame
    from wallbsp.app.gamescreen import middle_columns, picture_size
    from wallbsp.screen.art import art_for
    from wallbsp.screen.dehstrings import map_title
    from wallbsp.screen.messages import paint_text
    width, height = walk.display.get_size()
    wide = picture_size(walk)[0]
    x0, w = middle_columns(walk, wide) or (0, wide)
    left, across = x0 * width // wide, w * width // wide      # the 4:3 screen's columns
    key = (walk.world.level.name, across, height)
    if walk.title_cache[0] != key:
        art = walk.hud.art or art_for(walk.world.play)
        lump = walk.world.wad_map[1] if walk.world.wad_map is not None else None
        painted = paint_text(map_title(art, lump, walk.world.level.name), art)
        surface = None
        if painted is not None:
            rgb, mask = painted
            rows = rgb.shape[0] - 2                            # paint_text's margin
            picture = pygame.surfarray.make_surface(
                (rgb * mask[..., None]).transpose(1, 0, 2)[:, :rows].copy())
            picture.set_colorkey((0, 0, 0))
            size = (max(1, across), max(1, rows * height // SCREENHEIGHT))
            surface = (pygame.transform.scale(picture, size),
                       (167 - rows) * height // SCREENHEIGHT)
        walk.title_cache = (key, surface)
    if walk.title_cache[1] is not None:
        picture, top = walk.title_cache[1]
        walk.display.blit(picture, (left, top))


def has_allmap(walk) -> bool:
    """The player carries the computer area map (``pw_allmap``)."""
    from wallbsp.doom import info
    player = walk.world.play.players[walk.world.play.consoleplayer]
    return bool(player.powers[info.pw_allmap])


def seen_lines(walk) -> SeenLines:
    """The walls seen on the level being played (anew when its state is: a new level, or
    this one again after a death)."""
    state = walk.world.state
    if walk.seen is None or walk.seen[0] is not state:
        lines = [line for line, _, _ in getattr(state, "walls", ())]
        if len(lines) != len(walk.tree.level.walls):
            lines = None                # not a play's state: the walls seen are the app's
        walk.seen = (state, SeenLines(walk.tree.level, lines))
    return walk.seen[1]


def whole_map(walk, size) -> MapView:
    """The whole level fitted into ``size`` as DOOM fits it (no margin), stretched down as
    the picture is: DOOM draws its map on the 320 x 200 screen a player sees at 4:3."""
    w, h = walk.size
    stretch = w / h / walk.aspect if walk.aspect else 1.0
    return MapView.centred(level_bounds(walk.tree), size, margin=0, stretch=stretch)


def map_view(walk, size) -> MapView:
    """``whole_map`` (``map_zoom`` 1), or ``map_zoom`` times closer with the player at the
    centre (DOOM's follow mode)."""
    whole = whole_map(walk, size)
    if walk.map_zoom <= 1.0:
        return whole
    scale, stretch = whole.scale * walk.map_zoom, whole.stretch
    player = walk.player
    return MapView((whole.x0, 0.0, 0.0, whole.y1), scale,
                   (size[0] / 2 - (player.x - whole.x0) * scale,
                    size[1] / 2 - (whole.y1 - player.y) * scale * stretch), stretch)


def _map_layer(walk, size, view):
    """The automap's lines now; partition lines computed on first use and kept."""
    if walk.show_partitions and walk.partitions is None:
        walk.partitions = partition_pieces(walk.tree, level_bounds(walk.tree))
    state, lines = walk.world.state, walk.world.play.lines
    flags = [line.flags for line in lines] if len(lines) == len(walk.tree.level.walls) \
        else None
    kinds = line_kinds(walk.tree.level, state.floor, state.ceiling, flags,
                       seen_lines(walk).walls, walk.map_cheat, has_allmap(walk))
    return automap_layer(walk.tree, kinds, view, size, walk.display, walk.map_overlay,
                         walk.partitions if walk.show_partitions else None,
                         map_line_width(walk))
