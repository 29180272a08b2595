"""The WAD as the play simulation reads it (``w_wad.c`` and the part of ``r_data.c`` the
game needs): lumps by name, a map's lumps with PWADs, the flats' numbers (the donut's
overrun reads one) and the wall textures' heights (``raiseToTexture``).  ``WadLumps`` is
a mixin of ``Play``; ``Game.g_init`` sets the directory it reads (``wad_dir``,
``wad_entries``, ``wad_entry_files``, ``wad_files``)."""
import struct

from wallbsp.doom.fixed import FRACBITS

from .demos import wad_image


class WadLumps:
    """Lumps, flats and texture heights (module docstring)."""

    def w_lump(self, name):
        """The bytes of the last lump called ``name`` (W_CacheLumpName), or None."""
        index = self.wad_dir.get(name.upper())
        return None if index is None else self._read_entry(index)

    def _read_entry(self, index):
        _, pos, size = self.wad_entries[index]
        with open(self.wad_entry_files[index], "rb") as f:
            f.seek(pos)
            return f.read(size)

    def map_wad(self, mapname):
        """What mapload reads map ``mapname`` from: the WAD's path, or with PWADs a WAD
        image of the map's marker and the ten lumps after it (wherever they came from)."""
        if not self.wad_files:
            return self.wad_path
        first = self.wad_dir[mapname]
        lumps = [(self.wad_entries[i][0], self._read_entry(i))
                 for i in range(first, min(first + 11, len(self.wad_entries)))]
        return wad_image(lumps)

    def _flat_names(self):
        """R_InitFlats' flat numbers: every lump from the last F_START to the last F_END,
        nested markers included, by name."""
        names = [e[0] for e in self.wad_entries]
        if "F_START" not in self.wad_dir or "F_END" not in self.wad_dir:
            return []
        first = len(names) - names[::-1].index("F_START")
        last = len(names) - 1 - names[::-1].index("F_END")
        return names[first:last]

    def texture_height(self, name):
        """``textureheight[R_TextureNumForName(name)]``: the wall texture's height in fixed
        point; "-" is texture 0, as in DOOM."""
        if self._texture_heights is None:
            self._texture_heights = self._read_texture_heights()
        heights, first = self._texture_heights
        if name[:1] == "-":
            return first
        try:
            return heights[name.upper()]
        except KeyError:
            raise KeyError(f"R_TextureNumForName: {name} not found") from None

    def _read_texture_heights(self):
        heights, first = {}, None
        for lump in ("TEXTURE1", "TEXTURE2"):
            raw = self.w_lump(lump)
            if raw is None:
                continue
            count = struct.unpack_from("<i", raw, 0)[0]
            for i in range(count):
                offset = struct.unpack_from("<i", raw, 4 + 4 * i)[0]
                name = raw[offset:offset + 8].split(b"\0", 1)[0].decode("latin-1").upper()
                height = struct.unpack_from("<h", raw, offset + 14)[0] << FRACBITS
                if first is None:
                    first = height
                heights.setdefault(name, height)   # the first of a name is found
        return heights, first
