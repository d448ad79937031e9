"""The reader's second development set (tests/data/reader_dev2/): new tasks written from scratch
after the first set (tests/data/reader_dev/) had been tuned on, for the next round of work on the
offline reader.

Nothing here runs the offline model: these tests keep the data honest (valid tasks about objects
and rooms the other sets do not use, each object named in its description, a current mutant
list), not the reader's scores.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from test_reader_dev_data import _mentions, _names

from logicenveval.benchmark import load_tasks, task_ids
from logicenveval.benchmark_validation import validate_task
from logicenveval.domain.catalog import load_catalog
from logicenveval.faults.score import shipped_is_current

DATA = Path(__file__).parent / "data"
NEW = DATA / "reader_dev2" / "tasks_new"
DEV_NEW = DATA / "reader_dev" / "tasks_new"


def test_the_set_has_new_tasks_whose_ids_collide_with_no_other_set() -> None:
    ids = task_ids(NEW)
    assert len(ids) >= 5
    assert not set(ids) & (set(task_ids()) | set(task_ids(DEV_NEW)))


def test_new_tasks_are_about_objects_and_rooms_the_other_sets_do_not_use() -> None:
    """Mostly categories neither the built-in tasks nor the first set's new tasks use, in room ids
    neither uses, and every object named in the description."""
    seen = [*load_tasks(), *load_tasks(DEV_NEW)]
    used = {spec.category for t in seen for spec in t.roles.values()}
    used_rooms = {room for t in seen for room in t.rooms}
    for task in load_tasks(NEW):
        categories = [spec.category for spec in task.roles.values()]
        fresh = [c for c in categories if c not in used]
        assert len(fresh) * 2 >= len(categories), (task.id, fresh)
        assert set(task.rooms) - used_rooms, (task.id, task.rooms)
        for role, spec in task.roles.items():
            assert _mentions(task.description, _names(role, spec.category)), (task.id, role)


def test_new_tasks_are_not_written_in_the_benchmark_template() -> None:
    """Written as a person would, not as "If the X is Y, ..." sentences."""
    for task in load_tasks(NEW):
        sentences = [s for s in re.split(r"(?<=[.!?\n])\s+", task.description) if s]
        templated = [s for s in sentences if re.match(r"If the \w+( \w+)? is \w+,", s)]
        assert len(templated) * 4 < len(sentences), (task.id, templated)


def test_every_task_ships_its_four_policies_and_a_current_mutant_list() -> None:
    """`killable_mutants.json` is keyed by the task (its description too): a description edited
    without `tasks mutants --write` would make every run classify it afresh."""
    tasks = load_tasks(NEW)
    for task in tasks:
        assert set(task.policies) == {"correct", "counterfactual", "unreachable", "lackbranch"}, task.id
    stale = [task.id for task in tasks if not shipped_is_current(task, NEW, load_catalog())]
    assert not stale, f"run `python -m logicenveval tasks mutants --write --tasks-dir {NEW}` for {stale}"


def test_a_dev2_task_validates() -> None:
    report = validate_task("lounge_voice_note", NEW, worlds=2)
    assert not report.problems, [str(p) for p in report.problems]


@pytest.mark.slow
def test_every_dev2_task_validates() -> None:
    problems = [str(p) for tid in task_ids(NEW) for p in validate_task(tid, NEW).problems]
    assert not problems, problems[:10]
