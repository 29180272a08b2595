"""Tree files (.wbsp) read without trust (issue 14 §1-5): a file either loads as a sound tree
for its level or is one TreeError line naming it, and reading it never takes much more
memory than the file holds."""
import io
import os
import struct
import tracemalloc
import zipfile

import numpy as np
import pytest

from wallbsp import compile_level, load_tree
from wallbsp.level.model import Level
from wallbsp.bsp.tree import BSPTree, TreeError
from wallbsp.bsp.treefile import ARRAY_LAYOUT, write_tree_file


def arrays_of(tree) -> dict:
    return {name: np.array(getattr(tree, name)) for name in ARRAY_LAYOUT}


def save_arrays(path, level, arrays, candidates=15, seed=0):
    write_tree_file(path, level, arrays, candidates, seed)
    return path


def rewrite(src, dst, replace=None, drop=(), add=None, compress=zipfile.ZIP_STORED):
    """Copy a tree file member by member (new CRCs), changing what is asked."""
    replace, add = replace or {}, add or {}
    with zipfile.ZipFile(src) as a, zipfile.ZipFile(dst, "w", compress) as b:
        for name in a.namelist():
            if name not in drop:
                b.writestr(name, replace.get(name, a.read(name)))
        for name, data in add.items():
            b.writestr(name, data)
    return dst


def npy(array) -> bytes:
    buf = io.BytesIO()
    np.lib.format.write_array(buf, np.asarray(array))
    return buf.getvalue()


def npy_with_header(text: str, data: bytes = b"") -> bytes:
    """A .npy member with any header text (padded as numpy pads it)."""
    body = text.encode("latin1")
    pad = 64 - (10 + len(body) + 1) % 64
    body += b" " * pad + b"\n"
    return b"\x93NUMPY\x01\x00" + struct.pack("<H", len(body)) + body + data


def refused(path, *words):
    with pytest.raises(TreeError) as err:
        load_tree(path)
    message = str(err.value)
    assert message.startswith(str(path)) and "\n" not in message, message
    for word in words:
        assert word in message, message
    return message


@pytest.fixture
def small(compiled_levels):
    return compiled_levels["small"]


@pytest.fixture
def good(tmp_path, small):
    path = tmp_path / "good.wbsp"
    small.save(path)
    return path


def renumbered_root_last(arrays):
    """The same tree with its nodes in reverse order (the root last) and segs re-tiled."""
    n = len(arrays["node_line"])
    old = np.arange(n)[::-1]                      # new node j is old node old[j]
    new_of = np.empty(n, dtype=np.int64)
    new_of[old] = np.arange(n)
    out = dict(arrays)
    seg_order = np.concatenate([np.arange(*arrays["node_segs"][i]) for i in old])
    for name in ("seg_wall", "seg_flip", "seg_t", "seg_xy"):
        out[name] = arrays[name][seg_order]
    counts = arrays["node_segs"][old, 1] - arrays["node_segs"][old, 0]
    stops = np.cumsum(counts)
    out["node_segs"] = np.stack([stops - counts, stops], axis=1).astype(np.int32)
    for name in ("node_line", "node_bbox"):
        out[name] = arrays[name][old]
    child = arrays["node_child"][old]
    out["node_child"] = np.where(child >= 0, new_of[np.maximum(child, 0)], child).astype(np.int32)
    out["root"] = np.array(new_of[int(arrays["root"])], dtype=np.int64)
    return out


# -- §1: what loads is a sound tree -------------------------------------------------------------

def test_a_renumbered_tree_loads_but_root_minus_one_is_refused(tmp_path, small):
    arrays = renumbered_root_last(arrays_of(small))
    assert int(arrays["root"]) == len(arrays["node_line"]) - 1
    tree = load_tree(save_arrays(tmp_path / "last.wbsp", small.level, arrays))
    for x, y in [(100, 100), (256, 300), (30, 480), (-50, 0)]:
        assert tree.locate(x, y) == small.locate(x, y)
        assert sorted(tree.front_to_back(x, y)) == list(range(small.seg_count))
    arrays["root"] = np.array(-1, dtype=np.int64)     # reads the last node from the end
    refused(save_arrays(tmp_path / "minus.wbsp", small.level, arrays), "root")


