"""Attempted environments are the denominator (issue 26): a generator never scores higher by
failing, and a unit that failed for infrastructure reasons is not measured, never zero."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from logicenveval.errors import ModelConnectionError, ModelReplyError
from logicenveval.generators.base import (
    Attempt,
    GenerationContext,
    GenerationFailure,
    GenerationResult,
    counted_attempts,
)
from logicenveval.generators.logicenvgen import LogicEnvGen
from logicenveval.metrics.records import EnvSample, PhysicsSummary, UnitRecord
from logicenveval.model.task import TaskBrief
from logicenveval.reporting.publish import publish
from logicenveval.reporting.tables import markdown
from logicenveval.runner.config import RunConfig
from logicenveval.runner.results import build_results, load_results, write_outputs
from logicenveval.runner.run import run
from logicenveval.runner.seeds import combine_seeds

TASK = "clean_living_room"
PATHS = [["tidy_toy:toy_on_floor=yes/toy_kind=doll", "tidy_book:book_on_floor=yes",
          "clean_mark:wipe_on_table=yes"],
         ["tidy_toy:toy_on_floor=yes/toy_kind=other", "tidy_book:book_on_floor=no",
          "clean_mark:wipe_on_table=no"],
         ["tidy_toy:toy_on_floor=no", "tidy_book:book_on_floor=yes", "clean_mark:wipe_on_table=yes"]]


def _sample(i: int, *, gen: str = "g", task: str = TASK, physics: bool = True, valid: bool = True) -> EnvSample:
    paths = PATHS[i % len(PATHS)]
    return EnvSample(
        generator=gen, task_id=task, env_id=f"{gen}-{i:02d}", covered_paths=paths,
        trajectory=" | ".join(paths), well_formed=True,
        physics=PhysicsSummary(floor_plan=physics, entity=physics, relation=physics),
        verdicts={"correct": "passed" if valid else "goal_unmet", "counterfactual": "tree_failure",
                  "unreachable": "passed", "lackbranch": "passed"},
        sim_ticks={"correct": 5})


def _unit(built: list[EnvSample], failed: int = 0, *, gen: str = "g", task: str = TASK,
          **extra: Any) -> UnitRecord:
    attempts = [Attempt(id=s.env_id, env_id=s.env_id) for s in built]
    attempts += [Attempt(id=f"x{i}", stage="construct", reason="no layout") for i in range(failed)]
    return UnitRecord(generator=gen, task_id=task, samples=built, attempts=attempts, **extra)


def _results(records: list[UnitRecord], gens: tuple[str, ...] = ("g",), seed: int = 0) -> dict[str, Any]:
    from logicenveval.benchmark import load_tasks

    tasks = load_tasks(None, sorted({r.task_id for r in records}))
    return build_results(RunConfig(generators=gens, seed=seed), tasks, records)


# --- the denominator ------------------------------------------------------------------------

def test_failing_half_the_attempts_scores_lower_phypr_and_scevr() -> None:
    samples = [_sample(i) for i in range(3)]
    clean = _results([_unit(samples)])["results"]["g"]
    half = _results([_unit(samples, failed=3)])["results"]["g"]
    assert (clean["n_attempted"], clean["n_failed"]) == (3, 0)
    assert (half["n_attempted"], half["n_failed"]) == (6, 3)
    for dim in ("floor_plan", "entity", "relation", "avg"):
        assert half["phypr"][dim] == pytest.approx(clean["phypr"][dim] / 2)
    assert half["scevr"] == pytest.approx(clean["scevr"] / 2)
    # LogCov, LD, JI and FauDR count only what was built
    for key in ("logcov", "ld", "ji"):
        assert half[key] == clean[key]
    assert half["faudr"] == clean["faudr"]


@given(st.lists(st.tuples(st.booleans(), st.booleans()), min_size=1, max_size=6),
       st.integers(0, 3), st.integers(1, 4))
@settings(max_examples=40, deadline=None)
def test_property_failed_attempts_never_raise_phypr_or_scevr(
        envs: list[tuple[bool, bool]], failed: int, more: int) -> None:
    samples = [_sample(i, physics=p, valid=v) for i, (p, v) in enumerate(envs)]
    before = _results([_unit(samples, failed)])["results"]["g"]
    after = _results([_unit(samples, failed + more)])["results"]["g"]
    assert after["n_attempted"] == before["n_attempted"] + more
    for dim in ("floor_plan", "entity", "relation", "avg"):
        assert after["phypr"][dim] <= before["phypr"][dim]
    assert after["scevr"] <= before["scevr"]


def test_per_task_counts_and_units_written_before_attempts_were_recorded() -> None:
    old = UnitRecord(generator="g", task_id=TASK, samples=[_sample(0)],
                     failures=[GenerationFailure(stage="construct", message="no layout", env_id="g-07"),
                               GenerationFailure(stage="construct", message="claim", env_id="g-00")])
    assert (old.n_attempted, old.n_failed) == (2, 1)  # g-00 was built: a note, not a failed attempt
    crashed = UnitRecord(generator="g", task_id=TASK, error="boom", error_kind="generation")
    assert (crashed.n_attempted, crashed.n_failed) == (1, 1)
    res = _results([old])
    assert res["per_task"]["g"][TASK]["n_attempted"] == 2 and res["per_task"]["g"][TASK]["n_failed"] == 1


def test_plug_in_rule_and_declared_attempts_must_match_the_envs() -> None:
    from logicenveval.benchmark import load_task
    from logicenveval.model.tree import Trajectory, task_paths
    from logicenveval.sim.situations import situation_env

    task = load_task(TASK)
    env = situation_env(task, Trajectory(tuple(p[0] for p in task_paths(task))))
    env = env.model_copy(update={"env_id": "mine-00"})
    derived = counted_attempts(GenerationResult(envs=[env], failures=[
        GenerationFailure(stage="layout", message="did not fit", env_id="mine-01"),
        GenerationFailure(stage="layout", message="again", env_id="mine-01"),
        GenerationFailure(stage="note", message="slow", env_id="mine-00"),
        GenerationFailure(stage="plan", message="no env id")]))
    assert [(a.id, a.built) for a in derived] == [("mine-00", True), ("mine-01", False)]
    (nothing,) = counted_attempts(GenerationResult(failures=[GenerationFailure(stage="ask", message="bad")]))
    assert not nothing.built and nothing.reason == "bad"
    (empty,) = counted_attempts(GenerationResult())
    assert empty.reason == "the generator returned no environment"
    with pytest.raises(ValueError, match="one built attempt per returned environment"):
        GenerationResult(envs=[env], attempts=[Attempt(id="a", env_id="other")])
    with pytest.raises(ValueError, match="either env_id"):
        Attempt(id="a")


# --- whole units ----------------------------------------------------------------------------

class Planned:
    """Plans four environments, then its model's reply stays invalid."""

    name = "planned"

    def generate(self, brief: TaskBrief, ctx: GenerationContext) -> GenerationResult:
        ctx.plan_attempts(4)
        raise ModelReplyError("the reply stayed invalid after 3 attempts", field="tree")


