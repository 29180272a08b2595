"""DOOM-format maps imported as levels: the mapping, the colours, the errors, and Freedoom.

The small WADs are written here (lumps built by hand, packed by ``wallbsp.assets.wad.wad_bytes``), so
every path of the importer is exercised with bytes whose meaning the test states."""
from __future__ import annotations

import itertools
import os
import struct
from dataclasses import dataclass, field
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from wallbsp.level.model import Level, LevelError
from wadkit import BLUE, DARK, GREEN, RED, flat, patch, playpal, pnames, texture_lump
from wallbsp.assets.colours import GREY, SKY_BLUE
from wallbsp.level.wadmap import import_wad, load_wad_level, parse_wad_spec
from wallbsp.assets.wad import wad_bytes

NONE = 0xFFFF

SOLID = patch(4, 4, [[(0, [RED] * 4)]] * 4)                 # 4 × 4 red
BLUE_BAR = patch(2, 4, [[(0, [BLUE] * 4)]] * 2)             # 2 × 4 blue
HOLES = patch(2, 4, [[(0, [GREEN]), (3, [GREEN])], []])     # two green pixels, the rest clear
PATCHES = ["PSOLID", "PBLUE", "PHOLES"]
TEXTURES = [
    ("RED", 4, 4, [(0, 0, 0)]),
    # blue over the right half: 8 red + 8 blue pixels. Weighting the patches by their own
    # pixels would give (16 red + 8 blue) / 24 instead.
    ("MIX", 4, 4, [(0, 0, 0), (2, 0, 1)]),
    # only one column of the bar is inside the texture
    ("CLIP", 4, 4, [(3, 0, 1)]),
    # two green pixels painted over red: 14 red + 2 green
    ("HOLE", 4, 4, [(0, 0, 0), (0, 0, 2)]),
    # clear pixels do not count: the average of two green pixels is green
    ("SPARSE", 4, 4, [(0, 0, 2)]),
]
COLOUR = {"RED": "#c80000", "MIX": "#640032", "CLIP": "#000064", "HOLE": "#af2000",
          "SPARSE": "#00ff00", "FLOOR1": "#640032", "CEIL1": "#0a141e"}


def resources() -> list[tuple[str, bytes]]:
    return [("PLAYPAL", playpal()),
            ("PNAMES", pnames(PATCHES)), ("TEXTURE1", texture_lump(TEXTURES)),
            ("P_START", b""), ("PSOLID", SOLID), ("PBLUE", BLUE_BAR), ("PHOLES", HOLES),
            ("P_END", b""),
            ("F_START", b""), ("FLOOR1", flat([RED] * 2048 + [BLUE] * 2048)),
            ("CEIL1", flat([DARK] * 4096)), ("F_SKY1", flat([BLUE] * 4096)), ("F_END", b"")]


# ---------------------------------------------------------------------------------------------
# A two-room map. Room 0 is x 0..128, room 1 is x 128..256; both are y 0..128. Linedefs run
# clockwise, so that the room is on their right (the front).

