"""One worker or two: the same results.json apart from timings, whatever the schedule."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest

from logicenveval.cli import main

#: 8 tasks = 4 per worker: whole-task hand-offs and the single-unit tail both run
TASKS = ("clean_living_room,hallway_entry_tidy,kitchen_fridge_restock,bedroom_bookshelf_sorting,"
         "study_desk_cleanup,laundry_sorting,bedroom_morning_tidy,living_room_toy_boxes")


def _results(out: Path, *extra: str) -> dict[str, Any]:
    assert main(["run", "--model", "offline", "--tasks", TASKS, "--generators", "logicenvgen,cot",
                 "--output", str(out), "--quiet", *extra]) == 0
    (run_dir,) = [p for p in out.iterdir() if p.is_dir()]
    data: dict[str, Any] = json.loads((run_dir / "results.json").read_text())
    return data


def _stable(results: dict[str, Any]) -> dict[str, Any]:
    out = json.loads(json.dumps(results))
    out.pop("timing")
    for values in out["results"].values():
        values.pop("st_ms")
    for per in out["per_task"].values():
        for values in per.values():
            values.pop("st_ms")
    return out


@pytest.mark.slow
def test_one_and_two_workers_give_the_same_results(tmp_path: Path) -> None:
    one = _results(tmp_path / "one", "--executor", "inprocess")
    two = _results(tmp_path / "two", "--executor", "process", "--workers", "2")
    assert _stable(one) == _stable(two)
    # the timing block says where the time went, per generator and for the run itself
    for run in (one, two):
        phases = run["timing"]["phases"]
        assert set(phases) == {"logicenvgen", "cot"}
        assert {"generation", "layout", "physics", "simulation", "mutants", "writing", "saving"} \
            <= set(phases["logicenvgen"])  # `saving`: the unit committed where it was computed
        assert "layout" not in phases["cot"]  # CoT writes its coordinates down, no solver
        assert {"start-up", "tasks", "units", "results"} <= set(run["timing"]["run_phases"])


def test_workers_commit_their_units_and_write_their_pages(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """The run's process never writes a unit or a task page of a healthy worker: each worker
    commits its units and writes their pages, the same pages `report` and a resumed run write."""
    import logicenveval.reporting.leaderboard as leaderboard
    from logicenveval.runner.store import RunStore

    def not_here(*args: object) -> None:
        raise AssertionError("the run's process did a worker's job")

    monkeypatch.setattr(RunStore, "save", not_here)
    monkeypatch.setattr(leaderboard, "tick_data", not_here)  # made for each page it writes
    argv = ["run", "--model", "offline", "--tasks", "clean_living_room,bathroom_towel_refresh",
            "--generators", "cot,logicenvgen", "--workers", "2", "--output", str(tmp_path), "--quiet"]
    assert main(argv) == 0
    monkeypatch.undo()
    (run_dir,) = [p for p in tmp_path.iterdir() if p.is_dir()]
    store = RunStore(run_dir)
    for generator in ("cot", "logicenvgen"):
        for task in ("clean_living_room", "bathroom_towel_refresh"):
            unit = store.load(generator, task)
            assert unit is not None and unit.samples and unit.inputs  # complete, with its fingerprints
    pages = {p: p.read_bytes() for p in sorted((run_dir / "details").rglob("*.html"))}
    assert len(pages) == 4 and (run_dir / "details" / "page.js").is_file()
    assert main(["report", str(run_dir)]) == 0  # every page from the units alone
    assert {p: p.read_bytes() for p in pages} == pages
    for page in pages:
        page.unlink()
    assert main(argv) == 0  # resumed: the units are reused, their pages written by the run
    assert {p: p.read_bytes() for p in pages} == pages
