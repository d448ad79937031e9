"""Vocabulary-bound reply schemas: markers, enum/pattern specialisation, structured conditions."""

from __future__ import annotations

import json
from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from logicenveval.errors import ModelReplyError
from logicenveval.llm.ask import ask, reply_schema
from logicenveval.llm.base import ChatRequest
from logicenveval.llm.replies import FactorsWire, ObjectsReply
from logicenveval.llm.structured import literals_of, to_text
from logicenveval.llm.vocab import SNAKE, specialise
from logicenveval.model.conditions import STATE_FLAGS, parse

VOCAB: dict[str, Any] = {"roles": ["toy", "box"], "places": ["toy", "box", "floor"],
                         "rooms": ["living_room"], "attr_keys": SNAKE, "attr_values": SNAKE, "ids": SNAKE}
PAYLOAD = {"task": {"id": "t", "description": "Put the toy in the box if it is on the floor.",
                    "rooms": ["living_room"],
                    "roles": {"toy": {"category": "toy", "attributes": {}},
                              "box": {"category": "box", "attributes": {}}}},
           "subtask": {"id": "tidy", "description": "tidy", "roles": ["toy"]}, "feedback": []}


def _enums(schema: dict[str, Any]) -> dict[str, list[str]]:
    found: dict[str, list[str]] = {}

    def walk(node: Any) -> None:
        if isinstance(node, dict):
            if "x-vocab" in node and "enum" in node:
                found[node["x-vocab"]] = node["enum"]
            for v in node.values():
                walk(v)
        elif isinstance(node, list):
            for v in node:
                walk(v)

    walk(schema)
    return found


def test_specialised_schema_lists_the_vocabulary_and_leaves_the_shared_one_alone() -> None:
    base = reply_schema(FactorsWire)
    before = json.dumps(base, sort_keys=True)
    schema = specialise(base, VOCAB)
    assert json.dumps(base, sort_keys=True) == before
    enums = _enums(schema)
    assert enums["roles"] == ["toy", "box"] and enums["places"] == ["toy", "box", "floor"]
    text = json.dumps(schema)
    assert '"minProperties"' not in text  # llama.cpp's grammar does not enforce it
    assert '"minItems": 2' in text  # responses: an array with a bound the grammar enforces
    assert SNAKE.regex in text


class _Fixed:
    name = "fixed"

    def __init__(self, replies: list[Any]) -> None:
        self.replies = [json.dumps(r) for r in replies]
        self.requests: list[ChatRequest] = []

    def complete(self, request: ChatRequest) -> str:
        self.requests.append(request)
        return self.replies[min(len(self.requests), len(self.replies)) - 1]


def _factor(obj: str) -> dict[str, Any]:
    return {"factors": [{"id": "toy_on_floor", "question": "Is the toy on the floor?", "responses": [
        {"response": "yes", "condition": [{"predicate": "on", "object": obj, "support": "floor", "negated": False}]},
        {"response": "no", "condition": [{"predicate": "on", "object": obj, "support": "floor", "negated": True}]},
    ]}]}


def test_a_word_outside_the_vocabulary_is_reasked_quoting_it() -> None:
    model = _Fixed([_factor("sofa"), _factor("toy")])
    reply = ask(model, "identify_factors", PAYLOAD, FactorsWire, vocabulary=VOCAB)
    assert reply.factors[0].draft().values == {"yes": "on(toy, floor)", "no": "not on(toy, floor)"}
    feedback = model.requests[1].messages[-1]["content"]
    assert "'sofa' is not one of the roles: toy, box" in feedback


def test_without_a_vocabulary_the_marked_fields_are_free() -> None:
    reply = ask(_Fixed([_factor("sofa")]), "identify_factors", PAYLOAD, FactorsWire)
    assert reply.factors[0].responses[0].condition[0].object == "sofa"  # type: ignore[union-attr]


def test_repeated_responses_are_invalid() -> None:
    bad = _factor("toy")
    bad["factors"][0]["responses"][1]["response"] = "yes"
    with pytest.raises(ModelReplyError, match="response 'yes' twice"):
        ask(_Fixed([bad]), "identify_factors", PAYLOAD, FactorsWire, vocabulary=VOCAB)