class Unplanned:
    name = "unplanned"

    def generate(self, brief: TaskBrief, ctx: GenerationContext) -> GenerationResult:
        raise ModelReplyError("the first reply stayed invalid", field="subtasks")


class Flaky(LogicEnvGen):
    """The exact-cover LogicEnvGen whose endpoint is unreachable on one task."""

    def __init__(self) -> None:
        super().__init__(selector="exact", name="flaky")

    def generate(self, brief: TaskBrief, ctx: GenerationContext) -> GenerationResult:
        if brief.id == "kitchen_fridge_restock":
            raise ModelConnectionError("cannot reach http://127.0.0.1:9/v1", field="base_url")
        return super().generate(brief, ctx)


class Unreachable:
    name = "unreachable"

    def generate(self, brief: TaskBrief, ctx: GenerationContext) -> GenerationResult:
        raise ModelConnectionError("cannot reach http://127.0.0.1:9/v1", field="base_url")


def _run(tmp_path: Path, generators: tuple[str, ...], tasks: tuple[str, ...] = (TASK,),
         **config: Any) -> dict[str, Any]:
    outcome = run(RunConfig(generators=generators, tasks=tasks, executor="inprocess",
                            output=str(tmp_path), max_infra_failures=0, **config), show_progress=False)
    publish(outcome.run_dir, outcome.results, outcome.records)
    return outcome.results


