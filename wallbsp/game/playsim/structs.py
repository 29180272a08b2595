"""DOOM's run-time structures with C's field names (``r_defs.h``, ``p_mobj.h``,
``d_player.h``, ``d_think.h``, ``d_ticcmd.h``).  Plain slotted classes: the port reads and
writes their fields as the C code does.  Fixed-point fields are ints (map units × 65536),
angles unsigned 32-bit ints, textures and flats their names (str).
"""


class Thinker:
    """A node of the thinker list (``thinker_t``).  ``func`` is the unbound ``Play`` method
    that runs it each tic (``func(play, thinker)``), or ``None`` once removed (C's -1):
    the list walk unlinks removed thinkers when it reaches them."""
    __slots__ = ("prev", "next", "func")

    def __init__(self):
        self.prev = self.next = None
        self.func = None


class Vertex:
    __slots__ = ("x", "y")

    def __init__(self, x, y):
        self.x, self.y = x, y


class DegenMobj:
    """A sector's sound origin (``degenmobj_t``): only a position."""
    __slots__ = ("x", "y", "z")

    def __init__(self, x=0, y=0, z=0):
        self.x, self.y, self.z = x, y, z


class Sector:
    __slots__ = ("id", "floorheight", "ceilingheight", "floorpic", "ceilingpic",
                 "lightlevel", "special", "tag", "soundtraversed", "soundtarget",
                 "blockbox", "soundorg", "validcount", "thinglist", "specialdata",
                 "linecount", "lines")

    def __init__(self, id):
        self.id = id
        self.floorheight = self.ceilingheight = 0
        self.floorpic = self.ceilingpic = "-"
        self.lightlevel = self.special = self.tag = 0
        self.soundtraversed = 0
        self.soundtarget = None
        self.blockbox = [0, 0, 0, 0]          # BOXTOP, BOXBOTTOM, BOXLEFT, BOXRIGHT
        self.soundorg = DegenMobj()
        self.validcount = 0
        self.thinglist = None                 # first mobj, linked by snext/sprev
        self.specialdata = None               # the thinker moving it, if any
        self.linecount = 0
        self.lines = []


class Side:
    __slots__ = ("id", "textureoffset", "rowoffset", "toptexture", "bottomtexture",
                 "midtexture", "sector")

    def __init__(self, id):
        self.id = id
        self.textureoffset = self.rowoffset = 0
        self.toptexture = self.bottomtexture = self.midtexture = "-"
        self.sector = None


# slopetype_t
ST_HORIZONTAL, ST_VERTICAL, ST_POSITIVE, ST_NEGATIVE = range(4)


class Line:
    __slots__ = ("id", "v1", "v2", "dx", "dy", "flags", "special", "tag", "sidenum",
                 "bbox", "slopetype", "frontsector", "backsector", "validcount",
                 "specialdata")

    def __init__(self, id):
        self.id = id
        self.v1 = self.v2 = None
        self.dx = self.dy = 0
        self.flags = self.special = self.tag = 0
        self.sidenum = [-1, -1]
        self.bbox = [0, 0, 0, 0]
        self.slopetype = ST_HORIZONTAL
        self.frontsector = self.backsector = None
        self.validcount = 0
        self.specialdata = None


class Seg:
    __slots__ = ("v1", "v2", "offset", "angle", "sidedef", "linedef", "frontsector",
                 "backsector")

    def __init__(self):
        self.v1 = self.v2 = None
        self.offset = self.angle = 0
        self.sidedef = self.linedef = None
        self.frontsector = self.backsector = None


class Subsector:
    __slots__ = ("sector", "numlines", "firstline")

    def __init__(self):
        self.sector = None
        self.numlines = self.firstline = 0


class Node:
    __slots__ = ("x", "y", "dx", "dy", "bbox", "children")

    def __init__(self):
        self.x = self.y = self.dx = self.dy = 0
        self.bbox = [[0, 0, 0, 0], [0, 0, 0, 0]]
        self.children = [0, 0]                # NF_SUBSECTOR (0x8000) marks a subsector


class MapThing:
    """A THINGS entry as DOOM reads it (map units, degrees)."""
    __slots__ = ("x", "y", "angle", "type", "options")

    def __init__(self, x=0, y=0, angle=0, type=0, options=0):
        self.x, self.y, self.angle, self.type, self.options = x, y, angle, type, options


class Mobj(Thinker):
    __slots__ = ("x", "y", "z", "snext", "sprev", "angle", "sprite", "frame", "bnext",
                 "bprev", "subsector", "floorz", "ceilingz", "radius", "height", "momx",
                 "momy", "momz", "validcount", "type", "info", "tics", "state", "flags",
                 "health", "movedir", "movecount", "target", "reactiontime", "threshold",
                 "player", "lastlook", "spawnpoint", "tracer")

    def __init__(self):
        super().__init__()
        self.x = self.y = self.z = 0
        self.snext = self.sprev = self.bnext = self.bprev = None
        self.angle = self.sprite = self.frame = 0
        self.subsector = None
        self.floorz = self.ceilingz = self.radius = self.height = 0
        self.momx = self.momy = self.momz = 0
        self.validcount = self.type = 0
        self.info = None
        self.tics = 0
        self.state = 0                        # index into info.STATES
        self.flags = self.health = self.movedir = self.movecount = 0
        self.target = self.tracer = self.player = None
        self.reactiontime = self.threshold = self.lastlook = 0
        self.spawnpoint = MapThing()


