"""What the properties panel shows for each mode, and how a changed value is set.

A ``Field`` reads one value from a sector, wall or thing and writes it back through the
model's ``set_sector``/``set_line``/``set_thing`` for every selected item at once (one
edit, one undo).  Kinds: ``number`` (typed, or the wheel by ``step``), ``flag`` (a click
toggles), ``texture``/``flat``/``thing`` (a click opens the browser), ``special`` (typed,
shown with DOOM's name), ``fixed`` (shown only).
"""
from __future__ import annotations

from dataclasses import dataclass

from wallbsp.editor.specials import line_special_name, sector_special_name
from wallbsp.editor.thingkinds import kind_of

__all__ = ["Field", "FIELDS", "SET", "value_text"]

SKILL_BITS = {"skills 1-2": 1, "skill 3": 2, "skills 4-5": 4}
AMBUSH, NOT_SINGLE = 8, 16


@dataclass(frozen=True)
class Field:
    label: str
    kind: str
    get: object                  # item -> value
    put: object = None           # value -> the keyword arguments of the set command
    step: int = 1                # the wheel's step for numbers
    name: object = None          # value -> a name shown beside it (specials, things)


def _attr(name):
    return lambda item: getattr(item, name)


def _put(name):
    return lambda value: {name: value}


def _side(which, part):
    def get(wall):
        side = getattr(wall, which)
        return None if side is None else getattr(side, part)
    return get


def _put_side(which, part):
    return lambda value: {which: {part: value}}


def _flag_bit(bit):
    return lambda thing: bool(thing.flags & bit)


def _sector_fields():
    return [
        Field("floor", "number", _attr("floor"), _put("floor"), 8),
        Field("ceiling", "number", _attr("ceiling"), _put("ceiling"), 8),
        Field("light", "number", _attr("light"), _put("light"), 16),
        Field("floor flat", "flat", _attr("floor_texture"), _put("floor_texture")),
        Field("ceiling flat", "flat", _attr("ceiling_texture"), _put("ceiling_texture")),
        Field("special", "special", _attr("special"), _put("special"),
              name=sector_special_name),
        Field("tag", "number", _attr("tag"), _put("tag")),
    ]


def _line_fields():
    fields = [
        Field("two-sided", "fixed", lambda w: w.back is not None),
        Field("blocks", "flag", _attr("blocks"), _put("blocks")),
        Field("upper unpegged", "flag", _attr("upper_unpegged"), _put("upper_unpegged")),
        Field("lower unpegged", "flag", _attr("lower_unpegged"), _put("lower_unpegged")),
        Field("secret", "flag", _attr("secret"), _put("secret")),
        Field("sound-blocking", "flag", _attr("blocks_sound"), _put("blocks_sound")),
        Field("hidden on map", "flag", _attr("hidden"), _put("hidden")),
        Field("special", "special", _attr("special"), _put("special"),
              name=line_special_name),
        Field("tag", "number", _attr("tag"), _put("tag")),
    ]
    for which, title in (("front_side", "front"), ("back_side", "back")):
        fields += [Field(f"{title} upper", "texture", _side(which, "upper"),
                         _put_side(which, "upper")),
                   Field(f"{title} middle", "texture", _side(which, "middle"),
                         _put_side(which, "middle")),
                   Field(f"{title} lower", "texture", _side(which, "lower"),
                         _put_side(which, "lower")),
                   Field(f"{title} x offset", "number", _side(which, "x_offset"),
                         _put_side(which, "x_offset"), 8),
                   Field(f"{title} y offset", "number", _side(which, "y_offset"),
                         _put_side(which, "y_offset"), 8)]
    return fields


def _thing_fields():
    return [
        Field("type", "thing", _attr("type"), _put("type"), name=lambda t: kind_of(t).name),
        Field("angle", "number", _attr("angle"), _put("angle"), 45),
        Field("x", "number", _attr("x"), _put("x"), 8),
        Field("y", "number", _attr("y"), _put("y"), 8),
        *(Field(label, "flag", _flag_bit(bit), _skill_put(label))
          for label, bit in SKILL_BITS.items()),
        Field("ambush", "flag", _flag_bit(AMBUSH), _put("ambush")),
        Field("not single player", "flag", _flag_bit(NOT_SINGLE), _put("multiplayer")),
    ]


def _skill_put(label):
    """A skill flag is set as the model's ``skills`` triple, the others kept per thing:
    so the command is made per value of the other two (``panel`` groups by them)."""
    index = list(SKILL_BITS).index(label)

    def put(value, thing=None):
        skills = [bool(thing.flags & b) for b in SKILL_BITS.values()] if thing else [True] * 3
        skills[index] = value
        return {"skills": tuple(skills)}
    put.per_item = True
    return put


def _vertex_fields():
    return [Field("x", "fixed", lambda v: v[0]), Field("y", "fixed", lambda v: v[1])]


FIELDS = {"sectors": _sector_fields(), "lines": _line_fields(), "things": _thing_fields(),
          "vertices": _vertex_fields()}
SET = {"sectors": "set_sector", "lines": "set_line", "things": "set_thing"}


def value_text(field: Field, values: list) -> str:
    """The text of a field over the selection: its value, or "mixed"."""
    if not values:
        return ""
    first = values[0]
    if any(v != first for v in values[1:]):
        return "(mixed)"
    if field.kind in ("flag", "fixed") and isinstance(first, bool):
        return "yes" if first else "no"
    if first is None:
        return "-"
    if isinstance(first, float) and first.is_integer():
        first = int(first)
    text = str(first)
    if field.name is not None:
        text += f"  {field.name(first)}"
    return text
