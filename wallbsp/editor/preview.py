"""The 3-D preview and play (placeholder)."""
from __future__ import annotations


def camera_point(session):
    cam = getattr(session, "camera", None)
    if cam is not None:
        return cam[0], cam[1]
    return session.mouse_map()
