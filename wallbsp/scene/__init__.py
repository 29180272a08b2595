"""The world's current state as the renderer reads it: heights and light of every sector
(``state``), the things and their drawn rows (``things``, ``thingrows``, ``thingtypes``), their
compiled walks down the tree (``leafwalk``).  What blocks and what sees is the play
simulation's (``game.playsim``; questions between tics: ``game.probe``)."""
