"""Hostile inputs of issue 34's classes, made from good ones: saves re-sealed around a forged
body (the digest made anew, as an attacker can), saves whose body inflates without end,
vanilla demos with no end marker or naming a map the WAD lacks, pathological WAD maps.
Used by tools/fuzz_inputs.py (the campaign) and the tests (tests/test_untrusted_*.py)."""
import hashlib
import json
import random
import struct
import zlib

PREFIX = struct.Struct("<8sIII")
DIGEST = 32


def split_save(data: bytes):
    """(prefix fields, header bytes, compressed body) of a save."""
    magic, version, head_len, body_len = PREFIX.unpack_from(data)
    head = data[PREFIX.size:PREFIX.size + head_len]
    body = data[PREFIX.size + head_len:PREFIX.size + head_len + body_len]
    return (magic, version), head, body


def seal(magic_version, head: bytes, packed: bytes) -> bytes:
    """A save of these parts with its sizes and digest made anew."""
    out = PREFIX.pack(*magic_version, len(head), len(packed)) + head + packed
    return out + hashlib.sha256(out).digest()


def body_of(data: bytes):
    return json.loads(zlib.decompress(split_save(data)[2]))


def reforge(data: bytes, edit) -> bytes:
    """The save with ``edit(body)`` applied to its JSON body, re-sealed."""
    mv, head, _ = split_save(data)
    body = body_of(data)
    edit(body)
    return seal(mv, head, zlib.compress(json.dumps(body, separators=(",", ":")).encode(), 9))


def with_raw_body(data: bytes, raw: bytes) -> bytes:
    """The save with ``raw`` (any bytes) as its body's inflated text, re-sealed."""
    mv, head, _ = split_save(data)
    return seal(mv, head, zlib.compress(raw, 9))


def inflating_save(data: bytes, inflated: int) -> bytes:
    """A save whose body inflates to ``inflated`` bytes of JSON (spaces in an array):
    about a thousandth of that on disk."""
    mv, head, _ = split_save(data)
    z = zlib.compressobj(1)
    chunk = b" " * (1 << 20)
    parts = [z.compress(b"[")]
    for _ in range(inflated >> 20):
        parts.append(z.compress(chunk))
    parts.append(z.compress(b"0]") + z.flush())
    return seal(mv, head, b"".join(parts))


def first_mobj_row(body):
    """(index, row) of the body's first map object thinker."""
    mobj = next(i for i, c in enumerate(body["classes"]) if c[0].endswith(":Mobj"))
    i = next(i for i, row in enumerate(body["thinkers"]) if row[0] == mobj)
    return i, body["thinkers"][i]


def set_mobj_field(data: bytes, name: str, value) -> bytes:
    """The save with the first map object's field ``name`` set to ``value``."""
    def edit(body):
        _, row = first_mobj_row(body)
        fields = body["classes"][row[0]][1]
        row[1 + fields.index(name)] = value
    return reforge(data, edit)


def copied_thinkers(data: bytes, count: int) -> bytes:
    """The save with ``count`` copies of its first map object's row added."""
    def edit(body):
        _, row = first_mobj_row(body)
        body["thinkers"].extend([row] * count)
    return reforge(data, edit)


def endless_demo(size: int, seed: int = 1) -> bytes:
    """A v1.9 demo of at most ``size`` bytes (one player, E1M1, skill 3): whole tics to the
    end, none starting with the end marker (0x80)."""
    rng = random.Random(seed)
    tics = bytearray(rng.getrandbits(8) for _ in range(4096))
    for k in range(0, len(tics), 4):
        if tics[k] == 0x80:
            tics[k] = 0x7F
    body = bytes(tics) * (size // len(tics))
    return bytes([109, 2, 1, 1, 0, 0, 0, 0, 0, 1, 0, 0, 0]) + body[:(size - 13) // 4 * 4]


def demo_of_map(episode: int, gamemap: int, tics: int = 35) -> bytes:
    """A v1.9 demo of ``tics`` idle tics on the map (episode, map), then its end marker."""
    return bytes([109, 2, episode, gamemap, 0, 0, 0, 0, 0, 1, 0, 0, 0]) + \
        b"\0\0\0\0" * tics + b"\x80"


def garbage_wad_map(seed: int = 7, lines: int = 1100, extent: int = 4096) -> bytes:
    """A PWAD with map MAP01 (and E1M1) whose linedefs join random vertices: walls that cross
    each other everywhere (issue 34's pathological map), one sector, a player start."""
    rng = random.Random(seed)
    vertices = [(rng.randrange(-extent, extent), rng.randrange(-extent, extent))
                for _ in range(lines)]
    vert = b"".join(struct.pack("<hh", x, y) for x, y in vertices)
    linedefs, k = bytearray(), 0
    for i in range(lines):
        j = rng.randrange(lines)
        if j == i:
            continue
        linedefs += struct.pack("<hhhhhhh", i, j, 1, 0, 0, k, -1)
        k += 1
    sides = b"".join(struct.pack("<hh8s8s8sh", 0, 0, b"-", b"-", b"STARTAN3", 0)
                     for _ in range(k))
    sectors = struct.pack("<hh8s8shhh", 0, 128, b"FLOOR4_8", b"CEIL3_5", 160, 0, 0)
    things = struct.pack("<hhhhh", vertices[0][0], vertices[0][1], 0, 1, 7)
    lumps = []
    for name in ("MAP01", "E1M1"):
        lumps += [(name, b""), ("THINGS", things), ("LINEDEFS", bytes(linedefs)),
                  ("SIDEDEFS", sides), ("VERTEXES", vert), ("SECTORS", sectors)]
    body, entries = bytearray(), []
    for name, lump in lumps:
        entries.append(struct.pack("<ii8s", 12 + len(body), len(lump), name.encode()))
        body += lump
    return b"PWAD" + struct.pack("<ii", len(entries), 12 + len(body)) + bytes(body) + \
        b"".join(entries)
