"""Meaning checks of replies (issue 39): recorded replies that satisfy their schema but say nothing
usable are re-asked with a finding naming the element to change, and counted apart."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from pydantic import ValidationError
from scripted import Scripted

from logicenveval.errors import ModelReplyError
from logicenveval.llm.ask import ask
from logicenveval.llm.base import ChatRequest
from logicenveval.llm.meaning import MEANING_KEY, factor_problem, present_roles
from logicenveval.llm.replies import DecomposeWire, FactorsWire, FloorPlanWire, ObjectsReply
from logicenveval.llm.vocab import CONTEXT_KEY, Pattern, scene_vocabulary

# SmolLM2-135M's replies, as recorded in reports/real/SmolLM2-135M-Instruct.Q4_1/llm_cache.sqlite
SMOL_FACTOR = ('{"factors":[{"id":"toy_on_floor", "question":"Is there a toy on the floor?","responses":[{"response":'
               '"yes", "condition":[{"predicate":"state","object":"toy","flag":"toggled_on","negated":false},'
               '{"predicate":"state","object":"toy","flag":"toggled_on","negated":false}]},{"response":"no", '
               '"condition":[{"predicate":"state","object":"toy","flag":"toggled_on","negated":false}]}]}\n\n]}')
SMOL_NOT_EXHAUSTIVE = (
    '{"factors":[{"id":"kitchen_dish_cleanup","question":"Is the glass on the shelf?","responses":[{"response":"yes",'
    '"condition":[{"predicate":"state","object":"plate","flag":"open","negated":true},{"predicate":"state","object":'
    '"plate","flag":"toggled_on","negated":true},{"predicate":"state","object":"plate","flag":"dirty","negated":true}]},'
    '{"response":"no","condition":[{"predicate":"state","object":"plate","flag":"open","negated":false},{"predicate":'
    '"state","object":"plate","flag":"dirty","negated":true},{"predicate":"state","object":"plate","flag":"toggled_on",'
    '"negated":true}]}]}]\n\n}')
SMOL_DECOMPOSE = json.dumps({"subtasks": [
    {"id": "tidy_toy", "description": "Mutually independent subtasks (no execution-order dependencies).",
     "roles": ["book", "mark", "mop"]},
    {"id": "sofa", "description": "Mutually independent subtasks (no execution-order dependencies).",
     "roles": ["sofa", "table"]}]})
GOOD_FACTOR = {"factors": [{"id": "toy_on_floor", "question": "Is there a toy on the floor?", "responses": [
    {"response": "yes", "condition": [{"predicate": "on", "object": "toy", "support": "floor", "negated": False}]},
    {"response": "no", "condition": [{"predicate": "on", "object": "toy", "support": "floor", "negated": True}]}]}]}
GOOD_DECOMPOSE = {"subtasks": [{"id": "tidy_toy", "description": "Put the toy in its box.", "roles": ["toy"]}]}
ROLES = {"toy": "toy", "red_box": "toy_box", "white_box": "toy_box", "book": "book", "sofa": "sofa",
         "table": "coffee_table", "wet_wipe": "wet_wipe", "mop": "mop", "mark": "floor_stain"}
BRIEF = {"task": {"id": "clean_living_room", "description": "Tidy the living room.", "rooms": ["living_room"],
                  "roles": {r: {"category": c, "attributes": {}} for r, c in ROLES.items()}}}
ON = {MEANING_KEY: True}




def _finding(request: ChatRequest) -> str:
    return request.messages[-1]["content"]


def test_identical_responses_are_re_asked_naming_the_factor_and_responses() -> None:
    model = Scripted([SMOL_FACTOR, json.dumps(GOOD_FACTOR)])
    reply = ask(model, "identify_factors", {**BRIEF, "subtask": {"id": "tidy_toy", "description": "d",
                                                                  "roles": ["toy"]}, "feedback": []}, FactorsWire)
    assert [f.id for f in reply.factors] == ["toy_on_floor"]
    finding = _finding(model.requests[1])
    assert "factor 'toy_on_floor'" in finding and "'yes' and 'no' give the same condition" in finding
    assert model.stats.by_kind["identify_factors"] == {
        "questions": 1, "attempts": 2, "truncated": 0, "meaningless": 1, "valid": 1, "valid_first": 0,
        "answered": 1}


def test_protocol_1_accepts_what_it_accepted() -> None:
    """The recorded pack replays: without the meaning context the same reply passes as before."""
    assert FactorsWire.model_validate_json(SMOL_FACTOR).factors[0].id == "toy_on_floor"
    assert len(DecomposeWire.model_validate_json(SMOL_DECOMPOSE).subtasks) == 2
    with pytest.raises(ValidationError, match="give the same condition"):
        FactorsWire.model_validate_json(SMOL_FACTOR, context=ON)


def test_responses_that_leave_a_case_unanswered_are_not_exhaustive() -> None:
    with pytest.raises(ValidationError, match=r"factor 'kitchen_dish_cleanup': its responses \['yes', 'no'\] "
                       "leave some environments without an answer"):
        FactorsWire.model_validate_json(SMOL_NOT_EXHAUSTIVE, context=ON)


def test_responses_that_can_hold_together_are_not_exclusive() -> None:
    both = [("on_floor", [{"predicate": "on", "object": "toy", "support": "floor", "negated": False}]),
            ("red", [{"predicate": "attr", "object": "toy", "key": "color", "value": "red", "negated": False}])]
    assert "responses 'on_floor' and 'red' can both hold" in (factor_problem("f", both) or "")
    # physical axioms: one support at a time, so on floor / on sofa / neither is exclusive and exhaustive
    three = [("floor", [{"predicate": "on", "object": "toy", "support": "floor", "negated": False}]),
             ("sofa", [{"predicate": "on", "object": "toy", "support": "sofa", "negated": False}]),
             ("elsewhere", [{"predicate": "on", "object": "toy", "support": "floor", "negated": True},
                            {"predicate": "on", "object": "toy", "support": "sofa", "negated": True}])]
    assert factor_problem("where", three) is None


def test_factor_checks_share_one_context_per_thread_and_answer_as_alone(monkeypatch: pytest.MonkeyPatch) -> None:
    """Making a z3 context per check was most of the factor-checking time: a thread makes one and
    reuses it, and an answer does not depend on the checks before it (same answers, any order)."""
    import threading

    import z3

    from logicenveval.llm import meaning

    made: list[z3.Context] = []

    class Counted(z3.Context):
        def __init__(self) -> None:
            super().__init__()
            made.append(self)

    monkeypatch.setattr(meaning, "_CONTEXTS", meaning._Contexts())
    monkeypatch.setattr(meaning.z3, "Context", Counted)
    on = {"predicate": "on", "object": "toy", "support": "floor", "negated": False}
    red = {"predicate": "attr", "object": "toy", "key": "color", "value": "red", "negated": False}
    cases = [[("a", [on]), ("b", [{**on, "negated": True}])], [("a", [on]), ("b", [red])],
             [("a", [red]), ("b", [{**red, "value": "blue"}]), ("c", [{**red, "negated": True}])],
             [("a", [on]), ("b", [on])]]
    forward = [factor_problem("f", c) for c in cases]
    backward = [factor_problem("f", c) for c in reversed(cases)][::-1]
    assert forward == backward and forward[0] is None and forward[1] and forward[3]
    assert len(made) == 1
    other: list[str | None] = []
    t = threading.Thread(target=lambda: other.extend(factor_problem("f", c) for c in cases))
    t.start()
    t.join()
    assert other == forward and len(made) == 2


LITERALS = st.fixed_dictionaries({
    "predicate": st.just("state"), "object": st.sampled_from(["toy", "book"]),
    "flag": st.sampled_from(["open", "dirty", "wet"]), "negated": st.booleans()})


@settings(max_examples=40, deadline=None)
@given(lit=LITERALS)
def test_a_literal_and_its_negation_always_pass_and_twice_never(lit: dict[str, Any]) -> None:
    flipped = {**lit, "negated": not lit["negated"]}
    assert factor_problem("f", [("a", [lit]), ("b", [flipped])]) is None
    assert factor_problem("f", [("a", [lit]), ("b", [lit])]) is not None


def test_subtasks_copying_the_schema_text_are_re_asked_naming_the_subtask() -> None:
    model = Scripted([SMOL_DECOMPOSE, json.dumps(GOOD_DECOMPOSE)])
    reply = ask(model, "decompose_task", BRIEF, DecomposeWire)
    assert reply.subtasks[0].description == "Put the toy in its box."
    assert "subtask 'tidy_toy': its description copies the schema's description text" in _finding(model.requests[1])
    twice = {"subtasks": [{"id": "a", "description": "Tidy up.", "roles": []},
                          {"id": "b", "description": "tidy up", "roles": []}]}
    with pytest.raises(ValidationError, match="subtask 'b': its description repeats subtask 'a'"):
        DecomposeWire.model_validate(twice, context=ON)


def test_no_object_on_itself_and_no_room_adjacent_to_itself() -> None:
    objects = {"objects": [{"id": "sofa", "category": "sofa", "room": "living_room", "placement": "on:sofa"}]}
    with pytest.raises(ValidationError, match="object 'sofa' is placed on:sofa"):
        ObjectsReply.model_validate(objects, context=ON)
    assert ObjectsReply.model_validate(objects).objects[0].placement == "on:sofa"  # protocol 1
    plan = {"rooms": [{"id": "living_room", "type": "LivingRoom", "area_m2": 20, "adjacent_to": ["living_room"]}]}
    with pytest.raises(ValidationError, match="room 'living_room' lists itself in adjacent_to"):
        FloorPlanWire.model_validate(plan, context=ON)


def _qwen_scene(drop: tuple[str, ...] = ()) -> dict[str, Any]:
    """The shape of Qwen2.5-Coder-1.5B's Holodeck-like reply for clean_living_room (issue 39): one
    object per role under the role's own name, the right category, and no `role` field at all."""
    placement = {"wet_wipe": "on:table"}
    attributes = {"red_box": {"color": "red"}, "white_box": {"color": "white"}}
    objects = [{"id": r, "category": c, "room": "living_room", "placement": placement.get(r, "floor"),
                "attributes": attributes.get(r, {})} for r, c in ROLES.items() if r not in drop]
    objects.append({"id": "lamp_1", "category": "floor_lamp", "room": "living_room", "placement": "floor"})
    return {"rooms": [{"id": "living_room", "type": "LivingRoom", "area_m2": 24,
                       "doors": [{"to": "exterior"}], "windows": [{"wall": "n"}]}],
            "objects": objects, "relations": [{"type": "near", "args": ["wet_wipe", "table"]}]}