@dataclass
class Map:
    vertices: list = field(default_factory=lambda: [
        (0, 0), (128, 0), (128, 128), (0, 128), (256, 0), (256, 128),
        (128, 0),              # 6: a duplicate of vertex 1
        (64, 64), (64, 64)])   # 7, 8: the ends of a zero-length linedef
    # (floor, ceiling, floor flat, ceiling flat, light)
    sectors: list = field(default_factory=lambda: [
        [0, 128, "FLOOR1", "CEIL1", 160], [16, 96, "FLOOR1", "F_SKY1", 300]])
    # (upper, lower, middle, sector)
    sidedefs: list = field(default_factory=lambda: [
        ["-", "-", "RED", 0], ["-", "-", "RED", 0], ["-", "-", "RED", 0],
        ["MIX", "HOLE", "-", 0],    # 3: the portal's front, in room 0
        ["-", "-", "-", 1],         # 4: the portal's back, in room 1
        ["-", "-", "CLIP", 1], ["-", "-", "SPARSE", 1], ["-", "-", "RED", 1]])
    # (v1, v2, right, left)
    linedefs: list = field(default_factory=lambda: [
        [0, 3, 0, NONE],        # wall 0: west wall of room 0
        [3, 2, 1, NONE],        # wall 1: north wall of room 0
        [2, 1, 3, 4],           # wall 2: the portal, room 0 in front
        [6, 0, 2, NONE],        # wall 3: south wall of room 0, from the duplicate vertex
        [2, 5, 5, NONE],        # wall 4: north wall of room 1
        [4, 5, NONE, 6],        # wall 5: east wall of room 1, only a left side: turned round
        [4, 1, 7, NONE],        # wall 6: south wall of room 1
        [7, 8, 7, NONE],        # zero length: dropped
        [0, 2, NONE, NONE]])    # no sidedefs: dropped
    # (x, y, angle, type)
    things: list = field(default_factory=lambda: [
        (200, 64, 0, 3004), (64, 64, 0, 1), (32, 96, 180, 1)])
    name: str = "MAP01"
    # linedef -> (flags, special, tag); sector -> (special, tag); sidedef -> (x, y) offsets
    line_fields: dict = field(default_factory=dict)
    sector_fields: dict = field(default_factory=dict)
    side_offsets: dict = field(default_factory=dict)

    def lumps(self) -> list[tuple[str, bytes]]:
        return [
            (self.name, b""),
            ("THINGS", b"".join(struct.pack("<hhhhh", x, y, a, t, 7)
                                for x, y, a, t in self.things)),
            ("LINEDEFS", b"".join(struct.pack("<HHHHHHH", v1, v2,
                                                  *self.line_fields.get(i, (1, 0, 0)), r, lf)
                                  for i, (v1, v2, r, lf) in enumerate(self.linedefs))),
            ("SIDEDEFS", b"".join(struct.pack("<hh8s8s8sH", *self.side_offsets.get(i, (0, 0)),
                                              u.encode(), lo.encode(), m.encode(), s)
                                  for i, (u, lo, m, s) in enumerate(self.sidedefs))),
            ("VERTEXES", b"".join(struct.pack("<hh", x, y) for x, y in self.vertices)),
            ("SEGS", b""), ("SSECTORS", b""), ("NODES", b""),
            ("SECTORS", b"".join(struct.pack("<hh8s8shHH", f, c, ff.encode(), cf.encode(), li,
                                             *self.sector_fields.get(i, (0, 0)))
                                 for i, (f, c, ff, cf, li) in enumerate(self.sectors))),
            ("REJECT", b""), ("BLOCKMAP", b"")]


@pytest.fixture(autouse=True)
def in_tmp_path(tmp_path, monkeypatch):
    # WADs are written to the working directory, so that messages name them "test.wad"
    monkeypatch.chdir(tmp_path)


def write_wad(*maps: Map, extra: list | None = None, name="test.wad") -> Path:
    path = Path(name)
    lumps = [lump for m in maps for lump in m.lumps()] + resources() + (extra or [])
    path.write_bytes(wad_bytes(lumps))
    return path


@pytest.fixture
def two_rooms() -> dict:
    return import_wad(write_wad(Map()), "map01")


def raises_one_line(match: str):
    class Check:
        def __enter__(self):
            self.ctx = pytest.raises(LevelError, match=match)
            self.info = self.ctx.__enter__()
            return self.info

        def __exit__(self, *exc):
            result = self.ctx.__exit__(*exc)
            assert "\n" not in str(self.info.value)
            return result
    return Check()


# ---------------------------------------------------------------------------------------------
# Mapping linedefs, sidedefs, sectors and things

def test_level_dict_has_the_level_format(two_rooms):
    assert two_rooms["format"] == "wallbsp-level" and two_rooms["version"] == 2
    assert two_rooms["name"] == "MAP01 (test.wad)"
    assert two_rooms["resources"] == [os.path.abspath("test.wad")]   # loads from anywhere


