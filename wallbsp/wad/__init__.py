"""DOOM's WAD files: the archive (``archive``), its pictures (``graphics``, ``textures``), the
average colours an import falls back to (``colours``) and maps imported as levels
(``mapimport``). The names most callers want are here."""
from .archive import Wad, forget_wads, lump_name, open_wad, wad_bytes, write_wad
from .colours import GREY, SKY_BLUE, SKY_FLAT
from .graphics import Picture, ResourceError
from .mapimport import import_wad, list_maps, load_wad_level, map_lump_indices, parse_wad_spec
from .textures import WadTextures, wad_textures

__all__ = ["GREY", "Picture", "ResourceError", "SKY_BLUE", "SKY_FLAT", "Wad", "WadTextures",
           "forget_wads", "import_wad", "list_maps", "load_wad_level", "lump_name",
           "map_lump_indices", "open_wad", "parse_wad_spec", "wad_bytes", "wad_textures",
           "write_wad"]
