"""ViZDoom's scenarios in one room each (basic, defend_the_center, health_gathering,
take_cover, defend_the_line) as ``Scenario`` classes (``wallbsp.envs.vizdoom``)."""
from __future__ import annotations

import math

from wallbsp.game.scenario import Scenario

__all__ = ["Basic", "DefendTheCenter", "HealthGathering", "TakeCover", "DefendTheLine"]


class Basic(Scenario):
    """basic: a cacodemon that never moves or fights, one hit kills it, at a random spot
    on the far wall; -5 a bullet, +106 for the kill (which ends the episode), -1 a tic."""
    level = "basic"
    skill, start_tics, timeout = 5, 14, 300
    living_reward = -1.0
    buttons = ("MOVE_LEFT", "MOVE_RIGHT", "ATTACK")
    variables = ("AMMO2",)

    def reset(self, world, rng):
        self.take(world, "Fist")
        # ACS: Random(-161.0, 224.0), a fixed-point number
        y = rng.integers(-161 * 65536, 224 * 65536, endpoint=True) / 65536
        mo = self.spawn(world, "Cacodemon", 0.0, y, angle=180.0, check=False)
        self.set_speed(mo, 0)
        self.set_health(mo, 1)
        self.ignore_player(mo)

    def tic(self, world):
        reward = -5.0 if self.shots else 0.0
        if self.killed():
            reward += 106.0
            self.exit(world)
        return reward


class DefendTheCenter(Scenario):
    """defend_the_center: five one-hit monsters (demons and chainsaw marines, alternating)
    on a circle of radius 735 walk in; each kill +1 and the same kind comes back 90 tics
    later at a random angle; a pistol with 26 bullets; -1 for dying."""
    level = "defend_the_center"
    skill, start_tics, timeout = 3, 10, 2100
    death_penalty = 1.0
    buttons = ("TURN_LEFT", "TURN_RIGHT", "ATTACK")
    variables = ("AMMO2", "HEALTH")
    radius = 735.0
    # ViZDoom's MarineChainsawVzd has no DOOM counterpart: a demon at a marine's pace
    # (ZDoom's marine: 8 units a chase step of 4 tics; a demon steps every 2 tics, so 4)
    # and with a marine's radius (16, a thinner target)
    kinds = (("Demon", 4, 16), ("Demon", 10, 30))

    def reset(self, world, rng):
        self.rng, self.tracked = rng, {}
        for i, turn in enumerate((0, 13107, 26214, 39322, 52429)):   # 0.0, 0.2, ... 0.8
            self._spawn(world, i % 2, turn)
        self.clear_inventory(world)
        self.give(world, "Pistol")
        self.set_weapon(world, "Pistol")
        self.give(world, "ClipBox", 6)

    def _spawn(self, world, kind, turn) -> bool:
        """ACS: at ``turn`` (a fixed-point fraction of a circle, 65536 the whole) on the
        circle, facing byte angle ``(turn + 128) % 256`` (the script adds a byte angle to
        a fixed-point turn: monsters face all ways, and wake when they see or hear)."""
        a = 2 * math.pi * turn / 65536
        name, speed, radius = self.kinds[kind]
        mo = self.spawn(world, name, math.cos(a) * self.radius, math.sin(a) * self.radius,
                        angle=(turn + 128) % 256 * 360.0 / 256)
        if mo is None:
            return False
        self.set_speed(mo, speed)
        self.set_health(mo, 1)
        mo.radius = radius << 16
        self.tracked[mo] = kind
        return True

    def _respawn(self, world, kind, turn=None):
        if turn is None:
            turn = int(self.rng.integers(0, 65536, endpoint=True))  # ACS: random(0, 1.0)
        if not self._spawn(world, kind, turn):                      # the same place again
            self.later(world, 1, lambda: self._respawn(world, kind, turn))

    def tic(self, world):
        reward = 0.0
        for mo in self.killed():
            kind = self.tracked.pop(mo, None)
            if kind is None:
                continue
            self.remove(world, mo)
            reward += 1.0
            self.later(world, 90, lambda k=kind: self._respawn(world, k))
        return reward


