"""DOOM's status bar (``st_stuff.c``, ``st_lib.c``): the face's rules tic by tic
(``ST_Ticker``: ``FaceState``) and what the bar shows as patches at DOOM's 320 × 200
positions (``bar_patches``), painted into a 320 × 32 picture (``paint_bar``).

The face follows ``ST_updateFaceWidget`` exactly, with its priorities (dead > evil grin >
hurt by another > hurt by oneself > rampage > god mode > looking about), the pain offset
by health bracket and the straight/left/right look chosen by ``M_Random`` once a tic
(``ST_Ticker``'s draw from the play's ``rng.m_random``: DOOM draws it there too, so the
sounds' pitch variation after it stays DOOM's).  A new console player object (DOOM calls
``ST_Start`` from ``P_SpawnPlayer``) starts the face afresh.
"""
from __future__ import annotations

import numpy as np

from wallbsp.doom import info
from wallbsp.doom.fixed import ANG45, ANG180, ANG_MAX, point_to_angle2

__all__ = ["FaceState", "bar_patches", "paint_bar", "ST_X", "ST_Y", "ST_WIDTH", "ST_HEIGHT",
           "face_names", "bar_names"]

TICRATE = 35
ST_X, ST_Y, ST_WIDTH, ST_HEIGHT = 0, 168, 320, 32
ST_NUMPAINFACES, ST_NUMSTRAIGHTFACES, ST_NUMTURNFACES, ST_NUMSPECIALFACES = 5, 3, 2, 3
ST_FACESTRIDE = ST_NUMSTRAIGHTFACES + ST_NUMTURNFACES + ST_NUMSPECIALFACES
ST_TURNOFFSET = ST_NUMSTRAIGHTFACES
ST_OUCHOFFSET = ST_TURNOFFSET + ST_NUMTURNFACES
ST_EVILGRINOFFSET = ST_OUCHOFFSET + 1
ST_RAMPAGEOFFSET = ST_EVILGRINOFFSET + 1
ST_GODFACE = ST_NUMPAINFACES * ST_FACESTRIDE
ST_DEADFACE = ST_GODFACE + 1
ST_EVILGRINCOUNT, ST_STRAIGHTFACECOUNT = 2 * TICRATE, TICRATE // 2
ST_TURNCOUNT, ST_RAMPAGEDELAY, ST_MUCHPAIN = TICRATE, 2 * TICRATE, 20
ST_FACESX, ST_FACESY, ST_FX = 143, 168, 143
ST_AMMOX, ST_AMMOY, ST_HEALTHX, ST_HEALTHY = 44, 171, 90, 171
ST_ARMSX, ST_ARMSY, ST_ARMSBGX, ST_ARMSBGY, ST_ARMSXSPACE, ST_ARMSYSPACE = \
    111, 172, 104, 168, 12, 10
ST_FRAGSX, ST_FRAGSY, ST_ARMORX, ST_ARMORY = 138, 171, 221, 171
ST_KEYX, ST_KEYY = 239, (171, 181, 191)
ST_AMMOSX, ST_MAXAMMOSX, ST_AMMOSY = 288, 314, (173, 179, 191, 185)
NO_AMMO = 1994                      # STlib_drawNum draws nothing for it ("n/a")


def face_names() -> list[str]:
    """``faces[]`` of ST_loadUnloadGraphics, in DOOM's order."""
    names = []
    for i in range(ST_NUMPAINFACES):
        names += [f"STFST{i}{j}" for j in range(ST_NUMSTRAIGHTFACES)]
        names += [f"STFTR{i}0", f"STFTL{i}0", f"STFOUCH{i}", f"STFEVL{i}", f"STFKILL{i}"]
    return names + ["STFGOD0", "STFDEAD0"]


def bar_names() -> list[str]:
    """Every patch the bar may draw."""
    return (["STBAR", "STMBARL", "STMBARR", "STTPRCNT", "STTMINUS", "STARMS"]
            + [f"STTNUM{i}" for i in range(10)] + [f"STYSNUM{i}" for i in range(10)]
            + [f"STGNUM{i}" for i in range(2, 8)] + [f"STKEYS{i}" for i in range(6)]
            + [f"STFB{i}" for i in range(4)] + face_names())


