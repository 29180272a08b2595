"""UDMF maps (TEXTMAP ... ENDMAP) imported as levels: the tokenizer and grammar, the mapping
of each namespace's fields onto DOOM's, and the one-line errors with line and column.

The WADs are written here from text the tests state; the strongest check builds one map both
as UDMF and as DOOM-format lumps and asks for the same level."""
from __future__ import annotations

import struct
from pathlib import Path

import pytest

from wallbsp.app.cli import main
from wallbsp.assets.wad import wad_bytes
from wallbsp.level.model import LevelError
from wallbsp.level.udmf import parse
from wallbsp.level.udmfmap import map_is_udmf
from wallbsp.level.wadmap import import_wad, list_maps, load_wad_level

# Two rooms side by side (x 0..256 and 256..512), the middle line two-sided.
VERTICES = [(0, 0), (256, 0), (256, 256), (0, 256), (512, 0), (512, 256)]
# v1, v2, flags, special, tag, front, back (-1: none)
LINEDEFS = [(0, 3, 1, 0, 0, 0, -1), (3, 2, 0, 0, 0, 1, -1), (2, 1, 4 | 8, 2, 7, 2, 3),
            (1, 0, 16, 0, 0, 4, -1), (2, 5, 0, 0, 0, 5, -1), (5, 4, 0, 0, 0, 6, -1),
            (4, 1, 0, 0, 0, 7, -1)]
SIDEDEFS = [(0, "STARTAN3", 0), (8, "STARTAN3", 0), (0, "-", 0), (0, "-", 1),
            (-4, "STARTAN3", 0), (0, "BROWN1", 1), (0, "BROWN1", 1), (0, "BROWN1", 1)]
# floor, ceiling, floor flat, ceiling flat, light, special, tag
SECTORS = [(0, 128, "FLOOR4_8", "CEIL3_5", 192, 9, 7), (16, 112, "NUKAGE1", "F_SKY1", 160, 0, 0)]
# x, y, angle, type, DOOM flags, UDMF flags
THINGS = [(64, 128, 90, 1, 7, "skill1=true;skill2=true;skill3=true;skill4=true;skill5=true;"
                              "single=true;coop=true;dm=true;"),
          (300, 100, 180, 3004, 2 | 8 | 16, "skill3=true;ambush=true;coop=true;dm=true;")]
LINE_FLAGS = {1: "blocking", 4: "twosided", 8: "dontpegtop", 16: "dontpegbottom"}


def textmap(namespace="doom") -> str:
    out = [f'namespace = "{namespace}";', "// two rooms, written by hand", ""]
    out += [f"vertex /* {i} */ {{ x = {x}.0; y = {y}.000; }}" for i, (x, y) in enumerate(VERTICES)]
    for v1, v2, flags, special, tag, front, back in LINEDEFS:
        fields = "".join(f"{name} = true; " for bit, name in LINE_FLAGS.items() if flags & bit)
        fields += f"special = {special}; id = {tag}; arg0 = {tag}; " if special else ""
        fields += f"sideback = {back}; " if back >= 0 else ""
        out.append(f"linedef {{ v1 = {v1}; v2 = {v2}; sidefront = {front}; {fields}}}")
    for offset, middle, sector in SIDEDEFS:
        out.append(f'sidedef {{ offsetx = {offset}; texturemiddle = "{middle}"; '
                   f'sector = {sector}; }}')
    for floor, ceiling, ff, cf, light, special, tag in SECTORS:
        out.append(f'sector {{ heightfloor = {floor}; heightceiling = {ceiling}; '
                   f'texturefloor = "{ff}"; textureceiling = "{cf}"; lightlevel = {light}; '
                   f'special = {special}; id = {tag}; }}')
    for x, y, angle, kind, _, flags in THINGS:
        out.append(f"thing {{ x = {x}.0; y = {y}.0; angle = {angle}; type = {kind}; {flags} }}")
    return "\n".join(out) + "\n"


def binary_lumps() -> list[tuple[str, bytes]]:
    def name(n):
        return n.encode().ljust(8, b"\0")
    return [
        ("THINGS", b"".join(struct.pack("<hhhHH", x, y, a, t, f) for x, y, a, t, f, _ in THINGS)),
        ("LINEDEFS", b"".join(struct.pack("<7H", v1, v2, fl, sp, tag, fr, bk & 0xFFFF)
                              for v1, v2, fl, sp, tag, fr, bk in LINEDEFS)),
        ("SIDEDEFS", b"".join(struct.pack("<hh8s8s8sH", off, 0, b"-", b"-", name(m), s)
                              for off, m, s in SIDEDEFS)),
        ("VERTEXES", b"".join(struct.pack("<hh", x, y) for x, y in VERTICES)),
        ("SECTORS", b"".join(struct.pack("<hh8s8shHH", f, c, name(ff), name(cf), li, sp, tg)
                             for f, c, ff, cf, li, sp, tg in SECTORS))]


