"""The renderer: a world and a camera in, one frame out (SPEC §4–§5).

Two renderers share every piece of arithmetic and give the same pixels:

- ``order="front_to_back"`` (the default) walks the tree nearest first, as DOOM's
  ``R_RenderBSPNode`` does, keeping a sorted list of closed columns (``walk``);
- ``order="back_to_front"`` is the painter's algorithm (``painter``).

The reference code: only the walks are Python, touching each visited node and seg once;
they record the drawn pieces, and all pixel work is batched in numpy: ``rows`` turns pieces
into per-column rows, ``fill`` the rows into runs and the runs into pixels (flat colours),
``texfill`` the runs into texels (SPEC §4b) from the level's ``textures`` (one atlas, one lit
colour table), ``shading`` gives light levels and colours, ``layers`` the id and depth
buffers on demand.  Heights and light come from the ``WorldState`` of the source each frame
(``tables``).  Things and masked middle textures are drawn over the finished frame
(``overlay``).

Front to back, the same steps also run as compiled kernels (``compiled``), which give the
same bytes and are used when numba is there: ``walkkernel`` (the walk), ``columnkernel``
and ``compiledfill`` (entries, the flat and textured fills, the id and depth buffers),
``overlaykernel``, ``maskedkernel`` and ``overlaycompiled`` (the masked pass).

Modules: ``tables`` (what the tree and the world give), ``project`` (segs and boxes to
columns), ``columns`` (the closed-column list), ``walk``, ``painter``, ``rows``, ``fill``,
``texfill``, ``textures``, ``shading``, ``layers``, ``frame``; the masked pass: ``overlay``,
``sprites``, ``masked``, ``clipping``, ``atlas``; the kernels named above.
"""
from __future__ import annotations

from wallbsp.camera import Camera, Projection
from wallbsp.jit import kernels_enabled
from wallbsp.sim.state import state_of
from wallbsp.render.compiledfill import fill_compiled
from wallbsp.render.fill import drawsegs, fill_flat
from wallbsp.render.frame import Frame, save_ids
from wallbsp.render.layers import RunLayers
from wallbsp.render.overlay import draw_overlay, thing_boxes, walk_boxes
from wallbsp.render.painter import fill_back_to_front, walk_back_to_front
from wallbsp.render.rows import Entries
from wallbsp.render.tables import height_tables, tree_tables
from wallbsp.render.texfill import fill_textured, paint_textured
from wallbsp.render.textures import level_textures
from wallbsp.render.walk import walk_front_to_back
from wallbsp.render.walkkernel import walk_compiled

__all__ = ["render", "Frame", "save_ids"]

ORDERS = ("front_to_back", "back_to_front")


class _FrontToBackLayers(RunLayers):
    """Front to back also keeps the drawsegs, made from the entries' windows on demand."""

    def __init__(self, view, heights, tables, e, runs, windows):
        super().__init__(view, heights, tables, e, runs, lengths=runs.lengths)
        self._windows = windows

    def drawsegs(self):
        return drawsegs(self.e, self._windows)


def _front_to_back_compiled(tables, tex, heights, state, view, walk, light):
    """The compiled fill (textured, or flat colours when ``tex`` is None): ``(colour columns, layers, the masked pass's front, written)``."""
    colour, layers, e, written = fill_compiled(tables, tex, heights, state, view, walk.pieces,
                                               light)
    return colour, layers, (walk, e.piece_keys, layers.drawsegs), written


def _fill(order, tables, tex, heights, state, view, e, light):
    """``(colour columns, runs, where, pixels written)``: ``where`` is the entries' windows
    front to back, the per-pixel run numbers for the painter."""
    if order == "front_to_back":
        if tex is None:
            return fill_flat(tables, state, view, e, light)
        return fill_textured(tables, tex, heights, state, view, e, light)
    if tex is None:
        return fill_back_to_front(tables, state, view, e, light)
    return paint_textured(tables, tex, heights, state, view, e, light)


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
    view = Projection(camera, width, height)
    state = state_of(source)
    tables = tree_tables(state.tree)
    heights = height_tables(tables, state)
    tex = level_textures(tables, state) if textures else None
    if order == "front_to_back":
        walk = _walk(tables, heights, view, state)
    else:
        walk = walk_back_to_front(tables, view)
    if order == "front_to_back" and kernels_enabled():
        colour, layers, front, written = _front_to_back_compiled(tables, tex, heights, state,
                                                                 view, walk, light)
    else:
        colour, layers, front, written = _batch_fill(order, tables, tex, heights, state, view,
                                                     walk, light)
    walk.stats["pixels_written"] = written
    # sprites and masked middle textures, far to near, over the finished frame
    layers = draw_overlay(view, state, tables, heights, colour, layers, walk.stats, light, front,
                          textures)
    return Frame(view.width, view.height, colour, walk.stats, layers, walk.leaves)


def _walk(tables, heights, view, state):
    """The front-to-back walk, by the kernel when kernels are on."""
    if not kernels_enabled():
        return walk_front_to_back(tables, heights.key_solid, view, walk_boxes(state))
    return walk_compiled(tables, heights, view, thing_boxes(state))


def _batch_fill(order, tables, tex, heights, state, view, walk, light):
    """The numpy fills: ``(colour columns, layers, the masked pass's front, written)``."""
    e = Entries(tables, heights, view, walk.pieces)
    colour, runs, where, written = _fill(order, tables, tex, heights, state, view, e, light)
    if order == "front_to_back":
        layers = _FrontToBackLayers(view, heights, tables, e, runs, where)
        front = (walk, e.keys, lambda: drawsegs(e, where))
    else:
        layers = RunLayers(view, heights, tables, e, runs, pixel_run=where)
        front = None                     # the things are clipped by a front-to-back walk
    return colour, layers, front, written