def test_right_sidedef_is_front_and_left_is_back(two_rooms):
    portal = two_rooms["walls"][2]
    assert (portal["front"], portal["back"]) == (0, 1)
    assert all(w["back"] is None for i, w in enumerate(two_rooms["walls"]) if i != 2)


def test_left_only_linedef_is_turned_round(two_rooms):
    verts = two_rooms["vertices"]
    east = two_rooms["walls"][5]
    assert (verts[east["v1"]], verts[east["v2"]]) == ([256, 128], [256, 0])
    assert (east["front"], east["back"]) == (1, None)


def test_linedefs_without_sidedefs_or_length_are_dropped_with_a_warning():
    notes = []
    level = import_wad(write_wad(Map()), "MAP01", warnings=notes)
    assert len(level["walls"]) == 7          # nine linedefs, two dropped; order kept
    assert "test.wad: MAP01: LINEDEFS[7]: zero length (both ends at (64, 64)); dropped" in notes
    assert "test.wad: MAP01: LINEDEFS[8]: no sidedefs; dropped" in notes


def test_walls_keep_linedef_order(two_rooms):
    verts = two_rooms["vertices"]
    ends = [(tuple(verts[w["v1"]]), tuple(verts[w["v2"]])) for w in two_rooms["walls"]]
    assert ends == [((0, 0), (0, 128)), ((0, 128), (128, 128)), ((128, 128), (128, 0)),
                    ((128, 0), (0, 0)), ((128, 128), (256, 128)), ((256, 128), (256, 0)),
                    ((256, 0), (128, 0))]


def test_vertices_are_deduplicated_in_order_of_first_use(two_rooms):
    # the duplicate (128, 0) is merged; the zero-length line's vertices are gone
    assert two_rooms["vertices"] == [[0, 0], [0, 128], [128, 128], [128, 0], [256, 128], [256, 0]]


def test_sectors_keep_floor_ceiling_and_clamped_light():
    notes = []
    level = import_wad(write_wad(Map()), "MAP01", warnings=notes)
    assert [(s["floor"], s["ceiling"], s["light"]) for s in level["sectors"]] == \
        [(0, 128, 160), (16, 96, 255)]
    assert "test.wad: MAP01: SECTORS[1]: light 300 clamped to 0..255" in notes


def test_start_is_the_last_player_one_start(two_rooms):
    # DOOM spawns the player at the last type-1 thing; earlier ones become voodoo dolls
    assert two_rooms["start"] == {"x": 32, "y": 96, "angle": 180}


def test_start_without_player_start_is_the_bbox_centre():
    level = import_wad(write_wad(Map(things=[(10, 10, 0, 3004)])), "MAP01")
    assert level["start"] == {"x": 128, "y": 64, "angle": 90}


def test_load_wad_level_returns_a_validated_level_with_the_import_warnings():
    level = load_wad_level(write_wad(Map()), "MAP01")
    assert isinstance(level, Level)
    assert len(level.walls) == 7 and len(level.sectors) == 2
    assert level.source.endswith("test.wad:MAP01")
    assert any("LINEDEFS[8]: no sidedefs" in w for w in level.warnings)


def test_strict_load_turns_the_first_warning_into_an_error():
    with raises_one_line(r"^test\.wad: MAP01: LINEDEFS\[8\]: no sidedefs; dropped$"):
        load_wad_level(write_wad(Map()), "MAP01", strict=True)


def test_map_is_found_among_several():
    second = Map(name="MAP02", things=[(100, 50, 90, 1)])
    level = import_wad(write_wad(Map(), second), "MAP02")
    assert level["start"] == {"x": 100, "y": 50, "angle": 90}


# ---------------------------------------------------------------------------------------------
# Version 2: textures, flags, specials, things (DOOM's numbering kept)