@pytest.fixture(autouse=True)
def in_tmp_path(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)      # messages name the WADs "udmf.wad"


def udmf_wad(text: str, name="udmf.wad", extra=(), before=()) -> Path:
    raw = text.encode() if isinstance(text, str) else text
    Path(name).write_bytes(wad_bytes(list(before) + [("MAP01", b""), ("TEXTMAP", raw),
                                                     *extra, ("ENDMAP", b"")]))
    return Path(name)


def one_line_error(wad: Path, pattern: str) -> str:
    with pytest.raises(LevelError, match=pattern) as info:
        import_wad(wad, "MAP01")
    assert "\n" not in str(info.value)
    return str(info.value)


# ---------------------------------------------------------------------------------------------
# The grammar

def test_tokens_comments_escapes_numbers_and_case():
    parsed = parse('NameSpace = "ZDoom"; // a comment\n/* block\n comment */ Thing {\n'
                   ' X = 0x10; y = -010; angle = +45; height = 1.5e1; z = .5; w = 2.;\n'
                   ' comment = "say \\"hi\\" \\\\ back\\nslash"; ambush = TRUE; dm = false;\n'
                   ' user_odd_field = 3; } vertex{x=1;y=2;}', "m: TEXTMAP")
    assert parsed.globals == {"namespace": "ZDoom"}
    thing, vertex = parsed.blocks
    assert thing.kind == "thing" and vertex.fields == {"x": 1, "y": 2}
    assert thing.fields == {"x": 16, "y": -8, "angle": 45, "height": 15.0, "z": 0.5, "w": 2.0,
                            "comment": 'say "hi" \\ back\nslash', "ambush": True, "dm": False,
                            "user_odd_field": 3}
    assert parsed.place(thing.where("y")) == (4, 12)


@pytest.mark.parametrize("text, where, what", [
    ('namespace = "doom";\nlinedef {\n  v1 = 0;\n', "2:1", "block 'linedef' is never closed"),
    ('namespace = "doom";\nthing { x = @; }', "2:13", "unexpected character '@'"),
    ('namespace = "doom";\nthing { x = 12abc; }', "2:13", "bad token '12abc'"),
    ('namespace = "doom";\nthing { x = 09; }', "2:13", "bad octal number '09'"),
    ('namespace = "doom";\nthing { x = 1 }', "2:15", "expected ';' after the value of 'x'"),
    ('namespace = "doom";\nthing { x 1; }', "2:11", "expected '=' after 'x'"),
    ('namespace = "doom";\nthing { x = maybe; }', "2:13", "unknown keyword"),
    ('namespace = "doom";\nthing { = 1; }', "2:9", "expected a key or '}'"),
    ('namespace = "doom";\n}', "2:1", "expected a block name or a key"),
    ('namespace = "doom";\n/* open', "2:1", "comment '/\\*' is never closed"),
    ('namespace = "doom";\nthing { s = "open; }', "2:13", "string is never closed"),
])
def test_malformed_textmap_is_one_line_with_line_and_column(text, where, what):
    message = one_line_error(udmf_wad(text), None)
    assert message.startswith(f"udmf.wad: MAP01: TEXTMAP:{where}: "), message
    assert __import__("re").search(what, message), message


def test_malformed_textmap_exits_2_from_the_command_line(capsys):
    udmf_wad('namespace = "doom";\n\nvertex { x = 0; y = 0 }\n')
    assert main(["import-wad", "udmf.wad", "MAP01", "-o", "out.json"]) == 2
    err = capsys.readouterr().err.strip()
    assert "\n" not in err and "udmf.wad: MAP01: TEXTMAP:3:23: expected ';'" in err
    assert not Path("out.json").exists()


# ---------------------------------------------------------------------------------------------
# The mapping

