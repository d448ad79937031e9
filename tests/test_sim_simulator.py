"""BT.CPP control-node semantics, verdict order, and properties of the simulator."""

from __future__ import annotations

from typing import Any

from hypothesis import given, settings
from hypothesis import strategies as st
from sim_support import small_catalog

from logicenveval.domain.actions import ACTIONS
from logicenveval.model.envspec import EnvSpec
from logicenveval.model.task import task_from_dict
from logicenveval.sim.loader import policy_from_xml
from logicenveval.sim.simulator import simulate
from logicenveval.sim.verdict import Verdict
from logicenveval.sim.world import World

CAT = small_catalog()
ENV = EnvSpec.model_validate({
    "task_id": "tidy", "env_id": "e",
    "rooms": [{"id": "living_room"}, {"id": "kitchen"}],
    "doors": [{"id": "d", "rooms": ["living_room", "kitchen"]}],
    "objects": [
        {"id": "toy_1", "category": "toy", "room": "living_room", "attributes": {"kind": "car"}},
        {"id": "box_1", "category": "toy_box", "room": "living_room"},
        {"id": "sofa_1", "category": "sofa", "room": "living_room"},
        {"id": "fridge_1", "category": "fridge", "room": "kitchen"},
    ],
    "roles": {"toy": "toy_1", "box": "box_1", "sofa": "sofa_1", "fridge": "fridge_1"}})
TASK = task_from_dict({
    "id": "tidy", "description": "put the toy into the box", "rooms": ["living_room", "kitchen"],
    "roles": {"toy": {"category": "toy"}, "box": {"category": "toy_box"},
              "sofa": {"category": "sofa"}, "fridge": {"category": "fridge"}},
    "variables": {"where": {"question": "toy on floor?",
                            "values": {"yes": "on(toy, floor)", "no": "not on(toy, floor)"}}},
    "subtasks": [{"id": "s", "tree": {"var": "where", "branches": {
        "yes": {"plan": [], "goal": "inside(toy, box)"},
        "no": {"plan": [], "goal": "true"}}}}]})
TIDY = '<Walk target="toy"/><Pick obj="toy"/><Walk target="box"/><PutIn obj="toy" target="box"/>'


def run(body: str, env: EnvSpec = ENV, **kw: Any) -> Verdict:
    text = f'<root BTCPP_format="4"><BehaviorTree ID="Main">{body}</BehaviorTree></root>'
    return simulate(policy_from_xml(text, roles=TASK.roles), env, TASK, CAT, **kw)


def walks(v: Verdict) -> int:
    return sum(1 for e in v.trace if e["node"] == "Walk" and e["status"] == "SUCCESS")


# ----- verdict kinds ---------------------------------------------------------------------
def test_passed_and_one_tick_per_action() -> None:
    v = run(f"<Sequence>{TIDY}</Sequence>", trace=True)
    assert v.status == "passed" and v.goal_holds and v.ticks == 5
    assert v.final_state["roles"]["toy"]["container"] == "box_1"


def test_trace_shows_the_ports_a_node_ran_with() -> None:
    v = run(f"<Sequence>{TIDY}</Sequence>", trace=True)
    walks = [e for e in v.trace if e["node"] == "Walk"]
    # a node's ports are on its first event only (readers carry them forward by path)
    assert [(e["status"], e.get("ports")) for e in walks] == [
        ("RUNNING", "target=toy"), ("SUCCESS", None), ("RUNNING", "target=box"), ("SUCCESS", None)]
    assert all("ports" not in e for e in v.trace if e["node"] == "Sequence")


def test_precondition_violation_names_node_and_path() -> None:
    v = run('<Sequence><Walk target="box"/><PutIn obj="toy" target="box"/></Sequence>')
    assert v.status == "precondition_violation" and v.fault_node == "PutIn"
    assert v.fault_path == "Main/Sequence/PutIn[1]" and "not holding" in v.message


def test_violation_wins_even_if_fallback_recovers() -> None:
    v = run(f'<Fallback><Pick obj="toy"/><Sequence>{TIDY}</Sequence></Fallback>')
    assert v.status == "precondition_violation" and v.fault_node == "Pick"


