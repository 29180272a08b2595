"""A small game's classes for the content tests: a monster with its own attack (a Python
action), its projectile, a weapon and the item that gives it, and a health item."""
from wallbsp import content
from wallbsp.content.doom import DoomImp, DoomImpBall


class SpitBall(DoomImpBall):
    speed = 15
    damage = 2
    see_sound = "spitfi"
    states = """
    Spawn:
        SPBL AB 4 bright
        loop
    Death:
        SPBL CDE 5 bright
        stop
    """


class Spitter(DoomImp):
    editor_number = 30001
    health = 60
    painchance = 0
    see_sound = "spitsi"
    states = """
    Spawn:
        SPIT AB 10 A_Look
        loop
    See:
        SPIT AABBCCDD 3 A_Chase
        loop
    Missile:
        SPIT E 8 A_FaceTarget
        SPIT F 6 spit
        goto See
    Death:
        SPIT G 8
        SPIT H 8 A_Scream
        SPIT I 8 A_Fall
        SPIT J -1
        stop
    """

    def spit(play, actor):
        """The new attack: two balls, the second a little to the left."""
        if actor.target is None:
            return
        content.spawn_missile(play, actor, actor.target, SpitBall)
        ball = content.spawn_missile(play, actor, actor.target, SpitBall)
        ball.momx, ball.momy = ball.momx - ball.momy // 8, ball.momy + ball.momx // 8


class Blaster(content.Weapon):
    slot = 2
    ammo = "cell"
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
              goto Ready
    """

    def fire(play, player, psp):
        content.use_ammo(play, player)
        content.spawn_player_missile(play, player, SpitBall)


class BlasterPickup(content.Item):
    editor_number = 30002
    weapon = Blaster
    message = "You got the blaster!"
    states = "Spawn: BLSP A -1\n stop"


class Mushroom(content.Item):
    editor_number = 30003
    health_given = 5
    max_health = 150
    message = "A mushroom."
    states = "Spawn: MUSH AB 6\n loop"