def test_sides_keep_their_textures_and_offsets():
    m = Map(side_offsets={3: (5, -7)})
    portal = import_wad(write_wad(m), "MAP01")["walls"][2]
    assert portal["front_side"] == {"upper": "MIX", "middle": None, "lower": "HOLE",
                                    "x_offset": 5, "y_offset": -7}
    assert portal["back_side"] == {"upper": None, "middle": None, "lower": None,
                                   "x_offset": 0, "y_offset": 0}


def test_turned_round_linedef_keeps_its_one_side_as_the_front(two_rooms):
    east = two_rooms["walls"][5]        # only a left sidedef (6): it is the front side now
    assert east["front_side"]["middle"] == "SPARSE" and "back_side" not in east


def test_linedef_flags_become_pegging_and_blocking():
    # ML_BLOCKING 1, ML_DONTPEGTOP 8, ML_DONTPEGBOTTOM 16; blocking matters on two-sided walls
    m = Map(line_fields={0: (1 | 8, 0, 0), 2: (1 | 16, 0, 0), 1: (0, 0, 0)})
    walls = import_wad(write_wad(m), "MAP01")["walls"]
    assert (walls[0]["upper_unpegged"], walls[0]["lower_unpegged"], walls[0]["blocks"]) == \
        (True, False, False)
    assert (walls[2]["upper_unpegged"], walls[2]["lower_unpegged"], walls[2]["blocks"]) == \
        (False, True, True)
    assert walls[1]["blocks"] is False


def test_line_and_sector_specials_and_tags_are_kept():
    m = Map(line_fields={2: (4, 1, 0), 6: (1, 62, 9)}, sector_fields={1: (9, 7)})
    level = import_wad(write_wad(m), "MAP01")
    assert [(w["special"], w["tag"]) for w in level["walls"]][2:7:4] == [(1, 0), (62, 9)]
    assert [(s["special"], s["tag"]) for s in level["sectors"]] == [(0, 0), (9, 7)]


def test_sector_flats_are_named_and_sky_is_kept(two_rooms):
    s0, s1 = two_rooms["sectors"]
    assert (s0["floor_texture"], s0["ceiling_texture"]) == ("FLOOR1", "CEIL1")
    assert (s1["floor_texture"], s1["ceiling_texture"]) == ("FLOOR1", "F_SKY1")


def test_all_things_are_kept_in_order(two_rooms):
    assert two_rooms["things"] == [
        {"x": 200, "y": 64, "angle": 0, "type": 3004, "flags": 7},
        {"x": 64, "y": 64, "angle": 0, "type": 1, "flags": 7},
        {"x": 32, "y": 96, "angle": 180, "type": 1, "flags": 7}]


def test_version_2_import_loads_as_a_level_with_textures():
    level = load_wad_level(write_wad(Map(line_fields={2: (1 | 8, 11, 3)})), "MAP01")
    portal = level.walls[2]
    assert portal.front_side.upper == "MIX" and portal.back_side is not None
    assert portal.upper_unpegged and portal.blocks and (portal.special, portal.tag) == (11, 3)
    assert level.sectors[1].ceiling_texture == "F_SKY1" and len(level.things) == 3
    assert [str(p) for p in level.resource_paths()] == [os.path.abspath("test.wad")]


# ---------------------------------------------------------------------------------------------
# Colours

def test_one_sided_wall_colour_is_its_middle_texture_average(two_rooms):
    walls = two_rooms["walls"]
    assert walls[0]["color"] == COLOUR["RED"]
    assert "upper_color" not in walls[0] and "lower_color" not in walls[0]


def test_texture_colour_is_the_composite_average_with_later_patches_on_top(two_rooms):
    portal = two_rooms["walls"][2]
    assert portal["upper_color"] == COLOUR["MIX"]      # 8 red, 8 blue: not patch-weighted
    assert portal["lower_color"] == COLOUR["HOLE"]     # 14 red, 2 green


def test_patch_outside_the_texture_is_clipped(two_rooms):
    assert two_rooms["walls"][4]["color"] == COLOUR["CLIP"]


def test_clear_pixels_do_not_count(two_rooms):
    assert two_rooms["walls"][5]["color"] == COLOUR["SPARSE"]