def test_doom_namespace_gives_the_level_of_the_same_map_in_doom_format():
    Path("doom.wad").write_bytes(wad_bytes([("MAP01", b"")] + binary_lumps()))
    from_udmf, from_doom = [], []
    udmf = import_wad(udmf_wad(textmap("doom")), "MAP01", warnings=from_udmf)
    doom = import_wad("doom.wad", "MAP01", warnings=from_doom)
    for level in (udmf, doom):
        del level["name"], level["resources"]
    assert udmf == doom
    assert udmf["walls"][2]["special"] == 2 and udmf["walls"][2]["tag"] == 7
    assert udmf["walls"][2]["back"] == 1 and udmf["walls"][2]["upper_unpegged"]
    assert [t["flags"] for t in udmf["things"]] == [7, 26]
    assert udmf["sectors"][0]["special"] == 9 and udmf["sectors"][0]["tag"] == 7
    assert udmf["start"] == {"x": 64, "y": 128, "angle": 90}
    # the same warnings (missing palette and textures), bar the lump names
    assert len(from_udmf) == len(from_doom)


def test_level_loads_lists_and_renders_from_the_command_line(capsys):
    udmf_wad(textmap("doom"), extra=[("BEHAVIOR", b"ACS\0"), ("SCRIPTS", b"script 1 {}"),
                                     ("ZNODES", b"")],
             before=[("DECORATE", b"actor Foo {}")])
    assert list_maps("udmf.wad") == ["MAP01"] and map_is_udmf("udmf.wad", "map01")
    level = load_wad_level("udmf.wad", "map01")
    assert len(level.walls) == 7 and len(level.sectors) == 2 and len(level.things) == 2
    ignored = [w for w in level.warnings if "ignored" in w]
    assert ignored == ["udmf.wad: MAP01: ignored (wallbsp runs no ACS scripts or DECORATE "
                       "actors and builds its own tree): BEHAVIOR, SCRIPTS, ZNODES, "
                       "DECORATE (WAD)"]
    assert main(["render", "udmf.wad:MAP01", "-o", "x.png", "--size", "64x40"]) == 0
    assert Path("x.png").stat().st_size > 0
    assert main(["import-wad", "udmf.wad", "MAP01", "-o", "level.json"]) == 0


def test_fractional_coordinates_are_rounded_with_one_warning():
    text = textmap().replace("x = 256.0; y = 256.000;", "x = 255.6; y = 256.4;")
    text = text.replace("x = 300.0;", "x = 300.25;")
    notes = []
    level = import_wad(udmf_wad(text), "MAP01", warnings=notes)
    assert [256, 256] in level["vertices"] and level["things"][1]["x"] == 300
    assert [n for n in notes if "fractional" in n] == [
        "udmf.wad: MAP01: TEXTMAP: 3 fractional coordinates of vertices and things rounded "
        "to whole map units"]


ZDOOM_LINES = {   # linedef 2 (the two-sided one): UDMF fields → (DOOM special, tag)
    "special = 12; playeruse = true; repeatspecial = true;": (1, 0),               # manual door
    "special = 12; arg0 = 0; arg1 = 64; playeruse = true;": (117, 0),              # blazing
    "special = 11; arg0 = 5; playercross = true;": (2, 5),                         # W1 open
    "special = 10; arg0 = 5; playeruse = true; repeatspecial = true;": (42, 5),    # SR close
    "special = 13; arg0 = 0; arg2 = 150; arg3 = 2; playeruse = true;": (26, 0),    # blue key
    "special = 206; arg0 = 3; arg1 = 32; playercross = true; repeatspecial = true;": (88, 3),
    "special = 62; arg0 = 3; arg1 = 64; playeruse = true;": (122, 3),              # fast lift
    "special = 70; arg1 = 9; playercross = true; repeatspecial = true;": (97, 9),  # teleport
    "special = 70; arg1 = 9; monstercross = true;": (125, 9),
    "special = 243; playeruse = true;": (11, 0),                                   # exit
    "special = 244; playercross = true;": (124, 0),                                # secret exit
    "special = 80; arg0 = 1; playeruse = true;": (0, 0),                           # ACS
}


@pytest.mark.parametrize("fields", sorted(ZDOOM_LINES))
def test_zdoom_line_specials_map_onto_dooms(fields):
    text = textmap("zdoom").replace("special = 2; id = 7; arg0 = 7; ", fields)
    notes = []
    wall = import_wad(udmf_wad(text), "MAP01", warnings=notes)["walls"][2]
    assert (wall["special"], wall["tag"]) == ZDOOM_LINES[fields]
    unmapped = [n for n in notes if "no DOOM equivalent" in n]
    assert unmapped == ([] if ZDOOM_LINES[fields][0] else [
        "udmf.wad: MAP01: TEXTMAP: linedef specials with no DOOM equivalent do nothing "
        "here: 80"])


