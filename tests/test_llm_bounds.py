"""The offline model writes within the list bounds of the schema it is sent, as a grammar must."""

from __future__ import annotations

from typing import Any

from hypothesis import given
from hypothesis import strategies as st

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
