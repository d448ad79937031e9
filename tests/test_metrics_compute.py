"""Per-task metrics and aggregation, with hand-computed values on Clean Living Room."""

from __future__ import annotations

import itertools
import json
from pathlib import Path
from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from logicenveval.benchmark import load_task
from logicenveval.errors import MetricsError
from logicenveval.metrics.compute import GeneratorMetrics, TaskMetrics, aggregate, task_metrics
from logicenveval.metrics.records import EnvSample, PhysicsSummary
from logicenveval.model.task import Task

TASKS = Path(__file__).resolve().parents[1] / "benchmark_data" / "tasks"
DOLL = "tidy_toy:toy_on_floor=yes/toy_kind=doll"
OTHER = "tidy_toy:toy_on_floor=yes/toy_kind=other"
NOTOY = "tidy_toy:toy_on_floor=no"
BOOK = "tidy_book:book_on_floor=yes"
NOBOOK = "tidy_book:book_on_floor=no"
WIPE = "clean_mark:wipe_on_table=yes"
MOP = "clean_mark:wipe_on_table=no"
STEP = {
    DOLL: [("toy_on_floor", "yes"), ("toy_kind", "doll")],
    OTHER: [("toy_on_floor", "yes"), ("toy_kind", "other")],
    NOTOY: [("toy_on_floor", "no")],
    BOOK: [("book_on_floor", "yes")],
    NOBOOK: [("book_on_floor", "no")],
    WIPE: [("wipe_on_table", "yes")],
    MOP: [("wipe_on_table", "no")],
}
TRAJS = list(itertools.product([DOLL, OTHER, NOTOY], [BOOK, NOBOOK], [WIPE, MOP]))


@pytest.fixture(scope="module")
def task() -> Task:
    return load_task("clean_living_room", TASKS)


def _sample(
    env_id: str,
    paths: list[str],
    *,
    well_formed: bool = True,
    verdicts: dict[str, str] | None = None,
    physics: tuple[bool, bool, bool] = (True, True, True),
    ms: float = 2.0,
    ticks: int = 7,
    extended: tuple[str, ...] = (),
    task_id: str = "clean_living_room",
) -> EnvSample:
    verdicts = verdicts if verdicts is not None else {
        "correct": "passed", "counterfactual": "tree_failure", "unreachable": "passed", "lackbranch": "passed"
    }
    return EnvSample(
        generator="g",
        task_id=task_id,
        env_id=env_id,
        covered_paths=paths,
        trajectory=" | ".join(paths) if len(paths) == 3 else None,
        conditions=[c for p in paths for c in STEP[p]],
        well_formed=well_formed,
        physics=PhysicsSummary(floor_plan=physics[0], entity=physics[1], relation=physics[2],
                               extended=not extended,
                               extended_failures=[{"code": c, "dimension": "entity"} for c in extended]),
        verdicts=verdicts,
        sim_ms={k: ms for k in verdicts},
        sim_ticks={k: ticks for k in verdicts},
    )


def test_paper_example_one_environment(task: Task) -> None:
    m = task_metrics(task, [_sample("e0", [DOLL, BOOK, WIPE])])
    # our tree has 3 + 2 + 2 = 7 decision paths and 8 atomic conditions
    assert m.logcov == pytest.approx(3 / 7)
    assert m.ld == pytest.approx(4 / 8)
    # reference = exact cover of size 3, whose first row is doll|yes|yes
    assert m.min_cover == 3
    assert m.ji == pytest.approx(1 / 3)
    assert m.redundancy == pytest.approx(1 / 3)
    assert m.faudr == {"counterfactual": True, "unreachable": False, "lackbranch": False}
    assert m.st_ms == pytest.approx(2.0)
    assert m.n_valid == 1


def test_ill_formed_and_invalid_envs(task: Task) -> None:
    samples = [
        _sample("e0", [DOLL, BOOK, WIPE], verdicts={"correct": "passed", "unreachable": "passed"}),
        _sample("e1", [OTHER, NOBOOK, MOP], well_formed=False),  # ill-formed: covers nothing
        _sample(
            "e2", [NOTOY, NOBOOK, MOP],
            verdicts={"correct": "goal_unmet", "unreachable": "tree_failure"}, physics=(True, False, True),
        ),
    ]
    m = task_metrics(task, samples, n_failed=1)
    assert m.covered_paths == sorted([DOLL, BOOK, WIPE, NOTOY, NOBOOK, MOP])
    assert m.logcov == pytest.approx(6 / 7)
    assert m.ld == pytest.approx(7 / 8)  # toy_kind=other only in the ill-formed env
    assert m.n_valid == 1  # e1 ill-formed, e2 correct BT fails
    assert m.faudr["unreachable"] is False  # its failure is in an invalid env
    assert m.faudr["counterfactual"] is False  # it fails only in the ill-formed e1
    # ST: correct over 3 envs = 6 ms; unreachable 3 envs = 6 ms; counterfactual/lackbranch only e1
    assert m.st_ms == pytest.approx((6 + 6 + 2 + 2) / 4)
    assert m.st_ticks == pytest.approx((21 + 21 + 7 + 7) / 4)  # same shape as ST, in ticks
    g = aggregate([m])
    assert g.n_envs == 3
    assert g.phypr.floor_plan == pytest.approx(3 / 4)  # the failed generation counts as failing
    assert g.phypr.entity == pytest.approx(2 / 4)
    assert g.phypr.avg == pytest.approx((3 / 4 + 2 / 4 + 3 / 4) / 3)
    assert g.scevr == pytest.approx(1 / 4)


