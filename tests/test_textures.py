"""wallbsp's own texture set: every name shipped as a PNG of its size, fallback colours near
the pictures, sprites with transparency, and tools/make_textures.py reproduces the files."""
from pathlib import Path

import numpy as np
import pygame
import pytest

from toolscripts import tool_script

from wallbsp.assets.catalogue import (FLATS, MASKED_TEXTURES, SPRITES, TEXTURE_DIR,
    WALL_TEXTURES)
from wallbsp.assets.resources import ResourceSet


def load(path: Path) -> np.ndarray:
    """(height, width, 4) RGBA texels of a PNG."""
    surface = pygame.image.load(str(path))
    rgb = pygame.surfarray.array3d(surface).transpose(1, 0, 2)
    alpha = pygame.surfarray.array_alpha(surface).T
    return np.dstack([rgb, alpha])


def shipped():
    files = {f"{n}.png": (w, h, c) for n, (w, h, c) in WALL_TEXTURES.items()}
    files.update({f"flats/{n}.png": (64, 64, c) for n, c in FLATS.items()})
    files.update({f"sprites/{n}.png": (w, h, None) for n, (w, h) in SPRITES.items()})
    return files


@pytest.mark.parametrize("path,spec", sorted(shipped().items()))
def test_each_picture_is_shipped_at_its_size_near_its_fallback_colour(path, spec):
    width, height, fallback = spec
    texels = load(TEXTURE_DIR / path)
    assert texels.shape[:2] == (height, width)
    opaque = texels[..., 3] == 255
    if fallback is not None:
        # walls and flats are solid, except the see-through ones
        assert opaque.all() != (Path(path).stem in MASKED_TEXTURES)
        mean = texels[opaque][:, :3].mean(axis=0)
        expected = [int(fallback[k:k + 2], 16) for k in (1, 3, 5)]
        assert np.abs(mean - expected).max() <= 3


@pytest.mark.parametrize("name", sorted(SPRITES))
def test_sprites_stand_on_their_bottom_row_with_see_through_texels(name):
    alpha = load(TEXTURE_DIR / "sprites" / f"{name}.png")[..., 3]
    assert set(np.unique(alpha)) == {0, 255}
    assert alpha[-1].any()                               # feet on the floor
    assert (alpha == 0).mean() > 0.05


def test_nothing_else_in_the_folder():
    names = {p.relative_to(TEXTURE_DIR).as_posix() for p in TEXTURE_DIR.rglob("*.png")}
    assert names == set(shipped())


def test_the_resource_reader_finds_each_namespace():
    res = ResourceSet([TEXTURE_DIR])
    assert res.wall("BRICK1").pixels.shape[:2] == (128, 128)
    assert res.flat("LAVA1") is not None and res.flat("BRICK1") is None
    assert res.sprite("BAR1A0").mask.any()


def test_the_script_draws_exactly_the_shipped_pixels():
    for path, picture in tool_script("make_textures").all_pictures().items():
        texels = load(TEXTURE_DIR / path)
        channels = picture.shape[2]
        assert np.array_equal(texels[..., :channels], picture), path