FACES = face_names()


def pain_offset(health: int) -> int:
    """ST_calcPainOffset."""
    health = min(health, 100)
    return ST_FACESTRIDE * (((100 - health) * ST_NUMPAINFACES) // 101)


class FaceState:
    """``ST_Ticker``'s state for one player: ``tick(play, player)`` once a level tic,
    ``index`` the face (``FACES[index]``)."""

    def __init__(self):
        self.mo = None
        self.start(None)

    def start(self, player) -> None:
        """ST_initData (with the widgets' statics as ST_Start leaves them)."""
        self.mo = None if player is None else player.mo
        self.index = 0
        self.count = 0
        self.priority = 0
        self.lastattackdown = -1
        self.oldhealth = -1
        self.randomnumber = 0
        self.oldweaponsowned = list(player.weaponowned) if player is not None \
            else [0] * 9

    def tick(self, play, player, random=True) -> None:
        """ST_Ticker: ``M_Random`` (``play.rng.m_random``; ``random=False`` uses 0 and
        leaves the play's numbers alone), the face, the remembered health."""
        if player.mo is not self.mo:
            self.start(player)
        self.randomnumber = play.rng.m_random() if random else 0
        self._update(player)
        self.oldhealth = player.health

    def _update(self, p) -> None:
        """ST_updateFaceWidget."""
        if self.priority < 10 and not p.health:
            self.priority, self.index, self.count = 9, ST_DEADFACE, 1
        if self.priority < 9 and p.bonuscount:
            grin = False
            for i, owned in enumerate(p.weaponowned):
                if self.oldweaponsowned[i] != owned:
                    grin = True
                    self.oldweaponsowned[i] = owned
            if grin:
                self.priority, self.count = 8, ST_EVILGRINCOUNT
                self.index = pain_offset(p.health) + ST_EVILGRINOFFSET
        if self.priority < 8 and p.damagecount and p.attacker is not None \
                and p.attacker is not p.mo:
            self.priority = 7
            if p.health - self.oldhealth > ST_MUCHPAIN:
                self.count = ST_TURNCOUNT
                self.index = pain_offset(p.health) + ST_OUCHOFFSET
            else:
                bad = point_to_angle2(p.mo.x, p.mo.y, p.attacker.x, p.attacker.y)
                angle = p.mo.angle & ANG_MAX
                if bad > angle:
                    diff = bad - angle
                    right = diff > ANG180
                else:
                    diff = (angle - bad) & ANG_MAX
                    right = diff <= ANG180
                self.count = ST_TURNCOUNT
                self.index = pain_offset(p.health)
                if diff < ANG45:
                    self.index += ST_RAMPAGEOFFSET
                elif right:
                    self.index += ST_TURNOFFSET
                else:
                    self.index += ST_TURNOFFSET + 1
        if self.priority < 7 and p.damagecount:
            self.count = ST_TURNCOUNT
            if p.health - self.oldhealth > ST_MUCHPAIN:
                self.priority = 7
                self.index = pain_offset(p.health) + ST_OUCHOFFSET
            else:
                self.priority = 6
                self.index = pain_offset(p.health) + ST_RAMPAGEOFFSET
        if self.priority < 6:
            if p.attackdown:
                if self.lastattackdown == -1:
                    self.lastattackdown = ST_RAMPAGEDELAY
                else:
                    self.lastattackdown -= 1
                    if not self.lastattackdown:
                        self.priority = 5
                        self.index = pain_offset(p.health) + ST_RAMPAGEOFFSET
                        self.count = 1
                        self.lastattackdown = 1
            else:
                self.lastattackdown = -1
        if self.priority < 5 and ((p.cheats & info.CF_GODMODE)
                                  or p.powers[info.pw_invulnerability]):
            self.priority, self.index, self.count = 4, ST_GODFACE, 1
        if not self.count:
            self.index = pain_offset(p.health) + self.randomnumber % 3
            self.count = ST_STRAIGHTFACECOUNT
            self.priority = 0
        self.count -= 1


def bar_patches(play, player, face_index: int, widths, index=None) -> list[tuple[str, int, int]]:
    """``(patch name, x, y)`` at 320 × 200 positions, in ST_Drawer's order, for ``player``
    (number ``index``, DOOM's ``consoleplayer`` when None) with face ``face_index``;
    ``widths(name)`` gives a patch's width (numbers are placed right to left by the width of
    digit 0, as STlib_drawNum does)."""
    index = play.consoleplayer if index is None else index
    out = []
    sbar = "STBAR" if widths("STBAR") else "STMBARL"
    out.append((sbar, ST_X, ST_Y))
    if sbar == "STMBARL":
        out.append(("STMBARR", ST_ARMSBGX, ST_Y))
    if play.netgame:
        out.append((f"STFB{index}", ST_FX, ST_Y))

    def number(x, y, num, width, digits):
        w = widths(digits + "0")
        if num == NO_AMMO:
            return
        neg = num < 0
        if neg:
            num = -(-9 if width == 2 and num < -9 else -99 if width == 3 and num < -99
                    else num)
        if not num:
            out.append((digits + "0", x - w, y))
        while num and width:
            x -= w
            out.append((f"{digits}{num % 10}", x, y))
            num //= 10
            width -= 1
        if neg:
            out.append(("STTMINUS", x - 8, y))

    ammo = play.tables.weaponinfo[player.readyweapon].ammo
    number(ST_AMMOX, ST_AMMOY, NO_AMMO if ammo == info.am_noammo else player.ammo[ammo],
           3, "STTNUM")
    for i in range(4):
        number(ST_AMMOSX, ST_AMMOSY[i], player.ammo[i], 3, "STYSNUM")
        number(ST_MAXAMMOSX, ST_AMMOSY[i], player.maxammo[i], 3, "STYSNUM")
    out.append(("STTPRCNT", ST_HEALTHX, ST_HEALTHY))
    number(ST_HEALTHX, ST_HEALTHY, player.health, 3, "STTNUM")
    out.append(("STTPRCNT", ST_ARMORX, ST_ARMORY))
    number(ST_ARMORX, ST_ARMORY, player.armorpoints, 3, "STTNUM")
    if not play.deathmatch:
        out.append(("STARMS", ST_ARMSBGX, ST_ARMSBGY))
        for i in range(6):
            name = f"STYSNUM{i + 2}" if player.weaponowned[i + 1] else f"STGNUM{i + 2}"
            out.append((name, ST_ARMSX + (i % 3) * ST_ARMSXSPACE,
                        ST_ARMSY + (i // 3) * ST_ARMSYSPACE))
    out.append((FACES[face_index], ST_FACESX, ST_FACESY))
    for i in range(3):
        key = i + 3 if player.cards[i + 3] else i if player.cards[i] else -1
        if key >= 0:
            out.append((f"STKEYS{key}", ST_KEYX, ST_KEYY[i]))
    if play.deathmatch:
        frags = sum(-f if i == index else f for i, f in enumerate(player.frags))
        number(ST_FRAGSX, ST_FRAGSY, frags, 2, "STTNUM")
    return out


def paint_bar(patches, art) -> np.ndarray:
    """The bar as ``(32, 320, 3)`` uint8: each patch's opaque texels at its place less its
    offsets (V_DrawPatch), clipped to the bar."""
    canvas = np.zeros((ST_HEIGHT, ST_WIDTH, 3), np.uint8)
    for name, x, y in patches:
        picture = art.patch(name)
        if picture is None:
            continue
        rgb, mask = art.rgb(picture)
        blit(canvas, rgb, mask, x - picture.left - ST_X, y - picture.top - ST_Y)
    return canvas


def blit(canvas, rgb, mask, x, y) -> None:
    """``rgb`` where ``mask``, its top left at ``(x, y)`` of ``canvas``, clipped."""
    h, w = mask.shape
    x0, y0 = max(x, 0), max(y, 0)
    x1, y1 = min(x + w, canvas.shape[1]), min(y + h, canvas.shape[0])
    if x0 < x1 and y0 < y1:
        np.copyto(canvas[y0:y1, x0:x1], rgb[y0 - y:y1 - y, x0 - x:x1 - x],
                  where=mask[y0 - y:y1 - y, x0 - x:x1 - x, None])
