"""Texture resources: WAD pictures (composites, flats, sprites, markers, palette, colour map),
PNG folders, the search order, and damaged or hostile resources as one-line errors with a
bounded cost."""
from __future__ import annotations

import os
import struct
import tracemalloc
from pathlib import Path

import numpy as np
import pygame
import pytest

from test_wad import Map, freedoom
from wadkit import BLUE, GREEN, RED, colormap, flat, patch, playpal, pnames, texture_lump
from wallbsp.level.model import LevelError
from wallbsp.assets.resources import (ResourceError, ResourceSet, forget_shared_resources,
    shared_resources, sky_name)
from wallbsp.level.wadmap import load_wad_level
from wallbsp.assets.wad import write_wad
from wallbsp.assets.pictures import MAX_TEXELS, decode_picture

SOLID = patch(4, 4, [[(0, [RED] * 4)]] * 4)
BAR = patch(2, 3, [[(1, [BLUE, BLUE])], [(0, [BLUE])]], left=1, top=3)
SPRITE = patch(2, 2, [[(0, [GREEN, GREEN])], [(1, [RED])]], left=1, top=2)
TEXTURES = [("RED", 4, 4, [(0, 0, 0)]),
            ("HOLEY", 5, 4, [(0, 0, 0), (3, 1, 1)]),     # column 4 only partly covered
            ("SHARED", 4, 4, [(0, 0, 0)])]               # also a flat's name


def lumps(**replace) -> list[tuple[str, bytes]]:
    base = [("PLAYPAL", playpal()), ("COLORMAP", colormap()),
            ("PNAMES", pnames(["PSOLID", "PBAR"])), ("TEXTURE1", texture_lump(TEXTURES)),
            ("P_START", b""), ("PSOLID", SOLID), ("PBAR", BAR), ("P_END", b""),
            ("F_START", b""), ("FLOOR1", flat([RED] * 4096)),
            ("F1_START", b""), ("SHARED", flat([GREEN] * 4096)), ("F1_END", b""),
            ("F_END", b""),
            ("FF_START", b""), ("PWADFLAT", flat([BLUE] * 4096)), ("FF_END", b""),
            ("S_START", b""), ("TROOA1", SPRITE), ("TROOB2B8", SPRITE), ("TROOC0", SPRITE),
            ("S_END", b""),
            ("SS_START", b""), ("BAR1A0", BAR), ("SS_END", b"")]
    return [(name, replace.get(name, raw)) for name, raw in base]


@pytest.fixture(autouse=True)
def in_tmp_path(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)     # messages name files as written: "res.wad"


def wad(name="res.wad", **replace) -> Path:
    write_wad(name, lumps(**replace))
    return Path(name)


# ---------------------------------------------------------------------------------------------
# WAD pictures

def test_composite_is_patches_in_order_transparent_where_uncovered():
    tex = ResourceSet([wad()]).wall("HOLEY")
    assert (tex.width, tex.height) == (5, 4) and tex.paletted
    assert (tex.pixels[:3] == RED).all() and tex.mask[:4].all()
    # the bar at x 3..4, y 1..3: its column 0 has rows 1, 2 (+1) -> 2, 3; column 1 row 0 -> 1
    assert tex.pixels[3].tolist() == [RED, RED, BLUE, BLUE]
    assert tex.mask[4].tolist() == [False, True, False, False] and tex.pixels[4, 1] == BLUE


def test_wall_flat_and_sprite_namespaces_are_separate():
    res = ResourceSet([wad()])
    assert (res.wall("SHARED").pixels == RED).all()
    assert (res.flat("SHARED").pixels == GREEN).all()     # inside nested F1_ markers
    assert res.sprite("SHARED") is None and res.flat("TROOA1") is None
    assert res.wall("FLOOR1") is None


def test_flats_come_from_f_and_ff_markers_and_are_64_square():
    res = ResourceSet([wad()])
    for name, colour in (("FLOOR1", RED), ("PWADFLAT", BLUE)):
        picture = res.flat(name)
        assert picture.pixels.shape == (64, 64) and picture.mask.all()
        assert (picture.pixels == colour).all()


