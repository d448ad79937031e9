"""Room rectangles from room areas: the Holodeck-like's floor plan and the offline CoT/IFG
writer's habit.

Rooms are laid out side by side along x in the order they are listed, each from z = 0 to its
depth, so that consecutive rooms share a wall. Within a room, x runs east and z north from its
south-west corner; walls are `s` (z = 0), `n` (z = depth), `w` (x = 0) and `e` (x = width).
"""

from __future__ import annotations

import math
from dataclasses import dataclass


@dataclass(frozen=True)
class RoomRect:
    id: str
    x0: float
    width: float
    depth: float

    @property
    def polygon(self) -> list[tuple[float, float]]:
        x1 = round(self.x0 + self.width, 3)
        return [(self.x0, 0.0), (x1, 0.0), (x1, self.depth), (self.x0, self.depth)]


def room_dims(area_m2: float) -> tuple[float, float]:
    """(width, depth) of a 5:4 rectangle of about `area_m2`, rounded to 10 cm."""
    width = round(math.sqrt(1.25 * area_m2), 1)
    return width, round(area_m2 / width, 1)


def layout_rooms(rooms: list[tuple[str, float]]) -> list[RoomRect]:
    """Rectangles side by side along x for (room id, area) pairs, in order."""
    out: list[RoomRect] = []
    x = 0.0
    for rid, area in rooms:
        w, d = room_dims(area)
        out.append(RoomRect(rid, round(x, 3), w, d))
        x += w
    return out