def test_a_unit_failed_for_generation_reasons_counts_its_planned_attempts(tmp_path: Path) -> None:
    res = _run(tmp_path, (f"{__name__}:Planned", f"{__name__}:Unplanned"))
    planned, unplanned = res["results"]["planned"], res["results"]["unplanned"]
    assert planned["measured"] and (planned["n_attempted"], planned["n_failed"]) == (4, 4)
    assert (unplanned["n_attempted"], unplanned["n_failed"]) == (1, 1)
    for row in (planned, unplanned):
        assert row["phypr"]["avg"] == 0.0 and row["scevr"] == 0.0 and row["logcov"] == 0.0
    assert "| planned |" in markdown(res) and "0/4" not in markdown(res) and "4/4" in markdown(res)


def test_an_infrastructure_failure_is_not_measured_never_zero(tmp_path: Path) -> None:
    tasks = (TASK, "kitchen_fridge_restock")
    res = _run(tmp_path, (f"{__name__}:Flaky", f"{__name__}:Unreachable"), tasks)
    flaky, down = res["results"]["flaky"], res["results"]["unreachable"]
    assert flaky["measured"] and flaky["not_measured_tasks"] == ["kitchen_fridge_restock"]
    assert list(res["per_task"]["flaky"]) == [TASK]  # left out of the aggregation
    alone = _run(tmp_path / "alone", (f"{__name__}:Flaky",), (TASK,))["results"]["flaky"]
    assert {k: v for k, v in flaky.items() if k not in ("st_ms", "ci95", "not_measured_tasks")} == \
        {k: v for k, v in alone.items() if k not in ("st_ms", "ci95", "not_measured_tasks")}
    assert down["measured"] is False and down["not_measured_tasks"] == sorted(tasks)
    assert down["phypr"] == {"floor_plan": None, "entity": None, "relation": None, "avg": None}
    assert down["logcov"] is None and down["scevr"] is None and down["n_attempted"] is None
    assert res["per_task"]["unreachable"] == {}
    row = next(line for line in markdown(res).splitlines() if line.startswith("| unreachable |"))
    assert row.count("not measured") == row.count("|") - 2 and "0.00" not in row
    run_dir = next(p for p in tmp_path.iterdir() if p.is_dir() and p.name != "alone")
    assert load_results(run_dir)["results"]["unreachable"]["measured"] is False  # a valid results.json
    html = (run_dir / "leaderboard.html").read_text()
    assert "<td>not measured</td>" in html


def test_multi_seed_results_leave_out_unmeasured_tasks_and_count_attempts() -> None:
    good = [_unit([_sample(0)], failed=1), _unit([], failed=1, task="kitchen_fridge_restock")]
    infra = UnitRecord(generator="g", task_id="kitchen_fridge_restock", error="endpoint down",
                       error_kind="infrastructure")
    seed0 = _results(good)
    seed1 = _results([good[0], infra], seed=1)
    seed1["tasks"] = seed0["tasks"]
    both = combine_seeds("r", {}, [seed0, seed1])["results"]["g"]
    assert both["not_measured_tasks"] == ["kitchen_fridge_restock"] and both["measured"]
    assert (both["n_attempted"], both["n_failed"]) == (4, 2)  # clean_living_room, two seeds
    assert both["phypr"]["avg"] == pytest.approx(0.5)


# --- the offline generators and evaluate ----------------------------------------------------