def test_flat_is_indexed_by_column_then_row():
    rows = [x + 2 * y for y in range(64) for x in range(64)]
    picture = ResourceSet([wad(FLOOR1=bytes(v % 256 for v in rows))]).flat("FLOOR1")
    assert picture.pixels[5, 7] == 5 + 2 * 7       # pixels[x, y]: lump byte y * 64 + x


def test_sprites_keep_offsets_and_come_from_s_and_ss_markers():
    res = ResourceSet([wad()])
    troo = res.sprite("trooa1")                     # names are case-insensitive
    assert (troo.left, troo.top) == (1, 2)
    assert troo.pixels.tolist() == [[GREEN, GREEN], [0, RED]]
    assert troo.mask.tolist() == [[True, True], [False, True]]
    assert res.sprite("BAR1A0").height == 3


def test_sprite_frames_by_rotation_with_mirrors_and_all_rotations():
    res = ResourceSet([wad()])
    picture, mirrored = res.sprite_frame("TROO", "B", 8)
    assert picture is res.sprite("TROOB2B8") and mirrored
    assert res.sprite_frame("TROO", "B", 2)[1] is False
    assert res.sprite_frame("TROO", "C", 5)[0] is res.sprite("TROOC0")
    assert res.sprite_frame("TROO", "A", 3) is None


def test_palette_and_colormap():
    res = ResourceSet([wad()])
    assert res.palette.shape == (256, 3) and res.palette[RED].tolist() == [200, 0, 0]
    assert res.colormap.shape == (34, 256) and res.colormap[3, 10] == 13


def test_pictures_are_decoded_once_and_only_when_asked():
    res = ResourceSet([wad()])
    textures = res.sources[0].textures
    assert textures.decoded_bytes == 0
    first = res.wall("RED")
    assert res.wall("RED") is first and textures.decoded_bytes > 0


def test_sky_name_follows_doom():
    assert [sky_name(n) for n in ("E1M1", "e3m9 (doom.wad)", "E4M2", "MAP01", "MAP11",
                                  "MAP12", "MAP20", "MAP21", "MAP32", "Two rooms")] == \
        ["SKY1", "SKY3", "SKY4", "SKY1", "SKY1", "SKY2", "SKY2", "SKY3", "SKY3", "SKY1"]


# ---------------------------------------------------------------------------------------------
# PNG folders and the search order

def save_png(path: Path, rgba: list[list[tuple[int, int, int, int]]]) -> None:
    """rgba[y][x]"""
    surface = pygame.Surface((len(rgba[0]), len(rgba)), pygame.SRCALPHA)
    for y, row in enumerate(rgba):
        for x, colour in enumerate(row):
            surface.set_at((x, y), colour)
    path.parent.mkdir(parents=True, exist_ok=True)
    pygame.image.save(surface, str(path))


OPAQUE, CLEAR = (10, 20, 30, 255), (0, 0, 0, 0)


def png_folder() -> Path:
    folder = Path("tex")
    save_png(folder / "brick.png", [[OPAQUE, CLEAR, OPAQUE], [(1, 2, 3, 200)] * 3])
    save_png(folder / "RED.png", [[(255, 0, 0, 255)]])
    save_png(folder / "flats" / "brick.png", [[(9, 9, 9, 255)] * 64] * 64)
    save_png(folder / "sprites" / "ball.png", [[OPAQUE] * 4] * 6)
    return folder


def test_png_folder_gives_rgb_and_alpha_mask_per_namespace():
    res = ResourceSet([png_folder()])
    wall = res.wall("BRICK")
    assert not wall.paletted and wall.pixels.shape == (3, 2, 3)
    assert wall.pixels[0, 0].tolist() == [10, 20, 30] and wall.pixels[1, 1].tolist() == [1, 2, 3]
    assert wall.mask.tolist() == [[True, True], [False, True], [True, True]]
    assert res.flat("brick").pixels.shape == (64, 64, 3)
    assert (res.flat("brick").pixels == 9).all()
    ball = res.sprite("BALL")
    assert (ball.left, ball.top) == (2, 6)
    assert res.sprite("BRICK") is None and res.palette is None


