#!/usr/bin/env python3
"""Our own sprites and textures for the game level (no third-party art), drawn with numpy
(tools/spritekit.py) into wallbsp/data/game/: ``sprites/NAMEF0.png`` for every frame of
every state the level's things (and what they spawn: fireballs, puffs, blood, dropped
weapons, the player's own body) and ViZDoom's scenarios' things (the cacodemon and its
fireball, the chaingunner, the rocket, the health bonus: wallbsp/envs/vizdoom*.py) can be
in, and the red door and lift textures.  The scenarios use these folders when Freedoom's
IWAD is not installed (``wallbsp.envs.scenarios.our_resources``).

Which frames exist is read from DOOM's state table (``wallbsp.doom.info``): each monster's
chains (spawn, see, pain, melee, missile, death, gib) say what a frame shows — walking,
aiming or firing (a full-bright frame is a muzzle flash), in pain, falling over, torn
apart — so a frame the play can show is never missing.  Rotation 0 (``POSSA0``): one
picture for every angle, which DOOM allows.  Deterministic: random numbers come from each
picture's name.  Sprites already in wallbsp/data/textures/sprites (lamp, medikit, ...) are
left to that folder, which the level names after this one.

    python tools/make_game_art.py            # writes wallbsp/data/game/
"""
from __future__ import annotations

import sys
import zlib
from pathlib import Path

import numpy as np

from wallbsp.assets.catalogue import SPRITES
from wallbsp.doom import info

import spritekit as sk
import texturekit as kit
from make_textures import write_pictures

ROOT = Path(__file__).resolve().parent.parent
OUT = ROOT / "wallbsp" / "data" / "game"
FULLBRIGHT = 0x8000

BODIES = {
    "POSS": sk.Body(36, 54, (214, 160, 130), (110, 100, 62), (52, 70, 40), (70, 70, 74)),
    "SPOS": sk.Body(38, 54, (200, 170, 150), (62, 62, 66), (40, 40, 44), (100, 70, 40),
                    bulk=1.1, eyes=(200, 30, 30)),
    "TROO": sk.Body(40, 56, (130, 88, 52), (120, 80, 48), (104, 70, 42), None,
                    eyes=(255, 170, 30), spikes=(230, 222, 200)),
    "SARG": sk.Body(52, 54, (214, 120, 130), (200, 106, 118), (170, 90, 100), None,
                    bulk=1.45, head=1.25, eyes=(250, 220, 60), jaws=True),
    "PLAY": sk.Body(36, 56, (200, 150, 120), (60, 120, 60), (50, 96, 50), (60, 60, 64),
                    helmet=(70, 130, 70)),
    "CPOS": sk.Body(40, 56, (206, 150, 124), (150, 42, 36), (58, 54, 56), (92, 92, 98),
                    bulk=1.15),
}
# what the game level places, and what those things spawn or drop
LEVEL_TYPES = (3004, 9, 3001, 3002, 2001, 2002, 2007, 2008, 2048, 2049, 2011, 2012, 2018,
               13, 2035, 2028)
SPAWNED = ("MT_PLAYER", "MT_TROOPSHOT", "MT_PUFF", "MT_BLOOD", "MT_TFOG", "MT_CLIP",
           "MT_SHOTGUN")
# what the scenarios spawn beyond those (Cacodemon, ChaingunGuy, HealthBonus, Medikit,
# GreenArmor, ...), and the fireball, rocket and gun those make or drop
SCENARIO_TYPES = (3005, 65, 2014, 2012, 2018)
SCENARIO_SPAWNED = ("MT_HEADSHOT", "MT_ROCKET", "MT_CHAINGUN")
# states the player's code sets itself (P_SetMobjState(mo, S_PLAY_ATK2) as a weapon fires)
SET_BY_CODE = {"MT_PLAYER": ("missilestate", "S_PLAY_ATK2")}
CHAINS = ("seestate", "missilestate", "meleestate", "painstate", "deathstate", "xdeathstate",
          "spawnstate")


def rng_for(name: str) -> np.random.Generator:
    return np.random.default_rng(zlib.crc32(name.encode("ascii")))


def chain(state: int, others=()) -> list:
    """The states from ``state`` on, each once, in the order the play goes through them,
    up to the start of another of the object's chains (an attack going back to walking)."""
    out = []
    while state and state not in out and (not out or state not in others):
        out.append(state)
        state = info.STATES[state].nextstate
    return out