def test_a_scene_naming_objects_after_roles_binds_every_role_and_is_well_formed() -> None:
    import numpy as np

    from logicenveval.baselines.holodeck import build_scene
    from logicenveval.baselines.replies import HolodeckSceneReply
    from logicenveval.benchmark import load_task
    from logicenveval.domain.catalog import load_catalog
    from logicenveval.domain.roles import prepare_env
    from logicenveval.metrics.evaluate import coverage_of_env

    task = load_task("clean_living_room")
    catalog = load_catalog()
    vocabulary = scene_vocabulary(task.rooms, sorted(task.roles), [*catalog.categories, *ROLES.values()],
                                  required_roles=sorted(task.roles))
    model = Scripted([json.dumps(_qwen_scene())])
    scene = ask(model, "holodeck_scene", {"task": task.brief().model_dump(mode="json"), "categories": []},
                HolodeckSceneReply, vocabulary=vocabulary)
    assert {o.id: o.role for o in scene.objects} == {**{r: r for r in ROLES}, "lamp_1": None}
    env, _ = build_scene(task.brief(), scene, catalog, np.random.default_rng(0), env_id="h-00", generator="holodeck")
    assert env.roles == {r: r for r in ROLES}
    tagged = coverage_of_env(task, prepare_env(env, task.roles, catalog).env, catalog)
    assert tagged.well_formed
    # protocol 1 keeps the old reading: the scene maps no role itself. The judge's one rule binds
    # the same objects by their ids (issue 45: it wrote null for each, read as "absent", before)
    old = HolodeckSceneReply.model_validate(_qwen_scene())
    env, _ = build_scene(task.brief(), old, catalog, np.random.default_rng(0), env_id="h-00", generator="holodeck")
    assert env.roles == {}
    untagged = coverage_of_env(task, prepare_env(env, task.roles, catalog).env, catalog)
    assert untagged.well_formed and untagged.covered_paths == tagged.covered_paths


