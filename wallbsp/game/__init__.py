"""The game: DOOM's play simulation and the World around it (pure, no pygame).

``world`` is the ``World`` (SPEC §8, §10): a ``playsim.Play`` on a compiled tree's level,
driven one tic command at a time (``ticcmds``); ``playload`` chooses the map the Play loads
and numbers the things, ``playstate`` feeds the renderer's ``WorldState`` from the Play;
``demo`` holds our own demo files; ``maporder`` says which map follows which.
"""
