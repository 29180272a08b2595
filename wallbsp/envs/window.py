"""The ``human`` render mode: a pygame window showing the view, scaled up.  Imported by
the first ``render()`` in that mode only, so an environment never touches a display
otherwise (training on a machine without one)."""
from __future__ import annotations

import numpy as np

__all__ = ["Window"]

MIN_WIDTH = 640              # a 160 x 120 view is shown at least this wide


class Window:
    def __init__(self, width: int, height: int):
        import pygame
        self.pygame = pygame
        pygame.display.init()
        scale = max(1, -(-MIN_WIDTH // width))
        self.size = (width * scale, height * scale)
        self.screen = pygame.display.set_mode(self.size)
        pygame.display.set_caption("wallbsp")
        self.clock = pygame.time.Clock()

    def show(self, rgb: np.ndarray, fps: float) -> None:
        """Draw one frame and keep to ``fps``; window events are taken (so the window
        answers) but closing it is the program's business (``env.close()``)."""
        pygame = self.pygame
        pygame.event.pump()
        surface = pygame.surfarray.make_surface(rgb.transpose(1, 0, 2))
        pygame.transform.scale(surface, self.size, self.screen)
        pygame.display.flip()
        self.clock.tick(fps)

    def close(self) -> None:
        self.pygame.display.quit()
