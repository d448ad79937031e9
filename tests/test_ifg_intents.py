"""IFG samples each intent in its own request (request protocol 5, issue 46): i ~ M(p) at the
intent temperature, then r ~ M(p, i). Under protocol 4 one request asked for all k intents as
free strings; Qwen2.5-Coder-1.5B gave 1 of 8, and 21 of its 24 attempts failed for it."""

from __future__ import annotations

import json
from typing import Any

import numpy as np
import pytest
from pydantic import ValidationError

from logicenveval.baselines.replies import IntentWire
from logicenveval.benchmark import load_task
from logicenveval.domain.catalog import load_catalog
from logicenveval.generators.base import (
    GenerationContext,
    GenerationResult,
    make_generator,
    unit_seed,
)
from logicenveval.generators.plan import plan_vocabulary
from logicenveval.llm.base import ChatRequest
from logicenveval.llm.meaning import MEANING_KEY
from logicenveval.llm.vocab import CONTEXT_KEY
from logicenveval.offline.model import OfflineModel

TASK = "clean_living_room"


class Seen:
    """The offline model, keeping every request; `broken`: intent requests answered with junk."""

    def __init__(self, protocol: int, broken: tuple[int, ...] = ()) -> None:
        self.inner = OfflineModel()
        self.inner.reply_protocol = protocol  # type: ignore[attr-defined]
        self.reply_protocol = protocol
        self.name, self.stats = self.inner.name, self.inner.stats
        self.requests: list[ChatRequest] = []
        self.broken = broken

    def complete(self, request: ChatRequest) -> str:
        self.requests.append(request)
        # a re-ask carries the refused reply and the finding after the first two messages
        asked = [r for r in self.requests if r.kind == "ifg_intent" and len(r.messages) == 2]
        if request.kind == "ifg_intent" and len(asked) - 1 in self.broken:
            return json.dumps({"description": "x", "facts": [{"predicate": "attr", "object": "sofa"}]})
        return self.inner.complete(request)


def _ifg(model: Any) -> GenerationResult:
    task = load_task(TASK)
    ctx = GenerationContext(model=model, catalog=load_catalog(), seed=0,
                            rng=np.random.default_rng(unit_seed(0, "ifg", task.id)))
    return make_generator("ifg").generate(task.brief(), ctx)


def test_each_intent_is_its_own_request_at_the_intent_temperature() -> None:
    model = Seen(5)
    result = _ifg(model)
    intents = [r for r in model.requests if r.kind == "ifg_intent"]
    assert len(intents) == 8 and not [r for r in model.requests if r.kind == "ifg_intents"]
    assert {r.temperature for r in intents} == {1.1} and len({r.seed for r in intents}) == 8
    assert len({json.dumps(r.messages) for r in intents}) == 1  # the same question, sampled apart
    assert len(result.envs) == 8 and all(a.built for a in result.attempts)
    assert {r.temperature for r in model.requests if r.kind == "ifg_environment"} == {0.5}


def test_a_failed_intent_loses_that_intent_only() -> None:
    model = Seen(5, broken=(2,))
    result = _ifg(model)
    failed = [a for a in result.attempts if not a.built]
    assert [(a.id, a.stage) for a in failed] == [("ifg-02", "ifg_intent")]
    assert len(result.envs) == 7 and [a.id for a in result.attempts] == [f"ifg-{i:02d}" for i in range(8)]
    assert [f.env_id for f in result.failures if f.stage == "ifg_intent"] == ["ifg-02"]


def test_protocol_4_still_asks_all_intents_at_once() -> None:
    model = Seen(4)
    _ifg(model)
    assert [r.kind for r in model.requests].count("ifg_intents") == 1
    assert "ifg_intent" not in [r.kind for r in model.requests]


def _context() -> dict[str, Any]:
    brief = load_task(TASK).brief()
    return {MEANING_KEY: True, CONTEXT_KEY: plan_vocabulary(brief)}


@pytest.mark.parametrize("fact", [
    {"predicate": "attr", "object": "cabinet", "key": "opened", "value": "yes", "negated": True},  # no such role
    {"predicate": "attr", "object": "sofa", "negated": True},  # `not attr(cabinet, opened)`: wrong arity
    {"predicate": "state", "object": "sofa", "flag": "opened", "negated": False},  # no such flag
])
def test_intent_facts_are_literals_of_the_task_s_words(fact: dict[str, Any]) -> None:
    with pytest.raises(ValidationError):
        IntentWire.model_validate({"description": "d", "facts": [fact]}, context=_context())


