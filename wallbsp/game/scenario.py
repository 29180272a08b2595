"""Scenarios in Python: what ViZDoom's ACS scripts do, over a ``World``.

A ``Scenario`` is a small class over a level::

    class Basic(Scenario):
        level = "basic"                      # wallbsp/data/scenarios/basic.json, or a path
        skill, start_tics, timeout = 5, 14, 300
        living_reward = -1.0
        buttons = ("MOVE_LEFT", "MOVE_RIGHT", "ATTACK")
        variables = ("AMMO2",)

        def reset(self, world, rng):         # place the player, spawn things
            mo = self.spawn(world, "Cacodemon", 0, rng.uniform(-161, 224), angle=180)
            self.set_health(mo, 1); self.ignore_player(mo)

        def tic(self, world):                # after every tic: the reward of the tic
            reward = -5.0 * self.shots
            if self.killed():
                reward += 106.0; self.exit(world)
            return reward

``events`` (``Events``) are DOOM's own moments, read from the play's event log
(``wallbsp.game.playsim.events``: ``P_DamageMobj``, ``P_KillMobj`` and
``P_TouchSpecialThing`` record them; ``install_events`` makes the reader of one play):
during a tic ``self.events`` is that tic's list of ``Event(kind, target, source, amount,
type)`` with kind ``"damage"``, ``"kill"``, ``"pickup"``, ``"shot"``.  The counters ViZDoom
reports (damage dealt and taken, hits, hits taken) are kept beside them.  What a scenario
changes in the game (damage factors, monsters that ignore the player, its own pickups, no
autoaim) are rules of the play itself (``Play.set_damage_factor``, ``keep_asleep``,
``set_pickup_effect``, ``noautoaim``): no method of the play is replaced.

Helpers (ACS → here): ``Spawn`` → ``spawn``; ``delay`` and timed spawns → ``later``;
``SetActorProperty(APROP_Speed/Health/DamageFactor)`` → ``set_speed``, ``set_health``,
``set_damage_factor``; ``Thing_Hate`` → ``hate_player`` / ``ignore_player``;
``GiveInventory``/``TakeInventory``/``ClearInventory``/``SetWeapon`` → ``give``, ``take``,
``clear_inventory``, ``set_weapon``; ``Thing_Damage`` → ``damage``; ``Thing_Remove`` →
``remove``; ``Exit_Normal`` → ``exit``; ``SetActorPosition`` of the player →
``World.place_player``.  Thing names are ZDoom's class names of DOOM's things
(``THING_TYPES``) or ``MT_*`` numbers.
"""
from __future__ import annotations

from pathlib import Path
from typing import NamedTuple

from wallbsp.doom import info
from wallbsp.game.playsim.events import Damaged, Killed, PickedUp

__all__ = ["Scenario", "Event", "Events", "install_events", "THING_TYPES", "thing_type",
           "SCENARIO_DIR"]

SCENARIO_DIR = Path(__file__).resolve().parent.parent / "data" / "scenarios"
FRAC = 65536

THING_TYPES = {
    "DoomPlayer": info.MT_PLAYER, "ZombieMan": info.MT_POSSESSED,
    "ShotgunGuy": info.MT_SHOTGUY, "ChaingunGuy": info.MT_CHAINGUY,
    "DoomImp": info.MT_TROOP, "Demon": info.MT_SERGEANT, "Spectre": info.MT_SHADOWS,
    "Cacodemon": info.MT_HEAD, "LostSoul": info.MT_SKULL, "BaronOfHell": info.MT_BRUISER,
    "Revenant": info.MT_UNDEAD, "Arachnotron": info.MT_BABY, "Cyberdemon": info.MT_CYBORG,
    "Medikit": info.MT_MISC11, "Stimpack": info.MT_MISC10, "HealthBonus": info.MT_MISC2,
    "ArmorBonus": info.MT_MISC3, "GreenArmor": info.MT_MISC0, "BlueArmor": info.MT_MISC1,
    "Clip": info.MT_CLIP, "ClipBox": info.MT_MISC17, "Shell": info.MT_MISC22,
    "RocketAmmo": info.MT_MISC18, "Cell": info.MT_MISC20, "Shotgun": info.MT_SHOTGUN,
    "Chaingun": info.MT_CHAINGUN, "RocketLauncher": info.MT_MISC27,
    "ExplosiveBarrel": info.MT_BARREL,
}
WEAPONS = {"Fist": info.wp_fist, "Pistol": info.wp_pistol, "Shotgun": info.wp_shotgun,
           "Chaingun": info.wp_chaingun, "RocketLauncher": info.wp_missile,
           "PlasmaRifle": info.wp_plasma, "BFG9000": info.wp_bfg,
           "Chainsaw": info.wp_chainsaw, "SuperShotgun": info.wp_supershotgun}
