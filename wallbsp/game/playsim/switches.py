"""``p_switch.c``: wall switches and buttons (their two textures, by name), and what using
a line does (``P_UseSpecialLine``).  The buttons' countdown runs in ``P_UpdateSpecials``
(``specials.py``).

Per-level state: ``init_switches()`` sets ``buttonlist`` (``MAXBUTTONS`` free
``button_t``; ``P_SpawnSpecials`` empties it again) and forgets the switch list, which
``P_InitSwitchList`` makes from ``self.gamemode`` (called at game start, or on first use).
"""
from wallbsp.doom import info
from wallbsp.doom.info import ML_SECRET

from .spectypes import (BLAZEDWUS, BOTTOM, BUILD8, BUTTONTIME, CRUSHANDRAISE, DOWNWAITUPSTAY,
                        LOWERFLOOR, LOWERFLOORTOLOWEST, LOWERTOFLOOR, MAXBUTTONS, MIDDLE,
                        RAISEANDCHANGE, RAISEFLOOR, RAISEFLOOR512, RAISEFLOORCRUSH,
                        RAISEFLOORTONEAREST, RAISEFLOORTURBO, RAISETONEARESTANDCHANGE, TOP,
                        TURBO16, TURBOLOWER, VLD_BLAZECLOSE, VLD_BLAZEOPEN, VLD_BLAZERAISE,
                        VLD_CLOSE, VLD_NORMAL, VLD_OPEN, button_t)
from .events import USED, LineActivated
from .structs import COMMERCIAL, REGISTERED, RETAIL

# alphSwitchList: (off, on, the first "episode" that has it: 1 shareware, 2 registered and
# Ultimate, 3 Doom II)
ALPH_SWITCH_LIST = (
    ("SW1BRCOM", "SW2BRCOM", 1), ("SW1BRN1", "SW2BRN1", 1), ("SW1BRN2", "SW2BRN2", 1),
    ("SW1BRNGN", "SW2BRNGN", 1), ("SW1BROWN", "SW2BROWN", 1), ("SW1COMM", "SW2COMM", 1),
    ("SW1COMP", "SW2COMP", 1), ("SW1DIRT", "SW2DIRT", 1), ("SW1EXIT", "SW2EXIT", 1),
    ("SW1GRAY", "SW2GRAY", 1), ("SW1GRAY1", "SW2GRAY1", 1), ("SW1METAL", "SW2METAL", 1),
    ("SW1PIPE", "SW2PIPE", 1), ("SW1SLAD", "SW2SLAD", 1), ("SW1STARG", "SW2STARG", 1),
    ("SW1STON1", "SW2STON1", 1), ("SW1STON2", "SW2STON2", 1), ("SW1STONE", "SW2STONE", 1),
    ("SW1STRTN", "SW2STRTN", 1),
    ("SW1BLUE", "SW2BLUE", 2), ("SW1CMT", "SW2CMT", 2), ("SW1GARG", "SW2GARG", 2),
    ("SW1GSTON", "SW2GSTON", 2), ("SW1HOT", "SW2HOT", 2), ("SW1LION", "SW2LION", 2),
    ("SW1SATYR", "SW2SATYR", 2), ("SW1SKIN", "SW2SKIN", 2), ("SW1VINE", "SW2VINE", 2),
    ("SW1WOOD", "SW2WOOD", 2),
    ("SW1PANEL", "SW2PANEL", 3), ("SW1ROCK", "SW2ROCK", 3), ("SW1MET2", "SW2MET2", 3),
    ("SW1WDMET", "SW2WDMET", 3), ("SW1BRIK", "SW2BRIK", 3), ("SW1MOD1", "SW2MOD1", 3),
    ("SW1ZIM", "SW2ZIM", 3), ("SW1STON6", "SW2STON6", 3), ("SW1TEK", "SW2TEK", 3),
    ("SW1MARB", "SW2MARB", 3), ("SW1SKULL", "SW2SKULL", 3),
)

# the manual doors (EV_VerticalDoor)
_MANUAL_DOORS = frozenset((1, 26, 27, 28, 31, 32, 33, 34, 117, 118))
# what monsters may use
_MONSTER_USES = frozenset((1, 32, 33, 34))

