"""``p_lights.c``: the light thinkers of special sectors (fire flicker, broken flashing,
strobes, glow; structures in ``spectypes.py``) with their ``P_Random`` calls, and the line
specials that set light levels.

No per-level state of its own.
"""
from .spectypes import (GLOWSPEED, SLOWDARK, STROBEBRIGHT, fireflicker_t, glow_t,
                        lightflash_t, strobe_t)


class Lights:
    # -- fire flicker ------------------------------------------------------------------------
    def t_fire_flicker(self, flick):
        flick.count -= 1
        if flick.count:
            return
        amount = (self.rng.p_random() & 3) * 16
        sector = flick.sector
        if sector.lightlevel - amount < flick.minlight:
            sector.lightlevel = flick.minlight
        else:
            sector.lightlevel = flick.maxlight - amount
        flick.count = 4

    def p_spawn_fire_flicker(self, sector):
        sector.special = 0                          # nothing special during play
        flick = fireflicker_t()
        self.p_add_thinker(flick)
        flick.func = type(self).t_fire_flicker
        flick.sector = sector
        flick.maxlight = sector.lightlevel
        flick.minlight = self.p_find_min_surrounding_light(sector, sector.lightlevel) + 16
        flick.count = 4

    # -- broken light flashing ---------------------------------------------------------------
    def t_light_flash(self, flash):
        flash.count -= 1
        if flash.count:
            return
        if flash.sector.lightlevel == flash.maxlight:
            flash.sector.lightlevel = flash.minlight
            flash.count = (self.rng.p_random() & flash.mintime) + 1
        else:
            flash.sector.lightlevel = flash.maxlight
            flash.count = (self.rng.p_random() & flash.maxtime) + 1

    def p_spawn_light_flash(self, sector):
        sector.special = 0
        flash = lightflash_t()
        self.p_add_thinker(flash)
        flash.func = type(self).t_light_flash
        flash.sector = sector
        flash.maxlight = sector.lightlevel
        flash.minlight = self.p_find_min_surrounding_light(sector, sector.lightlevel)
        flash.maxtime = 64
        flash.mintime = 7
        flash.count = (self.rng.p_random() & flash.maxtime) + 1

    # -- strobes -----------------------------------------------------------------------------
    def t_strobe_flash(self, flash):
        flash.count -= 1
        if flash.count:
            return
        if flash.sector.lightlevel == flash.minlight:
            flash.sector.lightlevel = flash.maxlight
            flash.count = flash.brighttime
        else:
            flash.sector.lightlevel = flash.minlight
            flash.count = flash.darktime

    def p_spawn_strobe_flash(self, sector, fastOrSlow, inSync):
        flash = strobe_t()
        self.p_add_thinker(flash)
        flash.sector = sector
        flash.darktime = fastOrSlow
        flash.brighttime = STROBEBRIGHT
        flash.func = type(self).t_strobe_flash
        flash.maxlight = sector.lightlevel
        flash.minlight = self.p_find_min_surrounding_light(sector, sector.lightlevel)
        if flash.minlight == flash.maxlight:
            flash.minlight = 0
        sector.special = 0
        if not inSync:
            flash.count = (self.rng.p_random() & 7) + 1
        else:
            flash.count = 1

    def ev_start_light_strobing(self, line):
        """Strobes the tagged sectors that have no mover (a strobe is no mover: a second
        trigger adds a second strobe)."""
        for sec in self.idle_tagged_sectors(line):
            self.p_spawn_strobe_flash(sec, SLOWDARK, 0)

    # -- light levels set by lines -----------------------------------------------------------
    def ev_turn_tag_lights_off(self, line):
        """Each tagged sector takes its darkest neighbour's light."""
        for sector in self.sectors:
            if sector.tag == line.tag:
                minimum = sector.lightlevel
                for templine in sector.lines:
                    tsec = self.get_next_sector(templine, sector)
                    if tsec is None:
                        continue
                    if tsec.lightlevel < minimum:
                        minimum = tsec.lightlevel
                sector.lightlevel = minimum

    def ev_light_turn_on(self, line, bright):
        """Sets the tagged sectors' light to ``bright``; 0 means the brightest neighbour's,
        found for the first tagged sector and then kept for the others (vanilla)."""
        for sector in self.sectors:
            if sector.tag == line.tag:
                if not bright:
                    for templine in sector.lines:
                        temp = self.get_next_sector(templine, sector)
                        if temp is None:
                            continue
                        if temp.lightlevel > bright:
                            bright = temp.lightlevel
                sector.lightlevel = bright

    # -- glow --------------------------------------------------------------------------------
    def t_glow(self, g):
        if g.direction == -1:
            g.sector.lightlevel -= GLOWSPEED
            if g.sector.lightlevel <= g.minlight:
                g.sector.lightlevel += GLOWSPEED
                g.direction = 1
        elif g.direction == 1:
            g.sector.lightlevel += GLOWSPEED
            if g.sector.lightlevel >= g.maxlight:
                g.sector.lightlevel -= GLOWSPEED
                g.direction = -1

    def p_spawn_glowing_light(self, sector):
        g = glow_t()
        self.p_add_thinker(g)
        g.sector = sector
        g.minlight = self.p_find_min_surrounding_light(sector, sector.lightlevel)
        g.maxlight = sector.lightlevel
        g.func = type(self).t_glow
        g.direction = -1
        sector.special = 0