def test_sources_are_searched_in_order():
    folder, wad_path = png_folder(), wad()
    assert not ResourceSet([folder, wad_path]).wall("RED").paletted     # the PNG comes first
    assert ResourceSet([wad_path, folder]).wall("RED").paletted
    both = ResourceSet([folder, wad_path])
    assert both.wall("HOLEY").paletted and not both.wall("BRICK").paletted
    assert both.palette is not None


def test_shared_resources_is_one_set_until_a_source_changes():
    folder, wad_path = png_folder(), wad()
    first = shared_resources([folder, wad_path])
    assert shared_resources([folder.resolve(), wad_path]) is first     # however it is named
    assert shared_resources([wad_path, folder]) is not first           # another order
    assert first.wall("BRICK") is not None and first.wall("NEW") is None
    stat = folder.stat()
    save_png(folder / "NEW.png", [[OPAQUE]])
    os.utime(folder, ns=(stat.st_atime_ns, stat.st_mtime_ns + 10 ** 9))   # a later mtime
    changed = shared_resources([folder, wad_path])
    assert changed is not first and changed.wall("NEW") is not None
    wad(FLOOR1=flat([GREEN] * 4096))                                   # the WAD rewritten
    rewritten = shared_resources([folder, wad_path])
    assert rewritten is not changed
    assert rewritten.flat("FLOOR1").pixels[0, 0] != changed.flat("FLOOR1").pixels[0, 0]
    forget_shared_resources()
    assert shared_resources([folder, wad_path]) is not rewritten


def test_from_level_reads_the_imported_wad_and_names_missing_textures():
    write_wad("map.wad", Map().lumps() + lumps())
    level = load_wad_level("map.wad", "MAP01")
    res = ResourceSet.from_level(level)
    assert res.wall("RED") is not None and res.flat("FLOOR1") is not None
    missing = res.missing(level)
    assert any("walls[2].front_side.upper: texture MIX not found" in n for n in missing)
    assert any("sectors[0].ceiling_texture: flat CEIL1 not found" in n for n in missing)
    assert not any("F_SKY1" in n for n in missing)


def test_png_flat_of_the_wrong_size_is_an_error():
    save_png(Path("tex/flats/odd.png"), [[OPAQUE] * 3])
    with pytest.raises(ResourceError, match=r"^tex/flats/odd\.png: a flat is 64 × 64"):
        ResourceSet(["tex"]).flat("ODD")


def test_png_header_size_is_checked_before_decoding():
    big = Path("tex/huge.png")
    big.parent.mkdir()
    # a valid PNG header claiming 100000 × 100000 pixels, and nothing else
    big.write_bytes(b"\x89PNG\r\n\x1a\n" + struct.pack(">I4sII", 13, b"IHDR", 100_000, 100_000))
    with pytest.raises(ResourceError,
                       match=r"^tex/huge\.png: a 100000 × 100000 picture is refused"):
        ResourceSet(["tex"]).wall("HUGE")


# ---------------------------------------------------------------------------------------------
# Damaged resources: one line naming the file and lump

def texture_at_offset(offset: int) -> bytes:
    raw = bytearray(texture_lump(TEXTURES))
    struct.pack_into("<i", raw, 8, offset)      # texture 1's offset
    return bytes(raw)


