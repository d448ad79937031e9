"""Mutation operators, classification by simulation, pruning soundness and `tasks mutants`."""

from __future__ import annotations

import functools
import json

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from logicenveval.benchmark import load_task, policy_path, task_ids
from logicenveval.cli import main
from logicenveval.domain.catalog import load_catalog
from logicenveval.errors import PolicyFormatError
from logicenveval.faults.classify import MutantRunner, _distance, classify_task, task_worlds
from logicenveval.faults.operators import (
    FAULT_CLASSES,
    OPERATORS,
    PARENT_EDITS,
    _edits,
    _get,
    _mutant,
    _replace,
    mutants,
)
from logicenveval.faults.score import clear_cache, scorer_for
from logicenveval.sim.loader import load_policy, policy_from_xml, policy_to_xml
from logicenveval.sim.policy import Policy, PolicyNode
from logicenveval.sim.simulator import CompiledPolicy, simulate, task_goal
from logicenveval.sim.world import World


def _correct(task_id: str):  # type: ignore[no-untyped-def]
    task = load_task(task_id)
    return task, load_policy(policy_path(task, "correct"), roles=task.roles, rooms=task.rooms)


@functools.lru_cache(maxsize=4)
def _prepared(task_id: str):  # type: ignore[no-untyped-def]
    task, correct = _correct(task_id)
    cat = load_catalog()
    muts = mutants(correct, roles=task.roles, rooms=task.rooms)
    return task, cat, muts, MutantRunner(correct, muts), task_worlds(task, cat, 3)


@pytest.mark.parametrize("task_id", ["clean_living_room", "bedroom_bookshelf_sorting"])
def test_mutants_are_valid_distinct_first_order_and_deterministic(task_id: str) -> None:
    task, correct = _correct(task_id)
    muts = mutants(correct, roles=task.roles, rooms=task.rooms)
    assert [m.id for m in muts] == [m.id for m in mutants(correct, roles=task.roles, rooms=task.rooms)]
    assert len({m.id for m in muts}) == len(muts)
    assert len({m.xml for m in muts}) == len(muts) and policy_to_xml(correct) not in {m.xml for m in muts}
    assert {m.fault_class for m in muts} == set(FAULT_CLASSES)
    for m in muts:
        assert m.fault_class == OPERATORS[m.operator]
        reloaded = policy_from_xml(m.xml, "mutant", roles=task.roles, rooms=task.rooms)
        assert policy_to_xml(reloaded) == m.xml  # valid BT.CPP v4 XML that round-trips
        # first order: outside the edited node's parent, the mutant is the correct BT
        tree, idx = m.location
        assert {k: v for k, v in m.policy.trees.items() if k != tree} == {
            k: v for k, v in correct.trees.items() if k != tree}
        original = _get(correct.trees[tree], idx[:-1])
        restored = _replace(m.policy.trees[tree], idx[:-1], lambda _, o=original: o)
        assert restored == correct.trees[tree]


def _reference_mutants(policy: Policy, roles: list[str] | None, rooms: list[str] | None) -> list[str]:
    """The definition `mutants` implements without printing XML: every edit applied, printed,
    dropped if its XML is the correct BT's or an earlier mutant's, kept if it loads again."""
    seen, out = {policy_to_xml(policy)}, []
    for edit in _edits(policy):
        m = _mutant(policy, edit)
        if m.xml in seen:
            continue
        try:
            policy_from_xml(m.xml, "mutant", roles=roles, rooms=rooms)
        except PolicyFormatError:
            continue
        seen.add(m.xml)
        out.append(m.id)
    return out


_LEAVES = ['<Walk target="toy"/>', '<Walk target="box"/>', '<Pick obj="toy"/>', '<Pick obj="box"/>',
           '<PutIn obj="toy" target="box"/>', '<Place obj="toy" target="floor"/>',
           '<Holding obj="toy"/>', '<On obj="toy" target="floor"/>', "<AlwaysSuccess/>",
           '<SubTree ID="Sub"/>']