def test_violation_wins_even_if_retry_recovers() -> None:
    v = run('<RetryUntilSuccessful num_attempts="3"><Sequence><Pick obj="toy"/></Sequence>'
            '</RetryUntilSuccessful>')
    assert v.status == "precondition_violation"


def test_tree_failure_and_goal_unmet_and_tick_limit() -> None:
    v = run(f'<Sequence><Inside obj="toy" target="box"/>{TIDY}</Sequence>')
    assert v.status == "tree_failure" and v.fault_node == "Inside"
    v = run('<Sequence><Walk target="toy"/><Pick obj="toy"/><Walk target="sofa"/>'
            '<Place obj="toy" target="sofa"/></Sequence>')
    assert v.status == "goal_unmet" and v.goal_holds is False
    v = run(f"<Sequence>{TIDY}</Sequence>", tick_limit=3)
    assert v.status == "tick_limit" and v.ticks == 3
    v = run('<KeepRunningUntilFailure><AlwaysSuccess/></KeepRunningUntilFailure>')
    assert v.status == "tick_limit" and v.ticks == 50


def test_endless_retry_returns_running_between_attempts() -> None:
    # BT.CPP 4.x: a child failing synchronously from IDLE hands the flow back (RUNNING), so an
    # endless Retry is one attempt per tick and ends at the tick limit
    v = run('<RetryUntilSuccessful num_attempts="-1"><AlwaysFailure/></RetryUntilSuccessful>')
    assert v.status == "tick_limit" and v.ticks == 50


def test_ill_formed_when_no_branch_holds() -> None:
    env = ENV.model_copy(update={"roles": {**ENV.roles, "toy": None}})
    # an absent toy is neither on the floor nor on the sofa: no branch holds
    task = TASK.model_copy(update={"variables": {"where": TASK.variables["where"].model_copy(
        update={"values": {"yes": "on(toy, floor)", "no": "on(toy, sofa)"}})}})
    text = '<root BTCPP_format="4"><BehaviorTree ID="M"><AlwaysSuccess/></BehaviorTree></root>'
    v = simulate(policy_from_xml(text), env, task, CAT)
    assert v.status == "ill_formed" and v.goal_holds is None


def test_verdict_json_round_trip() -> None:
    v = run(f"<Sequence>{TIDY}</Sequence>", trace=True)
    assert Verdict.model_validate_json(v.model_dump_json()) == v


# ----- BT.CPP semantics ------------------------------------------------------------------
def test_reactive_sequence_rechecks_conditions_each_tick() -> None:
    guarded = ('<{seq}><Inverter><Holding obj="toy"/></Inverter><Sequence>'
               '<Walk target="toy"/><Pick obj="toy"/><Walk target="box"/></Sequence></{seq}>')
    assert run(guarded.format(seq="Sequence")).status == "goal_unmet"  # condition ticked once
    v = run(guarded.format(seq="ReactiveSequence"))
    assert v.status == "tree_failure" and v.fault_node == "Holding"


def test_sequence_with_memory_resumes_at_failed_child() -> None:
    body = ('<RetryUntilSuccessful num_attempts="3"><{seq}><Walk target="toy"/>'
            '<Near obj="box"/></{seq}></RetryUntilSuccessful>')
    plain = run(body.format(seq="Sequence"), trace=True)
    memory = run(body.format(seq="SequenceWithMemory"), trace=True)
    assert plain.status == memory.status == "tree_failure"
    assert walks(plain) == 3 and walks(memory) == 1


def test_fallback_and_reactive_fallback() -> None:
    assert run(f'<Fallback><Inside obj="toy" target="box"/><Sequence>{TIDY}</Sequence>'
               '</Fallback>').status == "passed"
    # the reactive form re-checks the first child each tick; the toy never gets inside until
    # the end, so the sequence finishes as well
    assert run(f'<ReactiveFallback><Inside obj="toy" target="box"/><Sequence>{TIDY}</Sequence>'
               '</ReactiveFallback>').status == "passed"
    # ReactiveFallback halts the running branch as soon as an earlier child succeeds
    v = run('<ReactiveFallback><Near obj="toy"/><Sequence><Walk target="toy"/>'
            '<Walk target="sofa"/></Sequence></ReactiveFallback>', trace=True)
    assert v.status == "goal_unmet" and walks(v) == 1


