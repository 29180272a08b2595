"""The player's messages as the WAD words them: DEH_String's substitutions of the IWAD's
``DEHACKED`` lump (Chocolate Doom loads a Freedoom IWAD's, whose BEX ``[STRINGS]`` say
"Got a 1% armor bonus." for DOOM's "Picked up an armor bonus.").

The play simulation keeps DOOM's own English (``d_englsh.h``, DOOM's facts: the text is
what demos and saves know); the screen shows ``shown(text, art)``, the WAD's replacement
of that text when its DEHACKED names the string's mnemonic, else the text itself.
"""
from __future__ import annotations

from wallbsp.assets.wad import open_wad
from wallbsp.screen.finale import bex_strings

__all__ = ["ENGLISH", "shown", "replacements", "map_title"]

# BEX mnemonic -> DOOM's English, for the messages the game shows
ENGLISH = {
    "GOTARMOR": "Picked up the armor.", "GOTMEGA": "Picked up the MegaArmor!",
    "GOTHTHBONUS": "Picked up a health bonus.", "GOTARMBONUS": "Picked up an armor bonus.",
    "GOTSTIM": "Picked up a stimpack.", "GOTMEDINEED": "Picked up a medikit that you REALLY need!",
    "GOTMEDIKIT": "Picked up a medikit.", "GOTSUPER": "Supercharge!",
    "GOTBLUECARD": "Picked up a blue keycard.", "GOTYELWCARD": "Picked up a yellow keycard.",
    "GOTREDCARD": "Picked up a red keycard.", "GOTBLUESKUL": "Picked up a blue skull key.",
    "GOTYELWSKUL": "Picked up a yellow skull key.", "GOTREDSKULL": "Picked up a red skull key.",
    "GOTINVUL": "Invulnerability!", "GOTBERSERK": "Berserk!",
    "GOTINVIS": "Partial Invisibility", "GOTSUIT": "Radiation Shielding Suit",
    "GOTMAP": "Computer Area Map", "GOTVISOR": "Light Amplification Visor",
    "GOTMSPHERE": "MegaSphere!", "GOTCLIP": "Picked up a clip.",
    "GOTCLIPBOX": "Picked up a box of bullets.", "GOTROCKET": "Picked up a rocket.",
    "GOTROCKBOX": "Picked up a box of rockets.", "GOTCELL": "Picked up an energy cell.",
    "GOTCELLBOX": "Picked up an energy cell pack.", "GOTSHELLS": "Picked up 4 shotgun shells.",
    "GOTSHELLBOX": "Picked up a box of shotgun shells.",
    "GOTBACKPACK": "Picked up a backpack full of ammo!",
    "GOTBFG9000": "You got the BFG9000!  Oh, yes.", "GOTCHAINGUN": "You got the chaingun!",
    "GOTCHAINSAW": "A chainsaw!  Find some meat!",
    "GOTLAUNCHER": "You got the rocket launcher!", "GOTPLASMA": "You got the plasma gun!",
    "GOTSHOTGUN": "You got the shotgun!", "GOTSHOTGUN2": "You got the super shotgun!",
    "PD_BLUEO": "You need a blue key to activate this object",
    "PD_REDO": "You need a red key to activate this object",
    "PD_YELLOWO": "You need a yellow key to activate this object",
    "PD_BLUEK": "You need a blue key to open this door",
    "PD_REDK": "You need a red key to open this door",
    "PD_YELLOWK": "You need a yellow key to open this door",
    "STSTR_DQDON": "Degreelessness Mode On", "STSTR_DQDOFF": "Degreelessness Mode Off",
    "STSTR_KFAADDED": "Very Happy Ammo Added", "STSTR_FAADDED": "Ammo (no keys) Added",
    "STSTR_NCON": "No Clipping Mode ON", "STSTR_NCOFF": "No Clipping Mode OFF",
    "STSTR_CHOPPERS": "... doesn't suck - GM", "STSTR_CLEV": "Changing Level...",
}


def replacements(paths) -> dict:
    """``DOOM's English -> the WAD's`` from the IWAD's (``paths[0]``) DEHACKED lump."""
    strings = _strings(paths)
    return {ENGLISH[name]: value for name, value in strings.items() if name in ENGLISH}


def map_title(art, lump: str, level_name: str) -> str:
    """The automap's title of map ``lump`` (HU_Start's ``HU_TITLE``: the WAD's DEHACKED
    ``HUSTR_E1M1`` / ``HUSTR_1``; DOOM's own English names are not carried, so without one
    the lump's name), or ``level_name`` for a level of our own (``lump`` None)."""
    if lump is None:
        return level_name
    strings = art.__dict__.get("_bexstrings")
    if strings is None:
        strings = art.__dict__["_bexstrings"] = _strings(getattr(art, "paths", ()))
    key = f"HUSTR_{int(lump[3:])}" if lump.upper().startswith("MAP") and lump[3:].isdigit() \
        else f"HUSTR_{lump.upper()}"
    return strings.get(key, lump)


def _strings(paths) -> dict:
    if not paths:
        return {}
    try:
        with open_wad(paths[0]) as wad:
            raw = wad.lump("DEHACKED")
    except (OSError, ValueError):
        return {}
    return bex_strings(raw) if raw else {}


def shown(text: str, art) -> str:
    """``text`` as the art's WAD words it (cached on the art; our own art: as it is)."""
    table = art.__dict__.get("_dehstrings")
    if table is None:
        table = art.__dict__["_dehstrings"] = replacements(getattr(art, "paths", ()))
    return table.get(text, text)
