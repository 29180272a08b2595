"""DOOM's arithmetic and tables, shared by the play simulation and the renderer: 16.16 fixed
point and binary angles (``fixed``), the random number table (``rng``), the state and object
tables of ``info.c`` (``info``), FNV-1a for traces (``fnv``), and the compiled fixed-point walks
DOOM makes over its nodes and blockmap (``nodewalks``, ``blockwalk``)."""
