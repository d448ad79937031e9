"""Loading task folders (`<tasks_dir>/<task_id>/task.json` + policies) with precise errors."""

from __future__ import annotations

import re
from pathlib import Path

from pydantic import ValidationError

from logicenveval.errors import ConditionSyntaxError, TaskFormatError, did_you_mean
from logicenveval.limits import limit, parse_json, raise_hint, read_text
from logicenveval.model.task import Task
from logicenveval.validation import first_error

_TASK_ID = re.compile(r"[a-z0-9_]+")
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
    text = read_text(p, what="task file", error=TaskFormatError, max_bytes="max_task_bytes",
                     hint="each task folder needs a task.json")
    data = parse_json(text, file=str(p), error=TaskFormatError)
    _check_sizes(data, str(p))
    try:
        task = Task.model_validate(data)
    except ValidationError as exc:
        loc, msg = first_error(exc)
        raise TaskFormatError(msg, file=str(p), field=loc,
                              hint="see docs/task-format.md for the task format") from None
    except ConditionSyntaxError as exc:
        raise TaskFormatError(exc.message, file=str(p), column=exc.column, hint=exc.hint) from None
    except RecursionError:
        raise TaskFormatError("the task nests too deeply to read", file=str(p),
                              hint="decision trees and conditions nest a few levels, not thousands") from None
    if task.id != p.parent.name:
        raise TaskFormatError(f"task id {task.id!r} differs from its folder name {p.parent.name!r}",
                              file=str(p), field="id", hint="rename the folder or the id")
    return task


def _check_sizes(data: object, file: str) -> None:
    """Refuse inputs whose size alone would make loading or generation slow or deep."""
    if not isinstance(data, dict):
        return
    description = data.get("description")
    cap = limit("max_description_chars")
    if isinstance(description, str) and len(description) > cap:
        raise TaskFormatError(f"description has {len(description)} characters, more than the "
                              f"limit of {cap}", file=file, field="description",
                              hint=raise_hint("max_description_chars"))
    max_depth = limit("max_tree_depth")
    subtasks = data.get("subtasks")
    for i, st in enumerate(subtasks if isinstance(subtasks, list) else []):
        level = [st.get("tree")] if isinstance(st, dict) else []
        depth = 0
        while level:
            depth += 1
            if depth > max_depth:
                raise TaskFormatError(f"decision tree deeper than {max_depth} levels",
                                      file=file, field=f"subtasks.{i}.tree",
                                      hint=raise_hint("max_tree_depth"))
            level = [c for n in level if isinstance(n, dict)
                     and isinstance(n.get("branches"), dict) for c in n["branches"].values()]


def task_ids(directory: str | Path | None = None) -> list[str]:
    d = tasks_dir(directory)
    return sorted(p.parent.name for p in d.glob("*/task.json"))


def load_task(task_id: str, directory: str | Path | None = None) -> Task:
    d = tasks_dir(directory)
    if not _TASK_ID.fullmatch(task_id):
        raise TaskFormatError(f"{task_id!r} is not a task id", file=str(d),
                              hint="task ids are folder names of lowercase letters, digits and _; "
                              "list them with `python -m logicenveval tasks list`")
    path = d / task_id / "task.json"
    if not path.exists():
        raise TaskFormatError(f"unknown task {task_id!r}{did_you_mean(task_id, task_ids(d))}",
                              file=str(d),
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
    path = (d / task.policies[kind]).resolve()
    if not path.is_relative_to(d.resolve()):
        raise TaskFormatError(f"policy {task.policies[kind]!r} is outside the task folder",
                              file=str(d / "task.json"), field=f"policies.{kind}",
                              hint="policies are files inside the task's own folder")
    return d / task.policies[kind]
