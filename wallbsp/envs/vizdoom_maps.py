"""ViZDoom's scenarios on ViZDoom's own maps (my_way_home, deadly_corridor,
health_gathering_supreme, predict_position) as ``Scenario`` classes
(``wallbsp.envs.vizdoom``): the maps and their things' places are converted from a ViZDoom
installation when first used (``vizdoom_source``)."""
from __future__ import annotations

from wallbsp.envs.vizdoom_rooms import HealthGathering
from wallbsp.envs.vizdoom_source import spots as map_spots
from wallbsp.game.scenario import Scenario

__all__ = ["MyWayHome", "DeadlyCorridor", "HealthGatheringSupreme", "PredictPosition"]


class MyWayHome(Scenario):
    """my_way_home: a maze of rooms; the player starts at one of 17 spots, facing a random
    way; the green armour at (1040, -352) is +1 and the end; -0.0001 a tic."""
    level = "my_way_home"
    skill, start_tics, timeout = 5, 10, 2100
    living_reward = -0.0001
    buttons = ("TURN_LEFT", "TURN_RIGHT", "MOVE_FORWARD", "MOVE_LEFT", "MOVE_RIGHT")
    variables = ()
    render_weapon = False               # ClearInventory: empty-handed in ViZDoom

    def reset(self, world, rng):
        things = map_spots(self.level)
        spots = [(t["x"], t["y"]) for t in things if t["type"] == 9001]
        x, y = spots[int(rng.integers(len(spots)))]     # ACS: random(10, 26), the tids
        turn = int(rng.integers(0, 65536, endpoint=True))  # ACS: random(0, 1.0)
        world.place_player(x, y, turn * 360.0 / 65536 % 360.0)
        for t in things:
            if t["type"] == 2018:
                self.spawn(world, "GreenArmor", t["x"], t["y"], angle=t["angle"], check=False)
        self.clear_inventory(world)

    def tic(self, world):
        if self.picked_up("GreenArmor"):
            self.exit(world)
            return 1.0
        return 0.0


class DeadlyCorridor(Scenario):
    """deadly_corridor: a corridor with six one-hit gunmen that never move (zombiemen,
    shotgun guys, chaingunners at skill 5) on its sides and the green armour at its end
    (x = 1312); the reward is the player's progress along x each tic, +1000 for the
    armour (which ends the episode), -100 for dying; the player takes double damage."""
    level = "deadly_corridor"
    skill, start_tics, timeout = 5, 1, 2100
    death_penalty = 100.0
    buttons = ("MOVE_LEFT", "MOVE_RIGHT", "ATTACK", "MOVE_FORWARD", "MOVE_BACKWARD",
               "TURN_LEFT", "TURN_RIGHT")
    variables = ("HEALTH",)
    MONSTERS = {9: "ShotgunGuy", 3004: "ZombieMan", 65: "ChaingunGuy"}

    def reset(self, world, rng):
        for t in map_spots(self.level):
            if t["type"] in self.MONSTERS:
                mo = self.spawn(world, self.MONSTERS[t["type"]], t["x"], t["y"],
                                angle=t["angle"], check=False)
                self.set_speed(mo, 0)
                self.set_health(mo, 1)
            elif t["type"] == 2018:
                self.spawn(world, "GreenArmor", t["x"], t["y"], angle=t["angle"],
                           check=False)
        self.set_damage_factor(world.play.players[0].mo, 2.0)
        self.clear_inventory(world)
        self.give(world, "Pistol")
        self.set_weapon(world, "Pistol")
        self.give(world, "ClipBox", 6)
        self.x = world.player.x

    def tic(self, world):
        x = world.player.x
        reward, self.x = x - self.x, x
        if self.picked_up("GreenArmor"):
            reward += 1000.0
            self.exit(world)
        return reward


