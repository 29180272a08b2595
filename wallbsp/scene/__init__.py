"""The world's current state as the renderer reads it: heights and light of every sector
(``state``), the things and their drawn rows (``things``, ``thingrows``, ``thingtypes``), their
compiled walks down the tree (``leafwalk``); and the float collision queries over the tree
(``collision``, ``queries``, ``querytables``, ``blockmap``)."""