# switches (S, changed for good) and buttons (B, flip back after BUTTONTIME):
# special -> (method, its argument(s) after the line, use again)
_SWITCHES = {
    7: ("ev_build_stairs", (BUILD8,), 0),
    9: ("ev_do_donut", (), 0),
    14: ("ev_do_plat", (RAISEANDCHANGE, 32), 0),
    15: ("ev_do_plat", (RAISEANDCHANGE, 24), 0),
    18: ("ev_do_floor", (RAISEFLOORTONEAREST,), 0),
    20: ("ev_do_plat", (RAISETONEARESTANDCHANGE, 0), 0),
    21: ("ev_do_plat", (DOWNWAITUPSTAY, 0), 0),
    23: ("ev_do_floor", (LOWERFLOORTOLOWEST,), 0),
    29: ("ev_do_door", (VLD_NORMAL,), 0),
    41: ("ev_do_ceiling", (LOWERTOFLOOR,), 0),
    71: ("ev_do_floor", (TURBOLOWER,), 0),
    49: ("ev_do_ceiling", (CRUSHANDRAISE,), 0),
    50: ("ev_do_door", (VLD_CLOSE,), 0),
    55: ("ev_do_floor", (RAISEFLOORCRUSH,), 0),
    101: ("ev_do_floor", (RAISEFLOOR,), 0),
    102: ("ev_do_floor", (LOWERFLOOR,), 0),
    103: ("ev_do_door", (VLD_OPEN,), 0),
    111: ("ev_do_door", (VLD_BLAZERAISE,), 0),
    112: ("ev_do_door", (VLD_BLAZEOPEN,), 0),
    113: ("ev_do_door", (VLD_BLAZECLOSE,), 0),
    122: ("ev_do_plat", (BLAZEDWUS, 0), 0),
    127: ("ev_build_stairs", (TURBO16,), 0),
    131: ("ev_do_floor", (RAISEFLOORTURBO,), 0),
    140: ("ev_do_floor", (RAISEFLOOR512,), 0),
    # buttons
    42: ("ev_do_door", (VLD_CLOSE,), 1),
    43: ("ev_do_ceiling", (LOWERTOFLOOR,), 1),
    45: ("ev_do_floor", (LOWERFLOOR,), 1),
    60: ("ev_do_floor", (LOWERFLOORTOLOWEST,), 1),
    61: ("ev_do_door", (VLD_OPEN,), 1),
    62: ("ev_do_plat", (DOWNWAITUPSTAY, 1), 1),
    63: ("ev_do_door", (VLD_NORMAL,), 1),
    64: ("ev_do_floor", (RAISEFLOOR,), 1),
    66: ("ev_do_plat", (RAISEANDCHANGE, 24), 1),
    67: ("ev_do_plat", (RAISEANDCHANGE, 32), 1),
    65: ("ev_do_floor", (RAISEFLOORCRUSH,), 1),
    68: ("ev_do_plat", (RAISETONEARESTANDCHANGE, 0), 1),
    69: ("ev_do_floor", (RAISEFLOORTONEAREST,), 1),
    70: ("ev_do_floor", (TURBOLOWER,), 1),
    114: ("ev_do_door", (VLD_BLAZERAISE,), 1),
    115: ("ev_do_door", (VLD_BLAZEOPEN,), 1),
    116: ("ev_do_door", (VLD_BLAZECLOSE,), 1),
    123: ("ev_do_plat", (BLAZEDWUS, 0), 1),
    132: ("ev_do_floor", (RAISEFLOORTURBO,), 1),
}
# the blazing locked doors: special -> use again
_LOCKED_SWITCHES = {133: 0, 135: 0, 137: 0, 99: 1, 134: 1, 136: 1}


