"""LogicEnvGen's plan held to the physical axioms, from request protocol 7 on (issue 46,
`logic.axioms`): a factor response no environment can meet is rule (d)'s to ask again, and a tree
asks on a path only factors whose every response the path leaves possible, so no planned
situation puts one object in two places."""

from __future__ import annotations

import itertools
import json

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scripted import Scripted

from logicenveval.domain.catalog import load_catalog
from logicenveval.generators.base import GenerationContext
from logicenveval.generators.plan import (
    PlanLog,
    _grow_tree,
    _identify,
    check_factor,
    plan_vocabulary,
)
from logicenveval.llm.base import ChatRequest, ModelStats
from logicenveval.llm.replies import FactorDraft, PlanLeaf, QueryNode, SubtaskDraft
from logicenveval.logic.axioms import Axioms
from logicenveval.model.conditions import parse
from logicenveval.model.task import Role, TaskBrief

CATALOG = load_catalog()
ROLES = {"bottle": Role(category="medicine_bottle"), "vanity": Role(category="bathroom_vanity"),
         "cabinet": Role(category="medicine_cabinet"), "towel": Role(category="towel"),
         "mop": Role(category="mop", optional=True)}
BRIEF = TaskBrief(id="bathroom_counter_sort", description="Sort out the bathroom counter.",
                  rooms=["bathroom"], roles=ROLES)


def _possible(*texts: str) -> bool:
    conds = [parse(t) for t in texts]
    return Axioms(ROLES, conds).possible(*conds)


@pytest.mark.parametrize("texts", [
    ("on(bottle, bottle)",), ("inside(towel, towel)",),
    ("on(bottle, vanity)", "on(bottle, floor)"), ("on(bottle, vanity)", "inside(bottle, cabinet)"),
    ("attr(towel, colour, red)", "attr(towel, colour, blue)"),
    ("in_room(towel, bathroom)", "in_room(towel, kitchen)"),
    ("on(towel, mop)", "not exists(mop)"),
])
def test_what_no_environment_can_meet(texts: tuple[str, ...]) -> None:
    """An object on or in itself, in two places or rooms, an attribute with two values, a
    required role absent, something resting on an absent object."""
    assert not _possible(*texts)


@pytest.mark.parametrize("texts", [
    ("on(bottle, vanity)", "not on(bottle, floor)"), ("on(bottle, vanity)", "inside(towel, cabinet)"),
    ("not exists(mop)",), ("on(bottle, vanity) or on(bottle, floor)",), ("not on(bottle, bottle)",),
    ("attr(towel, colour, red)", "attr(towel, size, big)"), ("in_room(towel, bathroom)", "in_room(towel, bathroom_1)"),
])
def test_what_an_environment_can_meet(texts: tuple[str, ...]) -> None:
    """Near misses: two objects in two places, an optional role absent, a disjunction, two
    attributes, one room named by its id and its type."""
    assert _possible(*texts)


#: Qwen2.5-Coder-1.5B's protocol-6 factor for bathroom_counter_sort, as recorded (its brief named
#: no vanity, so the model put the bottle on itself)
RECORDED = ('{"factors":[{"id":"medicine_bottle_on_vanity","question":"Is the medicine bottle on the vanity?",'
            '"responses":[{"response":"yes","condition":[{"predicate":"on","object":"bottle","support":"bottle",'
            '"negated":false}]},{"response":"no","condition":[{"predicate":"on","object":"bottle",'
            '"support":"bottle","negated":true}]}]}]}')
FLOOR = ('{"factors":[{"id":"bottle_on_floor","question":"Is the bottle on the floor?","responses":['
         '{"response":"yes","condition":[{"predicate":"on","object":"bottle","support":"floor","negated":false}]},'
         '{"response":"no","condition":[{"predicate":"on","object":"bottle","support":"floor","negated":true}]}]}]}')


def test_check_factor_names_an_object_on_itself_only_with_the_axioms() -> None:
    factor = FactorDraft(id="on_vanity", question="Is the bottle on the vanity?",
                         values={"yes": "on(bottle, bottle)", "no": "not on(bottle, bottle)"})
    assert check_factor(BRIEF, factor, CATALOG) == []
    assert check_factor(BRIEF, factor, CATALOG, axioms=True) == [
        "factor 'on_vanity' value 'yes': on(bottle, bottle) can never hold: it puts an object on or in "
        "itself or in two places, or gives one attribute two values; ask about something that can differ "
        "between environments of this task"]


@pytest.mark.parametrize(("protocol", "asked", "kept"), [(7, 2, ["bottle_on_floor"]),
                                                          (6, 1, ["medicine_bottle_on_vanity"])])
def test_identify_asks_again_from_protocol_7_and_protocol_6_packs_replay_as_recorded(
        protocol: int, asked: int, kept: list[str]) -> None:
    model = Scripted([RECORDED, FLOOR], reply_protocol=protocol)
    ctx = GenerationContext(model=model, catalog=CATALOG, rng=np.random.default_rng(0))
    subtask = SubtaskDraft(id="sort_bottle", description="Put the bottle away.", roles=["bottle"])
    factors = _identify(BRIEF, ctx, plan_vocabulary(BRIEF), PlanLog(), subtask, 2)
    assert [f.id for f in factors] == kept and len(model.requests) == asked


