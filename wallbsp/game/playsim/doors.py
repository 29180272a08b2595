"""``p_doors.c``: vertical doors (``vldoor_t``, in ``spectypes.py``): the thinker, the tagged
doors of switches and walk-over lines, the manual doors a player or monster uses, and the
doors that special sectors start with.

No per-level state of its own.
"""
from wallbsp.doom import info
from wallbsp.doom.fixed import FRACUNIT

from .spectypes import (CRUSHED, PASTDEST, TICRATE, VDOORSPEED, VDOORWAIT, VLD_BLAZECLOSE,
                        VLD_BLAZEOPEN, VLD_BLAZERAISE, VLD_CLOSE, VLD_CLOSE30THENOPEN,
                        VLD_NORMAL, VLD_OPEN, VLD_RAISEIN5MINS, vldoor_t)

PD_BLUEO = "You need a blue key to activate this object"
PD_REDO = "You need a red key to activate this object"
PD_YELLOWO = "You need a yellow key to activate this object"
PD_BLUEK = "You need a blue key to open this door"
PD_REDK = "You need a red key to open this door"
PD_YELLOWK = "You need a yellow key to open this door"

# EV_DoLockedDoor's switches: special -> (card, skull, message)
_LOCKED_SWITCHES = {
    99: ("it_bluecard", "it_blueskull", PD_BLUEO), 133: ("it_bluecard", "it_blueskull", PD_BLUEO),
    134: ("it_redcard", "it_redskull", PD_REDO), 135: ("it_redcard", "it_redskull", PD_REDO),
    136: ("it_yellowcard", "it_yellowskull", PD_YELLOWO),
    137: ("it_yellowcard", "it_yellowskull", PD_YELLOWO),
}
# EV_VerticalDoor's locked doors
_LOCKED_DOORS = {
    26: ("it_bluecard", "it_blueskull", PD_BLUEK), 32: ("it_bluecard", "it_blueskull", PD_BLUEK),
    27: ("it_yellowcard", "it_yellowskull", PD_YELLOWK),
    34: ("it_yellowcard", "it_yellowskull", PD_YELLOWK),
    28: ("it_redcard", "it_redskull", PD_REDK), 33: ("it_redcard", "it_redskull", PD_REDK),
}
# manual doors that go back up or down when used while moving ("raise", not "open")
_REUSABLE = (1, 26, 27, 28, 117)
# the manual door each special makes: special -> (type, speed, one-shot)
_MANUAL = {
    1: (VLD_NORMAL, VDOORSPEED, False), 26: (VLD_NORMAL, VDOORSPEED, False),
    27: (VLD_NORMAL, VDOORSPEED, False), 28: (VLD_NORMAL, VDOORSPEED, False),
    31: (VLD_OPEN, VDOORSPEED, True), 32: (VLD_OPEN, VDOORSPEED, True),
    33: (VLD_OPEN, VDOORSPEED, True), 34: (VLD_OPEN, VDOORSPEED, True),
    117: (VLD_BLAZERAISE, VDOORSPEED * 4, False),
    118: (VLD_BLAZEOPEN, VDOORSPEED * 4, True),
}