def test_if_then_else_and_while_do_else() -> None:
    assert run(f'<IfThenElse><On obj="toy" target="floor"/><Sequence>{TIDY}</Sequence>'
               '<AlwaysFailure/></IfThenElse>').status == "passed"
    # two children and a false condition: FAILURE
    assert run('<IfThenElse><On obj="toy" target="sofa"/><AlwaysSuccess/></IfThenElse>'
               ).status == "tree_failure"
    # WhileDoElse re-evaluates the condition and switches branch (halting the other)
    v = run('<WhileDoElse><Inverter><Holding obj="toy"/></Inverter>'
            '<Sequence><Walk target="toy"/><Pick obj="toy"/><Walk target="sofa"/></Sequence>'
            '<Sequence><Walk target="box"/><PutIn obj="toy" target="box"/></Sequence>'
            '</WhileDoElse>', trace=True)
    assert v.status == "passed" and walks(v) == 2


def test_an_action_in_a_condition_slot_runs_once() -> None:
    """BT.CPP 4.10 (recorded: tests/conformance, `while_do_else_action_condition`): a finished
    action keeps its status until a parent resets it. WhileDoElse re-ticks its condition while
    the branch runs; a Pick there is not picked again (which would violate 'hand empty')."""
    v = run('<Sequence><Walk target="toy"/><WhileDoElse><Pick obj="toy"/>'
            '<Sequence><Walk target="box"/><PutIn obj="toy" target="box"/></Sequence>'
            "<AlwaysFailure/></WhileDoElse></Sequence>", trace=True)
    assert v.status == "passed" and v.ticks == 5
    assert [e["status"] for e in v.trace if e["node"] == "Pick"] == ["RUNNING", "SUCCESS"]
    # under a decorator the action is reset after each tick and runs again (BT.CPP alike)
    v = run('<Sequence><Walk target="toy"/><WhileDoElse><ForceSuccess><Pick obj="toy"/>'
            '</ForceSuccess><Sequence><Walk target="box"/><PutIn obj="toy" target="box"/>'
            "</Sequence></WhileDoElse></Sequence>")
    assert v.status == "precondition_violation" and v.fault_node == "Pick"


def test_parallel_counts() -> None:
    both = '<Parallel{a}><Walk target="toy"/><AlwaysFailure/></Parallel>'
    assert run(both.format(a="")).status == "tree_failure"  # failure_count=1
    assert run(both.format(a=' success_count="1" failure_count="2"')).status == "goal_unmet"
    v = run('<Parallel success_count="2"><Walk target="toy"/><Walk target="box"/></Parallel>',
            trace=True)
    assert v.ticks == 2 and walks(v) == 2


def test_decorators() -> None:
    assert run("<Inverter><AlwaysSuccess/></Inverter>").status == "tree_failure"
    assert run('<ForceFailure><Walk target="toy"/></ForceFailure>').status == "tree_failure"
    assert run('<ForceSuccess><On obj="toy" target="sofa"/></ForceSuccess>').status == "goal_unmet"
    v = run('<Repeat num_cycles="3"><Walk target="toy"/></Repeat>', trace=True)
    assert walks(v) == 3 and v.status == "goal_unmet"
    v = run('<RetryUntilSuccessful num_attempts="2"><On obj="toy" target="sofa"/>'
            '</RetryUntilSuccessful>', trace=True)
    assert v.status == "tree_failure" and len(v.trace) == 2