def test_an_offline_generation_failure_is_counted(tmp_path: Path) -> None:
    """A real failure of a shipped generator with the offline model: with our re-selection check
    (`reselect`), no-DBP's selected objects do not realise one of its `hallway_entry_tidy`
    situations after the re-asks (the quick start's former logicenvgen-exact layout failure on
    `bathroom_counter_sort` depended on sampled sizes and went away when door positions became
    layout variables, issue 26)."""
    res = _run(tmp_path, ("logicenvgen-no-dbp",), ("hallway_entry_tidy",), brief="roles",
               generator_args={"logicenvgen-no-dbp": {"reselect": True}})
    row = res["results"]["logicenvgen-no-dbp"]
    per = res["per_task"]["logicenvgen-no-dbp"]["hallway_entry_tidy"]
    assert row["n_failed"] == per["n_failed"] == 1
    assert row["n_attempted"] == row["n_envs"] + 1 == per["n_attempted"]
    assert row["phypr"]["avg"] == pytest.approx(row["n_envs"] / row["n_attempted"])
    assert f"1/{row['n_attempted']}" in markdown(res)


def test_holodeck_scene_that_left_out_a_role_object_is_a_failed_attempt(monkeypatch: pytest.MonkeyPatch) -> None:
    import numpy as np

    import logicenveval.baselines.holodeck as holodeck
    from logicenveval.benchmark import load_task
    from logicenveval.domain.catalog import load_catalog
    from logicenveval.llm.registry import make_model

    real = holodeck.build_scene

    def dropping(*args: Any, **kwargs: Any) -> Any:
        env, log = real(*args, **kwargs)
        scene = args[1]
        log["dropped"].append(next(o.id for o in scene.objects if o.role))
        return env, log

    monkeypatch.setattr(holodeck, "build_scene", dropping)
    ctx = GenerationContext(model=make_model("offline", "", no_cache=True), catalog=load_catalog(),
                            rng=np.random.default_rng(0))
    result = holodeck.Holodeck().generate(load_task(TASK).brief(), ctx)
    assert result.envs == [] and len(result.attempts) == 1 and not result.attempts[0].built
    assert "left out" in (result.attempts[0].reason or "") and "scene" in result.artifacts


def test_cot_reply_that_never_validates_fails_every_draft_it_could_write() -> None:
    import numpy as np

    from logicenveval.baselines.cot import CoT
    from logicenveval.baselines.ifg import IFG
    from logicenveval.benchmark import load_task
    from logicenveval.domain.catalog import load_catalog

    class Garbage:
        name = "garbage"

        def complete(self, request: Any) -> str:
            return "not json"

    brief = load_task(TASK).brief()
    ctx = GenerationContext(model=Garbage(), catalog=load_catalog(), rng=np.random.default_rng(0))
    cot = CoT(max_environments=5).generate(brief, ctx)
    assert len(cot.attempts) == 5 and not any(a.built for a in cot.attempts)
    assert ctx.planned_attempts == 5
    ifg = IFG(k=3).generate(brief, ctx)
    assert len(ifg.attempts) == 3 and not any(a.built for a in ifg.attempts)


def test_ifg_intents_missing_from_the_reply_are_failed_attempts(monkeypatch: pytest.MonkeyPatch) -> None:
    """Under request protocol 4 one reply gives every intent (protocol 5 asks each on its own:
    tests/test_ifg_intents.py)."""
    import numpy as np

    import logicenveval.baselines.ifg as ifg
    from logicenveval.benchmark import load_task
    from logicenveval.domain.catalog import load_catalog
    from logicenveval.llm.registry import make_model

    real = ifg.ask

    def fewer(model: Any, kind: str, *args: Any, **kwargs: Any) -> Any:
        reply = real(model, kind, *args, **kwargs)
        return reply.model_copy(update={"trajectories": reply.trajectories[:2]}) if kind == "ifg_intents" else reply

    monkeypatch.setattr(ifg, "ask", fewer)
    ctx = GenerationContext(model=make_model("offline", "protocol=4", no_cache=True), catalog=load_catalog(),
                            rng=np.random.default_rng(0))
    result = ifg.IFG(k=4).generate(load_task(TASK).brief(), ctx)
    assert [a.built for a in result.attempts] == [True, True, False, False]
    assert "gave 2 of the 4 intents" in (result.attempts[-1].reason or "")


