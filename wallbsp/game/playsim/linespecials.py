"""``p_spec.c``, second half: the walk-over lines (``P_CrossSpecialLine``) and the shot lines
(``P_ShootSpecialLine``).

No per-level state of its own.
"""
from wallbsp.doom import info

from .spectypes import (BLAZEDWUS, BUILD8, CRUSHANDRAISE, DOWNWAITUPSTAY, FASTCRUSHANDRAISE,
                        LOWERANDCHANGE, LOWERANDCRUSH, LOWERFLOOR, LOWERFLOORTOLOWEST,
                        PERPETUALRAISE, RAISEFLOOR, RAISEFLOOR24, RAISEFLOOR24ANDCHANGE,
                        RAISEFLOORCRUSH, RAISEFLOORTONEAREST, RAISEFLOORTURBO,
                        RAISETONEARESTANDCHANGE, RAISETOHIGHEST, RAISETOTEXTURE,
                        SILENTCRUSHANDRAISE, TURBO16, TURBOLOWER, VLD_BLAZECLOSE,
                        VLD_BLAZEOPEN, VLD_BLAZERAISE, VLD_CLOSE, VLD_CLOSE30THENOPEN,
                        VLD_NORMAL, VLD_OPEN)
from .events import CROSSED, SHOT, LineActivated
from .structs import EXE_DOOM_1_2

# walk-over lines: special -> the calls it makes, as (method, arguments after the line);
# a method taking the side and the thing too is marked by the argument "side+thing"
_W_ONCE = {                     # W1: the special is cleared
    2: (("ev_do_door", (VLD_OPEN,)),),
    3: (("ev_do_door", (VLD_CLOSE,)),),
    4: (("ev_do_door", (VLD_NORMAL,)),),
    5: (("ev_do_floor", (RAISEFLOOR,)),),
    6: (("ev_do_ceiling", (FASTCRUSHANDRAISE,)),),
    8: (("ev_build_stairs", (BUILD8,)),),
    10: (("ev_do_plat", (DOWNWAITUPSTAY, 0)),),
    12: (("ev_light_turn_on", (0,)),),
    13: (("ev_light_turn_on", (255,)),),
    16: (("ev_do_door", (VLD_CLOSE30THENOPEN,)),),
    17: (("ev_start_light_strobing", ()),),
    19: (("ev_do_floor", (LOWERFLOOR,)),),
    22: (("ev_do_plat", (RAISETONEARESTANDCHANGE, 0)),),
    25: (("ev_do_ceiling", (CRUSHANDRAISE,)),),
    30: (("ev_do_floor", (RAISETOTEXTURE,)),),
    35: (("ev_light_turn_on", (35,)),),
    36: (("ev_do_floor", (TURBOLOWER,)),),
    37: (("ev_do_floor", (LOWERANDCHANGE,)),),
    38: (("ev_do_floor", (LOWERFLOORTOLOWEST,)),),
    39: (("ev_teleport", "side+thing"),),
    40: (("ev_do_ceiling", (RAISETOHIGHEST,)), ("ev_do_floor", (LOWERFLOORTOLOWEST,))),
    44: (("ev_do_ceiling", (LOWERANDCRUSH,)),),
    53: (("ev_do_plat", (PERPETUALRAISE, 0)),),
    54: (("ev_stop_plat", ()),),
    56: (("ev_do_floor", (RAISEFLOORCRUSH,)),),
    57: (("ev_ceiling_crush_stop", ()),),
    58: (("ev_do_floor", (RAISEFLOOR24,)),),
    59: (("ev_do_floor", (RAISEFLOOR24ANDCHANGE,)),),
    104: (("ev_turn_tag_lights_off", ()),),
    108: (("ev_do_door", (VLD_BLAZERAISE,)),),
    109: (("ev_do_door", (VLD_BLAZEOPEN,)),),
    100: (("ev_build_stairs", (TURBO16,)),),
    110: (("ev_do_door", (VLD_BLAZECLOSE,)),),
    119: (("ev_do_floor", (RAISEFLOORTONEAREST,)),),
    121: (("ev_do_plat", (BLAZEDWUS, 0)),),
    130: (("ev_do_floor", (RAISEFLOORTURBO,)),),
    141: (("ev_do_ceiling", (SILENTCRUSHANDRAISE,)),),
}
_W_REPEAT = {                   # WR: the special stays
    72: (("ev_do_ceiling", (LOWERANDCRUSH,)),),
    73: (("ev_do_ceiling", (CRUSHANDRAISE,)),),
    74: (("ev_ceiling_crush_stop", ()),),
    75: (("ev_do_door", (VLD_CLOSE,)),),
    76: (("ev_do_door", (VLD_CLOSE30THENOPEN,)),),
    77: (("ev_do_ceiling", (FASTCRUSHANDRAISE,)),),
    79: (("ev_light_turn_on", (35,)),),
    80: (("ev_light_turn_on", (0,)),),
    81: (("ev_light_turn_on", (255,)),),
    82: (("ev_do_floor", (LOWERFLOORTOLOWEST,)),),
    83: (("ev_do_floor", (LOWERFLOOR,)),),
    84: (("ev_do_floor", (LOWERANDCHANGE,)),),
    86: (("ev_do_door", (VLD_OPEN,)),),
    87: (("ev_do_plat", (PERPETUALRAISE, 0)),),
    88: (("ev_do_plat", (DOWNWAITUPSTAY, 0)),),
    89: (("ev_stop_plat", ()),),
    90: (("ev_do_door", (VLD_NORMAL,)),),
    91: (("ev_do_floor", (RAISEFLOOR,)),),
    92: (("ev_do_floor", (RAISEFLOOR24,)),),
    93: (("ev_do_floor", (RAISEFLOOR24ANDCHANGE,)),),
    94: (("ev_do_floor", (RAISEFLOORCRUSH,)),),
    95: (("ev_do_plat", (RAISETONEARESTANDCHANGE, 0)),),
    96: (("ev_do_floor", (RAISETOTEXTURE,)),),
    97: (("ev_teleport", "side+thing"),),
    98: (("ev_do_floor", (TURBOLOWER,)),),
    105: (("ev_do_door", (VLD_BLAZERAISE,)),),
    106: (("ev_do_door", (VLD_BLAZEOPEN,)),),
    107: (("ev_do_door", (VLD_BLAZECLOSE,)),),
    120: (("ev_do_plat", (BLAZEDWUS, 0)),),
    128: (("ev_do_floor", (RAISEFLOORTONEAREST,)),),
    129: (("ev_do_floor", (RAISEFLOORTURBO,)),),
}
# the lines monsters (and anything not a player) trigger
_MONSTER_CROSSES = frozenset((39, 97, 125, 126, 4, 10, 88))
# projectiles that trigger nothing (from v1.4 on)
_NEVER_CROSS = frozenset((info.MT_ROCKET, info.MT_PLASMA, info.MT_BFG, info.MT_TROOPSHOT,
                          info.MT_HEADSHOT, info.MT_BRUISERSHOT))