def test_subtree_path() -> None:
    text = ('<root BTCPP_format="4" main_tree_to_execute="Main">'
            '<BehaviorTree ID="Main"><Sequence><SubTree ID="Put"/></Sequence></BehaviorTree>'
            '<BehaviorTree ID="Put"><PutIn obj="toy" target="box"/></BehaviorTree></root>')
    v = simulate(policy_from_xml(text), ENV, TASK, CAT)
    assert v.fault_path == "Main/Sequence/SubTree(Put)[0]/PutIn"


def test_tree_ticks_under_py_trees_behaviour_tree_with_visitors() -> None:
    """The executed tree is a py_trees tree: BehaviourTree and its visitors drive it too."""
    import py_trees

    from logicenveval.sim.nodes import Episode, build_tree

    text = f'<root BTCPP_format="4"><BehaviorTree ID="Main"><Sequence>{TIDY}</Sequence></BehaviorTree></root>'
    root = build_tree(policy_from_xml(text, roles=TASK.roles))
    world = World.from_env(ENV, CAT)
    root.binding.ep = Episode(world)
    tree = py_trees.trees.BehaviourTree(root)
    snapshot = py_trees.visitors.SnapshotVisitor()
    tree.visitors.append(snapshot)
    seen: set[str] = set()
    while root.status is not py_trees.common.Status.SUCCESS and tree.count < 10:
        tree.tick()
        seen |= {n.name for n in root.iterate() if n.id in snapshot.visited}
    assert tree.count == 5 and world.holds("inside", ("toy", "box"))
    assert {"Walk(target=toy)", "Pick(obj=toy)", "PutIn(obj=toy, target=box)"} <= seen


# ----- properties ------------------------------------------------------------------------
NAMES = ["toy", "box", "sofa", "fridge", "floor", "kitchen", "living_room"]
STEP = st.tuples(st.sampled_from(sorted(ACTIONS)), st.sampled_from(NAMES), st.sampled_from(NAMES))


def _leaf(step: tuple[str, str, str]) -> str:
    name, a, b = step
    spec = ACTIONS[name]
    args = dict(zip(spec.ports, (a, b), strict=False))
    return f"<{name} " + " ".join(f'{k}="{v}"' for k, v in args.items()) + "/>"


@settings(max_examples=60, deadline=None)
@given(st.lists(STEP, min_size=1, max_size=8))
def test_random_sequences_never_mutate_the_env_and_are_deterministic(
        steps: list[tuple[str, str, str]]) -> None:
    before = ENV.model_dump_json()
    body = "<Sequence>" + "".join(_leaf(s) for s in steps) + "</Sequence>"
    text = f'<root BTCPP_format="4"><BehaviorTree ID="M">{body}</BehaviorTree></root>'
    policy = policy_from_xml(text)
    first = simulate(policy, ENV, TASK, CAT, trace=True)
    assert simulate(policy, ENV, TASK, CAT, trace=True) == first
    assert ENV.model_dump_json() == before


@settings(max_examples=60, deadline=None)
@given(st.lists(STEP, min_size=1, max_size=10))
def test_sequences_of_valid_actions_pass_preconditions(steps: list[tuple[str, str, str]]) -> None:
    world = World.from_env(ENV, CAT)
    valid: list[str] = []
    for name, a, b in steps:
        spec = ACTIONS[name]
        args = dict(zip(spec.ports, (a, b), strict=False))
        if spec.check(world, args) is None:
            spec.apply(world, args)
            valid.append(_leaf((name, a, b)))
    if not valid:
        return
    body = "<Sequence>" + "".join(valid) + "</Sequence>"
    text = f'<root BTCPP_format="4"><BehaviorTree ID="M">{body}</BehaviorTree></root>'
    v = simulate(policy_from_xml(text), ENV, TASK, CAT)
    assert v.status in ("passed", "goal_unmet") and v.ticks == len(valid) + 1


