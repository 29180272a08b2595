"""The compiled picture decoder (``assets.postdecode``) against the numpy walk it stands in for
(``pictures._decode_columns``): the same pixels and mask, byte for byte, for every Freedoom
sprite and patch and for hand-made and random lumps; damage goes to the numpy walk, which
names it."""
from __future__ import annotations

import struct

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings, strategies as st

from test_wad import freedoom
from wadkit import BLUE, GREEN, RED, patch
from wallbsp.assets import pictures
from wallbsp.assets.pictures import ResourceError, decode_picture
from wallbsp.assets.postdecode import decode_posts
from wallbsp.assets.wad import open_wad
from wallbsp.assets.wadtextures import SPRITE_MARKERS

PATCH_MARKERS = (("P_START", "PP_START"), ("P_END", "PP_END"))


def by_kernel(raw: bytes):
    width, height = struct.unpack_from("<hh", raw)
    pixels = np.zeros((width, height), np.uint8)
    mask = np.zeros((width, height), bool)
    return decode_posts(np.frombuffer(raw, np.uint8), pixels, mask), pixels, mask


def by_numpy(raw: bytes):
    """The numpy walk over every column (shared columns walked once per column)."""
    width, height = struct.unpack_from("<hh", raw)
    starts = np.frombuffer(raw, "<u4", width, 8).astype(np.int64)
    return pictures._decode_columns(np.frombuffer(raw, np.uint8), starts, height, "ref")


def assert_same(raw: bytes) -> None:
    ok, pixels, mask = by_kernel(raw)
    assert ok
    ref_pixels, ref_mask = by_numpy(raw)
    assert pixels.dtype == ref_pixels.dtype and mask.dtype == ref_mask.dtype
    assert pixels.tobytes() == ref_pixels.tobytes() and mask.tobytes() == ref_mask.tobytes()


@pytest.mark.parametrize("wad", ["freedoom1.wad", "freedoom2.wad"])
def test_every_freedoom_sprite_and_patch_decodes_as_the_numpy_walk(wad):
    with open_wad(freedoom(wad)) as w:
        found = {**w.between(*SPRITE_MARKERS), **w.between(*PATCH_MARKERS)}
        lumps = [w.read(i) for i in found.values()]
    assert len(lumps) > 1000
    for raw in lumps:
        assert_same(raw)


def column(posts: list[tuple[int, int, bytes]], end: bool = True) -> bytes:
    """Posts as (top delta, length byte, texels): the length may differ from the texels."""
    return b"".join(bytes([d, n, 0]) + t + b"\0" for d, n, t in posts) + (b"\xff" if end else b"")


def lump(width: int, height: int, columns: list[bytes], order: list[int] | None = None) -> bytes:
    """A picture whose column x starts at ``columns[order[x]]`` (shared columns allowed)."""
    order = list(range(len(columns))) if order is None else order
    starts, at = [], 8 + 4 * width
    for c in columns:
        starts.append(at)
        at += len(c)
    return struct.pack("<hhhh", width, height, 0, 0) + \
        struct.pack(f"<{width}I", *[starts[k] for k in order]) + b"".join(columns)


SYNTHETIC = {
    "plain": patch(2, 3, [[(1, [BLUE, BLUE])], [(0, [BLUE])]]),
    "two posts a column": patch(2, 8, [[(0, [RED] * 2), (5, [GREEN] * 3)]] * 2),
    "overlapping posts, later wins": lump(1, 7, [column([(0, 4, bytes([RED] * 4)),
                                                         (2, 3, bytes([GREEN] * 3))])]),
    "DeePsea relative deltas": lump(1, 300, [column([(200, 10, bytes([RED] * 10)),
                                                     (50, 5, bytes([BLUE] * 5))])]),
    "delta equal to the previous top": lump(1, 10, [column([(3, 1, b"\x01"),
                                                            (3, 1, b"\x02")])]),
    "post past the bottom": lump(1, 4, [column([(2, 9, bytes(range(1, 10)))])]),
    "post below the canvas": lump(1, 4, [column([(9, 2, b"\x05\x06")])]),
    "no end mark after height + 1 posts": lump(1, 2, [column([(0, 0, b"")] * 3, end=False)]),
    "shared columns": lump(4, 3, [column([(0, 3, b"\x07\x08\x09")]), column([])],
                           order=[1, 0, 0, 1]),
    "long post clipped by the budget": lump(2, 5, [column([(0, 2, b"\x01\x02"),
                                                           (1, 4, b"\x03\x04\x05\x06")])] * 2),
}


@pytest.mark.parametrize("case", SYNTHETIC)
def test_synthetic_pictures_decode_as_the_numpy_walk(case):
    assert_same(SYNTHETIC[case])
    picture = decode_picture(SYNTHETIC[case], case)
    ok, pixels, mask = by_kernel(SYNTHETIC[case])
    assert (picture.pixels == pixels).all() and (picture.mask == mask).all()


def test_later_post_wins_and_relative_deltas_are_followed():
    picture = decode_picture(SYNTHETIC["overlapping posts, later wins"], "x")
    assert picture.pixels[0].tolist() == [RED, RED, GREEN, GREEN, GREEN, 0, 0]
    tall = decode_picture(SYNTHETIC["DeePsea relative deltas"], "x")
    assert np.flatnonzero(tall.mask[0]).tolist() == list(range(200, 210)) + \
        list(range(250, 255))
    equal = decode_picture(SYNTHETIC["delta equal to the previous top"], "x")
    assert np.flatnonzero(equal.mask[0]).tolist() == [3, 6]


DAMAGED = {
    "post cut short": (lump(1, 4, [column([(0, 3, b"\x01\x02\x03")])])[:-3],
                       r"^P: truncated: a column has a post cut short \(17 bytes\)$"),
    "no end mark": (lump(1, 4, [column([(0, 1, b"\x01")], end=False)]),
                    r"^P: truncated: a column has no end mark \(17 bytes\)$"),
    "column past the lump": (struct.pack("<hhhhI", 1, 4, 0, 0, 99) + b"\xff",
                             r"^P: column 0 starts at offset 99, past the end of the lump"),
}


@pytest.mark.parametrize("case", DAMAGED)
def test_damaged_picture_fails_the_kernel_and_the_numpy_walk_names_it(case):
    raw, message = DAMAGED[case]
    assert not by_kernel(raw)[0]
    with pytest.raises(ResourceError, match=message):
        decode_picture(raw, "P")


POSTS = st.lists(st.tuples(st.one_of(st.integers(0, 6), st.integers(0, 254)), st.integers(0, 12), st.integers(0, 12)),
                 max_size=5)


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(height=st.integers(1, 40), columns=st.lists(POSTS, min_size=1, max_size=4),
       order=st.lists(st.integers(0, 3), min_size=1, max_size=6),
       cut=st.integers(0, 20), tail=st.binary(max_size=8))
def test_random_lumps_agree_or_both_refuse(height, columns, order, cut, tail):
    # posts whose length byte may differ from their texels, shared columns, a lump cut short
    # or with bytes after it
    order = [k % len(columns) for k in order]
    body = [column([(d, n, bytes(range(1, m + 1))) for d, n, m in posts]) for posts in columns]
    raw = lump(len(order), height, body, order) + tail
    raw = raw[:max(8 + 4 * len(order), len(raw) - cut)]
    ok, pixels, mask = by_kernel(raw)
    try:
        ref_pixels, ref_mask = by_numpy(raw)
    except ResourceError:
        assert not ok
        return
    assert ok and pixels.tobytes() == ref_pixels.tobytes() and \
        mask.tobytes() == ref_mask.tobytes()
