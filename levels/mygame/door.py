"""Spitter Hall's script: the hall's door opens as its line is crossed; the end, when quiet."""


def on_start(level):
    level.print("Take the blaster and cross into the hall.")


def on_line_crossed(level, line, thing):
    if line.tag == 7 and thing is level.player.mo and level.open_door(7):
        level.print("The door grinds open...")        # (False: it is moving already)


def on_killed(level, target, source):
    if target.player is None and level.player.killcount == level.play.totalkills:
        level.print("The hall is quiet.")
        level.after(35 * 3, level.end)
