"""A run scores each unit as it arrives (its closest minimum cover, JI) instead of all of them
after the last unit: the same results.json, and `build_results` reuses exactly those scores."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest

from logicenveval.benchmark import load_tasks
from logicenveval.metrics.compute import TaskMetrics
from logicenveval.metrics.records import EnvSample, PhysicsSummary, UnitRecord
from logicenveval.runner import results as results_mod
from logicenveval.runner.config import RunConfig
from logicenveval.runner.results import build_results, unit_metrics
from logicenveval.runner.run import run
from logicenveval.runner.store import RunStore

TASK = "clean_living_room"
PATHS = ["tidy_toy:toy_on_floor=yes/toy_kind=doll", "tidy_book:book_on_floor=yes",
         "clean_mark:wipe_on_table=yes"]


def _unit(gen: str) -> UnitRecord:
    sample = EnvSample(generator=gen, task_id=TASK, env_id=f"{gen}-0", covered_paths=PATHS,
                       trajectory=" | ".join(PATHS), well_formed=True,
                       physics=PhysicsSummary(floor_plan=True, entity=True, relation=True),
                       verdicts={"correct": "passed"})
    return UnitRecord(generator=gen, task_id=TASK, samples=[sample])


def test_build_results_reuses_the_scores_of_exactly_those_records(monkeypatch: pytest.MonkeyPatch) -> None:
    (task,) = load_tasks(None, [TASK])
    a, b = _unit("a"), _unit("b")
    scored_a = unit_metrics(task, a)
    calls: list[str] = []
    real = results_mod.unit_metrics

    def counted(t: Any, u: UnitRecord) -> TaskMetrics:
        calls.append(u.generator)
        return real(t, u)

    monkeypatch.setattr(results_mod, "unit_metrics", counted)
    config = RunConfig(generators=("a", "b"))
    stale_b = (_unit("b"), unit_metrics(task, b))  # another record object under b's key
    out = build_results(config, [task], [a, b], scored={("a", TASK): (a, scored_a), ("b", TASK): stale_b})
    assert calls == ["b"]  # a's score reused; b's record is not the one scored: scored again
    plain = build_results(config, [task], [a, b])
    assert out["per_task"] == plain["per_task"] and out["results"] == plain["results"]


def test_a_run_scores_units_as_they_arrive_with_the_same_results(tmp_path: Path) -> None:
    config = RunConfig(model="offline", generators=("cot",), tasks=(TASK,), output=str(tmp_path),
                       executor="inprocess")
    outcome = run(config, show_progress=False)
    assert "scoring" in outcome.results["timing"]["run_phases"]
    written = json.loads((outcome.run_dir / "results.json").read_text())
    (task,) = load_tasks(None, [TASK])
    records = [RunStore(outcome.run_dir).load("cot", TASK)]
    assert records[0] is not None
    again = build_results(config, [task], [r for r in records if r is not None])
    assert written["per_task"] == again["per_task"] and written["results"] == again["results"]
