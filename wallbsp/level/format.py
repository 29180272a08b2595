"""The level file's vocabulary (SPEC §2, §2b): its format name, versions, keys and limits,
shared by the reader and the writer."""

FORMAT = "wallbsp-level"
VERSIONS = (1, 2)
MAX_LIGHT = 255
MAX_NUMBER = 65535           # specials, tags, thing types and flags: DOOM's 16-bit fields
NO_TEXTURE = "-"             # DOOM's name for "no texture" on a side

# the known keys of each kind of object; ..._2: those of version 2
ROOT_KEYS = ("format", "version", "name", "vertices", "sectors", "walls", "start")
ROOT_KEYS_2 = ROOT_KEYS + ("resources", "sky", "things", "thing_types", "script")
SECTOR_KEYS = ("floor", "ceiling", "light", "floor_color", "ceiling_color", "sky")
SECTOR_KEYS_2 = SECTOR_KEYS + ("floor_texture", "ceiling_texture", "special", "tag")
WALL_KEYS = ("v1", "v2", "front", "back", "color", "upper_color", "lower_color")
WALL_FLAGS = ("upper_unpegged", "lower_unpegged", "blocks", "secret", "blocks_sound", "hidden")
# the wall flags that are DOOM's linedef bits as they are (the others depend on the sides)
WALL_LINE_BITS = {"secret": 32, "blocks_sound": 64, "hidden": 128}  # ML_SECRET, ML_SOUNDBLOCK, ML_DONTDRAW
WALL_KEYS_2 = WALL_KEYS + ("front_side", "back_side") + WALL_FLAGS + ("special", "tag")
SIDE_KEYS = ("upper", "middle", "lower", "x_offset", "y_offset")
START_KEYS = ("x", "y", "angle")
THING_KEYS = ("x", "y", "angle", "type", "flags")
THING_TYPE_KEYS = ("sprite", "radius", "height", "solid")
