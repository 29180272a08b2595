"""Extracts DOOM's object tables from Chocolate Doom's sources into
``wallbsp/data/doom/info.json``, which ``wallbsp.doom.info`` loads.

    python tools/extract_doom_info.py /work/src/choco/src/doom

It reads the enums and numeric ``#define``s of info.h, sounds.h, doomdef.h, doomdata.h,
p_mobj.h, d_player.h, d_items.h and p_local.h; ``sprnames``, ``states`` and ``mobjinfo``
from info.c; ``weaponinfo`` from d_items.c; ``S_sfx`` (names, priorities, links) from
sounds.c.  Every value is evaluated here, so the data file holds plain numbers.
"""
import json
import re
import sys
from pathlib import Path

OUT = Path(__file__).resolve().parent.parent / "wallbsp" / "data" / "doom" / "info.json"
HEADERS = ["info.h", "sounds.h", "doomdef.h", "doomdata.h", "p_mobj.h", "d_player.h",
           "d_items.h", "p_local.h"]
MOBJINFO_FIELDS = 23
BASE = {"FRACBITS": 16, "FRACUNIT": 1 << 16, "TICRATE": 35, "INT_MIN": -2 ** 31,
        "INT_MAX": 2 ** 31 - 1, "NULL": 0}


def strip_comments(text):
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
    return re.sub(r"//[^\n]*", "", text)


def evaluate(expr, env):
    """A C constant expression of ints, names and | * + - << ( ) as Python evaluates it
    (the same for these operands: no divisions, no unsigned wrap-around)."""
    expr = expr.strip()
    if not re.fullmatch(r"[\w\s|*+\-<>()]+", expr):
        raise ValueError(expr)
    expr = re.sub(r"\b(0[xX][0-9a-fA-F]+|\d+)[uUlL]*\b", r"\1", expr)
    return int(eval(expr, {"__builtins__": {}}, env))


class Constants:
    """Enum members and #defines in source order, as (name, value, group)."""

    def __init__(self):
        self.env = dict(BASE)
        self.items = []             # [name, value, enum type name or "#define"]
        self.enums = {}             # enum type name -> member names in order

    def add(self, name, value, group):
        if name in self.env and name not in BASE:
            if self.env[name] != value:
                raise SystemExit(f"{name}: defined twice ({self.env[name]}, {value})")
            return
        self.env[name] = value
        self.items.append([name, value, group])

    def read_header(self, text):
        text = strip_comments(text)
        for m in re.finditer(r"#define[ \t]+(\w+)[ \t]+([^\n]+)|"
                             r"(?:typedef\s+)?enum\s*(\w*)\s*\{(.*?)\}\s*(\w*)\s*;", text, re.S):
            if m.group(1):
                try:
                    self.add(m.group(1), evaluate(m.group(2), self.env), "#define")
                except (ValueError, NameError, SyntaxError):
                    pass                # a macro with arguments, a string, a header guard
            else:
                self.read_enum(m.group(5) or m.group(3) or "enum", m.group(4))

    def read_enum(self, typename, body):
        value, names = 0, []
        for member in body.split(","):
            member = member.strip()
            if not member:
                continue
            name, _, expr = member.partition("=")
            if expr:
                value = evaluate(expr, self.env)
            self.add(name.strip(), value, typename)
            names.append(name.strip())
            value += 1
        self.enums[typename] = names


def braced(text, start):
    """The text inside the braces opening at or after ``start``, and the index after them."""
    i = text.index("{", start)
    depth = 0
    for j in range(i, len(text)):
        if text[j] == "{":
            depth += 1
        elif text[j] == "}":
            depth -= 1
            if depth == 0:
                return text[i + 1:j], j + 1
    raise SystemExit("unbalanced braces")


def top_level_items(body):
    """The brace-enclosed items of an array initialiser."""
    items, pos = [], 0
    while True:
        i = body.find("{", pos)
        if i < 0:
            return items
        inner, pos = braced(body, i)
        items.append(inner)