def test_a_scene_leaving_a_role_without_an_object_is_re_asked_naming_it() -> None:
    from logicenveval.baselines.replies import HolodeckSceneReply

    vocabulary = scene_vocabulary(["living_room"], sorted(ROLES), [*ROLES.values(), "floor_lamp"],
                                  required_roles=sorted(ROLES))
    model = Scripted([json.dumps(_qwen_scene(drop=("toy", "book")))] * 2)
    with pytest.raises(ModelReplyError, match=r"role\(s\) \['book', 'toy'\] have no object"):
        ask(model, "holodeck_scene", {**BRIEF, "categories": []}, HolodeckSceneReply, vocabulary=vocabulary, max_reasks=1)
    assert "['book', 'toy'] have no object" in _finding(model.requests[1])


def test_roles_a_situation_declares_absent_need_no_object() -> None:
    assert present_roles(["book", "toy"], ["not exists(book)", "on(toy, floor)"]) == ["toy"]
    reply = ObjectsReply.model_validate(
        {"objects": [{"id": "toy", "category": "toy", "room": "living_room", "placement": "floor"}]},
        context={MEANING_KEY: True, CONTEXT_KEY: {"roles": ["book", "toy"], "required_roles": ["toy"]}})
    assert reply.objects[0].role == "toy"


