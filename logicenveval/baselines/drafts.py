"""Instantiating a model's environment draft (rooms + placed objects) as an EnvSpec, as given.

No solver and no repair: the only transformation is geometry bookkeeping (room rectangles side
by side, room-relative coordinates made absolute, doors and windows put on the walls the draft
names). A draft that cannot be an EnvSpec (an unknown support id, a room missing) raises
`EnvSpecError`, which the baselines record as a generation failure.
"""

from __future__ import annotations

from typing import Any

from pydantic import ValidationError

from logicenveval.baselines.geometry import RoomRect, layout_rooms
from logicenveval.errors import EnvSpecError
from logicenveval.generators.construction import placement_fields
from logicenveval.llm.replies import DoorDraft, PlacedObject, RelationDraft, RoomDraft
from logicenveval.model.envspec import EnvSpec
from logicenveval.model.task import TaskBrief
from logicenveval.validation import first_error


def floor_plan(rooms: list[RoomDraft]) -> tuple[list[RoomRect], list[dict[str, Any]], list[dict[str, Any]]]:
    """Room rectangles, doors and windows (EnvSpec dicts) of a list of room drafts."""
    rects = layout_rooms([(r.id, r.area_m2) for r in rooms])
    by_id = {r.id: r for r in rects}
    order = [r.id for r in rects]
    doors: list[dict[str, Any]] = []
    windows: list[dict[str, Any]] = []
    for room, rect in zip(rooms, rects, strict=True):
        for d in room.doors:
            doors.append({"id": f"d{len(doors)}", "rooms": [room.id, d.to], "type": d.type,
                          "state": d.state, "segment": _door_segment(rect, d, by_id, order)})
        for w in room.windows:
            windows.append({"id": f"w{len(windows)}", "room": room.id, "sill": w.sill, "height": w.height,
                            "state": w.state, "segment": _wall_segment(rect, w.wall, w.width)})
    return rects, doors, windows


def _wall_segment(rect: RoomRect, wall: str, length: float) -> list[list[float]]:
    """A centred segment of `length` on a wall of `rect`."""
    along = rect.width if wall in "ns" else rect.depth
    half = min(length, along - 0.2) / 2
    if wall in "ns":
        z = 0.0 if wall == "s" else rect.depth
        mid = rect.x0 + rect.width / 2
        return [[round(mid - half, 3), z], [round(mid + half, 3), z]]
    x = rect.x0 if wall == "w" else round(rect.x0 + rect.width, 3)
    mid = rect.depth / 2
    return [[x, round(mid - half, 3)], [x, round(mid + half, 3)]]


def _door_segment(rect: RoomRect, door: DoorDraft, by_id: dict[str, RoomRect], order: list[str]) -> list[list[float]]:
    """Exterior doors on the south wall; doors between consecutive rooms on their shared wall;
    a door to a room that shares no wall goes on the north wall, as the draft asked."""
    other = by_id.get(door.to)
    if other is not None and abs(order.index(door.to) - order.index(rect.id)) == 1:
        x = max(rect.x0, other.x0)
        mid = min(rect.depth, other.depth) / 2
        return [[x, round(mid - door.width / 2, 3)], [x, round(mid + door.width / 2, 3)]]
    if other is None and door.to == "exterior":
        return _wall_segment(rect, "s", door.width)
    return _wall_segment(rect, "n", door.width)


def env_from_draft(
    brief: TaskBrief,
    *,
    env_id: str,
    generator: str,
    rooms: list[RoomDraft],
    objects: list[PlacedObject],
    relations: list[RelationDraft],
    extra: dict[str, Any] | None = None,
) -> EnvSpec:
    """The EnvSpec of a draft whose object positions are relative to their room's corner."""
    rects, doors, windows = floor_plan(rooms)
    offset = {r.id: r.x0 for r in rects}
    out: list[dict[str, Any]] = []
    roles: dict[str, str | None] = {r: None for r in brief.roles}
    for o in objects:
        support, container = placement_fields(o.placement)
        x, y, z = o.position
        out.append({"id": o.id, "category": o.category, "room": o.room,
                    "position": [round(x + offset.get(o.room, 0.0), 3), y, z], "size": list(o.size),
                    "yaw": o.yaw, "support": support, "container": container,
                    "attributes": dict(o.attributes), "states": dict(o.states)})
        if o.role in roles and roles[o.role] is None:
            roles[o.role] = o.id
    data = {
        "task_id": brief.id, "generator": generator, "env_id": env_id, "claimed_trajectory": None,
        "rooms": [{"id": r.id, "type": d.type, "polygon": r.polygon} for r, d in zip(rects, rooms, strict=True)],
        "doors": doors, "windows": windows, "objects": out,
        "relations": [{"type": r.type, "args": list(r.args)} for r in relations],
        "roles": roles, "agent": {"room": brief.rooms[0] if brief.rooms[0] in offset else rooms[0].id},
        **(extra or {}),
    }
    try:
        return EnvSpec.model_validate(data)
    except ValidationError as exc:
        loc, msg = first_error(exc)
        raise EnvSpecError(f"{env_id}: the model's environment draft is not a valid EnvSpec: {msg}",
                           field=loc or None,
                           hint="the baseline instantiates drafts as given; the model must name existing "
                                "rooms and object ids") from None