def frame_roles(types=LEVEL_TYPES, spawned=SPAWNED) -> dict:
    """(sprite, frame letter) -> (chain, index among the chain's frames, their number,
    whether it flashes: full bright, or the state that shoots) for every frame the types can
    show; a frame in several chains takes the first of CHAINS."""
    mobjs = [info.DOOMEDNUM[t] for t in types] + [getattr(info, n) for n in spawned]
    roles = {}
    for mt in mobjs:
        starts = {getattr(info.MOBJINFO[mt], name): name for name in CHAINS}
        extra = SET_BY_CODE.get(info.MOBJTYPE_NAMES[mt])
        if extra:
            starts[getattr(info, extra[1])] = extra[0]
        for first, name in starts.items():
            frames = {}
            for s in chain(first, starts):
                st = info.STATES[s]
                key = (info.SPRNAMES[st.sprite], chr(ord("A") + (st.frame & 0x7FFF)))
                shoots = bool(st.frame & FULLBRIGHT) or "Attack" in (st.action or "")
                frames.setdefault(key, shoots)      # as first shown: CPOSE aims, F fires
            for k, (key, flash) in enumerate(frames.items()):
                roles.setdefault(key, (name, k, len(frames), flash))
    return roles


def monster_frame(sprite: str, frame: str, role: tuple) -> np.ndarray:
    name, k, n, bright = role
    t = k / max(n - 1, 1)
    r = rng_for(sprite + frame)
    if sprite == "HEAD":
        return cacodemon_frame(name, k, n, bright, r)
    body = BODIES[sprite]
    if name in ("seestate", "spawnstate"):
        return sk.figure(body, sk.Pose(step=(1, 0, -1, 0)[k % 4]))
    if name in ("missilestate", "meleestate"):
        if body.jaws:
            return sk.figure(body, sk.Pose(aim=0.3 + 0.5 * t, bite=1.0 if bright else 0.4 * t))
        return sk.figure(body, sk.Pose(aim=1.0 if body.weapon else 0.3 + 0.7 * t, flash=bright))
    if name == "painstate":
        return sk.figure(body, sk.Pose(pain=True))
    if name == "deathstate":
        return sk.dying(body, t, r)
    return sk.gibbed(body, t, r)


def cacodemon_frame(name, k, n, bright, rng):
    """Floating (A), opening its mouth to spit (B-D), in pain (E-F), dying (G-L)."""
    if name == "missilestate":
        return sk.cacodemon(mouth=0.35 + 0.65 * k / max(n - 1, 1), fire=bright)
    if name == "painstate":
        return sk.cacodemon(mouth=0.3 + 0.4 * k, eye=0.4 - 0.4 * k, pain=True)
    if name == "deathstate":
        return sk.caco_dying(k / max(n - 1, 1), rng)
    return sk.cacodemon()


# -- pickups and effects -----------------------------------------------------------------------

def gun_on_floor(w, h, stock, barrels):
    pic = sk.canvas(w, h)
    sk.box(pic, 2, h - 7, w * 0.35, h - 2, stock)
    sk.box(pic, w * 0.3, h - 9, w * 0.62, h - 3, (60, 60, 66))
    for k in range(barrels):
        y = h - 9 + k * 2
        sk.box(pic, w * 0.6, y, w - 2, y + 2, (96, 98, 104))
    return sk.outline(pic)


def ammo_box(w, h, colour, round_colour, rounds):
    pic = sk.canvas(w, h)
    sk.box(pic, 1, h * 0.4, w - 1, h, colour)
    for k in range(rounds):
        x = 3 + k * (w - 6) / max(rounds - 1, 1)
        sk.capsule(pic, x, h * 0.1 + 1.5, x, h * 0.4, 1.3, round_colour)
    sk.box(pic, w * 0.3, h * 0.55, w * 0.7, h * 0.75, (230, 220, 150), False)
    return sk.outline(pic)


def clip(w=10, h=14):
    pic = sk.canvas(w, h)
    sk.box(pic, 2, 3, w - 2, h, (70, 76, 52))
    sk.box(pic, 3, 0, w - 3, 3, (212, 170, 70))
    return sk.outline(pic)


def shells(w=18, h=10):
    pic = sk.canvas(w, h)
    for k in range(4):
        x = 2 + k * 4
        sk.box(pic, x, 1, x + 3, h - 3, (190, 30, 26))
        sk.box(pic, x, h - 3, x + 3, h, (212, 170, 70))
    return sk.outline(pic)


def armour(bright):
    w, h = 32, 22
    pic = sk.canvas(w, h)
    green = (70, 190, 70) if bright else (50, 150, 50)
    sk.ellipse(pic, w / 2 - 0.5, h / 2 + 1, w / 2 - 2, h / 2 - 1, green)
    sk.box(pic, w / 2 - 5, 0, w / 2 + 4, 5, (0, 0, 0), False)
    pic[:5, int(w / 2 - 5):int(w / 2 + 4), 3] = 0            # the neck hole
    sk.box(pic, w / 2 - 1.5, 6, w / 2 + 0.5, h - 2, tuple(0.6 * np.array(green)), False)
    return sk.outline(pic)