class Switches:
    def init_switches(self):
        self.buttonlist = [button_t() for _ in range(MAXBUTTONS)]
        self.switchlist = None
        self.numswitches = 0
        self.sides_changed = 0          # textures switched so far (read by game.playstate)

    def p_init_switch_list(self):
        """The switch textures of the game mode, in pairs (off, on): ``switchlist[i ^ 1]``
        is the other texture of ``switchlist[i]``."""
        if self.gamemode in (REGISTERED, RETAIL):
            episode = 2
        elif self.gamemode == COMMERCIAL:
            episode = 3
        else:
            episode = 1
        self.switchlist = []
        for name1, name2, ep in ALPH_SWITCH_LIST:
            if ep <= episode:
                self.switchlist += [name1, name2]
        self.numswitches = len(self.switchlist) // 2

    # -- buttons -----------------------------------------------------------------------------
    def p_start_button(self, line, w, texture, time):
        """Counts a button down to turning back to ``texture``."""
        for button in self.buttonlist:
            if button.btimer and button.line is line:
                return                              # already pressed
        for button in self.buttonlist:
            if not button.btimer:
                button.line = line
                button.where = w
                button.btexture = texture
                button.btimer = time
                button.soundorg = line.frontsector.soundorg
                return
        raise RuntimeError("P_StartButton: no button slots left!")

    def p_change_switch_texture(self, line, useAgain):
        """Flips the front side's switch texture (top, middle or bottom, whichever the switch
        list names first); a button (``useAgain``) flips back later, a switch loses its
        special."""
        if self.switchlist is None:
            self.p_init_switch_list()
        if not useAgain:
            line.special = 0
        side = self.sides[line.sidenum[0]]
        tex_top = _upper(side.toptexture)
        tex_mid = _upper(side.midtexture)
        tex_bot = _upper(side.bottomtexture)
        sound = info.sfx_swtchn
        if line.special == 11:                      # exit switch (never: cleared above)
            sound = info.sfx_swtchx
        # the sound's origin is the FIRST button slot's (a vanilla slip: sound only)
        origin = self.buttonlist[0].soundorg
        switchlist = self.switchlist
        for i in range(self.numswitches * 2):
            name = switchlist[i]
            if name == tex_top:
                where = TOP
                side.toptexture = switchlist[i ^ 1]
            elif name == tex_mid:
                where = MIDDLE
                side.midtexture = switchlist[i ^ 1]
            elif name == tex_bot:
                where = BOTTOM
                side.bottomtexture = switchlist[i ^ 1]
            else:
                continue
            self.sides_changed += 1
            self.s_start_sound(origin, sound)
            if useAgain:
                self.p_start_button(line, where, name, BUTTONTIME)
            return

    # -- using a line ------------------------------------------------------------------------
    def p_use_special_line(self, thing, line, side):
        """What using ``line`` from ``side`` does; False when nothing may happen (its back,
        or a special monsters may not use)."""
        if side:
            # use the back sides of VERY SPECIAL lines... (124, the unused sliding door)
            if line.special != 124:
                return False
        if thing.player is None:
            if line.flags & ML_SECRET:
                return False                        # never open secret doors
            if line.special not in _MONSTER_USES:
                return False

        special = line.special
        self.events.append(LineActivated(line, thing, USED, side, special))
        if special in _MANUAL_DOORS:
            self.ev_vertical_door(line, thing)
        elif special in _SWITCHES:
            method, args, use_again = _SWITCHES[special]
            if getattr(self, method)(line, *args):
                self.p_change_switch_texture(line, use_again)
        elif special in _LOCKED_SWITCHES:
            if self.ev_do_locked_door(line, VLD_BLAZEOPEN, thing):
                self.p_change_switch_texture(line, _LOCKED_SWITCHES[special])
        elif special == 11:                         # exit level
            self.p_change_switch_texture(line, 0)
            self.g_exit_level()
        elif special == 51:                         # secret exit
            self.p_change_switch_texture(line, 0)
            self.g_secret_exit_level()
        elif special == 138:                        # light turn on
            self.ev_light_turn_on(line, 255)
            self.p_change_switch_texture(line, 1)
        elif special == 139:                        # light turn off
            self.ev_light_turn_on(line, 35)
            self.p_change_switch_texture(line, 1)
        return True


def _upper(name):
    return name.upper() if name else name
