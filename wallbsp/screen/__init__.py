"""What DOOM draws around and over the 3-D view, on an RGB frame with numpy (no display):
the status bar (``statusbar``: ``st_stuff.c``'s widgets and face), the weapon and its
flash (``weapon``: ``R_DrawPSprite``), the screen flashes of PLAYPAL and the
invulnerability colour map (``hud.palette_index``, ``art``), the messages in the WAD's font
(``messages``: ``hu_stuff.c``).  ``hud.Hud`` puts them together; ``art`` decodes the
pictures once per WAD (or our own, for levels without one).  See ``hud``'s docstring."""
