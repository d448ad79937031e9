"""Loading task folders (`<tasks_dir>/<task_id>/task.json` + policies) with precise errors."""

from __future__ import annotations

import json
from pathlib import Path

from pydantic import ValidationError

from logicenveval.errors import ConditionSyntaxError, TaskFormatError
from logicenveval.model.task import Task
from logicenveval.validation import first_error

DEFAULT_TASKS_DIR = Path(__file__).resolve().parents[1] / "benchmark_data" / "tasks"


def tasks_dir(path: str | Path | None = None) -> Path:
    d = Path(path) if path else DEFAULT_TASKS_DIR
    if not d.is_dir():
        raise TaskFormatError("tasks directory not found", file=str(d),
                              hint="pass --tasks-dir pointing at a folder of <task_id>/task.json")
    return d


def load_task_file(path: str | Path) -> Task:
    """Parse and structurally validate one task.json."""
    p = Path(path)
    try:
        data = json.loads(p.read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise TaskFormatError("task file not found", file=str(p),
                              hint="each task folder needs a task.json") from None
    except json.JSONDecodeError as exc:
        raise TaskFormatError(f"invalid JSON: {exc.msg}", file=str(p), line=exc.lineno,
                              column=exc.colno, hint="fix the JSON syntax") from None
    try:
        task = Task.model_validate(data)
    except ValidationError as exc:
        loc, msg = first_error(exc)
        raise TaskFormatError(msg, file=str(p), field=loc,
                              hint="see DESIGN.md §4 for the task format") from None
    except ConditionSyntaxError as exc:
        raise TaskFormatError(exc.message, file=str(p), column=exc.column, hint=exc.hint) from None
    if task.id != p.parent.name:
        raise TaskFormatError(f"task id {task.id!r} differs from its folder name {p.parent.name!r}",
                              file=str(p), field="id", hint="rename the folder or the id")
    return task


def task_ids(directory: str | Path | None = None) -> list[str]:
    d = tasks_dir(directory)
    return sorted(p.parent.name for p in d.glob("*/task.json"))


def load_task(task_id: str, directory: str | Path | None = None) -> Task:
    d = tasks_dir(directory)
    path = d / task_id / "task.json"
    if not path.exists():
        raise TaskFormatError(f"unknown task {task_id!r}", file=str(d),
                              hint="list tasks with `python -m logicenveval tasks list`")
    return load_task_file(path)


def load_tasks(directory: str | Path | None = None, ids: list[str] | None = None) -> list[Task]:
    """Load all tasks of a directory (sorted by id) or the selected ids, in the given order."""
    return [load_task(t, directory) for t in (ids if ids else task_ids(directory))]


def policy_path(task: Task, kind: str, directory: str | Path | None = None) -> Path:
    """Path of one of the task's four policies (`correct`, `counterfactual`, ...)."""
    d = tasks_dir(directory) / task.id
    if kind not in task.policies:
        raise TaskFormatError(f"task {task.id!r} declares no {kind!r} policy",
                              file=str(d / "task.json"), field="policies",
                              hint="add it under \"policies\"")
    return d / task.policies[kind]