@pytest.mark.parametrize("name, value", [
    ("node_child", lambda a: -len(a["leaf_sector"]) - 1),
    ("node_child", lambda a: len(a["node_line"])),
    ("node_segs", lambda a: -1),
    ("seg_wall", lambda a: -1),
    ("leaf_sector", lambda a: -2),
    ("root", lambda a: len(a["node_line"])),
])
def test_an_index_out_of_range_is_refused(tmp_path, small, name, value):
    arrays = arrays_of(small)
    target = arrays[name].reshape(-1)
    target[len(target) // 2] = value(arrays)
    refused(save_arrays(tmp_path / "bad.wbsp", small.level, arrays), "not a sound tree")


def _moved(level: Level, dx: int) -> Level:
    vertices = [(x + dx, y) for x, y in level.vertices]
    return Level(level.name, vertices, level.sectors, level.walls, level.start)


def test_a_moved_level_with_its_hash_recomputed_is_refused(tmp_path, small):
    moved = _moved(small.level, 1)
    refused(save_arrays(tmp_path / "moved.wbsp", moved, arrays_of(small)), "not a sound tree")


def test_arrays_of_another_levels_tree_are_refused(tmp_path, small, compiled_levels):
    other = compile_level(_moved(small.level, 1))
    refused(save_arrays(tmp_path / "a.wbsp", small.level, arrays_of(other)))
    refused(save_arrays(tmp_path / "b.wbsp", small.level, arrays_of(compiled_levels["multi"])))


def test_another_sound_tree_of_the_same_level_loads(tmp_path, small):
    other = compile_level(small.level, candidates=2, seed=5)
    tree = load_tree(save_arrays(tmp_path / "seed5.wbsp", small.level, arrays_of(other)))
    assert tree.front_to_back(200, 200) == other.front_to_back(200, 200)


def test_a_flipped_byte_with_a_valid_crc_is_refused_or_harmless(tmp_path, good, small):
    """Every array member, bytes spread over its data: flip one (the zip is rewritten, so
    the CRC is right).  What still loads must behave exactly like the original."""
    points = [(100, 100), (256, 300), (30, 480), (470, 40), (300, 200.5)]
    loaded = refusals = 0
    with zipfile.ZipFile(good) as zf:
        members = {name: zf.read(name) for name in zf.namelist()}
    for name in ARRAY_LAYOUT:
        raw = members[name + ".npy"]
        data_start = len(raw) - np.asarray(getattr(small, name)).nbytes
        for at in range(data_start, len(raw), max(1, (len(raw) - data_start) // 5)):
            for mask in (0x01, 0x80):
                damaged = bytearray(raw)
                damaged[at] ^= mask
                path = rewrite(good, tmp_path / "flip.wbsp", {name + ".npy": bytes(damaged)})
                try:
                    tree = load_tree(path)
                except TreeError:
                    refusals += 1
                    continue
                loaded += 1
                for p in points:
                    assert tree.front_to_back(*p) == small.front_to_back(*p), (name, at)
                    assert tree.locate(*p) == small.locate(*p), (name, at)
    assert refusals > 10 * max(loaded, 1)


def test_validate_refuses_a_root_of_minus_one_in_memory(small):
    tree = BSPTree(small.level, dict(arrays_of(small), root=np.array(-1)), 15, 0)
    with pytest.raises(ValueError, match="root"):
        tree.validate()


# -- §2: array headers -------------------------------------------------------------------------

@pytest.mark.parametrize("member, header", [
    ("node_line", "{'descr': '<i8', 'fortran_order': False, 'shape': (-1, 3), }"),
    ("node_line", "{'descr': '<i8', 'fortran_order': False, 'shape': (2**64 - 1, 3), }"),
    ("node_line", "{'descr': '<i8', 'fortran_order': False, 'shape': (18446744073709551615, 3), }"),
    ("seg_wall", "{'descr': '<i4', 'fortran_order': False, 'shape': (-5,), }"),
    ("seg_wall", "{'descr': '<i4', 'fortran_order': False, 'shape': (("),
    ("seg_wall", "{'descr': '<i4', 'fortran_order': False, 'shape': [3], }"),
    ("seg_xy", "{'descr': '|O', 'fortran_order': False, 'shape': (1, 4), }"),
    ("seg_xy", "not a header at all"),
])
def test_a_bad_array_header_is_one_tree_error(tmp_path, good, member, header):
    path = rewrite(good, tmp_path / "bad.wbsp", {member + ".npy": npy_with_header(header)})
    refused(path, member)


def test_arrays_whose_lengths_cannot_form_a_tree_are_refused_before_reading(tmp_path, good,
                                                                           small):
    path = rewrite(good, tmp_path / "bad.wbsp",
                   {"leaf_sector.npy": npy(np.append(small.leaf_sector, -1).astype(np.int32))})
    refused(path, "leaves")


# -- §3: JSON members --------------------------------------------------------------------------

@pytest.mark.parametrize("member, text", [
    ("level.json", b"[" * 100_000 + b"]" * 100_000),
    ("header.json", b"[" * 30_000 + b"]" * 30_000),
    ("header.json", b"{" * 100_000),
])
def test_json_nested_deeper_than_python_can_go_is_one_tree_error(tmp_path, good, member, text):
    refused(rewrite(good, tmp_path / "deep.wbsp", {member: text}), "header.json"
            if member == "header.json" else "level.json")


@pytest.mark.parametrize("key, value", [
    ("candidates", -3), ("candidates", [1]), ("seed", "zero"), ("seed", True),
    ("level_sha256", 5), ("level_sha256", "ab"),
])
def test_header_fields_of_the_wrong_kind_are_refused(tmp_path, good, key, value):
    import json
    with zipfile.ZipFile(good) as zf:
        header = json.loads(zf.read("header.json"))
    header[key] = value
    refused(rewrite(good, tmp_path / "h.wbsp", {"header.json": json.dumps(header)}), key)


# -- §4: float coordinates ---------------------------------------------------------------------

@pytest.mark.parametrize("name", ["seg_xy", "node_bbox"])
@pytest.mark.parametrize("value", [np.nan, np.inf, -np.inf, 1e300, 2.0 ** 21])
def test_a_coordinate_that_is_not_a_map_number_is_refused(tmp_path, small, name, value):
    arrays = arrays_of(small)
    arrays[name][1, 2] = value
    refused(save_arrays(tmp_path / "f.wbsp", small.level, arrays), name)
    tree = BSPTree(small.level, arrays, 15, 0)
    with pytest.raises(ValueError, match=name):
        tree.validate()


# -- §5: zip bombs and strange archives --------------------------------------------------------

def test_unknown_missing_or_repeated_members_are_refused(tmp_path, good):
    refused(rewrite(good, tmp_path / "a.wbsp", add={"notes.txt": b"hi"}), "notes.txt")
    refused(rewrite(good, tmp_path / "b.wbsp", drop={"seg_t.npy"}), "seg_t", "missing")
    with pytest.warns(UserWarning):      # zipfile itself warns of the duplicate name
        path = rewrite(good, tmp_path / "c.wbsp", add={"seg_t.npy": b"x"})
    refused(path, "twice")


def test_a_compressed_member_is_refused(tmp_path, good):
    refused(rewrite(good, tmp_path / "z.wbsp", compress=zipfile.ZIP_DEFLATED), "compressed")


def _declare_size(path, member, size):
    """Patch the uncompressed size the archive declares for member (local header and
    central directory), leaving its data alone."""
    raw = bytearray(path.read_bytes())
    with zipfile.ZipFile(path) as zf:
        info = zf.getinfo(member)
        start = zf.start_dir
    struct.pack_into("<I", raw, info.header_offset + 22, size)
    at = start
    while raw[at:at + 4] == b"PK\x01\x02":
        n, m, k = struct.unpack_from("<HHH", raw, at + 28)
        if raw[at + 46:at + 46 + n].decode() == member:
            struct.pack_into("<I", raw, at + 24, size)
        at += 46 + n + m + k
    path.write_bytes(bytes(raw))
    return path


@pytest.mark.parametrize("compress", [zipfile.ZIP_STORED, zipfile.ZIP_DEFLATED])
def test_a_member_declaring_a_gibibyte_fails_fast_and_small(tmp_path, good, compress):
    path = rewrite(good, tmp_path / "bomb.wbsp", compress=compress)
    _declare_size(path, "node_line.npy", 2 ** 30)
    tracemalloc.start()
    try:
        refused(path)
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert peak < 4 << 20, peak


def test_an_array_header_claiming_gigabytes_allocates_nothing(tmp_path, good):
    header = "{'descr': '<f8', 'fortran_order': False, 'shape': (33554432, 4), }"
    path = rewrite(good, tmp_path / "big.wbsp", {"seg_xy.npy": npy_with_header(header)})
    tracemalloc.start()
    try:
        refused(path, "seg_xy")
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert peak < 4 << 20, peak


def test_what_is_not_a_regular_file_is_refused_without_blocking(tmp_path):
    fifo = tmp_path / "pipe.wbsp"
    os.mkfifo(fifo)
    refused(fifo, "FIFO", "not a regular file")
    refused(tmp_path, "directory")
    refused(tmp_path / "absent.wbsp", "no such file")
