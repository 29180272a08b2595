"""The game: what a player does and what the world's rules do in answer (pure, no pygame).

``player`` moves the player; ``rules`` (with ``specials``, ``movers``, ``lights``,
``switches``) runs DOOM's line and sector specials over a ``WorldState``.
"""