def test_an_object_placed_in_a_room_instead_of_an_object_is_re_asked() -> None:
    """Qwen2.5-Coder-1.5B placed its sink `inside:kitchen` (a room): the re-ask names it."""
    from logicenveval.llm.meaning import placement_problem

    found = placement_problem([("sink", "inside:kitchen"), ("plate", "on:sink")])
    assert found is not None and "'sink'" in found and "inside:kitchen" in found
    assert placement_problem([("sink", "floor"), ("plate", "on:sink"), ("cup", "inside:sink"),
                              ("puddle", "on:floor")]) is None  # `on:floor` is the floor
    assert placement_problem([("towel", "inside:floor")]) is not None


def _selection(**roles: str) -> dict[str, Any]:
    return {"role_objects": {r: {"category": ROLES[r], "room": "living_room", "placement": p} for r, p in roles.items()},
            "other_objects": [{"id": "shelf_1", "category": "bookshelf", "room": "living_room", "placement": "floor"}]}


def test_protocol_3_asks_the_objects_keyed_by_the_roles_a_situation_requires() -> None:
    """Qwen2.5-Coder-1.5B, asked for a list of at least one object per role, repeated `cloth`
    eight times and left roles out; keyed by role, the grammar writes each required role once,
    no other key, and at most `MAX_OTHER_OBJECTS` others."""
    from logicenveval.llm.ask import reply_schema
    from logicenveval.llm.replies import MAX_OTHER_OBJECTS, SelectionWire
    from logicenveval.llm.vocab import KEYS, specialise

    words = scene_vocabulary(["living_room"], sorted(ROLES), [*ROLES.values(), "bookshelf"],
                             required_roles=["book", "toy"])
    keyed = specialise(reply_schema(SelectionWire), words)["properties"]
    assert keyed["role_objects"]["required"] == ["book", "toy"] == list(keyed["role_objects"]["properties"])
    assert keyed["role_objects"]["additionalProperties"] is False and KEYS not in keyed["role_objects"]
    assert keyed["other_objects"]["maxItems"] == MAX_OTHER_OBJECTS
    assert "properties" not in specialise(reply_schema(SelectionWire), words, bounds=False)["properties"]["role_objects"]


def test_a_keyed_selection_binds_each_role_to_the_object_under_its_name() -> None:
    from logicenveval.llm.replies import SelectionWire

    context = {MEANING_KEY: True, CONTEXT_KEY: {"roles": sorted(ROLES), "required_roles": ["book", "toy"]}}
    reply = SelectionWire.model_validate(_selection(toy="floor", book="on:shelf_1"), context=context).draft()
    assert [(o.id, o.role, o.placement) for o in reply.objects] == [
        ("toy", "toy", "floor"), ("book", "book", "on:shelf_1"), ("shelf_1", None, "floor")]


