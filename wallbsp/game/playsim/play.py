"""``Play``: DOOM's play simulation as one object, composed of the mixins listed in
``MIXINS`` (one or two per DOOM source file, see ``__init__``), in DOOM's order of files.

Every mixin is named here and nowhere else: a new DOOM function goes into the module of
its C file, a new module's class is added to ``MIXINS`` (``tests/test_playsim_play.py``
checks that every mixin-looking class of the package is listed or named in
``NOT_MIXINS``).  No two mixins define the same method, so the order is for the reader.

``Play(wad_path, files=())`` (``files``: PWADs) has the game-wide state (``Game.g_init``);
a level is loaded by ``g_init_new`` or ``g_do_play_demo`` (``trace.play_demo`` plays a
whole demo).
"""
from .archvile import ArchVile
from .attacks import MonsterAttacks
from .brain import BossBrain
from .bsptables import BspTables
from .ceilings import Ceilings
from .collide import Collide
from .damage import Damage
from .deaths import MonsterDeaths
from .doors import Doors
from .floors import Floors
from .game import Game
from .gameplayers import GamePlayers
from .hearing import Hearing
from .hitscan import Hitscan
from .interact import Interact
from .intermission import Intermission
from .levelbsp import LevelBsp
from .levelmap import LevelMap
from .lights import Lights
from .linespecials import LineSpecials
from .extnodes import ExtNodes
from .mapload import MapLoad
from .maputil import MapUtil
from .mobjs import Mobjs
from .mobjspawn import MobjSpawn
from .monsters import Monsters
from .pathtraverse import PathTraverse
from .plats import Plats
from .player import PlayerThink
from .sight import Sight
from .slide import Slide
from .specials import Specials
from .switches import Switches
from .teleport import Teleport
from .ticker import Ticker
from .wadlumps import WadLumps
from .weaponfire import WeaponFire
from .weapons import Weapons

# The composition of Play, by DOOM's source file (a base listed after the class deriving
# from it: Mobjs derives from MobjSpawn, MapLoad and Sight from BspTables).
MIXINS = (
    Game, GamePlayers,                          # g_game.c
    Intermission,                               # wi_stuff.c, f_finale.c (their timing)
    WadLumps,                                   # w_wad.c, r_data.c
    MapLoad, ExtNodes, LevelMap, LevelBsp,      # p_setup.c (ZDoom's XNOD, our levels)
    Ticker,                                     # p_tick.c
    MapUtil, PathTraverse,                      # p_maputl.c
    Sight, BspTables,                           # p_sight.c, r_main.c
    Collide, Slide, Hitscan,                    # p_map.c
    Mobjs, MobjSpawn,                           # p_mobj.c
    PlayerThink,                                # p_user.c
    Monsters, Hearing, MonsterAttacks, MonsterDeaths, ArchVile, BossBrain,   # p_enemy.c
    Weapons, WeaponFire,                        # p_pspr.c
    Interact, Damage,                           # p_inter.c
    Doors, Floors, Ceilings, Plats, Lights,     # p_doors.c, p_floor.c, p_ceilng.c, ...
    Switches, Teleport,                         # p_switch.c, p_telept.c
    Specials, LineSpecials,                     # p_spec.c
)

# Public classes of the package that are not mixins of Play, and what they are instead.
NOT_MIXINS = {
    "Decoder": "saverestore: reads a save into a Play",
    "Encoder": "savestate: writes a Play's state",
    "References": "savestate: numbers the objects of a save",
    "Unset": "savestate: the value of a slot never assigned",
    "Divline": "pathtraverse: a trace's line (a structure)",
    "Intercept": "pathtraverse: a line or thing a trace crosses (a structure)",
    "ButtonSoundOrigin": "specials: where a switch's sound comes from (a structure)",
    "Demo": "demos: a vanilla demo's header and tics",
    "DemoTic": "demos: one tic of a demo",
}


class Play(*MIXINS):
    """DOOM's play simulation (see play.py)."""

    def __init__(self, wad_path, files=()):
        self.g_init(wad_path, files)


def play_class():
    """The ``Play`` class (kept for callers that compose on it, such as ``WorldPlay``)."""
    return Play
