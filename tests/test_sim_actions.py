"""Preconditions and effects of every action of DESIGN.md §5, on a hand-built world."""

from __future__ import annotations

import pytest
from sim_support import small_catalog

from logicenveval.domain.actions import ACTIONS
from logicenveval.model.envspec import EnvSpec
from logicenveval.sim.world import World, holds_initial


def _env(**extra_roles: str | None) -> EnvSpec:
    objects = [
        {"id": "toy_1", "category": "toy", "room": "living_room", "support": "floor",
         "attributes": {"kind": "doll"}},
        {"id": "sofa_1", "category": "sofa", "room": "living_room"},
        {"id": "box_1", "category": "toy_box", "room": "living_room"},
        {"id": "fridge_1", "category": "fridge", "room": "kitchen"},
        {"id": "milk_1", "category": "cup", "room": "kitchen", "support": None,
         "container": "fridge_1"},
        {"id": "lamp_1", "category": "lamp", "room": "living_room", "support": "sofa_1"},
        {"id": "sink_1", "category": "sink", "room": "kitchen"},
        {"id": "stain_1", "category": "floor_stain", "room": "living_room"},
        {"id": "statue_1", "category": "unknown_statue", "room": "living_room"},
        {"id": "shed_box", "category": "toy_box", "room": "shed"},
    ]
    roles: dict[str, str | None] = {"toy": "toy_1", "sofa": "sofa_1", "box": "box_1",
                                    "fridge": "fridge_1", "cup": "milk_1", "lamp": "lamp_1",
                                    "sink": "sink_1", "mark": "stain_1", "ghost": None}
    roles.update(extra_roles)
    return EnvSpec.model_validate({
        "task_id": "t", "env_id": "e",
        "rooms": [{"id": "living_room"}, {"id": "kitchen", "type": "Kitchen"}, {"id": "shed"}],
        "doors": [{"id": "d", "rooms": ["living_room", "kitchen"], "state": "closed"}],
        "objects": objects, "roles": roles})


@pytest.fixture
def world() -> World:
    return World.from_env(_env(), small_catalog())


def act(w: World, name: str, **args: str) -> str | None:
    spec = ACTIONS[name]
    why = spec.check(w, args)
    if why is None:
        spec.apply(w, args)
    return why


def test_initial_predicates(world: World) -> None:
    h = world.holds
    assert h("exists", ("toy",)) and not h("exists", ("ghost",))
    assert h("on", ("toy", "floor")) and h("on", ("lamp", "sofa")) and h("inside", ("cup", "fridge"))
    assert h("in_room", ("cup", "kitchen")) and h("in_room", ("cup", "Kitchen"))
    assert h("attr", ("toy", "kind", "doll")) and not h("attr", ("toy", "kind", "car"))
    assert h("state", ("mark", "dirty"))  # catalog default state
    assert h("agent_in", ("living_room",)) and h("agent_in", ("LivingRoom",))
    assert h("near", ("floor",)) and not h("near", ("toy",)) and not h("holding", ("toy",))
    # every predicate about an unbound role is false, also negative-looking ones
    for name, args in [("on", ("ghost", "floor")), ("state", ("ghost", "dirty")),
                       ("in_room", ("ghost", "living_room")), ("near", ("ghost",))]:
        assert not h(name, args)


def test_walk(world: World) -> None:
    assert act(world, "Walk", target="cup") is None  # through a closed door
    assert world.holds("near", ("cup",)) and world.holds("agent_in", ("kitchen",))
    assert act(world, "Walk", target="living_room") is None
    assert world.holds("near", ("living_room",)) and not world.holds("near", ("cup",))
    assert "not reachable" in (act(world, "Walk", target="shed_box") or "")
    assert "not bound" in (act(world, "Walk", target="ghost") or "")
    assert "no such object" in (act(world, "Walk", target="nothing") or "")


def test_pick(world: World) -> None:
    assert "not near" in (act(world, "Pick", obj="toy") or "")
    act(world, "Walk", target="sofa")
    assert "not pickable" in (act(world, "Pick", obj="sofa") or "")
    act(world, "Walk", target="toy")
    assert act(world, "Pick", obj="toy") is None
    assert world.holds("holding", ("toy",)) and not world.holds("on", ("toy", "floor"))
    assert world.holds("near", ("toy",))  # keeps you near its old place
    act(world, "Walk", target="lamp")
    assert "hand is not empty" in (act(world, "Pick", obj="lamp") or "")