def test_aggregate_means_over_tasks(task: Task) -> None:
    a = task_metrics(task, [_sample("e0", [DOLL, BOOK, WIPE])])
    empty = task_metrics(task, [], n_failed=2)
    assert empty.logcov == 0.0 and empty.ji == 0.0
    assert empty.redundancy is None and empty.st_ms is None and empty.st_ticks is None  # issue 34
    b = empty.model_copy(update={"task_id": "other_task"})
    g = aggregate([a, b])
    assert g.redundancy == a.redundancy and g.st_ticks == a.st_ticks  # failing does not look lean
    assert aggregate([b]).redundancy is None and aggregate([b]).st_ms is None
    assert g.logcov == pytest.approx(3 / 14)
    assert g.faudr.counterfactual == pytest.approx(0.5)
    assert g.faudr.avg == pytest.approx(0.5 / 3)
    assert g.scevr == pytest.approx(1 / 3)
    assert g.ji == pytest.approx(1 / 6)


def test_results_shape_has_exactly_design_keys(task: Task) -> None:
    g = aggregate([task_metrics(task, [_sample("e0", [DOLL, BOOK, WIPE])])])
    dumped = json.loads(g.model_dump_json())
    assert set(dumped) == {
        "phypr", "logcov", "ld", "scevr", "faudr", "st_ms", "st_ticks", "ji", "ji_fixed", "redundancy", "n_envs",
        "plausibility", "faudr_mut", "faudr_mut_by_class", "n_attempted", "n_failed", "realised_share",
    }
    assert set(dumped["plausibility"]) == {"rate", "codes"}
    assert set(dumped["phypr"]) == {"floor_plan", "entity", "relation", "avg"}
    assert set(dumped["faudr"]) == {"counterfactual", "unreachable", "lackbranch", "avg"}
    assert GeneratorMetrics.model_validate(dumped) == g


def test_task_metrics_json_round_trip(task: Task) -> None:
    m = task_metrics(task, [_sample("e0", [DOLL, BOOK, WIPE])])
    assert TaskMetrics.model_validate_json(m.model_dump_json()) == m


def test_bad_inputs(task: Task) -> None:
    with pytest.raises(MetricsError, match="belongs to task 'x'"):
        task_metrics(task, [_sample("e0", [DOLL, BOOK, WIPE], task_id="x")])
    bad = _sample("e0", [DOLL, BOOK, WIPE]).model_copy(update={"covered_paths": ["tidy_toy:nope"]})
    with pytest.raises(MetricsError, match="unknown decision path"):
        task_metrics(task, [bad])
    with pytest.raises(MetricsError, match="negative"):
        task_metrics(task, [], n_failed=-1)
    with pytest.raises(MetricsError, match="no task metrics"):
        aggregate([])
    m = task_metrics(task, [])
    with pytest.raises(MetricsError, match="more than once"):
        aggregate([m, m])


def test_realising_the_reference_scores_one(task: Task) -> None:
    from logicenveval.logic.reference import reference_set

    samples = [
        _sample(f"e{i}", [p.key for p in t.paths]) for i, t in enumerate(reference_set(task))
    ]
    m = task_metrics(task, samples)
    assert (m.logcov, m.ld, m.ji, m.redundancy) == (1.0, 1.0, 1.0, 1.0)


@given(st.lists(st.sampled_from(TRAJS), max_size=6), st.integers(0, 3))
@settings(max_examples=40, deadline=None)
def test_property_metric_ranges_and_monotone_coverage(picks: list[tuple[str, str, str]], failed: int) -> None:
    task = load_task("clean_living_room", TASKS)
    samples = [_sample(f"e{i}", list(t)) for i, t in enumerate(picks)]
    m = task_metrics(task, samples, n_failed=failed)
    for v in (m.logcov, m.ld, m.ji):
        assert 0.0 <= v <= 1.0
    bigger = task_metrics(task, [*samples, _sample("extra", [OTHER, NOBOOK, MOP])], n_failed=failed)
    assert bigger.logcov >= m.logcov and bigger.ld >= m.ld
    g = aggregate([m])
    assert 0.0 <= g.scevr <= g.phypr.floor_plan <= 1.0


