"""The 3-D preview and play: the renderer's view from a camera the author places, and F9.

``'`` puts the camera at the mouse, ``;`` turns it towards the mouse; Tab shows the view
(``wallbsp.render`` at 320 × 200, drawn twice as large in the map view's corner) from the
newest compiled tree, so it follows every edit once the background compile has it.  F9
plays the level from the mouse's point with DOOM's rules: the walkthrough's own frames
(``app.walkthrough``) in the editor's window; Escape comes back to the editor as it was.
"""
from __future__ import annotations

import dataclasses
import math
import time

import numpy as np
import pygame

from wallbsp.app.mapview import draw_marker
from wallbsp.camera import eye_camera
from wallbsp.level.model import Start
from wallbsp.render import render
from wallbsp.scene.state import state_of

__all__ = ["Preview", "toggle_preview", "place_camera", "aim_camera", "camera_point",
           "play_here", "PREVIEW_SIZE"]

PREVIEW_SIZE = (320, 200)
PREVIEW_SCALE = 2
FOV = 90.0
MAX_FRAME_TIME = 0.1


def camera_point(session):
    """Where the camera is (the mouse when none was placed)."""
    if session.camera is not None:
        return session.camera[0], session.camera[1]
    return session.mouse_map()


def place_camera(session):
    x, y = session.snapped_mouse()
    angle = session.camera[2] if session.camera is not None else session.level.start.angle
    session.camera = (x, y, angle)
    session.say(f"camera at ({x}, {y}); ; turns it to the mouse, Tab shows its view")


def aim_camera(session):
    if session.camera is None:
        place_camera(session)
        return
    x, y, _ = session.camera
    mx, my = session.mouse_map()
    if (mx, my) != (x, y):
        session.camera = (x, y, math.degrees(math.atan2(my - y, mx - x)) % 360)


def toggle_preview(session):
    if session.preview is None:
        if session.camera is None:
            st = session.level.start
            session.camera = (st.x, st.y, st.angle)
        session.preview = Preview()
        session.say("3-D preview: ' places the camera, ; aims it, Tab hides it")
    else:
        session.preview = None


class Preview:
    """The renderer's picture from the session's camera, redrawn each frame it is shown."""

    def __init__(self):
        self.surface = None
        self.frame_ms = 0.0

    def picture(self, session):
        """The view as a (320, 200) surface, or None while there is no tree yet."""
        live = session.compiler
        overlay = live.overlay if live is not None else None
        if overlay is None or overlay.tree.node_count == 0:
            return None
        started = time.perf_counter()
        state = state_of(overlay.tree)
        x, y, angle = session.camera
        frame = render(state, eye_camera(state, x, y, angle, FOV), *PREVIEW_SIZE)
        rgb = np.ascontiguousarray(frame.color.transpose(1, 0, 2))
        if self.surface is None:
            self.surface = pygame.Surface(PREVIEW_SIZE, 0, session.display)
        pygame.surfarray.blit_array(self.surface, rgb)
        self.frame_ms = 1000 * (time.perf_counter() - started)
        return self.surface

    def draw(self, session, surface):
        view = session.view
        w, h = PREVIEW_SIZE[0] * PREVIEW_SCALE, PREVIEW_SIZE[1] * PREVIEW_SCALE
        left, top = view.width - w - 10, view.height - h - 10
        _marker(session, surface)
        picture = self.picture(session)
        pygame.draw.rect(surface, (90, 90, 100), (left - 1, top - 1, w + 2, h + 2), 1)
        if picture is None:
            text = session.small_font.render("compiling...", True, (200, 200, 200))
            surface.blit(text, (left + 10, top + 10))
            return
        pygame.transform.scale(picture, (w, h), surface.subsurface((left, top, w, h)))


def _marker(session, surface):
    """The camera on the map: a circle and its view cone."""
    x, y, angle = session.camera
    draw_marker(surface, session.view, (x, y), 16, angle, FOV)


# -- F9: play from the mouse ------------------------------------------------------------------

class _BackToEditor:
    """The walkthrough's overlay while playing from the editor: Escape ends the play (the
    game keeps running under it: ``pauses`` is False)."""
    pauses = False

    def key(self, walk, key):
        if key == pygame.K_ESCAPE:
            walk.running = False
            return True
        return False


def play_level(level, x, y, angle):
    """The level with the player starting at (x, y) facing ``angle`` (its player-1 start
    thing, if any, left out), compiled."""
    from wallbsp.bsp.build import compile_level
    things = tuple(t for t in level.things if t.type != 1)
    start = Start(float(x), float(y), float(angle))
    return compile_level(dataclasses.replace(level, things=things, start=start))


def play_here(session, frames=None):
    """Play from the mouse (F9) in this window until Escape (or ``frames`` frames)."""
    from wallbsp.app.walkthrough import Walkthrough, headless_frame, step_frame
    from wallbsp.files import LevelError
    x, y = session.snapped_mouse()
    sector = session.editor.pick(x, y, "sectors", 0)
    if sector is None:
        session.say("F9 plays from the mouse: put it inside a sector", refused=True)
        return
    angle = session.camera[2] if session.camera is not None else session.level.start.angle
    _notice(session, "compiling the level to play it...")
    try:
        tree = play_level(session.level, x, y, angle)
        walk = Walkthrough.at_start(tree, PREVIEW_SIZE, session.display.get_size())
    except (LevelError, ValueError) as err:
        session.say(f"cannot play: {err}", refused=True)
        return
    walk.display, walk.font, walk.overlay = session.display, session.font, _BackToEditor()
    walk.show_help = False
    pygame.display.set_caption(f"wallbsp edit - playing {session.level.name} (Escape: back)")
    last = time.perf_counter()
    count = 0
    while walk.running and (frames is None or count < frames):
        now = time.perf_counter()
        dt, last = min(now - last, MAX_FRAME_TIME), now
        (step_frame(walk, dt) if frames is None else headless_frame(walk, 0.0))
        count += 1
    if walk.mouse_grab:
        from wallbsp.app.window import toggle_mouse_grab
        toggle_mouse_grab(walk)
    pygame.display.set_caption(f"wallbsp edit - {session.level.name}")
    session.say(f"back from playing ({walk.world.tic_count} tics)")
    return walk


def _notice(session, text):
    """Say ``text`` now, before a wait (the frame is drawn at once)."""
    from wallbsp.editor.frame import draw_frame
    session.say(text)
    draw_frame(session)