def keycard(bright):
    pic = kit.keycard(None, *SPRITES["RKEYA0"])
    if bright:
        opaque = pic[..., 3] > 0
        pic[opaque, :3] = np.minimum(pic[opaque, :3] * 1.35 + 30, 255)
    return pic


def barrel(bright):
    w, h = SPRITES["BAR1A0"]
    pic = kit.barrel(None, w, h)
    if bright:
        pic[:3, :, :3] = np.where(pic[:3, :, 3:] > 0, [150, 255, 110], 0)
    return pic


def centred(pic):
    """Transparent rows below: the picture's middle is at the thing's height (a missile,
    a puff, blood), as DOOM's offsets put them."""
    return np.concatenate([pic, np.zeros_like(pic)], axis=0)


def fireball(flying: bool, k: int, n: int, size=16, violet=False):
    """The imp's fireball (``violet``: the cacodemon's): flying (two flickering frames), or
    bursting (frame k of n)."""
    pic = sk.canvas(size, size)
    c = size / 2 - 0.5
    hue = (lambda r, g, b: (0.9 * r, b, min(1.6 * g, 255))) if violet else (lambda *rgb: rgb)
    if flying:
        sk.glow(pic, c, c, size / 2 - 2 - k, hue(255, 90 + 50 * k, 30))
        return pic
    t = (k + 1) / n                         # a ring growing and going dark
    r = size / 2 - 1
    sk.glow(pic, c, c, r, hue(255 - 100 * t, 150 - 110 * t, 40))
    ys, xs = sk.grid(pic)
    pic[np.hypot(xs - c, ys - c) < r * t * 0.8, 3] = 0
    return pic


def puff(k):
    pic = sk.canvas(12, 12)
    if k == 0:
        sk.glow(pic, 5.5, 5.5, 3, (255, 240, 160))
        return pic
    grey = 200 - 40 * k
    sk.ellipse(pic, 5.5, 6.5 - k, 2 + k, 2 + k, (grey, grey, grey))
    return pic


def blood(frame):
    size = {"A": 1.2, "B": 2.0, "C": 3.0}[frame]
    pic = sk.canvas(10, 12)
    sk.ellipse(pic, 4.5, 6, size, size * 1.3, (170, 0, 0))
    sk.ellipse(pic, 4.5 + size, 8, size * 0.6, size * 0.6, (140, 0, 0))
    return pic


def teleport_fog(k, n, rng):
    """Green-white sparks in a column, rising and thinning out."""
    w, h = 32, 56
    pic = sk.canvas(w, h)
    t = k / (n - 1)
    count = int(40 * (1 - abs(2 * t - 1)) + 6)
    for _ in range(count):
        x, y = rng.normal(w / 2, 5 + 4 * t), rng.uniform(h * (0.5 - 0.4 * t), h - 2)
        sk.glow(pic, x, y, rng.uniform(1.2, 2.5), (120, 255, 140))
    return pic


def barrel_explosion(k, n):
    if k < 2:
        pic = barrel(k == 1)
        return pic
    w, h = 48, 48
    pic = sk.canvas(w, h)
    t = (k - 1) / (n - 2)
    sk.glow(pic, w / 2, h - 16 - 6 * t, 8 + 14 * t, (255, 170 - 90 * t, 40))
    return pic


def rocket():
    """A rocket seen from behind (the way the player sees it fly): a grey body, four
    fins and the burning exhaust."""
    pic = sk.canvas(16, 16)
    for dx, dy in ((0, -1), (0, 1), (-1, 0), (1, 0)):
        sk.box(pic, 7.5 - 1 + dx * 6 - abs(dy), 7.5 - 1 + dy * 6 - abs(dx), 7.5 + 1 + dx * 6
               + abs(dy), 7.5 + 1 + dy * 6 + abs(dx), (86, 88, 92))
    sk.ellipse(pic, 7.5, 7.5, 5, 5, (150, 150, 156))
    sk.glow(pic, 7.5, 7.5, 3.2, (255, 190, 60))
    return sk.outline(pic)


def explosion(k, n, size=40):
    """The rocket's blast: a ball of fire, growing, going red and breaking up."""
    pic = sk.canvas(size, size)
    t = k / max(n - 1, 1)
    c = size / 2 - 0.5
    sk.glow(pic, c, c, size * (0.3 + 0.18 * t), (255, 210 - 130 * t, 60 - 40 * t))
    rng = rng_for(f"MISL{k}")
    ys, xs = sk.grid(pic)
    for _ in range(int(8 * t)):               # holes as it burns out
        x, y = rng.uniform(6, size - 6, 2)
        pic[np.hypot(xs - x, ys - y) < 1 + 3 * t, 3] = 0
    return pic