def test_zdoom_sector_specials_and_thing_flags():
    text = textmap("zdoom").replace("special = 9; id = 7;", "special = 1024; id = 7;")
    text = text.replace("special = 0; id = 0;", "special = 83; id = 0;")
    text = text.replace("skill3=true;ambush=true;", "skill1=true;skill3=true;ambush=true;")
    notes = []
    level = import_wad(udmf_wad(text), "MAP01", warnings=notes)
    assert [s["special"] for s in level["sectors"]] == [9, 5]     # secret; lava as hellslime
    assert [t["flags"] for t in level["things"]] == [7, 1 | 2 | 8 | 16]
    assert any("sector specials with no exact DOOM equivalent" in n and ": 83" in n
               for n in notes)
    assert any("1 thing in skill 1 but not 2" in n for n in notes)


def test_namespaces():
    notes = []
    import_wad(udmf_wad(textmap("doom").replace('namespace = "doom";', "")), "MAP01",
               warnings=notes)
    assert "udmf.wad: MAP01: TEXTMAP: no namespace; read as 'doom'" in notes
    for namespace in ("Heretic", "strife", "zdoomtranslated"):     # DOOM-numbered specials
        wall = import_wad(udmf_wad(textmap(namespace)), "MAP01")["walls"][2]
        assert (wall["special"], wall["tag"]) == (2, 7)
    for namespace in ("hexen", "vavoom"):                          # Hexen-style: 2 is not DOOM's
        assert import_wad(udmf_wad(textmap(namespace)), "MAP01")["walls"][2]["special"] == 0


@pytest.mark.parametrize("edit, where, what", [
    (("v1 = 0; v2 = 3;", "v2 = 3;"), "TEXTMAP:10:1: linedef 0: missing required field 'v1'",
     None),
    (('sector { heightfloor = 0;', 'sector { texturefloor = "X"; heightfloor = 0;'),
     None, None),
    (("sidefront = 4;", "sidefront = 40;"), "TEXTMAP:13:", "linedef 3: sidefront: sidedef 40 "
     "does not exist \\(8 sidedefs\\)"),
    (("v1 = 4; v2 = 1;", "v1 = 4.5; v2 = 1;"), "TEXTMAP:16:", "linedef 6: v1: expected an "
     "integer, got 4.5"),
    (("type = 3004;", 'type = "imp";'), "TEXTMAP:", "thing 1: type: expected a number"),
    (("type = 3004;", "type = 70000;"), "TEXTMAP:", "thing 1: type: 70000 is out of range"),
    (('texturefloor = "NUKAGE1"; ', ""), "TEXTMAP:26:1: sector 1: missing required field "
     "'texturefloor'", None),
    (("x = 512.0; y = 0.000;", "x = 1e300; y = 0.0;"), "TEXTMAP:", "vertex 4: x: .* out of "
     "range"),
])
def test_bad_fields_are_one_line_with_line_and_column(edit, where, what):
    text = textmap().replace(*edit)
    assert text != textmap()
    if where is None:            # a duplicate field: the last one counts, as in ZDoom
        import_wad(udmf_wad(text), "MAP01")
        return
    message = one_line_error(udmf_wad(text), None)
    assert message.startswith("udmf.wad: MAP01: " + where.split(":")[0]), message
    assert where in message if what is None else __import__("re").search(what, message), \
        message
    assert __import__("re").match(r"udmf\.wad: MAP01: TEXTMAP:\d+:\d+: ", message), message


def test_missing_endmap_is_an_error():
    Path("open.wad").write_bytes(wad_bytes([("MAP01", b""), ("TEXTMAP", textmap().encode())]))
    one_line_error(Path("open.wad"), r"^open\.wad: MAP01: ENDMAP: missing")


def test_coordinates_beyond_16_bits_keep_their_vertices_apart():
    text = textmap()
    for x, y in VERTICES:                # 256 → 65536: past DOOM's 16 bits, within 2**20
        text = text.replace(f"x = {x}.0; y = {y}.000;", f"x = {x * 256}.0; y = {y * 256}.0;")
    text = text.replace("x = 64.0; y = 128.0;", "x = 16384.0; y = 32768.0;")
    level = load_wad_level(udmf_wad(text), "MAP01")
    assert sorted(level.vertices) == sorted((x * 256, y * 256) for x, y in VERTICES)