def test_two_sided_wall_without_middle_takes_its_upper_colour(two_rooms):
    assert two_rooms["walls"][2]["color"] == COLOUR["MIX"]


def test_upper_texture_comes_from_the_side_with_the_higher_ceiling():
    m = Map()
    m.sidedefs[3][0], m.sidedefs[4][0] = "RED", "MIX"   # front ceiling 128 > back ceiling 96
    m.sectors[1][1] = 200                                 # now the back's ceiling is higher
    portal = import_wad(write_wad(m), "MAP01")["walls"][2]
    assert portal["upper_color"] == COLOUR["MIX"]


def test_missing_upper_texture_falls_back_to_the_other_side():
    m = Map()
    m.sidedefs[3][0], m.sidedefs[4][0] = "-", "SPARSE"
    portal = import_wad(write_wad(m), "MAP01")["walls"][2]
    assert portal["upper_color"] == COLOUR["SPARSE"]


def test_two_sided_wall_without_textures_is_grey():
    m = Map()
    m.sidedefs[3][:3] = ["-", "-", "-"]
    portal = import_wad(write_wad(m), "MAP01")["walls"][2]
    assert portal["color"] == GREY
    assert "upper_color" not in portal and "lower_color" not in portal


def test_flat_colour_is_its_average_and_sky_is_blue(two_rooms):
    s0, s1 = two_rooms["sectors"]
    assert (s0["floor_color"], s0["ceiling_color"]) == (COLOUR["FLOOR1"], COLOUR["CEIL1"])
    assert (s1["floor_color"], s1["ceiling_color"]) == (COLOUR["FLOOR1"], SKY_BLUE)
    assert s1.get("sky") is True and "sky" not in s0      # F_SKY1: open sky, full bright


def test_upper_between_two_skies_is_sky_blue():
    m = Map()
    m.sectors[0][3] = "F_SKY1"
    portal = import_wad(write_wad(m), "MAP01")["walls"][2]
    assert portal["upper_color"] == SKY_BLUE
    assert portal["color"] == COLOUR["MIX"]     # the texture is still the wall's colour


def test_missing_texture_and_flat_are_grey_with_a_warning():
    m = Map()
    m.sidedefs[0][2] = "NOSUCH"
    m.sectors[0][2] = "NOFLAT"
    notes = []
    level = import_wad(write_wad(m), "MAP01", warnings=notes)
    assert level["walls"][0]["color"] == GREY and level["sectors"][0]["floor_color"] == GREY
    assert "test.wad: MAP01: SIDEDEFS[0]: middle texture NOSUCH not found; grey used" in notes
    assert "test.wad: MAP01: SECTORS[0]: floor flat NOFLAT not found; grey used" in notes


def test_texture_names_are_case_insensitive():
    m = Map()
    m.sidedefs[0][2] = "red"
    assert import_wad(write_wad(m), "MAP01")["walls"][0]["color"] == COLOUR["RED"]


def test_tall_patch_posts_are_relative_to_the_previous_one():
    # DeePsea tall patches: a top delta not below the previous post's is relative to it, so
    # the pixels are at rows 200 and 200 + 100 = 300: both inside a 320-row texture
    tall = patch(1, 320, [[(200, [GREEN]), (100, [BLUE])]])
    extra_textures = TEXTURES + [("TALL", 1, 320, [(0, 0, 3)]), ("SHORT", 1, 250, [(0, 0, 3)])]
    lumps = [lump for lump in resources() if lump[0] != "TEXTURE1"]
    lumps[1] = ("PNAMES", pnames(PATCHES + ["PTALL"]))
    lumps += [("TEXTURE1", texture_lump(extra_textures)), ("PTALL", tall)]
    m = Map()
    m.sidedefs[0][2], m.sidedefs[1][2] = "TALL", "SHORT"
    path = Path("tall.wad")
    path.write_bytes(wad_bytes(m.lumps() + lumps))
    walls = import_wad(path, "MAP01")["walls"]
    assert walls[0]["color"] == "#008032"    # (green + blue) / 2, 127.5 rounded to even
    assert walls[1]["color"] == "#00ff00"    # the blue pixel at row 300 is clipped