def read_states(info_c, consts):
    body, _ = braced(info_c, info_c.index("states[NUMSTATES]"))
    states = []
    for item in top_level_items(body):
        m = re.fullmatch(r"\s*(\w+)\s*,\s*(-?\d+)\s*,\s*(-?\d+)\s*,\s*\{\s*(\w+)\s*\}\s*,"
                         r"\s*(\w+)\s*,\s*(-?\d+)\s*,\s*(-?\d+)\s*", item)
        if not m:
            raise SystemExit(f"state not understood: {item!r}")
        sprite, frame, tics, action, nextstate, misc1, misc2 = m.groups()
        states.append([consts.env[sprite], int(frame), int(tics),
                       None if action == "NULL" else action, consts.env[nextstate],
                       int(misc1), int(misc2)])
    return states


def read_records(source, marker, width, consts):
    body, _ = braced(source, source.index(marker))
    records = []
    for item in top_level_items(body):
        values = [evaluate(v, consts.env) for v in item.split(",") if v.strip()]
        if len(values) != width:
            raise SystemExit(f"{marker}: a record of {len(values)} values: {item!r}")
        records.append(values)
    return records


def read_sprnames(info_c):
    body, _ = braced(info_c, info_c.index("sprnames[]"))
    return re.findall(r'"(\w+)"', body)


def read_sfx(sounds_c, consts):
    body, _ = braced(sounds_c, sounds_c.index("S_sfx[]"))
    sfx = []
    for m in re.finditer(r'SOUND(_LINK)?\(\s*"(\w+)"\s*,\s*(\d+)\s*(?:,\s*(\w+)\s*,\s*(-?\d+)'
                         r'\s*,\s*(-?\d+)\s*)?\)', body):
        link = consts.env[m.group(4)] if m.group(1) else None
        pitch = int(m.group(5)) if m.group(1) else -1
        volume = int(m.group(6)) if m.group(1) else -1
        sfx.append([m.group(2), int(m.group(3)), link, pitch, volume])
    return sfx


def extract(src):
    consts = Constants()
    for header in HEADERS:
        consts.read_header((src / header).read_text(encoding="latin-1"))
    info_c = strip_comments((src / "info.c").read_text(encoding="latin-1"))
    items_c = strip_comments((src / "d_items.c").read_text(encoding="latin-1"))
    sounds_c = strip_comments((src / "sounds.c").read_text(encoding="latin-1"))
    data = {
        "constants": consts.items,
        "enums": consts.enums,
        "sprnames": read_sprnames(info_c),
        "states": read_states(info_c, consts),
        "mobjinfo": read_records(info_c, "mobjinfo[NUMMOBJTYPES]", MOBJINFO_FIELDS, consts),
        "weaponinfo": read_records(items_c, "weaponinfo[NUMWEAPONS]", 6, consts),
        "sfx": read_sfx(sounds_c, consts),
    }
    env = consts.env
    for key, count in (("sprnames", "NUMSPRITES"), ("states", "NUMSTATES"),
                       ("mobjinfo", "NUMMOBJTYPES"), ("weaponinfo", "NUMWEAPONS"),
                       ("sfx", "NUMSFX")):
        if len(data[key]) != env[count]:
            raise SystemExit(f"{key}: {len(data[key])} entries, {count} = {env[count]}")
    return data


def main(argv):
    if len(argv) != 2:
        raise SystemExit(__doc__)
    data = extract(Path(argv[1]))
    with open(OUT, "w") as f:            # one record a line: readable diffs
        f.write("{\n")
        keys = list(data)
        for n, key in enumerate(keys):
            value = data[key]
            f.write(f"{json.dumps(key)}: ")
            if isinstance(value, list):
                f.write("[\n" + ",\n".join(json.dumps(v, separators=(",", ":"))
                                           for v in value) + "\n]")
            else:
                f.write(json.dumps(value, separators=(",", ":")))
            f.write(",\n" if n < len(keys) - 1 else "\n")
        f.write("}\n")
    print(f"wrote {OUT}")


if __name__ == "__main__":
    main(sys.argv)