def test_scene_vocabulary_binds_categories_rooms_and_placements() -> None:
    from logicenveval.llm.vocab import scene_vocabulary

    vocab = scene_vocabulary(["living_room"], ["toy"], ["toy", "sofa"])
    sofa = {"id": "sofa_1", "category": "sofa", "room": "living_room", "placement": "floor"}
    obj = {"id": "toy", "category": "toy", "room": "living_room", "role": "toy", "placement": "on:sofa_1"}
    ok = ask(_Fixed([{"objects": [sofa, obj]}]), "select_objects",
             {**PAYLOAD, "rooms": [], "facts": [], "categories": []}, ObjectsReply, vocabulary=vocab)
    assert ok.objects[1].placement == "on:sofa_1"
    with pytest.raises(ModelReplyError, match="'on the sofa' is not a valid placements"):
        ask(_Fixed([{"objects": [sofa, {**obj, "placement": "on the sofa"}]}]), "select_objects",
            {**PAYLOAD, "rooms": [], "facts": [], "categories": []}, ObjectsReply, vocabulary=vocab)
    with pytest.raises(ModelReplyError, match="'sofa_1' is not an object of this reply"):
        ask(_Fixed([{"objects": [obj]}]), "select_objects",
            {**PAYLOAD, "rooms": [], "facts": [], "categories": []}, ObjectsReply, vocabulary=vocab)


_ATOM = st.one_of(
    st.builds(lambda r, s: f"on({r}, {s})", st.sampled_from(["toy", "box"]), st.sampled_from(["box", "floor"])),
    st.builds(lambda r, f: f"state({r}, {f})", st.sampled_from(["toy", "box"]), st.sampled_from(STATE_FLAGS)),
    st.builds(lambda r, k, v: f"attr({r}, {k}, {v})", st.sampled_from(["toy"]), st.sampled_from(["color", "kind"]),
              st.sampled_from(["red", "doll"])),
    st.builds(lambda r: f"exists({r})", st.sampled_from(["toy", "box"])),
    st.builds(lambda r, room: f"in_room({r}, {room})", st.sampled_from(["toy"]), st.sampled_from(["living_room"])),
    st.builds(lambda r, c: f"inside({r}, {c})", st.sampled_from(["toy"]), st.sampled_from(["box"])),
)


@given(st.lists(st.tuples(st.booleans(), _ATOM), min_size=1, max_size=3))
def test_structured_conditions_round_trip(parts: list[tuple[bool, str]]) -> None:
    text = " and ".join(("not " if neg else "") + atom for neg, atom in parts)
    from pydantic import TypeAdapter

    from logicenveval.llm.structured import Conjunction

    lits = TypeAdapter(Conjunction).validate_python(literals_of(text))
    assert parse(to_text(lits)) == parse(text)


def test_floor_plan_lists_each_room_once_with_whole_square_metres() -> None:
    from logicenveval.llm.replies import FloorPlanWire
    from logicenveval.llm.vocab import scene_vocabulary

    vocab = scene_vocabulary(["kitchen", "hallway"], [], [])
    schema = specialise(reply_schema(FloorPlanWire), vocab)
    assert schema["properties"]["rooms"]["maxItems"] == 2
    assert schema["$defs"]["RoomWire"]["properties"]["area_m2"] == {"maximum": 80, "minimum": 3, "type": "integer"}
    room = {"id": "kitchen", "type": "Kitchen", "area_m2": 12}
    with pytest.raises(ModelReplyError, match="room 'kitchen' is listed twice"):
        ask(_Fixed([{"rooms": [room, room]}]), "floor_plan", {**PAYLOAD, "situation": []}, FloorPlanWire, vocabulary=vocab)
    plan = ask(_Fixed([{"rooms": [room]}]), "floor_plan", {**PAYLOAD, "situation": []}, FloorPlanWire, vocabulary=vocab).draft()
    assert plan.rooms[0].area_m2 == 12.0


def test_a_relation_with_the_wrong_number_of_objects_is_invalid() -> None:
    from logicenveval.llm.replies import RelationDraft

    with pytest.raises(ValueError, match="'inside' takes 2 object id"):
        RelationDraft(type="inside", args=["cup"])
    assert RelationDraft(type="edge", args=["sofa"]).args == ["sofa"]


def test_repeated_object_ids_are_refused_so_the_model_is_asked_again() -> None:
    from pydantic import ValidationError

    from logicenveval.llm.replies import ObjectsReply

    obj = {"id": "living_room", "category": "sofa", "room": "living_room", "placement": "floor"}
    with pytest.raises(ValidationError, match="repeated: \\['living_room'\\]"):
        ObjectsReply.model_validate({"objects": [obj, {**obj, "category": "rug"}]})


def test_an_environment_assembled_from_bad_drafts_fails_its_attempt_not_the_unit() -> None:
    """Model-made drafts that cannot form an EnvSpec raise EnvSpecError (a failed attempt),
    never pydantic's ValidationError (an internal error that fails the whole unit)."""
    from logicenveval.benchmark import load_task
    from logicenveval.errors import EnvSpecError
    from logicenveval.generators.construction import symbolic_env
    from logicenveval.llm.replies import ObjectDraft

    brief = load_task("clean_living_room").brief()
    draft = ObjectDraft.model_validate({"id": "sofa_1", "category": "sofa", "room": "living_room",
                                        "placement": "floor"})
    with pytest.raises(EnvSpecError, match="unique"):
        symbolic_env(brief, "e-00", "logicenvgen", [{"id": "living_room", "type": "LivingRoom"}],
                     [draft, draft])