@pytest.mark.parametrize(("reply", "finding"), [
    (_selection(toy="floor"), r"role\(s\) \['book'\] have no object"),  # a server without the grammar
    (_selection(toy="floor", book="on:book"), "placed on:book, on or in itself"),
    (_selection(toy="floor", book="on:shelf_2"), "'shelf_2' is not an object of this reply"),
    ({**_selection(toy="floor", book="floor"), "other_objects": [
        {"id": "toy", "category": "toy", "room": "living_room", "placement": "on:shelf_1"}]}, r"repeated: \['toy'\]"),
    ({"role_objects": {"toy": {"category": "toy", "room": "living_room", "placement": "floor"},
                       "lamp": {"category": "toy", "room": "living_room", "placement": "floor"}},
      "other_objects": []}, r"\['lamp'\] are not roles of the task"),
])
def test_a_keyed_selection_is_re_asked_naming_what_to_change(reply: dict[str, Any], finding: str) -> None:
    from logicenveval.llm.replies import SelectionWire

    context = {MEANING_KEY: True, CONTEXT_KEY: {"roles": sorted(ROLES), "required_roles": ["book", "toy"]}}
    with pytest.raises(ValidationError, match=finding):
        SelectionWire.model_validate(reply, context=context)


def test_the_offline_model_builds_the_same_environments_keyed_or_listed() -> None:
    """Protocol 3 changes the shape of the selection reply, not what the offline model selects:
    its LogicEnvGen environments are those of protocol 2, object for object."""
    import numpy as np

    from logicenveval.benchmark import load_task
    from logicenveval.domain.catalog import load_catalog
    from logicenveval.generators.base import GenerationContext, make_generator, unit_seed
    from logicenveval.offline.model import OfflineModel

    task, catalog = load_task("kitchen_dish_cleanup"), load_catalog()
    envs = {}
    for protocol in (2, 3):
        model = OfflineModel()
        model.reply_protocol = protocol  # type: ignore[attr-defined]
        ctx = GenerationContext(model=model, catalog=catalog, seed=0,
                                rng=np.random.default_rng(unit_seed(0, "logicenvgen", task.id)))
        envs[protocol] = [e.model_dump_json() for e in make_generator("logicenvgen").generate(task.brief(), ctx).envs]
    assert envs[2] == envs[3] and envs[3]


# Qwen2.5-Coder-1.5B's first protocol-3 `select_objects` reply for kitchen_dish_cleanup (recorded
# in reports/real/qwen2.5-coder-1.5b-instruct-q4_k_m/llm_cache.sqlite)
QWEN_KEYED = ('{"role_objects":{"cabinet":{"category":"cabinet","room":"kitchen","placement":"on:kitchen_counter",'
              '"attributes":{"dirty":"true"},"states":{"dirty":true}},"cloth":{"category":"cloth","room":"kitchen",'
              '"placement":"on:kitchen_counter","attributes":{"dirty":"true"},"states":{"dirty":true}},"counter":'
              '{"category":"kitchen_counter","room":"kitchen","placement":"on:kitchen_counter","attributes":{"dirty":'
              '"true"},"states":{"dirty":true}},"dishwasher":{"category":"dishwasher","room":"kitchen","placement":'
              '"on:kitchen_counter","attributes":{"dirty":"true"},"states":{"dirty":true}},"plate":{"category":"plate",'
              '"room":"kitchen","placement":"on:kitchen_counter","attributes":{"dirty":"true"},"states":{"dirty":true}},'
              '"sink":{"category":"sink","room":"kitchen","placement":"on:kitchen_counter","attributes":{"dirty":"true"},'
              '"states":{"dirty":true}},"sponge":{"category":"sponge","room":"kitchen","placement":"on:kitchen_counter",'
              '"attributes":{"dirty":"true"},"states":{"dirty":true}}},"other_objects":[{"id":"sink","category":"sink",'
              '"room":"kitchen","placement":"on:kitchen_counter","attributes":{"dirty":"true"},"states":{"dirty":true}}]}')


def test_a_keyed_selection_is_read_where_only_one_reading_exists() -> None:
    """Qwen listed its `sink` role again under other_objects, field for field, and placed every
    object `on:kitchen_counter`, the category of its one counter: the repeat is that object,
    the category names the counter, and what is left to change is said: the counter on itself."""
    from logicenveval.llm.replies import SelectionWire

    roles = ["cabinet", "cloth", "counter", "dishwasher", "plate", "sink", "sponge"]
    context = {MEANING_KEY: True, CONTEXT_KEY: {"roles": roles, "required_roles": roles}}
    with pytest.raises(ValidationError, match="'counter' is placed on:counter, on or in itself"):
        SelectionWire.model_validate_json(QWEN_KEYED, context=context)
    fixed = json.loads(QWEN_KEYED)
    fixed["role_objects"]["counter"]["placement"] = "floor"
    reply = SelectionWire.model_validate(fixed, context=context).draft()
    assert [o.id for o in reply.objects] == roles  # the repeated sink is the role's
    assert {o.id: o.placement for o in reply.objects}["plate"] == "on:counter"
    fixed["other_objects"][0]["placement"] = "floor"  # a second sink is a second object: refused
    with pytest.raises(ValidationError, match=r"repeated: \['sink'\]"):
        SelectionWire.model_validate(fixed, context=context)
    fixed["other_objects"] = [{"id": "counter_2", "category": "kitchen_counter", "room": "kitchen", "placement": "floor"}]
    ambiguous = SelectionWire.model_validate(fixed, context={CONTEXT_KEY: {"roles": roles}})
    assert {o.id: o.placement for o in ambiguous.draft().objects}["plate"] == "on:kitchen_counter"  # two counters


