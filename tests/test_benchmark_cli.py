"""`tasks list|show|validate|stats` end to end, and the benchmark's size (acceptance test)."""

from __future__ import annotations

from pathlib import Path

import pytest

from logicenveval.benchmark import DEFAULT_TASKS_DIR, load_task
from logicenveval.benchmark_stats import minimal_cover, task_stats, to_markdown
from logicenveval.cli import main

FIXTURES = Path(__file__).parent / "fixtures" / "broken_tasks"

EXPECTED = {
    "missing_role": ["policies/correct.xml", "'broom'"],
    "overlapping_values": ["variables.toy_kind", "overlap"],
    "faulty_passes_everywhere": ["policies/unreachable.xml", "passes every situation"],
    "correct_fails_one_situation": ["policies/correct.xml", "situation pillow:"],
    "non_exhaustive_values": ["variables.pillow_on_floor", "not exhaustive"],
    "unknown_category": ["roles.mop.category", "hoverboard_mop"],
}


@pytest.mark.parametrize("case", sorted(EXPECTED))
def test_validate_exits_1_on_broken_fixture(case: str, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["tasks", "validate", "--tasks-dir", str(FIXTURES / case)]) == 1
    out = capsys.readouterr().out
    problems = [line for line in out.splitlines() if line.startswith("problem:")]
    assert problems and all("living_room_toy_boxes" in p for p in problems)
    assert any(all(s in p for s in EXPECTED[case]) for p in problems), out


def test_validate_exits_0_on_valid_tasks(capsys: pytest.CaptureFixture[str]) -> None:
    args = ["tasks", "validate", "--task", "lamp_or_pillow_fetch", "--task", "living_room_toy_boxes"]
    assert main(args) == 0
    assert "all 2 task(s) valid" in capsys.readouterr().out


def test_list_and_show(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["tasks", "list"]) == 0
    assert "bedroom_bookshelf_sorting" in capsys.readouterr().out
    assert main(["tasks", "show", "bedroom_bookshelf_sorting"]) == 0
    out = capsys.readouterr().out
    assert "shelf_essays" in out and "book_kind=essay" in out


def test_show_unknown_task_is_an_error() -> None:
    assert main(["tasks", "show", "no_such_task"]) == 2


def test_stats_figures() -> None:
    task = load_task("bedroom_bookshelf_sorting")
    s = task_stats(task, DEFAULT_TASKS_DIR)
    assert (s.subtasks, s.variables, s.decision_paths, s.trajectories) == (3, 5, 9, 24)
    assert s.min_cover == minimal_cover(task) == 4
    assert s.bt_nodes > 20
    md = to_markdown([s])
    assert md.splitlines()[2].startswith("| bedroom_bookshelf_sorting | 1 | 9 | 3 | 5 | 9 | 24 | 4 |")
    assert "**total**" in md


def test_stats_markdown_command(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["tasks", "stats", "--markdown"]) == 0
    out = capsys.readouterr().out
    assert out.startswith("| task | rooms |") and "| **total** |" in out


def test_benchmark_has_25_tasks_and_100_policies() -> None:
    """Acceptance test of issue 4: fails until all 25 tasks are shipped."""
    tasks = sorted(p.parent for p in DEFAULT_TASKS_DIR.glob("*/task.json"))
    xml = list(DEFAULT_TASKS_DIR.glob("*/policies/*.xml"))
    assert len(tasks) == 25
    assert len(xml) == 100
