"""Floor plans: non-overlapping rectangles, door and window slots on shared/exterior walls with room
for every opening, the no-solver placement rule, determinism."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from logicenveval.errors import EnvSpecError
from logicenveval.model.envspec import EnvSpec
from logicenveval.physics import check_env
from logicenveval.scene.floorplan import CORNER, GAP, place_by_rule, plan_floor
from logicenveval.scene.spec import DoorRequest, RoomRequest, WindowRequest


def _env(plan: object) -> EnvSpec:
    plan = place_by_rule(plan, np.random.default_rng(1))  # type: ignore[arg-type]
    return EnvSpec.model_validate({"task_id": "t", "env_id": "e",
                                   "rooms": [r.model_dump() for r in plan.rooms],  # type: ignore[attr-defined]
                                   "doors": [d.model_dump() for d in plan.doors],  # type: ignore[attr-defined]
                                   "windows": [w.model_dump() for w in plan.windows]})  # type: ignore[attr-defined]


def test_two_rooms_share_a_door_and_have_an_entrance() -> None:
    rooms = [RoomRequest(id="living_room", area=20, adjacent_to=["kitchen"], windows=[WindowRequest(wall="s")]),
             RoomRequest(id="kitchen", type="Kitchen", area=12, doors=[DoorRequest(to="exterior", state="open")])]
    plan = plan_floor(rooms, np.random.default_rng(0))
    pairs = {tuple(sorted(d.rooms)) for d in plan.doors}
    assert ("kitchen", "living_room") in pairs and ("exterior", "kitchen") in pairs
    assert next(d for d in plan.doors if "exterior" in d.rooms).state == "open"
    assert len(plan.windows) == 1 and plan.windows[0].room == "living_room"
    assert check_env(_env(plan)).floor_plan.passed


def test_duplicate_room_ids_raise() -> None:
    with pytest.raises(EnvSpecError, match="repeated"):
        plan_floor([RoomRequest(id="a"), RoomRequest(id="a")], np.random.default_rng(0))


def test_unknown_adjacency_is_a_warning() -> None:
    plan = plan_floor([RoomRequest(id="a", adjacent_to=["ghost"])], np.random.default_rng(0))
    assert any("ghost" in w for w in plan.warnings)


@settings(max_examples=40, deadline=None)
@given(st.integers(1, 7), st.integers(0, 10_000), st.data())
def test_property_plans_pass_the_floor_plan_check(n: int, seed: int, data: st.DataObject) -> None:
    rooms = []
    for i in range(n):
        adj = [f"r{j}" for j in data.draw(st.lists(st.integers(0, max(0, i - 1)), max_size=2)) if i]
        wins = [WindowRequest(wall=w) for w in data.draw(st.lists(st.sampled_from("nsew"), max_size=2))]
        rooms.append(RoomRequest(id=f"r{i}", area=data.draw(st.floats(6, 40)), adjacent_to=adj, windows=wins))
    a = plan_floor(rooms, np.random.default_rng(seed))
    b = plan_floor(rooms, np.random.default_rng(seed))
    assert a == b
    env = _env(a)
    report = check_env(env)
    assert report.floor_plan.passed, report.floor_plan.failures
    reach = {rooms[0].id}
    for _ in range(n):
        for d in a.doors:
            if set(d.rooms) & reach:
                reach |= set(d.rooms) - {"exterior"}
    assert reach == {r.id for r in rooms}
    assert any("exterior" in d.rooms for d in a.doors)
    assert all(d.segment is None for d in a.doors) and all(w.segment is None for w in a.windows)
    assert set(a.slots) == {d.id for d in a.doors} | {w.id for w in a.windows}
    for _oid, slot in a.slots.items():  # the slot lies on its owner's wall, corners cleared
        e = slot.edge
        assert e.lo + CORNER - 1e-9 <= slot.lo and slot.hi <= e.hi - CORNER + 1e-9
        assert slot.hi - slot.lo >= slot.width - 1e-9
        assert slot.owner in {r.id for r in rooms}
    by_stretch: dict[tuple[str, float, float, float], float] = {}
    for slot in a.slots.values():  # every opening of a stretch fits on it together
        key = (slot.edge.axis, slot.edge.at, slot.lo, slot.hi)
        by_stretch[key] = by_stretch.get(key, -GAP) + slot.width + GAP
    assert all(used <= key[3] - key[2] + 1e-9 for key, used in by_stretch.items())