def test_wad_without_playpal_uses_default_colours_with_a_warning():
    path = Path("bare.wad")
    path.write_bytes(wad_bytes(Map().lumps()))
    notes = []
    level = import_wad(path, "MAP01", warnings=notes)
    assert {w["color"] for w in level["walls"]} == {GREY}
    assert any("PLAYPAL: missing" in n for n in notes)


def test_colours_are_recomputed_when_the_wad_changes():
    path = write_wad(Map())
    assert import_wad(path, "MAP01")["walls"][0]["color"] == COLOUR["RED"]
    m = Map()
    m.sidedefs[0][2] = "SPARSE"
    write_wad(m, extra=[("PAD", b"x")])     # a different size, whatever the mtime
    assert import_wad(path, "MAP01")["walls"][0]["color"] == COLOUR["SPARSE"]


# ---------------------------------------------------------------------------------------------
# Errors: one line, with the place

def test_missing_file_is_an_error():
    with raises_one_line(r"nothere\.wad: cannot read"):
        import_wad(Path("nothere.wad"), "MAP01")


def test_truncated_header_is_an_error():
    path = Path("short.wad")
    path.write_bytes(b"PWAD\x01\x00")
    with raises_one_line(r"short\.wad: header: truncated"):
        import_wad(path, "MAP01")


def test_bad_magic_is_an_error():
    path = Path("bad.wad")
    path.write_bytes(b"JUNK" + wad_bytes(Map().lumps())[4:])
    with raises_one_line(r"bad\.wad: header: bad magic b'JUNK'"):
        import_wad(path, "MAP01")


def test_truncated_directory_is_an_error():
    path = write_wad(Map())
    path.write_bytes(path.read_bytes()[:-10])
    with raises_one_line(r"test\.wad: directory: \d+ entries at offset \d+ run past the end"):
        import_wad(path, "MAP01")


def test_lump_outside_the_file_is_an_error():
    path = write_wad(Map())
    raw = bytearray(path.read_bytes())
    _, _, offset = struct.unpack_from("<4sii", raw)
    struct.pack_into("<i", raw, offset + 16 * 2, 10_000_000)     # entry 2: LINEDEFS
    path.write_bytes(raw)
    with raises_one_line(r"test\.wad: directory\[2\]: lump LINEDEFS at offset 10000000 "
                         r"\(126 bytes\) lies outside the file"):
        import_wad(path, "MAP01")


def test_lump_size_not_a_whole_number_of_records_is_an_error():
    lumps = Map().lumps()
    lumps[2] = ("LINEDEFS", lumps[2][1] + b"\0")
    path = Path("odd.wad")
    path.write_bytes(wad_bytes(lumps + resources()))
    with raises_one_line(r"odd\.wad: MAP01: LINEDEFS: 127 bytes is not a whole number of "
                         r"14-byte records"):
        import_wad(path, "MAP01")


def test_missing_map_lists_the_maps():
    path = write_wad(Map(), Map(name="MAP02"))
    with raises_one_line(r"test\.wad: MAP07: no such map \(2 maps: MAP01, MAP02\)"):
        import_wad(path, "MAP07")


def test_missing_map_lump_is_an_error():
    path = Path("nosectors.wad")
    path.write_bytes(wad_bytes([lump for lump in Map().lumps() if lump[0] != "SECTORS"]))
    with raises_one_line(r"nosectors\.wad: MAP01: SECTORS: missing"):
        import_wad(path, "MAP01")


def test_bad_vertex_index_is_an_error():
    m = Map()
    m.linedefs[1][1] = 99
    with raises_one_line(r"test\.wad: MAP01: LINEDEFS\[1\]: v2: vertex 99 does not exist "
                         r"\(9 vertices\)"):
        import_wad(write_wad(m), "MAP01")