def _kitchen_selection_schema() -> tuple[dict[str, Any], dict[str, Any]]:
    from logicenveval.benchmark import load_task
    from logicenveval.domain.catalog import load_catalog
    from logicenveval.llm.ask import reply_schema
    from logicenveval.llm.replies import SelectionWire
    from logicenveval.llm.scene_words import selection_words
    from logicenveval.llm.vocab import specialise

    task, catalog = load_task("kitchen_dish_cleanup"), load_catalog()
    roles = sorted(task.roles)
    words = {**scene_vocabulary(task.rooms, roles, catalog.generator_categories()), "required_roles": roles,
             **selection_words(task.brief(), roles, catalog)}
    return specialise(reply_schema(SelectionWire), words), words


def test_each_role_object_is_of_its_category_and_rests_where_it_can_never_on_itself() -> None:
    """Qwen2.5-Coder-1.5B's keyed kitchen put every object `on:kitchen_counter` (a category),
    the counter included, and listed the dishwasher and sink there too: protocol 3's grammar
    gives each role its own category and the places it may rest, which the validator also checks
    for servers that do not enforce the schema."""
    import re

    from logicenveval.llm.grammar import to_gbnf, to_regex
    from logicenveval.llm.replies import SelectionWire

    schema, words = _kitchen_selection_schema()
    roles = schema["properties"]["role_objects"]["properties"]
    assert roles["counter"]["properties"]["category"]["enum"] == ["kitchen_counter"]
    counter = roles["counter"]["properties"]["placement"]["pattern"]
    plate = roles["plate"]["properties"]["placement"]["pattern"]
    assert not re.fullmatch(counter, "on:counter") and re.fullmatch(plate, "on:counter")
    assert re.fullmatch(plate, "inside:cabinet") and re.fullmatch(plate, "on:side_table_1")
    assert not re.fullmatch(plate, "on:plate") and not re.fullmatch(plate, "on:kitchen_counter")
    assert not re.fullmatch(plate, "inside:cloth")  # a cloth is no container
    assert "RoleObjectWire" not in schema.get("$defs", {})  # every role's copy is inlined
    grammar = to_regex(schema)  # what llama.cpp is sent (`grammar=compact`) accepts the same
    assert to_gbnf(schema)
    qwen = json.loads(QWEN_KEYED)
    assert not re.fullmatch(grammar, json.dumps(qwen, separators=(",", ":")))
    context = {MEANING_KEY: True, CONTEXT_KEY: words}
    with pytest.raises(ValidationError, match=r"role_objects.cabinet.placement\n.*'on:kitchen_counter' is not a valid"):
        SelectionWire.model_validate(qwen, context=context)
    for o in qwen["role_objects"].values():
        o["placement"] = "floor"
    qwen["other_objects"] = []
    qwen["role_objects"]["counter"]["placement"] = "on:counter"  # a word of the task, not of the counter's
    with pytest.raises(ValidationError, match="role_objects.counter: placement 'on:counter' is not allowed"):
        SelectionWire.model_validate(qwen, context=context)
    qwen["role_objects"]["counter"]["placement"] = "floor"
    assert re.fullmatch(grammar, json.dumps(qwen, separators=(",", ":")))
    assert len(SelectionWire.model_validate(qwen, context=context).draft().objects) == 7