# ----- control nodes against a logical reference ------------------------------------------
# Over condition leaves (instant, side-effect free) every BT.CPP control node has a boolean
# meaning; a tree of them must finish in one tick with exactly that outcome (SequenceWithMemory,
# AsyncSequence/AsyncFallback and multi-cycle loops hand back RUNNING between children: see the
# conformance corpus).
_WORLD = World.from_env(ENV, CAT)
_CONDS = [('<On obj="toy" target="floor"/>', _WORLD.holds("on", ("toy", "floor"))),
          ('<Holding obj="toy"/>', _WORLD.holds("holding", ("toy",))),
          ('<Inside obj="toy" target="box"/>', _WORLD.holds("inside", ("toy", "box"))),
          ("<AlwaysSuccess/>", True), ("<AlwaysFailure/>", False)]


def _parallel(kids: list[bool], s: int, f: int) -> bool:
    n_s = n_f = 0
    for k in kids:
        n_s, n_f = n_s + k, n_f + (not k)
        if n_s >= s:
            return True
        if len(kids) - n_f < s or n_f == f:
            return False
    raise AssertionError("unreachable with instant children")


def _tree(children: st.SearchStrategy[tuple[str, bool]]) -> st.SearchStrategy[tuple[str, bool]]:
    kids = st.lists(children, min_size=1, max_size=3)

    def wrap(tag: str, value: object, parts: list[tuple[str, bool]], attrs: str = "") -> tuple[str, bool]:
        return f"<{tag}{attrs}>" + "".join(x for x, _ in parts) + f"</{tag}>", bool(value)

    return st.one_of(
        kids.map(lambda ps: wrap("Sequence", all(v for _, v in ps), ps)),
        kids.map(lambda ps: wrap("ReactiveSequence", all(v for _, v in ps), ps)),
        kids.map(lambda ps: wrap("Fallback", any(v for _, v in ps), ps)),
        kids.map(lambda ps: wrap("ReactiveFallback", any(v for _, v in ps), ps)),
        st.tuples(children, children, children).map(
            lambda t: wrap("IfThenElse", t[1][1] if t[0][1] else t[2][1], list(t))),
        st.tuples(children, children).map(lambda t: wrap("IfThenElse", t[0][1] and t[1][1], list(t))),
        st.tuples(children, children, children).map(
            lambda t: wrap("WhileDoElse", t[1][1] if t[0][1] else t[2][1], list(t))),
        st.tuples(kids, st.integers(1, 3), st.integers(1, 3)).filter(
            lambda t: max(t[1], t[2]) <= len(t[0])).map(
            lambda t: wrap("Parallel", _parallel([v for _, v in t[0]], t[1], t[2]), t[0],
                           f' success_count="{t[1]}" failure_count="{t[2]}"')),
        children.map(lambda c: wrap("Inverter", not c[1], [c])),
        children.map(lambda c: wrap("ForceSuccess", True, [c])),
        children.map(lambda c: wrap("ForceFailure", False, [c])),
        # one cycle/attempt: with more, BT.CPP 4.x returns RUNNING between them (not instant)
        children.map(lambda c: wrap("Repeat", c[1], [c], ' num_cycles="1"')),
        children.map(lambda c: wrap("RetryUntilSuccessful", c[1], [c], ' num_attempts="1"')),
    )


TREES = st.recursive(st.sampled_from(_CONDS), _tree, max_leaves=12)


@settings(max_examples=150, deadline=None)
@given(TREES)
def test_control_nodes_over_conditions_match_their_logic(tree: tuple[str, bool]) -> None:
    body, expected = tree
    v = run(body)
    assert v.ticks == 1
    assert v.status == ("goal_unmet" if expected else "tree_failure"), body


@settings(max_examples=60, deadline=None)
@given(TREES)
def test_random_trees_round_trip_through_py_trees(tree: tuple[str, bool]) -> None:
    from logicenveval.sim.pytrees_io import tree_from_xml, tree_to_xml

    text = f'<root BTCPP_format="4"><BehaviorTree ID="Main">{tree[0]}</BehaviorTree></root>'
    exported = tree_to_xml(tree_from_xml(text, roles=TASK.roles))
    assert policy_from_xml(exported, roles=TASK.roles) == policy_from_xml(text, roles=TASK.roles)
    assert run(tree[0]) == simulate(policy_from_xml(exported), ENV, TASK, CAT)


