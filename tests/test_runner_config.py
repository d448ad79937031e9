"""`selected_tasks`: the one check of a `--tasks` list that `run` and `evaluate` share (the CLI
checks repeats at parse time too; this is what Python callers get)."""

from __future__ import annotations

from pathlib import Path

import pytest

from logicenveval.errors import ConfigError
from logicenveval.runner.config import RunConfig, selected_tasks
from logicenveval.runner.run import run

KNOWN = ["clean_living_room", "kitchen_dish_cleanup", "bathroom_counter_sort"]


def test_a_list_of_known_tasks_named_once_is_kept_in_its_order() -> None:
    assert selected_tasks(["kitchen_dish_cleanup", "clean_living_room"], KNOWN) == [
        "kitchen_dish_cleanup", "clean_living_room"]
    assert selected_tasks([], KNOWN) == []


@pytest.mark.parametrize(("tasks", "needle"), [
    (["clean_living_room", "kitchen_dish_cleanup", "clean_living_room"], "listed twice: ['clean_living_room']"),
    (["clean_living_room", "no_such_task"], "unknown task(s) ['no_such_task']"),
])
def test_repeated_or_unknown_tasks_are_one_error_naming_them(tasks: list[str], needle: str) -> None:
    with pytest.raises(ConfigError, match="--tasks") as info:
        selected_tasks(tasks, KNOWN)
    assert needle in str(info.value)


def test_run_from_python_refuses_a_repeated_task_before_any_work(tmp_path: Path) -> None:
    config = RunConfig(model="offline", generators=("holodeck",), output=str(tmp_path),
                       tasks=("clean_living_room", "clean_living_room"))
    with pytest.raises(ConfigError, match="listed twice"):
        run(config, show_progress=False)
    assert not any(tmp_path.iterdir())