class Doors:
    # -- the thinker -------------------------------------------------------------------------
    def t_vertical_door(self, door):
        direction = door.direction
        if direction == 0:
            self._door_waiting(door)
        elif direction == 2:
            self._door_initial_wait(door)
        elif direction == -1:
            self._door_down(door)
        elif direction == 1:
            self._door_up(door)

    def _door_waiting(self, door):
        door.topcountdown -= 1
        if door.topcountdown:
            return
        if door.type == VLD_BLAZERAISE:
            door.direction = -1                     # time to go back down
            self.s_start_sound(door.sector.soundorg, info.sfx_bdcls)
        elif door.type == VLD_NORMAL:
            door.direction = -1
            self.s_start_sound(door.sector.soundorg, info.sfx_dorcls)
        elif door.type == VLD_CLOSE30THENOPEN:
            door.direction = 1
            self.s_start_sound(door.sector.soundorg, info.sfx_doropn)

    def _door_initial_wait(self, door):
        door.topcountdown -= 1
        if door.topcountdown:
            return
        if door.type == VLD_RAISEIN5MINS:
            door.direction = 1
            door.type = VLD_NORMAL
            self.s_start_sound(door.sector.soundorg, info.sfx_doropn)

    def _door_down(self, door):
        sector = door.sector
        res = self.t_move_plane(sector, door.speed, sector.floorheight, False, 1,
                                door.direction)
        if res == PASTDEST:
            if door.type in (VLD_BLAZERAISE, VLD_BLAZECLOSE):
                sector.specialdata = None
                self.p_remove_thinker(door)
                self.s_start_sound(sector.soundorg, info.sfx_bdcls)
            elif door.type in (VLD_NORMAL, VLD_CLOSE):
                sector.specialdata = None
                self.p_remove_thinker(door)
            elif door.type == VLD_CLOSE30THENOPEN:
                door.direction = 0
                door.topcountdown = TICRATE * 30
        elif res == CRUSHED:
            if door.type not in (VLD_BLAZECLOSE, VLD_CLOSE):   # closing doors stay down
                door.direction = 1
                self.s_start_sound(sector.soundorg, info.sfx_doropn)

    def _door_up(self, door):
        res = self.t_move_plane(door.sector, door.speed, door.topheight, False, 1,
                                door.direction)
        if res == PASTDEST:
            if door.type in (VLD_BLAZERAISE, VLD_NORMAL):
                door.direction = 0                  # wait at top
                door.topcountdown = door.topwait
            elif door.type in (VLD_CLOSE30THENOPEN, VLD_BLAZEOPEN, VLD_OPEN):
                door.sector.specialdata = None
                self.p_remove_thinker(door)

    # -- tagged doors ------------------------------------------------------------------------
    def _has_key(self, player, card, skull):
        return player.cards[getattr(info, card)] or player.cards[getattr(info, skull)]

    def ev_do_locked_door(self, line, type, thing):
        player = thing.player
        if player is None:
            return 0
        lock = _LOCKED_SWITCHES.get(line.special)
        if lock is not None and not self._has_key(player, lock[0], lock[1]):
            player.message = lock[2]
            self.s_start_sound(None, info.sfx_oof)
            return 0
        return self.ev_do_door(line, type)

    def ev_do_door(self, line, type):
        rtn = 0
        for sec in self.idle_tagged_sectors(line):
            rtn = 1
            door = self._new_door(sec)
            door.type = type
            door.topwait = VDOORWAIT
            door.speed = VDOORSPEED
            self._start_tagged_door(door, sec, type)
        return rtn

    def _new_door(self, sec):
        door = vldoor_t()
        self.p_add_thinker(door)
        sec.specialdata = door
        door.func = type(self).t_vertical_door
        door.sector = sec
        return door

    def _start_tagged_door(self, door, sec, type):
        if type == VLD_BLAZECLOSE:
            door.topheight = self.p_find_lowest_ceiling_surrounding(sec) - 4 * FRACUNIT
            door.direction = -1
            door.speed = VDOORSPEED * 4
            self.s_start_sound(sec.soundorg, info.sfx_bdcls)
        elif type == VLD_CLOSE:
            door.topheight = self.p_find_lowest_ceiling_surrounding(sec) - 4 * FRACUNIT
            door.direction = -1
            self.s_start_sound(sec.soundorg, info.sfx_dorcls)
        elif type == VLD_CLOSE30THENOPEN:
            door.topheight = sec.ceilingheight
            door.direction = -1
            self.s_start_sound(sec.soundorg, info.sfx_dorcls)
        elif type in (VLD_BLAZERAISE, VLD_BLAZEOPEN):
            door.direction = 1
            door.topheight = self.p_find_lowest_ceiling_surrounding(sec) - 4 * FRACUNIT
            door.speed = VDOORSPEED * 4
            if door.topheight != sec.ceilingheight:
                self.s_start_sound(sec.soundorg, info.sfx_bdopn)
        elif type in (VLD_NORMAL, VLD_OPEN):
            door.direction = 1
            door.topheight = self.p_find_lowest_ceiling_surrounding(sec) - 4 * FRACUNIT
            if door.topheight != sec.ceilingheight:
                self.s_start_sound(sec.soundorg, info.sfx_doropn)

    # -- manual doors ------------------------------------------------------------------------
    def ev_vertical_door(self, line, thing):
        """Opens the sector behind ``line`` (no tag), or turns a moving raise door back."""
        player = thing.player
        lock = _LOCKED_DOORS.get(line.special)
        if lock is not None:
            if player is None:
                return
            if not self._has_key(player, lock[0], lock[1]):
                player.message = lock[2]
                self.s_start_sound(None, info.sfx_oof)
                return

        if line.sidenum[1] == -1:
            raise RuntimeError("EV_VerticalDoor: DR special type on 1-sided linedef")
        sec = self.sides[line.sidenum[1]].sector

        if sec.specialdata is not None:
            if line.special in _REUSABLE:
                self._reuse_door(sec.specialdata, thing)
                return
            # other specials fall through and start a second thinker on the sector

        if line.special in (117, 118):              # blazing
            self.s_start_sound(sec.soundorg, info.sfx_bdopn)
        else:                                       # normal and locked doors
            self.s_start_sound(sec.soundorg, info.sfx_doropn)

        door = self._new_door(sec)
        door.direction = 1
        door.speed = VDOORSPEED
        door.topwait = VDOORWAIT
        manual = _MANUAL.get(line.special)
        if manual is not None:
            door.type, door.speed, once = manual
            if once:
                line.special = 0
        # (another special leaves type as the fresh structure has it: vld_normal)
        door.topheight = self.p_find_lowest_ceiling_surrounding(sec) - 4 * FRACUNIT

    def _reuse_door(self, door, thing):
        """A raise door used while it moves.  ``specialdata`` may not be a door at all: C
        then reads and writes the word where a door keeps ``direction`` (on x86-64, where
        the reference traces were made: a platform's ``count``, a ceiling's ``speed``, a
        floor's texture), and Chocolate Doom sets a platform's ``wait`` to -1 when told to
        close it, as 32-bit vanilla did."""
        field = type(door).DOOR_DIRECTION_ALIAS
        direction = getattr(door, field) if field else 0
        if direction == -1:
            if field:
                setattr(door, field, 1)             # go back up
            return
        if thing.player is None:
            return                                  # JDC: bad guys never close doors
        if door.func == type(self).t_vertical_door:
            door.direction = -1                     # start going down immediately
        elif door.func == type(self).t_plat_raise:
            door.wait = -1
        elif field:
            setattr(door, field, -1)

    # -- doors of special sectors ------------------------------------------------------------
    def p_spawn_door_close_in_30(self, sec):
        door = self._new_door(sec)
        sec.special = 0
        door.direction = 0
        door.type = VLD_NORMAL
        door.speed = VDOORSPEED
        door.topcountdown = 30 * TICRATE

    def p_spawn_door_raise_in_5_mins(self, sec, secnum):
        door = self._new_door(sec)
        sec.special = 0
        door.direction = 2
        door.type = VLD_RAISEIN5MINS
        door.speed = VDOORSPEED
        door.topheight = self.p_find_lowest_ceiling_surrounding(sec) - 4 * FRACUNIT
        door.topwait = VDOORWAIT
        door.topcountdown = 5 * 60 * TICRATE
