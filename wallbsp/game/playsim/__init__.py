"""DOOM's play simulation, exactly: linuxdoom's ``p_*.c`` and ``g_game.c``'s tic loop in
16.16 fixed point, proven tic by tic against Chocolate Doom's traces of the Freedoom demos.

How the port is organised (read this before adding to it):

- **One state object.** ``Play`` (``play.py``) holds everything DOOM keeps in globals for a
  level: the map (``sectors``, ``lines``, ``sides``, ``segs``, ``subsectors``, ``nodes``,
  the blockmap and reject), the thinker list, the players, the random numbers, ``leveltime``
  and the scratch globals of the movement code (``tmthing``, ``tmfloorz``, ...).  Several
  ``Play`` objects live side by side in one process (vector environments).
- **Mixins, one per C file.** ``Play`` is composed of mixin classes, one per source file of
  DOOM (``collide.py`` is ``p_map.c``'s movement half, ``monsters.py`` is ``p_enemy.c``, ...).
  A DOOM function becomes a method named by ``cname``: ``P_TryMove`` → ``self.p_try_move``,
  ``A_Chase`` → ``self.a_chase``, ``EV_DoDoor`` → ``self.ev_do_door``, ``T_MoveFloor`` →
  ``self.t_move_floor``, ``PIT_CheckLine`` → ``self.pit_check_line``.  So a module calls
  another's functions without importing it, and a reader finds DOOM's function by its name.
- **DOOM's numbers.** Positions, heights, momenta: fixed point ints (``sim.fixed``); angles:
  unsigned 32-bit ints; every random number from ``self.rng.p_random()`` in DOOM's order.
  C's 32-bit wrap-around is applied where DOOM relies on it (``fixed.wrap32``).
- **Structures** are in ``structs.py`` with C's field names; a mobj's ``state`` is an index
  into the play's ``states``; ``info`` is its ``MobjInfo`` record.
- **DOOM's tables are the play's own.**  ``self.tables`` (``doom.tables.Tables``) holds
  ``info.py``'s tables, or a game's with its own actors added; ``set_tables`` binds
  ``self.states``, ``self.mobjinfo``, ``self.weaponinfo`` and ``self.state_rows`` for the hot
  paths.  Read them there, never ``info.STATES`` and its like: skill 5 and a game's actors
  change the play's tables only, so plays of different skills or games share a process.
"""
import re

_WORD = re.compile(r"[A-Z]+(?=[A-Z][a-z]|\d|\b|_)|[A-Z]?[a-z]+|\d+|[A-Z]+")


def cname(name):
    """DOOM's C function name as this package's method name: ``P_TryMove`` → ``p_try_move``."""
    return "_".join(w.lower() for part in name.split("_") for w in _WORD.findall(part))
