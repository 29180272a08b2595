"""The node builder: DOOM maps' VERTEXES, SEGS, SSECTORS, NODES, BLOCKMAP and REJECT
(``wadnodes.rebuild_wad``; ``wallbsp nodes``), checks of anyone's nodes (``check``), and our
levels as PWADs (``export``).  docs/nodes.md."""
