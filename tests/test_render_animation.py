"""Animated flats and wall textures (DOOM's P_InitPicAnims and P_UpdateSpecials): the runs
found in a WAD, and frames of Freedoom's E1M1 at several leveltimes against the same view
with every animated surface renamed, by DOOM's rule computed here from the WAD's own
directory, to the picture it should show."""
from __future__ import annotations

import copy
import struct
from dataclasses import replace

import numpy as np
import pytest

from test_wad import freedoom
from wadkit import colormap, flat, playpal
from wallbsp.assets.animations import animations
from wallbsp.assets.resources import ResourceSet
from wallbsp.assets.wad import wad_bytes
from wallbsp.camera import Camera
from wallbsp.render import render
from wallbsp.render.frame import KIND_FLOOR, KIND_WALL
from wallbsp.scene.state import WorldState

RUNS = {"flat": [("NUKAGE1", "NUKAGE3"), ("FWATER1", "FWATER4"), ("SWATER1", "SWATER4"),
                 ("LAVA1", "LAVA4"), ("BLOOD1", "BLOOD3"), ("RROCK05", "RROCK08"),
                 ("SLIME01", "SLIME04"), ("SLIME05", "SLIME08"), ("SLIME09", "SLIME12")],
        "wall": [("BLODGR1", "BLODGR4"), ("SLADRIP1", "SLADRIP3"), ("BLODRIP1", "BLODRIP4"),
                 ("FIREWALA", "FIREWALL"), ("GSTFONT1", "GSTFONT3"), ("FIRELAV3", "FIRELAVA"),
                 ("FIREMAG1", "FIREMAG3"), ("FIREBLU1", "FIREBLU2"), ("ROCKRED1", "ROCKRED3"),
                 ("BFALL1", "BFALL4"), ("SFALL1", "SFALL4"), ("WFALL1", "WFALL4"),
                 ("DBRAIN1", "DBRAIN4")]}
NUKAGE_POOL = 18                                  # E1M1's nukage pit


def lump_names(path) -> list[str]:
    """The WAD's directory, read here (not through wallbsp)."""
    raw = open(path, "rb").read()
    count, at = struct.unpack_from("<ii", raw, 4)
    return [raw[at + 16 * i + 8:at + 16 * i + 16].rstrip(b"\0").decode() for i in range(count)]


def texture_names(path) -> list[str]:
    raw, names = open(path, "rb").read(), lump_names(path)
    count, at = struct.unpack_from("<ii", raw, 4)
    out = []
    for lump in ("TEXTURE1", "TEXTURE2"):
        if lump in names:
            pos, _ = struct.unpack_from("<ii", raw, at + 16 * names.index(lump))
            n = struct.unpack_from("<i", raw, pos)[0]
            for k in range(n):
                entry = pos + struct.unpack_from("<i", raw, pos + 4 + 4 * k)[0]
                out.append(raw[entry:entry + 8].rstrip(b"\0").decode())
    return out


