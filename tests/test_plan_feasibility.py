"""Rule (d) of the plan's verification, from protocol 6 on: a factor response its objects' kinds
can never meet ("Is the counter open?", "Is the counter on the floor?" with a kitchen counter) is
named and asked again, then dropped (issue 46, `generators.feasibility`)."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from scripted import Scripted

from logicenveval.domain.catalog import load_catalog
from logicenveval.generators.base import GenerationContext
from logicenveval.generators.feasibility import floor_furniture, impossible
from logicenveval.generators.plan import PlanLog, _identify, check_factor, plan_vocabulary
from logicenveval.llm.replies import FactorDraft, SubtaskDraft
from logicenveval.logic.axioms import Axioms
from logicenveval.model.conditions import parse
from logicenveval.model.task import Role, TaskBrief

ROOT = Path(__file__).resolve().parents[1]
CATALOG = load_catalog()
ROLES = {"counter": Role(category="kitchen_counter"), "plate": Role(category="plate"),
         "cabinet": Role(category="kitchen_cabinet"), "lamp": Role(category="table_lamp"),
         "sofa": Role(category="sofa", optional=True), "puddle": Role(category="water_puddle")}
BRIEF = TaskBrief(id="kitchen_dish_cleanup", description="Put the plate away.", rooms=["kitchen"],
                  roles=ROLES)


def _why(text: str) -> list[str]:
    return impossible(parse(text), ROLES, CATALOG)


def test_the_recorded_qwen_factors_cannot_hold_of_a_kitchen_counter() -> None:
    """Qwen2.5-Coder-1.5B's factors for kitchen_dish_cleanup (protocol 6, description brief)."""
    assert _why("state(counter, open)") == [
        "state(counter, open) can never hold: a kitchen_counter cannot be opened (the catalog)"]
    assert _why("not on(counter, floor)") == [
        "not on(counter, floor) can never hold: a kitchen_counter is furniture and stands on the floor"]
    assert _why("not state(counter, open)") == [] and _why("on(counter, floor)") == []


@pytest.mark.parametrize("text", [
    "state(cabinet, open)", "state(lamp, toggled_on)", "on(plate, floor)", "not on(plate, counter)",
    "inside(plate, cabinet)", "not on(sofa, floor)", "not on(puddle, floor)", "state(counter, dirty)",
    "state(counter, open) or on(plate, counter)", "not (state(counter, open) and on(plate, counter))",
])
def test_what_a_kind_can_meet_is_not_refused(text: str) -> None:
    """Near misses: an openable cabinet, a switchable lamp, a plate anywhere, an optional sofa that
    may be absent, a puddle (it holds nothing: not furniture), a dirty counter, and a condition
    that holds by another of its parts."""
    assert _why(text) == []


@pytest.mark.parametrize("text", ["on(counter, table)", "inside(counter, cabinet)", "on(sofa, counter)",
                                  "state(plate, toggled_on) and on(plate, counter)"])
def test_furniture_off_the_floor_and_flags_without_affordance_are_refused(text: str) -> None:
    assert len(_why(text)) == 1


def test_furniture_holds_things_stands_only_on_the_floor_and_is_not_pickable() -> None:
    assert floor_furniture("kitchen_counter", CATALOG) and floor_furniture("sofa", CATALOG) \
        and floor_furniture("trash_can", CATALOG)
    assert not any(floor_furniture(k, CATALOG) for k in ("water_puddle", "floor_stain", "rug", "book", "plate", "nope"))


def _task_files() -> list[Path]:
    return sorted([*ROOT.glob("benchmark_data/tasks/*/task.json"), *ROOT.glob("tests/data/*/tasks_*/*/task.json")])


def test_no_ground_truth_factor_or_stated_fact_of_any_task_is_refused() -> None:
    """Calibration on data written apart from the rules: every response of every factor and every
    constraint fact of the 25 tasks and of every test set (rewordings, new tasks, held-out) can
    hold, of the roles' kinds (protocol 6) and under the physical axioms (protocol 7)."""
    files = _task_files()
    assert len(files) > 200
    refused = []
    for path in files:
        task = json.loads(path.read_text())
        roles = {r: Role.model_validate(v) for r, v in task["roles"].items()}
        texts = [t for v in task.get("variables", {}).values() for t in v["values"].values()]
        texts += [c["fact"] for c in task.get("constraints", [])]
        axioms = Axioms(roles, [parse(t) for t in texts])
        refused += [(path.parent.name, t) for t in texts
                    if impossible(parse(t), roles, CATALOG) or not axioms.possible(parse(t))]
    assert refused == []


def test_check_factor_names_the_value_only_when_given_the_catalog() -> None:
    factor = FactorDraft(id="counter_on_floor", question="Is the counter on the floor?",
                         values={"yes": "on(counter, floor)", "no": "not on(counter, floor)"})
    assert check_factor(BRIEF, factor) == []
    assert check_factor(BRIEF, factor, CATALOG) == [
        "factor 'counter_on_floor' value 'no': not on(counter, floor) can never hold: a kitchen_counter is "
        "furniture and stands on the floor; ask about something that can differ between environments of this task"]


def _reply(factor_id: str, subject: str, flag: str) -> str:
    cond = [{"predicate": "state", "object": subject, "flag": flag, "negated": False}]
    return json.dumps({"factors": [{"id": factor_id, "question": f"Is the {subject} {flag}?", "responses": [
        {"response": "yes", "condition": cond},
        {"response": "no", "condition": [{**cond[0], "negated": True}]}]}]})


@pytest.mark.parametrize(("protocol", "asked", "kept"), [(6, 2, ["plate_dirty"]), (5, 1, ["counter_open"])])
def test_identify_asks_again_from_protocol_6_and_packs_before_replay_as_recorded(
        protocol: int, asked: int, kept: list[str]) -> None:
    model = Scripted([_reply("counter_open", "counter", "open"), _reply("plate_dirty", "plate", "dirty")],
                     reply_protocol=protocol)
    ctx = GenerationContext(model=model, catalog=CATALOG, rng=np.random.default_rng(0))
    subtask = SubtaskDraft(id="tidy_plate", description="Put the plate away.", roles=["plate", "counter"])
    log = PlanLog()
    factors = _identify(BRIEF, ctx, plan_vocabulary(BRIEF), log, subtask, 2)
    assert [f.id for f in factors] == kept and len(model.requests) == asked
    if protocol == 6:
        assert "can never hold" in json.dumps(model.requests[1].payload["feedback"])