AMMO = {"Clip": info.am_clip, "Shell": info.am_shell, "RocketAmmo": info.am_misl,
        "Cell": info.am_cell}
AMMO["ClipBox"], AMMO["ShellBox"] = info.am_clip, info.am_shell
WEAPON_AMMO = {info.wp_pistol: 20, info.wp_shotgun: 8, info.wp_chaingun: 20,
               info.wp_missile: 2, info.wp_plasma: 40, info.wp_bfg: 40,
               info.wp_supershotgun: 8}        # ZDoom's AmmoGive of a weapon given


def thing_type(name) -> int:
    """The ``MT_*`` number of a ZDoom class name (``THING_TYPES``) or of an ``MT_*``."""
    if isinstance(name, str):
        if name not in THING_TYPES:
            raise ValueError(f"unknown thing {name!r} (known: {sorted(THING_TYPES)})")
        return THING_TYPES[name]
    return int(name)


class Event(NamedTuple):
    kind: str                 # "damage", "kill", "pickup", "shot"
    target: object = None     # the mobj damaged, killed or picked up
    source: object = None     # who did it (a mobj, or None: the world)
    amount: int = 0           # health taken away; rounds fired
    type: int = -1            # the target's MT_* number


class Events:
    """What one play's event log said, as a scenario reads it (module docstring), and the
    rules a scenario sets on that play."""

    def __init__(self, play):
        self.play = play
        self.events: list[Event] = []
        # ViZDoom's counters of player 0 (DAMAGECOUNT, HITCOUNT, ...; current after read())
        self.damage_dealt = self.hits = self.damage_taken = self.hits_taken = 0
        self._ammo = sum(play.players[0].ammo)
        play.take_events()                  # what came before (the level's start) is not ours

    # -- the play's rules (playsim: damage.py, monsters.py, interact.py, hitscan.py) --------
    def set_factor(self, mo, factor) -> None:
        self.play.set_damage_factor(mo, factor)

    def ignore(self, mo) -> None:
        self.play.keep_asleep(mo)

    def on_pickup(self, mo, effect) -> None:
        self.play.set_pickup_effect(mo, effect)

    @property
    def noautoaim(self) -> bool:
        return self.play.noautoaim

    @noautoaim.setter
    def noautoaim(self, value) -> None:
        self.play.noautoaim = bool(value)

    # -- the log ------------------------------------------------------------------------
    def read(self) -> None:
        """Takes the play's log into ``events`` and the counters (the play is read by
        this one reader: whatever else takes its log takes it from here)."""
        log = self.play.take_events()
        if not log:
            return
        me = self.play.players[0]
        append = self.events.append
        for e in log:
            kind = type(e)
            if kind is Damaged:
                if e.amount <= 0:
                    continue
                target = e.target
                append(Event("damage", target, e.source, e.amount, target.type))
                if e.source is me.mo and target is not me.mo:
                    self.damage_dealt += e.amount
                    self.hits += 1
                if target.player is me:     # the player's health stops at 0
                    self.damage_taken += e.amount + min(0, e.health)
                    self.hits_taken += 1
            elif kind is Killed:
                append(Event("kill", e.target, e.source, 0, e.target.type))
            elif kind is PickedUp:
                append(Event("pickup", e.item, e.toucher, 0, e.item.type))

    def after_tic(self) -> None:
        """Reads the log and the rounds the player fired this tic (call after each tic)."""
        self.read()
        ammo = sum(self.play.players[0].ammo)
        if ammo < self._ammo:
            self.events.append(Event("shot", None, self.play.players[0].mo,
                                     self._ammo - ammo))
        self._ammo = ammo

    def take(self) -> list[Event]:
        """The events since the last take; the list starts again."""
        self.read()
        events, self.events = self.events, []
        return events


def install_events(world) -> Events:
    """The reader of ``world.play``'s event log (module docstring)."""
    return Events(world.play)