def test_pick_from_closed_container(world: World) -> None:
    act(world, "Walk", target="cup")
    assert "closed container" in (act(world, "Pick", obj="cup") or "")
    act(world, "Walk", target="fridge")
    assert act(world, "Open", obj="fridge") is None and world.holds("state", ("fridge", "open"))
    act(world, "Walk", target="cup")
    assert act(world, "Pick", obj="cup") is None


def test_place(world: World) -> None:
    act(world, "Walk", target="toy")
    act(world, "Pick", obj="toy")
    assert "not near" in (act(world, "Place", obj="toy", target="sofa") or "")
    act(world, "Walk", target="box")
    assert "not a surface" in (act(world, "Place", obj="toy", target="box") or "")
    act(world, "Walk", target="sofa")
    assert "not holding" in (act(world, "Place", obj="lamp", target="sofa") or "")
    assert act(world, "Place", obj="toy", target="sofa") is None
    assert world.holds("on", ("toy", "sofa")) and not world.holds("holding", ("toy",))


def test_place_on_floor_goes_to_agent_room(world: World) -> None:
    act(world, "Walk", target="toy")
    act(world, "Pick", obj="toy")
    act(world, "Walk", target="sink")
    assert world.holds("in_room", ("toy", "kitchen"))  # carried along
    assert act(world, "Place", obj="toy", target="floor") is None
    assert world.holds("on", ("toy", "floor")) and world.holds("in_room", ("toy", "kitchen"))


def test_putin(world: World) -> None:
    act(world, "Walk", target="toy")
    assert "not holding" in (act(world, "PutIn", obj="toy", target="box") or "")
    act(world, "Pick", obj="toy")
    act(world, "Walk", target="sofa")
    assert "not a container" in (act(world, "PutIn", obj="toy", target="sofa") or "")
    act(world, "Walk", target="fridge")
    assert "closed" in (act(world, "PutIn", obj="toy", target="fridge") or "")
    act(world, "Walk", target="box")
    assert act(world, "PutIn", obj="toy", target="box") is None  # toy_box: never openable
    assert world.holds("inside", ("toy", "box")) and not world.holds("on", ("toy", "floor"))


def test_open_close_toggle(world: World) -> None:
    assert "not near" in (act(world, "Open", obj="fridge") or "")
    act(world, "Walk", target="box")
    assert "not openable" in (act(world, "Open", obj="box") or "")
    assert "not toggleable" in (act(world, "ToggleOn", obj="box") or "")
    act(world, "Walk", target="fridge")
    act(world, "Open", obj="fridge")
    assert act(world, "Close", obj="fridge") is None and not world.holds("state", ("fridge", "open"))
    act(world, "Walk", target="lamp")
    assert act(world, "ToggleOn", obj="lamp") is None and world.holds("state", ("lamp", "toggled_on"))
    assert act(world, "ToggleOff", obj="lamp") is None
    assert not world.holds("state", ("lamp", "toggled_on"))


def test_clean_and_fill(world: World) -> None:
    assert "not near" in (act(world, "Clean", obj="mark") or "")
    act(world, "Walk", target="mark")
    assert "not holding tool" in (act(world, "Clean", obj="mark", tool="toy") or "")
    assert "not bound" in (act(world, "Clean", obj="mark", tool="ghost") or "")
    assert act(world, "Clean", obj="mark") is None and not world.holds("state", ("mark", "dirty"))
    act(world, "Walk", target="fridge")
    act(world, "Open", obj="fridge")
    act(world, "Walk", target="cup")
    act(world, "Pick", obj="cup")
    assert "not near" in (act(world, "Fill", obj="cup", source="sink") or "")
    act(world, "Walk", target="sink")
    assert act(world, "Fill", obj="cup", source="sink") is None
    assert world.holds("state", ("cup", "filled"))


def test_unknown_category_is_obstacle(world: World) -> None:
    act(world, "Walk", target="statue_1")
    assert "not pickable" in (act(world, "Pick", obj="statue_1") or "")


def test_copy_is_independent(world: World) -> None:
    w2 = world.copy()
    act(w2, "Walk", target="toy")
    act(w2, "Pick", obj="toy")
    assert world.holds("on", ("toy", "floor")) and not world.holds("holding", ("toy",))


def test_holds_initial_matches_world() -> None:
    h = holds_initial(_env(), small_catalog())
    assert h("inside", ("cup", "fridge")) and not h("exists", ("ghost",))