class LineSpecials:
    def p_cross_special_line(self, linenum, side, thing):
        """``thing`` is crossing line number ``linenum`` from ``side`` (0 front, 1 back)."""
        line = self.lines[linenum]
        if self.gameversion <= EXE_DOOM_1_2:
            if line.special > 98 and line.special != 104:
                return
        elif thing.player is None:
            if thing.type in _NEVER_CROSS:
                return
        if thing.player is None and line.special not in _MONSTER_CROSSES:
            return

        special = line.special
        self.events.append(LineActivated(line, thing, CROSSED, side, special))
        calls = _W_ONCE.get(special)
        if calls is not None:
            self._cross_calls(calls, line, side, thing)
            line.special = 0
            return
        calls = _W_REPEAT.get(special)
        if calls is not None:
            self._cross_calls(calls, line, side, thing)
            return
        if special == 52:                           # exit
            self.g_exit_level()
        elif special == 124:                        # secret exit
            self.g_secret_exit_level()
        elif special == 125:                        # teleport, monsters only, once
            if thing.player is None:
                self.ev_teleport(line, side, thing)
                line.special = 0
        elif special == 126:                        # teleport, monsters only
            if thing.player is None:
                self.ev_teleport(line, side, thing)

    def _cross_calls(self, calls, line, side, thing):
        for method, args in calls:
            if args == "side+thing":
                getattr(self, method)(line, side, thing)
            else:
                getattr(self, method)(line, *args)

    def p_shoot_special_line(self, thing, line):
        """``thing``'s shot hit ``line``."""
        if thing.player is None and line.special != 46:
            return                                  # only the door opens for monsters
        special = line.special
        self.events.append(LineActivated(line, thing, SHOT, -1, special))
        if special == 24:                           # raise floor
            self.ev_do_floor(line, RAISEFLOOR)
            self.p_change_switch_texture(line, 0)
        elif special == 46:                         # open door
            self.ev_do_door(line, VLD_OPEN)
            self.p_change_switch_texture(line, 1)
        elif special == 47:                         # raise floor to nearest and change
            self.ev_do_plat(line, RAISETONEARESTANDCHANGE, 0)
            self.p_change_switch_texture(line, 0)