@st.composite
def _trees(draw: st.DrawFn, depth: int = 3) -> str:
    """Small BTs with repeated siblings (duplicate mutants), one-child controls (invalid
    deletions), IfThenElse and skip branches."""
    if depth == 0 or draw(st.integers(0, 3)) == 0:
        return draw(st.sampled_from(_LEAVES))
    kind = draw(st.sampled_from(["Sequence", "Fallback", "ReactiveSequence", "IfThenElse",
                                 "SkipBranch", "Inverter"]))
    if kind == "Inverter":
        return f"<Inverter>{draw(_trees(depth - 1))}</Inverter>"
    if kind == "SkipBranch":
        return f'<Fallback><Inverter><Holding obj="toy"/></Inverter>{draw(_trees(depth - 1))}</Fallback>'
    n = draw(st.integers(2, 3)) if kind == "IfThenElse" else draw(st.integers(1, 4))
    kids = [draw(_trees(depth - 1)) for _ in range(n)]
    if draw(st.booleans()) and n > 1:
        kids[1] = kids[0]  # equal siblings
    return f"<{kind}>{''.join(kids)}</{kind}>"


@settings(max_examples=150, deadline=None)
@given(_trees(), _trees())
def test_mutants_equal_printing_and_reloading_every_edit(main_tree: str, sub_tree: str) -> None:
    xml = (f'<root BTCPP_format="4" main_tree_to_execute="Main"><BehaviorTree ID="Main">{main_tree}'
           f'</BehaviorTree><BehaviorTree ID="Sub">{sub_tree.replace("SubTree", "AlwaysSuccess")}'
           "</BehaviorTree></root>")
    roles = ["toy", "box"]
    try:
        policy = policy_from_xml(xml, "p", roles=roles)
    except PolicyFormatError:
        return
    got = mutants(policy, roles=roles)
    assert [m.id for m in got] == _reference_mutants(policy, roles, None)
    for m in got:  # a deletion's or reorder's region: the node and its later siblings then
        tree, idx = m.location
        if m.operator in PARENT_EDITS:
            parent = _get(policy.trees[tree], idx[:-1])
            assert m.region == tuple((*idx[:-1], j) for j in range(idx[-1], len(parent.children)))