def test_evaluate_counts_an_invalid_file_as_one_failed_attempt(tmp_path: Path) -> None:
    from logicenveval.runner.score_envs import EvaluateConfig, evaluate_envs

    first = _run(tmp_path / "run", ("logicenvgen-exact",))
    run_dir = next(p for p in (tmp_path / "run").iterdir() if p.is_dir())
    folder = tmp_path / "envs" / TASK
    folder.mkdir(parents=True)
    for p in (run_dir / "envs" / "logicenvgen-exact" / TASK).glob("logicenvgen-exact-*.json"):
        (folder / p.name).write_text(p.read_text())
    (folder / "broken.json").write_text("{not json")
    out = evaluate_envs(EvaluateConfig(envs_dir=str(tmp_path / "envs"), name="mine", executor="inprocess",
                                       output=str(tmp_path / "ev")))
    row, base = out.results["results"]["mine"], first["results"]["logicenvgen-exact"]
    assert (row["n_envs"], row["n_failed"], row["n_attempted"]) == (base["n_envs"], 1, base["n_envs"] + 1)
    assert row["phypr"]["avg"] < base["phypr"]["avg"] and row["scevr"] < base["scevr"]
    assert row["logcov"] == base["logcov"]


# --- budgets --------------------------------------------------------------------------------

def tiny_budget() -> LogicEnvGen:
    return LogicEnvGen(selector="exhaustive", name="tiny-exhaustive", max_subsets=10)


def test_a_budget_hit_is_recorded_per_task_and_labels_the_row(tmp_path: Path) -> None:
    res = _run(tmp_path, (f"{__name__}:tiny_budget", "logicenvgen-exhaustive"),
               (TASK, "kitchen_fridge_restock"))
    tiny, full = res["results"]["tiny-exhaustive"], res["results"]["logicenvgen-exhaustive"]
    assert tiny["budget_hit_tasks"] == [TASK, "kitchen_fridge_restock"] and full["budget_hit_tasks"] == []
    assert res["per_task"]["tiny-exhaustive"][TASK]["budget_hit"] is True
    assert res["per_task"]["logicenvgen-exhaustive"][TASK]["budget_hit"] is False
    text = markdown(res)
    assert "| tiny-exhaustive (budget hit 2/2) |" in text and "| logicenvgen-exhaustive |" in text
    run_dir = next(p for p in tmp_path.iterdir() if p.is_dir())
    plan = json.loads((run_dir / "envs" / "tiny-exhaustive" / TASK / "plan.json").read_text())
    assert plan["exhaustive"]["optimal"] is False and plan["exhaustive"]["subsets_tested"] == 10
    write_outputs(run_dir, res, [])
    assert load_results(run_dir)["results"]["tiny-exhaustive"]["budget_hit_tasks"] == [TASK, "kitchen_fridge_restock"]


def test_every_failed_attempt_s_reason_is_on_record_counted() -> None:
    """A failed attempt no generation failure states (IFG's intents a reply did not give: 21 of
    Qwen2.5-Coder-1.5B's 24) is listed in results.json `failures` with how many it counts, and
    so in the leaderboard and the terminal's reasons; a stated one is listed once."""
    stated = GenerationFailure(stage="construct", message="no layout", env_id="x0")
    unit = _unit([_sample(0)], failed=3, failures=[stated])
    unit = unit.model_copy(update={"attempts": [*unit.attempts, Attempt(id="y", stage="ifg_intents",
                                                                        reason="1 of 8 intents")]})
    entries = _results([unit])["failures"]["g"]
    assert [(e["stage"], e["message"], e.get("attempts")) for e in entries] == [
        ("construct", "no layout", None), ("ifg_intents", "1 of 8 intents", 1)]
    bare = _results([_unit([_sample(0)], failed=3)])["failures"]["g"]
    assert [(e["message"], e["attempts"]) for e in bare] == [("no layout", 3)]
