"""The offline model writes within the list bounds of the schema it is sent, as a grammar must."""

from __future__ import annotations

from typing import Any

from hypothesis import given
from hypothesis import strategies as st
from scripted import Scripted

from logicenveval.benchmark import load_task, tasks_dir
from logicenveval.generators.brief import generator_brief
from logicenveval.llm.ask import ask
from logicenveval.llm.bounds import fit_arrays
from logicenveval.llm.replies import DecomposeWire
from logicenveval.offline.model import OfflineModel

SCHEMA: dict[str, Any] = DecomposeWire.model_json_schema()


def test_lists_are_cut_at_max_items_through_refs() -> None:
    reply = {"reasoning": "kept", "subtasks": [{"id": f"s{i}", "description": "d",
                                               "roles": [f"r{j}" for j in range(12)]} for i in range(9)]}
    fitted = fit_arrays(reply, SCHEMA)
    assert len(fitted["subtasks"]) == 6 and all(len(s["roles"]) == 8 for s in fitted["subtasks"])
    assert fitted["subtasks"][0]["roles"] == [f"r{j}" for j in range(8)]  # the first ones, in order
    assert fitted["reasoning"] == "kept"  # what the schema does not describe stays
    DecomposeWire.model_validate({"subtasks": fitted["subtasks"]})
    assert reply["subtasks"][0]["roles"][8] == "r8"  # the input is not changed


@given(st.recursive(st.none() | st.integers() | st.text(max_size=3),
                    lambda inner: st.lists(inner, max_size=4) | st.dictionaries(st.text(max_size=3), inner, max_size=3)))
def test_a_value_the_schema_does_not_bound_is_kept(value: Any) -> None:
    assert fit_arrays(value, {}) == value and fit_arrays(value, {"type": "object"}) == value


def test_offline_decomposition_of_a_task_with_many_roles_fits_its_schema() -> None:
    """Description mode read all 12 roles of multi_room_pet_care into one subtask, past the
    schema's 8: the unit failed as a whole instead of answering as a bounded model would."""
    model = OfflineModel()
    task = load_task("multi_room_pet_care", tasks_dir())
    brief = generator_brief(task, "description", model)
    reply = ask(model, "decompose_task", {"task": brief.model_dump(mode="json")}, DecomposeWire)
    assert max(len(s.roles) for s in reply.subtasks) == 8  # the reading's 12, cut as a grammar would


# ----- numbers: the compact grammar cannot bound a decimal, so the reply reader sets it to the bound

def test_numbers_outside_their_bounds_are_set_to_the_bound_through_refs_lists_and_maps() -> None:
    from logicenveval.llm.bounds import fit_numbers
    from logicenveval.llm.replies import FloorPlanReply

    schema = FloorPlanReply.model_json_schema()
    room = {"id": "kitchen", "type": "Kitchen", "area_m2": 120, "doors": [{"to": "exterior", "width": 3.5}],
            "windows": [{"wall": "n", "width": 1.2, "height": 0.1, "sill": 0.9}]}
    fitted, paths = fit_numbers({"rooms": [room]}, schema)
    assert paths == ["rooms.0.area_m2", "rooms.0.doors.0.width", "rooms.0.windows.0.height"]
    assert fitted["rooms"][0]["area_m2"] == 80.0 and fitted["rooms"][0]["doors"][0]["width"] == 2.0
    assert fitted["rooms"][0]["windows"][0] == {"wall": "n", "width": 1.2, "height": 0.3, "sill": 0.9}
    FloorPlanReply.model_validate(fitted)
    assert room["area_m2"] == 120  # the input is not changed


def test_values_inside_their_bounds_and_other_types_are_kept() -> None:
    from logicenveval.llm.bounds import fit_numbers

    schema = {"type": "object", "properties": {
        "n": {"anyOf": [{"type": "number", "maximum": 1}, {"type": "null"}]},
        "flag": {"type": "boolean", "maximum": 0}, "s": {"type": "string"}}}
    assert fit_numbers({"n": None, "flag": True, "s": "9"}, schema) == ({"n": None, "flag": True, "s": "9"}, [])
    assert fit_numbers({"n": 4}, schema) == ({"n": 1}, ["n"])  # the number branch of an anyOf


@given(st.floats(allow_nan=False, allow_infinity=False, min_value=-1e6, max_value=1e6))
def test_a_fitted_number_lies_within_its_bounds(x: float) -> None:
    from logicenveval.llm.bounds import fit_numbers

    fitted, paths = fit_numbers({"w": x}, {"type": "object", "properties": {
        "w": {"type": "number", "minimum": 0.6, "maximum": 2.0}}})
    assert 0.6 <= fitted["w"] <= 2.0 and (paths == []) == (0.6 <= x <= 2.0)


def test_a_reply_with_a_door_too_wide_is_taken_and_the_clamp_counted() -> None:
    """Qwen2.5-Coder-1.5B's Holodeck-like scene wrote a door wider than 2 m under the compact
    grammar, which bounds no decimal; the reply was refused whole."""
    import json

    from logicenveval.llm.replies import FloorPlanReply
    from logicenveval.llm.vocab import scene_vocabulary

    model = Scripted([json.dumps({"rooms": [{"id": "kitchen", "type": "Kitchen", "area_m2": 30,
                                             "doors": [{"to": "exterior", "width": 2.4}]}]})], reply_protocol=5)
    brief = generator_brief(load_task("kitchen_dish_cleanup", tasks_dir()), "description", OfflineModel())
    reply = ask(model, "floor_plan", {"task": brief.model_dump(mode="json"), "situation": []}, FloorPlanReply,
                vocabulary=scene_vocabulary(["kitchen"], sorted(brief.roles), ["plate"], None))
    assert reply.rooms[0].doors[0].width == 2.0 and len(model.requests) == 1
    assert model.stats.by_kind["floor_plan"]["clamped"] == 1
