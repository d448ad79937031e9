"""The coordinates an LLM writes down when asked for positions without a solver.

Used by the offline CoT and IFG handlers and by LogicEnvGen's no-CAS ablation (so it sits in
`scene`, below both generators and baselines): furniture goes along the walls one after another
(south, north, west, east), loose items lie in a row across the middle of the room, wall objects
hang on the west wall, and small items stand on their support's top (or sit inside their
container), spread along x. Nothing checks collisions, door swing or overhang: whatever physical
mistakes this produces are judged by the checker like a real model's.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from logicenveval.domain.catalog import Catalog

#: extents of an object whose category the catalog does not know
UNKNOWN_SIZE = (0.4, 0.4, 0.4)
WALL_Y = 1.5  # centre height of wall-mounted objects
_SLOTS = (("s", 0.0), ("n", 180.0), ("w", 90.0), ("e", 270.0))


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


def guess_coordinates(
    objects: list[dict[str, Any]],
    dims: dict[str, tuple[float, float]],
    catalog: Catalog,
    *,
    rng: np.random.Generator | None = None,
    wall_gap: float = 0.05,
    doors: dict[str, dict[str, list[tuple[float, float]]]] | None = None,
) -> list[dict[str, Any]]:
    """Object drafts (`id, category, room, placement, ...`) with `position`, `size`, `yaw` added.

    `dims` maps room id to (width, depth); positions are relative to the room's south-west corner.
    With `rng`, furniture stands up to `wall_gap` metres off its wall (a sampled model's sloppiness).
    `doors` maps room id → wall → (start, end) stretches along that wall that furniture skips, as a
    model told where the doors are keeps them free.
    """
    placed: dict[str, dict[str, Any]] = {}
    by_room: dict[str, list[dict[str, Any]]] = {}
    for o in objects:
        by_room.setdefault(o["room"], []).append(o)
    for room, items in by_room.items():
        width, depth = dims[room]
        _furniture(items, width, depth, catalog, placed, rng, wall_gap, (doors or {}).get(room, {}))
    _held(objects, catalog, placed)
    return [placed[o["id"]] for o in objects if o["id"] in placed]


def _skip_doors(start: float, along: float, spans: list[tuple[float, float]]) -> float:
    """The first position from `start` where a piece `along` long clears every door stretch."""
    for a, b in sorted(spans):
        if start < b and start + along > a:
            start = b + 0.05
    return start


def _furniture(items: list[dict[str, Any]], width: float, depth: float, catalog: Catalog,
               placed: dict[str, dict[str, Any]], rng: np.random.Generator | None, wall_gap: float,
               doors: dict[str, list[tuple[float, float]]]) -> None:
    cursors = {"s": 0.1, "n": 0.1, "w": 0.1, "e": 0.1}
    loose = [o for o in items if o["placement"] == "floor" and _pickable(o, catalog)]
    wall_z = 0.3
    for o in items:
        size = typical_size(o["category"], catalog)
        if o["placement"] == "wall":
            placed[o["id"]] = {**o, "size": size, "yaw": 90.0,
                               "position": (round(size[2] / 2 + 0.01, 3), WALL_Y, round(wall_z + size[0] / 2, 3))}
            wall_z += size[0] + 0.2
            continue
        if o["placement"] != "floor" or o in loose:
            continue
        gap = wall_gap * float(rng.random()) if rng is not None else wall_gap
        for wall, yaw in _SLOTS:
            fx, fz = footprint(size, yaw)
            along, limit = (fx, width) if wall in "sn" else (fz, depth)
            cursors[wall] = _skip_doors(cursors[wall], along, doors.get(wall, []))
            if cursors[wall] + along <= limit - 0.1:
                break
        else:
            wall, yaw = "s", 0.0  # the walls are full: the model keeps writing along the south wall
            fx, fz = footprint(size, yaw)
            along = fx
        start = cursors[wall]
        cursors[wall] = start + along + 0.1
        if wall == "s":
            pos = (start + fx / 2, fz / 2 + gap)
        elif wall == "n":
            pos = (start + fx / 2, depth - fz / 2 - gap)
        elif wall == "w":
            pos = (fx / 2 + gap, start + fz / 2)
        else:
            pos = (width - fx / 2 - gap, start + fz / 2)
        placed[o["id"]] = {**o, "size": size, "yaw": yaw,
                           "position": (round(pos[0], 3), size[1] / 2, round(pos[1], 3))}
    for k, o in enumerate(loose):
        size = typical_size(o["category"], catalog)
        x = width * (k + 1) / (len(loose) + 1)
        placed[o["id"]] = {**o, "size": size, "yaw": 0.0,
                           "position": (round(x, 3), size[1] / 2, round(depth / 2, 3))}


def _pickable(o: dict[str, Any], catalog: Catalog) -> bool:
    cat = catalog.get(o["category"])
    return bool(cat and cat.pickable)


def _held(objects: list[dict[str, Any]], catalog: Catalog, placed: dict[str, dict[str, Any]]) -> None:
    """Items on a support's top or in a container, spread along the holder's x extent."""
    pending = [o for o in objects if o["id"] not in placed]
    groups: dict[str, list[dict[str, Any]]] = {}
    for o in pending:
        groups.setdefault(o["placement"], []).append(o)
    for _ in range(len(pending) + 1):
        progress = False
        for placement, items in groups.items():
            holder_id = placement.split(":", 1)[1] if ":" in placement else ""
            if holder_id not in placed or items[0]["id"] in placed:
                continue
            holder = placed[holder_id]
            hx, hy, hz = holder["position"]
            fx, _ = footprint(holder["size"], holder["yaw"])
            inside = placement.startswith("inside:")
            base = hy - holder["size"][1] / 2 + 0.05 if inside else hy + holder["size"][1] / 2
            for k, o in enumerate(items):
                size = typical_size(o["category"], catalog)
                x = hx - fx / 2 + fx * (k + 0.5) / len(items)
                placed[o["id"]] = {**o, "size": size, "yaw": 0.0,
                                   "position": (round(x, 3), base + size[1] / 2, round(hz, 3))}
            progress = True
        if not progress:
            break
    for o in objects:  # a holder the model never placed: the item ends up on the floor at the door
        if o["id"] not in placed:
            size = typical_size(o["category"], catalog)
            placed[o["id"]] = {**o, "placement": "floor", "size": size, "yaw": 0.0,
                               "position": (0.5, size[1] / 2, 0.5)}