DAMAGED = {
    "truncated patch": ({"PSOLID": SOLID[:20]}, "RED", r"res\.wad: PSOLID: truncated"),
    "post cut short": ({"PSOLID": SOLID[:-3]}, "RED", r"res\.wad: PSOLID: truncated: a column"),
    "bad PNAMES index": ({"TEXTURE1": texture_lump([("RED", 4, 4, [(0, 0, 9)])])}, "RED",
                         r"res\.wad: TEXTURE1: RED: patch 0 uses PNAMES entry 9 \(2 names\)"),
    "texture past the lump": ({"TEXTURE1": texture_at_offset(9999)}, "RED",
                              r"res\.wad: TEXTURE1: texture 1 at offset 9999 lies past the end "
                              r"of the lump"),
    "patches past the lump": ({"TEXTURE1": texture_lump(TEXTURES)[:-4]}, "RED",
                              r"res\.wad: TEXTURE1: SHARED: 1 patches run past the end"),
    "PNAMES too short": ({"PNAMES": struct.pack("<i", 50) + b"PSOLID\0\0"}, "RED",
                         r"res\.wad: PNAMES: 50 names do not fit in 12 bytes"),
    "missing patch lump": ({"PNAMES": pnames(["NOPE", "PBAR"])}, "RED",
                           r"res\.wad: TEXTURE1: RED: patch 0 \(NOPE\) is not in the WAD"),
    "absurd size": ({"TEXTURE1": texture_lump([("RED", 30000, 30000, [(0, 0, 0)])])}, "RED",
                    r"res\.wad: TEXTURE1: RED: a 30000 × 30000 picture is refused"),
    "column past the lump": ({"PSOLID": SOLID[:8] + struct.pack("<I", 5000) + SOLID[12:]},
                             "RED", r"res\.wad: PSOLID: column 0 starts at offset 5000"),
}


@pytest.mark.parametrize("case", DAMAGED)
def test_damaged_wad_resource_is_one_line_naming_the_lump(case):
    replace, name, message = DAMAGED[case]
    res = ResourceSet([wad(**replace)])
    with pytest.raises(ResourceError, match="^" + message) as info:
        res.wall(name)
    assert "\n" not in str(info.value) and isinstance(info.value, LevelError)


def test_damaged_flat_and_unreadable_png_are_one_line():
    with pytest.raises(ResourceError, match=r"^res\.wad: FLOOR1: truncated \(10 bytes"):
        ResourceSet([wad(FLOOR1=b"x" * 10)]).flat("FLOOR1")
    Path("tex").mkdir()
    Path("tex/bad.png").write_bytes(b"not a png at all, just text")
    with pytest.raises(ResourceError, match=r"^tex/bad\.png: not a PNG image$"):
        ResourceSet(["tex"]).wall("BAD")
    Path("tex/cut.png").write_bytes(Path(png_folder() / "brick.png").read_bytes()[:40])
    with pytest.raises(ResourceError, match=r"^tex/cut\.png: not a readable PNG image"):
        ResourceSet(["tex"]).wall("CUT")


def test_missing_resource_path_is_an_error():
    with pytest.raises(ResourceError, match=r"^nothere\.wad: cannot read"):
        ResourceSet(["nothere.wad"])
    Path("junk.wad").write_bytes(b"JUNKJUNKJUNKJUNK")
    with pytest.raises(ResourceError, match=r"^junk\.wad: header: bad magic"):
        ResourceSet(["junk.wad"])


@pytest.mark.parametrize("case", ["truncated patch", "bad PNAMES index",
                                  "texture past the lump"])
