"""Reading PNG files in tests: pygame's decoder (SDL_image / libpng), so the pictures that
wallbsp.image writes are checked by a reader that is not ours."""
import os

import numpy as np

os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")
import pygame  # noqa: E402


def load_png(path) -> np.ndarray:
    """The picture in ``path`` as ``(height, width, 3)`` uint8 (alpha dropped)."""
    surface = pygame.image.load(os.fspath(path))
    return np.ascontiguousarray(pygame.surfarray.array3d(surface).transpose(1, 0, 2))