def test_leaves_call_the_py_trees_lifecycle_hooks_only_where_overridden() -> None:
    """A leaf tick skips py_trees' no-op `initialise`/`terminate`, but a leaf class that
    defines them still gets both, at the moments py_trees' `Behaviour.tick` calls them."""
    import py_trees

    from logicenveval.sim.nodes import ActionNode, ConditionNode, ConstNode, Leaf

    assert not (ActionNode.hooks or ConditionNode.hooks or ConstNode.hooks)
    calls: list[str] = []

    class Hooked(Leaf):
        def __init__(self) -> None:
            super().__init__("hooked")
            self.script = [py_trees.common.Status.RUNNING, py_trees.common.Status.SUCCESS]

        def initialise(self) -> None:
            calls.append("initialise")

        def update(self) -> py_trees.common.Status:
            return self.script.pop(0)

        def terminate(self, new_status: py_trees.common.Status) -> None:
            calls.append(f"terminate {new_status.value}")

    leaf = Hooked()
    assert leaf.hooks
    leaf.binding = type("B", (), {"ep": None})()  # type: ignore[assignment]
    leaf.tick_once()
    leaf.tick_once()
    assert calls == ["initialise", "terminate SUCCESS"]


def test_a_reused_tree_starts_every_episode_reset() -> None:
    """`CompiledPolicy` resets its nodes in bulk between episodes (statuses, child indices,
    loop counters): an episode after any other ends as on a freshly built tree."""
    from logicenveval.sim.simulator import CompiledPolicy, task_goal

    xml = ('<root BTCPP_format="4"><BehaviorTree ID="Main"><Sequence>'
           '<RetryUntilSuccessful num_attempts="3"><Sequence><Walk target="toy"/>'
           '<Holding obj="toy"/></Sequence></RetryUntilSuccessful>' + TIDY +
           '</Sequence></BehaviorTree></root>')
    policy = policy_from_xml(xml, roles=TASK.roles)
    world = World.from_env(ENV, CAT)
    goal = task_goal(TASK, world)
    fresh = [CompiledPolicy(policy).run(world.copy(), goal, tick_limit=n).model_dump()
             for n in range(1, 14)]
    reused = CompiledPolicy(policy)
    assert [reused.run(world.copy(), goal, tick_limit=n).model_dump() for n in range(1, 14)] == fresh
    assert [reused.run(world.copy(), goal, tick_limit=n).model_dump()
            for n in reversed(range(1, 14))] == fresh[::-1]


def test_verdicts_are_what_validation_gives_and_the_digest_is_optional() -> None:
    """`CompiledPolicy.run` builds its verdicts without re-validating them: each equals its own
    validated JSON round trip, for every verdict kind; `final_state=False` only leaves the
    final-state digest out (the report's traced runs do not keep it)."""
    from logicenveval.sim.simulator import CompiledPolicy, task_goal

    world = World.from_env(ENV, CAT)
    goal = task_goal(TASK, world)
    bodies = {"passed": TIDY, "precondition_violation": '<Pick obj="toy"/>',
              "tree_failure": '<Holding obj="toy"/>', "goal_unmet": '<Walk target="toy"/>',
              "tick_limit": '<KeepRunningUntilFailure><AlwaysSuccess/></KeepRunningUntilFailure>'}
    for status, body in bodies.items():
        xml = f'<root BTCPP_format="4"><BehaviorTree ID="Main"><Sequence>{body}</Sequence></BehaviorTree></root>'
        cp = CompiledPolicy(policy_from_xml(xml, roles=TASK.roles))
        for goal_ in (goal, None):
            full = cp.run(world.copy(), goal_, trace=True)
            assert full.status == (status if goal_ is not None or status not in ("passed", "goal_unmet")
                                   else "ill_formed")
            assert Verdict.model_validate_json(full.model_dump_json()) == full
            assert full.final_state and full.final_state["roles"]
            bare = cp.run(world.copy(), goal_, trace=True, final_state=False)
            assert bare.final_state == {} and bare.model_copy(update={"final_state": full.final_state}) == full