class HealthGatheringSupreme(HealthGathering):
    """health_gathering_supreme: a larger acid room (1856) with pillars; 30 medikits of 20
    health (always picked up) and 2 poisons (30 damage) at first, then a medikit and a
    poison, 25 tics, a medikit, 25 tics, ...; the player starts at one of 12 spots facing
    a random way; +1 a tic alive, -100 for dying."""
    level = "health_gathering_supreme"
    size, first, poisons, every = 1856.0, 30, 2, 25

    def reset(self, world, rng):
        self.rng = rng
        for _ in range(self.first):
            self._item(world)
        for _ in range(self.poisons):
            self._poison(world)
        self._loop(world)
        spots = [(t["x"], t["y"]) for t in map_spots(self.level) if t["type"] == 9001]
        x, y = spots[int(rng.integers(len(spots)))]     # ACS: random(10, 21), the tids
        turn = int(rng.integers(0, 65536, endpoint=True))
        world.place_player(x, y, turn * 360.0 / 65536 % 360.0)
        self.clear_inventory(world)

    def _place(self, world, kind):
        while True:
            mo = self.spawn(world, kind, self.rng.uniform(1.0, self.size - 1.0),
                            self.rng.uniform(1.0, self.size - 1.0))
            if mo is not None:
                return mo

    def _item(self, world):
        self.on_pickup(self._place(world, "Medikit"), _heal)

    def _poison(self, world):
        # DECORATE's Poison: the health bonus's picture, counted as an item
        self.on_pickup(self._place(world, "HealthBonus"),
                       lambda p: _poisoned(world, p))

    def _loop(self, world):
        self._item(world)
        self._poison(world)
        self.later(world, self.every, lambda: self._second(world))

    def _second(self, world):
        self._item(world)
        self.later(world, self.every, lambda: self._loop(world))


class PredictPosition(Scenario):
    """predict_position: a cacodemon (120 health, never attacking) flies along a line at a
    random x in [0, 200] from a random y towards one end; the player has a rocket
    launcher with one rocket and no autoaim and cannot be hurt; the kill is +1 and the end,
    the rocket spent ends the episode 45 tics later; -0.001 a tic."""
    level = "predict_position"
    skill, start_tics, timeout = 1, 16, 300
    living_reward = -0.001
    buttons = ("TURN_LEFT", "TURN_RIGHT", "ATTACK")
    variables = ()
    speed = 20.0 / 3          # ZDoom's speed 20 a chase step, one step every 3 tics

    def reset(self, world, rng):
        fixed = lambda lo, hi: int(rng.integers(lo * 65536, hi * 65536, endpoint=True)) / 65536
        x = fixed(0, 200)
        self.caco = self.spawn(world, "Cacodemon", x, fixed(-600, 600), angle=180.0,
                               check=False)
        self.set_health(self.caco, 120)
        self.ignore_player(self.caco)
        self.goal = 608.0 if fixed(0, 1) > 0.5 else -608.0
        self.recorder.noautoaim = True
        self.set_damage_factor(world.play.players[0].mo, 0.0)
        self.clear_inventory(world)
        self.give(world, "RocketLauncher")
        self.take(world, "RocketAmmo", 1)
        self.set_weapon(world, "RocketLauncher")
        self.ending = False

    def tic(self, world):
        if self.killed("Cacodemon"):
            self.exit(world)
            return 1.0
        mo, play = self.caco, world.play
        if mo.health > 0 and mo.func is not None:
            y = mo.y / 65536
            step = max(-self.speed, min(self.speed, self.goal - y))
            if step:
                play.p_unset_thing_position(mo)
                mo.y += int(round(step * 65536))
                play.p_set_thing_position(mo)
        if not self.ending and world.play.players[0].ammo[3] == 0:     # am_misl
            self.ending = True
            self.later(world, 45, lambda: self.exit(world))
        return 0.0


def _heal(player):
    player.health = min(100, player.health + 20)
    player.mo.health = player.health
    player.bonuscount += 6


def _poisoned(world, player):
    player.itemcount += 1
    world.play.p_damage_mobj(player.mo, None, None, 30)
