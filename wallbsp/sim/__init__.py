"""Run-time state read by both the renderer and the game: DOOM's arithmetic (``fixed``),
random numbers (``rng``), state and object tables (``info``), the world's current heights,
light and things, the blockmap, collision and sight."""