def test_damaged_texture_through_the_command_line_is_exit_2_and_one_line(capsys, case):
    from wallbsp.app.cli import main
    replace, _, message = DAMAGED[case]
    write_wad("map.wad", Map().lumps() + lumps(**replace))
    assert main(["import-wad", "--strict", "map.wad", "MAP01", "-o", "out.json"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "map.wad: " in err[0] and not Path("out.json").exists()
    # without --strict the map imports, the damaged texture grey, the damage a warning
    assert main(["import-wad", "map.wad", "MAP01", "-o", "out.json"]) == 0
    assert any(line.startswith("warning: map.wad: ") and "grey used" in line
               for line in capsys.readouterr().err.splitlines())


# ---------------------------------------------------------------------------------------------
# Picture bombs (issue 14 §6): the cost is the picture's own size

def peak_bytes(call) -> int:
    call()      # once untraced: the first decode may load numba and the compiled decoder
    tracemalloc.start()
    try:
        call()
        return tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()


def test_patch_whose_columns_share_one_long_column_stays_small():
    # 1,000 columns, all pointing at one column of 100 posts of 255 texels each (~26 KB)
    width, height = 1000, 200
    column = b"".join(bytes([min(k, 254), 255, 0]) + bytes([RED]) * 255 + b"\0"
                      for k in range(100)) + b"\xff"
    raw = struct.pack("<hhhh", width, height, 0, 0) + \
        struct.pack(f"<{width}I", *[8 + 4 * width] * width) + column
    picture = None

    def decode():
        nonlocal picture
        picture = decode_picture(raw, "BOMB")
    assert peak_bytes(decode) < 8 * width * height      # a few bytes a texel, not 1 GB
    assert picture.mask.all() and (picture.pixels == RED).all()


def test_columns_starting_along_a_chain_of_empty_posts_stay_small():
    # 1,000 columns, each starting one post further along a chain of 7,000 empty posts
    width, height, chain = 1000, 128, 7000
    first = 8 + 4 * width
    raw = struct.pack("<hhhh", width, height, 0, 0) + \
        struct.pack(f"<{width}I", *[first + 4 * k for k in range(width)]) + \
        bytes([0, 0, 0, 0]) * chain + b"\xff"
    assert len(raw) < 40_000
    picture = None

    def decode():
        nonlocal picture
        picture = decode_picture(raw, "CHAIN")
    assert peak_bytes(decode) < 64 * width * height
    assert not picture.mask.any()


def test_texture_placing_a_patch_many_times_stays_small():
    big = patch(256, 128, [[(0, [RED] * 128)]] * 256)
    placements = [(x % 3, x % 2, 0) for x in range(400)]     # 6 places, each many times
    res = ResourceSet([wad(PSOLID=big, TEXTURE1=texture_lump([("RED", 64, 64, placements)]))])
    picture = None

    def composite():
        nonlocal picture
        picture = res.wall("RED")
    assert peak_bytes(composite) < 2_000_000      # the patch (64 KB) and the canvas, not 560 MB
    assert picture.mask.all()


def test_texture_painting_its_patches_over_and_over_is_refused():
    big = patch(256, 128, [[(0, [RED] * 128)]] * 256)
    placements = [(x % 20, x // 20, 0) for x in range(400)]      # 400 distinct placements
    res = ResourceSet([wad(PSOLID=big, TEXTURE1=texture_lump([("RED", 64, 64, placements)]))])
    with pytest.raises(ResourceError, match=r"^res\.wad: TEXTURE1: RED: its patches cover it "
                                            r"more than 16 times over; refused$"):
        res.wall("RED")


def test_refused_sizes_cover_what_one_lump_could_ask_for():
    assert MAX_TEXELS <= 1 << 22      # a refused picture never costs more than a few MB


# ---------------------------------------------------------------------------------------------
# Freedoom: a real composite against its patches, decoded here independently

def reference_patch(raw: bytes):
    """A plain post walker: {(x, y): index} of a patch's opaque texels (no tall patches)."""
    width = struct.unpack_from("<h", raw)[0]
    texels = {}
    for x in range(width):
        pos = struct.unpack_from("<I", raw, 8 + 4 * x)[0]
        while raw[pos] != 0xFF:
            top, length = raw[pos], raw[pos + 1]
            for k in range(length):
                texels[(x, top + k)] = raw[pos + 3 + k]
            pos += length + 4
    return texels


def test_freedoom_composite_matches_its_patches():
    from wallbsp.assets.wad import open_wad
    path = freedoom("freedoom2.wad")
    res = ResourceSet([path])
    textures = res.sources[0].textures
    name = next(n for n in textures.wall_names() if len(textures.definition(n).patches) >= 3)
    tdef, names = textures.definition(name), textures.patch_names()
    expected = {}
    with open_wad(path) as w:
        for ox, oy, p in tdef.patches.tolist():
            for (x, y), value in reference_patch(w.lump(names[p])).items():
                if 0 <= x + ox < tdef.width and 0 <= y + oy < tdef.height:
                    expected[(x + ox, y + oy)] = value
    picture = res.wall(name)
    assert set(zip(*np.nonzero(picture.mask))) == set(expected)
    assert all(picture.pixels[xy] == v for xy, v in expected.items())