def test_extra_checks_are_reported_apart_from_phypr(task: Task) -> None:
    samples = [
        _sample("e0", [DOLL, BOOK, WIPE], extended=("blocks_door", "size_out_of_range")),
        _sample("e1", [OTHER, NOBOOK, MOP], extended=("blocks_door",)),
        _sample("e2", [NOTOY, NOBOOK, MOP]),
    ]
    m = task_metrics(task, samples, n_failed=1)
    assert m.n_extended_ok == 1 and m.extended_codes == {"blocks_door": 2, "size_out_of_range": 1}
    g = aggregate([m])
    assert g.phypr.entity == pytest.approx(3 / 4)  # the extra codes do not touch PhyPR
    assert g.plausibility.rate == pytest.approx(1 / 4)
    assert g.plausibility.codes == {"blocks_door": 2, "size_out_of_range": 1}


def test_faudr_mut_counts_killed_mutants_in_valid_envs_only(task: Task) -> None:
    mutants = {"m1": "counterfactual", "m2": "counterfactual", "m3": "lackbranch", "m4": "unreachable"}
    valid = _sample("e0", [DOLL, BOOK, WIPE]).model_copy(update={"killed_mutants": ["m1", "m3"]})
    invalid = _sample("e1", [OTHER, BOOK, MOP], verdicts={"correct": "goal_unmet"}).model_copy(
        update={"killed_mutants": ["m2", "m4"]})
    m = task_metrics(task, [valid, invalid], mutants=mutants)
    assert m.faudr_mut == pytest.approx(2 / 4)
    assert m.faudr_mut_by_class == {"counterfactual": 0.5, "lackbranch": 1.0, "unreachable": 0.0}
    other = task_metrics(load_task("living_room_toy_boxes", TASKS), [], mutants={"x": "lackbranch"})
    g = aggregate([m, other])
    assert g.faudr_mut == pytest.approx((0.5 + 0.0) / 2)
    assert g.faudr_mut_by_class["lackbranch"] == pytest.approx((1.0 + 0.0) / 2)
    assert g.faudr_mut_by_class["unreachable"] == pytest.approx(0.0)


def test_faudr_mut_is_none_when_not_scored(task: Task) -> None:
    m = task_metrics(task, [_sample("e0", [DOLL, BOOK, WIPE])])
    assert m.faudr_mut is None and m.faudr_mut_by_class == {}
    assert aggregate([m]).faudr_mut is None


def test_compare_never_calls_failing_a_task_faster_or_leaner(task: Task) -> None:
    """A task without environments has no ST/Redundancy: B failing the second task must not make
    those figures 'improved' (issue 34)."""
    from logicenveval.reporting.compare import compare_results

    full = task_metrics(task, [_sample("e0", [DOLL, BOOK, WIPE]), _sample("e1", [DOLL, BOOK, WIPE])])
    cheap = task_metrics(task, [_sample("e0", [DOLL, BOOK, WIPE])])
    failed = task_metrics(task, [], n_failed=2)

    def results(second: TaskMetrics) -> dict[str, Any]:
        cells = {"t1": full.model_dump(mode="json"), "t2": second.model_dump(mode="json") | {"task_id": "t2"}}
        return {"tasks": ["t1", "t2"], "seed": 0, "per_task": {"g": cells},
                "results": {"g": aggregate([full, second.model_copy(update={"task_id": "t2"})]).model_dump(mode="json")}}

    deltas = {d.path: d for d in compare_results(results(cheap), results(failed)).pairs[0].deltas}
    for path in (("redundancy",), ("st_ticks",), ("st_ms",)):
        assert not deltas[path].improved and deltas[path].before == deltas[path].after


def test_ji_compares_the_reported_set_when_it_is_made_of_gt_trajectories(task: Task) -> None:
    """The paper's JI compares the generated trajectory set: an attempt that was not built still
    belongs to it; targets in a generator's own vocabulary fall back to the realised set."""
    built = [_sample("e0", [DOLL, BOOK, WIPE])]
    gt = [" | ".join(p) for p in (["tidy_toy:toy_on_floor=yes/toy_kind=doll", "tidy_book:book_on_floor=yes",
                                   "clean_mark:wipe_on_table=yes"],
                                  ["tidy_toy:toy_on_floor=no", "tidy_book:book_on_floor=no",
                                   "clean_mark:wipe_on_table=no"])]
    realised = task_metrics(task, built, n_failed=1)
    reported = task_metrics(task, built, n_failed=1, reported=gt)
    own = task_metrics(task, built, n_failed=1, reported=["handle_toy:toy_here=yes", gt[1]])
    assert reported.ji_set == "reported" and realised.ji_set == own.ji_set == "realised"
    assert own.ji == realised.ji and reported.ji > realised.ji
