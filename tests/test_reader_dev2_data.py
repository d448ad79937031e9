"""The reader's second development set (tests/data/reader_dev2/): new tasks written from scratch
after the first set (tests/data/reader_dev/) had been tuned on, for the next round of work on the
offline reader.

Nothing here runs the offline model: these tests keep the data honest (valid tasks about objects
and rooms the other sets do not use, each object named in its description, a current mutant
list), not the reader's scores.
"""

from __future__ import annotations

import pytest
from reader_sets import (
    DATA,
    check_all_validate,
    check_mutant_lists_current,
    check_new_tasks_are_fresh,
    check_not_templated,
    check_policies,
    check_validates,
)

from logicenveval.benchmark import task_ids

NEW = DATA / "reader_dev2" / "tasks_new"
DEV_NEW = DATA / "reader_dev" / "tasks_new"


def test_the_set_has_new_tasks_whose_ids_collide_with_no_other_set() -> None:
    ids = task_ids(NEW)
    assert len(ids) >= 5
    assert not set(ids) & (set(task_ids()) | set(task_ids(DEV_NEW)))


def test_new_tasks_are_about_objects_and_rooms_the_other_sets_do_not_use() -> None:
    check_new_tasks_are_fresh(NEW, [DEV_NEW])


def test_new_tasks_are_not_written_in_the_benchmark_template() -> None:
    check_not_templated(NEW, breaks=r"[.!?\n]")


def test_every_task_ships_its_four_policies_and_a_current_mutant_list() -> None:
    check_policies([NEW])
    check_mutant_lists_current([NEW])


def test_a_dev2_task_validates() -> None:
    check_validates(NEW, "lounge_voice_note")


@pytest.mark.slow
def test_every_dev2_task_validates() -> None:
    check_all_validate(NEW)
