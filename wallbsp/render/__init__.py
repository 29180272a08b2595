"""The renderer: a world and a camera in, one frame out (SPEC §4–§5).

Every stage is a compiled kernel (``wallbsp.jit``; ``NUMBA_DISABLE_JIT=1`` runs them as
Python, to step through), fed from per-tree and per-world tables:

1. ``walk`` — the tree walked front to back (DOOM's ``R_RenderBSPNode``, with its closed
   columns and early out) or back to front (the painter's order, ``order="back_to_front"``),
   into drawn *pieces* (a seg's span of columns) and the leaves entered;
2. ``entries`` — the pieces per column, with their rows and the windows they leave open
   (DOOM's drawsegs);
3. ``fill`` — every pixel, textured (SPEC §4b; ``textures``, ``packing``, ``surfaces``) or
   in flat colours, lit by ``shading`` (DOOM's light diminishing);
4. the masked pass (``overlay``: ``sprites``, ``masked``, ``composite``, ``atlas``) — things
   and see-through middle textures, far to near, clipped to the walk's windows;
5. ``layers`` and ``rows`` — the kind, index and depth buffers and row-major copies, only
   when asked for.

Both orders give the same color, kind, index and depth; their ``stats`` differ (the painter
writes pixels many times).  Heights and light come from the ``WorldState`` of the source
each frame (``tables``); ``project`` holds the view as the kernels read it.
"""
from __future__ import annotations

import numpy as np

from wallbsp.camera import Camera, Projection
from wallbsp.scene.state import state_of
from wallbsp.render.entries import entries_of
from wallbsp.render import fill
from wallbsp.render.frame import Frame, save_ids
from wallbsp.render.layers import Layers
from wallbsp.render.overlay import draw_overlay, thing_boxes
from wallbsp.render.project import view_of
from wallbsp.render.surfaces import flat_of, flat_parts, key_parts, scene_of, surfaces_of
from wallbsp.render.tables import height_tables, tree_tables
from wallbsp.render.textures import level_textures
from wallbsp.render.walk import walk_back_to_front, walk_front_to_back

__all__ = ["render", "Frame", "save_ids"]

ORDERS = ("front_to_back", "back_to_front")


def render(source, camera: Camera, width: int, height: int, order: str = "front_to_back",
           light: bool = True, textures: bool = True) -> Frame:
    """Render one ``width × height`` frame of ``source`` (a tree, a ``WorldState`` or
    anything with one as ``.state``) seen by ``camera`` (SPEC §4–§5), with the source's
    current sector heights and light.

    ``order="front_to_back"`` (default) is the column-list renderer with early out;
    ``order="back_to_front"`` the painter's algorithm.  Both give the same color, kind,
    index and depth; their ``stats`` differ (the painter writes pixels many times).
    ``light=False`` draws every surface full bright.  A level that names resources is
    drawn textured (SPEC §4b) unless ``textures=False`` (flat colours)."""
    if order not in ORDERS:
        raise ValueError(f"order must be 'front_to_back' or 'back_to_front', got {order!r}")
    projection = Projection(camera, width, height)
    view = view_of(projection)
    state = state_of(source)
    tables = tree_tables(state.tree)
    heights = height_tables(tables, state)
    tex = level_textures(tables, state) if textures else None
    painter = order == "back_to_front"
    if painter:
        walk = walk_back_to_front(tables, view)
    else:
        walk = walk_front_to_back(tables, heights, view, thing_boxes(state))
    entries, drawsegs, piece_keys = entries_of(walk.pieces, view, projection.u, heights)
    scene = scene_of(tables, heights, state)
    colour = np.empty(view.width * view.height, dtype="<u4")
    if tex is None:
        parts = flat_parts(tables)
        written = fill.paint_flat(tuple(entries), tuple(view), tuple(scene), tuple(flat_of(tables)),
                             bool(light), painter, colour)
    else:
        parts = key_parts(tables, tex)
        written = fill.paint_textured(tuple(entries), tuple(view), projection.u, tuple(parts),
                                      tuple(scene),
                                 tuple(surfaces_of(tex, projection, state.leveltime)),
                                 bool(light), painter, colour)
    walk.stats["pixels_written"] = int(written)
    columns = colour.view(np.uint8).reshape(view.width, view.height, 4)[:, :, :3]
    layers = Layers(view, entries, None if painter else drawsegs, parts, scene, painter, colour,
                    columns)
    # sprites and masked middle textures, far to near, over the finished frame; the
    # painter's are clipped by the windows of a front-to-back walk
    front = None if painter else (walk, piece_keys, drawsegs)
    layers = draw_overlay(view, projection.u, state, tables, heights, scene, columns, layers,
                          walk.stats, light, front, textures)
    return Frame(view.width, view.height, columns, walk.stats, layers, walk.leaves)