class Scenario:
    """A level and its rules (module docstring).  Override ``reset``, ``tic``, ``done``."""

    level = None              # a name in wallbsp/data/scenarios, a level path or a tree
    skill = 3                 # 1-5 (ViZDoom's doom_skill)
    start_tics = 1            # ViZDoom's episode_start_time (its default 1): tics before
                              # the first action
    timeout = None            # ViZDoom's episode_timeout: the agent's tics after those
    living_reward = 0.0
    death_penalty = 0.0
    buttons: tuple = ()
    variables: tuple = ()
    render_weapon = True      # the environment draws the weapon in hand (ViZDoom's default);
                              # False where ZDoom's ClearInventory leaves no weapon at all
                              # (DOOM's player always keeps the fist)

    def __init__(self):
        self.events: list[Event] = []
        self.recorder: Events | None = None
        self._timers: list = []
        self._seq = 0

    # -- what a scenario says -----------------------------------------------------------
    def reset(self, world, rng) -> None:
        """Set the episode up (the player, things, timers); ``rng``: numpy's Generator."""

    def tic(self, world) -> float:
        """After each tic: its reward beyond ``living_reward`` and ``death_penalty``."""
        return 0.0

    def done(self, world) -> bool:
        """Whether the episode is over (besides the player's death and an exit)."""
        return False

    # -- run by the environment ---------------------------------------------------------
    def begin(self, world, rng) -> None:
        self.recorder = install_events(world)
        self.events, self._timers, self._seq = [], [], 0
        self.weapon_up(world)
        self.reset(world, rng)

    def after_tic(self, world) -> float:
        self.recorder.after_tic()
        self.events = self.recorder.take()
        now = world.play.leveltime
        while self._timers and self._timers[0][0] <= now:
            _, _, call = self._timers.pop(0)
            call()
        return float(self.tic(world))

    # -- events of this tic ----------------------------------------------------------------
    def killed(self, mtype=None) -> list:
        """The mobjs killed this tic (of type ``mtype``: a name or MT_ number)."""
        want = None if mtype is None else thing_type(mtype)
        return [e.target for e in self.events
                if e.kind == "kill" and (want is None or e.type == want)]

    def picked_up(self, mtype=None) -> list:
        want = None if mtype is None else thing_type(mtype)
        return [e.target for e in self.events
                if e.kind == "pickup" and (want is None or e.type == want)]

    @property
    def shots(self) -> int:
        """Rounds the player fired this tic."""
        if not self.events:
            return 0
        return sum(e.amount for e in self.events if e.kind == "shot")

    # -- the helpers ---------------------------------------------------------------------
    def later(self, world, tics: int, call) -> None:
        """Call ``call()`` after ``tics`` tics (ACS's ``delay``)."""
        due = world.play.leveltime + max(1, int(tics))
        self._seq += 1
        self._timers.append((due, self._seq, call))
        self._timers.sort(key=lambda t: (t[0], t[1]))

    @staticmethod
    def spawn(world, kind, x, y, angle=0.0, z=None, check=True):
        """A new thing of ``kind`` at (x, y) (on the floor, or at height ``z``) facing
        ``angle`` degrees; None if it does not fit there (ACS's ``Spawn`` returning 0)."""
        play, mtype = world.play, thing_type(kind)
        mo = play.p_spawn_mobj(int(round(x * FRAC)), int(round(y * FRAC)),
                               info.ONFLOORZ if z is None else int(round(z * FRAC)), mtype)
        mo.angle = int(round(angle % 360.0 * (1 << 32) / 360.0)) & 0xFFFFFFFF
        # ViZDoom's spawned monsters see the player at their first look, every one; DOOM's
        # P_LookForPlayers, from a random lastlook, gives up without looking one time in
        # four in a single-player game (its "stop" is the player it reaches last)
        mo.lastlook = next((i for i, on in enumerate(play.playeringame) if on), 0)
        if check:
            flags = mo.flags
            if flags & (info.MF_SOLID | info.MF_SHOOTABLE):
                mo.flags |= info.MF_SOLID
                fits = play.p_check_position(mo, mo.x, mo.y)
                mo.flags = flags
            else:                   # ZDoom: solid things do not block what is not solid
                fits = play.p_check_lines(mo, mo.x, mo.y)
            if not fits or not _inside(world, mo):
                play.p_remove_mobj(mo)
                return None
        return mo

    def on_pickup(self, mo, effect) -> None:
        """Picking ``mo`` up calls ``effect(player)`` (DOOM's ``player_t``) instead of
        DOOM's rule for its type, and always succeeds (a DECORATE item with
        ``INVENTORY.ALWAYSPICKUP``)."""
        self.recorder.on_pickup(mo, effect)

    @staticmethod
    def remove(world, mo) -> None:
        if mo.func is not None:
            world.play.p_remove_mobj(mo)

    @staticmethod
    def set_speed(mo, speed) -> None:
        """The thing's speed (map units a step; its own copy of DOOM's record)."""
        mo.info = mo.info._replace(speed=int(speed))

    @staticmethod
    def set_health(mo, health) -> None:
        mo.health = int(health)

    def set_damage_factor(self, mo, factor) -> None:
        """Damage to ``mo`` is multiplied by ``factor`` (ZDoom's APROP_DamageFactor)."""
        self.recorder.set_factor(mo, factor)

    def ignore_player(self, mo) -> None:
        """The thing never wakes (ViZDoom's ``Thing_Hate`` of a thing that is not there):
        its ``A_Look`` does nothing; shot, it still feels pain."""
        self.recorder.ignore(mo)

    @staticmethod
    def hate_player(world, mo) -> None:
        """The thing hunts the player now."""
        mo.target = world.play.players[0].mo
        mo.threshold = 0
        if mo.state == mo.info.spawnstate and mo.info.seestate:
            world.play.p_set_mobj_state(mo, mo.info.seestate)

    @staticmethod
    def give(world, item, amount=1) -> None:
        """A weapon (with ZDoom's ammo), ammo (rounds, up to the limit), ``"Health"`` (up to
        100) or ``"Armor"``."""
        p = world.play.players[0]
        if item in WEAPONS:
            wp = WEAPONS[item]
            p.weaponowned[wp] = True
            ammo = info.WEAPONINFO[wp].ammo
            if wp in WEAPON_AMMO:
                p.ammo[ammo] = min(p.maxammo[ammo], p.ammo[ammo] + WEAPON_AMMO[wp])
        elif item in AMMO:
            a = AMMO[item]
            p.ammo[a] = min(p.maxammo[a], p.ammo[a] + int(amount))
        elif item == "Health":
            p.health = min(100, p.health + int(amount))
            p.mo.health = p.health
        elif item == "Armor":
            p.armorpoints, p.armortype = int(amount), max(p.armortype, 1)
        else:
            raise ValueError(f"give: unknown item {item!r}")

    @staticmethod
    def take(world, item, amount=None) -> None:
        p = world.play.players[0]
        if item in WEAPONS:
            p.weaponowned[WEAPONS[item]] = False
        elif item in AMMO:
            a = AMMO[item]
            p.ammo[a] = 0 if amount is None else max(0, p.ammo[a] - int(amount))
        else:
            raise ValueError(f"take: unknown item {item!r}")

    @staticmethod
    def clear_inventory(world) -> None:
        """No weapons but the fist, no ammo, no armour, no keys."""
        p = world.play.players[0]
        p.weaponowned = [wp == info.wp_fist for wp in range(len(p.weaponowned))]
        p.ammo = [0] * len(p.ammo)
        p.armorpoints = p.armortype = 0
        p.cards = [False] * len(p.cards)
        Scenario.set_weapon(world, "Fist")

    @staticmethod
    def set_weapon(world, weapon) -> None:
        """The weapon in hand now, already raised (ACS's ``SetWeapon`` at the start)."""
        p = world.play.players[0]
        p.readyweapon = p.pendingweapon = WEAPONS[weapon]
        Scenario.weapon_up(world)

    @staticmethod
    def weapon_up(world) -> None:
        """The weapon in hand ready to fire now, as ZDoom has it when a level starts (DOOM
        raises it from the bottom of the screen first)."""
        from wallbsp.game.playsim.weapons import PS_WEAPON, WEAPONTOP
        play, p = world.play, world.play.players[0]
        play.p_setup_psprites(p)
        p.psprites[PS_WEAPON].sy = WEAPONTOP
        play.p_set_psprite(p, PS_WEAPON, play.weaponinfo[p.readyweapon].readystate)

    @staticmethod
    def damage(world, amount, target=None) -> None:
        """``amount`` damage to ``target`` (the player by default), from the world."""
        play = world.play
        play.p_damage_mobj(target or play.players[0].mo, None, None, int(amount))

    @staticmethod
    def exit(world) -> None:
        """Leave the level (``Exit_Normal``): the episode ends after this tic."""
        world.play.g_exit_level()


def _inside(world, mo) -> bool:
    """The thing's box lies within the map (each corner is in one of the level's sectors).
    The corners are taken a fixed-point unit inside the box: a box that touches a wall is
    in the map, as DOOM's PIT_CheckLine lets it be (ACS's ``Spawn`` at y = 20 of a radius-20
    imp against the wall at y = 0, in take_cover)."""
    r = (mo.radius - 1) / FRAC
    x, y = mo.x / FRAC, mo.y / FRAC
    return all(world.tree.locate(x + dx, y + dy) is not None
               for dx in (-r, r) for dy in (-r, r))
