"""Instantiating a model's written environment as an EnvSpec, as given; Holodeck-like's floor plan.

CoT and IFG write the whole environment — room polygons, door and window segments, object
positions, one world frame — and `env_from_draft` copies it into an EnvSpec: no solver, no
repair, the only additions are door/window ids (`d0`, `w0`, … in the order written). A draft that
cannot be an EnvSpec (an unknown support id or room) raises `EnvSpecError`, which the baselines
record as a generation failure; a physically wrong one is an EnvSpec the PhyPR checker judges.

`floor_plan` is the Holodeck-like's floor plan from rooms by area (rectangles side by side).
"""

from __future__ import annotations

from typing import Any

from pydantic import ValidationError

from logicenveval.baselines.geometry import RoomRect, layout_rooms
from logicenveval.baselines.replies import WrittenEnvironment
from logicenveval.errors import EnvSpecError
from logicenveval.generators.construction import placement_fields
from logicenveval.llm.replies import DoorDraft, RoomDraft
from logicenveval.model.envspec import EnvSpec
from logicenveval.model.task import TaskBrief
from logicenveval.validation import first_error


def floor_plan(rooms: list[RoomDraft]) -> tuple[list[RoomRect], list[dict[str, Any]], list[dict[str, Any]]]:
    """Holodeck-like: room rectangles, doors and windows (EnvSpec dicts) of a list of room drafts."""
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


def env_from_draft(brief: TaskBrief, *, env_id: str, generator: str, draft: WrittenEnvironment,
                   extra: dict[str, Any] | None = None) -> EnvSpec:
    """The EnvSpec of a written environment, coordinates exactly as the model wrote them.

    `roles` holds only the roles the draft gives an object (`role` of an object): a role the
    draft leaves out is not written as null (which would say "absent" and stop the judge), so
    the harness binds it by meaning (`domain.roles`) exactly as for every other method."""
    objects: list[dict[str, Any]] = []
    roles: dict[str, str | None] = {}
    for o in draft.objects:
        support, container = placement_fields(o.placement)
        objects.append({"id": o.id, "category": o.category, "room": o.room, "position": list(o.position),
                        "size": list(o.size), "yaw": o.yaw, "support": support, "container": container,
                        "attributes": dict(o.attributes), "states": dict(o.states)})
        if o.role in brief.roles and o.role not in roles:
            roles[o.role] = o.id
    room_ids = [r.id for r in draft.rooms]
    data = {
        "task_id": brief.id, "generator": generator, "env_id": env_id, "claimed_trajectory": None,
        "rooms": [{"id": r.id, "type": r.type, "polygon": [list(p) for p in r.polygon]} for r in draft.rooms],
        "doors": [{"id": f"d{k}", "rooms": list(d.rooms), "segment": [list(p) for p in d.segment],
                   "height": d.height, "type": d.type, "state": d.state} for k, d in enumerate(draft.doors)],
        "windows": [{"id": f"w{k}", "room": w.room, "segment": [list(p) for p in w.segment], "sill": w.sill,
                     "height": w.height, "state": w.state} for k, w in enumerate(draft.windows)],
        "objects": objects, "relations": [{"type": r.type, "args": list(r.args)} for r in draft.relations],
        "roles": roles, "agent": {"room": brief.rooms[0] if brief.rooms[0] in room_ids else room_ids[0]},
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