def health_bonus(k, n):
    """The health bonus (and health_gathering_supreme's poison): a small blue bottle whose
    glass glimmers brighter from frame to frame."""
    w, h = 14, 18
    pic = sk.canvas(w, h)
    glass = np.array([60.0, 96.0, 230.0]) * (0.85 + 0.3 * k / max(n - 1, 1))
    sk.ellipse(pic, w / 2 - 0.5, h - 6.5, 5.5, 5.5, tuple(np.minimum(glass, 255)))
    sk.box(pic, w / 2 - 2.5, 2, w / 2 + 1.5, h - 10, tuple(np.minimum(glass, 255)))
    sk.box(pic, w / 2 - 3, 0, w / 2 + 2, 3, (200, 200, 210))
    sk.ellipse(pic, w / 2 - 2.5, h - 8, 1.3, 1.8 + k * 0.3, (230, 240, 255), False)
    return sk.outline(pic)


def item_pictures(roles: dict) -> dict:
    """The pickups' and effects' pictures, keyed (sprite, frame)."""
    out = {("SHOT", "A"): gun_on_floor(56, 12, (110, 74, 40), 2),
           ("MGUN", "A"): gun_on_floor(54, 16, (60, 60, 66), 4),
           ("CLIP", "A"): clip(), ("SHEL", "A"): shells(),
           ("AMMO", "A"): ammo_box(28, 18, (80, 86, 56), (212, 170, 70), 6),
           ("SBOX", "A"): ammo_box(32, 16, (150, 60, 40), (190, 30, 26), 5),
           ("ARM1", "A"): armour(False), ("ARM1", "B"): armour(True),
           ("RKEY", "A"): keycard(False), ("RKEY", "B"): keycard(True),
           ("BAR1", "A"): barrel(False), ("BAR1", "B"): barrel(True)}
    for (sprite, frame), (_name, k, n, _bright) in roles.items():
        if sprite in ("BAL1", "BAL2"):
            out[sprite, frame] = centred(fireball(_name == "spawnstate", k, n,
                                                  violet=sprite == "BAL2"))
        elif sprite == "MISL":
            out[sprite, frame] = centred(rocket() if _name == "spawnstate"
                                         else explosion(k, n))
        elif sprite == "BON1":
            out[sprite, frame] = health_bonus(k, n)
        elif sprite == "PUFF":
            out[sprite, frame] = centred(puff(k))
        elif sprite == "BLUD":
            out[sprite, frame] = centred(blood(frame))
        elif sprite == "TFOG":
            out[sprite, frame] = teleport_fog(k, n, rng_for(sprite + frame))
        elif sprite == "BEXP":
            out[sprite, frame] = barrel_explosion(k, n)
    return out


# -- wall textures -------------------------------------------------------------------------------

def red_door(w=64, h=72):
    pic = kit.door(rng_for("DOORRED"), w, h, np.array([110.0, 92.0, 80.0]),
                   np.array([60.0, 40.0, 40.0]))
    ys, xs = kit.grid(h, w)
    stripe = ((ys >= 30) & (ys < 42)) & (xs >= 4) & (xs < w - 4)
    return np.where(stripe[..., None], np.array([200.0, 30.0, 24.0]), pic)


def lift(w=64, h=128):
    """A lift's side: grooved metal with a yellow and black band at the top."""
    pic = kit.grooves(rng_for("LIFT1"), w, h, np.array([100.0, 98.0, 86.0]))
    ys, xs = kit.grid(h, w)
    band = ys < 10
    stripes = ((xs + ys) // 6) % 2 == 0
    colour = np.where(stripes[..., None], [220.0, 190.0, 40.0], [30.0, 30.0, 30.0])
    return np.where(band[..., None], colour, pic)


def all_pictures() -> dict[str, np.ndarray]:
    """Relative path → uint8 picture for everything this script draws."""
    roles = frame_roles(LEVEL_TYPES + SCENARIO_TYPES, SPAWNED + SCENARIO_SPAWNED)
    items = item_pictures(roles)
    out = {"DOORRED.png": red_door(), "LIFT1.png": lift()}
    for (sprite, frame), role in sorted(roles.items()):
        name = f"{sprite}{frame}0"
        if name in SPRITES:                   # drawn by make_textures.py
            continue
        if sprite in BODIES or sprite == "HEAD":
            picture = monster_frame(sprite, frame, role)
        elif (sprite, frame) in items:
            picture = items[sprite, frame]
        else:
            raise AssertionError(f"no drawing for {name}")
        out[f"sprites/{name}.png"] = picture
    return {path: kit.to_uint8(p) for path, p in out.items()}


def main() -> int:
    write_pictures(all_pictures(), OUT)
    return 0


if __name__ == "__main__":
    sys.exit(main())