class HealthGathering(Scenario):
    """health_gathering: a square room of acid (8 damage every 32 tics), 16 medikits at
    the start and one more every 30 tics at random spots; +1 a tic alive, -100 for dying."""
    level = "health_gathering"
    skill, start_tics, timeout = 3, 1, 2100
    living_reward, death_penalty = 1.0, 100.0
    buttons = ("TURN_LEFT", "TURN_RIGHT", "MOVE_FORWARD")
    variables = ("HEALTH",)
    render_weapon = False               # ClearInventory: empty-handed in ViZDoom
    size, first, every, item = 1216.0, 16, 30, "Medikit"
    acid, acid_every = 8, 32

    def reset(self, world, rng):
        self.rng = rng
        self.clear_inventory(world)
        for _ in range(self.first):
            self._item(world)
        self._loop(world)

    def _item(self, world):
        while True:
            x = self.rng.uniform(1.0, self.size - 1.0)
            y = self.rng.uniform(1.0, self.size - 1.0)
            if self.spawn(world, self.item, x, y) is not None:
                return

    def _loop(self, world):
        self._item(world)
        self.later(world, self.every, lambda: self._loop(world))

    def tic(self, world):
        # ZDoom's dDamage_LavaHefty: 8 points when the level's clock is a multiple of 32
        if (world.play.leveltime - 1) % self.acid_every == 0 and not world.dead:
            self.damage(world, self.acid)
        return 0.0


class TakeCover(Scenario):
    """take_cover: imps that never move (and no fireball hurts them) fire from the far
    wall, three at first and one more every 60 tics; the player, unarmed, takes 7 times
    the damage; +1 a tic alive; no time limit."""
    level = "take_cover"
    skill, start_tics, timeout = 4, 1, None
    living_reward = 1.0
    buttons = ("MOVE_LEFT", "MOVE_RIGHT")
    variables = ("HEALTH",)
    render_weapon = False               # ClearInventory: empty-handed in ViZDoom

    def reset(self, world, rng):
        self.rng = rng
        for y in (20.0, 278.0, 652.0):
            self._imp(world, y)
        self.later(world, 60, lambda: self._loop(world))
        self.set_damage_factor(world.play.players[0].mo, 7.0)
        self.clear_inventory(world)

    def _imp(self, world, y):
        mo = self.spawn(world, "DoomImp", 64.0, y, angle=180.0)
        if mo is not None:
            self.set_speed(mo, 0)
            self.set_damage_factor(mo, 0.0)

    def _loop(self, world):
        self._imp(world, self.rng.uniform(20.0, 652.0))
        self.later(world, 60, lambda: self._loop(world))


class DefendTheLine(Scenario):
    """defend_the_line: three imps that never move and three demons at the far wall,
    one hit each at first; each kill +1 and the monster comes back at its place 90 tics
    later with 4 more health; unlimited bullets; -1 for dying; no time limit."""
    level = "defend_the_line"
    skill, start_tics, timeout = 3, 10, None
    death_penalty = 1.0
    buttons = ("TURN_LEFT", "TURN_RIGHT", "ATTACK")
    variables = ("AMMO2", "HEALTH")

    def reset(self, world, rng):
        self.tracked = {}
        for y in (90.0, 200.0, 400.0):
            self._monster(world, "DoomImp", y, 1)
        for y in (150.0, 300.0, 450.0):
            self._monster(world, "Demon", y, 1)
        self.give(world, "Clip", 20)

    def _monster(self, world, kind, y, health) -> bool:
        mo = self.spawn(world, kind, 64.0, y, angle=180.0)
        if mo is None:
            return False
        if kind == "DoomImp":
            self.set_speed(mo, 0)
        self.set_health(mo, health)
        self.tracked[mo] = (kind, y, health + 4)
        return True

    def _respawn(self, world, kind, y, health):
        if not self._monster(world, kind, y, health):
            self.later(world, 2, lambda: self._respawn(world, kind, y, health))

    def tic(self, world):
        if world.play.leveltime > 1:             # ACS: delay(1), then a bullet a tic
            self.give(world, "Clip", 1)
        reward = 0.0
        for mo in self.killed():
            spec = self.tracked.pop(mo, None)
            if spec is None:
                continue
            self.remove(world, mo)
            reward += 1.0
            self.later(world, 90, lambda s=spec: self._respawn(world, *s))
        return reward