def _specialised_by_deepcopy(schema: dict[str, Any], vocabulary: dict[str, Any]) -> dict[str, Any]:
    """The earlier `specialise` (deep copy, then mark in place): the reference of the one-pass one."""
    import copy

    from logicenveval.llm.vocab import COUNT, MARK, Pattern

    out = copy.deepcopy(schema)

    def walk(node: Any) -> None:
        if isinstance(node, dict):
            name = node.get(MARK)
            words = vocabulary.get(name) if isinstance(name, str) else None
            if isinstance(words, Pattern):
                node["pattern"] = words.regex
            elif words:
                node["enum"] = list(dict.fromkeys(words))
            counted = node.get(COUNT)
            bound = vocabulary.get(counted) if isinstance(counted, str) else None
            if bound and not isinstance(bound, Pattern):
                node["maxItems"] = len(set(bound))
            for value in node.values():
                walk(value)
        elif isinstance(node, list):
            for value in node:
                walk(value)

    walk(out)
    return out


_NAMES = st.sampled_from(["roles", "places", "ids", "rooms", "absent"])
_LEAF = st.one_of(st.none(), st.booleans(), st.integers(), st.text(max_size=4))
_SCHEMA = st.recursive(
    st.dictionaries(st.sampled_from(["type", "enum", "pattern", "maxItems", "x-vocab", "x-count", "a"]),
                    st.one_of(_LEAF, _NAMES), max_size=4),
    lambda inner: st.one_of(st.lists(inner, max_size=3),
                            st.dictionaries(st.sampled_from(["properties", "items", "anyOf", "x", "enum"]),
                                            inner, max_size=3)),
    max_leaves=12)


@settings(deadline=None)
@given(_SCHEMA)
def test_specialise_matches_the_deep_copy_reference(schema: Any) -> None:
    """One pass gives what deep-copying then marking gave, key order included, and leaves the
    shared schema as it was."""
    from logicenveval.llm.vocab import COUNT, MARK

    assert MARK == "x-vocab" and COUNT == "x-count"
    base = {"root": schema}
    before = json.dumps(base)
    for vocab in (VOCAB, {"roles": ["a", "a", "b"]}, {"ids": SNAKE}):
        assert json.dumps(specialise(base, vocab)) == json.dumps(_specialised_by_deepcopy(base, vocab))
    assert json.dumps(base) == before


def test_a_room_may_name_only_the_other_rooms_as_neighbours_from_protocol_2_on() -> None:
    """Qwen2.5-Coder-1.5B, offered only its own room for `adjacent_to`, listed it in all three
    attempts of a one-room task's floor plan; protocol 2 bounds the list to the other rooms."""
    from logicenveval.llm.ask import reply_schema
    from logicenveval.llm.replies import FloorPlanWire
    from logicenveval.llm.vocab import OTHERS, specialise

    words = {"rooms": ["living_room"], "room_types": ["LivingRoom"], "door_targets": ["living_room", "exterior"]}
    two = {**words, "rooms": ["living_room", "kitchen"]}

    def adjacent(schema: dict) -> dict:
        return schema["$defs"]["RoomWire"]["properties"]["adjacent_to"]

    assert adjacent(specialise(reply_schema(FloorPlanWire), words))["maxItems"] == 0
    assert adjacent(specialise(reply_schema(FloorPlanWire), two))["maxItems"] == 1
    old = adjacent(specialise(reply_schema(FloorPlanWire), words, bounds=False))
    assert "maxItems" not in old and OTHERS not in old  # protocol 1's request text
    assert OTHERS not in json.dumps(specialise(reply_schema(FloorPlanWire), None))


def test_a_scene_lists_at_least_one_object_per_required_role_from_protocol_2_on() -> None:
    """Qwen2.5-Coder-1.5B wrote one object per `select_objects` reply, re-asked or not; protocol
    2's grammar asks for at least one object per role the situation requires."""
    from logicenveval.llm.ask import reply_schema
    from logicenveval.llm.replies import ObjectsReply
    from logicenveval.llm.vocab import AT_LEAST, scene_vocabulary, specialise

    words = scene_vocabulary(["bathroom"], ["mop", "toothbrush", "vanity"], ["mop", "toothbrush", "vanity"],
                             required_roles=["mop", "vanity"])
    assert specialise(reply_schema(ObjectsReply), words)["properties"]["objects"]["minItems"] == 2
    old = specialise(reply_schema(ObjectsReply), words, bounds=False)["properties"]["objects"]
    assert old["minItems"] == 1 and AT_LEAST not in old  # protocol 1's request text
    none = specialise(reply_schema(ObjectsReply), {**words, "required_roles": []})["properties"]["objects"]
    assert none["minItems"] == 1