def test_the_mutants_of_a_large_bt_are_an_evenly_spaced_sample(monkeypatch: pytest.MonkeyPatch) -> None:
    """Above `max_mutants`, an evenly spaced sample of the full list (docs/faults.md)."""
    task, correct = _correct("clean_living_room")
    main = correct.trees[correct.main]
    copies = tuple(correct.trees[t] for _ in range(12) for t in ("TidyToy", "TidyBook"))
    big = Policy(correct.main, {**correct.trees, correct.main: PolicyNode(
        main.kind, main.params, (*main.children[:-1], *copies, main.children[-1]), main.name)})
    monkeypatch.setenv("LOGICENVEVAL_MAX_MUTANTS", "1000000")
    full = [m.id for m in mutants(big, roles=task.roles, rooms=task.rooms)]
    assert len(full) > 500
    monkeypatch.delenv("LOGICENVEVAL_MAX_MUTANTS")
    capped = [m.id for m in mutants(big, roles=task.roles, rooms=task.rooms)]
    assert len(capped) == 500 and capped == [full[k * len(full) // 500] for k in range(500)]
    assert {i.split("@")[0] for i in capped} == {i.split("@")[0] for i in full}
    monkeypatch.setenv("LOGICENVEVAL_MAX_MUTANTS", "1000000")
    assert _reference_mutants(big, task.roles, task.rooms) == full


def test_classification_reproduces_the_hand_written_faults() -> None:
    report = classify_task("clean_living_room", worlds=2)
    assert len(report.killable) >= 20
    assert report.outcomes and all(o.killed_by or o.equivalent for o in report.outcomes)
    for kind, match in report.handwritten.items():
        assert match.reproduced_by, kind
        assert match.edits == _distance(*[load_policy(policy_path(load_task("clean_living_room"), k))
                                          for k in ("correct", kind)])
        ids = {o.id: o for o in report.outcomes}
        assert ids[match.reproduced_by[0]].killed_by == match.signature
    # kill verdicts follow the taxonomy: deleting a Walk breaks a precondition
    walks = [o for o in report.killable if o.operator == "delete_precondition"]
    assert walks and all("precondition_violation" in ks for o in walks for ks in o.killed_by.values())


def _full(muts, env, task, cat) -> dict[int, str]:  # type: ignore[no-untyped-def]
    return {i: v.status for i, m in enumerate(muts)
            if (v := simulate(m.policy, env, task, cat)).status != "passed"}


@settings(max_examples=12, deadline=None)
@given(st.sampled_from(task_ids()), st.integers(0, 10_000))
def test_pruned_resumed_runner_equals_simulating_every_mutant(task_id: str, pick: int) -> None:
    """A mutant whose edited region the correct BT never ticks is judged without simulation,
    the others resume from the correct BT's recorded state where they can first differ; this
    must give exactly the verdicts of simulating every mutant from the start."""
    task, cat, muts, runner, envs = _prepared(task_id)
    _, env = envs[pick % len(envs)]
    world = World.from_env(env, cat)
    assert runner.run(world, task_goal(task, world)) == _full(muts, env, task, cat)


def test_constant_leaves_count_as_ticked() -> None:
    """`AlwaysSuccess` leaves leave no trace event; the runner still sees them ticked (the
    trace-based pruning called deleting this else branch equivalent)."""
    task, cat, muts, runner, envs = _prepared("multi_room_lights_off")
    mid = "delete_alternative@Main:2.2.2"
    i = next(k for k, m in enumerate(muts) if m.id == mid)
    worlds = [env for key, env in envs if "laptop_where=other" in key]
    assert worlds
    for env in worlds:
        world = World.from_env(env, cat)
        got = runner.run(world, task_goal(task, world))
        assert got == _full(muts, env, task, cat)
        assert got[i] == "tree_failure"


@pytest.mark.parametrize("task_id", ["hallway_coat_and_bag", "multi_room_lights_off", "kitchen_dish_cleanup"])
def test_resuming_any_recorded_tick_ends_as_the_recording(task_id: str) -> None:
    """`CompiledPolicy.record` snapshots every node's state and the world before each root tick;
    resuming from any snapshot must end exactly as the recorded episode (all four BTs)."""
    task = load_task(task_id)
    cat = load_catalog()
    for kind in task.policies:
        cp = CompiledPolicy(load_policy(policy_path(task, kind), roles=task.roles, rooms=task.rooms))
        for _, env in task_worlds(task, cat, 1)[:12]:
            w = World.from_env(env, cat)
            goal = task_goal(task, w)
            rec = cp.record(w.copy(), goal)
            assert rec.status == cp.status(w.copy(), goal)
            for snap in rec.snapshots:
                assert cp.resume(snap, goal) == rec.status


def test_status_matches_run() -> None:
    task, correct = _correct("clean_living_room")
    cat = load_catalog()
    cp = CompiledPolicy(correct)
    for _, env in task_worlds(task, cat, 2):
        w = World.from_env(env, cat)
        goal = task_goal(task, w)
        assert cp.status(w.copy(), goal) == cp.run(w.copy(), goal).status


def test_scorer_cache_is_keyed_and_reused(tmp_path) -> None:  # type: ignore[no-untyped-def]
    task = load_task("lamp_or_pillow_fetch")
    cat = load_catalog()
    scorer = scorer_for(task, None, cat, cache_dir=tmp_path, worlds=1)
    data = json.loads((tmp_path / "lamp_or_pillow_fetch.json").read_text())
    assert data["killable"] == [m.id for m in scorer.killable] and len(data["key"]) == 64
    (tmp_path / "lamp_or_pillow_fetch.json").write_text('{"key": "stale", "killable": []}')
    clear_cache()
    again = scorer_for(task, None, cat, cache_dir=tmp_path, worlds=1)  # stale cache: recomputed
    assert [m.id for m in again.killable] == [m.id for m in scorer.killable]
    (tmp_path / "lamp_or_pillow_fetch.json").write_bytes(b"\xff\xfe garbage")
    clear_cache()
    garbled = scorer_for(task, None, cat, cache_dir=tmp_path, worlds=1)  # unreadable: recomputed
    assert [m.id for m in garbled.killable] == [m.id for m in scorer.killable]


def test_tasks_mutants_cli(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["tasks", "mutants", "--tasks", "lamp_or_pillow_fetch", "--worlds", "2", "--json"]) == 0
    (row,) = json.loads(capsys.readouterr().out)
    assert row["task"] == "lamp_or_pillow_fetch"
    assert row["killable"] + row["equivalent"] == row["mutants"] == len(row["mutant_list"])
    assert all(h["reproduced_by"] for h in row["handwritten"].values())
    assert main(["tasks", "mutants", "--tasks", "lamp_or_pillow_fetch", "--worlds", "2"]) == 0
    assert "killable" in capsys.readouterr().out
    assert main(["tasks", "mutants", "--tasks", "no_such_task"]) == 2


def test_shipped_killable_lists_are_current_and_equal_a_fresh_classification() -> None:
    from logicenveval.benchmark import task_ids
    from logicenveval.faults.score import shipped_is_current, shipped_path

    cat = load_catalog()
    stale = [t for t in task_ids() if not shipped_is_current(load_task(t), None, cat)]
    assert not stale, f"run `python -m logicenveval tasks mutants --write` (stale: {stale})"
    task = load_task("lamp_or_pillow_fetch")
    shipped = json.loads(shipped_path(task, None).read_text())["killable"]
    assert shipped == [o.id for o in classify_task(task, None, cat).killable]


def test_written_list_is_read_instead_of_classifying(tmp_path, monkeypatch) -> None:  # type: ignore[no-untyped-def]
    import shutil

    from logicenveval.benchmark import DEFAULT_TASKS_DIR

    shutil.copytree(DEFAULT_TASKS_DIR / "lamp_or_pillow_fetch", tmp_path / "lamp_or_pillow_fetch")
    (tmp_path / "lamp_or_pillow_fetch" / "killable_mutants.json").unlink()
    assert main(["tasks", "mutants", "--tasks", "lamp_or_pillow_fetch", "--worlds", "2", "--write",
                 "--tasks-dir", str(tmp_path)]) == 0
    written = json.loads((tmp_path / "lamp_or_pillow_fetch" / "killable_mutants.json").read_text())

    def refuse(*a, **k):  # type: ignore[no-untyped-def]
        raise AssertionError("classified although a current list was shipped")

    monkeypatch.setattr("logicenveval.faults.score.classify_task", refuse)
    clear_cache()
    task = load_task("lamp_or_pillow_fetch", tmp_path)
    scorer = scorer_for(task, tmp_path, load_catalog(), worlds=2)
    assert [m.id for m in scorer.killable] == written["killable"]


def test_killed_is_memoised_by_the_symbolic_world_only() -> None:
    from logicenveval.faults.score import MutationScorer
    from logicenveval.model.envspec import EnvSpec
    from logicenveval.sim.world import symbolic_key

    task, cat, muts, _, worlds = _prepared("lamp_or_pillow_fetch")
    _, correct = _correct("lamp_or_pillow_fetch")
    envs: list[EnvSpec] = [env for _, env in worlds]
    fresh = [MutationScorer(correct, muts).killed(env, task, cat) for env in envs]
    shared = MutationScorer(correct, muts)
    assert [shared.killed(env, task, cat) for env in envs] == fresh
    env = envs[0]
    renamed = env.model_copy(update={"env_id": "another-name"})
    assert symbolic_key(renamed) == symbolic_key(env)  # the file's name is not part of the world
    first = env.objects[0]
    for change in ({"room": "elsewhere"}, {"states": {**first.states, "dirty": True}},
                   {"attributes": {**first.attributes, "colour": "x"}}, {"category": "mug"},
                   {"support": "floor-x"}, {"container": "box-x"}):
        changed = env.model_copy(update={"objects": [first.model_copy(update=change), *env.objects[1:]]})
        assert symbolic_key(changed) != symbolic_key(env), change
    assert symbolic_key(env.model_copy(update={"roles": {}})) != symbolic_key(env)


def test_mutants_are_scored_on_the_env_as_judged() -> None:
    """An env whose roles the harness binds kills the same mutants as the same env with its roles."""
    from logicenveval.faults.score import MutationScorer
    from logicenveval.runner.evaluation import evaluate_env, with_killed_mutants

    task, cat, muts, _, worlds = _prepared("lamp_or_pillow_fetch")
    _, correct = _correct("lamp_or_pillow_fetch")
    policies = {k: load_policy(policy_path(task, k), roles=task.roles, rooms=task.rooms) for k in task.policies}
    scorer = MutationScorer(correct, muts)
    situation = worlds[0][1]
    # object ids unlike role names (as generators write them), so an unbound role cannot be
    # resolved by accident through an id equal to its name
    new = {o.id: f"obj{i}" for i, o in enumerate(situation.objects)}
    env = situation.model_copy(update={
        "objects": [o.model_copy(update={"id": new[o.id],
                                         "support": new.get(o.support or "", o.support),
                                         "container": new.get(o.container or "", o.container)})
                    for o in situation.objects],
        "roles": {r: new[oid] if oid else None for r, oid in situation.roles.items()}})
    anonymous = env.model_copy(update={"roles": {}})
    with_roles = with_killed_mutants(evaluate_env("g", task, env, policies, cat), task, scorer, cat)
    bound = with_killed_mutants(evaluate_env("g", task, anonymous, policies, cat), task, scorer, cat)
    assert bound.verdicts["correct"] == "passed" and bound.killed_mutants
    assert bound.killed_mutants == with_roles.killed_mutants
    # the fixture discriminates: scored on the unbound env, more mutants would count as killed
    assert MutationScorer(correct, muts).killed(anonymous, task, cat) != bound.killed_mutants


def test_a_task_bt_and_its_mutants_are_prepared_once_per_process(tmp_path, monkeypatch) -> None:  # type: ignore[no-untyped-def]
    """Every unit of a task needs the same parsed BT and mutant list: a worker makes them once,
    and again only when the BT file's content or a limit changes."""
    import shutil

    import logicenveval.faults.score as score
    from logicenveval.benchmark import DEFAULT_TASKS_DIR

    shutil.copytree(DEFAULT_TASKS_DIR / "lamp_or_pillow_fetch", tmp_path / "lamp_or_pillow_fetch")
    listed: list[int] = []

    def counting(policy, **kw):  # type: ignore[no-untyped-def]
        listed.append(1)
        return mutants(policy, **kw)

    monkeypatch.setattr(score, "mutants", counting)
    clear_cache()
    task = load_task("lamp_or_pillow_fetch", tmp_path)
    cat = load_catalog()
    first = scorer_for(task, tmp_path, cat, worlds=2)
    assert scorer_for(load_task("lamp_or_pillow_fetch", tmp_path), tmp_path, cat, worlds=2) is first
    assert len(listed) == 1
    bt = policy_path(task, "correct", tmp_path)
    bt.write_text(bt.read_text().replace("<BehaviorTree", "<!-- edited -->\n<BehaviorTree", 1))
    scorer_for(task, tmp_path, cat, worlds=2)
    assert len(listed) == 2  # new content: parsed and listed again
    monkeypatch.setenv("LOGICENVEVAL_MAX_MUTANTS", "7")
    assert len(scorer_for(task, tmp_path, cat, worlds=2).killable) <= 7
    assert len(listed) == 3  # another limit: another list
    clear_cache()


def test_evaluation_builds_the_initial_world_once_for_coverage_and_traced_episodes(monkeypatch) -> None:  # type: ignore[no-untyped-def]
    """Coverage and the traced episodes share one initial world; only the timed episodes (the
    paper's ST: `simulate` whole) build their own."""
    from logicenveval.runner.evaluation import evaluate_env

    task, cat, _, _, worlds = _prepared("lamp_or_pillow_fetch")
    policies = {k: load_policy(policy_path(task, k), roles=task.roles, rooms=task.rooms) for k in task.policies}
    env = worlds[0][1]
    built: list[int] = []
    original = World.from_env.__func__  # type: ignore[attr-defined]

    def counting(cls, *a, **kw):  # type: ignore[no-untyped-def]
        built.append(1)
        return original(cls, *a, **kw)

    monkeypatch.setattr(World, "from_env", classmethod(counting))
    done = evaluate_env("g", task, env, policies, cat)
    assert len(built) == 1 + len(policies)
    for kind, policy in policies.items():  # the traces are those of `simulate`
        alone = simulate(policy, env, task, cat, trace=True)
        assert done.traces[kind].status == alone.status == done.sample.verdicts[kind]
        assert done.traces[kind].trace == [str(t) for t in alone.trace]


def test_a_symbolic_world_already_traced_is_not_traced_again(monkeypatch) -> None:  # type: ignore[no-untyped-def]
    """Another environment realising the same situation with the same objects (another id,
    other coordinates) reuses the traces; its timed episodes still run."""
    from logicenveval.runner import evaluation
    from logicenveval.sim.simulator import CompiledPolicy

    task, cat, _, _, worlds = _prepared("lamp_or_pillow_fetch")
    policies = {k: load_policy(policy_path(task, k), roles=task.roles, rooms=task.rooms) for k in task.policies}
    env = worlds[1][1]
    twin = env.model_copy(update={"env_id": "twin", "agent": env.agent.model_copy(update={"position": (9.0, 9.0)})})
    runs: list[bool] = []
    original = CompiledPolicy.run

    def counting(self, *a, trace=False, **kw):  # type: ignore[no-untyped-def]
        runs.append(trace)
        return original(self, *a, trace=trace, **kw)

    monkeypatch.setattr(CompiledPolicy, "run", counting)
    monkeypatch.setattr(evaluation, "_TRACED", {})
    first = evaluation.evaluate_env("g", task, env, policies, cat)
    assert runs.count(True) == runs.count(False) == len(policies)
    second = evaluation.evaluate_env("h", task, twin, policies, cat)
    assert runs.count(True) == len(policies) and runs.count(False) == 2 * len(policies)
    assert second.traces == first.traces and second.sample.sim_ticks == first.sample.sim_ticks
    other = worlds[2][1]  # another situation: traced
    evaluation.evaluate_env("g", task, other, policies, cat)
    assert runs.count(True) == 2 * len(policies)