def test_bad_sidedef_index_is_an_error():
    m = Map()
    m.linedefs[4][3] = 50
    with raises_one_line(r"test\.wad: MAP01: LINEDEFS\[4\]: left sidedef 50 does not exist "
                         r"\(8 sidedefs\)"):
        import_wad(write_wad(m), "MAP01")


def test_bad_sector_index_is_an_error():
    m = Map()
    m.sidedefs[6][3] = 7
    with raises_one_line(r"test\.wad: MAP01: SIDEDEFS\[6\]: sector 7 does not exist "
                         r"\(2 sectors\)"):
        import_wad(write_wad(m), "MAP01")


def test_hexen_maps_are_refused():
    # UDMF maps (TEXTMAP) are read: tests/test_udmf.py
    hexen = Path("hexen.wad")
    hexen.write_bytes(wad_bytes(Map().lumps() + [("BEHAVIOR", b"ACS\0")]))
    with raises_one_line(r"hexen\.wad: MAP01: Hexen-format maps"):
        import_wad(hexen, "MAP01")


def test_malformed_texture1_gives_grey_walls_and_a_warning():
    lumps = [(n, raw[:30]) if n == "TEXTURE1" else (n, raw) for n, raw in resources()]
    path = Path("oddtex.wad")
    path.write_bytes(wad_bytes(Map().lumps() + lumps))
    notes = []
    level = import_wad(path, "MAP01", warnings=notes)
    assert "oddtex.wad: TEXTURE1: texture 0 at offset 24 lies past the end of the lump " \
           "(30 bytes); grey used" in notes
    assert level["walls"][0]["color"] == GREY
    assert level["sectors"][0]["floor_color"] == COLOUR["FLOOR1"]     # flats are unaffected


_FUZZED = itertools.count()


