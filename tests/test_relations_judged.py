"""What the grammar lets a model write, the validator reads (issue 46, item 7): a relation of
the wrong arity or relating an object to itself is dropped and said why, for every method that
writes relations, never the whole reply refused. Live on `living_room_plant_care`, both of
Qwen2.5-Coder-1.5B's Holodeck-like scene replies were refused whole for `edge(vase,
side_table)` (the grammar lets every relation take one or two objects)."""

from __future__ import annotations

import json
from typing import Any

import numpy as np
import pytest

from logicenveval.benchmark import load_task
from logicenveval.domain.catalog import load_catalog
from logicenveval.generators.base import (
    GenerationContext,
    GenerationResult,
    make_generator,
    unit_seed,
)
from logicenveval.llm.base import ChatRequest
from logicenveval.llm.replies import RelationsWire, judged_relations
from logicenveval.offline.model import OfflineModel

TASK = "clean_living_room"


class WithBadRelations:
    """The offline model, with two relations no checker can use added to every reply that
    writes relations: one of the wrong arity, one of an object with itself."""

    def __init__(self) -> None:
        self.inner = OfflineModel()
        self.name = self.inner.name
        self.stats = self.inner.stats

    def __getattr__(self, name: str) -> Any:
        return getattr(self.inner, name)

    def complete(self, request: ChatRequest) -> str:
        reply = json.loads(self.inner.complete(request))
        for part in reply.get("environments", [reply]):
            ids = [*part.get("role_objects", {}), *(o["id"] for o in part.get("objects", []))]
            if "relations" in part and len(ids) >= 2:
                part["relations"] += [{"type": "edge", "args": [ids[0], ids[1]]},
                                      {"type": "on", "args": [ids[1], ids[1]]}]
        return json.dumps(reply)


def _generate(model: Any, generator: str) -> GenerationResult:
    task = load_task(TASK)
    ctx = GenerationContext(model=model, catalog=load_catalog(), seed=0,
                            rng=np.random.default_rng(unit_seed(0, generator, task.id)))
    return make_generator(generator).generate(task.brief(), ctx)


@pytest.mark.parametrize("generator", ["holodeck", "cot", "ifg"])
def test_a_relation_the_checker_cannot_use_is_dropped_and_recorded_not_the_reply(generator: str) -> None:
    clean = _generate(OfflineModel(), generator)
    noisy = _generate(WithBadRelations(), generator)
    assert clean.envs and [e.model_dump_json() for e in noisy.envs] == [e.model_dump_json() for e in clean.envs]
    dropped = noisy.artifacts["dropped_relations"]
    assert set(dropped) == {e.env_id for e in noisy.envs}
    for pairs in dropped.values():
        assert [why.split(" ")[0].split("(")[0] for _, why in pairs] == ["edge", "on"]
        assert "takes 1 object id(s), not 2" in pairs[0][1] and "to itself" in pairs[1][1]
    assert "dropped_relations" not in clean.artifacts


def test_judged_relations_leaves_unparsable_relations_to_the_reply_s_own_error() -> None:
    from pydantic import ValidationError

    from logicenveval.baselines.replies import WrittenEnvironment

    base = {"rooms": [{"id": "r", "type": "LivingRoom", "polygon": [[0, 0], [1, 0], [1, 1]]}],
            "objects": [{"id": "vase", "category": "vase", "room": "r", "placement": "floor",
                         "position": [0, 0, 0], "size": [1, 1, 1]}]}
    with pytest.raises(ValidationError, match="relations"):
        WrittenEnvironment.model_validate({**base, "relations": [{"type": "edge"}]})
    kept = WrittenEnvironment.model_validate({**base, "relations": [{"type": "edge", "args": ["vase"]}]})
    assert kept.dropped_relations == [] and [r.args for r in kept.relations] == [["vase"]]


def test_the_same_split_for_every_reply_kind() -> None:
    """`judged_relations` and LogicEnvGen's `RelationsWire.split` give the same reasons."""
    relations = [{"type": "edge", "args": ["a", "b"]}, {"type": "on", "args": ["a", "a"]},
                 {"type": "on", "args": ["a", "b"]}]

    class Info:
        context = None

    data, dropped = judged_relations({"relations": relations}, Info())  # type: ignore[arg-type]
    good, bad = RelationsWire.model_validate({"relations": relations}).split()
    assert data["relations"] == [r.model_dump() for r in good] and dropped == bad


def test_a_cot_draft_that_copies_an_earlier_one_is_a_failed_attempt_named_as_a_copy() -> None:
    """Qwen2.5-Coder-1.5B's CoT replies copied one environment 12 times (issue 46); 12 copies
    counted as 12 environments, raising PhyPR and SceVR for nothing new."""

    class Copying(WithBadRelations):
        def complete(self, request: ChatRequest) -> str:
            reply = json.loads(self.inner.complete(request))
            if request.kind == "cot_environments":
                first = reply["environments"][0]
                reply["environments"] = [first, {**first, "situation": "another words"}, *reply["environments"][1:]]
            return json.dumps(reply)

    clean = _generate(OfflineModel(), "cot")
    copied = _generate(Copying(), "cot")
    assert len(copied.envs) == len(clean.envs)
    failed = [a for a in copied.attempts if not a.built]
    assert [(a.id, a.stage) for a in failed] == [("cot-01", "distinct")]
    assert failed[0].reason is not None and failed[0].reason.startswith("a copy of cot-00")