def doom_translation(path, tic: int) -> dict:
    """name -> the name DOOM draws for it after P_UpdateSpecials at ``tic``:
    ``basepic + ((tic / 8 + i) % numpics)`` over DOOM's flat and texture numbers."""
    lumps = lump_names(path)
    first_flat = lumps.index("F_START") + 1
    numbers = {"flat": {n: i - first_flat for i, n in enumerate(lumps) if i >= first_flat},
               "wall": {n: i for i, n in enumerate(texture_names(path))}}
    shows = {}
    for kind, runs in RUNS.items():
        number = numbers[kind]
        name_of = {i: n for n, i in number.items()}
        for start, end in runs:
            if start in number and end in number:
                base, count = number[start], number[end] - number[start] + 1
                for i in range(base, base + count):
                    shows[name_of[i]] = name_of[base + (tic // 8 + i) % count]
    return shows


@pytest.fixture(scope="module")
def e1m1(freedoom_cache):
    wad = freedoom("freedoom1.wad")
    tree = freedoom_cache.tree("freedoom1.wad", "E1M1")
    floor = tree.level.sectors[tree.locate(1400, 900)].floor
    camera = Camera(1400, 900, floor + 41, 30)                       # the nukage pit
    return wad, tree, camera


def renamed_tree(tree, shows):
    """The same tree over a copy of its level with every animated flat and wall texture
    renamed to what ``shows`` says it draws (a plain level: every name shows itself)."""
    level = tree.level

    def side(s):
        return None if s is None else replace(s, **{p: shows.get(getattr(s, p), getattr(s, p))
                                                    for p in ("upper", "middle", "lower")})
    sectors = [replace(s, floor_texture=shows.get(s.floor_texture, s.floor_texture),
                       ceiling_texture=shows.get(s.ceiling_texture, s.ceiling_texture))
               for s in level.sectors]
    walls = [replace(w, front_side=side(w.front_side), back_side=side(w.back_side))
             for w in level.walls]
    renamed = copy.copy(tree)
    renamed.level = replace(level, sectors=sectors, walls=walls)
    return renamed


@pytest.mark.parametrize("leveltime", [1, 17, 200])
def test_e1m1_animates_by_doom_rule(e1m1, leveltime):
    wad, tree, camera = e1m1
    state = WorldState(tree)
    state.leveltime = leveltime
    frame = render(state, camera, 160, 100)
    expected = render(renamed_tree(tree, doom_translation(wad, leveltime - 1)), camera, 160, 100)
    assert not np.array_equal(expected.color, render(tree, camera, 160, 100).color)
    assert np.array_equal(frame.color, expected.color)
    assert np.array_equal(frame.index, expected.index)


def test_e1m1_nukage_shows_the_next_flat_eight_tics_later(e1m1):
    wad, tree, camera = e1m1
    state = WorldState(tree)
    frames = []
    for leveltime in (1, 9):
        state.leveltime = leveltime
        frames.append(render(state, camera, 160, 100))
    pool = (frames[0].kind == KIND_FLOOR) & (frames[0].index == NUKAGE_POOL)
    assert pool.sum() > 2000
    differ = (frames[0].color != frames[1].color).any(-1)
    assert differ[pool].mean() > 0.8
    # what changed is the animated surfaces only (the pool and the slime falls)
    walls = {i for i, w in enumerate(tree.level.walls) for s in (w.front_side, w.back_side)
             if s is not None and s.lower == "SFALL1"}
    falls = (frames[0].kind == KIND_WALL) & np.isin(frames[0].index, list(walls))
    assert falls.any() and not differ[~(pool | falls | (frames[0].kind == KIND_FLOOR))].any()
    # tic 0 shows NUKAGE2 for NUKAGE1 (flat 121, 121 % 3 = 1), tic 8 NUKAGE3
    state = WorldState(tree)
    for frame, name in zip(frames, ("NUKAGE2", "NUKAGE3")):
        state.set_floor_texture(NUKAGE_POOL, name)
        plain = render(state, camera, 160, 100)
        assert np.array_equal(plain.color[pool], frame.color[pool])


def test_before_the_first_tic_every_name_shows_itself(e1m1):
    _, tree, camera = e1m1
    assert WorldState(tree).leveltime == 0
    assert np.array_equal(render(WorldState(tree), camera, 96, 60).color,
                          render(tree, camera, 96, 60).color)


def test_a_level_without_animated_surfaces_draws_the_same_at_any_leveltime():
    from conftest import ROOT
    from wallbsp import compile_level, load_level
    level = load_level(ROOT / "wallbsp" / "data" / "textured.json")
    tree = compile_level(level)
    camera = Camera(level.start.x, level.start.y, 41, level.start.angle)
    state = WorldState(tree)
    first = render(state, camera, 96, 60).color.copy()
    state.leveltime = 1234
    assert np.array_equal(render(state, camera, 96, 60).color, first)


def one_flat(index: int) -> bytes:
    return flat([index] * 4096)


def test_runs_follow_the_wad_order_and_need_both_ends(tmp_path):
    lumps = [("PLAYPAL", playpal()), ("COLORMAP", colormap()), ("F_START", b""),
             ("FLOOR0", one_flat(1)), ("NUKAGE1", one_flat(2)), ("NUKAGE3", one_flat(3)),
             ("NUKAGE2", one_flat(4)), ("LAVA1", one_flat(1)), ("BLOOD3", one_flat(1)),
             ("BLOOD1", one_flat(2)), ("F_END", b"")]
    path = tmp_path / "anim.wad"
    path.write_bytes(wad_bytes(lumps))
    runs = animations(ResourceSet([path]))
    # NUKAGE1..NUKAGE3 as the WAD holds them (NUKAGE2 after the end is not in it), numbered
    # from F_START: FLOOR0 is flat 0; LAVA has no end, BLOOD's end comes first
    assert [(r.kind, r.names, r.speed, r.first) for r in runs] == [
        ("flat", ("NUKAGE1", "NUKAGE3"), 8, 1)]