@settings(max_examples=75, deadline=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(data=st.data())
def test_damaged_wad_imports_or_fails_with_one_line(data):
    raw = bytearray(wad_bytes(Map().lumps() + resources()))
    if data.draw(st.booleans(), label="truncate"):
        raw = raw[:data.draw(st.integers(0, len(raw) - 1), label="length")]
    else:
        for _ in range(data.draw(st.integers(1, 8), label="flips")):
            raw[data.draw(st.integers(0, len(raw) - 1))] = data.draw(st.integers(0, 255))
    path = Path(f"fuzz{next(_FUZZED)}.wad")     # a new file each time: no stale cache entry
    path.write_bytes(raw)
    try:
        level = import_wad(path, "MAP01")
    except LevelError as e:
        assert "\n" not in str(e) and str(e).startswith(str(path))
    else:     # damage that leaves the map readable: whatever is left is consistent
        n_vertices, n_sectors = len(level["vertices"]), len(level["sectors"])
        for w in level["walls"]:
            assert 0 <= w["v1"] < n_vertices and 0 <= w["v2"] < n_vertices
            assert 0 <= w["front"] < n_sectors and (w["back"] is None or w["back"] < n_sectors)


# ---------------------------------------------------------------------------------------------
# The WAD:MAP form

def test_wad_spec_is_split_at_the_last_colon():
    assert parse_wad_spec("freedoom2.wad:MAP01") == ("freedoom2.wad", "MAP01")
    assert parse_wad_spec("dir/doom.wad:e1m1") == ("dir/doom.wad", "E1M1")


def test_plain_paths_are_not_wad_specs():
    assert parse_wad_spec("level.json") is None
    assert parse_wad_spec("dir/a:b.json") is None       # not a lump name after the colon
    assert parse_wad_spec(":MAP01") is None
    assert parse_wad_spec("doom.wad:") is None


def test_existing_file_with_a_colon_is_a_level_path():
    odd = Path("rooms:MAP01")
    odd.write_text("{}")
    assert parse_wad_spec(str(odd)) is None


# ---------------------------------------------------------------------------------------------
# Freedoom: every map imports

FREEDOOM = Path(os.environ.get("FREEDOOM_DIR", "/usr/share/games/doom"))
FREEDOOM_MAPS = ([("freedoom1.wad", f"E{e}M{m}") for e in range(1, 5) for m in range(1, 10)]
                 + [("freedoom2.wad", f"MAP{m:02d}") for m in range(1, 33)])
# The suite looks at a handful: E1M1 and MAP01 (the maps everything else uses), MAP12 (the
# largest, 10,884 linedefs) and one map of each other episode. tools/bench.py maps imports,
# compiles, validates and draws the start view of every map (tools/benchkit/maps.py).
FREEDOOM_SAMPLE = [("freedoom1.wad", "E1M1"), ("freedoom1.wad", "E2M6"), ("freedoom1.wad", "E3M1"),
                   ("freedoom1.wad", "E4M1"), ("freedoom2.wad", "MAP01"), ("freedoom2.wad", "MAP12")]


def freedoom(wad: str) -> Path:
    path = FREEDOOM / wad
    if not path.exists():
        pytest.skip(f"{path} is absent (Debian package 'freedoom', or set FREEDOOM_DIR)")
    return path


@pytest.mark.parametrize("wad,map_name", FREEDOOM_SAMPLE)
def test_freedoom_maps_import(wad, map_name):
    """A sample (FREEDOOM_SAMPLE); tools/bench.py maps imports every map."""
    level = import_wad(freedoom(wad), map_name)
    walls, sectors, verts = level["walls"], level["sectors"], level["vertices"]
    assert len(walls) > 100 and len(sectors) > 10
    assert all(0 <= w["front"] < len(sectors) for w in walls)
    assert all(w["back"] is None or 0 <= w["back"] < len(sectors) for w in walls)
    assert all(w["v1"] != w["v2"] for w in walls)
    xs, ys = [v[0] for v in verts], [v[1] for v in verts]
    start = level["start"]
    assert min(xs) <= start["x"] <= max(xs) and min(ys) <= start["y"] <= max(ys)


@pytest.mark.parametrize("wad,map_name", [("freedoom1.wad", "E1M1"), ("freedoom2.wad", "MAP12")])
def test_freedoom_map_loads_as_a_level(freedoom_cache, wad, map_name):
    level = freedoom_cache.level(wad, map_name)
    assert level.walls and level.sectors


# ---------------------------------------------------------------------------------------------
# The command line: import-wad, and WAD:MAP wherever a level is read

def test_import_wad_writes_a_level_that_compiles(capsys):
    from wallbsp import load_level
    from wallbsp.app.cli import main
    wad = write_wad(Map())
    assert main(["import-wad", str(wad), "MAP01", "-o", "map01.json"]) == 0
    level = load_level("map01.json")
    assert len(level.walls) == 7 and len(level.sectors) == 2
    assert main(["compile", "map01.json", "-o", "map01.wbsp"]) == 0
    assert Path("map01.wbsp").exists()


@pytest.mark.parametrize("command", [["compile"], ["stats"], ["render", "-o", "f.png"],
                                     ["draw", "-o", "d.png"]])
def test_wad_colon_map_stands_for_a_level(capsys, command):
    from wallbsp.app.cli import main
    wad = write_wad(Map())
    assert main([command[0], f"{wad}:map01", *command[1:]]) == 0
    if command == ["compile"]:
        assert Path("test-MAP01.wbsp").exists()      # default output: WADNAME-MAP, here


@pytest.mark.parametrize("argv", [["import-wad", "test.wad", "MAP07", "-o", "x.json"],
                                  ["render", "test.wad:MAP07", "-o", "x.png"],
                                  ["import-wad", "missing.wad", "MAP01", "-o", "x.json"]])
def test_bad_wad_input_is_one_line_and_exit_2(capsys, argv):
    from wallbsp.app.cli import main
    write_wad(Map())
    assert main(argv) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and ("MAP07" in err or "missing.wad" in err)
    assert not Path("x.json").exists() and not Path("x.png").exists()