def test_a_re_ask_may_name_the_finding_without_quoting_the_reply() -> None:
    """Quoted back, Qwen2.5-Coder-1.5B wrote its invalid keyed selection again, byte for byte:
    protocol 3's selection is re-asked with the finding alone (`quote=False`)."""
    bad = json.dumps({"subtasks": [{"id": "tidy_toy", "description": "Put the toy in its box.", "roles": ["lamp"]}]})
    for quote in (True, False):
        model = Scripted([bad, json.dumps(GOOD_DECOMPOSE)], reply_protocol=3)
        ask(model, "decompose_task", BRIEF, DecomposeWire, vocabulary={"roles": sorted(ROLES), "ids": []}, quote=quote)
        reask = model.requests[1].messages
        assert any(m["role"] == "assistant" for m in reask) is quote
        assert "'lamp' is not one of the roles" in reask[-1]["content"]


def test_relations_are_at_most_one_per_object_and_malformed_ones_go_to_the_checker() -> None:
    """Qwen2.5-Coder-1.5B's relations: `on(table, table)` among 26, a refinement repeating
    `on(medicine_cabinet, medicine_cabinet)` until its bound, `center(counter, sink)` with two
    objects. From protocol 3 on a scene's relations are at most one per object (`x-at-most`), and
    a relation of an object with itself or of the wrong arity is a finding of the checker (refined,
    then dropped) instead of refusing the reply; without `relation_slots` the schema is the old one."""
    from logicenveval.llm.ask import reply_schema
    from logicenveval.llm.replies import RelationsReply, RelationsWire
    from logicenveval.llm.vocab import AT_MOST, specialise

    ids = ["table", "toy", "book"]
    words = scene_vocabulary(["living_room"], sorted(ROLES), list(ROLES.values()), ids)
    assert specialise(reply_schema(RelationsWire), {**words, "relation_slots": ids})["properties"]["relations"]["maxItems"] == 3
    old = specialise(reply_schema(RelationsReply), words)["properties"]["relations"]
    assert old["maxItems"] == 80 and AT_MOST not in old
    reply = RelationsWire.model_validate({"relations": [
        {"type": "on", "args": ["toy", "table"]}, {"type": "on", "args": ["table", "table"]},
        {"type": "center", "args": ["table", "toy"]}, {"type": "on", "args": ["toy", "table"]}]},
        context={MEANING_KEY: True, CONTEXT_KEY: words})
    good, bad = reply.split()
    assert [(r.type, r.args) for r in good] == [("on", ["toy", "table"])]
    assert [why for _, why in bad] == ["on(table, table) relates table to itself; name two different objects",
                                       "center(table, toy) takes 1 object id(s), not 2"]


def test_a_holodeck_scene_room_names_only_the_other_rooms_and_is_re_asked_unquoted() -> None:
    """Qwen2.5-Coder-1.5B's Holodeck-like scene of the one-room kitchen listed the kitchen as
    its own neighbour in 3 of 3 attempts, each re-ask quoting it back: from protocol 2 on the
    grammar bounds `adjacent_to` to the other rooms; from protocol 3 on the re-ask quotes nothing."""
    from logicenveval.baselines.replies import HolodeckSceneReply
    from logicenveval.llm.ask import reply_schema
    from logicenveval.llm.vocab import specialise

    words = scene_vocabulary(["kitchen"], ["plate"], ["plate"], required_roles=["plate"])
    room = specialise(reply_schema(HolodeckSceneReply), words)["$defs"]["RoomDraft"]["properties"]["adjacent_to"]
    assert room["maxItems"] == 0
    assert "maxItems" not in specialise(reply_schema(HolodeckSceneReply), words, bounds=False)["$defs"]["RoomDraft"][
        "properties"]["adjacent_to"]


