"""DOOM's object tables (``info.c``, ``d_items.c``, ``sounds.c``) and the constants of its
headers, as Chocolate Doom has them (the original DOOM v1.9 tables).

- ``STATES``: ``State`` records (``sprite``, ``frame``, ``tics``, ``action`` — the C name of
  the action function such as ``"A_Chase"``, or ``None`` — ``nextstate``, ``misc1``,
  ``misc2``), indexed by the ``S_*`` numbers;
- ``MOBJINFO``: ``MobjInfo`` records with ``mobjinfo_t``'s field names, indexed by ``MT_*``;
- ``WEAPONINFO``: ``WeaponInfo`` records (``ammo``, ``upstate``, ``downstate``,
  ``readystate``, ``atkstate``, ``flashstate``), indexed by ``wp_*``;
- ``SPRNAMES`` (by ``SPR_*``), ``SFX`` (``SfxInfo``: ``name``, ``priority``, ``link``,
  ``pitch``, ``volume``, by ``sfx_*``), ``STATE_NAMES``, ``MOBJTYPE_NAMES``, ``SFX_NAMES``;
- ``DOOMEDNUM``: a map thing's type → the first ``MT_*`` with that ``doomednum``, the one
  P_SpawnMapThing's search finds;
- every enum member and numeric ``#define`` of info.h, sounds.h, doomdef.h, doomdata.h,
  p_mobj.h, d_player.h, d_items.h and p_local.h as a module constant with its C name:
  ``S_PLAY``, ``MT_TROOP``, ``SPR_TROO``, ``sfx_pistol``, ``mus_e1m1``, ``MF_SOLID``,
  ``wp_pistol``, ``am_clip``, ``pw_invulnerability``, ``it_bluecard``, ``NUMSTATES``,
  ``MTF_AMBUSH``, ``ML_TWOSIDED``, ``NF_SUBSECTOR``, ``MAXHEALTH``, ``VIEWHEIGHT``,
  ``MAXRADIUS``, ``MELEERANGE``, ``ONFLOORZ``, ``INVULNTICS``, ``CF_NOCLIP``, ...

The data come from ``wallbsp/data/doom/info.json``, written by
``tools/extract_doom_info.py`` from the C sources.  The records are tuples, never changed;
a ``Play`` reads them through its own ``doom.tables.Tables`` (these by default), which
skill 5 and a game's own actors replace for that play alone.
"""
import json
from pathlib import Path
from typing import NamedTuple, Optional


class State(NamedTuple):
    sprite: int
    frame: int
    tics: int
    action: Optional[str]
    nextstate: int
    misc1: int
    misc2: int


class MobjInfo(NamedTuple):
    doomednum: int
    spawnstate: int
    spawnhealth: int
    seestate: int
    seesound: int
    reactiontime: int
    attacksound: int
    painstate: int
    painchance: int
    painsound: int
    meleestate: int
    missilestate: int
    deathstate: int
    xdeathstate: int
    deathsound: int
    speed: int
    radius: int
    height: int
    mass: int
    damage: int
    activesound: int
    flags: int
    raisestate: int


class WeaponInfo(NamedTuple):
    ammo: int
    upstate: int
    downstate: int
    readystate: int
    atkstate: int
    flashstate: int


class SfxInfo(NamedTuple):
    name: str                 # the lump is "DS" + name upper-cased
    priority: int
    link: Optional[int]       # sfx_* this one borrows (chgun → pistol), or None
    pitch: int
    volume: int


def _load():
    path = Path(__file__).resolve().parent.parent / "data" / "doom" / "info.json"
    with open(path) as f:
        return json.load(f)


_DATA = _load()
for _name, _value, _group in _DATA["constants"]:
    globals()[_name] = _value
ENUMS = {k: tuple(v) for k, v in _DATA["enums"].items()}   # C enum type → member names
STATES = tuple(State(*s) for s in _DATA["states"])
MOBJINFO = tuple(MobjInfo(*m) for m in _DATA["mobjinfo"])
WEAPONINFO = tuple(WeaponInfo(*w) for w in _DATA["weaponinfo"])
SPRNAMES = tuple(_DATA["sprnames"])
SFX = tuple(SfxInfo(*s) for s in _DATA["sfx"])
STATE_NAMES = ENUMS["statenum_t"][:NUMSTATES]            # noqa: F821 (loaded above)
MOBJTYPE_NAMES = ENUMS["mobjtype_t"][:NUMMOBJTYPES]      # noqa: F821
SFX_NAMES = ENUMS["sfxenum_t"][:NUMSFX]                  # noqa: F821

DOOMEDNUM = {}
for _i, _m in enumerate(MOBJINFO):
    if _m.doomednum != -1:
        DOOMEDNUM.setdefault(_m.doomednum, _i)
del _DATA, _name, _value, _group, _i, _m