class TicCmd:
    """``ticcmd_t``: what a player asks for in one tic.  ``forwardmove`` and ``sidemove``
    are signed bytes, ``angleturn`` a signed 16-bit turn (a demo stores its high byte),
    ``buttons`` DOOM's BT_* bits."""
    __slots__ = ("forwardmove", "sidemove", "angleturn", "consistancy", "chatchar",
                 "buttons")

    def __init__(self, forwardmove=0, sidemove=0, angleturn=0, buttons=0):
        self.forwardmove, self.sidemove = forwardmove, sidemove
        self.angleturn, self.buttons = angleturn, buttons
        self.consistancy = self.chatchar = 0

    def copy_to(self, cmd):
        """``*cmd = *self`` for the fields a command carries (G_Ticker's copy into a
        player's ``cmd``)."""
        cmd.forwardmove, cmd.sidemove = self.forwardmove, self.sidemove
        cmd.angleturn, cmd.buttons = self.angleturn, self.buttons

    def __repr__(self):
        return (f"TicCmd(forwardmove={self.forwardmove}, sidemove={self.sidemove}, "
                f"angleturn={self.angleturn}, buttons={self.buttons})")

    def __eq__(self, other):
        if not isinstance(other, TicCmd):
            return NotImplemented
        return (self.forwardmove, self.sidemove, self.angleturn, self.buttons) == \
            (other.forwardmove, other.sidemove, other.angleturn, other.buttons)

    __hash__ = None


# buttons (d_event.h)
BT_ATTACK, BT_USE, BT_SPECIAL, BT_CHANGE = 1, 2, 128, 4
BT_WEAPONMASK, BT_WEAPONSHIFT = 8 + 16 + 32, 3


class PspDef:
    """An overlay sprite of the player's view (weapon, flash): ``state`` is a state index or
    ``None`` when off."""
    __slots__ = ("state", "tics", "sx", "sy")

    def __init__(self):
        self.state = None
        self.tics = self.sx = self.sy = 0


# skill_t (doomdef.h)
SK_BABY, SK_EASY, SK_MEDIUM, SK_HARD, SK_NIGHTMARE = range(5)

# playerstate_t
PST_LIVE, PST_DEAD, PST_REBORN = range(3)
NUMPOWERS, NUMCARDS, NUMWEAPONS, NUMAMMO, NUMPSPRITES, MAXPLAYERS = 6, 6, 9, 4, 2, 4


class Player:
    __slots__ = ("mo", "playerstate", "cmd", "viewz", "viewheight", "deltaviewheight",
                 "bob", "health", "armorpoints", "armortype", "powers", "cards",
                 "backpack", "frags", "readyweapon", "pendingweapon", "weaponowned",
                 "ammo", "maxammo", "attackdown", "usedown", "cheats", "refire",
                 "killcount", "itemcount", "secretcount", "message", "damagecount",
                 "bonuscount", "attacker", "extralight", "fixedcolormap", "colormap",
                 "psprites", "didsecret")

    def __init__(self):
        self.mo = None
        self.playerstate = PST_REBORN
        self.cmd = TicCmd()
        self.viewz = self.viewheight = self.deltaviewheight = self.bob = 0
        self.health = self.armorpoints = self.armortype = 0
        self.powers = [0] * NUMPOWERS
        self.cards = [False] * NUMCARDS
        self.backpack = False
        self.frags = [0] * MAXPLAYERS
        self.readyweapon = self.pendingweapon = 0
        self.weaponowned = [0] * NUMWEAPONS
        self.ammo = [0] * NUMAMMO
        self.maxammo = [0] * NUMAMMO
        self.attackdown = self.usedown = self.cheats = self.refire = 0
        self.killcount = self.itemcount = self.secretcount = 0
        self.message = None
        self.damagecount = self.bonuscount = 0
        self.attacker = None
        self.extralight = self.fixedcolormap = self.colormap = 0
        self.psprites = [PspDef() for _ in range(NUMPSPRITES)]
        self.didsecret = False


# GameMode_t and GameVersion_t (Chocolate Doom's d_mode.h): which executable's rules apply
SHAREWARE, REGISTERED, COMMERCIAL, RETAIL = range(4)
EXE_DOOM_1_2, EXE_DOOM_1_666, EXE_DOOM_1_7, EXE_DOOM_1_8, EXE_DOOM_1_9, EXE_HACX, \
    EXE_ULTIMATE, EXE_FINAL, EXE_FINAL2, EXE_CHEX = range(10)
