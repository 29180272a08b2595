"""``p_spec.h``: the sector movers' and lights' thinker structures (C's field names) and the
enums and constants of DOOM's specials, shared by ``doors.py``, ``floors.py``,
``ceilings.py``, ``plats.py``, ``lights.py``, ``switches.py``, ``specials.py`` and
``linespecials.py`` (and usable by any module that starts a mover, e.g. ``A_BossDeath``).

Only data lives here: no ``Play`` methods.

The ``DOOR_DIRECTION_ALIAS`` class attributes say which field of each structure a
``vldoor_t``'s ``direction`` overlays in memory on x86-64, where Chocolate Doom made the
reference traces: ``EV_VerticalDoor`` reads and writes ``door->direction`` through a
``sector->specialdata`` that may be a platform, a floor or a ceiling (see ``doors.py``).
"""
from .structs import Thinker

TICRATE = 35

# d_player.h cheat_t
CF_NOCLIP, CF_GODMODE, CF_NOMOMENTUM = 1, 2, 4

# p_spec.h: result_e (T_MovePlane)
OK, CRUSHED, PASTDEST = range(3)

# -- doors -----------------------------------------------------------------------------------
# vldoor_e
(VLD_NORMAL, VLD_CLOSE30THENOPEN, VLD_CLOSE, VLD_OPEN, VLD_RAISEIN5MINS, VLD_BLAZERAISE,
 VLD_BLAZEOPEN, VLD_BLAZECLOSE) = range(8)
VDOORSPEED = 2 << 16
VDOORWAIT = 150

# -- ceilings --------------------------------------------------------------------------------
# ceiling_e
(LOWERTOFLOOR, RAISETOHIGHEST, LOWERANDCRUSH, CRUSHANDRAISE, FASTCRUSHANDRAISE,
 SILENTCRUSHANDRAISE) = range(6)
CEILSPEED = 1 << 16
CEILWAIT = 150
MAXCEILINGS = 30

# -- floors ----------------------------------------------------------------------------------
# floor_e
(LOWERFLOOR, LOWERFLOORTOLOWEST, TURBOLOWER, RAISEFLOOR, RAISEFLOORTONEAREST, RAISETOTEXTURE,
 LOWERANDCHANGE, RAISEFLOOR24, RAISEFLOOR24ANDCHANGE, RAISEFLOORCRUSH, RAISEFLOORTURBO,
 DONUTRAISE, RAISEFLOOR512) = range(13)
# stair_e
BUILD8, TURBO16 = range(2)
FLOORSPEED = 1 << 16
# e6y: EV_BuildStairs leaves floormove_t.crush uninitialised; Chocolate Doom gives it a
# value that is neither false nor true (it still counts as "crush" in PIT_ChangeSector)
STAIRS_UNINITIALIZED_CRUSH_FIELD_VALUE = 10

# -- platforms -------------------------------------------------------------------------------
# plat_e
UP, DOWN, WAITING, IN_STASIS = range(4)
# plattype_e
PERPETUALRAISE, DOWNWAITUPSTAY, RAISEANDCHANGE, RAISETONEARESTANDCHANGE, BLAZEDWUS = range(5)
PLATWAIT = 3
PLATSPEED = 1 << 16
MAXPLATS = 30

# -- lights ----------------------------------------------------------------------------------
GLOWSPEED = 8
STROBEBRIGHT = 5
FASTDARK = 15
SLOWDARK = 35

# -- switches --------------------------------------------------------------------------------
# bwhere_e
TOP, MIDDLE, BOTTOM = range(3)
MAXSWITCHES = 50
MAXBUTTONS = 16
BUTTONTIME = 35

# line flags (doomdata.h) used by the specials


class vldoor_t(Thinker):
    __slots__ = ("type", "sector", "topheight", "speed", "direction", "topwait",
                 "topcountdown")
    DOOR_DIRECTION_ALIAS = "direction"

    def __init__(self):
        super().__init__()
        self.type = VLD_NORMAL
        self.sector = None
        self.topheight = self.speed = self.direction = 0
        self.topwait = self.topcountdown = 0


class ceiling_t(Thinker):
    __slots__ = ("type", "sector", "bottomheight", "topheight", "speed", "crush",
                 "direction", "tag", "olddirection")
    DOOR_DIRECTION_ALIAS = "speed"          # offset 48 on x86-64

    def __init__(self):
        super().__init__()
        self.type = LOWERTOFLOOR
        self.sector = None
        self.bottomheight = self.topheight = self.speed = 0
        self.crush = False
        self.direction = self.tag = self.olddirection = 0


class floormove_t(Thinker):
    __slots__ = ("type", "crush", "sector", "direction", "newspecial", "texture",
                 "floordestheight", "speed")
    # offset 48 on x86-64 is the short ``texture`` (a flat number) and two bytes of padding:
    # here a flat name, so a door's direction read there is never -1 and writes are dropped
    DOOR_DIRECTION_ALIAS = None

    def __init__(self):
        super().__init__()
        self.type = LOWERFLOOR
        self.crush = False
        self.sector = None
        self.direction = self.newspecial = 0
        self.texture = None                 # a flat name
        self.floordestheight = self.speed = 0


class plat_t(Thinker):
    __slots__ = ("sector", "speed", "low", "high", "wait", "count", "status", "oldstatus",
                 "crush", "tag", "type")
    DOOR_DIRECTION_ALIAS = "count"          # offset 48 on x86-64

    def __init__(self):
        super().__init__()
        self.sector = None
        self.speed = self.low = self.high = self.wait = self.count = 0
        self.status = self.oldstatus = UP
        self.crush = False
        self.tag = 0
        self.type = PERPETUALRAISE


class fireflicker_t(Thinker):
    __slots__ = ("sector", "count", "maxlight", "minlight")

    def __init__(self):
        super().__init__()
        self.sector = None
        self.count = self.maxlight = self.minlight = 0


class lightflash_t(Thinker):
    __slots__ = ("sector", "count", "maxlight", "minlight", "maxtime", "mintime")

    def __init__(self):
        super().__init__()
        self.sector = None
        self.count = self.maxlight = self.minlight = self.maxtime = self.mintime = 0


class strobe_t(Thinker):
    __slots__ = ("sector", "count", "minlight", "maxlight", "darktime", "brighttime")

    def __init__(self):
        super().__init__()
        self.sector = None
        self.count = self.minlight = self.maxlight = self.darktime = self.brighttime = 0


class glow_t(Thinker):
    __slots__ = ("sector", "minlight", "maxlight", "direction")

    def __init__(self):
        super().__init__()
        self.sector = None
        self.minlight = self.maxlight = self.direction = 0


class button_t:
    """A switch waiting to flip back (``button_t``); ``btexture`` is a texture name,
    ``btimer`` 0 when the slot is free."""
    __slots__ = ("line", "where", "btexture", "btimer", "soundorg")

    def __init__(self):
        self.clear()

    def clear(self):
        """``memset(&buttonlist[i], 0, sizeof(button_t))``."""
        self.line = None
        self.where = TOP
        self.btexture = None
        self.btimer = 0
        self.soundorg = None