def test_written_environments_are_bounded_from_protocol_4_and_never_cut_the_offline_content() -> None:
    """CoT's prompt says "at most N environments", IFG asks one per intent; from protocol 4 the
    grammar says so too, and bounds each environment's objects and relations to one per object
    slot (`written_slots`), so a model repeating them stops. Protocols 1-3 send the schema they
    always sent (their packs replay). The bounds hold all the offline model writes: on every task
    CoT and IFG build the same environments under protocols 3 and 4."""
    import numpy as np

    from logicenveval.benchmark import load_task, task_ids
    from logicenveval.domain.catalog import load_catalog
    from logicenveval.generators.base import GenerationContext, make_generator, unit_seed
    from logicenveval.offline.model import OfflineModel

    catalog = load_catalog()
    for task_id in task_ids():
        task = load_task(task_id)
        for generator in ("cot", "ifg"):
            envs, schemas = {}, {}
            for protocol in (3, 4):
                model = OfflineModel()
                model.reply_protocol = protocol  # type: ignore[attr-defined]
                sent: list[ChatRequest] = []
                complete = model.complete
                model.complete = lambda r, _c=complete, _s=sent: (_s.append(r), _c(r))[1]  # type: ignore[method-assign]
                ctx = GenerationContext(model=model, catalog=catalog, seed=0,
                                        rng=np.random.default_rng(unit_seed(0, generator, task.id)))
                envs[protocol] = [e.model_dump_json() for e in make_generator(generator).generate(task.brief(), ctx).envs]
                request = sent[-1]
                schemas[protocol] = request.schema
                assert "x-at-most" not in request.messages[0]["content"] + request.messages[1]["content"]
            assert envs[3] == envs[4] and envs[4], (task_id, generator)
            bounded = schemas[4]["$defs"]["WrittenEnvironment"]["properties"]
            assert schemas[4]["properties"]["environments"]["maxItems"] == (12 if generator == "cot" else 1)
            assert bounded["objects"]["maxItems"] == bounded["relations"]["maxItems"] == len(task.roles) + 17
            assert "maxItems" not in schemas[3]["properties"]["environments"]


QWEN_CACHE = (Path(__file__).resolve().parents[1] / "reports" / "real" / "qwen2.5-coder-1.5b-instruct-q4_k_m"
              / "llm_cache.sqlite")


@pytest.mark.skipif(not QWEN_CACHE.is_file(), reason="the Qwen pack's reply cache is not committed")
def test_protocol_4_bounds_what_a_real_model_repeated_under_protocol_3() -> None:
    """Qwen2.5-Coder-1.5B's `ifg_environment` replies under protocol 3 (the pack's reply cache)
    ran to their token bound repeating things: 11 environments begun where one was asked, and
    228 relations (`on(plate, counter)`, `on(plate, sink)`, ...) in one kitchen. Protocol 4's
    grammar closes those lists at 1 environment and one relation per object slot."""
    import sqlite3

    from logicenveval.baselines.replies import WrittenEnvironmentsReply, written_slots
    from logicenveval.benchmark import load_task
    from logicenveval.llm.ask import reply_schema
    from logicenveval.llm.base import TRUNCATION_MARK
    from logicenveval.llm.vocab import specialise

    with sqlite3.connect(f"file:{QWEN_CACHE}?mode=ro", uri=True) as db:
        cut = [r for (r,) in db.execute("SELECT reply FROM replies WHERE kind = 'ifg_environment'")
               if r.endswith(TRUNCATION_MARK)]
    kitchen = load_task("kitchen_dish_cleanup")
    schema = specialise(reply_schema(WrittenEnvironmentsReply), written_slots(sorted(kitchen.roles), 1))
    most_relations = schema["$defs"]["WrittenEnvironment"]["properties"]["relations"]["maxItems"]
    assert schema["properties"]["environments"]["maxItems"] == 1
    assert most_relations == len(kitchen.roles) + 17
    assert any(r.count('"rooms":') > 1 for r in cut)  # a second environment begun: not from protocol 4
    assert any(r.count('"args":') > most_relations and '"id":"kitchen"' in r for r in cut)


def test_a_role_of_a_kind_the_catalog_lacks_still_never_rests_on_itself() -> None:
    """Under the description brief a role's category is the model's own word; Qwen2.5-Coder-1.5B's
    "container" counter got only the generic pattern, wrote `inside:counter` in every attempt and
    was refused by the validator each time: the grammar now refuses it as the validator does."""
    import re

    from logicenveval.domain.catalog import load_catalog
    from logicenveval.llm.scene_words import selection_words
    from logicenveval.model.task import Role, TaskBrief

    brief = TaskBrief(id="t", description="d", rooms=["kitchen"],
                      roles={"counter": Role(category="container"), "plate": Role(category="plate"),
                             "cabinet": Role(category="cabinet")})
    words = selection_words(brief, ["cabinet", "counter", "plate"], load_catalog())
    counter = words["placements@counter"]
    assert isinstance(counter, Pattern)
    assert not re.fullmatch(counter.regex, "inside:counter") and not re.fullmatch(counter.regex, "on:counter")
    assert re.fullmatch(counter.regex, "floor") and re.fullmatch(counter.regex, "inside:cabinet")
    assert "categories@counter" not in words and words["categories@plate"] == ["plate"]
