"""Spitter Hall's own things: a monster with a new attack, its spit, a weapon, its ammunition
and the item that gives it (docs/modding.md walks through this file)."""
from wallbsp import content
from wallbsp.content.doom import DoomImp, DoomImpBall


class SpitBall(DoomImpBall):          # the imp's fireball, changed
    speed = 15                        # map units a tic
    damage = 1                        # DOOM's missile damage: 1d8 times this
    see_sound = "spitfi"              # sounds/DSSPITFI.wav
    states = """
    Spawn:    SPBL AB 4 bright
              loop
    Death:    SPBL CDE 5 bright
              stop"""


class Spitter(DoomImp):               # the imp's sounds, speed and pain; our own look
    editor_number = 30001
    health = 60
    see_sound = "spitsi"
    states = """
    Spawn:    SPIT AB 10 A_Look
              loop
    See:      SPIT AABBCCDD 3 A_Chase
              loop
    Melee:                            # close up it spits too (the imp would claw)
    Missile:  SPIT E 8 A_FaceTarget
              SPIT F 6 spit
              goto See
    Death:    SPIT G 8
              SPIT H 8 A_Scream
              SPIT I 8 A_Fall
              SPIT J -1
              stop"""

    def spit(play, actor):
        """The new attack: two balls at once, the second veering left."""
        if actor.target is None:
            return
        content.spawn_missile(play, actor, actor.target, SpitBall)
        ball = content.spawn_missile(play, actor, actor.target, SpitBall)
        ball.momx, ball.momy = ball.momx - ball.momy // 8, ball.momy + ball.momx // 8


class Gel(content.Ammo):              # the blaster's own ammunition, and a can of it
    editor_number = 30003
    max_amount, backpack_max = 100, 200
    clip = 20                         # a can holds a clip; the blaster comes with two
    message = "Picked up a can of gel."
    states = """
    Spawn:    GELA A -1
              stop"""


class Blaster(content.Weapon):
    slot = 2                          # the pistol's key
    ammo = Gel
    ammo_use = 2
    states = """
    Ready:    BLSG A 1 A_WeaponReady
              loop
    Deselect: BLSG A 1 A_Lower
              loop
    Select:   BLSG A 1 A_Raise
              loop
    Fire:     BLSG B 3 fire
              BLSG C 5
              BLSG A 5 A_ReFire
              goto Ready"""

    def fire(play, player, psp):
        content.use_ammo(play, player)
        content.spawn_player_missile(play, player, SpitBall)


class BlasterPickup(content.Item):
    editor_number = 30002
    weapon = Blaster                  # and two clips of gel, as DOOM's weapons give
    message = "You got the blaster!"
    states = """
    Spawn:    BLSP A -1
              stop"""