def test_an_intent_stating_a_literal_both_ways_is_refused() -> None:
    on = {"predicate": "on", "object": "toy", "support": "floor", "negated": False}
    with pytest.raises(ValidationError, match="and its negation"):
        IntentWire.model_validate({"description": "d", "facts": [on, {**on, "negated": True}]}, context=_context())
    ok = IntentWire.model_validate({"description": "d", "facts": [on, on]}, context=_context())
    assert ok.texts() == ["on(toy, floor)"]


class SelfSupporting(Seen):
    """CoT's first reply puts its first object on itself (Qwen's bathroom drafts put the
    medicine cabinet inside itself), then answers as the offline model."""

    def complete(self, request: ChatRequest) -> str:
        self.requests.append(request)
        reply = json.loads(self.inner.complete(request))
        if request.kind == "cot_environments" and len(self.requests) == 1:
            first = reply["environments"][0]["objects"][0]
            first["placement"] = f"inside:{first['id']}"
        return json.dumps(reply)


def _cot(model: Any) -> GenerationResult:
    task = load_task(TASK)
    ctx = GenerationContext(model=model, catalog=load_catalog(), seed=0,
                            rng=np.random.default_rng(unit_seed(0, "cot", task.id)))
    return make_generator("cot").generate(task.brief(), ctx)


def test_written_environments_get_the_scene_s_words_and_checks_from_protocol_5() -> None:
    """The same setup for every method (issue 46): a written environment's categories, rooms,
    roles and placements are in the grammar, and an object on itself is re-asked as in
    LogicEnvGen's and Holodeck-like's scenes; under protocol 4 it was a final failure."""
    new, old = SelfSupporting(5), SelfSupporting(4)
    built, failed = _cot(new), _cot(old)
    assert [r.kind for r in new.requests] == ["cot_environments"] * 2  # re-asked once
    assert "inside" in new.requests[1].messages[-1]["content"]
    assert all(a.built for a in built.attempts) and len(built.envs) == len(_cot(Seen(5)).envs)
    assert [r.kind for r in old.requests] == ["cot_environments"]
    assert not all(a.built for a in failed.attempts)
    placed = new.requests[0].schema["$defs"]["PlacedObject"]["properties"]
    assert "enum" in placed["category"] and "enum" in placed["room"]
    assert "enum" not in old.requests[0].schema["$defs"]["PlacedObject"]["properties"]["category"]


def test_state_keys_are_the_flags_from_protocol_5() -> None:
    """Qwen2.5-Coder-1.5B wrote its schema's words as state keys (`"states":
    {"additionalProperties": false}`, 9 of 11 scenes): from protocol 5 on a scene object's
    `states` has the condition language's flags as its only (optional) keys in the grammar, and a
    reply with another key is re-asked; under protocol 4 the schema is what it always was."""
    from logicenveval.llm.replies import SelectionWire
    from logicenveval.model.conditions import STATE_FLAGS

    seen = {p: Seen(p) for p in (4, 5)}
    for model in seen.values():
        task = load_task(TASK)
        ctx = GenerationContext(model=model, catalog=load_catalog(), seed=0,
                                rng=np.random.default_rng(unit_seed(0, "logicenvgen", task.id)))
        assert make_generator("logicenvgen").generate(task.brief(), ctx).envs
    first = {p: next(r for r in m.requests if r.kind == "select_objects") for p, m in seen.items()}
    states = first[5].schema["$defs"]["OtherObjectWire"]["properties"]["states"]
    assert list(states["properties"]) == list(STATE_FLAGS) and states["additionalProperties"] is False
    assert "properties" not in first[4].schema["$defs"]["OtherObjectWire"]["properties"]["states"]
    assert "x-some-keys" not in json.dumps(first[4].schema) + json.dumps(first[5].schema)
    reply = json.loads(seen[5].inner.complete(first[5]))
    reply["other_objects"][0]["states"] = {"additionalProperties": False}
    with pytest.raises(ValidationError, match="not state flags"):
        SelectionWire.model_validate(reply, context={CONTEXT_KEY: {"state_flags": list(STATE_FLAGS)}})
