"""UDMF text (a map's TEXTMAP lump) read into blocks of fields: the grammar of the Universal
Doom Map Format specification v1.1, section I, and nothing about what the fields mean
(that is ``udmfmap``).

    translation_unit := (block | assignment)*
    block            := identifier '{' assignment* '}'
    assignment       := identifier '=' value ';'
    value            := integer | float | quoted_string | true | false

- Identifiers (block names, keys) are case-insensitive: they are kept in lower case.
- Integers are decimal, hexadecimal (``0x1F``) or octal (``017``), with an optional sign;
  floats have a point and an optional exponent (``-12.5``, ``1.e3``; ``1e3`` and ``.5`` are
  read too); strings are double-quoted with backslash escapes (``\\"``, ``\\\\``, ``\\n``, ``\\t``;
  any other escaped character stands for itself, as in ZDoom's scanner).
- ``// ...`` and ``/* ... */`` comments (not nested) count as white space.
- Any other bare word as a value (the spec's "keyword") is an error: only true and false are
  defined.
Every error is one ``LevelError`` line: ``WHERE:LINE:COLUMN: what``, lines and columns
counted from 1 (``WHERE`` names the file, the map and the lump).
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field

from wallbsp.files import LevelError

_TOKEN = re.compile(r"""
    (?P<space>\s+)
  | (?P<comment>//[^\n]*|/\*.*?\*/)
  | (?P<open_comment>/\*)
  | (?P<string>"(?:[^"\\]|\\.)*")
  | (?P<open_string>")
  | (?P<float>[+-]?(?:[0-9]+\.[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?|[+-]?[0-9]+[eE][+-]?[0-9]+)
  | (?P<hex>[+-]?0[xX][0-9A-Fa-f]+)
  | (?P<int>[+-]?[0-9]+)
  | (?P<word>[A-Za-z_][A-Za-z0-9_]*)
  | (?P<punct>[{}=;])
""", re.VERBOSE | re.DOTALL)
_WORD_CHAR = re.compile(r"[A-Za-z0-9_.]")
_ESCAPE = re.compile(r"\\(.)", re.DOTALL)
_ESCAPES = {"n": "\n", "t": "\t", "r": "\r"}


@dataclass
class Block:
    """One ``name { ... }`` block: its fields (lower-case key → value) and where the block and
    each field begin (offsets into the text; ``Textmap.place`` turns them into line and
    column).  The quick reader leaves ``places`` empty and keeps the body to find them in
    when an error needs one (``where``)."""
    kind: str
    at: int
    fields: dict[str, object] = field(default_factory=dict)
    places: dict[str, int] = field(default_factory=dict)
    body: tuple[str, int] | None = None        # (text with comments blanked, its offset)

    def where(self, key: str) -> int:
        """The offset of field ``key`` (of its last assignment), else of the block."""
        if self.body is not None and not self.places:
            text, at = self.body
            self.places = {m.group(1).lower(): at + m.start(1)
                           for m in _ASSIGNMENT.finditer(text)}
        return self.places.get(key, self.at)


@dataclass
class Textmap:
    where: str
    text: str
    globals: dict[str, object]
    global_places: dict[str, int]
    blocks: list[Block]

    def place(self, offset: int) -> tuple[int, int]:
        """(line, column) of an offset, both from 1."""
        return place(self.text, offset)

    def error(self, offset: int, message: str) -> LevelError:
        line, column = self.place(offset)
        return LevelError(f"{self.where}:{line}:{column}: {message}")


def place(text: str, offset: int) -> tuple[int, int]:
    """(line, column) of an offset into ``text``, both from 1 (only errors need it)."""
    line = text.count("\n", 0, offset) + 1
    return line, offset - (text.rfind("\n", 0, offset) + 1) + 1


def _fail(where: str, text: str, offset: int, message: str) -> LevelError:
    line, column = place(text, offset)
    return LevelError(f"{where}:{line}:{column}: {message}")


def _shown(s: str) -> str:
    s = s if len(s) <= 20 else s[:20] + "..."
    return repr(s)


def tokens(text: str, where: str):
    """(kind, value, offset) for each token: kinds "value", "word", "{", "}", "=", ";"."""
    match = _TOKEN.match
    at, n = 0, len(text)
    while at < n:
        m = match(text, at)
        if m is None:
            raise _fail(where, text, at, f"unexpected character {_shown(text[at])}")
        kind, raw, end = m.lastgroup, m.group(), m.end()
        if kind in ("float", "hex", "int", "word") and end < n and _WORD_CHAR.match(text, end):
            bad = re.compile(r"[A-Za-z0-9_.+-]*").match(text, end).end()
            raise _fail(where, text, at, f"bad token {_shown(text[at:bad])}")
        if kind == "space" or kind == "comment":
            pass
        elif kind == "open_comment":
            raise _fail(where, text, at, "comment '/*' is never closed")
        elif kind == "open_string":
            raise _fail(where, text, at, "string is never closed")
        elif kind == "string":
            yield "value", _ESCAPE.sub(lambda e: _ESCAPES.get(e.group(1), e.group(1)),
                                       raw[1:-1]), at
        elif kind == "float":
            yield "value", float(raw), at
        elif kind == "hex":
            yield "value", int(raw, 16), at
        elif kind == "int":
            digits = raw.lstrip("+-")
            if len(digits) > 1 and digits[0] == "0":
                if not all(c in "01234567" for c in digits):
                    raise _fail(where, text, at, f"bad octal number {_shown(raw)}")
                yield "value", int(raw[: len(raw) - len(digits)] + digits[1:], 8), at
            else:
                yield "value", int(raw), at
        elif kind == "word":
            yield "word", raw, at
        else:
            yield raw, raw, at
        at = end


_KEYWORDS = {"true": True, "false": False}


def parse(text: str, where: str) -> Textmap:
    """The blocks and global assignments of a UDMF text, in order.  ``where`` begins every
    error message (``file: MAP: TEXTMAP``).  A well-formed text is read by a few regular
    expressions a block at a time (``_quick``); anything they do not take is read again
    token by token (``_exact``), which finds the error and its place."""
    return _quick(text, where) or _exact(text, where)


# The quick reader: comments blanked to spaces (offsets kept), then whole assignments and
# blocks matched at once; any surprise gives None and the exact reader takes over.
_STRING_OR_COMMENT = re.compile(r'"(?:[^"\\]|\\.)*"|//[^\n]*|/\*.*?\*/', re.DOTALL)
_RAW_VALUE = r'"(?:[^"\\]|\\.)*"|[^;{}"\s/]+'
_ASSIGNMENT = re.compile(r"\s*([A-Za-z_][A-Za-z0-9_]*)\s*=\s*(" + _RAW_VALUE + r")\s*;")
_ITEM = re.compile(r"\s*([A-Za-z_][A-Za-z0-9_]*)\s*(?:=\s*(" + _RAW_VALUE + r")\s*;|\{(" +
                   r"(?:\s*[A-Za-z_][A-Za-z0-9_]*\s*=\s*(?:" + _RAW_VALUE + r")\s*;)*\s*" +
                   r")\})")
_NUMBER = re.compile(r"(?P<float>[+-]?(?:[0-9]+\.[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?"
                     r"|[+-]?[0-9]+[eE][+-]?[0-9]+)|(?P<hex>[+-]?0[xX][0-9A-Fa-f]+)"
                     r"|(?P<oct>[+-]?0[0-7]+)|(?P<int>[+-]?(?:0|[1-9][0-9]*))")
_NOT_A_VALUE = object()


def _blank(m: re.Match) -> str:
    found = m.group()
    return found if found[0] == '"' else re.sub(r"[^\n]", " ", found)


def _value(raw: str, cache: dict):
    """The value a raw token stands for (kept in ``cache``), or _NOT_A_VALUE."""
    m = None if raw[0] == '"' else _NUMBER.fullmatch(raw)
    if raw[0] == '"':
        value = _ESCAPE.sub(lambda e: _ESCAPES.get(e.group(1), e.group(1)), raw[1:-1])
    elif m is None:
        value = _KEYWORDS.get(raw.lower(), _NOT_A_VALUE)
    elif m.lastgroup == "float":
        value = float(raw)
    elif m.lastgroup == "hex":
        value = int(raw, 16)
    elif m.lastgroup == "oct":
        value = int(raw, 8)
    else:
        value = int(raw)
    cache[raw] = value
    return value


def _quick(text: str, where: str) -> Textmap | None:
    clean = _STRING_OR_COMMENT.sub(_blank, text)       # the same length: offsets hold
    globals_: dict[str, object] = {}
    global_places: dict[str, int] = {}
    blocks: list[Block] = []
    cache: dict = {}
    at, item, find_all = 0, _ITEM.match, _ASSIGNMENT.findall
    while True:
        m = item(clean, at)
        if m is None:
            return Textmap(where, text, globals_, global_places, blocks) \
                if not clean[at:].strip() else None
        name, raw, body = m.groups()
        name_at = m.start(1)
        if raw is not None:
            value = _value(raw, cache)
            if value is _NOT_A_VALUE:
                return None
            globals_[name.lower()] = value
            global_places[name.lower()] = name_at
        else:
            pairs = find_all(body)
            try:
                fields = {key.lower(): cache[raw] for key, raw in pairs}
            except KeyError:                    # a value not seen before: read them
                if any(_value(raw, cache) is _NOT_A_VALUE for _, raw in pairs):
                    return None
                fields = {key.lower(): cache[raw] for key, raw in pairs}
            blocks.append(Block(name.lower(), name_at, fields, {}, (body, m.start(3))))
        at = m.end()


def _exact(text: str, where: str) -> Textmap:
    stream = tokens(text, where)
    end = (None, None, len(text))
    globals_: dict[str, object] = {}
    global_places: dict[str, int] = {}
    blocks: list[Block] = []

    def describe(token) -> str:
        kind, value, _ = token
        if kind is None:
            return "the end of the lump"
        if kind == "value":
            return f"the value {value!r}" if not isinstance(value, str) else \
                f"the string {_shown(value)}"
        if kind == "word":
            return f"{value!r}"
        return f"'{kind}'"

    def expect(kinds: str, after: str, wanted: str = ""):
        token = next(stream, end)
        if token[0] not in kinds.split():
            wanted = wanted or " or ".join(f"'{k}'" for k in kinds.split())
            raise _fail(where, text, token[2], f"expected {wanted} {after}, "
                                               f"found {describe(token)}")
        return token

    def value_after(key: str, key_at: int):
        kind, value, at = expect("value word", f"after '{key} ='", "a value")
        if kind == "word":
            value = _KEYWORDS.get(value.lower())
            if value is None:
                raise _fail(where, text, at, f"{key}: unknown keyword "
                                             f"(only true and false are defined)")
        expect(";", f"after the value of '{key}'")
        return value

    while True:
        token = next(stream, end)
        kind, name, at = token
        if kind is None:
            break
        if kind != "word":
            raise _fail(where, text, at, f"expected a block name or a key, found "
                                         f"{describe(token)}")
        name = name.lower()
        kind2, _, at2 = expect("= {", f"after {name!r}")
        if kind2 == "=":
            globals_[name] = value_after(name, at)
            global_places[name] = at
            continue
        block = Block(name, at)
        while True:
            token = next(stream, end)
            kind, key, key_at = token
            if kind == "}":
                break
            if kind is None:
                raise _fail(where, text, at, f"block {name!r} is never closed "
                                             f"(no '}}' before the end of the lump)")
            if kind != "word":
                raise _fail(where, text, key_at, f"expected a key or '}}' in block {name!r}, "
                                                 f"found {describe(token)}")
            key = key.lower()
            expect("=", f"after {key!r}")
            block.fields[key] = value_after(key, key_at)
            block.places[key] = key_at
        blocks.append(block)
    return Textmap(where, text, globals_, global_places, blocks)