class FirstOffered:
    """A model growing trees by always asking the first factor it is offered (never `act` while a
    factor is left), and writing one plain leaf per situation: the widest tree the planner allows."""

    name = "first-offered"
    run_dir = None

    def __init__(self, protocol: int) -> None:
        self.reply_protocol = protocol
        self.stats = ModelStats()
        self.offered: list[list[str]] = []

    def complete(self, request: ChatRequest) -> str:
        props = request.schema["properties"]
        if request.kind == "tree_step":
            options = props["next"]["enum"]
            self.offered.append(options)
            return json.dumps({"next": options[0]})
        n = props["leaves"]["minItems"]
        return json.dumps({"leaves": [{"plan": ["tidy up"], "goal": []}] * n})


def _paths(node: QueryNode | PlanLeaf, path: tuple[tuple[str, str], ...] = ()) -> list[tuple[tuple[str, str], ...]]:
    if isinstance(node, PlanLeaf):
        return [path]
    return [p for v, c in node.branches.items() for p in _paths(c, (*path, (node.var, v)))]


def _yes_no(fid: str, text: str) -> FactorDraft:
    return FactorDraft(id=fid, question=f"{fid}?", values={"yes": text, "no": f"not {text}"})


def _grow(factors: list[FactorDraft], protocol: int) -> tuple[QueryNode | PlanLeaf, FirstOffered]:
    model = FirstOffered(protocol)
    ctx = GenerationContext(model=model, catalog=CATALOG, rng=np.random.default_rng(0))
    subtask = SubtaskDraft(id="sort", description="Sort out the counter.", roles=list(ROLES))
    tree = _grow_tree(BRIEF, ctx, subtask, {f.id: f for f in factors}, PlanLog())
    return tree, model


#: the recorded plan's shape: two placements of one bottle as independent factors, and one of
#: them asked twice under two ids
VANITY, FLOOR_F, AGAIN = (_yes_no("on_vanity", "on(bottle, vanity)"), _yes_no("on_floor", "on(bottle, floor)"),
                          _yes_no("close_vanity", "on(bottle, vanity)"))
WET = _yes_no("towel_wet", "state(towel, wet)")


def test_a_path_does_not_ask_what_it_decided() -> None:
    tree, model = _grow([VANITY, FLOOR_F, AGAIN, WET], 7)
    paths = _paths(tree)
    assert (("on_vanity", "yes"), ("towel_wet", "yes")) in paths
    assert all(("on_floor", "yes") not in p or ("on_vanity", "yes") not in p for p in paths)
    assert not any(dict(p).get("close_vanity") for p in paths)  # the same question twice is decided
    assert ["towel_wet", "act"] in model.offered  # after "on the vanity: yes"
    assert len(paths) == 6  # vanity yes × wet, vanity no × floor × wet


def test_protocol_6_packs_grow_the_trees_they_recorded() -> None:
    tree, _ = _grow([VANITY, FLOOR_F, AGAIN, WET], 6)
    assert len(_paths(tree)) == 16
    assert any(("on_floor", "yes") in p and ("on_vanity", "yes") in p for p in _paths(tree))


_PLACES = ["vanity", "floor", "cabinet", "towel"]
_LITERALS = [f"{'inside' if p == 'cabinet' else 'on'}(bottle, {p})" for p in _PLACES] + [
    "state(towel, wet)", "attr(towel, colour, red)", "attr(towel, colour, blue)", "exists(mop)"]


@settings(max_examples=25, deadline=None)
@given(st.lists(st.sampled_from(_LITERALS), min_size=1, max_size=4))
def test_every_planned_situation_can_hold(literals: list[str]) -> None:
    """Whatever yes/no factors are identified, every path of a protocol-7 tree can hold, and a
    factor every answer of which is open stays asked (the tree is no smaller than it must be)."""
    factors = [_yes_no(f"f{i}", t) for i, t in enumerate(literals)]
    tree, _ = _grow(factors, 7)
    conds = {(f.id, v): parse(t) for f in factors for v, t in f.values.items()}
    axioms = Axioms(ROLES, conds.values())
    for path in _paths(tree):
        assert axioms.possible(*(conds[s] for s in path))
        asked = {f for f, _ in path}
        for f in factors:
            if f.id not in asked:  # left out only because the path decides or rules it out
                assert not all(axioms.possible(*(conds[s] for s in path), conds[f.id, v]) for v in f.values)


def test_independent_factors_are_all_asked_on_every_path() -> None:
    """Near miss: factors about different objects never decide each other."""
    factors = [_yes_no("a", "on(bottle, vanity)"), WET, _yes_no("c", "exists(mop)")]
    tree, _ = _grow(factors, 7)
    assert sorted(_paths(tree)) == sorted(itertools.product(*[[(f.id, "yes"), (f.id, "no")] for f in factors]))
