"""Room rectangles from room areas, and typical sizes: the Holodeck-like's floor plan and the
offline CoT/IFG writer's habit.

Rooms are laid out side by side along x in the order they are listed, each from z = 0 to its
depth, so that consecutive rooms share a wall. Within a room, x runs east and z north from its
south-west corner; walls are `s` (z = 0), `n` (z = depth), `w` (x = 0) and `e` (x = width).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from logicenveval.domain.catalog import Catalog

#: extents of an object whose category the catalog does not know
UNKNOWN_SIZE = (0.4, 0.4, 0.4)


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


def typical_size(category: str, catalog: Catalog) -> tuple[float, float, float]:
    """The middle of the catalog's size range: what a model guesses for an ordinary instance."""
    cat = catalog.get(category)
    if cat is None:
        return UNKNOWN_SIZE
    lo, hi = cat.size_min, cat.size_max
    return (round((lo[0] + hi[0]) / 2, 3), round((lo[1] + hi[1]) / 2, 3), round((lo[2] + hi[2]) / 2, 3))


def footprint(size: tuple[float, float, float], yaw: float) -> tuple[float, float]:
    """Extents along x and z after a rotation by a multiple of 90 degrees."""
    if round(yaw) % 180 == 90:
        return size[2], size[0]
    return size[0], size[2]
